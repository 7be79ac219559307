#include "materials/laws/elastic.hpp"

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "materials/return_mapping.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& Elastic::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("E"), R("PR"), R("DA"), R("DB"), R("K")}}}};
  return spec;
}

Elastic::Params Elastic::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  Params p;
  readElastic(c, p.E, p.nu);
  return p;
}

Elastic Elastic::make(const Params& p, const CurveAt&, const std::string& at) {
  checkModuli(at, p.E, p.nu);
  return Elastic{moduliFromYoung(p.E, p.nu)};
}

void Elastic::update(PointBatch& b) const {
  elasticUpdate(b, moduli);
}

void Elastic::updatePlaneStress(PlaneStressPoints& b) const {
  planeStressElastic(b, moduli);
}

FibreLaw Elastic::fibre() const {
  FibreLaw f;
  f.E = youngOf(moduli);
  f.G = moduli.shear;
  return f;
}

}  // namespace crumple::materials
