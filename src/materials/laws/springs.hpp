// The laws of discrete springs and dampers (*ELEMENT_DISCRETE, *SECTION_DISCRETE; LS-DYNA
// Keyword Manual vol. II, *MAT_SPRING_ELASTIC (S01), *MAT_DAMPER_VISCOUS (S02),
// *MAT_SPRING_NONLINEAR_ELASTIC (S04)): a force along the element from its elongation or
// elongation rate (src/elements/discrete.cpp). They have no density (the nodes carry the mass).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "materials/law.hpp"

namespace crumple::materials {

// What the discrete kernel needs of a spring or damper law.
struct DiscreteLaw {
  enum class Kind : uint8_t { SpringElastic, DamperViscous, SpringNonlinear };
  Kind kind = Kind::SpringElastic;
  double k = 0.0;                        // stiffness (SpringElastic) or damping constant
  std::vector<double> curve_x, curve_y;  // SpringNonlinear: force vs elongation
};

// S01: F = K dL.
struct SpringElastic {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_SPRING_ELASTIC", "*MAT_S01"};
  static constexpr Cost kCost = Cost::Discrete;
  static constexpr bool kDensity = false;
  struct Params {
    using Law = SpringElastic;
    double k = 0;
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static DiscreteLaw make(const Params& p, const CurveAt& curves, const std::string& at);
};

// S02: F = DC dL/dt.
struct DamperViscous {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_DAMPER_VISCOUS", "*MAT_S02"};
  static constexpr Cost kCost = Cost::Discrete;
  static constexpr bool kDensity = false;
  struct Params {
    using Law = DamperViscous;
    double dc = 0;
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static DiscreteLaw make(const Params& p, const CurveAt& curves, const std::string& at);
};

// S04: F = curve(dL); LCR (rate scaling) is refused.
struct SpringNonlinear {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_SPRING_NONLINEAR_ELASTIC",
                                                             "*MAT_S04"};
  static constexpr Cost kCost = Cost::Discrete;
  static constexpr bool kDensity = false;
  struct Params {
    using Law = SpringNonlinear;
    int32_t curve = -1;
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static DiscreteLaw make(const Params& p, const CurveAt& curves, const std::string& at);
};

}  // namespace crumple::materials
