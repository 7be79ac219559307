// Meaning of the structural element keywords: *ELEMENT_SHELL(_THICKNESS), *ELEMENT_BEAM,
// *ELEMENT_DISCRETE, *SECTION_SHELL, *SECTION_BEAM, *SECTION_DISCRETE
// and *CONTROL_SHELL (LS-DYNA Keyword Manual Vol. I and II).
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "model/beam_shapes.hpp"
#include "model/build_context.hpp"
#include "util/error.hpp"

namespace crumple::model::build {

using deck::Card;
using deck::CardCursor;
using deck::keywordSpec;

namespace {

const char* sectionKeyword(SectionKind k) {
  switch (k) {
    case SectionKind::Solid:
      return "*SECTION_SOLID";
    case SectionKind::Shell:
      return "*SECTION_SHELL";
    case SectionKind::Beam:
      return "*SECTION_BEAM";
    case SectionKind::Discrete:
      return "*SECTION_DISCRETE";
    case SectionKind::Sph:
      return "*SECTION_SPH";
  }
  return "*SECTION";
}

// Card 1 of an element keyword: EID, PID and the node fields N1..Nn, found once per keyword
// (not by name per line).
template <int N>
struct ElementSlots {
  deck::FieldSlot eid, pid;
  std::array<deck::FieldSlot, N> nodes;
  ElementSlots(const deck::CardSpec& card, const std::array<std::string_view, N>& names)
      : eid(card.slot("EID")), pid(card.slot("PID")) {
    for (std::size_t i = 0; i < N; ++i) nodes[i] = card.slot(names[i]);
  }
};

// Elements read with EID, PID and n node fields N1..Nn of card 1, in the order `nodes` gives.
template <int N>
Context::ElementInput<N> elementCard(Context& ctx, const Card& c, SectionKind kind,
                                     const ElementSlots<N>& f,
                                     const std::array<deck::FieldSlot, N>& nodes) {
  Context::ElementInput<N> e{positiveId(c, f.eid),
                             ctx.part(c, "PID", c.integer(f.pid)),
                             {},
                             c.fileIndex(),
                             c.lineNumber()};
  ctx.checkPartUsable(c, e.part);
  checkSectionKind(ctx, c, e.part, kind);
  for (std::size_t i = 0; i < N; ++i) {
    const int64_t id = c.integer(nodes[i]);
    if (id == 0) c.fail(nodes[i].name, "node id missing");
    e.nodes[i] = ctx.node(c, nodes[i].name, id);
  }
  return e;
}

}  // namespace

namespace {
// Thick shells keep their *SECTION_TSHELL among the solid sections (model.hpp).
bool thickShellPart(const Context& ctx, const Part& p) {
  return p.section_kind == SectionKind::Solid &&
         isThickShell(ctx.model.solid_sections[std::size_t(p.section)].elform);
}
}  // namespace

bool sectionKindFits(const Context& ctx, std::string_view keyword, int32_t part, SectionKind kind) {
  const Part& p = ctx.model.parts[static_cast<std::size_t>(part)];
  return p.section == kNone ||
         (p.section_kind == kind && thickShellPart(ctx, p) == (keyword == "*ELEMENT_TSHELL"));
}

void checkSectionKind(Context& ctx, const Card& c, int32_t part, SectionKind kind) {
  if (sectionKindFits(ctx, c.keyword().name, part, kind)) return;
  const Part& p = ctx.model.parts[static_cast<std::size_t>(part)];
  const bool tshell_part = thickShellPart(ctx, p);
  const bool tshell_keyword = c.keyword().name == "*ELEMENT_TSHELL";
  c.fail("PID", "part " + std::to_string(p.id) + " has a " +
                    (tshell_part ? "*SECTION_TSHELL" : sectionKeyword(p.section_kind)) +
                    " section, but " + c.keyword().name + " needs a " +
                    (tshell_keyword ? "*SECTION_TSHELL" : sectionKeyword(kind)));
}

namespace {
// A shell needs a thickness: its own (THIC1) or its section's T1.
void checkShellThickness(const Context& ctx, const Card& c, const Context::ElementInput<4>& e) {
  if (e.real[0] > 0) return;
  const Part& p = ctx.model.parts[static_cast<std::size_t>(e.part)];
  if (p.section == kNone || p.section_kind != SectionKind::Shell) return;
  const SectionShell& s = ctx.model.shell_sections[static_cast<std::size_t>(p.section)];
  // 2D solids (ELFORM 13, 15) have no thickness (src/elements/solid2d.hpp).
  if (s.t[0] > 0 || s.elform == 13 || s.elform == 15) return;
  c.fail("EID", "shell " + std::to_string(e.id) + " has no thickness: section " +
                    std::to_string(s.id) + " gives T1 = 0 and the element none (" +
                    "*ELEMENT_SHELL_THICKNESS)");
}
}  // namespace

void readShells(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*ELEMENT_SHELL");
  const auto& card1 = spec.card("card 1");
  const ElementSlots<4> slots(card1, {"N1", "N2", "N3", "N4"});
  // A triangle is written with N4 = N3 or N4 blank (Keyword Manual, *ELEMENT_SHELL).
  const std::array<deck::FieldSlot, 4> tri{slots.nodes[0], slots.nodes[1], slots.nodes[2],
                                           slots.nodes[2]};
  const std::array<deck::FieldSlot, 4> n5_n8{card1.slot("N5"), card1.slot("N6"), card1.slot("N7"),
                                             card1.slot("N8")};
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(card1);
    auto e = elementCard<4>(ctx, c, SectionKind::Shell, slots,
                            c.integer(slots.nodes[3]) == 0 ? tri : slots.nodes);
    for (const auto& n : n5_n8)
      if (c.integer(n) != 0) ctx.reject(c, n.name, "8-node shells are not supported (4-node only)");
    if (opts.has("THICKNESS")) {
      const Card& t = cur.read(spec.card("thickness card"));
      for (int i = 0; i < 4; ++i) {
        const std::string f = "THIC" + std::to_string(i + 1);
        e.real[static_cast<std::size_t>(i)] = t.real(f);
        if (e.real[static_cast<std::size_t>(i)] < 0) t.fail(f, "a thickness must not be negative");
      }
      // Corners left 0 take THIC1; all 0 means the section's thicknesses.
      if (e.real[0] > 0)
        for (auto& th : e.real)
          if (th == 0) th = e.real[0];
      if (t.real("BETA") != 0)
        ctx.ignore(kw.name, "BETA",
                   "the material angle only matters for anisotropic materials, which are not "
                   "supported",
                   t.where());
    }
    checkShellThickness(ctx, c, e);
    ctx.shell_input.push_back(e);
    ctx.collect(cur);
  }
}

namespace {

// Defaults of blank section dimensions (Keyword Manual, *SECTION_BEAM): TS2 = TS1, TT2 = TT1;
// J = ISS + ITT (thin section), SA = A.
void completeBeamSection(SectionBeam& s) {
  if (s.ts2 <= 0) s.ts2 = s.ts1;
  if (s.tt2 <= 0) s.tt2 = s.tt1;
  if (s.j <= 0) s.j = s.iss + s.itt;
  if (s.sa <= 0) s.sa = s.a;
}

// The *INTEGRATION_BEAM a section names (QR/IRID = -irid).
int32_t beamIntegration(Context& ctx, const Card& c, int64_t irid) {
  const auto& rules = ctx.model.beam_integrations;
  for (std::size_t k = 0; k < rules.size(); ++k)
    if (rules[k].id == irid) return static_cast<int32_t>(k);
  c.fail("QR/IRID", "no *INTEGRATION_BEAM with IRID " + std::to_string(irid));
}

// The dimensions a beam runs with must be positive: checked per element, since a section may
// leave them to *ELEMENT_BEAM_THICKNESS (pre-processors write them per element). A standard
// shape of *INTEGRATION_BEAM brings its own.
void checkBeamSection(const Model& m, const Card& c, const SectionBeam& s, int64_t eid) {
  auto need = [&](double value, const char* what) {
    if (value > 0) return;
    c.fail("EID", "beam " + std::to_string(eid) + " has no " + what + ": section " +
                      std::to_string(s.id) + " gives none and the element none " +
                      "(*ELEMENT_BEAM_THICKNESS)");
  };
  if (s.elform == 1 || s.elform == 9) {
    if (s.integration != kNone && !m.beam_integrations[std::size_t(s.integration)].normalized)
      return;
    need(s.ts1, "thickness TS1");
    if (s.cst == 0) need(s.tt1, "thickness TT1");
    return;
  }
  need(s.a, "area A");
  if (s.elform != 2) return;
  need(s.iss, "moment of inertia ISS");
  need(s.itt, "moment of inertia ITT");
}

// *ELEMENT_BEAM_THICKNESS card 2: PARM1-5 by ELFORM (Keyword Manual, *ELEMENT_BEAM): 1 and 9
// TS1 TS2 TT1 TT2; 2 A ISS ITT IRR (J) SA; 3 A. A field left 0 keeps the section's value.
std::array<double, 5> elementDimensions(const Card& t) {
  std::array<double, 5> p{};
  for (std::size_t i = 0; i < 5; ++i) {
    const std::string f = "PARM" + std::to_string(i + 1);
    p[i] = t.real(f);
    if (p[i] < 0) t.fail(f, "a section dimension must not be negative");
  }
  return p;
}

// The section of an element with its own dimensions p (all 0: the section's) and end
// releases (elements/beam_release.hpp's bits): a copy of its part's section. Elements with
// the same share one (blocks are per section).
using ElementSections = std::map<std::tuple<int32_t, std::array<double, 5>, int>, int32_t>;
int32_t elementSection(Context& ctx, const util::SourceLoc& where, int32_t section,
                       const std::array<double, 5>& p, int release, ElementSections& made) {
  const auto key = std::make_tuple(section, p, release);
  if (const auto it = made.find(key); it != made.end()) return it->second;
  SectionBeam s = ctx.model.beam_sections[static_cast<std::size_t>(section)];
  s.release = release;
  auto put = [&](double& field, double value) {
    if (value > 0) field = value;
  };
  if (s.elform == 1 || s.elform == 9) {
    put(s.ts1, p[0]);
    put(s.ts2, p[1]);
    put(s.tt1, p[2]);
    put(s.tt2, p[3]);
  } else {
    put(s.a, p[0]);
    if (s.elform == 2) {
      put(s.iss, p[1]);
      put(s.itt, p[2]);
      put(s.j, p[3]);
      put(s.sa, p[4]);
    }
  }
  completeBeamSection(s);
  s.where = where;
  const auto index = static_cast<int32_t>(ctx.model.beam_sections.size());
  ctx.model.beam_sections.push_back(s);
  made.emplace(key, index);
  return index;
}

// RT1 RR1 RT2 RR2 (Keyword Manual, *ELEMENT_BEAM: 0 none, 1 x, 2 y, 3 z, 4 xy, 5 yz, 6 zx, 7
// all) as elements/beam_release.hpp's bits, in the element's axes (LOCAL 2, the default; LOCAL 1,
// global axes, is refused when an end is released). The corotational beams (ELFORM 1, 2) take
// them; the manual gives them no meaning for the spot weld beam (9), nor have they one for a
// truss (3).
int beamReleases(Context& ctx, const Card& c, const std::array<deck::FieldSlot, 4>& codes,
                 const deck::FieldSlot& local, int32_t section) {
  std::array<int64_t, 4> v{};
  for (std::size_t i = 0; i < 4; ++i) {
    v[i] = c.integer(codes[i]);
    if (v[i] < 0 || v[i] > 7) c.fail(codes[i].name, "must be 0 to 7");
  }
  const int64_t system = c.integer(local);
  if (system != 0 && system != 1 && system != 2) c.fail(local.name, "must be 1 or 2");
  if (std::all_of(v.begin(), v.end(), [](int64_t x) { return x == 0; })) return 0;
  if (system == 1) {
    ctx.reject(c, local.name, "end releases in global axes (LOCAL 1) are not supported");
    return 0;
  }
  if (section != kNone) {
    const int elform = ctx.model.beam_sections[static_cast<std::size_t>(section)].elform;
    if (elform != 1 && elform != 2) {
      const std::size_t first = v[0] != 0 ? 0 : v[1] != 0 ? 1 : v[2] != 0 ? 2 : 3;
      ctx.reject(c, codes[first].name,
                 "end releases apply to ELFORM 1 and 2 beams (the part's section has ELFORM " +
                     std::to_string(elform) + ")");
      return 0;
    }
  }
  // Codes to axis bits (x 1, y 2, z 4); translations then rotations, six bits per end.
  static constexpr int kAxes[8] = {0, 1, 2, 4, 3, 6, 5, 7};
  auto end = [&](std::size_t rt, std::size_t rr) { return kAxes[v[rt]] | (kAxes[v[rr]] << 3); };
  return end(0, 1) | (end(2, 3) << 6);
}

}  // namespace

void readBeams(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*ELEMENT_BEAM");
  const auto& card1 = spec.card("card 1");
  const ElementSlots<2> slots(card1, {"N1", "N2"});
  const deck::FieldSlot n3_slot = card1.slot("N3"), local = card1.slot("LOCAL");
  const std::array<deck::FieldSlot, 4> releases{card1.slot("RT1"), card1.slot("RR1"),
                                                card1.slot("RT2"), card1.slot("RR2")};
  ElementSections made;
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(card1);
    auto e = elementCard<2>(ctx, c, SectionKind::Beam, slots, slots.nodes);
    if (e.nodes[0] == e.nodes[1]) c.fail("N2", "a beam needs two distinct nodes");
    if (const int64_t n3 = c.integer(n3_slot); n3 != 0) e.aux = ctx.node(c, "N3", n3);
    const int32_t section = ctx.model.parts[static_cast<std::size_t>(e.part)].section;
    const int release = beamReleases(ctx, c, releases, local, section);
    if (opts.has("THICKNESS") || release != 0) {
      std::array<double, 5> dims{};
      util::SourceLoc where = c.where();
      if (opts.has("THICKNESS")) {
        const Card& t = cur.read(spec.card("thickness card"));
        dims = elementDimensions(t);
        where = t.where();
      }
      if (section != kNone) e.section = elementSection(ctx, where, section, dims, release, made);
    }
    if (section != kNone) {
      const auto s = static_cast<std::size_t>(e.section != kNone ? e.section : section);
      checkBeamSection(ctx.model, c, ctx.model.beam_sections[s], e.id);
    }
    ctx.beam_input.push_back(e);
    ctx.collect(cur);
  }
}

void readDiscretes(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*ELEMENT_DISCRETE");
  const auto& card1 = spec.card("card 1");
  const ElementSlots<2> slots(card1, {"N1", "N2"});
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(card1);
    auto e = elementCard<2>(ctx, c, SectionKind::Discrete, slots, slots.nodes);
    if (e.nodes[0] == e.nodes[1]) c.fail("N2", "a discrete element needs two distinct nodes");
    if (c.integer("VID") != 0)
      ctx.reject(c, "VID", "orientation vectors (*DEFINE_SD_ORIENTATION) are not supported");
    c.integer("PF");
    e.real[0] = c.real("S");
    e.real[1] = c.real("OFFSET");
    ctx.discrete_input.push_back(e);
    ctx.collect(cur);
  }
}

namespace {

// QR/IRID (Keyword Manual, *SECTION_SHELL): 0 Gauss (Lobatto with *CONTROL_SHELL INTGRD 1),
// < 0 the *INTEGRATION_SHELL rule -QR/IRID, which gives the number of points (NIP is then
// ignored, as the manual says); the built-in rules QR > 0 are refused.
// *SECTION_TSHELL's QR reads the same (field `qr_field`).
template <class Section>
void readShellRule(Context& ctx, const Card& c, std::string_view qr_field, Section& s) {
  const int64_t qr = c.integer(qr_field);
  if (qr > 0) {
    ctx.reject(c, qr_field, "of the quadrature rules only 0 (Gauss) and < 0 (*INTEGRATION_SHELL)");
    return;
  }
  if (qr == 0) return;
  const auto rule = ctx.shell_rules.find(-qr);
  if (rule == ctx.shell_rules.end())
    c.fail(qr_field, "no *INTEGRATION_SHELL with IRID " + std::to_string(-qr));
  s.zeta = rule->second.zeta;
  s.weight = rule->second.weight;
  s.nip = static_cast<int>(s.zeta.size());
}

// One *INTEGRATION_SHELL rule's points: as given (ESOP 0; S in [-1, 1], WF the fraction of
// the thickness, the fractions summing to 1), or NIPTS layers of equal thickness (ESOP 1:
// the point cards, if any, only name PIDs; a keyword whose ESOP 1 rule has none holds no
// other rule after it).
Context::ShellRule readShellPoints(Context& ctx, CardCursor& cur, const deck::KeywordSpec& spec,
                                   const Card& c, int64_t nipts, bool equal) {
  Context::ShellRule r;
  double total = 0.0;
  for (int64_t k = 0; k < nipts; ++k) {
    const bool card = !equal || !cur.atEnd();
    if (card) {
      const Card& p = cur.read(spec.card("point card"));
      if (p.integer("PID") != 0)
        ctx.reject(p, "PID", "a material per integration point (layered shells) is not supported");
      if (!equal) {
        if (!(std::abs(p.real("S")) <= 1.0)) p.fail("S", "the point must lie in [-1, 1]");
        if (!(p.real("WF") > 0)) p.fail("WF", "the weighting factor must be positive");
        r.zeta.push_back(p.real("S"));
        r.weight.push_back(p.real("WF"));
        total += p.real("WF");
        continue;
      }
    }
    r.zeta.push_back(-1.0 + (2.0 * double(k) + 1.0) / double(nipts));
    r.weight.push_back(1.0 / double(nipts));
  }
  if (!equal && std::abs(total - 1.0) > 1e-3)
    c.fail("NIPTS", "the weighting factors WF sum to " + std::to_string(total) +
                        ", not 1 (each is the fraction of the thickness at its point)");
  return r;
}

// ICOMP (Keyword Manual, *SECTION_SHELL): 1 reads the material angle of every integration
// point, B1..B8 a card after card 2, as many cards as NIP needs (the rule's points with
// QR/IRID < 0). An isotropic law ignores the angles; an orthotropic one turns its axes by them.
void readPlyAngles(CardCursor& cur, const deck::KeywordSpec& spec, const Card& c, SectionShell& s,
                   bool planar) {
  const int64_t icomp = c.integer("ICOMP");
  if (icomp == 0) return;
  if (icomp != 1) c.fail("ICOMP", "must be 0 or 1 (layered: an angle per integration point)");
  if (planar) c.fail("ICOMP", "a 2D solid (ELFORM 13, 15) has no layers");
  for (int k = 0; k < s.nip; k += 8) {
    if (cur.atEnd())
      c.fail("ICOMP", "ICOMP 1 needs " + std::to_string(s.nip) +
                          " angles B1.. (NIP), on cards after card 2; the keyword ends first");
    const Card& a = cur.read(spec.card("angle card"));
    for (int j = 0; j < 8 && k + j < s.nip; ++j)
      s.ply_angle.push_back(a.real("B" + std::to_string(j + 1)));
  }
}

}  // namespace

void readIntegrationShell(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*INTEGRATION_SHELL");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec.card("card 1"));
    const int64_t irid = positiveId(c, "IRID"), nipts = c.integer("NIPTS");
    if (nipts < 1 || nipts > 10) c.fail("NIPTS", "give 1 to 10 points (as NIP)");
    const int64_t esop = c.integer("ESOP");
    if (esop != 0 && esop != 1) c.fail("ESOP", "must be 0 (points given) or 1 (equal layers)");
    if (c.integer("FAILOPT") != 0)
      ctx.ignore(kw.name, "FAILOPT", "failure across layers of different materials (PID)",
                 c.where());
    auto rule = readShellPoints(ctx, cur, spec, c, nipts, esop == 1);
    if (!ctx.shell_rules.emplace(irid, std::move(rule)).second)
      c.fail("IRID", "*INTEGRATION_SHELL " + std::to_string(irid) + " is already defined");
    ctx.collect(cur);
  }
}

void readSectionShell(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*SECTION_SHELL");
  CardCursor cur(kw, ctx.deck);
  while (nextRecord(cur, opts.has("TITLE"))) {
    readTitleCard(cur, spec, opts);
    const Card& c = cur.read(spec.card("card 1"));
    const Card& c2 = cur.read(spec.card("card 2"));
    SectionShell s;
    s.id = positiveId(c, "SECID");
    s.where = c.where();
    const auto elform = c.integer("ELFORM");
    // ELFORM (Keyword Manual, *SECTION_SHELL): 2 Belytschko-Tsay, 4 C0 triangle, 10
    // Belytschko-Wong-Chiang (BT with the warping correction), 16 fully integrated; the 2D
    // solids 13 (plane strain) and 15 (axisymmetric, volume weighted; src/elements/solid2d.hpp).
    // Others (14, the area-weighted axisymmetric form, among them) are refused on use.
    const bool planar = elform == 13 || elform == 15;
    if (elform != 2 && elform != 4 && elform != 10 && elform != 16 && !planar) {
      ctx.define(Kind::Section, s.id, c, "SECID");
      ctx.defineUnsupported(Kind::Section, s.id, kw.name + " ELFORM=" + std::to_string(elform),
                            c.where());
      ctx.reportUnsupported(kw,
                            "ELFORM " + std::to_string(elform) +
                                " not supported (2, 4, 10, 16 and the 2D solids 13 and 15 are)",
                            false);
      ctx.collect(cur);
      continue;
    }
    s.elform = static_cast<int>(elform);
    s.shrf = c.real("SHRF");
    if (!(s.shrf > 0)) c.fail("SHRF", "the shear factor must be positive");
    const int64_t nip = planar ? 1 : c.integer("NIP");
    if (nip < 1 || nip > 10) c.fail("NIP", "must be 1 to 10 through-thickness points");
    s.nip = static_cast<int>(nip);
    c.real("PROPT");  // printout only
    readShellRule(ctx, c, "QR/IRID", s);
    c.integer("SETYP");
    for (int i = 0; i < 4; ++i) {
      const std::string f = "T" + std::to_string(i + 1);
      s.t[static_cast<std::size_t>(i)] = c2.real(f);
    }
    readPlyAngles(cur, spec, c, s, planar);
    // T1 = 0 is valid when the elements give their own thickness (*ELEMENT_SHELL_THICKNESS,
    // as pre-processors write per-element thickness): checked per element.
    if (!(s.t[0] >= 0)) c2.fail("T1", "the shell thickness must not be negative");
    for (auto& t : s.t)
      if (t <= 0) t = s.t[0];
    // A 2D solid has no thickness: plane strain is per unit depth, the axisymmetric element per
    // radian (src/elements/solid2d.hpp).
    if (planar && s.t[0] != 0.0 && s.t[0] != 1.0)
      ctx.ignore(kw.name, "T1",
                 "2D solids (ELFORM 13, 15) have no thickness: masses and forces are per unit "
                 "depth (13) or per radian (15)",
                 c2.where());
    if (c2.real("NLOC") != 0 && planar)
      ctx.ignore(kw.name, "NLOC", "a 2D solid (ELFORM 13, 15) has no reference surface",
                 c2.where());
    else if (c2.real("NLOC") != 0)
      ctx.reject(c2, "NLOC", "reference surfaces off the mid-surface are not supported");
    ctx.define(Kind::Section, s.id, c, "SECID");
    ctx.model.shell_sections.push_back(s);
    ctx.collect(cur);
  }
}

namespace {

// ICOMP = 1: the layer angles B1..B(NIP), eight to a card. Zero angles change nothing for the
// isotropic laws thick shells run, so they are read and noted; others are refused.
void readTShellAngles(Context& ctx, CardCursor& cur, const deck::KeywordSpec& spec, const Card& c,
                      int nip) {
  for (int k = 0; k < nip; k += 8) {
    if (cur.atEnd()) c.fail("ICOMP", "ICOMP = 1 needs the angle cards B1..B" + std::to_string(nip));
    const Card& a = cur.read(spec.card("angle card"));
    for (int i = k; i < std::min(nip, k + 8); ++i) {
      const std::string f = "B" + std::to_string(i - k + 1);
      if (a.real(f) != 0.0)
        ctx.reject(a, f, "layer angles (composite thick shells, ICOMP = 1) other than 0");
    }
  }
  ctx.ignore("*SECTION_TSHELL", "ICOMP",
             "ICOMP = 1 with every angle 0 runs as ICOMP = 0 (the material axes are the element's)",
             c.where());
}

}  // namespace

// *SECTION_TSHELL (Keyword Manual vol. I): ELFORM 1 (one point in the plane, NIP through the
// thickness, hourglass control) and 2 (selective reduced, 2 x 2 points in the plane; both
// src/elements/tshell.hpp) run; the others are refused when an element uses the section. Kept
// among the solid sections (model.hpp, kThickShellOnePoint, kThickShellSelective).
void readSectionTShell(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*SECTION_TSHELL");
  CardCursor cur(kw, ctx.deck);
  while (nextRecord(cur, opts.has("TITLE"))) {
    readTitleCard(cur, spec, opts);
    const Card& c = cur.read(spec.card("card 1"));
    SectionSolid s;
    s.id = positiveId(c, "SECID");
    s.where = c.where();
    const int64_t nip = c.integer("NIP");
    if (nip < 1 || nip > 10) c.fail("NIP", "must be 1 to 10 through-thickness points");
    s.nip = static_cast<int>(nip);
    const int64_t icomp = c.integer("ICOMP");
    if (icomp != 0 && icomp != 1) c.fail("ICOMP", "must be 0 or 1");
    if (icomp == 1) readTShellAngles(ctx, cur, spec, c, s.nip);
    const auto elform = c.integer("ELFORM");
    ctx.define(Kind::Section, s.id, c, "SECID");
    if (elform != 1 && elform != 2) {
      ctx.defineUnsupported(Kind::Section, s.id, kw.name + " ELFORM=" + std::to_string(elform),
                            c.where());
      ctx.reportUnsupported(kw,
                            "ELFORM " + std::to_string(elform) +
                                " not supported yet (ELFORM 1, one point in the plane, and 2, "
                                "selective reduced 2 x 2, are)",
                            false);
      ctx.collect(cur);
      continue;
    }
    s.elform = elform == 2 ? kThickShellSelective : kThickShellOnePoint;
    s.shrf = c.real("SHRF");
    if (!(s.shrf > 0)) c.fail("SHRF", "the shear factor must be positive");
    c.real("PROPT");  // printout only
    readShellRule(ctx, c, "QR", s);
    // One point through the thickness leaves the element's bending modes free.
    if (s.nip < 2)
      c.fail(s.zeta.empty() ? "NIP" : "QR",
             "a thick shell (ELFORM 1 or 2) needs at least 2 points through the thickness");
    if (c.integer("TSHEAR") != 0)
      ctx.reject(c, "TSHEAR", "the parabolic transverse shear (TSHEAR = 1); 0 is supported");
    ctx.model.solid_sections.push_back(s);
    ctx.collect(cur);
  }
}

// *ELEMENT_TSHELL: EID PID N1..N8, stored with the solids (their ids share the solids' id
// space here). Degenerate (prism) thick shells are refused.
void readTShells(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*ELEMENT_TSHELL");
  const auto& card1 = spec.card("card 1");
  const ElementSlots<8> slots(card1, {"N1", "N2", "N3", "N4", "N5", "N6", "N7", "N8"});
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(card1);
    auto e = elementCard<8>(ctx, c, SectionKind::Solid, slots, slots.nodes);
    for (std::size_t i = 0; i < 8; ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (e.nodes[i] == e.nodes[j])
          c.fail(slots.nodes[i].name,
                 "degenerate thick shells (prisms: N3 = N4 and N7 = N8) are not supported: " +
                     std::string(slots.nodes[i].name) + " repeats " +
                     std::string(slots.nodes[j].name) + " (give 8 distinct nodes)");
    ctx.solid_input.push_back(e);
    ctx.collect(cur);
  }
}

void readSectionBeam(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*SECTION_BEAM");
  CardCursor cur(kw, ctx.deck);
  while (nextRecord(cur, opts.has("TITLE"))) {
    readTitleCard(cur, spec, opts);
    const Card& c = cur.read(spec.card("card 1"));
    SectionBeam s;
    s.id = positiveId(c, "SECID");
    s.where = c.where();
    const auto elform = c.integer("ELFORM");
    if ((elform < 1 || elform > 3) && elform != 9) {
      // The second card's layout depends on ELFORM; skip it with the definition.
      if (!cur.atEnd()) cur.read(spec.card("resultant card"));
      ctx.define(Kind::Section, s.id, c, "SECID");
      ctx.defineUnsupported(Kind::Section, s.id, kw.name + " ELFORM=" + std::to_string(elform),
                            c.where());
      ctx.reportUnsupported(
          kw,
          "ELFORM " + std::to_string(elform) +
              " not supported (1 Hughes-Liu, 2 resultant, 3 truss, 9 spot weld are)",
          false);
      ctx.collect(cur);
      continue;
    }
    s.elform = static_cast<int>(elform);
    s.shrf = c.real("SHRF");
    s.qr = static_cast<int>(c.integer("QR/IRID"));
    s.cst = static_cast<int>(c.integer("CST"));
    if (c.real("SCOOR") != 0)
      ctx.reject(c, "SCOOR", "offset beam reference axes (SCOOR) are not supported");
    if (c.real("NSM") != 0) ctx.reject(c, "NSM", "non-structural mass is not supported");
    // ELFORM 9, the spot-weld beam, takes the integrated beam's section card (CST 0 rectangle
    // TS x TT, 1 circle of outer diameter TS and inner TT; Keyword Manual *SECTION_BEAM).
    if (s.elform == 1 || s.elform == 9) {
      const Card& c2 = cur.read(spec.card("integrated card"));
      if (s.cst != 0 && s.cst != 1)
        ctx.reject(c, "CST", "only rectangular (0) and tubular (1) cross-sections are supported");
      if (s.qr < 0) {
        s.integration = beamIntegration(ctx, c, -s.qr);
      } else if (s.qr < 1 || s.qr > 5) {
        ctx.reject(c, "QR/IRID", "the built-in rules are 1 to 5 (and IRID < 0 a user rule)");
      }
      s.ts1 = c2.real("TS1");
      s.ts2 = c2.real("TS2");
      s.tt1 = c2.real("TT1");
      s.tt2 = c2.real("TT2");
      // Zero dimensions may come per element (*ELEMENT_BEAM_THICKNESS): checked per element.
      for (auto f : {"TS1", "TT1"})
        if (c2.real(f) < 0) c2.fail(f, "the section dimension must not be negative");
      if (c2.real("NSLOC") != 0 || c2.real("NTLOC") != 0)
        ctx.reject(c2, c2.real("NSLOC") != 0 ? "NSLOC" : "NTLOC",
                   "offset reference axes are not supported");
    } else {
      const Card& c2 = cur.read(spec.card("resultant card"));
      s.a = c2.real("A");
      if (s.elform == 2) {
        s.iss = c2.real("ISS");
        s.itt = c2.real("ITT");
        s.j = c2.real("J");
        s.sa = c2.real("SA");
      }
      for (auto f : {"A", "ISS", "ITT"})
        if (c2.real(f) < 0) c2.fail(f, "the section property must not be negative");
      c2.real("IST");
    }
    completeBeamSection(s);
    ctx.define(Kind::Section, s.id, c, "SECID");
    ctx.model.beam_sections.push_back(s);
    ctx.collect(cur);
  }
}

void readIntegrationBeam(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*INTEGRATION_BEAM");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec.card("card 1"));
    BeamIntegration r;
    r.id = positiveId(c, "IRID");
    r.where = c.where();
    const int64_t nip = c.integer("NIP"), icst = c.integer("ICST");
    r.ra = c.real("RA");
    if (icst > 0) {
      const Card& c2 = cur.read(spec.card("card 2"));
      if (c2.real("SREF") != 0 || c2.real("TREF") != 0)
        ctx.reject(c2, c2.real("SREF") != 0 ? "SREF" : "TREF",
                   "offset reference axes of a standard section are not supported");
      if (icst != 1) {
        ctx.reject(c, "ICST", "of the standard sections only ICST 1 (W section) is supported");
      } else {
        std::array<double, 6> d{};
        for (std::size_t k = 0; k < 6; ++k) d[k] = c2.real("D" + std::to_string(k + 1));
        std::string error;
        r.points = wSectionPoints(d, error);
        if (r.points.empty()) c2.fail("D1", error);
      }
      if (c.integer("K") != 0)
        ctx.ignore(kw.name, "K",
                   "a standard section is integrated with Crumple's own exact rule "
                   "(model/beam_shapes.hpp)",
                   c.where());
    } else {
      if (nip < 1 || nip > 32) c.fail("NIP", "give 1 to 32 user integration points");
      if (!(r.ra > 0)) c.fail("RA", "the relative area of user points must be positive");
      r.normalized = true;
      for (int64_t k = 0; k < nip; ++k) {
        const Card& p = cur.read(spec.card("point card"));
        if (p.integer("PID") != 0)
          ctx.reject(p, "PID", "a material per integration point is not supported");
        if (!(p.real("WF") > 0)) p.fail("WF", "the weighting factor must be positive");
        r.points.push_back({p.real("S"), p.real("T"), p.real("WF")});
      }
    }
    ctx.model.beam_integrations.push_back(r);
    ctx.collect(cur);
  }
}

void readSectionDiscrete(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*SECTION_DISCRETE");
  CardCursor cur(kw, ctx.deck);
  while (nextRecord(cur, opts.has("TITLE"))) {
    readTitleCard(cur, spec, opts);
    const Card& c = cur.read(spec.card("card 1"));
    const Card& c2 = cur.readOptional(spec.card("card 2"));
    SectionDiscrete s;
    s.id = positiveId(c, "SECID");
    s.where = c.where();
    s.dro = static_cast<int>(c.integer("DRO"));
    if (s.dro != 0)
      ctx.reject(c, "DRO", "torsional (rotational) discrete elements are not supported");
    for (auto f : {"KD", "V0", "CL", "FD"})
      if (c.real(f) != 0)
        ctx.reject(c, f,
                   "dynamic magnification, clearance and failure of springs are not supported");
    for (auto f : {"CDL", "TDL"})
      if (c2.real(f) != 0) ctx.reject(c2, f, "deflection limits of springs are not supported");
    ctx.define(Kind::Section, s.id, c, "SECID");
    ctx.model.discrete_sections.push_back(s);
    ctx.collect(cur);
  }
}

void readControlShell(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*CONTROL_SHELL");
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(spec.card("card 1"));
  const Card& c2 = cur.readOptional(spec.card("card 2"));
  auto& ctl = ctx.model.controls;
  c.real("WRPANG");  // warping angle for a warning only
  c.integer("IRNXX");
  c.integer("THEORY");  // the section's ELFORM is used; blank ELFORM gives 2 as THEORY does
  c.integer("MITER");   // the plane-stress return is always iterated to sigma_zz = 0
  c.integer("PROJ");
  // ESORT: degenerate quadrilaterals always run as C0 triangles (as ESORT = 1).
  c.integer("ESORT");
  ctl.shell_thickness_update = c.integer("ISTUPD") != 0;
  const int64_t bwc = c.integer("BWC");
  if (bwc != 1 && bwc != 2) c.fail("BWC", "must be 1 (warping correction) or 2 (none)");
  ctl.shell_bwc = bwc == 1;
  const int64_t intgrd = c2.integer("INTGRD");
  if (intgrd != 0 && intgrd != 1) c2.fail("INTGRD", "must be 0 (Gauss) or 1 (Lobatto)");
  ctl.shell_lobatto = intgrd == 1;
  if (c2.real("ROTASCL") != 1.0)
    ctx.ignore(kw.name, "ROTASCL",
               "the rotary inertia of shells is the element's own (Belytschko-Tsay scaling)",
               c2.where());
  // Cards 3 to 5 hold, among others, the shell failure and deletion settings (NFAIL1, NFAIL4,
  // PSNFAIL, DELFR): none is acted on, which a user relying on them must learn.
  ctx.collect(cur);
  cur.skipBlankLines();
  if (!cur.atEnd())
    ctx.ignore(kw.name, "cards 3-5",
               "not read: failure and deletion settings (NFAIL1, NFAIL4, ...) are not honoured",
               ctx.deck.loc(cur.peek()));
}

}  // namespace crumple::model::build
