// Beam end releases (LS-DYNA Keyword Manual, *ELEMENT_BEAM RT1 RR1 RT2 RR2 with LOCAL 2: the
// element's own r s t axes): an end may let a translation or a rotation of its node pass
// without force, as a hinge or a slide between the node and the element.
//
// The corotational beams (beam.cpp) carry the resultants R = (N, T, G_1s, G_1t, G_2s, G_2t)
// conjugate to the deformation d = (elongation, twist, theta_1s, theta_1t, theta_2s,
// theta_2t), and the end forces follow from R through the chord: along s at node 1
// (G_1t + G_2t) / L, along t -(G_1s + G_2s) / L, along r -N. A release is therefore a
// linear condition c . R = 0 on the resultants:
//   translation along r at either end       N = 0
//   rotation about r at either end          T = 0
//   rotation about s (t) at end a           G_as = 0 (G_at = 0)
//   translation along s at either end       G_1t + G_2t = 0 (the shear along s)
//   translation along t at either end       G_1s + G_2s = 0
// Each condition frees the deformation it is conjugate to: the hinge rotation theta_as, the
// slide that turns the chord (theta_1t and theta_2t alike), the elongation or the twist.
// Freeing the deformation h = c (the same vector) makes the hinge's work R . h = c . R zero,
// so the release stores no energy. The increments of a step become dd + h alpha with alpha
// from the elastic stiffness K of the element (static condensation, Przemieniecki, Theory of
// Matrix Structural Analysis, 1968, sec. 5.8 on released ends):
//   c . (R_old + K (dd + c alpha)) = 0,   alpha = -c . (R_old + K dd) / (c . K c).
// The resultants of the step then meet the condition exactly for an elastic element (and the
// resultant beam's plastic return scales the released component with the others); for a
// Hughes-Liu section that yields, the point stresses leave a residual of the step's order,
// which the next step's alpha removes (R_old enters it). In a bending plane two conditions
// (both ends hinged, or a hinge and a slide) leave the plane no stiffness: both resultants
// then go to zero the same way, with the plane's 2 x 2 stiffness. The geometry stays the
// nodes': a slide does not move the chord (small slides, as the condition is linear in R).
#pragma once

#include <array>
#include <cstdint>

namespace crumple::elements {

// The elastic stiffness of an element's deformation, block diagonal: elongation, twist, and
// per bending plane the symmetric 2 x 2 (k11, k12, k22) of (theta_1, theta_2) to (G_1, G_2):
// plane s is (theta_1s, theta_2s), plane t (theta_1t, theta_2t).
struct DeformationStiffness {
  double axial = 0.0, torsion = 0.0;
  std::array<double, 3> s{}, t{};
};

// Adds to the deformation increments dd of a step the free deformation of the releases so that
// R_old + K dd meets every released condition (file comment). `release` holds
// domain::BeamSection::release's bits; no-op for 0.
void applyReleases(int release, const DeformationStiffness& K, const std::array<double, 6>& R_old,
                   std::array<double, 6>& dd);

}  // namespace crumple::elements
