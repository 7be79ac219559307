#include "model/units.hpp"

#include <array>
#include <cmath>
#include <map>
#include <variant>

#include <fmt/format.h>

#include "materials/materials.hpp"

namespace crumple::model {
namespace {

// Keyword Manual vol. I, "Consistent units" (steel's density and modulus as the manual's
// table gives them, with 210 GPa).
constexpr std::array kSystems = {
    NamedUnits{"kg-m-s", "m", "s", "kg", "N", "Pa", 7850.0, 2.1e11},
    NamedUnits{"kg-mm-ms", "mm", "ms", "kg", "kN", "GPa", 7.85e-6, 210.0},
    NamedUnits{"t-mm-s", "mm", "s", "t", "N", "MPa", 7.85e-9, 2.1e5},
    NamedUnits{"g-mm-ms", "mm", "ms", "g", "N", "MPa", 7.85e-3, 2.1e5},
    NamedUnits{"g-cm-us", "cm", "us", "g", "1e7 N", "Mbar", 7.85, 2.1},
    NamedUnits{"kg-mm-s", "mm", "s", "kg", "mN", "kPa", 7.85e-6, 2.1e8},
    NamedUnits{"lbfs2/in-in-s", "in", "s", "lbf s^2/in", "lbf", "psi", 7.35e-4, 3.0e7},
};

// The spellings *CONTROL_UNITS accepts for each unit (Keyword Manual vol. I).
std::string_view canonicalUnit(std::string_view word) {
  static const std::map<std::string_view, std::string_view> kSpellings = {
      {"m", "m"},
      {"mm", "mm"},
      {"cm", "cm"},
      {"in", "in"},
      {"sec", "s"},
      {"s", "s"},
      {"ms", "ms"},
      {"micro_s", "us"},
      {"us", "us"},
      {"kg", "kg"},
      {"g", "g"},
      {"mtrc_ton", "t"},
      {"ton", "t"},
      {"t", "t"},
      {"lbf*s2/in", "lbf s^2/in"},
      {"lbfs2/in", "lbf s^2/in"}};
  const auto it = kSpellings.find(word);
  return it == kSpellings.end() ? std::string_view{} : it->second;
}

// Metals only: their modulus and density are known in every system. Rubber, foam, soil and
// fluid laws say nothing about the units.
bool isMetalLaw(std::string_view keyword) {
  return keyword == "*MAT_ELASTIC" || keyword == "*MAT_PLASTIC_KINEMATIC" ||
         keyword == "*MAT_PIECEWISE_LINEAR_PLASTICITY" || keyword == "*MAT_POWER_LAW_PLASTICITY" ||
         keyword == "*MAT_STRAIN_RATE_DEPENDENT_PLASTICITY" || keyword == "*MAT_RIGID";
}

double youngOfParams(const materials::LawParams& p) {
  return std::visit(
      [](const auto& params) {
        if constexpr (requires { params.E; })
          return static_cast<double>(params.E);
        else
          return 0.0;
      },
      p);
}

// Decades between a material and the nearest reference metal of a system; the density counts
// half, since analysts scale it for the time step and the modulus they leave alone.
double distance(const NamedUnits& u, double rho, double young) {
  constexpr std::array<std::array<double, 2>, 2> kMetals = {
      {{1.0, 1.0}, {2700.0 / 7850.0, 1.0 / 3.0}}};
  double best = INFINITY;
  for (const auto& [density_ratio, young_ratio] : kMetals)
    best = std::min(best, std::abs(std::log10(young / (u.steel_young * young_ratio))) +
                              0.5 * std::abs(std::log10(rho / (u.steel_density * density_ratio))));
  return best;
}

}  // namespace

std::span<const NamedUnits> unitSystems() {
  return kSystems;
}

const NamedUnits* unitSystemOf(std::string_view length, std::string_view time,
                               std::string_view mass) {
  const auto l = canonicalUnit(length), t = canonicalUnit(time), m = canonicalUnit(mass);
  for (const auto& u : kSystems)
    if (u.length == l && u.time == t && u.mass == m) return &u;
  return nullptr;
}

void inferUnits(Model& m) {
  if (!m.units.name.empty()) return;
  constexpr double kReach = 1.0;  // decades; the systems are at least three apart
  struct Votes {
    int count = 0;
    const Material* example = nullptr;
  };
  std::map<std::string_view, Votes> votes;
  int metals = 0;
  for (const auto& mat : m.materials) {
    const double young = youngOfParams(mat.law);
    if (!isMetalLaw(materials::keywordOf(mat.law)) || !(mat.rho > 0) || !(young > 0)) continue;
    ++metals;
    for (const auto& u : kSystems)
      if (distance(u, mat.rho, young) <= kReach) {
        Votes& v = votes[u.name];
        if (v.count++ == 0) v.example = &mat;
      }
  }
  if (votes.empty()) {
    m.units.source = metals ? "not known: no *CONTROL_UNITS, and no metal's density and Young's "
                              "modulus is near steel's or aluminium's in a consistent system"
                            : "not known: no *CONTROL_UNITS and no metal to infer it from";
    return;
  }
  auto best = votes.begin();
  for (auto it = votes.begin(); it != votes.end(); ++it)
    if (it->second.count > best->second.count) best = it;
  const Material& e = *best->second.example;
  m.units.name = std::string(best->first);
  m.units.source = fmt::format(
      "inferred from {} of {} metal materials (e.g. {} {}: density {:g}, E {:g})",
      best->second.count, metals, materials::keywordOf(e.law), e.id, e.rho, youngOfParams(e.law));
}

std::string describeUnits(const UnitSystem& u) {
  for (const auto& s : kSystems)
    if (s.name == u.name)
      return fmt::format("{} (mass {}, length {}, time {}, force {}, stress {})", s.name, s.mass,
                         s.length, s.time, s.force, s.stress);
  return "not known";
}

}  // namespace crumple::model
