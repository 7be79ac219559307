// 2D solids: 4-node (and degenerate 3-node) quadrilaterals in the global x-y plane with two
// translational freedoms per node, given as *ELEMENT_SHELL of a *SECTION_SHELL with ELFORM 13
// (plane strain, unit thickness) or ELFORM 15 (axisymmetric, volume weighted: x is the radius,
// y the axis of symmetry; masses, forces and energies per radian). LS-DYNA Keyword Manual
// vol. I, *SECTION_SHELL (ELFORM 13, 15); LS-DYNA Theory Manual, "Two-dimensional solid
// elements"; Hallquist, NIKE2D / DYNA2D User Manuals (UCRL-52678, UCID-18756) for the
// one-point quadrilateral with hourglass control.
//
// One-point mean-strain quadrilateral (the 2D Flanagan-Belytschko element): with the weight
// w = r (ELFORM 15) or 1 (ELFORM 13), each corner a has the weighted gradient integrals
//   B_a = integral of grad N_a w dA,  H_a = integral of N_a dA (ELFORM 15 only, the hoop row),
//   V = integral of w dA,             M_a = integral of N_a w dA (row-sum lumped mass / rho),
// all exact by 2 x 2 Gauss on the bilinear map. The mean rate of deformation is
// D_ij = sym(sum_a v_ia B_aj) / V in the plane, D_zz = sum_a v_xa H_a / V (the hoop rate, the
// mean of v_x / r; 0 for plane strain), and the corner force is minus the work conjugate:
// f_xa = -(s_xx B_ax + s_xy B_ay + s_zz H_a), f_ya = -(s_xy B_ax + s_yy B_ay). A uniform
// strain (u = a x, v = b y) gives D = (a, b, a) exactly (the patch test) and a uniform stress
// with s_zz = s_xx is in equilibrium at interior nodes (the forces are -s dV/dx_a), also on
// the axis. The solid law sees the full 3-D rate (zz from D_zz, yz = zx = 0). Viscous
// hourglass control on the one 2D hourglass mode per direction, coefficient
// QM rho c V / (4 sqrt(A)) (the 3-D rule QM rho c V^(2/3) / 4 with the element's depth V / A);
// IHQ 1 on the +-1 vector, IHQ 2 and 3 on the vector projected orthogonal to linear fields.
// Stable step: L = A / (longest diagonal), c = sqrt((K + 4G/3) / rho), with the solids' bulk
// viscosity term (elements/hex8.hpp, solidTimeStep).
#pragma once

#include <cstddef>
#include <vector>

#include "domain/blocks.hpp"
#include "domain/subdomain.hpp"
#include "elements/hex8.hpp"

namespace crumple::elements {

// Initial volume (area0), thickness 1, stable step of every element of a planar shell block;
// writes each corner's lumped mass rho0 M_a into the x component of its force slot and a
// nominal rotational inertia m_a A / 8 into its moment slot (the nodes' rotations carry no
// moment: the elements have none). bad_elem: an element with V <= 0 (or, axisymmetric, a
// corner at negative radius).
BlockStatus initializeSolid2D(domain::ShellBlock& block, const domain::NodeVector& x0,
                              double* slots, std::vector<double>& element_dt,
                              const BulkViscosity& bv);

// One cycle for elements [first, last) of a planar shell block, in computeShellForces'
// conventions (slots, energies, erosion, stable step); z components of the forces and every
// moment are zero.
BlockStatus computeSolid2DForces(domain::ShellBlock& block, const domain::NodeVector& x,
                                 const domain::NodeVector& v, double dt, const BulkViscosity& bv,
                                 double* slots, std::size_t first, std::size_t last);

// The weighted integrals of one element (corners x[a], y[a]): B_a (bx, by), H_a, M_a and V
// as above (axisymmetric: weight r = x; otherwise 1 and H = 0). For tests and output.
struct Solid2DIntegrals {
  double bx[4], by[4], h[4], m[4], vol;
};
Solid2DIntegrals solid2DIntegrals(const double x[4], const double y[4], bool axisymmetric);

}  // namespace crumple::elements
