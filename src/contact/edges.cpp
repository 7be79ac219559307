// Beam-to-beam contact of *CONTACT_AUTOMATIC_GENERAL (docs/theory.md, "Beam edges"): every
// beam is a capsule, its axis between its two nodes with the radius of its contact thickness
// (LS-DYNA Keyword Manual, *CONTACT_AUTOMATIC_GENERAL and *PART_CONTACT OPTT; LS-DYNA Theory
// Manual, "Contact-Impact Algorithm": edge-to-edge contact). Two capsules touch where the
// distance between the closest points of their axes is below the sum of their radii; the
// penalty spring acts along the line joining those points and is shared between each edge's
// nodes by the closest-point parameters, so that force and moment balance. The checks, the
// records and their canonical order are the node-to-segment ones (contact.cpp).
#include <algorithm>

#include "contact/contact.hpp"
#include "contact/geometry.hpp"

namespace crumple::contact {

void Contact::addEdgePass(int32_t iface, const model::ContactSurface& side, double sf) {
  Pass p;
  p.iface = iface;
  p.edges = true;
  p.skip_same_part = model_.contacts[std::size_t(iface)].skip_same_part_edges;
  p.first_check = num_checks_;
  const double slsfac = model_.contact_controls.slsfac;
  for (std::size_t k = 0; k < side.edges.size(); ++k) {
    const int32_t a = contactNode(side.edges[k][0]), b = contactNode(side.edges[k][1]);
    const double r = side.edge_radius[k];
    p.node.push_back(a);
    p.node2.push_back(b);
    p.node_half.push_back(r);
    p.seg.push_back({a, b, a, b});
    p.seg_half.push_back(r);
    p.seg_k.push_back(slsfac * sf * side.edge_stiffness[k]);
    p.seg_depth.push_back(2.0 * r);
    p.edge_part.push_back(side.edge_part[k]);
    p.max_node_half = std::max(p.max_node_half, r);
  }
  registerPass(std::move(p));
}

void Contact::refreshEdgeReach() {
  // Two capsules touch only if their middles are within half of both lengths and both radii:
  // the bucket reach is half the longest segment plus reach_extra, so reach_extra holds the
  // other half length and the radii, at the lengths of now (beams stretch).
  for (Pass& p : passes_) {
    if (p.segpairs) {
      // Segment pairs: the largest check segment's radius and both thicknesses, and half the
      // deepest element (a solid face's centroid may be that far behind the other's plane).
      double radius = 0.0, depth = 0.0, seg_half = 0.0;
      for (std::size_t k = 0; k < p.check_seg.size(); ++k) {
        Vec3 c{};
        for (int32_t a : p.check_seg[k]) c = add(c, scale(at(x_, std::size_t(a)), 0.25));
        for (int32_t a : p.check_seg[k])
          radius = std::max(radius, norm(sub(at(x_, std::size_t(a)), c)));
        depth = std::max(depth, p.check_depth[k]);
      }
      for (std::size_t s = 0; s < p.seg.size(); ++s) {
        seg_half = std::max(seg_half, p.seg_half[s]);
        depth = std::max(depth, p.seg_depth[s]);
      }
      p.reach_extra = radius + p.max_node_half + seg_half + 0.5 * depth;
      continue;
    }
    if (!p.edges) continue;
    double longest = 0.0;
    for (std::size_t k = 0; k < p.node.size(); ++k)
      longest = std::max(
          longest, norm(sub(at(x_, std::size_t(p.node2[k])), at(x_, std::size_t(p.node[k])))));
    p.reach_extra = 2.0 * p.max_node_half + 0.5 * longest;
  }
}

const Contact::EdgePair* Contact::findEdgePair(int32_t check, int32_t segment) const {
  const auto it = std::lower_bound(
      edge_pairs_.begin(), edge_pairs_.end(), std::pair{check, segment},
      [](const EdgePair& e, const std::pair<int32_t, int32_t>& key) {
        return e.check < key.first || (e.check == key.first && e.segment < key.second);
      });
  if (it == edge_pairs_.end() || it->check != check || it->segment != segment) return nullptr;
  return &*it;
}

const Contact::EdgePair* Contact::continuedEdgePair(const Pass& p, std::size_t a,
                                                    std::size_t b) const {
  auto near = [&](std::size_t x, std::size_t y) {
    const auto &ex = p.seg[x], &ey = p.seg[y];
    return x == y || ex[0] == ey[0] || ex[0] == ey[1] || ex[1] == ey[0] || ex[1] == ey[1];
  };
  for (const EdgePair& e : edge_pairs_) {
    if (&passes_[std::size_t(check_pass_[std::size_t(e.check)])] != &p) continue;
    const auto x = std::size_t(e.check - p.first_check), y = std::size_t(e.segment);
    if ((near(x, a) && near(y, b)) || (near(x, b) && near(y, a))) return &e;
  }
  return nullptr;
}

namespace {

// The closest points of two edges given by their contact nodes, at positions xs.
EdgePoints edgePointsAt(const std::vector<double>& xs, int32_t a0, int32_t a1, int32_t b0,
                        int32_t b1) {
  return closestEdgePoints(at(xs, std::size_t(a0)), at(xs, std::size_t(a1)),
                           at(xs, std::size_t(b0)), at(xs, std::size_t(b1)));
}

}  // namespace

std::optional<Record> Contact::edgePair(const Pass& p, int32_t check, std::size_t s,
                                        double dt_prev) const {
  const auto k = std::size_t(check - p.first_check);
  const int32_t a0 = p.node[k], a1 = p.node2[k];
  const int32_t b0 = p.seg[s][0], b1 = p.seg[s][1];
  const EdgePoints e = edgePointsAt(x_, a0, a1, b0, b1);
  const double h = p.node_half[k] + p.seg_half[s];
  Vec3 d = sub(e.p, e.q);
  double dist = norm(d);
  if (!(dist < h)) return std::nullopt;
  const EdgePoints before = edgePointsAt(x_prev_, a0, a1, b0, b1);
  const Vec3 d_before = sub(before.p, before.q);
  const EdgePair* last = findEdgePair(check, int32_t(s));
  // A pair already overlapping a step ago that was not in contact then continues the contact
  // of a neighbouring pair (the point slid over the node two edges share) when there is one.
  if (!last && norm(d_before) < h) last = continuedEdgePair(p, k, s);
  // A pair first found inside the sum of the radii (the capsules came together sideways past
  // an end, or overlapped from the start) keeps the overlap it had a step before as its entry
  // offset, so that the force starts from zero rather than with a jump (which makes energy).
  const double entry = last ? last->entry : std::max(0.0, h - norm(d_before));
  const double pen = h - dist - entry;
  if (!(pen > 0.0)) return std::nullopt;
  // Axes that cross exactly have no closest-point line: the line of the last step is taken;
  // if that too is zero the pair is left for the next cycle (a measure-zero event).
  if (!(dist > 0.0)) {
    d = d_before;
    dist = norm(d);
    if (!(dist > 0.0)) return std::nullopt;
  }
  NodeAndSegment m;
  m.x_node = e.p;
  m.v_node = add(scale(at(v_, std::size_t(a0)), 1.0 - e.s), scale(at(v_, std::size_t(a1)), e.s));
  m.m_node = (1.0 - e.s) * mass_[std::size_t(a0)] + e.s * mass_[std::size_t(a1)];
  m.x_seg = {at(x_, std::size_t(b0)), at(x_, std::size_t(b1)), e.q, e.q};
  m.v_seg = {at(v_, std::size_t(b0)), at(v_, std::size_t(b1)), Vec3{}, Vec3{}};
  m.m_seg = {mass_[std::size_t(b0)], mass_[std::size_t(b1)], 0.0, 0.0};
  const Penetration found{check, int32_t(s), {1.0 - e.t, e.t, 0.0, 0.0}, scale(d, 1.0 / dist), pen,
                          0,     entry};
  // The pair's stiffness is the softer edge's (as the minimum of segment and node of
  // LS-DYNA's default penalty option).
  const double stiffness = std::min(p.seg_k[k], p.seg_k[s]);
  const auto& ci = model_.contacts[std::size_t(p.iface)];
  Record r =
      penaltyForce(found, m, stiffness, last ? last->friction : Vec3{}, ci, dt_stiff_, dt_prev);
  r.edge_s = e.s;
  return r;
}

void Contact::checkPairs(std::size_t i, double time, double dt_prev, int64_t& tests,
                         std::vector<Record>& out) const {
  // A beam edge's or a segment's check (segpairs.cpp): each candidate whose widened box
  // overlaps the box of the check's nodes is tested.
  const int32_t check = partition_.mine()[i];
  const auto pass = std::size_t(check_pass_[std::size_t(check)]);
  const Pass& p = passes_[pass];
  const auto& ci = model_.contacts[std::size_t(p.iface)];
  if (time < ci.birth || time > ci.death) return;
  const auto k = std::size_t(check - p.first_check);
  const std::array<int32_t, 4> corners =
      p.edges ? std::array<int32_t, 4>{p.node[k], p.node2[k], p.node[k], p.node2[k]}
              : p.check_seg[k];
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (int32_t a : corners)
    for (std::size_t c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], x_[3 * std::size_t(a) + c]);
      hi[c] = std::max(hi[c], x_[3 * std::size_t(a) + c]);
    }
  for (const int32_t candidate : search_.candidates(i)) {
    const auto s = std::size_t(candidate);
    const double* box = search_.box(pass, s);
    bool apart = false;
    for (std::size_t c = 0; c < 3; ++c) apart = apart || hi[c] < box[c] || lo[c] > box[3 + c];
    if (apart) continue;
    ++tests;
    if (auto r = p.edges ? edgePair(p, check, s, dt_prev) : segmentPair(p, check, s, dt_prev))
      out.push_back(*r);
  }
}

void Contact::listInitialEdgeOverlaps(std::size_t pass) {
  // Every rank looks at every check of the pass, in check order. The overlaps stay as entry
  // offsets whatever IGNORE says: moving beam nodes apart would strain what joins them.
  const Pass& p = passes_[pass];
  const auto& ci = model_.contacts[std::size_t(p.iface)];
  std::vector<int32_t> candidates;
  for (std::size_t k = 0; k < p.node.size(); ++k) {
    const auto check = p.first_check + int32_t(k);
    candidates.clear();
    search_.collectCandidates(p, pass, check, 0.0, x_, candidates);
    for (const int32_t s : candidates) {
      const auto& b = p.seg[std::size_t(s)];
      const EdgePoints e = edgePointsAt(x_, p.node[k], p.node2[k], b[0], b[1]);
      const double h = p.node_half[k] + p.seg_half[std::size_t(s)];
      const double overlap = h - norm(sub(e.p, e.q));
      if (overlap > 1e-9 * h)
        initial_.push_back({ci.id,
                            model_.nodes.size()
                                ? model_.nodes.id[std::size_t(cn_model_[std::size_t(p.node[k])])]
                                : 0,
                            overlap});
    }
  }
}

void Contact::applyEdgeRecord(const Pass& p, const Record& r) {
  const auto k = std::size_t(r.check - p.first_check);
  const auto& b = p.seg[std::size_t(r.segment)];
  // Added on every rank holding the node, in record order.
  addNodeForce(p.node[k], scale(r.force, 1.0 - r.edge_s));
  addNodeForce(p.node2[k], scale(r.force, r.edge_s));
  addNodeForce(b[0], segmentReaction(r, 0));
  addNodeForce(b[1], segmentReaction(r, 1));
  edge_pairs_.push_back({r.check, r.segment, r.friction, r.entry});
}

}  // namespace crumple::contact
