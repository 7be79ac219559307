// Unit tests of the closest points of two beam axes (src/contact/geometry.hpp,
// closestEdgePoints), the geometry of beam-to-beam contact: crossing axes, clamping to the
// ends, parallel axes (the middle of the overlap, or the nearest ends), and the balance of the
// penalty force shared by the parameters (penalty.hpp). Expected values are derived in the
// comments.
#include <gtest/gtest.h>

#include "contact/geometry.hpp"
#include "contact/penalty.hpp"
#include "model/contact.hpp"

namespace {

using crumple::util::Vec3;
namespace contact = crumple::contact;

void expectPoints(const contact::EdgePoints& e, double s, double t) {
  EXPECT_NEAR(e.s, s, 1e-14);
  EXPECT_NEAR(e.t, t, 1e-14);
}

TEST(ContactEdges, CrossingAxesMeetAtTheirCommonPerpendicular) {
  // p along x from (0,0,0) to (2,0,0), q along y at z = 0.3 through x = 0.5: the common
  // perpendicular joins (0.5, 0, 0) (s = 0.25) and (0.5, 0, 0.3) (t = 0.5 of y in [-1, 1]).
  const auto e = contact::closestEdgePoints({0, 0, 0}, {2, 0, 0}, {0.5, -1, 0.3}, {0.5, 1, 0.3});
  expectPoints(e, 0.25, 0.5);
  EXPECT_NEAR(e.q[2] - e.p[2], 0.3, 1e-14);
}

TEST(ContactEdges, ClampsToTheEndsPastThem) {
  // q's axis passes over p's line at x = 3, beyond p's end (2, 0, 0): s = 1.5 clamped to 1,
  // and q's point nearest to (2, 0, 0) is (3, 0, 0.3), t = 0.5.
  const auto e = contact::closestEdgePoints({0, 0, 0}, {2, 0, 0}, {3, -1, 0.3}, {3, 1, 0.3});
  expectPoints(e, 1.0, 0.5);
  // The lines cross at (1, 0, 0), before q's start (t = -0.5): q from (1, 1, 0) to (1, 3, 0)
  // is clamped to t = 0, and p's point nearest to (1, 1, 0) is s = 0.5.
  const auto f = contact::closestEdgePoints({0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 3, 0});
  expectPoints(f, 0.5, 0.0);
}

TEST(ContactEdges, ParallelAxesTakeTheMiddleOfTheOverlap) {
  // q from x = 0 to 4 at z = 0.2; p from x = 1 to 2 lies over it: the overlap is [1, 2], its
  // middle x = 1.5: s = 0.5 on p, t = 1.5 / 4 = 0.375 on q.
  const auto a = contact::closestEdgePoints({1, 0, 0}, {2, 0, 0}, {0, 0, 0.2}, {4, 0, 0.2});
  expectPoints(a, 0.5, 0.375);
  // p from x = 3 to 5 reaches past q's end: the overlap [3, 4], middle 3.5: s = 0.25,
  // t = 0.875. Turned round (p from 5 to 3), s = 0.75.
  const auto b = contact::closestEdgePoints({3, 0, 0}, {5, 0, 0}, {0, 0, 0.2}, {4, 0, 0.2});
  expectPoints(b, 0.25, 0.875);
  const auto c = contact::closestEdgePoints({5, 0, 0}, {3, 0, 0}, {0, 0, 0.2}, {4, 0, 0.2});
  expectPoints(c, 0.75, 0.875);
  // No overlap: p from 5 to 6 is past q's end; the nearest ends are q's t = 1 and p's s = 0.
  const auto d = contact::closestEdgePoints({5, 0, 0}, {6, 0, 0}, {0, 0, 0.2}, {4, 0, 0.2});
  expectPoints(d, 0.0, 1.0);
  EXPECT_NEAR(crumple::util::norm(crumple::util::sub(d.p, d.q)), std::sqrt(1.0 + 0.04), 1e-14);
}

TEST(ContactEdges, SharedForceBalancesForceAndMoment) {
  // The force f at p's point goes to p's nodes as (1 - s) f and s f, the reaction -f to q's
  // nodes as (1 - t) and t: the four sum to zero, and so do their moments, the points lying on
  // the line of f.
  const Vec3 p0{0, 0, 0}, p1{2, 0, 0}, q0{0.5, -1, 0.3}, q1{0.5, 3, 0.3};
  const auto e = contact::closestEdgePoints(p0, p1, q0, q1);
  contact::Record r;
  r.N = {1.0 - e.t, e.t, 0.0, 0.0};
  r.force = {0.0, 0.0, -7.0};
  using crumple::util::add;
  using crumple::util::cross;
  using crumple::util::scale;
  const Vec3 f0 = scale(r.force, 1.0 - e.s), f1 = scale(r.force, e.s);
  const Vec3 g0 = contact::segmentReaction(r, 0), g1 = contact::segmentReaction(r, 1);
  const Vec3 sum = add(add(f0, f1), add(g0, g1));
  const Vec3 moment = add(add(cross(p0, f0), cross(p1, f1)), add(cross(q0, g0), cross(q1, g1)));
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(sum[i], 0.0, 1e-14);
    EXPECT_NEAR(moment[i], 0.0, 1e-13);
  }
}

}  // namespace
