// *MAT_MODIFIED_PIECEWISE_LINEAR_PLASTICITY (123): *MAT_024 (its hardening, rate forms, FAIL
// and TDEL, read and run by the PiecewiseLinear unit: make() gives a PiecewiseLinear, so the
// kernels are MAT_024's) plus the shell failure criteria of card 2: EPSTHIN, the thinning
// strain at failure, EPSMAJ, the major in-plane strain at failure, and NUMINT, the
// through-thickness points that must fail before the shell is deleted (LS-DYNA Keyword Manual
// vol. II, *MAT_MODIFIED_PIECEWISE_LINEAR_PLASTICITY). The criteria reach the kernels as
// erosion criteria (materials/erosion.hpp) with the part's *MAT_ADD_EROSION ones.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "materials/erosion.hpp"
#include "materials/laws/piecewise_linear.hpp"

namespace crumple::materials {

struct ModifiedPiecewiseLinear {
  static constexpr std::array<std::string_view, 2> kKeywords{
      "*MAT_MODIFIED_PIECEWISE_LINEAR_PLASTICITY", "*MAT_123"};
  static constexpr Cost kCost = Cost::Plastic;
  static constexpr bool kPlastic = true;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;

  struct Params {
    using Law = ModifiedPiecewiseLinear;
    PiecewiseLinear::Params base;
    double epsthin = 0;  // thinning strain at failure (shells); 0 = none
    double epsmaj = 0;   // major in-plane strain at failure (shells); 0 = none
    int32_t numint = 0;  // failed points that delete a shell; 0 = all
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static PiecewiseLinear make(const Params& p, const CurveAt& curves, const std::string& at) {
    return PiecewiseLinear::make(p.base, curves, at);
  }
  // The criteria the law adds to the part's erosion.
  static void addErosion(const Params& p, Erosion& er);
};

}  // namespace crumple::materials
