// *MAT_SOIL_AND_FOAM (005): the soil and crushable-foam model of LS-DYNA (Keyword Manual vol.
// II, *MAT_SOIL_AND_FOAM; Theory Manual, "Material Model 5: Soil and Crushable Foam"; the
// model of Krieg, "A simple constitutive description for cellular concrete", SC-DR-72-0883,
// Sandia 1972). Solids only, as in LS-DYNA.
//
// Pressure (positive in compression) is a function of the compressive volumetric strain
// x = -ln(V/V0): the tabulated curve P(x) (EPS1-10 = ln(V/V0), negative in compression, with
// P1-10, or a curve LCID; a first point at zero strain is added when the table starts past
// it) while loading past the largest compression reached, x_max; below it, the straight
// unloading line of slope KUN from (x_max, P(x_max)), which reloading retraces (VCR = 0). With
// VCR = 1 the curve is followed both ways (nonlinear elastic). Past the last point the curve
// goes on with its last slope. The pressure is cut off at PC (<= 0; blank: no tension), and
// where it is cut the deviatoric stress is zeroed (Theory Manual). The deviator is elastic
// with shear modulus G and perfectly plastic on the pressure-dependent surface
//   J2 = 1/2 s:s <= a0 + a1 p + a2 p^2   (taken as 0 where the polynomial is negative),
// returned radially with the new pressure. x is integrated from the volumetric strain
// increments (d ln V = tr D dt); history: x and x_max (kHistory = 2).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "materials/law.hpp"

namespace crumple::materials {

struct SoilAndFoam {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_SOIL_AND_FOAM", "*MAT_005"};
  static constexpr Cost kCost = Cost::Plastic;
  static constexpr bool kPlastic = false;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  static constexpr int kHistory = 2;  // h[0] = x = -ln(V/V0), h[1] = x_max

  struct Params {
    using Law = SoilAndFoam;
    double G = 0, kun = 0, a0 = 0, a1 = 0, a2 = 0, pc = 0;
    bool crush = true;   // VCR = 0: volumetric crushing (unloading along KUN)
    int32_t curve = -1;  // model curve index: x = -ln(V/V0) (ascending) vs pressure
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static SoilAndFoam make(const Params& p, const CurveAt& curves, const std::string& at);

  Moduli moduli;  // K: the stiffest of KUN and the curve's slopes (wave speed); G
  double G = 0, kun = 0, a0 = 0, a1 = 0, a2 = 0, pc = 0;
  bool crush = true;
  std::vector<double> x, p;  // the pressure curve, x ascending from 0
  void update(PointBatch& b) const;
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return 0.0; }
  // Pressure at compressive volumetric strain x_new given the largest compression x_max
  // reached before the step; updates x_max when loading.
  double pressure(double x_new, double& x_max) const;
};

}  // namespace crumple::materials
