// Contact surfaces that follow element erosion (docs/theory.md, "Eroding contact").
//
// An eroded element leaves every interface: its segments no longer push, and a node whose
// elements have all eroded (a free node) is no longer checked, as LS-DYNA's *CONTROL_CONTACT
// ENMASS 0 (Keyword Manual: "eroding nodes are removed from the calculation"). With ENMASS 1
// the free nodes of solids stay in every interface they were in, with their mass (the
// debris of a perforated target still strikes); with 2 those of shells too.
// *CONTACT_ERODING_ interfaces with EROSOP 1 go further (Keyword Manual, *CONTACT_ERODING_...):
// their surfaces hold every face of their solids, and a face with a solid across it
// (ContactSurface::segment_neighbour) is in contact once that solid has eroded and its own
// element lives; their checks are the nodes on faces in contact, so the nodes erosion exposes
// join as the faces do.
//
// Every rank holds the same flags. Each rank finds the eroded elements among its own
// (erodedHere, when its element pass reports erosion), and the lists of every rank meet at
// the next bucket sort (Contact::syncErosion), so that all ranks mark the same elements in
// the same cycle: the same bits for any number of ranks.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "contact/pass.hpp"
#include "domain/subdomain.hpp"
#include "model/model.hpp"

namespace crumple::contact {

class SurfaceErosion {
 public:
  // Tracks the elements of the passes' segments, the solids across them and every element at
  // a contact node (cn_model: the contact nodes' model indices); the flags start as the
  // initial surfaces have them (interior faces and their nodes out).
  void build(const model::Model& m, const std::vector<Pass>& passes,
             const std::vector<int32_t>& cn_model, const domain::Subdomain& sd);
  bool segmentLive(std::size_t pass, std::size_t seg) const { return seg_live_[pass][seg] != 0; }
  // Pass `pass`'s flags, one per segment (for loops over its candidates).
  const uint8_t* segmentFlags(std::size_t pass) const { return seg_live_[pass].data(); }
  bool checkLive(std::size_t check) const { return check_live_[check] != 0; }
  // The tracked elements of this rank's blocks that have eroded and are not yet marked, as
  // global element indices, ascending.
  std::vector<int64_t> erodedHere() const;
  // Marks these elements eroded (the same list on every rank) and updates the flags; false if
  // none of them was tracked (nothing changed).
  bool markEroded(std::span<const int64_t> elements, const std::vector<Pass>& passes);

 private:
  int32_t slotOf(int64_t element) const;  // index into tracked_, or -1
  std::vector<int32_t> slotsOf(const std::vector<int64_t>& elements) const;  // -1 stays -1
  // A face with `owner` (slot) and the solid `across` (slot, -1 none) is in contact.
  bool faceLive(int32_t owner, int32_t across) const {
    return alive_[std::size_t(owner)] != 0 && (across < 0 || alive_[std::size_t(across)] == 0);
  }
  void trackNodeElements(const model::Model& m, const std::vector<int32_t>& cn_model);
  // Whether a free node stays in contact under ENMASS `enmass`, given whether it had a solid
  // and a shell among its elements.
  static bool keepsFreeNode(int enmass, bool solid, bool shell) {
    return (enmass >= 1 && solid) || (enmass == 2 && shell);
  }
  void locate(const domain::Subdomain& sd);
  void refresh(const std::vector<Pass>& passes);
  void refreshChecks(const std::vector<Pass>& passes);

  std::vector<int64_t> tracked_;  // global element indices, ascending
  std::vector<uint8_t> alive_;    // per tracked element
  // Per contact node, the slots of the elements at it (CSR).
  std::vector<int32_t> node_ptr_, node_elem_;
  // Per pass: its segments' elements and the solids across them (slots; -1 none), and the
  // faces of the checks' own surface for the passes whose checks follow the exposed faces.
  struct PassSlots {
    std::vector<int32_t> seg_owner, seg_across;
    std::vector<int32_t> check_owner, check_across;  // segment pairs: the checks' segments
    std::vector<int32_t> own_owner, own_across;      // Pass::exposure passes
  };
  std::vector<PassSlots> slots_;
  // This rank's tracked elements: their block's `active` flags (blocks are not resized once
  // the subdomain is built) and their index there.
  struct Local {
    const std::vector<uint8_t>* active = nullptr;
    int32_t index = 0, slot = 0;
  };
  std::vector<Local> local_;
  std::vector<std::vector<uint8_t>> seg_live_;
  // Per contact node: kDead, kLive (one of its elements lives, or it has none) or kFree (its
  // elements have all eroded and ENMASS keeps it).
  enum NodeState : uint8_t { kDead = 0, kLive = 1, kFree = 2 };
  std::vector<uint8_t> node_live_, check_live_;
  std::vector<uint8_t> keep_free_;  // per contact node: kept in contact once free (ENMASS)
};

}  // namespace crumple::contact
