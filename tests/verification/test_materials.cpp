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

namespace {

// A unit cube stretched along x at the constant velocity v and narrowed along y and z at v / 2
// (its faces x = 1, y = 1, z = 1 prescribed, x = 0, y = 0, z = 0 on rollers) to 10 % strain:
// every degree of freedom is prescribed, so the deformation is homogeneous and known, with no
// inertia, and nearly isochoric, as plastic flow is.
std::string isochoricPull(const std::string& material, double v) {
  const double t_end = 0.1 / v;
  std::string s = material + termination(t_end);
  for (int d = 0; d < 3; ++d) {
    const double vd = d == 0 ? v : -0.5 * v;
    s += fmt::format("*DEFINE_CURVE\n{:10d}\n{:20.12g}{:20.12g}\n{:20.12g}{:20.12g}\n", 90 + d, 0.0,
                     vd, 2.0 * t_end, vd);
    s += brickNodeSet(1 + d, 1, 1, 1, [d](int i, int j, int k) {
      return (d == 0 ? i : d == 1 ? j : k) == 1;
    });
    s += fmt::format("*BOUNDARY_PRESCRIBED_MOTION_SET\n{:10d}{:10d}{:10d}{:10d}{:10.1f}\n", 1 + d,
                     d + 1, 0, 90 + d, 1.0);
    s += brickNodeSet(4 + d, 1, 1, 1, [d](int i, int j, int k) {
      return (d == 0 ? i : d == 1 ? j : k) == 0;
    });
    s += fmt::format("*BOUNDARY_SPC_SET\n{:10d}{:10d}{:10d}{:10d}{:10d}\n", 4 + d, 0,
                     d == 0 ? 1 : 0, d == 1 ? 1 : 0, d == 2 ? 1 : 0);
  }
  return brickDeck(1, 1, 1, 1.0, 1.0, 1.0, s);
}

// *MAT_024 (mm, s, t, MPa) with LCSS naming a *DEFINE_TABLE of three yield curves at 1, 10 and
// 100 /s, each curve following the table.
const std::string kRateTable024 =
    "*MAT_024\n1,2e-5,70000,0.33\n0,0,5\n"
    "*DEFINE_TABLE\n5\n1.0\n10.0\n100.0\n"
    "*DEFINE_CURVE\n101\n0,200\n0.05,300\n0.2,360\n"
    "*DEFINE_CURVE\n102\n0,250\n0.1,400\n"
    "*DEFINE_CURVE\n103\n0,320\n0.02,380\n0.3,500\n";

// The table's curves written out (extrapolated with their last slopes).
double curve1(double e) {
  return e < 0.05 ? 200.0 + 2000.0 * e : 300.0 + 400.0 * (e - 0.05);
}
double curve10(double e) {
  return 250.0 + 1500.0 * e;
}
double curve100(double e) {
  return e < 0.02 ? 320.0 + 3000.0 * e : 380.0 + 120.0 / 0.28 * (e - 0.02);
}

// The table's yield stress at plastic strain e and strain rate r: linear in r between the
// neighbouring rates' curves (Keyword Manual vol. II, *MAT_024 LCSS).
double tableYield(double e, double r) {
  if (r <= 1.0) return curve1(e);
  if (r >= 100.0) return curve100(e);
  return r < 10.0 ? curve1(e) + (r - 1.0) / 9.0 * (curve10(e) - curve1(e))
                  : curve10(e) + (r - 10.0) / 90.0 * (curve100(e) - curve10(e));
}

}  // namespace

// *MAT_024 with a rate table in whole runs: a hex stretched at 3 /s (between the 1 and 10 /s
// curves) and at 40 /s (between 10 and 100 /s) to 10 % strain. Once plastic, its von Mises
// stress is the table's yield stress at its effective strain rate, sqrt(2/3 dev(D):dev(D)) of
// the prescribed motion (D_xx = v / L_x, D_yy = D_zz = -v / (2 L_y)), and its plastic strain.
TEST(VerificationMaterials, RateTablePullAtTwoRates) {
  for (const double rate : {3.0, 40.0}) {
    auto sim = Simulation::fromText("rate_table_pull", isochoricPull(kRateTable024, rate));
    double worst = 0.0, last_eps_p = 0.0;
    int checked = 0;
    sim->run([&](const auto&) {
      const auto& blk = sim->sd.solid_blocks.at(0);
      const double eps_p = blk.eps_p.at(0);
      if (eps_p < 1e-3) return;
      // Nodes 2 = (1,0,0), 3 = (0,1,0), 1 = (0,0,0); v = rate (L0 = 1).
      const double lx = sim->x(2, 0) - sim->x(1, 0), ly = sim->x(3, 1) - sim->x(1, 1);
      const double dx = rate / lx, dy = -0.5 * rate / ly, tr = (dx + 2.0 * dy) / 3.0;
      const double r = std::sqrt(2.0 / 3.0 * ((dx - tr) * (dx - tr) + 2.0 * (dy - tr) * (dy - tr)));
      double sig[6];
      for (int k = 0; k < 6; ++k) sig[k] = blk.sigAt(k, 0);
      const double p = (sig[0] + sig[1] + sig[2]) / 3.0;
      const double q = std::sqrt(1.5 * ((sig[0] - p) * (sig[0] - p) + (sig[1] - p) * (sig[1] - p) +
                                        (sig[2] - p) * (sig[2] - p)) +
                                 3.0 * (sig[3] * sig[3] + sig[4] * sig[4] + sig[5] * sig[5]));
      const double expected = tableYield(eps_p, r);
      worst = std::max(worst, std::abs(q - expected) / expected);
      last_eps_p = eps_p;
      ++checked;
    });
    EXPECT_GT(checked, 100) << rate;
    EXPECT_GT(last_eps_p, 0.08) << rate;
    EXPECT_LT(worst, 1e-3) << rate;
    // The check tells the interpolated curve from the neighbouring rates' curves: they lie
    // more than the tolerance away from it at the end.
    const double y = tableYield(last_eps_p, rate / 1.1);
    const double below = rate < 10.0 ? curve1(last_eps_p) : curve10(last_eps_p);
    const double above = rate < 10.0 ? curve10(last_eps_p) : curve100(last_eps_p);
    EXPECT_GT(std::min(y - below, above - y), 0.015 * y) << rate;
    RecordProperty(rate < 10.0 ? "worst_error_3_per_s" : "worst_error_40_per_s",
                   fmt::format("{:.3g}", worst));
  }
}
