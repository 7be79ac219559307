// *MAT_FRAZER_NASH_RUBBER_MODEL (031): the Frazer-Nash rubber of LS-DYNA (Keyword Manual vol.
// II, *MAT_FRAZER_NASH_RUBBER_MODEL; Theory Manual, "Material Model 31: Frazer-Nash Rubber",
// after Kenchington, "A non-linear elastic material model for DYNA3D", 1988). Solids only here
// (ELFORM 1, 10). The strain energy
//   U = C100 I1 + C200 I1^2 + C300 I1^3 + C400 I1^4 + C110 I1 I2 + C210 I1^2 I2
//       + C010 I2 + C020 I2^2 + f(J)
// is written, as the Theory Manual writes it, in the invariants of a Green-St. Venant strain,
// I1 = tr E and I2 = ((tr E)^2 - E:E) / 2, and J = det F, with S = dU/dE turned into the Cauchy
// stress. The manual calls f(J) the hydrostatic work term and does not give it. Here E is the
// Green strain of the isochoric part C_bar = J^-2/3 C, so that the polynomial is the distortional
// energy and f(J) = K (J - 1)^2 / 2 the hydrostatic one (Flory's split; Holzapfel, "Nonlinear
// Solid Mechanics", 2000, sec. 6.4): sigma = dev(F_bar S_bar F_bar^T) / J + K (J - 1) I. The
// shear modulus is G = C100 - C010 / 2 and K = 2 G (1 + nu) / (3 (1 - 2 nu)) from PR. The
// polynomial of the full (not isochoric) E with a quadratic f(J) was tried first: with the
// coefficients the LSTC deck's fit gives, its compressible response softens in volume and the
// squeezed hex pulls (docs/theory.md: doubtful, LS-DYNA's own f and strain are not published).
// With LCID the coefficients C100..C020 are flags (1: the term takes part in the least-squares
// fit to the uniaxial test curve, force vs change in gauge length; SGL, SW, ST), the stretch
// taken as incompressible, lambda and lambda^-1/2. EXIT = 0 (stop when a principal Green strain
// leaves [EMIN, EMAX]) is refused; EXIT != 0 runs the polynomial past the limits (LS-DYNA
// extrapolates), so EMAX and EMIN change nothing. REF = 1 is refused.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "materials/hyperelastic.hpp"
#include "materials/law.hpp"

namespace crumple::materials {

struct FrazerNash {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_FRAZER_NASH_RUBBER_MODEL",
                                                             "*MAT_031"};
  static constexpr Cost kCost = Cost::Elastic;
  static constexpr bool kPlastic = false;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  static constexpr bool kDeformationGradient = true;

  // The eight terms in card order: C100 C200 C300 C400 C110 C210 C010 C020.
  static constexpr int kTerms = 8;
  struct Params {
    using Law = FrazerNash;
    double nu = 0;
    double c[kTerms] = {};
    double sgl = 0, sw = 0, st = 0;
    int32_t curve = -1;  // model curve index of LCID (the fit), -1 without
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static FrazerNash make(const Params& p, const CurveAt& curves, const std::string& at);

  Moduli moduli;  // the small-strain K and G (wave speed, hourglass control)
  double c100 = 0, c200 = 0, c300 = 0, c400 = 0, c110 = 0, c210 = 0, c010 = 0, c020 = 0;
  void update(PointBatch& p) const;
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return 0.0; }
  // The strain energy per unit initial volume at the point's B (for tests and checks).
  double energy(const LeftCauchyGreen& k) const;
};

}  // namespace crumple::materials
