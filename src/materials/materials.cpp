// What the rest of Crumple asks of a law, answered for every law of registry.hpp, and the
// checks the law units share.
#include "materials/materials.hpp"

#include <stdexcept>

#include "deck/card.hpp"
#include "util/error.hpp"

namespace crumple::materials {

Moduli moduliFromYoung(double E, double nu) {
  // Isotropic linear elasticity: K = E / (3 (1 - 2 nu)), G = E / (2 (1 + nu)).
  return Moduli{E / (3.0 * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

Moduli moduliFromShear(double G, double nu) {
  return Moduli{2.0 * G * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu)), G};
}

void readElastic(const deck::Card& c, double& E, double& nu) {
  E = c.real("E");
  nu = c.real("PR");
  if (E <= 0) c.fail("E", "Young's modulus must be positive");
  if (!(nu > -1.0 && nu < 0.5)) c.fail("PR", "Poisson's ratio must lie in (-1, 0.5)");
}

void checkYield(const deck::Card& c, double E, double sigy, double etan) {
  if (sigy <= 0) c.fail("SIGY", "the yield stress must be positive");
  if (etan < 0 || etan >= E) c.fail("ETAN", "the tangent modulus must lie in [0, E)");
}

void checkModuli(const std::string& at, double E, double nu) {
  if (!(E > 0.0)) throw util::InputError(at + "E must be positive");
  if (!(nu > -1.0 && nu < 0.5)) throw util::InputError(at + "PR must lie in (-1, 0.5)");
}

void checkTangent(const std::string& at, double E, double etan) {
  if (!(etan >= 0.0 && etan < E)) throw util::InputError(at + "ETAN must lie in [0, E)");
}

TableData CurveAt::table(int32_t i) const {
  if (!tables_) throw std::logic_error("a law asked for a table of a model without tables");
  return tables_(i);
}

namespace {

template <class U>
using Made = decltype(U::make(std::declval<const typename U::Params&>(),
                              std::declval<const CurveAt&>(), std::declval<const std::string&>()));

template <class U>
constexpr bool kContinuum = requires(const Made<U>& m) {
  m.moduli;
};

template <class U>
constexpr bool supportsFamily(Family f) {
  if constexpr (requires { U::kRigid; }) return f != Family::Discrete;
  // Bypassed shells and beams need no update (their blocks give mass only).
  if constexpr (requires { U::kMassOnlyStructures; })
    if (f == Family::Shell || f == Family::Beam) return true;
  if constexpr (std::is_same_v<Made<U>, DiscreteLaw>) return f == Family::Discrete;
  using M = Made<U>;
  switch (f) {
    case Family::Solid:
      return SolidLaw<M>;
    case Family::Shell:
      return ShellLaw<M>;
    case Family::Beam:
      return BeamLaw<M>;
    case Family::Discrete:
      return false;
  }
  return false;
}

}  // namespace

std::string_view keywordOf(const LawParams& p) {
  return std::visit([](const auto& l) { return UnitOf<std::decay_t<decltype(l)>>::kKeywords[0]; },
                    p);
}

int typeNumberOf(const LawParams& p) {
  const std::string_view numbered = std::visit(
      [](const auto& l) { return UnitOf<std::decay_t<decltype(l)>>::kKeywords.back(); }, p);
  constexpr std::string_view kPrefix = "*MAT_";
  if (numbered.substr(0, kPrefix.size()) != kPrefix) return 0;
  int n = 0;
  for (char c : numbered.substr(kPrefix.size())) {
    if (c < '0' || c > '9') return 0;
    n = 10 * n + (c - '0');
  }
  return n;
}

bool supports(const LawParams& p, Family f) {
  return std::visit(
      [f](const auto& l) { return supportsFamily<UnitOf<std::decay_t<decltype(l)>>>(f); }, p);
}

Cost costOf(const LawParams& p) {
  return std::visit([](const auto& l) { return UnitOf<std::decay_t<decltype(l)>>::kCost; }, p);
}

bool hasDensity(const LawParams& p) {
  return std::visit([](const auto& l) { return UnitOf<std::decay_t<decltype(l)>>::kDensity; }, p);
}

bool isRigid(const LawParams& p) {
  return std::visit(
      [](const auto& l) {
        return requires {
          UnitOf<std::decay_t<decltype(l)>>::kRigid;
        };
      },
      p);
}

int historyCountOf(const LawParams& p) {
  return std::visit([](const auto& l) { return historyOf<UnitOf<std::decay_t<decltype(l)>>>(); },
                    p);
}

bool usesEos(const LawParams& p) {
  return std::visit(
      [](const auto& l) {
        return requires {
          UnitOf<std::decay_t<decltype(l)>>::kEos;
        };
      },
      p);
}

bool massOnlyStructures(const LawParams& p) {
  return std::visit(
      [](const auto& l) {
        return requires {
          UnitOf<std::decay_t<decltype(l)>>::kMassOnlyStructures;
        };
      },
      p);
}

bool needsDeformationGradient(const LawParams& p) {
  return std::visit(
      [](const auto& l) { return needsDeformationGradient<UnitOf<std::decay_t<decltype(l)>>>(); },
      p);
}

const BeamOnly* beamOnlyOf(const LawParams& p) {
  return std::visit(
      [](const auto& l) -> const BeamOnly* {
        using U = UnitOf<std::decay_t<decltype(l)>>;
        if constexpr (requires { U::kBeamOnly; })
          return &U::kBeamOnly;
        else
          return nullptr;
      },
      p);
}

std::string solidRefusalOf(const LawParams& p) {
  return std::visit(
      [](const auto& l) -> std::string {
        using U = UnitOf<std::decay_t<decltype(l)>>;
        if constexpr (requires { U::solidRefusal(l); })
          return U::solidRefusal(l);
        else
          return {};
      },
      p);
}

Law makeLaw(const LawParams& p, const CurveAt& curves, const std::string& at, const Eos* eos) {
  return std::visit(
      [&](const auto& params) -> Law {
        using U = UnitOf<std::decay_t<decltype(params)>>;
        if constexpr (!kContinuum<U>) {
          throw util::InputError(at +
                                 "is a spring or damper material: only discrete elements "
                                 "(*ELEMENT_DISCRETE) can use it");
        } else if constexpr (requires { U::kEos; }) {
          return U::make(params, curves, at, eos);
        } else {
          if (eos)
            throw util::InputError(at +
                                   "has its own pressure response: it cannot use an equation "
                                   "of state (*PART EOSID)");
          return U::make(params, curves, at);
        }
      },
      p);
}

DiscreteLaw makeDiscreteLaw(const LawParams& p, const CurveAt& curves, const std::string& at) {
  return std::visit(
      [&](const auto& params) -> DiscreteLaw {
        using U = UnitOf<std::decay_t<decltype(params)>>;
        if constexpr (std::is_same_v<Made<U>, DiscreteLaw>)
          return U::make(params, curves, at);
        else
          throw util::InputError(at +
                                 "is not a spring or damper material: discrete elements "
                                 "need one");
      },
      p);
}

void noUpdateFor(Family f) {
  static constexpr const char* kNames[] = {"solid", "shell", "beam", "discrete"};
  throw std::logic_error(std::string("a law without a ") + kNames[static_cast<int>(f)] +
                         " update reached its kernel");
}

FibreLaw fibreLawOf(const Law& law) {
  return std::visit(
      [](const auto& l) -> FibreLaw {
        if constexpr (BeamLaw<std::decay_t<decltype(l)>>)
          return l.fibre();
        else
          noUpdateFor(Family::Beam);
      },
      law);
}

}  // namespace crumple::materials
