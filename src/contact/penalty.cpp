#include "contact/penalty.hpp"

#include <algorithm>
#include <cmath>

namespace crumple::contact {

namespace {

// Stability: a contact spring adds k / m* to the square of the highest frequency of the nodes
// it joins, which the element step (TSSFAC 0.9) leaves little room for; a node of a symmetric
// interface may carry several springs. Capping k at kStableFraction m* / dt^2 keeps omega dt
// of one spring at or below 2 sqrt(kStableFraction). dt is the stiffness step (the initial
// step, raised when the step grows), never the current one: a cap that rose when the step fell
// would multiply the force of every penetration already there in one cycle, and make energy.
constexpr double kStableFraction = 0.1;
// The rotational tie (addTiedMoment): the shells' rotary inertia is scaled up so that their
// rotations never set the step, which leaves room for a stiffer spring than the translational
// cap; at 0.1 the tied edge of a T-joint was 13% more flexible than the merged joint.
constexpr double kRotationalFraction = 2.0;

// m* = m_node m_seg / (m_node + m_seg), the mass of the node-segment pair.
double pairMass(double m_node, double m_seg) {
  return m_node + m_seg > 0.0 ? m_node * m_seg / (m_node + m_seg) : 0.0;
}

double stableStiffness(double k, double m_eff, double dt_stiff) {
  if (dt_stiff > 0.0 && m_eff > 0.0)
    k = std::min(k, kStableFraction * m_eff / (dt_stiff * dt_stiff));
  return k;
}

// VDC percent of critical damping of the node-segment pair.
double dampingCoefficient(const model::ContactInterface& ci, double k, double m_eff) {
  return 0.01 * ci.vdc * 2.0 * std::sqrt(k * m_eff);
}

}  // namespace

void pack(const Record& r, std::vector<double>& out) {
  forEachField(r, [&](const auto& v) { out.push_back(double(v)); });
}

Record unpack(const double* in) {
  Record r;
  forEachField(r, [&](auto& v) { v = static_cast<std::remove_reference_t<decltype(v)>>(*in++); });
  return r;
}

Record penaltyForce(const Penetration& p, const NodeAndSegment& m, double stiffness,
                    const Vec3& friction, const model::ContactInterface& ci, double dt_stiff,
                    double dt_prev) {
  // Relative velocity of the node to the contact point of the segment.
  Vec3 vrel = m.v_node;
  double m_seg = 0.0;
  for (std::size_t a = 0; a < 4; ++a) {
    if (p.N[a] == 0.0) continue;
    vrel = sub(vrel, scale(m.v_seg[a], p.N[a]));
    m_seg += p.N[a] * m.m_seg[a];
  }
  const double m_eff = pairMass(m.m_node, m_seg);
  double k = stiffness;
  // SOFT = 1: a stiffness from the masses and the step, so soft foam against steel still
  // stops (LS-DYNA Theory Manual, "soft constraint penalty": 0.5 SOFSCL m / dt^2, dt the
  // initial step, updated when the step grows, or the interface's DTSTIF when given).
  const double dt_soft = ci.dtstif > 0.0 ? ci.dtstif : dt_stiff;
  if (ci.soft == 1 && dt_soft > 0.0) k = std::max(k, 0.5 * ci.sofscl * m_eff / (dt_soft * dt_soft));
  k = stableStiffness(k, m_eff, dt_stiff);
  const Vec3& n = p.push;
  const double pen = p.depth;
  const double vn = dot(vrel, n);
  double fn = k * pen;
  if (ci.vdc > 0.0) fn -= dampingCoefficient(ci, k, m_eff) * vn;
  fn = std::max(fn, 0.0);
  // Energy dissipated by the damping part of fn over the last step (v(n-1/2) dt(n-1/2)).
  double dissipated = -(fn - k * pen) * vn * dt_prev;
  Vec3 ft{};
  if (ci.fs > 0.0 || ci.fd > 0.0) {
    // Elastic stick: the tangential force grows by k times the slip increment and is capped
    // at mu fn.
    const Vec3 vt = sub(vrel, scale(n, vn));
    const double mu = ci.fd + (ci.fs - ci.fd) * std::exp(-ci.dc * norm(vt));
    Vec3 old = sub(friction, scale(n, dot(friction, n)));
    ft = sub(old, scale(vt, k * dt_prev));
    const double cap = mu * fn;
    const double mag = norm(ft);
    if (mag > cap) ft = mag > 0.0 ? scale(ft, cap / mag) : Vec3{};
  }
  dissipated -= dot(ft, sub(vrel, scale(n, vn))) * dt_prev;
  Record r;
  r.check = p.check;
  r.segment = p.segment;
  r.N = p.N;
  r.force = add(scale(n, fn), ft);
  r.friction = ft;
  r.penetration = pen;
  r.energy = 0.5 * k * pen * pen;
  r.dissipated = dissipated;
  r.side = p.side;
  r.entry = p.entry;
  return r;
}

Record tiedForce(int32_t check, int32_t segment, const std::array<double, 4>& N, double offset,
                 const NodeAndSegment& m, double stiffness, const model::ContactInterface& ci,
                 double dt_stiff, double dt_prev) {
  Vec3 xc{}, vc{};
  double m_seg = 0.0;
  for (std::size_t a = 0; a < 4; ++a) {
    if (a == 3 && m.triangle) break;
    xc = add(xc, scale(m.x_seg[a], N[a]));
    vc = add(vc, scale(m.v_seg[a], N[a]));
    m_seg += N[a] * m.m_seg[a];
  }
  if (offset != 0.0)
    xc = add(xc, scale(segmentNormal(m.x_seg[0], m.x_seg[1], m.x_seg[2], m.x_seg[3]), offset));
  const Vec3 g = sub(xc, m.x_node);
  const double m_eff = pairMass(m.m_node, m_seg);
  const double k = stableStiffness(stiffness, m_eff, dt_stiff);
  Vec3 f = scale(g, k);
  double dissipated = 0.0;
  if (ci.vdc > 0.0) {
    const Vec3 dv = sub(vc, m.v_node);
    const double c_damp = dampingCoefficient(ci, k, m_eff);
    f = add(f, scale(dv, c_damp));
    dissipated = c_damp * dot(dv, dv) * dt_prev;
  }
  const double gap = norm(g);
  Record r;
  r.check = check;
  r.segment = segment;
  r.N = N;
  r.force = f;
  r.penetration = gap;
  r.energy = 0.5 * k * gap * gap;
  r.dissipated = dissipated;
  return r;
}

bool tieBreaks(const Record& r, const NodeAndSegment& m, int side,
               const model::ContactInterface::Tiebreak& tb, double area) {
  const Vec3 n = segmentNormal(m.x_seg[0], m.x_seg[1], m.x_seg[2], m.x_seg[3]);
  // The force on the node pulls it back towards the segment when the bond is in tension.
  const double along = dot(r.force, n);
  const double tension = std::max(0.0, -side * along);
  const double shear = norm(sub(r.force, scale(n, along)));
  const double scale_by = tb.stress ? area : 1.0;
  const double fn = tb.normal * scale_by, fs = tb.shear * scale_by;
  if (!(fn > 0.0) || !(fs > 0.0)) return true;  // a node with no area holds nothing
  return std::pow(tension / fn, tb.nen) + std::pow(shear / fs, tb.mes) >= 1.0;
}

void addTiedMoment(Record& r, const NodeAndSegment& m, const Vec3& moment, double dt_stiff,
                   double dt_prev) {
  Vec3 xc{}, wc{};
  double i_seg = 0.0;
  for (std::size_t a = 0; a < 4; ++a) {
    if (a == 3 && m.triangle) break;
    xc = add(xc, scale(m.x_seg[a], r.N[a]));
    wc = add(wc, scale(m.w_seg[a], r.N[a]));
    i_seg += r.N[a] * m.i_seg[a];
  }
  // The force acts at the node, its reaction at the tied point: their moment goes to the
  // segment's nodes as moments (the nodes of a solid have none to take it).
  r.arm = cross(sub(m.x_node, xc), r.force);
  const double i_eff = pairMass(m.i_node, i_seg);
  if (!(m.i_node > 0.0) || !(i_seg > 0.0) || !(dt_stiff > 0.0)) return;
  const double k = kRotationalFraction * i_eff / (dt_stiff * dt_stiff);
  const Vec3 dw = sub(wc, m.w_node);
  // The stored moment turns with the pair (objective under a rigid spin of the joint).
  const Vec3 spin = scale(add(wc, m.w_node), 0.5);
  Vec3 mo = add(moment, scale(cross(spin, moment), dt_prev));
  mo = add(mo, scale(dw, k * dt_prev));
  r.moment = mo;
  r.energy += 0.5 * dot(mo, mo) / k;
}

}  // namespace crumple::contact
