// The three-dimensional stress updates laws are built from: Hooke's law and J2 plasticity by
// radial return (formulation and references in return_mapping.cpp). A law unit translates its
// parameters into these (src/materials/laws/) and calls them on a batch of points; they hold
// no law of their own.
#pragma once

#include <cmath>
#include <limits>
#include <span>

#include "materials/law.hpp"
#include "materials/rate.hpp"

namespace crumple::materials {

// Linear mixed hardening: the yield stress rf (sigy + Hi eps_p) with the Cowper-Symonds
// factor rf = 1 + (rate / C)^inv_P (C == 0: rate independent), else the factor of an LCSR
// curve (rate.hpp; empty: none), else (sigy_rate not empty) the initial yield stress given as
// a curve of the strain rate, sigy_rate(rate) + Hi eps_p (*MAT_019 LC1; rf = 1); and Prager's
// kinematic hardening with modulus Hk.
struct LinearHardening {
  double sigy = 0.0;  // initial yield stress
  double Hi = 0.0;    // isotropic plastic modulus
  double Hk = 0.0;    // kinematic plastic modulus
  double C = 0.0, inv_P = 0.0;
  RateCurve lcsr;
  RateCurve sigy_rate;  // the initial yield stress vs effective strain rate (as an LCSR curve)
};

// Isotropic hardening along a piecewise-linear yield curve (stress vs effective plastic
// strain, linearly extrapolated past its ends), with the same rate factors; or, when `table`
// is not empty, along the curve of a rate table at the point's strain rate (eps, sig unused).
// `viscoplastic` (*MAT_024 VP = 1): the rate forms take the effective plastic strain rate of
// the step inside the consistency condition (viscoplasticFlow), not the total strain rate.
struct CurveHardening {
  std::span<const double> eps, sig;
  double C = 0.0, inv_P = 0.0;
  RateCurve lcsr;
  RateTable table;
  bool viscoplastic = false;
};

// VP = 1 (LS-DYNA Keyword Manual vol. II, *MAT_024 VP; Theory Manual, material 24): the yield
// stress y(e, r) of P at the effective plastic strain e and the plastic strain rate
// r = (e - e0) inv_dt of a step that starts at e0, and its slope along the step,
// h = dy/de + inv_dt dy/dr, the derivative a return onto y needs. At e = e0 (r = 0) y is the
// static yield stress: the yield check of the viscoplastic formulation. The Cowper-Symonds
// factor's rate slope is infinite at r = 0 for P > 1; it is taken as 0 there (the returns
// bracket their root, so a missing slope costs iterations, not accuracy).
void viscoplasticFlow(const CurveHardening& P, double e, double e0, double inv_dt, double& y,
                      double& h);

// Isotropic power-law hardening, the yield stress rf k (eps0 + eps_p)^n (*MAT_POWER_LAW_
// PLASTICITY, 018: eps0 the strain at yield), with the Cowper-Symonds factor of C and inv_P
// (C == 0: rate independent).
struct PowerHardening {
  double k = 0.0, n = 0.0, eps0 = 0.0;
  double C = 0.0, inv_P = 0.0;
  // Static flow stress k (eps0 + eps_p)^n and its slope n k (eps0 + eps_p)^(n - 1) (0 where
  // eps0 + eps_p is 0: the slope of n < 1 is infinite there, where Newton is not evaluated).
  double flow(double eps_p) const { return k * std::pow(eps0 + eps_p, n); }
  double slope(double eps_p) const {
    const double e = eps0 + eps_p;
    return e > 0.0 && n != 0.0 ? n * k * std::pow(e, n - 1.0) : 0.0;
  }
};

// The effective plastic strain increment x of a radial return from a trial von Mises stress q
// above the flow stress y(eps_p): the root of g(x) = q - G3 x - y(eps_p + x), where G3 = 3 G
// and y does not decrease. g falls from g(0) > 0 to g(hi) <= 0 at hi = g(0) / G3: Newton from
// hi, kept inside the bracket [lo, hi] by bisection, converges to round-off whatever the sign
// of y'' (Simo & Hughes, Computational Inelasticity, 1998, Box 3.1, with a safeguard).
// `flow(e, y, h)` gives the flow stress y and its slope h at e. `may_fall`: y may fall below
// y(eps_p) (*MAT_024 VP = 1 on a rate table whose curves cross), which may leave g(hi) > 0:
// the bracket is then doubled until g changes sign (-G3 x wins), and a root is found inside.
template <class Flow>
double radialReturnIncrement(double q, double eps_p, double G3, const Flow& flow,
                             bool may_fall = false) {
  double y = 0.0, h = 0.0;
  flow(eps_p, y, h);
  double lo = 0.0, hi = (q - y) / G3;
  double x = hi;
  for (int it = 0; it < 200; ++it) {
    flow(eps_p + x, y, h);
    const double g = q - G3 * x - y;
    if (g == 0.0) return x;
    if (may_fall && g > 0.0 && x >= hi) {  // the root lies past hi
      lo = x;
      hi = x = 2.0 * x;
      continue;
    }
    (g > 0.0 ? lo : hi) = x;
    double next = x + g / (G3 + h);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == x || hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * hi) return next;
    x = next;
  }
  return x;
}

// s += lambda tr(de) I + 2 G de.
void elasticUpdate(PointBatch& b, const Moduli& m);
// Elastic predictor and radial return; `kinematic` updates the back stress b.alpha.
void linearHardeningReturn(PointBatch& b, const Moduli& m, const LinearHardening& P,
                           bool kinematic);
void curveHardeningReturn(PointBatch& b, const Moduli& m, const CurveHardening& P);
void powerHardeningReturn(PointBatch& b, const Moduli& m, const PowerHardening& P);
// Static flow stress of the curve at an effective plastic strain.
double curveFlowStress(const CurveHardening& P, double eps_p);
// The effective strain rate sqrt(2/3 dev(de):dev(de)) / dt of a step (0 when dt is 0), the rate
// of the rate forms here (VP = 0), for the laws that measure it themselves.
double effectiveStrainRate(const double de[6], double dt);
// The deviator (tensor shear) of a stress; returns its pressure (positive in compression).
inline double deviator(const double s[6], double dev[6]) {
  const double p = -(s[0] + s[1] + s[2]) / 3.0;
  for (int k = 0; k < 6; ++k) dev[k] = k < 3 ? s[k] + p : s[k];
  return p;
}
// The von Mises stress sqrt(3/2 s:s) of a deviator (tensor shear components counted twice).
inline double vonMises(const double s[6]) {
  const double ss =
      s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
  return std::sqrt(1.5 * ss);
}
// Raises b.failed where the effective plastic strain has reached `limit` (> 0).
void markFailed(PointBatch& b, double limit);

}  // namespace crumple::materials
