// Meaning of *EOS_LINEAR_POLYNOMIAL and *EOS_GRUNEISEN (LS-DYNA Keyword Manual vol. II, "*EOS";
// materials/eos.hpp has the formulas) and of *PART EOSID: a part's equation of state reaches
// the law of its solids (materials::makeLaw), for the laws whose unit declares kEos.
#include <string>

#include "deck/card.hpp"
#include "model/build_context.hpp"

namespace crumple::model::build {

using deck::Card;
using deck::CardCursor;

namespace {

// EOSID, the title and the definition record shared by both forms; `coefficients` fills the
// form's parameters from its cards.
template <class F>
void readEos(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts,
             std::string_view name, materials::Eos::Form form, F&& coefficients) {
  const auto& spec = deck::keywordSpec(name);
  CardCursor cur(kw, ctx.deck);
  EquationOfState e;
  e.title = readTitleCard(cur, spec, opts);
  const Card& c1 = cur.read(spec.card("card 1"));
  const Card& c2 = cur.readOptional(spec.card("card 2"));
  e.id = positiveId(c1, "EOSID");
  ctx.define(Kind::Eos, e.id, c1, "EOSID");
  e.where = c1.where();
  e.eos.form = form;
  coefficients(c1, c2, e.eos);
  e.eos.v0 = c2.real("V0");
  if (!(e.eos.v0 > 0.0)) c2.fail("V0", "the initial relative volume must be positive");
  ctx.model.eos.push_back(std::move(e));
  ctx.collect(cur);
}

}  // namespace

void readEosLinearPolynomial(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  readEos(ctx, kw, opts, "*EOS_LINEAR_POLYNOMIAL", materials::Eos::Form::LinearPolynomial,
          [](const Card& c1, const Card& c2, materials::Eos& eos) {
            static constexpr std::string_view kC[7] = {"C0", "C1", "C2", "C3", "C4", "C5", "C6"};
            for (int i = 0; i < 7; ++i) eos.c[static_cast<std::size_t>(i)] = c1.real(kC[i]);
            eos.e0 = c2.real("E0");
          });
}

void readEosGruneisen(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  readEos(ctx, kw, opts, "*EOS_GRUNEISEN", materials::Eos::Form::Gruneisen,
          [](const Card& c1, const Card&, materials::Eos& eos) {
            static constexpr std::string_view kC[6] = {"C", "S1", "S2", "S3", "GAMAO", "A"};
            for (int i = 0; i < 6; ++i) eos.c[static_cast<std::size_t>(i)] = c1.real(kC[i]);
            eos.e0 = c1.real("E0");
            if (!(eos.c[0] > 0.0)) c1.fail("C", "the sound speed must be positive");
          });
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
             ", which needs an equation of state (*EOS_LINEAR_POLYNOMIAL, *EOS_GRUNEISEN)");
  else if (p.eos != kNone && p.section_kind != SectionKind::Solid &&
           p.section_kind != SectionKind::Sph)
    ctx.ignore("*PART", "EOSID",
               part + " has no solid elements: its equation of state acts on nothing", p.where);
}

}  // namespace crumple::model::build
