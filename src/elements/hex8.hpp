// The 8-node hexahedron with one-point integration: the uniform-strain element of
// Flanagan & Belytschko (1981), "A uniform strain hexahedron and quadrilateral with orthogonal
// hourglass control", IJNME 17:679-706, as used in DYNA3D (Hallquist, DYNA3D User Manual,
// UCRL-MA-107254, section 2).
//
// Kernels work on batches of kBatch elements held as structure of arrays; lanes beyond the
// batch's count replicate the last element so every loop has a constant trip count and every
// element goes through the same instructions wherever it sits (determinism).
#pragma once

#include <cstdint>

#include "domain/subdomain.hpp"

namespace crumple::elements {

inline constexpr int kBatch = domain::kSolidBatch;

// Coordinates or velocities of the 8 nodes of a batch: v[component][node][lane].
using NodalBatch = double[3][8][kBatch];

// Volume gradient B_ai = dV/dx_ai of a trilinear hexahedron (exact, FB 1981 eq. 79 and the
// node permutation of its Appendix); the uniform-strain gradient is B/V. V = sum_a x_a.B_a/3.
void volumeGradient(const NodalBatch& x, NodalBatch& b);

// Bulk viscosity coefficients (*CONTROL_BULK_VISCOSITY): quadratic Q1 and linear Q2.
struct BulkViscosity {
  double q1 = 1.5;
  double q2 = 0.06;
};

// What one pass over a block found; merged over blocks by the solver.
struct BlockStatus {
  double dt_min = 1e300;  // smallest stable element step (before TSSFAC)
  int32_t dt_elem = -1;   // model index of the controlling element
  int32_t bad_elem = -1;  // model index of an element with volume <= 0
  int32_t eroded = 0;     // elements eroded in this pass

  // An element's stable step: kept with the element when it is the smallest so far.
  void observeStep(double dte, int32_t elem) {
    if (dte < dt_min) {
      dt_min = dte;
      dt_elem = elem;
    }
  }
};

// One cycle for a block of one-point solids, hexahedra (ELFORM 1) or tetrahedra (ELFORM 10,
// nodes N1 N2 N3 N4 N4 N4 N4 N4, no hourglass control; hex8_kernel.hpp): strain rate at the
// mid-step geometry x - dt/2 v, Jaumann stress rotation, material update, bulk viscosity, stress
// divergence at x, hourglass forces, element energies and stable time step. Corner forces go to the
// block's force slots (no scatter). `dt` is the step dt(n-1/2) that brought x and v to this cycle.
// Elements [first, last) of the block only, both multiples of kBatch or last == size().
// ELFORM 13 blocks (the nodal-pressure tetrahedron, tet_nodal.hpp) run the tetrahedron with the
// volumetric strain from `nodal_ev`, the nodal strains of this pass (one per local node).
BlockStatus computeSolidForces(domain::SolidBlock& block, const domain::NodeVector& x,
                               const domain::NodeVector& v, double dt, const BulkViscosity& bv,
                               double* slots, std::size_t first, std::size_t last,
                               const double* nodal_ev = nullptr);
inline BlockStatus computeSolidForces(domain::SolidBlock& block, const domain::NodeVector& x,
                                      const domain::NodeVector& v, double dt,
                                      const BulkViscosity& bv, double* slots) {
  return computeSolidForces(block, x, v, dt, bv, slots, 0, block.size());
}

// The fully integrated hexahedron (ELFORM 2) over elements [first, last): 2x2x2 Gauss points
// with the element-mean dilatation (B-bar); no hourglass control (src/elements/hex8_full.cpp).
// Blocks of ELFORM 15 (pentahedra, N1 N2 N3 N4 N5 N5 N6 N6) run the same with 2 points.
BlockStatus computeFullSolidForces(domain::SolidBlock& block, const domain::NodeVector& x,
                                   const domain::NodeVector& v, double dt, const BulkViscosity& bv,
                                   double* slots, std::size_t first, std::size_t last);

// Initial volumes and the stable step of a block; writes each corner's lumped mass
// (rho0 V0 / 8; a tetrahedron's rho0 V0 / 4 at corners 1-4, 0 at 5-8) into the x component
// of its force slot, so that nodal masses are assembled by
// the same ordered gather as forces.
BlockStatus initializeSolids(domain::SolidBlock& block, const domain::NodeVector& x0, double* slots,
                             std::vector<double>& element_dt, const BulkViscosity& bv);

// Marks elements that share no node with any other element (through the gather plan, so
// neighbours on other ranks count) and gives them the step factor sqrt((K + 4G/3) / 3K):
// such an element's breathing mode has omega = 2 sqrt(3K / (K + 4G/3)) c / h, above the
// L / c estimate (0.73 h/c at nu = 0.3). In a mesh this mode cannot form.
void markIsolatedElements(domain::SolidBlock& block, const domain::GatherPlan& plan);

// Stable time step of one element from its characteristic length (volume / largest face
// area; a tetrahedron's minimum altitude; LS-DYNA Theory Manual "Time step control") and the
// dilatational wave speed, reduced for bulk viscosity: dt = L / (Q + sqrt(Q^2 + c^2)), Q = Q2 c +
// Q1 L |tr D| (for either sign of tr D: a step that jumps with the sign pumps energy into vibrating
// elements).
double solidTimeStep(double length, double wave_speed, double trace_d, const BulkViscosity& bv);

}  // namespace crumple::elements
