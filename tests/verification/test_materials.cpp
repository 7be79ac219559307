// Material laws in whole runs: one hex driven through a prescribed homogeneous deformation, its
// stress against the law's analytic answer.
#include <gtest/gtest.h>

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
