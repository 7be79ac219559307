// Segment-based contact, SOFT = 2 (LS-DYNA Keyword Manual, *CONTACT optional card A; LS-DYNA
// Theory Manual, "Contact-Impact Algorithm", segment-based penalty; after Belytschko & Neal
// 1991, "Contact-impact by the pinball algorithm with penalty and Lagrangian methods", IJNME
// 31): segments are checked against segments, not nodes against segments, so that a sheet's
// edge crossing another sheet between their nodes is caught. docs/theory.md, "Segment-based
// contact", says which check Crumple makes:
// - shells (a contact thickness h, the sum of the two half thicknesses): the two segments'
//   mid-surfaces closer than h. The pair's contact point is the centroid of one segment over
//   the other when there is one (faces lying on each other), else the closest points of the
//   two (an edge against a face or an edge: the edge-to-edge check of DEPTH 2);
// - solid faces (h = 0, one-sided): facing segments, the centroid of one behind the other's
//   plane and over it (Belytschko & Neal's pinball sits at the centroid).
// The penalty stiffness is LS-DYNA's for SOFT = 2, k = 0.5 SLSFAC SFS m1 m2 / (m1 + m2) / dt^2,
// from the two segments' masses and the stiffness step. The force acts
// along the line of the contact points (or the normal), on each segment's nodes by its
// weights there: equal and opposite, so momentum is exact. The records, their order and their
// history are the beam edges' (edges.cpp).
#include <algorithm>
#include <cmath>

#include "contact/contact.hpp"
#include "contact/geometry.hpp"

namespace crumple::contact {

void Contact::addSegmentPass(int32_t iface, const model::ContactSurface& a,
                             const model::ContactSurface& b, bool self) {
  const auto& ci = model_.contacts[std::size_t(iface)];
  const double slsfac = model_.contact_controls.slsfac;
  Pass p;
  p.iface = iface;
  p.self = self;
  p.segpairs = true;
  p.first_check = num_checks_;
  auto nodesOf = [&](const std::array<int32_t, 4>& s) {
    return std::array<int32_t, 4>{contactNode(s[0]), contactNode(s[1]), contactNode(s[2]),
                                  contactNode(s[3])};
  };
  for (std::size_t k = 0; k < a.segments.size(); ++k) {
    p.check_seg.push_back(nodesOf(a.segments[k]));
    p.node.push_back(p.check_seg.back()[0]);
    p.node_half.push_back(0.5 * a.segment_thickness[k]);
    p.check_depth.push_back(a.segment_depth[k]);
    p.check_k.push_back(slsfac * ci.sfs);
    p.max_node_half = std::max(p.max_node_half, p.node_half.back());
  }
  for (std::size_t k = 0; k < b.segments.size(); ++k) {
    p.seg.push_back(nodesOf(b.segments[k]));
    p.seg_half.push_back(0.5 * b.segment_thickness[k]);
    p.seg_k.push_back(slsfac * (self ? ci.sfs : ci.sfm));
    p.seg_depth.push_back(b.segment_depth[k]);
  }
  p.check_elem = a.segment_element;
  p.check_across = a.segment_neighbour;
  p.seg_elem = b.segment_element;
  p.seg_across = b.segment_neighbour;
  registerPass(std::move(p));
}

namespace {

// A segment's corners at positions xs.
std::array<Vec3, 4> cornersAt(const std::vector<double>& xs, const std::array<int32_t, 4>& s) {
  return {at(xs, std::size_t(s[0])), at(xs, std::size_t(s[1])), at(xs, std::size_t(s[2])),
          at(xs, std::size_t(s[3]))};
}

Vec3 centroidOf(const std::array<Vec3, 4>& c, bool triangle) {
  if (triangle) return scale(add(add(c[0], c[1]), c[2]), 1.0 / 3.0);
  return scale(add(add(c[0], c[1]), add(c[2], c[3])), 0.25);
}

std::array<double, 4> centroidWeights(bool triangle) {
  if (triangle) return {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0, 0.0};
  return {0.25, 0.25, 0.25, 0.25};
}

// One segment pair's geometry: the contact points on the check's segment (weights Na) and on
// the other (Nb), the unit direction the check's segment is pushed, and the signed gap
// (negative: penetration). `side`: shells, the side of the normal of b (or of a) that a is on.
struct PairGap {
  std::array<double, 4> Na{}, Nb{};
  Vec3 push{};
  double gap = 0.0;
  int8_t side = 0;
};

struct PairShape {
  std::array<Vec3, 4> a, b;
  bool tri_a = false, tri_b = false;
  double h = 0.0;                         // sum of the half thicknesses (0: two solid faces)
  double depth_a = 0.0, depth_b = 0.0;    // element depths under the faces
  bool solid_a = false, solid_b = false;  // a solid face (one-sided) against a shell
};

// The centroid of `from` over segment `onto` (projected inside it): its projection.
std::optional<Projection> centroidOver(const std::array<Vec3, 4>& from, bool tri_from,
                                       const std::array<Vec3, 4>& onto, bool tri_onto) {
  const Projection pr =
      project(centroidOf(from, tri_from), onto[0], onto[1], onto[2], onto[3], tri_onto, 0.0);
  if (!pr.inside) return std::nullopt;
  return pr;
}

// Solid faces: facing (normals within 60 degrees of opposite), the centroid of one behind the
// other's plane by less than half the element under it; the deeper of the two ways, a first.
// A new pair (`fresh`) also needs that centroid in front of the plane a step ago (`before`):
// a centroid already inside that did not come in through this face is a face meeting the
// side of a block near its edge, not a contact (the node-to-segment rule of contact.cpp).
std::optional<PairGap> solidPairGap(const PairShape& s, const PairShape& before, bool fresh) {
  const Vec3 na = segmentNormal(s.a[0], s.a[1], s.a[2], s.a[3]);
  const Vec3 nb = segmentNormal(s.b[0], s.b[1], s.b[2], s.b[3]);
  if (!(dot(na, nb) < -0.5)) return std::nullopt;
  auto cameIn = [&](bool a_over_b) {
    if (!fresh) return true;
    const auto& from = a_over_b ? before.a : before.b;
    const auto& onto = a_over_b ? before.b : before.a;
    const Vec3 n = segmentNormal(onto[0], onto[1], onto[2], onto[3]);
    return dot(sub(centroidOf(from, a_over_b ? s.tri_a : s.tri_b), onto[0]), n) >= 0.0;
  };
  std::optional<PairGap> best;
  if (const auto pr = centroidOver(s.a, s.tri_a, s.b, s.tri_b);
      pr && pr->d > -0.5 * s.depth_b && cameIn(true))
    best = PairGap{centroidWeights(s.tri_a), pr->N, pr->normal, pr->d, 0};
  if (const auto pr = centroidOver(s.b, s.tri_b, s.a, s.tri_a);
      pr && pr->d > -0.5 * s.depth_a && (!best || pr->d < best->gap) && cameIn(false))
    best = PairGap{pr->N, centroidWeights(s.tri_b), scale(pr->normal, -1.0), pr->d, 0};
  if (!best || !(best->gap < 0.0)) return std::nullopt;
  return best;
}

// The gap of faces on each other from the centroid's distance d along the push: d - h. A
// centroid past the other mid-surface (d < 0: the faces cross there) takes the closest points'
// distance instead, as before it crossed (a Workbench block face through a plate gave a pair
// a penetration of 4 mm against h = 0.5 mm at once).
double centroidGap(double d, double closest, double h) {
  return (d >= 0.0 ? d : closest) - h;
}

// Shells: the mid-surfaces closer than h. The gap is their distance less h, which moves
// continuously with the nodes whatever features are nearest (a gap that jumped, as a centroid
// distance does when the centroid leaves the other segment, would make energy). The force
// acts along the line of the closest points, at them; faces lying on each other (that line
// within 8 degrees of b's normal) have no single closest point, and take it at a's centroid
// over b, or b's over a (Belytschko & Neal's pinball at the centroid), or not at all. There the
// gap is the centroid's distance from the other segment along b's normal, less h: the force
// must be the gradient of the penalty energy k gap^2 / 2 at the point it acts on (the gap of the
// nearest corners with the force at the centroid did work the spring never stored: a block
// sliding onto a plate while turning gained 7.8 % of the energy). `side`: the
// side of b's normal a is on, kept from the pair's history (a sheet pushed past the other's
// mid-surface is still pushed back, not through), else the side a step ago.
std::optional<PairGap> shellPairGap(const PairShape& s, int side, const PairShape& before) {
  const SegmentPoints c = closestSegmentPoints(s.a, s.tri_a, s.b, s.tri_b);
  if (!(c.dist < s.h)) return std::nullopt;
  const Vec3 nb = segmentNormal(s.b[0], s.b[1], s.b[2], s.b[3]);
  Vec3 d = sub(c.p, c.q);
  if (side == 0) {
    const SegmentPoints c0 = closestSegmentPoints(before.a, s.tri_a, before.b, s.tri_b);
    const Vec3 nb0 = segmentNormal(before.b[0], before.b[1], before.b[2], before.b[3]);
    const double along = dot(sub(c0.p, c0.q), nb0);
    side = (along != 0.0 ? along : dot(d, nb)) >= 0.0 ? 1 : -1;
  }
  if (!(c.dist > 0.0) || dot(d, nb) * side < 0.0) d = scale(nb, double(side));
  if (!(norm(d) > 0.0)) return std::nullopt;
  const Vec3 n = scale(d, 1.0 / norm(d));
  // A solid face meets a sheet only in front of it (within 60 degrees of its outward normal):
  // the side faces of a block pushed into a sheet cross the sheet edge-on, and the block's
  // face under it is the one in contact.
  if (s.solid_b && !(dot(n, nb) > 0.5)) return std::nullopt;
  if (s.solid_a && !(dot(n, segmentNormal(s.a[0], s.a[1], s.a[2], s.a[3])) < -0.5))
    return std::nullopt;
  PairGap g{c.Na, c.Nb, n, c.dist - s.h, int8_t(side)};
  if (std::abs(dot(n, nb)) > 0.99) {
    const Vec3 push = scale(nb, double(side));
    if (const auto pr = centroidOver(s.a, s.tri_a, s.b, s.tri_b)) {
      g.Na = centroidWeights(s.tri_a);
      g.Nb = pr->N;
      g.push = push;
      g.gap = centroidGap(dot(sub(centroidOf(s.a, s.tri_a), pr->point), push), c.dist, s.h);
    } else if (const auto pb = centroidOver(s.b, s.tri_b, s.a, s.tri_a)) {
      g.Na = pb->N;
      g.Nb = centroidWeights(s.tri_b);
      g.push = push;
      g.gap = centroidGap(dot(sub(pb->point, centroidOf(s.b, s.tri_b)), push), c.dist, s.h);
    } else {
      // Faces on each other that only touch at an edge or a corner (neither centroid over the
      // other): their neighbours, over which the centroids lie, carry the contact. Taken at
      // the nearest features instead, such pairs made energy (a 2 x 2 block face dropped with
      // its edges over a sheet's element edges: ratio 1.6).
      return std::nullopt;
    }
  }
  return g;
}

// Check k of pass p against its segment s at positions xs.
PairShape pairShapeAt(const Pass& p, std::size_t k, std::size_t s, const std::vector<double>& xs) {
  const auto& sa = p.check_seg[k];
  const auto& sb = p.seg[s];
  return PairShape{cornersAt(xs, sa),
                   cornersAt(xs, sb),
                   sa[2] == sa[3],
                   sb[2] == sb[3],
                   p.node_half[k] + p.seg_half[s],
                   p.check_depth[k],
                   p.seg_depth[s],
                   p.node_half[k] == 0.0,
                   p.seg_half[s] == 0.0};
}

}  // namespace

std::optional<Record> Contact::segmentPair(const Pass& p, int32_t check, std::size_t s,
                                           double dt_prev) const {
  const auto k = std::size_t(check - p.first_check);
  const auto& sa = p.check_seg[k];
  const auto& sb = p.seg[s];
  const PairShape now = pairShapeAt(p, k, s, x_), before = pairShapeAt(p, k, s, x_prev_);
  const EdgePair* last = findEdgePair(check, int32_t(s));
  const auto g = now.h > 0.0 ? shellPairGap(now, last ? last->side : 0, before)
                             : solidPairGap(now, before, last == nullptr);
  if (!g) return std::nullopt;
  // A pair first found already penetrating (it came together sideways, or overlapped from
  // the start) keeps that a step ago as its entry offset, so that the force starts from zero
  // rather than with a jump (which makes energy).
  double entry = 0.0;
  if (last) {
    entry = last->entry;
  } else if (now.h > 0.0) {
    // Shells: the overlap of the mid-surfaces' distance a step ago, whatever the filters of
    // shellPairGap said then (a pair they let through now and not then starts from zero).
    entry =
        std::max(0.0, now.h - closestSegmentPoints(before.a, now.tri_a, before.b, now.tri_b).dist);
  } else {
    const auto g0 = solidPairGap(before, before, false);
    entry = g0 ? std::max(0.0, -g0->gap) : 0.0;
  }
  const double pen = -g->gap - entry;
  if (!(pen > 0.0)) return std::nullopt;
  NodeAndSegment m;
  for (std::size_t a = 0; a < 4; ++a) {
    const auto na = std::size_t(sa[a]), nb = std::size_t(sb[a]);
    m.x_node = add(m.x_node, scale(now.a[a], g->Na[a]));
    m.v_node = add(m.v_node, scale(at(v_, na), g->Na[a]));
    m.x_seg[a] = now.b[a];
    m.v_seg[a] = at(v_, nb);
  }
  m.triangle = now.tri_b;
  // SOFT = 2: k = 0.5 SLSFAC SF m1 m2 / (m1 + m2) / dt^2 (LS-DYNA Theory Manual, segment-based
  // contact), m1 and m2 the segments' masses, here the mean nodal mass of each segment's
  // corners: fixed for the pair, so that k does not jump when the contact point moves from
  // one feature to another (a jump at a fixed penetration makes energy).
  auto segmentMass = [&](const std::array<int32_t, 4>& seg) {
    const bool tri = seg[2] == seg[3];
    double sum = 0.0;
    for (std::size_t a = 0; a < (tri ? 3u : 4u); ++a) sum += mass_[std::size_t(seg[a])];
    return sum / (tri ? 3.0 : 4.0);
  };
  const double m_a = segmentMass(sa), m_b = segmentMass(sb);
  const double m_pair = m_a + m_b > 0.0 ? m_a * m_b / (m_a + m_b) : 0.0;
  // The same masses for the stability cap and the damping of penaltyForce: a cap from the
  // masses at the contact point would change k when the point moves to another feature.
  m.m_node = m_a;
  m.m_seg.fill(m_b);
  const double sf = std::min(p.check_k[k], p.seg_k[s]);
  const double stiffness = dt_stiff_ > 0.0 ? 0.5 * sf * m_pair / (dt_stiff_ * dt_stiff_) : 0.0;
  const Penetration found{check, int32_t(s), g->Nb, g->push, pen, g->side, entry};
  const auto& ci = model_.contacts[std::size_t(p.iface)];
  Record r =
      penaltyForce(found, m, stiffness, last ? last->friction : Vec3{}, ci, dt_stiff_, dt_prev);
  r.M = g->Na;
  // Friction and damping work of a new pair: its force acts from this cycle, over half of the
  // step before in the central-difference sense (the other half is booked when it ends:
  // bookEndedSegmentPairs); a full step booked here made energy at every new pair.
  if (!last) r.dissipated *= 0.5;
  return r;
}

void Contact::listInitialSegmentOverlaps(std::size_t pass) {
  // Every rank looks at every check of the pass, in check order. The overlaps stay as entry
  // offsets whatever IGNORE says (a pair found inside starts from its overlap: segmentPair).
  const Pass& p = passes_[pass];
  const auto& ci = model_.contacts[std::size_t(p.iface)];
  std::vector<int32_t> candidates;
  for (std::size_t k = 0; k < p.check_seg.size(); ++k) {
    const auto check = p.first_check + int32_t(k);
    candidates.clear();
    search_.collectCandidates(p, pass, check, 0.0, x_, candidates);
    for (const int32_t s : candidates) {
      const PairShape shape = pairShapeAt(p, k, std::size_t(s), x_);
      const auto g =
          shape.h > 0.0 ? shellPairGap(shape, 0, shape) : solidPairGap(shape, shape, false);
      const double ref = shape.h > 0.0 ? shape.h : p.seg_depth[std::size_t(s)];
      if (g && -g->gap > 1e-9 * ref)
        initial_.push_back(
            {ci.id,
             model_.nodes.size()
                 ? model_.nodes.id[std::size_t(cn_model_[std::size_t(p.check_seg[k][0])])]
                 : 0,
             -g->gap});
    }
  }
}

void Contact::applySegmentRecord(const Pass& p, const Record& r) {
  const auto& sa = p.check_seg[std::size_t(r.check - p.first_check)];
  const auto& sb = p.seg[std::size_t(r.segment)];
  // Added on every rank holding the node, in record order; a triangle's repeated corner has
  // weight 0 on its copy.
  for (std::size_t a = 0; a < 4; ++a) {
    if (r.M[a] != 0.0) addNodeForce(sa[a], scale(r.force, r.M[a]));
    if (r.N[a] != 0.0) addNodeForce(sb[a], segmentReaction(r, a));
  }
  edge_pairs_.push_back({r.check, r.segment, r.friction, r.entry, r.side, r.energy, r.dissipated});
}

}  // namespace crumple::contact
