// Erosion criteria added to a law: *MAT_ADD_EROSION (LS-DYNA Keyword Manual vol. II) on any law
// of solids and shells, and the shell criteria of *MAT_MODIFIED_PIECEWISE_LINEAR_PLASTICITY
// (123): EPSTHIN, EPSMAJ, NUMINT. A point fails when NCS of the *MAT_ADD_EROSION criteria hold
// at once, or when one of the law's own criteria (thinning, major strain) holds; a failed point
// stays failed. The element is deleted through the one erosion path of its kernel (the law's
// failure flag): a one-point solid at once, a shell when NUMFIP of its points have failed.
//
// The criteria see the point's stress at the end of the step and its total strain: the rate of
// deformation integrated over the run and turned with the stress (Jaumann, solids) or kept in
// the corotational element frame (shells), a logarithmic strain on proportional paths. Strain
// is stored only when a strain criterion is set, so a law without erosion pays nothing and one
// with stress criteria alone pays no storage.
#pragma once

#include <cstdint>

#include "materials/principal.hpp"

namespace crumple::materials {

enum class Criterion : uint8_t {
  MaxPressure,         // MXPRES: p = -tr(sigma)/3 >= MXPRES
  MinPrincipalStrain,  // MNEPS: smallest principal strain <= MNEPS
  EffectiveStrain,     // EFFEPS: sqrt(2/3 e':e') >= EFFEPS
  VolumetricStrain,    // VOLEPS: tr(e) >= VOLEPS (> 0) or <= VOLEPS (< 0)
  MinPressure,         // MNPRES: p <= MNPRES
  MaxPrincipalStress,  // SIGP1: largest principal stress >= SIGP1
  VonMises,            // SIGVM: sqrt(3/2 s':s') >= SIGVM
  MaxPrincipalStrain,  // MXEPS: largest principal strain >= MXEPS
  ShearStrain,         // EPSSH: (e1 - e3) / 2 >= EPSSH (tensorial shear strain)
  FailureTime,         // FAILTM: time >= FAILTM
  Thinning,            // *MAT_123 EPSTHIN (shells): -e_zz >= EPSTHIN
  MajorStrain,         // *MAT_123 EPSMAJ (shells): largest in-plane principal strain >= EPSMAJ
};
inline constexpr int kCriteria = 12;

// Trivially copyable: stored in the Model, which travels between ranks as bytes.
struct Erosion {
  double limit[kCriteria] = {};
  uint32_t active = 0;  // bit c: criterion c is set
  int32_t ncs = 1;      // *MAT_ADD_EROSION criteria that must hold at once
  // Shells: failed points that delete the element (NUMFIP, *MAT_123 NUMINT); 0 = all of them.
  int32_t numfip = 0;

  bool any() const { return active != 0; }
  bool has(Criterion c) const { return (active >> static_cast<int>(c)) & 1U; }
  void set(Criterion c, double v) {
    limit[static_cast<int>(c)] = v;
    active |= 1U << static_cast<int>(c);
  }
  double at(Criterion c) const { return limit[static_cast<int>(c)]; }
  // A criterion on the total strain is set (the kernel then stores it).
  bool needsStrain() const;
  // The criteria that apply to solids (the shell-only ones of *MAT_123 removed).
  Erosion forSolids() const;
};

// Whether a point with stress s and total strain e (Voigt, tensor shear components) fails at
// `time`. Shells pass their plane stress and strain with s_zz = 0, e_zz the thickness strain.
bool pointFails(const Erosion& er, const Voigt& s, const Voigt& e, double time);

}  // namespace crumple::materials
