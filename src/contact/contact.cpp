#include "contact/contact.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <tuple>

#include <omp.h>

#include "contact/geometry.hpp"
#include "util/archive.hpp"
#include "util/error.hpp"

namespace crumple::contact {

// A segment a check's node may be in contact with, and how it ranks among the others.
struct Contact::Candidate {
  int32_t seg = -1;
  int rank = 3;        // 0 the segment of the last cycle, 1 crossed in the last step, 2 other
  double entry = 0.0;  // penetration the node already had when the contact began
  Projection proj;
  SurfaceGap surface;
};

Contact::Contact(const model::Model& model, domain::Subdomain& sd, comm::Communicator& comm)
    : model_(model), sd_(sd), comm_(comm), partition_(comm) {
  if (model.contacts.empty()) return;
  // Contact nodes: the union of every side's nodes and segment nodes (a force transducer's
  // are only compared with the others' records).
  for (const auto& ci : model.contacts)
    for (const auto* s : {&ci.a, &ci.b}) {
      if (ci.kind == model::ContactKind::Transducer) break;
      cn_model_.insert(cn_model_.end(), s->nodes.begin(), s->nodes.end());
      for (const auto& seg : s->segments) cn_model_.insert(cn_model_.end(), seg.begin(), seg.end());
      for (const auto& e : s->edges) cn_model_.insert(cn_model_.end(), e.begin(), e.end());
    }
  std::sort(cn_model_.begin(), cn_model_.end());
  cn_model_.erase(std::unique(cn_model_.begin(), cn_model_.end()), cn_model_.end());
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
  for (std::size_t i = 0; i < model.contacts.size(); ++i) {
    const auto& ci = model.contacts[i];
    const auto iface = int32_t(i);
    if (ci.soft == 2) {
      // Segment-based contact: segment pairs (the model refuses it elsewhere), and beam edges
      // as the node-to-segment interfaces have them.
      const bool self = ci.kind == model::ContactKind::SingleSurface;
      if (!ci.a.segments.empty()) addSegmentPass(iface, ci.a, self ? ci.a : ci.b, self);
      if (self && !ci.a.edges.empty()) addEdgePass(iface, ci.a, ci.sfs);
      continue;
    }
    switch (ci.kind) {
      case model::ContactKind::NodesToSurface:
        addPass(iface, ci.a, ci.b, ci.sfm, false);
        if (ci.tiebreak.on) makeTiebreak(passes_.back(), ci.a);
        break;
      case model::ContactKind::SurfaceToSurface:
        addPass(iface, ci.a, ci.b, ci.sfm, false);
        if (ci.tiebreak.on) makeTiebreak(passes_.back(), ci.a);
        addPass(iface, ci.b, ci.a, ci.sfs, false);
        break;
      case model::ContactKind::SingleSurface:
        // Beam nodes against segments, and beam edges against each other (AUTOMATIC_GENERAL).
        if (!ci.a.segments.empty()) addPass(iface, ci.a, ci.a, ci.sfs, true);
        if (!ci.a.edges.empty()) addEdgePass(iface, ci.a, ci.sfs);
        break;
      case model::ContactKind::Tied:
        addPass(iface, ci.a, ci.b, ci.sfm, false);
        passes_.back().tied = true;
        passes_.back().tie_rotations = ci.tie_rotations;
        rotations_ = rotations_ || (ci.tie_rotations && sd.rotations);
        break;
      case model::ContactKind::Transducer:
        break;
    }
  }
  stats_.checks = num_checks_;
  for (const auto& ci : model.contacts)
    if (ci.bsort > 0)
      max_sort_interval_ =
          max_sort_interval_ > 0 ? std::min(max_sort_interval_, ci.bsort) : ci.bsort;
  friction_.assign(3 * std::size_t(num_checks_), 0.0);
  last_seg_.assign(std::size_t(num_checks_), -1);
  last_side_.assign(std::size_t(num_checks_), 0);
  entry_.assign(std::size_t(num_checks_), 0.0);
  held_.assign(std::size_t(num_checks_), 0.0);
  tie_seg_.assign(std::size_t(num_checks_), -1);
  tie_weight_.assign(std::size_t(num_checks_), {});
  tie_offset_.assign(std::size_t(num_checks_), 0.0);
  tie_moment_.assign(3 * std::size_t(num_checks_), 0.0);
  if (rotations_) {
    w_.assign(3 * ncn, 0.0);
    inertia_.assign(ncn, 0.0);
  }
  stored_.assign(model.contacts.size(), 0.0);
  dissipated_.assign(model.contacts.size(), 0.0);
  erosion_.build(model, passes_, cn_model_, sd);
}

Contact::~Contact() = default;

int32_t Contact::contactNode(int32_t model_node) const {
  return int32_t(std::lower_bound(cn_model_.begin(), cn_model_.end(), model_node) -
                 cn_model_.begin());
}

namespace {

// The segment across each edge of each segment (Pass::seg_nbr): edges sorted by their nodes,
// an edge met exactly twice joins its two segments.
std::vector<std::array<int32_t, 4>> edgeNeighbours(const std::vector<std::array<int32_t, 4>>& seg) {
  struct Edge {
    int32_t a, b, s, k;
  };
  std::vector<Edge> edges;
  for (std::size_t s = 0; s < seg.size(); ++s)
    for (int32_t k = 0; k < 4; ++k) {
      const int32_t a = seg[s][std::size_t(k)], b = seg[s][std::size_t((k + 1) % 4)];
      if (a != b) edges.push_back({std::min(a, b), std::max(a, b), int32_t(s), k});
    }
  std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
    return std::tie(x.a, x.b, x.s, x.k) < std::tie(y.a, y.b, y.s, y.k);
  });
  std::vector<std::array<int32_t, 4>> out(seg.size(), {-1, -1, -1, -1});
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b) ++j;
    if (j - i == 2) {
      const Edge &e = edges[i], &f = edges[i + 1];
      out[std::size_t(e.s)][std::size_t(e.k)] = f.s;
      out[std::size_t(f.s)][std::size_t(f.k)] = e.s;
    }
    i = j;
  }
  return out;
}

// The part of r across the edge direction e (|e|^2 = ee): in the plane of a segment, the
// direction away from its edge.
Vec3 acrossEdge(const Vec3& r, const Vec3& e, double ee) {
  return sub(r, scale(e, dot(r, e) / ee));
}

// Whether the node at x is off the segment's closest point sideways, not along the normal:
// its projection was clamped to an edge or corner (the tolerance band).
bool offEdge(const Vec3& x, const Projection& pr, double h) {
  const Vec3 r = sub(x, pr.point);
  const Vec3 sideways = sub(r, scale(pr.normal, dot(r, pr.normal)));
  return dot(sideways, sideways) > 1e-12 * h * h;
}

// The segments of a side with their corners as indices into its nodes (-1: a corner not
// among them): Pass::own_faces.
std::vector<std::array<int32_t, 4>> ownFaces(const model::ContactSurface& side) {
  std::vector<std::array<int32_t, 4>> out;
  for (const auto& s : side.segments) {
    std::array<int32_t, 4> f{};
    for (std::size_t a = 0; a < 4; ++a) {
      const auto it = std::lower_bound(side.nodes.begin(), side.nodes.end(), s[a]);
      f[a] = it != side.nodes.end() && *it == s[a] ? int32_t(it - side.nodes.begin()) : -1;
    }
    out.push_back(f);
  }
  return out;
}

}  // namespace

void Contact::addPass(int32_t iface, const model::ContactSurface& nodes,
                      const model::ContactSurface& segs, double sf, bool self) {
  Pass p;
  p.iface = iface;
  p.self = self;
  p.first_check = num_checks_;
  const double slsfac = model_.contact_controls.slsfac;
  double max_node_half = 0.0, max_seg_half = 0.0, max_depth = 0.0;
  for (std::size_t k = 0; k < nodes.nodes.size(); ++k) {
    p.node.push_back(contactNode(nodes.nodes[k]));
    p.node_half.push_back(nodes.node_half_thickness[k]);
    max_node_half = std::max(max_node_half, nodes.node_half_thickness[k]);
  }
  for (std::size_t k = 0; k < segs.segments.size(); ++k) {
    const auto& s = segs.segments[k];
    p.seg.push_back({contactNode(s[0]), contactNode(s[1]), contactNode(s[2]), contactNode(s[3])});
    p.seg_half.push_back(0.5 * segs.segment_thickness[k]);
    p.seg_k.push_back(slsfac * sf * segs.segment_stiffness[k]);
    p.seg_depth.push_back(segs.segment_depth[k]);
    max_seg_half = std::max(max_seg_half, 0.5 * segs.segment_thickness[k]);
    max_depth = std::max(max_depth, segs.segment_depth[k]);
  }
  p.reach_extra = max_node_half + max_seg_half + 0.5 * max_depth;
  p.max_node_half = max_node_half;
  p.seg_nbr = edgeNeighbours(p.seg);
  p.seg_elem = segs.segment_element;
  p.seg_across = segs.segment_neighbour;
  if (model_.contacts[std::size_t(iface)].eroding && !nodes.segments.empty()) {
    // The nodes of an eroding surface are checked while they are on its faces in contact.
    p.exposure = true;
    p.own_faces = ownFaces(nodes);
    p.own_elem = nodes.segment_element;
    p.own_across = nodes.segment_neighbour;
  }
  if (self) {
    const std::size_t ncn = cn_model_.size();
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
  registerPass(std::move(p));
}

void Contact::makeTiebreak(Pass& p, const model::ContactSurface& nodes) {
  p.tied = true;
  p.tiebreak = true;
  p.own_faces = ownFaces(nodes);
}

void Contact::bondAreas(Pass& p) {
  // The faces of the bond: those whose corners are all tied, their area shared among the
  // corners (a node set side has none: with failure stresses its nodes hold nothing).
  p.node_area.assign(p.node.size(), 0.0);
  for (const auto& f : p.own_faces) {
    const bool tri = f[2] == f[3];
    const std::size_t n = tri ? 3 : 4;
    bool bonded = true;
    for (std::size_t a = 0; a < n; ++a)
      bonded = bonded && f[a] >= 0 && tie_seg_[std::size_t(p.first_check + f[a])] >= 0;
    if (!bonded) continue;
    auto xa = [&](std::size_t a) { return at(x_, std::size_t(p.node[std::size_t(f[a])])); };
    const Vec3 c = cross(sub(xa(2), xa(0)), sub(xa(3), xa(1)));
    const double share = 0.5 * norm(c) / double(n);
    for (std::size_t a = 0; a < n; ++a) p.node_area[std::size_t(f[a])] += share;
  }
}

void Contact::registerPass(Pass p) {
  num_checks_ += int32_t(p.node.size());
  for (int32_t node : p.node) {
    check_pass_.push_back(int32_t(passes_.size()));
    check_node_.push_back(node);
  }
  passes_.push_back(std::move(p));
}

namespace {
// A contact node as its owner sends it at a sort: its position and velocity, and its position
// at the last contact pass (for the crossing rule). Indices stay integers on the way.
struct OwnedNode {
  int32_t owner = 0;
  int32_t node = 0;  // contact node index
  Vec3 x{}, v{}, x_prev{};
  Vec3 w{};  // angular velocity (rotational ties; else 0)
};
}  // namespace

void Contact::gatherNodes() {
  // All contact nodes, from their owners: at set-up and at every bucket sort.
  std::vector<OwnedNode> mine;
  for (std::size_t i = 0; i < cn_model_.size(); ++i) {
    if (!cn_owned_[i]) continue;
    const auto l = std::size_t(cn_local_[i]);
    mine.push_back({comm_.rank(), int32_t(i), at(sd_.x, l), at(sd_.v, l), at(x_owned_prev_, i),
                    rotations_ ? at(sd_.w, l) : Vec3{}});
  }
  for (const OwnedNode& n : comm_.allGather(mine)) {
    const auto i = std::size_t(n.node);
    owner_[i] = n.owner;
    for (std::size_t c = 0; c < 3; ++c) {
      x_[3 * i + c] = n.x[c];
      v_[3 * i + c] = n.v[c];
      x_prev_[3 * i + c] = n.x_prev[c];
      if (rotations_) w_[3 * i + c] = n.w[c];
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
      if (rotations_) w_[3 * std::size_t(i) + std::size_t(c)] = sd_.w[3 * l + std::size_t(c)];
    }
  }
  // Positions and velocities together (and angular velocities for rotational ties), one
  // message per owner.
  if (rotations_) {
    needed_.begin({sd_.x, sd_.v, sd_.w});
    needed_.end({x_, v_, w_});
    return;
  }
  needed_.begin({sd_.x, sd_.v});
  needed_.end({x_, v_});
}

void Contact::gatherMasses() {
  // Nodal masses (with mass scaling) for the soft stiffness and the damping.
  struct NodeMass {
    int64_t node = 0;  // contact node index (64 bits: no padding travels)
    double mass = 0.0;
    double inertia = 0.0;  // rotary inertia (rotational ties)
  };
  std::vector<NodeMass> mine;
  for (std::size_t i = 0; i < cn_model_.size(); ++i)
    if (cn_owned_[i]) {
      const auto l = std::size_t(cn_local_[i]);
      mine.push_back({int64_t(i), sd_.mass[l], rotations_ ? sd_.inertia[l] : 0.0});
    }
  for (const NodeMass& n : comm_.allGather(mine)) {
    mass_[std::size_t(n.node)] = n.mass;
    if (rotations_) inertia_[std::size_t(n.node)] = n.inertia;
  }
}

void Contact::buildRoutes() {
  // The nodes this rank reads until the next sort.
  std::vector<uint8_t> need(cn_model_.size(), 0);
  const auto& checks = partition_.mine();
  for (const int32_t active : search_.active()) {
    const auto i = std::size_t(active);
    const auto check = std::size_t(checks[i]);
    const Pass& p = passes_[std::size_t(check_pass_[check])];
    need[std::size_t(check_node_[check])] = 1;
    if (p.edges) need[std::size_t(p.node2[check - std::size_t(p.first_check)])] = 1;
    if (p.segpairs)
      for (int32_t a : p.check_seg[check - std::size_t(p.first_check)]) need[std::size_t(a)] = 1;
    for (int32_t s : search_.candidates(i))
      for (int32_t a : p.seg[std::size_t(s)]) need[std::size_t(a)] = 1;
    if (p.tied && tie_seg_[check] >= 0)
      for (int32_t a : p.seg[std::size_t(tie_seg_[check])]) need[std::size_t(a)] = 1;
  }
  needed_local_.clear();
  struct Request {
    int32_t rank = 0;  // the rank that reads the node
    int32_t node = 0;  // contact node index
  };
  std::vector<Request> requests;  // the nodes held elsewhere
  for (std::size_t i = 0; i < need.size(); ++i) {
    if (!need[i]) continue;
    if (cn_local_[i] >= 0)
      needed_local_.push_back(int32_t(i));
    else
      requests.push_back({comm_.rank(), int32_t(i)});
  }
  if (!comm_.distributed()) {
    needed_ = comm::Exchange();
    return;
  }
  // Every rank learns what every other needs (at sorts only): each owner serves its nodes, in
  // ascending node order on both sides, so the messages carry values only.
  std::vector<comm::Exchange::Peer> peers(std::size_t(comm_.size()));
  for (std::size_t r = 0; r < peers.size(); ++r) peers[r].rank = int(r);
  for (const auto& [who, node] : comm_.allGather(requests)) {
    const auto owner = owner_[std::size_t(node)];
    // The owner packs from its own arrays; the reader unpacks into x_ and v_.
    if (owner == comm_.rank()) peers[std::size_t(who)].send.push_back(cn_local_[std::size_t(node)]);
    if (who == comm_.rank()) peers[std::size_t(owner)].recv.push_back(node);
  }
  needed_ = comm::Exchange(comm_, std::move(peers), 3, rotations_ ? 3 : 2);
}

void Contact::sortAll() {
  refreshEdgeReach();
  search_.sort(passes_, x_);
  x_sorted_ = x_;
}

void Contact::buildCandidateLists() {
  search_.buildCandidateLists(passes_, partition_.mine(), check_pass_, tie_seg_, x_);
}

bool Contact::tracks(const Pass& p, int32_t check, std::size_t s, const Projection& pr) const {
  // The segment of the last cycle, or a neighbour of it (sharing a node) that continues the
  // same surface (normals within 45 degrees), onto which the node slid.
  const int32_t last_seg = last_seg_[std::size_t(check)];
  if (int32_t(s) == last_seg) return true;
  if (last_seg < 0) return false;
  const auto& sl = p.seg[std::size_t(last_seg)];
  bool shares = false;
  for (int32_t a : sl)
    for (int32_t b : p.seg[s]) shares = shares || a == b;
  if (!shares) return false;
  const Vec3 n_last = segmentNormal(at(x_, std::size_t(sl[0])), at(x_, std::size_t(sl[1])),
                                    at(x_, std::size_t(sl[2])), at(x_, std::size_t(sl[3])));
  return dot(n_last, pr.normal) > 0.7071;
}

// Inlined into its one caller, the per-candidate loop: called per candidate segment it cost
// 0.3% of the contact step (callgrind, contact_tube, 1 thread).
[[gnu::always_inline]] inline std::optional<Contact::Candidate> Contact::rankSegment(
    const Pass& p, const CheckNode& c, std::size_t s, bool initial) const {
  const std::size_t node = c.node;
  const Vec3& x = c.x;
  const double h_node = c.half;
  const int32_t check = c.check;
  const double h = h_node + p.seg_half[s];
  const auto& sn = p.seg[s];
  // The node projected onto the segment, at x(n) or at x(n-1) (where the node came from).
  auto projectAt = [&](const std::vector<double>& xs) {
    return project(at(xs, node), at(xs, std::size_t(sn[0])), at(xs, std::size_t(sn[1])),
                   at(xs, std::size_t(sn[2])), at(xs, std::size_t(sn[3])), sn[2] == sn[3]);
  };
  const Projection pr = projectAt(x_);
  const bool shell = p.seg_half[s] > 0.0;
  if (!pr.inside && !shell) return std::nullopt;
  const bool tracked = tracks(p, check, s, pr);
  auto previous = [&] { return projectAt(x_prev_); };
  std::optional<Candidate> out(std::in_place);
  Candidate& cand = *out;
  cand.seg = int32_t(s);
  cand.proj = pr;
  if (shell && !pr.inside && !pastExposedEdge(p, s, x)) return std::nullopt;
  // Over the tolerance band past an exposed edge (the projection clamped to the edge) the node
  // takes the rounded edge too, so that its gap is continuous where the band begins: the
  // face's gap, measured from the plane at the clamped point, jumped from the edge's
  // dist - h to the whole thickness for a node in the segment's plane, with k h^2 / 2 - k p^2
  // / 2 of energy from nowhere (two plates meeting edge to edge).
  const bool rounded = shell && (!pr.inside || (offEdge(x, pr, h) && pastExposedEdge(p, s, x)));
  if (rounded) {
    const auto g = shellEdgeGap(x, pr, h);
    if (!g) return std::nullopt;
    cand.surface = *g;
    cand.rank = tracked ? 0 : 1;
    if (!tracked && !initial) {
      const Projection prev = previous();
      cand.entry = std::max(0.0, h - norm(sub(at(x_prev_, node), prev.point)));
    }
  } else if (shell) {
    // The side is the one the node is in contact on (tracked) or came from: a node pressed
    // past the mid-surface is still pushed back where it came from, never through.
    int side = tracked && last_side_[std::size_t(check)] != 0 ? last_side_[std::size_t(check)] : 0;
    double d_prev = pr.d;
    if (side == 0) {
      d_prev = initial ? pr.d : previous().d;
      side = (d_prev != 0.0 ? d_prev : pr.d) >= 0.0 ? 1 : -1;
    }
    const auto g = shellFaceGap(pr, h, side);
    if (!g) return std::nullopt;
    cand.surface = *g;
    cand.rank = tracked ? 0 : 1;
    // A node that comes over the segment sideways (past a free edge, round a fold) is
    // already inside the contact thickness when first found: that depth is its entry
    // offset, so the force starts from zero rather than with a jump (which makes energy).
    if (!tracked && !initial) cand.entry = std::max(0.0, h - side * d_prev);
  } else {
    const auto g = solidFaceGap(pr, h_node, p.seg_depth[s]);
    if (!g) return std::nullopt;
    cand.surface = *g;
    if (tracked) {
      cand.rank = 0;
    } else {
      // A node already inside a solid that did not come in through this face (nor slide
      // onto it from the face it was on) is not in contact with it: it is a node near an
      // edge, below the plane of a side face. Only the initial check takes such nodes
      // (x(n-1) is x(n) there).
      cand.rank = initial || previous().d - h_node >= 0.0 ? 1 : 2;
      if (cand.rank == 2 && !initial) return std::nullopt;
    }
  }
  if (!(cand.surface.gap < 0.0)) return std::nullopt;
  return out;
}

bool Contact::pastExposedEdge(const Pass& p, std::size_t s, const Vec3& x) const {
  // LS-DYNA's automatic contacts wrap the contact surface round the exterior edges of shells
  // (LSTC FAQ "contact.13vs26"): a node past an edge shared with a neighbour that lies towards
  // it is the neighbour's to take, over its face or past its own edges. Rounding every edge
  // made a shell thick against its mesh touch its own sheet in its plane (the bolted joint's
  // 6.4 mm bolt head on 2 mm shells). The outside of a fold, where the neighbour turns away
  // from the node, stays rounded: no face covers it.
  const auto& sn = p.seg[s];
  const int corners = sn[2] == sn[3] ? 3 : 4;
  auto centroid = [&](const std::array<int32_t, 4>& n, int count) {
    Vec3 c{};
    for (int k = 0; k < count; ++k) c = add(c, at(x_, std::size_t(n[std::size_t(k)])));
    return scale(c, 1.0 / count);
  };
  const Vec3 c = centroid(sn, corners);
  bool past_any = false;
  for (std::size_t k = 0; k < 4; ++k) {
    const auto ia = std::size_t(sn[k]), ib = std::size_t(sn[(k + 1) % 4]);
    if (ia == ib) continue;
    const Vec3 a = at(x_, ia), e = sub(at(x_, ib), a);
    const double ee = dot(e, e);
    if (!(ee > 0.0)) continue;
    const Vec3 mid = add(a, scale(e, 0.5));
    const Vec3 r = sub(x, a);
    if (!(dot(r, acrossEdge(sub(mid, c), e, ee)) > 0.0)) continue;  // not past this edge
    past_any = true;
    const int32_t nb = p.seg_nbr[s][k];
    if (nb < 0 || !live(p, std::size_t(nb))) return true;  // a free edge (or freed by erosion)
    const auto& nn = p.seg[std::size_t(nb)];
    const Vec3 into = acrossEdge(sub(centroid(nn, nn[2] == nn[3] ? 3 : 4), mid), e, ee);
    if (!(dot(r, into) > 0.0)) return true;  // the neighbour turns away: a fold's outside
  }
  // Past no edge by this measure (a warped segment the projection calls outside): rounded.
  return !past_any;
}

std::optional<Contact::Candidate> Contact::chooseSegment(std::size_t pass, int32_t check,
                                                         std::span<const int32_t> candidates,
                                                         int64_t& tests, bool initial) const {
  // Which segment a node is in contact with must not jump (a jump to a deeper penetration
  // makes energy): tracked segments first (rank 0), then a segment the node came to in the
  // last step (rank 1), then the nearest way out, the least penetration; ties to the lower
  // segment.
  const Pass& p = passes_[pass];
  std::optional<Candidate> best;
  if (!erosion_.checkLive(std::size_t(check))) return best;
  const auto local = std::size_t(check - p.first_check);
  const CheckNode c{check, std::size_t(p.node[local]), at(x_, std::size_t(p.node[local])),
                    p.node_half[local]};
  const Vec3& x = c.x;
  const uint8_t* live = erosion_.segmentFlags(pass);
  for (const int32_t candidate : candidates) {
    const auto s = std::size_t(candidate);
    const double* box = search_.box(pass, s);
    if (x[0] < box[0] || x[0] > box[3] || x[1] < box[1] || x[1] > box[4] || x[2] < box[2] ||
        x[2] > box[5])
      continue;
    if (!live[s]) continue;
    ++tests;
    const auto cand = rankSegment(p, c, s, initial);
    if (!cand) continue;
    const double gap = cand->surface.gap;
    if (!best || cand->rank < best->rank ||
        (cand->rank == best->rank &&
         (gap > best->surface.gap || (gap == best->surface.gap && cand->seg < best->seg))))
      best = cand;
  }
  return best;
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

void Contact::tieNodes(std::size_t pass, bool keep_offset) {
  // Each node is tied to the nearest point of the segment it lies on (within a tolerance of
  // the segment's size, as DYNA3D's tied slide surfaces, or the interface's tie distance:
  // negative SST/MST), for the whole run; without _OFFSET it is first moved onto that point.
  // Every rank does the same, in check order.
  const Pass& p = passes_[pass];
  const double tie_distance = model_.contacts[std::size_t(p.iface)].tie_distance;
  for (std::size_t k = 0; k < p.node.size(); ++k) {
    const auto check = std::size_t(p.first_check) + k;
    const auto node = std::size_t(p.node[k]);
    const Vec3 x = at(x_, node);
    int32_t best = -1;
    Projection best_pr;
    double best_dist = 1e300;
    std::vector<int32_t> candidates;
    search_.collectCandidates(p, pass, int32_t(check), tie_distance, x_, candidates);
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
      const double tolerance = tie_distance > 0.0
                                   ? tie_distance
                                   : std::max(0.05 * size, 2.0 * p.seg_half[std::size_t(s)]);
      if (dist <= tolerance && dist < best_dist) {
        best = s;
        best_pr = pr;
        best_dist = dist;
      }
    }
    if (best < 0) continue;
    ++stats_.tied_nodes;
    tie_seg_[check] = best;
    tie_weight_[check] = best_pr.N;
    if (keep_offset) {
      tie_offset_[check] = best_pr.d;
      continue;
    }
    const Vec3 dx = sub(best_pr.point, x);
    moveNode(node, dx);
  }
}

void Contact::resolveInitialPenetrations(std::size_t pass) {
  // Every rank looks at every check of the pass, in check order. DYNA3D moves a penetrating
  // node back onto the surface (and says so); IGNORE 1 and 2 keep the penetration as an
  // offset.
  const Pass& p = passes_[pass];
  const auto& ci = model_.contacts[std::size_t(p.iface)];
  int64_t tests = 0;
  std::vector<int32_t> candidates;
  for (std::size_t k = 0; k < p.node.size(); ++k) {
    const auto check = p.first_check + int32_t(k);
    candidates.clear();
    search_.collectCandidates(p, pass, check, 0.0, x_, candidates);
    const auto best = chooseSegment(pass, check, candidates, tests, true);
    if (!best) continue;
    const auto node = std::size_t(p.node[k]);
    // Nodes that touch to round-off are not penetrations (a block resting on a plate).
    const auto seg = std::size_t(best->seg);
    const double ref = p.seg_half[seg] > 0.0 ? p.seg_half[seg] : p.seg_depth[seg];
    const double gap = best->surface.gap;
    if (-gap <= 1e-9 * ref) continue;
    initial_.push_back(
        {ci.id, model_.nodes.size() ? model_.nodes.id[std::size_t(cn_model_[node])] : 0, -gap});
    if (model::ignoreOf(ci, model_.contact_controls) != 0) {
      // Tracked (LS-DYNA's IGNORE 1 and 2): the node starts in contact with this segment,
      // its initial penetration the contact's entry offset, so the force starts from zero;
      // the offset then follows the penetration down (checkOne).
      const auto c = std::size_t(check);
      last_seg_[c] = best->seg;
      last_side_[c] = int8_t(best->surface.side);
      entry_[c] = -gap;
      in_contact_.push_back(check);
      continue;
    }
    moveNode(node, scale(best->surface.push, -gap));
    moved_initial_ = true;
  }
}

void Contact::initialize(double dt0) {
  if (empty()) return;
  dt_stiff_ = dt0;
  gatherMasses();
  recordOwnedPositions();
  x_prev_.assign(x_.size(), 0.0);
  gatherNodes();
  x_prev_ = x_;
  sortAll();
  need_sort_ = false;
  partition_.cutEvenly(check_node_, x_);
  // Ties and initial penetrations, found by every rank over every check (once).
  search_.updateBoxes(passes_, x_, false);
  for (std::size_t pass = 0; pass < passes_.size(); ++pass) {
    const Pass& p = passes_[pass];
    if (p.tied) {  // tiebreak: tied where they are
      tieNodes(pass, p.tiebreak || model_.contacts[std::size_t(p.iface)].offset);
      if (p.tiebreak) bondAreas(passes_[pass]);
    } else if (p.edges)
      listInitialEdgeOverlaps(pass);
    else if (p.segpairs)
      listInitialSegmentOverlaps(pass);
    else
      resolveInitialPenetrations(pass);
  }
  x_sorted_ = x_;
  x_prev_ = x_;
  recordOwnedPositions();
  search_.updateBoxes(passes_, x_, false);
  cutByCandidates();
  buildCandidateLists();
  buildRoutes();
}

void Contact::cutByCandidates() {
  // The first cut weighs each check by the node-segment tests it will make each cycle until
  // the next sort (its candidates; one for a tie), not one per check: a drop onto a target
  // has its active checks in one corner, and an even cut gave them all to one rank (the cask
  // drop at 2 ranks: 499 us of checks against 1 us per cycle), with no sort to re-cut it. A
  // check with nothing near weighs almost nothing. Who computes a check does not change
  // its result: same bits (docs/parallel.md, "Contact").
  if (!comm_.distributed()) {
    partition_.cutEvenly(check_node_, x_);  // one rank: every check is its own
    return;
  }
  std::vector<int32_t> all(static_cast<std::size_t>(num_checks_));
  std::iota(all.begin(), all.end(), 0);
  search_.buildCandidateLists(passes_, all, check_pass_, tie_seg_, x_);
  std::vector<double> weight(all.size(), 1e-3);
  for (const int32_t i : search_.active())
    weight[std::size_t(i)] +=
        std::max<double>(1.0, double(search_.candidates(std::size_t(i)).size()));
  partition_.cut(check_node_, x_, weight);
}

NodeAndSegment Contact::nodeAndSegment(std::size_t node, const std::array<int32_t, 4>& seg) const {
  NodeAndSegment m;
  m.x_node = at(x_, node);
  m.v_node = at(v_, node);
  m.m_node = mass_[node];
  for (std::size_t a = 0; a < 4; ++a) {
    const auto n = std::size_t(seg[a]);
    m.x_seg[a] = at(x_, n);
    m.v_seg[a] = at(v_, n);
    m.m_seg[a] = mass_[n];
  }
  m.triangle = seg[3] == seg[2];
  if (!rotations_) return m;
  m.w_node = at(w_, node);
  m.i_node = inertia_[node];
  for (std::size_t a = 0; a < 4; ++a) {
    m.w_seg[a] = at(w_, std::size_t(seg[a]));
    m.i_seg[a] = inertia_[std::size_t(seg[a])];
  }
  return m;
}

std::optional<Record> Contact::checkOne(std::size_t i, double time, double dt_prev,
                                        int64_t& tests) const {
  const int32_t check = partition_.mine()[i];
  const auto c = std::size_t(check);
  const auto pass = std::size_t(check_pass_[c]);
  const Pass& p = passes_[pass];
  const auto& ci = model_.contacts[std::size_t(p.iface)];
  if (time < ci.birth || time > ci.death) return std::nullopt;
  const auto node = std::size_t(check_node_[c]);
  if (p.tied && (!p.tiebreak || tie_seg_[c] >= 0)) {
    // A tie ends with its node's elements or its segment's element (erosion.hpp).
    const int32_t s = tie_seg_[c];
    if (s < 0 || !erosion_.checkLive(c) || !live(p, std::size_t(s))) return std::nullopt;
    // A tie is as stiff as the elements it joins: the penalty without SLSFAC.
    const NodeAndSegment m = nodeAndSegment(node, p.seg[std::size_t(s)]);
    Record r =
        tiedForce(check, s, tie_weight_[c], tie_offset_[c], m,
                  p.seg_k[std::size_t(s)] / model_.contact_controls.slsfac, ci, dt_stiff_, dt_prev);
    if (p.tie_rotations && rotations_) addTiedMoment(r, m, at(tie_moment_, c), dt_stiff_, dt_prev);
    if (p.tiebreak)
      r.released = tieBreaks(r, m, tie_offset_[c] >= 0.0 ? 1 : -1, ci.tiebreak,
                             p.node_area[c - std::size_t(p.first_check)]);
    return r;
  }
  auto best = chooseSegment(pass, check, search_.candidates(i), tests, false);
  if (!best) return std::nullopt;
  // Tracked contacts keep the entry offset they began with. IGNORE 1 and 2 (LS-DYNA's
  // tracking of initial penetrations, LSTC FAQ "contact.ignore1"): when the penetration falls
  // below the offset, the offset falls with it, and the contact stays tracked with no force;
  // a node that backed out and comes in again is pushed back from the depth it came out to.
  const double depth = -best->surface.gap;
  const bool tracking = model::ignoreOf(ci, model_.contact_controls) != 0;
  if (best->rank == 0) best->entry = tracking ? std::min(entry_[c], depth) : entry_[c];
  const double pen = depth - best->entry;
  if (!(pen > 0.0)) {
    if (!(tracking && best->rank == 0)) return std::nullopt;
    Record r;
    r.check = check;
    r.segment = best->seg;
    r.N = best->proj.N;
    r.side = int8_t(best->surface.side);
    r.entry = best->entry;
    return r;
  }
  const auto seg = std::size_t(best->seg);
  const Penetration found{
      check,      best->seg, best->proj.N, best->surface.push, pen, int8_t(best->surface.side),
      best->entry};
  return penaltyForce(found, nodeAndSegment(node, p.seg[seg]), p.seg_k[seg], at(friction_, c), ci,
                      dt_stiff_, dt_prev);
}

std::vector<Record> Contact::checkContacts(double time, double dt_prev) {
  // Threaded like the element kernels: each check is computed alone from state nobody writes
  // during the loop, and the records are put in check order afterwards (gatherRecords), so
  // the bits do not depend on the thread count. Few active checks run on one thread (the
  // fork would cost more than it saves).
  constexpr std::size_t kParallelChecks = 128;
  const auto& active = search_.active();
  const std::size_t n = active.size();
  // Scratch kept between cycles (this is the cycle's hot path): cleared, not reallocated.
  const auto& checks = partition_.mine();
  auto& tests = check_tests_;
  auto& found = thread_records_;
  tests.assign(n, 0);
  found.resize(static_cast<std::size_t>(omp_get_max_threads()));
  for (auto& f : found) f.clear();
#pragma omp parallel if (n >= kParallelChecks)
  {
    auto& mine = found[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      const auto i = std::size_t(active[k]);
      const Pass& p = passes_[std::size_t(check_pass_[std::size_t(checks[i])])];
      if (p.edges || p.segpairs)
        checkPairs(i, time, dt_prev, tests[k], mine);
      else if (auto r = checkOne(i, time, dt_prev, tests[k]))
        mine.push_back(*r);
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    partition_.addCost(checks[std::size_t(active[k])], tests[k]);
    stats_.tests += tests[k];
  }
  std::vector<Record> all;
  for (const auto& f : found) all.insert(all.end(), f.begin(), f.end());
  return all;
}

bool Contact::sortIfDue() {
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
  // Erosion here changes the surfaces: every rank sorts and hears of it (syncErosion).
  if (!eroded_here_.empty()) travel = std::numeric_limits<double>::infinity();
  if (comm_.distributed()) travel = -comm_.minAll(-travel);
  ++cycles_since_sort_;
  if (!(2.0 * std::sqrt(travel) > search_.margin() || need_sort_ ||
        (max_sort_interval_ > 0 && cycles_since_sort_ >= max_sort_interval_)))
    return false;
  cycles_since_sort_ = 0;
  need_sort_ = false;
  syncErosion();
  // Every node, from its owner (with its position of the last pass, for the crossing rule);
  // serially too: serial is one rank.
  gatherNodes();
  if (partition_.maybeRebalance(check_node_, x_, model_.contact_controls.rebalance_threshold))
    ++stats_.rebalances;
  sortAll();
  ++stats_.sorts;
  return true;
}

void Contact::computeForces(double time, double dt_prev) {
  if (empty()) return;
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  // The needed entries of x_ become x(n-1) (they were read last cycle), then x(n).
  std::swap(x_prev_, x_);
  gatherNeeded();
  const auto t1 = Clock::now();
  const bool resorted = sortIfDue();
  // The owners' positions of this pass, sent with the next full gather.
  recordOwnedPositions();
  search_.updateBoxes(passes_, x_, !resorted);
  if (resorted) {
    buildCandidateLists();
    buildRoutes();
  }
  const auto t2 = Clock::now();
  dt_stiff_ = std::max(dt_stiff_, dt_prev);
  auto mine = checkContacts(time, dt_prev);
  const auto t3 = Clock::now();
  gatherRecords(std::move(mine));
  const auto t4 = Clock::now();
  applyRecords();
  const auto t5 = Clock::now();
  auto sec = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  // The split the 32-rank model of docs/parallel.md needs: the checks divide among ranks, the
  // rest is done by every rank, the two gathers grow with the surface.
  stats_.search_s += sec(t2, t3);
  stats_.exchange_s += sec(t0, t1) + sec(t3, t4);
  stats_.replicated_s += sec(t1, t2) + sec(t4, t5);
  stats_.records += int64_t(records_.size());
  ++stats_.cycles;
}

void Contact::syncErosion() {
  std::vector<int64_t> all = comm_.distributed() ? comm_.allGather(eroded_here_) : eroded_here_;
  eroded_here_.clear();
  if (all.empty()) return;
  std::sort(all.begin(), all.end());
  erosion_.markEroded(all, passes_);
}

void Contact::gatherRecords(std::vector<Record> mine) {
  if (comm_.distributed()) {
    std::vector<double> wire;
    wire.reserve(kRecordDoubles * mine.size());
    for (const Record& r : mine) pack(r, wire);
    const auto all = comm_.allGather(wire);
    records_.clear();
    for (std::size_t k = 0; k + kRecordDoubles <= all.size(); k += kRecordDoubles)
      records_.push_back(unpack(&all[k]));
  } else {
    records_ = std::move(mine);
  }
  // Canonical order: by check index (each check is computed by one rank, once), then segment
  // (a beam edge check has a record per edge it touches).
  std::sort(records_.begin(), records_.end(), [](const Record& a, const Record& b) {
    return a.check < b.check || (a.check == b.check && a.segment < b.segment);
  });
}

void Contact::applyRecords() {
  // The history of the checks in contact last cycle is cleared (not of every check: this is
  // the cycle's hot path, and most checks are never in contact), then set from the records.
  last_contact_seg_.clear();
  for (const int32_t c : in_contact_) {
    const auto check = std::size_t(c);
    for (std::size_t k = 0; k < 3; ++k) {
      friction_[3 * check + k] = 0.0;
      tie_moment_[3 * check + k] = 0.0;
    }
    last_contact_seg_.push_back(last_seg_[check]);
    last_seg_[check] = -1;
    last_side_[check] = 0;
    entry_[check] = 0.0;
  }
  std::swap(in_contact_, last_in_contact_);
  in_contact_.clear();
  std::swap(edge_pairs_, last_pairs_);
  edge_pairs_.clear();
  std::fill(stored_.begin(), stored_.end(), 0.0);
  for (const Record& r : records_) {
    const auto check = std::size_t(r.check);
    const Pass& p = passes_[std::size_t(check_pass_[check])];
    const auto seg = std::size_t(r.segment);
    const auto& sn = p.seg[seg];
    if (r.released) {
      // The bond is gone from the next cycle on: its spring's energy stays in the contact
      // energy (as work done on the interface), the check searches like any other.
      dissipated_[std::size_t(p.iface)] += r.energy;
      tie_seg_[check] = -1;
      need_sort_ = true;
    } else {
      stored_[std::size_t(p.iface)] += r.energy;
    }
    dissipated_[std::size_t(p.iface)] += r.dissipated;
    notePenetration(p, r);
    if (p.edges) {
      applyEdgeRecord(p, r);
      continue;
    }
    if (p.segpairs) {
      applySegmentRecord(p, r);
      continue;
    }
    for (std::size_t c = 0; c < 3; ++c) friction_[3 * check + c] = r.friction[c];
    last_seg_[check] = r.segment;
    holdEnergy(check, r.released ? 0.0 : r.energy);
    in_contact_.push_back(r.check);
    last_side_[check] = r.side;
    entry_[check] = r.entry;
    // Added on every rank holding the node.
    addNodeForce(check_node_[check], r.force);
    for (std::size_t a = 0; a < 4; ++a) {
      if (a == 3 && sn[3] == sn[2]) break;
      addNodeForce(sn[a], segmentReaction(r, a));
    }
    if (p.tie_rotations) applyTiedMoment(p, r);
  }
  bookEndedNodeChecks();
  bookEndedSegmentPairs();
}

void Contact::bookEndedNodeChecks() {
  // A node check can end while the node is still behind the segment plane: the node slides
  // past the segment's outer edge (off a block's corner) or its segment leaves the surface.
  // The penalty spring's k p^2 / 2 of its last cycle is then not given back to the bodies,
  // and dropped from the stored energy alone it left the balance short by it (a block sliding
  // off a layer's edge: energy ratio 0.88). It stays in the contact energy as work done on
  // the interface (LS-DYNA Theory Manual, "sliding interface energy"), as for the segment
  // pairs (bookEndedSegmentPairs). A check whose spring was unloading (the node parting: its
  // last force acts over the step that takes it out and gives the energy back) books
  // nothing: booked, it over-counted by that last k p^2 / 2 (free nodes kicked off a block:
  // energy ratio 1.0007 instead of 1.00005). A check ended by erosion (its segment's element,
  // or its node's, eroded) books its spring's energy whatever the spring was doing: the node
  // is still behind the plane and nothing gives the energy back (a block pressed into an
  // eroding layer: energy ratio 0.62 when unloading springs booked nothing).
  for (std::size_t k = 0; k < last_in_contact_.size(); ++k) {
    const auto check = std::size_t(last_in_contact_[k]);
    if (last_seg_[check] >= 0) continue;
    const Pass& p = passes_[std::size_t(check_pass_[check])];
    const int32_t seg = last_contact_seg_[k];
    const bool eroded = !erosion_.checkLive(check) || (seg >= 0 && !live(p, std::size_t(seg)));
    if (held_[check] > 0.0 || eroded) dissipated_[std::size_t(p.iface)] += std::abs(held_[check]);
    held_[check] = 0.0;
  }
}

void Contact::holdEnergy(std::size_t check, double energy) {
  // Signed: negative while the spring unloads (less than last cycle).
  held_[check] = energy < std::abs(held_[check]) ? -energy : energy;
}

void Contact::bookEndedSegmentPairs() {
  // A segment pair can end while its faces still overlap (a centroid leaves the other segment
  // and the next segment's pair starts from zero force, a face turns past the filters): its
  // spring's energy is not given back to the bodies. The contact (sliding) energy is the work
  // done on the contact forces (LS-DYNA Theory Manual, "sliding interface energy"), so that
  // energy stays in it, as in LS-DYNA's; dropped from the stored energy alone, it left the
  // balance short by it (0.7 % on the sliding test of test_segment_contact.py). With it goes
  // the second half of the friction and damping work of the pair's last force (segmentPair
  // books a new pair's first half): a force of cycle n acts over half the step before and
  // half the step after. A pair that ended because its faces parted keeps the k p^2 / 2 of its
  // last cycle too, an over-count of at most one step's unloading (telling the two apart from
  // the pair's last rate of penetration was worse: the handover to the next segment is not
  // at that rate).
  for (const EdgePair& e : last_pairs_) {
    const Pass& p = passes_[std::size_t(check_pass_[std::size_t(e.check)])];
    if (p.segpairs && !findEdgePair(e.check, e.segment))
      dissipated_[std::size_t(p.iface)] += e.energy + 0.5 * e.dissipated;
  }
}

void Contact::applyTiedMoment(const Pass& p, const Record& r) {
  // The node takes the rotational spring's moment, the segment's nodes -N_a of it and of the
  // moment of the tie force about the tied point (penalty.hpp, Record::arm).
  const auto check = std::size_t(r.check);
  for (std::size_t c = 0; c < 3; ++c) tie_moment_[3 * check + c] = r.moment[c];
  addNodeMoment(check_node_[check], r.moment);
  const auto& sn = p.seg[std::size_t(r.segment)];
  const Vec3 total = add(r.moment, r.arm);
  for (std::size_t a = 0; a < 4; ++a) {
    if (a == 3 && sn[3] == sn[2]) break;
    addNodeMoment(sn[a], scale(total, -r.N[a]));
  }
}

void Contact::addNodeMoment(int32_t node, const Vec3& m) {
  const int32_t l = cn_local_[std::size_t(node)];
  if (l < 0 || !sd_.rotations) return;
  for (std::size_t c = 0; c < 3; ++c) sd_.moment[3 * std::size_t(l) + c] += m[c];
}

void Contact::addNodeForce(int32_t node, const Vec3& f) {
  const int32_t l = cn_local_[std::size_t(node)];
  if (l < 0) return;
  for (std::size_t c = 0; c < 3; ++c) sd_.f[3 * std::size_t(l) + c] += f[c];
}

void Contact::notePenetration(const Pass& p, const Record& r) {
  // Geometric penetration (with the entry and initial offsets) relative to the contact
  // thickness (shells, beams) or the element depth (solids).
  const auto check = std::size_t(r.check);
  const auto seg = std::size_t(r.segment);
  const double h = p.seg_half[seg] + p.node_half[check - std::size_t(p.first_check)];
  const double ref = h > 0.0 ? 2.0 * h : p.seg_depth[seg];
  if (ref > 0.0)
    stats_.max_penetration_ratio =
        std::max(stats_.max_penetration_ratio, (r.penetration + r.entry) / ref);
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
  for (const Record& r : records_) {
    const auto pass_index = std::size_t(check_pass_[std::size_t(r.check)]);
    const Pass& p = passes_[pass_index];
    auto& o = out[std::size_t(p.iface)];
    // The second pass of a symmetric interface has the B side's nodes against A's segments.
    const bool reversed = pass_index > 0 && passes_[pass_index - 1].iface == p.iface;
    auto& on_node = reversed ? o.side_b : o.side_a;
    auto& on_seg = reversed ? o.side_a : o.side_b;
    for (std::size_t c = 0; c < 3; ++c) {
      on_node[c] += r.force[c];
      on_seg[c] -= r.force[c];
    }
    ++o.pairs;
  }
  for (std::size_t i = 0; i < out.size(); ++i)
    if (model_.contacts[i].kind == model::ContactKind::Transducer) measure(i, out[i]);
  return out;
}

void Contact::measure(std::size_t iface, InterfaceForces& o) const {
  // The node-to-segment records of the other interfaces between the transducer's sides (the
  // force on side A's nodes, minus it on B's), or on side A alone when B is empty (its nodes'
  // forces and their segments' reactions). Beam edge and segment pair records are not seen.
  const auto& ci = model_.contacts[iface];
  auto in = [&](const model::ContactSurface& s, int32_t cn) {
    return std::binary_search(s.nodes.begin(), s.nodes.end(), cn_model_[std::size_t(cn)]);
  };
  const bool one_side = ci.b.nodes.empty();
  o = InterfaceForces{ci.id, {}, {}, 0.0, 0};
  for (const Record& r : records_) {
    const Pass& p = passes_[std::size_t(check_pass_[std::size_t(r.check)])];
    if (p.edges || p.segpairs) continue;
    const int32_t node = check_node_[std::size_t(r.check)];
    const auto& sn = p.seg[std::size_t(r.segment)];
    const std::size_t corners = sn[2] == sn[3] ? 3 : 4;
    auto all_in = [&](const model::ContactSurface& s) {
      return std::all_of(sn.begin(), sn.begin() + std::ptrdiff_t(corners),
                         [&](int32_t a) { return in(s, a); });
    };
    Vec3 f{};
    if (one_side) {
      if (in(ci.a, node)) f = r.force;
      for (std::size_t a = 0; a < corners; ++a)
        if (in(ci.a, sn[a])) f = add(f, segmentReaction(r, a));
    } else if (in(ci.a, node) && all_in(ci.b)) {
      f = r.force;
    } else if (in(ci.b, node) && all_in(ci.a)) {
      f = scale(r.force, -1.0);
    } else {
      continue;
    }
    for (std::size_t c = 0; c < 3; ++c) {
      o.side_a[c] += f[c];
      if (!one_side) o.side_b[c] -= f[c];
    }
    ++o.pairs;
  }
}

std::vector<char> Contact::saveState() const {
  // Positions of the last contact pass of every node, from the owners (collective).
  std::vector<double> x = x_;
  if (comm_.distributed()) {
    struct OwnedPosition {
      int64_t node = 0;  // contact node index
      Vec3 x{};
    };
    std::vector<OwnedPosition> mine;
    for (std::size_t i = 0; i < cn_model_.size(); ++i)
      if (cn_owned_[i]) mine.push_back({int64_t(i), at(x_owned_prev_, i)});
    for (const OwnedPosition& p : comm_.allGather(mine))
      for (std::size_t c = 0; c < 3; ++c) x[3 * std::size_t(p.node) + c] = p.x[c];
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
  // The elements eroded before the dump, from the element states restored before this section
  // (each rank its own): the surfaces as they were.
  eroded_here_ = erosion_.erodedHere();
  syncErosion();
  in_contact_.clear();
  for (int32_t c = 0; c < num_checks_; ++c)
    if (last_seg_[std::size_t(c)] >= 0) in_contact_.push_back(c);
  // The buckets, boxes and candidate lists of the last sort, rebuilt from its positions.
  x_ = x_sorted_;
  sortAll();
  search_.updateBoxes(passes_, x_, false);
  cutByCandidates();
  buildCandidateLists();
  buildRoutes();
  x_ = std::move(x);
  for (std::size_t i = 0; i < cn_model_.size(); ++i)
    if (cn_owned_[i])
      for (int c = 0; c < 3; ++c)
        x_owned_prev_[3 * i + std::size_t(c)] = x_[3 * i + std::size_t(c)];
}

}  // namespace crumple::contact
