#include "materials/laws/rigid.hpp"

#include <cmath>

#include "deck/card.hpp"
#include "deck/layout.hpp"

namespace crumple::materials {

const deck::KeywordSpec& Rigid::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("E"), R("PR"), R("N"), R("COUPLE"), R("M"), R("ALIAS")}},
       {"card 2", {R("CMO"), R("CON1"), R("CON2")}},
       {"card 3", {R("LCO/A1"), R("A2"), R("A3"), R("V1"), R("V2"), R("V3")}}}};
  return spec;
}

Rigid::Params Rigid::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  const deck::Card& c2 = in.optionalCard("card 2");
  const deck::Card& c3 = in.optionalCard("card 3");
  Params p;
  readElastic(c, p.E, p.nu);
  for (auto f : {"N", "COUPLE", "M", "ALIAS"}) c.real(f);  // coupling with MADYMO: not used
  const double cmo = c2.real("CMO");
  if (cmo == -1.0)
    in.reject(c2, "CMO", "constraints in a local coordinate system (CMO=-1) are not supported");
  else if (cmo != 0.0 && cmo != 1.0)
    c2.fail("CMO", "must be 0, 1 or -1");
  p.cmo = static_cast<int>(cmo);
  if (p.cmo == 1) {
    const double con1 = c2.real("CON1"), con2 = c2.real("CON2");
    if (con1 < 0 || con1 > 7 || con1 != std::floor(con1)) c2.fail("CON1", "must be 0 to 7");
    if (con2 < 0 || con2 > 7 || con2 != std::floor(con2)) c2.fail("CON2", "must be 0 to 7");
    p.con1 = static_cast<int>(con1);
    p.con2 = static_cast<int>(con2);
  } else {
    c2.real("CON1");
    c2.real("CON2");
  }
  // Card 3 (local axes for output) changes no result.
  for (auto f : {"LCO/A1", "A2", "A3", "V1", "V2", "V3"}) c3.real(f);
  return p;
}

Elastic Rigid::make(const Params& p, const CurveAt& curves, const std::string& at) {
  return Elastic::make({p.E, p.nu}, curves, at);
}

}  // namespace crumple::materials
