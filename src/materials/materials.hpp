// The material laws as the rest of Crumple sees them: the deck's parameters of any law
// (LawParams, stored in the Model), the law a continuum element kernel runs (Law: a variant
// over the laws that have stress updates, so a kernel is instantiated per law and makes no
// virtual call per point) and the questions asked of a law by the model builder, the
// partitioner and the solver. All of it is generated from the list in registry.hpp.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include "materials/eos.hpp"
#include "materials/registry.hpp"

namespace crumple::materials {

// The element families a law can serve.
enum class Family : uint8_t { Solid, Shell, Beam, Discrete };

// A kernel law with the update of each continuum family (law.hpp).
template <class L>
concept SolidLaw = requires(const L& l, PointBatch& b) {
  l.update(b);
};
template <class L>
concept ShellLaw = requires(const L& l, PlaneStressPoints& b) {
  l.updatePlaneStress(b);
};
template <class L>
concept BeamLaw = requires(const L& l) {
  l.fibre();
};

// Thrown by a kernel handed a law without its family's update: the model builder refuses such
// a part (finishParts), so this is a coding error, never an input one.
[[noreturn]] void noUpdateFor(Family f);

namespace detail {

template <class List>
struct Variants;
template <class... L>
struct Variants<LawList<L...>> {
  using Params = std::variant<typename L::Params...>;
};

template <class T, class... Ts>
struct AppendUnique {
  using type = std::conditional_t<(std::is_same_v<T, Ts> || ...), std::variant<Ts...>,
                                  std::variant<Ts..., T>>;
};
template <class V, class... L>
struct RuntimeOf;
template <class... Ts>
struct RuntimeOf<std::variant<Ts...>> {
  using type = std::variant<Ts...>;
};
template <class... Ts, class L, class... Rest>
struct RuntimeOf<std::variant<Ts...>, L, Rest...> {
  using Made =
      decltype(L::make(std::declval<const typename L::Params&>(), std::declval<const CurveAt&>(),
                       std::declval<const std::string&>()));
  // Continuum laws only: a law whose make() gives a continuum law adds it once.
  using Next = std::conditional_t < requires(const Made& m) { m.moduli; }
  , typename AppendUnique<Made, Ts...>::type, std::variant < Ts... >> ;
  using type = typename RuntimeOf<Next, Rest...>::type;
};
template <class List>
struct Runtime;
template <class... L>
struct Runtime<LawList<L...>> {
  using type = typename RuntimeOf<std::variant<>, L...>::type;
};

}  // namespace detail

// The deck's parameters of any law.
using LawParams = detail::Variants<AllLaws>::Params;
// The law of a continuum element block.
using Law = detail::Runtime<AllLaws>::type;

template <class P>
using UnitOf = typename P::Law;

// "*MAT_ELASTIC", "*MAT_RIGID", ... for messages and summaries.
std::string_view keywordOf(const LawParams& p);
// LS-DYNA's material type number (1 for *MAT_ELASTIC = *MAT_001, 24 for *MAT_024, ...), from
// the law's numbered keyword; 0 for laws numbered otherwise (*MAT_S01). For elout.
int typeNumberOf(const LawParams& p);
// Whether the law has an update for the element family (rigid laws serve every continuum
// family; spring and damper laws only discrete elements).
bool supports(const LawParams& p, Family f);
// The cost class of the law for the partitioner.
Cost costOf(const LawParams& p);
// False for spring and damper laws, which have no density field.
bool hasDensity(const LawParams& p);
bool isRigid(const LawParams& p);
// The number of history variables of the law's points (materials::historyOf of its unit).
int historyCountOf(const LawParams& p);
// Whether the law's solids take the part's equation of state (its unit declares kEos).
bool usesEos(const LawParams& p);
// Whether the law's shells and beams give mass only (its unit declares kMassOnlyStructures).
bool massOnlyStructures(const LawParams& p);
// Whether the law's stress is a function of the deformation gradient (hyperelastic laws; its
// unit declares kDeformationGradient): only the one-point solids give it.
bool needsDeformationGradient(const LawParams& p);

// The one beam formulation the law runs on (its unit's kBeamOnly), or null for any.
const BeamOnly* beamOnlyOf(const LawParams& p);
// What the law's parameters need that its solids do not have (its unit's
// solidRefusal(Params), e.g. a spot weld's resultant failure), or empty.
std::string solidRefusalOf(const LawParams& p);

// The kernel law of a continuum part; `at` prefixes messages ("deck.k:12: *MAT_ELASTIC 3: ").
// `eos` is the part's equation of state, given to a law that declares kEos (solid blocks).
// Throws util::InputError when the parameters are unusable, the law has no continuum update or
// an equation of state is given to a law that has its own pressure response.
Law makeLaw(const LawParams& p, const CurveAt& curves, const std::string& at,
            const Eos* eos = nullptr);
// The law of a discrete part; throws util::InputError for a law that is not a spring or damper.
DiscreteLaw makeDiscreteLaw(const LawParams& p, const CurveAt& curves, const std::string& at);

// Questions every kernel law answers.
inline const Moduli& moduliOf(const Law& law) {
  return std::visit([](const auto& l) -> const Moduli& { return l.moduli; }, law);
}
inline double deletionStepOf(const Law& law) {
  return std::visit([](const auto& l) { return l.deletionStep(); }, law);
}
inline double failureStrainOf(const Law& law) {
  return std::visit([](const auto& l) { return l.failureStrain(); }, law);
}
inline bool isPlastic(const Law& law) {
  return std::visit([](const auto& l) { return std::decay_t<decltype(l)>::kPlastic; }, law);
}
inline int historyCount(const Law& law) {
  return std::visit([](const auto& l) { return historyOf<std::decay_t<decltype(l)>>(); }, law);
}
inline bool needsDeformationGradient(const Law& law) {
  return std::visit(
      [](const auto& l) { return needsDeformationGradient<std::decay_t<decltype(l)>>(); }, law);
}
inline bool isKinematic(const Law& law) {
  return std::visit([](const auto& l) { return std::decay_t<decltype(l)>::kKinematic; }, law);
}
// Whether the law's shell points keep 3 alpha fields (materials::shellAlphaOf).
inline bool hasShellAlpha(const Law& law) {
  return std::visit([](const auto& l) { return shellAlphaOf<std::decay_t<decltype(l)>>(); }, law);
}
// The density of a beam block's nodal masses for the material density ro (the unit's
// massDensity, else ro).
inline double massDensityOf(const Law& law, double ro) {
  return std::visit(
      [ro](const auto& l) {
        if constexpr (requires { l.massDensity(ro); })
          return l.massDensity(ro);
        else
          return ro;
      },
      law);
}
// The beam fibre law; throws std::logic_error for a law without one (refused at build).
FibreLaw fibreLawOf(const Law& law);

}  // namespace crumple::materials
