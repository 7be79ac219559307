// *MAT_ELASTIC_PLASTIC_HYDRO (010) at a material point in uniaxial strain against the answer
// worked by hand (Keyword Manual vol. II, *MAT_010): the deviator yields at the axial strain
// SIG0 / 2G and then hardens along sigma_y = SIG0 + EH eps_p with deps_p = 2G deps / (3G + EH);
// the pressure is the EOS's, held at PC in tension (PC = 0: no cutoff); the EPS/ES table
// replaces SIG0 and EH; FS fails the point.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <variant>

#include "material_point.hpp"
#include "materials/materials.hpp"

namespace m = crumple::materials;

namespace {

// Copper-like (mm, ms, g, MPa): the Taylor deck's G and SIG0, a linear EOS p = K mu.
constexpr double kG = 37593.0, kK = 140000.0, kRho = 8.9e-3, kSig0 = 180.0, kEh = 500.0;

m::ElasticPlasticHydro::Params params(double pc = 0.0, double fs = 0.0) {
  m::ElasticPlasticHydro::Params p;
  p.rho = kRho;
  p.G = kG;
  p.sig0 = kSig0;
  p.eh = kEh;
  p.pc = pc;
  p.fs = fs;
  return p;
}

m::ElasticPlasticHydro makeLaw(const m::ElasticPlasticHydro::Params& p,
                               const m::CurveAt& curves = {}) {
  m::Eos eos;  // linear polynomial p = K mu
  eos.c[1] = kK;
  return std::get<m::ElasticPlasticHydro>(m::makeLaw(p, curves, "", &eos));
}

using Point = crumple::testing::mp::SolidPoint;

// The von Mises stress expected in uniaxial strain at total axial log strain |eps| for a law
// with initial yield y0 and linear hardening h.
double expectedMises(double eps, double y0, double h) {
  const double ey = y0 / (2.0 * kG);
  if (std::abs(eps) <= ey) return 2.0 * kG * std::abs(eps);
  return y0 + h * (std::abs(eps) - ey) * 2.0 * kG / (3.0 * kG + h);
}

}  // namespace

// Compression in uniaxial strain: von Mises stress, plastic strain and axial stress
// -p - 2/3 q with p = K (1/V - 1), V = exp(eps), to round-off.
TEST(ElasticPlasticHydro, UniaxialStrainCompression) {
  const auto law = makeLaw(params());
  EXPECT_NEAR(law.moduli.bulk, kK, 1e-9 * kK);
  Point pt;
  const double de = -2e-4;
  double eps = 0.0;
  for (int i = 0; i < 300; ++i) {
    pt.step(law, {de, 0, 0, 0, 0, 0}, 1e-3);
    eps += de;
    const double q = expectedMises(eps, kSig0, kEh);
    ASSERT_NEAR(pt.mises(), q, 1e-9 * q) << i;
    const double p = kK * (std::exp(-eps) - 1.0);
    ASSERT_NEAR(pt.s[0], -p - 2.0 / 3.0 * q, 1e-9 * p) << i;
    ASSERT_NEAR(pt.s[1], -p + q / 3.0, 1e-9 * p) << i;
  }
  // Yield at 180 / 75186 = 0.00239; at 0.06: eps_p = (0.06 - 0.00239) 75186 / 113279.
  EXPECT_NEAR(pt.eps_p, (0.06 - kSig0 / (2.0 * kG)) * 2.0 * kG / (3.0 * kG + kEh), 1e-10);
  EXPECT_NEAR(pt.h[0], -0.06, 1e-12);  // ln(V / V0)
}

// Tension in uniaxial strain: the pressure falls to PC and stays there; with PC = 0 it goes on
// falling (no cutoff).
TEST(ElasticPlasticHydro, PressureCutoffInTension) {
  const auto cut = makeLaw(params(-300.0));
  const auto free = makeLaw(params(0.0));
  EXPECT_EQ(free.cutoff(), -std::numeric_limits<double>::infinity());
  Point a, b;
  for (int i = 0; i < 50; ++i) {
    a.step(cut, {1e-4, 0, 0, 0, 0, 0}, 1e-3);
    b.step(free, {1e-4, 0, 0, 0, 0, 0}, 1e-3);
  }
  const double pa = -(a.s[0] + a.s[1] + a.s[2]) / 3.0, pb = -(b.s[0] + b.s[1] + b.s[2]) / 3.0;
  EXPECT_EQ(pa, -300.0);
  EXPECT_NEAR(pb, kK * (std::exp(-0.005) - 1.0), 1e-9 * kK);  // -698
  EXPECT_NEAR(a.mises(), b.mises(), 1e-9 * b.mises());        // the deviator is the same
}

// The EPS/ES table (here 180 at 0, 300 at 0.1, 320 at 1) replaces SIG0 and EH: the von Mises
// stress follows the piecewise curve, extrapolated past its last point.
TEST(ElasticPlasticHydro, YieldCurveFromTable) {
  static const std::vector<double> x{0.0, 0.1, 1.0}, y{180.0, 300.0, 320.0};
  auto p = params();
  p.sig0 = 0.0;
  p.curve = 0;
  const auto law = makeLaw(p, m::CurveAt([](int32_t) { return m::CurveData{-1, x, y}; }));
  Point pt;
  for (int i = 0; i < 1200; ++i) {
    pt.step(law, {0, 0, 0, 2e-3, 0, 0}, 1e-3);  // pure shear: no pressure
    const double e = pt.eps_p;
    const double expect = e <= 0.0  ? pt.mises()
                          : e < 0.1 ? 180.0 + 1200.0 * e
                                    : 300.0 + 20.0 / 0.9 * (e - 0.1);
    ASSERT_NEAR(pt.mises(), expect, 1e-9 * expect) << i;
  }
  EXPECT_GT(pt.eps_p, 1.2);  // past the last point
}

// FS: the point fails in the step its effective plastic strain reaches FS, not before.
TEST(ElasticPlasticHydro, FailsAtFailureStrain) {
  const auto law = makeLaw(params(0.0, 0.05));
  EXPECT_EQ(law.failureStrain(), 0.05);
  Point pt;
  while (!pt.failed) {
    const double before = pt.eps_p;
    pt.step(law, {-1e-3, 0, 0, 0, 0, 0}, 1e-3);
    if (pt.failed) {
      EXPECT_LT(before, 0.05);
      EXPECT_GE(pt.eps_p, 0.05);
    }
    ASSERT_LT(pt.eps_p, 1.0);
  }
}
