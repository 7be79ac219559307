#include "contact/search.hpp"

#include <algorithm>
#include <cmath>

#include "contact/geometry.hpp"

namespace crumple::contact {

namespace {

// The margin is this fraction of the smallest reach of any pass: short candidate lists, and
// sorts not too often.
constexpr double kMarginFraction = 0.25;

Vec3 centroid(const std::array<int32_t, 4>& seg, const std::vector<double>& x) {
  Vec3 c{};
  for (int32_t a : seg) c = add(c, at(x, std::size_t(a)));
  return scale(c, 0.25);
}

// How far from a segment's centroid a node can touch it: the segment's radius plus the
// contact thicknesses and half the deepest element.
double reachOf(const Pass& p, const std::vector<double>& x) {
  double radius = 0.0;
  for (const auto& seg : p.seg) {
    const Vec3 c = centroid(seg, x);
    for (int32_t a : seg) radius = std::max(radius, norm(sub(at(x, std::size_t(a)), c)));
  }
  return radius + p.reach_extra;
}

}  // namespace

void BucketSearch::sort(const std::vector<Pass>& passes, const std::vector<double>& x) {
  // The margin node and segment may close by before the next sort (the caller re-sorts when
  // twice the largest travel exceeds it): a quarter of the smallest reach, so that the
  // candidate lists stay short; each pass's cells hold its reach plus the margin, so the 27
  // cells around a node hold every segment it can meet before the next sort.
  grids_.resize(passes.size());
  double smallest = 1e300;
  for (std::size_t i = 0; i < passes.size(); ++i) {
    grids_[i].reach = reachOf(passes[i], x);
    if (!passes[i].seg.empty()) smallest = std::min(smallest, grids_[i].reach);
  }
  margin_ = smallest < 1e300 ? kMarginFraction * smallest : 0.0;
  for (std::size_t i = 0; i < passes.size(); ++i) sortBuckets(passes[i], grids_[i], x);
}

void BucketSearch::sortBuckets(const Pass& p, Grid& g, const std::vector<double>& x) const {
  const std::size_t ns = p.seg.size();
  std::vector<Vec3> centre(ns);
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (std::size_t s = 0; s < ns; ++s) {
    centre[s] = centroid(p.seg[s], x);
    for (std::size_t i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], centre[s][i]);
      hi[i] = std::max(hi[i], centre[s][i]);
    }
  }
  // Cell size: a node meets segments whose centroid is within the reach, and may close by the
  // margin before the next sort.
  double cell = g.reach + margin_;
  // Keep the grid at most a few cells per segment (a long thin surface would otherwise make
  // most cells empty).
  for (;;) {
    std::size_t cells = 1;
    for (std::size_t i = 0; i < 3; ++i) cells *= std::size_t((hi[i] - lo[i]) / cell) + 1;
    if (cells <= 4 * ns + 64) break;
    cell *= 1.5;
  }
  g.cell = cell;
  g.lo = lo;
  for (std::size_t i = 0; i < 3; ++i) g.dims[i] = int32_t((hi[i] - lo[i]) / cell) + 1;
  const std::size_t ncell =
      std::size_t(g.dims[0]) * std::size_t(g.dims[1]) * std::size_t(g.dims[2]);
  // Counting sort of the segments by cell (CSR, ascending segment index within a cell).
  g.cell_ptr.assign(ncell + 1, 0);
  std::vector<int32_t> cell_of(ns);
  for (std::size_t s = 0; s < ns; ++s) {
    std::size_t id = 0;
    for (std::size_t i = 3; i-- > 0;) {
      const auto k = std::clamp(int32_t((centre[s][i] - lo[i]) / cell), 0, g.dims[i] - 1);
      id = id * std::size_t(g.dims[i]) + std::size_t(k);
    }
    cell_of[s] = int32_t(id);
    ++g.cell_ptr[id + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) g.cell_ptr[c + 1] += g.cell_ptr[c];
  g.cell_seg.assign(ns, 0);
  std::vector<int32_t> fill(g.cell_ptr.begin(), g.cell_ptr.end() - 1);
  for (std::size_t s = 0; s < ns; ++s)
    g.cell_seg[std::size_t(fill[std::size_t(cell_of[s])]++)] = int32_t(s);
}

void BucketSearch::updateBoxes(const std::vector<Pass>& passes, const std::vector<double>& x,
                               bool needed_only) {
  // Slack: the contact thickness of any node of the pass with the segment, the depth a node may
  // reach into a solid, and the parametric tolerance of "over the segment".
  for (std::size_t pass = 0; pass < passes.size(); ++pass) {
    const Pass& p = passes[pass];
    Grid& g = grids_[pass];
    const std::size_t ns = p.seg.size();
    g.box.resize(6 * ns);
    const std::size_t count = needed_only ? g.needed.size() : ns;
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t s = needed_only ? std::size_t(g.needed[k]) : k;
      double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
      for (int32_t a : p.seg[s])
        for (std::size_t i = 0; i < 3; ++i) {
          lo[i] = std::min(lo[i], x[3 * std::size_t(a) + i]);
          hi[i] = std::max(hi[i], x[3 * std::size_t(a) + i]);
        }
      const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
      const double slack = p.max_node_half + p.seg_half[s] +
                           (p.seg_half[s] > 0.0 ? 0.0 : 0.5 * p.seg_depth[s]) +
                           2.0 * kInsideTolerance * extent;
      for (std::size_t i = 0; i < 3; ++i) {
        g.box[6 * s + i] = lo[i] - slack;
        g.box[6 * s + 3 + i] = hi[i] + slack;
      }
    }
  }
}

template <class F>
void BucketSearch::forEachNear(const Grid& g, const Vec3& xn, F&& f) const {
  // The segments in the point's bucket and the 26 around it.
  std::array<int32_t, 3> k{};
  for (std::size_t i = 0; i < 3; ++i) {
    const double r = (xn[i] - g.lo[i]) / g.cell;
    if (r < -1.0 || r >= double(g.dims[i]) + 1.0) return;
    k[i] = int32_t(std::floor(r));
  }
  for (int32_t cz = std::max(k[2] - 1, 0); cz <= std::min(k[2] + 1, g.dims[2] - 1); ++cz)
    for (int32_t cy = std::max(k[1] - 1, 0); cy <= std::min(k[1] + 1, g.dims[1] - 1); ++cy)
      for (int32_t cx = std::max(k[0] - 1, 0); cx <= std::min(k[0] + 1, g.dims[0] - 1); ++cx) {
        const std::size_t c =
            (std::size_t(cz) * std::size_t(g.dims[1]) + std::size_t(cy)) * std::size_t(g.dims[0]) +
            std::size_t(cx);
        for (int32_t q = g.cell_ptr[c]; q < g.cell_ptr[c + 1]; ++q)
          f(std::size_t(g.cell_seg[std::size_t(q)]));
      }
}

void BucketSearch::collectCandidates(const Pass& p, std::size_t pass, int32_t check, double margin,
                                     const std::vector<double>& x,
                                     std::vector<int32_t>& out) const {
  if (p.edges) {
    collectEdgeCandidates(p, pass, check, margin, x, out);
    return;
  }
  if (p.segpairs) {
    collectSegmentCandidates(p, pass, check, margin, x, out);
    return;
  }
  // The segments near the node whose widened box, grown by what node and segment may still
  // travel before the next sort, holds the node.
  const Grid& g = grids_[pass];
  const int32_t node = p.node[std::size_t(check - p.first_check)];
  const Vec3 xn = at(x, std::size_t(node));
  const int32_t* near_begin =
      p.self ? &p.near_node[std::size_t(p.near_ptr[std::size_t(node)])] : nullptr;
  const int32_t* near_end =
      p.self ? &p.near_node[std::size_t(p.near_ptr[std::size_t(node) + 1])] : nullptr;
  forEachNear(g, xn, [&](std::size_t s) {
    const double* box = &g.box[6 * s];
    if (xn[0] < box[0] - margin || xn[0] > box[3] + margin || xn[1] < box[1] - margin ||
        xn[1] > box[4] + margin || xn[2] < box[2] - margin || xn[2] > box[5] + margin)
      return;
    // A node is never in contact with its own segments, nor (single surface) with the
    // segments next to them.
    bool skip = false;
    for (int32_t a : p.seg[s]) {
      if (a == node) skip = true;
      if (near_begin && std::binary_search(near_begin, near_end, a)) skip = true;
    }
    if (!skip) out.push_back(int32_t(s));
  });
}

void BucketSearch::collectEdgeCandidates(const Pass& p, std::size_t pass, int32_t check,
                                         double margin, const std::vector<double>& x,
                                         std::vector<int32_t>& out) const {
  // The edges near the check's edge (its middle's bucket and the 26 around it: the reach
  // holds half the longest edge) whose widened box, grown by the margin, overlaps the edge's
  // box. Each pair once: only edges of higher index; never an edge sharing a node, nor (CPARM8)
  // one of the same part.
  const Grid& g = grids_[pass];
  const auto k = std::size_t(check - p.first_check);
  const auto a0 = p.node[k], a1 = p.node2[k];
  const Vec3 x0 = at(x, std::size_t(a0)), x1 = at(x, std::size_t(a1));
  double lo[3], hi[3];
  for (std::size_t i = 0; i < 3; ++i) {
    lo[i] = std::min(x0[i], x1[i]) - margin;
    hi[i] = std::max(x0[i], x1[i]) + margin;
  }
  const std::size_t first = out.size();
  forEachNear(g, scale(add(x0, x1), 0.5), [&](std::size_t s) {
    if (s <= k) return;
    const double* box = &g.box[6 * s];
    for (std::size_t i = 0; i < 3; ++i)
      if (hi[i] < box[i] || lo[i] > box[3 + i]) return;
    const auto& b = p.seg[s];
    if (b[0] == a0 || b[0] == a1 || b[1] == a0 || b[1] == a1) return;
    if (p.skip_same_part && p.edge_part[s] == p.edge_part[k]) return;
    out.push_back(int32_t(s));
  });
  // Ascending, so that a check's records come in the same order whatever the bucket layout.
  std::sort(out.begin() + std::ptrdiff_t(first), out.end());
}

void BucketSearch::collectSegmentCandidates(const Pass& p, std::size_t pass, int32_t check,
                                            double margin, const std::vector<double>& x,
                                            std::vector<int32_t>& out) const {
  // The segments near the check's segment (its centroid's bucket and the 26 around it: the
  // reach holds the largest check segment's radius) whose widened box, grown by the margin,
  // overlaps its box. Never a segment sharing a node with it (its neighbours, whose contact
  // is the element's own business); single surface: each pair once, by the lower index.
  const Grid& g = grids_[pass];
  const auto k = std::size_t(check - p.first_check);
  const auto& cs = p.check_seg[k];
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (int32_t a : cs)
    for (std::size_t i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], x[3 * std::size_t(a) + i] - margin);
      hi[i] = std::max(hi[i], x[3 * std::size_t(a) + i] + margin);
    }
  const std::size_t first = out.size();
  forEachNear(g, centroid(cs, x), [&](std::size_t s) {
    if (p.self && s <= k) return;
    const double* box = &g.box[6 * s];
    for (std::size_t i = 0; i < 3; ++i)
      if (hi[i] < box[i] || lo[i] > box[3 + i]) return;
    for (int32_t a : p.seg[s])
      for (int32_t b : cs)
        if (a == b) return;
    out.push_back(int32_t(s));
  });
  std::sort(out.begin() + std::ptrdiff_t(first), out.end());
}

void BucketSearch::buildCandidateLists(const std::vector<Pass>& passes,
                                       const std::vector<int32_t>& checks,
                                       const std::vector<int32_t>& check_pass,
                                       const std::vector<int32_t>& tie_seg,
                                       const std::vector<double>& x) {
  // Valid until the next sort: node and segment then have closed by at most the margin.
  cand_ptr_.assign(1, 0);
  cand_seg_.clear();
  active_.clear();
  for (std::size_t i = 0; i < checks.size(); ++i) {
    const auto check = std::size_t(checks[i]);
    const auto pass = std::size_t(check_pass[check]);
    const Pass& p = passes[pass];
    // A tiebreak check whose bond has failed (or never formed) is an ordinary one.
    if (!p.tied || (p.tiebreak && tie_seg[check] < 0))
      collectCandidates(p, pass, int32_t(check), 1.1 * margin_, x, cand_seg_);
    cand_ptr_.push_back(int32_t(cand_seg_.size()));
    // Only checks that can meet something before the next sort are visited each cycle.
    if (cand_ptr_[i + 1] > cand_ptr_[i] || (p.tied && tie_seg[check] >= 0))
      active_.push_back(int32_t(i));
  }
  // The segments whose boxes this rank needs until the next sort.
  for (auto& g : grids_) g.needed.clear();
  for (std::size_t i = 0; i < checks.size(); ++i) {
    Grid& g = grids_[std::size_t(check_pass[std::size_t(checks[i])])];
    g.needed.insert(g.needed.end(), cand_seg_.begin() + cand_ptr_[i],
                    cand_seg_.begin() + cand_ptr_[i + 1]);
  }
  for (auto& g : grids_) {
    std::sort(g.needed.begin(), g.needed.end());
    g.needed.erase(std::unique(g.needed.begin(), g.needed.end()), g.needed.end());
  }
}

}  // namespace crumple::contact
