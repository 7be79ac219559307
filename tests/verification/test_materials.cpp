// Material laws in whole runs: one hex driven through a prescribed homogeneous deformation, its
// stress against the law's analytic answer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "harness.hpp"

using crumple::testing::brickDeck;
using crumple::testing::brickNodeSet;
using crumple::testing::Simulation;
using crumple::testing::termination;

namespace {

// A unit cube whose faces x = 1, y = 1, z = 1 move by -a(t) along their normals (a from curve
// 1) and whose faces x = 0, y = 0, z = 0 are held: V/V0 = (1 - a)^3, no shear.
std::string triaxialCompression(const std::string& material, double t_end) {
  std::string s = material + termination(t_end);
  for (int d = 0; d < 3; ++d) {
    s += brickNodeSet(1 + d, 1, 1, 1, [d](int i, int j, int k) {
      return (d == 0 ? i : d == 1 ? j : k) == 1;
    });
    s += brickNodeSet(4 + d, 1, 1, 1, [d](int i, int j, int k) {
      return (d == 0 ? i : d == 1 ? j : k) == 0;
    });
    s += fmt::format("*BOUNDARY_PRESCRIBED_MOTION_SET\n{:10d}{:10d}{:10d}{:10d}{:10.1f}\n", 1 + d,
                     d + 1, 2, 1, -1.0);
    const int dof = d + 1;
    s += fmt::format("*BOUNDARY_SPC_SET\n{:10d}{:10d}{:10d}{:10d}{:10d}\n", 4 + d, 0,
                     dof == 1 ? 1 : 0, dof == 2 ? 1 : 0, dof == 3 ? 1 : 0);
  }
  return brickDeck(1, 1, 1, 1.0, 1.0, 1.0, s);
}

}  // namespace

// *MAT_SOIL_AND_FOAM in a whole run: the pressure of a hex squeezed to x = -ln(V/V0) = 0.15,
// released to 0.13 (past the cutoff) and squeezed again to 0.2 follows the curve, the unloading
// line of slope KUN and the cutoff PC (the material-point answers of test_soil_foam.cpp).
TEST(VerificationMaterials, SoilAndFoamHydrostaticCycle) {
  // Displacement a(t) of the moving faces at the turning points: a = 1 - exp(-x / 3).
  const std::vector<std::pair<double, double>> turns = {
      {0.0, 0.0}, {0.25, 0.15}, {0.3, 0.13}, {0.35, 0.15}, {0.5, 0.20}};
  std::string curve = "*DEFINE_CURVE\n         1\n";
  for (const auto& [t, x] : turns)
    curve += fmt::format("{:20.12g}{:20.12g}\n", t, 1.0 - std::exp(-x / 3.0));
  const std::string soil =
      "*MAT_SOIL_AND_FOAM\n"
      "         1     0.001    1000.0    1000.0       1.0       0.4      0.02      -2.0\n"
      "       0.0       0.0\n"
      "       0.0     -0.05      -0.1      -0.2\n\n"
      "       0.0       5.0       7.0      15.0\n\n" +
      curve;
  auto sim = Simulation::fromText("soil_cycle", triaxialCompression(soil, 0.5));
  // x(t) from the prescribed faces, the expected pressure on the cycle's branches.
  auto expected = [](double x, double x_max) {
    auto P = [](double v) {
      return v < 0.05 ? 100.0 * v : v < 0.1 ? 5.0 + 40.0 * (v - 0.05) : 7.0 + 80.0 * (v - 0.1);
    };
    return x >= x_max ? P(x) : std::max(P(x_max) - 1000.0 * (x_max - x), -2.0);
  };
  double x_max = 0.0, x_prev = 0.0, worst = 0.0;
  int checked = 0;
  sim->run([&](const auto&) {
    const double a = sim->x0(8, 0) - sim->x(8, 0);  // node 8 = (1, 1, 1)
    const double x = -3.0 * std::log(1.0 - a);
    x_max = std::max(x_max, x);
    const auto& blk = sim->sd.solid_blocks.at(0);
    const double p = -(blk.sigAt(0, 0) + blk.sigAt(1, 0) + blk.sigAt(2, 0)) / 3.0;
    // The hex integrates ln V from its midpoint strain rate, so the stress may lag the node
    // positions by up to one step: measured in units of the stiffest slope (KUN) times the
    // step's strain increment.
    const double step = 1000.0 * std::abs(x - x_prev);
    worst = std::max(worst, std::abs(p - expected(x, x_max)) / (step + 1e-3));
    x_prev = x;
    ++checked;
  });
  EXPECT_GT(checked, 200);
  EXPECT_LT(worst, 1.0);
  const auto& blk = sim->sd.solid_blocks.at(0);
  EXPECT_NEAR(-blk.sigAt(0, 0), 15.0, 0.05);
  EXPECT_NEAR(blk.sigAt(3, 0), 0.0, 1e-12);
}

// *MAT_CRUSHABLE_FOAM in a whole run: a unit hex crushed in uniaxial strain (face x = 1 driven
// by -a(t), face x = 0 held in x, the lateral faces held in their normal directions), so that
// gamma = 1 - V/V0 = a. With PR = 0 the axial stress alone carries the load: -Y(a) while a
// passes its largest value a_max (elastic at first, with the curve's last slope Ee = 120 as
// Young's modulus), elastic from -Y(a_max) on unloading and reloading (the answers of
// test_crushable_foam.cpp at a point).
TEST(VerificationMaterials, CrushableFoamUniaxialStrainCrush) {
  const std::vector<std::pair<double, double>> turns = {
      {0.0, 0.0}, {0.3, 0.7}, {0.4, 0.64}, {0.5, 0.75}};
  std::string curve = "*DEFINE_CURVE\n         1\n";
  for (const auto& [t, a] : turns) curve += fmt::format("{:20.12g}{:20.12g}\n", t, a);
  const std::string foam =
      "*MAT_CRUSHABLE_FOAM\n"
      "         1     0.001     123.0       0.0         2       1.0\n"
      "*DEFINE_CURVE\n         2\n"
      "                 0.0                 2.0\n                 0.2                 3.0\n"
      "                 0.5                 4.0\n                 0.8                40.0\n" +
      curve + termination(0.5);
  std::string s = foam;
  s += brickNodeSet(1, 1, 1, 1, [](int i, int, int) { return i == 1; });
  s += "*BOUNDARY_PRESCRIBED_MOTION_SET\n         1         1         2         1      -1.0\n";
  for (int d = 0; d < 3; ++d) {
    s += brickNodeSet(2 + d, 1, 1, 1, [d](int i, int j, int k) {
      const int c = d == 0 ? i : d == 1 ? j : k;
      return c == 0 || (d > 0 && c == 1);
    });
    s += fmt::format("*BOUNDARY_SPC_SET\n{:10d}{:10d}{:10d}{:10d}{:10d}\n", 2 + d, 0, int(d == 0),
                     int(d == 1), int(d == 2));
  }
  auto sim = Simulation::fromText("foam_crush", brickDeck(1, 1, 1, 1.0, 1.0, 1.0, s));
  auto yield = [](double g) {
    return g < 0.2 ? 2.0 + 5.0 * g : g < 0.5 ? 3.0 + (g - 0.2) / 0.3 : 4.0 + 120.0 * (g - 0.5);
  };
  auto expected = [&](double a, double a_max) {
    if (a >= a_max) return std::max(120.0 * std::log(1.0 - a), -yield(a));
    return -yield(a_max) + 120.0 * std::log((1.0 - a) / (1.0 - a_max));
  };
  // The callback sees the nodes after the step's position update and the stress of the step,
  // computed on the positions before it: the stress is checked against those (a, a_max).
  double a = 0.0, a_max = 0.0, worst = 0.0, lateral = 0.0;
  int checked = 0;
  sim->run([&](const auto&) {
    const auto& blk = sim->sd.solid_blocks.at(0);
    worst = std::max(worst, std::abs(blk.sigAt(0, 0) - expected(a, a_max)));
    lateral = std::max(
        {lateral, std::abs(blk.sigAt(1, 0)), std::abs(blk.sigAt(2, 0)), std::abs(blk.sigAt(3, 0))});
    a = sim->x0(8, 0) - sim->x(8, 0);  // node 8 = (1, 1, 1)
    a_max = std::max(a_max, a);
    ++checked;
  });
  EXPECT_GT(checked, 200);
  // What is left is the hex's midpoint integration of ln V (2.5e-4 here; the stress reaches 34).
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(lateral, 1e-9);
  EXPECT_NEAR(a_max, 0.75, 1e-6);
}
