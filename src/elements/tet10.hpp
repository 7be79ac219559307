// The 10-node tetrahedron (*SECTION_SOLID ELFORM 16): quadratic shape functions on the corners
// N1..N4 and the mid-side nodes N5 (edge 1-2), N6 (2-3), N7 (3-1), N8 (1-4), N9 (2-4),
// N10 (3-4); in volume coordinates L1..L4, N_a = L_a (2 L_a - 1) at a corner and 4 L_i L_j at
// the node on edge i-j (Zienkiewicz & Taylor, The Finite Element Method, vol. 1, the quadratic
// tetrahedron; Hughes, The Finite Element Method, section 3.6). Four Gauss points (L = a, b, b,
// b and its permutations, a = (5 + 3 sqrt 5) / 20, b = (5 - sqrt 5) / 20, weight 1/24 each:
// exact for quadratics, so for the stiffness of straight-sided elements), each with its own
// stress and material history, updated as the fully integrated hexahedron updates its points:
// the rate of deformation at the mid-step geometry, the Jaumann rotation, the law, the stress
// divergence at x(n). Full integration: no hourglass modes, no hourglass control.
//
// Mass: the diagonal of the consistent mass matrix scaled to the element's mass (Hinton, Rock &
// Zienkiewicz 1976, "A note on mass lumping and related processes in the finite element
// method", Earthq. Eng. Struct. Dyn. 4:245-249): rho0 V0 / 36 at each corner and 4 rho0 V0 / 27
// at each mid-side node, positive and summing to rho0 V0 (the row sums would give the corners
// -rho0 V0 / 20).
//
// Stable step: dt = L / c with L = h_min / 4, h_min the corner tetrahedron's smallest altitude
// (docs/theory.md, "The 10-node tetrahedron": the highest frequency of one element with this
// mass, by power iteration on M^-1 K, gives dt_crit between 0.27 h_min / c (regular element,
// nu = 0.499) and 0.34 h_min / c).
#pragma once

#include <vector>

#include "domain/subdomain.hpp"
#include "elements/hex8.hpp"

namespace crumple::elements {

// Sizes the block's state (point and element arrays, padded to whole batches).
void resizeTet10Block(domain::Tet10Block& block);

// Initial volumes, lumped masses (into the x component of each node's slot) and each element's
// stable step (element_dt, one per element).
BlockStatus initializeTet10(domain::Tet10Block& block, const domain::NodeVector& x0, double* slots,
                            std::vector<double>& element_dt, const BulkViscosity& bv);

// One cycle for elements [first, last) of the block: rates at x - dt/2 v, the laws at the four
// points, the forces at x into the block's slots, the energies and the stable step.
BlockStatus computeTet10Forces(domain::Tet10Block& block, const domain::NodeVector& x,
                               const domain::NodeVector& v, double dt, const BulkViscosity& bv,
                               double* slots, std::size_t first, std::size_t last);

// The characteristic length of a 10-node tetrahedron on its corners: h_min / 4 (above).
inline constexpr double kTet10LengthFactor = 0.25;

// Node a's share of the element mass (HRZ lumping, above): 1/36 at the corners (a < 4), 4/27
// at the mid-side nodes.
inline constexpr double tet10MassShare(int a) {
  return a < 4 ? 1.0 / 36.0 : 4.0 / 27.0;
}

}  // namespace crumple::elements
