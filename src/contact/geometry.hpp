// Where a node lies relative to a contact segment: the closest point of the segment, its
// shape-function weights and the normal there. Shared by the search and the force kernel.
#pragma once

#include <array>

#include "util/vec3.hpp"

namespace crumple::contact {

using util::add;
using util::cross;
using util::dot;
using util::norm;
using util::scale;
using util::sub;
using util::Vec3;

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
                   bool triangle, double tolerance = 0.02);

}  // namespace crumple::contact
