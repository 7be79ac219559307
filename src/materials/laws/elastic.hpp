// *MAT_ELASTIC (001): isotropic hypoelastic solid, s += lambda tr(de) I + 2 G de (LS-DYNA
// Keyword Manual vol. II, *MAT_ELASTIC; Theory Manual, material model 1). DA, DB (axial and
// bending damping of the Belytschko resultant beam) and K (bulk modulus of the fluid option)
// are read and not honoured.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "materials/law.hpp"
#include "materials/plane_stress.hpp"
#include "materials/uniaxial.hpp"

namespace crumple::materials {

struct Elastic {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_ELASTIC", "*MAT_001"};
  static constexpr Cost kCost = Cost::Elastic;
  static constexpr bool kPlastic = false;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;

  struct Params {
    using Law = Elastic;
    double E = 0, nu = 0;
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static Elastic make(const Params& p, const CurveAt& curves, const std::string& at);

  Moduli moduli;
  void update(PointBatch& b) const;
  void updatePlaneStress(PlaneStressPoints& b) const;
  FibreLaw fibre() const;
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return 0.0; }
};

}  // namespace crumple::materials
