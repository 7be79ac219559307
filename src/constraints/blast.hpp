// Empirical air blast on segments: *LOAD_BLAST_ENHANCED with *LOAD_BLAST_SEGMENT_SET (LS-DYNA
// Keyword Manual, *LOAD_BLAST_ENHANCED; the ConWep method of Randers-Pehrson & Bannister,
// "Airblast loading model for DYNA2D and DYNA3D", ARL-TR-1310, 1997).
//
// The blast parameters of a hemispherical TNT surface burst at the scaled distance
// Z = R / W^(1/3) come from the Kingery-Bulmash fits (Kingery & Bulmash, "Air blast parameters
// from TNT spherical air burst and hemispherical surface burst", ARBRL-TR-02555, 1984), in the
// polynomial form of UFC 3-340-02 (2008), sec. 2-13: U = C0 + C1 log10 Z,
// log10 Y = sum_i K_i U^i, in feet, pounds, milliseconds and psi (scaled by W^(1/3) where the
// quantity is a time or an impulse). Each segment sees, from its arrival time ta, the incident
// and the normally reflected pressure as Friedlander pulses of the positive phase duration t0
// whose decay constants make their positive-phase integrals the fitted impulses,
//   p(tau) = P (1 - tau / t0) exp(-b tau / t0),   I = P t0 (1 / b - (1 - exp(-b)) / b^2),
// combined by the angle of incidence theta between the segment's normal and the direction to
// the charge (Randers-Pehrson & Bannister 1997):
//   p = Pr cos^2 theta + Pi (1 + cos^2 theta - 2 cos theta)   (cos theta >= 0)
//   p = Pi                                                    (cos theta < 0: facing away).
// Only the hemispherical surface burst (BLAST = 2) is provided: the free-air (BLAST = 1)
// reflected-pressure coefficients we could find in published sources did not reproduce
// Pr / Pso -> 2 at large Z, so that option is refused rather than guessed.
#pragma once

#include <array>

#include "model/model.hpp"

namespace crumple::constraints {

using model::BlastCharge;

// Blast parameters at one scaled distance, in feet, pounds, milliseconds and psi: ta, t0 and
// the impulses scaled by W^(1/3) (ms / lb^(1/3), psi ms / lb^(1/3)).
struct BlastParameters {
  double ta = 0.0;   // arrival time
  double t0 = 0.0;   // positive phase duration
  double pso = 0.0;  // incident (side-on) peak overpressure
  double pr = 0.0;   // normally reflected peak overpressure
  double is = 0.0;   // incident positive impulse
  double ir = 0.0;   // reflected positive impulse
};

// Kingery-Bulmash hemispherical surface burst at z (ft / lb^(1/3)); z is clamped to the fits'
// range, 0.17 to 100 (the positive phase duration from 0.45).
BlastParameters hemisphericalBurst(double z);
inline constexpr double kBlastZMin = 0.17, kBlastZMax = 100.0;

// The Friedlander decay constant b of a positive phase of peak p, duration t0 and impulse i:
// the root of i = p t0 (1 / b - (1 - exp(-b)) / b^2), found by bisection (b may be negative
// when i > p t0 / 2; the triangle, b = 0, when i = p t0 / 2).
double friedlanderDecay(double p, double t0, double impulse);
// p (1 - tau / t0) exp(-b tau / t0) for tau >= 0 (0 before); after t0 the negative phase it
// gives, or 0 when negative_phase is false.
double friedlander(double p, double t0, double b, double tau, bool negative_phase);

// The pulse a charge sends to one point at the range r (deck units): the arrival time and
// duration in deck time, the peaks in deck pressure and the decay constants of the incident
// and reflected pulses.
struct BlastPulse {
  double arrival = 0.0, duration = 0.0;
  double pso = 0.0, pr = 0.0, b_incident = 0.0, b_reflected = 0.0;
};
BlastPulse blastPulse(const BlastCharge& charge, double range);

// The pressure at time t of the pulse on a surface whose outward normal makes cos_angle with
// the direction to the charge.
double blastPressure(const BlastCharge& charge, const BlastPulse& pulse, double t,
                     double cos_angle);

}  // namespace crumple::constraints
