// *MAT_PLASTIC_KINEMATIC (003): von Mises plasticity with linear mixed hardening (BETA: 0
// kinematic, 1 isotropic), Cowper-Symonds rate scaling of the yield stress by
// 1 + (rate / SRC)^(1 / SRP), and erosion at the effective plastic strain FS (LS-DYNA Keyword
// Manual vol. II, *MAT_PLASTIC_KINEMATIC; Theory Manual, material model 3). The returns are
// in return_mapping.cpp (solids), plane_stress.cpp (shells) and uniaxial.cpp (beams).
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "materials/law.hpp"
#include "materials/plane_stress.hpp"
#include "materials/return_mapping.hpp"
#include "materials/uniaxial.hpp"

namespace crumple::materials {

struct PlasticKinematic {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_PLASTIC_KINEMATIC", "*MAT_003"};
  static constexpr Cost kCost = Cost::Plastic;
  static constexpr bool kPlastic = true;
  static constexpr bool kKinematic = true;
  static constexpr bool kDensity = true;

  struct Params {
    using Law = PlasticKinematic;
    double E = 0, nu = 0, sigy = 0, etan = 0;
    double beta = 0;          // 0 kinematic, 1 isotropic hardening, in between mixed
    double src = 0, srp = 0;  // Cowper-Symonds C and P; 0 = rate independent
    double fs = 0;            // effective plastic strain at failure (erosion); 0 = none
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static PlasticKinematic make(const Params& p, const CurveAt& curves, const std::string& at);

  Moduli moduli;
  LinearHardening hardening;  // Hi = beta Ep, Hk = (1 - beta) Ep, Ep = E Etan / (E - Etan)
  double fs = 0;
  void update(PointBatch& b) const;
  void updatePlaneStress(PlaneStressPoints& b) const;
  FibreLaw fibre() const;
  double failureStrain() const { return fs; }
  double deletionStep() const { return 0.0; }
};

}  // namespace crumple::materials
