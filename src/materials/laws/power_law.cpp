#include "materials/laws/power_law.hpp"

#include <cmath>
#include <limits>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& PowerLaw::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("E"), R("PR"), R("K"), R("N"), R("SRC"), R("SRP")}},
       {"card 2", {R("SIGY"), R("VP"), R("EPSF")}}}};
  return spec;
}

double PowerLaw::yieldStrain(const Params& p) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!(p.k > 0.0) || !(p.E > 0.0)) return nan;
  // Keyword Manual, *MAT_018 remarks: SIGY = 0, the intersection of sigma = E eps with
  // sigma = k eps^n; 0 < SIGY < 0.02, the strain itself; SIGY >= 0.02, the yield stress.
  if (p.sigy == 0.0) return p.n >= 0.0 && p.n < 1.0 ? std::pow(p.E / p.k, 1.0 / (p.n - 1.0)) : nan;
  if (p.sigy > 0.0 && p.sigy < 0.02) return p.sigy;
  if (p.sigy >= 0.02 && p.n > 0.0) return std::pow(p.sigy / p.k, 1.0 / p.n);
  return nan;
}

PowerLaw::Params PowerLaw::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  const deck::Card& c2 = in.optionalCard("card 2");
  Params p;
  readElastic(c, p.E, p.nu);
  p.k = c.real("K");
  p.n = c.real("N");
  if (!(p.k > 0.0)) c.fail("K", "the strength coefficient must be positive");
  if (p.n < 0.0) c.fail("N", "the hardening exponent must not be negative");
  p.src = c.real("SRC");
  p.srp = c.real("SRP");
  if (p.src < 0) c.fail("SRC", "must not be negative");
  if (p.srp < 0) c.fail("SRP", "must not be negative");
  p.sigy = c2.real("SIGY");
  if (p.sigy < 0.0) c2.fail("SIGY", "must not be negative");
  if (p.sigy == 0.0 && !(p.n < 1.0))
    c2.fail("SIGY", "with N >= 1 the elastic line meets k eps^N nowhere: give SIGY");
  if (p.sigy >= 0.02 && !(p.n > 0.0))
    c2.fail("SIGY", "a yield stress (>= 0.02) needs N > 0 to give the strain at yield");
  if (c2.real("VP") != 0.0)
    in.reject(c2, "VP",
              "only VP = 0 (the Cowper-Symonds factor scales the yield stress at the total "
              "effective strain rate) is supported; VP = 1 (viscoplastic) is not");
  p.epsf = c2.real("EPSF");
  if (p.epsf < 0.0) c2.fail("EPSF", "must not be negative");
  return p;
}

PowerLaw PowerLaw::make(const Params& p, const CurveAt&, const std::string& at) {
  checkModuli(at, p.E, p.nu);
  const double eps0 = yieldStrain(p);
  if (!(eps0 >= 0.0) || !std::isfinite(eps0))
    throw util::InputError(at + "K, N and SIGY give no strain at yield");
  PowerLaw law;
  law.moduli = moduliFromYoung(p.E, p.nu);
  law.hardening.k = p.k;
  law.hardening.n = p.n;
  law.hardening.eps0 = eps0;
  if (p.src > 0.0 && p.srp > 0.0) {
    law.hardening.C = p.src;
    law.hardening.inv_P = 1.0 / p.srp;
  }
  law.epsf = p.epsf;
  return law;
}

void PowerLaw::update(PointBatch& b) const {
  powerHardeningReturn(b, moduli, hardening);
  markFailed(b, epsf);
}

void PowerLaw::updatePlaneStress(PlaneStressPoints& b) const {
  planeStressPower(b, moduli, hardening);
  markFailed(b, epsf);
}

FibreLaw PowerLaw::fibre() const {
  FibreLaw f;
  f.E = youngOf(moduli);
  f.G = moduli.shear;
  f.plastic = true;
  f.power = hardening;
  f.sigy = hardening.flow(0.0);
  f.C = hardening.C;
  f.inv_P = hardening.inv_P;
  f.fail = epsf;
  return f;
}

}  // namespace crumple::materials
