// Unit tests of the empirical blast load (constraints/blast.hpp): the Kingery-Bulmash
// hemispherical surface-burst parameters against an independent published fit of the same
// data, the Friedlander pulse's impulse, and the angle-of-incidence combination.
#include <gtest/gtest.h>

#include <cmath>

#include "constraints/blast.hpp"

namespace {

using crumple::constraints::BlastCharge;
using crumple::constraints::blastPressure;
using crumple::constraints::blastPulse;
using crumple::constraints::friedlander;
using crumple::constraints::friedlanderDecay;
using crumple::constraints::hemisphericalBurst;

// Swisdak, "Simplified Kingery Airblast Calculations", Naval Surface Warfare Center Indian
// Head, 1994 (DTIC ADA526744): hemispherical TNT surface burst, metric (Z in m / kg^(1/3),
// kPa, ms / kg^(1/3), kPa ms / kg^(1/3)): Y = exp(A + B ln Z + C ln^2 Z + ...), one set of
// coefficients per range of Z. A fit of the Kingery-Bulmash data independent of UFC 3-340-02's.
double swisdak(double z, std::initializer_list<double> c) {
  const double l = std::log(z);
  double y = 0.0, p = 1.0;
  for (const double a : c) {
    y += a * p;
    p *= l;
  }
  return std::exp(y);
}
struct Reference {
  double pso, pr, ta, t0, is, ir;
};
Reference swisdakAt(double z) {
  Reference r;
  r.pso = z <= 2.9 ? swisdak(z, {7.2106, -2.1069, -0.3229, 0.1117, 0.0685})
                   : swisdak(z, {7.5938, -3.0523, 0.40977, 0.0261, -0.01267});
  r.pr = z <= 2.0 ? swisdak(z, {9.006, -2.6893, -0.6295, 0.1011, 0.29255, 0.13505, 0.019736})
                  : swisdak(z, {8.8396, -1.733, -2.64, 2.293, -0.8232, 0.14247, -0.0099});
  r.ta = z <= 1.5 ? swisdak(z, {-0.7604, 1.8058, 0.1257, -0.0437, -0.0310, -0.00669})
                  : swisdak(z, {-0.7137, 1.5732, 0.5561, -0.4213, 0.1054, -0.00929});
  r.t0 = z <= 1.02  ? swisdak(z, {0.5426, 3.2299, -1.5931, -5.9667, -4.0815, -0.9149})
         : z <= 2.8 ? swisdak(z, {0.5440, 2.7082, -9.7354, 14.3425, -9.7791, 2.8535})
                    : swisdak(z, {-2.4608, 7.1639, -5.6215, 2.2711, -0.44994, 0.03486});
  r.is = z <= 0.96   ? swisdak(z, {5.522, 1.117, 0.6, -0.292, -0.087})
         : z <= 2.38 ? swisdak(z, {5.465, -0.308, -1.464, 1.362, -0.432})
                     : swisdak(z, {5.2749, -0.4677, -0.2499, 0.0588, -0.00554});
  r.ir = swisdak(z, {6.7853, -1.3466, 0.101, -0.01123});
  return r;
}

constexpr double kFtPerM = 3.28083989501, kLbPerKg = 2.20462262185, kKpaPerPsi = 6.89475729317;

// At three scaled distances, from close in (Z = 0.5 m/kg^(1/3), Pso about 5 MPa) to far
// (Z = 10, about 15 kPa), the UFC 3-340-02 polynomials agree with Swisdak's fits within 2 %
// (Swisdak states his fits reproduce Kingery-Bulmash to about 1 %).
TEST(Blast, KingeryBulmashMatchesSwisdakAtThreeScaledDistances) {
  const double w13 = std::cbrt(kLbPerKg);  // (lb / kg)^(1/3)
  for (const double zm : {0.5, 2.0, 10.0}) {
    const auto k = hemisphericalBurst(zm * kFtPerM / w13);
    const Reference r = swisdakAt(zm);
    SCOPED_TRACE("Z = " + std::to_string(zm) + " m/kg^(1/3)");
    EXPECT_NEAR(k.pso * kKpaPerPsi / r.pso, 1.0, 0.02);
    EXPECT_NEAR(k.pr * kKpaPerPsi / r.pr, 1.0, 0.02);
    EXPECT_NEAR(k.ta * w13 / r.ta, 1.0, 0.02);
    EXPECT_NEAR(k.t0 * w13 / r.t0, 1.0, 0.02);
    EXPECT_NEAR(k.is * kKpaPerPsi * w13 / r.is, 1.0, 0.02);
    EXPECT_NEAR(k.ir * kKpaPerPsi * w13 / r.ir, 1.0, 0.02);
  }
}

// Far from the charge the blast is acoustic: normal reflection doubles the pressure.
TEST(Blast, ReflectionFactorTendsToTwoFarAway) {
  const auto k = hemisphericalBurst(100.0);
  EXPECT_NEAR(k.pr / k.pso, 2.0, 0.05);
  // and it grows close in (about 8 at Z = 1 ft/lb^(1/3), strong shocks)
  const auto c = hemisphericalBurst(1.0);
  EXPECT_GT(c.pr / c.pso, 6.0);
}

// The fits of several ranges meet where they join (positive phase duration at Z = 2.54 and 7,
// incident impulse at 2.41 ft/lb^(1/3)) within 2 %.
TEST(Blast, PiecewiseFitsAreContinuous) {
  for (const double z : {2.41, 2.54, 7.0}) {
    const auto below = hemisphericalBurst(z * (1.0 - 1e-9));
    const auto above = hemisphericalBurst(z * (1.0 + 1e-9));
    SCOPED_TRACE(z);
    EXPECT_NEAR(below.t0 / above.t0, 1.0, 0.02);
    EXPECT_NEAR(below.is / above.is, 1.0, 0.02);
  }
}

// The decay constant makes the positive phase's integral the impulse it was given; a
// triangular pulse (i = p t0 / 2) has b = 0.
TEST(Blast, FriedlanderPulseCarriesTheImpulse) {
  const double p = 3.0, t0 = 2.0;
  EXPECT_NEAR(friedlanderDecay(p, t0, 0.5 * p * t0), 0.0, 1e-9);
  for (const double impulse : {0.2, 1.0, 2.9, 3.5}) {
    const double b = friedlanderDecay(p, t0, impulse);
    const int n = 20000;
    double sum = 0.0;  // Simpson over [0, t0]
    for (int i = 0; i <= n; ++i) {
      const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      sum += w * friedlander(p, t0, b, t0 * i / n, true);
    }
    EXPECT_NEAR(sum * t0 / n / 3.0, impulse, 1e-9 * impulse) << impulse;
  }
  // The negative phase follows the same curve, or is cut off.
  const double b = friedlanderDecay(p, t0, 1.0);
  EXPECT_LT(friedlander(p, t0, b, 1.5 * t0, true), 0.0);
  EXPECT_EQ(friedlander(p, t0, b, 1.5 * t0, false), 0.0);
  EXPECT_EQ(friedlander(p, t0, b, -1e-12, true), 0.0);
}

// Randers-Pehrson & Bannister: facing the charge the reflected pressure, side-on the incident,
// facing away the incident; in SI units (UNIT 2) the peaks are the fits' converted.
TEST(Blast, AngleOfIncidenceCombinesIncidentAndReflected) {
  BlastCharge c;
  c.mass = 100.0;
  c.cfm = kLbPerKg, c.cfl = kFtPerM, c.cft = 1e3, c.cfp = 1.0 / (1e3 * kKpaPerPsi);
  const double range = 10.0;
  const auto pulse = blastPulse(c, range);
  const auto k = hemisphericalBurst(range * kFtPerM / std::cbrt(c.mass * kLbPerKg));
  EXPECT_NEAR(pulse.pso, k.pso * kKpaPerPsi * 1e3, 1e-9 * pulse.pso);
  EXPECT_NEAR(pulse.pr, k.pr * kKpaPerPsi * 1e3, 1e-9 * pulse.pr);
  const double t = pulse.arrival;
  EXPECT_EQ(blastPressure(c, pulse, t * (1 - 1e-9), 1.0), 0.0);  // before arrival
  EXPECT_NEAR(blastPressure(c, pulse, t, 1.0), pulse.pr, 1e-9 * pulse.pr);
  EXPECT_NEAR(blastPressure(c, pulse, t, 0.0), pulse.pso, 1e-9 * pulse.pso);
  EXPECT_NEAR(blastPressure(c, pulse, t, -0.5), pulse.pso, 1e-9 * pulse.pso);
  const double c45 = std::sqrt(0.5);
  EXPECT_NEAR(blastPressure(c, pulse, t, c45), 0.5 * pulse.pr + pulse.pso * (1.5 - 2.0 * c45),
              1e-9 * pulse.pr);
  c.death = 0.5 * t;
  EXPECT_EQ(blastPressure(c, pulse, t, 1.0), 0.0);  // after DEATH
}

}  // namespace
