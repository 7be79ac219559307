// SPH particles as an element family the solver runs (issue 14; LS-DYNA Theory Manual,
// "Smoothed Particle Hydrodynamics"; docs/theory.md, "SPH"). Each pass, at x(n) with the
// velocities v(n-1/2) over dt(n-1/2), like the element kernels:
//   1. the neighbour pairs (sph::neighbourPairs, ascending (i, j));
//   2. the density rate (continuity) and velocity gradient L of every particle (sph.hpp);
//   3. rho(n) = rho + dt drho/dt; h(n) = h (1 + dt div(v) / 3) held in [HMIN h0, HMAX h0]
//      (the particle's volume m / rho ~ h^3);
//   4. the stress: rotated by the Jaumann rate, sig += dt (W sig - sig W), W = skew(L), then
//      advanced by the part's law with the strain increment sym(L) dt (the same 3-D update the
//      solids call, materials/law.hpp), its work (sig_old + sig) / 2 : de m / rho into the
//      particle's internal energy;
//   5. the forces m_i dv_i/dt (stress divergence and Monaghan's viscosity, sph.hpp) added to the
//      nodal force; the viscosity's dissipation into the internal energy.
// The stable step of a particle is h / (c + |v|) (LS-DYNA Theory Manual, SPH, "time
// integration": dt = C_CFL min_i h_i / (c_i + |v_i|), C_CFL the deck's TSSFAC), c the
// particle's sound speed sqrt((K + 4/3 G) / rho).
//
// Every sum runs serially in the fixed pair order over the particles of one rank (they all live
// on the rank of the element-less nodes), so the bits do not depend on threads or ranks.
#pragma once

#include <cstdint>

#include "domain/blocks.hpp"
#include "domain/subdomain.hpp"

namespace crumple::elements {

struct SphStatus {
  double dt_min = 1e300;     // smallest particle step (before TSSFAC)
  int64_t dt_particle = -1;  // its particle (index in the block)
};

// Initial state: rho0, zero stress, h0 per part (SPHINI, or CSLH x the largest of the part's
// nearest-neighbour distances), sound speeds; returns the initial step. Throws
// util::InputError for a part with fewer than two particles and no SPHINI.
SphStatus initializeSph(domain::SphBlock& b, const domain::NodeVector& x);

// One pass (above): updates the particles' state and adds their forces to f (3 per node).
SphStatus computeSphForces(domain::SphBlock& b, const domain::NodeVector& x,
                           const domain::NodeVector& v, double dt, domain::NodeVector& f);

}  // namespace crumple::elements
