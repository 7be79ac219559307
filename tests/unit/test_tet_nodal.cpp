// Unit tests of the nodal-pressure tetrahedron (*SECTION_SOLID ELFORM 13,
// src/elements/tet_nodal.cpp): the patch test on a distorted mesh (a uniform deformation gives
// every element the same, exact stress), a rigid rotation (no stress), the energy-consistent
// split (deviatoric stress of the element, pressure the mean of the nodal pressures), the
// refusal of a law that cannot split, and the nodal volumes gathered over ranks as in serial.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "domain/subdomain.hpp"
#include "elements/hex8.hpp"
#include "elements/tet_nodal.hpp"
#include "gather.hpp"
#include "model/model.hpp"
#include "patch_field.hpp"
#include "tet_brick.hpp"

namespace {

constexpr double kE = 210.0, kNu = 0.3;

// The nodal strains ln(V_a / V0_a) of a serial subdomain at x: the solver's first pass
// (Solver::computeNodalVolumetricStrain) without the exchange.
std::vector<double> nodalStrains(crumple::domain::Subdomain& sd) {
  for (const auto& blk : sd.solid_blocks)
    crumple::elements::writeNodalVolumes(blk, sd.x0, sd.x, sd.slots.data());
  std::vector<double> volumes(2 * sd.numNodes(), 0.0);
  const auto& plan = sd.nodal_volume;
  for (std::size_t n = 0; n < sd.numNodes(); ++n)
    for (int32_t k = plan.ptr[n]; k < plan.ptr[n + 1]; ++k)
      for (std::size_t c = 0; c < 2; ++c)
        volumes[2 * n + c] += sd.slots[3 * std::size_t(plan.slot[std::size_t(k)]) + c];
  std::vector<double> strain;
  crumple::elements::nodalVolumetricStrain(volumes, strain);
  return strain;
}

// A distorted 2 x 2 x 2 brick of 48 ELFORM 13 tetrahedra, initialised.
struct Patch {
  crumple::model::Model m;
  crumple::domain::Subdomain sd;
  explicit Patch(const crumple::testing::BrickOptions& opt)
      : m(crumple::testing::tetBrick(2, 2, 2, opt, 13)),
        sd(crumple::domain::buildSerialSubdomain(m)) {
    std::vector<double> dt_e;
    crumple::elements::initializeSolids(sd.solid_blocks.at(0), sd.x0, sd.slots.data(), dt_e, {});
  }
  crumple::domain::SolidBlock& block() { return sd.solid_blocks.at(0); }
  // One pass at the current x and v over the step dt.
  void pass(double dt) {
    const auto ev = nodalStrains(sd);
    auto& blk = block();
    crumple::elements::computeSolidForces(blk, sd.x, sd.v, dt, {0.0, 0.0}, sd.slots.data(), 0,
                                          blk.size(), ev.data());
  }
};

crumple::testing::BrickOptions distorted() {
  crumple::testing::BrickOptions opt;
  opt.position = crumple::testing::distortedPatchNode;
  return opt;
}

using Mat3 = std::array<std::array<double, 3>, 3>;

Mat3 inverse(const Mat3& a) {
  const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                     a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                     a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      r[std::size_t(i)][std::size_t(j)] =
          (a[std::size_t(i1)][std::size_t(j1)] * a[std::size_t(i2)][std::size_t(j2)] -
           a[std::size_t(i1)][std::size_t(j2)] * a[std::size_t(i2)][std::size_t(j1)]) /
          det;
    }
  return r;
}

double det3(const Mat3& a) {
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
         a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// Patch test: the step from x0 to x = x0 + dt G x0 is a uniform deformation. Every element
// has the same mid-step strain increment de = sym(G (I + dt G / 2)^-1) dt, and every node the
// volume ratio det(I + dt G): the stress is 2 mu dev(de) + K ln det(I + dt G) I in every
// element, to rounding, on a mesh of distorted tetrahedra; the interior node's forces balance.
TEST(TetNodalPatch, UniformDeformationGivesTheExactUniformStress) {
  Patch p(distorted());
  auto& sd = p.sd;
  const double dt = 1e-2;
  const auto& G = crumple::testing::kPatchG;
  for (std::size_t n = 0; n < sd.numNodes(); ++n)
    for (std::size_t i = 0; i < 3; ++i) {
      double v = 0.0;
      for (std::size_t j = 0; j < 3; ++j) v += G[i][j] * sd.x0[3 * n + j];
      sd.v[3 * n + i] = v;
      sd.x[3 * n + i] = sd.x0[3 * n + i] + dt * v;
    }
  p.pass(dt);
  Mat3 half, full;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      half[i][j] = (i == j ? 1.0 : 0.0) + 0.5 * dt * G[i][j];
      full[i][j] = (i == j ? 1.0 : 0.0) + dt * G[i][j];
    }
  const Mat3 hinv = inverse(half);
  Mat3 de;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      double lij = 0.0, lji = 0.0;
      for (std::size_t k = 0; k < 3; ++k) {
        lij += G[i][k] * hinv[k][j];
        lji += G[j][k] * hinv[k][i];
      }
      de[i][j] = 0.5 * (lij + lji) * dt;
    }
  const double mu = kE / (2 * (1 + kNu)), K = kE / (3 * (1 - 2 * kNu));
  const double tr = de[0][0] + de[1][1] + de[2][2];
  const double p_k = K * std::log(det3(full));
  const std::array<double, 6> expect = {2 * mu * (de[0][0] - tr / 3) + p_k,
                                        2 * mu * (de[1][1] - tr / 3) + p_k,
                                        2 * mu * (de[2][2] - tr / 3) + p_k,
                                        2 * mu * de[0][1],
                                        2 * mu * de[1][2],
                                        2 * mu * de[2][0]};
  auto& blk = p.block();
  ASSERT_EQ(blk.size(), 48u);
  for (std::size_t e = 0; e < blk.size(); ++e)
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(blk.sigAt(k, e), expect[std::size_t(k)], 1e-12) << e << " " << k;
  // Under a uniform deformation the nodal strain is the element's own: the mid-step rate
  // tr(de) agrees with ln det(I + dt G) to third order in dt G, so ELFORM 13 passes the patch
  // test that ELFORM 10 passes.
  EXPECT_NEAR(p_k, K * tr, 1e-12);
  const auto f = crumple::testing::gatheredForces(sd);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[3 * 13 + std::size_t(c)], 0.0, 1e-13) << c;
}

// A rigid rotation by 40 degrees about an oblique axis in one step, v = (R - I) x0 / dt: the
// mid-step velocity gradient (R - I)(R + I)^-1 / dt is skew and every volume keeps its
// value, so no stress arises.
TEST(TetNodalPatch, RigidRotationGivesNoStress) {
  Patch p(distorted());
  auto& sd = p.sd;
  const double dt = 1e-3, angle = 40.0 * M_PI / 180.0;
  const double ax[3] = {1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)};
  const double c = std::cos(angle), s = std::sin(angle);
  double R[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double cross = i == j ? 0.0 : ((j - i + 3) % 3 == 1 ? -1.0 : 1.0) * ax[3 - i - j];
      R[i][j] = (i == j ? c : 0.0) + (1 - c) * ax[i] * ax[j] + s * cross;
    }
  for (std::size_t n = 0; n < sd.numNodes(); ++n)
    for (std::size_t i = 0; i < 3; ++i) {
      double x = 0.0;
      for (std::size_t j = 0; j < 3; ++j) x += R[i][j] * sd.x0[3 * n + j];
      sd.x[3 * n + i] = x;
      sd.v[3 * n + i] = (x - sd.x0[3 * n + i]) / dt;
    }
  p.pass(dt);
  auto& blk = p.block();
  double worst = 0.0;
  for (std::size_t e = 0; e < blk.size(); ++e)
    for (int k = 0; k < 6; ++k) worst = std::max(worst, std::abs(blk.sigAt(k, e)));
  EXPECT_LT(worst, 1e-12 * kE);
}

// Bonet & Burton's split: with the same nodal volumes, the element's pressure is the mean of
// its nodes' K ln(V_a / V0_a), whatever its own volume change, and its deviatoric stress is
// ELFORM 10's. One node of the patch is moved: only the elements at it see a volume change of
// their own, but every element sharing a node with them sees the nodal strain.
TEST(TetNodalSplit, PressureIsTheMeanOfTheNodalPressures) {
  Patch p(distorted());
  auto& sd = p.sd;
  const double dt = 1.0;
  const std::size_t moved = 13;  // the centre node
  const double u[3] = {2e-4, -1e-4, 3e-4};
  for (std::size_t c = 0; c < 3; ++c) {
    sd.v[3 * moved + c] = u[c] / dt;
    sd.x[3 * moved + c] = sd.x0[3 * moved + c] + u[c];
  }
  const auto ev = nodalStrains(sd);
  p.pass(dt);
  // The same step under ELFORM 10.
  auto m10 = crumple::testing::tetBrick(2, 2, 2, distorted(), 10);
  auto sd10 = crumple::domain::buildSerialSubdomain(m10);
  auto& b10 = sd10.solid_blocks.at(0);
  std::vector<double> dt_e;
  crumple::elements::initializeSolids(b10, sd10.x0, sd10.slots.data(), dt_e, {});
  sd10.x = sd.x;
  sd10.v = sd.v;
  crumple::elements::computeSolidForces(b10, sd10.x, sd10.v, dt, {0.0, 0.0}, sd10.slots.data());
  const double K = kE / (3 * (1 - 2 * kNu));
  auto& blk = p.block();
  int touched = 0;
  for (std::size_t e = 0; e < blk.size(); ++e) {
    double mean_ev = 0.0;
    for (int a = 0; a < 4; ++a) mean_ev += 0.25 * ev[std::size_t(blk.conn[e][std::size_t(a)])];
    const double pr = (blk.sigAt(0, e) + blk.sigAt(1, e) + blk.sigAt(2, e)) / 3.0;
    const double pr10 = (b10.sigAt(0, e) + b10.sigAt(1, e) + b10.sigAt(2, e)) / 3.0;
    EXPECT_NEAR(pr, K * mean_ev, 1e-14 * K) << e;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(blk.sigAt(k, e) - pr, b10.sigAt(k, e) - pr10, 1e-13 * kE) << e;
    for (int k = 3; k < 6; ++k) EXPECT_NEAR(blk.sigAt(k, e), b10.sigAt(k, e), 1e-13 * kE) << e;
    if (mean_ev != 0.0) ++touched;
  }
  // Every element of the 2 x 2 x 2 patch has a node among the moved node's neighbours.
  EXPECT_GT(touched, 24);
}

// The nodal volumes of elements on other ranks reach the node as its own elements' do: each
// rank's subdomain of a partitioned brick has the plan of the serial one at its nodes (the
// same sources in the same order), ghost slots included.
TEST(TetNodalPlan, RanksGatherTheSameSourcesAsSerial) {
  const auto m = crumple::testing::tetBrick(3, 2, 2, distorted(), 13);
  const auto serial = crumple::domain::buildSerialSubdomain(m);
  std::vector<int32_t> rank(m.numElements());
  for (std::size_t e = 0; e < rank.size(); ++e) rank[e] = int32_t(e * 3 / rank.size());
  for (int r = 0; r < 3; ++r) {
    const auto sd = crumple::domain::buildSubdomain(m, rank, r, 3);
    std::size_t received = 0;
    for (const auto& peer : sd.nodal_volume_peers) {
      received += peer.recv_slots.size();
      EXPECT_FALSE(peer.send_slots.empty());
    }
    EXPECT_GT(received, 0u) << r;
    for (std::size_t n = 0; n < sd.numNodes(); ++n) {
      const auto g = std::size_t(sd.node_model[n]);
      EXPECT_EQ(sd.nodal_volume.ptr[n + 1] - sd.nodal_volume.ptr[n],
                serial.nodal_volume.ptr[g + 1] - serial.nodal_volume.ptr[g])
          << r << " " << n;
    }
  }
  // Every corner of every tetrahedron, 8 slots per element, once.
  EXPECT_EQ(serial.nodal_volume.slot.size(), 8 * m.numElements());
}

}  // namespace
