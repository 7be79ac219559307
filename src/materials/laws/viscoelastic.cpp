#include "materials/laws/viscoelastic.hpp"

#include <cmath>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "util/error.hpp"

namespace crumple::materials {

namespace {

// The step's constants: the long-term and relaxing shear moduli, the decay exp(-BETA dt) of h
// and the weight (1 - exp(-BETA dt)) / (BETA dt) of this step's strain in it (1 as dt -> 0).
struct Step {
  double K = 0, g_inf = 0, g_relax = 0, decay = 1, weight = 1;
  Step(const Viscoelastic& law, double dt)
      : K(law.moduli.bulk), g_inf(law.gi), g_relax(law.moduli.shear - law.gi) {
    const double x = law.beta * dt;
    decay = std::exp(-x);
    weight = x > 1e-8 ? -std::expm1(-x) / x : 1.0 - 0.5 * x;
  }
  // The shear modulus the step's deviatoric strain meets.
  double effectiveShear() const { return g_inf + g_relax * weight; }
};

// One point: stress s and relaxing stress h (Voigt, tensor shear) advanced by the strain
// increment de.
void advance(const Step& st, const double de[6], double s[6], double h[6]) {
  const double tr = de[0] + de[1] + de[2];
  const double mean_old = (s[0] + s[1] + s[2]) / 3.0, mean = mean_old + st.K * tr;
  for (int k = 0; k < 6; ++k) {
    const double dev_de = k < 3 ? de[k] - tr / 3.0 : de[k];
    const double long_term = (k < 3 ? s[k] - mean_old : s[k]) - h[k] + 2.0 * st.g_inf * dev_de;
    h[k] = st.decay * h[k] + 2.0 * st.g_relax * st.weight * dev_de;
    s[k] = long_term + h[k] + (k < 3 ? mean : 0.0);
  }
}

}  // namespace

const deck::KeywordSpec& Viscoelastic::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(), {"card 1", {I("MID"), R("RO"), R("BULK"), R("G0"), R("GI"), R("BETA")}}}};
  return spec;
}

Viscoelastic::Params Viscoelastic::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  Params p;
  p.bulk = c.real("BULK");
  p.g0 = c.real("G0");
  p.gi = c.real("GI");
  p.beta = c.real("BETA");
  if (!(p.bulk > 0.0)) c.fail("BULK", "the bulk modulus must be positive");
  if (!(p.g0 > 0.0)) c.fail("G0", "the short-time shear modulus must be positive");
  if (p.gi < 0.0 || p.gi > p.g0) c.fail("GI", "the long-time shear modulus must lie in [0, G0]");
  if (p.beta < 0.0) c.fail("BETA", "the decay constant must not be negative");
  return p;
}

Viscoelastic Viscoelastic::make(const Params& p, const CurveAt&, const std::string& at) {
  if (!(p.bulk > 0.0) || !(p.g0 > 0.0) || p.gi < 0.0 || p.gi > p.g0 || p.beta < 0.0)
    throw util::InputError(at +
                           ": *MAT_VISCOELASTIC needs BULK > 0, G0 > 0, 0 <= GI <= G0 "
                           "and BETA >= 0");
  Viscoelastic law;
  law.moduli = {p.bulk, p.g0};
  law.gi = p.gi;
  law.beta = p.beta;
  return law;
}

void Viscoelastic::update(PointBatch& b) const {
  const Step st(*this, b.dt);
  for (int i = 0; i < b.n; ++i) {
    double de[6], s[6], h[6];
    for (int k = 0; k < 6; ++k) {
      de[k] = b.de[k][i];
      s[k] = b.s[k][i];
      h[k] = b.alpha[k][i];
    }
    advance(st, de, s, h);
    for (int k = 0; k < 6; ++k) {
      b.s[k][i] = s[k];
      b.alpha[k][i] = h[k];
    }
  }
}

// Plane stress: sigma_zz is linear in the thickness strain increment, with slope
// K + 4/3 G_eff, so one correction from de_zz = 0 makes it zero.
void Viscoelastic::updatePlaneStress(PlaneStressPoints& b) const {
  const Step st(*this, b.dt);
  const double slope = st.K + 4.0 / 3.0 * st.effectiveShear();
  for (int i = 0; i < b.n; ++i) {
    const double s0[6] = {b.s[0][i], b.s[1][i], 0.0, b.s[2][i], 0.0, 0.0};
    const double hxx = b.alpha[0][i], hyy = b.alpha[1][i];
    const double h0[6] = {hxx, hyy, -(hxx + hyy), b.alpha[2][i], 0.0, 0.0};
    double de[6] = {b.de[0][i], b.de[1][i], 0.0, b.de[2][i], 0.0, 0.0};
    double s[6], h[6];
    for (int k = 0; k < 6; ++k) {
      s[k] = s0[k];
      h[k] = h0[k];
    }
    advance(st, de, s, h);
    de[2] = -s[2] / slope;
    for (int k = 0; k < 6; ++k) {
      s[k] = s0[k];
      h[k] = h0[k];
    }
    advance(st, de, s, h);
    b.s[0][i] = s[0];
    b.s[1][i] = s[1];
    b.s[2][i] = s[3];
    b.alpha[0][i] = h[0];
    b.alpha[1][i] = h[1];
    b.alpha[2][i] = h[3];
    b.de_zz[i] = de[2];
    if (b.failed) b.failed[i] = 0;
  }
}

}  // namespace crumple::materials
