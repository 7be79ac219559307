// The three-dimensional stress updates laws are built from: Hooke's law and J2 plasticity by
// radial return (formulation and references in return_mapping.cpp). A law unit translates its
// parameters into these (src/materials/laws/) and calls them on a batch of points; they hold
// no law of their own.
#pragma once

#include <span>

#include "materials/law.hpp"
#include "materials/rate.hpp"

namespace crumple::materials {

// Linear mixed hardening: the yield stress rf (sigy + Hi eps_p) with the Cowper-Symonds
// factor rf = 1 + (rate / C)^inv_P (C == 0: rate independent), else the factor of an LCSR
// curve (rate.hpp; empty: none), and Prager's kinematic hardening with modulus Hk.
struct LinearHardening {
  double sigy = 0.0;  // initial yield stress
  double Hi = 0.0;    // isotropic plastic modulus
  double Hk = 0.0;    // kinematic plastic modulus
  double C = 0.0, inv_P = 0.0;
  RateCurve lcsr;
};

// Isotropic hardening along a piecewise-linear yield curve (stress vs effective plastic
// strain, linearly extrapolated past its ends), with the same rate factors; or, when `table`
// is not empty, along the curve of a rate table at the point's strain rate (eps, sig unused).
struct CurveHardening {
  std::span<const double> eps, sig;
  double C = 0.0, inv_P = 0.0;
  RateCurve lcsr;
  RateTable table;
};

// s += lambda tr(de) I + 2 G de.
void elasticUpdate(PointBatch& b, const Moduli& m);
// Elastic predictor and radial return; `kinematic` updates the back stress b.alpha.
void linearHardeningReturn(PointBatch& b, const Moduli& m, const LinearHardening& P,
                           bool kinematic);
void curveHardeningReturn(PointBatch& b, const Moduli& m, const CurveHardening& P);
// Static flow stress of the curve at an effective plastic strain.
double curveFlowStress(const CurveHardening& P, double eps_p);
// The effective strain rate sqrt(2/3 dev(de):dev(de)) / dt of a step (0 when dt is 0), the rate
// of the rate forms here (VP = 0), for the laws that measure it themselves.
double effectiveStrainRate(const double de[6], double dt);
// Raises b.failed where the effective plastic strain has reached `limit` (> 0).
void markFailed(PointBatch& b, double limit);

}  // namespace crumple::materials
