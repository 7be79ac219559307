// Pentahedra (*SECTION_SOLID ELFORM 15, and degenerate hexahedra sorted by *CONTROL_SOLID
// ESORT = 1) through whole runs: energy of a free vibration, the same answer bit for bit
// whichever way a deck writes its prisms, the ESORT = 0 warning, a cantilever against beam
// theory; and *INITIAL_VELOCITY_GENERATION in a local coordinate system (ICID).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "harness.hpp"
#include "solid_runs.hpp"
#include "util/error.hpp"

namespace {

using crumple::testing::kEsort1;
using crumple::testing::kSteel;
using crumple::testing::kSteelRho;
using crumple::testing::Simulation;
using crumple::testing::termination;
using crumple::testing::vibratingBar;

// How a deck writes its prisms.
enum class PrismInput {
  Elform15Other,  // *SECTION_SOLID ELFORM 15, N1 N2 N3 N3 N5 N6 N7 N7 (N3 = N4, N7 = N8)
  Elform1Manual,  // ELFORM 1, N1 N2 N3 N4 N5 N5 N6 N6 (the Keyword Manual's pentahedron)
  Elform1Other,   // ELFORM 1, N3 = N4 and N7 = N8
};

// An nx x ny x nz brick on [0,lx]x[0,ly]x[0,lz] (node ids as brickDeck), each cell cut along
// its diagonal from corner (i, j) to (i+1, j+1) into two prisms with their axes along z.
std::string prismDeck(int nx, int ny, int nz, double lx, double ly, double lz, PrismInput input,
                      const std::string& extra) {
  std::string s = "*KEYWORD\n*TITLE\nverification pentahedra\n" + extra;
  s += fmt::format(
      "*PART\nprisms\n         1         1         1\n*SECTION_SOLID\n         1{:10d}\n",
      input == PrismInput::Elform15Other ? 15 : 1);
  s += "*NODE\n";
  auto id = [&](int i, int j, int k) { return 1 + i + (nx + 1) * (j + (ny + 1) * k); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", id(i, j, k), lx * i / nx, ly * j / ny,
                         lz * k / nz);
  s += "*ELEMENT_SOLID\n";
  int e = 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int h[4][2] = {{id(i, j, k), id(i, j, k + 1)},
                             {id(i + 1, j, k), id(i + 1, j, k + 1)},
                             {id(i + 1, j + 1, k), id(i + 1, j + 1, k + 1)},
                             {id(i, j + 1, k), id(i, j + 1, k + 1)}};
        for (const auto& t : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
          // Bottom triangle a b c (normal +z), top d e f above it.
          const int a = h[t[0]][0], b = h[t[1]][0], c = h[t[2]][0];
          const int d = h[t[0]][1], f2 = h[t[1]][1], g = h[t[2]][1];
          const bool manual = input == PrismInput::Elform1Manual;
          s += manual ? fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", e++, 1,
                                    a, c, g, d, b, b, f2, f2)
                      : fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", e++, 1,
                                    a, b, c, c, d, f2, g, g);
        }
      }
  return s + "*END\n";
}

// A writer of prism decks for the shared checks (solid_runs.hpp).
crumple::testing::BrickWriter prismWriter(PrismInput input) {
  return
      [input](int nx, int ny, int nz, double lx, double ly, double lz, const std::string& extra) {
        return prismDeck(nx, ny, nz, lx, ly, lz, input, extra);
      };
}

TEST(VerificationPentas, FreeVibrationConservesEnergy) {
  EXPECT_LT(crumple::testing::freeBarEnergyDrift(prismWriter(PrismInput::Elform15Other),
                                                 "prism_vibration"),
            3e-3);
}

std::string esortDeck(PrismInput input, const std::string& control) {
  return prismDeck(4, 2, 2, 40.0, 10.0, 10.0, input,
                   kSteel + control + termination(0.05) + vibratingBar(4, 5.0));
}

TEST(VerificationPentas, EsortRunsDegenerateHexahedraAsElform15BitForBit) {
  crumple::testing::expectSortedRunsAsNative(
      "pesort", esortDeck(PrismInput::Elform15Other, ""),
      {esortDeck(PrismInput::Elform1Manual, kEsort1), esortDeck(PrismInput::Elform1Other, kEsort1)},
      esortDeck(PrismInput::Elform1Manual, ""));
}

TEST(VerificationPentas, Esort0WarnsWithTheCountPerPart) {
  using crumple::testing::esortNote;
  const auto note = esortNote("pesort_warn", esortDeck(PrismInput::Elform1Manual, ""));
  EXPECT_NE(note.find("part 1: 32 degenerate solid(s) (0 tetrahedra, 32 pentahedra, 0 "
                      "other) run as ELFORM 1 hexahedra"),
            std::string::npos)
      << note;
  EXPECT_NE(note.find("pentahedra as ELFORM 15"), std::string::npos) << note;
  EXPECT_EQ(esortNote("pesort_quiet", esortDeck(PrismInput::Elform15Other, "")), "");
  EXPECT_EQ(esortNote("pesort_quiet", esortDeck(PrismInput::Elform1Other, kEsort1)), "");
}

TEST(VerificationPentas, RefusesAHexahedronUnderElform15) {
  std::string deck =
      prismDeck(1, 1, 1, 1, 1, 1, PrismInput::Elform15Other, kSteel + termination(0.01));
  const auto at = deck.find("*ELEMENT_SOLID\n") + 15;
  deck = deck.substr(0, at) +
         "     100       1       1       2       4       3       5       6       8       7\n" +
         deck.substr(at);
  try {
    Simulation::fromText("hex_as_penta", deck);
    ADD_FAILURE() << "a hexahedron under ELFORM 15 was accepted";
  } catch (const crumple::util::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ELFORM 15) needs 6 distinct nodes"), std::string::npos)
        << e.what();
  }
}

// The cantilever of solid_runs.hpp in cells of two prisms with their axes along z. Bending in
// the plane of the axes (tip load along z) sees the bending strain vary between the two points:
// 1.048 of Timoshenko's deflection (the same mesh of ELFORM 10 tetrahedra gives 0.50, of
// collapsed ELFORM 1 hexahedra 1.01). Bending in the plane of the triangles (load along y)
// has the constant-strain triangle across the depth, two through it, and locks as the
// tetrahedra do: 0.505.
TEST(VerificationPentas, CantileverBendingAgainstBeamTheory) {
  const auto write = prismWriter(PrismInput::Elform15Other);
  const double along = crumple::testing::cantileverTipRatio(write, "", 3, "penta_cant_z");
  const double across = crumple::testing::cantileverTipRatio(write, "", 2, "penta_cant_y");
  EXPECT_GT(along, 0.97);
  EXPECT_LT(along, 1.10);
  EXPECT_GT(across, 0.40);
  EXPECT_LT(across, 0.65);
}

// *INITIAL_VELOCITY_GENERATION with ICID: (VX, VY, VZ) and the axis (NX, NY, NZ) are components
// in the local system; the centre stays global. A free block given v = (3, 0, 0) in a system
// turned 30 degrees about z and 20 about the new x moves with the turned velocity; a spin
// about the local z axis gives omega e_z' x (x - xc).
TEST(VerificationPentas, InitialVelocityInALocalSystem) {
  const double a = 30.0 * M_PI / 180.0, b = 20.0 * M_PI / 180.0;
  // Local axes: e1 = Rz(a) x, e2 = Rz(a) Rx(b) y, e3 = e1 x e2.
  const double e1[3] = {std::cos(a), std::sin(a), 0.0};
  const double e2[3] = {-std::sin(a) * std::cos(b), std::cos(a) * std::cos(b), std::sin(b)};
  const double e3[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                        e1[0] * e2[1] - e1[1] * e2[0]};
  const std::string frame = fmt::format(
      "*DEFINE_COORDINATE_SYSTEM\n         7{:10.6f}{:10.6f}{:10.6f}{:10.6f}{:10.6f}{:10.6f}\n"
      "{:10.6f}{:10.6f}{:10.6f}\n",
      1.0, 2.0, 3.0, 1.0 + e1[0], 2.0 + e1[1], 3.0 + e1[2], 1.0 + e2[0], 2.0 + e2[1], 3.0 + e2[2]);
  const auto deck = [&](double vx, double omega) {
    return prismDeck(
        2, 2, 2, 10, 10, 10, PrismInput::Elform15Other,
        kSteel + termination(0.05) + frame +
            fmt::format("*INITIAL_VELOCITY_GENERATION\n         1         2{:10.4g}"
                        "{:10.4g}         0         0         0         7\n"
                        "       5.0       5.0       5.0         0         0       1.0\n",
                        omega, vx));
  };
  // Translation: every node starts, and the block's momentum stays, along e1 (|v| = 3; the
  // deck's points have 6 decimals, hence the 1e-5 on the direction).
  auto sim = Simulation::fromText("icid_translation", deck(3.0, 0.0));
  const double mass = kSteelRho * 1000.0;
  double p0[3];
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(sim->v(14, c), 3.0 * e1[c], 3e-5) << c;
    p0[c] = sim->momentum(c);
    EXPECT_NEAR(p0[c], mass * 3.0 * e1[c], mass * 3e-5) << c;
  }
  sim->run();
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sim->momentum(c), p0[c], 1e-14) << c;
  // The centre node (5, 5, 5) has moved by v t along e1.
  const double t = sim->solver->time();
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(sim->x(14, c) - sim->x0(14, c), 3.0 * e1[c] * t, 3e-5 * t) << c;
  // Rotation about the local z axis through the global centre (5, 5, 5): corner node 1 at
  // the origin starts with omega e3 x (x - xc).
  auto spin = Simulation::fromText("icid_spin", deck(0.0, 0.2));
  const double r[3] = {-5.0, -5.0, -5.0};
  const double w[3] = {e3[1] * r[2] - e3[2] * r[1], e3[2] * r[0] - e3[0] * r[2],
                       e3[0] * r[1] - e3[1] * r[0]};
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(spin->v(1, c), 0.2 * w[c], 1e-5) << c;
}

}  // namespace
