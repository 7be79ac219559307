// Tetrahedra (*SECTION_SOLID ELFORM 10) and *CONTROL_SOLID ESORT through whole runs: energy
// of a free vibration, the same answer bit for bit whichever way a deck writes its
// tetrahedra, the ESORT = 0 warning, refusals, and a cantilever against beam theory.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "harness.hpp"
#include "solid_runs.hpp"
#include "util/error.hpp"

namespace {

using crumple::testing::Simulation;
using crumple::testing::termination;

using crumple::testing::kEsort1;
using crumple::testing::kSteel;
using crumple::testing::vibratingBar;

// How a deck writes its tetrahedra.
enum class TetInput {
  Elform10Blank,     // *SECTION_SOLID ELFORM 10, N5-N8 blank
  Elform1Repeated,   // ELFORM 1, N1 N2 N3 N4 N4 N4 N4 N4 (LS-DYNA's degenerate hexahedron)
  Elform1N3EqualsN4  // ELFORM 1, N1 N2 N3 N3 N4 N4 N4 N4 (the other degenerate convention)
};

// Kuhn's six tetrahedra of a hexahedron (tools/deckgen.py KUHN_TETS), 0-based corners.
constexpr int kKuhn[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                             {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};

// An nx x ny x nz brick on [0,lx]x[0,ly]x[0,lz] (node ids as brickDeck), each cell cut into
// six tetrahedra, part 1.
std::string tetDeck(int nx, int ny, int nz, double lx, double ly, double lz, TetInput input,
                    const std::string& extra) {
  std::string s = "*KEYWORD\n*TITLE\nverification tetrahedra\n" + extra;
  s +=
      fmt::format("*PART\ntets\n         1         1         1\n*SECTION_SOLID\n         1{:10d}\n",
                  input == TetInput::Elform10Blank ? 10 : 1);
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
        const int h[8] = {
            id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
            id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        for (const auto& t : kKuhn) {
          const int a = h[t[0]], b = h[t[1]], c = h[t[2]], d = h[t[3]];
          switch (input) {
            case TetInput::Elform10Blank:
              s += fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", e++, 1, a, b, c, d);
              break;
            case TetInput::Elform1Repeated:
              s += fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", e++, 1, a, b,
                               c, d, d, d, d, d);
              break;
            case TetInput::Elform1N3EqualsN4:
              s += fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", e++, 1, a, b,
                               c, c, d, d, d, d);
              break;
          }
        }
      }
  return s + "*END\n";
}

// Total energy over 10 axial periods of a free tetrahedral bar (within 0.2 %, no drift from
// the first period to the last).
TEST(VerificationTets, FreeVibrationConservesEnergy) {
  const auto write = [](int nx, int ny, int nz, double lx, double ly, double lz,
                        const std::string& extra) {
    return tetDeck(nx, ny, nz, lx, ly, lz, TetInput::Elform10Blank, extra);
  };
  EXPECT_LT(crumple::testing::freeBarEnergyDrift(write, "tet_vibration"), 3e-3);
}

std::string esortDeck(TetInput input, const std::string& control) {
  return tetDeck(4, 2, 2, 40.0, 10.0, 10.0, input,
                 kSteel + control + termination(0.05) + vibratingBar(4, 5.0));
}

TEST(VerificationTets, EsortRunsDegenerateHexahedraAsElform10BitForBit) {
  crumple::testing::expectSortedRunsAsNative("esort", esortDeck(TetInput::Elform10Blank, ""),
                                             {esortDeck(TetInput::Elform1Repeated, kEsort1),
                                              esortDeck(TetInput::Elform1N3EqualsN4, kEsort1)},
                                             esortDeck(TetInput::Elform1Repeated, ""));
}

TEST(VerificationTets, Esort0WarnsWithTheCountPerPart) {
  using crumple::testing::esortNote;
  const auto note = esortNote("esort_warn", esortDeck(TetInput::Elform1Repeated, ""));
  EXPECT_NE(note.find("part 1: 96 degenerate solid(s) (96 tetrahedra, 0 pentahedra, 0 "
                      "other) run as ELFORM 1 hexahedra"),
            std::string::npos)
      << note;
  EXPECT_NE(note.find("ESORT = 1 runs the tetrahedra as ELFORM 10"), std::string::npos) << note;
  // Sorted or native: nothing to say.
  EXPECT_EQ(esortNote("esort_quiet", esortDeck(TetInput::Elform10Blank, "")), "");
  EXPECT_EQ(esortNote("esort_quiet", esortDeck(TetInput::Elform1Repeated, kEsort1)), "");
}

TEST(VerificationTets, RefusesWhatItCannotRun) {
  // A hexahedron under an ELFORM 10 section.
  std::string hex = tetDeck(1, 1, 1, 1, 1, 1, TetInput::Elform10Blank, kSteel + termination(0.01));
  const auto at = hex.find("*ELEMENT_SOLID\n") + 15;
  hex = hex.substr(0, at) +
        "     100       1       1       2       4       3       5       6       8       7\n" +
        hex.substr(at);
  try {
    Simulation::fromText("hex_as_tet", hex);
    ADD_FAILURE() << "a hexahedron under ELFORM 10 was accepted";
  } catch (const crumple::util::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs 4 distinct nodes, not 8"), std::string::npos)
        << e.what();
  }
}

// The cantilever of crumple::testing::cantileverTipRatio, cells of six tetrahedra, tip load
// along z.
double cantileverTipRatio(TetInput input, const std::string& control, const char* label) {
  const auto write = [input](int nx, int ny, int nz, double lx, double ly, double lz,
                             const std::string& extra) {
    return tetDeck(nx, ny, nz, lx, ly, lz, input, extra);
  };
  return crumple::testing::cantileverTipRatio(write, control, 3, label);
}

// One-point tetrahedra are constant-strain elements: two layers through the depth cannot bend,
// so the sorted mesh is much too stiff (shear locking in bending). Written as collapsed
// one-point hexahedra under ESORT = 0 the same mesh is softer (the hourglass modes of the
// collapsed element are held only by hourglass control), and not closer to the truth for a
// sound reason. The test holds the ordering and a broad band, not an accuracy tets lack.
TEST(VerificationTets, CantileverBendingAgainstBeamTheory) {
  const double sorted = cantileverTipRatio(TetInput::Elform1Repeated, kEsort1, "tet_cant_esort1");
  const double unsorted = cantileverTipRatio(TetInput::Elform1Repeated, "", "tet_cant_esort0");
  EXPECT_GT(sorted, 0.1);
  EXPECT_LT(sorted, 0.9);
  EXPECT_GT(unsorted, sorted);
}

}  // namespace
