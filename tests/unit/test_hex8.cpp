// Unit tests of the one-point hexahedron: its volume gradient, the patch test (uniform strain
// reproduced exactly on a distorted mesh, interior forces in balance, no hourglass work) and
// objectivity under a finite rigid rotation.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <span>

#include "brick_model.hpp"
#include "domain/subdomain.hpp"
#include "elements/hex8.hpp"
#include "gather.hpp"
#include "model/model.hpp"

namespace {

using crumple::elements::kBatch;
using crumple::elements::NodalBatch;

constexpr double kNatural[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

// dV/dx_a by 2x2x2 Gauss quadrature of det(J) dN_a/dx: exact for a trilinear hexahedron.
void quadratureGradient(const double x[8][3], double b[8][3], double& vol) {
  const double g = 1.0 / std::sqrt(3.0);
  vol = 0.0;
  for (auto& r : std::span<double[3]>(b, 8)) r[0] = r[1] = r[2] = 0.0;
  for (double xi : {-g, g})
    for (double eta : {-g, g})
      for (double zeta : {-g, g}) {
        double dn[8][3];
        for (int a = 0; a < 8; ++a) {
          const double* n = kNatural[a];
          dn[a][0] = n[0] * (1 + n[1] * eta) * (1 + n[2] * zeta) / 8;
          dn[a][1] = (1 + n[0] * xi) * n[1] * (1 + n[2] * zeta) / 8;
          dn[a][2] = (1 + n[0] * xi) * (1 + n[1] * eta) * n[2] / 8;
        }
        double J[3][3] = {};
        for (int a = 0; a < 8; ++a)
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) J[i][j] += dn[a][i] * x[a][j];
        const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                           J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                           J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
        double inv[3][3];
        inv[0][0] = (J[1][1] * J[2][2] - J[1][2] * J[2][1]) / det;
        inv[0][1] = (J[0][2] * J[2][1] - J[0][1] * J[2][2]) / det;
        inv[0][2] = (J[0][1] * J[1][2] - J[0][2] * J[1][1]) / det;
        inv[1][0] = (J[1][2] * J[2][0] - J[1][0] * J[2][2]) / det;
        inv[1][1] = (J[0][0] * J[2][2] - J[0][2] * J[2][0]) / det;
        inv[1][2] = (J[0][2] * J[1][0] - J[0][0] * J[1][2]) / det;
        inv[2][0] = (J[1][0] * J[2][1] - J[1][1] * J[2][0]) / det;
        inv[2][1] = (J[0][1] * J[2][0] - J[0][0] * J[2][1]) / det;
        inv[2][2] = (J[0][0] * J[1][1] - J[0][1] * J[1][0]) / det;
        vol += det;
        // dN/dx_j = sum_i inv(J)_ji dN/dxi_i
        for (int a = 0; a < 8; ++a)
          for (int j = 0; j < 3; ++j) {
            double s = 0.0;
            for (int i = 0; i < 3; ++i) s += inv[j][i] * dn[a][i];
            b[a][j] += det * s;
          }
      }
}

TEST(Hex8, VolumeGradientMatchesExactQuadrature) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.12);
  NodalBatch xb, bb;
  double x[kBatch][8][3];
  for (int l = 0; l < kBatch; ++l)
    for (int a = 0; a < 8; ++a)
      for (int c = 0; c < 3; ++c) {
        const double scale[3] = {2.0, 1.0, 3.0};
        x[l][a][c] = 0.5 * (kNatural[a][c] + 1.0) * scale[c] + noise(rng);
        xb[c][a][l] = x[l][a][c];
      }
  crumple::elements::volumeGradient(xb, bb);
  for (int l = 0; l < kBatch; ++l) {
    double b[8][3], vol;
    quadratureGradient(x[l], b, vol);
    double v_from_b = 0.0;
    for (int a = 0; a < 8; ++a)
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(bb[c][a][l], b[a][c], 1e-13);
        v_from_b += x[l][a][c] * bb[c][a][l];
      }
    // The volume is homogeneous of degree one in each coordinate direction: V = x . B / 3.
    EXPECT_NEAR(v_from_b / 3.0, vol, 1e-13);
  }
}

// A 2x2x2 block of unit-ish hexes whose centre node is moved off-centre (distorted mesh).
crumple::model::Model distortedBlock(int ihq) {
  crumple::testing::BrickOptions opt;
  opt.ihq = ihq;
  opt.qh = 0.1;
  opt.position = [](int i, int j, int k) {
    if (i == 1 && j == 1 && k == 1) return crumple::model::Vec3{1.17, 0.91, 1.08};
    if (i == 1 && j == 0 && k == 1) return crumple::model::Vec3{1.1, 0.0, 0.93};
    return crumple::model::Vec3{double(i), double(j), double(k)};
  };
  return crumple::testing::brickModel(2, 2, 2, opt);
}

// The patch-test field: linear velocity v = G x (stretch, shear and spin), over a step dt.
constexpr double G[3][3] = {{1e-3, 4e-4, -2e-4}, {-1e-4, -3e-4, 5e-4}, {3e-4, 2e-4, 6e-4}};

// Sets v = G x0 and the geometry at the end of the step, x = x0 + dt v / 2, so that the
// mid-step geometry is x0.
void imposeLinearField(crumple::domain::Subdomain& sd, double dt) {
  for (std::size_t n = 0; n < sd.numNodes(); ++n)
    for (int i = 0; i < 3; ++i) {
      double v = 0.0;
      for (int j = 0; j < 3; ++j) v += G[i][j] * sd.x0[3 * n + j];
      sd.v[3 * n + i] = v;
    }
  for (std::size_t i = 0; i < sd.x.size(); ++i) sd.x[i] = sd.x0[i] + 0.5 * dt * sd.v[i];
}

class Hex8Patch : public ::testing::TestWithParam<int> {};

TEST_P(Hex8Patch, UniformStrainIsExactAndInteriorForcesBalance) {
  const auto m = distortedBlock(GetParam());
  auto sd = crumple::domain::buildSerialSubdomain(m);
  auto& blk = sd.solid_blocks.at(0);
  std::vector<double> dt_e;
  crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {});
  const double dt = 1e-2;
  imposeLinearField(sd, dt);
  crumple::elements::BulkViscosity bv{0.0, 0.0};
  crumple::elements::computeSolidForces(blk, sd.x, sd.v, dt, bv, sd.slots.data());

  // Every element carries the same stress: the strain of a linear field is exact.
  for (int k = 0; k < 6; ++k)
    for (std::size_t e = 1; e < blk.size(); ++e)
      EXPECT_NEAR(blk.sigAt(k, e), blk.sigAt(k, 0), 1e-12 * std::abs(blk.sigAt(0, 0))) << k;
  // Expected stress: lambda tr(D dt) I + 2 mu D dt (the Jaumann term vanishes from zero stress).
  const double E = 210.0, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double tr = (G[0][0] + G[1][1] + G[2][2]) * dt;
  EXPECT_NEAR(blk.sigAt(0, 0), lambda * tr + 2 * mu * G[0][0] * dt, 1e-12);
  EXPECT_NEAR(blk.sigAt(3, 0), mu * (G[0][1] + G[1][0]) * dt, 1e-12);
  // No hourglass work for a linear field on the FB-projected forms.
  if (GetParam() >= 2) {
    for (std::size_t e = 0; e < blk.size(); ++e) EXPECT_NEAR(blk.e_hg[e], 0.0, 1e-20);
  }

  // Gather and check the interior node (13) is in equilibrium.
  const auto f = crumple::testing::gatheredForces(sd);
  const double scale = std::abs(blk.sigAt(0, 0));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[3 * 13 + c], 0.0, 1e-13 * scale) << c;
}

INSTANTIATE_TEST_SUITE_P(HourglassTypes, Hex8Patch, ::testing::Values(2, 3, 4, 5));

TEST(Hex8, FiniteRigidRotationProducesNoStress) {
  const auto m = distortedBlock(4);
  auto sd = crumple::domain::buildSerialSubdomain(m);
  auto& blk = sd.solid_blocks.at(0);
  std::vector<double> dt_e;
  crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {});
  crumple::elements::BulkViscosity bv;
  // Rotate the block by 90 degrees about a skew axis in 200 steps; velocities are chosen so
  // that positions follow the exact rotation, as prescribed motion would impose.
  const double axis[3] = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  auto rotate = [&](double angle, const double* p, double* out) {
    const double c = std::cos(angle), s = std::sin(angle);
    const double d = axis[0] * p[0] + axis[1] * p[1] + axis[2] * p[2];
    const double cr[3] = {axis[1] * p[2] - axis[2] * p[1], axis[2] * p[0] - axis[0] * p[2],
                          axis[0] * p[1] - axis[1] * p[0]};
    for (int i = 0; i < 3; ++i) out[i] = p[i] * c + cr[i] * s + axis[i] * d * (1 - c);
  };
  const int steps = 200;
  const double dt = 1e-3, dangle = M_PI / 2 / steps;
  for (int n = 0; n < steps; ++n) {
    for (std::size_t k = 0; k < sd.numNodes(); ++k) {
      double now[3], next[3];
      rotate(n * dangle, &sd.x0[3 * k], now);
      rotate((n + 1) * dangle, &sd.x0[3 * k], next);
      for (int c = 0; c < 3; ++c) {
        sd.v[3 * k + c] = (next[c] - now[c]) / dt;
        sd.x[3 * k + c] = next[c];
      }
    }
    crumple::elements::computeSolidForces(blk, sd.x, sd.v, dt, bv, sd.slots.data());
  }
  for (int k = 0; k < 6; ++k)
    for (std::size_t e = 0; e < blk.size(); ++e) EXPECT_NEAR(blk.sigAt(k, e), 0.0, 1e-11) << k;
  for (std::size_t e = 0; e < blk.size(); ++e) {
    EXPECT_NEAR(blk.e_hg[e], 0.0, 1e-16);
    EXPECT_NEAR(blk.vol[e], blk.vol0[e], 1e-12);
  }
}

// The stiffness hourglass resistance is a vector in the global frame: a rigid rotation of the
// element must turn it (and create none). Rotate by 90 degrees about z in 400 steps; the
// first-order spin update grows its length by (1 + dtheta^2)^(steps/2) = 0.3 % and turns it
// by atan(dtheta) a step, short of 90 degrees by 400 dtheta^3 / 3 = 8e-6 rad.
TEST(Hex8, StiffnessHourglassResistanceTurnsWithTheElement) {
  const auto m = distortedBlock(4);
  auto sd = crumple::domain::buildSerialSubdomain(m);
  auto& blk = sd.solid_blocks.at(0);
  std::vector<double> dt_e;
  crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {});
  for (std::size_t e = 0; e < blk.size(); ++e) {
    blk.hgqAt(0, e) = 1.0;          // mode 1, x component
    blk.hgqAt(3 * 2 + 2, e) = 0.5;  // mode 3, z component (on the rotation axis: unchanged)
  }
  const int steps = 400;
  const double dt = 1e-3, dangle = M_PI / 2 / steps;
  crumple::elements::BulkViscosity bv;
  for (int n = 0; n < steps; ++n) {
    for (std::size_t k = 0; k < sd.numNodes(); ++k) {
      const double* p = &sd.x0[3 * k];
      const double c0 = std::cos(n * dangle), s0 = std::sin(n * dangle);
      const double c1 = std::cos((n + 1) * dangle), s1 = std::sin((n + 1) * dangle);
      const double now[3] = {c0 * p[0] - s0 * p[1], s0 * p[0] + c0 * p[1], p[2]};
      const double next[3] = {c1 * p[0] - s1 * p[1], s1 * p[0] + c1 * p[1], p[2]};
      for (int c = 0; c < 3; ++c) {
        sd.v[3 * k + c] = (next[c] - now[c]) / dt;
        sd.x[3 * k + c] = next[c];
      }
    }
    crumple::elements::computeSolidForces(blk, sd.x, sd.v, dt, bv, sd.slots.data());
  }
  for (std::size_t e = 0; e < blk.size(); ++e) {
    EXPECT_NEAR(blk.hgqAt(0, e), 0.0, 1e-5) << e;  // x turned into y
    EXPECT_NEAR(blk.hgqAt(1, e), 1.0, 5e-3) << e;
    EXPECT_NEAR(blk.hgqAt(2, e), 0.0, 1e-12) << e;
    EXPECT_NEAR(blk.hgqAt(3 * 2 + 2, e), 0.5, 1e-12) << e;
  }
}

// The fully integrated elements (ELFORM 2, and -1, -2 with the shear correction, which acts
// on hourglass velocities only) pass the same patch test: with a linear velocity field every
// Gauss point of every element carries the same stress, and the interior node of the distorted
// block is in equilibrium.
class Hex8Full : public ::testing::TestWithParam<int> {};

TEST_P(Hex8Full, UniformStrainIsExactAndInteriorForcesBalance) {
  auto m = distortedBlock(1);
  m.solid_sections[0].elform = GetParam();
  auto sd = crumple::domain::buildSerialSubdomain(m);
  auto& blk = sd.solid_blocks.at(0);
  ASSERT_EQ(blk.elform, GetParam());
  std::vector<double> dt_e;
  crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {});
  const double dt = 1e-2;
  imposeLinearField(sd, dt);
  crumple::elements::computeFullSolidForces(blk, sd.x, sd.v, dt, {0.0, 0.0}, sd.slots.data(), 0,
                                            blk.size());
  const double E = 210.0, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double tr = (G[0][0] + G[1][1] + G[2][2]) * dt;
  const std::size_t padded = blk.paddedSize();
  for (int q = 0; q < 8; ++q)
    for (std::size_t e = 0; e < blk.size(); ++e) {
      EXPECT_NEAR(blk.sig_ip[0][q * padded + e], lambda * tr + 2 * mu * G[0][0] * dt, 1e-12);
      EXPECT_NEAR(blk.sig_ip[3][q * padded + e], mu * (G[0][1] + G[1][0]) * dt, 1e-12);
    }
  const auto f = crumple::testing::gatheredForces(sd);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[3 * 13 + c], 0.0, 1e-13 * std::abs(blk.sigAt(0, 0)));
}

// ... and a finite rigid rotation leaves every Gauss point unstressed.
TEST_P(Hex8Full, FiniteRigidRotationProducesNoStress) {
  auto m = distortedBlock(1);
  m.solid_sections[0].elform = GetParam();
  auto sd = crumple::domain::buildSerialSubdomain(m);
  auto& blk = sd.solid_blocks.at(0);
  std::vector<double> dt_e;
  crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {});
  const int steps = 200;
  const double dt = 1e-3, dangle = M_PI / 2 / steps;
  for (int n = 0; n < steps; ++n) {
    for (std::size_t k = 0; k < sd.numNodes(); ++k) {
      const double* p = &sd.x0[3 * k];
      const double c0 = std::cos(n * dangle), s0 = std::sin(n * dangle);
      const double c1 = std::cos((n + 1) * dangle), s1 = std::sin((n + 1) * dangle);
      const double now[3] = {p[0], c0 * p[1] - s0 * p[2], s0 * p[1] + c0 * p[2]};
      const double next[3] = {p[0], c1 * p[1] - s1 * p[2], s1 * p[1] + c1 * p[2]};
      for (int c = 0; c < 3; ++c) {
        sd.v[3 * k + c] = (next[c] - now[c]) / dt;
        sd.x[3 * k + c] = next[c];
      }
    }
    crumple::elements::computeFullSolidForces(blk, sd.x, sd.v, dt, {}, sd.slots.data(), 0,
                                              blk.size());
  }
  for (const auto& comp : blk.sig_ip)
    for (double s : comp) EXPECT_NEAR(s, 0.0, 1e-11);
}

INSTANTIATE_TEST_SUITE_P(Forms, Hex8Full, ::testing::Values(2, -1, -2));

TEST(Hex8, StableStepOfACubeIsEdgeOverWaveSpeed) {
  using crumple::elements::solidTimeStep;
  // Without bulk viscosity: L / c.
  EXPECT_DOUBLE_EQ(solidTimeStep(2.0, 4.0, 0.0, {0.0, 0.0}), 0.5);
  // With it: L / (Q + sqrt(Q^2 + c^2)), Q = Q2 c + Q1 L |tr D|.
  const crumple::elements::BulkViscosity bv;  // Q1 = 1.5, Q2 = 0.06
  EXPECT_DOUBLE_EQ(solidTimeStep(2.0, 4.0, 0.0, bv), 2.0 / (0.24 + std::sqrt(0.24 * 0.24 + 16.0)));
  EXPECT_LT(solidTimeStep(2.0, 4.0, -1.0, bv), solidTimeStep(2.0, 4.0, 0.0, bv));
  // The step must not jump when tr(D) changes sign: a step modulated in phase with a
  // vibrating element pumps energy into it.
  EXPECT_DOUBLE_EQ(solidTimeStep(2.0, 4.0, 1e-9, bv), solidTimeStep(2.0, 4.0, -1e-9, bv));
}

}  // namespace
