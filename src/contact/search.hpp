// The bucket search (Benson & Hallquist 1990, "A single surface contact algorithm for the
// post-buckling analysis of shell structures", CMAME 78): each pass's segments are binned by
// centroid into a grid of buckets, and each check keeps, until the next sort, the segments of
// its bucket and the 26 around it whose widened bounding box holds its node (docs/theory.md,
// "Search"). The cost is linear in the surface size.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "contact/pass.hpp"
#include "util/vec3.hpp"

namespace crumple::contact {

using util::Vec3;

class BucketSearch {
 public:
  // Bins every pass's segments at the positions x (3 per contact node): the margin node and
  // segment may close by before the next sort, then each pass's grid.
  void sort(const std::vector<Pass>& passes, const std::vector<double>& x);
  // The widened bounding boxes of the segments at x; between sorts (`needed_only`) only those
  // of the segments in this rank's candidate lists.
  void updateBoxes(const std::vector<Pass>& passes, const std::vector<double>& x, bool needed_only);
  // Segments check may meet before the next sort (appended to `out`), its node and the boxes
  // being `margin` apart at the most.
  void collectCandidates(const Pass& pass, std::size_t pass_index, int32_t check, double margin,
                         const std::vector<double>& x, std::vector<int32_t>& out) const;
  // The candidate lists of `checks` (global, ascending), valid until the next sort.
  // check_pass: the pass of every check; tie_seg: the segment a check of a tied pass is held
  // to, or -1 (a tied check is visited each cycle without candidates).
  void buildCandidateLists(const std::vector<Pass>& passes, const std::vector<int32_t>& checks,
                           const std::vector<int32_t>& check_pass,
                           const std::vector<int32_t>& tie_seg, const std::vector<double>& x);

  // The margin of the last sort: node and segment may close by this much before the next.
  double margin() const { return margin_; }
  // Widened bounding box of a segment (lo xyz, hi xyz).
  const double* box(std::size_t pass, std::size_t seg) const { return &grids_[pass].box[6 * seg]; }
  // Indices into the `checks` of buildCandidateLists that have candidates or a tie: the ones
  // visited each cycle.
  const std::vector<int32_t>& active() const { return active_; }
  std::span<const int32_t> candidates(std::size_t i) const {
    return {cand_seg_.data() + cand_ptr_[i], std::size_t(cand_ptr_[i + 1] - cand_ptr_[i])};
  }

 private:
  // One pass's buckets, rebuilt at each sort, and its segments' boxes, updated each cycle.
  struct Grid {
    double reach = 0.0;           // segment radius + Pass::reach_extra at the last sort
    std::vector<double> box;      // per segment: widened bounding box (lo xyz, hi xyz)
    std::vector<int32_t> needed;  // segments in this rank's candidate lists (ascending)
    std::array<double, 3> lo{};
    double cell = 1.0;
    std::array<int32_t, 3> dims{1, 1, 1};
    std::vector<int32_t> cell_ptr, cell_seg;
  };
  void sortBuckets(const Pass& pass, Grid& grid, const std::vector<double>& x) const;
  // Calls f(segment) for the segments binned in the bucket of xn and the 26 around it.
  template <class F>
  void forEachNear(const Grid& g, const Vec3& xn, F&& f) const;
  // collectCandidates for a pass of beam edges (Pass::edges).
  void collectEdgeCandidates(const Pass& pass, std::size_t pass_index, int32_t check, double margin,
                             const std::vector<double>& x, std::vector<int32_t>& out) const;

  // collectCandidates for a pass of segment pairs (Pass::segpairs).
  void collectSegmentCandidates(const Pass& pass, std::size_t pass_index, int32_t check,
                                double margin, const std::vector<double>& x,
                                std::vector<int32_t>& out) const;

  std::vector<Grid> grids_;  // per pass
  double margin_ = 0.0;
  std::vector<int32_t> cand_ptr_, cand_seg_;  // candidate segments of each check (CSR)
  std::vector<int32_t> active_;
};

}  // namespace crumple::contact
