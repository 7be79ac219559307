// *MAT_VISCOELASTIC (006) at a material point against the hereditary integral of the Theory
// Manual (material model 6) worked in closed form: shear at a constant rate, relaxation after
// a step strain, the elastic bulk response, and the shell's plane-stress update against the
// solid update at the thickness strain it finds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "material_point.hpp"
#include "materials/materials.hpp"
#include "util/error.hpp"

namespace m = crumple::materials;
using crumple::testing::mp::ShellPoint;
using crumple::testing::mp::SolidPoint;

namespace {

// A rubber-like solid, mm ms MPa-ish units: K 2000, G0 10, GI 2, BETA 0.5 per time unit.
constexpr double kBulk = 2000.0, kG0 = 10.0, kGi = 2.0, kBeta = 0.5;

m::Law makeLaw(double gi = kGi, double beta = kBeta) {
  m::Viscoelastic::Params p;
  p.bulk = kBulk;
  p.g0 = kG0;
  p.gi = gi;
  p.beta = beta;
  return m::makeLaw(p, {}, "");
}

// tau(t) = 2 int_0^t G(t - s) (gamma_dot / 2) ds for an engineering shear rate gamma_dot.
double shearAtConstantRate(double gamma_dot, double t) {
  return kGi * gamma_dot * t + (kG0 - kGi) * gamma_dot * -std::expm1(-kBeta * t) / kBeta;
}

}  // namespace

// The recursive update integrates h exactly for a strain rate constant over each step, so a
// constant rate gives the closed form at any step size, uneven steps included.
TEST(Viscoelastic, ShearAtConstantRateFollowsTheHereditaryIntegral) {
  const m::Law law = makeLaw();
  const double rate = 0.02;  // engineering shear strain per time unit
  SolidPoint p;
  double t = 0.0;
  for (int i = 0; i < 1200; ++i) {
    const double dt = i % 3 == 0 ? 0.05 : 0.013;
    p.step(law, {0, 0, 0, 0.5 * rate * dt, 0, 0}, dt);
    t += dt;
    ASSERT_NEAR(p.s[3], shearAtConstantRate(rate, t), 1e-12 * kG0) << "t " << t;
  }
  // Long after the relaxation time the stress grows at the long-time modulus only.
  EXPECT_GT(t, 10.0 / kBeta);
  EXPECT_NEAR(p.s[3], kGi * rate * t + (kG0 - kGi) * rate / kBeta, 1e-3 * p.s[3]);
  for (int k : {0, 1, 2, 4, 5}) EXPECT_EQ(p.s[static_cast<std::size_t>(k)], 0.0);
}

// A shear strain applied at once and held: tau = gamma (GI + (G0 - GI) exp(-BETA t)).
TEST(Viscoelastic, StepStrainRelaxesToTheLongTimeModulus) {
  const m::Law law = makeLaw();
  const double gamma = 0.01;
  SolidPoint p;
  p.step(law, {0, 0, 0, 0.5 * gamma, 0, 0}, 1e-12);
  EXPECT_NEAR(p.s[3], kG0 * gamma, 1e-9 * kG0 * gamma);
  double t = 0.0;
  for (int i = 0; i < 200; ++i) {
    p.step(law, {}, 0.1);
    t += 0.1;
    ASSERT_NEAR(p.s[3], gamma * (kGi + (kG0 - kGi) * std::exp(-kBeta * t)), 1e-9 * kG0 * gamma);
  }
  // GI = 0: a fluid-like solid relaxes to no shear stress.
  const m::Law fluid = makeLaw(0.0);
  SolidPoint q;
  q.step(fluid, {0, 0, 0, 0.5 * gamma, 0, 0}, 1e-12);
  for (int i = 0; i < 100; ++i) q.step(fluid, {}, 1.0);
  EXPECT_NEAR(q.s[3], kG0 * gamma * std::exp(-kBeta * 100.0), 1e-15);
}

// Volume change alone: the pressure is elastic (K times the summed volumetric strain, the
// ln(V / V0) of the manual for the solids' logarithmic increments), no deviator, nothing relaxes.
TEST(Viscoelastic, BulkResponseIsElastic) {
  const m::Law law = makeLaw();
  SolidPoint p;
  for (int i = 0; i < 50; ++i) p.step(law, {-1e-4, -1e-4, -1e-4, 0, 0, 0}, 0.3);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.s[static_cast<std::size_t>(k)], -kBulk * 0.015, 1e-10);
  for (double a : p.alpha) EXPECT_NEAR(a, 0.0, 1e-14);
}

// The shell point: in-plane stress and relaxing stress equal to the solid update at the
// thickness strain the shell returns, whose sigma_zz is then zero, over a random path.
TEST(Viscoelastic, PlaneStressMatchesTheSolidAtItsThicknessStrain) {
  const m::Law law = makeLaw();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-2e-3, 2e-3);
  ShellPoint shell;
  SolidPoint solid;
  for (int i = 0; i < 100; ++i) {
    const double dxx = u(rng), dyy = u(rng), dxy = u(rng), dt = 0.05 + 0.1 * (i % 4);
    shell.step(law, dxx, dyy, dxy, dt);
    solid.step(law, {dxx, dyy, shell.de_zz, dxy, 0, 0}, dt);
    ASSERT_NEAR(solid.s[2], 0.0, 1e-11 * kBulk);
    EXPECT_NEAR(shell.s[0], solid.s[0], 1e-11 * kBulk);
    EXPECT_NEAR(shell.s[1], solid.s[1], 1e-11 * kBulk);
    EXPECT_NEAR(shell.s[2], solid.s[3], 1e-11 * kBulk);
    EXPECT_NEAR(shell.alpha[0], solid.alpha[0], 1e-11 * kBulk);
    EXPECT_NEAR(shell.alpha[2], solid.alpha[3], 1e-11 * kBulk);
  }
  EXPECT_GT(std::abs(shell.s[0]), 1e-3);
}

// Parameters no reader would pass are refused when the law is made.
TEST(Viscoelastic, BadParametersRefused) {
  EXPECT_THROW(makeLaw(20.0), crumple::util::InputError);  // GI > G0
  EXPECT_THROW(makeLaw(kGi, -1.0), crumple::util::InputError);
}
