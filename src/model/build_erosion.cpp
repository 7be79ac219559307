// Meaning of *MAT_ADD_EROSION (LS-DYNA Keyword Manual vol. II): erosion criteria added to the
// material MID, whatever its law (materials/erosion.hpp evaluates them, the element kernels
// delete). Cards 1 and 2 are honoured except SIGTH and IMPULSE (the Tuler-Butcher impulse) and
// the curve forms of SIGVM and MXEPS; cards 3-5 (damage, forming limit, nonlocal, temperature
// and time-step criteria) are refused field by field when they set anything.
#include <cmath>
#include <string>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "model/build_context.hpp"

namespace crumple::model::build {

using deck::Card;
using deck::CardCursor;
using materials::Criterion;

namespace {

struct Field {
  std::string_view name;
  Criterion criterion;
};

// The criteria of cards 1 and 2. A value equal to EXCL is excluded ("only the failure values
// not set to the exclusion number are invoked"); MXPRES, MNEPS, EFFEPS and VOLEPS are also
// excluded when exactly zero ("to maintain compatibility with old input files").
constexpr Field kCard1[] = {{"MXPRES", Criterion::MaxPressure},
                            {"MNEPS", Criterion::MinPrincipalStrain},
                            {"EFFEPS", Criterion::EffectiveStrain},
                            {"VOLEPS", Criterion::VolumetricStrain}};
constexpr Field kCard2[] = {
    {"MNPRES", Criterion::MinPressure}, {"SIGP1", Criterion::MaxPrincipalStress},
    {"SIGVM", Criterion::VonMises},     {"MXEPS", Criterion::MaxPrincipalStrain},
    {"EPSSH", Criterion::ShearStrain},  {"FAILTM", Criterion::FailureTime}};

void readCriteria(Context& ctx, const Card& c1, const Card& c2, materials::Erosion& er) {
  const double excl = c1.real("EXCL");
  for (const Field& f : kCard1)
    if (const double v = c1.real(f.name); v != 0.0 && v != excl) er.set(f.criterion, v);
  for (const Field& f : kCard2) {
    double v = c2.real(f.name);
    if (v == excl) continue;
    if (v < 0.0 && (f.name == "SIGVM" || f.name == "MXEPS")) {
      ctx.reject(c2, f.name,
                 "a negative value (a curve of the limit against the strain rate) is not "
                 "supported");
      continue;
    }
    // FAILTM < 0: |FAILTM|; its inactivity during dynamic relaxation is not modelled.
    if (f.name == "FAILTM") v = std::abs(v);
    er.set(f.criterion, v);
  }
  for (std::string_view name : {"SIGTH", "IMPULSE"})
    if (const double v = c2.real(name); v != excl)
      ctx.reject(c2, name, "the Tuler-Butcher impulse criterion (SIGTH, IMPULSE) is not supported");
}

// NUMFIP (failed points that delete a shell; default 1) and NCS (criteria at once; default 1).
void readCounts(Context& ctx, const Card& c1, materials::Erosion& er) {
  const double numfip = c1.real("NUMFIP"), ncs = c1.real("NCS");
  if (numfip < 0.0)
    ctx.reject(c1, "NUMFIP", "a negative NUMFIP (a percentage of the points) is not supported");
  er.numfip = numfip >= 1.0 ? static_cast<int32_t>(numfip) : 1;
  er.ncs = ncs >= 1.0 ? static_cast<int32_t>(ncs) : 1;
}

// Cards 3-5: any value set there is refused by its field.
void refuseExtendedCards(Context& ctx, const Card& c3, const Card& c4, const Card& c5) {
  const std::string why = "is not supported with *MAT_ADD_EROSION";
  for (std::string_view f :
       {"IDAM", "DMGTYP", "LCSDG", "ECRIT", "DMGEXP", "DCRIT", "FADEXP", "LCREGD"})
    if (!c3.blank(f) && c3.real(f) != 0.0) ctx.reject(c3, f, std::string(f) + " " + why);
  for (std::string_view f :
       {"LCFLD", "EPSTHIN", "ENGCRT", "RADCRT", "LCEPS12", "LCEPS13", "LCEPSMX"})
    if (!c4.blank(f) && c4.real(f) != 0.0) ctx.reject(c4, f, std::string(f) + " " + why);
  for (std::string_view f : {"DTEFLT", "MXTMP", "DTMIN"})
    if (!c5.blank(f) && c5.real(f) != 0.0) ctx.reject(c5, f, std::string(f) + " " + why);
}

}  // namespace

void readAddErosion(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = deck::keywordSpec("*MAT_ADD_EROSION");
  CardCursor cur(kw, ctx.deck);
  readTitleCard(cur, spec, opts);
  const Card& c1 = cur.read(spec.card("card 1"));
  const Card& c2 = cur.readOptional(spec.card("card 2"));
  const Card& c3 = cur.readOptional(spec.card("card 3"));
  const Card& c4 = cur.readOptional(spec.card("card 4"));
  const Card& c5 = cur.readOptional(spec.card("card 5"));
  const int64_t mid = c1.integer("MID");
  // A material Crumple cannot read already stops every part that uses it.
  if (ctx.isUnsupported(Kind::Material, mid)) return ctx.collect(cur);
  const auto it = ctx.material_index.find(mid);
  if (it == ctx.material_index.end()) c1.fail("MID", ctx.undefinedMessage(Kind::Material, mid));
  materials::Erosion& er = ctx.model.materials[static_cast<std::size_t>(it->second)].erosion;
  readCriteria(ctx, c1, c2, er);
  readCounts(ctx, c1, er);
  refuseExtendedCards(ctx, c3, c4, c5);
  ctx.collect(cur);
}

void checkPartErosion(Context& ctx, std::size_t part) {
  const Part& p = ctx.model.parts[part];
  const materials::Erosion& er = ctx.model.materials[static_cast<std::size_t>(p.material)].erosion;
  if (!er.any() || !ctx.part_problem[part].empty()) return;
  // The kernels that evaluate the criteria: one-point solids (ELFORM 1, 10) and the shells
  // (ELFORM 2, 4, 16). Gauss-point solids, 2D solids and beams do not yet.
  const auto idx = static_cast<std::size_t>(p.section);
  // The shell criteria of *MAT_123 (EPSTHIN, EPSMAJ) do not apply to the other families.
  bool ok = !er.forSolids().any();
  const bool tshell =
      p.section_kind == SectionKind::Solid && isThickShell(ctx.model.solid_sections[idx].elform);
  if (tshell)
    ok = false;
  else if (p.section_kind == SectionKind::Solid)
    ok = ok || !isFullyIntegratedHex(ctx.model.solid_sections[idx].elform);
  else if (p.section_kind == SectionKind::Shell)
    ok = ctx.model.shell_sections[idx].elform != 13 && ctx.model.shell_sections[idx].elform != 15;
  // Integrated beams (Hughes-Liu, ELFORM 1) take EFFEPS alone, on the effective plastic strain
  // of their section points: the first point to reach it deletes the beam, as the law's FAIL.
  else if (p.section_kind == SectionKind::Beam && ctx.model.beam_sections[idx].elform == 1 &&
           er.active == 1U << static_cast<int>(materials::Criterion::EffectiveStrain)) {
    ctx.ignore("*MAT_ADD_EROSION", "EFFEPS",
               "on beams (part " + std::to_string(p.id) +
                   ") it is checked against the effective plastic strain of the section points "
                   "(the elastic strain, below 1 % for metals, left out); NUMFIP 1",
               p.where);
    return;
  }
  if (ok) return;
  const std::string family = tshell                                 ? "thick shells"
                             : p.section_kind == SectionKind::Solid ? "ELFORM 2 solids (and -1, -2)"
                             : p.section_kind == SectionKind::Shell ? "2D solids"
                                                                    : "beams and discretes";
  // Refused where an element uses the part (Context::checkPartUsable), as a missing feature.
  ctx.part_problem[part] = {
      p.where.str() + ": part " + std::to_string(p.id) + ": the erosion criteria of material " +
          std::to_string(ctx.model.materials[static_cast<std::size_t>(p.material)].id) +
          " (*MAT_ADD_EROSION, *MAT_123 EPSTHIN/EPSMAJ) are evaluated on one-point solids "
          "(ELFORM 1, 10) and shells (ELFORM 2, 4, 16) only, not on " +
          family,
      "*MAT_ADD_EROSION on " + family};
}

}  // namespace crumple::model::build
