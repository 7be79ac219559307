// *MAT_RIGID (020): the part moves as one rigid body (src/constraints/rigid.cpp). E and PR
// only size the contact stiffness; CMO / CON1 / CON2 fix global translations and rotations of
// the body's centre of mass (LS-DYNA Keyword Manual vol. II, *MAT_RIGID). Its elements
// compute no stress: the kernels see the elastic law of E and PR (wave speeds at set-up).
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "materials/law.hpp"
#include "materials/laws/elastic.hpp"

namespace crumple::materials {

struct Rigid {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_RIGID", "*MAT_020"};
  static constexpr Cost kCost = Cost::Rigid;
  static constexpr bool kDensity = true;
  // Solids, shells and beams may be rigid.
  static constexpr bool kRigid = true;

  struct Params {
    using Law = Rigid;
    double E = 0, nu = 0;
    int cmo = 0;   // 0 free, 1 constraints in global directions (CON1 / CON2 codes)
    int con1 = 0;  // translation code: 0 none, 1 x, 2 y, 3 z, 4 xy, 5 yz, 6 zx, 7 all
    int con2 = 0;  // rotation code, same digits
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  // The law of the rigid part's elements.
  static Elastic make(const Params& p, const CurveAt& curves, const std::string& at);
};

}  // namespace crumple::materials
