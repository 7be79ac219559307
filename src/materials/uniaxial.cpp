// Truss and beam-fibre stress updates (see uniaxial.hpp for the formulation).
#include "materials/uniaxial.hpp"

#include "util/curve.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

namespace crumple::materials {

namespace {

// Flow stress and its slope dsigma_y / deps_p at eps_p of the yield curve (x, cy); on a step
// up in the curve the stress stands on the riser.
template <class Y>
void curveStressAndSlope(std::span<const double> x, const Y& cy, double eps_p, double& y,
                         double& h) {
  util::valueAndSlope(x, cy, eps_p, y, h);
}

// Static flow stress and its slope dsigma_y / deps_p at eps_p (a rate table: its first curve).
void flowStressAndSlope(const FibreLaw& law, double eps_p, double& y, double& h) {
  if (!law.table.empty()) {
    curveStressAndSlope(law.table.eps, law.table.at(0.0), eps_p, y, h);
    return;
  }
  if (law.power.k > 0.0) {
    y = law.power.flow(eps_p);
    h = law.power.slope(eps_p);
    return;
  }
  if (law.curve_eps.empty()) {
    y = law.sigy + law.Hi * eps_p;
    h = law.Hi;
    return;
  }
  curveStressAndSlope(law.curve_eps, law.curve_sig, eps_p, y, h);
}

// The effective strain rate of the step for plastically incompressible flow,
// sqrt(2/3 e:e) / dt = sqrt(de^2 + (dgs^2 + dgt^2) / 3) / dt (0 without a step), the rate of
// every rate form (VP = 0).
double fibreRate(double de, double dgs, double dgt, double dt) {
  return dt > 0.0 ? std::sqrt(de * de + (dgs * dgs + dgt * dgt) / 3.0) / dt : 0.0;
}

}  // namespace

double flowStress(const FibreLaw& law, double eps_p) {
  double y = 0.0, h = 0.0;
  flowStressAndSlope(law, eps_p, y, h);
  return y;
}

bool updateFibre(const FibreLaw& fibre, FibrePoint& p, double de, double dgs, double dgt,
                 double dt) {
  // MAT_019: the linear yield curve of the fibre's strain rate (a copy only for it).
  FibreLaw at_rate;
  if (!fibre.sigy_rate.empty()) {
    at_rate = fibre;
    at_rate.sigy = fibre.sigy_rate(fibreRate(de, dgs, dgt, dt));
  }
  const FibreLaw& law = fibre.sigy_rate.empty() ? fibre : at_rate;
  // Elastic predictor.
  const double s_tr = p.sig + law.E * de;
  const double ts_tr = p.tau_s + law.G * dgs;
  const double tt_tr = p.tau_t + law.G * dgt;
  p.sig = s_tr;
  p.tau_s = ts_tr;
  p.tau_t = tt_tr;
  if (!law.plastic) return false;

  // Rate effects at the fibre's strain rate: the Cowper-Symonds or LCSR factor on the yield
  // stress, or the yield curve of the rate table at that rate (with rf = 1). VP = 1: rf = 1,
  // and the flow stress is the one at the step's plastic strain rate (viscoplasticFlow).
  const bool vp = law.viscoplastic;
  double rf = 1.0;
  if (!vp && law.C > 0.0 && dt > 0.0) {
    rf = 1.0 + std::pow(fibreRate(de, dgs, dgt, dt) / law.C, law.inv_P);
  } else if (!vp && !law.lcsr.empty()) {
    rf = law.lcsr(fibreRate(de, dgs, dgt, dt));
  }
  const bool tabled = !vp && !law.table.empty();
  const CurveBlend blend = tabled ? law.table.at(fibreRate(de, dgs, dgt, dt)) : CurveBlend{};
  const CurveHardening vp_curve{law.curve_eps, law.curve_sig, law.C, law.inv_P,
                                law.lcsr,      law.table,     true};
  const double e0 = p.eps_p, inv_dt = dt > 0.0 ? 1.0 / dt : 0.0;
  auto flow = [&](double eps_p, double& y, double& h) {
    if (vp) {
      viscoplasticFlow(vp_curve, eps_p, e0, inv_dt, y, h);
    } else if (tabled) {
      curveStressAndSlope(law.table.eps, blend, eps_p, y, h);
    } else {
      flowStressAndSlope(law, eps_p, y, h);
    }
  };
  const double x = s_tr - p.alpha, ys = ts_tr - p.alpha_s, yt = tt_tr - p.alpha_t;
  const double xx = x * x, yy = ys * ys + yt * yt;
  const double q_tr = std::sqrt(xx + 3.0 * yy);
  double y0 = 0.0, h0 = 0.0;
  flow(p.eps_p, y0, h0);
  const double f = q_tr - rf * y0;
  if (f > 0.0) {
    // g(d) = q(n+1)(d) - rf sigma_y(eps_p + d) = 0 for the plastic strain increment d, with
    // q(n+1) from the return formulas (uniaxial.hpp). g decreases from f > 0; Newton steps
    // are kept inside the bracket [lo, hi] of the root, bisection otherwise.
    const double a = law.E + law.Hk, b = 3.0 * law.G + law.Hk;
    const double tiny = 1e-300;
    auto eval = [&](double d, double& g, double& dg, double& yield) {
      double y = 0.0, h = 0.0;
      flow(p.eps_p + d, y, h);
      yield = std::max(rf * y, tiny);  // a curve softened to zero carries no stress
      const double hr = rf * h;
      const double yv = d / yield;
      const double ua = 1.0 + a * yv, ub = 1.0 + b * yv;
      const double q = std::sqrt(xx / (ua * ua) + 3.0 * yy / (ub * ub));
      const double dq_dy =
          -(a * xx / (ua * ua * ua) + 3.0 * b * yy / (ub * ub * ub)) / std::max(q, tiny);
      g = q - yield;
      dg = dq_dy * (yield - d * hr) / (yield * yield) - hr;
    };
    // First guess: the exact answer for linear hardening when the trial state is uniaxial or
    // pure shear (the modulus along the trial direction).
    const double m = (a * xx + 3.0 * b * yy) / (xx + 3.0 * yy);
    double d = f / std::max(m + std::max(rf * h0, 0.0), tiny);
    double lo = 0.0, hi = std::numeric_limits<double>::infinity();
    double yield = rf * y0;
    for (int it = 0; it < 60; ++it) {
      double g = 0.0, dg = 0.0;
      eval(d, g, dg, yield);
      if (g > 0.0) {
        lo = d;
      } else {
        hi = d;
      }
      // (hi stays infinite until an iterate overshoots the root.)
      if (std::abs(g) <= 1e-13 * yield || (std::isfinite(hi) && hi - lo <= 1e-15 * hi)) break;
      double next = dg < 0.0 ? d - g / dg : lo;
      if (!(next > lo && next < hi)) next = std::isinf(hi) ? 2.0 * d : 0.5 * (lo + hi);
      d = next;
    }
    double g = 0.0, dg = 0.0;
    eval(d, g, dg, yield);
    const double yv = d / yield;
    const double xr = x / (1.0 + a * yv);
    const double xs = ys / (1.0 + b * yv), xt = yt / (1.0 + b * yv);
    // Prager: the back stress moves by Hk deps along the flow direction xi / q, q = yield.
    const double ck = law.Hk * yv;
    p.alpha += ck * xr;
    p.alpha_s += ck * xs;
    p.alpha_t += ck * xt;
    p.sig = p.alpha + xr;
    p.tau_s = p.alpha_s + xs;
    p.tau_t = p.alpha_t + xt;
    p.eps_p += d;
  }
  return law.fail > 0.0 && p.eps_p >= law.fail;
}

}  // namespace crumple::materials
