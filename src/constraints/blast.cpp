#include "constraints/blast.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace crumple::constraints {

namespace {

// One Kingery-Bulmash fit: U = c0 + c1 log10 Z, log10 Y = sum k_i U^i (UFC 3-340-02, sec.
// 2-13; hemispherical surface burst, feet-pound-millisecond-psi units).
struct Fit {
  double c0, c1;
  std::vector<double> k;
};

double evaluate(const Fit& f, double z) {
  const double u = f.c0 + f.c1 * std::log10(z);
  double y = 0.0, power = 1.0;
  for (const double k : f.k) {
    y += k * power;
    power *= u;
  }
  return std::pow(10.0, y);
}

const Fit kIncidentPressure{
    -0.756579302,
    1.3503425,
    {1.942250201, -1.695898874, -0.154159377, 0.514060731, 0.098853437, -0.293912623, -0.026811235,
     0.109097496, 0.001628468, -0.021463103, 0.000145672, 0.001678478}};
const Fit kReflectedPressure{
    -0.789312406,
    1.366377192,
    {2.564313211, -2.210308706, -0.218536586, 0.895319589, 0.249890098, -0.569249437, -0.117916824,
     0.224131161, 0.024562026, -0.0455116, -0.001909307, 0.003614712}};
const Fit kArrivalTime{-0.755684473,
                       1.377842236,
                       {-0.173607601, 1.357064963, 0.052492799, -0.196563954, -0.060177005,
                        0.069636027, 0.021529749, -0.016165893, -0.00232532, 0.001477521}};
// Positive phase duration in three ranges of Z: 0.45-2.54, 2.54-7, 7-100. The seventh
// coefficient of the middle range is 1.61822e-4, as in the free-air fit; the value ten times
// larger that some transcriptions carry breaks the continuity at Z = 2.54 by a factor 1.8.
const Fit kDuration1{
    -0.179021705,
    5.250991939,
    {-0.728671776, 0.130143718, 0.134872512, 0.039157428, -0.004759337, -0.004281446}};
const Fit kDuration2{-5.859098123,
                     9.299628861,
                     {0.200965073, -0.029794427, 0.030632954, 0.018340557, -0.017396467,
                      -0.00106322, 0.0056206, 0.000161822, -0.000686019}};
const Fit kDuration3{
    -4.926994911,
    3.463497456,
    {0.57246247, 0.09330353, -0.000584942, -0.00226885, -0.002959086, 0.001480299}};
// Incident impulse in two ranges: 0.17-2.41, 2.41-100.
const Fit kIncidentImpulse1{
    0.832468843, 3.076032967, {1.571592406, -0.502992764, 0.171335645, 0.045017696, -0.011896463}};
const Fit kIncidentImpulse2{-2.913586168,
                            2.406977454,
                            {0.719852656, -0.384519027, -0.026081671, 0.005957988, 0.014544526,
                             -0.006632893, -0.002841893, 0.001364482}};
const Fit kReflectedImpulse{
    -0.781951689, 1.334220499, {1.752916778, -0.949516093, 0.112136119, -0.025065918}};

// 1 / b - (1 - exp(-b)) / b^2, with its series near b = 0 (where the difference cancels).
double friedlanderShape(double b) {
  if (std::abs(b) < 1e-4) return 0.5 - b / 6.0 + b * b / 24.0;
  return 1.0 / b - (1.0 - std::exp(-b)) / (b * b);
}

}  // namespace

BlastParameters hemisphericalBurst(double z) {
  z = std::clamp(z, kBlastZMin, kBlastZMax);
  BlastParameters p;
  p.pso = evaluate(kIncidentPressure, z);
  p.pr = evaluate(kReflectedPressure, z);
  p.ta = evaluate(kArrivalTime, z);
  const double zd = std::max(z, 0.45);
  p.t0 = evaluate(zd < 2.54 ? kDuration1 : zd < 7.0 ? kDuration2 : kDuration3, zd);
  p.is = evaluate(z < 2.41 ? kIncidentImpulse1 : kIncidentImpulse2, z);
  p.ir = evaluate(kReflectedImpulse, z);
  return p;
}

double friedlanderDecay(double p, double t0, double impulse) {
  if (!(p > 0.0) || !(t0 > 0.0)) return 0.0;
  const double target = impulse / (p * t0);
  // friedlanderShape falls monotonically from +inf (b -> -inf) to 0 (b -> +inf).
  double lo = -30.0, hi = 500.0;
  if (target >= friedlanderShape(lo)) return lo;
  if (target <= friedlanderShape(hi)) return hi;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (friedlanderShape(mid) > target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double friedlander(double p, double t0, double b, double tau, bool negative_phase) {
  if (tau < 0.0 || !(t0 > 0.0)) return 0.0;
  if (tau > t0 && !negative_phase) return 0.0;
  return p * (1.0 - tau / t0) * std::exp(-b * tau / t0);
}

BlastPulse blastPulse(const BlastCharge& c, double range) {
  const double w = c.mass * c.cfm;  // pounds of TNT
  const double w13 = std::cbrt(w);
  const BlastParameters k = hemisphericalBurst(range * c.cfl / w13);
  BlastPulse out;
  out.arrival = c.tbo + k.ta * w13 / c.cft;
  out.duration = k.t0 * w13 / c.cft;
  out.pso = k.pso / c.cfp;
  out.pr = k.pr / c.cfp;
  out.b_incident = friedlanderDecay(k.pso, k.t0, k.is);
  out.b_reflected = friedlanderDecay(k.pr, k.t0, k.ir);
  return out;
}

double blastPressure(const BlastCharge& c, const BlastPulse& pulse, double t, double cos_angle) {
  if (t >= c.death) return 0.0;
  const double tau = t - pulse.arrival;
  const double pi = friedlander(pulse.pso, pulse.duration, pulse.b_incident, tau, c.negative_phase);
  if (cos_angle < 0.0) return pi;
  const double pr = friedlander(pulse.pr, pulse.duration, pulse.b_reflected, tau, c.negative_phase);
  const double c2 = cos_angle * cos_angle;
  return pr * c2 + pi * (1.0 + c2 - 2.0 * cos_angle);
}

}  // namespace crumple::constraints
