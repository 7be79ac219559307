// Unit tests of the constant-strain tetrahedron (*SECTION_SOLID ELFORM 10): its volume
// gradient, the patch test on a distorted tetrahedral mesh, the internal force of one element
// against B^T D B V u computed here independently, the lumped mass, and the stable step (the
// minimum altitude over the wave speed) against the highest frequency of the assembled mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "brick_model.hpp"
#include "domain/subdomain.hpp"
#include "elements/hex8.hpp"
#include "gather.hpp"
#include "model/model.hpp"
#include "model/solid_shape.hpp"
#include "patch_field.hpp"
#include "tet_brick.hpp"

namespace {

using crumple::model::Vec3;

constexpr double kE = 210.0, kNu = 0.3, kRho = 7.85e-6;

using crumple::testing::tetBrick;

// One tetrahedron with the given corners.
crumple::model::Model oneTet(const std::array<Vec3, 4>& x, double nu = kNu) {
  crumple::testing::BrickOptions opt;
  opt.law = crumple::materials::Elastic::Params{kE, nu};
  auto m = crumple::testing::brickModel(1, 1, 1, opt);
  m.nodes.id = {1, 2, 3, 4};
  m.nodes.x.assign(x.begin(), x.end());
  m.solids.nodes = {{0, 1, 2, 3, 3, 3, 3, 3}};
  m.solid_sections[0].elform = 10;
  m.initial_velocity.assign(4, {0, 0, 0});
  m.finalize();
  return m;
}

// Shape-function gradients of a linear tetrahedron from the inverse of [1 x y z] (the
// textbook route, independent of the kernel's cross products) and its volume.
void shapeGradients(const std::array<Vec3, 4>& x, double g[4][3], double& vol) {
  double a[4][4];
  for (int r = 0; r < 4; ++r) {
    a[r][0] = 1.0;
    for (int c = 0; c < 3; ++c) a[r][c + 1] = x[std::size_t(r)][std::size_t(c)];
  }
  // Gauss-Jordan inverse of the 4x4 matrix.
  double inv[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  for (int c = 0; c < 4; ++c) {
    int p = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    std::swap(a[c], a[p]);
    std::swap(inv[c], inv[p]);
    const double d = a[c][c];
    for (int k = 0; k < 4; ++k) a[c][k] /= d, inv[c][k] /= d;
    for (int r = 0; r < 4; ++r)
      if (r != c) {
        const double f = a[r][c];
        for (int k = 0; k < 4; ++k) a[r][k] -= f * a[c][k], inv[r][k] -= f * inv[c][k];
      }
  }
  // N_a = inv[0][a] + inv[1][a] x + inv[2][a] y + inv[3][a] z.
  for (int n = 0; n < 4; ++n)
    for (int c = 0; c < 3; ++c) g[n][c] = inv[c + 1][n];
  const double e[3][3] = {{x[1][0] - x[0][0], x[1][1] - x[0][1], x[1][2] - x[0][2]},
                          {x[2][0] - x[0][0], x[2][1] - x[0][1], x[2][2] - x[0][2]},
                          {x[3][0] - x[0][0], x[3][1] - x[0][1], x[3][2] - x[0][2]}};
  vol = (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
         e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
         e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
        6.0;
}

// The element stiffness B^T D B V (12 x 12, node-major) of isotropic elasticity.
void stiffness(const double g[4][3], double vol, double E, double nu, double k[12][12]) {
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const double dot = g[a][0] * g[b][0] + g[a][1] * g[b][1] + g[a][2] * g[b][2];
          k[3 * a + i][3 * b + j] = vol * (lambda * g[a][i] * g[b][j] + mu * g[a][j] * g[b][i] +
                                           (i == j ? mu * dot : 0.0));
        }
}

std::array<Vec3, 4> randomTet(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  std::array<Vec3, 4> x = {Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{0, 1.5, 0}, Vec3{0, 0, 1}};
  for (auto& p : x)
    for (auto& c : p) c += u(rng);
  return x;
}

TEST(Tet4, CanonicalFormKeepsTheBaseAndApex) {
  using crumple::model::canonicalTet;
  // N4 repeated (LS-DYNA) and N3 = N4 with N5 repeated (the other convention) give the same.
  const std::array<int32_t, 8> a{10, 11, 12, 13, 13, 13, 13, 13};
  const std::array<int32_t, 8> b{10, 11, 12, 12, 13, 13, 13, 13};
  EXPECT_EQ(canonicalTet(a), a);
  EXPECT_EQ(canonicalTet(b), a);
  EXPECT_TRUE(crumple::model::isCanonicalTet(a));
  EXPECT_FALSE(crumple::model::isCanonicalTet(b));
  int32_t faces[6][4];
  int sizes[6];
  ASSERT_EQ(crumple::model::solidFaces(b, faces, sizes), 4);
  for (int f = 0; f < 4; ++f) EXPECT_EQ(sizes[f], 3);
}

TEST(Tet4, InternalForceIsBtDBVOfASmallDisplacement) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 5; ++trial) {
    const auto x0 = randomTet(rng);
    const auto m = oneTet(x0);
    auto sd = crumple::domain::buildSerialSubdomain(m);
    auto& blk = sd.solid_blocks.at(0);
    ASSERT_EQ(blk.elform, 10);
    std::vector<double> dt_e;
    crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {});
    // Lumped mass: a quarter of rho V at each node (gathered from the slots).
    double g[4][3], vol;
    shapeGradients(x0, g, vol);
    const auto mass = crumple::testing::gatheredForces(sd);
    for (int a = 0; a < 4; ++a) EXPECT_NEAR(mass[3 * a], kRho * vol / 4, 1e-15 * kRho * vol) << a;
    // A small displacement u over one step: v = u / dt, mid-step geometry x0.
    std::uniform_real_distribution<double> ud(-1.0, 1.0);
    const double dt = 1.0, scale = 1e-8;
    double u[12];
    for (double& c : u) c = scale * ud(rng);
    for (int i = 0; i < 12; ++i) {
      sd.v[std::size_t(i)] = u[i] / dt;
      sd.x[std::size_t(i)] = sd.x0[std::size_t(i)] + 0.5 * u[i];
    }
    crumple::elements::computeSolidForces(blk, sd.x, sd.v, dt, {0.0, 0.0}, sd.slots.data());
    const auto f = crumple::testing::gatheredForces(sd);
    double k[12][12];
    stiffness(g, vol, kE, kNu, k);
    double fmax = 0.0;
    double expect[12];
    for (int i = 0; i < 12; ++i) {
      expect[i] = 0.0;
      for (int j = 0; j < 12; ++j) expect[i] -= k[i][j] * u[j];
      fmax = std::max(fmax, std::abs(expect[i]));
    }
    // The kernel takes B at x = x0 + u / 2: a relative difference of order |u| / size.
    for (int i = 0; i < 12; ++i) EXPECT_NEAR(f[std::size_t(i)], expect[i], 1e-6 * fmax) << i;
  }
}

TEST(Tet4Patch, UniformStrainIsExactAndInteriorForcesBalance) {
  crumple::testing::BrickOptions opt;
  // Interior nodes moved off the grid: every tetrahedron is distorted.
  opt.position = crumple::testing::distortedPatchNode;
  const auto m = tetBrick(2, 2, 2, opt);
  auto sd = crumple::domain::buildSerialSubdomain(m);
  auto& blk = sd.solid_blocks.at(0);
  ASSERT_EQ(blk.size(), 48u);
  std::vector<double> dt_e;
  crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {});
  const double dt = 1e-2;
  crumple::testing::setPatchVelocity(sd, dt);
  crumple::elements::computeSolidForces(blk, sd.x, sd.v, dt, {0.0, 0.0}, sd.slots.data());
  const auto expect = crumple::testing::patchStress(kE, kNu, dt);
  for (std::size_t e = 0; e < blk.size(); ++e)
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(blk.sigAt(k, e), expect[std::size_t(k)], 1e-13) << e << " " << k;
  EXPECT_EQ(blk.e_hg[0], 0.0);
  // The centre node (1,1,1), index 13, is interior: its forces balance.
  const auto f = crumple::testing::gatheredForces(sd);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[3 * 13 + std::size_t(c)], 0.0, 1e-15) << c;
}

// Highest circular frequency of the assembled tetrahedral mesh with lumped masses (power
// iteration on M^-1 K, K assembled here from shapeGradients).
double highestFrequency(const crumple::model::Model& m, double nu) {
  const std::size_t nn = m.nodes.size();
  std::vector<double> mass(nn, 0.0);
  std::vector<std::array<double, 144>> ke(m.solids.size());
  for (std::size_t e = 0; e < m.solids.size(); ++e) {
    std::array<Vec3, 4> x;
    for (int a = 0; a < 4; ++a) x[std::size_t(a)] = m.nodes.x[std::size_t(m.solids.nodes[e][a])];
    double g[4][3], vol, k[12][12];
    shapeGradients(x, g, vol);
    stiffness(g, vol, kE, nu, k);
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) ke[e][std::size_t(12 * i + j)] = k[i][j];
    for (int a = 0; a < 4; ++a) mass[std::size_t(m.solids.nodes[e][a])] += kRho * vol / 4;
  }
  std::vector<double> x(3 * nn), y(3 * nn);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::sin(1.7 * double(i) + 0.3);
  double lambda = 0.0;
  for (int it = 0; it < 4000; ++it) {
    std::fill(y.begin(), y.end(), 0.0);
    for (std::size_t e = 0; e < m.solids.size(); ++e) {
      const auto& n = m.solids.nodes[e];
      for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 12; ++j)
          y[3 * std::size_t(n[i / 3]) + std::size_t(i % 3)] +=
              ke[e][std::size_t(12 * i + j)] * x[3 * std::size_t(n[j / 3]) + std::size_t(j % 3)];
    }
    double norm = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i) norm += (y[i] /= mass[i / 3]) * y[i];
    lambda = std::sqrt(norm);
    for (std::size_t i = 0; i < y.size(); ++i) x[i] = y[i] / lambda;
  }
  return std::sqrt(lambda);
}

TEST(Tet4, StableStepIsTheMinimumAltitudeOverTheWaveSpeed) {
  // The unit corner tetrahedron: largest face sqrt(3)/2, V = 1/6, minimum altitude 1/sqrt(3).
  const auto m = oneTet({Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}});
  auto sd = crumple::domain::buildSerialSubdomain(m);
  auto& blk = sd.solid_blocks.at(0);
  std::vector<double> dt_e;
  crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {0.0, 0.0});
  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  const double c = std::sqrt((lambda + 2 * mu) / kRho);
  EXPECT_NEAR(dt_e[0], 1.0 / std::sqrt(3.0) / c, 1e-15 / c);
  // Alone, its highest mode is faster than the altitude rule allows: the isolated element's
  // factor 0.5 brings it within 2 / omega.
  crumple::elements::markIsolatedElements(blk, sd.internal);
  ASSERT_FALSE(blk.dt_scale.empty());
  EXPECT_EQ(blk.dt_scale[0], 0.5);
  const double omega1 = highestFrequency(m, kNu);
  EXPECT_GT(1.0 / std::sqrt(3.0) / c, 2.0 / omega1);
  EXPECT_LT(0.5 / std::sqrt(3.0) / c, 2.0 / omega1);
}

TEST(Tet4, StepOfAMeshIsWithinItsHighestFrequency) {
  // A distorted 3 x 3 x 3 Kuhn mesh, nearly incompressible too: TSSFAC (0.9) times the step
  // with the default bulk viscosity stays below 2 / omega_max of the assembled mesh, and the
  // altitude rule is not far below it (it is an estimate, not a bound: 0.89 to 0.98 of
  // 2 / omega_max c / L on regular Kuhn and five-tet meshes, docs/theory.md).
  for (double nu : {0.3, 0.49}) {
    crumple::testing::BrickOptions opt;
    opt.law = crumple::materials::Elastic::Params{kE, nu};
    opt.position = [](int i, int j, int k) {
      return Vec3{i + 0.08 * std::sin(1.0 + j + 2.0 * k), j + 0.08 * std::cos(i + 0.5 * k),
                  k + 0.05 * std::sin(2.0 * i + j)};
    };
    const auto m = tetBrick(3, 3, 3, opt);
    auto sd = crumple::domain::buildSerialSubdomain(m);
    auto& blk = sd.solid_blocks.at(0);
    crumple::elements::markIsolatedElements(blk, sd.internal);
    EXPECT_TRUE(blk.dt_scale.empty());
    std::vector<double> dt_e;
    const auto st =
        crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {1.5, 0.06});
    const double critical = 2.0 / highestFrequency(m, nu);
    EXPECT_LT(0.9 * st.dt_min, critical) << nu;
    EXPECT_GT(st.dt_min, 0.8 * critical) << nu;
    RecordProperty(nu < 0.4 ? "step_over_critical_nu03" : "step_over_critical_nu049",
                   std::to_string(st.dt_min / critical));
  }
}

}  // namespace
