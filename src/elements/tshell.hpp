// The thick shell (*SECTION_TSHELL ELFORM 1, *ELEMENT_TSHELL): an 8-node brick whose stresses
// follow the shell's plane-stress laws (LS-DYNA Theory Manual, "Thick shell": formulation 1,
// one point in the plane with NIP points through the thickness and hourglass control; Hallquist,
// LS-DYNA Theory Manual 2006, ch. 7). Nodes N1-N4 form the bottom face, N5-N8 the top; the
// thickness runs from the bottom to the top.
//
// Corotational as the Belytschko-Tsay shell (elements/shell.hpp): the lamina frame of each
// element comes from its mid-surface (the means of the bottom and top corners) with the normal
// along the cross product of the diagonals and the first axis along side 1-2, and the stresses
// live in it, so that a rigid rotation changes none of them. At each point (0, 0, zeta_i) the
// velocity gradient of the trilinear brick, in the lamina frame, gives the in-plane strain
// increments to the plane-stress law (sigma_zz = 0 in the law) and the transverse shears to an
// elastic update with SHRF. Forces are the integral of sigma' grad N over the points at x(n);
// the in-plane hourglass modes xi eta and xi eta zeta, which points on the element's axis do not
// see, take the hexahedron's Flanagan-Belytschko control (hex8_kernel.hpp). A thickness-stretch
// stiffness (Young's modulus on the difference between the element's kinematic thickness strain
// and the one the plane-stress law asks for) gives the mode in which the top face moves against
// the bottom along the normal a resistance that plane stress alone would not. Theory notes in
// docs/theory.md, "Thick shells".
//
// ELFORM 2 (selective reduced; LS-DYNA Theory Manual, "Thick shell", formulation 2: 2 x 2
// integration in the plane, no hourglass control): the same element with the in-plane strains
// and the thickness stretch at the 2 x 2 Gauss points of every thickness level (4 NIP points,
// SolidBlock::plane_points = 4) and the transverse shear at the centre of the plane, one value
// per thickness level (the 2 x 2 rule would lock it in bending).
#pragma once

#include <cstddef>

#include "domain/subdomain.hpp"
#include "elements/hex8.hpp"

namespace crumple::elements {

// One cycle for elements [first, last) of a thick-shell block (both multiples of kBatch or
// last == size()), with the inputs, slots, energies, erosion (a law's failure at every point)
// and stable step of computeSolidForces; no bulk viscosity.
BlockStatus computeThickShellForces(domain::SolidBlock& block, const domain::NodeVector& x,
                                    const domain::NodeVector& v, double dt, double* slots,
                                    std::size_t first, std::size_t last);

// The through-thickness rule of a thick-shell block: the section's *INTEGRATION_SHELL rule if
// it gave one, else Gauss (or Lobatto) with block.points points.
void setThickShellRule(domain::SolidBlock& block);

// Characteristic length of each lane of a batch of thick shells at x: the smaller of the
// thickness (volume / mid-surface area) and the shell's in-plane length (mid-surface area /
// longest side), LS-DYNA Theory Manual, "Time step control", thick shells. With the plate wave
// speed (thickShellWaveSpeed) it gives the stable step L / c.
void thickShellLengths(const NodalBatch& x, double (&length)[kBatch]);

// sqrt(E / (rho (1 - nu^2))) of the block's law at its initial density.
double thickShellWaveSpeed(const domain::SolidBlock& block);

// Cauchy stress in the global frame (Voigt xx, yy, zz, xy, yz, zx, tensor shear) and effective
// plastic strain of thick shell e at its bottom (0) and top (2) thickness points (the lowest
// and highest zeta, the mean over the in-plane points) in the lamina frame of the current
// coordinates x, and (1) the element's through-thickness means (block.sig, block.eps_p). For
// output (the d3plot thick-shell records).
void thickShellLayerStress(const domain::SolidBlock& block, const domain::NodeVector& x,
                           std::size_t e, double (&layers)[3][6], double (&eps)[3]);

}  // namespace crumple::elements
