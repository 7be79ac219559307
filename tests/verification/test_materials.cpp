// Material laws in whole runs: one hex driven through a prescribed homogeneous deformation, its
// stress against the law's analytic answer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#include "harness.hpp"

using crumple::testing::brickDeck;
using crumple::testing::brickNodeSet;
using crumple::testing::Simulation;
using crumple::testing::termination;
using crumple::testing::triaxialCompression;
using crumple::testing::uniaxialPull;
using crumple::testing::uniaxialStrainCrush;

namespace {

// The von Mises stress of the first point of a solid block.
template <class Block>
double misesOf(const Block& blk) {
  double sig[6];
  for (int k = 0; k < 6; ++k) sig[k] = blk.sigAt(k, 0);
  const double p = (sig[0] + sig[1] + sig[2]) / 3.0;
  return std::sqrt(1.5 * ((sig[0] - p) * (sig[0] - p) + (sig[1] - p) * (sig[1] - p) +
                          (sig[2] - p) * (sig[2] - p)) +
                   3.0 * (sig[3] * sig[3] + sig[4] * sig[4] + sig[5] * sig[5]));
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

// The effective strain rate sqrt(2/3 dev(D):dev(D)) of isochoricPull at velocity v now
// (D_xx = v / L_x, D_yy = D_zz = -v / (2 L_y); nodes 1 = (0,0,0), 2 = (1,0,0), 3 = (0,1,0)).
double isochoricRate(const Simulation& sim, double v) {
  const double lx = sim.x(2, 0) - sim.x(1, 0), ly = sim.x(3, 1) - sim.x(1, 1);
  const double dx = v / lx, dy = -0.5 * v / ly, tr = (dx + 2.0 * dy) / 3.0;
  return std::sqrt(2.0 / 3.0 * ((dx - tr) * (dx - tr) + 2.0 * (dy - tr) * (dy - tr)));
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
      const double r = isochoricRate(*sim, rate);
      const double q = misesOf(blk);
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

// *MAT_NULL with *EOS_LINEAR_POLYNOMIAL (water: RO 1e-6 kg/mm^3, C1 = K = 2.2 GPa) in a column
// 100 mm long, laterally held (uniaxial strain), striking a stonewall at v0 = 10 m/s. Acoustic
// theory: the wall pressure is rho c v0 with c = sqrt(C1 / rho) while the column touches, for
// 2 L / c, and the column leaves at v0 (mu = v0 / c = 0.7%: the linear range). 3% on pressure
// and duration, 5% on the rebound, as for the elastic bar (test_impact.cpp).
TEST(VerificationMaterials, NullWaterColumnOnStonewall) {
  const double rho = 1.0e-6, K = 2.2, v0 = 10.0, L = 100.0;
  const double c = std::sqrt(K / rho), pressure = rho * c * v0, duration = 2.0 * L / c;
  std::string extra =
      "*MAT_NULL\n         1    1.0e-6\n"
      "*EOS_LINEAR_POLYNOMIAL\n         1       0.0       2.2\n\n" +
      termination(0.2) +
      "*INITIAL_VELOCITY\n         0\n       0.0       0.0     -10.0\n"
      "*RIGIDWALL_PLANAR\n         0\n"
      "       0.0       0.0       0.0       0.0       0.0       1.0\n" +
      brickNodeSet(1, 1, 1, 100, [](int, int, int) { return true; }) +
      "*BOUNDARY_SPC_SET\n         1         0         1         1         0\n";
  std::string deck = brickDeck(1, 1, 100, 1.0, 1.0, L, extra);
  const std::string part = "*PART\nbrick\n         1         1         1\n";
  ASSERT_NE(deck.find(part), std::string::npos);
  deck.replace(deck.find(part), part.size(),
               "*PART\nwater\n         1         1         1         1\n");
  auto sim = Simulation::fromText("null_water_column", deck);
  std::vector<std::pair<double, double>> force;
  sim->run([&](const auto& s) {
    force.emplace_back(s.time(), s.boundary().walls().at(0).normal_force);
  });
  const auto wall = crumple::testing::wallPlateau(force, pressure, duration);
  ASSERT_GT(wall.samples, 10);
  EXPECT_NEAR(wall.mean, pressure, 0.03 * pressure) << "wall pressure";  // area 1 mm^2
  EXPECT_NEAR(wall.duration, duration, 0.03 * duration) << "contact duration";
  double mass = 0.0;
  for (double m : sim->sd.mass) mass += m;
  EXPECT_NEAR(sim->momentum(2) / mass, v0, 0.05 * v0) << "rebound speed";
  EXPECT_NEAR(sim->solver->energies().ratio, 1.0, 0.01);
}

namespace {

// An elastic steel cube (10 mm, 2 x 2 x 2 hexes, part 1) falling at 5 m/s onto a plate of null
// shells (*MAT_NULL, part 2: 30 mm square of 1 mm quads, 0.5 mm thick, YM 210 GPa, PR 0.3)
// 1 mm below it; node-to-surface contact of the cube's nodes on the shells. `held`: the plate's
// nodes are fixed (a rigid surface covered by null shells; steel density, so the shells' own
// step would be four times shorter than the cube's), else free and heavy (RO 0.01).
std::string nullPlateDeck(bool held) {
  const double ro = held ? 7.8e-6 : 1.0e-2;
  std::string s = "*KEYWORD\n*TITLE\ncube on null shells\n" + termination(0.6) +
                  "*PART\ncube\n         1         1         1\n"
                  "*PART\nnull plate\n         2         2         2\n"
                  "*SECTION_SOLID\n         1         1\n"
                  "*SECTION_SHELL\n         2         2\n       0.5       0.5       0.5       0.5\n"
                  "*MAT_ELASTIC\n         1    7.8e-6     210.0       0.3\n" +
                  fmt::format(
                      "*MAT_NULL\n         2{:10.4g}       0.0       0.0       0.0       0.0"
                      "     210.0       0.3\n",
                      ro) +
                  "*CONTACT_NODES_TO_SURFACE\n         1         2         3         3\n"
                  "*NODE\n";
  // Cube nodes 1..27 on [0,10]^2 x [1,11]; plate nodes 1001.. on [-10,20]^2 at z = 0.
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i)
        s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", 1 + i + 3 * j + 9 * k, 5.0 * i, 5.0 * j,
                         1.0 + 5.0 * k);
  for (int j = 0; j <= 30; ++j)
    for (int i = 0; i <= 30; ++i)
      s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", 1001 + i + 31 * j, -10.0 + i, -10.0 + j,
                       0.0);
  s += "*ELEMENT_SOLID\n";
  int e = 1;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        auto n = [&](int a, int b, int c) { return 1 + (i + a) + 3 * (j + b) + 9 * (k + c); };
        s += fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", e++, 1, n(0, 0, 0),
                         n(1, 0, 0), n(1, 1, 0), n(0, 1, 0), n(0, 0, 1), n(1, 0, 1), n(1, 1, 1),
                         n(0, 1, 1));
      }
  s += "*ELEMENT_SHELL\n";
  for (int j = 0; j < 30; ++j)
    for (int i = 0; i < 30; ++i) {
      const int n = 1001 + i + 31 * j;
      s += fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", 100 + i + 30 * j, 2, n, n + 1, n + 32,
                       n + 31);
    }
  s += "*INITIAL_VELOCITY_NODE\n";
  for (int n = 1; n <= 27; ++n) s += fmt::format("{:10d}       0.0       0.0      -5.0\n", n);
  if (held) {
    s += "*SET_NODE_LIST_GENERATE\n         1\n      1001      1961\n";
    s += "*BOUNDARY_SPC_SET\n         1         0         1         1         1\n";
  }
  return s + "*END\n";
}

double cubeMomentumZ(const Simulation& sim) {
  double p = 0.0;
  for (int64_t n = 1; n <= 27; ++n) p += sim.sd.mass[sim.local(n)] * sim.v(n, 2);
  return p;
}

}  // namespace

// Null shells carry contact and nothing else (LS-DYNA bypasses them in the element
// processing): on a held plate the cube rebounds as from a rigid surface; on a free plate the
// shells push back only through their nodes' inertia, the plate's far nodes never move and
// momentum is conserved; they never store energy and never set the time step, though their
// own (1 mm quads of YM 210 GPa) would be five times shorter than the cube's.
TEST(VerificationMaterials, NullShellsCarryContactOnly) {
  auto held = Simulation::fromText("null_plate_held", nullPlateDeck(true));
  EXPECT_EQ(held->solver->initialDtElement().find("shell"), std::string::npos)
      << held->solver->initialDtElement();
  const double p0 = cubeMomentumZ(*held);
  held->run();
  EXPECT_GT(cubeMomentumZ(*held), -0.8 * p0) << "rebound from the held null shells";
  const auto& shells = held->sd.shell_blocks.at(0);
  for (std::size_t e = 0; e < shells.size(); ++e) {
    EXPECT_EQ(shells.e_int[e], 0.0);
    EXPECT_EQ(shells.sigAt(0, 0, e), 0.0);
  }

  auto free = Simulation::fromText("null_plate_free", nullPlateDeck(false));
  const double total0 = free->momentum(2);
  free->run();
  const double cube = cubeMomentumZ(*free);
  // The heavy nodes under it throw the cube back (p0 < 0): about 2/3 of its momentum.
  EXPECT_GT(cube, -0.4 * p0) << "the contact did not turn the cube";
  EXPECT_NEAR(free->momentum(2), total0, 1e-9 * std::abs(total0));
  EXPECT_EQ(free->v(1001, 2), 0.0);  // plate corner, far from the cube
  EXPECT_EQ(free->x(1001, 2), 0.0);
  EXPECT_LT(free->v(1001 + 15 + 31 * 15, 2), 0.0);  // under the cube's centre: pushed down
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
  s += uniaxialStrainCrush();
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

namespace {

// *MAT_JOHNSON_COOK (mm, s, t, MPa): A, B, N, C, M, TM, TR of 4340 steel (Johnson & Cook 1983,
// table 1), CP 4.77e8 mm^2/(s^2 K); a fracture locus scaled down (D1 0.01, D2 0.1, D3 -2.12,
// D4 0.002, D5 0.61) so that the hex fails within the 10 % pull; SPALL 1 with a remote PC.
// Pressure from *EOS_LINEAR_POLYNOMIAL, C1 = K = 160 GPa.
const std::string kJohnsonCook =
    "*MAT_JOHNSON_COOK\n1,7.83e-9,80000.0\n792.0,510.0,0.26,0.014,1.03,1793.0,294.0,1.0\n"
    "4.77e8,-1.0e9,1.0,0,0.01,0.1,-2.12,0.002\n0.61\n"
    "*EOS_LINEAR_POLYNOMIAL\n1,0.0,160000.0\n";

// The Johnson-Cook flow stress and fracture strain (Johnson & Cook 1983 eq. 1, 1985 eq. 2)
// written out for the constants above, at rate r (EPSO 1 /s) and temperature rise dT.
double jcFlow(double e, double r, double dT) {
  return (792.0 + 510.0 * std::pow(e, 0.26)) * (1.0 + 0.014 * std::log(std::max(r, 1.0))) *
         (1.0 - std::pow(dT / (1793.0 - 294.0), 1.03));
}
double jcFracture(double triax, double r, double dT) {
  return (0.01 + 0.1 * std::exp(-2.12 * triax)) * (1.0 + 0.002 * std::log(std::max(r, 1.0))) *
         (1.0 + 0.61 * dT / (1793.0 - 294.0));
}

}  // namespace

// *MAT_JOHNSON_COOK in a whole run: a hex pulled at 1000 /s in uniaxial stress (uniaxialPull)
// to failure. Each cycle its von Mises stress is the flow stress at its plastic
// strain, strain rate and the temperature of the cycle's start; the damage summed here from
// the written-out fracture strain at the element's triaxiality reaches 1 in the cycle the
// element erodes, at a plastic strain within 1 % of eps_f at sigma* = 1/3.
TEST(VerificationMaterials, JohnsonCookPullToFailure) {
  const double rate = 1000.0;
  std::string deck = uniaxialPull(kJohnsonCook, rate);
  const std::string part = "*PART\nbrick\n         1         1         1\n";
  ASSERT_NE(deck.find(part), std::string::npos);
  deck.replace(deck.find(part), part.size(), "*PART\nsteel\n1,1,1,1\n");
  auto sim = Simulation::fromText("jc_pull", deck);
  using Block = std::decay_t<decltype(sim->sd.solid_blocks.at(0))>;
  double damage = 0.0, eps_prev = 0.0, dT_prev = 0.0, worst = 0.0, eps_fail = -1.0;
  double damage_at_fail = 0.0, dT_fail = 0.0;
  int plastic = 0;
  auto each = [&] {
    const auto& blk = sim->sd.solid_blocks.at(0);
    // The effective strain rate from the nodes' velocities (nodes 1 = (0,0,0), 2 = (1,0,0),
    // 3 = (0,1,0), 5 = (0,0,1)); y and z contract alike.
    const double lx = sim->x(2, 0) - sim->x(1, 0), ly = sim->x(3, 1) - sim->x(1, 1);
    const double lz = sim->x(5, 2) - sim->x(1, 2);
    const double dx = (sim->v(2, 0) - sim->v(1, 0)) / lx, dy = (sim->v(3, 1) - sim->v(1, 1)) / ly;
    const double dz = (sim->v(5, 2) - sim->v(1, 2)) / lz, tr = (dx + dy + dz) / 3.0;
    const double r = std::sqrt(
        2.0 / 3.0 * ((dx - tr) * (dx - tr) + (dy - tr) * (dy - tr) + (dz - tr) * (dz - tr)));
    if (!blk.active.at(0)) {
      eps_fail = eps_prev;
      damage_at_fail = damage;
      dT_fail = dT_prev;
      return;
    }
    const double eps_p = blk.eps_p.at(0);
    const double dT =
        blk.hist.at(Block::blocked(blk.history, crumple::materials::JohnsonCook::kHeat, 0));
    double sig[6];
    for (int k = 0; k < 6; ++k) sig[k] = blk.sigAt(k, 0);
    const double m = (sig[0] + sig[1] + sig[2]) / 3.0;
    const double q = std::sqrt(1.5 * ((sig[0] - m) * (sig[0] - m) + (sig[1] - m) * (sig[1] - m) +
                                      (sig[2] - m) * (sig[2] - m)) +
                               3.0 * (sig[3] * sig[3] + sig[4] * sig[4] + sig[5] * sig[5]));
    if (eps_p > eps_prev) {
      // Past the first 0.5 % of plastic strain: at yield the lateral faces ring, and the rate
      // read from the velocities after the cycle differs from the kernel's mid-step one.
      const double expected = jcFlow(eps_p, r, dT_prev);
      if (eps_p > 0.005) worst = std::max(worst, std::abs(q - expected) / expected);
      damage += (eps_p - eps_prev) / jcFracture(m / q, r, dT_prev);
      EXPECT_NEAR(
          blk.hist.at(Block::blocked(blk.history, crumple::materials::JohnsonCook::kDamage, 0)),
          damage, 1e-5);
      ++plastic;
    }
    eps_prev = eps_p;
    dT_prev = dT;
  };
  // Cycles up to the erosion (after it nothing of the element is left to check).
  while (!sim->solver->finished() && eps_fail < 0.0) {
    sim->solver->step();
    each();
  }
  EXPECT_GT(plastic, 100);
  // The rate read here from the velocities after the cycle is within ~1 % of the kernel's
  // mid-step one (the lateral faces still ring a little): 1.4e-4 on the rate factor. Leaving
  // out the rate factor (9.7 %) or the heating (1 - T*^M, ~1.6 % at 27 K) fails this.
  EXPECT_LT(worst, 2e-4);
  ASSERT_GE(eps_fail, 0.0) << "the hex did not erode";
  // The erosion cycle is the one whose plastic increment took D past 1.
  EXPECT_LT(damage_at_fail, 1.0);
  const double ef = jcFracture(1.0 / 3.0, rate, dT_fail);  // 0.0593 x 1.0138 x (1 + 0.61 T*)
  EXPECT_NEAR(eps_fail, ef, 0.01 * ef);                    // measured 0.06035 against 0.06057
  RecordProperty("erosion_plastic_strain", fmt::format("{:.4g} (formula {:.4g})", eps_fail, ef));
  RecordProperty("worst_flow_stress_error", fmt::format("{:.3g}", worst));
}

// SPALL = 2 in a whole run: the hex of uniaxialPull (4340 steel as above, no damage, PC = -500
// MPa) stretched at 100 /s. Elastic in uniaxial stress, its axial stress is E eps (E = 9 K G
// / (3 K + G) = 205714 MPa), the largest principal stress; it spalls in the cycle in which that
// stress first exceeds -PC = 500 MPa, at eps = 500 / E = 2.43e-3 (before yield at 792 MPa), and
// carries no stress at all for the rest of the pull, while its faces keep moving apart.
// Measured: 499.89 MPa in the last cycle before the spall (a cycle adds 2.5 MPa), the spall at
// eps = 2.456e-3, 1.0 % past 500 / E (the hex's elastic slope is 0.6 % below E: the EOS is
// p = K (V0/V - 1), the strain engineering, the lateral faces ring a little).
TEST(VerificationMaterials, JohnsonCookMaxPrincipalStressSpall) {
  const std::string spall =
      "*MAT_JOHNSON_COOK\n1,7.83e-9,80000.0\n792.0,510.0,0.26,0.014,1.03,1793.0,294.0,1.0\n"
      "4.77e8,-500.0,2.0\n*EOS_LINEAR_POLYNOMIAL\n1,0.0,160000.0\n";
  std::string deck = uniaxialPull(spall, 100.0, 0.01);
  const std::string part = "*PART\nbrick\n         1         1         1\n";
  ASSERT_NE(deck.find(part), std::string::npos);
  deck.replace(deck.find(part), part.size(), "*PART\nsteel\n1,1,1,1\n");
  auto sim = Simulation::fromText("jc_spall", deck);
  using Block = std::decay_t<decltype(sim->sd.solid_blocks.at(0))>;
  const double E = 9.0 * 160000.0 * 80000.0 / (3.0 * 160000.0 + 80000.0);
  double last_stress = 0.0, strain_at_spall = -1.0;
  int after = 0;
  while (!sim->solver->finished()) {
    sim->solver->step();
    const auto& blk = sim->sd.solid_blocks.at(0);
    const double flag =
        blk.hist.at(Block::blocked(blk.history, crumple::materials::JohnsonCook::kSpall, 0));
    if (flag == 0.0) {
      last_stress = blk.sigAt(0, 0);
      EXPECT_LE(last_stress, 500.0);
      continue;
    }
    if (strain_at_spall < 0.0) strain_at_spall = sim->x(2, 0) - sim->x(1, 0) - 1.0;
    for (int k = 0; k < 6; ++k) EXPECT_EQ(blk.sigAt(k, 0), 0.0);
    ++after;
  }
  ASSERT_GT(strain_at_spall, 0.0) << "the hex did not spall";
  EXPECT_GT(after, 100);          // cycles after the spall, to 1 % strain
  EXPECT_GT(last_stress, 495.0);  // within two cycles' rise of 500 MPa
  EXPECT_NEAR(strain_at_spall, 500.0 / E, 0.02 * 500.0 / E);
  EXPECT_GT(sim->x(2, 0) - sim->x(1, 0) - 1.0, 0.009);
  RecordProperty("spall_strain",
                 fmt::format("{:.5g} (500 / E = {:.5g})", strain_at_spall, 500.0 / E));
}

namespace {

// *MAT_POWER_LAW_PLASTICITY (mm, s, t, MPa): E 210 GPa, PR 0.3, k 500 MPa, n 0.2, Cowper-Symonds
// SRC 40 /s, SRP 5; SIGY 0, so eps_yp = (E / k)^(1 / (n - 1)) (Keyword Manual, *MAT_018).
const std::string kPowerLaw = "*MAT_POWER_LAW_PLASTICITY\n1,7.85e-9,210000,0.3,500,0.2,40,5\n";

double powerFlow(double e, double rate) {
  return (1.0 + std::pow(rate / 40.0, 0.2)) * 500.0 * std::pow(std::pow(420.0, -1.25) + e, 0.2);
}

}  // namespace

// *MAT_018 in a whole run: the hex of isochoricPull stretched at 100 /s to 10 % strain. Once
// plastic, its von Mises stress is the power law times the Cowper-Symonds factor at its
// plastic strain and the effective strain rate of the prescribed motion (without the factor it
// would be 2.2 times lower), and the internal energy is the work of that stress: the elastic
// energy plus the plastic work integrated here from the element's own history.
TEST(VerificationMaterials, PowerLawPullAtRate) {
  const double rate = 100.0;
  auto sim = Simulation::fromText("power_law_pull", isochoricPull(kPowerLaw, rate));
  double worst = 0.0, eps_prev = 0.0, q_prev = 0.0, plastic_work = 0.0;
  int checked = 0;
  sim->run([&](const auto&) {
    const auto& blk = sim->sd.solid_blocks.at(0);
    const double eps_p = blk.eps_p.at(0);
    const double q = misesOf(blk);
    if (eps_p > eps_prev) plastic_work += 0.5 * (q + q_prev) * (eps_p - eps_prev);
    eps_prev = eps_p;
    q_prev = q;
    if (eps_p < 1e-3) return;
    const double r = isochoricRate(*sim, rate);
    worst = std::max(worst, std::abs(q - powerFlow(eps_p, r)) / q);
    ++checked;
  });
  EXPECT_GT(checked, 100);
  EXPECT_GT(eps_prev, 0.08);
  EXPECT_LT(worst, 1e-3);
  // Energy: internal = plastic work + elastic energy of the current volume.
  const auto& blk = sim->sd.solid_blocks.at(0);
  double sig[6];
  for (int k = 0; k < 6; ++k) sig[k] = blk.sigAt(k, 0);
  const double vol =
      (sim->x(2, 0) - sim->x(1, 0)) * (sim->x(3, 1) - sim->x(1, 1)) * (sim->x(5, 2) - sim->x(1, 2));
  // Elastic energy q^2 / (6 G) + p^2 / (2 K), G = 80769, K = 175000.
  const double pm = (sig[0] + sig[1] + sig[2]) / 3.0;
  const double elastic = q_prev * q_prev / (6.0 * 80769.23) + pm * pm / (2.0 * 175000.0);
  const double e = sim->solver->energies().internal;
  EXPECT_NEAR(e, (plastic_work + elastic) * vol, 0.01 * e);  // measured 0.4 %
  EXPECT_NEAR(sim->solver->energies().ratio, 1.0, 0.01);
  RecordProperty("worst_flow_stress_error", fmt::format("{:.3g}", worst));
  RecordProperty("internal_over_plastic_work",
                 fmt::format("{:.4g}", e / ((plastic_work + elastic) * vol)));
}

// *MAT_019 in a whole run: the hex of isochoricPull stretched at 40 /s and at 400 /s (beyond
// the last point of LC1: its end slope) to 10 %
// strain, LC1 (mm s t MPa) 200, 250, 400 MPa at 0, 10, 100 /s, ETAN 2 GPa. Once plastic, its
// von Mises stress is sigma_0(rate) + Ep eps_p at the effective strain rate of the motion.
TEST(VerificationMaterials, StrainRatePlasticityPullAtTwoRates) {
  const std::string mat =
      "*MAT_STRAIN_RATE_DEPENDENT_PLASTICITY\n1,7.85e-9,200000,0.3\n7,2000\n"
      "*DEFINE_CURVE\n7\n0,200\n10,250\n100,400\n";
  auto sigma0 = [](double r) {
    return r < 10.0 ? 200.0 + 5.0 * r : 250.0 + 150.0 / 90.0 * (r - 10.0);
  };
  const double Ep = 200000.0 * 2000.0 / 198000.0;
  for (const double rate : {40.0, 400.0}) {
    auto sim = Simulation::fromText("mat019_pull", isochoricPull(mat, rate));
    double worst = 0.0, last = 0.0;
    int checked = 0;
    sim->run([&](const auto&) {
      const auto& blk = sim->sd.solid_blocks.at(0);
      const double eps_p = blk.eps_p.at(0);
      if (eps_p < 1e-3) return;
      const double r = isochoricRate(*sim, rate);
      const double q = misesOf(blk);
      worst = std::max(worst, std::abs(q - (sigma0(r) + Ep * eps_p)) / q);
      last = eps_p;
      ++checked;
    });
    EXPECT_GT(checked, 100) << rate;
    EXPECT_GT(last, 0.08) << rate;
    // Reading sigma_0 at the static rate instead is 60 % (40 /s) and 4.5 times (400 /s) off.
    EXPECT_LT(worst, 1e-3) << rate;
    RecordProperty(rate < 100.0 ? "worst_error_40_per_s" : "worst_error_400_per_s",
                   fmt::format("{:.3g}", worst));
  }
}

// *MAT_VISCOELASTIC in a whole run: a unit hex in uniaxial strain (as above) squeezed at a
// constant rate to a = 1e-3 over t1 = 0.01, then held. Theory Manual, material model 6, for a
// strain eps(t) = ln(1 - a) growing at the rate r until t1: the pressure stays K eps, and the
// axial less the lateral stress, twice the shear part of the hereditary integral, is
//   2 GI eps + 2 (G0 - GI) r (1 - exp(-BETA min(t, t1))) / BETA exp(-BETA max(t - t1, 0)),
// relaxing after the hold to 2 GI eps1. Checked through the hex's stress (rotation and the
// relaxing stress kept in its back-stress slots) within 1% of the deviator at its peak.
TEST(VerificationMaterials, ViscoelasticRelaxesInUniaxialStrain) {
  const double K = 2000.0, G0 = 10.0, Gi = 2.0, beta = 10.0, t1 = 0.01, a1 = 1e-3;
  const std::string mat = fmt::format(
      "*MAT_VISCOELASTIC\n         1    1.0e-6{:10.4g}{:10.4g}{:10.4g}{:10.4g}\n"
      "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n"
      "{:20.12g}{:20.12g}\n                 1.0{:20.12g}\n",
      K, G0, Gi, beta, t1, a1, a1);
  auto sim = Simulation::fromText(
      "visco_relax",
      brickDeck(1, 1, 1, 1.0, 1.0, 1.0, mat + termination(0.3) + uniaxialStrainCrush()));
  const double eps1 = std::log(1.0 - a1), rate = eps1 / t1;
  auto deviator = [&](double t) {
    const double eps = t < t1 ? rate * t : eps1;
    const double relaxing =
        -std::expm1(-beta * std::min(t, t1)) / beta * std::exp(-beta * std::max(t - t1, 0.0));
    return 2.0 * Gi * eps + 2.0 * (G0 - Gi) * rate * relaxing;
  };
  const double peak = std::abs(deviator(t1));
  double worst = 0.0, worst_p = 0.0, t_prev = 0.0;
  int checked = 0;
  sim->run([&](const auto& s) {
    // The stress of the step was computed at the positions before it (t_prev).
    const auto& blk = sim->sd.solid_blocks.at(0);
    const double sxx = blk.sigAt(0, 0), syy = blk.sigAt(1, 0), szz = blk.sigAt(2, 0);
    worst = std::max(worst, std::abs(sxx - syy - deviator(t_prev)));
    const double a = sim->x0(8, 0) - sim->x(8, 0);
    worst_p = std::max(worst_p, std::abs((sxx + syy + szz) / 3.0 - K * std::log(1.0 - a)));
    t_prev = s.time();
    ++checked;
  });
  EXPECT_GT(checked, 1000);
  EXPECT_LT(worst, 0.01 * peak);
  EXPECT_LT(worst_p, 0.01 * K * std::abs(eps1));
  RecordProperty("worst_deviator_error_over_peak", std::to_string(worst / peak));
}

// *MAT_SPOTWELD on a hexahedral weld (mm, s, t, MPa): the hex of isochoricPull stretched at
// 100 /s. Once plastic, its von Mises stress is SIGY + EH eps_p (linear isotropic hardening, no
// rate effect), and the element is deleted in the cycle its effective plastic strain reaches
// EFAIL = 0.05 (Keyword Manual, *MAT_SPOTWELD: "effective plastic strain in weld material at
// failure"); a weld without EFAIL stays.
TEST(VerificationMaterials, SpotweldHexYieldsAndFailsAtEfail) {
  auto pull = [](const std::string& card2, double& worst, double& eps_at_deletion) {
    const std::string mat = "*MAT_SPOTWELD\n1,7.85e-9,210000,0.3,300,1000\n" + card2;
    auto sim = Simulation::fromText("spotweld_hex_pull", isochoricPull(mat, 100.0));
    bool deleted = false;
    sim->run([&](const auto&) {
      const auto& blk = sim->sd.solid_blocks.at(0);
      if (deleted) return;
      if (!blk.active.at(0)) {
        deleted = true;
        eps_at_deletion = blk.eps_p.at(0);
        return;
      }
      const double eps_p = blk.eps_p.at(0);
      if (eps_p > 1e-3)
        worst = std::max(worst, std::abs(misesOf(blk) - (300.0 + 1000.0 * eps_p)) / 300.0);
    });
    return deleted;
  };
  double worst = 0.0, eps_at_deletion = 0.0;
  EXPECT_TRUE(pull("0.05\n", worst, eps_at_deletion));
  EXPECT_LT(worst, 1e-3);
  EXPECT_GE(eps_at_deletion, 0.05);
  EXPECT_LT(eps_at_deletion, 0.0505);
  RecordProperty("worst_flow_stress_error", fmt::format("{:.3g}", worst));
  RecordProperty("plastic_strain_at_deletion", fmt::format("{:.5g}", eps_at_deletion));
  double worst_kept = 0.0, unused = 0.0;
  EXPECT_FALSE(pull("\n", worst_kept, unused));
  EXPECT_LT(worst_kept, 1e-3);
}
