// *MAT_STRAIN_RATE_DEPENDENT_PLASTICITY (019): von Mises plasticity with a yield stress that
// depends on the effective strain rate,
//   sigma_y = sigma_0(rate) + Ep eps_p,   Ep = E ETAN / (E - ETAN),
// sigma_0 the curve LC1 (yield stress vs effective strain rate; piecewise linear, extrapolated
// with its end slopes as every curve of a law) at the total effective strain rate of the step
// (VP = 0), and deletion of elements whose step falls below TDEL (LS-DYNA Keyword Manual vol.
// II, *MAT_STRAIN_RATE_DEPENDENT_PLASTICITY; Theory Manual, material model 19). The returns are
// the linear-hardening ones (return_mapping.hpp, LinearHardening::sigy_rate), exact at the
// step's rate. Not supported, refused by the reader: LC2 (E vs rate), LC3 (ETAN vs rate), LC4
// (failure stress vs rate, and so RDEF) and VP = 1 (viscoplastic).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "materials/law.hpp"
#include "materials/plane_stress.hpp"
#include "materials/return_mapping.hpp"
#include "materials/uniaxial.hpp"

namespace crumple::materials {

struct StrainRatePlasticity {
  static constexpr std::array<std::string_view, 2> kKeywords{
      "*MAT_STRAIN_RATE_DEPENDENT_PLASTICITY", "*MAT_019"};
  static constexpr Cost kCost = Cost::Plastic;
  static constexpr bool kPlastic = true;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;

  struct Params {
    using Law = StrainRatePlasticity;
    double E = 0, nu = 0, etan = 0;
    int32_t lc1 = -1;  // curve index: yield stress vs effective strain rate
    double tdel = 0;   // minimum time step for automatic element deletion
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static StrainRatePlasticity make(const Params& p, const CurveAt& curves, const std::string& at);

  Moduli moduli;
  double Hi = 0;                          // Ep
  std::vector<double> lc1_rate, lc1_sig;  // LC1
  double tdel = 0;
  void update(PointBatch& b) const;
  void updatePlaneStress(PlaneStressPoints& b) const;
  FibreLaw fibre() const;
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return tdel; }
  // The yield stress at an effective plastic strain and strain rate.
  double yieldStress(double eps_p, double rate) const { return yieldCurve()(rate) + Hi * eps_p; }

 private:
  RateCurve yieldCurve() const { return {lc1_rate, lc1_sig}; }
  LinearHardening hardening() const {
    LinearHardening h;
    h.sigy = yieldCurve()(0.0);
    h.Hi = Hi;
    h.sigy_rate = yieldCurve();
    return h;
  }
};

}  // namespace crumple::materials
