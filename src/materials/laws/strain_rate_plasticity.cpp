#include "materials/laws/strain_rate_plasticity.hpp"

#include <cstddef>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& StrainRatePlasticity::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("E"), R("PR"), R("VP")}},
       {"card 2", {I("LC1"), R("ETAN"), I("LC2"), I("LC3"), I("LC4"), R("TDEL"), R("RDEF")}}}};
  return spec;
}

StrainRatePlasticity::Params StrainRatePlasticity::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  const deck::Card& c2 = in.card("card 2");
  Params p;
  readElastic(c, p.E, p.nu);
  if (c.real("VP") != 0.0)
    in.reject(c, "VP",
              "only VP = 0 (the yield stress at the total effective strain rate) is supported; "
              "VP = 1 (viscoplastic) is not");
  const int64_t lc1 = c2.integer("LC1");
  if (lc1 <= 0) c2.fail("LC1", "the curve of yield stress vs effective strain rate is required");
  p.lc1 = in.curve(c2, "LC1", lc1);
  p.etan = c2.real("ETAN");
  if (p.etan < 0.0 || !(p.etan < p.E)) c2.fail("ETAN", "must lie in [0, E)");
  // Keyword Manual, *MAT_019: LC2 and LC3 make E and ETAN functions of the rate, LC4 a failure
  // stress (RDEF: which stress); each changes the answer.
  if (c2.integer("LC2") != 0)
    in.reject(c2, "LC2", "Young's modulus as a function of the strain rate is not supported");
  if (c2.integer("LC3") != 0)
    in.reject(c2, "LC3", "the tangent modulus as a function of the strain rate is not supported");
  if (c2.integer("LC4") != 0) {
    in.reject(c2, "LC4", "failure at a stress that depends on the strain rate is not supported");
  } else if (c2.real("RDEF") != 0.0) {
    in.ignore(c2, "RDEF", "it redefines the failure curve LC4, which is not given");
  }
  p.tdel = c2.real("TDEL");
  if (p.tdel < 0.0) c2.fail("TDEL", "must not be negative");
  return p;
}

StrainRatePlasticity StrainRatePlasticity::make(const Params& p, const CurveAt& curves,
                                                const std::string& at) {
  checkModuli(at, p.E, p.nu);
  checkTangent(at, p.E, p.etan);
  if (p.lc1 < 0) throw util::InputError(at + "LC1 (yield stress vs strain rate) is required");
  const CurveData c = curves(p.lc1);
  const std::string name = "LC1 curve " + std::to_string(c.id);
  if (c.x.empty() || c.x.size() != c.y.size()) throw util::InputError(at + name + " has no points");
  for (std::size_t k = 0; k < c.y.size(); ++k) {
    if (k > 0 && !(c.x[k] >= c.x[k - 1]))
      throw util::InputError(at + name + " must have non-decreasing strain rates");
    if (!(c.y[k] > 0.0)) throw util::InputError(at + name + " must have positive yield stresses");
  }
  StrainRatePlasticity law;
  law.moduli = moduliFromYoung(p.E, p.nu);
  law.Hi = plasticModulus(youngOf(law.moduli), p.etan);
  law.lc1_rate.assign(c.x.begin(), c.x.end());
  law.lc1_sig.assign(c.y.begin(), c.y.end());
  law.tdel = p.tdel;
  return law;
}

void StrainRatePlasticity::update(PointBatch& b) const {
  linearHardeningReturn(b, moduli, hardening(), false);
}

void StrainRatePlasticity::updatePlaneStress(PlaneStressPoints& b) const {
  planeStressLinear(b, moduli, hardening(), false);
}

FibreLaw StrainRatePlasticity::fibre() const {
  FibreLaw f;
  f.E = youngOf(moduli);
  f.G = moduli.shear;
  f.plastic = true;
  const LinearHardening h = hardening();
  f.sigy = h.sigy;
  f.Hi = Hi;
  f.sigy_rate = h.sigy_rate;
  return f;
}

}  // namespace crumple::materials
