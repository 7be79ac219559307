// Plane-stress elasticity and J2 plasticity for shell integration points (see plane_stress.hpp).
//
// Notation (Simo & Taylor 1986; Simo & Hughes 1998, sec. 3.4), vectors of plane stress with
// tensor shear components:
//   C      plane-stress elasticity  E/(1-nu^2) [1 nu 0; nu 1 0; 0 0 (1-nu)] (acting on
//          tensor shear: s_xy = 2 G e_xy)
//   P      the projection with 1/2 s.P.s = J2 of the 3D stress (s_xx, s_yy, 0, s_xy):
//          s.P.s = (s_xx + s_yy)^2 / 6 + (s_xx - s_yy)^2 / 2 + 2 s_xy^2
//   xi     relative stress s - alpha (alpha: back stress in plane-stress form, the plane tensor
//          with the deviator of the 3D back stress)
//   q      von Mises stress sqrt(3/2 xi.P.xi)
// Flow and hardening: plastic strain rate gamma P xi (engineering shear), effective plastic
// strain rate 2/3 gamma q, back stress rate 2/3 Hk gamma xi (Prager's rule written for the
// plane-stress form of alpha). C P and P share the eigenvectors (1, 1, 0), (1, -1, 0),
// (0, 0, 1), so the backward-Euler return is diagonal in them:
//   xi_k = xi_k^trial / (1 + m_k dgamma),  m_1 = E / (3 (1 - nu)) + 2/3 Hk,  m_2 = 2 G + 2/3 Hk
// (m_2 for both the (1, -1, 0) and the shear mode), and consistency
//   g(dgamma) = q(dgamma) - sigma_y(eps_p + 2/3 dgamma q(dgamma)) = 0
// is one scalar equation, solved by Newton's method from the root of the one-mode problem
// (exact when xi^trial has a single mode). A bracket [lo, hi] (hi from q <= q_trial /
// (1 + min(m) dgamma) and sigma_y >= its current value) guards the iteration where the
// hardening curve bends the other way. Each point iterates until its own Newton step is below
// 1e-8 of dgamma (and applies it: the quadratic convergence leaves an error of order 1e-16) or
// its residual is round-off (1e-15 q), so a point's result does not depend on the other points
// in the batch.
//
// The thickness strain increment that keeps sigma_zz = 0 is the elastic part -nu/E (ds_xx +
// ds_yy) plus the plastic part -(deps^p_xx + deps^p_yy) = -dgamma (xi_xx + xi_yy) / 3
// (plastic incompressibility).
#include "materials/plane_stress.hpp"

#include "util/curve.hpp"
#include "util/target_clones.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

namespace crumple::materials {

double youngModulus(const Moduli& m) {
  return 9.0 * m.bulk * m.shear / (3.0 * m.bulk + m.shear);
}

double poissonRatio(const Moduli& m) {
  return (3.0 * m.bulk - 2.0 * m.shear) / (2.0 * (3.0 * m.bulk + m.shear));
}

namespace {

constexpr double kTwoThirds = 2.0 / 3.0;
// The iteration stops once a step is below this fraction of dgamma and applies that step: the
// linear-hardening return converges cubically (Halley), the error left is then of order 1e-15
// of dgamma, round-off; the curve return (Newton, quadratic) uses kNewtonTolerance.
constexpr double kHalleyTolerance = 1e-5;
constexpr double kNewtonTolerance = 1e-8;
// A residual this small relative to q is round-off: the point is on the yield surface (the
// relative step may then stay above kNewtonTolerance when dgamma itself is tiny).
constexpr double kResidualFloor = 1e-15;
// Points per chunk of the linear-hardening return (stack scratch).
constexpr int kChunk = 64;

// Restrict-qualified views of a PlaneStressPoints (see soa.hpp for why these are members of a
// struct passed by value).
struct Views {
  double* __restrict s0;
  double* __restrict s1;
  double* __restrict s2;
  const double* __restrict d0;
  const double* __restrict d1;
  const double* __restrict d2;
  double* __restrict dzz;
  double* __restrict ep;
  double* __restrict a0;
  double* __restrict a1;
  double* __restrict a2;
  uint8_t* __restrict failed;
};

Views viewsOf(const PlaneStressPoints& b) {
  return Views{b.s[0],  b.s[1],  b.s[2],     b.de[0],    b.de[1],    b.de[2],
               b.de_zz, b.eps_p, b.alpha[0], b.alpha[1], b.alpha[2], b.failed};
}

struct ElasticConstants {
  double E = 0, nu = 0;
  double E1 = 0;    // E / (1 - nu^2)
  double G2 = 0;    // 2 G
  double nu_E = 0;  // nu / E
  double m1 = 0;    // E / (3 (1 - nu)): the (1, 1, 0) eigenvalue of C P
};

ElasticConstants elasticConstantsOf(const Moduli& m) {
  ElasticConstants c;
  c.E = youngModulus(m);
  c.nu = poissonRatio(m);
  c.E1 = c.E / (1.0 - c.nu * c.nu);
  c.G2 = 2.0 * m.shear;
  c.nu_E = c.nu / c.E;
  c.m1 = c.E / (3.0 * (1.0 - c.nu));
  return c;
}

// How the yield stress depends on the strain rate (as in return_mapping.cpp).
enum class Rate : uint8_t { None, CowperSymonds, Curve, Table, Yield };

// The effective strain rate of the in-plane increment completed by an incompressible thickness
// strain, -(de_xx + de_yy): the strain of fully developed plastic flow, where the rate matters
// (the thickness strain is only known after the return). Every rate form uses it (VP = 0).
inline double effectiveRate(double d0, double d1, double d2, double inv_dt) {
  const double dz = d0 + d1;
  const double ee = d0 * d0 + d1 * d1 + dz * dz + 2.0 * d2 * d2;
  return std::sqrt(kTwoThirds * ee) * inv_dt;
}

// Cowper-Symonds factor 1 + (rate / C)^(1/P).
inline double cowperSymonds(double d0, double d1, double d2, double inv_dt, double C,
                            double inv_P) {
  return 1.0 + std::pow(effectiveRate(d0, d1, d2, inv_dt) / C, inv_P);
}

// The factor rf on the yield stress of a point (1 for Rate::None and Rate::Table).
template <Rate kRate, class P>
inline double rateFactor(const P& law, double d0, double d1, double d2, double inv_dt) {
  if constexpr (kRate == Rate::CowperSymonds)
    return cowperSymonds(d0, d1, d2, inv_dt, law.C, law.inv_P);
  if constexpr (kRate == Rate::Curve) return law.lcsr(effectiveRate(d0, d1, d2, inv_dt));
  return 1.0;
}

// First Newton iterate: the exact root when the trial relative stress has one mode only
// (q = q_trial / (1 + m dgamma)), with m the modes' mean weighted by their share of xi.P.xi;
// sy the current flow stress and H its slope. Saves the 3-5 iterations of a start from zero.
inline double firstGuess(double q, double sy, double H, double c1, double c2, double m1,
                         double m2) {
  // (q - sy) / (sy m + 2/3 H q) with m = (c1 m1 + c2 m2) / (c1 + c2): one division.
  const double c = c1 + c2;
  return (q - sy) * c / (sy * (c1 * m1 + c2 * m2) + kTwoThirds * H * q * c);
}

// 1 / (1 + m1 dgamma) and 1 / (1 + m2 dgamma) with one division.
inline void inverseFactors(double m1, double m2, double dg, double& i1, double& i2) {
  const double d1 = 1.0 + m1 * dg, d2 = 1.0 + m2 * dg;
  const double inv = 1.0 / (d1 * d2);
  i1 = d2 * inv;
  i2 = d1 * inv;
}

// Newton's step for g = q - sigma_y: g / g' = g q / N, with (S = u1 m1 i1 + u2 m2 i2, so that
// dq/dgamma = -3/2 S / q; H the flow stress slope; q2 = q^2)
//   g' = dq - H 2/3 (q + dgamma dq) = N / q,  N = S (H dgamma - 3/2) - 2/3 H q^2,
// which needs no division by q.
inline double newtonDenominator(double S, double q2, double H, double dg) {
  return S * (H * dg - 1.5) - kTwoThirds * H * q2;
}

// ---- elastic --------------------------------------------------------------------------------
CRUMPLE_TARGET_CLONES void elasticPlaneStress(Views a, int n, const ElasticConstants c) {
  const double zz = -c.nu / (1.0 - c.nu);
  for (int i = 0; i < n; ++i) {
    const double d0 = a.d0[i], d1 = a.d1[i];
    a.s0[i] += c.E1 * (d0 + c.nu * d1);
    a.s1[i] += c.E1 * (d1 + c.nu * d0);
    a.s2[i] += c.G2 * a.d2[i];
    a.dzz[i] = zz * (d0 + d1);
  }
}

// ---- linear mixed hardening (MAT_003, bilinear MAT_024) --------------------------------------

// Trial state of a chunk: what the Newton iteration needs per point.
struct Trial {
  double t0[kChunk], t1[kChunk], t2[kChunk];  // trial stress
  double x1[kChunk], x2[kChunk], x3[kChunk];  // trial xi in the eigenbasis: xx+yy, xx-yy, xy
  double c1[kChunk], c2[kChunk];              // xi.P.xi = c1 / D1^2 + c2 / D2^2
  double sy[kChunk], k[kChunk];               // flow stress sy + k dgamma q (see below)
  double dg[kChunk], lo[kChunk], hi[kChunk], live[kChunk];
};

// Linear hardening makes consistency a polynomial. With the flow stress at the end of the step
// sigma_y = sy + Hi' 2/3 dgamma q (sy = rf (sigy + Hi eps_p), Hi' = rf Hi), q = sigma_y gives
// q = sy / (1 - k dgamma), k = 2/3 Hi', and q^2 = 3/2 (c1 / D1^2 + c2 / D2^2) (D = 1 + m
// dgamma) becomes, multiplied out,
//   P(dgamma) = 3/2 (c1 D2^2 + c2 D1^2) K^2 - sy^2 D1^2 D2^2 = 0,   K = 1 - k dgamma,
// a quartic whose root in [0, 1/k) is the return: P > 0 below it (q > sigma_y), P < 0 above.
// Halley's method on P (cubic convergence) needs one division per step and no square root:
//   next = dgamma - 2 P P' / (2 P'^2 - P P'').
inline double halleyStep(double c1, double c2, double sy, double k, double m1, double m2, double dg,
                         double& p) {
  const double d1 = 1.0 + m1 * dg, d2 = 1.0 + m2 * dg, kk = 1.0 - k * dg;
  const double a = 1.5 * (c1 * d2 * d2 + c2 * d1 * d1);
  const double da = 3.0 * (c1 * m2 * d2 + c2 * m1 * d1);
  const double dda = 3.0 * (c1 * m2 * m2 + c2 * m1 * m1);
  const double s2 = sy * sy, e = d1 * d2, de = m1 * d2 + m2 * d1;
  p = a * kk * kk - s2 * e * e;
  const double dp = (da * kk - 2.0 * k * a) * kk - 2.0 * s2 * e * de;
  const double ddp =
      (dda * kk - 4.0 * k * da) * kk + 2.0 * k * k * a - 2.0 * s2 * (de * de + 2.0 * m1 * m2 * e);
  return dg - 2.0 * p * dp / (2.0 * dp * dp - p * ddp);
}

template <bool kKinematic, Rate kRate>
CRUMPLE_TARGET_CLONES void linearPlaneStress(Views a, int n, double dt, const ElasticConstants c,
                                             const LinearHardening P) {
  const double m1 = c.m1 + kTwoThirds * P.Hk, m2 = c.G2 + kTwoThirds * P.Hk;
  const double inv_m_min = 1.0 / std::min(m1, m2);
  const double inv_dt = dt > 0.0 ? 1.0 / dt : 0.0;
  const double huge = std::numeric_limits<double>::max();
  Trial w;
  for (int base = 0; base < n; base += kChunk) {
    const int m = std::min(kChunk, n - base);
    double* __restrict s0 = a.s0 + base;
    double* __restrict s1 = a.s1 + base;
    double* __restrict s2 = a.s2 + base;
    const double* __restrict d0 = a.d0 + base;
    const double* __restrict d1 = a.d1 + base;
    const double* __restrict d2 = a.d2 + base;
    double* __restrict ep = a.ep + base;
    double* __restrict al0 = kKinematic ? a.a0 + base : nullptr;
    double* __restrict al1 = kKinematic ? a.a1 + base : nullptr;
    double* __restrict al2 = kKinematic ? a.a2 + base : nullptr;
    // Elastic predictor; yield check at the current plastic strain.
    double plastic_points = 0.0;
#pragma omp simd reduction(+ : plastic_points)
    for (int i = 0; i < m; ++i) {
      const double t0 = s0[i] + c.E1 * (d0[i] + c.nu * d1[i]);
      const double t1 = s1[i] + c.E1 * (d1[i] + c.nu * d0[i]);
      const double t2 = s2[i] + c.G2 * d2[i];
      w.t0[i] = t0;
      w.t1[i] = t1;
      w.t2[i] = t2;
      double xx = t0, yy = t1, xy = t2;
      if constexpr (kKinematic) {
        xx -= al0[i];
        yy -= al1[i];
        xy -= al2[i];
      }
      const double x1 = xx + yy, x2 = xx - yy;
      w.x1[i] = x1;
      w.x2[i] = x2;
      w.x3[i] = xy;
      const double c1 = x1 * x1 * (1.0 / 6.0);
      const double c2 = 0.5 * x2 * x2 + 2.0 * xy * xy;
      w.c1[i] = c1;
      w.c2[i] = c2;
      const double rf = rateFactor<kRate>(P, d0[i], d1[i], d2[i], inv_dt);
      const double sy0 =
          kRate == Rate::Yield ? P.sigy_rate(effectiveRate(d0[i], d1[i], d2[i], inv_dt)) : P.sigy;
      const double sy = rf * (sy0 + P.Hi * ep[i]);
      const double k = kTwoThirds * rf * P.Hi;
      w.sy[i] = sy;
      w.k[i] = k;
      const double q = std::sqrt(1.5 * (c1 + c2));
      const double live = q > sy ? 1.0 : 0.0;
      w.dg[i] = live != 0.0 ? firstGuess(q, sy, rf * P.Hi, c1, c2, m1, m2) : 0.0;
      w.lo[i] = 0.0;
      // Root bound: q(dgamma) <= q_trial / (1 + min(m) dgamma) and sigma_y >= sy (Hi >= 0).
      w.hi[i] = sy > 0.0 ? 2.0 * (q / sy - 1.0) * inv_m_min : huge;
      w.live[i] = live;
      plastic_points += live;
    }
    // An elastic chunk (the common case) takes the trial state as it is: the general path below
    // gives the same bits for an elastic point (dgamma = 0 subtracts exact zeros).
    if (plastic_points == 0.0) {
      for (int i = 0; i < m; ++i) {
        a.dzz[base + i] = -c.nu_E * ((w.t0[i] + w.t1[i]) - (s0[i] + s1[i]));
        s0[i] = w.t0[i];
        s1[i] = w.t1[i];
        s2[i] = w.t2[i];
      }
      continue;
    }
    // Halley iterations on P; a converged point keeps its value (selects, no branch).
    for (int it = 0; it < kPlaneStressMaxIterations; ++it) {
      double any = 0.0;
#pragma omp simd reduction(+ : any)
      for (int i = 0; i < m; ++i) {
        const double dg = w.dg[i];
        double p;
        double next = halleyStep(w.c1[i], w.c2[i], w.sy[i], w.k[i], m1, m2, dg, p);
        const double lo = p > 0.0 ? dg : w.lo[i];
        const double hi = p > 0.0 ? w.hi[i] : dg;
        // Bitwise & (no short circuit): the loop body stays branch-free. K = 1 - k dgamma must
        // stay positive (beyond it the quartic has roots of no meaning).
        next = ((next >= lo) & (next <= hi) & (w.k[i] * next < 1.0)) ? next : 0.5 * (lo + hi);
        const double d12 = (1.0 + m1 * dg) * (1.0 + m2 * dg);
        const bool live = w.live[i] != 0.0;
        const bool moving = (std::abs(next - dg) > kHalleyTolerance * next) &
                            (std::abs(p) > kResidualFloor * w.sy[i] * w.sy[i] * d12 * d12);
        w.dg[i] = live ? next : dg;
        w.lo[i] = live ? lo : w.lo[i];
        w.hi[i] = live ? hi : w.hi[i];
        const double still = live & moving ? 1.0 : 0.0;
        w.live[i] = still;
        any += still;
      }
      if (any == 0.0) break;
    }
    // Returned stress, back stress, plastic strain and thickness strain.
#pragma omp simd
    for (int i = 0; i < m; ++i) {
      const double dg = w.dg[i];
      double i1, i2;
      inverseFactors(m1, m2, dg, i1, i2);
      const double y1 = w.x1[i] * i1, y2 = w.x2[i] * i2;
      const double xx = 0.5 * (y1 + y2), yy = 0.5 * (y1 - y2), xy = w.x3[i] * i2;
      const bool plastic = dg > 0.0;
      // q at the end of the step is the flow stress there, sy / (1 - k dgamma).
      const double q = w.sy[i] / (1.0 - w.k[i] * dg);
      double n0 = xx, n1 = yy, n2 = xy;
      if constexpr (kKinematic) {
        const double ca = kTwoThirds * P.Hk * dg;
        const double b0 = al0[i] + ca * xx, b1 = al1[i] + ca * yy, b2 = al2[i] + ca * xy;
        n0 += b0;
        n1 += b1;
        n2 += b2;
        al0[i] = plastic ? b0 : al0[i];
        al1[i] = plastic ? b1 : al1[i];
        al2[i] = plastic ? b2 : al2[i];
      }
      n0 = plastic ? n0 : w.t0[i];
      n1 = plastic ? n1 : w.t1[i];
      n2 = plastic ? n2 : w.t2[i];
      a.dzz[base + i] = -c.nu_E * ((n0 + n1) - (s0[i] + s1[i])) - dg * (xx + yy) * (1.0 / 3.0);
      s0[i] = n0;
      s1[i] = n1;
      s2[i] = n2;
      ep[i] = ep[i] + (plastic ? kTwoThirds * dg * q : 0.0);
    }
  }
}

// Failure by effective plastic strain: set where reached (a failed point stays failed because
// its plastic strain never decreases).
}  // namespace

void markFailed(PlaneStressPoints& b, double limit) {
  if (b.failed == nullptr) return;
  uint8_t* __restrict failed = b.failed;
  if (!(limit > 0.0) || b.eps_p == nullptr) {
    std::fill(failed, failed + b.n, uint8_t{0});
    return;
  }
  const double* __restrict ep = b.eps_p;
  for (int i = 0; i < b.n; ++i) failed[i] = static_cast<uint8_t>(ep[i] >= limit ? 1 : 0);
}

namespace {

// Cowper-Symonds (C > 0) before an LCSR curve before a yield-stress curve (MAT_019 LC1): the
// law units give only one of them.
template <bool kKinematic>
void linearUpdate(PlaneStressPoints& b, const ElasticConstants& c, const LinearHardening& P) {
  if (P.C > 0.0) {
    linearPlaneStress<kKinematic, Rate::CowperSymonds>(viewsOf(b), b.n, b.dt, c, P);
  } else if (!P.lcsr.empty()) {
    linearPlaneStress<kKinematic, Rate::Curve>(viewsOf(b), b.n, b.dt, c, P);
  } else if (!P.sigy_rate.empty()) {
    linearPlaneStress<kKinematic, Rate::Yield>(viewsOf(b), b.n, b.dt, c, P);
  } else {
    linearPlaneStress<kKinematic, Rate::None>(viewsOf(b), b.n, b.dt, c, P);
  }
}

// ---- piecewise-linear yield curve (MAT_024 with LCSS) ---------------------------------------
// Flow stress and slope of the curve at eps, with the segment convention of
// model::Curve::valueExtrapolated: segment k holds [x[k], x[k+1]), clamped to the end segments
// (linear extrapolation beyond them); a single point is a constant flow stress.
template <class Y>
void curveAt(std::span<const double> x, const Y& y, double eps, double& h, double& slope) {
  if (x.size() == 1) {
    h = y[0];
    slope = 0.0;
    return;
  }
  const std::size_t k = util::segmentOf(x, eps);
  const double dx = x[k + 1] - x[k];
  if (dx <= 0.0) {
    h = y[k + 1];
    slope = 0.0;
    return;
  }
  slope = (y[k + 1] - y[k]) / dx;
  h = y[k] + (y[k + 1] - y[k]) * (eps - x[k]) / dx;
}

// The residual q(dg) - flow(e + 2/3 dg q(dg)) of the return below at dg.
template <class Flow>
double flowResidual(const Flow& flow, double dg, double e, double c1, double c2, double m1,
                    double m2) {
  double i1, i2, h, slope;
  inverseFactors(m1, m2, dg, i1, i2);
  const double q = std::sqrt(1.5 * (c1 * i1 * i1 + c2 * i2 * i2));
  flow(e + kTwoThirds * dg * q, h, slope);
  return q - h;
}

// The plastic multiplier of the same return as linearPlaneStress (no back stress) onto a
// flow stress `flow(eps, h, slope)` that does not decrease, looked up at the current iterate,
// from the trial state (c1, c2, q_trial) at plastic strain e; 0 for an elastic step.
// `may_fall`: the flow stress may fall below its value at e (*MAT_024 VP = 1 on a rate table
// whose curves cross), so the bracket's upper end from it may hold no root: it is doubled
// until the residual there is not positive.
template <class Flow>
double flowMultiplier(const Flow& flow, double e, double c1, double c2, double m1, double m2,
                      bool may_fall = false) {
  double h, slope;
  flow(e, h, slope);
  const double q_trial = std::sqrt(1.5 * (c1 + c2));
  double dg = 0.0;
  if (!(q_trial > h)) return dg;
  dg = firstGuess(q_trial, h, slope, c1, c2, m1, m2);
  double lo = 0.0;
  double hi =
      h > 0.0 ? 2.0 * (q_trial / h - 1.0) / std::min(m1, m2) : std::numeric_limits<double>::max();
  if (may_fall && h > 0.0) {
    for (int k = 0; k < kPlaneStressMaxIterations; ++k) {
      if (!(flowResidual(flow, hi, e, c1, c2, m1, m2) > 0.0)) break;
      lo = hi;
      hi *= 2.0;
    }
    if (!(dg > lo && dg < hi)) dg = 0.5 * (lo + hi);
  }
  for (int it = 0; it < kPlaneStressMaxIterations; ++it) {
    double i1, i2;
    inverseFactors(m1, m2, dg, i1, i2);
    const double u1 = c1 * i1 * i1, u2 = c2 * i2 * i2;
    const double q2 = 1.5 * (u1 + u2);
    const double q = std::sqrt(q2);
    flow(e + kTwoThirds * dg * q, h, slope);
    const double g = q - h;
    if (g > 0.0) {
      lo = dg;
    } else {
      hi = dg;
    }
    double next = dg - g * q / newtonDenominator(u1 * m1 * i1 + u2 * m2 * i2, q2, slope, dg);
    next = (next >= lo && next <= hi) ? next : 0.5 * (lo + hi);
    const bool converged =
        !(std::abs(next - dg) > kNewtonTolerance * next) || !(std::abs(g) > kResidualFloor * q);
    dg = next;
    if (converged) break;
  }
  return dg;
}

// The multiplier onto the curve (x, y) scaled by rf.
template <class Y>
double curveMultiplier(std::span<const double> x, const Y& y, double rf, double e, double c1,
                       double c2, double m1, double m2) {
  return flowMultiplier(
      [&](double eps, double& h, double& slope) {
        curveAt(x, y, eps, h, slope);
        h *= rf;
        slope *= rf;
      },
      e, c1, c2, m1, m2);
}

// Isotropic hardening, one point at a time (the hardening's evaluation does not vectorise):
// the elastic predictor, the multiplier `multiplier(d0, d1, d2, e, c1, c2, m1, m2)` of the
// point, the return and the thickness strain.
template <class Multiplier>
void isotropicPlaneStress(PlaneStressPoints& b, const Moduli& moduli,
                          const Multiplier& multiplier) {
  const ElasticConstants c = elasticConstantsOf(moduli);
  const double m1 = c.m1, m2 = c.G2;
  for (int i = 0; i < b.n; ++i) {
    const double d0 = b.de[0][i], d1 = b.de[1][i], d2 = b.de[2][i];
    const double s0 = b.s[0][i], s1 = b.s[1][i];
    const double t0 = s0 + c.E1 * (d0 + c.nu * d1);
    const double t1 = s1 + c.E1 * (d1 + c.nu * d0);
    const double t2 = b.s[2][i] + c.G2 * d2;
    const double x1 = t0 + t1, x2 = t0 - t1;
    const double c1 = x1 * x1 * (1.0 / 6.0), c2 = 0.5 * x2 * x2 + 2.0 * t2 * t2;
    const double e = b.eps_p[i];
    const double dg = multiplier(d0, d1, d2, e, c1, c2, m1, m2);
    double i1, i2;
    inverseFactors(m1, m2, dg, i1, i2);
    const double y1 = x1 * i1, y2 = x2 * i2;
    const bool plastic = dg > 0.0;
    const double n0 = plastic ? 0.5 * (y1 + y2) : t0;
    const double n1 = plastic ? 0.5 * (y1 - y2) : t1;
    const double n2 = plastic ? t2 * i2 : t2;
    const double q = std::sqrt(1.5 * (c1 * i1 * i1 + c2 * i2 * i2));
    b.de_zz[i] = -c.nu_E * ((n0 + n1) - (s0 + s1)) - dg * (n0 + n1) * (1.0 / 3.0);
    b.s[0][i] = n0;
    b.s[1][i] = n1;
    b.s[2][i] = n2;
    b.eps_p[i] = e + (plastic ? kTwoThirds * dg * q : 0.0);
  }
}

// MAT_024 with a yield curve. With a rate table the curve is the table's at the point's strain
// rate (rate.hpp), on which the return is exact.
template <Rate kRate>
void curvePlaneStress(PlaneStressPoints& b, const Moduli& moduli, const CurveHardening& law) {
  const double inv_dt = b.dt > 0.0 ? 1.0 / b.dt : 0.0;
  isotropicPlaneStress(
      b, moduli,
      [&](double d0, double d1, double d2, double e, double c1, double c2, double m1, double m2) {
        if constexpr (kRate == Rate::Table) {
          const CurveBlend y = law.table.at(effectiveRate(d0, d1, d2, inv_dt));
          return curveMultiplier(law.table.eps, y, 1.0, e, c1, c2, m1, m2);
        } else {
          const double rf = rateFactor<kRate>(law, d0, d1, d2, inv_dt);
          return curveMultiplier(law.eps, law.sig, rf, e, c1, c2, m1, m2);
        }
      });
}

// MAT_024 with VP = 1: the return onto the yield stress at the plastic strain rate of the
// step (return_mapping.hpp, viscoplasticFlow), whose slope along the step includes the rate's.
void viscoplasticCurvePlaneStress(PlaneStressPoints& b, const Moduli& moduli,
                                  const CurveHardening& law) {
  const double inv_dt = b.dt > 0.0 ? 1.0 / b.dt : 0.0;
  isotropicPlaneStress(
      b, moduli, [&](double, double, double, double e, double c1, double c2, double m1, double m2) {
        auto flow = [&](double eps, double& h, double& slope) {
          viscoplasticFlow(law, eps, e, inv_dt, h, slope);
        };
        return flowMultiplier(flow, e, c1, c2, m1, m2, true);
      });
}

// MAT_018: the power law scaled by the Cowper-Symonds factor.
template <Rate kRate>
void powerPlaneStress(PlaneStressPoints& b, const Moduli& moduli, const PowerHardening& law) {
  const double inv_dt = b.dt > 0.0 ? 1.0 / b.dt : 0.0;
  isotropicPlaneStress(
      b, moduli,
      [&](double d0, double d1, double d2, double e, double c1, double c2, double m1, double m2) {
        const double rf = rateFactor<kRate>(law, d0, d1, d2, inv_dt);
        auto flow = [&](double eps, double& h, double& slope) {
          h = rf * law.flow(eps);
          slope = rf * law.slope(eps);
        };
        return flowMultiplier(flow, e, c1, c2, m1, m2);
      });
}

}  // namespace

void planeStressElastic(PlaneStressPoints& b, const Moduli& m) {
  elasticPlaneStress(viewsOf(b), b.n, elasticConstantsOf(m));
  if (b.failed != nullptr) std::fill(b.failed, b.failed + b.n, uint8_t{0});
}

void planeStressLinear(PlaneStressPoints& b, const Moduli& m, const LinearHardening& P,
                       bool kinematic) {
  if (kinematic) {
    linearUpdate<true>(b, elasticConstantsOf(m), P);
  } else {
    linearUpdate<false>(b, elasticConstantsOf(m), P);
  }
}

void planeStressPower(PlaneStressPoints& b, const Moduli& m, const PowerHardening& P) {
  if (P.C > 0.0) {
    powerPlaneStress<Rate::CowperSymonds>(b, m, P);
  } else {
    powerPlaneStress<Rate::None>(b, m, P);
  }
}

void planeStressCurve(PlaneStressPoints& b, const Moduli& m, const CurveHardening& P) {
  if (P.viscoplastic) {
    viscoplasticCurvePlaneStress(b, m, P);
  } else if (!P.table.empty()) {
    curvePlaneStress<Rate::Table>(b, m, P);
  } else if (P.C > 0.0) {
    curvePlaneStress<Rate::CowperSymonds>(b, m, P);
  } else if (!P.lcsr.empty()) {
    curvePlaneStress<Rate::Curve>(b, m, P);
  } else {
    curvePlaneStress<Rate::None>(b, m, P);
  }
}

}  // namespace crumple::materials
