// Constitutive updates over batches of integration points (structure of arrays).
//
// A law is a plain struct of parameters with a const `update(PointBatch&)` that advances the
// stress of every point in the batch over one time step. The element kernel has already
// rotated the stress to the current configuration (Jaumann rate) and passes the strain
// increment de = D*dt. Kernels are templated on the law (see elements/hex8.hpp), so there is
// no virtual call per point.
//
// Voigt order everywhere: xx, yy, zz, xy, yz, zx, tensor (not engineering) shear components.
#pragma once

#include <cstdint>
#include <variant>
#include <vector>

#include "model/model.hpp"

namespace crumple::materials {

// A batch of n integration points; every pointer addresses n contiguous values.
struct PointBatch {
  int n = 0;
  double dt = 0.0;
  double* s[6] = {};          // stress, in/out
  const double* de[6] = {};   // strain increment D*dt, in
  double* eps_p = nullptr;    // effective plastic strain, in/out (laws with plasticity)
  double* alpha[6] = {};      // back stress, in/out (laws with kinematic hardening)
  uint8_t* failed = nullptr;  // out: set to 1 when the point reaches the failure strain
};

// Elastic moduli every law exposes for wave speeds and hourglass control.
struct Moduli {
  double bulk = 0.0;   // K
  double shear = 0.0;  // G
};

// *MAT_ELASTIC: hypoelastic, s += lambda tr(de) I + 2 G de.
struct Elastic {
  Moduli moduli;
  static constexpr bool kPlastic = false;
  static constexpr bool kKinematic = false;
  void update(PointBatch& b) const;
};

// *MAT_PLASTIC_KINEMATIC: von Mises with linear mixed hardening (beta: 0 kinematic,
// 1 isotropic), radial return; Cowper-Symonds scaling of the yield stress by
// 1 + (rate/C)^(1/P); failure at effective plastic strain fs.
struct PlasticKinematic {
  Moduli moduli;
  double sigy = 0, etan = 0, beta = 0, src = 0, srp = 0, fs = 0;
  static constexpr bool kPlastic = true;
  static constexpr bool kKinematic = true;
  void update(PointBatch& b) const;
};

// *MAT_PIECEWISE_LINEAR_PLASTICITY: von Mises, isotropic hardening from a yield curve
// (LCSS, stress vs effective plastic strain) or bilinear (SIGY, ETAN); Cowper-Symonds rate
// scaling; failure at effective plastic strain `fail`.
struct PiecewiseLinear {
  Moduli moduli;
  double sigy = 0, etan = 0, c = 0, p = 0, fail = 0;
  std::vector<double> curve_eps, curve_sig;  // empty: bilinear from sigy/etan
  static constexpr bool kPlastic = true;
  static constexpr bool kKinematic = false;
  void update(PointBatch& b) const;
  double yieldStress(double eps_p) const;  // static (rate-free) flow stress
};

using Law = std::variant<Elastic, PlasticKinematic, PiecewiseLinear>;

// Builds the law of a model material (curves resolved through the model).
Law makeLaw(const model::Material& m, const model::Model& model);

// Bulk and shear modulus from E and nu.
Moduli moduliFromYoung(double E, double nu);

// Young's modulus from the bulk and shear moduli the laws store.
inline double youngOf(const Moduli& m) {
  return 9.0 * m.bulk * m.shear / (3.0 * m.bulk + m.shear);
}

// Plastic hardening modulus dsigma/deps_p of a bilinear curve with tangent Etan, so that the
// uniaxial slope after yield, E Ep / (E + Ep), is Etan. Precondition Etan < E (makeLaw).
inline double plasticModulus(double E, double etan) {
  return E * etan / (E - etan);
}

}  // namespace crumple::materials
