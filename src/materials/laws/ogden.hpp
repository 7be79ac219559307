// *MAT_OGDEN_RUBBER (077_O): the Ogden rubber of LS-DYNA (Keyword Manual vol. II,
// *MAT_OGDEN_RUBBER; Theory Manual, "Material Model 77: Hyperelastic and Ogden Rubber Model";
// Ogden, "Large deformation isotropic elasticity", Proc. R. Soc. Lond. A 326, 1972). Solids only
// here (ELFORM 1, 10), as the other rubbers. The strain energy per unit initial volume
//   W = sum_i=1..3 sum_j=1..n (mu_j / alpha_j) (lbar_i^alpha_j - 1) + K (J - 1 - ln J)
// is written, as the manuals write it, in the principal stretches of the isochoric part,
// lbar_i = J^-1/3 lambda_i (the lambda_i^2 are the principal values of B = F F^T, found by
// materials/principal), with up to 8 terms MU_j, ALPHA_j. The coefficient of each term is
// mu_j / alpha_j (Ogden 1972; not Abaqus's 2 mu_j / alpha_j^2), so the small-strain shear
// modulus is G = sum_j mu_j alpha_j / 2, and one term with alpha = 2 is the neo-Hookean solid
// with G = mu. K = 2 G (1 + nu) / (3 (1 - 2 nu)) from PR. The principal Kirchhoff stresses
//   tau_i = sum_j mu_j (lbar_i^alpha_j - (1/3) sum_k lbar_k^alpha_j) + K (J - 1)
// (Theory Manual; Holzapfel, "Nonlinear Solid Mechanics", 2000, sec. 6.4, 6.5) on the principal
// axes of B give the Cauchy stress sigma = tau / J: a function of F alone, no history.
// PR < 0 means Poisson's ratio |PR| and an extra card 2, whose hysteresis table TBHYS and
// compression compliances D1-D3 are refused. Also refused: N > 0 (the nonlinear fit of MU_j,
// ALPHA_j to test curves), N = -1 (MU_j, ALPHA_j as curves of temperature), G != 0 (the
// frequency-independent frictional damping with SIGF), viscoelastic cards with GI != 0, REF = 1.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "materials/hyperelastic.hpp"
#include "materials/law.hpp"

namespace crumple::materials {

struct Ogden {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_OGDEN_RUBBER", "*MAT_077_O"};
  static constexpr Cost kCost = Cost::Elastic;
  static constexpr bool kPlastic = false;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  static constexpr bool kDeformationGradient = true;

  static constexpr int kTerms = 8;
  struct Params {
    using Law = Ogden;
    double nu = 0;
    double mu[kTerms] = {}, alpha[kTerms] = {};  // a term with mu = 0 is absent
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static Ogden make(const Params& p, const CurveAt& curves, const std::string& at);

  Moduli moduli;  // the small-strain K and G (wave speed, hourglass control)
  int terms = 0;  // the terms with mu != 0, first in mu and alpha
  double mu[kTerms] = {}, alpha[kTerms] = {};
  void update(PointBatch& p) const;
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return 0.0; }
  // The principal Cauchy stresses at the principal values b of B (any order) and J = det F.
  std::array<double, 3> principalStress(const std::array<double, 3>& b, double J) const;
  // The strain energy per unit initial volume at the point's B (for tests and checks).
  double energy(const LeftCauchyGreen& k) const;
};

}  // namespace crumple::materials
