// Damping (*DAMPING_GLOBAL, *DAMPING_PART_MASS, *DAMPING_PART_STIFFNESS) and per-element beam
// sections (*ELEMENT_BEAM_THICKNESS) through the whole pipeline, against the damped
// oscillator (docs/theory.md, "Damping"):
//   - mass damping f = -D m v on a spring-mass: fraction of critical xi = D / (2 omega), the
//     logarithmic decrement delta = 2 pi xi / sqrt(1 - xi^2) (Clough & Penzien, Dynamics of
//     Structures, 1993, sec. 2-6);
//   - stiffness damping C = beta K on a two-mass chain: each mode keeps its shape and decays
//     with xi_i = beta omega_i / 2, so the higher mode decays omega_2 / omega_1 times faster;
//   - the energy balance kinetic + internal + damping = initial + external work;
//   - *ELEMENT_BEAM_THICKNESS gives what the same dimensions in *SECTION_BEAM give.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "harness.hpp"

namespace {

using crumple::testing::Simulation;
using crumple::testing::termination;

// A chain along x of `n` elements of length 1 (E A / L = kK), node 1 held, node i + 1 carrying
// the point mass kM; only the x translation is free. ELFORM 2 (resultant beam) or 3 (truss).
constexpr double kE = 1.0e5, kA = 1.0, kM = 1.0, kRho = 1.0e-3, kK = kE * kA;

std::string chainDeck(int n, int elform, const std::string& extra, const std::vector<double>& v0) {
  std::string s = "*KEYWORD\n*TITLE\ndamped chain\n" + extra;
  s += fmt::format("*MAT_ELASTIC\n         1{:10.4g}{:10.4g}       0.0\n", kRho, kE);
  s += fmt::format("*SECTION_BEAM\n         1{:10d}       1.0         2         0\n", elform);
  s += elform == 2
           ? fmt::format("{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}\n", kA, 0.1, 0.1, 0.2, kA)
           : fmt::format("{:10.4g}\n", kA);
  s += "*PART\nchain\n         1         1         1\n*NODE\n";
  for (int i = 0; i <= n; ++i)
    s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", i + 1, double(i), 0.0, 0.0);
  s += "*ELEMENT_BEAM\n";
  for (int i = 1; i <= n; ++i) s += fmt::format("{:8d}{:8d}{:8d}{:8d}\n", i, 1, i, i + 1);
  s += "*ELEMENT_MASS\n";
  for (int i = 1; i <= n; ++i) s += fmt::format("{:8d}{:8d}{:16.9g}{:8d}\n", i, i + 1, kM, 1);
  s += "*BOUNDARY_SPC_NODE\n";
  s += "         1         0         1         1         1         1         1         1\n";
  for (int i = 1; i <= n; ++i)
    s += fmt::format(
        "{:10d}         0         0         1         1         1         1         1\n", i + 1);
  s += "*INITIAL_VELOCITY_NODE\n";
  for (int i = 1; i <= n; ++i) s += fmt::format("{:10d}{:10.6g}\n", i + 1, v0[std::size_t(i - 1)]);
  return s + "*END\n";
}

// A constant curve 1 (value `y`).
std::string constantCurve(int id, double y) {
  return fmt::format("*DEFINE_CURVE\n{:10d}\n{:20.12g}{:20.12g}\n{:20.12g}{:20.12g}\n", id, 0.0, y,
                     1e6, y);
}

// The logarithmic decrement per cycle of a decaying oscillation: from its positive peaks
// (local maxima above zero), over as many cycles as there are peaks after the first.
double logDecrement(const std::vector<double>& u) {
  std::vector<double> peaks;
  for (std::size_t i = 1; i + 1 < u.size(); ++i)
    if (u[i] > 0 && u[i] >= u[i - 1] && u[i] > u[i + 1]) peaks.push_back(u[i]);
  if (peaks.size() < 3) return NAN;
  return std::log(peaks.front() / peaks.back()) / double(peaks.size() - 1);
}

double decrementOf(double xi) {
  return 2.0 * M_PI * xi / std::sqrt(1.0 - xi * xi);
}

// ---- mass damping: one mass on a spring ----------------------------------------------------

class MassDamping : public ::testing::TestWithParam<std::string> {};

TEST_P(MassDamping, LogarithmicDecrementIsTwoPiXi) {
  const double m = kM + 0.5 * kRho * kA;  // the point mass and the truss's lumped half
  const double omega = std::sqrt(kK / m);
  const double xi = 0.05, D = 2.0 * xi * omega;
  const double period = 2.0 * M_PI / omega;
  std::string damping;
  if (GetParam() == "GLOBAL")
    damping = fmt::format("*DAMPING_GLOBAL\n         0{:10.6g}\n", D);
  else
    damping = constantCurve(7, 1.0) + fmt::format(
                                          "*DAMPING_PART_MASS\n         1         7"
                                          "{:10.6g}         0\n",
                                          D);
  auto sim = Simulation::fromText("mass_damping_" + GetParam(),
                                  chainDeck(1, 3, damping + termination(6.2 * period), {1.0}));
  std::vector<double> u;
  sim->run([&](const auto&) { u.push_back(sim->x(2, 0) - sim->x0(2, 0)); });
  const double delta = logDecrement(u);
  std::printf("mass damping (%s): xi %.4f, decrement %.5f (analytic %.5f)\n", GetParam().c_str(),
              xi, delta, decrementOf(xi));
  EXPECT_NEAR(delta, decrementOf(xi), 0.01 * decrementOf(xi));
  // The energy taken out is booked: kinetic + internal + damping = the initial kinetic energy.
  const auto e = sim->solver->energies();
  EXPECT_GT(e.damping, 0.8 * e.initial);
  EXPECT_NEAR(e.ratio, 1.0, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Damping, MassDamping, ::testing::Values("GLOBAL", "PART_MASS"));

// ---- stiffness damping: two masses, two modes ----------------------------------------------

struct TwoModes {
  double omega[2];
  std::array<double, 2> shape[2];  // (u2, u3) of each mode
  double m[2];
};

// Modes of the chain fixed - k - m1 - k - m2: det(K - w^2 M) = 0.
TwoModes twoModes(double m1, double m2) {
  TwoModes t{};
  const double a = m1 * m2, b = -(2.0 * kK * m2 + kK * m1), c = kK * kK;
  const double disc = std::sqrt(b * b - 4 * a * c);
  const double lam[2] = {(-b - disc) / (2 * a), (-b + disc) / (2 * a)};
  for (int i = 0; i < 2; ++i) {
    t.omega[i] = std::sqrt(lam[i]);
    t.shape[i] = {1.0, (2.0 * kK - lam[i] * m1) / kK};
  }
  t.m[0] = m1;
  t.m[1] = m2;
  return t;
}

// Modal coordinate i of the displacements (u2, u3): phi_i^T M u / phi_i^T M phi_i.
double modal(const TwoModes& t, int i, double u2, double u3) {
  const auto& p = t.shape[i];
  return (p[0] * t.m[0] * u2 + p[1] * t.m[1] * u3) / (p[0] * t.m[0] * p[0] + p[1] * t.m[1] * p[1]);
}

// Runs the two-mass chain with *DAMPING_PART_STIFFNESS COEF `coef` and checks each mode's
// fraction of critical damping against beta omega_i / 2.
void checkRayleighDecay(const std::string& name, int elform, double coef, double beta) {
  // Lumped masses: the middle node has a whole element's mass, the end node half.
  const TwoModes t = twoModes(kM + kRho * kA, kM + 0.5 * kRho * kA);
  const double period = 2.0 * M_PI / t.omega[0];
  // Both modes at once: velocities along the sum of the two shapes.
  const std::vector<double> v0 = {t.shape[0][0] + 0.5 * t.shape[1][0],
                                  t.shape[0][1] + 0.5 * t.shape[1][1]};
  const std::string damping = fmt::format("*DAMPING_PART_STIFFNESS\n         1{:10.5g}\n", coef);
  auto sim =
      Simulation::fromText(name, chainDeck(2, elform, damping + termination(4.2 * period), v0));
  std::vector<double> q[2];
  sim->run([&](const auto&) {
    const double u2 = sim->x(2, 0) - sim->x0(2, 0), u3 = sim->x(3, 0) - sim->x0(3, 0);
    for (int i = 0; i < 2; ++i) q[i].push_back(modal(t, i, u2, u3));
  });
  double xi[2];
  for (int i = 0; i < 2; ++i) {
    const double xi_exact = 0.5 * beta * t.omega[i];
    const double delta = logDecrement(q[i]);
    // Invert delta = 2 pi xi / sqrt(1 - xi^2).
    xi[i] = delta / std::sqrt(4.0 * M_PI * M_PI + delta * delta);
    std::printf("%s: ELFORM %d COEF %g mode %d: omega %.2f, xi %.5f (Rayleigh %.5f)\n",
                name.c_str(), elform, coef, i + 1, t.omega[i], xi[i], xi_exact);
    EXPECT_NEAR(xi[i], xi_exact, 0.02 * xi_exact);
  }
  EXPECT_NEAR(xi[1] / xi[0], t.omega[1] / t.omega[0], 0.02 * t.omega[1] / t.omega[0]);
  const auto e = sim->solver->energies();
  EXPECT_GT(e.damping, 0.1 * e.initial);
  EXPECT_NEAR(e.ratio, 1.0, 0.01);
}

class StiffnessDamping : public ::testing::TestWithParam<int> {};

// COEF < 0: beta = |COEF|, chosen for 2 % of critical in mode 1.
TEST_P(StiffnessDamping, HigherModeDecaysAsRayleighSays) {
  const TwoModes t = twoModes(kM + kRho * kA, kM + 0.5 * kRho * kA);
  const double beta = 2.0 * 0.02 / t.omega[0];
  checkRayleighDecay(fmt::format("stiffness_damping_{}", GetParam()), GetParam(), -beta, beta);
}

// COEF > 0: the fraction of critical damping at the element's highest frequency 2 / dt_e, i.e.
// beta = COEF dt_e; a truss's dt_e is L / c.
TEST(StiffnessDampingFraction, BetaIsCoefTimesTheElementStep) {
  const double coef = 1.0, dt_e = 1.0 * std::sqrt(kRho / kE);
  checkRayleighDecay("stiffness_damping_fraction", 3, coef, coef * dt_e);
}

INSTANTIATE_TEST_SUITE_P(Damping, StiffnessDamping, ::testing::Values(2, 3));

// ---- energy balance with work done: a pulled chain under mass and stiffness damping ---------

TEST(DampingEnergy, KineticInternalDampingEqualWork) {
  const double omega = std::sqrt(kK / kM), period = 2.0 * M_PI / omega;
  std::string extra = constantCurve(7, 1.0) + constantCurve(8, 1.0);
  extra += fmt::format("*DAMPING_PART_MASS\n         1         7{:10.6g}         0\n", 0.1 * omega);
  extra += fmt::format("*DAMPING_PART_STIFFNESS\n         1{:10.5g}\n", -0.05 / omega);
  extra += "*LOAD_NODE_POINT\n         3         1         8     1000.\n";
  auto sim = Simulation::fromText("damping_energy",
                                  chainDeck(2, 2, extra + termination(4.0 * period), {0.0, 0.0}));
  double worst = 0.0;
  int samples = 0;
  sim->run([&](const auto& s) {
    if (s.cycle() % 10 != 0 || s.time() < period) return;
    const auto e = s.energies();
    const double reference = e.initial + e.external_work;
    worst = std::max(worst, std::abs(e.kinetic + e.internal + e.damping - reference) / reference);
    ++samples;
  });
  const auto e = sim->solver->energies();
  std::printf("pulled chain: work %.4g, kinetic %.4g, internal %.4g, damping %.4g, worst %.2e\n",
              e.external_work, e.kinetic, e.internal, e.damping, worst);
  EXPECT_GT(samples, 100);
  EXPECT_GT(e.damping, 0.2 * e.external_work);
  EXPECT_LT(worst, 0.01);
}

// ---- *ELEMENT_BEAM_THICKNESS ------------------------------------------------------------------

// A cantilever of 6 beams along x struck sideways, in two parts with different sections
// (elements 1-3: section 1, 4-6: section 2); with `thickness` the two parts share one blank
// section and every element gives its dimensions on the _THICKNESS card.
std::string cantilever(int elform, bool thickness) {
  const std::array<std::array<double, 5>, 2> dims =
      elform == 2 ? std::array<std::array<double, 5>, 2>{{{2.0, 0.4, 0.3, 0.5, 1.5},
                                                          {1.0, 0.1, 0.08, 0.15, 0.8}}}
                  : std::array<std::array<double, 5>, 2>{
                        {{1.2, 1.0, 1.5, 1.3, 0.0}, {0.8, 0.7, 1.0, 0.9, 0.0}}};
  std::string s = "*KEYWORD\n*TITLE\ncantilever\n" + termination(0.05);
  s += fmt::format("*MAT_ELASTIC\n         1{:10.4g}{:10.4g}       0.3\n", 1e-3, 1e5);
  auto section = [&](int id, const std::array<double, 5>& d) {
    std::string c =
        fmt::format("*SECTION_BEAM\n{:10d}{:10d}       1.0         2         0\n", id, elform);
    if (elform == 2)
      return c + fmt::format("{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}\n", d[0], d[1], d[2], d[3],
                             d[4]);
    return c + fmt::format("{:10.4g}{:10.4g}{:10.4g}{:10.4g}\n", d[0], d[1], d[2], d[3]);
  };
  if (thickness) {
    s += section(1, {0, 0, 0, 0, 0});
    s += "*PART\nbeam\n         1         1         1\n";
  } else {
    s += section(1, dims[0]) + section(2, dims[1]);
    s +=
        "*PART\nroot\n         1         1         1\n*PART\ntip\n         2         2         1\n";
  }
  s += "*NODE\n";
  for (int i = 0; i <= 6; ++i)
    s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", i + 1, double(i), 0.0, 0.0);
  s += thickness ? "*ELEMENT_BEAM_THICKNESS\n" : "*ELEMENT_BEAM\n";
  for (int i = 1; i <= 6; ++i) {
    const int part = thickness ? 1 : (i <= 3 ? 1 : 2);
    s += fmt::format("{:8d}{:8d}{:8d}{:8d}\n", i, part, i, i + 1);
    if (thickness) {
      const auto& d = dims[i <= 3 ? 0 : 1];
      s += fmt::format("{:16.9g}{:16.9g}{:16.9g}{:16.9g}{:16.9g}\n", d[0], d[1], d[2], d[3], d[4]);
    }
  }
  s += "*BOUNDARY_SPC_NODE\n         1         0         1         1         1         1         1"
       "         1\n";
  s += "*INITIAL_VELOCITY_NODE\n";
  for (int i = 2; i <= 7; ++i)
    s += fmt::format("{:10d}{:10.4g}{:10.4g}{:10.4g}\n", i, 0.0, 0.3 * i, 0.1 * i);
  return s + "*END\n";
}

class BeamThickness : public ::testing::TestWithParam<int> {};

TEST_P(BeamThickness, SameAsTheEquivalentSections) {
  const int elform = GetParam();
  auto a = Simulation::fromText(fmt::format("beam_sections_{}", elform), cantilever(elform, false));
  auto b = Simulation::fromText(fmt::format("beam_thickness_{}", elform), cantilever(elform, true));
  EXPECT_EQ(a->sd.beam_blocks.size(), 2u);
  EXPECT_EQ(b->sd.beam_blocks.size(), 2u);  // one per distinct set of dimensions
  a->run();
  b->run();
  double largest = 0.0;
  for (int node = 2; node <= 7; ++node)
    for (int c = 0; c < 3; ++c) {
      largest = std::max(largest, std::abs(a->x(node, c) - a->x0(node, c)));
      EXPECT_DOUBLE_EQ(a->x(node, c), b->x(node, c)) << "node " << node << " component " << c;
      EXPECT_DOUBLE_EQ(a->v(node, c), b->v(node, c)) << "node " << node << " component " << c;
    }
  EXPECT_GT(largest, 1e-3);  // the beams have moved
}

INSTANTIATE_TEST_SUITE_P(Damping, BeamThickness, ::testing::Values(1, 2));

}  // namespace
