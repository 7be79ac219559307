// Three-dimensional stress updates the laws are built from (return_mapping.hpp): Hooke's law
// and J2 (von Mises) plasticity with radial return, used by *MAT_PLASTIC_KINEMATIC (003) and
// *MAT_PIECEWISE_LINEAR_PLASTICITY (024) among others.
//
// The plastic updates use the classical elastic-predictor / radial-return algorithm (Wilkins 1964;
// Krieg & Key 1976; Simo & Hughes, Computational Inelasticity, 1998, Box 3.2 for linear
// combined isotropic/kinematic hardening; LS-DYNA Theory Manual, material models 3 and 24).
//
// Notation (tensor shear components throughout, Voigt order xx yy zz xy yz zx):
//   t      trial stress  s + lambda tr(de) I + 2 G de
//   xi     relative stress  dev(t) - alpha  (alpha, the back stress, is deviatoric)
//   q      von Mises norm  sqrt(3/2 xi:xi)
//   n      flow direction  3/2 xi / q, so that the plastic strain increment is deps * n and
//          deps is the effective plastic strain increment (sqrt(2/3 n:n) = 1)
// With Prager's rule dalpha = 2/3 Hk deps n and isotropic modulus Hi, the relative stress
// shrinks radially: q_new = q - (3 G + Hk) deps, while the yield stress grows by Hi deps, so
//   deps = f / (3 G + Hk + Hi),  f = q - sigma_y.
// For MAT_003, Hk = (1 - beta) Ep and Hi = beta Ep with Ep = E Etan / (E - Etan), so the
// uniaxial stress-strain slope after yield is E Ep / (E + Ep) = Etan for every beta.
//
// Loops are written per point without any cross-point data so that a point's result does
// not depend on its position in the batch (vector body and scalar remainder execute the same
// IEEE operations; the build disables FMA contraction).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "materials/return_mapping.hpp"
#include "materials/soa.hpp"
#include "util/curve.hpp"

namespace crumple::materials {

namespace {

constexpr double kThird = 1.0 / 3.0;

// How the yield stress depends on the strain rate: not at all, the Cowper-Symonds factor, the
// factor of an LCSR curve, or the curve of a rate table at the rate (rate.hpp).
enum class Rate : uint8_t { None, CowperSymonds, Curve, Table, Yield };

// The effective strain rate of the step, sqrt(2/3 dev(de):dev(de)) / dt (LS-DYNA keyword
// manual, MAT_003 and MAT_024), the rate of every rate form (VP = 0).
inline double effectiveRate(double d0, double d1, double d2, double d3, double d4, double d5,
                            double tr, double inv_dt) {
  const double e0 = d0 - tr * kThird;
  const double e1 = d1 - tr * kThird;
  const double e2 = d2 - tr * kThird;
  const double ee = e0 * e0 + e1 * e1 + e2 * e2 + 2.0 * (d3 * d3 + d4 * d4 + d5 * d5);
  return std::sqrt(2.0 / 3.0 * ee) * inv_dt;
}

// The rate factor rf of a rate form at an effective strain rate (1 for Rate::None, Table):
// Cowper-Symonds 1 + (rate / C)^(1/P), or the LCSR curve's factor.
template <Rate kRate, class P>
inline double factorAt(const P& law, double rate) {
  if constexpr (kRate == Rate::CowperSymonds) return 1.0 + std::pow(rate / law.C, law.inv_P);
  if constexpr (kRate == Rate::Curve) return law.lcsr(rate);
  return 1.0;
}

// The initial yield stress of a point: the curve of the strain rate (Rate::Yield), else sigy.
template <Rate kRate>
inline double initialYield(const LinearHardening& law, double d0, double d1, double d2, double d3,
                           double d4, double d5, double tr, double inv_dt) {
  if constexpr (kRate == Rate::Yield)
    return law.sigy_rate(effectiveRate(d0, d1, d2, d3, d4, d5, tr, inv_dt));
  return law.sigy;
}

// The factor rf on the yield stress of a point (1 for Rate::None, Table and Yield).
template <Rate kRate, class P>
inline double rateFactor(const P& law, double d0, double d1, double d2, double d3, double d4,
                         double d5, double tr, double inv_dt) {
  if constexpr (kRate == Rate::CowperSymonds || kRate == Rate::Curve)
    return factorAt<kRate>(law, effectiveRate(d0, d1, d2, d3, d4, d5, tr, inv_dt));
  return 1.0;
}

// Hypoelastic (Hooke's law on the rate of deformation): the kernel has already applied the
// Jaumann rotation, so the increment is ds = lambda tr(de) I + 2 G de with tensor shear
// components (2 G de_xy is the shear stress increment for de_xy = D_xy dt).
void elasticKernel(detail::Soa a, int n, double lam, double G2) {
  for (int i = 0; i < n; ++i) {
    const double lt = lam * (a.d0[i] + a.d1[i] + a.d2[i]);
    a.s0[i] += lt + G2 * a.d0[i];
    a.s1[i] += lt + G2 * a.d1[i];
    a.s2[i] += lt + G2 * a.d2[i];
    a.s3[i] += G2 * a.d3[i];
    a.s4[i] += G2 * a.d4[i];
    a.s5[i] += G2 * a.d5[i];
  }
}

// Elastic predictor and radial return for linear mixed hardening; exact for linear hardening
// (the return is along the trial direction, which the back stress update preserves).
// The return has no branch: deps = max(f, 0) / (...) is zero for elastic points and the
// corrections then subtract exact zeros, so elastic points keep the trial stress bit for bit
// (the selects are if-converted; with -fno-math-errno -fno-trapping-math, which change no
// result, GCC vectorises this loop).
template <bool kKinematic, Rate kRate>
void linearHardeningKernel(detail::Soa a, int n, double dt, double G, double lam,
                           const LinearHardening& P) {
  const double G2 = 2.0 * G, G3 = 3.0 * G;
  const double inv_dt = dt > 0.0 ? 1.0 / dt : 0.0;
  for (int i = 0; i < n; ++i) {
    // Elastic predictor (same expression as Elastic::update).
    const double tr = a.d0[i] + a.d1[i] + a.d2[i];
    const double lt = lam * tr;
    const double t0 = a.s0[i] + (lt + G2 * a.d0[i]);
    const double t1 = a.s1[i] + (lt + G2 * a.d1[i]);
    const double t2 = a.s2[i] + (lt + G2 * a.d2[i]);
    const double t3 = a.s3[i] + G2 * a.d3[i];
    const double t4 = a.s4[i] + G2 * a.d4[i];
    const double t5 = a.s5[i] + G2 * a.d5[i];
    const double rf =
        rateFactor<kRate>(P, a.d0[i], a.d1[i], a.d2[i], a.d3[i], a.d4[i], a.d5[i], tr, inv_dt);
    // Relative deviatoric stress and its von Mises norm.
    const double p = (t0 + t1 + t2) * kThird;
    double x0 = t0 - p, x1 = t1 - p, x2 = t2 - p, x3 = t3, x4 = t4, x5 = t5;
    if constexpr (kKinematic) {
      x0 -= a.a0[i];
      x1 -= a.a1[i];
      x2 -= a.a2[i];
      x3 -= a.a3[i];
      x4 -= a.a4[i];
      x5 -= a.a5[i];
    }
    const double j2 = 0.5 * (x0 * x0 + x1 * x1 + x2 * x2) + (x3 * x3 + x4 * x4 + x5 * x5);
    const double q = std::sqrt(3.0 * j2);
    const double e = a.ep[i];
    // sigma_y = rf (sigy + Hi eps_p): the rate factor scales the isotropic yield stress only
    // (LS-DYNA MAT_003), so consistency at eps_p + deps gives 3G + Hk + rf Hi below; this
    // reduces to 3G + Ep when rf = 1 and lands exactly on the surface otherwise.
    const double sy0 =
        initialYield<kRate>(P, a.d0[i], a.d1[i], a.d2[i], a.d3[i], a.d4[i], a.d5[i], tr, inv_dt);
    const double f = q - rf * (sy0 + P.Hi * e);
    const double deps = (f > 0.0 ? f : 0.0) / (G3 + P.Hk + rf * P.Hi);
    // ds = -2 G deps n = -3 G deps xi / q; dalpha = 2/3 Hk deps n = Hk deps xi / q.
    const double c = deps / (q > 0.0 ? q : 1.0);
    const double cs = G3 * c;
    a.s0[i] = t0 - cs * x0;
    a.s1[i] = t1 - cs * x1;
    a.s2[i] = t2 - cs * x2;
    a.s3[i] = t3 - cs * x3;
    a.s4[i] = t4 - cs * x4;
    a.s5[i] = t5 - cs * x5;
    if constexpr (kKinematic) {
      const double ca = P.Hk * c;
      a.a0[i] += ca * x0;
      a.a1[i] += ca * x1;
      a.a2[i] += ca * x2;
      a.a3[i] += ca * x3;
      a.a4[i] += ca * x4;
      a.a5[i] += ca * x5;
    }
    a.ep[i] = e + deps;
  }
}

template <bool kKinematic, Rate kRate>
void linearHardeningUpdate(PointBatch& b, const Moduli& m, const LinearHardening& P) {
  linearHardeningKernel<kKinematic, kRate>(detail::soaOf(b), b.n, b.dt, m.shear,
                                           m.bulk - 2.0 * m.shear / 3.0, P);
}

// ---- piecewise-linear yield curve ---------------------------------------------------------
// The segment search and interpolation of util/curve.hpp, as model::Curve::valueExtrapolated.
using util::onSegment;
using util::segmentOf;

// Effective plastic strain increment that returns a trial stress of von Mises norm q > the
// current flow stress to the piecewise-linear curve h scaled by rf:
//   g(deps) = q - 3 G deps - rf h(eps_p + deps) = 0.
// g is piecewise linear and decreasing (for slopes above -3G/rf), so walking the segments
// from eps_p and solving linearly in the segment where g changes sign is exact (it is the
// Newton iteration on the piecewise-linear curve, converged in one step per segment crossed).
template <class Y>
double returnToCurve(std::span<const double> x, const Y& y, double G3, double rf, double q,
                     double eps) {
  const std::size_t m = x.size();
  if (m == 1) return (q - rf * y[0]) / G3;  // constant flow stress: perfect plasticity
  std::size_t k = segmentOf(x, eps);
  double xa = eps, ha = onSegment(x, y, k, eps);
  for (;;) {
    const double ga = q - G3 * (xa - eps) - rf * ha;
    const double dx = x[k + 1] - x[k];
    const double H = dx > 0.0 ? (y[k + 1] - y[k]) / dx : 0.0;
    if (k + 2 == m) return (xa - eps) + ga / (G3 + rf * H);  // last segment: unbounded
    const double xb = x[k + 1], hb = y[k + 1];
    const double gb = q - G3 * (xb - eps) - rf * hb;
    if (gb <= 0.0) {
      // Root in [xa, xb]; on a zero-length segment (a step up in the curve) the stress stops
      // on the riser, at the step's plastic strain.
      return dx > 0.0 ? (xa - eps) + ga / (G3 + rf * H) : xa - eps;
    }
    ++k;
    xa = std::max(xa, xb);
    ha = hb;
  }
}

// Static flow stress of the curve (x, y) at an effective plastic strain.
template <class Y>
double flowStressOn(std::span<const double> x, const Y& y, double eps_p) {
  if (x.size() == 1) return y[0];
  return onSegment(x, y, segmentOf(x, eps_p), eps_p);
}

// The effective plastic strain increment of a trial stress of norm q at plastic strain e on
// the curve (x, y) scaled by rf: 0 inside the yield surface, else the exact return.
template <class Y>
double curveIncrement(std::span<const double> x, const Y& y, double G3, double rf, double q,
                      double e) {
  const double f = q - rf * flowStressOn(x, y, e);
  return f > 0.0 ? returnToCurve(x, y, G3, rf, q, e) : 0.0;
}

// Radial return with isotropic hardening: the elastic predictor, then the effective plastic
// strain increment `increment(rate, q, eps_p)` (0 inside the yield surface) at the step's
// effective strain rate (computed only when kRated), then the deviator shrunk along itself.
// Elastic points take the same correction code with deps = 0 (exact no-op).
template <bool kRated, class Increment>
void isotropicRadialUpdate(PointBatch& b, const Moduli& m, const Increment& increment) {
  const double G = m.shear;
  const double lam = m.bulk - 2.0 * G / 3.0;
  const double G2 = 2.0 * G, G3 = 3.0 * G;
  const double inv_dt = b.dt > 0.0 ? 1.0 / b.dt : 0.0;
  for (int i = 0; i < b.n; ++i) {
    const double d0 = b.de[0][i], d1 = b.de[1][i], d2 = b.de[2][i];
    const double d3 = b.de[3][i], d4 = b.de[4][i], d5 = b.de[5][i];
    const double tr = d0 + d1 + d2;
    const double lt = lam * tr;
    const double t0 = b.s[0][i] + (lt + G2 * d0);
    const double t1 = b.s[1][i] + (lt + G2 * d1);
    const double t2 = b.s[2][i] + (lt + G2 * d2);
    const double t3 = b.s[3][i] + G2 * d3;
    const double t4 = b.s[4][i] + G2 * d4;
    const double t5 = b.s[5][i] + G2 * d5;
    const double p = (t0 + t1 + t2) * kThird;
    const double x0 = t0 - p, x1 = t1 - p, x2 = t2 - p;
    const double j2 = 0.5 * (x0 * x0 + x1 * x1 + x2 * x2) + (t3 * t3 + t4 * t4 + t5 * t5);
    const double q = std::sqrt(3.0 * j2);
    const double e = b.eps_p[i];
    const double rate = kRated ? effectiveRate(d0, d1, d2, d3, d4, d5, tr, inv_dt) : 0.0;
    const double deps = increment(rate, G3, q, e);
    const double cs = G3 * deps / (q > 0.0 ? q : 1.0);
    b.s[0][i] = t0 - cs * x0;
    b.s[1][i] = t1 - cs * x1;
    b.s[2][i] = t2 - cs * x2;
    b.s[3][i] = t3 - cs * t3;
    b.s[4][i] = t4 - cs * t4;
    b.s[5][i] = t5 - cs * t5;
    b.eps_p[i] = e + deps;
  }
}

// MAT_024 with a yield curve: isotropic hardening only, so the return is radial on dev(t).
// With a rate table the curve is the table's at the point's strain rate (rate.hpp), on which
// the return is exact.
template <Rate kRate>
void curveHardeningUpdate(PointBatch& b, const Moduli& m, const CurveHardening& P) {
  const std::span<const double> cx = P.eps, cy = P.sig;
  isotropicRadialUpdate<kRate != Rate::None>(b, m, [&](double rate, double G3, double q, double e) {
    if constexpr (kRate == Rate::Table) {
      return curveIncrement(P.table.eps, P.table.at(rate), G3, 1.0, q, e);
    } else {
      return curveIncrement(cx, cy, G3, factorAt<kRate>(P, rate), q, e);
    }
  });
}

// MAT_024 with VP = 1: the radial return onto the yield stress at the step's plastic strain
// rate (viscoplasticFlow), by safeguarded Newton; the yield check is at the static surface.
void viscoplasticCurveUpdate(PointBatch& b, const Moduli& m, const CurveHardening& P) {
  const double inv_dt = b.dt > 0.0 ? 1.0 / b.dt : 0.0;
  isotropicRadialUpdate<false>(b, m, [&](double, double G3, double q, double e) {
    double y = 0.0, h = 0.0;
    viscoplasticFlow(P, e, e, inv_dt, y, h);
    if (!(q > y)) return 0.0;
    return radialReturnIncrement(
        q, e, G3,
        [&](double x, double& yx, double& hx) { viscoplasticFlow(P, x, e, inv_dt, yx, hx); }, true);
  });
}

// MAT_018: the power law scaled by the Cowper-Symonds factor, by safeguarded Newton.
template <Rate kRate>
void powerHardeningUpdate(PointBatch& b, const Moduli& m, const PowerHardening& P) {
  isotropicRadialUpdate<kRate != Rate::None>(b, m, [&](double rate, double G3, double q, double e) {
    const double rf = factorAt<kRate>(P, rate);
    if (!(q > rf * P.flow(e))) return 0.0;
    return radialReturnIncrement(q, e, G3, [&](double x, double& y, double& h) {
      y = rf * P.flow(x);
      h = rf * P.slope(x);
    });
  });
}

}  // namespace

void elasticUpdate(PointBatch& b, const Moduli& m) {
  const double G2 = 2.0 * m.shear;
  elasticKernel(detail::soaOf(b), b.n, m.bulk - G2 / 3.0, G2);
}

namespace {
// Cowper-Symonds (C > 0) before an LCSR curve before a yield-stress curve: the law units give
// only one of them.
template <bool kKinematic>
void linearHardeningRate(PointBatch& b, const Moduli& m, const LinearHardening& P) {
  if (P.C > 0.0) {
    linearHardeningUpdate<kKinematic, Rate::CowperSymonds>(b, m, P);
  } else if (!P.lcsr.empty()) {
    linearHardeningUpdate<kKinematic, Rate::Curve>(b, m, P);
  } else if (!P.sigy_rate.empty()) {
    linearHardeningUpdate<kKinematic, Rate::Yield>(b, m, P);
  } else {
    linearHardeningUpdate<kKinematic, Rate::None>(b, m, P);
  }
}
}  // namespace

void linearHardeningReturn(PointBatch& b, const Moduli& m, const LinearHardening& P,
                           bool kinematic) {
  if (kinematic) {
    linearHardeningRate<true>(b, m, P);
  } else {
    linearHardeningRate<false>(b, m, P);
  }
}

double effectiveStrainRate(const double de[6], double dt) {
  const double tr = de[0] + de[1] + de[2];
  return effectiveRate(de[0], de[1], de[2], de[3], de[4], de[5], tr, dt > 0.0 ? 1.0 / dt : 0.0);
}

double curveFlowStress(const CurveHardening& P, double eps_p) {
  return flowStressOn(P.eps, P.sig, eps_p);
}

void viscoplasticFlow(const CurveHardening& P, double e, double e0, double inv_dt, double& y,
                      double& h) {
  const double r = e > e0 ? (e - e0) * inv_dt : 0.0;
  if (!P.table.empty()) {
    // y = lo(e) + w(r) (hi(e) - lo(e)): the blend's slope in e, and the curves' spread times
    // the weight's slope in r.
    const CurveBlend blend = P.table.at(r);
    const std::size_t n = P.table.eps.size();
    double lo = 0.0, hi = 0.0, slope = 0.0;
    util::valueAndSlope(P.table.eps, blend, e, y, slope);
    util::valueAndSlope(P.table.eps, std::span<const double>(blend.lo, n), e, lo, h);
    util::valueAndSlope(P.table.eps, std::span<const double>(blend.hi, n), e, hi, h);
    h = slope + inv_dt * (hi - lo) * P.table.weightSlope(r);
    return;
  }
  double ys = 0.0, hs = 0.0;  // the static curve
  util::valueAndSlope(P.eps, P.sig, e, ys, hs);
  double rf = 1.0, drf = 0.0;  // the rate factor and its slope in r
  if (P.C > 0.0) {
    rf = 1.0 + std::pow(r / P.C, P.inv_P);
    drf = r > 0.0 ? P.inv_P * (rf - 1.0) / r : 0.0;
  } else if (!P.lcsr.empty()) {
    P.lcsr.valueAndSlope(r, rf, drf);
  }
  y = rf * ys;
  h = rf * hs + inv_dt * drf * ys;
}

void powerHardeningReturn(PointBatch& b, const Moduli& m, const PowerHardening& P) {
  if (P.C > 0.0) {
    powerHardeningUpdate<Rate::CowperSymonds>(b, m, P);
  } else {
    powerHardeningUpdate<Rate::None>(b, m, P);
  }
}

void curveHardeningReturn(PointBatch& b, const Moduli& m, const CurveHardening& P) {
  if (P.viscoplastic) {
    viscoplasticCurveUpdate(b, m, P);
  } else if (!P.table.empty()) {
    curveHardeningUpdate<Rate::Table>(b, m, P);
  } else if (P.C > 0.0) {
    curveHardeningUpdate<Rate::CowperSymonds>(b, m, P);
  } else if (!P.lcsr.empty()) {
    curveHardeningUpdate<Rate::Curve>(b, m, P);
  } else {
    curveHardeningUpdate<Rate::None>(b, m, P);
  }
}

// Failure by effective plastic strain: the flag is only ever raised; the caller erodes.
void markFailed(PointBatch& b, double limit) {
  if (!(limit > 0.0) || b.failed == nullptr) return;
  const double* __restrict ep = b.eps_p;
  uint8_t* __restrict failed = b.failed;
  for (int i = 0; i < b.n; ++i) failed[i] |= static_cast<uint8_t>(ep[i] >= limit ? 1 : 0);
}

}  // namespace crumple::materials
