// Unit tests of the 10-node tetrahedron (*SECTION_SOLID ELFORM 16, src/elements/tet10.cpp):
// the lumped mass, the patch test on a distorted mesh with curved edges, a rigid rotation, and
// the stable step against the highest frequency of an assembled mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "brick_model.hpp"
#include "domain/subdomain.hpp"
#include "elements/tet10.hpp"
#include "gather.hpp"
#include "model/model.hpp"
#include "patch_field.hpp"
#include "tet_brick.hpp"

namespace {

using crumple::model::Vec3;
using crumple::testing::tet10Brick;

constexpr double kE = 210.0, kNu = 0.3, kRho = 7.85e-6;

// Mid-side nodes moved off their edges: every element has curved edges.
Vec3 bow(const Vec3& x) {
  return {0.04 * std::sin(2.0 * x[1] + x[2]), 0.03 * std::cos(x[0] + 3.0 * x[2]),
          0.05 * std::sin(x[0] * x[1] + 1.0)};
}

crumple::domain::Tet10Block& onlyBlock(crumple::domain::Subdomain& sd) {
  EXPECT_TRUE(sd.solid_blocks.empty());
  return sd.tet10_blocks.at(0);
}

TEST(Tet10, ModelAndBlockKeepTenNodesPerElement) {
  const auto m = tet10Brick(1, 1, 1);
  // 8 corners and 19 edges (12 of the cube, 6 face diagonals, 1 body diagonal).
  EXPECT_EQ(m.nodes.size(), 27u);
  EXPECT_EQ(m.solidFormulation(0), 16);
  int32_t n[crumple::model::kMaxElementNodes];
  EXPECT_EQ(m.elementNodes(0, n), 10);
  auto sd = crumple::domain::buildSerialSubdomain(m);
  const auto& blk = onlyBlock(sd);
  EXPECT_EQ(blk.size(), 6u);
  for (int a = 0; a < 10; ++a) EXPECT_EQ(blk.conn[0][std::size_t(a)], n[a]) << a;
}

TEST(Tet10, LumpedMassIsPositiveAndConservesTheElementMass) {
  crumple::testing::BrickOptions opt;
  opt.position = crumple::testing::distortedPatchNode;
  const auto m = tet10Brick(2, 2, 2, opt, bow);
  auto sd = crumple::domain::buildSerialSubdomain(m);
  auto& blk = onlyBlock(sd);
  crumple::elements::resizeTet10Block(blk);
  std::vector<double> dt_e;
  const auto st = crumple::elements::initializeTet10(blk, sd.x0, sd.slots.data(), dt_e, {0.0, 0.0});
  EXPECT_LT(st.bad_elem, 0);
  double volume = 0.0;
  for (std::size_t e = 0; e < blk.size(); ++e) volume += blk.vol0[e];
  // The distorted 2 x 2 x 2 brick keeps its volume 8 (the interior moves inside it; the
  // bowed edges add and remove volume): only the total mass is checked against the volume.
  const auto mass = crumple::testing::gatheredForces(sd);
  double total = 0.0;
  for (std::size_t n = 0; n < sd.numNodes(); ++n) {
    EXPECT_GT(mass[3 * n], 0.0) << n;
    total += mass[3 * n];
  }
  EXPECT_NEAR(total, kRho * volume, 1e-14 * kRho * volume);
  // One element's shares: 1/36 at the corners, 4/27 at the mid-side nodes.
  const double* slot = sd.slots.data() + 3 * blk.slot_offset;
  for (int a = 0; a < 10; ++a)
    EXPECT_NEAR(slot[3 * a], kRho * blk.vol0[0] * (a < 4 ? 1.0 / 36 : 4.0 / 27), 1e-20) << a;
}

// Uniform strain on a distorted mesh (interior corners off the grid; with `curved`, every
// mid-side node off its edge too): the isoparametric quadratic field holds the linear velocity
// exactly, so every point's stress is the exact one (to 1e-10 of its size). Returns the
// largest force at the interior nodes (the centre corner (1,1,1) and the mid-side nodes of its
// edges), which balance where the rule integrates the element exactly.
double patchTest(bool curved) {
  crumple::testing::BrickOptions opt;
  opt.position = crumple::testing::distortedPatchNode;
  const auto m = curved ? tet10Brick(2, 2, 2, opt, bow) : tet10Brick(2, 2, 2, opt);
  auto sd = crumple::domain::buildSerialSubdomain(m);
  auto& blk = onlyBlock(sd);
  EXPECT_EQ(blk.size(), 48u);
  crumple::elements::resizeTet10Block(blk);
  std::vector<double> dt_e;
  crumple::elements::initializeTet10(blk, sd.x0, sd.slots.data(), dt_e, {0.0, 0.0});
  const double dt = 1e-2;
  crumple::testing::setPatchVelocity(sd, dt);
  crumple::elements::computeTet10Forces(blk, sd.x, sd.v, dt, {0.0, 0.0}, sd.slots.data(), 0,
                                        blk.size());
  const auto expect = crumple::testing::patchStress(kE, kNu, dt);
  double size = 0.0;
  for (double s : expect) size = std::max(size, std::abs(s));
  const std::size_t padded = blk.paddedSize();
  for (std::size_t e = 0; e < blk.size(); ++e)
    for (int k = 0; k < 6; ++k) {
      for (std::size_t q = 0; q < 4; ++q)
        EXPECT_NEAR(blk.sig_ip[std::size_t(k)][q * padded + e], expect[std::size_t(k)],
                    1e-10 * size)
            << curved << " " << e << " " << k << " " << q;
      EXPECT_NEAR(blk.sigAt(k, e), expect[std::size_t(k)], 1e-10 * size);
    }
  const auto f = crumple::testing::gatheredForces(sd);
  std::vector<int32_t> interior = {13};
  for (std::size_t e = 0; e < m.solids.size(); ++e)
    for (int k = 0; k < 6; ++k) {
      const auto& c = crumple::testing::kTet10Edges[k];
      if (m.solids.nodes[e][std::size_t(c[0])] == 13 || m.solids.nodes[e][std::size_t(c[1])] == 13)
        interior.push_back(m.solids.mid[e][std::size_t(k)]);
    }
  double worst = 0.0;
  for (int32_t n : interior)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(f[3 * std::size_t(n) + std::size_t(c)]));
  // Relative to sigma x a unit face.
  return worst / size;
}

// Straight edges: det J is constant in each element, the rule integrates grad N exactly and
// the interior forces balance to round-off.
TEST(Tet10Patch, UniformStrainIsExactAndInteriorForcesBalance) {
  EXPECT_LT(patchTest(false), 1e-10);
}

// Curved edges: the stress is still exact at every point; the interior forces balance only to
// the accuracy of the 4-point rule on cubic integrands (grad N det J), so they are reported,
// not held to round-off.
TEST(Tet10Patch, UniformStrainIsExactWithCurvedEdges) {
  const double imbalance = patchTest(true);
  std::printf("[ figure ] curved-edge patch: interior force imbalance / sigma = %.2e\n", imbalance);
  EXPECT_LT(imbalance, 1e-2);
}

// x(n) = R(theta_n) X: the mid-step rate of deformation of a rigid rotation is zero to
// round-off (the velocity gradient on the mid-step geometry is a Cayley transform, skew), so
// a quarter turn in 200 steps leaves the stress at zero.
TEST(Tet10, RigidRotationGivesNoStress) {
  crumple::testing::BrickOptions opt;
  opt.position = crumple::testing::distortedPatchNode;
  const auto m = tet10Brick(2, 1, 1, opt, bow);
  auto sd = crumple::domain::buildSerialSubdomain(m);
  auto& blk = onlyBlock(sd);
  crumple::elements::resizeTet10Block(blk);
  std::vector<double> dt_e;
  crumple::elements::initializeTet10(blk, sd.x0, sd.slots.data(), dt_e, {0.0, 0.0});
  // Rotation about the unit axis (1, 2, 2) / 3.
  const double ax[3] = {1.0 / 3, 2.0 / 3, 2.0 / 3};
  auto rotate = [&](double th, const double* p, double* out) {
    const double c = std::cos(th), s = std::sin(th);
    const double d = ax[0] * p[0] + ax[1] * p[1] + ax[2] * p[2];
    const double cr[3] = {ax[1] * p[2] - ax[2] * p[1], ax[2] * p[0] - ax[0] * p[2],
                          ax[0] * p[1] - ax[1] * p[0]};
    for (int i = 0; i < 3; ++i) out[i] = p[i] * c + cr[i] * s + ax[i] * d * (1 - c);
  };
  const int steps = 200;
  const double dt = 1e-3, dth = 0.5 * M_PI / steps;
  std::vector<double> prev = sd.x0;
  double worst = 0.0;
  for (int n = 1; n <= steps; ++n) {
    for (std::size_t i = 0; i < sd.numNodes(); ++i) rotate(n * dth, &sd.x0[3 * i], &sd.x[3 * i]);
    for (std::size_t i = 0; i < sd.x.size(); ++i) sd.v[i] = (sd.x[i] - prev[i]) / dt;
    prev = sd.x;
    const auto st = crumple::elements::computeTet10Forces(blk, sd.x, sd.v, dt, {0.0, 0.0},
                                                          sd.slots.data(), 0, blk.size());
    EXPECT_LT(st.bad_elem, 0);
    for (const auto& s : blk.sig_ip)
      for (std::size_t i = 0; i < 4 * blk.paddedSize(); ++i)
        worst = std::max(worst, std::abs(s[i]));
  }
  // The rotation's velocity gradient times E is 210 x 7.9 = 1.6e3 per unit time; round-off
  // leaves 1e-12 of the stress a strain of 1e-14 would give.
  EXPECT_LT(worst, 1e-12 * kE);
  std::printf("[ figure ] rigid quarter turn in %d steps: largest |stress| %.2e (E = %g)\n", steps,
              worst, kE);
}

// Highest circular frequency of the assembled mesh with the kernel's lumped masses: power
// iteration on M^-1 K, with K u taken from the kernel itself (the force of a small
// displacement u over one step from zero stress, no bulk viscosity).
double highestFrequency(crumple::domain::Subdomain& sd, crumple::domain::Tet10Block& blk,
                        const std::vector<double>& mass) {
  std::vector<double> u(sd.x0.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = std::sin(1.7 * double(i) + 0.3);
  const double scale = 1e-9;
  double lambda = 0.0;
  for (int it = 0; it < 1500; ++it) {
    for (auto& s : blk.sig_ip) std::fill(s.begin(), s.end(), 0.0);
    for (std::size_t i = 0; i < u.size(); ++i) {
      sd.v[i] = scale * u[i];
      sd.x[i] = sd.x0[i] + 0.5 * scale * u[i];
    }
    crumple::elements::computeTet10Forces(blk, sd.x, sd.v, 1.0, {0.0, 0.0}, sd.slots.data(), 0,
                                          blk.size());
    auto f = crumple::testing::gatheredForces(sd);
    double norm = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      f[i] = -f[i] / (scale * mass[3 * (i / 3)]);
      norm += f[i] * f[i];
    }
    lambda = std::sqrt(norm);
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = f[i] / lambda;
  }
  return std::sqrt(lambda);
}

// The step L / c with L = h_min / 4 (tet10.hpp): TSSFAC (0.9) times it stays below
// 2 / omega_max of a distorted mesh, compressible and nearly incompressible, and is not far
// below it (measured 0.6 to 0.8 of it).
TEST(Tet10, StableStepIsWithinTheHighestFrequency) {
  for (double nu : {0.3, 0.49}) {
    crumple::testing::BrickOptions opt;
    opt.law = crumple::materials::Elastic::Params{kE, nu};
    opt.position = [](int i, int j, int k) {
      return Vec3{i + 0.08 * std::sin(1.0 + j + 2.0 * k), j + 0.08 * std::cos(i + 0.5 * k),
                  k + 0.05 * std::sin(2.0 * i + j)};
    };
    const auto m = tet10Brick(2, 2, 1, opt);
    auto sd = crumple::domain::buildSerialSubdomain(m);
    auto& blk = onlyBlock(sd);
    crumple::elements::resizeTet10Block(blk);
    std::vector<double> dt_e;
    const auto st =
        crumple::elements::initializeTet10(blk, sd.x0, sd.slots.data(), dt_e, {0.0, 0.0});
    const auto mass = crumple::testing::gatheredForces(sd);
    const double critical = 2.0 / highestFrequency(sd, blk, mass);
    EXPECT_LT(0.9 * st.dt_min, critical) << nu;
    EXPECT_GT(st.dt_min, 0.5 * critical) << nu;
    std::printf("[ figure ] 10-node tetrahedra, nu = %.2f: L / c over 2 / omega_max = %.3f\n", nu,
                st.dt_min / critical);
  }
}

}  // namespace
