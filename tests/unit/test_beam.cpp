// Beams, trusses and discrete elements, each driven by a small explicit loop written here
// like the solver's cycle: the kernel writes its slots, nodes sum them in element order,
// masses come from the initialisation's slots, central differences (first step from
// v(-1/2) = v(0) over half a step, dt = 0 on the first kernel call), clamps and prescribed
// velocities applied to v(n+1/2).
//
// Checked against closed forms: cantilever frequency and tip deflection (Euler-Bernoulli) for
// the resultant and the Hughes-Liu beam, axial bar frequency and bilinear plasticity of the
// truss, rigid rotation (no force, no energy), the stable steps (the manual's formulas are
// sharp for the lumped mass and inertia), spring-mass frequency, damper dissipation and the
// nonlinear spring's curve.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "domain/blocks.hpp"
#include "elements/beam.hpp"
#include "elements/beam_release.hpp"
#include "elements/discrete.hpp"
#include "materials/materials.hpp"
#include "materials/uniaxial.hpp"
#include "model/model.hpp"
#include "rate_law.hpp"

namespace d = crumple::domain;
namespace el = crumple::elements;
namespace m = crumple::materials;

namespace {

using Vec = std::array<double, 3>;
constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A figure for the test report (RecordProperty), with its significant digits.
std::string fig(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", value);
  return buf;
}

// Steel.
constexpr double kE = 210e9, kNu = 0.3, kRho = 7850.0;

m::Law elastic(double E = kE, double nu = kNu) {
  return m::Elastic{m::moduliFromYoung(E, nu)};
}

// Steel laws from their deck parameters.
m::PlasticKinematic law003(double sigy, double etan, double beta, double fs = 0.0) {
  return m::PlasticKinematic::make({kE, kNu, sigy, etan, beta, 0.0, 0.0, fs}, {}, "");
}
m::PiecewiseLinear law024(double sigy, double etan) {
  m::PiecewiseLinear::Params p;
  p.E = kE;
  p.nu = kNu;
  p.sigy = sigy;
  p.etan = etan;
  return m::PiecewiseLinear::make(p, {}, "");
}

// A rectangular (b x h) section for the resultant beam: b along s, h along t.
d::BeamSection resultantSection(double b, double h, double sa = 0.0) {
  d::BeamSection s;
  s.elform = 2;
  s.a = b * h;
  s.iss = b * h * h * h / 12.0;  // about s: bending with the stress varying along t
  s.itt = h * b * b * b / 12.0;
  const double a = std::max(b, h), c = std::min(b, h);
  s.j = a * c * c * c * (1.0 / 3.0 - 0.21 * c / a * (1.0 - c * c * c * c / (12.0 * a * a * a * a)));
  s.sa = sa;
  return s;
}

d::BeamSection hughesLiuRect(double ts, double tt) {
  d::BeamSection s;
  s.elform = 1;
  s.cst = 0;
  s.ts1 = s.ts2 = ts;
  s.tt1 = s.tt2 = tt;
  return s;
}

d::BeamSection hughesLiuTube(double outer, double inner) {
  d::BeamSection s;
  s.elform = 1;
  s.cst = 1;
  s.ts1 = s.ts2 = outer;
  s.tt1 = s.tt2 = inner;
  return s;
}

d::BeamSection truss(double area) {
  d::BeamSection s;
  s.elform = 3;
  s.a = area;
  return s;
}

// A beam block over given nodes and the nodal state of an explicit loop around it.
struct Rig {
  d::BeamBlock blk;
  d::NodeVector x, v, w, f, mom, f_ext, m_ext;
  std::vector<double> mass, inertia, slots, element_dt;
  std::vector<uint8_t> clamped;                              // all six dofs held
  std::vector<std::pair<std::size_t, double>> prescribed;    // (index into v, velocity)
  std::vector<std::pair<std::size_t, double>> prescribed_w;  // (index into w, spin)
  double damping = 0.0;  // mass-proportional: a -= damping v (and likewise for rotations)
  double dt_prev = 0.0;
  long cycle = 0;
  double time = 0.0;
  el::BlockStatus init_status, status;

  std::size_t numNodes() const { return mass.size(); }
  Vec node(const d::NodeVector& a, std::size_t n) const {
    return {a[3 * n], a[3 * n + 1], a[3 * n + 2]};
  }

  void gather() {
    std::fill(f.begin(), f.end(), 0.0);
    std::fill(mom.begin(), mom.end(), 0.0);
    for (std::size_t e = 0; e < blk.size(); ++e)
      for (int a = 0; a < 2; ++a) {
        const auto n = static_cast<std::size_t>(blk.conn[e][static_cast<std::size_t>(a)]);
        for (int c = 0; c < 3; ++c) {
          f[3 * n + c] += slots[3 * (blk.slot_offset + 4 * e + a) + c];
          mom[3 * n + c] += slots[3 * (blk.slot_offset + 4 * e + 2 + a) + c];
        }
      }
  }

  void forces() {
    status = el::computeBeamForces(blk, x, v, w, dt_prev, slots.data(), 0, blk.size());
    gather();
  }

  // One cycle: forces at x(n), v(n+1/2), x(n+1).
  void step(double dt) {
    forces();
    const double dt_n = cycle == 0 ? 0.5 * dt : 0.5 * (dt_prev + dt);
    for (std::size_t n = 0; n < numNodes(); ++n)
      for (int c = 0; c < 3; ++c) {
        const std::size_t i = 3 * n + c;
        if (clamped[n]) {
          v[i] = w[i] = 0.0;
          continue;
        }
        v[i] += dt_n * ((f[i] + f_ext[i]) / mass[n] - damping * v[i]);
        if (inertia[n] > 0.0) w[i] += dt_n * ((mom[i] + m_ext[i]) / inertia[n] - damping * w[i]);
      }
    for (const auto& [i, value] : prescribed) v[i] = value;
    for (const auto& [i, value] : prescribed_w) w[i] = value;
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += dt * v[i];
    dt_prev = dt;
    ++cycle;
    time += dt;
  }

  double kinetic() const {
    double k = 0.0;
    for (std::size_t n = 0; n < numNodes(); ++n)
      for (int c = 0; c < 3; ++c)
        k += 0.5 *
             (mass[n] * v[3 * n + c] * v[3 * n + c] + inertia[n] * w[3 * n + c] * w[3 * n + c]);
    return k;
  }
  double internal() const {
    double e = 0.0;
    for (double ei : blk.e_int) e += ei;
    return e;
  }
  double stableStep() const { return init_status.dt_min; }
};

// Elements between consecutive nodes; the orientation point of each element is its first
// node shifted by s_dir (the s axis), or NaN for the kernel's default.
Rig makeRig(const d::NodeVector& x0, const d::BeamSection& sec, const m::Law& law, double rho,
            const Vec& s_dir, bool default_orientation = false) {
  Rig r;
  const std::size_t nn = x0.size() / 3, ne = nn - 1;
  r.blk.section = sec;
  r.blk.law = law;
  r.blk.rho0 = rho;
  for (std::size_t e = 0; e < ne; ++e) {
    r.blk.elem.push_back(static_cast<int32_t>(e));
    r.blk.elem_id.push_back(static_cast<int64_t>(e + 1));
    r.blk.conn.push_back(
        {static_cast<int32_t>(e), static_cast<int32_t>(e + 1), crumple::model::kNone});
    if (default_orientation) {
      r.blk.orientation.push_back({kNaN, kNaN, kNaN});
    } else {
      r.blk.orientation.push_back(
          {x0[3 * e] + s_dir[0], x0[3 * e + 1] + s_dir[1], x0[3 * e + 2] + s_dir[2]});
    }
  }
  el::resizeBeamBlock(r.blk, ne);
  r.slots.assign(3 * 4 * ne, 0.0);
  r.init_status = el::initializeBeams(r.blk, x0, r.slots.data(), r.element_dt);
  r.x = x0;
  r.v.assign(x0.size(), 0.0);
  r.w.assign(x0.size(), 0.0);
  r.f.assign(x0.size(), 0.0);
  r.mom.assign(x0.size(), 0.0);
  r.f_ext.assign(x0.size(), 0.0);
  r.m_ext.assign(x0.size(), 0.0);
  r.mass.assign(nn, 0.0);
  r.inertia.assign(nn, 0.0);
  r.clamped.assign(nn, 0);
  for (std::size_t e = 0; e < ne; ++e)
    for (int a = 0; a < 2; ++a) {
      const auto n = static_cast<std::size_t>(r.blk.conn[e][static_cast<std::size_t>(a)]);
      r.mass[n] += r.slots[3 * (4 * e + a)];
      r.inertia[n] += r.slots[3 * (4 * e + 2 + a)];
    }
  return r;
}

d::NodeVector lineAlongX(int n, double length) {
  d::NodeVector x0;
  for (int i = 0; i <= n; ++i) {
    x0.push_back(length * i / n);
    x0.push_back(0.0);
    x0.push_back(0.0);
  }
  return x0;
}

// Times at which a sampled signal changes sign (linear interpolation between samples).
struct CrossingCounter {
  double t_prev = 0.0, y_prev = 0.0;
  bool started = false;
  std::vector<double> times;
  void add(double t, double y) {
    if (started && ((y_prev < 0.0 && y >= 0.0) || (y_prev > 0.0 && y <= 0.0)))
      times.push_back(t_prev + (t - t_prev) * y_prev / (y_prev - y));
    t_prev = t;
    y_prev = y;
    started = true;
  }
  // Mean period from the first to the last crossing (two crossings per period).
  double period() const {
    return 2.0 * (times.back() - times.front()) / static_cast<double>(times.size() - 1);
  }
};

// First bending frequency of a cantilever along x (clamped at x = 0), deflecting in y: the
// beam starts straight with the velocity of the static tip-load shape (mostly mode 1).
double cantileverFrequency(const d::BeamSection& sec, int n, double length, double periods_expected,
                           double f_expected) {
  Rig r = makeRig(lineAlongX(n, length), sec, elastic(), kRho, {0.0, 1.0, 0.0});
  r.clamped[0] = 1;
  const double V = 1e-3;
  for (std::size_t i = 0; i < r.numNodes(); ++i) {
    const double s = r.x[3 * i] / length;
    r.v[3 * i + 1] = V * 0.5 * s * s * (3.0 - s);
    r.w[3 * i + 2] = V * 1.5 * s * (2.0 - s) / length;  // d(v_y)/dx: turns x towards y
  }
  const double dt = 0.9 * r.stableStep();
  CrossingCounter tip;
  const std::size_t tip_y = 3 * (r.numNodes() - 1) + 1;
  while (r.time < periods_expected / f_expected) {
    r.step(dt);
    tip.add(r.time, r.x[tip_y]);
  }
  EXPECT_GE(tip.times.size(), 4u);
  return 1.0 / tip.period();
}

// Euler-Bernoulli cantilever: f1 = 1.8751^2 / (2 pi) sqrt(E I / (rho A L^4)).
double cantileverF1(double I, double A, double length) {
  return 1.8751 * 1.8751 / (2.0 * kPi) * std::sqrt(kE * I / (kRho * A * std::pow(length, 4)));
}

// Tip deflection of a cantilever under a tip load in y ramped smoothly over three periods and
// held, with mass-proportional damping near critical for mode 1 (the static answer).
double cantileverTipDeflection(const d::BeamSection& sec, int n, double length, double load,
                               double f1, double* energy_error = nullptr) {
  Rig r = makeRig(lineAlongX(n, length), sec, elastic(), kRho, {0.0, 1.0, 0.0});
  r.clamped[0] = 1;
  const double omega = 2.0 * kPi * f1;
  r.damping = 1.4 * omega;
  const double dt = 0.9 * r.stableStep();
  const double ramp = 3.0 / f1, end = 8.0 / f1;
  const std::size_t tip_y = 3 * (r.numNodes() - 1) + 1;
  while (r.time < end) {
    const double s = std::min(r.time / ramp, 1.0);
    r.f_ext[tip_y] = load * 0.5 * (1.0 - std::cos(kPi * s));
    r.step(dt);
  }
  if (energy_error != nullptr) {
    // At rest, the internal energy is the elastic energy P delta / 2.
    const double delta = r.x[tip_y];
    *energy_error = r.internal() / (0.5 * load * delta) - 1.0;
  }
  return r.x[tip_y];
}

// ---- resultant beam (ELFORM 2) --------------------------------------------------------------

TEST(BeamResultant, CantileverFirstFrequency) {
  const double h = 0.03, L = 1.0;
  const d::BeamSection sec = resultantSection(h, h);
  const double f1 = cantileverF1(sec.iss, sec.a, L);
  const double f = cantileverFrequency(sec, 20, L, 2.6, f1);
  EXPECT_NEAR(f / f1, 1.0, 0.02) << "f = " << f << " Hz, f1 = " << f1 << " Hz";
  RecordProperty("frequency_ratio", fig(f / f1));
}

TEST(BeamResultant, CantileverTipDeflection) {
  const double h = 0.03, L = 1.0;
  const d::BeamSection sec = resultantSection(h, h, 5.0 / 6.0 * h * h);
  const double f1 = cantileverF1(sec.iss, sec.a, L);
  const double P = 500.0;
  double energy_error = 0.0;
  const double delta = cantileverTipDeflection(sec, 20, L, P, f1, &energy_error);
  const double exact = P * L * L * L / (3.0 * kE * sec.iss);
  EXPECT_NEAR(delta / exact, 1.0, 0.03) << "delta = " << delta << ", PL^3/3EI = " << exact;
  EXPECT_NEAR(energy_error, 0.0, 0.01);
  RecordProperty("deflection_ratio", fig(delta / exact));
  RecordProperty("energy_error", fig(energy_error));
}

// ---- Hughes-Liu beam (ELFORM 1) -------------------------------------------------------------

TEST(BeamHughesLiu, CantileverFirstFrequencyRectangular) {
  const double h = 0.03, L = 1.0;
  const d::BeamSection sec = hughesLiuRect(h, h);
  const double f1 = cantileverF1(h * h * h * h / 12.0, h * h, L);
  const double f = cantileverFrequency(sec, 20, L, 2.6, f1);
  EXPECT_NEAR(f / f1, 1.0, 0.02) << "f = " << f << " Hz, f1 = " << f1 << " Hz";
  RecordProperty("frequency_ratio", fig(f / f1));
}

TEST(BeamHughesLiu, CantileverFirstFrequencyTubular) {
  const double D = 0.04, Di = 0.034, L = 1.0;
  const d::BeamSection sec = hughesLiuTube(D, Di);
  const double A = kPi * (D * D - Di * Di) / 4.0;
  const double I = kPi * (std::pow(D, 4) - std::pow(Di, 4)) / 64.0;
  const double f1 = cantileverF1(I, A, L);
  const double f = cantileverFrequency(sec, 20, L, 2.6, f1);
  EXPECT_NEAR(f / f1, 1.0, 0.02) << "f = " << f << " Hz, f1 = " << f1 << " Hz";
  RecordProperty("frequency_ratio", fig(f / f1));
}

TEST(BeamHughesLiu, CantileverTipDeflection) {
  const double h = 0.03, L = 1.0;
  d::BeamSection sec = hughesLiuRect(h, h);
  sec.shear_factor = 5.0 / 6.0;
  const double I = h * h * h * h / 12.0;
  const double f1 = cantileverF1(I, h * h, L);
  const double P = 500.0;
  double energy_error = 0.0;
  const double delta = cantileverTipDeflection(sec, 20, L, P, f1, &energy_error);
  const double exact = P * L * L * L / (3.0 * kE * I);
  EXPECT_NEAR(delta / exact, 1.0, 0.03) << "delta = " << delta << ", PL^3/3EI = " << exact;
  EXPECT_NEAR(energy_error, 0.0, 0.01);
  RecordProperty("deflection_ratio", fig(delta / exact));
  RecordProperty("energy_error", fig(energy_error));
}

// ---- end moments under prescribed end rotations ---------------------------------------------

// One element with both ends held in place and turned in opposite senses about the axis
// `axis` (0 r = x, 2 t = z) at a constant rate: pure bending (curvature 2 theta / L, no
// shear) or pure twist (2 theta / L). Records the moment on node 2 about that axis, which
// resists the turn, against the curvature or twist per length.
struct TurnResult {
  std::vector<double> kappa, moment;
  Rig rig;
};

TurnResult turnEnds(const d::BeamSection& sec, const m::Law& law, double length, int axis,
                    double kappa_end, int steps) {
  TurnResult out;
  out.rig = makeRig(lineAlongX(1, length), sec, law, kRho, {0.0, 1.0, 0.0});
  Rig& r = out.rig;
  const double dt = 0.5 * r.stableStep();
  const double omega = 0.5 * kappa_end * length / (steps * dt);
  for (std::size_t i = 0; i < 6; ++i) {
    r.prescribed.push_back({i, 0.0});
    const bool turned = i % 3 == static_cast<std::size_t>(axis);
    r.prescribed_w.push_back({i, turned ? (i < 3 ? -omega : omega) : 0.0});
  }
  for (int k = 0; k <= steps; ++k) {
    // The kernel call of cycle k sees each end turned by omega dt k (the first call has
    // dt = 0).
    const double angle = omega * dt * k;
    r.step(dt);
    out.kappa.push_back(2.0 * angle / length);
    out.moment.push_back(-r.mom[3 + static_cast<std::size_t>(axis)]);
  }
  return out;
}

TEST(BeamResultant, BendingAndTorsionStiffness) {
  const double b = 0.02, h = 0.03, L = 0.25;
  const d::BeamSection sec = resultantSection(b, h);
  const double G = kE / (2.0 * (1.0 + kNu));
  const TurnResult bend = turnEnds(sec, elastic(), L, 2, 1e-3, 20);
  EXPECT_NEAR(bend.moment.back() / (kE * sec.itt * bend.kappa.back()), 1.0, 1e-5);
  const TurnResult twist = turnEnds(sec, elastic(), L, 0, 1e-3, 20);
  EXPECT_NEAR(twist.moment.back() / (G * sec.j * twist.kappa.back()), 1.0, 1e-5);
  // Energy of the deformation, E I kappa^2 L / 2.
  const double k = bend.kappa.back();
  EXPECT_NEAR(bend.rig.internal() / (0.5 * kE * sec.itt * k * k * L), 1.0, 1e-3);
}

TEST(BeamHughesLiu, BendingAndTorsionStiffness) {
  const double b = 0.02, h = 0.03, L = 0.25;
  const double G = kE / (2.0 * (1.0 + kNu));
  // Rectangle b (s) x h (t), 2x2 Gauss: E I exact; torsion from the points: the polar moment.
  const d::BeamSection rect = hughesLiuRect(b, h);
  const double itt = h * b * b * b / 12.0, iss = b * h * h * h / 12.0;
  const TurnResult bend = turnEnds(rect, elastic(), L, 2, 1e-3, 20);
  EXPECT_NEAR(bend.moment.back() / (kE * itt * bend.kappa.back()), 1.0, 1e-5);
  const TurnResult twist = turnEnds(rect, elastic(), L, 0, 1e-3, 20);
  EXPECT_NEAR(twist.moment.back() / (G * (iss + itt) * twist.kappa.back()), 1.0, 1e-5);
  // Tube: the ring of points gives I and J exactly.
  const double D = 0.04, Di = 0.03;
  const d::BeamSection tube = hughesLiuTube(D, Di);
  const double I = kPi * (std::pow(D, 4) - std::pow(Di, 4)) / 64.0;
  const TurnResult tube_bend = turnEnds(tube, elastic(), L, 2, 1e-3, 20);
  EXPECT_NEAR(tube_bend.moment.back() / (kE * I * tube_bend.kappa.back()), 1.0, 1e-5);
  const TurnResult tube_twist = turnEnds(tube, elastic(), L, 0, 1e-3, 20);
  EXPECT_NEAR(tube_twist.moment.back() / (G * 2.0 * I * tube_twist.kappa.back()), 1.0, 1e-5);
}

TEST(BeamHughesLiu, PlasticMomentOfTheSection) {
  // Perfectly plastic MAT_024 bent far past first yield: every point at sigy, so the moment
  // is sigy sum_i w_i |s_i| of the rule; with 4x4 Gauss (QR 5) that is 4 % above the exact
  // sigy h b^2 / 4 of the rectangle.
  const double b = 0.02, h = 0.03, L = 0.25;
  const double sigy = 250e6;
  const m::PiecewiseLinear pl = law024(sigy, 0.0);
  d::BeamSection sec = hughesLiuRect(b, h);
  sec.qr = 5;
  const double eps_y = sigy / kE;
  const TurnResult bend = turnEnds(sec, pl, L, 2, 60.0 * eps_y / (0.5 * b), 400);
  const double g[2] = {0.3399810435848563, 0.8611363115940526};
  const double w[2] = {0.6521451548625461, 0.3478548451374538};
  double rule = 0.0;  // sum over the 4x4 points of (area) |s|
  for (int i = 0; i < 2; ++i) rule += 2.0 * w[i] * 0.5 * b * g[i] * 0.5 * b * h;
  EXPECT_NEAR(bend.moment.back() / (sigy * rule), 1.0, 1e-9);
  const double exact = sigy * h * b * b / 4.0;
  EXPECT_NEAR(bend.moment.back() / exact, 1.0, 0.05);
  // Elastic at first: the moment follows E I kappa up to first yield of the outer points.
  EXPECT_NEAR(bend.moment[2] / (kE * h * b * b * b / 12.0 * bend.kappa[2]), 1.0, 1e-5);
  RecordProperty("moment_over_exact_plastic_moment", fig(bend.moment.back() / exact));
}

TEST(BeamResultant, PlasticLawsRunAsResultantPlasticity) {
  // MAT_003 on ELFORM 2: the end moment stops at the fully plastic moment of the solid
  // section with this A and I (sigy h b^2 / 4 for the rectangle); hardening is not used.
  const double b = 0.02, h = 0.03, L = 0.25;
  const double sigy = 250e6;
  const m::PlasticKinematic pk = law003(sigy, 2e9, 1.0);
  const d::BeamSection sec = resultantSection(b, h);
  const double eps_y = sigy / kE;
  const TurnResult bend = turnEnds(sec, pk, L, 2, 20.0 * eps_y / (0.5 * b), 200);
  const double mp = sigy * h * b * b / 4.0;
  EXPECT_NEAR(bend.moment.back() / mp, 1.0, 1e-9);
  EXPECT_NEAR(bend.moment[2] / (kE * sec.itt * bend.kappa[2]), 1.0, 1e-5);
  // Energy: the elastic part plus the plastic dissipation, M_p times the plastic rotation.
  double work = 0.0;
  for (std::size_t k = 1; k < bend.kappa.size(); ++k)
    work += 0.5 * (bend.moment[k] + bend.moment[k - 1]) * (bend.kappa[k] - bend.kappa[k - 1]) * L;
  EXPECT_NEAR(bend.rig.internal() / work, 1.0, 1e-3);
}

// ---- rigid motion -----------------------------------------------------------------------------

// Rotation matrix about a unit axis (Rodrigues).
std::array<Vec, 3> rotation(const Vec& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), k = 1.0 - c;
  const double x = axis[0], y = axis[1], z = axis[2];
  return {{{c + k * x * x, k * x * y - s * z, k * x * z + s * y},
           {k * y * x + s * z, c + k * y * y, k * y * z - s * x},
           {k * z * x - s * y, k * z * y + s * x, c + k * z * z}}};
}

// Three elements in a general direction turned rigidly by 90 degrees about an axis through a
// point off the beam, positions prescribed exactly and the nodal angular velocities equal to
// the rigid spin: no force, no moment, no energy, at every cycle.
void expectNoForceUnderRigidRotation(const d::BeamSection& sec) {
  d::NodeVector x0;
  const Vec start = {0.3, -0.2, 0.5}, dir = {0.48, 0.6, 0.64};
  for (int i = 0; i <= 3; ++i)
    for (int c = 0; c < 3; ++c) x0.push_back(start[c] + 0.1 * i * dir[c]);
  Rig r = makeRig(x0, sec, elastic(), kRho, {0.0, 0.0, 1.0});
  const Vec centre = {-0.4, 0.1, 0.2};
  const Vec axis = {2.0 / 7.0, 3.0 / 7.0, 6.0 / 7.0};
  const double omega = 50.0;  // rad/s
  const int steps = 400;
  const double dt = 0.5 * kPi / omega / steps;
  const double EA = kE * (sec.elform == 1 ? sec.ts1 * sec.tt1 : sec.a);
  double max_force = 0.0, max_moment = 0.0;
  for (int k = 0; k <= steps; ++k) {
    const auto R = rotation(axis, omega * dt * k);
    d::NodeVector x_prev = r.x;
    for (std::size_t n = 0; n < r.numNodes(); ++n) {
      Vec p;
      for (int c = 0; c < 3; ++c) p[c] = x0[3 * n + c] - centre[c];
      for (int i = 0; i < 3; ++i) {
        r.x[3 * n + i] = centre[i] + R[i][0] * p[0] + R[i][1] * p[1] + R[i][2] * p[2];
        r.v[3 * n + i] = k == 0 ? 0.0 : (r.x[3 * n + i] - x_prev[3 * n + i]) / dt;
        r.w[3 * n + i] = k == 0 ? 0.0 : omega * axis[i];
      }
    }
    r.dt_prev = k == 0 ? 0.0 : dt;
    r.forces();
    for (std::size_t i = 0; i < r.f.size(); ++i) {
      max_force = std::max(max_force, std::abs(r.f[i]));
      max_moment = std::max(max_moment, std::abs(r.mom[i]));
    }
  }
  EXPECT_LT(max_force, 1e-9 * EA);
  ::testing::Test::RecordProperty("max_force_over_EA", fig(max_force / EA));
  ::testing::Test::RecordProperty("max_moment_over_EAL", fig(max_moment / (EA * 0.1)));
  ::testing::Test::RecordProperty("internal_energy", fig(r.internal()));
  EXPECT_LT(max_moment, 1e-9 * EA * 0.1);
  EXPECT_LT(std::abs(r.internal()), 1e-18 * EA * 0.3);
}

TEST(BeamResultant, RigidRotationGivesNoForce) {
  expectNoForceUnderRigidRotation(resultantSection(0.02, 0.03));
}

TEST(BeamHughesLiu, RigidRotationGivesNoForce) {
  expectNoForceUnderRigidRotation(hughesLiuRect(0.02, 0.03));
}

TEST(Truss, RigidRotationGivesNoForce) {
  expectNoForceUnderRigidRotation(truss(6e-4));
}

// ---- stable steps -----------------------------------------------------------------------------

// One free element from random velocities and spins: central differences stay bounded at
// 0.98 of the element's step and blow up at 1.05 of it, so the step formula is the critical
// step of the lumped mass and inertia (the highest mode is the one it names).
double growthOfFreeElement(const d::BeamSection& sec, double length, double factor) {
  Rig r = makeRig(lineAlongX(1, length), sec, elastic(), kRho, {0.0, 1.0, 0.0});
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double& vi : r.v) vi = 1e-3 * u(rng);
  for (double& wi : r.w) wi = 1e-3 / length * u(rng);
  const double e0 = r.kinetic();
  const double dt = factor * r.stableStep();
  double peak = 0.0;
  for (int k = 0; k < 3000; ++k) {
    r.step(dt);
    const double e = r.kinetic() + r.internal();
    if (!std::isfinite(e)) return std::numeric_limits<double>::infinity();
    peak = std::max(peak, e);
    if (peak > 1e6 * e0) break;
  }
  return peak / e0;
}

TEST(BeamResultant, StableStepIsSharp) {
  // A stubby element (L / h = 2/3): the manual's bending limit is below L / c.
  const double h = 0.03, L = 0.02;
  const d::BeamSection sec = resultantSection(h, h);
  const double c = std::sqrt(kE / kRho);
  const double I = sec.iss, A = sec.a;
  const double bending =
      0.5 * L / (c * std::sqrt(3.0 * I * (1.0 / (12.0 * I + A * L * L) + 1.0 / (A * L * L))));
  ASSERT_LT(bending, L / c);
  EXPECT_NEAR(el::beamTimeStep(sec, L, kE, kE / 2.6, kRho), bending, 1e-15 * bending);
  const double stable = growthOfFreeElement(sec, L, 0.98);
  const double unstable = growthOfFreeElement(sec, L, 1.05);
  EXPECT_LT(stable, 100.0);
  EXPECT_GT(unstable, 1e6);
  RecordProperty("growth_0.98", fig(stable));
  RecordProperty("growth_1.05", fig(unstable));
}

TEST(BeamResultant, StableStepOfSlenderElementIsAxial) {
  const double h = 0.03, L = 0.5;
  const d::BeamSection sec = resultantSection(h, h);
  const double c = std::sqrt(kE / kRho);
  EXPECT_DOUBLE_EQ(el::beamTimeStep(sec, L, kE, kE / 2.6, kRho), L / c);
  const double stable = growthOfFreeElement(sec, L, 0.98);
  const double unstable = growthOfFreeElement(sec, L, 1.05);
  EXPECT_LT(stable, 100.0);
  EXPECT_GT(unstable, 1e6);
  RecordProperty("growth_0.98", fig(stable));
  RecordProperty("growth_1.05", fig(unstable));
}

TEST(BeamHughesLiu, StableStepIsAxial) {
  // L / c holds even for a stubby element: the lumped inertia keeps bending and shear below.
  for (double L : {0.02, 0.5}) {
    d::BeamSection sec = hughesLiuRect(0.03, 0.03);
    EXPECT_LT(growthOfFreeElement(sec, L, 0.98), 100.0) << "L = " << L;
    EXPECT_GT(growthOfFreeElement(sec, L, 1.05), 1e6) << "L = " << L;
  }
}

TEST(Beam, MassAndInertiaOfEnds) {
  const double h = 0.03, L = 0.4;
  const d::BeamSection sec = resultantSection(h, 2.0 * h);
  Rig r = makeRig(lineAlongX(1, L), sec, elastic(), kRho, {0.0, 1.0, 0.0});
  const double m = 0.5 * kRho * sec.a * L;
  EXPECT_DOUBLE_EQ(r.mass[0], m);
  EXPECT_DOUBLE_EQ(r.mass[1], m);
  const double I = std::max(sec.iss, sec.itt);
  EXPECT_NEAR(r.inertia[0], m * (L * L / 4.0 + 3.0 * I / sec.a), 1e-14 * r.inertia[0]);
  // Slot components other than x are zero.
  for (int s = 0; s < 4; ++s) {
    EXPECT_EQ(r.slots[3 * s + 1], 0.0);
    EXPECT_EQ(r.slots[3 * s + 2], 0.0);
  }
  Rig t = makeRig(lineAlongX(1, L), truss(2e-3), elastic(), kRho, {0.0, 1.0, 0.0});
  EXPECT_DOUBLE_EQ(t.mass[1], 0.5 * kRho * 2e-3 * L);
  EXPECT_EQ(t.inertia[1], 0.0);
  EXPECT_NEAR(t.element_dt[0], L / std::sqrt(kE / kRho), 1e-12 * t.element_dt[0]);
}

TEST(Beam, DefaultOrientationIsOrthogonal) {
  // Without an orientation node the kernel picks s; a beam in bending about either axis must
  // then still be stiff (a frame, not NaN).
  const d::BeamSection sec = resultantSection(0.02, 0.02);
  d::NodeVector x0 = {0.0, 0.0, 0.0, 0.3, 0.4, 0.0};
  Rig r = makeRig(x0, sec, elastic(), kRho, {0.0, 0.0, 0.0}, true);
  ASSERT_EQ(r.init_status.bad_elem, -1);
  const double dt = 1e-7;
  r.clamped[0] = 1;
  r.v[5] = 1.0;  // push the free end along z
  r.step(dt);
  r.step(dt);
  r.forces();
  EXPECT_TRUE(std::isfinite(r.f[5]));
  EXPECT_LT(r.f[5], 0.0);  // restoring
}

// ---- truss (ELFORM 3) ------------------------------------------------------------------------

TEST(Truss, AxialBarFrequency) {
  // Fixed-free bar: f = c / (4 L); started with the velocity of its first mode.
  const double L = 1.0;
  Rig r = makeRig(lineAlongX(20, L), truss(1e-4), elastic(), kRho, {0.0, 1.0, 0.0});
  r.clamped[0] = 1;
  for (std::size_t i = 0; i < r.numNodes(); ++i)
    r.v[3 * i] = 0.1 * std::sin(0.5 * kPi * r.x[3 * i] / L);
  const double c = std::sqrt(kE / kRho), f_exact = c / (4.0 * L);
  const double dt = 0.9 * r.stableStep();
  const double e0 = r.kinetic();
  CrossingCounter tip;
  const std::size_t tip_x = 3 * (r.numNodes() - 1);
  double worst_balance = 0.0;
  while (r.time < 3.2 / f_exact) {
    r.step(dt);
    tip.add(r.time, r.x[tip_x] - L);
    worst_balance = std::max(worst_balance, std::abs(r.kinetic() + r.internal() - e0) / e0);
  }
  EXPECT_NEAR(1.0 / tip.period() / f_exact, 1.0, 0.01);
  RecordProperty("frequency_ratio", fig(1.0 / tip.period() / f_exact));
  RecordProperty("energy_balance", fig(worst_balance));
  // Kinetic energy at half steps against the internal energy: agree to O(omega dt).
  EXPECT_LT(worst_balance, 0.1);
}

// A truss pulled at a constant slow rate from one clamped end; the stress against the
// logarithmic strain ln(L / L0) follows the bilinear curve, and the axial force is the true
// stress on the current area A0 L0 / L.
struct PullResult {
  std::vector<double> strain, stress, force;
  std::size_t turn = 0;  // first sample after the reversal
};

PullResult pullTruss(const m::Law& law, double strain_rate, double to_strain, double back_to) {
  const double L = 0.1, A = 1e-4;
  Rig r = makeRig(lineAlongX(1, L), truss(A), law, kRho, {0.0, 1.0, 0.0});
  r.clamped[0] = 1;
  r.prescribed = {{3, strain_rate * L}, {4, 0.0}, {5, 0.0}};
  const double dt = 0.5 * r.stableStep();
  PullResult out;
  bool back = false;
  for (int k = 0; k < 200000; ++k) {
    const double length = r.x[3] - r.x[0];  // x(n), where step() computes the forces
    r.step(dt);
    const double eps = std::log(length / L);
    const double N = -r.f[3];  // the element pulls node 2 back
    out.strain.push_back(eps);
    out.force.push_back(N);
    out.stress.push_back(N * length / (A * L));
    if (!back && eps >= to_strain) {
      back = true;
      out.turn = out.strain.size();
      r.prescribed[0].second = -strain_rate * L;
    }
    if (back && eps <= back_to) break;
  }
  return out;
}

TEST(Truss, PlasticYieldsAtSigyA) {
  // MAT_024 bilinear with ETAN = 0: elastic, then a plateau at sigy on the current area.
  const double sigy = 250e6;
  const PullResult res = pullTruss(law024(sigy, 0.0), 1.0, 0.01, 0.01);
  const double A = 1e-4, eps_y = sigy / kE;
  for (std::size_t k = 0; k < res.turn; ++k) {
    const double eps = res.strain[k];
    if (eps < 0.9 * eps_y) {
      EXPECT_NEAR(res.stress[k], kE * eps, 1e-3 * sigy);
    } else if (eps > 1.1 * eps_y) {
      EXPECT_NEAR(res.stress[k], sigy, 1e-6 * sigy);
      EXPECT_NEAR(res.force[k], sigy * A * std::exp(-eps), 1e-6 * sigy * A);
    }
  }
  EXPECT_GT(res.strain.back(), 0.0099);
}

TEST(Truss, KinematicHardeningHasBauschingerEffect) {
  // MAT_003, BETA = 0: slope ETAN after yield; on reversal, yield again at sigma_max - 2 sigy.
  const double sigy = 250e6, etan = 2e9;
  const PullResult res = pullTruss(law003(sigy, etan, 0.0), 0.25, 0.01, -0.01);
  const double eps_y = sigy / kE;
  double s_max = 0.0, eps_max = 0.0;
  std::size_t k_max = 0;
  for (std::size_t k = 0; k < res.strain.size(); ++k)
    if (res.strain[k] > eps_max) {
      eps_max = res.strain[k];
      s_max = res.stress[k];
      k_max = k;
    }
  EXPECT_NEAR(s_max, sigy + etan * (eps_max - eps_y), 2e-3 * sigy);
  // Reverse yield: the first point on the way back whose stress leaves the elastic line.
  double reverse_yield = 0.0;
  for (std::size_t k = k_max + 1; k < res.strain.size(); ++k) {
    const double elastic_line = s_max + kE * (res.strain[k] - eps_max);
    if (std::abs(res.stress[k] - elastic_line) > 1e-3 * sigy) {
      reverse_yield = res.stress[k - 1];
      break;
    }
  }
  EXPECT_NEAR(reverse_yield, s_max - 2.0 * sigy, 0.01 * sigy);
  RecordProperty("reverse_yield_error", fig((reverse_yield - (s_max - 2.0 * sigy)) / sigy));
  RecordProperty("peak_error", fig((s_max - (sigy + etan * (eps_max - eps_y))) / sigy));
}

TEST(Truss, FibreReturnIsOnTheYieldSurface) {
  // The beam-fibre return (axial plus shear) lands on the surface, with plastic strain
  // increments along the normal (MAT_024 with a curve, MAT_003 mixed hardening).
  const m::PlasticKinematic pk = law003(300e6, 1e9, 0.5);
  m::PiecewiseLinear pl = law024(300e6, 0.0);
  pl.curve_eps = {0.0, 0.02, 0.05, 0.2};
  pl.curve_sig = {300e6, 360e6, 380e6, 400e6};
  for (const m::Law& law : {m::Law(pk), m::Law(pl)}) {
    const m::FibreLaw fl = m::fibreLawOf(law);
    m::FibrePoint p;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int k = 0; k < 400; ++k) {
      const double de = 6e-4 * u(rng) + 2e-4, dgs = 8e-4 * u(rng), dgt = 8e-4 * u(rng);
      const m::FibrePoint old = p;
      m::updateFibre(fl, p, de, dgs, dgt, 1e-6);
      if (p.eps_p > old.eps_p) {
        const double x = p.sig - p.alpha, ys = p.tau_s - p.alpha_s, yt = p.tau_t - p.alpha_t;
        const double q = std::sqrt(x * x + 3.0 * (ys * ys + yt * yt));
        EXPECT_NEAR(q, m::flowStress(fl, p.eps_p), 1e-9 * fl.sigy);
        // Plastic strain increment along n = (x, 3 ys, 3 yt) / q: the elastic part of the
        // increment explains the rest.
        const double dep = p.eps_p - old.eps_p;
        const double ee = (p.sig - old.sig) / fl.E;
        EXPECT_NEAR(de - ee, dep * x / q, 1e-9 * std::abs(de) + 1e-15);
        const double es = (p.tau_s - old.tau_s) / fl.G;
        EXPECT_NEAR(dgs - es, dep * 3.0 * ys / q, 1e-9 * std::abs(dgs) + 1e-15);
      }
    }
    EXPECT_GT(p.eps_p, 0.01);
  }
}

// Rate-dependent yield curves in a truss fibre (tests/support/rate_law.hpp): pulled at a
// constant strain rate below, between and above a table's rates (and with LCSR), the axial
// stress after every plastic step is the yield stress at that rate and the plastic strain.
TEST(Truss, RateDependentYieldStaysOnTheCurveAtTheRate) {
  namespace rl = crumple::testing::rate_law;
  const auto laws = rl::allLaws();
  for (const auto& [law, yield] : laws) {
    const m::FibreLaw fl = m::fibreLawOf(law);
    for (const double rate : {0.5, 40.0, 1000.0}) {
      m::FibrePoint p;
      const double de = 2e-4, dt = de / rate;
      for (int n = 0; n < 500; ++n) {
        const double before = p.eps_p;
        m::updateFibre(fl, p, de, 0.0, 0.0, dt);
        const double expected = yield(p.eps_p, rate);  // a truss: the rate is de / dt
        if (p.eps_p == before) {
          ASSERT_LE(p.sig, expected * (1.0 + 1e-12)) << rate << " " << n;
          continue;
        }
        ASSERT_NEAR(p.sig, expected, 1e-6 * expected) << rate << " " << n;
      }
      EXPECT_GT(p.eps_p, 0.06) << rate;  // LCSR at 1000 /s: 2 % elastic strain
    }
  }
  // The static flow stress of a table is its first curve's.
  EXPECT_DOUBLE_EQ(m::flowStress(m::fibreLawOf(rl::tableLaw(0)), 0.1), rl::hA(0.1));
}

// VP = 1 in a truss fibre: after every plastic step the axial stress is the yield stress at the
// new plastic strain and the step's plastic strain rate; with Cowper-Symonds P = 1 on a flat
// curve the stress follows Perzyna's overstress law (tests/support/rate_law.hpp) with M = E.
TEST(Truss, ViscoplasticYieldIsAtThePlasticStrainRate) {
  namespace rl = crumple::testing::rate_law;
  for (const auto& [law, yield] : rl::allLaws(true)) {
    const m::FibreLaw fl = m::fibreLawOf(law);
    for (const double rate : {0.5, 40.0, 1000.0}) {
      m::FibrePoint p;
      const double de = 2e-4, dt = de / rate;
      for (int n = 0; n < 500; ++n) {
        const double before = p.eps_p;
        m::updateFibre(fl, p, de, 0.0, 0.0, dt);
        const double expected = yield(p.eps_p, (p.eps_p - before) / dt);
        if (p.eps_p == before) {
          ASSERT_LE(p.sig, expected * (1.0 + 1e-12)) << rate << " " << n;
          continue;
        }
        ASSERT_NEAR(p.sig, expected, 1e-9 * expected) << rate << " " << n;
      }
      EXPECT_GT(p.eps_p, 0.06) << rate;
    }
  }
  rl::Overstress o;
  const m::Law overstress = rl::cowperSymondsLaw(0.0, o.C, 1.0);  // fl views its curve
  const m::FibreLaw fl = m::fibreLawOf(overstress);
  o.M = fl.E;
  const double dt = 0.01 / o.rateConstant();
  m::FibrePoint p;
  p.sig = o.sigy;
  double q_be = o.sigy;
  for (int k = 1; k <= 1000; ++k) {
    m::updateFibre(fl, p, o.rate * dt, 0.0, 0.0, dt);
    q_be = o.backwardEuler(q_be, dt);
    ASSERT_NEAR(p.sig, q_be, 1e-9 * q_be) << k;
    ASSERT_NEAR(p.sig, o.exact(k * dt), 0.01 * (o.steady() - o.sigy)) << k;
  }
  EXPECT_NEAR(p.sig, o.steady(), 1e-4 * o.steady());
}

TEST(Truss, ErodesAtFailureStrain) {
  // MAT_003 FS: once the point reaches the failure strain the element is removed, its slots
  // zeroed, once.
  const double sigy = 250e6, fs = 0.005;
  const m::PlasticKinematic pk = law003(sigy, 1e9, 1.0, fs);
  const double L = 0.1;
  Rig r = makeRig(lineAlongX(1, L), truss(1e-4), pk, kRho, {0.0, 1.0, 0.0});
  r.clamped[0] = 1;
  r.prescribed = {{3, 0.1 * L}, {4, 0.0}, {5, 0.0}};
  const double dt = 0.5 * r.stableStep();
  int eroded = 0;
  double strain_at_erosion = 0.0;
  for (int k = 0; k < 20000 && r.time < 0.1; ++k) {
    const double length = r.x[3] - r.x[0];
    r.step(dt);
    if (r.status.eroded > 0 && eroded == 0) strain_at_erosion = std::log(length / L);
    eroded += r.status.eroded;
  }
  EXPECT_EQ(eroded, 1);
  EXPECT_EQ(r.blk.active[0], 0);
  for (double sl : r.slots) EXPECT_EQ(sl, 0.0);
  EXPECT_NEAR(strain_at_erosion, fs + sigy / kE, 2e-4);
}

TEST(Beam, ZeroLengthElementIsReported) {
  d::NodeVector x0 = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0};
  Rig r = makeRig(x0, resultantSection(0.02, 0.02), elastic(), kRho, {0.0, 1.0, 0.0});
  EXPECT_EQ(r.init_status.bad_elem, 1);
}

// ---- discrete elements ------------------------------------------------------------------------

struct Discrete {
  d::DiscreteBlock blk;
  d::NodeVector x, v, f;
  std::vector<double> mass, slots;
  std::vector<uint8_t> fixed;
  double dt_prev = 0.0, time = 0.0;
  long cycle = 0;

  void forces() {
    el::computeDiscreteForces(blk, x, v, dt_prev, slots.data(), 0, blk.size());
    std::fill(f.begin(), f.end(), 0.0);
    for (std::size_t e = 0; e < blk.size(); ++e)
      for (int a = 0; a < 2; ++a) {
        const auto n = static_cast<std::size_t>(blk.conn[e][static_cast<std::size_t>(a)]);
        for (int c = 0; c < 3; ++c) f[3 * n + c] += slots[3 * (2 * e + a) + c];
      }
  }
  void step(double dt) {
    forces();
    const double dt_n = cycle == 0 ? 0.5 * dt : 0.5 * (dt_prev + dt);
    for (std::size_t n = 0; n < mass.size(); ++n)
      for (int c = 0; c < 3; ++c)
        v[3 * n + c] = fixed[n] ? 0.0 : v[3 * n + c] + dt_n * f[3 * n + c] / mass[n];
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += dt * v[i];
    dt_prev = dt;
    time += dt;
    ++cycle;
  }
};

// One element from node 0 (fixed) to node 1 (mass m) along a unit axis, length L0.
Discrete makeDiscrete(d::DiscreteBlock::Kind kind, double k, double m, const Vec& axis, double L0,
                      double scale = 1.0, double offset = 0.0) {
  Discrete s;
  s.blk.law.kind = kind;
  s.blk.law.k = k;
  s.blk.elem = {0};
  s.blk.elem_id = {1};
  s.blk.conn = {{0, 1}};
  s.blk.scale = {scale};
  s.blk.offset = {offset};
  el::resizeDiscreteBlock(s.blk, 1);
  s.x = {0.1, 0.2, 0.3, 0.1 + L0 * axis[0], 0.2 + L0 * axis[1], 0.3 + L0 * axis[2]};
  s.v.assign(6, 0.0);
  s.f.assign(6, 0.0);
  s.mass = {1.0, m};
  s.fixed = {1, 0};
  s.slots.assign(6, 1.0);
  el::initializeDiscretes(s.blk, s.x, s.slots.data());
  return s;
}

TEST(Discrete, SpringMassFrequency) {
  const double k = 800.0, m = 2.0, L0 = 1.5;
  const Vec axis = {1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
  Discrete s = makeDiscrete(d::DiscreteBlock::Kind::SpringElastic, k, m, axis, L0);
  for (double sl : s.slots) EXPECT_EQ(sl, 0.0);  // no mass from discretes
  // LS-DYNA's step, from the masses at the two ends.
  EXPECT_DOUBLE_EQ(el::discreteStableStep(s.blk, {3.0, 2.0}, 0),
                   std::sqrt(2.0 * 3.0 * 2.0 / (k * 5.0)));
  EXPECT_DOUBLE_EQ(el::discreteStableStep(s.blk, {0.0, 2.0}, 0), std::sqrt(2.0 * 2.0 / k));
  const double v0 = 0.05;
  for (int c = 0; c < 3; ++c) s.v[3 + c] = v0 * axis[c];
  const double dt = 0.005 * el::discreteStableStep(s.blk, {0.0, m}, 0);
  const double omega = std::sqrt(k / m);
  CrossingCounter elongation;
  double worst = 0.0;
  const double e0 = 0.5 * m * v0 * v0;
  while (s.time < 3.3 * 2.0 * kPi / omega) {
    s.step(dt);
    elongation.add(s.time, s.blk.elongation[0]);
    double ke = 0.0;
    for (int c = 0; c < 3; ++c) ke += 0.5 * m * s.v[3 + c] * s.v[3 + c];
    worst = std::max(worst, std::abs(ke + s.blk.e_int[0] - e0) / e0);
  }
  EXPECT_NEAR(2.0 * kPi / elongation.period() / omega, 1.0, 0.01);
  RecordProperty("frequency_ratio", fig(2.0 * kPi / elongation.period() / omega));
  RecordProperty("energy_balance", fig(worst));
  EXPECT_LT(worst, 0.01);
}

TEST(Discrete, SpringForceWithScaleAndOffset) {
  // F = S k (delta + OFFSET), tension pulling node 1 towards node 2.
  Discrete s = makeDiscrete(d::DiscreteBlock::Kind::SpringElastic, 100.0, 1.0, {0.0, 0.0, 1.0}, 1.0,
                            2.0, 0.01);
  s.x[5] += 0.02;  // elongation 0.02
  s.forces();
  EXPECT_NEAR(s.f[2], 2.0 * 100.0 * 0.03, 1e-12);
  EXPECT_NEAR(s.f[5], -2.0 * 100.0 * 0.03, 1e-12);
  EXPECT_NEAR(s.blk.force[0], 6.0, 1e-12);
}

TEST(Discrete, DamperDissipatesEnergy) {
  const double c = 4.0, m = 2.0, v0 = 1.0;
  const Vec axis = {0.0, 0.6, 0.8};
  Discrete s = makeDiscrete(d::DiscreteBlock::Kind::DamperViscous, c, m, axis, 0.5);
  EXPECT_DOUBLE_EQ(el::discreteStableStep(s.blk, {0.0, m}, 0), m / c);
  for (int k = 0; k < 3; ++k) s.v[3 + k] = v0 * axis[k];
  const double dt = 1e-3;
  double dissipated = 0.0;  // c v^2 over each step, from the velocities the damper saw
  while (s.time < 1.0 - 1e-12) {
    const double v_mid = s.v[3] * axis[0] + s.v[4] * axis[1] + s.v[5] * axis[2];
    s.step(dt);
    if (s.cycle > 1) dissipated += c * v_mid * v_mid * dt;
  }
  double v_end = 0.0;
  for (int k = 0; k < 3; ++k) v_end += s.v[3 + k] * axis[k];
  EXPECT_NEAR(v_end / (v0 * std::exp(-c / m * s.time)), 1.0, 0.01);
  const double lost = 0.5 * m * (v0 * v0 - v_end * v_end);
  EXPECT_NEAR(s.blk.e_int[0] / lost, 1.0, 0.01);
  RecordProperty("velocity_ratio", fig(v_end / (v0 * std::exp(-c / m * s.time))));
  RecordProperty("energy_ratio", fig(s.blk.e_int[0] / lost));
  EXPECT_NEAR(s.blk.e_int[0], dissipated, 1e-9 * dissipated);
}

TEST(Discrete, NonlinearSpringFollowsItsCurve) {
  const double S = 2.0, offset = 0.01;
  Discrete s = makeDiscrete(d::DiscreteBlock::Kind::SpringNonlinear, 0.0, 1.0, {0.6, 0.0, -0.8},
                            1.0, S, offset);
  s.blk.law.curve_x = {-0.1, 0.0, 0.05, 0.1};
  s.blk.law.curve_y = {-50.0, 0.0, 100.0, 120.0};
  el::initializeDiscretes(s.blk, s.x, s.slots.data());
  auto curve = [&](double u) {
    const auto& X = s.blk.law.curve_x;
    const auto& Y = s.blk.law.curve_y;
    if (u < X[1]) return Y[0] + (Y[1] - Y[0]) / (X[1] - X[0]) * (u - X[0]);
    if (u < X[2]) return Y[1] + (Y[2] - Y[1]) / (X[2] - X[1]) * (u - X[1]);
    return Y[2] + (Y[3] - Y[2]) / (X[3] - X[2]) * (u - X[2]);
  };
  // Stretch to +0.2 (beyond the last point), then compress to -0.2 (beyond the first), and
  // back to the start: the force follows S f(delta + offset) throughout.
  s.fixed = {1, 1};
  const double rate = 0.1, dt = 1e-3;
  double max_error = 0.0, max_energy = 0.0;
  const Vec axis = {0.6, 0.0, -0.8};
  for (double target : {0.2, -0.2, 0.0}) {
    const double sign = target > s.blk.elongation[0] ? 1.0 : -1.0;
    while (sign * (target - s.blk.elongation[0]) > 1e-9) {
      const double step = std::min(rate * dt, std::abs(target - s.blk.elongation[0]));
      for (int c = 0; c < 3; ++c) {
        s.v[3 + c] = sign * step / dt * axis[c];
        s.x[3 + c] += step * sign * axis[c];
      }
      s.dt_prev = dt;
      s.forces();
      const double delta = s.blk.elongation[0];
      const double expected = S * curve(delta + offset);
      max_error = std::max(max_error, std::abs(s.blk.force[0] - expected));
      // Force on node 2 is minus the tension along the axis.
      const double on2 = s.f[3] * axis[0] + s.f[4] * axis[1] + s.f[5] * axis[2];
      max_error = std::max(max_error, std::abs(on2 + expected));
      max_energy = std::max(max_energy, s.blk.e_int[0]);
    }
  }
  EXPECT_LT(max_error, 1e-9 * 240.0);
  // Back at the start: the elastic spring has given back its work (up to the trapezoid
  // error at the curve's kinks).
  EXPECT_LT(std::abs(s.blk.e_int[0]), 1e-4 * max_energy);
  // Stable step from the tangent at the current elongation (offset 0.01: second segment).
  EXPECT_DOUBLE_EQ(el::discreteStableStep(s.blk, {0.0, 3.0}, 0),
                   std::sqrt(2.0 * 3.0 / (S * 2000.0)));
}

}  // namespace

// The release condensation (elements/beam_release.hpp): after it, R_old + K dd meets each
// released condition exactly and the increments moved only along the freed deformation (the
// condition's own vector, so the hinge does no work); two conditions in a plane zero both
// of its resultants; an end without releases is untouched.
TEST(BeamRelease, CondensationMeetsTheReleasedCondition) {
  using crumple::elements::applyReleases;
  using crumple::elements::DeformationStiffness;
  DeformationStiffness K;
  K.axial = 3.0;
  K.torsion = 0.7;
  K.s = {4.0, 1.5, 5.0};
  K.t = {2.0, -0.5, 2.5};
  const std::array<double, 6> R_old = {0.3, -0.2, 1.1, -0.4, 0.6, 0.9};
  const std::array<double, 6> dd0 = {0.01, 0.02, -0.03, 0.04, 0.05, -0.06};
  auto after = [&](int release) {
    std::array<double, 6> dd = dd0;
    applyReleases(release, K, R_old, dd);
    return dd;
  };
  auto resultant = [&](const std::array<double, 6>& dd, int k) {
    const auto& p = (k == 2 || k == 4) ? K.s : K.t;
    const int i = (k == 2 || k == 3) ? 0 : 1;
    const int a = (k == 2 || k == 4) ? 2 : 3, b = a + 2;  // the plane's two components
    return R_old[std::size_t(k)] + (i == 0 ? p[0] * dd[std::size_t(a)] + p[1] * dd[std::size_t(b)]
                                           : p[1] * dd[std::size_t(a)] + p[2] * dd[std::size_t(b)]);
  };
  EXPECT_EQ(after(0), dd0);
  // End 2 translation along r (bit 6): N = 0; the rest untouched.
  auto d = after(1 << 6);
  EXPECT_NEAR(R_old[0] + K.axial * d[0], 0.0, 1e-15);
  for (std::size_t k = 1; k < 6; ++k) EXPECT_EQ(d[k], dd0[k]);
  // End 1 rotation about r (bit 3): T = 0.
  d = after(1 << 3);
  EXPECT_NEAR(R_old[1] + K.torsion * d[1], 0.0, 1e-15);
  // End 1 rotation about s (bit 4): G_1s = 0, only theta_1s moved.
  d = after(1 << 4);
  EXPECT_NEAR(resultant(d, 2), 0.0, 1e-15);
  EXPECT_EQ(d[4], dd0[4]);
  // End 2 rotation about t (bit 11): G_2t = 0, only theta_2t moved.
  d = after(1 << 11);
  EXPECT_NEAR(resultant(d, 5), 0.0, 1e-15);
  EXPECT_EQ(d[3], dd0[3]);
  // End 1 translation along s (bit 1): the shear along s, G_1t + G_2t = 0, with theta_1t and
  // theta_2t moved alike (the chord's turn).
  d = after(1 << 1);
  EXPECT_NEAR(resultant(d, 3) + resultant(d, 5), 0.0, 1e-15);
  EXPECT_NEAR(d[3] - dd0[3], d[5] - dd0[5], 1e-15);
  EXPECT_NE(resultant(d, 3), 0.0);  // a couple remains
  // Both ends hinged about s: plane s carries nothing.
  d = after((1 << 4) | (1 << 10));
  EXPECT_NEAR(resultant(d, 2), 0.0, 1e-15);
  EXPECT_NEAR(resultant(d, 4), 0.0, 1e-15);
  EXPECT_EQ(d[3], dd0[3]);
  EXPECT_EQ(d[5], dd0[5]);
}
