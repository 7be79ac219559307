// *MAT_LOW_DENSITY_FOAM (057) in a whole run: a unit cube (one ELFORM 1 hex) on rollers on its
// faces x = 0, y = 0, z = 0 is squeezed along x by its face x = 1 (prescribed displacement) to
// 60 % and let back, the other faces free. With zero Poisson's ratio the cube stays in uniaxial
// compression F = diag(lambda, 1, 1) and the force on the face x = 1 over its initial area is
// the nominal stress: the curve while loading, the curve times the hysteresis factor
// 1 - (1 - HU) (1 - (W / W_max)^SHAPE) while unloading. The internal energy at full squeeze is
// the area under the curve, W_max V0; back at lambda = 1 it is what the loop dissipated,
// W_max (1 - HU) SHAPE / (SHAPE + 1) (integral of the factor over W from 0 to W_max); and the
// work of the prescribed face balances the internal and kinetic energies.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "harness.hpp"

using crumple::testing::brickDeck;
using crumple::testing::brickNodeSet;
using crumple::testing::Simulation;
using crumple::testing::termination;

namespace {

// The curve (engineering strain, nominal stress; compression positive) and its integral at the
// knots (trapezoids by hand): Phi(0.6) = 0.005 + 0.05 + 0.02375 = 0.07875.
const std::vector<double> kStrain{0.0, 0.1, 0.5, 0.7, 0.8}, kStress{0.0, 0.1, 0.15, 0.5, 1.5};
constexpr double kSqueeze = 0.6, kPhiSqueeze = 0.07875;
constexpr double kHu = 0.2, kShape = 2.0;

double curve(double eps) {
  std::size_t k = 0;
  while (k + 2 < kStrain.size() && eps >= kStrain[k + 1]) ++k;
  return kStress[k] +
         (kStress[k + 1] - kStress[k]) * (eps - kStrain[k]) / (kStrain[k + 1] - kStrain[k]);
}

double phi(double eps) {
  double w = 0.0;
  for (std::size_t k = 0; k + 1 < kStrain.size() && kStrain[k] < eps; ++k) {
    const double b = std::min(eps, kStrain[k + 1]);
    w += 0.5 * (b - kStrain[k]) * (kStress[k] + curve(b));
  }
  return w;
}

// E = 1 (tension), RO = 1e-4: the stiffest slope, 10, gives c = 316; HU 0.2, SHAPE 2, DAMP 0,
// BVFLAG as given; material 1 with its curve 7.
std::string foamCards(int bvflag) {
  std::string s = fmt::format(
      "*MAT_LOW_DENSITY_FOAM\n"
      "         1    1.0e-4       1.0         7       0.0       0.2       0.0       0.0\n"
      "       2.0       0.0{:10d}       0.0       0.0       0.0       0.0\n",
      bvflag);
  s += "*DEFINE_CURVE\n         7\n";
  for (std::size_t k = 0; k < kStrain.size(); ++k)
    s += fmt::format("{:20.12g}{:20.12g}\n", kStrain[k], kStress[k]);
  return s;
}

// The unit cube, face x = 1 displaced by the curve of (t, u) points.
std::string squeezeDeck(int bvflag, const std::vector<std::pair<double, double>>& motion) {
  std::string s = foamCards(bvflag);
  s += termination(motion.back().first);
  s += "*DEFINE_CURVE\n        90\n";
  for (const auto& [t, u] : motion) s += fmt::format("{:20.12g}{:20.12g}\n", t, u);
  s += brickNodeSet(1, 1, 1, 1, [](int i, int, int) { return i == 1; });
  s += "*BOUNDARY_PRESCRIBED_MOTION_SET\n         1         1         2        90       1.0\n";
  return brickDeck(1, 1, 1, 1.0, 1.0, 1.0, s + crumple::testing::rollersOnLowFaces());
}

// Face x = 1 moves by -0.6 over [0, 1] (about 400 cycles), holds to 1.2, returns over [1.2, 2.2]
// and holds to 2.4; no bulk viscosity (BVFLAG 0).
std::string squeezeAndRelease() {
  return squeezeDeck(0, {{0.0, 0.0}, {1.0, -kSqueeze}, {1.2, -kSqueeze}, {2.2, 0.0}, {2.4, 0.0}});
}

}  // namespace

TEST(VerificationLowDensityFoam, SqueezeAndReleaseFollowTheCurveAndDissipateTheLoop) {
  auto sim = Simulation::fromText("ldf_squeeze", squeezeAndRelease());
  // Node 2 starts at (1, 0, 0): 1 - x is the strain. A pass's stress is that of the positions
  // it started from, those the previous cycle left.
  double eps_prev = 0.0, eps_max = 0.0, w_max = 0.0;
  double worst_loading = 0.0, worst_unloading = 0.0, at_hold = 0.0, e_hold = 0.0;
  // The area of the force-displacement loop (trapezoids over the pairs (eps, sigma)).
  double loop = 0.0, eps_last = 0.0, sigma_last = 0.0;
  sim->run([&](const crumple::solver::Solver& solver) {
    const double sigma = -sim->sd.solid_blocks.at(0).sigAt(0, 0);  // compression positive
    const double eps = eps_prev;
    loop += 0.5 * (sigma + sigma_last) * (eps - eps_last);
    eps_last = eps;
    sigma_last = sigma;
    if (eps >= eps_max - 1e-15) {
      eps_max = eps;
      w_max = phi(eps);
      worst_loading = std::max(worst_loading, std::abs(sigma - curve(eps)));
    } else {
      const double r = phi(eps) / w_max;
      const double want = curve(eps) * (1.0 - (1.0 - kHu) * (1.0 - std::pow(r, kShape)));
      worst_unloading = std::max(worst_unloading, std::abs(sigma - want));
    }
    const double t = solver.time();
    if (t > 1.1 && t < 1.2) {
      at_hold = sigma;
      e_hold = solver.energies().internal;
    }
    eps_prev = 1.0 - sim->x(2, 0);
  });
  EXPECT_NEAR(eps_max, kSqueeze, 1e-12);
  EXPECT_NEAR(phi(kSqueeze), kPhiSqueeze, 1e-15);
  // Force / A0 on the face: the curve while loading, the hysteresis law while unloading.
  EXPECT_LT(worst_loading, 1e-9);
  EXPECT_LT(worst_unloading, 1e-9);
  EXPECT_NEAR(at_hold, curve(kSqueeze), 1e-12);
  // Energy: W_max V0 at full squeeze, the loop's dissipation at the end.
  EXPECT_NEAR(e_hold, kPhiSqueeze, 0.005 * kPhiSqueeze);
  const auto e = sim->solver->energies();
  const double dissipated = kPhiSqueeze * (1.0 - kHu) * kShape / (kShape + 1.0);
  EXPECT_NEAR(dissipated, 0.042, 1e-15);
  EXPECT_NEAR(e.internal, dissipated, 0.005 * dissipated);
  EXPECT_NEAR(loop, dissipated, 0.005 * dissipated);
  EXPECT_NEAR(1.0 - sim->x(2, 0), 0.0, 1e-9);
  EXPECT_NEAR(sim->sd.solid_blocks.at(0).sigAt(0, 0), 0.0, 1e-9);
  EXPECT_NEAR(e.external_work, e.internal + e.kinetic + e.hourglass, 0.01 * kPhiSqueeze);
}

// BVFLAG: a fast squeeze to 30 % in 0.09 (the strain rate 3.3, about 30 wave transits), held to
// 0.12, stores the area under the curve, Phi(0.3) = 0.0275, as internal energy with BVFLAG 0
// (LS-DYNA's default: no bulk viscosity on the foam; 0.02 % found); with BVFLAG 1 the default
// bulk viscosity (Q1 1.5, Q2 0.06: q = rho L (Q1 L rate^2 + Q2 c rate), some 5 % of the stress
// each) adds its work on top (9 % found).
TEST(VerificationLowDensityFoam, BulkViscosityOnlyWithBvflag) {
  const double phi03 = phi(0.3);
  EXPECT_NEAR(phi03, 0.0275, 1e-15);
  const std::vector<std::pair<double, double>> motion{{0.0, 0.0}, {0.09, -0.3}, {0.12, -0.3}};
  auto off = Simulation::fromText("ldf_bv0", squeezeDeck(0, motion));
  off->run();
  EXPECT_NEAR(off->solver->energies().internal, phi03, 0.005 * phi03);
  auto on = Simulation::fromText("ldf_bv1", squeezeDeck(1, motion));
  on->run();
  EXPECT_GT(on->solver->energies().internal, 1.05 * phi03);
  EXPECT_NEAR(on->solver->energies().external_work, on->solver->energies().internal, 0.005 * phi03);
}

namespace {

// A 4 x 4 x 4 block of the unit cube whose boundary nodes are driven along x(t) = X (1 - a t)
// (a = 0.75 over [0, 1]: lambda = 0.25 in every direction; the faces X = 0 held by SPCs), the
// inner 27 nodes free.
std::string hydrostaticBlock() {
  constexpr int n = 4;
  std::string s = foamCards(0) + termination(1.0);
  s += "*DEFINE_CURVE\n        90\n" + fmt::format("{:20.12g}{:20.12g}\n", 0.0, 0.0) +
       fmt::format("{:20.12g}{:20.12g}\n", 1.0, -0.75);
  std::string motion = "*BOUNDARY_PRESCRIBED_MOTION_NODE\n", spc = "*BOUNDARY_SPC_NODE\n";
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const int ijk[3] = {i, j, k};
        if (i % n && j % n && k % n) continue;
        const int node = 1 + i + (n + 1) * (j + (n + 1) * k);
        for (int d = 0; d < 3; ++d)
          if (ijk[d] > 0)
            motion += fmt::format("{:10d}{:10d}{:10d}{:10d}{:10.4f}\n", node, d + 1, 2, 90,
                                  double(ijk[d]) / n);
        if (i == 0 || j == 0 || k == 0)
          spc += fmt::format("{:10d}{:10d}{:10d}{:10d}{:10d}\n", node, 0, int(i == 0), int(j == 0),
                             int(k == 0));
      }
  return brickDeck(n, n, n, 1.0, 1.0, 1.0, s + motion + spc);
}

}  // namespace

// Squeezed hydrostatically to lambda = 0.25, each direction's Cauchy stress is f(0.75) / 0.0625
// = 16 and its tangent 10 / 0.25 = 40 times the slope the constant moduli see at the density
// reached: the law's per-point wave modulus keeps the step stable (with lambda + 2 mu = E_max
// alone the block blew up at lambda = 0.28). The inner nodes follow the homogeneous motion and
// the internal energy is 3 Phi(0.75) V0 = 0.4725, the work of the driven boundary.
TEST(VerificationLowDensityFoam, HydrostaticSqueezeStaysStable) {
  auto sim = Simulation::fromText("ldf_hydro", hydrostaticBlock());
  sim->run();
  EXPECT_NEAR(sim->solver->time(), 1.0, 1e-9);
  const int centre = 1 + 2 + 5 * (2 + 5 * 2);  // (0.5, 0.5, 0.5)
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sim->x(centre, c), 0.125, 1e-3);
  const double stored = 3.0 * phi(0.75);
  EXPECT_NEAR(stored, 0.4725, 1e-12);
  const auto e = sim->solver->energies();
  EXPECT_NEAR(e.internal, stored, 0.01 * stored);
  EXPECT_NEAR(e.external_work, e.internal + e.kinetic + e.hourglass, 0.01 * stored);
}
