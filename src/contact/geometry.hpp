// Where a node lies relative to a contact segment: the closest point of the segment, its
// shape-function weights and the normal there, and the contact surface the segment offers the
// node (docs/theory.md, "Node against segment"). Shared by the search and the force kernel.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "util/vec3.hpp"

namespace crumple::contact {

using util::add;
using util::cross;
using util::dot;
using util::norm;
using util::scale;
using util::sub;
using util::Vec3;

// Parametric tolerance of "the node is over the segment" (see project).
constexpr double kInsideTolerance = 0.02;

// Node i of an array of 3 doubles per node.
inline Vec3 at(const std::vector<double>& a, std::size_t i) {
  return {a[3 * i], a[3 * i + 1], a[3 * i + 2]};
}

struct Projection {
  std::array<double, 4> N{};  // weights of the segment nodes at the closest point
  Vec3 point{};               // closest point
  Vec3 normal{};              // unit normal of the segment there (segment orientation)
  double d = 0.0;             // signed distance of the node along `normal`
  bool inside = false;        // the node projects onto the segment (within the tolerance)
};

// Projection of p onto the quadrilateral x0..x3 (bilinear, Hallquist's isoparametric
// segment; a triangle when `triangle`, x3 == x2). `tolerance` widens the parametric range so
// that a node over the common edge of two segments is caught by both (DYNA3D does the same
// to keep nodes from slipping between segments).
Projection project(const Vec3& p, const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3,
                   bool triangle, double tolerance = kInsideTolerance);

// Unit normal of the segment x0..x3 along its diagonals, (x2 - x0) x (x3 - x1); zero for a
// degenerate segment.
inline Vec3 segmentNormal(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  const Vec3 c = cross(sub(x2, x0), sub(x3, x1));
  const double len = norm(c);
  return len > 0.0 ? scale(c, 1.0 / len) : Vec3{};
}

// The contact surface of one segment as one node sees it.
struct SurfaceGap {
  double gap = 0.0;  // distance of the node from the surface; negative: penetration
  Vec3 push{};       // unit direction the node is pushed out
  int side = 1;      // shells: the side of the mid-surface the node is on (along the normal)
};

// A solid face: one-sided, along the outward normal, offset by the node's half shell
// thickness h_node. A node deeper than half the element under the face (`depth`) is on the
// far side of something else: no contact.
inline std::optional<SurfaceGap> solidFaceGap(const Projection& pr, double h_node, double depth) {
  SurfaceGap g{pr.d - h_node, pr.normal, 1};
  if (!(g.gap > -0.5 * depth)) return std::nullopt;
  return g;
}

// A shell, the node over the segment: both sides are surfaces, offset from the mid-surface by
// h, the sum of the node's and the segment's half thicknesses. `side` is the side the node is
// on (the search's choice, from its history); a node through the whole contact thickness is
// not this sheet's: no contact.
inline std::optional<SurfaceGap> shellFaceGap(const Projection& pr, double h, int side) {
  const double ds = side * pr.d;
  if (ds < -h) return std::nullopt;
  return SurfaceGap{ds - h, scale(pr.normal, double(side)), side};
}

// A shell, the node beyond the segment's edge (a free edge, the outside of a fold): the
// surface is rounded, the node keeps the distance h from the nearest point of the segment, so
// that nodes cannot slip past edges and ridges into the contact thickness of the next one.
inline std::optional<SurfaceGap> shellEdgeGap(const Vec3& x, const Projection& pr, double h) {
  const Vec3 r = sub(x, pr.point);
  const double dist = norm(r);
  if (!(dist < h) || !(dist > 0.0)) return std::nullopt;
  return SurfaceGap{dist - h, scale(r, 1.0 / dist), dot(r, pr.normal) >= 0.0 ? 1 : -1};
}

// The closest points of two segments p0-p1 and q0-q1 (beam axes): p0 + s (p1 - p0) and
// q0 + t (q1 - q0), s and t in [0, 1] (the classic segment-segment problem, the minimum of
// |p(s) - q(t)|^2 with clamping to the ends: Lumelsky 1985, "On fast computation of distance
// between line segments", Inf. Proc. Letters 21; Ericson 2005, "Real-Time Collision
// Detection", 5.1.9). Parallel axes have a line of closest points: the middle of the part of
// p's axis over q's is taken, so that two beams lying along each other share the force evenly
// between their nodes; without overlap, the nearest ends.
struct EdgePoints {
  double s = 0.0, t = 0.0;  // parameters on p and q
  Vec3 p{}, q{};            // the points
};
EdgePoints closestEdgePoints(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);

}  // namespace crumple::contact

namespace crumple::contact {

// The closest points of two contact segments a and b (four corners each; a triangle repeats
// its third), each split into the triangles (0, 1, 2) and (0, 2, 3): the smallest of the
// vertex-triangle and edge-edge distances of every triangle pair (Ericson 2005, "Real-Time
// Collision Detection", 5.1.5 and 5.1.9), so a warped quad is two planar triangles. Weights
// Na, Nb on the corners give the points (sum 1). Ties go to the first feature found (vertices
// of a, of b, then edges), so the result is the same bits every time. Segments whose
// triangles intersect get the distance of their nearest features, not 0: a caller keeps
// their history (the side they came from).
struct SegmentPoints {
  std::array<double, 4> Na{}, Nb{};
  Vec3 p{}, q{};
  double dist = 0.0;
};
SegmentPoints closestSegmentPoints(const std::array<Vec3, 4>& a, bool tri_a,
                                   const std::array<Vec3, 4>& b, bool tri_b);

}  // namespace crumple::contact
