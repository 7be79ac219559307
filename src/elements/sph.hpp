// Smoothed particle hydrodynamics, the particle-level core (issue 14; LS-DYNA Theory Manual,
// "Smoothed Particle Hydrodynamics"; J. J. Monaghan, "Smoothed particle hydrodynamics", Annu.
// Rev. Astron. Astrophys. 30, 1992, 543-574; L. D. Libersky, A. G. Petschek, T. C. Carney, J. R.
// Hipp and F. A. Allahdadi, "High strain Lagrangian hydrodynamics", J. Comput. Phys. 109, 1993,
// 67-75): the kernel, the neighbour search and the particle sums, verified on their own
// (tests/unit/test_sph.cpp); the element family that runs them is src/elements/sph_family.hpp.
//
// Kernel: the cubic B-spline of support 2h (Monaghan 1992, eq. 2.6; the Theory Manual's
// "smoothing kernel"), W(r, h) = C_d / h^d theta(q), q = r / h,
//   theta = 1 - 3/2 q^2 + 3/4 q^3 (q <= 1),  1/4 (2 - q)^3 (1 < q <= 2),  0 beyond,
//   C_1 = 2/3, C_2 = 10 / (7 pi), C_3 = 1 / pi (so that W integrates to 1).
// A pair of particles of smoothing lengths h_i, h_j uses h_ij = (h_i + h_j) / 2, so that
// W_ij = W_ji and the pair forces are equal and opposite (momentum conserved exactly).
//
// Sums over the neighbours j of particle i (grad_i W_ij = dW/dr (x_i - x_j) / r):
//   density rate      drho_i/dt = sum_j m_j (v_i - v_j) . grad_i W_ij              (continuity)
//   velocity gradient L_i = -sum_j (m_j / rho_j) (v_i - v_j) (x) grad_i W_ij
//   momentum          m_i dv_i/dt = sum_j m_i m_j (sig_i / rho_i^2 + sig_j / rho_j^2
//                                                  - Pi_ij I) . grad_i W_ij
// with Monaghan's artificial viscosity (Monaghan 1992, eq. 4.2), for approaching pairs
// (v_ij . x_ij < 0): Pi_ij = (-alpha c_ij mu_ij + beta mu_ij^2) / rho_ij,
//   mu_ij = h_ij v_ij . x_ij / (r^2 + 0.01 h_ij^2), c_ij, rho_ij the pair's means.
// Smoothing length (LS-DYNA's *SECTION_SPH): h0 = CSLH x the largest of the particles'
// nearest-neighbour distances, then dh/dt = h div(v) / d, held in [HMIN h0, HMAX h0].
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "util/vec3.hpp"

namespace crumple::elements::sph {

using util::Vec3;

// The cubic B-spline W(r, h) in `dim` dimensions (1, 2 or 3) and its slope dW/dr.
double kernel(int dim, double r, double h);
double kernelSlope(int dim, double r, double h);

// The pairs (i, j), i < j, of particles closer than 2 h_ij, found with a bucket grid of cell
// 2 max(h) and listed in ascending (i, j): the fixed order every sum below follows, whatever
// the number of ranks or threads (ARCHITECTURE.md, Determinism).
std::vector<std::pair<int32_t, int32_t>> neighbourPairs(std::span<const Vec3> x,
                                                        std::span<const double> h);

// CSLH x the largest nearest-neighbour distance of the particles (LS-DYNA's initial
// smoothing length of a part).
double initialSmoothingLength(std::span<const Vec3> x, double cslh);

// The particles' state the sums read.
struct Particles {
  int dim = 3;
  std::span<const Vec3> x, v;
  std::span<const double> mass, rho, h;
  std::span<const std::array<double, 6>> sig;  // Cauchy stress, Voigt (tensor shear)
  std::span<const double> c;                   // sound speed
  double alpha = 1.0, beta = 1.0;              // artificial viscosity (linear, quadratic)
};

// Density rate and velocity gradient (row-major L[3 a + b] = dv_a / dx_b) of every particle.
void computeRates(const Particles& p, std::span<const std::pair<int32_t, int32_t>> pairs,
                  std::vector<double>& drho, std::vector<std::array<double, 9>>& grad_v);

// The force m_i dv_i/dt on every particle (stress and artificial viscosity). With `heat`, also
// the rate at which the viscosity turns kinetic into internal energy, half of each pair's
// m_i m_j Pi_ij v_ij . grad_i W_ij to each of its particles (>= 0).
void computeForces(const Particles& p, std::span<const std::pair<int32_t, int32_t>> pairs,
                   std::vector<Vec3>& force, std::vector<double>* heat = nullptr);

}  // namespace crumple::elements::sph
