// Stress updates of the laws in materials.hpp for truss and beam integration points.
//
// A beam fibre carries the axial stress sigma_rr and the two transverse shear stresses tau_rs,
// tau_rt of the corotational (r, s, t) frame; sigma_ss = sigma_tt = tau_st = 0 (the beam
// stress state of the Hughes-Liu beam, LS-DYNA Theory Manual, "Hughes-Liu Beam"). A truss
// point is the same with no shear. The von Mises norm of this state is
//   q = sqrt(xi_r^2 + 3 xi_s^2 + 3 xi_t^2),   xi = (sigma, tau_s, tau_t) - back stress,
// and the laws keep their meaning: MAT_003 with linear mixed hardening (Prager back stress,
// its uniaxial slope after yield is ETAN for every BETA), MAT_024 with a bilinear or tabulated
// isotropic yield curve; Cowper-Symonds rate scaling of the yield stress; failure at an
// effective plastic strain (FS, FAIL).
//
// The update is a closest-point return in the reduced space (Simo & Hughes, Computational
// Inelasticity, 1998, sec. 3.3, restricted to the three non-zero components): with the elastic
// moduli E (axial) and G (shear, engineering strain), the relative stress returns as
//   xi_r = xi_r^trial / (1 + (E + Hk) y),  xi_s,t = xi_s,t^trial / (1 + (3G + Hk) y),
// y = deps / q(n+1), so the return is not radial (E != 3G); one scalar equation in the
// effective plastic strain increment deps is solved by safeguarded Newton iteration. For a
// truss (no shear) it is the exact one-dimensional return.
//
// Points are updated one at a time (blocks of beams are small, see domain/blocks.hpp): one
// call per point, no virtual call; a law unit translates itself once per block (its fibre()).
#pragma once

#include <span>

#include "materials/law.hpp"
#include "materials/rate.hpp"
#include "materials/return_mapping.hpp"

namespace crumple::materials {

struct Muscle;

// State of one truss or beam integration point.
struct FibrePoint {
  double sig = 0.0, tau_s = 0.0, tau_t = 0.0;        // sigma_rr, tau_rs, tau_rt
  double eps_p = 0.0;                                // effective plastic strain
  double alpha = 0.0, alpha_s = 0.0, alpha_t = 0.0;  // back stress (MAT_003), same components
};

// The force-resultant and time failure of *MAT_SPOTWELD on spot-weld beams
// (laws/spotweld.hpp): the axial and shear forces, the torque and the bending moments at
// which the weld fails (0: that term left out), and the failure time (0: none).
struct ResultantFailure {
  double nrr = 0.0, nrs = 0.0, nrt = 0.0, mrr = 0.0, mss = 0.0, mtt = 0.0;
  double tfail = 0.0;
  bool byResultants() const {
    return nrr > 0.0 || nrs > 0.0 || nrt > 0.0 || mrr > 0.0 || mss > 0.0 || mtt > 0.0;
  }
};

// A law's parameters as the fibre update uses them.
struct FibreLaw {
  double E = 0.0, G = 0.0;  // Young's and shear modulus
  bool plastic = false;
  double sigy = 0.0;  // initial (static) yield stress
  double Hi = 0.0;    // linear isotropic plastic modulus (uniaxial: dsigma_y / deps_p)
  double Hk = 0.0;    // linear kinematic plastic modulus
  // MAT_024 with LCSS: yield stress vs effective plastic strain (isotropic only); empty
  // otherwise. Views into the block's law, which outlives the FibreLaw.
  std::span<const double> curve_eps, curve_sig;
  // MAT_018: the power law k (eps0 + eps_p)^n when power.k > 0 (isotropic only; sigy, Hi and
  // the curve unused).
  PowerHardening power;
  double C = 0.0, inv_P = 0.0;  // Cowper-Symonds 1 + (rate / C)^(1/P); C == 0: rate independent
  // MAT_024 LCSR (a factor on the yield stress) or a rate table in LCSS (the yield curve at the
  // fibre's strain rate; curve_eps and curve_sig are then empty): rate.hpp. Views into the
  // block's law.
  RateCurve lcsr;
  RateTable table;
  // MAT_019 LC1: the initial yield stress vs the strain rate (sigy unused); empty: none.
  RateCurve sigy_rate;
  // MAT_024 VP = 1: C and P, lcsr or the table at the fibre's plastic strain rate, inside the
  // return (return_mapping.hpp, viscoplasticFlow); the yield curve is then curve_eps/curve_sig.
  bool viscoplastic = false;
  double fail = 0.0;      // effective plastic strain at failure; 0: none
  ResultantFailure weld;  // *MAT_SPOTWELD only (the beam kernel checks it)
  // *MAT_MUSCLE: the truss kernel takes its stress from this law (laws/muscle.hpp), not from
  // updateFibre; null otherwise. A view into the block's law.
  const Muscle* muscle = nullptr;
};

// Static yield stress at an effective plastic strain (Hi and the curve; no rate factor; with a
// rate table, the curve of its first rate).
double flowStress(const FibreLaw& law, double eps_p);

// Advances p over one step by the axial strain increment de and the engineering shear strain
// increments dgs, dgt (gamma_rs, gamma_rt); dt sets the strain rate of the Cowper-Symonds
// factor, the LCSR factor or the rate table's curve (with VP = 1, the plastic strain rate). Returns
// true when the point has reached the failure strain.
bool updateFibre(const FibreLaw& law, FibrePoint& p, double de, double dgs, double dgt, double dt);

}  // namespace crumple::materials
