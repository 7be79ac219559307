#include "materials/laws/springs.hpp"

#include "deck/card.hpp"
#include "deck/layout.hpp"

namespace crumple::materials {

using deck::I;
using deck::R;

const deck::KeywordSpec& SpringElastic::cards() {
  static const deck::KeywordSpec spec{kKeywords[0],
                                      {deck::titleCard(), {"card 1", {I("MID"), R("K")}}}};
  return spec;
}

SpringElastic::Params SpringElastic::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  Params p{c.real("K")};
  if (!(p.k > 0)) c.fail("K", "the spring stiffness must be positive");
  return p;
}

DiscreteLaw SpringElastic::make(const Params& p, const CurveAt&, const std::string&) {
  return DiscreteLaw{DiscreteLaw::Kind::SpringElastic, p.k, {}, {}};
}

const deck::KeywordSpec& DamperViscous::cards() {
  static const deck::KeywordSpec spec{kKeywords[0],
                                      {deck::titleCard(), {"card 1", {I("MID"), R("DC")}}}};
  return spec;
}

DamperViscous::Params DamperViscous::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  Params p{c.real("DC")};
  if (!(p.dc > 0)) c.fail("DC", "the damping constant must be positive");
  return p;
}

DiscreteLaw DamperViscous::make(const Params& p, const CurveAt&, const std::string&) {
  return DiscreteLaw{DiscreteLaw::Kind::DamperViscous, p.dc, {}, {}};
}

const deck::KeywordSpec& SpringNonlinear::cards() {
  static const deck::KeywordSpec spec{
      kKeywords[0], {deck::titleCard(), {"card 1", {I("MID"), I("LCD"), I("LCR")}}}};
  return spec;
}

SpringNonlinear::Params SpringNonlinear::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  Params p{in.curve(c, "LCD", c.integer("LCD"))};
  if (c.integer("LCR") != 0)
    in.reject(c, "LCR", "rate-dependent spring scaling (LCR) is not supported");
  return p;
}

DiscreteLaw SpringNonlinear::make(const Params& p, const CurveAt& curves, const std::string&) {
  const CurveData c = curves(p.curve);
  return DiscreteLaw{
      DiscreteLaw::Kind::SpringNonlinear, 0.0, {c.x.begin(), c.x.end()}, {c.y.begin(), c.y.end()}};
}

}  // namespace crumple::materials
