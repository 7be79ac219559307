// The checks and constraints of 2D solids (*SECTION_SHELL ELFORM 13 plane strain, 15
// axisymmetric; src/elements/solid2d.hpp). LS-DYNA runs a 2D model as a whole: its elements lie
// in the x-y plane with two translational freedoms per node (Keyword Manual vol. I,
// *SECTION_SHELL; Theory Manual, "Two-dimensional solid elements").
#include <fmt/format.h>

#include <set>

#include "model/build_context.hpp"

namespace crumple::model::build {

namespace {

bool isPlanarPart(const Model& m, const Part& p) {
  if (p.section_kind != SectionKind::Shell || p.section == kNone) return false;
  const int f = m.shell_sections[static_cast<std::size_t>(p.section)].elform;
  return f == 13 || f == 15;
}

// A 2D part's law: the 3-D solid update, no history variables (the shell block has no room
// for them), no equation of state, not rigid; viscous hourglass control only.
void checkPlanarPart(Context& ctx, const Part& p) {
  const Model& m = ctx.model;
  const std::string at =
      fmt::format("{}: part {} (2D solid, *SECTION_SHELL ELFORM {})", p.where.str(), p.id,
                  m.shell_sections[std::size_t(p.section)].elform);
  if (p.material == kNone) return;
  const Material& mat = m.materials[static_cast<std::size_t>(p.material)];
  const std::string law(materials::keywordOf(mat.law));
  if (materials::isRigid(mat.law) || !materials::supports(mat.law, materials::Family::Solid))
    ctx.fail(fmt::format("{}: material {} ({}) has no solid update a 2D solid can use", at, mat.id,
                         law));
  else if (materials::historyCountOf(mat.law) > 0 || materials::usesEos(mat.law) || p.eos != kNone)
    ctx.fail(fmt::format(
        "{}: material {} ({}) keeps history variables or an equation of state, which 2D "
        "solids do not support yet",
        at, mat.id, law));
  else if (materials::needsDeformationGradient(mat.law))
    ctx.fail(fmt::format(
        "{}: material {} ({}) is hyperelastic (a function of the deformation gradient), which "
        "only the one-point solids (*SECTION_SOLID ELFORM 1, 10) support yet",
        at, mat.id, law));
  const int ihq =
      p.hourglass != kNone ? m.hourglass[std::size_t(p.hourglass)].ihq : m.controls.hourglass_ihq;
  if (ihq < 1 || ihq > 3)
    ctx.fail(
        fmt::format("{}: hourglass type IHQ {} is not supported for 2D solids (the viscous "
                    "types 1-3 are)",
                    at, ihq));
}

// What a 2D model cannot hold, each refused with its keyword.
void refuseMixed(Context& ctx, std::size_t planar_shells) {
  const Model& m = ctx.model;
  auto refuse = [&](std::size_t n, const char* what) {
    if (n > 0)
      ctx.fail(
          fmt::format("2D solids (*SECTION_SHELL ELFORM 13, 15) run only with other 2D "
                      "solids: the deck also has {} {}",
                      n, what));
  };
  refuse(m.solids.size(), "*ELEMENT_SOLID");
  refuse(m.shells.size() - planar_shells, "*ELEMENT_SHELL of 3-D shell sections");
  refuse(m.beams.size(), "*ELEMENT_BEAM");
  refuse(m.discretes.size(), "*ELEMENT_DISCRETE");
  refuse(m.contacts.size(), "*CONTACT definitions (2D contact is not supported)");
  refuse(m.pressure_loads.size(), "*LOAD_SEGMENT pressure loads (2D segments are not supported)");
  refuse(m.rigid_walls.size(), "*RIGIDWALL definitions (not supported with 2D solids)");
  refuse(m.cross_sections.size(),
         "*DATABASE_CROSS_SECTION definitions (not supported with 2D solids)");
}

}  // namespace

void finishPlanar(Context& ctx) {
  Model& m = ctx.model;
  std::size_t planar_shells = 0;
  bool axisymmetric = false;
  std::set<int32_t> nodes;
  for (std::size_t e = 0; e < m.shells.size(); ++e) {
    const Part& p = m.parts[static_cast<std::size_t>(m.shells.part[e])];
    if (!isPlanarPart(m, p)) continue;
    ++planar_shells;
    axisymmetric = axisymmetric || m.shell_sections[std::size_t(p.section)].elform == 15;
    for (int32_t n : m.shells.nodes[e]) nodes.insert(n);
  }
  if (planar_shells == 0) return;
  for (const Part& p : m.parts)
    if (isPlanarPart(m, p)) checkPlanarPart(ctx, p);
  refuseMixed(ctx, planar_shells);
  // The radius of an axisymmetric model is x >= 0 (the y axis is the axis of symmetry).
  for (int32_t n : nodes)
    if (axisymmetric && m.nodes.x[std::size_t(n)][0] < 0.0) {
      ctx.fail(
          fmt::format("*NODE {}: x = {} < 0 in an axisymmetric model (x is the radius, "
                      "the y axis the axis of symmetry)",
                      m.nodes.id[std::size_t(n)], m.nodes.x[std::size_t(n)][0]));
      break;
    }
  // Two freedoms per node: z and the rotations are held (a z velocity given in the deck stays
  // out of the answer, as in LS-DYNA's 2D solver, which has no z freedom).
  constexpr DofMask kOutOfPlane = 0b111100;
  for (int32_t n : nodes) m.spcs.push_back({n, kOutOfPlane});
}

}  // namespace crumple::model::build
