// Discrete springs and dampers between two nodes (*ELEMENT_DISCRETE with *SECTION_DISCRETE
// and *MAT_SPRING_ELASTIC (S01), *MAT_DAMPER_VISCOUS (S02), *MAT_SPRING_NONLINEAR_ELASTIC
// (S04); LS-DYNA Theory Manual, "Discrete Elements and Masses").
//
// The force acts along the current axis n = (x2 - x1) / L; with the elongation
// delta = L - L0 (L0 the initial length) and S the element's scale factor:
//   SpringElastic    F = S k (delta + OFFSET)
//   SpringNonlinear  F = S f(delta + OFFSET), f the force-elongation curve, linear between its
//                    points and extrapolated with the slopes of its end segments
//   DamperViscous    F = S c d(delta)/dt, the rate at the mid-step geometry
// F > 0 is tension. Slots (blocks.hpp): the force on node a (0, 1) at slot_offset + 2 e + a,
// +F n on node 1 and -F n on node 2 (the element's force ON the node, as for solids).
// Discrete elements carry no mass: the nodes get theirs from other elements or *ELEMENT_MASS.
// An element of zero length has no axis and exerts no force (LS-DYNA would need an
// orientation vector, which these elements do not have).
#pragma once

#include <cstddef>
#include <vector>

#include "domain/blocks.hpp"
#include "domain/subdomain.hpp"
#include "elements/hex8.hpp"

namespace crumple::elements {

// Sizes the kernel's state (length0, e_int, force, elongation) of a block of n elements.
void resizeDiscreteBlock(domain::DiscreteBlock& block, std::size_t n);

// Initial lengths; the force and energy start from the offset. If slots is given, zeroes the
// block's slots (discretes add no mass to the ordered mass gather).
void initializeDiscretes(domain::DiscreteBlock& block, const domain::NodeVector& x0,
                         double* slots = nullptr);

// One cycle for elements [first, last): x = x(n), v = v(n-1/2), dt = dt(n-1/2). Writes the
// forces to the slots and accumulates e_int: springs by the trapezoidal rule on the force
// over the elongation increment, dampers F rate dt (the dissipated energy). The stable step
// needs the nodal masses, which the block does not know: dt_min stays at its "none" value and
// the solver takes the step from discreteStableStep.
BlockStatus computeDiscreteForces(domain::DiscreteBlock& block, const domain::NodeVector& x,
                                  const domain::NodeVector& v, double dt, double* slots,
                                  std::size_t first, std::size_t last);

// Stable step of element e from the assembled nodal masses (indexed by local node) and the
// block's current state (LS-DYNA Theory Manual, "Time Step Control", discrete elements):
//   springs  dt = sqrt(2 m1 m2 / (k (m1 + m2))), k = S k, or for SpringNonlinear S times the
//            slope of the curve at the current elongation (the tangent stiffness),
//   dampers  dt = m1 m2 / (c (m1 + m2)), c = S c (see discrete.cpp).
// A node without mass (e.g. constrained) leaves the other mass alone; no mass at all, or no
// stiffness, gives 1e300 (no limit).
double discreteStableStep(const domain::DiscreteBlock& block, const std::vector<double>& nodal_mass,
                          std::size_t e);

}  // namespace crumple::elements
