// Discrete springs and dampers (formulation in discrete.hpp).
//
// Stable steps. A spring k between masses m1, m2 has omega_max^2 = k (m1 + m2) / (m1 m2), so
// central differences are stable up to 2 / omega_max; LS-DYNA takes
// sqrt(2 m1 m2 / (k (m1 + m2))), 1 / sqrt(2) of that, for margin (Theory Manual, "Time Step
// Control", discrete elements). For a damper c the explicit update of the relative velocity
// is u(n+1/2) = (1 - dt c (m1 + m2) / (m1 m2)) u(n-1/2): stable up to 2 m1 m2 / (c (m1 + m2)),
// and without overshoot (the relative velocity never reverses within a step) up to half
// that, m1 m2 / (c (m1 + m2)), which is the step used (our choice: we found no damper rule in
// the manual).
#include "elements/discrete.hpp"

#include "util/curve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace crumple::elements {

namespace {

using Vec = std::array<double, 3>;

inline Vec nodeVec(const domain::NodeVector& v, int32_t n) {
  const double* p = &v[3 * static_cast<std::size_t>(n)];
  return {p[0], p[1], p[2]};
}
inline double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double scaleOf(const domain::DiscreteBlock& b, std::size_t e) {
  return b.scale.empty() ? 1.0 : b.scale[e];
}
double offsetOf(const domain::DiscreteBlock& b, std::size_t e) {
  return b.offset.empty() ? 0.0 : b.offset[e];
}

// Curve value and slope at t (util/curve.hpp segments: the end slopes continue past the ends).
void curveAt(const std::vector<double>& x, const std::vector<double>& y, double t, double& value,
             double& slope) {
  if (x.empty()) {
    value = slope = 0.0;
    return;
  }
  util::valueAndSlope(x, y, t, value, slope);
}

// Spring force at elongation delta (springs only).
double springForce(const domain::DiscreteBlock& b, std::size_t e, double delta) {
  const double u = delta + offsetOf(b, e);
  if (b.law.kind == domain::DiscreteBlock::Kind::SpringElastic) return scaleOf(b, e) * b.law.k * u;
  double value = 0.0, slope = 0.0;
  curveAt(b.law.curve_x, b.law.curve_y, u, value, slope);
  return scaleOf(b, e) * value;
}

}  // namespace

void resizeDiscreteBlock(domain::DiscreteBlock& blk, std::size_t n) {
  blk.length0.assign(n, 0.0);
  blk.e_int.assign(n, 0.0);
  blk.force.assign(n, 0.0);
  blk.elongation.assign(n, 0.0);
}

void initializeDiscretes(domain::DiscreteBlock& blk, const domain::NodeVector& x0, double* slots) {
  const bool damper = blk.law.kind == domain::DiscreteBlock::Kind::DamperViscous;
  for (std::size_t e = 0; e < blk.size(); ++e) {
    const auto& c = blk.conn[e];
    const Vec x1 = nodeVec(x0, c[0]), x2 = nodeVec(x0, c[1]);
    const Vec d = {x2[0] - x1[0], x2[1] - x1[1], x2[2] - x1[2]};
    blk.length0[e] = std::sqrt(dot(d, d));
    blk.elongation[e] = 0.0;
    blk.force[e] = damper ? 0.0 : springForce(blk, e, 0.0);
    blk.e_int[e] = 0.0;
    if (slots != nullptr) {
      double* slot = slots + 3 * (blk.slot_offset + 2 * e);
      std::fill(slot, slot + 6, 0.0);
    }
  }
}

BlockStatus computeDiscreteForces(domain::DiscreteBlock& blk, const domain::NodeVector& x,
                                  const domain::NodeVector& v, double dt, double* slots,
                                  std::size_t first, std::size_t last) {
  if (first > last || last > blk.size())
    throw std::logic_error("computeDiscreteForces: element range outside the block");
  const bool damper = blk.law.kind == domain::DiscreteBlock::Kind::DamperViscous;
  BlockStatus st;
  for (std::size_t e = first; e < last; ++e) {
    double* slot = slots + 3 * (blk.slot_offset + 2 * e);
    const auto& c = blk.conn[e];
    const Vec x1 = nodeVec(x, c[0]), x2 = nodeVec(x, c[1]);
    const Vec d = {x2[0] - x1[0], x2[1] - x1[1], x2[2] - x1[2]};
    const double length = std::sqrt(dot(d, d));
    double force = 0.0;
    if (damper) {
      // Elongation rate at the mid-step geometry x(n) - dt/2 v: the midpoint rule, so that a
      // rigid rotation gives none.
      const Vec v1 = nodeVec(v, c[0]), v2 = nodeVec(v, c[1]);
      const Vec dv = {v2[0] - v1[0], v2[1] - v1[1], v2[2] - v1[2]};
      const Vec dm = {d[0] - 0.5 * dt * dv[0], d[1] - 0.5 * dt * dv[1], d[2] - 0.5 * dt * dv[2]};
      const double lm = std::sqrt(dot(dm, dm));
      const double rate = lm > 0.0 ? dot(dm, dv) / lm : 0.0;
      force = length > 0.0 ? scaleOf(blk, e) * blk.law.k * rate : 0.0;
      blk.e_int[e] += force * rate * dt;
      blk.elongation[e] = length - blk.length0[e];
    } else {
      const double delta = length - blk.length0[e];
      force = length > 0.0 ? springForce(blk, e, delta) : 0.0;
      blk.e_int[e] += 0.5 * (blk.force[e] + force) * (delta - blk.elongation[e]);
      blk.elongation[e] = delta;
    }
    blk.force[e] = force;
    const double f = length > 0.0 ? force / length : 0.0;
    for (int i = 0; i < 3; ++i) {
      const double fi = f * d[static_cast<std::size_t>(i)];
      slot[i] = fi;
      slot[3 + i] = -fi;
    }
  }
  return st;
}

double discreteStableStep(const domain::DiscreteBlock& blk, const std::vector<double>& nodal_mass,
                          std::size_t e) {
  constexpr double kNoLimit = 1e300;
  const auto& c = blk.conn[e];
  const double m1 = nodal_mass[static_cast<std::size_t>(c[0])];
  const double m2 = nodal_mass[static_cast<std::size_t>(c[1])];
  double m = 0.0;
  if (m1 > 0.0 && m2 > 0.0) {
    m = m1 * m2 / (m1 + m2);
  } else {
    m = std::max(m1, m2);
  }
  if (!(m > 0.0)) return kNoLimit;
  const double s = scaleOf(blk, e);
  switch (blk.law.kind) {
    case domain::DiscreteBlock::Kind::DamperViscous: {
      const double cd = std::abs(s * blk.law.k);
      return cd > 0.0 ? m / cd : kNoLimit;
    }
    case domain::DiscreteBlock::Kind::SpringNonlinear: {
      double value = 0.0, slope = 0.0;
      curveAt(blk.law.curve_x, blk.law.curve_y, blk.elongation[e] + offsetOf(blk, e), value, slope);
      const double k = s * slope;
      return k > 0.0 ? std::sqrt(2.0 * m / k) : kNoLimit;
    }
    default: {
      const double k = std::abs(s * blk.law.k);
      return k > 0.0 ? std::sqrt(2.0 * m / k) : kNoLimit;
    }
  }
}

}  // namespace crumple::elements
