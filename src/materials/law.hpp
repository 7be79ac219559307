// What every material law shares, and the shape of a law unit.
//
// A law is one unit: one header and one source file in src/materials/laws/ and one line in
// src/materials/registry.hpp. The unit is a struct (Serac's material pattern: parameters, a
// state layout and const updates; ../shared/STYLE.md) that declares
//   kKeywords                  the *MAT_ names it reads (first: the name in messages)
//   kCost                      its cost class for the partitioner's element weights
//   kPlastic, kKinematic       its history: effective plastic strain, back stress
//   kHistory (optional)        further history variables per point (0 when not declared;
//                              at most kMaxHistory), stored by the blocks and dumps
//   kDensity                   false for spring and damper laws (no RO field)
//   kEos (optional)            its solids take the part's equation of state (*PART EOSID,
//                              required): make() then has a fourth parameter, the Eos
//                              (materials/eos.hpp); a part of another law with one is refused
//   kMassOnlyStructures (opt.) its shells and beams are bypassed: mass and inertia only, no
//                              force and no time step (LS-DYNA's null shells and beams)
//   kDeformationGradient (opt.) its stress is a function of the deformation gradient F
//                              (hyperelastic laws): the one-point solids give PointBatch::F,
//                              and parts of other solid formulations are refused
//   kShellStrain (optional)    its shell points keep the accumulated in-plane logarithmic
//                              strain (xx, yy, xy in the element frame) in the 3 alpha fields
//                              of a point (hyperelastic laws, whose shell stress is a function
//                              of it: PlaneStressPoints::alpha)
//   kWaveModulus (optional)    its update reports each point's wave modulus rho c^2 at the new
//                              state in PointBatch::modulus (laws whose tangent grows with the
//                              deformation beyond what constant moduli can bound: *MAT_057); the
//                              one-point solids take the larger of it and lambda + 2 mu for the
//                              point's wave speed (stable step, bulk viscosity, hourglass)
//   kElementGeometry (opt.)    its one-point solids give the law each element's edges x2 - x1
//                              and x4 - x1 at x(n) (PointBatch::edge: material axes from the
//                              element's nodes, LS-DYNA's AOPT 0) and its characteristic length
//                              at the mid-step geometry (PointBatch::length: viscous stresses
//                              of the form rho c L D); with kDeformationGradient only (the
//                              one-point solids are the only ones that give them)
//   kLayered (optional)        an orthotropic shell law: its shell points get their layer's
//                              angle (PlaneStressPoints::ply, *SECTION_SHELL ICOMP 1) and the
//                              elements take their transverse shear moduli from
//                              transverseShear(angle, g) (g[0] xz-xz, g[1] yz-yz, g[2] the
//                              coupling, in the element frame), averaged over the layers
//   kPointFailure (optional)   its plane-stress update sets PlaneStressPoints::failed itself
//                              (a failed point carries no stress; the element erodes when all
//                              its points have failed), whatever failureStrain() says
//   bulkViscosity() (optional) false when the law's solids take no bulk viscosity (LS-DYNA's
//                              *MAT_LOW_DENSITY_FOAM BVFLAG 0); else *CONTROL_BULK_VISCOSITY's
//   kBeamOnly (optional)       the one *SECTION_BEAM ELFORM its beam parts may use (a BeamOnly,
//                              which may allow solid parts too); parts of other sections are
//                              refused (model/build_mesh.cpp)
//   solidRefusal(Params) (opt.) why its solids cannot run these parameters (what only its beams
//                              do), else empty: a solid part of it is then refused
//   massDensity(ro) (optional) the density of its beams' nodal masses from RO (else RO)
//   Params                     the deck's parameters, stored in the Model (trivially copyable:
//                              the Model is sent to the other ranks as bytes); Params::Law
//                              names the unit
//   cards()                    its card layout (field names, widths, defaults)
//   read(LawInput&)            its deck reader: cards -> Params, with the checks of the fields
//   make(Params, CurveAt)      the law the kernels use (curves and tables resolved)
// and, for each element family it can be used with, the update that family calls:
//   update(PointBatch&)                      solids (3-D stress)
//   updatePlaneStress(PlaneStressPoints&)    shells (plane stress)
//   fibre()                                  beams and trusses (uniaxial, materials/uniaxial)
//   discrete()                               springs and dampers (force vs elongation)
// with failureStrain() (erosion; 0 = none) and deletionStep() (TDEL; 0 = none). A law that
// lacks the update of a family its part uses is refused when the model is built, naming the
// part (model/build_mesh.cpp, finishParts); kernels never fall back to another law.
//
// Voigt order everywhere: xx, yy, zz, xy, yz, zx, tensor (not engineering) shear components.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace crumple::deck {
class Card;
struct FieldSpec;
struct KeywordSpec;
}  // namespace crumple::deck

namespace crumple::materials {

// History variables a law may keep per point besides eps_p and alpha.
inline constexpr int kMaxHistory = 8;

// The number of history variables of a law (its kHistory, else 0).
template <class L>
constexpr int historyOf() {
  if constexpr (requires { L::kHistory; }) {
    static_assert(L::kHistory >= 0 && L::kHistory <= kMaxHistory, "kHistory out of range");
    return L::kHistory;
  } else {
    return 0;
  }
}

// Whether the law's stress is a function of the deformation gradient (its kDeformationGradient,
// else false).
template <class L>
constexpr bool needsDeformationGradient() {
  if constexpr (requires { L::kDeformationGradient; })
    return L::kDeformationGradient;
  else
    return false;
}

// Whether the law's one-point solids give it the element's edges and length (its
// kElementGeometry, else false).
template <class L>
constexpr bool needsElementGeometry() {
  if constexpr (requires { L::kElementGeometry; }) {
    static_assert(!L::kElementGeometry || needsDeformationGradient<L>(),
                  "kElementGeometry needs kDeformationGradient (one-point solids only)");
    return L::kElementGeometry;
  } else {
    return false;
  }
}

// Whether the law's shell points keep their in-plane strain (its kShellStrain, else false).
template <class L>
constexpr bool keepsShellStrain() {
  if constexpr (requires { L::kShellStrain; })
    return L::kShellStrain;
  else
    return false;
}

// Whether the law's shell points keep 3 alpha fields each: the back stress of kinematic
// hardening, or the strain of kShellStrain.
template <class L>
constexpr bool shellAlphaOf() {
  return L::kKinematic || keepsShellStrain<L>();
}

// Whether the law is an orthotropic layered shell law (its kLayered, else false).
template <class L>
constexpr bool isLayered() {
  if constexpr (requires { L::kLayered; })
    return L::kLayered;
  else
    return false;
}

// Whether the law's plane-stress update fails points itself (its kPointFailure, else false).
template <class L>
constexpr bool failsPoints() {
  if constexpr (requires { L::kPointFailure; })
    return L::kPointFailure;
  else
    return false;
}

// Whether the law reports its points' wave modulus (its kWaveModulus, else false).
template <class L>
constexpr bool reportsWaveModulus() {
  if constexpr (requires { L::kWaveModulus; })
    return L::kWaveModulus;
  else
    return false;
}

// Whether the law's solids take the bulk viscosity (its bulkViscosity(), else true).
template <class L>
bool takesBulkViscosity(const L& law) {
  if constexpr (requires { law.bulkViscosity(); })
    return law.bulkViscosity();
  else
    return true;
}

// A batch of n integration points; every pointer addresses n contiguous values.
struct PointBatch {
  int n = 0;
  double dt = 0.0;
  double* s[6] = {};            // stress, in/out
  const double* de[6] = {};     // strain increment D*dt, in
  double* eps_p = nullptr;      // effective plastic strain, in/out (laws with plasticity)
  double* alpha[6] = {};        // back stress, in/out (laws with kinematic hardening)
  uint8_t* failed = nullptr;    // out: set to 1 when the point reaches the failure strain
  double* h[kMaxHistory] = {};  // the law's history variables h[0..kHistory), in/out
  // The deformation gradient F_ij = dx_i/dX_j at x(n) from the initial geometry, row-major
  // (F[3 i + j]), in; given only to laws that declare kDeformationGradient, else null.
  const double* F[9] = {};
  // Out, for laws that declare kWaveModulus (else null): each point's wave modulus rho c^2 at
  // the new state, c the fastest wave speed in the current configuration.
  double* modulus = nullptr;
  // In, for laws that declare kElementGeometry (else null): the element's edge vectors from its
  // node 1 to its nodes 2 and 4 at x(n) (edge[0..2] = x2 - x1, edge[3..5] = x4 - x1), and its
  // characteristic length (volume over largest face area; the tetrahedron's least altitude) at
  // the mid-step geometry x(n-1/2).
  const double* edge[6] = {};
  const double* length = nullptr;
};

// A law that runs on one beam formulation only: its ELFORM and what to call those beams in
// messages.
struct BeamOnly {
  int elform = 0;
  std::string_view what;
  bool solids = false;  // solid parts may use it too
};

// Elastic moduli every continuum law exposes for wave speeds and hourglass control.
struct Moduli {
  double bulk = 0.0;   // K
  double shear = 0.0;  // G
};

// Bulk and shear modulus from E and nu.
Moduli moduliFromYoung(double E, double nu);
// Bulk and shear modulus from G and nu: K = 2 G (1 + nu) / (3 (1 - 2 nu)) (the small-strain
// moduli of the rubbers, whose decks give a shear modulus and Poisson's ratio).
Moduli moduliFromShear(double G, double nu);

// Young's modulus from the bulk and shear moduli the laws store.
inline double youngOf(const Moduli& m) {
  return 9.0 * m.bulk * m.shear / (3.0 * m.bulk + m.shear);
}

// Plastic hardening modulus dsigma/deps_p of a bilinear curve with tangent Etan, so that the
// uniaxial slope after yield, E Ep / (E + Ep), is Etan. Precondition Etan < E (the readers).
inline double plasticModulus(double E, double etan) {
  return E * etan / (E - etan);
}

// The partitioner's cost classes (docs/parallel.md, "Element weights").
enum class Cost : uint8_t { Elastic, Plastic, Rigid, Discrete };

// A curve as a law sees it (a view into the Model's curves).
struct CurveData {
  int64_t id = 0;
  std::span<const double> x, y;
};
// A *DEFINE_TABLE as a law sees it: one curve (model curve index) per value, the values
// increasing (a view into the Model's tables).
struct TableData {
  int64_t id = 0;
  std::span<const double> values;
  std::span<const int32_t> curves;
};
// The Model's curves and tables as make() sees them: curves(i) is the curve with model curve
// index i, curves.table(i) the table with model table index i. Built from a callable for
// curves alone (a law without tables, the tests), or from both.
class CurveAt {
 public:
  using Curves = std::function<CurveData(int32_t)>;
  using Tables = std::function<TableData(int32_t)>;
  CurveAt() = default;
  // Implicit, so that a callable for curves alone converts as it did before tables.
  template <class F, class = std::enable_if_t<std::is_convertible_v<F, Curves> &&
                                              !std::is_same_v<std::decay_t<F>, CurveAt>>>
  CurveAt(F curves) : curves_(std::move(curves)) {}  // NOLINT(google-explicit-constructor)
  CurveAt(Curves curves, Tables tables) : curves_(std::move(curves)), tables_(std::move(tables)) {}
  CurveData operator()(int32_t i) const { return curves_(i); }
  // A table; throws std::logic_error when built without tables (a coding error: a reader
  // gives a table index only where the model has tables).
  TableData table(int32_t i) const;

 private:
  Curves curves_;
  Tables tables_;
};

// What a law's deck reader may ask of the model builder: its cards in order, verdicts on
// values Crumple cannot honour, and curves. The builder implements it (model/build_mesh.cpp),
// so a law's reader sees no model internals.
class LawInput {
 public:
  virtual ~LawInput() = default;
  // The card with this label of the law's cards(); read once, in the order asked.
  virtual const deck::Card& card(std::string_view label) = 0;
  // The same for a card the deck may leave out (then all its fields take their defaults).
  virtual const deck::Card& optionalCard(std::string_view label) = 0;
  // A value that changes the answer and that Crumple cannot honour: the deck is refused
  // (run --ignore-unsupported goes on without it).
  virtual void reject(const deck::Card& c, std::string_view field, const std::string& why) = 0;
  // A value read but not honoured that does not change the answer: noted in the report.
  virtual void ignore(const deck::Card& c, std::string_view field, const std::string& why) = 0;
  // The model index of the curve a field names; an input error when it is not defined.
  virtual int32_t curve(const deck::Card& c, std::string_view field, int64_t id) = 0;
  // As curve(), but a curve that is defined by a keyword Crumple does not support refuses the
  // deck (reject) and gives -1.
  virtual int32_t curveOrReject(const deck::Card& c, std::string_view field, int64_t id) = 0;
  // The model index of the *DEFINE_TABLE with this id, or -1 when no table has it (the id may
  // name a curve). A table is read and checked where it is defined (model/build_sets.cpp).
  virtual int32_t table(const deck::Card& c, std::string_view field, int64_t id) = 0;
  // Stores a curve the law defines in its own cards; returns its model curve index.
  virtual int32_t addCurve(int64_t id, std::vector<double> x, std::vector<double> y) = 0;
  // The material's id (MID).
  virtual int64_t materialId() const = 0;
};

// Reads and checks the fields E and PR of an isotropic law (Card::fail on a bad value).
void readElastic(const deck::Card& c, double& E, double& nu);
// SIGY positive and ETAN in [0, E) (Card::fail on a bad value).
void checkYield(const deck::Card& c, double E, double sigy, double etan);
// The same checks in make(), for parameters that did not come through a reader (a Model built
// in code or received as bytes): util::InputError prefixed by `at`. E and nu must give
// positive K and G; ETAN must lie in [0, E) (Ep = E Etan / (E - Etan) is singular at E).
void checkModuli(const std::string& at, double E, double nu);
void checkTangent(const std::string& at, double E, double etan);

}  // namespace crumple::materials
