#include "materials/laws/plastic_kinematic.hpp"

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& PlasticKinematic::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("E"), R("PR"), R("SIGY"), R("ETAN"), R("BETA")}},
       {"card 2", {R("SRC"), R("SRP"), R("FS"), R("VP")}}}};
  return spec;
}

PlasticKinematic::Params PlasticKinematic::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  const deck::Card& c2 = in.optionalCard("card 2");
  Params p;
  readElastic(c, p.E, p.nu);
  p.sigy = c.real("SIGY");
  p.etan = c.real("ETAN");
  checkYield(c, p.E, p.sigy, p.etan);
  p.beta = c.real("BETA");
  if (p.beta < 0 || p.beta > 1) c.fail("BETA", "must lie in [0, 1]");
  p.src = c2.real("SRC");
  p.srp = c2.real("SRP");
  if (p.src < 0) c2.fail("SRC", "must not be negative");
  if (p.srp < 0) c2.fail("SRP", "must not be negative");
  p.fs = c2.real("FS");
  if (p.fs < 0) in.reject(c2, "FS", "a negative FS (failure by *MAT_ADD_EROSION) is not supported");
  return p;
}

PlasticKinematic PlasticKinematic::make(const Params& p, const CurveAt&, const std::string& at) {
  checkModuli(at, p.E, p.nu);
  checkTangent(at, p.E, p.etan);
  if (!(p.beta >= 0.0 && p.beta <= 1.0)) throw util::InputError(at + "BETA must lie in [0, 1]");
  PlasticKinematic law;
  law.moduli = moduliFromYoung(p.E, p.nu);
  // beta splits the plastic modulus between isotropic and kinematic hardening; the uniaxial
  // slope after yield is Etan for every beta.
  const double Ep = plasticModulus(youngOf(law.moduli), p.etan);
  law.hardening.sigy = p.sigy;
  law.hardening.Hi = p.beta * Ep;
  law.hardening.Hk = (1.0 - p.beta) * Ep;
  if (p.src > 0.0 && p.srp > 0.0) {
    law.hardening.C = p.src;
    law.hardening.inv_P = 1.0 / p.srp;
  }
  law.fs = p.fs;
  return law;
}

void PlasticKinematic::update(PointBatch& b) const {
  linearHardeningReturn(b, moduli, hardening, true);
  markFailed(b, fs);
}

void PlasticKinematic::updatePlaneStress(PlaneStressPoints& b) const {
  planeStressLinear(b, moduli, hardening, true);
  markFailed(b, fs);
}

FibreLaw PlasticKinematic::fibre() const {
  FibreLaw f;
  f.E = youngOf(moduli);
  f.G = moduli.shear;
  f.plastic = true;
  f.sigy = hardening.sigy;
  f.Hi = hardening.Hi;
  f.Hk = hardening.Hk;
  f.C = hardening.C;
  f.inv_P = hardening.inv_P;
  f.fail = fs;
  return f;
}

}  // namespace crumple::materials
