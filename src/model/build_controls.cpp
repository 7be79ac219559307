// Meaning of *TITLE, the *CONTROL_ keywords and the *DATABASE_ output requests Crumple
// honours (LS-DYNA Keyword Manual Vol. I). Keywords read only so that their non-default
// fields can be reported go through readIgnoredControl.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "model/build_context.hpp"
#include "model/units.hpp"
#include "util/vec3.hpp"

namespace crumple::model::build {

namespace {
using deck::Card;
using deck::CardCursor;
using deck::keywordSpec;
}  // namespace

void readTitle(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(keywordSpec("*TITLE").card("card 1"));
  // The first *TITLE wins; a deck has one (case-specific ones are skipped by the reader).
  if (ctx.model.title.empty()) ctx.model.title = c.text("TITLE");
  ctx.collect(cur);
}

void readControlTermination(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(keywordSpec("*CONTROL_TERMINATION").card("card 1"));
  Controls& k = ctx.model.controls;
  k.end_time = c.real("ENDTIM");
  if (k.end_time < 0) c.fail("ENDTIM", "must not be negative");
  k.end_cycle = c.integer("ENDCYC");
  k.dt_min_ratio = c.real("DTMIN");
  // ENDMAS defaults to 1e8 (%), i.e. no check; Controls keeps 0 for "none".
  const double endmas = c.real("ENDMAS");
  k.end_mass_ratio = endmas >= 1e8 ? 0.0 : endmas;
  ctx.collect(cur);
}

// *CONTROL_IMPLICIT_GENERAL IMFLAG (Keyword Manual): anything but 0 asks for an implicit
// (static or dynamic) solution, which an explicit code cannot give: refused with the reason,
// or with ReadOptions::implicit_as_explicit run explicitly and said so.
void readControlImplicitGeneral(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(keywordSpec("*CONTROL_IMPLICIT_GENERAL").card("card 1"));
  if (const int64_t imflag = c.integer("IMFLAG"); imflag != 0) {
    const std::string what = "IMFLAG " + std::to_string(imflag) +
                             " asks for an implicit analysis; Crumple is explicit only";
    if (ctx.options.implicit_as_explicit)
      ctx.ignore(kw.name, "IMFLAG", what + ": run explicitly (--implicit-as-explicit)", c.where());
    else
      ctx.reject(c, "IMFLAG",
                 what + " (--implicit-as-explicit runs it explicitly; the answer will differ)",
                 "implicit analysis");
  }
  ctx.collect(cur);
}

// *CONTROL_DYNAMIC_RELAXATION (and its old name *CONTROL_DAMPING; Keyword Manual vol. I):
// IDRFLG 1 (and -1, whose extra time-history output during the phase Crumple does not write)
// runs the relaxation phase, 0 runs it when a curve has SIDR 1 or 2, -999 never; the other
// values (initialisation to a prescribed geometry, implicit relaxation) are refused, as is the
// automatic control of IRELAL = 1. NRCYCK, DRTOL, DRFCTR: 0 is the default; DRTERM 0 = none;
// TSSFDR 0 = TSSFAC.
void readControlDynamicRelaxation(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(keywordSpec(kw.name).card("card 1"));
  auto& dr = ctx.model.controls.relaxation;
  dr.idrflg = c.integer("IDRFLG");
  if (dr.idrflg == -1)
    ctx.ignore(kw.name, "IDRFLG",
               "-1: the relaxation runs as with 1, without time-history output during it",
               c.where());
  else if (dr.idrflg != 0 && dr.idrflg != 1 && dr.idrflg != -999)
    ctx.reject(c, "IDRFLG",
               "IDRFLG " + std::to_string(dr.idrflg) +
                   ": only explicit dynamic relaxation (IDRFLG 0, 1, -1, -999) is supported",
               "dynamic relaxation IDRFLG " + std::to_string(dr.idrflg));
  if (c.integer("IRELAL") != 0)
    ctx.reject(c, "IRELAL",
               "IRELAL " + std::to_string(c.integer("IRELAL")) +
                   ": the automatic relaxation control (Papadrakakis) is not supported",
               "dynamic relaxation IRELAL");
  dr.nrcyck = c.integer("NRCYCK");
  if (dr.nrcyck <= 0) c.fail("NRCYCK", "must be positive");
  dr.drtol = c.real("DRTOL");
  if (!(dr.drtol > 0.0 && dr.drtol < 1.0)) c.fail("DRTOL", "must lie in (0, 1)");
  dr.drfctr = c.real("DRFCTR");
  if (!(dr.drfctr > 0.0 && dr.drfctr <= 1.0)) c.fail("DRFCTR", "must lie in (0, 1]");
  dr.drterm = c.real("DRTERM");
  if (dr.drterm < 0.0) c.fail("DRTERM", "must not be negative");
  dr.tssfdr = c.real("TSSFDR");
  if (dr.tssfdr < 0.0) c.fail("TSSFDR", "must not be negative");
  ctx.collect(cur);
}

// *CONTROL_UNITS (Keyword Manual vol. I): the units the deck is written in. The solution does
// not depend on them; they label the outputs (model/units.hpp). Blank fields are the manual's
// defaults (m, sec, kg).
void readControlUnits(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(keywordSpec("*CONTROL_UNITS").card("card 1"));
  auto word = [&c](std::string_view field, std::string_view blank) {
    std::string w = c.text(field);
    std::transform(w.begin(), w.end(), w.begin(),
                   [](unsigned char ch) { return std::tolower(ch); });
    return w.empty() ? std::string(blank) : w;
  };
  const std::string length = word("LENGTH", "m"), time = word("TIME", "sec"),
                    mass = word("MASS", "kg");
  if (const NamedUnits* u = unitSystemOf(length, time, mass))
    ctx.model.units = {std::string(u->name), "*CONTROL_UNITS at " + c.where().str()};
  else
    ctx.ignore(
        kw.name, "LENGTH",
        "LENGTH " + length + ", TIME " + time + ", MASS " + mass +
            " is not a consistent system Crumple names: the units are inferred from the metals",
        c.where());
  ctx.collect(cur);
}

// *CONTROL_SOLUTION SOLN: 0 structural; 1 thermal only, 2 coupled thermal-structural.
void readControlSolution(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(keywordSpec("*CONTROL_SOLUTION").card("card 1"));
  if (const int64_t soln = c.integer("SOLN"); soln != 0)
    ctx.reject(c, "SOLN",
               "SOLN " + std::to_string(soln) +
                   " asks for a thermal analysis; thermal analysis is out of scope",
               "thermal analysis");
  ctx.collect(cur);
}

void readControlTimestep(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*CONTROL_TIMESTEP");
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(spec.card("card 1"));
  cur.readOptional(spec.card("card 2"));
  Controls& k = ctx.model.controls;
  k.dt_init = c.real("DTINIT");
  k.tssfac = c.real("TSSFAC");
  if (!(k.tssfac > 0)) c.fail("TSSFAC", "must be positive");
  // The Keyword Manual sets no upper bound: above 1 the step exceeds the elements' own
  // estimates, which can be right when lumped masses (*ELEMENT_MASS) dominate and wrong
  // otherwise. Run as asked, and said.
  if (k.tssfac > 1)
    ctx.ignore(kw.name, "TSSFAC",
               "above 1: the step exceeds the element stability estimates (run as given; an "
               "unstable run ends on a non-finite velocity)",
               c.where());
  k.dt2ms = c.real("DT2MS");
  if (const int64_t lctm = c.integer("LCTM"); lctm != 0)
    k.dt_max_curve = ctx.curve(c, "LCTM", lctm);
  ctx.erode_flag = c.integer("ERODE");
  ctx.collect(cur);
}

void readControlHourglass(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(keywordSpec("*CONTROL_HOURGLASS").card("card 1"));
  Controls& k = ctx.model.controls;
  const int64_t ihq = c.integer("IHQ");
  if (!isSupportedIhq(ihq))
    ctx.reject(c, "IHQ", "IHQ " + std::to_string(ihq) + " is not supported (1 to 5 and 8 are)");
  else
    k.hourglass_ihq = static_cast<int>(ihq);
  ctx.ihq8_control = ihq == 8 ? &kw : nullptr;
  k.hourglass_qh = c.real("QH");
  if (k.hourglass_qh < 0) c.fail("QH", "must not be negative");
  ctx.collect(cur);
}

void readControlBulkViscosity(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(keywordSpec("*CONTROL_BULK_VISCOSITY").card("card 1"));
  Controls& k = ctx.model.controls;
  k.q_quadratic = c.real("Q1");
  k.q_linear = c.real("Q2");
  if (k.q_quadratic < 0) c.fail("Q1", "must not be negative");
  if (k.q_linear < 0) c.fail("Q2", "must not be negative");
  ctx.collect(cur);
}

// *CONTROL_RIGID (Keyword Manual vol. I). Every field's default (0) is what Crumple does; a
// value that would change the answer is refused by name:
//  - LMF 1 (Lagrange multiplier joints): Crumple's joints are penalty springs (LMF 0);
//  - JNTF 1, 2 (total formulations of the generalized joint stiffness): Crumple's joint
//    stiffness springs are updated incrementally (JNTF 0);
//  - METALF 1 (the metal-forming shortcut for rigid tools);
//  - GJADSTF, GJADVSC, TJADSTF, TJADVSC (added joint stiffness and damping);
// and accepted with a note where the value cannot matter here:
//  - ORTHMD, PARTM, SPARSE: options of *PART_MODES, which Crumple does not read;
//  - PLOTEL: *ELEMENT_PLOTEL for the output of nodal rigid bodies (output only);
//  - RBSMS: rigid bodies in selective mass scaling, which Crumple does not do;
//  - NORBIC: switches off an input check of rigid-body inertias; not the answer.
void readControlRigid(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*CONTROL_RIGID");
  CardCursor cur(kw, ctx.deck);
  const Card& c1 = cur.readOptional(spec.card("card 1"));
  const Card& c2 = cur.readOptional(spec.card("card 2"));
  if (c1.integer("LMF") != 0)
    ctx.reject(c1, "LMF", "Lagrange multiplier joints are not supported (LMF 0: penalty joints)");
  if (c1.integer("JNTF") != 0)
    ctx.reject(c1, "JNTF", "only the incremental joint stiffness update (JNTF 0) is supported");
  if (c1.integer("METALF") != 0)
    ctx.reject(c1, "METALF", "the metal-forming rigid body option is not supported");
  for (auto f : {"GJADSTF", "GJADVSC", "TJADSTF", "TJADVSC"})
    if (c2.real(f) != 0.0) ctx.reject(c2, f, "added joint stiffness and damping are not supported");
  for (auto f : {"ORTHMD", "PARTM", "SPARSE"})
    if (c1.integer(f) != 0)
      ctx.ignore(kw.name, f, "no effect: an option of *PART_MODES, which Crumple does not read",
                 c1.where());
  if (c1.integer("PLOTEL") != 0)
    ctx.ignore(kw.name, "PLOTEL", "output only: no *ELEMENT_PLOTEL are generated", c1.where());
  if (c1.integer("RBSMS") != 0)
    ctx.ignore(kw.name, "RBSMS", "no effect: Crumple has no selective mass scaling", c1.where());
  if (c2.integer("NORBIC") != 0)
    ctx.ignore(kw.name, "NORBIC", "no effect: an input check only", c2.where());
  ctx.collect(cur);
}

// HGEN 2 and RWEN 2 include hourglass and rigid-wall energy in the energy balance.
void readControlEnergy(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(keywordSpec("*CONTROL_ENERGY").card("card 1"));
  Controls& k = ctx.model.controls;
  k.hourglass_energy = c.integer("HGEN") == 2;
  k.rigidwall_energy = c.integer("RWEN") == 2;
  ctx.collect(cur);
}

void readIgnoredControl(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec(kw.name);
  CardCursor cur(kw, ctx.deck);
  for (const auto& card : spec.cards) {
    if (cur.atEnd()) break;
    cur.read(card);
  }
  ctx.collect(cur);
}

void readDatabaseAscii(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(keywordSpec(kw.name).card("card 1"));
  Controls& k = ctx.model.controls;
  const double dt = c.real("DT");
  if (dt < 0) c.fail("DT", "must not be negative");
  // Each keyword present asks for its file in LS-DYNA's ASCII layout, at DT (0: Crumple's
  // default interval, as for the CSV histories).
  const std::pair<std::string_view, std::pair<double*, bool*>> files[] = {
      {"*DATABASE_GLSTAT", {&k.glstat_dt, &k.ascii.glstat}},
      {"*DATABASE_MATSUM", {&k.matsum_dt, &k.ascii.matsum}},
      {"*DATABASE_NODOUT", {&k.nodout_dt, &k.ascii.nodout}},
      {"*DATABASE_RWFORC", {&k.rwforc_dt, &k.ascii.rwforc}},
      {"*DATABASE_RCFORC", {&k.rcforc_dt, &k.ascii.rcforc}},
      {"*DATABASE_SLEOUT", {&k.sleout_dt, &k.ascii.sleout}},
      {"*DATABASE_SECFORC", {&k.secforc_dt, &k.ascii.secforc}},
      {"*DATABASE_SPCFORC", {&k.spcforc_dt, &k.ascii.spcforc}},
      {"*DATABASE_BNDOUT", {&k.bndout_dt, &k.ascii.bndout}},
      {"*DATABASE_RBDOUT", {&k.rbdout_dt, &k.ascii.rbdout}},
      {"*DATABASE_DEFORC", {&k.deforc_dt, &k.ascii.deforc}},
      {"*DATABASE_JNTFORC", {&k.jntforc_dt, &k.ascii.jntforc}},
      {"*DATABASE_ELOUT", {&k.elout_dt, &k.ascii.elout}},
  };
  for (const auto& [name, target] : files)
    if (kw.name == name) {
      *target.first = dt;
      *target.second = true;
    }
  ctx.collect(cur);
}

namespace {
// The _ID card (CSID, TITLE; without it the 1-based order of definition) and card 1, whose
// `field` an id defined before is an error at.
CrossSection crossSectionHead(Context& ctx, CardCursor& cur, const deck::KeywordSpec& spec,
                              const deck::Keyword& kw, const KeywordOptions& opts,
                              std::string_view field, const Card*& c1) {
  CrossSection cs;
  cs.id = int64_t(ctx.model.cross_sections.size()) + 1;
  cs.where = ctx.deck.loc(kw);
  if (opts.has("ID")) {
    const Card& idc = cur.read(spec.card("id card"));
    if (!idc.blank("CSID")) cs.id = idc.integer("CSID");
    cs.title = idc.text("TITLE");
  }
  c1 = &cur.read(spec.card("card 1"));
  for (const auto& other : ctx.model.cross_sections)
    if (other.id == cs.id)
      c1->fail(field, "cross section " + std::to_string(cs.id) + " is already defined at " +
                          other.where.str());
  return cs;
}
}  // namespace

// Keyword Manual Vol. I, *DATABASE_CROSS_SECTION_SET: the force the given elements exert on the
// given nodes (src/output/sections.hpp); the thick shells of TSID (*SET_TSHELL) join the
// solids of HSID (they are kept with the solids). A local frame (ID) is not supported: the
// section is left out and said so (output only).
void readCrossSectionSet(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*DATABASE_CROSS_SECTION_SET");
  CardCursor cur(kw, ctx.deck);
  const Card* c = nullptr;
  CrossSection cs = crossSectionHead(ctx, cur, spec, kw, opts, "NSID", c);
  if (c->integer("ID") != 0) {
    ctx.reportUnsupported(kw, "section forces in a local frame (ID, ITYPE) not supported", false);
    return;
  }
  cs.by_set = true;
  const int64_t nsid = c->integer("NSID");
  if (nsid == 0) c->fail("NSID", "the nodes of the cut are required");
  for (int32_t n : ctx.nodeSet(*c, "NSID", nsid))
    cs.set_nodes.push_back(ctx.model.nodes.id[std::size_t(n)]);
  std::sort(cs.set_nodes.begin(), cs.set_nodes.end());
  static constexpr std::pair<std::string_view, Family> kSets[] = {{"HSID", Family::Solid},
                                                                  {"SSID", Family::Shell},
                                                                  {"BSID", Family::Beam},
                                                                  {"DSID", Family::Discrete}};
  bool any = false;
  for (const auto& [field, f] : kSets)
    if (const int64_t id = c->integer(field); id != 0) {
      cs.set_elements[static_cast<std::size_t>(f)] = ctx.elementSet(f, *c, field, id);
      any = true;
    }
  if (const int64_t id = c->integer("TSID"); id != 0) {
    auto& solids = cs.set_elements[static_cast<std::size_t>(Family::Solid)];
    const auto& thick = ctx.tshellSet(*c, "TSID", id);
    solids.insert(solids.end(), thick.begin(), thick.end());
    std::sort(solids.begin(), solids.end());
    solids.erase(std::unique(solids.begin(), solids.end()), solids.end());
    any = true;
  }
  if (!any) c->fail("HSID", "no element set: give HSID, SSID, BSID, DSID or TSID");
  ctx.model.cross_sections.push_back(std::move(cs));
  ctx.collect(cur);
}

void readCrossSectionPlane(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*DATABASE_CROSS_SECTION_PLANE");
  CardCursor cur(kw, ctx.deck);
  const Card* c1p = nullptr;
  CrossSection cs = crossSectionHead(ctx, cur, spec, kw, opts, "PSID", c1p);
  const Card& c1 = *c1p;
  const Card& c2 = cur.readOptional(spec.card("card 2"));
  // Forces in the frame of a rigid body, accelerometer or coordinate system (ID, ITYPE) are
  // not computed: the section is left out, and said so (output only: the run is unaffected).
  if (c2.integer("ID") != 0) {
    ctx.reportUnsupported(kw, "section forces in a local frame (ID, ITYPE) not supported", false);
    return;
  }
  cs.radius = c1.real("RADIUS");
  if (cs.radius < 0) c1.fail("RADIUS", "must not be negative");
  if (const int64_t psid = c1.integer("PSID"); psid != 0) cs.parts = ctx.partSet(c1, "PSID", psid);
  std::sort(cs.parts.begin(), cs.parts.end());
  cs.center = {c1.real("XCT"), c1.real("YCT"), c1.real("ZCT")};
  const Vec3 head = {c1.real("XCH"), c1.real("YCH"), c1.real("ZCH")};
  const Vec3 edge = {c2.real("XHEV"), c2.real("YHEV"), c2.real("ZHEV")};
  cs.lenl = c2.real("LENL");
  cs.lenm = c2.real("LENM");
  if (cs.lenl < 0 || cs.lenm < 0) c2.fail(cs.lenl < 0 ? "LENL" : "LENM", "must not be negative");
  cs.normal = util::unit(util::sub(head, cs.center));
  if (cs.normal == Vec3{}) c1.fail("XCH", "the normal's head is its tail: no direction");
  // l: the edge vector (tail XCT..) made normal to n; only a bounded cut needs it.
  const Vec3 l = util::sub(edge, cs.center);
  cs.l = util::unit(util::sub(l, util::scale(cs.normal, util::dot(l, cs.normal))));
  if ((cs.lenl > 0 || cs.lenm > 0) && cs.l == Vec3{})
    c2.fail("XHEV", "a bounded cut (LENL, LENM) needs an edge vector not along the normal");
  ctx.model.cross_sections.push_back(std::move(cs));
  ctx.collect(cur);
}

void readDatabaseD3plot(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*DATABASE_BINARY_D3PLOT");
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(spec.card("card 1"));
  cur.readOptional(spec.card("card 2"));
  ctx.model.controls.d3plot = true;  // LS-DYNA writes the d3plot family when this is present
  ctx.model.controls.d3plot_dt = c.real("DT");
  if (ctx.model.controls.d3plot_dt < 0) c.fail("DT", "must not be negative");
  // NPLTC: the number of plot states, DT = ENDTIM / NPLTC when DT is not given.
  ctx.d3plot_npltc = c.integer("NPLTC");
  ctx.collect(cur);
}

void readDatabaseExtentBinary(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  // Only the shell output switches are honoured; NEIPH, NEIPS, MAXINT (written as 3: mid,
  // inner and outer surface), STRFLG and the fields of cards 2 and 3 are left unread, so a
  // value other than the default is reported as read but not honoured.
  const auto& spec = keywordSpec("*DATABASE_EXTENT_BINARY");
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(spec.card("card 1"));
  for (const auto& name : {"card 2", "card 3"})
    if (!cur.atEnd()) cur.read(spec.card(name));
  // 1 (or blank) includes, 2 excludes for shells (Keyword Manual Vol. I,
  // *DATABASE_EXTENT_BINARY); SIGFLG and EPSFLG 3 exclude for solids too, which Crumple does not
  // do (the solid record has a fixed length of 7 words, the manual's NV3D without NEIPH).
  auto flag = [&](const char* field) {
    const int64_t v = c.integer(field);
    const bool solids_too =
        v == 3 && std::string_view(field) != "RLTFLG" && std::string_view(field) != "ENGFLG";
    if (v != 1 && v != 2 && !solids_too) c.fail(field, "must be 1 (include) or 2 (exclude)");
    if (solids_too)
      ctx.ignore(kw.name, field, "3 is honoured as 2: solids keep theirs in the d3plot", c.where());
    return v == 1;
  };
  D3plotExtent& e = ctx.model.controls.d3plot_extent;
  e.shell_stress = flag("SIGFLG");
  e.shell_plastic_strain = flag("EPSFLG");
  e.shell_resultants = flag("RLTFLG");
  e.shell_energy = flag("ENGFLG");
  ctx.collect(cur);
}

void readDatabaseD3dump(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(keywordSpec("*DATABASE_BINARY_D3DUMP").card("card 1"));
  const double cycles = c.real("CYCL");
  // A dump interval is a whole, positive number of cycles (0 or blank: no cycle-driven dumps).
  if (cycles < 0 || cycles != std::floor(cycles) || cycles > 1e15)
    c.fail("CYCL", "must be a whole number of cycles, 0 or more");
  ctx.model.controls.d3dump_cycles = static_cast<int64_t>(cycles);
  ctx.collect(cur);
}

void readHistoryNode(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*DATABASE_HISTORY_NODE");
  CardCursor cur(kw, ctx.deck);
  auto add = [&](int32_t n) {
    auto& h = ctx.model.history_nodes;
    if (std::find(h.begin(), h.end(), n) == h.end()) h.push_back(n);
  };
  while (nextRecord(cur, opts.has("ID"))) {
    if (opts.has("ID")) {
      // One node per card with its heading.
      const Card& c = cur.read(spec.card("id card"));
      add(ctx.node(c, "ID", c.integer("ID")));
    } else {
      const Card& c = cur.read(spec.card("card 1"));
      for (int k = 1; k <= 8; ++k) {
        const std::string f = "ID" + std::to_string(k);
        if (const int64_t id = c.integer(f); id != 0) add(ctx.node(c, f, id));
      }
    }
    ctx.collect(cur);
  }
}

void readHistoryNodeSet(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*DATABASE_HISTORY_NODE_SET").card("card 1");
  CardCursor cur(kw, ctx.deck);
  auto& h = ctx.model.history_nodes;
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec);
    for (int k = 1; k <= 8; ++k) {
      const std::string f = "ID" + std::to_string(k);
      if (const int64_t id = c.integer(f); id != 0)
        for (int32_t n : ctx.nodeSet(c, f, id))
          if (std::find(h.begin(), h.end(), n) == h.end()) h.push_back(n);
    }
    ctx.collect(cur);
  }
}

namespace {
// *DATABASE_HISTORY_TSHELL (with or without _ID, _SET): thick shells, of the solid family.
bool historyTShell(std::string_view name) {
  return name.rfind("*DATABASE_HISTORY_TSHELL", 0) == 0;
}
// The family of *DATABASE_HISTORY_SOLID, _SHELL, _BEAM or _TSHELL (with or without _ID, _SET).
model::Family historyFamily(std::string_view name) {
  if (name.rfind("*DATABASE_HISTORY_SOLID", 0) == 0 || historyTShell(name))
    return model::Family::Solid;
  if (name.rfind("*DATABASE_HISTORY_SHELL", 0) == 0) return model::Family::Shell;
  return model::Family::Beam;
}
// The spec name of the keyword without _ID ("*DATABASE_HISTORY_SOLID" or its _SET).
std::string historySpec(std::string_view name, model::Family f, bool set) {
  static constexpr std::string_view kName[] = {"*DATABASE_HISTORY_SOLID", "*DATABASE_HISTORY_SHELL",
                                               "*DATABASE_HISTORY_BEAM"};
  const std::string_view base =
      historyTShell(name) ? "*DATABASE_HISTORY_TSHELL" : kName[static_cast<int>(f)];
  return std::string(base) + (set ? "_SET" : "");
}
void addHistoryElement(Context& ctx, model::Family f, int32_t e) {
  auto& h = ctx.model.history_elements[static_cast<std::size_t>(f)];
  const auto it = std::lower_bound(h.begin(), h.end(), e);
  if (it == h.end() || *it != e) h.insert(it, e);
}
}  // namespace

// Keyword Manual vol. I, *DATABASE_HISTORY_OPTION: the elements whose stresses (solids,
// shells, thick shells: these kept with the solids, elout lists them with the solids) or
// resultants (beams) elout lists at *DATABASE_ELOUT's DT.
void readHistoryElement(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const model::Family f = historyFamily(kw.name);
  const bool tshell = historyTShell(kw.name);
  const auto& spec = keywordSpec(historySpec(kw.name, f, false));
  CardCursor cur(kw, ctx.deck);
  auto add = [&](const Card& c, std::string_view field, int64_t id) {
    const int32_t e = ctx.model.elementIndex(f, id);
    if (e == kNone || (tshell && !ctx.model.isThickShellElement(e)))
      c.fail(field, (tshell ? std::string("thick shell") : std::string(model::familyName(f))) +
                        " element " + std::to_string(id) + " is not defined");
    addHistoryElement(ctx, f, e);
  };
  while (nextRecord(cur, opts.has("ID"))) {
    if (opts.has("ID")) {
      const Card& c = cur.read(spec.card("id card"));
      add(c, "ID", c.integer("ID"));
    } else {
      const Card& c = cur.read(spec.card("card 1"));
      for (int k = 1; k <= 8; ++k) {
        const std::string field = "ID" + std::to_string(k);
        if (const int64_t id = c.integer(field); id != 0) add(c, field, id);
      }
    }
    ctx.collect(cur);
  }
}

void readHistoryElementSet(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const model::Family f = historyFamily(kw.name);
  const bool tshell = historyTShell(kw.name);
  const auto& spec = keywordSpec(historySpec(kw.name, f, true)).card("card 1");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec);
    for (int k = 1; k <= 8; ++k) {
      const std::string field = "ID" + std::to_string(k);
      if (const int64_t id = c.integer(field); id != 0)
        for (int32_t e : tshell ? ctx.tshellSet(c, field, id) : ctx.elementSet(f, c, field, id))
          addHistoryElement(ctx, f, e);
    }
    ctx.collect(cur);
  }
}

// What spcforc and bndout leave out (src/output/reactions.hpp): the constraints of rigid
// bodies act on the body's centre, not on nodes, and their reactions are not reported.
static void noteUnwrittenReactions(Context& ctx) {
  const Controls& k = ctx.model.controls;
  for (const auto& b : ctx.model.rigid.bodies) {
    if (k.ascii.spcforc && b.fixed != 0)
      ctx.ignore("*DATABASE_SPCFORC", "rigid body " + std::to_string(b.id),
                 "its constraints (CMO, SPCs of its nodes) are not in spcforc", b.where);
    if (k.ascii.bndout && !b.motions.empty())
      ctx.ignore("*DATABASE_BNDOUT", "rigid body " + std::to_string(b.id),
                 "its prescribed motion is not in bndout", b.where);
  }
}

namespace {

// Whether a part's elements run an hourglass control: one-point hexahedra (ELFORM 1) and the
// one-point shells (ELFORM 2, 4, 10). Fully integrated solids and shells, tetrahedra,
// pentahedra, beams and discretes have none.
bool hasHourglassControl(const Model& m, const Part& p) {
  if (p.section == kNone) return false;
  const auto s = static_cast<std::size_t>(p.section);
  if (p.section_kind == SectionKind::Solid) return m.solid_sections[s].elform == 1;
  if (p.section_kind == SectionKind::Shell) {
    const int f = m.shell_sections[s].elform;
    return f == 2 || f == 4 || f == 10;  // 2D solids (13, 15) are checked by finishPlanar
  }
  return false;
}

// IHQ 8 (Keyword Manual, *HOURGLASS / *CONTROL_HOURGLASS): "full projection warping stiffness
// for shell formulations 16 and -16". For an element with hourglass control the manual gives
// it no meaning we could check, so such parts are refused (as a missing feature, at the
// keyword that set IHQ 8) rather than run with another type.
void refuseWarpingOnHourglassElements(Context& ctx) {
  const Model& m = ctx.model;
  std::vector<char> used(m.parts.size(), 0);
  for (int32_t p : m.solids.part) used[static_cast<std::size_t>(p)] = 1;
  for (int32_t p : m.shells.part) used[static_cast<std::size_t>(p)] = 1;
  std::map<const deck::Keyword*, std::string> parts;  // the refused parts per keyword
  for (std::size_t i = 0; i < m.parts.size(); ++i) {
    const Part& p = m.parts[i];
    const deck::Keyword* kw = ctx.ihq8_control;
    if (p.hourglass != kNone) {
      const auto at = ctx.ihq8_hourglass.find(static_cast<std::size_t>(p.hourglass));
      kw = at != ctx.ihq8_hourglass.end() ? at->second : nullptr;
    }
    if (used[i] == 0 || kw == nullptr || !hasHourglassControl(m, p)) continue;
    parts[kw] += (parts[kw].empty() ? "" : ", ") + std::to_string(p.id);
  }
  for (const auto& [kw, ids] : parts) {
    const std::string message = fmt::format(
        "IHQ 8 (the warping stiffness of ELFORM 16 shells) is not supported on elements with "
        "hourglass control (one-point hexahedra and shells): part(s) {}; give them a *HOURGLASS "
        "of type 1-5",
        ids);
    if (!ctx.options.allow_unsupported)
      throw util::InputError(ctx.deck.loc(*kw).str() + ": " + kw->name + ": " + message);
    ctx.reportUnsupported(*kw, message, true, kw->name + " IHQ=8 on one-point elements");
  }
}

}  // namespace

void finishControls(Context& ctx) {
  Controls& k = ctx.model.controls;
  if (k.d3plot_dt == 0.0 && ctx.d3plot_npltc > 0 && k.end_time > 0)
    k.d3plot_dt = k.end_time / static_cast<double>(ctx.d3plot_npltc);
  // Solids and shells are eroded when their step falls below DTMIN with ERODE=1
  // (*CONTROL_TIMESTEP); a material's TDEL (*MAT_024) is applied per part by the solver.
  k.erode_on_dtmin = ctx.erode_flag == 1 && k.dt_min_ratio > 0;
  noteUnwrittenReactions(ctx);
  refuseWarpingOnHourglassElements(ctx);
}

}  // namespace crumple::model::build
