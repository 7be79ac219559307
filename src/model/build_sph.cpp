// Smoothed particle hydrodynamics input (issue 14): *SECTION_SPH, *ELEMENT_SPH and
// *CONTROL_SPH (LS-DYNA Keyword Manual vol. I). The particles run as the SPH family
// (src/elements/sph_family.hpp); what a card sets that Crumple does not do is refused by name
// or, where it cannot change the answer here, reported by Context::collect.
#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <string>

#include "model/build_context.hpp"
#include "util/error.hpp"

namespace crumple::model::build {

using deck::Card;
using deck::CardCursor;
using deck::keywordSpec;

// *SECTION_SPH: SECID CSLH HMIN HMAX SPHINI DEATH START SPHKERN. CSLH, HMIN, HMAX and SPHINI
// are honoured; a DEATH or START other than the defaults (particles that switch off or on in
// time) and a kernel other than the cubic B-spline (SPHKERN 0) are refused.
void readSectionSph(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*SECTION_SPH");
  CardCursor cur(kw, ctx.deck);
  while (nextRecord(cur, opts.has("TITLE"))) {
    readTitleCard(cur, spec, opts);
    const Card& c = cur.read(spec.card("card 1"));
    SectionSph s;
    s.id = positiveId(c, "SECID");
    s.where = c.where();
    s.cslh = c.real("CSLH");
    s.hmin = c.real("HMIN");
    s.hmax = c.real("HMAX");
    s.sphini = c.real("SPHINI");
    if (!(s.cslh > 0.0)) c.fail("CSLH", "must be positive");
    if (!(s.hmin > 0.0) || s.hmin > 1.0) c.fail("HMIN", "must lie in (0, 1]");
    if (s.hmax < 1.0) c.fail("HMAX", "must be at least 1");
    if (s.sphini < 0.0) c.fail("SPHINI", "must not be negative");
    if (c.real("DEATH") != 1e20)
      ctx.reject(c, "DEATH", "SPH particles that stop at a death time are not supported");
    if (c.real("START") != 0.0)
      ctx.reject(c, "START", "SPH particles that start late are not supported");
    if (c.integer("SPHKERN") != 0)
      ctx.reject(c, "SPHKERN", "only the cubic B-spline kernel (SPHKERN 0) is supported");
    ctx.define(Kind::Section, s.id, c, "SECID");
    ctx.model.sph_sections.push_back(s);
    ctx.collect(cur);
  }
}

// *ELEMENT_SPH: NID PID MASS, one particle at each node; MASS < 0 gives the particle's volume,
// its mass then the part's density times |MASS| (Keyword Manual, *ELEMENT_SPH).
void readElementSph(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*ELEMENT_SPH").card("card 1");
  CardCursor cur(kw, ctx.deck);
  auto& sph = ctx.model.sph;
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec);
    const int32_t node = ctx.node(c, "NID", c.integer("NID"));
    const int32_t part = ctx.part(c, "PID", c.integer("PID"));
    ctx.checkPartUsable(c, part);
    checkSectionKind(ctx, c, part, SectionKind::Sph);
    double mass = c.real("MASS");
    if (mass < 0.0) {
      const Part& p = ctx.model.parts[static_cast<std::size_t>(part)];
      if (p.material == kNone) c.fail("PID", "the part has no material to give the density");
      mass = -mass * ctx.model.materials[static_cast<std::size_t>(p.material)].rho;
    }
    if (!(mass > 0.0)) c.fail("MASS", "must not be zero");
    sph.node.push_back(node);
    sph.part.push_back(part);
    sph.mass.push_back(mass);
    ctx.collect(cur);
  }
}

// *CONTROL_SPH: IDIM (0 or 3: three-dimensional; 2: plane strain in the x-y plane) and FORM 0
// (the default formulation, the one src/elements/sph.hpp implements) are what Crumple runs, and
// other values (IDIM -2, axisymmetric; IDIM 1) are refused. NCBS,
// BOXID, DT, NMNEIGH, START, MAXV, CONT, DERIV, INI, IEROD, ICONT, IAVIS, ISYMP, ITHK, ISTAB,
// QL and ISHIFT are read and, when not their defaults, reported as not honoured (Crumple
// searches the neighbours every cycle, has no neighbour limit and no particle deactivation).
void readControlSph(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*CONTROL_SPH");
  CardCursor cur(kw, ctx.deck);
  const Card& c1 = cur.readOptional(spec.card("card 1"));
  const int64_t idim = c1.integer("IDIM");
  if (idim == 2)
    ctx.model.sph.dim = 2;
  else if (idim != 0 && idim != 3)
    ctx.reject(c1, "IDIM",
               "only three-dimensional (IDIM 0 or 3) and plane-strain (IDIM 2) SPH are supported");
  if (c1.integer("FORM") != 0)
    ctx.reject(c1, "FORM", "only the default SPH formulation (FORM 0) is supported");
  if (!cur.atEnd()) cur.readOptional(spec.card("card 2"));
  if (!cur.atEnd()) cur.readOptional(spec.card("card 3"));
  ctx.collect(cur);
}

// Plane-strain SPH (*CONTROL_SPH IDIM 2; Keyword Manual vol. I): the particles lie in one plane
// z = const and move in it. LS-DYNA's 2D SPH runs in a 2D model; Crumple's 2D model has no room
// for 3-D elements beside it, so they are refused, as with the 2D solids.
void finishPlaneSph(Context& ctx) {
  Model& m = ctx.model;
  if (m.sph.dim != 2 || m.sph.size() == 0) return;
  if (m.numElements() > 0)
    ctx.fail(fmt::format(
        "*CONTROL_SPH IDIM 2 (plane-strain SPH) runs only with SPH particles: the deck also has "
        "{} elements",
        m.numElements()));
  const double z0 = m.nodes.x[std::size_t(m.sph.node.front())][2];
  for (int32_t n : m.sph.node)
    if (m.nodes.x[std::size_t(n)][2] != z0) {
      ctx.fail(fmt::format(
          "*NODE {}: z = {} but SPH particle node {} has z = {}: with *CONTROL_SPH IDIM 2 "
          "(plane strain) every particle lies in one plane z = const",
          m.nodes.id[std::size_t(n)], m.nodes.x[std::size_t(n)][2],
          m.nodes.id[std::size_t(m.sph.node.front())], z0));
      return;
    }
  // Two freedoms per particle: z and the rotations are held (as the 2D solids' nodes).
  constexpr DofMask kOutOfPlane = 0b111100;
  for (int32_t n : m.sph.node) m.spcs.push_back({n, kOutOfPlane});
}

// After the elements: the particles in ascending node order, one per node, at nodes no element
// uses (a particle is a node of its own: it lives on the rank holding the element-less nodes).
void finishSph(Context& ctx) {
  auto& sph = ctx.model.sph;
  if (sph.size() == 0) return;
  std::vector<std::size_t> order(sph.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return sph.node[a] < sph.node[b]; });
  SphParticles sorted;
  sorted.dim = sph.dim;
  for (std::size_t k : order) {
    if (!sorted.node.empty() && sorted.node.back() == sph.node[k])
      throw util::InputError(ctx.model.deck_path + ": *ELEMENT_SPH: node " +
                             std::to_string(ctx.model.nodes.id[std::size_t(sph.node[k])]) +
                             " carries two SPH particles");
    sorted.node.push_back(sph.node[k]);
    sorted.part.push_back(sph.part[k]);
    sorted.mass.push_back(sph.mass[k]);
  }
  sph = std::move(sorted);
  // Particles take the plain 3-D stress update: not rigid bodies, not deformation-gradient laws
  // (hyperelastic: a particle has no reference configuration here).
  std::vector<char> seen(ctx.model.parts.size(), 0);
  for (int32_t part : sph.part) {
    if (seen[std::size_t(part)]++) continue;
    const Part& p = ctx.model.parts[std::size_t(part)];
    if (p.material == kNone) continue;
    const auto& law = ctx.model.materials[std::size_t(p.material)].law;
    if (materials::isRigid(law) || materials::needsDeformationGradient(law))
      throw util::InputError(p.where.str() + ": *PART card 2 field 3 (MID): part " +
                             std::to_string(p.id) + " has SPH particles and " +
                             materialKeyword(law) +
                             ", which SPH particles do not support (rigid and hyperelastic laws)");
  }
  std::vector<char> on_element(ctx.model.nodes.size(), 0);
  int32_t en[kMaxElementNodes];
  for (std::size_t g = 0; g < ctx.model.numElements(); ++g) {
    const int k = ctx.model.elementNodes(g, en);
    for (int a = 0; a < k; ++a) on_element[std::size_t(en[a])] = 1;
  }
  for (int32_t n : sph.node)
    if (on_element[std::size_t(n)])
      throw util::InputError(ctx.model.deck_path + ": *ELEMENT_SPH: node " +
                             std::to_string(ctx.model.nodes.id[std::size_t(n)]) +
                             " is also a node of an element (an SPH particle needs its own node)");
}

}  // namespace crumple::model::build
