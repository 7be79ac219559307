// *MAT_BLATZ-KO_RUBBER (007): the Blatz-Ko rubber of LS-DYNA (Keyword Manual vol. II,
// *MAT_BLATZ-KO_RUBBER: MID RO G REF; Theory Manual, "Material Model 7: Blatz-Ko Rubber"), one
// parameter, the shear modulus G, with Poisson's ratio fixed at nu = 0.463. Solids only here
// (ELFORM 1, 10), as the other rubbers.
// The Theory Manual gives the stress, not an energy: S_ij = G (V^-1 C_ij - V^(-1/(1-2 nu))
// delta_ij), V the relative volume, pushed forward as sigma = V^-1 F S F^T. Here it is taken from
// the energy of Blatz and Ko (1962, "Application of finite elastic theory to the deformation of
// rubbery materials", Trans. Soc. Rheology 6) with f = 1,
//   W = G/2 [ (I1 - 3) + (I3^-beta - 1) / beta ],   beta = nu / (1 - 2 nu),
// in the invariants of C = F^T F. S = 2 dW/dC = G (I - I3^-beta C^-1), and
//   sigma = J^-1 F S F^T = G (J^-1 B - J^(-1/(1-2 nu)) I)      (1 + 2 beta = 1 / (1 - 2 nu)),
// which is the manual's formula with the left Cauchy-Green tensor B = F F^T in place of C, read
// as the Cauchy stress. Read literally (C, then pushed forward) the manual's S is the derivative
// of no energy: d(J^-1 C)/dC lacks the major symmetry, so work around a closed path would not
// vanish. Both readings agree to first order (shear modulus G, Poisson's ratio nu);
// docs/theory.md says why this one was chosen (doubtful: LS-DYNA's code is not published).
// REF = 1 (*INITIAL_FOAM_REFERENCE_GEOMETRY) is refused.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "materials/hyperelastic.hpp"
#include "materials/law.hpp"

namespace crumple::materials {

struct BlatzKo {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_BLATZ-KO_RUBBER", "*MAT_007"};
  static constexpr Cost kCost = Cost::Elastic;
  static constexpr bool kPlastic = false;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  static constexpr bool kDeformationGradient = true;
  // Poisson's ratio, fixed by LS-DYNA (Theory Manual, Material Model 7).
  static constexpr double kNu = 0.463;

  struct Params {
    using Law = BlatzKo;
    double G = 0;
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static BlatzKo make(const Params& p, const CurveAt& curves, const std::string& at);

  Moduli moduli;  // the small-strain K and G (wave speed, hourglass control)
  double beta = 0;
  void update(PointBatch& p) const;
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return 0.0; }
  // The strain energy per unit initial volume at the point's B (for tests and checks).
  double energy(const LeftCauchyGreen& k) const;
};

}  // namespace crumple::materials
