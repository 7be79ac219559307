// Meaning of *DAMPING_GLOBAL, *DAMPING_PART_MASS(_SET) and *DAMPING_PART_STIFFNESS(_SET)
// (LS-DYNA Keyword Manual vol. I, *DAMPING). The formulations are in docs/theory.md
// ("Damping"): mass damping is the nodal force -D m v (src/solver/damping.cpp), stiffness
// damping the element stress beta D_el deps/dt (src/elements/beam.cpp).
#include <algorithm>
#include <string>

#include "model/build_context.hpp"

namespace crumple::model::build {

using deck::Card;
using deck::CardCursor;
using deck::keywordSpec;

namespace {

// STX..SRZ of a card; all zero means all one (Keyword Manual, *DAMPING_GLOBAL).
std::array<double, 6> scaleFactors(const Card& c) {
  static constexpr const char* kF[6] = {"STX", "STY", "STZ", "SRX", "SRY", "SRZ"};
  std::array<double, 6> s{};
  bool any = false;
  for (std::size_t i = 0; i < 6; ++i) {
    s[i] = c.real(kF[i]);
    if (s[i] < 0) c.fail(kF[i], "a damping scale factor must not be negative");
    any = any || s[i] != 0.0;
  }
  if (!any) s.fill(1.0);
  return s;
}

// The elements whose kernels add the damping stress (src/elements/beam.cpp): not the trusses
// of *MAT_MUSCLE, whose force is the muscle's own (it has its damping element, DMP).
bool stiffnessDampingRuns(const Model& m, const Part& part) {
  if (part.section == kNone || part.section_kind != SectionKind::Beam) return false;
  if (part.material != kNone && std::holds_alternative<materials::Muscle::Params>(
                                    m.materials[static_cast<std::size_t>(part.material)].law))
    return false;
  const int form = m.beam_sections[static_cast<std::size_t>(part.section)].elform;
  return form == 2 || form == 3;
}

}  // namespace

void readDampingGlobal(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*DAMPING_GLOBAL");
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(spec.card("card 1"));
  MassDamping d;
  d.global = true;
  d.where = c.where();
  // LCID: the damping constant against time; VALDMP is bypassed when LCID is given.
  if (const int64_t lcid = c.integer("LCID"); lcid != 0) {
    d.curve = ctx.curve(c, "LCID", lcid);
    d.value = 1.0;
    if (c.real("VALDMP") != 0)
      ctx.ignore(kw.name, "VALDMP", "bypassed by LCID (Keyword Manual)", c.where());
  } else {
    d.value = c.real("VALDMP");
  }
  if (d.value < 0) c.fail("VALDMP", "the damping constant must not be negative");
  d.scale = scaleFactors(c);
  ctx.model.mass_damping.push_back(std::move(d));
  ctx.collect(cur);
}

namespace {
// The parts of card field `field` (PID or, with _SET, PSID).
std::vector<int32_t> dampedParts(Context& ctx, const Card& c, bool set, const char* field) {
  const int64_t id = c.integer(field);
  if (set) return ctx.partSet(c, field, id);
  return {ctx.part(c, field, id)};
}
}  // namespace

void readDampingPartMass(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const bool set = opts.has("SET");
  const char* field = set ? "PSID" : "PID";
  const auto& spec = keywordSpec(set ? "*DAMPING_PART_MASS_SET" : "*DAMPING_PART_MASS");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec.card("card 1"));
    MassDamping d;
    d.where = c.where();
    const auto parts = dampedParts(ctx, c, set, field);
    d.nodes = parts;  // the parts for now; finishDamping turns them into nodes
    d.curve = ctx.curve(c, "LCID", c.integer("LCID"));
    d.value = c.real("SF");
    const int64_t flag = c.integer("FLAG");
    if (flag != 0 && flag != 1) c.fail("FLAG", "must be 0 or 1");
    if (flag == 1) d.scale = scaleFactors(cur.read(spec.card("card 2")));
    ctx.model.mass_damping.push_back(std::move(d));
    ctx.collect(cur);
  }
}

void readDampingPartStiffness(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const bool set = opts.has("SET");
  const char* field = set ? "PSID" : "PID";
  const auto& spec = keywordSpec(set ? "*DAMPING_PART_STIFFNESS_SET" : "*DAMPING_PART_STIFFNESS");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec.card("card 1"));
    const double coef = c.real("COEF");
    // COEF < 0: |COEF| is the Rayleigh coefficient beta of C = beta K (the LS-DYNA 950
    // formulation, kept under negative COEF since 970 rev. 3510). COEF > 0: LS-DYNA's later
    // formulation, "an approximate fraction of critical damping in the high-frequency domain"
    // (its details are not published): here beta = COEF x the element's stable step, i.e.
    // the fraction COEF of critical damping at the element's highest frequency 2 / dt_e
    // (docs/theory.md, "Damping").
    for (int32_t p : dampedParts(ctx, c, set, field)) {
      Part& part = ctx.model.parts[static_cast<std::size_t>(p)];
      if (coef != 0 && !stiffnessDampingRuns(ctx.model, part))
        ctx.reject(c, field,
                   "part " + std::to_string(part.id) +
                       ": stiffness damping runs on resultant beams and trusses (*SECTION_BEAM "
                       "ELFORM 2, 3; not *MAT_MUSCLE) only, not yet on solids, shells or "
                       "integrated beams");
      part.stiffness_damping = coef < 0 ? -coef : 0.0;
      part.stiffness_fraction = coef > 0 ? coef : 0.0;
    }
    ctx.collect(cur);
  }
}

// A part's mass damping acts on the nodes of its elements. A node shared with elements of
// other parts takes the fraction of its elements that are the parts' (what LS-DYNA does at
// such nodes is not documented; docs/theory.md).
void finishDamping(Context& ctx) {
  Model& m = ctx.model;
  if (m.mass_damping.empty()) return;
  std::vector<int32_t> count(m.nodes.size(), 0);
  const std::size_t ne = m.numElements();
  int32_t nodes[kMaxElementNodes];
  for (std::size_t g = 0; g < ne; ++g) {
    const int k = m.elementNodes(g, nodes);
    for (int a = 0; a < k; ++a) ++count[static_cast<std::size_t>(nodes[a])];
  }
  for (auto& d : m.mass_damping) {
    if (d.global) continue;
    std::vector<char> in_part(m.parts.size(), 0);
    for (int32_t p : d.nodes) in_part[static_cast<std::size_t>(p)] = 1;
    std::vector<int32_t> mine(m.nodes.size(), 0);
    for (std::size_t g = 0; g < ne; ++g) {
      if (!in_part[static_cast<std::size_t>(m.elementPart(g))]) continue;
      const int k = m.elementNodes(g, nodes);
      for (int a = 0; a < k; ++a) ++mine[static_cast<std::size_t>(nodes[a])];
    }
    d.nodes.clear();
    for (std::size_t n = 0; n < mine.size(); ++n) {
      if (mine[n] == 0) continue;
      d.nodes.push_back(static_cast<int32_t>(n));
      d.weight.push_back(double(mine[n]) / double(count[n]));
    }
  }
}

}  // namespace crumple::model::build
