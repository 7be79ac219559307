#include "materials/laws/muscle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "util/curve.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& Muscle::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("SNO"), R("SRM"), R("PIS"), R("SSM"), R("CER"), R("DMP")}},
       {"card 2", {R("ALM"), R("SFR"), R("SVS"), R("SVR"), R("SSP")}}}};
  return spec;
}

namespace {

// A field of card 2 that names a curve by its negative value: the model curve index, or -1
// for a value >= 0 (the field's constant).
int32_t curveField(LawInput& in, const deck::Card& c, std::string_view field) {
  const double v = c.real(field);
  if (v >= 0.0) return -1;
  if (v != std::floor(v)) c.fail(field, "a negative value names a curve: it must be an integer");
  return in.curveOrReject(c, field, static_cast<int64_t>(-v));
}

}  // namespace

Muscle::Params Muscle::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  const deck::Card& c2 = in.card("card 2");
  Params p;
  p.sno = c.real("SNO");
  p.srm = c.real("SRM");
  p.pis = c.real("PIS");
  p.ssm = c.real("SSM");
  p.cer = c.real("CER");
  p.dmp = c.real("DMP");
  if (!(p.sno > 0)) c.fail("SNO", "the initial stretch ratio must be positive");
  if (!(p.pis > 0)) c.fail("PIS", "the peak isometric stress must be positive");
  if (p.dmp < 0) c.fail("DMP", "the damping constant must not be negative");
  p.alm = std::max(c2.real("ALM"), 0.0);
  p.alm_curve = curveField(in, c2, "ALM");
  p.sfr = curveField(in, c2, "SFR");
  p.svs = curveField(in, c2, "SVS");
  p.svr = curveField(in, c2, "SVR");
  p.ssp = curveField(in, c2, "SSP");
  // The strain rate is normalised by SRM only where SVR is a curve.
  if (p.svr >= 0 && !(p.srm > 0))
    c.fail("SRM", "the maximum strain rate must be positive when SVR is a curve");
  p.exponential = c2.real("SSP") == 0.0;
  if (p.exponential) {
    if (!(p.ssm > 0))
      c.fail("SSM", "must be positive with SSP = 0 (the exponential parallel element)");
    if (p.cer == 0) c.fail("CER", "is required (non-zero) with SSP = 0");
  }
  return p;
}

namespace {

MuscleFactor factorOf(const CurveAt& curves, int32_t index, double constant) {
  MuscleFactor f;
  f.constant = constant;
  if (index < 0) return f;
  const CurveData d = curves(index);
  f.x.assign(d.x.begin(), d.x.end());
  f.y.assign(d.y.begin(), d.y.end());
  return f;
}

}  // namespace

Muscle Muscle::make(const Params& p, const CurveAt& curves, const std::string& at) {
  if (!(p.sno > 0.0)) throw util::InputError(at + "SNO must be positive");
  if (!(p.pis > 0.0)) throw util::InputError(at + "PIS must be positive");
  Muscle m;
  m.moduli = moduliFromYoung(p.pis, 0.0);
  m.sno = p.sno;
  m.srm = p.srm;
  m.pis = p.pis;
  m.ssm = p.ssm;
  m.cer = p.cer;
  m.dmp = p.dmp;
  m.exponential = p.exponential;
  m.activation = factorOf(curves, p.alm_curve, p.alm);
  m.rate_scale = factorOf(curves, p.sfr, 1.0);
  m.length = factorOf(curves, p.svs, 1.0);
  m.velocity = factorOf(curves, p.svr, 1.0);
  // SSP > 0: no parallel element; 0: the exponential (response()); < 0: the curve.
  m.passive = factorOf(curves, p.ssp, 0.0);
  if (std::any_of(m.rate_scale.y.begin(), m.rate_scale.y.end(), [](double y) { return y <= 0; }))
    throw util::InputError(at + "SFR: the scale factor of the maximum strain rate must be " +
                           "positive at every point of its curve");
  return m;
}

void MuscleFactor::at(double t, double& value, double& slope) const {
  if (x.empty()) {
    value = constant;
    slope = 0.0;
    return;
  }
  util::valueAndSlope(std::span<const double>(x), std::span<const double>(y), t, value, slope);
}

double Muscle::activationAhead(double t) const {
  if (activation.x.empty()) return activation.constant;
  double a = 0.0;
  for (std::size_t i = 0; i < activation.x.size(); ++i)
    if (activation.x[i] > t) a = std::max(a, activation.y[i]);
  return a;
}

MuscleResponse Muscle::response(double lambda, double eps_dot, double t) const {
  double a = 0.0, da = 0.0, fl = 0.0, dfl = 0.0, fr = 0.0, dfr = 0.0;
  // The activation is a curve of time: held at its end values outside it, as a load curve.
  activation.at(activation.x.empty() ? t : std::clamp(t, activation.x.front(), activation.x.back()),
                a, da);
  length.at(lambda, fl, dfl);
  rate_scale.at(lambda, fr, dfr);
  // The strain rate normalised by the maximum strain rate SRM f_r(lambda) (SVR a curve).
  const double rate_max = srm * fr;
  const double x = velocity.x.empty() ? 0.0 : eps_dot / rate_max;
  double fv = 0.0, dfv = 0.0;
  velocity.at(x, fv, dfv);
  double fp = 0.0, dfp = 0.0;
  if (exponential) {
    if (lambda > 1.0) {
      const double k = cer / ssm, scale = 1.0 / std::expm1(cer);
      fp = std::expm1(k * (lambda - 1.0)) * scale;
      dfp = k * std::exp(k * (lambda - 1.0)) * scale;
    }
  } else {
    passive.at(lambda, fp, dfp);
  }
  // The tangents take the largest activation still to come, so that the step is short
  // enough before the muscle is switched on (an inactive muscle without a parallel element
  // would have no step at all).
  const double a_step = std::max(a, activationAhead(t));
  MuscleResponse r;
  r.stress = pis * (a * fl * fv + fp) + dmp * eps_dot;
  r.modulus = pis * (std::abs(a_step * dfl * fv) + std::abs(dfp));
  r.viscosity = dmp + (velocity.x.empty() ? 0.0 : pis * std::abs(a_step * fl * dfv) / rate_max);
  return r;
}

FibreLaw Muscle::fibre() const {
  FibreLaw f;
  f.E = youngOf(moduli);
  f.G = moduli.shear;
  f.muscle = this;
  return f;
}

double muscleStep(const MuscleResponse& r, double rho, double L0, double l_orig) {
  const double lr2 = L0 * l_orig;
  const double omega2 = 4.0 * r.modulus / (rho * lr2);
  const double q = 2.0 * r.viscosity / (rho * lr2);
  const double den = std::sqrt(omega2 + q * q) + q;
  return den > 0.0 ? 2.0 / den : std::numeric_limits<double>::infinity();
}

}  // namespace crumple::materials
