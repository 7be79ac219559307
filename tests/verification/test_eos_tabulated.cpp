// *EOS_TABULATED_COMPACTION (EOS 8) and *EOS_TABULATED (EOS 9) in whole runs: a unit hex
// squeezed and released hydrostatically (triaxialCompression: the faces x, y, z = 1 driven by
// -a(t), the opposite faces held), its pressure against the table interpolated here from the
// deck's points (Keyword Manual vol. II, *EOS_TABULATED_COMPACTION, *EOS_TABULATED; Theory
// Manual, "Equation of State Form 8: Tabulated Compaction" and "Form 9: Tabulated") at the
// element's own ln V, least ln V and energy; the energy of EOS 9 over a squeeze-and-release
// cycle against the pressure work; and *MAT_SOIL_AND_FOAM with the same curve and KUN
// against *MAT_ELASTIC_PLASTIC_HYDRO with EOS 8 over the same cycle.
//
// Strain conventions: EOS 8 and 9 tabulate EV = ln V, V the relative volume to the reference
// state (V0 = 1 here: the initial state), negative in compression, in descending order;
// *MAT_005 tabulates EPS = ln(V / V0), negative in compression, in the same order. Crumple
// keeps both as sums of the step's tr(de) (the EOS laws ln(V/V0) in h[0], *MAT_005
// x = -ln(V/V0) in h[0]).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "harness.hpp"

using crumple::testing::Simulation;
using crumple::testing::termination;
using crumple::testing::triaxialCompression;

namespace {

// The table (EV descending; C in MPa; slopes of C in -eps_V: 1000, 600, 2200).
const std::vector<double> kEv{0.0, -0.05, -0.1, -0.2}, kC{0.0, 50.0, 80.0, 300.0},
    kT{1.0, 1.2, 1.5, 2.0}, kK{1500.0, 2000.0, 2500.0, 5000.0};

// A column interpolated linearly in the deck's descending EV, its end segments continued.
double interp(const std::vector<double>& y, double e) {
  std::size_t k = 0;
  while (k + 2 < kEv.size() && e < kEv[k + 1]) ++k;
  return y[k] + (y[k + 1] - y[k]) * (e - kEv[k]) / (kEv[k + 1] - kEv[k]);
}

// EOS 8's pressure: the curve while loading, else the line of slope K(eps_min) (K held at its
// end values past the table), plus GAMA T(eps) E.
double compaction(double e, double e_min, double gamma, double energy) {
  const double cold =
      e > e_min
          ? interp(kC, e_min) - interp(kK, std::clamp(e_min, kEv.back(), kEv.front())) * (e - e_min)
          : interp(kC, e);
  return cold + gamma * interp(kT, e) * energy;
}

// Five fields of width 16 per card: the column's points, then zeros to ten.
std::string rows(const std::vector<std::vector<double>>& columns) {
  std::string s;
  for (const auto& col : columns)
    for (int half = 0; half < 2; ++half) {
      for (std::size_t i = 5 * std::size_t(half); i < 5 * std::size_t(half) + 5; ++i)
        s += fmt::format("{:16.8g}", i < col.size() ? col[i] : 0.0);
      s += "\n";
    }
  return s;
}

// Curve 1: the faces' displacement a = 1 - exp(eps / 3) at the turning points (t, eps = ln V).
std::string path(const std::vector<std::pair<double, double>>& turns) {
  std::string s = "*DEFINE_CURVE\n         1\n";
  for (const auto& [t, e] : turns)
    s += fmt::format("{:20.12g}{:20.12g}\n", t, 1.0 - std::exp(e / 3.0));
  return s;
}

// The hex of triaxialCompression with the part taking equation of state 1.
std::string withEos(std::string deck) {
  const std::string part = "         1         1         1\n";
  deck.replace(deck.find(part, deck.find("*PART")), part.size(),
               "         1         1         1         1\n");
  return deck;
}

// The pressure of the hex's only point.
double pressureOf(const Simulation& sim) {
  const auto& blk = sim.sd.solid_blocks.at(0);
  return -(blk.sigAt(0, 0) + blk.sigAt(1, 0) + blk.sigAt(2, 0)) / 3.0;
}
// What the point of a law with an EOS holds: pressure, ln(V/V0), E - E0, least ln(V/V0).
struct PointState {
  double p, x, de, x_min;
};
PointState pointOf(const Simulation& sim) {
  const auto& blk = sim.sd.solid_blocks.at(0);
  using Block = std::decay_t<decltype(blk)>;
  const auto h = [&](int k) { return blk.hist.at(Block::blocked(blk.history, k, 0)); };
  return {pressureOf(sim), h(0), h(1), h(2)};
}
// ln V of the hex from its node 8 = (1, 1, 1): V = (1 - a)^3.
double lnVolume(const Simulation& sim) {
  return 3.0 * std::log(sim.x(8, 0));
}

// 1e-9 of the pressure (of 1 MPa near zero).
double relative(double got, double want) {
  return std::abs(got - want) / std::max(1.0, std::abs(want));
}

}  // namespace

// EOS 8 on *MAT_ELASTIC_PLASTIC_HYDRO (no yield: SIG0 far away), GAMA 0.2: squeezed to
// ln V = -0.15 (between EV3 and EV4), released to -0.08, squeezed again to -0.25 (past the
// table) and released to -0.22. The pressure follows the curve while loading and the line of
// slope K(eps_min) on unloading and reloading, with GAMA T E on both, to 1e-9 at the element's
// own ln V; that ln V is the hex's volume to the midpoint integration's accuracy.
TEST(VerificationEos, TabulatedCompactionHydrostaticCycle) {
  const double gamma = 0.2;
  const std::string mat =
      "*MAT_ELASTIC_PLASTIC_HYDRO\n         1     0.001    1000.0     1.0e9\n"
      "*EOS_TABULATED_COMPACTION\n         1       0.2\n" +
      rows({kEv, kC, kT, kK}) +
      path({{0.0, 0.0}, {0.3, -0.15}, {0.4, -0.08}, {0.6, -0.25}, {0.65, -0.22}});
  auto sim = Simulation::fromText("eos8_cycle", withEos(triaxialCompression(mat, 0.65)));
  double worst = 0.0, drift = 0.0, unloaded = 0.0, ln_v_last = 0.0;
  int checked = 0, on_line = 0, past_table = 0;
  sim->run([&](const auto&) {
    const PointState s = pointOf(*sim);
    worst = std::max(worst, relative(s.p, compaction(s.x, s.x_min, gamma, s.de)));
    // The step's stress is computed on the positions before it (as the soil test): its ln V
    // is that of the previous cycle's positions.
    drift = std::max(drift, std::abs(s.x - ln_v_last));
    ln_v_last = lnVolume(*sim);
    unloaded = std::max(unloaded, s.x - s.x_min);
    on_line += s.x > s.x_min + 1e-3;
    past_table += s.x_min < -0.2 && s.x > s.x_min + 1e-3;
    ++checked;
  });
  EXPECT_GT(checked, 1000);
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(drift, 1e-6);             // the hex's midpoint integration of ln V
  EXPECT_NEAR(unloaded, 0.07, 1e-3);  // released by 0.07 from -0.15
  EXPECT_GT(on_line, 200);            // unloading and reloading
  EXPECT_GT(past_table, 20);          // unloading past EV4: K held at K4
  const PointState end = pointOf(*sim);
  EXPECT_NEAR(end.x_min, -0.25, 1e-3);
  EXPECT_NEAR(end.x, -0.22, 1e-3);
  // 300 + 2200 x 0.05 at the turn, less K4 x 0.03 (to the step's strain, times K4), plus
  // GAMA T E with E of the compression.
  EXPECT_NEAR(end.p - gamma * interp(kT, end.x) * end.de, 410.0 - 5000.0 * 0.03, 3.0);
  EXPECT_GT(end.de, 20.0);  // the work of the squeezes less what the unloading gave back
}

// EOS 9 on *MAT_NULL (no viscosity, no cutoff in reach), GAMA 0.5 and E0 = 10: squeezed to
// ln V = -0.25, released to 0 and held there. The pressure is C + GAMA T E at the element's ln V
// and energy to 1e-9, on the way back too (the same curve: nonlinear elastic); the energy the EOS
// keeps equals the pressure work on the hex (-sum p dV from its nodes, trapezoidal) and the
// internal energy the element books, to 1e-6 of its peak, and is E0 again after the cycle.
// The bulk viscosity is made negligible (Q1 = Q2 = 1e-20): its work is the element's, not
// the EOS's.
TEST(VerificationEos, TabulatedHydrostaticCycleRetracesAndKeepsTheEnergy) {
  const double gamma = 0.5, e0 = 10.0;
  const std::string mat =
      "*MAT_NULL\n         1     0.001   -1.0e+6\n"
      "*EOS_TABULATED\n         1       0.5      10.0\n" +
      rows({kEv, kC, kT}) + "*CONTROL_BULK_VISCOSITY\n     1e-20     1e-20\n" +
      path({{0.0, 0.0}, {0.4, -0.25}, {0.8, 0.0}, {0.85, 0.0}});
  auto sim = Simulation::fromText("eos9_cycle", withEos(triaxialCompression(mat, 0.85)));
  double worst = 0.0, peak = 0.0, work = 0.0, work_gap = 0.0, booked_gap = 0.0;
  double v_last = 1.0, v_before = 1.0, p_prev = gamma * 1.0 * e0;  // the initial state
  int checked = 0;
  sim->run([&](const auto&) {
    const PointState s = pointOf(*sim);
    worst = std::max(worst, relative(s.p, interp(kC, s.x) + gamma * interp(kT, s.x) * (e0 + s.de)));
    // The step's stress is computed on the positions before it: its volume change is the one
    // between the two previous cycles' positions.
    work -= 0.5 * (p_prev + s.p) * (v_last - v_before);
    v_before = v_last;
    v_last = std::exp(lnVolume(*sim));
    p_prev = s.p;
    peak = std::max(peak, s.de);
    work_gap = std::max(work_gap, std::abs(work - s.de));
    booked_gap = std::max(booked_gap, std::abs(sim->sd.solid_blocks.at(0).e_int.at(0) - s.de));
    ++checked;
  });
  EXPECT_GT(checked, 1000);
  EXPECT_LT(worst, 1e-9);
  const PointState end = pointOf(*sim);
  EXPECT_GT(peak, 25.0);  // the squeeze's work, about 30 per unit volume
  EXPECT_LT(work_gap, 1e-6 * peak);
  EXPECT_LT(booked_gap, 1e-6 * peak);
  EXPECT_LT(std::abs(end.de), 1e-6 * peak);  // back at V0 with E0: reversible
  EXPECT_NEAR(end.p, gamma * e0, 1e-3);
}

// *MAT_SOIL_AND_FOAM (EPS = ln(V/V0) with P, KUN; no deviatoric limit in reach) and
// *MAT_ELASTIC_PLASTIC_HYDRO with EOS 8 of the same points (EV = ln V, V0 = 1; C = P, T = 0,
// every K = KUN), the same cutoff PC and shear modulus: the same stable step and, cycle by
// cycle, the same pressure through loading, unloading into tension, reloading and loading
// past the table.
TEST(VerificationEos, SoilAndFoamGivesTheSamePressuresAsTabulatedCompaction) {
  const auto turns = path({{0.0, 0.0}, {0.25, -0.15}, {0.32, -0.08}, {0.45, -0.22}, {0.5, -0.19}});
  const std::string soil =
      "*MAT_SOIL_AND_FOAM\n"
      "         1     0.001    1000.0    4000.0    1.0e12       0.0       0.0    -1.0e6\n"
      "       0.0       0.0\n"
      "       0.0     -0.05      -0.1      -0.2\n\n"
      "       0.0      50.0      80.0     300.0\n\n" +
      turns;
  const std::string hydro =
      "*MAT_ELASTIC_PLASTIC_HYDRO\n         1     0.001    1000.0    1.0e12       0.0    -1.0e6\n"
      "*EOS_TABULATED_COMPACTION\n         1\n" +
      rows({kEv, kC, {0.0}, {4000.0, 4000.0, 4000.0, 4000.0}}) + turns;
  auto a = Simulation::fromText("soil_same", triaxialCompression(soil, 0.5));
  auto b = Simulation::fromText("eos8_same", withEos(triaxialCompression(hydro, 0.5)));
  std::vector<double> pa, pb;
  a->run([&](const auto&) { pa.push_back(pressureOf(*a)); });
  b->run([&](const auto&) { pb.push_back(pressureOf(*b)); });
  const double low = *std::min_element(pb.begin(), pb.end());
  ASSERT_EQ(pa.size(), pb.size());  // the same wave modulus: the same steps
  EXPECT_GT(pa.size(), 1000u);
  double worst = 0.0;
  for (std::size_t i = 0; i < pa.size(); ++i) worst = std::max(worst, relative(pb[i], pa[i]));
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(low, -50.0);  // the unloading line went into tension (190 - 4000 x 0.07 = -90)
  EXPECT_NEAR(pa.back(), 300.0 + 2200.0 * 0.02 - 4000.0 * 0.03, 3.0);
}
