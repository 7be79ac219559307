#include "materials/laws/blatz_ko.hpp"

#include <cmath>
#include <string>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& BlatzKo::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0], {deck::titleCard(), {"card 1", {I("MID"), R("RO"), R("G"), R("REF")}}}};
  return spec;
}

BlatzKo::Params BlatzKo::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  Params p;
  p.G = c.real("G");
  if (!(p.G > 0.0)) c.fail("G", "the shear modulus must be positive");
  if (c.real("REF") != 0.0)
    in.reject(c, "REF", "REF = 1 (stress from *INITIAL_FOAM_REFERENCE_GEOMETRY) is not supported");
  return p;
}

BlatzKo BlatzKo::make(const Params& p, const CurveAt&, const std::string& at) {
  if (!(p.G > 0.0)) throw util::InputError(at + "the shear modulus G must be positive");
  BlatzKo m;
  m.moduli = moduliFromShear(p.G, kNu);
  m.beta = kNu / (1.0 - 2.0 * kNu);
  return m;
}

void BlatzKo::update(PointBatch& p) const {
  // W1 = G/2, W2 = 0, W3 = -G/2 I3^(-beta-1): sigma = 2/J (W1 B + I3 W3 I) = G/J (B - J^-2beta I).
  const double half = 0.5 * moduli.shear;
  for (int l = 0; l < p.n; ++l) {
    const LeftCauchyGreen k = leftCauchyGreen(p, l);
    invariantStress(k, half, 0.0, -half * std::pow(k.I3, -beta - 1.0), p, l);
  }
}

double BlatzKo::energy(const LeftCauchyGreen& k) const {
  return 0.5 * moduli.shear * ((k.I1 - 3.0) + (std::pow(k.I3, -beta) - 1.0) / beta);
}

}  // namespace crumple::materials
