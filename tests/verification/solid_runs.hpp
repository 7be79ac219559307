// Whole-run checks shared by the solid formulations that come as cut hexahedral bricks
// (tetrahedra in test_tets.cpp, pentahedra in test_pentas.cpp): a deck writer turns a brick of
// nx x ny x nz cells on [0,lx]x[0,ly]x[0,lz] (node ids as brickDeck) into that element's deck.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "harness.hpp"

namespace crumple::testing {

// Units mm, ms, kg, GPa (kN).
inline constexpr double kSteelE = 210.0, kSteelNu = 0.3, kSteelRho = 7.85e-6;
inline const std::string kSteel = "*MAT_ELASTIC\n         1   7.85e-6     210.0       0.3\n";
inline const std::string kEsort1 = "*CONTROL_SOLID\n         1\n";

using BrickWriter = std::function<std::string(int nx, int ny, int nz, double lx, double ly,
                                              double lz, const std::string& extra)>;

// brickDeck (8-node hexahedra) with its section's ELFORM set to `form`.
inline BrickWriter formWriter(int form) {
  return [form](int nx, int ny, int nz, double lx, double ly, double lz, const std::string& extra) {
    std::string deck = brickDeck(nx, ny, nz, lx, ly, lz, extra);
    const std::string one = "*SECTION_SOLID\n         1         1\n";
    deck.replace(deck.find(one), one.size(),
                 "*SECTION_SOLID\n         1" + fmt::format("{:10d}", form) + "\n");
    return deck;
  };
}

// A bar of nx x 2 x 2 cells held axially at x = 0, started with v_x = v0 x / L: its axial
// modes ring.
inline std::string vibratingBar(int nx, double v0) {
  std::string vel = "*INITIAL_VELOCITY_NODE\n";
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= nx; ++i)
        vel += fmt::format("{:10d}{:10.6g}{:10.6g}{:10.6g}\n", 1 + i + (nx + 1) * (j + 3 * k),
                           v0 * i / nx, 0.1 * v0 * j * k / 4.0, 0.0);
  return brickNodeSet(1, nx, 2, 2, [](int i, int, int) { return i == 0; }) + vel +
         "*BOUNDARY_SPC_SET\n         1         0         1         0         0\n";
}

// Total energy (kinetic + internal, bulk viscosity work included) over 10 axial periods of a
// free 80 x 10 x 10 mm bar: central differences conserve it up to a bounded oscillation; the
// element adds no hourglass energy. Returns the worst |E - E0| / E0.
inline double freeBarEnergyDrift(const BrickWriter& write, const char* label) {
  const int nx = 16;
  auto sim = Simulation::fromText(
      label, write(nx, 2, 2, 80.0, 10, 10, kSteel + termination(0.6) + vibratingBar(nx, 2.0)));
  const double e0 = sim->solver->energies().kinetic;
  EXPECT_GT(e0, 0.0);
  double worst = 0.0, max_internal = 0.0;
  sim->run([&](const auto& s) {
    // The last step is cut to end on ENDTIM: its half-step kinetic energy belongs to a
    // shorter step (an artefact of the bookkeeping, hexahedra show it too).
    if (s.finished()) return;
    const auto e = s.energies();
    worst = std::max(worst, std::abs(e.total - e0) / e0);
    max_internal = std::max(max_internal, e.internal);
  });
  EXPECT_EQ(sim->solver->energies().hourglass, 0.0);
  EXPECT_GT(max_internal, 0.5 * e0);  // it really vibrates
  std::printf("[ figure ] %s: %llu cycles, worst |E - E0| / E0 = %.2e\n", label,
              static_cast<unsigned long long>(sim->solver->cycle()), worst);
  return worst;
}

// The final state of a run, positions then velocities.
inline std::vector<double> finalState(const std::string& name, const std::string& deck) {
  auto sim = Simulation::fromText(name, deck);
  sim->run();
  std::vector<double> out = sim->sd.x;
  out.insert(out.end(), sim->sd.v.begin(), sim->sd.v.end());
  return out;
}

// ESORT: the decks of `sorted` (degenerate hexahedra under *CONTROL_SOLID ESORT = 1) end in
// the same state as `native` bit for bit; `unsorted` (ESORT = 0: collapsed one-point
// hexahedra) gives another answer.
inline void expectSortedRunsAsNative(const std::string& name, const std::string& native,
                                     const std::vector<std::string>& sorted,
                                     const std::string& unsorted) {
  const auto reference = finalState(name + "_native", native);
  for (std::size_t k = 0; k < sorted.size(); ++k)
    EXPECT_TRUE(finalState(name + "_sorted" + std::to_string(k), sorted[k]) == reference) << k;
  const auto other = finalState(name + "_unsorted", unsorted);
  EXPECT_EQ(other.size(), reference.size());
  double diff = 0.0;
  for (std::size_t i = 0; i < reference.size() && i < other.size(); ++i)
    diff = std::max(diff, std::abs(reference[i] - other[i]));
  EXPECT_GT(diff, 1e-6);
}

// The ESORT note of a deck's reading ("read but not honoured"), empty when there is none.
inline std::string esortNote(const std::string& name, const std::string& deck) {
  auto sim = Simulation::fromText(name, deck);
  for (const auto& i : sim->model.ignored)
    if (i.field == "ESORT") return i.reason;
  return "";
}

// A 100 x 10 x 10 mm steel cantilever of nx x 2 x 2 cells, clamped at x = 0, tip load P along
// `dof` (2: y, 3: z) ramped over 4 beam-theory periods and held for 2; the mean tip deflection
// over the hold against Timoshenko beam theory.
inline double cantileverTipRatio(const BrickWriter& write, const std::string& control, int dof,
                                 const char* label, int nx = 20) {
  const double L = 100.0, h = 10.0, P = 1.0;
  const double I = h * h * h * h / 12.0, A = h * h, G = kSteelE / (2 * (1 + kSteelNu));
  const double theory = P * L * L * L / (3 * kSteelE * I) + P * L / (5.0 / 6.0 * G * A);
  const double omega1 =
      1.875104 * 1.875104 * std::sqrt(kSteelE * I / (kSteelRho * A * L * L * L * L));
  const double period = 2.0 * M_PI / omega1;
  // Tip nodes (i = nx): bilinear weights of the 2 x 2 end face.
  std::string loads = fmt::format(
      "*DEFINE_CURVE\n         1\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n"
      "*LOAD_NODE_POINT\n",
      0.0, 0.0, 4.0 * period, 1.0, 1000.0, 1.0);
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 2; ++j) {
      const double w = (j == 1 ? 0.5 : 0.25) * (k == 1 ? 0.5 : 0.25);
      loads += fmt::format("{:10d}{:10d}         1{:10.4g}\n", 1 + nx + (nx + 1) * (j + 3 * k), dof,
                           P * w);
    }
  const std::string clamp =
      brickNodeSet(1, nx, 2, 2, [](int i, int, int) { return i == 0; }) +
      "*BOUNDARY_SPC_SET\n         1         0         1         1         1\n";
  auto sim = Simulation::fromText(
      label,
      write(nx, 2, 2, L, h, h, kSteel + control + termination(6.0 * period) + loads + clamp));
  const int64_t tip = 1 + nx + (nx + 1) * (1 + 3 * 1);
  double sum = 0.0, time = 0.0;
  sim->run([&](const solver::Solver& s) {
    if (s.time() <= 4.0 * period) return;
    sum += (sim->x(tip, dof - 1) - sim->x0(tip, dof - 1)) * s.dt();
    time += s.dt();
  });
  const double ratio = sum / time / theory;
  std::printf("[ figure ] cantilever %s: tip / beam theory = %.3f\n", label, ratio);
  return ratio;
}

}  // namespace crumple::testing
