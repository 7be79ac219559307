// Unit tests of one node against one segment (src/contact/geometry.hpp, penalty.hpp): the
// contact surface (solid face, shell offset by half thicknesses, rounded shell edge) and the
// penalty force (k p along the normal, reactions -N_a f in force and moment balance, Coulomb
// friction capped at mu f_n against the slip, VDC damping, SOFT = 1 and the stability cap).
// Every expected value is derived by hand in the comments.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "contact/geometry.hpp"
#include "contact/penalty.hpp"
#include "model/contact.hpp"

namespace {

using crumple::contact::NodeAndSegment;
using crumple::contact::Penetration;
using crumple::contact::Projection;
using crumple::contact::Record;
using crumple::contact::SurfaceGap;
using crumple::util::Vec3;

namespace contact = crumple::contact;

// The unit square in z = 0, nodes counter-clockwise seen from +z: its normal
// (x2 - x0) x (x3 - x1) = (1, 1, 0) x (-1, 1, 0) = (0, 0, 2) points to +z.
constexpr std::array<Vec3, 4> kSquare = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0},
                                         Vec3{0, 1, 0}};
// Last step; node and segment nodes of unit mass: m_seg = sum N_a = 1, m* = 1 x 1 / 2 = 0.5,
// and the stability cap 0.1 m* / dt^2 = 5e4 is above the stiffnesses used but in the cap test.
constexpr double kDt = 1e-3;

NodeAndSegment still(const Vec3& x_node) {
  NodeAndSegment m;
  m.x_node = x_node;
  m.m_node = 1.0;
  m.x_seg = kSquare;
  m.m_seg = {1.0, 1.0, 1.0, 1.0};
  return m;
}

Projection onSquare(const Vec3& x) {
  return contact::project(x, kSquare[0], kSquare[1], kSquare[2], kSquare[3], false);
}

// The force of a node found at `gap` (< 0) from the surface, as Contact::computeForces makes it.
Record force(const Projection& pr, const SurfaceGap& g, const NodeAndSegment& m, double k,
             const crumple::model::ContactInterface& ci, const Vec3& friction = {},
             double dt_stiff = kDt) {
  const Penetration p{7, 3, pr.N, g.push, -g.gap, int8_t(g.side), 0.0};
  return contact::penaltyForce(p, m, k, friction, ci, dt_stiff, kDt);
}

void expectVec(const Vec3& a, const Vec3& b, double tol = 1e-12) {
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << "component " << i;
}

// Sum of the forces and of their moments about the origin on node and segment nodes.
void expectBalanced(const Record& r, const NodeAndSegment& m) {
  Vec3 f = r.force;
  Vec3 moment = crumple::util::cross(m.x_node, r.force);
  for (std::size_t a = 0; a < 4; ++a) {
    const Vec3 fa = contact::segmentReaction(r, a);
    f = crumple::util::add(f, fa);
    moment = crumple::util::add(moment, crumple::util::cross(m.x_seg[a], fa));
  }
  expectVec(f, {0, 0, 0});
  expectVec(moment, {0, 0, 0});
}

TEST(ContactPenalty, SolidFaceForceIsStiffnessTimesPenetrationAlongNormal) {
  // Node at (0.25, 0.25, -0.01): xi = eta = -0.5, N_a = (1 +- 0.5)(1 +- 0.5) / 4, so
  // N = (0.5625, 0.1875, 0.0625, 0.1875), and 0.01 under the face. k = 1000: f = 10 along +z,
  // energy 1000 x 0.01^2 / 2 = 0.05.
  const Vec3 x{0.25, 0.25, -0.01};
  const Projection pr = onSquare(x);
  ASSERT_TRUE(pr.inside);
  const auto g = contact::solidFaceGap(pr, 0.0, 1.0);
  ASSERT_TRUE(g);
  EXPECT_NEAR(g->gap, -0.01, 1e-15);
  const NodeAndSegment m = still(x);
  const Record r = force(pr, *g, m, 1000.0, {});
  EXPECT_EQ(r.check, 7);
  EXPECT_EQ(r.segment, 3);
  expectVec(r.force, {0, 0, 10});
  EXPECT_NEAR(r.penetration, 0.01, 1e-15);
  EXPECT_NEAR(r.energy, 0.05, 1e-14);
  EXPECT_EQ(r.dissipated, 0.0);
  // Reactions -N_a f.
  expectVec(contact::segmentReaction(r, 0), {0, 0, -5.625});
  expectVec(contact::segmentReaction(r, 1), {0, 0, -1.875});
  expectVec(contact::segmentReaction(r, 2), {0, 0, -0.625});
  expectVec(contact::segmentReaction(r, 3), {0, 0, -1.875});
  // Moments about the origin: node (0.25, 0.25, -0.01) x (0, 0, 10) = (2.5, -2.5, 0); segment
  // (1, 0, 0) x (0, 0, -1.875) + (1, 1, 0) x (0, 0, -0.625) + (0, 1, 0) x (0, 0, -1.875)
  // = (0, 1.875, 0) + (-0.625, 0.625, 0) + (-1.875, 0, 0) = (-2.5, 2.5, 0).
  expectBalanced(r, m);
}

TEST(ContactPenalty, SolidFaceTakesNodeHalfThicknessAndRefusesTheFarSide) {
  // A shell node (half thickness 0.05) 0.03 above a solid face touches it 0.02 deep.
  const Projection above = onSquare({0.5, 0.5, 0.03});
  const auto g = contact::solidFaceGap(above, 0.05, 1.0);
  ASSERT_TRUE(g);
  EXPECT_NEAR(g->gap, -0.02, 1e-15);
  expectVec(g->push, {0, 0, 1});
  // Deeper than half the element under the face (depth 1): on the far side of something else.
  EXPECT_FALSE(contact::solidFaceGap(onSquare({0.5, 0.5, -0.6}), 0.0, 1.0));
  EXPECT_TRUE(contact::solidFaceGap(onSquare({0.5, 0.5, -0.4}), 0.0, 1.0));
}

TEST(ContactPenalty, ShellSurfaceIsAtHalfTheThicknesses) {
  // Segment thickness 0.2 and node shell thickness 0.1: the contact surfaces lie
  // h = 0.1 + 0.05 = 0.15 either side of the mid-surface.
  const double h = 0.15;
  // 0.1 above: gap 0.1 - 0.15 = -0.05, pushed up; k = 1000 gives 50 along +z.
  const Vec3 x_up{0.5, 0.5, 0.1};
  const Projection up = onSquare(x_up);
  const auto g_up = contact::shellFaceGap(up, h, 1);
  ASSERT_TRUE(g_up);
  EXPECT_NEAR(g_up->gap, -0.05, 1e-15);
  const Record r = force(up, *g_up, still(x_up), 1000.0, {});
  expectVec(r.force, {0, 0, 50}, 1e-11);
  EXPECT_EQ(r.side, 1);
  expectBalanced(r, still(x_up));
  // 0.12 below, on the lower side: gap 0.12 - 0.15 = -0.03, pushed down.
  const auto g_down = contact::shellFaceGap(onSquare({0.5, 0.5, -0.12}), h, -1);
  ASSERT_TRUE(g_down);
  EXPECT_NEAR(g_down->gap, -0.03, 1e-15);
  expectVec(g_down->push, {0, 0, -1});
  EXPECT_EQ(g_down->side, -1);
  // 0.2 above: clear by 0.05.
  const auto clear = contact::shellFaceGap(onSquare({0.5, 0.5, 0.2}), h, 1);
  ASSERT_TRUE(clear);
  EXPECT_NEAR(clear->gap, 0.05, 1e-15);
  // On the upper side but 0.16 below the mid-surface: through the whole contact thickness.
  EXPECT_FALSE(contact::shellFaceGap(onSquare({0.5, 0.5, -0.16}), h, 1));
}

TEST(ContactPenalty, ShellEdgeIsRounded) {
  // h = 0.6. The node (1.3, 0.25, 0.4) is beyond the edge x = 1: its nearest point of the
  // segment is (1, 0.25, 0) (xi = 1, eta = -0.5: N1 = 0.75, N2 = 0.25), r = (0.3, 0, 0.4),
  // |r| = 0.5: gap 0.5 - 0.6 = -0.1, push r / |r| = (0.6, 0, 0.8); k = 1000 gives 100 along
  // it, (60, 0, 80).
  const Vec3 x{1.3, 0.25, 0.4};
  const Projection pr = onSquare(x);
  ASSERT_FALSE(pr.inside);
  expectVec(pr.point, {1, 0.25, 0});
  const auto g = contact::shellEdgeGap(x, pr, 0.6);
  ASSERT_TRUE(g);
  EXPECT_NEAR(g->gap, -0.1, 1e-15);
  expectVec(g->push, {0.6, 0, 0.8}, 1e-15);
  EXPECT_EQ(g->side, 1);
  const Record r = force(pr, *g, still(x), 1000.0, {});
  expectVec(r.force, {60, 0, 80}, 1e-11);
  expectVec(contact::segmentReaction(r, 1), {-45, 0, -60}, 1e-11);
  expectVec(contact::segmentReaction(r, 2), {-15, 0, -20}, 1e-11);
  expectVec(contact::segmentReaction(r, 0), {0, 0, 0});
  // The node lies on the line through the contact point along the push: moments balance.
  expectBalanced(r, still(x));
  // Below the plane and beyond the edge: pushed down and out, side -1.
  const Vec3 below{1.3, 0.5, -0.4};
  const auto g_below = contact::shellEdgeGap(below, onSquare(below), 0.6);
  ASSERT_TRUE(g_below);
  expectVec(g_below->push, {0.6, 0, -0.8}, 1e-15);
  EXPECT_EQ(g_below->side, -1);
  // 0.6 or more from the edge: no contact (r = (0.6, 0, 0.8), |r| = 1).
  const Vec3 far{1.6, 0.5, 0.8};
  EXPECT_FALSE(contact::shellEdgeGap(far, onSquare(far), 0.6));
}

TEST(ContactPenalty, CoulombFrictionSticksThenSlidesAgainstTheSlip) {
  // The node 0.01 in a solid face: k = 1000, f_n = 10; FS = FD = 0.3: the cap is mu f_n = 3.
  crumple::model::ContactInterface ci;
  ci.fs = ci.fd = 0.3;
  const Vec3 x{0.5, 0.5, -0.01};
  const Projection pr = onSquare(x);
  const auto g = contact::solidFaceGap(pr, 0.0, 1.0);
  ASSERT_TRUE(g);
  // Stick: slip (2, 0, 0) over dt = 1e-3 grows the tangential force by k v dt = (-2, 0, 0),
  // under the cap.
  NodeAndSegment m = still(x);
  m.v_node = {2, 0, 0};
  Record r = force(pr, *g, m, 1000.0, ci);
  expectVec(r.friction, {-2, 0, 0}, 1e-12);
  expectVec(r.force, {-2, 0, 10}, 1e-12);
  // Slide: slip velocity (3, 4, 0), |v_t| = 5: k v dt = 5 > 3, so the force is 3 against the
  // slip, -(0.6, 0.8, 0) x 3 = (-1.8, -2.4, 0); it dissipates mu f_n |v_t| dt = 3 x 5 x 1e-3.
  m.v_node = {3, 4, 0};
  r = force(pr, *g, m, 1000.0, ci);
  expectVec(r.friction, {-1.8, -2.4, 0}, 1e-12);
  expectVec(r.force, {-1.8, -2.4, 10}, 1e-12);
  EXPECT_NEAR(r.dissipated, 0.015, 1e-15);
  // The slip is relative: the segment moving with the node leaves no friction.
  m.v_seg = {Vec3{3, 4, 0}, Vec3{3, 4, 0}, Vec3{3, 4, 0}, Vec3{3, 4, 0}};
  r = force(pr, *g, m, 1000.0, ci);
  expectVec(r.friction, {0, 0, 0});
  // The stick history carries over, less any normal part: (-1, 0, 5) becomes (-1, 0, 0).
  r = force(pr, *g, m, 1000.0, ci, {-1, 0, 5});
  expectVec(r.friction, {-1, 0, 0}, 1e-12);
  // mu decays with the slip speed: FS = 0.5, FD = 0.3, DC = 1 at |v_t| = 5 gives
  // mu = 0.3 + 0.2 e^-5, and the sliding force is mu x 10.
  ci.fs = 0.5;
  ci.dc = 1.0;
  m.v_seg = {};
  r = force(pr, *g, m, 1000.0, ci);
  EXPECT_NEAR(crumple::util::norm(r.friction), (0.3 + 0.2 * std::exp(-5.0)) * 10.0, 1e-12);
}

TEST(ContactPenalty, ViscousDampingIsFractionOfCritical) {
  // k = 800, m* = 0.5: critical 2 sqrt(k m*) = 2 x 20 = 40; VDC = 20 % gives c = 8. The node
  // 0.01 deep approaching at 2 (v_n = -2 along the push +z): f_n = 800 x 0.01 + 8 x 2 = 24.
  crumple::model::ContactInterface ci;
  ci.vdc = 20.0;
  const Vec3 x{0.5, 0.5, -0.01};
  const Projection pr = onSquare(x);
  const auto g = contact::solidFaceGap(pr, 0.0, 1.0);
  ASSERT_TRUE(g);
  NodeAndSegment m = still(x);
  m.v_node = {0, 0, -2};
  Record r = force(pr, *g, m, 800.0, ci);
  expectVec(r.force, {0, 0, 24}, 1e-12);
  // The damping part, 16, over dt at v_n = -2 dissipates 16 x 2 x 1e-3 = c v_n^2 dt.
  EXPECT_NEAR(r.dissipated, 0.032, 1e-15);
  // The spring energy does not include the damping.
  EXPECT_NEAR(r.energy, 0.5 * 800.0 * 1e-4, 1e-15);
  // Separating at 5: 8 - 40 < 0, so no force (contact does not pull).
  m.v_node = {0, 0, 5};
  r = force(pr, *g, m, 800.0, ci);
  expectVec(r.force, {0, 0, 0});
  // Approach is relative to the segment's contact point: both moving together, no damping.
  m.v_node = {0, 0, -2};
  m.v_seg = {Vec3{0, 0, -2}, Vec3{0, 0, -2}, Vec3{0, 0, -2}, Vec3{0, 0, -2}};
  r = force(pr, *g, m, 800.0, ci);
  expectVec(r.force, {0, 0, 8}, 1e-12);
}

TEST(ContactPenalty, SoftStiffnessAndStabilityCap) {
  const Vec3 x{0.5, 0.5, -0.01};
  const Projection pr = onSquare(x);
  const auto g = contact::solidFaceGap(pr, 0.0, 1.0);
  ASSERT_TRUE(g);
  // k = 1e6 is capped at 0.1 m* / dt^2 = 0.1 x 0.5 / 1e-6 = 5e4: f = 5e4 x 0.01 = 500.
  Record r = force(pr, *g, still(x), 1e6, {});
  expectVec(r.force, {0, 0, 500}, 1e-9);
  // SOFT = 1, SOFSCL 0.1, first step 1e-3: k = max(1000, 0.5 x 0.1 x 0.5 / 1e-6 = 2.5e4).
  crumple::model::ContactInterface ci;
  ci.soft = 1;
  ci.sofscl = 0.1;
  r = force(pr, *g, still(x), 1000.0, ci, {}, 1e-3);
  expectVec(r.force, {0, 0, 250}, 1e-9);
}

TEST(ContactPenalty, StabilityCapFollowsTheStiffnessStepNotTheLastStep) {
  // The step fell tenfold since the stiffness step (an element crushed elsewhere): the cap
  // stays 0.1 m* / dt_stiff^2 = 5e4, where the last step would have allowed 5e6 and
  // multiplied the force of the penetration already there a hundredfold in one cycle.
  const Vec3 x{0.5, 0.5, -0.01};
  const Projection pr = onSquare(x);
  const auto g = contact::solidFaceGap(pr, 0.0, 1.0);
  ASSERT_TRUE(g);
  const Penetration p{7, 3, pr.N, g->push, -g->gap, int8_t(g->side), 0.0};
  const Record r = contact::penaltyForce(p, still(x), 1e9, {}, {}, kDt, 0.1 * kDt);
  expectVec(r.force, {0, 0, 500}, 1e-9);
  EXPECT_NEAR(r.energy, 0.5 * 5e4 * 0.01 * 0.01, 1e-12);
  // Ties likewise.
  const Record t =
      contact::tiedForce(4, 2, {0.25, 0.25, 0.25, 0.25}, 0.0, still(x), 1e9, {}, kDt, 0.1 * kDt);
  expectVec(t.force, {0, 0, 0.01 * 0.1 * 0.5 / (kDt * kDt) * 1.0}, 1e-6);
}

TEST(ContactPenalty, TiedNodeIsPulledToItsPoint) {
  // Node 0.01 above the centre of the square, tied to the centre (N_a = 0.25): the spring
  // k = 1000 pulls it back with (0, 0, -10); the segment nodes take 2.5 each, up.
  const Vec3 x{0.5, 0.5, 0.01};
  const NodeAndSegment m = still(x);
  const Record r = contact::tiedForce(4, 2, {0.25, 0.25, 0.25, 0.25}, 0.0, m, 1000.0, {}, kDt, kDt);
  expectVec(r.force, {0, 0, -10}, 1e-12);
  EXPECT_NEAR(r.penetration, 0.01, 1e-15);
  EXPECT_NEAR(r.energy, 0.05, 1e-14);
  expectVec(contact::segmentReaction(r, 3), {0, 0, 2.5}, 1e-12);
  expectBalanced(r, m);
  // Tied with its offset 0.01 along the normal: no force.
  const Record offset =
      contact::tiedForce(4, 2, {0.25, 0.25, 0.25, 0.25}, 0.01, m, 1000.0, {}, kDt, kDt);
  expectVec(offset.force, {0, 0, 0}, 1e-12);
}

TEST(ContactPenalty, RecordTravelsAsTwentyNineDoublesInFieldOrder) {
  Record r;
  r.check = 12;
  r.segment = 5;
  r.N = {0.1, 0.2, 0.3, 0.4};
  r.force = {1, 2, 3};
  r.friction = {4, 5, 6};
  r.penetration = 0.5;
  r.energy = 0.25;
  r.dissipated = 0.125;
  r.side = -1;
  r.entry = 0.0625;
  r.edge_s = 0.75;
  r.M = {0.7, 0.1, 0.1, 0.1};
  r.moment = {7, 8, 9};
  r.arm = {-7, -8, -9};
  r.released = 1;
  std::vector<double> wire;
  contact::pack(r, wire);
  ASSERT_EQ(wire.size(), contact::kRecordDoubles);
  EXPECT_EQ(contact::kRecordDoubles, 29u);
  EXPECT_EQ(wire, (std::vector<double>{12,  5,   0.1, 0.2,  0.3,   0.4, 1,      2,    3,   4,
                                       5,   6,   0.5, 0.25, 0.125, -1,  0.0625, 0.75, 0.7, 0.1,
                                       0.1, 0.1, 7,   8,    9,     -7,  -8,     -9,   1}));
  const Record back = contact::unpack(wire.data());
  EXPECT_EQ(back.check, 12);
  EXPECT_EQ(back.segment, 5);
  EXPECT_EQ(back.N, r.N);
  EXPECT_EQ(back.force, r.force);
  EXPECT_EQ(back.friction, r.friction);
  EXPECT_EQ(back.side, -1);
  EXPECT_EQ(back.M, r.M);
  EXPECT_EQ(back.entry, 0.0625);
  EXPECT_EQ(back.edge_s, 0.75);
  EXPECT_EQ(back.moment, r.moment);
  EXPECT_EQ(back.arm, r.arm);
  EXPECT_EQ(back.released, 1);
}

}  // namespace
