// Meaning of *EOS_LINEAR_POLYNOMIAL, *EOS_GRUNEISEN, *EOS_TABULATED_COMPACTION and
// *EOS_TABULATED (LS-DYNA Keyword Manual vol. II, "*EOS"; materials/eos.hpp has the formulas)
// and of *PART EOSID: a part's equation of state reaches the law of its solids
// (materials::makeLaw), for the laws whose unit declares kEos.
#include <string>

#include "deck/card.hpp"
#include "model/build_context.hpp"

namespace crumple::model::build {

using deck::Card;
using deck::CardCursor;

namespace {

// EOSID, the title and the definition record shared by every form; `coefficients` fills the
// form's parameters from card 1 and the cards after it and returns the card that holds V0.
template <class F>
void readEos(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts,
             std::string_view name, materials::Eos::Form form, F&& coefficients) {
  const auto& spec = deck::keywordSpec(name);
  CardCursor cur(kw, ctx.deck);
  EquationOfState e;
  e.title = readTitleCard(cur, spec, opts);
  const Card& c1 = cur.read(spec.card("card 1"));
  e.id = positiveId(c1, "EOSID");
  ctx.define(Kind::Eos, e.id, c1, "EOSID");
  e.where = c1.where();
  e.eos.form = form;
  const Card& with_v0 = coefficients(c1, cur, spec, e.eos);
  e.eos.v0 = with_v0.real("V0");
  if (!(e.eos.v0 > 0.0)) with_v0.fail("V0", "the initial relative volume must be positive");
  ctx.model.eos.push_back(std::move(e));
  ctx.collect(cur);
}

// The curve ids of card 1 that newer manuals allow (LCC, LCT; EOS 8 also LCK, LCID), refused
// when set: Crumple reads the table's cards only.
void rejectCurves(Context& ctx, const Card& c1, bool compaction) {
  static constexpr std::string_view kCurves[4] = {"LCC", "LCT", "LCK", "LCID"};
  for (int i = 0; i < (compaction ? 4 : 2); ++i)
    if (c1.integer(kCurves[i]) != 0)
      ctx.reject(c1, kCurves[i],
                 i < 3 ? "a curve in place of the EV/C/T/K table is not supported: give the "
                         "table's cards (up to 10 points)"
                       : "energy deposition by a curve is not supported");
}

// The table of *EOS_TABULATED_COMPACTION (`compaction`: with the K column) and *EOS_TABULATED:
// GAMA and E0 of card 1 (its curve ids refused when set: rejectCurves), and the points
// EV/C/T(/K) of the cards after it (five to a card). The table holds the rows up to the last
// with a non-zero value (unused rows are blank or zero); EV must decrease strictly, as the
// Keyword Manual asks, and K be positive. Stored in ascending ln V (materials::EosTable).
const Card& readTable(Context& ctx, const Card& c1, CardCursor& cur, const deck::KeywordSpec& spec,
                      materials::Eos& eos, bool compaction) {
  eos.e0 = c1.real("E0");
  eos.table.gamma = c1.real("GAMA");
  rejectCurves(ctx, c1, compaction);
  static constexpr std::string_view kColumns[4] = {"EV", "C", "T", "K"};
  static constexpr std::string_view kLabels[8] = {"card 2", "card 3", "card 4", "card 5",
                                                  "card 6", "card 7", "card 8", "card 9"};
  const int columns = compaction ? 4 : 3;
  const Card* cards[8] = {};
  for (int c = 0; c < 2 * columns; ++c) cards[c] = &cur.readOptional(spec.card(kLabels[c]));
  const auto field = [](int column, int i) {
    return std::string(kColumns[column]) + std::to_string(i + 1);
  };
  const auto card = [&](int column, int i) -> const Card& { return *cards[2 * column + i / 5]; };
  double v[4][10] = {};
  int n = 0;
  for (int i = 0; i < 10; ++i)
    for (int column = 0; column < columns; ++column) {
      v[column][i] = card(column, i).real(field(column, i));
      if (v[column][i] != 0.0) n = i + 1;
    }
  if (n < 2)
    card(0, 0).fail("EV1", "the table needs at least two points (EV, C, T" +
                               std::string(compaction ? ", K" : "") +
                               "), as the Keyword Manual says");
  for (int i = 1; i < n; ++i)
    if (!(v[0][i] < v[0][i - 1]))
      card(0, i).fail(field(0, i),
                      "the volumetric strains ln V must decrease point by point (" +
                          field(0, i - 1) + " = " + std::to_string(v[0][i - 1]) + ", " +
                          field(0, i) + " = " + std::to_string(v[0][i]) +
                          "): the Keyword Manual gives them in descending order, negative in "
                          "compression");
  if (compaction)
    for (int i = 0; i < n; ++i)
      if (!(v[3][i] > 0.0))
        card(3, i).fail(field(3, i), "the unloading bulk modulus must be positive");
  materials::EosTable& t = eos.table;
  t.n = n;
  for (int i = 0; i < n; ++i) {
    const auto j = static_cast<std::size_t>(n - 1 - i);
    t.ln_v[j] = v[0][i];
    t.c[j] = v[1][i];
    t.t[j] = v[2][i];
    t.k[j] = v[3][i];
  }
  return c1;
}

}  // namespace

void readEosLinearPolynomial(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  readEos(ctx, kw, opts, "*EOS_LINEAR_POLYNOMIAL", materials::Eos::Form::LinearPolynomial,
          [](const Card& c1, CardCursor& cur, const deck::KeywordSpec& spec,
             materials::Eos& eos) -> const Card& {
            static constexpr std::string_view kC[7] = {"C0", "C1", "C2", "C3", "C4", "C5", "C6"};
            for (int i = 0; i < 7; ++i) eos.c[static_cast<std::size_t>(i)] = c1.real(kC[i]);
            const Card& c2 = cur.readOptional(spec.card("card 2"));
            eos.e0 = c2.real("E0");
            return c2;
          });
}

void readEosGruneisen(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  readEos(ctx, kw, opts, "*EOS_GRUNEISEN", materials::Eos::Form::Gruneisen,
          [](const Card& c1, CardCursor& cur, const deck::KeywordSpec& spec,
             materials::Eos& eos) -> const Card& {
            static constexpr std::string_view kC[6] = {"C", "S1", "S2", "S3", "GAMAO", "A"};
            for (int i = 0; i < 6; ++i) eos.c[static_cast<std::size_t>(i)] = c1.real(kC[i]);
            eos.e0 = c1.real("E0");
            if (!(eos.c[0] > 0.0)) c1.fail("C", "the sound speed must be positive");
            return cur.readOptional(spec.card("card 2"));
          });
}

void readEosTabulatedCompaction(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  readEos(
      ctx, kw, opts, "*EOS_TABULATED_COMPACTION", materials::Eos::Form::TabulatedCompaction,
      [&](const Card& c1, CardCursor& cur, const deck::KeywordSpec& spec,
          materials::Eos& eos) -> const Card& { return readTable(ctx, c1, cur, spec, eos, true); });
}

void readEosTabulated(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  readEos(ctx, kw, opts, "*EOS_TABULATED", materials::Eos::Form::Tabulated,
          [&](const Card& c1, CardCursor& cur, const deck::KeywordSpec& spec, materials::Eos& eos)
              -> const Card& { return readTable(ctx, c1, cur, spec, eos, false); });
}

void checkPartEos(Context& ctx, const Part& p) {
  const Material& m = ctx.model.materials[static_cast<std::size_t>(p.material)];
  const bool uses = materials::usesEos(m.law);
  const std::string part = "part " + std::to_string(p.id);
  const std::string mat = "material " + std::to_string(m.id) + " (" + materialKeyword(m.law) + ")";
  if (p.eos != kNone && !uses)
    ctx.fail(p.where.str() + ": *PART card 2 field 4 (EOSID): " + part +
             " names equation of state " +
             std::to_string(ctx.model.eos[static_cast<std::size_t>(p.eos)].id) + " but " + mat +
             " has its own pressure response and cannot use one");
  // The Keyword Manual (*MAT_NULL) requires an equation of state on solids; shells and beams
  // of such a law are bypassed and need none.
  else if (p.eos == kNone && uses &&
           (p.section_kind == SectionKind::Solid || p.section_kind == SectionKind::Sph))
    ctx.fail(p.where.str() + ": *PART card 2 field 4 (EOSID): " + part +
             " has solid elements and " + mat +
             ", which needs an equation of state (*EOS_LINEAR_POLYNOMIAL, *EOS_GRUNEISEN, "
             "*EOS_TABULATED_COMPACTION, *EOS_TABULATED)");
  else if (p.eos != kNone && p.section_kind != SectionKind::Solid &&
           p.section_kind != SectionKind::Sph)
    ctx.ignore("*PART", "EOSID",
               part + " has no solid elements: its equation of state acts on nothing", p.where);
}

}  // namespace crumple::model::build
