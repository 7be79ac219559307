// The fully integrated hexahedra for poor aspect ratios (*SECTION_SOLID ELFORM -1, -2;
// src/elements/hex8_full.cpp) against ELFORM 2: a slender cantilever of elongated bricks
// against beam theory (ELFORM 2 locks in shear, -1 and -2 do not), and energy conservation of
// a free vibrating bar (the forces are the transpose of the corrected strain rate).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "solid_runs.hpp"

namespace {

using crumple::testing::formWriter;

// The cantilever of solid_runs.hpp (100 x 10 x 10 mm, 2 x 2 cells across) with 4 cells along
// (25 x 5 x 5 mm bricks, aspect ratio 5) and with 2 (50 x 5 x 5, aspect 10), tip load along y.
// Figures (tip deflection / Timoshenko): ELFORM 2 locks, 0.299 (aspect 5) and 0.094 (aspect
// 10); -1 and -2 (one formulation here) give 1.047 and 0.983.
TEST(VerificationSolidForms, SlenderCantileverAgainstBeamTheory) {
  for (int nx : {4, 2}) {
    const std::string tag = "_nx" + std::to_string(nx);
    const double locked = crumple::testing::cantileverTipRatio(formWriter(2), "", 2,
                                                               ("cant_elform2" + tag).c_str(), nx);
    const double accurate = crumple::testing::cantileverTipRatio(
        formWriter(-1), "", 2, ("cant_elform-1" + tag).c_str(), nx);
    const double efficient = crumple::testing::cantileverTipRatio(
        formWriter(-2), "", 2, ("cant_elform-2" + tag).c_str(), nx);
    EXPECT_LT(locked, 0.8) << nx;
    EXPECT_NEAR(accurate, 1.0, 0.05) << nx;
    EXPECT_NEAR(efficient, 1.0, 0.05) << nx;
  }
}

// Total energy of the free vibrating bar of solid_runs.hpp (bending in its start field too).
TEST(VerificationSolidForms, FreeBarConservesEnergy) {
  EXPECT_LT(crumple::testing::freeBarEnergyDrift(formWriter(-1), "bar_elform-1"), 2e-3);
}

}  // namespace
