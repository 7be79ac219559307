// Two-node beams and trusses (*SECTION_BEAM ELFORM 1, 2, 3).
//
// ELFORM 2, the Belytschko-Schwer resultant beam (Belytschko, Schwer & Klein, "Large
// displacement, transient analysis of space frames", IJNME 11 (1977) 65-84; LS-DYNA Theory
// Manual, "Belytschko Beam"): a corotational beam whose deformation in the element frame
// (elongation, twist, end rotations relative to the chord) gives the resultants through the
// elastic beam stiffness, with transverse shear through the shear area SA.
//
// ELFORM 1, Hughes-Liu (Hughes & Liu, "Nonlinear finite element analysis of shells: Part I",
// CMAME 26 (1981) 331-362; LS-DYNA Theory Manual, "Hughes-Liu Beam"): straight fibres
// (Timoshenko kinematics), one integration point along the axis, the cross-section
// integrated with a quadrature rule, each point carrying sigma_rr, tau_rs, tau_rt in the
// corotational frame with the material law (materials/uniaxial.hpp).
//
// ELFORM 3, truss: axial force only, uniaxial stress through the law.
//
// Both beams use the same corotational frame (src/elements/beam.cpp). Slots (blocks.hpp):
// element e writes the force on its node a (0, 1) to slot slot_offset + 4 e + a and the
// moment on it to slot_offset + 4 e + 2 + a, global frame. Like the hex kernel's, the slot
// holds the element's force ON the node (minus the internal force vector), so that the
// solver's a = (f + f_ext) / m, alpha = (m + m_ext) / I is right after the gather.
#pragma once

#include <cstddef>
#include <vector>

#include "domain/blocks.hpp"
#include "domain/subdomain.hpp"
#include "elements/hex8.hpp"

namespace crumple::elements {

// Sizes the kernel's state of a block of n elements (length0, e_int, active, triad,
// deformation, resultant, point); call once section and law are set. The arrays the pipeline
// fills (elem, conn, orientation, ...) are not touched.
void resizeBeamBlock(domain::BeamBlock& block, std::size_t n);

// Initial lengths, frames and state; writes each end's lumped mass rho A L0 / 2 into the x
// component of its force slot and its rotational inertia (zero for trusses) into the x
// component of its moment slot, the other components zero; element_dt gets every element's
// stable step (beamTimeStep at L0). An element of zero length is reported in bad_elem.
//
// Orientation: the s axis lies in the plane of nodes 1, 2 and the orientation point
// (block.orientation). When conn[2] is model::kNone and the orientation point is NaN, the
// kernel picks the default: s is the global axis least aligned with the beam (the first of
// x, y, z on a tie) made orthogonal to it; t = r x s. The orientation point is read here
// only: afterwards the nodes' rotations carry the frame (its later motion is not followed).
BlockStatus initializeBeams(domain::BeamBlock& block, const domain::NodeVector& x0, double* slots,
                            std::vector<double>& element_dt);

// One cycle for elements [first, last) of a block: x = x(n), v = v(n-1/2), w = omega(n-1/2)
// (angular velocities, packed xyz per local node; not read for trusses), dt = dt(n-1/2).
// Writes end forces and moments to the slots, accumulates e_int, erodes elements whose
// material fails (slots zeroed), and returns the smallest stable step at x(n).
BlockStatus computeBeamForces(domain::BeamBlock& block, const domain::NodeVector& x,
                              const domain::NodeVector& v, const domain::NodeVector& w, double dt,
                              double* slots, std::size_t first, std::size_t last);

// Lumped rotational inertia of one end of a beam of length L, density rho, area A and largest
// second moment of area I: rho L (A L^2 + 12 I) / 8 (see beam.cpp for why).
// Section resultants of element e at mid-length, for the d3plot: axial force, shear forces
// along s and t, moments about s and t, torque. From the conjugate end resultants R (axial force,
// torque, moments about s and t at node 1, at node 2) as the Hughes-Liu update builds them:
// R = {N, T, -Ms + L Qt / 2, -Mt - L Qs / 2, Ms + L Qt / 2, Mt - L Qs / 2} with L the initial
// length, so Ms = (R4 - R2) / 2, Mt = (R5 - R3) / 2, Qt = (R2 + R4) / L, Qs = -(R3 + R5) / L.
void beamSectionResultants(const domain::BeamBlock& block, std::size_t e, double out[6]);

double beamRotationalInertia(double rho, double length, double area, double i_max);

// Stable step of one element (LS-DYNA Theory Manual, "Time Step Control", beams and trusses):
// L / c, c = sqrt(E / rho); for ELFORM 2 also the bending limit
//   0.5 L / (c sqrt(3 I (1 / (12 I + A L^2) + 1 / (A L^2)))),  I = max(ISS, ITT),
// and the torsion limit 2 / omega_twist of the lumped inertia (never smaller for a real
// section, J <= ISS + ITT; kept so that an odd J input cannot break the step).
double beamTimeStep(const domain::BeamSection& section, double length, double E, double G,
                    double rho);

// The stable step dt of an undamped element reduced for stiffness-proportional damping
// C = beta K: (2 / omega) (sqrt(1 + xi^2) - xi) with omega = 2 / dt and xi = beta omega / 2
// (Belytschko, Liu & Moran, Nonlinear Finite Elements for Continua and Structures, 2000,
// sec. 6.3.3, the central difference method with viscous damping).
double dampedStep(double dt, double beta);

}  // namespace crumple::elements
