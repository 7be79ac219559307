// *MAT_VISCOELASTIC (006): linear viscoelasticity in shear with one relaxation time, elastic in
// bulk (LS-DYNA Keyword Manual vol. II, *MAT_VISCOELASTIC; Theory Manual, material model 6,
// after Herrmann and Peterson 1968). The deviatoric stress is the hereditary integral
//   s'(t) = 2 int_0^t G(t - tau) D'(tau) dtau,   G(t) = GI + (G0 - GI) exp(-BETA t),
// with the Jaumann rate, and the pressure p = -K ln(V / V0) (K = BULK). The integral splits
// into a long-term part 2 GI int D' and a relaxing part h, dh/dt = 2 (G0 - GI) D' - BETA h,
// which is integrated exactly for D' constant over a step:
//   h(n+1) = exp(-BETA dt) h(n) + 2 (G0 - GI) (1 - exp(-BETA dt)) / (BETA dt) de'.
// h is a deviatoric tensor that must turn with the material, so it is kept in the back-stress
// slots (kKinematic), which every kernel rotates with the stress; the shells keep its in-plane
// components (h_zz = -(h_xx + h_yy): h has no trace). Solids and shells (plane stress: the
// thickness strain that makes sigma_zz = 0 solves one linear equation); beams are refused.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "materials/law.hpp"
#include "materials/plane_stress.hpp"

namespace crumple::materials {

struct Viscoelastic {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_VISCOELASTIC", "*MAT_006"};
  static constexpr Cost kCost = Cost::Elastic;
  static constexpr bool kPlastic = false;
  static constexpr bool kKinematic = true;  // the back-stress slots hold the relaxing stress h
  static constexpr bool kDensity = true;

  struct Params {
    using Law = Viscoelastic;
    double bulk = 0, g0 = 0, gi = 0, beta = 0;
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static Viscoelastic make(const Params& p, const CurveAt& curves, const std::string& at);

  Moduli moduli;  // K and the instantaneous shear modulus G0 (wave speed, hourglass)
  double gi = 0, beta = 0;
  void update(PointBatch& b) const;
  void updatePlaneStress(PlaneStressPoints& b) const;
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return 0.0; }
};

}  // namespace crumple::materials
