// Unit tests of the two-point pentahedron (*SECTION_SOLID ELFORM 15): the canonical node order
// of both degenerate-hexahedron conventions and its faces, the lumped mass, the patch test on a
// distorted prism mesh, the zero eigenvalues of the stiffness (one element and a mesh), and the
// stable step against the highest frequency of the assembled mesh. The stiffness is measured
// from the kernel itself: one small velocity per degree of freedom, the force it gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "brick_model.hpp"
#include "domain/subdomain.hpp"
#include "elements/hex8.hpp"
#include "gather.hpp"
#include "model/model.hpp"
#include "model/solid_shape.hpp"
#include "patch_field.hpp"

namespace {

using crumple::model::Vec3;

constexpr double kE = 210.0, kNu = 0.3, kRho = 7.85e-6;

// The brick model with each hexahedron cut along its bottom diagonal 1-3 into two prisms,
// written as N1 N2 N3 N3 N5 N6 N7 N7 (triangles at the hexahedron's bottom and top) and put in
// the canonical order as the reader does for ELFORM 15.
crumple::model::Model prismBrick(int nx, int ny, int nz, crumple::testing::BrickOptions opt = {}) {
  auto m = crumple::testing::brickModel(nx, ny, nz, opt);
  crumple::model::Solids prisms;
  constexpr int kCut[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (std::size_t e = 0; e < m.solids.size(); ++e)
    for (const auto& t : kCut) {
      const auto& h = m.solids.nodes[e];
      const auto at = [&](int i) { return h[std::size_t(i)]; };
      const std::array<int32_t, 8> hex{at(t[0]),     at(t[1]),     at(t[2]),     at(t[2]),
                                       at(t[0] + 4), at(t[1] + 4), at(t[2] + 4), at(t[2] + 4)};
      std::array<int32_t, 8> canonical{};
      EXPECT_TRUE(crumple::model::canonicalPrism(hex, canonical));
      prisms.id.push_back(int64_t(prisms.id.size()) + 1);
      prisms.part.push_back(0);
      prisms.nodes.push_back(canonical);
    }
  m.solids = prisms;
  m.solid_sections[0].elform = 15;
  m.finalize();
  return m;
}

// One prism: triangle x[0..2] at the bottom, x[3..5] above them, node ids 1-6.
crumple::model::Model onePrism(const std::array<Vec3, 6>& x) {
  auto m = crumple::testing::brickModel(1, 1, 1);
  m.nodes.id = {1, 2, 3, 4, 5, 6};
  m.nodes.x.assign(x.begin(), x.end());
  std::array<int32_t, 8> canonical{};
  EXPECT_TRUE(crumple::model::canonicalPrism({0, 1, 2, 2, 3, 4, 5, 5}, canonical));
  m.solids.nodes = {canonical};
  m.solid_sections[0].elform = 15;
  m.initial_velocity.assign(6, {0, 0, 0});
  m.finalize();
  return m;
}

const std::array<Vec3, 6> kDistorted = {Vec3{0.1, -0.05, 0.02}, Vec3{1.9, 0.1, -0.1},
                                        Vec3{0.2, 1.4, 0.05},   Vec3{-0.1, 0.1, 1.1},
                                        Vec3{1.6, -0.1, 0.8},   Vec3{0.05, 1.2, 1.3}};

// The stiffness K (n x n, n = 3 nodes) the kernel applies: column j from the force of a small
// displacement u e_j over one step (v = u / dt, mid-step geometry x0 + u / 2), f = -K u.
std::vector<double> kernelStiffness(const crumple::model::Model& m) {
  const std::size_t n = 3 * m.nodes.size();
  std::vector<double> k(n * n, 0.0);
  const double u = 1e-7, dt = 1.0;
  for (std::size_t j = 0; j < n; ++j) {
    auto sd = crumple::domain::buildSerialSubdomain(m);
    std::vector<double> dt_e;
    for (auto& blk : sd.solid_blocks)
      crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {0.0, 0.0});
    std::fill(sd.v.begin(), sd.v.end(), 0.0);
    sd.v[j] = u / dt;
    for (std::size_t i = 0; i < n; ++i) sd.x[i] = sd.x0[i] + 0.5 * dt * sd.v[i];
    for (auto& blk : sd.solid_blocks)
      crumple::elements::computeFullSolidForces(blk, sd.x, sd.v, dt, {0.0, 0.0}, sd.slots.data(), 0,
                                                blk.size());
    const auto f = crumple::testing::gatheredForces(sd);
    for (std::size_t i = 0; i < n; ++i) k[i * n + j] = -f[i] / u;
  }
  return k;
}

// Eigenvalues of a symmetric matrix (cyclic Jacobi), ascending.
std::vector<double> eigenvalues(std::vector<double> a, std::size_t n) {
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0.0;
    for (std::size_t p = 0; p < n; ++p)
      for (std::size_t q = p + 1; q < n; ++q) off += a[p * n + q] * a[p * n + q];
    if (off < 1e-30) break;
    for (std::size_t p = 0; p < n; ++p)
      for (std::size_t q = p + 1; q < n; ++q) {
        const double apq = a[p * n + q];
        if (apq == 0.0) continue;
        const double theta = (a[q * n + q] - a[p * n + p]) / (2 * apq);
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (std::size_t r = 0; r < n; ++r) {
          const double arp = a[r * n + p], arq = a[r * n + q];
          a[r * n + p] = c * arp - s * arq;
          a[r * n + q] = s * arp + c * arq;
        }
        for (std::size_t r = 0; r < n; ++r) {
          const double apr = a[p * n + r], aqr = a[q * n + r];
          a[p * n + r] = c * apr - s * aqr;
          a[q * n + r] = s * apr + c * aqr;
        }
      }
  }
  std::vector<double> ev(n);
  for (std::size_t i = 0; i < n; ++i) ev[i] = a[i * n + i];
  std::sort(ev.begin(), ev.end());
  return ev;
}

// The eigenvalues of the kernel's stiffness (symmetrised) scaled by M^-1/2 on both sides
// (lumped masses from the kernel's slots): omega^2 of the free mesh.
std::vector<double> squaredFrequencies(const crumple::model::Model& m) {
  auto k = kernelStiffness(m);
  const std::size_t n = 3 * m.nodes.size();
  auto sd = crumple::domain::buildSerialSubdomain(m);
  std::vector<double> dt_e;
  for (auto& blk : sd.solid_blocks)
    crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {0.0, 0.0});
  const auto mass = crumple::testing::gatheredForces(sd);
  std::vector<double> a(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      a[i * n + j] =
          0.5 * (k[i * n + j] + k[j * n + i]) / std::sqrt(mass[3 * (i / 3)] * mass[3 * (j / 3)]);
  return eigenvalues(a, n);
}

int zeroCount(const std::vector<double>& ev) {
  const double top = ev.back();
  return int(
      std::count_if(ev.begin(), ev.end(), [&](double v) { return std::abs(v) < 1e-6 * top; }));
}

TEST(Penta6, CanonicalFormOfBothConventions) {
  using crumple::model::canonicalPrism;
  // The Keyword Manual's N1 N2 N3 N4 N5 N5 N6 N6 is the canonical form itself.
  const std::array<int32_t, 8> manual{10, 11, 12, 13, 14, 14, 15, 15};
  std::array<int32_t, 8> out{};
  ASSERT_TRUE(canonicalPrism(manual, out));
  EXPECT_EQ(out, manual);
  EXPECT_TRUE(crumple::model::isCanonicalPrism(manual));
  // N3 = N4, N7 = N8 (triangles 10 11 12 below 14 15 16): the same prism in canonical order.
  const std::array<int32_t, 8> other{10, 11, 12, 12, 14, 15, 16, 16};
  ASSERT_TRUE(canonicalPrism(other, out));
  EXPECT_FALSE(crumple::model::isCanonicalPrism(other));
  EXPECT_TRUE(crumple::model::isCanonicalPrism(out));
  std::array<int32_t, 8> again{};
  ASSERT_TRUE(canonicalPrism(out, again));
  EXPECT_EQ(again, out);
  // Not prisms: a pyramid-like collapse and six nodes collapsed on adjacent faces.
  EXPECT_FALSE(canonicalPrism({1, 2, 3, 4, 5, 5, 5, 6}, out));
  EXPECT_FALSE(canonicalPrism({1, 2, 3, 4, 5, 5, 6, 7}, out));
  // Faces: two triangles and three quadrilaterals.
  int32_t faces[6][4];
  int sizes[6];
  ASSERT_EQ(crumple::model::solidFaces(manual, faces, sizes), 5);
  EXPECT_EQ(std::count(sizes, sizes + 5, 3), 2);
  EXPECT_EQ(std::count(sizes, sizes + 5, 4), 3);
}

TEST(Penta6, VolumeAndLumpedMass) {
  // An affine image of the unit prism (flat faces): V = det(A) / 2.
  const double A[3][3] = {{1.3, 0.2, -0.1}, {0.1, 0.9, 0.3}, {-0.2, 0.1, 1.7}};
  const Vec3 ref[6] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  std::array<Vec3, 6> x;
  for (int a = 0; a < 6; ++a)
    for (int i = 0; i < 3; ++i)
      x[std::size_t(a)][std::size_t(i)] =
          A[i][0] * ref[a][0] + A[i][1] * ref[a][1] + A[i][2] * ref[a][2];
  const double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
                     A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                     A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  auto sd = crumple::domain::buildSerialSubdomain(onePrism(x));
  auto& blk = sd.solid_blocks.at(0);
  ASSERT_EQ(blk.elform, 15);
  ASSERT_EQ(blk.points, 2);
  std::vector<double> dt_e;
  crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {});
  EXPECT_NEAR(blk.vol0[0], det / 2, 1e-14);
  const auto mass = crumple::testing::gatheredForces(sd);
  for (int a = 0; a < 6; ++a) EXPECT_NEAR(mass[3 * std::size_t(a)], kRho * det / 12, 1e-20) << a;
}

TEST(Penta6Patch, UniformStrainIsExactAndInteriorForcesBalance) {
  crumple::testing::BrickOptions opt;
  // Interior nodes moved off the grid: every prism is distorted (warped quadrilateral faces).
  opt.position = crumple::testing::distortedPatchNode;
  const auto m = prismBrick(2, 2, 2, opt);
  auto sd = crumple::domain::buildSerialSubdomain(m);
  auto& blk = sd.solid_blocks.at(0);
  ASSERT_EQ(blk.size(), 16u);
  std::vector<double> dt_e;
  crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {});
  const double dt = 1e-2;
  crumple::testing::setPatchVelocity(sd, dt);
  crumple::elements::computeFullSolidForces(blk, sd.x, sd.v, dt, {0.0, 0.0}, sd.slots.data(), 0,
                                            blk.size());
  const auto expect = crumple::testing::patchStress(kE, kNu, dt);
  const std::size_t padded = blk.paddedSize();
  for (std::size_t e = 0; e < blk.size(); ++e)
    for (std::size_t q = 0; q < 2; ++q)
      for (int k = 0; k < 6; ++k)
        EXPECT_NEAR(blk.sig_ip[std::size_t(k)][q * padded + e], expect[std::size_t(k)], 1e-13)
            << e << " " << k;
  EXPECT_EQ(blk.e_hg[0], 0.0);
  // The centre node (1,1,1), index 13, is interior: its forces balance.
  const auto f = crumple::testing::gatheredForces(sd);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[3 * 13 + std::size_t(c)], 0.0, 1e-15) << c;
}

TEST(Penta6, ZeroEigenvaluesAreTheRigidModesInAMesh) {
  // One element alone: the six rigid modes and one more, the twist about the prism's axis
  // (rotation growing linearly along it) that both points on the axis see as a rigid spin.
  const auto one = squaredFrequencies(onePrism(kDistorted));
  EXPECT_EQ(zeroCount(one), 7);
  // Two prisms sharing a face, and a distorted 2 x 1 x 1 mesh of four: exactly six, no
  // hourglass mode survives where the twist has a neighbour to shear.
  crumple::testing::BrickOptions opt;
  opt.position = [](int i, int j, int k) {
    return Vec3{i + 0.1 * std::sin(1.0 + j + 2.0 * k), j + 0.1 * std::cos(i + 0.5 * k),
                k + 0.07 * std::sin(2.0 * i + j)};
  };
  for (int nx : {1, 2}) {
    const auto ev = squaredFrequencies(prismBrick(nx, 1, 1, opt));
    EXPECT_EQ(zeroCount(ev), 6) << nx;
    EXPECT_GT(ev[6], 1e-4 * ev.back()) << nx;
  }
}

TEST(Penta6, StepOfAMeshIsWithinItsHighestFrequency) {
  // A distorted 2 x 2 x 1 prism mesh: TSSFAC (0.9) times the step with the default bulk
  // viscosity (V / A_max over the faces, as for hexahedra) stays below 2 / omega_max of the
  // assembled lumped-mass mesh, by about a factor 2: V / A_max is half the triangle's
  // altitude, a conservative length for prisms (docs/theory.md).
  crumple::testing::BrickOptions opt;
  opt.position = [](int i, int j, int k) {
    return Vec3{i + 0.08 * std::sin(1.0 + j + 2.0 * k), j + 0.08 * std::cos(i + 0.5 * k),
                k + 0.05 * std::sin(2.0 * i + j)};
  };
  const auto m = prismBrick(2, 2, 1, opt);
  const auto ev = squaredFrequencies(m);
  const double critical = 2.0 / std::sqrt(ev.back());
  auto sd = crumple::domain::buildSerialSubdomain(m);
  auto& blk = sd.solid_blocks.at(0);
  crumple::elements::markIsolatedElements(blk, sd.internal);
  EXPECT_TRUE(blk.dt_scale.empty());
  std::vector<double> dt_e;
  const auto st =
      crumple::elements::initializeSolids(blk, sd.x0, sd.slots.data(), dt_e, {1.5, 0.06});
  EXPECT_LT(0.9 * st.dt_min, critical);
  EXPECT_GT(st.dt_min, 0.4 * critical);
  RecordProperty("step_over_critical", std::to_string(st.dt_min / critical));
  std::printf("[ figure ] prism mesh: dt / (2 / omega_max) = %.3f\n", st.dt_min / critical);
}

}  // namespace
