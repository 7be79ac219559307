#include "materials/laws/modified_piecewise_linear.hpp"

#include "deck/card.hpp"
#include "deck/layout.hpp"

namespace crumple::materials {

const deck::KeywordSpec& ModifiedPiecewiseLinear::cards() {
  // *MAT_024's cards with EPSTHIN, EPSMAJ and NUMINT at the end of card 2 (Keyword Manual
  // vol. II, *MAT_MODIFIED_PIECEWISE_LINEAR_PLASTICITY).
  static const deck::KeywordSpec spec = PiecewiseLinear::cardsOf(
      kKeywords[0], {deck::R("EPSTHIN"), deck::R("EPSMAJ"), deck::I("NUMINT")});
  return spec;
}

ModifiedPiecewiseLinear::Params ModifiedPiecewiseLinear::read(LawInput& in) {
  Params p;
  // The same labels as *MAT_024's cards: its reader takes them from this layout.
  p.base = PiecewiseLinear::read(in);
  const deck::Card& c2 = in.optionalCard("card 2");
  p.epsthin = c2.real("EPSTHIN");
  p.epsmaj = c2.real("EPSMAJ");
  const int64_t numint = c2.integer("NUMINT");
  if (p.epsthin < 0.0) {
    in.reject(c2, "EPSTHIN", "a negative thinning strain at failure is not supported");
    p.epsthin = 0.0;
  }
  // Later manuals give EPSMAJ < 0 and NUMINT < 0 meanings (a curve, a percentage of the points)
  // that are not implemented.
  if (p.epsmaj < 0.0) {
    in.reject(c2, "EPSMAJ", "a negative EPSMAJ is not supported");
    p.epsmaj = 0.0;
  }
  if (numint < 0) in.reject(c2, "NUMINT", "a negative NUMINT (a percentage) is not supported");
  p.numint = numint > 0 ? static_cast<int32_t>(numint) : 0;
  return p;
}

void ModifiedPiecewiseLinear::addErosion(const Params& p, Erosion& er) {
  if (p.epsthin > 0.0) er.set(Criterion::Thinning, p.epsthin);
  if (p.epsmaj > 0.0) er.set(Criterion::MajorStrain, p.epsmaj);
  er.numfip = p.numint;
}

}  // namespace crumple::materials
