// *MAT_PIECEWISE_LINEAR_PLASTICITY (024): von Mises plasticity with isotropic hardening along
// a yield curve (LCSS, or the EPS1-8 / ES1-8 table, else bilinear from SIGY and ETAN), rate
// dependence by Cowper-Symonds scaling (C, P), by an LCSR curve scaling the yield stress, or by
// a *DEFINE_TABLE in LCSS giving one yield curve per strain rate (materials/rate.hpp), erosion
// at the effective plastic strain FAIL and deletion of elements whose step falls below TDEL
// (LS-DYNA Keyword Manual vol. II, *MAT_PIECEWISE_LINEAR_PLASTICITY; Theory Manual, material
// model 24). VP = 0: the rate forms scale the yield stress at the total effective strain rate
// of the step; VP = 1 (viscoplastic): at the effective plastic strain rate, inside the
// consistency condition (return_mapping.hpp, viscoplasticFlow; docs/theory.md).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "materials/law.hpp"
#include "materials/plane_stress.hpp"
#include "materials/rate.hpp"
#include "materials/return_mapping.hpp"
#include "materials/uniaxial.hpp"

namespace crumple::materials {

struct PiecewiseLinear {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_PIECEWISE_LINEAR_PLASTICITY",
                                                             "*MAT_024"};
  static constexpr Cost kCost = Cost::Plastic;
  static constexpr bool kPlastic = true;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;

  struct Params {
    using Law = PiecewiseLinear;
    double E = 0, nu = 0, sigy = 0, etan = 0;
    double fail = 0;      // effective plastic strain at failure (erosion); 0 = none
    double c = 0, p = 0;  // Cowper-Symonds rate parameters; 0 = rate independent
    int32_t lcss = -1;    // curve index: yield stress vs effective plastic strain; -1 = none
    double tdel = 0;      // minimum time step for automatic element deletion
    int32_t lcsr = -1;    // curve index: yield stress factor vs effective strain rate; -1 = none
    int32_t table = -1;   // LCSS naming a *DEFINE_TABLE: model table index; -1 = none
    bool viscoplastic = false;  // VP = 1 with a rate form (C and P, LCSR or a table)
  };
  static const deck::KeywordSpec& cards();
  // The cards of *MAT_024 under another keyword, with fields added at the end of card 2 (the
  // laws built on this one: *MAT_123).
  static deck::KeywordSpec cardsOf(std::string_view keyword,
                                   std::vector<deck::FieldSpec> card2_extra);
  static Params read(LawInput& in);
  static PiecewiseLinear make(const Params& p, const CurveAt& curves, const std::string& at);

  Moduli moduli;
  LinearHardening linear;                      // bilinear (no curve): sigy, Hi = Ep, C, inv_P
  std::vector<double> curve_eps, curve_sig;    // the yield curve; empty: bilinear or a table
  std::vector<double> lcsr_rate, lcsr_factor;  // the LCSR curve; empty: none
  RateTableData table;                         // the LCSS table; empty: none
  double fail = 0, tdel = 0;
  // VP = 1; a bilinear law then runs as the two-point curve (0, SIGY), (1, SIGY + Ep).
  bool viscoplastic = false;
  void update(PointBatch& b) const;
  void updatePlaneStress(PlaneStressPoints& b) const;
  FibreLaw fibre() const;
  double failureStrain() const { return fail; }
  double deletionStep() const { return tdel; }
  // Static (rate-free) flow stress at an effective plastic strain (a table: its first curve).
  double yieldStress(double eps_p) const;

 private:
  RateCurve rateCurve() const { return {lcsr_rate, lcsr_factor}; }
  CurveHardening curve() const {
    return {curve_eps, curve_sig, linear.C, linear.inv_P, rateCurve(), table.view(), viscoplastic};
  }
  LinearHardening bilinear() const {
    LinearHardening h = linear;
    h.lcsr = rateCurve();
    return h;
  }
  bool hasCurve() const { return !curve_eps.empty() || !table.rates.empty(); }
};

}  // namespace crumple::materials
