#include "app/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <map>
#include <set>

#include "model/build.hpp"
#include "model/units.hpp"

namespace crumple::app {

namespace {

// Per part, the solids that run as tetrahedra (ELFORM 10) and as pentahedra (ELFORM 15),
// native or sorted by ESORT, and the thick shells (kept with the solids), as the note the
// summary adds to the part's line.
std::map<int32_t, std::string> shapesPerPart(const model::Model& m) {
  std::map<int32_t, std::array<std::size_t, 4>> count;
  for (std::size_t e = 0; e < m.solids.size(); ++e) {
    const int form = m.solidFormulation(e);
    if (form == 10 || form == 15 || form == 16 || model::isThickShell(form))
      ++count[m.solids.part[e]][form == 10 ? 0 : form == 15 ? 1 : form == 16 ? 2 : 3];
  }
  std::map<int32_t, std::string> out;
  for (const auto& [part, n] : count)
    out[part] = (n[0] > 0 ? fmt::format(", {} as ELFORM 10 tetrahedra", n[0]) : "") +
                (n[1] > 0 ? fmt::format(", {} as ELFORM 15 pentahedra", n[1]) : "") +
                (n[2] > 0 ? fmt::format(", {} as ELFORM 16 10-node tetrahedra", n[2]) : "") +
                (n[3] > 0 ? fmt::format(", {} thick shells (*ELEMENT_TSHELL)", n[3]) : "");
  return out;
}

// A part of 2D solids (*SECTION_SHELL ELFORM 13, 15): what its shells are and what their
// masses and forces are per; empty for other parts.
std::string planarNote(const model::Model& m, const model::Part& part) {
  if (part.section_kind != model::SectionKind::Shell || part.section == model::kNone) return "";
  const int f = m.shell_sections[static_cast<std::size_t>(part.section)].elform;
  if (f == 13) return ", 2D plane-strain solids (ELFORM 13, per unit depth)";
  if (f == 15) return ", 2D axisymmetric solids (ELFORM 15, per radian)";
  return "";
}

}  // namespace

std::string modelSummary(const model::Model& m, const solver::Solver& s) {
  std::string out;
  out += fmt::format("deck: {}\n", m.deck_path);
  if (!m.title.empty()) out += fmt::format("title: {}\n", m.title);
  out += fmt::format("units: {}{}\n", model::describeUnits(m.units),
                     m.units.source.empty() ? "" : ", " + m.units.source);
  out += fmt::format("nodes: {}\nsolid elements: {}\n", m.nodes.size(), m.solids.size());
  if (m.shells.size() > 0) out += fmt::format("shell elements: {}\n", m.shells.size());
  if (m.beams.size() > 0) out += fmt::format("beam elements: {}\n", m.beams.size());
  if (m.discretes.size() > 0) out += fmt::format("discrete elements: {}\n", m.discretes.size());
  if (m.sph.size() > 0) out += fmt::format("SPH particles: {}\n", m.sph.size());
  std::map<std::pair<int32_t, int>, std::size_t> per_part;
  for (std::size_t g = 0; g < m.numElements(); ++g)
    ++per_part[{m.elementPart(g), int(m.element(g).first)}];
  static constexpr const char* kPlural[] = {"solids", "shells", "beams", "discretes"};
  static constexpr const char* kSingular[] = {"solid", "shell", "beam", "discrete"};
  const auto shapes = shapesPerPart(m);
  for (const auto& [key, count] : per_part) {
    const auto& part = m.parts[static_cast<std::size_t>(key.first)];
    const auto& mat = m.materials[static_cast<std::size_t>(part.material)];
    const auto t = key.second == int(model::Family::Solid) ? shapes.find(key.first) : shapes.end();
    out += fmt::format("  part {}{}: {} {}, {} {} (density {:g}){}\n", part.id,
                       part.title.empty() ? "" : " \"" + part.title + "\"", count,
                       count == 1 ? kSingular[key.second] : kPlural[key.second],
                       model::materialKeyword(mat.law), mat.id, mat.rho,
                       t == shapes.end() ? planarNote(m, part) : t->second);
  }
  out += fmt::format("total mass: {:.6g}\n", s.totalMass());
  if (s.addedMass() > 0.0)
    out += fmt::format("mass added by scaling (DT2MS): {:.6g} ({:.3g}%)\n", s.addedMass(),
                       100.0 * s.addedMass() / s.totalMass());
  out += fmt::format("initial time step: {:.6g} ({}, TSSFAC {:g})\n", s.initialDt(),
                     s.initialDtElement(), m.controls.tssfac);
  out += fmt::format("end time: {:g}\n", m.controls.end_time);
  if (!m.contacts.empty()) {
    static constexpr const char* kKind[] = {"nodes to surface", "surface to surface",
                                            "single surface", "tied", "force transducer"};
    static_assert(std::size(kKind) == std::size_t(model::ContactKind::Transducer) + 1);
    for (const auto& c : m.contacts)
      out += fmt::format(
          "contact {}{}: {}{}, {} nodes / {} segments against {} segments\n", c.id,
          c.title.empty() ? "" : " \"" + c.title + "\"", c.automatic ? "automatic " : "",
          kKind[int(c.kind)], c.a.nodes.size(), c.a.segments.size(),
          c.kind == model::ContactKind::SingleSurface ? c.a.segments.size() : c.b.segments.size());
    // Initial penetrations: DYNA3D moves the nodes back onto the surface (IGNORE 0), and
    // says so; with IGNORE 1 or 2 they are kept as an offset.
    if (const auto* c = s.contact()) {
      const auto& pen = c->initialPenetrations();
      if (!pen.empty()) {
        out += fmt::format("initial penetrations: {} ({})\n", pen.size(),
                           c->movedInitialPenetrations()
                               ? "moved back onto the surface before the first cycle"
                               : "kept as an offset (IGNORE)");
        const std::size_t shown = std::min<std::size_t>(pen.size(), 20);
        for (std::size_t k = 0; k < shown; ++k)
          out += fmt::format("  contact {} node {}: depth {:.4g}\n", pen[k].interface_id,
                             pen[k].node_id, pen[k].depth);
        if (shown < pen.size()) out += fmt::format("  ... and {} more\n", pen.size() - shown);
      }
    }
  }
  return out;
}

std::string warningsText(const model::Model& m) {
  std::string out;
  if (!m.unsupported.empty())
    out += "keywords read but not acted on:\n" + model::formatUnsupported(m);
  if (!m.ignored.empty()) out += "fields read but not honoured:\n" + model::formatIgnored(m);
  return out;
}

std::vector<const model::UnsupportedKeyword*> answerChanging(const model::Model& m) {
  std::vector<const model::UnsupportedKeyword*> out;
  for (const auto& u : m.unsupported)
    if (u.changes_answer) out.push_back(&u);
  return out;
}

std::size_t featureCount(const model::Model& m) {
  std::set<std::string> features;
  for (const auto* u : answerChanging(m)) features.insert(u->feature);
  return features.size();
}

std::string answerChangingText(const model::Model& m) {
  std::vector<std::string> order;
  std::map<std::string, std::pair<int, const model::UnsupportedKeyword*>> by_feature;
  for (const auto* u : answerChanging(m)) {
    auto [it, added] = by_feature.try_emplace(u->feature, 0, u);
    if (added) order.push_back(u->feature);
    it->second.first += u->count;
  }
  std::string out;
  for (const auto& f : order) {
    const auto& [count, u] = by_feature.at(f);
    out += fmt::format("  {} ({}x, first at {}): {}\n", f, count, u->first.str(), u->reason);
  }
  return out;
}

}  // namespace crumple::app
