// Plane-stress updates of the laws for shell integration points: the in-plane stress
// (xx, yy, xy) advances over one step while the normal stress sigma_zz stays zero; the thickness
// strain increment that this requires is returned for the thickness update. Transverse shear is
// elastic and is left to the element.
//
// Plastic laws use the plane-stress return mapping of Simo & Taylor (1986), "A return mapping
// algorithm for plane stress elastoplasticity", IJNME 22:649-670 (also Simo & Hughes,
// Computational Inelasticity, 1998, sec. 3.4): the return is solved in the three-dimensional
// space of plane stress, so sigma_zz is zero by construction, and the consistency condition is
// one scalar equation in the plastic multiplier, solved by Newton's method to convergence
// (a last Newton step below 1e-8 of the plastic multiplier, which leaves an error of order
// 1e-16) for each point. The converged stress is the one the 3D radial
// return (materials.hpp) gives when it is fed the returned thickness strain; the unit tests
// check this.
//
// Like return_mapping.hpp, these are the building blocks a law unit's updatePlaneStress calls
// on a batch of points held as structure of arrays (no virtual call per point), and a point's
// result never depends on the other points of the batch (each point iterates until its own
// convergence).
#pragma once

#include <cstdint>

#include "materials/law.hpp"
#include "materials/return_mapping.hpp"

namespace crumple::materials {

// A batch of n shell integration points; every pointer addresses n contiguous values. Shear
// components are tensor components (de_xy = D_xy dt), as in PointBatch.
struct PlaneStressPoints {
  int n = 0;
  double dt = 0.0;
  double* s[3] = {};         // in-plane stress xx, yy, xy in the element frame, in/out
  const double* de[3] = {};  // in-plane strain increment xx, yy, xy, in
  double* de_zz = nullptr;   // out: thickness strain increment (sigma_zz stays 0)
  double* eps_p = nullptr;   // effective plastic strain, in/out (plastic laws)
  // Back stress xx, yy, xy in plane-stress form (kinematic laws), or the accumulated in-plane
  // logarithmic strain xx, yy, xy (tensor shear) of kShellStrain laws; in/out.
  double* alpha[3] = {};
  uint8_t* failed = nullptr;    // out: 1 where the point has reached the failure strain, else 0
  double* h[kMaxHistory] = {};  // the law's history variables h[0..kHistory), in/out
  // In, for laws that declare kLayered (else null): the angle of each point's layer in radians
  // about the shell normal, from the element frame's first axis (*SECTION_SHELL ICOMP 1).
  const double* ply = nullptr;
};

// Young's modulus and Poisson's ratio from the moduli every law stores.
double youngModulus(const Moduli& m);
double poissonRatio(const Moduli& m);

// Newton iterations allowed per point before the return gives up on convergence (it keeps the
// last iterate); a return from an explicit step converges in 2 to 6.
inline constexpr int kPlaneStressMaxIterations = 60;

// Plane-stress Hooke's law; clears b.failed.
void planeStressElastic(PlaneStressPoints& b, const Moduli& m);
// Linear mixed hardening (return_mapping.hpp); `kinematic` updates the back stress b.alpha.
void planeStressLinear(PlaneStressPoints& b, const Moduli& m, const LinearHardening& P,
                       bool kinematic);
// Isotropic hardening along a yield curve.
void planeStressCurve(PlaneStressPoints& b, const Moduli& m, const CurveHardening& P);
// Isotropic power-law hardening (MAT_018).
void planeStressPower(PlaneStressPoints& b, const Moduli& m, const PowerHardening& P);
// Sets b.failed to 1 where the effective plastic strain has reached `limit`, else 0 (all 0
// when limit <= 0).
void markFailed(PlaneStressPoints& b, double limit);

}  // namespace crumple::materials
