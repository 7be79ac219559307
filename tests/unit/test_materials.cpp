// Constitutive laws: exact elastic answers, uniaxial-stress hardening slopes, Bauschinger
// effect, plastic incompressibility, consistency (return onto the yield surface), yield
// curves, Cowper-Symonds scaling, failure flags and batch-position independence.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <utility>
#include <variant>
#include <vector>

#include "materials/materials.hpp"
#include "rate_law.hpp"
#include "util/error.hpp"

namespace m = crumple::materials;

namespace {

// One integration point with all the state any law needs.
struct Point {
  std::array<double, 6> s{};
  std::array<double, 6> alpha{};
  double eps_p = 0.0;
  uint8_t failed = 0;
};

using Strain = std::array<double, 6>;

void update(const m::Law& law, m::PointBatch& b) {
  std::visit(
      [&](const auto& l) {
        if constexpr (requires { l.update(b); })
          l.update(b);
        else
          FAIL() << "a law without a solid update (beams only)";
      },
      law);
}

// Advances a single point by one step through a batch of one.
void step(const m::Law& law, Point& p, const Strain& de, double dt = 0.0) {
  m::PointBatch b;
  b.n = 1;
  b.dt = dt;
  for (int k = 0; k < 6; ++k) {
    b.s[k] = &p.s[k];
    b.de[k] = &de[k];
    b.alpha[k] = &p.alpha[k];
  }
  b.eps_p = &p.eps_p;
  b.failed = &p.failed;
  update(law, b);
}

// Uniaxial stress: one axial strain increment over dt, with the (equal) lateral strain
// increments found by secant iteration so that s_yy = s_zz = 0 at the end of the step; `used`
// (if given) receives the increment of the step.
void uniaxialStep(const m::Law& law, Point& p, double dex, double dt = 0.0,
                  Strain* used = nullptr) {
  const m::Moduli mod = m::moduliOf(law);
  const double nu = (3.0 * mod.bulk - 2.0 * mod.shear) / (2.0 * (3.0 * mod.bulk + mod.shear));
  auto trial = [&](double lat) {
    Point c = p;
    step(law, c, Strain{dex, lat, lat, 0, 0, 0}, dt);
    return c;
  };
  double x0 = -nu * dex, x1 = -0.5 * dex;
  Point c0 = trial(x0), c1 = trial(x1);
  for (int it = 0; it < 100; ++it) {
    const double r0 = c0.s[1], r1 = c1.s[1];
    if (std::abs(r1) <= 1e-13 * std::max(1.0, std::abs(c1.s[0])) || r1 == r0) break;
    const double x2 = x1 - r1 * (x1 - x0) / (r1 - r0);
    x0 = x1;
    c0 = c1;
    x1 = x2;
    c1 = trial(x1);
  }
  ASSERT_LE(std::abs(c1.s[1]), 1e-9 * std::max(1.0, std::abs(c1.s[0])));
  ASSERT_EQ(c1.s[1], c1.s[2]);  // symmetric lateral response
  p = c1;
  if (used != nullptr) *used = Strain{dex, x1, x1, 0, 0, 0};
}

// von Mises norm of dev(s) - alpha.
double vonMises(const Point& p, bool kinematic) {
  const double pr = (p.s[0] + p.s[1] + p.s[2]) / 3.0;
  double x[6];
  for (int k = 0; k < 6; ++k) x[k] = p.s[k] - (k < 3 ? pr : 0.0) - (kinematic ? p.alpha[k] : 0.0);
  const double j2 =
      0.5 * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) + x[3] * x[3] + x[4] * x[4] + x[5] * x[5];
  return std::sqrt(3.0 * j2);
}

// The effective strain rate sqrt(2/3 dev(de):dev(de)) / dt, computed independently.
double effectiveRate(const Strain& de, double dt) {
  const double tr = de[0] + de[1] + de[2];
  double ee = 0.0;
  for (int k = 0; k < 3; ++k) ee += (de[k] - tr / 3.0) * (de[k] - tr / 3.0);
  for (int k = 3; k < 6; ++k) ee += 2.0 * de[k] * de[k];
  return std::sqrt(2.0 / 3.0 * ee) / dt;
}

// Cowper-Symonds factor computed independently from the strain increment.
double csFactor(const Strain& de, double dt, double C, double P) {
  return 1.0 + std::pow(effectiveRate(de, dt) / C, 1.0 / P);
}

constexpr double kE = 210000.0, kNu = 0.3, kSigy = 250.0, kEtan = 2100.0;

// Laws are made from the deck's parameters, as the model gives them (make).
const std::vector<double> kCurveEps{0.0, 0.05, 0.2}, kCurveSig{200.0, 300.0, 360.0};
m::CurveData curveAt(int32_t i) {
  if (i != 0) throw crumple::util::InputError("no curve " + std::to_string(i));
  return {7, kCurveEps, kCurveSig};
}

m::PlasticKinematic makePK(double beta, double src = 0, double srp = 0, double fs = 0) {
  return m::PlasticKinematic::make({kE, kNu, kSigy, kEtan, beta, src, srp, fs}, curveAt, "");
}

m::PiecewiseLinear makePL(double sigy, double etan, double c = 0, double p = 0) {
  m::PiecewiseLinear::Params pp;
  pp.E = kE;
  pp.nu = kNu;
  pp.sigy = sigy;
  pp.etan = etan;
  pp.c = c;
  pp.p = p;
  return m::PiecewiseLinear::make(pp, curveAt, "");
}

// 3-point yield curve (aluminium-like) for MAT_024.
m::PiecewiseLinear makePLCurve(double c = 0, double p = 0, double fail = 0) {
  m::PiecewiseLinear::Params pp;
  pp.E = 70000.0;
  pp.nu = 0.33;
  pp.c = c;
  pp.p = p;
  pp.fail = fail;
  pp.lcss = 0;
  return m::PiecewiseLinear::make(pp, curveAt, "");
}

// The curve above, written out independently (extrapolated with the last slope).
double curveStress(double e) {
  if (e < 0.05) return 200.0 + 2000.0 * e;
  return 300.0 + 400.0 * (e - 0.05);
}

Strain randomStrain(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Strain d;
  for (double& v : d) v = u(rng);
  return d;
}

}  // namespace

// ---- elastic -------------------------------------------------------------------------------

TEST(MaterialsElastic, ModuliFromYoung) {
  const m::Moduli mod = m::moduliFromYoung(200.0, 0.25);
  EXPECT_DOUBLE_EQ(mod.bulk, 200.0 / 1.5);
  EXPECT_DOUBLE_EQ(mod.shear, 80.0);
}

TEST(MaterialsElastic, UniaxialStrainIsExact) {
  const m::Law law = m::Elastic{m::moduliFromYoung(kE, kNu)};
  const double lam = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), G = kE / (2 * (1 + kNu));
  Point p;
  const double d = 1e-4;
  step(law, p, Strain{d, 0, 0, 0, 0, 0});
  EXPECT_NEAR(p.s[0], (lam + 2 * G) * d, 1e-12 * (lam + 2 * G) * d);
  EXPECT_NEAR(p.s[1], lam * d, 1e-12 * lam * d);
  EXPECT_NEAR(p.s[2], lam * d, 1e-12 * lam * d);
  EXPECT_EQ(p.s[3], 0.0);
  EXPECT_EQ(p.s[4], 0.0);
  EXPECT_EQ(p.s[5], 0.0);
  EXPECT_EQ(p.eps_p, 0.0);
}

TEST(MaterialsElastic, PureShearUsesTensorComponents) {
  const m::Moduli mod = m::moduliFromYoung(kE, kNu);
  const m::Law law = m::Elastic{mod};
  Point p;
  const double g = 2e-4;  // tensor shear D_xy dt (engineering gamma would be 2g)
  step(law, p, Strain{0, 0, 0, g, 0, 0});
  step(law, p, Strain{0, 0, 0, 0, -g, 0});
  step(law, p, Strain{0, 0, 0, 0, 0, 0.5 * g});
  EXPECT_EQ(p.s[0], 0.0);
  EXPECT_EQ(p.s[1], 0.0);
  EXPECT_EQ(p.s[2], 0.0);
  EXPECT_DOUBLE_EQ(p.s[3], 2 * mod.shear * g);
  EXPECT_DOUBLE_EQ(p.s[4], -2 * mod.shear * g);
  EXPECT_DOUBLE_EQ(p.s[5], mod.shear * g);
}

// ---- MAT_003 -------------------------------------------------------------------------------

// Uniaxial stress after yield follows sigma = sigy + Etan (eps - sigy/E) for any beta.
TEST(MaterialsPlasticKinematic, UniaxialStressFollowsTangentModulus) {
  for (double beta : {0.0, 0.5, 1.0}) {
    SCOPED_TRACE(beta);
    const m::Law law = makePK(beta);
    Point p;
    double eps = 0.0;
    for (int i = 0; i < 100; ++i) {
      const double d = 2e-4;
      uniaxialStep(law, p, d);
      eps += d;
      const double expected = eps <= kSigy / kE ? kE * eps : kSigy + kEtan * (eps - kSigy / kE);
      EXPECT_NEAR(p.s[0], expected, 1e-6 * expected) << "eps " << eps;
      EXPECT_NEAR(p.eps_p, std::max(0.0, eps - p.s[0] / kE), 1e-9);
    }
    EXPECT_GT(p.eps_p, 0.015);
  }
}

// Load to eps_max, then reverse: reverse yielding at sigma_max - 2 R where R is the yield
// radius at eps_max: sigy (kinematic, Bauschinger), sigma_max (isotropic), in between mixed.
TEST(MaterialsPlasticKinematic, CyclicBauschingerAndIsotropicReversal) {
  const double Ep = kE * kEtan / (kE - kEtan);
  for (double beta : {0.0, 0.5, 1.0}) {
    SCOPED_TRACE(beta);
    const m::Law law = makePK(beta);
    Point p;
    const double d = 2e-4;
    const int n_up = 50;
    for (int i = 0; i < n_up; ++i) uniaxialStep(law, p, d);
    const double eps_max = n_up * d;
    const double sig_max = kSigy + kEtan * (eps_max - kSigy / kE);
    ASSERT_NEAR(p.s[0], sig_max, 1e-6 * sig_max);
    const double R = kSigy + beta * Ep * p.eps_p;
    const double sig_rev = sig_max - 2.0 * R;
    if (beta == 0.0) {
      EXPECT_NEAR(sig_rev, sig_max - 2 * kSigy, 1e-9);  // Bauschinger
    }
    if (beta == 1.0) {
      EXPECT_NEAR(sig_rev, -sig_max, 1e-9);  // isotropic: the surface grew to sigma_max
    }
    const double eps_rev = eps_max - (sig_max - sig_rev) / kE;
    const double eps_p_max = p.eps_p;
    double eps = eps_max;
    for (int i = 0; i < 100; ++i) {
      uniaxialStep(law, p, -d);
      eps -= d;
      if (eps > eps_rev) {
        EXPECT_NEAR(p.s[0], sig_max - kE * (eps_max - eps), 1e-6 * kSigy) << "eps " << eps;
        EXPECT_EQ(p.eps_p, eps_p_max) << "eps " << eps;
      } else {
        EXPECT_NEAR(p.s[0], sig_rev + kEtan * (eps - eps_rev), 1e-6 * kSigy) << "eps " << eps;
        EXPECT_NEAR(p.eps_p, eps_p_max + (eps_rev - eps) - (sig_rev - p.s[0]) / kE, 1e-9);
      }
    }
  }
}

// Plastic flow is deviatoric: the mean stress is K times the volumetric strain, whatever the
// plastic history; and every plastic step ends on the (rate-scaled) yield surface.
TEST(MaterialsPlasticKinematic, IncompressibleFlowAndConsistency) {
  const double Ep = kE * kEtan / (kE - kEtan);
  const double C = 40.4, P = 5.0, dt = 1e-6;
  for (bool rate : {false, true}) {
    for (double beta : {0.0, 0.3, 1.0}) {
      SCOPED_TRACE(beta);
      const m::Law law = rate ? makePK(beta, C, P) : makePK(beta);
      const m::Moduli mod = m::moduliOf(law);
      std::mt19937_64 rng(42);
      Point p;
      double vol = 0.0;
      int plastic_steps = 0;
      for (int i = 0; i < 300; ++i) {
        const Strain de = randomStrain(rng, 1.5e-3);
        const double ep0 = p.eps_p;
        step(law, p, de, dt);
        vol += de[0] + de[1] + de[2];
        const double pr = (p.s[0] + p.s[1] + p.s[2]) / 3.0;
        EXPECT_NEAR(pr, mod.bulk * vol, 1e-12 * mod.bulk * 1e-2);
        if (p.eps_p > ep0) {
          ++plastic_steps;
          const double rf = rate ? csFactor(de, dt, C, P) : 1.0;
          const double sy = rf * (kSigy + beta * Ep * p.eps_p);
          EXPECT_NEAR(vonMises(p, true), sy, 1e-11 * sy);
        } else {
          EXPECT_LE(vonMises(p, true), (rate ? csFactor(de, dt, C, P) : 1.0) *
                                           (kSigy + beta * Ep * p.eps_p) * (1 + 1e-12));
        }
        // The back stress stays deviatoric.
        EXPECT_NEAR(p.alpha[0] + p.alpha[1] + p.alpha[2], 0.0, 1e-12 * kSigy);
      }
      EXPECT_GT(plastic_steps, 100);
    }
  }
}

// Cowper-Symonds: first yield at (1 + (rate/C)^(1/P)) sigy for a deviatoric strain path.
TEST(MaterialsPlasticKinematic, CowperSymondsScalesFirstYield) {
  const double C = 40.4, P = 5.0, dt = 1e-5, d = 0.01;
  const Strain de{d, -0.5 * d, -0.5 * d, 0, 0, 0};  // effective rate d/dt = 1000/s
  const double rf = 1.0 + std::pow(1000.0 / C, 1.0 / P);
  // Perfectly plastic (ETAN 0): the surface stays at rf sigy.
  const m::PlasticKinematic pk =
      m::PlasticKinematic::make({kE, kNu, kSigy, 0.0, 0.0, C, P, 0.0}, curveAt, "");
  Point p;
  step(pk, p, de, dt);
  EXPECT_GT(p.eps_p, 0.0);
  EXPECT_NEAR(vonMises(p, false), rf * kSigy, 1e-12 * rf * kSigy);
  EXPECT_NEAR(std::abs(p.s[0] - p.s[1]), rf * kSigy, 1e-12 * rf * kSigy);

  // An elastic trial between sigy and rf sigy at that rate does not yield.
  const double G = pk.moduli.shear;
  const double d_el = 0.5 * (1.0 + rf) * kSigy / (3.0 * G);  // q_trial = 3 G d
  Point p2;
  step(pk, p2, Strain{d_el, -0.5 * d_el, -0.5 * d_el, 0, 0, 0}, d_el / 1000.0);
  EXPECT_EQ(p2.eps_p, 0.0);
  EXPECT_NEAR(vonMises(p2, false), 3.0 * G * d_el, 1e-12 * kSigy);

  // Without a time step there is no rate: plain sigy.
  Point p3;
  step(pk, p3, de, 0.0);
  EXPECT_NEAR(vonMises(p3, false), kSigy, 1e-12 * kSigy);
}

TEST(MaterialsPlasticKinematic, FailureFlagAtFailureStrain) {
  const double fs = 0.012;
  const m::Law law = makePK(0.5, 0, 0, fs);
  Point p;
  bool seen = false;
  for (int i = 0; i < 60; ++i) {
    uniaxialStep(law, p, 5e-4);
    EXPECT_EQ(p.failed, p.eps_p >= fs ? 1 : 0) << "eps_p " << p.eps_p;
    seen = seen || p.failed;
  }
  EXPECT_TRUE(seen);

  const m::Law no_fail = makePK(0.5);  // fs = 0: never
  Point q;
  for (int i = 0; i < 60; ++i) uniaxialStep(no_fail, q, 5e-4);
  EXPECT_GT(q.eps_p, fs);
  EXPECT_EQ(q.failed, 0);
}

// ---- MAT_024 -------------------------------------------------------------------------------

// Uniaxial stress reproduces the yield curve, including steps that cross a breakpoint or
// the end of the curve, and the extrapolation beyond it.
TEST(MaterialsPiecewiseLinear, UniaxialStressReproducesCurve) {
  const m::PiecewiseLinear pl = makePLCurve();
  const double E = 70000.0;
  EXPECT_DOUBLE_EQ(pl.yieldStress(0.0), 200.0);
  EXPECT_DOUBLE_EQ(pl.yieldStress(0.05), 300.0);
  EXPECT_NEAR(pl.yieldStress(0.3), 400.0, 1e-12);  // extrapolated
  for (double d : {0.0004, 0.0131, 0.047}) {
    SCOPED_TRACE(d);
    Point p;
    double eps = 0.0;
    while (eps < 0.35) {
      uniaxialStep(pl, p, d);
      eps += d;
      if (eps <= 200.0 / E) {
        EXPECT_NEAR(p.s[0], E * eps, 1e-9 * E * eps);
        EXPECT_EQ(p.eps_p, 0.0);
      } else {
        // Plastic axial strain = effective plastic strain in uniaxial stress.
        EXPECT_NEAR(p.eps_p, eps - p.s[0] / E, 1e-9);
        EXPECT_NEAR(p.s[0], curveStress(p.eps_p), 1e-6 * p.s[0]) << "eps " << eps;
      }
    }
    EXPECT_GT(p.eps_p, 0.2);  // went past the last point
  }
}

TEST(MaterialsPiecewiseLinear, BilinearMatchesTangentModulus) {
  const m::PiecewiseLinear pl = makePL(kSigy, kEtan);
  Point p;
  double eps = 0.0;
  for (int i = 0; i < 60; ++i) {
    uniaxialStep(pl, p, 3e-4);
    eps += 3e-4;
    const double expected = eps <= kSigy / kE ? kE * eps : kSigy + kEtan * (eps - kSigy / kE);
    EXPECT_NEAR(p.s[0], expected, 1e-6 * expected);
  }
  EXPECT_NEAR(pl.yieldStress(0.01), kSigy + kE * kEtan / (kE - kEtan) * 0.01, 1e-9);
}

TEST(MaterialsPiecewiseLinear, IncompressibleFlowAndReturnOnCurve) {
  const double C = 100.0, P = 4.0, dt = 1e-6;
  for (bool rate : {false, true}) {
    SCOPED_TRACE(rate);
    const m::PiecewiseLinear pl = rate ? makePLCurve(C, P) : makePLCurve();
    std::mt19937_64 rng(7);
    Point p;
    double vol = 0.0;
    int plastic_steps = 0;
    for (int i = 0; i < 400; ++i) {
      const Strain de = randomStrain(rng, 4e-3);
      const double ep0 = p.eps_p;
      step(pl, p, de, dt);
      vol += de[0] + de[1] + de[2];
      const double pr = (p.s[0] + p.s[1] + p.s[2]) / 3.0;
      EXPECT_NEAR(pr, pl.moduli.bulk * vol, 1e-12 * pl.moduli.bulk * 1e-1);
      if (p.eps_p > ep0) {
        ++plastic_steps;
        const double sy = (rate ? csFactor(de, dt, C, P) : 1.0) * curveStress(p.eps_p);
        EXPECT_NEAR(vonMises(p, false), sy, 1e-11 * sy);
      }
    }
    EXPECT_GT(plastic_steps, 100);
    EXPECT_GT(p.eps_p, 0.05);  // the walk crossed the breakpoint
  }
}

TEST(MaterialsPiecewiseLinear, CowperSymondsScalesFirstYield) {
  const double C = 40.0, P = 5.0, dt = 1e-5, d = 0.01;
  const Strain de{d, -0.5 * d, -0.5 * d, 0, 0, 0};
  const double rf = 1.0 + std::pow(1000.0 / C, 1.0 / P);
  m::PiecewiseLinear pl = makePLCurve(C, P);
  pl.curve_eps = {0.0};  // single point: perfectly plastic at 200
  pl.curve_sig = {200.0};
  Point p;
  step(pl, p, de, dt);
  EXPECT_GT(p.eps_p, 0.0);
  EXPECT_NEAR(vonMises(p, false), rf * 200.0, 1e-12 * rf * 200.0);

  const m::PiecewiseLinear bl = makePL(200.0, 0.0, C, P);  // bilinear with Etan = 0
  Point q;
  step(bl, q, de, dt);
  EXPECT_NEAR(vonMises(q, false), rf * 200.0, 1e-12 * rf * 200.0);
}

TEST(MaterialsPiecewiseLinear, FailureFlagAtFailureStrain) {
  const double fail = 0.03;
  const m::Law law = makePLCurve(0, 0, fail);
  Point p;
  bool seen = false;
  for (int i = 0; i < 40; ++i) {
    uniaxialStep(law, p, 1e-3);
    EXPECT_EQ(p.failed, p.eps_p >= fail ? 1 : 0) << "eps_p " << p.eps_p;
    seen = seen || p.failed;
  }
  EXPECT_TRUE(seen);
}

// ---- batch independence --------------------------------------------------------------------

// The same point gives bitwise identical results alone in a batch of 1 and at positions 0, 5
// and 12 of a batch of 13 (vectorised body versus scalar remainder).
TEST(MaterialsBatch, ResultsIndependentOfPositionInBatch) {
  const m::PiecewiseLinear bilinear = makePL(kSigy, kEtan, 40.0, 5.0);
  const std::vector<m::Law> laws{m::Elastic{m::moduliFromYoung(kE, kNu)},
                                 makePK(0.3),
                                 makePK(0.7, 40.4, 5.0, 0.01),
                                 makePLCurve(),
                                 makePLCurve(40.0, 5.0, 0.05),
                                 bilinear};
  for (std::size_t l = 0; l < laws.size(); ++l) {
    SCOPED_TRACE(l);
    for (int pos : {0, 5, 12}) {
      SCOPED_TRACE(pos);
      const int N = 13;
      std::mt19937_64 rng(1234);
      // SoA storage for the batch of 13 and the lone point.
      std::vector<double> s(6 * N), a(6 * N), de(6 * N), ep(N, 0.0);
      std::vector<uint8_t> failed(N, 0);
      std::uniform_real_distribution<double> u(-300.0, 300.0);
      for (double& v : s) v = u(rng);
      Point lone;
      for (int k = 0; k < 6; ++k) lone.s[k] = s[k * N + pos];
      m::PointBatch big, one;
      big.n = N;
      one.n = 1;
      Strain lone_de{};
      for (int k = 0; k < 6; ++k) {
        big.s[k] = &s[k * N];
        big.de[k] = &de[k * N];
        big.alpha[k] = &a[k * N];
        one.s[k] = &lone.s[k];
        one.de[k] = &lone_de[k];
        one.alpha[k] = &lone.alpha[k];
      }
      big.eps_p = ep.data();
      big.failed = failed.data();
      one.eps_p = &lone.eps_p;
      one.failed = &lone.failed;
      for (int st = 0; st < 40; ++st) {
        const double dt = 1e-6 * (1 + st % 3);
        big.dt = one.dt = dt;
        for (double& v : de) v = std::uniform_real_distribution<double>(-2e-3, 2e-3)(rng);
        for (int k = 0; k < 6; ++k) lone_de[k] = de[k * N + pos];
        update(laws[l], big);
        update(laws[l], one);
      }
      for (int k = 0; k < 6; ++k) {
        EXPECT_EQ(std::memcmp(&s[k * N + pos], &lone.s[k], sizeof(double)), 0) << k;
        EXPECT_EQ(std::memcmp(&a[k * N + pos], &lone.alpha[k], sizeof(double)), 0) << k;
      }
      EXPECT_EQ(std::memcmp(&ep[pos], &lone.eps_p, sizeof(double)), 0);
      EXPECT_EQ(failed[pos], lone.failed);
      if (l > 0) {
        EXPECT_GT(lone.eps_p, 0.0);
      }
    }
  }
}

// ---- rate dependence: LCSR and rate tables (tests/support/rate_law.hpp) ----------------------
namespace rl = crumple::testing::rate_law;

// Uniaxial stress at a constant strain rate (axial increments 2e-4 to 10 % strain): after
// every plastic step the von Mises stress is the expected yield stress at the step's
// effective strain rate and the new plastic strain, after an elastic step at most that (with
// the yield stress rising with the total rate, uniaxial stress may also be met elastically, at
// the higher rate of elastic lateral contraction); returns the last plastic step's rate and
// plastic strain.
template <class Yield>
std::pair<double, double> pullAtRate(const m::Law& law, double rate, Yield yield) {
  Point p;
  const double dex = 2e-4, dt = dex / rate;
  double r = 0.0;
  for (int k = 0; k < 500; ++k) {
    Strain de{};
    const double before = p.eps_p;
    uniaxialStep(law, p, dex, dt, &de);
    const double expected = yield(p.eps_p, effectiveRate(de, dt));
    if (p.eps_p == before) {
      EXPECT_LE(vonMises(p, false), expected * (1.0 + 1e-12)) << k;
      continue;
    }
    r = effectiveRate(de, dt);
    EXPECT_NEAR(vonMises(p, false), expected, 1e-6 * expected) << k;
    EXPECT_NEAR(p.s[0], expected, 1e-6 * expected) << k;  // uniaxial: s_xx is the von Mises stress
  }
  return {r, p.eps_p};
}

TEST(MaterialsPiecewiseLinear, RateTableUniaxialStressOnTheInterpolatedCurve) {
  const m::Law law = rl::tableLaw();
  // Below the first rate (the 1 /s curve), between 10 and 100 /s, above the last (100 /s).
  for (const double rate : {0.5, 40.0, 1000.0}) {
    const auto [r, eps_p] = pullAtRate(law, rate, rl::tableYield);
    // In plastic flow the step's rate is the axial rate (incompressible increments).
    EXPECT_NEAR(r, rate, 5e-3 * rate) << rate;
    EXPECT_GT(eps_p, 0.09) << rate;  // past the breakpoints of every curve but C's last
  }
  // Between 10 and 100 /s the stress lies strictly between the two curves.
  const auto [r, eps_p] = pullAtRate(law, 40.0, rl::tableYield);
  EXPECT_GT(rl::tableYield(eps_p, r), rl::hB(eps_p) + 1.0);
  EXPECT_LT(rl::tableYield(eps_p, r), rl::hC(eps_p) - 1.0);
}

TEST(MaterialsPiecewiseLinear, LogRateTableInterpolatesInLnRate) {
  // First value negative: the values are ln(rate); 31.6 /s lies halfway (in ln) between 1 and
  // 1000 /s.
  const m::Law law = rl::tableLaw(1);
  for (const double rate : {1e-4, 31.6, 1e4}) pullAtRate(law, rate, rl::logTableYield);
}

TEST(MaterialsPiecewiseLinear, LcsrScalesTheYieldStress) {
  for (const bool curve : {true, false}) {
    const m::Law law = rl::lcsrLaw(curve);
    for (const double rate : {20.0, 200.0}) {
      const auto [r, eps_p] = pullAtRate(law, rate, [&](double e, double rr) {
        return rl::lcsrFactor(rr) * rl::lcsrStatic(curve, e);
      });
      EXPECT_GT(eps_p, 0.08);
      // 200 /s is past the curve's last rate (100 /s): the factor follows its end slope.
      EXPECT_NEAR(r, rate, 1e-2 * rate);
    }
  }
}

// VP = 1 (viscoplastic, Keyword Manual *MAT_024 VP): pulled in uniaxial stress at a constant
// rate, after every plastic step the von Mises stress is the yield stress at the new plastic
// strain and the step's plastic strain rate, for every rate form (the tables, LCSR on a curve
// and on SIGY/ETAN, Cowper-Symonds), and the axial strain splits into the elastic strain of
// the stress increment and the plastic one (uniaxial flow: d eps_p^xx = d eps_p): the two
// equations that fix the step's answer.
TEST(MaterialsPiecewiseLinear, ViscoplasticYieldIsAtThePlasticStrainRate) {
  for (const auto& [law, yield] : rl::allLaws(true)) {
    const double E = m::youngOf(m::moduliOf(law));
    for (const double rate : {0.5, 40.0, 1000.0}) {
      Point p;
      const double dex = 2e-4, dt = dex / rate;
      for (int k = 0; k < 500; ++k) {
        const double before = p.eps_p, s_before = p.s[0];
        uniaxialStep(law, p, dex, dt);
        const double plastic_rate = (p.eps_p - before) / dt;
        const double expected = yield(p.eps_p, plastic_rate);
        if (p.eps_p == before) {
          ASSERT_LE(vonMises(p, false), expected * (1.0 + 1e-12)) << rate << " " << k;
          continue;
        }
        ASSERT_NEAR(vonMises(p, false), expected, 1e-10 * expected) << rate << " " << k;
        ASSERT_NEAR(p.eps_p - before, dex - (p.s[0] - s_before) / E, 1e-9 * dex) << k;
      }
      EXPECT_GT(p.eps_p, 0.06) << rate;
    }
  }
}

// VP = 1 with Cowper-Symonds P = 1 on a flat curve is Perzyna's overstress law (rate_law.hpp,
// Overstress): in pure shear from the yield surface at a constant rate, the return is its
// backward-Euler step to round-off, within 1 % of the overstress of the exact exponential
// approach at a step of 1/100 of the time constant, and ends at q_inf = SIGY (1 + rate / C).
TEST(MaterialsPiecewiseLinear, ViscoplasticOverstressFollowsPerzyna) {
  rl::Overstress o;
  const m::Law law = rl::cowperSymondsLaw(0.0, o.C, 1.0);
  o.M = 3.0 * m::moduliOf(law).shear;
  const double dt = 0.01 / o.rateConstant();
  const double d3 = 0.5 * std::sqrt(3.0) * o.rate * dt;  // tensor shear: effective rate `rate`
  Point p;
  p.s[3] = o.sigy / std::sqrt(3.0);
  double q_be = o.sigy;
  for (int k = 1; k <= 1000; ++k) {
    step(law, p, Strain{0, 0, 0, d3, 0, 0}, dt);
    q_be = o.backwardEuler(q_be, dt);
    const double q = vonMises(p, false);
    ASSERT_NEAR(q, q_be, 1e-11 * q) << k;
    ASSERT_NEAR(q, o.exact(k * dt), 0.01 * (o.steady() - o.sigy)) << k;
  }
  EXPECT_NEAR(vonMises(p, false), o.steady(), 1e-4 * o.steady());
}

// The shared checks of make(): a table that cannot be used is an input error naming it.
TEST(MaterialsPiecewiseLinear, RateTableChecks) {
  m::PiecewiseLinear::Params p;
  p.E = rl::kE;
  p.nu = rl::kNu;
  p.table = 0;
  const std::vector<double> down{10.0, 1.0, 100.0};
  const m::CurveAt bad(rl::rateCurves(), [&](int32_t) -> m::TableData {
    return {5, down, rl::kTableCurves};
  });
  EXPECT_THROW(m::PiecewiseLinear::make(p, bad, "at: "), crumple::util::InputError);
  // An LCSR curve whose factor reaches zero.
  p.table = -1;
  p.lcsr = 0;
  p.sigy = 250;
  const std::vector<double> zero{0.0, 1.0}, rates{0.0, 10.0};
  const m::CurveAt zf([&](int32_t) -> m::CurveData { return {9, rates, zero}; });
  EXPECT_THROW(m::PiecewiseLinear::make(p, zf, "at: "), crumple::util::InputError);
  // A table's first curve is its static curve; the initial yield stress is its first point.
  const m::PiecewiseLinear t = rl::tableLaw();
  EXPECT_EQ(t.yieldStress(0.0), 200.0);
  EXPECT_DOUBLE_EQ(t.yieldStress(0.1), rl::hA(0.1));
  // The merged grid: the plastic strains of all three curves.
  EXPECT_EQ(t.table.eps, (std::vector<double>{0.0, 0.02, 0.05, 0.1, 0.2, 0.3}));
}

// ---- makeLaw -------------------------------------------------------------------------------

TEST(MaterialsMakeLaw, BuildsEachLawFromItsParameters) {
  const m::Law l1 = m::makeLaw(m::Elastic::Params{200.0, 0.25}, curveAt, "");
  ASSERT_TRUE(std::holds_alternative<m::Elastic>(l1));
  EXPECT_DOUBLE_EQ(std::get<m::Elastic>(l1).moduli.shear, 80.0);

  const m::Law l2 = m::makeLaw(
      m::PlasticKinematic::Params{kE, kNu, kSigy, kEtan, 0.5, 40.4, 5.0, 0.2}, curveAt, "");
  ASSERT_TRUE(std::holds_alternative<m::PlasticKinematic>(l2));
  const auto& p2 = std::get<m::PlasticKinematic>(l2);
  const double Ep = kE * kEtan / (kE - kEtan);
  EXPECT_EQ(p2.hardening.sigy, kSigy);
  EXPECT_DOUBLE_EQ(p2.hardening.Hi, 0.5 * Ep);
  EXPECT_DOUBLE_EQ(p2.hardening.Hk, 0.5 * Ep);
  EXPECT_EQ(p2.hardening.C, 40.4);
  EXPECT_EQ(p2.hardening.inv_P, 1.0 / 5.0);
  EXPECT_EQ(p2.failureStrain(), 0.2);
  EXPECT_DOUBLE_EQ(p2.moduli.bulk, kE / (3 * (1 - 2 * kNu)));

  m::PiecewiseLinear::Params pll;
  pll.E = kE;
  pll.nu = kNu;
  pll.sigy = 999.0;  // ignored when LCSS is given
  pll.fail = 0.3;
  pll.c = 10.0;
  pll.p = 2.0;
  pll.tdel = 1e-7;
  pll.lcss = 0;
  const m::Law l3 = m::makeLaw(pll, curveAt, "");
  ASSERT_TRUE(std::holds_alternative<m::PiecewiseLinear>(l3));
  const auto& p3 = std::get<m::PiecewiseLinear>(l3);
  EXPECT_EQ(p3.yieldStress(0.0), 200.0);
  EXPECT_EQ(p3.curve_eps, kCurveEps);
  EXPECT_EQ(p3.curve_sig, kCurveSig);
  EXPECT_EQ(p3.failureStrain(), 0.3);
  EXPECT_EQ(m::deletionStepOf(l3), 1e-7);
  EXPECT_EQ(p3.linear.C, 10.0);
  EXPECT_EQ(p3.linear.inv_P, 0.5);
  EXPECT_DOUBLE_EQ(p3.yieldStress(0.3), 400.0);

  pll.lcss = -1;
  pll.sigy = 300.0;
  pll.etan = 1000.0;
  const auto p4 = std::get<m::PiecewiseLinear>(m::makeLaw(pll, curveAt, ""));
  EXPECT_TRUE(p4.curve_eps.empty());
  EXPECT_EQ(p4.yieldStress(0.0), 300.0);
  EXPECT_DOUBLE_EQ(p4.linear.Hi, kE * 1000.0 / (kE - 1000.0));

  // A rigid part's elements see the elastic law of its E and PR.
  const m::Law l5 = m::makeLaw(m::Rigid::Params{kE, kNu, 0, 0, 0}, curveAt, "");
  EXPECT_TRUE(std::holds_alternative<m::Elastic>(l5));
}

TEST(MaterialsMakeLaw, RejectsUnusableParameters) {
  m::PiecewiseLinear::Params pll;
  pll.E = kE;
  pll.nu = kNu;
  pll.sigy = kSigy;
  pll.lcss = 3;  // no such curve
  EXPECT_THROW(m::makeLaw(pll, curveAt, ""), crumple::util::InputError);
  // Etan = E; BETA > 1; PR = 0.5.
  EXPECT_THROW(m::makeLaw(m::PlasticKinematic::Params{kE, kNu, kSigy, kE, 0, 0, 0, 0}, curveAt, ""),
               crumple::util::InputError);
  EXPECT_THROW(
      m::makeLaw(m::PlasticKinematic::Params{kE, kNu, kSigy, kEtan, 1.5, 0, 0, 0}, curveAt, ""),
      crumple::util::InputError);
  EXPECT_THROW(m::makeLaw(m::Elastic::Params{kE, 0.5}, curveAt, ""), crumple::util::InputError);
  // A spring law has no continuum update, a continuum law no discrete force law.
  EXPECT_THROW(m::makeLaw(m::SpringElastic::Params{1.0}, curveAt, "at: "),
               crumple::util::InputError);
  EXPECT_THROW(m::makeDiscreteLaw(m::Elastic::Params{kE, kNu}, curveAt, "at: "),
               crumple::util::InputError);
}

// Which element families each law serves (the model refuses a part whose law lacks its
// family's update, naming the part: test_build.cpp).
TEST(MaterialsRegistry, FamiliesCostsAndNames) {
  using F = m::Family;
  const m::LawParams elastic = m::Elastic::Params{kE, kNu};
  const m::LawParams spring = m::SpringElastic::Params{1.0};
  const m::LawParams rigid = m::Rigid::Params{kE, kNu, 0, 0, 0};
  for (F f : {F::Solid, F::Shell, F::Beam}) {
    EXPECT_TRUE(m::supports(elastic, f));
    EXPECT_TRUE(m::supports(rigid, f));
    EXPECT_FALSE(m::supports(spring, f));
  }
  EXPECT_FALSE(m::supports(elastic, F::Discrete));
  EXPECT_FALSE(m::supports(rigid, F::Discrete));
  EXPECT_TRUE(m::supports(spring, F::Discrete));
  EXPECT_EQ(m::costOf(elastic), m::Cost::Elastic);
  EXPECT_EQ(m::costOf(m::LawParams{m::PiecewiseLinear::Params{}}), m::Cost::Plastic);
  EXPECT_EQ(m::costOf(rigid), m::Cost::Rigid);
  EXPECT_EQ(m::costOf(spring), m::Cost::Discrete);
  EXPECT_EQ(m::keywordOf(m::LawParams{m::PlasticKinematic::Params{}}), "*MAT_PLASTIC_KINEMATIC");
  EXPECT_FALSE(m::hasDensity(spring));
  EXPECT_TRUE(m::isRigid(rigid));
  EXPECT_FALSE(m::isRigid(elastic));
}
