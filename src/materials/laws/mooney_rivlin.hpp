// *MAT_MOONEY-RIVLIN_RUBBER (027): the compressible Mooney-Rivlin rubber of LS-DYNA (Keyword
// Manual vol. II, *MAT_MOONEY-RIVLIN_RUBBER; Theory Manual, "Material Model 27: Mooney-Rivlin
// Rubber"). Solids only here (ELFORM 1, 10): the strain energy
//   W = A (I1 - 3) + B (I2 - 3) + C (I3^-2 - 1) + D (I3 - 1)^2
// of the invariants of the right Cauchy-Green tensor, with C = A/2 + B (no stress in the
// reference state) and D = (A (5 nu - 2) + B (11 nu - 5)) / (2 (1 - 2 nu)) (the small-strain
// Poisson's ratio is PR); shear modulus G = 2 (A + B). The Cauchy stress follows from W
// (materials/hyperelastic.hpp), as a function of the deformation gradient F alone: no history,
// no stress rotation. With A = B = 0 and LCID, A and B are the least-squares fit of the uniaxial
// test curve (force vs change in gauge length; SGL, SW, ST), the nominal stress of an
// incompressible Mooney-Rivlin solid being P = 2 (lambda - lambda^-2) (A + B / lambda).
// REF = 1 (*INITIAL_FOAM_REFERENCE_GEOMETRY) is refused.
// Shells (plane stress): each point keeps its in-plane logarithmic strain e (xx, yy, xy in the
// corotational element frame, the sum of the strain increments D dt: the Hencky strain of the
// membrane when its principal axes do not turn in the element); the principal stretches
// lambda_i = exp(e_i) give B = diag(lambda_1^2, lambda_2^2, lambda_3^2), and lambda_3 is the
// stretch at which the stress above has sigma_33 = 0 (with the law's own compressibility D);
// the thickness follows it (de_zz = lambda_3(new) / lambda_3(old) - 1). docs/theory.md,
// "Mooney-Rivlin shells".
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "materials/law.hpp"
#include "materials/plane_stress.hpp"

namespace crumple::materials {

struct MooneyRivlin {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_MOONEY-RIVLIN_RUBBER",
                                                             "*MAT_027"};
  static constexpr Cost kCost = Cost::Elastic;
  static constexpr bool kPlastic = false;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  static constexpr bool kDeformationGradient = true;
  static constexpr bool kShellStrain = true;

  struct Params {
    using Law = MooneyRivlin;
    double nu = 0, a = 0, b = 0;
    double sgl = 0, sw = 0, st = 0;
    int32_t curve = -1;  // model curve index of LCID (the fit), -1 without
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static MooneyRivlin make(const Params& p, const CurveAt& curves, const std::string& at);

  Moduli moduli;  // the small-strain K and G (wave speed, hourglass control)
  double a = 0, b = 0, c = 0, d = 0;
  void update(PointBatch& p) const;
  void updatePlaneStress(PlaneStressPoints& pts) const;
  // The plane-stress Cauchy stress s (xx, yy, xy) at the in-plane logarithmic strain e (xx, yy,
  // xy; tensor shear), sigma_33 = 0; returns the thickness stretch lambda_3.
  double planeStress(const double (&e)[3], double (&s)[3]) const;
  // The principal Cauchy stress of the diagonal B = diag(b1, b2, b3) along axis bi.
  double principalStress(double b1, double b2, double b3, double bi) const;
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return 0.0; }
};

}  // namespace crumple::materials
