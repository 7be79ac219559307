#include "contact/contact.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include "contact/geometry.hpp"
#include "util/archive.hpp"
#include "util/error.hpp"

namespace crumple::contact {

namespace {

// A record of one node in contact: check, segment, the four weights, the force on the node
// (normal + friction), the friction part alone, the penetration, the energy of the penalty
// spring (k pen^2 / 2), the energy friction and damping dissipated over the last step, and
// the side of the segment the node is on, and its entry offset.
constexpr std::size_t kRecord = 17;
// Parametric tolerance of "the node is over the segment" (geometry.hpp).
constexpr double kInsideTolerance = 0.02;
constexpr double kStableFraction = 0.1;
constexpr double kMarginFraction = 0.25;

Vec3 at(const std::vector<double>& a, std::size_t i) {
  return {a[3 * i], a[3 * i + 1], a[3 * i + 2]};
}

}  // namespace

// The segments one side's nodes are checked against, with the bucket grid over them
// (Benson & Hallquist 1990, "A single surface contact algorithm for the post-buckling
// analysis of shell structures", CMAME 78: a grid of buckets, each node tested against the
// segments of its bucket and the 26 around it, so the cost is linear in the surface size).
struct Contact::Pass {
  int32_t iface = 0;                        // index into Model::contacts
  bool self = false;                        // single surface: skip segments next to the node
  int32_t first_check = 0;                  // global index of the first check
  std::vector<int32_t> node;                // contact node of each check
  std::vector<double> node_half;            // half shell thickness at the node
  std::vector<std::array<int32_t, 4>> seg;  // contact nodes
  std::vector<double> seg_half;             // half thickness (0: one-sided solid face)
  std::vector<double> seg_k;                // penalty stiffness with the scale factors
  std::vector<double> seg_depth;            // ContactSurface::segment_depth
  // Single surface: the nodes sharing a segment with each node (CSR over contact nodes).
  std::vector<int32_t> near_ptr, near_node;
  double reach_extra = 0.0;  // largest node + segment half thickness
  double reach = 0.0;        // segment radius + reach_extra at the last sort
  double max_node_half = 0.0;
  std::vector<double> box;      // per segment: widened bounding box (lo xyz, hi xyz), each cycle
  std::vector<int32_t> needed;  // segments in this rank's candidate lists (ascending)
  bool tied = false;            // nodes held to the point of the segment they started on
  // Bucket grid (rebuilt at each sort).
  std::array<double, 3> lo{};
  double cell = 1.0;
  std::array<int32_t, 3> dims{1, 1, 1};
  std::vector<int32_t> cell_ptr, cell_seg;
};

struct Contact::Candidate {
  int32_t seg = -1;
  int rank = 3;        // 0 the segment of the last cycle, 1 crossed in the last step, 2 other
  int side = 1;        // shells: the side of the mid-surface the node is on (along the normal)
  double entry = 0.0;  // penetration the node already had when the contact began
  Projection proj;
  Vec3 push{};       // unit direction the node is pushed
  double gap = 0.0;  // negative: penetration
};

Contact::Contact(const model::Model& model, domain::Subdomain& sd, comm::Communicator& comm)
    : model_(model), sd_(sd), comm_(comm) {
  if (model.contacts.empty()) return;
  // Contact nodes: the union of every side's nodes and segment nodes.
  for (const auto& ci : model.contacts)
    for (const auto* s : {&ci.a, &ci.b}) {
      cn_model_.insert(cn_model_.end(), s->nodes.begin(), s->nodes.end());
      for (const auto& seg : s->segments) cn_model_.insert(cn_model_.end(), seg.begin(), seg.end());
    }
  std::sort(cn_model_.begin(), cn_model_.end());
  cn_model_.erase(std::unique(cn_model_.begin(), cn_model_.end()), cn_model_.end());
  auto cn = [&](int32_t model_node) {
    return int32_t(std::lower_bound(cn_model_.begin(), cn_model_.end(), model_node) -
                   cn_model_.begin());
  };
  const std::size_t ncn = cn_model_.size();
  cn_local_.resize(ncn);
  cn_owned_.resize(ncn);
  for (std::size_t i = 0; i < ncn; ++i) {
    cn_local_[i] = sd.localNode(cn_model_[i]);
    cn_owned_[i] = cn_local_[i] >= 0 && sd.node_owned[std::size_t(cn_local_[i])];
  }
  x_.assign(3 * ncn, 0.0);
  x_owned_prev_.assign(3 * ncn, 0.0);
  owner_.assign(ncn, 0);
  v_.assign(3 * ncn, 0.0);
  mass_.assign(ncn, 0.0);
  const double slsfac = model.contact_controls.slsfac;

  auto addPass = [&](int32_t iface, const model::ContactSurface& nodes,
                     const model::ContactSurface& segs, double sf, bool self) {
    Pass p;
    p.iface = iface;
    p.self = self;
    p.first_check = num_checks_;
    double max_node_half = 0.0, max_seg_half = 0.0, max_depth = 0.0;
    for (std::size_t k = 0; k < nodes.nodes.size(); ++k) {
      p.node.push_back(cn(nodes.nodes[k]));
      p.node_half.push_back(nodes.node_half_thickness[k]);
      max_node_half = std::max(max_node_half, nodes.node_half_thickness[k]);
    }
    for (std::size_t k = 0; k < segs.segments.size(); ++k) {
      const auto& s = segs.segments[k];
      p.seg.push_back({cn(s[0]), cn(s[1]), cn(s[2]), cn(s[3])});
      p.seg_half.push_back(0.5 * segs.segment_thickness[k]);
      p.seg_k.push_back(slsfac * sf * segs.segment_stiffness[k]);
      p.seg_depth.push_back(segs.segment_depth[k]);
      max_seg_half = std::max(max_seg_half, 0.5 * segs.segment_thickness[k]);
      max_depth = std::max(max_depth, segs.segment_depth[k]);
    }
    p.reach_extra = max_node_half + max_seg_half + 0.5 * max_depth;
    p.max_node_half = max_node_half;
    if (self) {
      std::vector<std::vector<int32_t>> near(ncn);
      for (const auto& s : p.seg)
        for (int32_t a : s)
          for (int32_t b : s) near[std::size_t(a)].push_back(b);
      p.near_ptr.assign(ncn + 1, 0);
      for (std::size_t i = 0; i < ncn; ++i) {
        auto& v = near[i];
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end()), v.end());
        p.near_ptr[i + 1] = p.near_ptr[i] + int32_t(v.size());
        p.near_node.insert(p.near_node.end(), v.begin(), v.end());
      }
    }
    num_checks_ += int32_t(p.node.size());
    for (std::size_t k = 0; k < p.node.size(); ++k) check_pass_.push_back(int32_t(passes_.size()));
    passes_.push_back(std::move(p));
  };
  for (std::size_t i = 0; i < model.contacts.size(); ++i) {
    const auto& ci = model.contacts[i];
    const auto iface = int32_t(i);
    switch (ci.kind) {
      case model::ContactKind::NodesToSurface:
        addPass(iface, ci.a, ci.b, ci.sfm, false);
        break;
      case model::ContactKind::SurfaceToSurface:
        addPass(iface, ci.a, ci.b, ci.sfm, false);
        addPass(iface, ci.b, ci.a, ci.sfs, false);
        break;
      case model::ContactKind::SingleSurface:
        addPass(iface, ci.a, ci.a, ci.sfs, true);
        break;
      case model::ContactKind::Tied:
        addPass(iface, ci.a, ci.b, ci.sfm, false);
        passes_.back().tied = true;
        break;
    }
  }
  stats_.checks = num_checks_;
  for (const auto& ci : model.contacts)
    if (ci.bsort > 0)
      max_sort_interval_ =
          max_sort_interval_ > 0 ? std::min(max_sort_interval_, ci.bsort) : ci.bsort;
  friction_.assign(3 * std::size_t(num_checks_), 0.0);
  initial_gap_.assign(std::size_t(num_checks_), 0.0);
  last_seg_.assign(std::size_t(num_checks_), -1);
  last_side_.assign(std::size_t(num_checks_), 0);
  entry_.assign(std::size_t(num_checks_), 0.0);
  tie_seg_.assign(std::size_t(num_checks_), -1);
  tie_weight_.assign(4 * std::size_t(num_checks_), 0.0);
  tie_offset_.assign(std::size_t(num_checks_), 0.0);
  check_cost_.assign(std::size_t(num_checks_), 0.0);
  stored_.assign(model.contacts.size(), 0.0);
  dissipated_.assign(model.contacts.size(), 0.0);
}

Contact::~Contact() = default;

void Contact::gatherNodes() {
  // All contact nodes, from their owners: at set-up and at every bucket sort (positions,
  // velocities, and the owner's positions of the previous pass for the crossing rule).
  const std::size_t ncn = cn_model_.size();
  constexpr std::size_t kWidth = 11;
  std::vector<double> mine;
  for (std::size_t i = 0; i < ncn; ++i) {
    if (!cn_owned_[i]) continue;
    const auto l = std::size_t(cn_local_[i]);
    mine.push_back(double(comm_.rank()));
    mine.push_back(double(i));
    for (int c = 0; c < 3; ++c) mine.push_back(sd_.x[3 * l + std::size_t(c)]);
    for (int c = 0; c < 3; ++c) mine.push_back(sd_.v[3 * l + std::size_t(c)]);
    for (int c = 0; c < 3; ++c) mine.push_back(x_owned_prev_[3 * i + std::size_t(c)]);
  }
  const auto all = comm_.allGather(mine);
  for (std::size_t k = 0; k + kWidth <= all.size(); k += kWidth) {
    const auto i = std::size_t(all[k + 1]);
    owner_[i] = int32_t(all[k]);
    for (int c = 0; c < 3; ++c) {
      x_[3 * i + std::size_t(c)] = all[k + 2 + std::size_t(c)];
      v_[3 * i + std::size_t(c)] = all[k + 5 + std::size_t(c)];
      x_prev_[3 * i + std::size_t(c)] = all[k + 8 + std::size_t(c)];
    }
  }
}

void Contact::gatherNeeded() {
  // Between sorts a rank reads only the nodes of its checks and of their candidate segments:
  // the ones it holds from its own arrays (every rank holding a node has the same bits), the
  // others from their owners (the routes built at the sort), not every node from everyone.
  for (int32_t i : needed_local_) {
    const auto l = std::size_t(cn_local_[std::size_t(i)]);
    for (int c = 0; c < 3; ++c) {
      x_[3 * std::size_t(i) + std::size_t(c)] = sd_.x[3 * l + std::size_t(c)];
      v_[3 * std::size_t(i) + std::size_t(c)] = sd_.v[3 * l + std::size_t(c)];
    }
  }
  if (!comm_.distributed()) return;
  std::vector<comm::Message> sends, recvs;
  for (auto& r : send_routes_) {
    r.buffer.resize(6 * r.nodes.size());
    for (std::size_t k = 0; k < r.nodes.size(); ++k) {
      const auto l = std::size_t(cn_local_[std::size_t(r.nodes[k])]);
      for (int c = 0; c < 3; ++c) {
        r.buffer[6 * k + std::size_t(c)] = sd_.x[3 * l + std::size_t(c)];
        r.buffer[6 * k + 3 + std::size_t(c)] = sd_.v[3 * l + std::size_t(c)];
      }
    }
    sends.push_back({r.peer, r.buffer.data(), r.buffer.size()});
  }
  for (auto& r : recv_routes_) {
    r.buffer.resize(6 * r.nodes.size());
    recvs.push_back({r.peer, r.buffer.data(), r.buffer.size()});
  }
  comm_.exchangeBegin(sends, recvs);
  comm_.exchangeEnd();
  for (const auto& r : recv_routes_)
    for (std::size_t k = 0; k < r.nodes.size(); ++k) {
      const auto i = std::size_t(r.nodes[k]);
      for (int c = 0; c < 3; ++c) {
        x_[3 * i + std::size_t(c)] = r.buffer[6 * k + std::size_t(c)];
        v_[3 * i + std::size_t(c)] = r.buffer[6 * k + 3 + std::size_t(c)];
      }
    }
}

void Contact::buildRoutes() {
  // The nodes this rank reads until the next sort.
  std::vector<uint8_t> need(cn_model_.size(), 0);
  for (const int32_t active : active_) {
    const auto i = std::size_t(active);
    const int32_t check = my_checks_[i];
    const Pass& p = passes_[std::size_t(check_pass_[std::size_t(check)])];
    need[std::size_t(p.node[std::size_t(check - p.first_check)])] = 1;
    for (int32_t q = cand_ptr_[i]; q < cand_ptr_[i + 1]; ++q)
      for (int32_t a : p.seg[std::size_t(cand_seg_[std::size_t(q)])]) need[std::size_t(a)] = 1;
    if (p.tied && tie_seg_[std::size_t(check)] >= 0)
      for (int32_t a : p.seg[std::size_t(tie_seg_[std::size_t(check)])]) need[std::size_t(a)] = 1;
  }
  needed_local_.clear();
  std::vector<double> requests;  // (requesting rank, node) of the nodes held elsewhere
  for (std::size_t i = 0; i < need.size(); ++i) {
    if (!need[i]) continue;
    if (cn_local_[i] >= 0) {
      needed_local_.push_back(int32_t(i));
    } else {
      requests.push_back(double(comm_.rank()));
      requests.push_back(double(i));
    }
  }
  send_routes_.clear();
  recv_routes_.clear();
  if (!comm_.distributed()) return;
  // Every rank learns what every other needs (at sorts only): each owner serves its nodes, in
  // ascending node order on both sides, so the messages carry values only.
  const auto all = comm_.allGather(requests);
  std::vector<std::vector<int32_t>> to(std::size_t(comm_.size())), from(to.size());
  for (std::size_t k = 0; k + 2 <= all.size(); k += 2) {
    const auto who = std::size_t(all[k]);
    const auto i = std::size_t(all[k + 1]);
    const auto owner = std::size_t(owner_[i]);
    if (owner == std::size_t(comm_.rank())) to[who].push_back(int32_t(i));
    if (who == std::size_t(comm_.rank())) from[owner].push_back(int32_t(i));
  }
  for (std::size_t r = 0; r < to.size(); ++r) {
    if (!to[r].empty()) send_routes_.push_back({int(r), std::move(to[r]), {}});
    if (!from[r].empty()) recv_routes_.push_back({int(r), std::move(from[r]), {}});
  }
}

void Contact::updateBoxes(Pass& p, bool needed_only) {
  // Slack: the contact thickness of any node of the pass with the segment, the depth a node may
  // reach into a solid, and the parametric tolerance of "over the segment". Between sorts only
  // the segments in this rank's candidate lists are needed.
  const std::size_t ns = p.seg.size();
  p.box.resize(6 * ns);
  const std::size_t count = needed_only ? p.needed.size() : ns;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t s = needed_only ? std::size_t(p.needed[k]) : k;
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (int32_t a : p.seg[s])
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], x_[3 * std::size_t(a) + std::size_t(i)]);
        hi[i] = std::max(hi[i], x_[3 * std::size_t(a) + std::size_t(i)]);
      }
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    const double slack = p.max_node_half + p.seg_half[s] +
                         (p.seg_half[s] > 0.0 ? 0.0 : 0.5 * p.seg_depth[s]) +
                         2.0 * kInsideTolerance * extent;
    for (int i = 0; i < 3; ++i) {
      p.box[6 * s + std::size_t(i)] = lo[i] - slack;
      p.box[6 * s + 3 + std::size_t(i)] = hi[i] + slack;
    }
  }
}

void Contact::sortAll() {
  // The margin node and segment may close by before the next sort (computeForces re-sorts
  // when twice the largest travel exceeds it): a quarter of the smallest reach, so that the
  // candidate lists stay short; each pass's cells hold its reach plus the margin, so the 27
  // cells around a node hold every segment it can meet before the next sort.
  double smallest = 1e300;
  for (auto& p : passes_) {
    p.reach = reachOf(p);
    if (!p.seg.empty()) smallest = std::min(smallest, p.reach);
  }
  sort_margin_ = smallest < 1e300 ? kMarginFraction * smallest : 0.0;
  for (auto& p : passes_) sortBuckets(p);
  x_sorted_ = x_;
}

double Contact::reachOf(const Pass& p) const {
  double radius = 0.0;
  for (const auto& seg : p.seg) {
    Vec3 c{};
    for (int32_t a : seg) c = add(c, at(x_, std::size_t(a)));
    c = scale(c, 0.25);
    for (int32_t a : seg) radius = std::max(radius, norm(sub(at(x_, std::size_t(a)), c)));
  }
  return radius + p.reach_extra;
}

void Contact::sortBuckets(Pass& p) {
  const std::size_t ns = p.seg.size();
  std::vector<Vec3> centre(ns);
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (std::size_t s = 0; s < ns; ++s) {
    Vec3 c{};
    for (int32_t a : p.seg[s]) c = add(c, at(x_, std::size_t(a)));
    c = scale(c, 0.25);
    centre[s] = c;
    for (int i = 0; i < 3; ++i) {
      lo[std::size_t(i)] = std::min(lo[std::size_t(i)], c[std::size_t(i)]);
      hi[std::size_t(i)] = std::max(hi[std::size_t(i)], c[std::size_t(i)]);
    }
  }
  // Cell size: a node meets segments whose centroid is within the reach, and may close by the
  // margin before the next sort.
  double cell = p.reach + sort_margin_;
  // Keep the grid at most a few cells per segment (a long thin surface would otherwise make
  // most cells empty).
  for (;;) {
    std::size_t cells = 1;
    for (int i = 0; i < 3; ++i)
      cells *= std::size_t((hi[std::size_t(i)] - lo[std::size_t(i)]) / cell) + 1;
    if (cells <= 4 * ns + 64) break;
    cell *= 1.5;
  }
  p.cell = cell;
  p.lo = lo;
  for (int i = 0; i < 3; ++i)
    p.dims[std::size_t(i)] = int32_t((hi[std::size_t(i)] - lo[std::size_t(i)]) / cell) + 1;
  const std::size_t ncell =
      std::size_t(p.dims[0]) * std::size_t(p.dims[1]) * std::size_t(p.dims[2]);
  p.cell_ptr.assign(ncell + 1, 0);
  std::vector<int32_t> cell_of(ns);
  for (std::size_t s = 0; s < ns; ++s) {
    std::size_t id = 0;
    for (int i = 2; i >= 0; --i) {
      const auto k = std::clamp(int32_t((centre[s][std::size_t(i)] - lo[std::size_t(i)]) / cell), 0,
                                p.dims[std::size_t(i)] - 1);
      id = id * std::size_t(p.dims[std::size_t(i)]) + std::size_t(k);
    }
    cell_of[s] = int32_t(id);
    ++p.cell_ptr[id + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) p.cell_ptr[c + 1] += p.cell_ptr[c];
  p.cell_seg.assign(ns, 0);
  std::vector<int32_t> fill(p.cell_ptr.begin(), p.cell_ptr.end() - 1);
  for (std::size_t s = 0; s < ns; ++s)
    p.cell_seg[std::size_t(fill[std::size_t(cell_of[s])]++)] = int32_t(s);
}

Vec3 Contact::segmentNormal(const std::array<int32_t, 4>& s) const {
  const Vec3 c = cross(sub(at(x_, std::size_t(s[2])), at(x_, std::size_t(s[0]))),
                       sub(at(x_, std::size_t(s[3])), at(x_, std::size_t(s[1]))));
  const double len = norm(c);
  return len > 0.0 ? scale(c, 1.0 / len) : Vec3{};
}

void Contact::collectCandidates(const Pass& p, int32_t check, double margin,
                                std::vector<int32_t>& out) const {
  // The segments in the node's bucket and the 26 around it whose widened box, grown by what
  // node and segment may still travel before the next sort, holds the node.
  const int32_t node = p.node[std::size_t(check - p.first_check)];
  const Vec3 x = at(x_, std::size_t(node));
  std::array<int32_t, 3> k{};
  for (int i = 0; i < 3; ++i) {
    const double r = (x[std::size_t(i)] - p.lo[std::size_t(i)]) / p.cell;
    if (r < -1.0 || r >= double(p.dims[std::size_t(i)]) + 1.0) return;
    k[std::size_t(i)] = int32_t(std::floor(r));
  }
  const int32_t* near_begin =
      p.self ? &p.near_node[std::size_t(p.near_ptr[std::size_t(node)])] : nullptr;
  const int32_t* near_end =
      p.self ? &p.near_node[std::size_t(p.near_ptr[std::size_t(node) + 1])] : nullptr;
  for (int32_t cz = std::max(k[2] - 1, 0); cz <= std::min(k[2] + 1, p.dims[2] - 1); ++cz)
    for (int32_t cy = std::max(k[1] - 1, 0); cy <= std::min(k[1] + 1, p.dims[1] - 1); ++cy)
      for (int32_t cx = std::max(k[0] - 1, 0); cx <= std::min(k[0] + 1, p.dims[0] - 1); ++cx) {
        const std::size_t c =
            (std::size_t(cz) * std::size_t(p.dims[1]) + std::size_t(cy)) * std::size_t(p.dims[0]) +
            std::size_t(cx);
        for (int32_t q = p.cell_ptr[c]; q < p.cell_ptr[c + 1]; ++q) {
          const auto s = std::size_t(p.cell_seg[std::size_t(q)]);
          const double* box = &p.box[6 * s];
          if (x[0] < box[0] - margin || x[0] > box[3] + margin || x[1] < box[1] - margin ||
              x[1] > box[4] + margin || x[2] < box[2] - margin || x[2] > box[5] + margin)
            continue;
          // A node is never in contact with its own segments, nor (single surface) with the
          // segments next to them.
          bool skip = false;
          for (int32_t a : p.seg[s]) {
            if (a == node) skip = true;
            if (near_begin && std::binary_search(near_begin, near_end, a)) skip = true;
          }
          if (!skip) out.push_back(int32_t(s));
        }
      }
}

void Contact::buildCandidateLists() {
  // Valid until the next sort: node and segment then have closed by at most sort_margin_.
  cand_ptr_.assign(1, 0);
  cand_seg_.clear();
  active_.clear();
  for (std::size_t i = 0; i < my_checks_.size(); ++i) {
    const int32_t check = my_checks_[i];
    const Pass& p = passes_[std::size_t(check_pass_[std::size_t(check)])];
    if (!p.tied) collectCandidates(p, check, 1.1 * sort_margin_, cand_seg_);
    cand_ptr_.push_back(int32_t(cand_seg_.size()));
    // Only checks that can meet something before the next sort are visited each cycle.
    if (cand_ptr_[i + 1] > cand_ptr_[i] || (p.tied && tie_seg_[std::size_t(check)] >= 0))
      active_.push_back(int32_t(i));
  }
  // The segments whose boxes this rank needs until the next sort.
  for (auto& p : passes_) p.needed.clear();
  for (std::size_t i = 0; i < my_checks_.size(); ++i) {
    Pass& p = passes_[std::size_t(check_pass_[std::size_t(my_checks_[i])])];
    p.needed.insert(p.needed.end(), cand_seg_.begin() + cand_ptr_[i],
                    cand_seg_.begin() + cand_ptr_[i + 1]);
  }
  for (auto& p : passes_) {
    std::sort(p.needed.begin(), p.needed.end());
    p.needed.erase(std::unique(p.needed.begin(), p.needed.end()), p.needed.end());
  }
}

bool Contact::search(const Pass& p, int32_t check, const int32_t* candidates, std::size_t count,
                     Candidate& best, int64_t& tests, bool initial) const {
  const int32_t local = check - p.first_check;
  const int32_t node = p.node[std::size_t(local)];
  const Vec3 x = at(x_, std::size_t(node));
  const double h_node = p.node_half[std::size_t(local)];
  const int32_t last_seg = last_seg_[std::size_t(check)];
  bool found = false;
  for (std::size_t q = 0; q < count; ++q) {
    const auto s = std::size_t(candidates[q]);
    const double* box = &p.box[6 * s];
    if (x[0] < box[0] || x[0] > box[3] || x[1] < box[1] || x[1] > box[4] || x[2] < box[2] ||
        x[2] > box[5])
      continue;
    const auto& sn = p.seg[s];
    const double h = h_node + p.seg_half[s];
    ++tests;
    const Projection pr = project(x, at(x_, std::size_t(sn[0])), at(x_, std::size_t(sn[1])),
                                  at(x_, std::size_t(sn[2])), at(x_, std::size_t(sn[3])),
                                  sn[2] == sn[3], kInsideTolerance);
    const bool shell = p.seg_half[s] > 0.0;
    if (!pr.inside && !shell) continue;
    Candidate cand;
    cand.seg = int32_t(s);
    cand.proj = pr;
    // Tracked: the segment of the last cycle, or a neighbour of it (sharing a node) that
    // continues the same surface (normals within 45 degrees), onto which the node slid.
    // Which segment a node is in contact with must not jump (a jump to a deeper penetration
    // makes energy): tracked segments first (rank 0), then a segment the node came to in the
    // last step (rank 1), then the nearest way out, the least penetration; ties to the lower
    // segment.
    bool tracked = int32_t(s) == last_seg;
    if (!tracked && last_seg >= 0) {
      bool shares = false;
      for (int32_t a : p.seg[std::size_t(last_seg)])
        for (int32_t b : sn) shares = shares || a == b;
      if (shares) {
        const Vec3 n_last = segmentNormal(p.seg[std::size_t(last_seg)]);
        tracked = dot(n_last, pr.normal) > 0.7071;
      }
    }
    auto previous = [&] {
      return project(at(x_prev_, std::size_t(node)), at(x_prev_, std::size_t(sn[0])),
                     at(x_prev_, std::size_t(sn[1])), at(x_prev_, std::size_t(sn[2])),
                     at(x_prev_, std::size_t(sn[3])), sn[2] == sn[3], kInsideTolerance);
    };
    if (shell && !pr.inside) {
      // Beyond the segment's edge (a free edge, or the outside of a fold) the contact surface
      // is rounded: the node keeps its distance h from the nearest point of the segment, so
      // nodes cannot slip past edges and ridges into the contact thickness of the next one.
      const Vec3 r = sub(x, pr.point);
      const double dist = norm(r);
      if (!(dist < h) || !(dist > 0.0)) continue;
      cand.gap = dist - h;
      cand.push = scale(r, 1.0 / dist);
      cand.side = dot(r, pr.normal) >= 0.0 ? 1 : -1;
      cand.rank = tracked ? 0 : 1;
      if (!tracked && !initial) {
        const Projection prev = previous();
        cand.entry = std::max(0.0, h - norm(sub(at(x_prev_, std::size_t(node)), prev.point)));
      }
    } else if (shell) {
      // A shell: both sides are surfaces, offset by half the thicknesses. The side is the one
      // the node is in contact on (tracked) or came from: a node pressed past the mid-surface
      // is still pushed back where it came from, never through.
      int side =
          tracked && last_side_[std::size_t(check)] != 0 ? last_side_[std::size_t(check)] : 0;
      double d_prev = pr.d;
      if (side == 0) {
        d_prev = initial ? pr.d : previous().d;
        side = (d_prev != 0.0 ? d_prev : pr.d) >= 0.0 ? 1 : -1;
      }
      const double ds = side * pr.d;
      if (ds < -h) continue;  // through the whole contact thickness: not this sheet's node
      cand.gap = ds - h;
      cand.side = side;
      cand.push = scale(pr.normal, double(side));
      cand.rank = tracked ? 0 : 1;
      // A node that comes over the segment sideways (past a free edge, round a fold) is
      // already inside the contact thickness when first found: that depth is its entry
      // offset, so the force starts from zero rather than with a jump (which makes energy).
      if (!tracked && !initial) cand.entry = std::max(0.0, h - side * d_prev);
    } else {
      // A solid face: one side, the outward normal; a node deeper than half the
      // element under the face is on the far side of something else.
      cand.gap = pr.d - h_node;
      cand.push = pr.normal;
      cand.side = 1;
      if (!(cand.gap > -0.5 * p.seg_depth[s])) continue;
      if (tracked) {
        cand.rank = 0;
      } else {
        // A node already inside a solid that did not come in through this face (nor slide
        // onto it from the face it was on) is not in contact with it: it is a node near an
        // edge, below the plane of the side face. Only the initial check takes such nodes
        // (x(n-1) is x(n) there).
        cand.rank = initial || previous().d - h_node >= 0.0 ? 1 : 2;
        if (cand.rank == 2 && !initial) continue;
      }
    }
    if (!(cand.gap < 0.0)) continue;
    if (!found || cand.rank < best.rank ||
        (cand.rank == best.rank &&
         (cand.gap > best.gap || (cand.gap == best.gap && cand.seg < best.seg)))) {
      best = cand;
      found = true;
    }
  }
  return found;
}

void Contact::partitionChecks(const std::vector<double>& weight) {
  // Recursive coordinate bisection of the check nodes (Berger & Bokhari 1987), cutting the
  // longest extent at the weighted median; every rank computes the same cut.
  const int P = comm_.size();
  std::vector<int32_t> ids(static_cast<std::size_t>(num_checks_));
  std::iota(ids.begin(), ids.end(), 0);
  std::vector<int32_t> owner(static_cast<std::size_t>(num_checks_), 0);
  auto nodeOf = [&](int32_t c) {
    const Pass& p = passes_[std::size_t(check_pass_[std::size_t(c)])];
    return std::size_t(p.node[std::size_t(c - p.first_check)]);
  };
  struct Range {
    std::size_t begin, end;
    int first, parts;
  };
  std::vector<Range> stack{{0, ids.size(), 0, P}};
  while (!stack.empty()) {
    const Range r = stack.back();
    stack.pop_back();
    if (r.parts == 1 || r.end - r.begin <= 1) {
      for (std::size_t i = r.begin; i < r.end; ++i) owner[std::size_t(ids[i])] = r.first;
      continue;
    }
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (std::size_t i = r.begin; i < r.end; ++i) {
      const Vec3 x = at(x_, nodeOf(ids[i]));
      for (int d = 0; d < 3; ++d) {
        lo[std::size_t(d)] = std::min(lo[std::size_t(d)], x[std::size_t(d)]);
        hi[std::size_t(d)] = std::max(hi[std::size_t(d)], x[std::size_t(d)]);
      }
    }
    int axis = 0;
    for (int d = 1; d < 3; ++d)
      if (hi[std::size_t(d)] - lo[std::size_t(d)] > hi[std::size_t(axis)] - lo[std::size_t(axis)])
        axis = d;
    std::sort(ids.begin() + std::ptrdiff_t(r.begin), ids.begin() + std::ptrdiff_t(r.end),
              [&](int32_t a, int32_t b) {
                const double xa = x_[3 * nodeOf(a) + std::size_t(axis)];
                const double xb = x_[3 * nodeOf(b) + std::size_t(axis)];
                return xa < xb || (xa == xb && a < b);
              });
    const int left = r.parts / 2;
    double total = 0.0;
    for (std::size_t i = r.begin; i < r.end; ++i) total += weight[std::size_t(ids[i])];
    const double target = total * double(left) / double(r.parts);
    std::size_t cut = r.begin;
    double acc = 0.0;
    while (cut < r.end && acc + 0.5 * weight[std::size_t(ids[cut])] < target)
      acc += weight[std::size_t(ids[cut++])];
    stack.push_back({r.begin, cut, r.first, left});
    stack.push_back({cut, r.end, r.first + left, r.parts - left});
  }
  my_checks_.clear();
  for (int32_t c = 0; c < num_checks_; ++c)
    if (owner[std::size_t(c)] == comm_.rank()) my_checks_.push_back(c);
}

void Contact::maybeRebalance() {
  if (!comm_.distributed()) return;
  // The tests each rank did since the last look: re-cut with the measured costs when the
  // busiest rank is over the threshold.
  const auto loads = comm_.allGather(std::vector<double>{double(tests_since_balance_)});
  tests_since_balance_ = 0;
  double mx = 0.0, sum = 0.0;
  for (double l : loads) {
    mx = std::max(mx, l);
    sum += l;
  }
  const double mean = sum / double(loads.size());
  if (!(mean > 0.0) || mx <= model_.contact_controls.rebalance_threshold * mean) {
    std::fill(check_cost_.begin(), check_cost_.end(), 0.0);
    return;
  }
  std::vector<double> mine;
  for (int32_t c : my_checks_) {
    mine.push_back(double(c));
    mine.push_back(check_cost_[std::size_t(c)]);
  }
  const auto all = comm_.allGather(mine);
  std::vector<double> weight(std::size_t(num_checks_), 1.0);
  for (std::size_t k = 0; k + 2 <= all.size(); k += 2) weight[std::size_t(all[k])] += all[k + 1];
  partitionChecks(weight);
  std::fill(check_cost_.begin(), check_cost_.end(), 0.0);
  ++stats_.rebalances;
}

void Contact::recordOwnedPositions() {
  for (std::size_t i = 0; i < cn_model_.size(); ++i)
    if (cn_owned_[i])
      for (int c = 0; c < 3; ++c)
        x_owned_prev_[3 * i + std::size_t(c)] =
            sd_.x[3 * std::size_t(cn_local_[i]) + std::size_t(c)];
}

void Contact::moveNode(std::size_t node, const Vec3& dx) {
  // x and x0 together: a node moved before the first cycle is not strained.
  const int32_t l = cn_local_[node];
  for (int c = 0; c < 3; ++c) {
    x_[3 * node + std::size_t(c)] += dx[std::size_t(c)];
    if (l >= 0) {
      sd_.x[3 * std::size_t(l) + std::size_t(c)] += dx[std::size_t(c)];
      sd_.x0[3 * std::size_t(l) + std::size_t(c)] += dx[std::size_t(c)];
    }
  }
}

void Contact::tieNodes(const Pass& p, bool keep_offset) {
  // Each node is tied to the nearest point of the segment it lies on (within a tolerance of
  // the segment's size, as DYNA3D's tied slide surfaces), for the whole run; without _OFFSET
  // it is first moved onto that point. Every rank does the same, in check order.
  for (std::size_t k = 0; k < p.node.size(); ++k) {
    const auto check = std::size_t(p.first_check) + k;
    const auto node = std::size_t(p.node[k]);
    const Vec3 x = at(x_, node);
    int32_t best = -1;
    Projection best_pr;
    double best_dist = 1e300;
    std::vector<int32_t> candidates;
    collectCandidates(p, int32_t(check), 0.0, candidates);
    std::sort(candidates.begin(), candidates.end());
    for (int32_t s : candidates) {
      const auto& sn = p.seg[std::size_t(s)];
      const Projection pr =
          project(x, at(x_, std::size_t(sn[0])), at(x_, std::size_t(sn[1])),
                  at(x_, std::size_t(sn[2])), at(x_, std::size_t(sn[3])), sn[2] == sn[3], 0.05);
      if (!pr.inside) continue;
      const double dist = norm(sub(x, pr.point));
      const double size =
          std::sqrt(0.5 * norm(cross(sub(at(x_, std::size_t(sn[2])), at(x_, std::size_t(sn[0]))),
                                     sub(at(x_, std::size_t(sn[3])), at(x_, std::size_t(sn[1]))))));
      const double tolerance = std::max(0.05 * size, 2.0 * p.seg_half[std::size_t(s)]);
      if (dist <= tolerance && dist < best_dist) {
        best = s;
        best_pr = pr;
        best_dist = dist;
      }
    }
    if (best < 0) continue;
    ++stats_.tied_nodes;
    tie_seg_[check] = best;
    for (int a = 0; a < 4; ++a) tie_weight_[4 * check + std::size_t(a)] = best_pr.N[std::size_t(a)];
    if (keep_offset) {
      tie_offset_[check] = best_pr.d;
      continue;
    }
    const Vec3 dx = sub(best_pr.point, x);
    moveNode(node, dx);
  }
}

void Contact::initialize(double dt0) {
  if (empty()) return;
  dt0_ = dt0;
  // Nodal masses (with mass scaling) for the soft stiffness and the damping.
  {
    std::vector<double> mine;
    for (std::size_t i = 0; i < cn_model_.size(); ++i)
      if (cn_owned_[i]) {
        mine.push_back(double(i));
        mine.push_back(sd_.mass[std::size_t(cn_local_[i])]);
      }
    const auto all = comm_.allGather(mine);
    for (std::size_t k = 0; k + 2 <= all.size(); k += 2) mass_[std::size_t(all[k])] = all[k + 1];
  }
  recordOwnedPositions();
  x_prev_.assign(x_.size(), 0.0);
  gatherNodes();
  x_prev_ = x_;
  sortAll();
  need_sort_ = false;
  partitionChecks(std::vector<double>(std::size_t(num_checks_), 1.0));

  // Initial penetrations, found by every rank over every check (once), in check order.
  const int ignore = model_.contact_controls.ignore;
  int64_t tests = 0;
  for (auto& p : passes_) updateBoxes(p, false);
  std::vector<int32_t> candidates;
  for (const auto& p : passes_) {
    const auto& ci = model_.contacts[std::size_t(p.iface)];
    if (p.tied) {
      tieNodes(p, ci.offset);
      continue;
    }
    for (std::size_t k = 0; k < p.node.size(); ++k) {
      Candidate best;
      const auto check = p.first_check + int32_t(k);
      candidates.clear();
      collectCandidates(p, check, 0.0, candidates);
      if (!search(p, check, candidates.data(), candidates.size(), best, tests, true)) continue;
      const auto node = std::size_t(p.node[k]);
      // Nodes that touch to round-off are not penetrations (a block resting on a plate).
      const double ref = p.seg_half[std::size_t(best.seg)] > 0.0
                             ? p.seg_half[std::size_t(best.seg)]
                             : p.seg_depth[std::size_t(best.seg)];
      if (-best.gap <= 1e-9 * ref) continue;
      initial_.push_back({ci.id,
                          model_.nodes.size() ? model_.nodes.id[std::size_t(cn_model_[node])] : 0,
                          -best.gap});
      if (ignore != 0) {
        initial_gap_[std::size_t(check)] = -best.gap;
        continue;
      }
      // DYNA3D moves the node back onto the surface (and says so).
      const Vec3 dx = scale(best.push, -best.gap);
      moveNode(node, dx);
      moved_initial_ = true;
    }
  }
  x_sorted_ = x_;
  x_prev_ = x_;
  recordOwnedPositions();
  for (auto& p : passes_) updateBoxes(p, false);
  buildCandidateLists();
  buildRoutes();
}

void Contact::tiedForce(const Pass& p, int32_t check, double dt_prev,
                        std::vector<double>& records) const {
  // A penalty spring from the node to its tied point x_c + d0 n of the segment (the point
  // moves and turns with the segment), with VDC damping of the relative velocity.
  const auto c = std::size_t(check);
  const auto s = std::size_t(tie_seg_[c]);
  const auto& sn = p.seg[s];
  const auto node = std::size_t(p.node[c - std::size_t(p.first_check)]);
  const double* N = &tie_weight_[4 * c];
  Vec3 xc{}, vc{};
  double m_seg = 0.0;
  for (int a = 0; a < 4; ++a) {
    if (a == 3 && sn[3] == sn[2]) break;
    xc = add(xc, scale(at(x_, std::size_t(sn[std::size_t(a)])), N[a]));
    vc = add(vc, scale(at(v_, std::size_t(sn[std::size_t(a)])), N[a]));
    m_seg += N[a] * mass_[std::size_t(sn[std::size_t(a)])];
  }
  if (tie_offset_[c] != 0.0) xc = add(xc, scale(segmentNormal(sn), tie_offset_[c]));
  const Vec3 g = sub(xc, at(x_, node));
  const double m_node = mass_[node];
  const double m_eff = m_node + m_seg > 0.0 ? m_node * m_seg / (m_node + m_seg) : 0.0;
  // A tie should be as stiff as the elements it joins: the penalty without SLSFAC, within the
  // same stability bound as every contact spring.
  double k = p.seg_k[s] / model_.contact_controls.slsfac;
  if (dt_prev > 0.0 && m_eff > 0.0) k = std::min(k, kStableFraction * m_eff / (dt_prev * dt_prev));
  Vec3 f = scale(g, k);
  double dissipated = 0.0;
  const auto& ci = model_.contacts[std::size_t(p.iface)];
  if (ci.vdc > 0.0) {
    const Vec3 dv = sub(vc, at(v_, node));
    const double c_damp = 0.01 * ci.vdc * 2.0 * std::sqrt(k * m_eff);
    f = add(f, scale(dv, c_damp));
    dissipated = c_damp * dot(dv, dv) * dt_prev;
  }
  const double gap = norm(g);
  records.insert(records.end(), {double(check), double(s), N[0], N[1], N[2], N[3], f[0], f[1], f[2],
                                 0.0, 0.0, 0.0, gap, 0.5 * k * gap * gap, dissipated, 0.0, 0.0});
}

void Contact::computeForces(double time, double dt_prev) {
  if (empty()) return;
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  // The needed entries of x_ become x(n-1) (they were read last cycle), then x(n).
  std::swap(x_prev_, x_);
  gatherNeeded();
  const auto t1 = Clock::now();
  // Re-sort when some node may have travelled half the margin since the last sort: a node
  // and a segment closing at that speed stay within the 27 buckets searched. Each rank looks
  // at the nodes it owns; the maximum is exact, so every rank decides alike.
  double travel = 0.0;
  for (std::size_t i = 0; i < cn_model_.size(); ++i) {
    if (!cn_owned_[i]) continue;
    const auto l = std::size_t(cn_local_[i]);
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double d = sd_.x[3 * l + std::size_t(c)] - x_sorted_[3 * i + std::size_t(c)];
      d2 += d * d;
    }
    travel = std::max(travel, d2);
  }
  if (comm_.distributed()) travel = -comm_.minAll(-travel);
  ++cycles_since_sort_;
  bool resorted = false;
  if (2.0 * std::sqrt(travel) > sort_margin_ || need_sort_ ||
      (max_sort_interval_ > 0 && cycles_since_sort_ >= max_sort_interval_)) {
    cycles_since_sort_ = 0;
    resorted = true;
    // Every node, from its owner (with its position of the last pass, for the crossing rule);
    // serially too: serial is one rank.
    gatherNodes();
    maybeRebalance();
    sortAll();
    ++stats_.sorts;
  }
  // The owners' positions of this pass, sent with the next full gather.
  recordOwnedPositions();
  for (auto& p : passes_) updateBoxes(p, !resorted);
  if (resorted) {
    buildCandidateLists();
    buildRoutes();
  }

  std::vector<double> mine;
  int64_t tests = 0;
  const auto t2 = Clock::now();
  for (const int32_t active : active_) {
    const auto i = std::size_t(active);
    const int32_t check = my_checks_[i];
    const Pass& p = passes_[std::size_t(check_pass_[std::size_t(check)])];
    const auto& ci = model_.contacts[std::size_t(p.iface)];
    if (time < ci.birth || time > ci.death) continue;
    Candidate best;
    if (p.tied) {
      if (tie_seg_[std::size_t(check)] < 0) continue;
      tiedForce(p, check, dt_prev, mine);
      continue;
    }
    const int64_t before = tests;
    const auto first = std::size_t(cand_ptr_[i]);
    const bool hit = search(p, check, cand_seg_.data() + first,
                            std::size_t(cand_ptr_[i + 1]) - first, best, tests, false);
    check_cost_[std::size_t(check)] += double(tests - before);
    if (!hit) continue;
    // Tracked contacts keep the entry offset they began with.
    if (best.rank == 0) best.entry = entry_[std::size_t(check)];
    const double pen = -best.gap - initial_gap_[std::size_t(check)] - best.entry;
    if (!(pen > 0.0)) continue;
    const auto node = std::size_t(p.node[std::size_t(check - p.first_check)]);
    const auto& sn = p.seg[std::size_t(best.seg)];
    const auto& N = best.proj.N;
    // Relative velocity of the node to the contact point of the segment.
    Vec3 vrel = at(v_, node);
    double m_seg = 0.0;
    for (int a = 0; a < 4; ++a) {
      if (N[std::size_t(a)] == 0.0) continue;
      vrel = sub(vrel, scale(at(v_, std::size_t(sn[std::size_t(a)])), N[std::size_t(a)]));
      m_seg += N[std::size_t(a)] * mass_[std::size_t(sn[std::size_t(a)])];
    }
    const double m_node = mass_[node];
    const double m_eff = m_node + m_seg > 0.0 ? m_node * m_seg / (m_node + m_seg) : 0.0;
    double k = p.seg_k[std::size_t(best.seg)];
    // SOFT = 1: a stiffness from the masses and the step, so soft foam against steel still
    // stops (LS-DYNA Theory Manual, "soft constraint penalty": 0.5 SOFSCL m / dt^2).
    if (ci.soft == 1 && dt0_ > 0.0) k = std::max(k, 0.5 * ci.sofscl * m_eff / (dt0_ * dt0_));
    // Stability: the contact spring adds k / m_eff to the square of the highest frequency of
    // the nodes it joins, which the element step (TSSFAC 0.9) leaves little room for; a node
    // of a symmetric interface may carry several springs. Capping k at kStableFraction
    // m_eff / dt^2 keeps omega dt of one spring at or below 2 sqrt(kStableFraction).
    if (dt_prev > 0.0 && m_eff > 0.0)
      k = std::min(k, kStableFraction * m_eff / (dt_prev * dt_prev));
    const Vec3& n = best.push;
    const double vn = dot(vrel, n);
    double fn = k * pen;
    // Viscous damping, VDC percent of critical for the node-segment pair.
    if (ci.vdc > 0.0) fn -= 0.01 * ci.vdc * 2.0 * std::sqrt(k * m_eff) * vn;
    fn = std::max(fn, 0.0);
    // Energy dissipated by the damping part of fn over the last step (v(n-1/2) dt(n-1/2)).
    double dissipated = -(fn - k * pen) * vn * dt_prev;
    Vec3 ft{};
    if (ci.fs > 0.0 || ci.fd > 0.0) {
      // Coulomb friction with an elastic stick (LS-DYNA Theory Manual, "Friction"): the
      // tangential force grows by k times the slip increment and is capped at mu fn.
      const Vec3 vt = sub(vrel, scale(n, vn));
      const double mu = ci.fd + (ci.fs - ci.fd) * std::exp(-ci.dc * norm(vt));
      Vec3 old = at(friction_, std::size_t(check));
      old = sub(old, scale(n, dot(old, n)));
      ft = sub(old, scale(vt, k * dt_prev));
      const double cap = mu * fn;
      const double mag = norm(ft);
      if (mag > cap) ft = mag > 0.0 ? scale(ft, cap / mag) : Vec3{};
    }
    const Vec3 f = add(scale(n, fn), ft);
    dissipated -= dot(ft, sub(vrel, scale(n, vn))) * dt_prev;
    mine.insert(mine.end(), {double(check), double(best.seg), N[0], N[1], N[2], N[3], f[0], f[1],
                             f[2], ft[0], ft[1], ft[2], pen, 0.5 * k * pen * pen, dissipated,
                             double(best.side), best.entry});
  }
  stats_.tests += tests;
  tests_since_balance_ += tests;

  const auto t3 = Clock::now();
  records_ = comm_.distributed() ? comm_.allGather(mine) : std::move(mine);
  const auto t4 = Clock::now();
  // Canonical order: by check index (each check is computed by one rank).
  const std::size_t nrec = records_.size() / kRecord;
  std::vector<std::size_t> order(nrec);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return records_[kRecord * a] < records_[kRecord * b];
  });
  std::vector<double> sorted(records_.size());
  for (std::size_t r = 0; r < nrec; ++r)
    std::copy_n(&records_[kRecord * order[r]], kRecord, &sorted[kRecord * r]);
  records_ = std::move(sorted);

  // The history of the checks in contact last cycle is cleared (not of every check: this is
  // the cycle's hot path, and most checks are never in contact), then set from the records.
  for (const int32_t c : in_contact_) {
    const auto check = std::size_t(c);
    for (int k = 0; k < 3; ++k) friction_[3 * check + std::size_t(k)] = 0.0;
    last_seg_[check] = -1;
    last_side_[check] = 0;
    entry_[check] = 0.0;
  }
  in_contact_.clear();
  std::fill(stored_.begin(), stored_.end(), 0.0);
  for (std::size_t r = 0; r < nrec; ++r) {
    const double* rec = &records_[kRecord * r];
    const auto check = std::size_t(rec[0]);
    const Pass& p = passes_[std::size_t(check_pass_[check])];
    const auto node = std::size_t(p.node[check - std::size_t(p.first_check)]);
    const auto& sn = p.seg[std::size_t(rec[1])];
    for (int c = 0; c < 3; ++c) friction_[3 * check + std::size_t(c)] = rec[9 + c];
    last_seg_[check] = int32_t(rec[1]);
    in_contact_.push_back(int32_t(check));
    last_side_[check] = int8_t(rec[15]);
    entry_[check] = rec[16];
    stored_[std::size_t(p.iface)] += rec[13];
    dissipated_[std::size_t(p.iface)] += rec[14];
    // The node takes f, the segment's nodes -N_a f, each added on every rank holding it.
    if (cn_local_[node] >= 0)
      for (int c = 0; c < 3; ++c)
        sd_.f[3 * std::size_t(cn_local_[node]) + std::size_t(c)] += rec[6 + c];
    for (int a = 0; a < 4; ++a) {
      if (a == 3 && sn[3] == sn[2]) break;
      const int32_t l = cn_local_[std::size_t(sn[std::size_t(a)])];
      if (l < 0) continue;
      for (int c = 0; c < 3; ++c)
        sd_.f[3 * std::size_t(l) + std::size_t(c)] -= rec[2 + a] * rec[6 + c];
    }
    // Geometric penetration (with the entry and initial offsets) relative to the contact thickness
    // (shells) or the element depth (solids).
    const auto seg = std::size_t(rec[1]);
    const double h = p.seg_half[seg] + p.node_half[check - std::size_t(p.first_check)];
    const double ref = h > 0.0 ? 2.0 * h : p.seg_depth[seg];
    if (ref > 0.0)
      stats_.max_penetration_ratio =
          std::max(stats_.max_penetration_ratio, (rec[12] + rec[16] + initial_gap_[check]) / ref);
  }
  const auto t5 = Clock::now();
  auto sec = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  // The split the 32-rank model of docs/parallel.md needs: the checks divide among ranks, the
  // rest is done by every rank, the two gathers grow with the surface.
  stats_.search_s += sec(t2, t3);
  stats_.exchange_s += sec(t0, t1) + sec(t3, t4);
  stats_.replicated_s += sec(t1, t2) + sec(t4, t5);
  stats_.records += int64_t(records_.size() / kRecord);
  ++stats_.cycles;
}

double Contact::energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < stored_.size(); ++i) e += stored_[i] + dissipated_[i];
  return e;
}

std::vector<InterfaceForces> Contact::interfaceForces() const {
  std::vector<InterfaceForces> out(model_.contacts.size());
  if (empty()) return out;
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].id = model_.contacts[i].id;
    out[i].energy = stored_[i] + dissipated_[i];
  }
  const std::size_t nrec = records_.size() / kRecord;
  for (std::size_t r = 0; r < nrec; ++r) {
    const double* rec = &records_[kRecord * r];
    const auto pass_index = std::size_t(check_pass_[std::size_t(rec[0])]);
    const Pass& p = passes_[pass_index];
    auto& o = out[std::size_t(p.iface)];
    // The second pass of a symmetric interface has the B side's nodes against A's segments.
    const bool reversed = pass_index > 0 && passes_[pass_index - 1].iface == p.iface;
    auto& on_node = reversed ? o.side_b : o.side_a;
    auto& on_seg = reversed ? o.side_a : o.side_b;
    for (int c = 0; c < 3; ++c) {
      on_node[std::size_t(c)] += rec[6 + c];
      on_seg[std::size_t(c)] -= rec[6 + c];
    }
    ++o.pairs;
  }
  return out;
}

std::vector<char> Contact::saveState() const {
  // Positions of the last contact pass of every node, from the owners (collective).
  std::vector<double> x = x_;
  if (comm_.distributed()) {
    std::vector<double> mine;
    for (std::size_t i = 0; i < cn_model_.size(); ++i)
      if (cn_owned_[i]) {
        mine.push_back(double(i));
        for (int c = 0; c < 3; ++c) mine.push_back(x_owned_prev_[3 * i + std::size_t(c)]);
      }
    const auto all = comm_.allGather(mine);
    for (std::size_t k = 0; k + 4 <= all.size(); k += 4)
      for (int c = 0; c < 3; ++c)
        x[3 * std::size_t(all[k]) + std::size_t(c)] = all[k + 1 + std::size_t(c)];
  }
  if (!comm_.isRoot()) return {};
  util::ArchiveWriter w;
  w.put<int64_t>(num_checks_);
  w.put(x);
  const_cast<Contact*>(this)->history([&](const auto& v) { w.put(v); });
  return std::move(w.bytes());
}

void Contact::loadState(const std::vector<char>& bytes) {
  util::ArchiveReader r(bytes);
  int64_t checks = 0;
  r.get(checks);
  if (checks != num_checks_)
    throw util::InputError("restart dump: its contact section has " + std::to_string(checks) +
                           " checks, this deck " + std::to_string(num_checks_));
  std::vector<double> x;
  r.get(x);
  history([&](auto& v) { r.get(v); });
  if (!r.atEnd() || x.size() != x_.size() || x_sorted_.size() != x_.size())
    throw util::InputError("restart dump: the contact section is inconsistent");
  in_contact_.clear();
  for (int32_t c = 0; c < num_checks_; ++c)
    if (last_seg_[std::size_t(c)] >= 0) in_contact_.push_back(c);
  // The buckets, boxes and candidate lists of the last sort, rebuilt from its positions.
  x_ = x_sorted_;
  sortAll();
  partitionChecks(std::vector<double>(std::size_t(num_checks_), 1.0));
  for (auto& p : passes_) updateBoxes(p, false);
  buildCandidateLists();
  buildRoutes();
  x_ = std::move(x);
  for (std::size_t i = 0; i < cn_model_.size(); ++i)
    if (cn_owned_[i])
      for (int c = 0; c < 3; ++c)
        x_owned_prev_[3 * i + std::size_t(c)] = x_[3 * i + std::size_t(c)];
  need_sort_ = false;
}

}  // namespace crumple::contact
