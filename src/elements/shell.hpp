// The Belytschko-Lin-Tsay shell (ELFORM 2) and the C0 triangle (ELFORM 4, and every
// quadrilateral with n3 == n4): Belytschko, Lin & Tsay (1984), "Explicit algorithms for the
// nonlinear dynamics of shells", CMAME 42:225-251; Belytschko, Stolarski & Carpenter (1984),
// "A C0 triangular plate element with one-point quadrature", IJNME 20:787-802; as in DYNA3D
// (Hallquist, DYNA3D User Manual, UCRL-MA-107254) and the LS-DYNA Theory Manual
// ("Belytschko-Lin-Tsay shell", "C0 triangular shell").
//
// Corotational: each element carries a frame (normal from the cross product of the diagonals,
// first axis along side 1-2) in which its stresses and hourglass resistances live, so that a
// rigid rotation changes none of them. Velocity strains at the mid-surface with one-point
// quadrature in the plane, NIP points through the thickness with a plane-stress law
// (materials/plane_stress.hpp), elastic transverse shear with the shear factor, resultants to
// corner forces and moments, hourglass control and a drilling-rotation constraint (a small
// stiffness tying each corner's rotation about the normal to the membrane's spin, without
// which a bent mesh with viscous hourglass control spins its nodes about the normal). Theory
// notes in src/elements/shell.cpp.
//
// Kernels work on batches of kShellBatch elements held as structure of arrays, like the hex
// kernel (elements/hex8.hpp): lanes beyond the batch's count replicate its last element.
#pragma once

#include <cstddef>
#include <vector>

#include "domain/blocks.hpp"
#include "domain/subdomain.hpp"
#include "elements/hex8.hpp"

namespace crumple::elements {

inline constexpr int kShellBatch = domain::kShellBatch;
// Through-thickness points supported (LS-DYNA: NIP up to 10 with Gauss or Lobatto rules).
inline constexpr int kMaxShellPoints = 10;

// Through-thickness rule on [-1, 1]: Gauss-Legendre (nip 1-10) or Gauss-Lobatto (nip 3-10,
// both surfaces included), weights normalised to sum to 1, abscissae ascending.
void throughThicknessRule(int nip, bool lobatto, std::vector<double>& zeta,
                          std::vector<double>& weight);

// Allocates the per-element state of n elements, padded to whole batches: thickness, areas,
// energies, flags, stresses, drilling moments; plastic strain and back stress only if the law
// has them; hourglass resistances only for the stiffness forms (IHQ 4, 5). Sets the
// through-thickness rule from nip and lobatto. Everything starts at zero and active.
void resizeShellBlock(domain::ShellBlock& block, std::size_t n);

// Thickness (mean of the corner thicknesses), area and stable step of every element; writes
// each corner's lumped mass into the x component of its force slot and its rotational inertia
// into the x component of its moment slot (other components zero):
//   quadrilateral: m_a = rho t A / 4 at each corner;
//   triangle:      m_a = rho t A / 3 at corners 1-3, nothing at corner 4;
//   inertia:       I_a = m_a max(A / 8, t^2 / 12).
// The inertia is the scaled rotary inertia of Kennedy, Belytschko & Lin (1986), "Recent
// developments in explicit finite element techniques and their application to reactor
// structures", Nucl. Eng. Des. 97:1-24, with the plate's own t^2/12 as a floor for thick
// elements. It keeps the stiffest rotational mode, uniform rotation against the transverse
// shear (omega^2 = kappa G t A / (rho t A^2 / 8) = 8 kappa G / (rho A) = 2.6 E / (rho A) at
// nu = 0.3), below the membrane limit (2 / dt)^2 = 4 c^2 / L_s^2 = 4.4 E / (rho A) of a square
// element, so rotations do not control the step (tested: random rotation rates on free meshes
// at TSSFAC 0.95). element_dt[e] = L_s / c (shellTimeStep). bad_elem: an element with a
// non-positive area or thickness.
BlockStatus initializeShells(domain::ShellBlock& block, const domain::NodeVector& x0, double* slots,
                             std::vector<double>& element_dt);

// One cycle for elements [first, last) of a shell block (both multiples of kShellBatch or
// last == size()): x = x(n), v = v(n-1/2), w = omega(n-1/2), packed xyz per local node;
// dt = dt(n-1/2). Corner forces go to slots[3 (slot_offset + 8 e + a) + c] and corner moments
// to slots[3 (slot_offset + 8 e + 4 + a) + c], global frame, in the hex kernel's convention:
// the force the element exerts on the node (minus the internal force vector), so that the
// solver takes a = (f + f_ext) / m and alpha = m_slots / I. A triangle's corner 3 slots are
// zero (its node's share is at corner 2). Also energies (e_int, e_hg incremented), erosion
// (active = 0, slots zero, counted in `eroded`), the stable step (dt_min, dt_elem) and
// bad_elem (an element whose area is not positive).
// Element type: a quadrilateral with n3 == n4 runs as the C0 triangle whatever elform says;
// every other element runs as the Belytschko-Lin-Tsay quadrilateral (also under elform 4).
BlockStatus computeShellForces(domain::ShellBlock& block, const domain::NodeVector& x,
                               const domain::NodeVector& v, const domain::NodeVector& w, double dt,
                               double* slots, std::size_t first, std::size_t last);
inline BlockStatus computeShellForces(domain::ShellBlock& block, const domain::NodeVector& x,
                                      const domain::NodeVector& v, const domain::NodeVector& w,
                                      double dt, double* slots) {
  return computeShellForces(block, x, v, w, dt, slots, 0, block.size());
}

// The fully integrated shell (ELFORM 16, src/elements/shell_full.cpp) over elements [first,
// last) of a block with elform 16 (quadrilaterals only), with the same inputs, slots, energies,
// erosion and stable step as computeShellForces.
BlockStatus computeFullShellForces(domain::ShellBlock& block, const domain::NodeVector& x,
                                   const domain::NodeVector& v, const domain::NodeVector& w,
                                   double dt, double* slots, std::size_t first, std::size_t last);
inline BlockStatus computeFullShellForces(domain::ShellBlock& block, const domain::NodeVector& x,
                                          const domain::NodeVector& v, const domain::NodeVector& w,
                                          double dt, double* slots) {
  return computeFullShellForces(block, x, v, w, dt, slots, 0, block.size());
}

// Stable step of one shell (LS-DYNA Theory Manual, "Time step control", shell elements, the
// default characteristic length): dt = L_s / c, L_s = (1 + beta) A / (longest side), beta = 0
// for quadrilaterals and 1 for triangles, c = sqrt(E / (rho (1 - nu^2))) (plane-stress plate
// wave speed).
double shellTimeStep(double area, double longest_side, bool triangle, double wave_speed);

// Cauchy stress in the global frame (Voigt xx, yy, zz, xy, yz, zx, tensor shear) and effective
// plastic strain of element e at its bottom (0), mid (1) and top (2) surface: the integration
// points nearest to them; at the mid-surface with an even NIP, the through-thickness mean.
// x gives the element's current frame. For output (VTU).
void shellSurfaceStress(const domain::ShellBlock& block, const domain::NodeVector& x, std::size_t e,
                        double out[3][6], double eps_p_out[3]);

// As shellSurfaceStress, at every integration point through the thickness (out[nip][6],
// eps_p_out[nip]; the mean of the in-plane points), point 0 at the bottom (zeta = -1). For
// elout.
void shellPointStress(const domain::ShellBlock& block, const domain::NodeVector& x, std::size_t e,
                      double (*out)[6], double* eps_p_out);

// Resultants per unit width of element e in its corotational frame, for the d3plot: bending
// moments Mxx, Myy, Mxy, transverse shears Qx (from tau_zx), Qy (from tau_yz), membrane forces
// Nxx, Nyy, Nxy (the order lasso-python reads: moments, shears, normal forces; VTK 9.1's
// vtkLSDynaReader labels the three groups in another order); the mean over the in-plane points. N =
// integral of sigma dz, M = -integral of z sigma dz (the Belytschko-Tsay resultants of the LS-DYNA
// Theory Manual, z along the element normal), Q = t tau with the uniform transverse shear stress.
void shellResultants(const domain::ShellBlock& block, std::size_t e, double out[8]);

}  // namespace crumple::elements
