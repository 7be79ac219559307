// A Subdomain is what one rank computes on: its nodes in local numbering, its element blocks,
// the per-element force slots and the plan that gathers them into nodal forces in global
// element order. Serial is one subdomain holding everything.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "materials/materials.hpp"
#include "model/model.hpp"

namespace crumple::domain {

// Nodal values are packed xyz (3 doubles per node): the hex kernel gathers whole nodes, and a
// packed layout keeps the three components of a node on one cache line.
using NodeVector = std::vector<double>;

struct HourglassParams {
  int ihq = 1;      // 1-3 viscous, 4-5 stiffness (Flanagan-Belytschko)
  double qm = 0.1;  // coefficient
};

// Elements are processed in batches of this many; a block's per-element state arrays are
// padded to whole batches so that kernels load and store them as contiguous vectors (padding
// lanes compute on copies of real data and are never read back).
inline constexpr int kSolidBatch = 16;

// Elements of one part: one element type x one material x one section. State is a structure
// of arrays owned by the block; element e of the block is global (model) element elem[e].
struct SolidBlock {
  int32_t part = model::kNone;  // model part index
  int64_t part_id = 0;
  materials::Law law;
  double rho0 = 0.0;
  HourglassParams hourglass;

  std::vector<int32_t> elem;                 // model element index, ascending
  std::vector<std::array<int32_t, 8>> conn;  // local node indices
  std::size_t slot_offset = 0;               // first force slot (element-major, 8 corners)

  // Per-element state.
  std::array<std::vector<double>, 6> sig;    // Cauchy stress (Voigt, tensor shear)
  std::vector<double> eps_p;                 // effective plastic strain (plastic laws)
  std::array<std::vector<double>, 6> alpha;  // back stress (kinematic hardening laws)
  std::array<std::vector<double>, 12> hgq;   // hourglass resistance, stiffness forms (3 x 4)
  std::vector<double> vol0, vol;             // initial and current volume
  std::vector<double> e_int, e_hg;           // internal and hourglass energy
  std::vector<uint8_t> active;               // 0 once eroded
  std::vector<uint8_t> failed;               // material reports failure this cycle
  std::vector<double> mass_scale;            // mass scaling factor (>= 1), padded; empty if none

  std::size_t size() const { return elem.size(); }
  // Elements plus padding: a whole number of batches.
  std::size_t paddedSize() const {
    return (elem.size() + kSolidBatch - 1) / kSolidBatch * kSolidBatch;
  }
  void resize(std::size_t n, bool plastic, bool kinematic, bool stiffness_hourglass);
};

struct Subdomain {
  int rank = 0;
  int num_ranks = 1;

  // Nodes: local index -> model node index (ascending, so local order == global id order).
  std::vector<int32_t> node_model;
  std::vector<int64_t> node_id;  // user ids, for output
  NodeVector x0, x, v, a, f, f_ext;
  std::vector<double> mass;  // lumped nodal mass (incl. mass added by scaling)
  std::vector<double> mass_added;

  std::vector<SolidBlock> solid_blocks;
  std::size_t num_elements = 0;

  // Element corner forces: slots[3*(slot)+c], slot = block.slot_offset + 8*e + corner.
  std::vector<double> slots;
  // Gather plan (CSR): node n sums slots gather_slot[gather_ptr[n] .. gather_ptr[n+1])
  // in ascending (global element id, corner) order.
  std::vector<int32_t> gather_ptr;
  std::vector<int32_t> gather_slot;

  std::size_t numNodes() const { return node_model.size(); }
};

// Builds the subdomain that holds the given model elements (ascending) and the nodes they
// reference, plus `extra_nodes` (nodes attached to no element that this rank keeps).
Subdomain buildSubdomain(const model::Model& model, const std::vector<int32_t>& elements,
                         const std::vector<int32_t>& extra_nodes, int rank, int num_ranks);

// The single subdomain of a serial run: every node and element of the model.
Subdomain buildSerialSubdomain(const model::Model& model);

}  // namespace crumple::domain
