// *MAT_POWER_LAW_PLASTICITY (018): von Mises plasticity with isotropic power-law hardening
//   sigma_y = k (eps_yp + eps_p)^n,
// eps_yp the strain at yield: with SIGY = 0 the elastic strain where the elastic line E eps
// meets k eps^n, eps_yp = (E / k)^(1 / (n - 1)) (n < 1); with 0 < SIGY < 0.02, SIGY itself; with
// SIGY >= 0.02 (a stress), (SIGY / k)^(1 / n). Rate dependence by the Cowper-Symonds factor
// 1 + (rate / SRC)^(1 / SRP) on the yield stress at the total effective strain rate (VP = 0;
// VP = 1, viscoplastic, is refused), erosion at the effective plastic strain EPSF (LS-DYNA
// Keyword Manual vol. II, *MAT_POWER_LAW_PLASTICITY; Theory Manual, material model 18). Solids,
// shells and beams; the returns are the neutral ones of return_mapping.hpp (PowerHardening),
// plane_stress.hpp and uniaxial.hpp.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "materials/law.hpp"
#include "materials/plane_stress.hpp"
#include "materials/return_mapping.hpp"
#include "materials/uniaxial.hpp"

namespace crumple::materials {

struct PowerLaw {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_POWER_LAW_PLASTICITY",
                                                             "*MAT_018"};
  static constexpr Cost kCost = Cost::Plastic;
  static constexpr bool kPlastic = true;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;

  struct Params {
    using Law = PowerLaw;
    double E = 0, nu = 0, k = 0, n = 0;
    double src = 0, srp = 0;  // Cowper-Symonds C and P; 0 = rate independent
    double sigy = 0;          // 0: eps_yp from E and k; < 0.02: eps_yp; else the yield stress
    double epsf = 0;          // effective plastic strain at failure (erosion); 0 = none
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static PowerLaw make(const Params& p, const CurveAt& curves, const std::string& at);
  // The strain at yield eps_yp of the manual (SIGY, E, k, n as above); NaN when undefined.
  static double yieldStrain(const Params& p);

  Moduli moduli;
  PowerHardening hardening;  // k, n, eps0 = eps_yp, C, inv_P
  double epsf = 0;
  void update(PointBatch& b) const;
  void updatePlaneStress(PlaneStressPoints& b) const;
  FibreLaw fibre() const;
  double failureStrain() const { return epsf; }
  double deletionStep() const { return 0.0; }
};

}  // namespace crumple::materials
