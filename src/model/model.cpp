#include "model/model.hpp"

#include "model/solid_shape.hpp"

#include "util/curve.hpp"

#include <algorithm>
#include <iterator>
#include <string>
#include <type_traits>

namespace crumple::model {

double Curve::value(double t) const {
  if (x.empty()) return 0.0;
  if (x.size() == 1 || t <= x.front()) return y.front();
  if (t >= x.back()) return y.back();
  return util::onSegment(x, y, util::segmentOf(x, t), t);
}

double Curve::valueExtrapolated(double t) const {
  if (x.empty()) return 0.0;
  if (x.size() == 1) return y.front();
  return util::onSegment(x, y, util::segmentOf(x, t), t);
}

namespace {
int32_t find(const util::IdIndex& m, int64_t id) {
  static_assert(util::IdIndex::kAbsent == kNone);
  return m.find(id);
}
template <class Ids>
void fill(util::IdIndex& m, const Ids& ids) {
  m.assign(ids);
}
}  // namespace

int32_t Model::nodeIndex(int64_t id) const {
  return find(node_index_, id);
}
bool Model::isThickShellElement(int32_t e) const {
  const Part& p = parts[std::size_t(solids.part[std::size_t(e)])];
  return p.section_kind == SectionKind::Solid && p.section != kNone &&
         isThickShell(solid_sections[std::size_t(p.section)].elform);
}

int32_t Model::elementIndex(Family f, int64_t id) const {
  const auto& ids = familyIds(f);
  const auto it = std::lower_bound(ids.begin(), ids.end(), id);
  return it != ids.end() && *it == id ? static_cast<int32_t>(it - ids.begin()) : kNone;
}
const std::vector<int64_t>& Model::familyIds(Family f) const {
  switch (f) {
    case Family::Solid:
      return solids.id;
    case Family::Shell:
      return shells.id;
    case Family::Beam:
      return beams.id;
    case Family::Discrete:
      break;
  }
  return discretes.id;
}
int32_t Model::partIndex(int64_t id) const {
  return find(part_index_, id);
}
int32_t Model::curveIndex(int64_t id) const {
  return find(curve_index_, id);
}
int32_t Model::tableIndex(int64_t id) const {
  return find(table_index_, id);
}

const char* materialKeyword(const MaterialLaw& law) {
  // The units' keyword names are string literals, so the view is null-terminated.
  return materials::keywordOf(law).data();
}

const char* familyName(Family f) {
  switch (f) {
    case Family::Solid:
      return "solid";
    case Family::Shell:
      return "shell";
    case Family::Beam:
      return "beam";
    case Family::Discrete:
      return "discrete";
  }
  return "element";
}

std::size_t Model::familySize(Family f) const {
  switch (f) {
    case Family::Solid:
      return solids.size();
    case Family::Shell:
      return shells.size();
    case Family::Beam:
      return beams.size();
    case Family::Discrete:
      return discretes.size();
  }
  return 0;
}

std::size_t Model::familyOffset(Family f) const {
  std::size_t offset = 0;
  for (int k = 0; k < static_cast<int>(f); ++k) offset += familySize(static_cast<Family>(k));
  return offset;
}

std::size_t Model::numElements() const {
  return solids.size() + shells.size() + beams.size() + discretes.size();
}

std::pair<Family, int32_t> Model::element(std::size_t g) const {
  for (int k = 0; k < kFamilies; ++k) {
    const auto f = static_cast<Family>(k);
    const std::size_t n = familySize(f);
    if (g < n) return {f, static_cast<int32_t>(g)};
    g -= n;
  }
  return {Family::Solid, kNone};
}

namespace {
template <class List>
int copyNodes(const List& list, int32_t i, int32_t out[kMaxElementNodes]) {
  const auto& n = list.nodes[static_cast<std::size_t>(i)];
  if constexpr (std::is_same_v<List, Solids>)
    if (list.quadratic(static_cast<std::size_t>(i))) {
      // The 10-node tetrahedron: its corners, then its mid-side nodes.
      for (int a = 0; a < 4; ++a) out[a] = n[static_cast<std::size_t>(a)];
      for (int a = 0; a < 6; ++a)
        out[4 + a] = list.mid[static_cast<std::size_t>(i)][std::size_t(a)];
      return 10;
    }
  for (int a = 0; a < List::kNodes; ++a) out[a] = n[static_cast<std::size_t>(a)];
  return List::kNodes;
}
template <class F>
auto onFamily(const Model& m, std::size_t g, F&& f) {
  const auto [family, i] = m.element(g);
  switch (family) {
    case Family::Shell:
      return f(m.shells, i);
    case Family::Beam:
      return f(m.beams, i);
    case Family::Discrete:
      return f(m.discretes, i);
    default:
      return f(m.solids, i);
  }
}
}  // namespace

int Model::elementNodes(std::size_t g, int32_t out[kMaxElementNodes]) const {
  return onFamily(*this, g, [&](const auto& list, int32_t i) { return copyNodes(list, i, out); });
}

int32_t Model::elementPart(std::size_t g) const {
  return onFamily(
      *this, g, [](const auto& list, int32_t i) { return list.part[static_cast<std::size_t>(i)]; });
}

int Model::solidFormulation(std::size_t e) const {
  const Part& part = parts[static_cast<std::size_t>(solids.part[e])];
  const int form = part.section == kNone || part.section_kind != SectionKind::Solid
                       ? 1
                       : solid_sections[static_cast<std::size_t>(part.section)].elform;
  if (!controls.solid_esort || (form != 1 && !isFullyIntegratedHex(form))) return form;
  if (isCanonicalTet(solids.nodes[e])) return 10;
  return isCanonicalPrism(solids.nodes[e]) ? 15 : form;
}

int64_t Model::elementId(std::size_t g) const {
  return onFamily(*this, g,
                  [](const auto& list, int32_t i) { return list.id[static_cast<std::size_t>(i)]; });
}

std::string Model::elementName(std::size_t g) const {
  return std::string(familyName(element(g).first)) + " element " + std::to_string(elementId(g));
}

void Model::releaseMesh() {
  nodes = Nodes{};
  solids = Solids{};
  shells = Shells{};
  beams = Beams{};
  discretes = Discretes{};
  sph = SphParticles{};
  node_sets.clear();
  part_sets.clear();
  segment_sets.clear();
  for (auto& sets : element_sets) sets.clear();
  tshell_sets.clear();
  std::vector<Vec3>().swap(initial_velocity);
  std::vector<Vec3>().swap(initial_angular_velocity);
  node_index_.clear();
}

void Model::finalize() {
  fill(node_index_, nodes.id);
  std::vector<int64_t> ids;
  for (const auto& p : parts) ids.push_back(p.id);
  fill(part_index_, ids);
  ids.clear();
  for (const auto& c : curves) ids.push_back(c.id);
  fill(curve_index_, ids);
  ids.clear();
  for (const auto& t : tables) ids.push_back(t.id);
  fill(table_index_, ids);
}

}  // namespace crumple::model
