// Beam and truss kernels (formulations in beam.hpp).
//
// Corotational frame (ELFORM 1, 2). Each end node of an element carries its own frame T_a
// (columns r, s, t), stored as a unit quaternion and turned every cycle by the node's
// rotation increment exp(omega(n-1/2) dt), so it is the node's rotation since the start
// applied to the initial element frame. The element frame E = (e1, e2, e3) follows the chord,
// e1 = (x2 - x1) / L, with e2 in the plane of e1 and the mean of the two nodal s axes
// (Crisfield, Non-linear Finite Element Analysis of Solids and Structures, vol. 2, 1997,
// ch. 17: the twist is shared between the ends). The deformational rotation of node a is the
// rotation vector of E^T T_a; a rigid motion leaves it zero to round-off however large the
// rotation. The deformation of an element is then
//   d = (L - L0, theta_2r - theta_1r, theta_1s, theta_1t, theta_2s, theta_2t)
// and its virtual work through the chord (a transverse displacement turns the chord by
// (dx2 - dx1) / L) gives the end forces from the resultants conjugate to d:
//   f_int(1) = -N e1 + (G_1t + G_2t) / L e2 - (G_1s + G_2s) / L e3,  f_int(2) = -f_int(1),
//   m_int(a) = G_ar e1 + G_as e2 + G_at e3,
// equilibrated exactly (forces and moments sum to zero), so momentum and angular momentum are
// conserved. The slots get minus these (the force on the node).
//
// Resultants (ELFORM 2), in the element frame and incrementally, the increments of d over the
// step through the elastic stiffness of a Timoshenko beam (phi = 12 E I / (G SA L0^2); SA = 0:
// no shear deformation; Przemieniecki, Theory of Matrix Structural Analysis, 1968, sec. 5.6):
//   N += E A dd_0 / L0,  T += G J dd_1 / L0,
//   M_1 += E I / (L0 (1 + phi)) ((4 + phi) dtheta_1 + (2 - phi) dtheta_2),  M_2 likewise.
// Plastic laws on ELFORM 2: LS-DYNA's plasticity for the resultant beam is *MAT_028
// (RESULTANT_PLASTICITY), whose beam treatment its keyword manual gives as elastic-perfectly
// plastic; what LS-DYNA itself does with 003 and 024 on ELFORM 2 we could not check. Here
// those laws run as an elastic-perfectly-plastic resultant model with their initial yield
// stress (no hardening, rate effects or failure): at each end the resultants are
// scaled back onto (N/Np)^2 + (T/Tp)^2 + (Ms/Msp)^2 + (Mt/Mtp)^2 <= 1, with the fully plastic
// values of a solid section of the given A, I and J: Np = sigy A, Mp = sqrt(3) / 2 sigy
// sqrt(A I) (solid rectangle: A h / 4 with h = sqrt(12 I / A)), Tp = 2 sqrt(2) / 3 tau_y
// sqrt(A J) (solid circle), tau_y = sigy / sqrt(3). This is an estimate; sections with other
// shape factors need *MAT_028-like data the deck does not give.
//
// Hughes-Liu (ELFORM 1), one point along the axis, written in the same corotational frame
// rather than with the nodal fibre directors of the degenerated continuum (for one point
// along the axis both give the same strain increments to first order in the step): strain
// eps0 = dd_0 / L0, curvatures kappa_s = (theta_2s - theta_1s) / L0, kappa_t likewise, twist
// kappa_r = dd_1 / L0, and transverse shear at mid-length gamma_s = -(theta_1t + theta_2t) / 2,
// gamma_t = (theta_1s + theta_2s) / 2 (the chord carries no slope in its own frame). A point
// (s, t) of the section strains by
//   de = deps0 - s dkappa_t + t dkappa_s,  dg_s = k dgamma_s - t dkappa_r,
//   dg_t = k dgamma_t + s dkappa_r      (k = SHRF),
// the law updates (sigma, tau_s, tau_t) there, and the section integrals N = int sigma,
// M_s = int sigma t, M_t = -int sigma s, Q = k int tau, T = int (s tau_t - t tau_s) give
//   G_1s = -M_s + L0 Q_t / 2, G_2s = M_s + L0 Q_t / 2, G_1t = -M_t - L0 Q_s / 2,
//   G_2t = M_t - L0 Q_s / 2, G_1r = -T, G_2r = T.
// One point along the axis leaves no spurious mode in a two-node Timoshenko beam (both of
// its deformation modes per plane, curvature and shear, strain the point), so no hourglass
// control is needed. Torsion follows from the points (the polar moment; for rectangles this
// exceeds St Venant's J, as in any fibre-integrated beam).
//
// Truss (ELFORM 3): the rate of deformation at the mid-step geometry, de = dt e . dv / L
// (the midpoint rule: zero for a rigid rotation), updates the axial stress, which is the
// true stress on the current area A0 L0 / L (constant volume).
//
// Mass (LS-DYNA Theory Manual, "Belytschko Beam" and "Hughes-Liu Beam": lumped
// translational mass rho A L / 2 per node). Rotational inertia: the manual's bending step
// for ELFORM 2 (beamTimeStep) is, we find, exactly the critical step 2 / omega of a free
// element whose nodes carry m = rho A L / 2 and the inertia
//   I_r = rho L (A L^2 + 12 I) / 8 = m (L^2 / 4 + 3 I / A),   I = max(ISS, ITT):
// its antisymmetric bending mode (w1 = -w2, theta1 = theta2) has
// omega^2 = E I / L^3 (24 / m + 6 L^2 / I_r) = 48 c^2 I / L^2 (1 / (A L^2) + 1 / (12 I + A L^2)),
// the manual's expression, and its other rotational modes are slower (checked by the unit
// test BeamResultant.StableStepIsSharp). We lump I_r about every axis (a scalar inertia; the
// solver's nodes have no inertia tensor), so that rotation never sets a step below the
// manual's. With it the Hughes-Liu beam's shear mode stays within its L / c step while
// SHRF <= 1 + nu. The DYNA3D source was not available to us to compare its own lumping.
#include "elements/beam.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <variant>

#include "elements/beam_release.hpp"
#include "materials/laws/muscle.hpp"
#include "materials/uniaxial.hpp"
#include "util/curve.hpp"
#include "util/vec3.hpp"

namespace crumple::elements {

namespace {

using Vec = util::Vec3;
using Quat = std::array<double, 4>;  // w, x, y, z
using util::add;
using util::cross;
using util::dot;
using util::norm;
using util::scale;
using util::sub;
inline Vec nodeVec(const domain::NodeVector& v, int32_t n) {
  const double* p = &v[3 * static_cast<std::size_t>(n)];
  return {p[0], p[1], p[2]};
}

// A frame: its three axes in global coordinates (the columns of a rotation matrix).
struct Frame {
  Vec r, s, t;
};

Frame frameOf(const Quat& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {{1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + w * z), 2.0 * (x * z - w * y)},
          {2.0 * (x * y - w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z + w * x)},
          {2.0 * (x * z + w * y), 2.0 * (y * z - w * x), 1.0 - 2.0 * (x * x + y * y)}};
}

// Unit quaternion of the rotation whose matrix has columns r, s, t (Shepperd's method: the
// largest of the four candidates is the one taken through the square root).
Quat quatOf(const Frame& f) {
  const double m00 = f.r[0], m10 = f.r[1], m20 = f.r[2];
  const double m01 = f.s[0], m11 = f.s[1], m21 = f.s[2];
  const double m02 = f.t[0], m12 = f.t[1], m22 = f.t[2];
  const double tr = m00 + m11 + m22;
  Quat q;
  if (tr > 0.0) {
    const double s = 2.0 * std::sqrt(tr + 1.0);
    q = {0.25 * s, (m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s};
  } else if (m00 > m11 && m00 > m22) {
    const double s = 2.0 * std::sqrt(1.0 + m00 - m11 - m22);
    q = {(m21 - m12) / s, 0.25 * s, (m01 + m10) / s, (m02 + m20) / s};
  } else if (m11 > m22) {
    const double s = 2.0 * std::sqrt(1.0 + m11 - m00 - m22);
    q = {(m02 - m20) / s, (m01 + m10) / s, 0.25 * s, (m12 + m21) / s};
  } else {
    const double s = 2.0 * std::sqrt(1.0 + m22 - m00 - m11);
    q = {(m10 - m01) / s, (m02 + m20) / s, (m12 + m21) / s, 0.25 * s};
  }
  return q;
}

// q turned by the rotation vector phi (global axes): exp(phi) q, renormalised.
Quat rotated(const Quat& q, const Vec& phi) {
  const double angle = norm(phi);
  const double h = 0.5 * angle;
  // sin(h) / angle, with its series where the division loses digits.
  const double k = angle > 1e-4 ? std::sin(h) / angle : 0.5 - angle * angle / 48.0;
  const double dw = std::cos(h), dx = k * phi[0], dy = k * phi[1], dz = k * phi[2];
  Quat p = {
      dw * q[0] - dx * q[1] - dy * q[2] - dz * q[3], dw * q[1] + dx * q[0] + dy * q[3] - dz * q[2],
      dw * q[2] + dy * q[0] + dz * q[1] - dx * q[3], dw * q[3] + dz * q[0] + dx * q[2] - dy * q[1]};
  const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]);
  for (double& c : p) c /= n;
  return p;
}

// Rotation vector, in the element frame E, of the rotation E^T T (the node frame seen from
// the element): axis times angle, from the skew part and the trace.
Vec relativeRotation(const Frame& E, const Frame& T) {
  // Q_ij = E_i . T_j
  const Vec* e[3] = {&E.r, &E.s, &E.t};
  const Vec* t[3] = {&T.r, &T.s, &T.t};
  double Q[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Q[i][j] = dot(*e[i], *t[j]);
  const Vec v = {0.5 * (Q[2][1] - Q[1][2]), 0.5 * (Q[0][2] - Q[2][0]), 0.5 * (Q[1][0] - Q[0][1])};
  const double sin_a = norm(v);
  const double cos_a = 0.5 * (Q[0][0] + Q[1][1] + Q[2][2] - 1.0);
  const double angle = std::atan2(sin_a, cos_a);
  const double f = sin_a > 1e-8 ? angle / sin_a : 1.0 + sin_a * sin_a / 6.0;
  return scale(v, f);
}

// Cross-section of a block: area, second moments, torsion constant, and for Hughes-Liu the
// integration points (s, t) with their areas.
constexpr std::size_t kMaxPoints = 32;
struct Section {
  double area = 0.0, iss = 0.0, itt = 0.0, j = 0.0;
  int points = 0;
  std::array<double, kMaxPoints> s{}, t{}, w{};
};

// One-dimensional rules on [-1, 1] for QR 1..5.
struct Rule {
  int n;
  std::array<double, 5> x, w;
};
Rule ruleOf(int qr) {
  const double g2 = 1.0 / std::sqrt(3.0), g3 = std::sqrt(0.6);
  switch (qr) {
    case 1:
      return {1, {0.0}, {2.0}};
    case 3:
      return {3, {-g3, 0.0, g3}, {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};
    case 4:  // Lobatto: points on the faces, where plastic flow starts
      return {3, {-1.0, 0.0, 1.0}, {1.0 / 3.0, 4.0 / 3.0, 1.0 / 3.0}};
    case 5:
      return {4,
              {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526},
              {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538}};
    default:
      return {2, {-g2, g2}, {1.0, 1.0}};
  }
}

constexpr int kRingPoints = 16;
constexpr double kPi = 3.14159265358979323846;

// A section of *INTEGRATION_BEAM points (QR/IRID < 0): A, ISS, ITT from the points, so that
// the mass and the elastic stiffness are those the points integrate; J the polar moment, as
// for the built-in rules.
Section userSection(const domain::BeamSection& sec, double ts, double tt) {
  Section out;
  const double full = sec.user_ra * ts * tt;
  out.points = static_cast<int>(std::min(sec.user_points.size(), kMaxPoints));
  for (std::size_t k = 0; k < static_cast<std::size_t>(out.points); ++k) {
    const auto& p = sec.user_points[k];
    out.s[k] = sec.user_normalized ? 0.5 * ts * p[0] : p[0];
    out.t[k] = sec.user_normalized ? 0.5 * tt * p[1] : p[1];
    out.w[k] = sec.user_normalized ? p[2] * full : p[2];
    out.area += out.w[k];
    out.iss += out.w[k] * out.t[k] * out.t[k];
    out.itt += out.w[k] * out.s[k] * out.s[k];
  }
  out.j = out.iss + out.itt;
  return out;
}

Section sectionOf(const domain::BeamSection& sec) {
  Section out;
  if (sec.elform != 1 && sec.elform != 9) {
    out.area = sec.a;
    out.iss = sec.iss;
    out.itt = sec.itt;
    out.j = sec.j;
    out.points = sec.elform == 3 ? 1 : 0;
    return out;
  }
  // Hughes-Liu and spot weld: the section at mid-length (one point along the axis); TS2, TT2
  // default to TS1, TT1 (LS-DYNA *SECTION_BEAM).
  const double ts = 0.5 * (sec.ts1 + (sec.ts2 > 0.0 ? sec.ts2 : sec.ts1));
  const double tt = 0.5 * (sec.tt1 + (sec.tt2 > 0.0 ? sec.tt2 : sec.tt1));
  if (!sec.user_points.empty()) return userSection(sec, ts, tt);
  if (sec.cst == 1) {
    // Tube, outer diameter ts, inner tt: 16 points on the ring of radius
    // sqrt((Ro^2 + Ri^2) / 2), which gives A, I and the polar moment J exactly.
    const double ro = 0.5 * ts, ri = 0.5 * tt;
    out.area = kPi * (ro * ro - ri * ri);
    out.iss = out.itt = 0.25 * out.area * (ro * ro + ri * ri);
    out.j = out.iss + out.itt;
    const double radius = std::sqrt(0.5 * (ro * ro + ri * ri));
    out.points = kRingPoints;
    for (int k = 0; k < kRingPoints; ++k) {
      const double angle = (k + 0.5) * 2.0 * kPi / kRingPoints;
      out.s[static_cast<std::size_t>(k)] = radius * std::cos(angle);
      out.t[static_cast<std::size_t>(k)] = radius * std::sin(angle);
      out.w[static_cast<std::size_t>(k)] = out.area / kRingPoints;
    }
    return out;
  }
  out.area = ts * tt;
  out.iss = ts * tt * tt * tt / 12.0;  // about s: the stress varies along t
  out.itt = tt * ts * ts * ts / 12.0;
  out.j = out.iss + out.itt;
  const Rule rule = ruleOf(sec.qr);
  out.points = rule.n * rule.n;
  for (int i = 0; i < rule.n; ++i)
    for (int k = 0; k < rule.n; ++k) {
      const auto p = static_cast<std::size_t>(i * rule.n + k);
      const auto ii = static_cast<std::size_t>(i), kk = static_cast<std::size_t>(k);
      out.s[p] = 0.5 * ts * rule.x[ii];
      out.t[p] = 0.5 * tt * rule.x[kk];
      out.w[p] = 0.25 * out.area * rule.w[ii] * rule.w[kk];
    }
  return out;
}

// The initial frame of an element: r along the chord, s in the plane of the nodes and the
// orientation point (beam.hpp for the default).
Frame initialFrame(const Vec& x1, const Vec& x2, const std::array<double, 3>& orientation) {
  const Vec d = sub(x2, x1);
  const Vec r = scale(d, 1.0 / norm(d));
  Vec s = {0.0, 0.0, 0.0};
  const bool given = std::isfinite(orientation[0]) && std::isfinite(orientation[1]) &&
                     std::isfinite(orientation[2]);
  if (given) {
    const Vec p = sub({orientation[0], orientation[1], orientation[2]}, x1);
    s = sub(p, scale(r, dot(p, r)));
  }
  // The default, also for an orientation point on the beam's line (no plane to span).
  if (!given || norm(s) <= 1e-10 * norm(d)) {
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(r[static_cast<std::size_t>(i)]) < std::abs(r[static_cast<std::size_t>(k)]))
        k = i;
    Vec axis = {0.0, 0.0, 0.0};
    axis[static_cast<std::size_t>(k)] = 1.0;
    s = sub(axis, scale(r, r[static_cast<std::size_t>(k)]));
  }
  s = scale(s, 1.0 / norm(s));
  return {r, s, cross(r, s)};
}

// The element frame at x(n) from the chord and the nodal frames.
Frame elementFrame(const Vec& e1, const Frame& t1, const Frame& t2) {
  const Vec p = add(t1.s, t2.s);
  Vec e3 = cross(e1, p);
  e3 = scale(e3, 1.0 / norm(e3));
  return {e1, cross(e3, e1), e3};
}

// The resultant return of ELFORM 2 with a plastic law (see the top of this file).
struct ResultantCapacity {
  double n = 0.0, t = 0.0, ms = 0.0, mt = 0.0;
};

ResultantCapacity capacityOf(const Section& sec, double sigy) {
  ResultantCapacity c;
  c.n = sigy * sec.area;
  c.ms = 0.5 * std::sqrt(3.0) * sigy * std::sqrt(sec.area * sec.iss);
  c.mt = 0.5 * std::sqrt(3.0) * sigy * std::sqrt(sec.area * sec.itt);
  c.t = 2.0 * std::sqrt(2.0) / 3.0 * (sigy / std::sqrt(3.0)) * std::sqrt(sec.area * sec.j);
  return c;
}

inline double ratio2(double value, double capacity) {
  if (!(capacity > 0.0)) return 0.0;  // no stiffness there either (A, I or J zero)
  const double r = value / capacity;
  return r * r;
}

void returnResultants(std::array<double, 6>& R, const ResultantCapacity& cap) {
  const double shared = ratio2(R[0], cap.n) + ratio2(R[1], cap.t);
  const double f1 = shared + ratio2(R[2], cap.ms) + ratio2(R[3], cap.mt);
  const double f2 = shared + ratio2(R[4], cap.ms) + ratio2(R[5], cap.mt);
  const double b1 = f1 > 1.0 ? 1.0 / std::sqrt(f1) : 1.0;
  const double b2 = f2 > 1.0 ? 1.0 / std::sqrt(f2) : 1.0;
  // Axial force and torque are shared by the ends: the stronger scaling applies to them, each
  // end's moments take their own (every end then lies on or inside its surface).
  const double b = std::min(b1, b2);
  R[0] *= b;
  R[1] *= b;
  R[2] *= b1;
  R[3] *= b1;
  R[4] *= b2;
  R[5] *= b2;
}

// The axial force a preloaded element carries at t(n) (*INITIAL_AXIAL_FORCE_BEAM), or NaN
// once its curve has ended (the preload is complete: LS-DYNA Keyword Manual, "when the load
// curve ends ... the initialization is assumed to be completed") or for an element without
// one.
double preloadForce(const domain::BeamBlock& blk, std::size_t e) {
  if (blk.preload.empty() || blk.preload[e] < 0) return std::nan("");
  const auto& p = blk.preloads[static_cast<std::size_t>(blk.preload[e])];
  if (!(blk.time < p.t.back())) return std::nan("");
  double value = 0.0, slope = 0.0;
  util::valueAndSlope(p.t, p.force, std::max(blk.time, p.t.front()), value, slope);
  return p.scale * value;
}

// Sets the axial stress of the section's points so that they carry the preload force: all the
// same (KBEND = 0, no bending stiffness during the preload) or shifted by a common amount,
// which keeps the gradient the bending gave them (KBEND = 1).
void applyPreload(materials::FibrePoint* pts, const Section& sec, double force, bool kbend) {
  const auto npt = static_cast<std::size_t>(sec.points);
  double carried = 0.0;
  for (std::size_t i = 0; i < npt; ++i) carried += sec.w[i] * pts[i].sig;
  const double shift = (force - carried) / sec.area;
  for (std::size_t i = 0; i < npt; ++i) pts[i].sig = kbend ? pts[i].sig + shift : force / sec.area;
}

// One step of the section's points (Hughes-Liu, spot weld) from the increments dd of the
// corotational deformation: strains at the points, the law (and a preload), the section
// integrals into blk.resultant[e], the work into blk.e_int[e]. True when a point has failed.
bool integrateSection(domain::BeamBlock& blk, std::size_t e, const materials::FibreLaw& law,
                      const Section& sec, const std::array<double, 6>& dd, double dt) {
  const double L0 = blk.length0[e], shrf = blk.section.shear_factor;
  const auto npt = static_cast<std::size_t>(blk.points);
  const double deps0 = dd[0] / L0, dkr = dd[1] / L0;
  const double dks = (dd[4] - dd[2]) / L0, dkt = (dd[5] - dd[3]) / L0;
  const double dgs = -0.5 * shrf * (dd[3] + dd[5]);
  const double dgt = 0.5 * shrf * (dd[2] + dd[4]);
  materials::FibrePoint* pts = &blk.point[e * npt];
  std::array<double, kMaxPoints> so{}, tso{}, tto{}, des{}, dgss{}, dgts{};
  bool failed = false;
  for (std::size_t i = 0; i < npt; ++i) {
    const double s = sec.s[i], t = sec.t[i];
    des[i] = deps0 - s * dkt + t * dks;
    dgss[i] = dgs - t * dkr;
    dgts[i] = dgt + s * dkr;
    materials::FibrePoint& p = pts[i];
    so[i] = p.sig;
    tso[i] = p.tau_s;
    tto[i] = p.tau_t;
    failed = materials::updateFibre(law, p, des[i], dgss[i], dgts[i], dt) || failed;
  }
  const double preload = preloadForce(blk, e);
  if (std::isfinite(preload))
    applyPreload(pts, sec, preload, blk.preloads[static_cast<std::size_t>(blk.preload[e])].kbend);
  double N = 0.0, Ms = 0.0, Mt = 0.0, Qs = 0.0, Qt = 0.0, T = 0.0, work = 0.0;
  for (std::size_t i = 0; i < npt; ++i) {
    const double s = sec.s[i], t = sec.t[i], wa = sec.w[i];
    const materials::FibrePoint& p = pts[i];
    work += wa * (0.5 * (so[i] + p.sig) * des[i] + 0.5 * (tso[i] + p.tau_s) * dgss[i] +
                  0.5 * (tto[i] + p.tau_t) * dgts[i]);
    N += wa * p.sig;
    Ms += wa * p.sig * t;
    Mt -= wa * p.sig * s;
    Qs += wa * p.tau_s;
    Qt += wa * p.tau_t;
    T += wa * (s * p.tau_t - t * p.tau_s);
  }
  Qs *= shrf;
  Qt *= shrf;
  blk.e_int[e] += work * L0;
  blk.resultant[e] = {
      N, T, -Ms + 0.5 * L0 * Qt, -Mt - 0.5 * L0 * Qs, Ms + 0.5 * L0 * Qt, Mt - 0.5 * L0 * Qs};
  return failed;
}

// *MAT_SPOTWELD's failure of a weld beam at t(n) from its end resultants R (laws/spotweld.hpp):
// the time TFAIL, or the resultant criterion with the section forces at mid-length (the
// integration point: beamSectionResultants' conversion).
bool weldFails(const materials::ResultantFailure& f, const std::array<double, 6>& R, double L0,
               double time) {
  if (f.tfail > 0.0 && time >= f.tfail) return true;
  if (!f.byResultants()) return false;
  const double n = std::max(R[0], 0.0), qs = -(R[3] + R[5]) / L0, qt = (R[2] + R[4]) / L0;
  const double ms = 0.5 * (R[4] - R[2]), mt = 0.5 * (R[5] - R[3]), torque = R[1];
  const double sum = ratio2(n, f.nrr) + ratio2(qs, f.nrs) + ratio2(qt, f.nrt) +
                     ratio2(torque, f.mrr) + ratio2(ms, f.mss) + ratio2(mt, f.mtt);
  return sum >= 1.0;
}

void noteBad(BlockStatus& st, int32_t elem) {
  if (st.bad_elem < 0 || elem < st.bad_elem) st.bad_elem = elem;
}

void noteStep(BlockStatus& st, double dt, int32_t elem) {
  if (dt < st.dt_min || (dt == st.dt_min && elem < st.dt_elem)) {
    st.dt_min = dt;
    st.dt_elem = elem;
  }
}

}  // namespace

double beamRotationalInertia(double rho, double length, double area, double i_max) {
  return rho * length * (area * length * length + 12.0 * i_max) / 8.0;
}

double beamTimeStep(const domain::BeamSection& section, double length, double E, double G,
                    double rho) {
  const double c = std::sqrt(E / rho);
  double dt = length / c;
  if (section.elform == 2) {
    const double A = section.a, I = std::max(section.iss, section.itt);
    const double al2 = A * length * length;
    if (I > 0.0 && al2 > 0.0) {
      const double bending =
          0.5 * length / (c * std::sqrt(3.0 * I * (1.0 / (12.0 * I + al2) + 1.0 / al2)));
      dt = std::min(dt, bending);
    }
    // Torsional mode of the free element, theta1 = -theta2: omega^2 = 2 G J / (L I_r).
    const double ir = beamRotationalInertia(rho, length, A, I);
    if (section.j > 0.0 && ir > 0.0)
      dt = std::min(dt, 2.0 * std::sqrt(length * ir / (2.0 * G * section.j)));
  }
  return dt;
}

double dampedStep(double dt, double beta) {
  if (!(beta > 0.0) || !(dt > 0.0)) return dt;
  const double xi = beta / dt;  // beta omega_max / 2 with omega_max = 2 / dt
  return dt * (std::sqrt(1.0 + xi * xi) - xi);
}

void resizeBeamBlock(domain::BeamBlock& blk, std::size_t n) {
  const Section sec = sectionOf(blk.section);
  const bool frames = blk.section.elform != 3;
  blk.length0.assign(n, 0.0);
  blk.e_int.assign(n, 0.0);
  const bool damped = blk.stiffness_damping > 0.0 || blk.stiffness_fraction > 0.0;
  blk.e_damp.assign(damped ? n : 0, 0.0);
  blk.damping_resultant.assign(damped ? n : 0, {});
  blk.active.assign(n, 1);
  blk.triad.assign(frames ? n : 0, {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0});
  blk.deformation.assign(frames ? n : 0, {});
  blk.resultant.assign(n, {});
  blk.points = sec.points;
  blk.point.assign(n * static_cast<std::size_t>(sec.points), materials::FibrePoint{});
}

BlockStatus initializeBeams(domain::BeamBlock& blk, const domain::NodeVector& x0, double* slots,
                            std::vector<double>& element_dt) {
  const Section sec = sectionOf(blk.section);
  const double E = materials::youngOf(materials::moduliOf(blk.law));
  const double G = materials::moduliOf(blk.law).shear;
  const bool frames = blk.section.elform != 3;
  const double i_max = std::max(sec.iss, sec.itt);
  const materials::Muscle* muscle = std::get_if<materials::Muscle>(&blk.law);
  BlockStatus st;
  const std::size_t ne = blk.size();
  element_dt.assign(ne, 0.0);
  for (std::size_t e = 0; e < ne; ++e) {
    double* slot = slots + 3 * (blk.slot_offset + 4 * e);
    std::fill(slot, slot + 12, 0.0);
    const auto& c = blk.conn[e];
    const Vec x1 = nodeVec(x0, c[0]), x2 = nodeVec(x0, c[1]);
    const double length = norm(sub(x2, x1));
    blk.length0[e] = length;
    blk.e_int[e] = 0.0;
    blk.active[e] = 1;
    if (!(length > 0.0)) {
      noteBad(st, blk.elem[e]);
      continue;
    }
    if (frames) {
      const Quat q = quatOf(initialFrame(x1, x2, blk.orientation[e]));
      blk.triad[e] = {q[0], q[1], q[2], q[3], q[0], q[1], q[2], q[3]};
      blk.deformation[e] = {};
    }
    blk.resultant[e] = {};
    const double mass = 0.5 * blk.rho0 * sec.area * length;
    const double inertia = frames ? beamRotationalInertia(blk.rho0, length, sec.area, i_max) : 0.0;
    for (int a = 0; a < 2; ++a) {
      slot[3 * a] = mass;
      slot[3 * (2 + a)] = inertia;
    }
    const double dt_free = beamTimeStep(blk.section, length, E, G, blk.rho0);
    const double dte =
        muscle ? materials::muscleStep(muscle->response(muscle->sno, 0.0, 0.0), blk.rho0, length,
                                       length / muscle->sno)
               : dampedStep(dt_free, blk.stiffness_damping + blk.stiffness_fraction * dt_free);
    element_dt[e] = dte;
    noteStep(st, dte, blk.elem[e]);
  }
  return st;
}

namespace {

// The increments of the ELFORM 2 resultants for the deformation increment dd through the
// elastic Timoshenko beam stiffness (top of file).
// One bending plane of the Timoshenko beam of second moment `inertia`: phi = 12 E I /
// (G SA L0^2) (0 without a shear area) and k = E I / (L0 (1 + phi)); the end moments are
// k ((4 + phi) theta_1 + (2 - phi) theta_2) and the same with the ends swapped.
struct PlaneBending {
  double k, phi;
};
PlaneBending timoshenkoPlane(double E, double G, double inertia, double sa, double L0) {
  const double phi = sa > 0.0 ? 12.0 * E * inertia / (G * sa * L0 * L0) : 0.0;
  return {E * inertia / (L0 * (1.0 + phi)), phi};
}

std::array<double, 6> elasticIncrement(const Section& sec, double sa, double E, double G, double L0,
                                       const std::array<double, 6>& dd) {
  const auto [ks, phi_s] = timoshenkoPlane(E, G, sec.iss, sa, L0);
  const auto [kt, phi_t] = timoshenkoPlane(E, G, sec.itt, sa, L0);
  return {E * sec.area * dd[0] / L0,
          G * sec.j * dd[1] / L0,
          ks * ((4.0 + phi_s) * dd[2] + (2.0 - phi_s) * dd[4]),
          kt * ((4.0 + phi_t) * dd[3] + (2.0 - phi_t) * dd[5]),
          ks * ((2.0 - phi_s) * dd[2] + (4.0 + phi_s) * dd[4]),
          kt * ((2.0 - phi_t) * dd[3] + (4.0 + phi_t) * dd[5])};
}

// The elastic stiffness of the deformation for the end releases (beam_release.hpp): ELFORM 2
// that of elasticIncrement; Hughes-Liu that of its one point (top of file): M_s = E ISS
// kappa_s, Q_t = SHRF^2 G A gamma_t, so that per plane (E I / L0) [1 -1; -1 1] +
// (SHRF^2 G A L0 / 4) [1 1; 1 1].
DeformationStiffness releaseStiffness(const Section& sec, const domain::BeamSection& bs, double E,
                                      double G, double L0) {
  DeformationStiffness K;
  K.axial = E * sec.area / L0;
  K.torsion = G * sec.j / L0;
  if (bs.elform == 2) {
    auto plane = [&](double inertia) -> std::array<double, 3> {
      const auto [k, phi] = timoshenkoPlane(E, G, inertia, bs.sa, L0);
      return {k * (4.0 + phi), k * (2.0 - phi), k * (4.0 + phi)};
    };
    K.s = plane(sec.iss);
    K.t = plane(sec.itt);
    return K;
  }
  const double shear = bs.shear_factor * bs.shear_factor * G * sec.area * L0 / 4.0;
  K.s = {E * sec.iss / L0 + shear, shear - E * sec.iss / L0, E * sec.iss / L0 + shear};
  K.t = {E * sec.itt / L0 + shear, shear - E * sec.itt / L0, E * sec.itt / L0 + shear};
  return K;
}

// The end forces and moments on the nodes (minus the internal force vector) from the
// resultants G = (N, T, G_1s, G_1t, G_2s, G_2t) conjugate to the deformation (top of file).
void writeEndForces(const Frame& E, double length, const std::array<double, 6>& G_end,
                    double* slot) {
  const double N = G_end[0], torque = G_end[1];
  const double g1s = G_end[2], g1t = G_end[3], g2s = G_end[4], g2t = G_end[5];
  const Vec f1 =
      add(add(scale(E.r, -N), scale(E.s, (g1t + g2t) / length)), scale(E.t, -(g1s + g2s) / length));
  const Vec m1 = add(add(scale(E.r, -torque), scale(E.s, g1s)), scale(E.t, g1t));
  const Vec m2 = add(add(scale(E.r, torque), scale(E.s, g2s)), scale(E.t, g2t));
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    slot[0 + i] = -f1[k];
    slot[3 + i] = f1[k];
    slot[6 + i] = -m1[k];
    slot[9 + i] = -m2[k];
  }
}

// A truss's axial force N after the step and whether its law failed; for a muscle also its
// stable step.
struct TrussStep {
  double N = 0.0;
  bool failed = false;
  double dt = 0.0;
};

// The truss of a fibre law: the log strain increment de through the law, true stress on the
// current area A L0 / L (constant volume), and the stiffness damping beta.
TrussStep trussStress(domain::BeamBlock& blk, std::size_t e, const materials::FibreLaw& law,
                      double area, double length, double de, double dt, double beta) {
  const double L0 = blk.length0[e];
  materials::FibrePoint& p = blk.point[e];
  const double s_old = p.sig;
  TrussStep out;
  out.failed = materials::updateFibre(law, p, de, 0.0, 0.0, dt);
  blk.e_int[e] += area * L0 * 0.5 * (s_old + p.sig) * de;
  // Stiffness damping: the viscous stress beta E deps/dt over the step (no damping force
  // on an eroding element: `failed` zeroes the slots).
  const double sig_d = beta > 0.0 && dt > 0.0 ? beta * law.E * de / dt : 0.0;
  if (beta > 0.0) {
    // Trapezoidal like the internal energy: the stress of the last cycle and this one over
    // the step between them (what the energy identity of the cycle books).
    double& sig_d_old = blk.damping_resultant[e][0];
    blk.e_damp[e] += area * L0 * 0.5 * (sig_d_old + sig_d) * de;
    sig_d_old = sig_d;
  }
  out.N = (p.sig + sig_d) * area * L0 / length;
  return out;
}

// The truss of *MAT_MUSCLE (materials/laws/muscle.hpp) at t(n): the stress of the stretch
// L / l_orig at x(n) and the strain rate of the mid-step rate of length dl_dt, force sigma A.
// Its work, trapezoidal over the step's length change dt dl_dt, is the internal energy (the
// damping element's included: it is the material's). The stress is kept in the point for the
// next step's work and for output.
TrussStep muscleTruss(domain::BeamBlock& blk, std::size_t e, const materials::Muscle& m,
                      double area, double length, double dl_dt, double dt) {
  const double L0 = blk.length0[e], l_orig = L0 / m.sno;
  materials::FibrePoint& p = blk.point[e];
  const materials::MuscleResponse r = m.response(length / l_orig, dl_dt / l_orig, blk.time);
  blk.e_int[e] += area * 0.5 * (p.sig + r.stress) * dl_dt * dt;
  p.sig = r.stress;
  return {r.stress * area, false, materials::muscleStep(r, blk.rho0, L0, l_orig)};
}

BlockStatus beamForces(domain::BeamBlock& blk, const materials::FibreLaw& law, const Section& sec,
                       const domain::NodeVector& x, const domain::NodeVector& v,
                       const domain::NodeVector& w, double dt, double* slots, std::size_t first,
                       std::size_t last) {
  const domain::BeamSection& bs = blk.section;
  const int form = bs.elform;
  const double E = law.E, G = law.G;
  const bool resultant_plastic = form == 2 && law.plastic;
  const ResultantCapacity cap = capacityOf(sec, law.sigy);
  BlockStatus st;

  for (std::size_t e = first; e < last; ++e) {
    double* slot = slots + 3 * (blk.slot_offset + 4 * e);
    if (!blk.active[e]) {
      std::fill(slot, slot + 12, 0.0);
      continue;
    }
    const auto& c = blk.conn[e];
    const Vec x1 = nodeVec(x, c[0]), x2 = nodeVec(x, c[1]);
    const Vec d = sub(x2, x1);
    const double length = norm(d);
    const double L0 = blk.length0[e];
    if (!(length > 0.0) || !(L0 > 0.0)) {
      noteBad(st, blk.elem[e]);
      std::fill(slot, slot + 12, 0.0);
      continue;
    }
    const Vec e1 = scale(d, 1.0 / length);
    bool failed = false;
    // The element's step, and the stiffness damping beta it sets with COEF > 0.
    const double dt_free = beamTimeStep(bs, length, E, G, blk.rho0);
    const double beta = blk.stiffness_damping + blk.stiffness_fraction * dt_free;

    if (form == 3) {
      // --- truss: axial rate of deformation at the mid-step geometry ----------------------
      const Vec dv = sub(nodeVec(v, c[1]), nodeVec(v, c[0]));
      const Vec dm = sub(d, scale(dv, 0.5 * dt));
      const TrussStep ts = law.muscle ? muscleTruss(blk, e, *law.muscle, sec.area, length,
                                                    dot(dm, dv) / norm(dm), dt)
                                      : trussStress(blk, e, law, sec.area, length,
                                                    dt * dot(dm, dv) / dot(dm, dm), dt, beta);
      failed = ts.failed;
      blk.resultant[e] = {ts.N, 0.0, 0.0, 0.0, 0.0, 0.0};
      if (!failed) {
        for (int i = 0; i < 3; ++i) {
          const auto k = static_cast<std::size_t>(i);
          slot[i] = ts.N * e1[k];
          slot[3 + i] = -ts.N * e1[k];
          slot[6 + i] = slot[9 + i] = 0.0;
        }
      }
      if (law.muscle && !failed) {
        noteStep(st, ts.dt, blk.elem[e]);
        continue;
      }
    } else {
      // --- corotational beams: nodal frames, element frame, deformation -------------------
      auto& tri = blk.triad[e];
      Quat q1 = {tri[0], tri[1], tri[2], tri[3]}, q2 = {tri[4], tri[5], tri[6], tri[7]};
      q1 = rotated(q1, scale(nodeVec(w, c[0]), dt));
      q2 = rotated(q2, scale(nodeVec(w, c[1]), dt));
      tri = {q1[0], q1[1], q1[2], q1[3], q2[0], q2[1], q2[2], q2[3]};
      const Frame t1 = frameOf(q1), t2 = frameOf(q2);
      const Frame F = elementFrame(e1, t1, t2);
      const Vec th1 = relativeRotation(F, t1), th2 = relativeRotation(F, t2);
      // L - L0 without the cancellation of two close lengths.
      const double elong = (dot(d, d) - L0 * L0) / (length + L0);
      const std::array<double, 6> now = {elong, th2[0] - th1[0], th1[1], th1[2], th2[1], th2[2]};
      std::array<double, 6> dd;
      for (std::size_t k = 0; k < 6; ++k) dd[k] = now[k] - blk.deformation[e][k];
      blk.deformation[e] = now;
      // The work through the nodes: the releases' free deformation does none.
      const std::array<double, 6> dd_nodes = dd;
      if (bs.release != 0)
        applyReleases(bs.release, releaseStiffness(sec, bs, E, G, L0), blk.resultant[e], dd);

      std::array<double, 6> R = blk.resultant[e];
      if (form == 2) {
        // --- Belytschko-Schwer: resultants through the beam stiffness ---------------------
        const std::array<double, 6> R_old = R;
        const std::array<double, 6> dR = elasticIncrement(sec, bs.sa, E, G, L0, dd);
        for (std::size_t k = 0; k < 6; ++k) R[k] += dR[k];
        if (resultant_plastic) returnResultants(R, cap);
        double work = 0.0;
        for (std::size_t k = 0; k < 6; ++k) work += 0.5 * (R_old[k] + R[k]) * dd_nodes[k];
        blk.e_int[e] += work;
        blk.resultant[e] = R;
        // Stiffness damping: beta K dd/dt, the elastic increment over the step times beta/dt
        // (C = beta K; on top of the resultants, not kept in them), its work trapezoidal like
        // the internal energy's.
        if (beta > 0.0 && dt > 0.0)
          for (std::size_t k = 0; k < 6; ++k) {
            const double Rd = beta / dt * dR[k];
            double& Rd_old = blk.damping_resultant[e][k];
            blk.e_damp[e] += 0.5 * (Rd_old + Rd) * dd_nodes[k];
            Rd_old = Rd;
            R[k] += Rd;
          }
        writeEndForces(F, length, R, slot);
      } else {
        // --- Hughes-Liu, spot weld: the section's points through the law ----------------
        failed = integrateSection(blk, e, law, sec, dd, dt) || failed;
        R = blk.resultant[e];
        if (form == 9 && !failed) failed = weldFails(law.weld, R, L0, blk.time);
        if (!failed) writeEndForces(F, length, R, slot);
      }
    }

    if (failed) {
      // LS-DYNA FAIL / FS: the element is removed, its slots zeroed.
      blk.active[e] = 0;
      std::fill(slot, slot + 12, 0.0);
      ++st.eroded;
      continue;
    }
    noteStep(st, dampedStep(dt_free, beta), blk.elem[e]);
  }
  return st;
}

}  // namespace

BlockStatus computeBeamForces(domain::BeamBlock& block, const domain::NodeVector& x,
                              const domain::NodeVector& v, const domain::NodeVector& w, double dt,
                              double* slots, std::size_t first, std::size_t last) {
  if (first > last || last > block.size())
    throw std::logic_error("computeBeamForces: element range outside the block");
  const Section sec = sectionOf(block.section);
  if (block.points != sec.points ||
      block.point.size() != block.size() * static_cast<std::size_t>(sec.points))
    throw std::logic_error("computeBeamForces: state not sized for the section (resizeBeamBlock)");
  materials::FibreLaw law = materials::fibreLawOf(block.law);
  // *MAT_ADD_EROSION EFFEPS on a beam: a failure strain of the points, as the law's FAIL.
  if (block.erosion.has(materials::Criterion::EffectiveStrain)) {
    const double limit = block.erosion.at(materials::Criterion::EffectiveStrain);
    law.fail = law.fail > 0.0 ? std::min(law.fail, limit) : limit;
  }
  return beamForces(block, law, sec, x, v, w, dt, slots, first, last);
}

void beamSectionResultants(const domain::BeamBlock& blk, std::size_t e, double out[6]) {
  const std::array<double, 6>& R = blk.resultant[e];
  const double L = blk.length0[e];
  const double r[6] = {
      R[0], -(R[3] + R[5]) / L, (R[2] + R[4]) / L, 0.5 * (R[4] - R[2]), 0.5 * (R[5] - R[3]), R[1]};
  std::copy(r, r + 6, out);
}

}  // namespace crumple::elements
