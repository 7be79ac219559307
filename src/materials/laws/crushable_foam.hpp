// *MAT_CRUSHABLE_FOAM (063), MODEL 0: the crushable-foam model of LS-DYNA (Keyword Manual vol.
// II, *MAT_CRUSHABLE_FOAM, fields and remarks; the update as OpenRadioss' port of the family,
// sigeps163.F90, does it). Solids only, as in LS-DYNA. docs/theory.md gives the sources and the
// choices made where they differ.
//
// The stress is updated elastically (isotropic, Young's modulus Ee and Poisson's ratio PR),
// then each principal stress of the trial is confined to [-Y, TSC]: compression beyond the
// yield stress Y is cut back to -Y (perfectly plastic), tension beyond the cutoff TSC to TSC
// (TSC = 0: no tension). Y is the curve LCID (yield stress vs volumetric strain
// gamma = 1 - V/V0) at the largest gamma reached, so unloading and reloading below it are
// elastic (Keyword Manual: "unloading is fully elastic"). Ee is the slope of the last segment of
// LCID (Keyword Manual, field E: for MODEL 0 "the final slope of curve LCID determines the
// elastic stiffness for loading and unloading ... also used in the time step calculation";
// E itself sets only the contact stiffness). gamma comes from ln(V/V0), integrated from the
// volumetric strain increments (d ln V = tr D dt). History: ln(V/V0) and the largest gamma.
// DAMP > 0 and MODEL 1, 2 are refused (see read()).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "materials/law.hpp"

namespace crumple::materials {

struct CrushableFoam {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_CRUSHABLE_FOAM", "*MAT_063"};
  static constexpr Cost kCost = Cost::Plastic;
  static constexpr bool kPlastic = false;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  static constexpr int kHistory = 2;  // h[0] = ln(V/V0), h[1] = largest gamma = 1 - V/V0

  struct Params {
    using Law = CrushableFoam;
    double E = 0, nu = 0;  // E: contact stiffness only (the model builder's bulk modulus)
    double tsc = 0;        // tensile stress cutoff, >= 0
    int32_t curve = -1;    // model curve index: yield stress vs gamma
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static CrushableFoam make(const Params& p, const CurveAt& curves, const std::string& at);

  Moduli moduli;  // from Ee (the last slope of the curve) and PR: stress update and wave speed
  double tsc = 0;
  std::vector<double> gamma, yield;  // the curve, gamma increasing
  void update(PointBatch& b) const;
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return 0.0; }
  // Y(gamma_max): the curve, with its end slopes beyond its ends, never below zero.
  double yieldStress(double gamma_max) const;
};

}  // namespace crumple::materials
