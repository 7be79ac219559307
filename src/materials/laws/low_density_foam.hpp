// *MAT_LOW_DENSITY_FOAM (057): the low-density urethane foam of LS-DYNA (Keyword Manual vol. II,
// *MAT_LOW_DENSITY_FOAM; Theory Manual, "Material Model 57: Low Density Urethane Foam", after
// Storakers 1986). Solids only, as in LS-DYNA (one-point ELFORM 1, 10: the law needs F).
//
// Each principal direction of the left stretch V (F = V R) acts alone (zero Poisson's ratio):
// with the stretch lambda_i and the elongation eps_i = 1 - lambda_i (positive in compression),
// the nominal stress is the curve LCID, f(eps_i), in compression and E (lambda_i - 1), cut off at
// TC, in tension; the Cauchy stress is sigma_i = tau_i / (lambda_j lambda_k) on the axes of V.
// This is the hyperelastic solid of W = sum_i Phi(lambda_i), dPhi/dlambda = tau, so the stress
// is a function of F and the history only (no rotation integrated step by step).
// Hysteresis (HU < 1): the loading stress is scaled by 1 - (1 - HU) (1 - (W / W_max)^SHAPE),
// W = sum_i Phi the loading curve's energy at the present stretches and W_max the largest W
// reached (Keyword Manual, HU and SHAPE; the damage form OpenRadioss' /MAT/LAW90 gives the same
// fields). At W = W_max the factor is 1: loading follows the curve, unloading and reloading
// below W_max the scaled curve; a loop to W_max dissipates W_max (1 - HU) SHAPE / (SHAPE + 1).
// FAIL = 1: once a tensile nominal stress reaches TC the point carries no tension any more.
// Wave speed: at least that of E_max = max(E, the curve's largest slope) with zero Poisson's
// ratio, and each point reports its own (kWaveModulus) for compression in several directions.
// BVFLAG = 0 (LS-DYNA's default): no bulk viscosity on the law's elements (bulkViscosity()).
// Refused (changes the answer, not done here): DAMP > 0 (blank is LS-DYNA's 0.05), BETA != 0
// (creep of the unloading curve), ED != 0 (Maxwell rate effects), REF = 1. docs/theory.md,
// "Low-density foam".
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "materials/law.hpp"

namespace crumple::materials {

struct LowDensityFoam {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_LOW_DENSITY_FOAM", "*MAT_057"};
  static constexpr Cost kCost = Cost::Plastic;  // an eigen-decomposition per point
  static constexpr bool kPlastic = false;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  static constexpr bool kDeformationGradient = true;
  static constexpr int kHistory = 2;  // h[0] = W_max, h[1] = 1 once torn (FAIL = 1)
  // The Cauchy tangent of direction i is slope_i lambda_i / (lambda_j lambda_k): under
  // compression in several directions it outgrows any constant modulus (docs/theory.md).
  static constexpr bool kWaveModulus = true;

  struct Params {
    using Law = LowDensityFoam;
    double E = 0, nu = 0;  // the contact stiffness's modulus (KCON, else E) and 0 (contact only)
    double young = 0;      // E: the tensile modulus
    double tc = 1e20;      // TC: cutoff of the tensile nominal stress
    double hu = 1, shape = 1;
    bool tear = false;            // FAIL = 1
    bool bulk_viscosity = false;  // BVFLAG = 1
    int32_t curve = -1;           // model curve index of LCID
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static LowDensityFoam make(const Params& p, const CurveAt& curves, const std::string& at);

  // K = E_max / 3 and G = E_max / 2 (lambda + 2 mu = E_max, zero Poisson's ratio), E_max the
  // larger of E and the curve's stiffest slope (wave speed and hourglass control).
  Moduli moduli;
  double young = 0, tc = 1e20, hu = 1, shape = 1;
  bool tear = false, bulk_visc = false;
  std::vector<double> strain, stress, energy;  // the curve from (0, 0), and its integral
  void update(PointBatch& p) const;
  bool bulkViscosity() const { return bulk_visc; }
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return 0.0; }

  // The loading nominal stress (positive in tension) at stretch lambda, and its energy
  // Phi(lambda) = integral from 1 to lambda; `torn`: no tension.
  double nominal(double lambda, bool torn) const;
  double work(double lambda, bool torn) const;
  // The hysteresis factor at W given W_max (>= W).
  double unloadingFactor(double w, double w_max) const;
  // The stiffest slope d tau / d lambda of the loading response near lambda: E in tension, in
  // compression the larger of the slopes of the curve's segment at 1 - lambda and of the next
  // one (the point may enter it within the step).
  double slopeNear(double lambda) const;
  // rho c^2 at the principal stretches: max_i slope_i lambda_i / (lambda_j lambda_k).
  double waveModulus(const std::array<double, 3>& lambda) const;
};

}  // namespace crumple::materials
