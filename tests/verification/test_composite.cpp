// Laminated shells of *MAT_ENHANCED_COMPOSITE_DAMAGE (054 / 055) with *SECTION_SHELL ICOMP 1
// through the whole pipeline, against classical lamination theory (tools/clt.py computes every
// reference number below from the ply data, independently of Crumple) and the Chang-Chang
// strengths:
//  - membrane: one element of [0/45/-45/90]s stretched along x (all nodes driven): the force
//    per width N = A eps (ELFORM 2 and 16);
//  - off-axis: one ply at 30 degrees driven through the strain of uniaxial stress that CLT
//    predicts (eps_y = -0.2269 eps_x, gamma_xy = -1.3515 eps_x): N_y and N_xy vanish, N_x / eps_x
//    = 1 / a11;
//  - bending: a [0/0/90/90]s cantilever strip's first frequency against 1 / d11 (CLT);
//  - failure: a 0-degree ply stretched along the fibres peaks at XT, fails in fibre tension and
//    erodes; stretched across, its sigma_bb peaks at YT (CRIT 54 and 55), the matrix fails and
//    the element stays.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "elements/shell.hpp"
#include "harness.hpp"

namespace {

using crumple::testing::measuredPeriod;
using crumple::testing::Simulation;
using crumple::testing::termination;

// The ply (GPa, mm, ms, kg): EA 181, EB 10.3, PRBA 0.016, GAB 7.17, GBC 3, GCA 7.17; XC 1.5,
// XT 1.5, YC 0.246, YT 0.04, SC 0.068.
constexpr double kRho = 1.6e-6, kXt = 1.5, kYt = 0.04;

// `axes`: cards 2 (from AOPT on), 3 and 4 up to D3; `card5` card 5.
std::string plyMaterial(int crit = 54, const std::string& axes = "0\n0,0,0,0,0,0,0\n0,0,0,0,0,0",
                        const std::string& card5 = "0,0,0,0,0,0,0,0") {
  return fmt::format(
      "*MAT_ENHANCED_COMPOSITE_DAMAGE\n1,{},181,10.3,0,0.016\n7.17,3.0,7.17,0,{},0,0\n{}\n"
      "1.5,1.5,0.246,0.04,0.068,{}\n",
      kRho, axes, card5, crit);
}

// A section of thickness 1 with one point per ply (ESOP 1: equal layers) at these angles.
std::string layup(int elform, const std::vector<int>& angles) {
  const auto n = angles.size();
  std::string s = fmt::format(
      "*INTEGRATION_SHELL\n9,{},1\n*SECTION_SHELL\n1,{},0.8333,{},1,-9,1\n"
      "1.0,1.0,1.0,1.0\n",
      n, elform, n);
  for (std::size_t i = 0; i < n; ++i) s += fmt::format("{}{}", angles[i], i + 1 == n ? "\n" : ",");
  return s;
}

// One 10 x 10 element in the x-y plane, every node driven with the velocity L x (L the
// symmetric velocity gradient lxx, lyy, lxy), z and rotations held.
std::string drivenElement(const std::string& material, const std::string& section, double lxx,
                          double lyy, double lxy, double end) {
  std::string s = "*KEYWORD\n" + termination(end) + material + section +
                  "*PART\nply\n1,1,1\n*NODE\n1,0,0,0\n2,10,0,0\n3,10,10,0\n4,0,10,0\n"
                  "*ELEMENT_SHELL\n1,1,1,2,3,4\n*DEFINE_CURVE\n1\n0,1\n1000,1\n"
                  "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  // A zero velocity is an SPC (SF 0 on the motion card would read as its default, 1).
  const double xy[4][2] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  std::string spc = "*BOUNDARY_SPC_NODE\n";
  for (int a = 0; a < 4; ++a) {
    const double v[2] = {lxx * xy[a][0] + lxy * xy[a][1], lxy * xy[a][0] + lyy * xy[a][1]};
    for (int d = 0; d < 2; ++d)
      if (v[d] != 0.0) s += fmt::format("{},{},0,1,{:.17g}\n", a + 1, d + 1, v[d]);
    spc += fmt::format("{},0,{},{},1,1,1,1\n", a + 1, int(v[0] == 0.0), int(v[1] == 0.0));
  }
  return s + spc + "*END\n";
}

// Runs the driven element; returns node 2's x before the last position update: the element's
// stress has integrated the strain rate up to that geometry (the update x(n+1) = x(n) +
// dt v(n+1/2) is taken up by the next cycle's strain), so eps = ln(x / 10) with it.
double runDriven(Simulation& sim) {
  double before = sim.x(2, 0), last = before;
  sim.run([&](const crumple::solver::Solver&) {
    before = last;
    last = sim.x(2, 0);
  });
  return before;
}

// The membrane resultants N_xx, N_yy, N_xy per unit width of the one element.
std::array<double, 3> membrane(const Simulation& sim) {
  double r[8];
  crumple::elements::shellResultants(sim.sd.shell_blocks.at(0), 0, r);
  return {r[5], r[6], r[7]};
}

}  // namespace

// A of [0/45/-45/90]s (h = 1, tools/clt.py): A11 = A22 = 76.37395134, A12 = 22.61737507,
// A16 = A26 = 0. Uniaxial strain eps = ln(x / x0) along x: N = (A11, A12, 0) eps, to the
// round-off of the hypoelastic update (its midpoint strain increments sum to ln(x / x0) within
// O(dt^2)).
TEST(VerificationComposite, QuasiIsotropicMembraneIsTheAMatrix) {
  for (int elform : {2, 16}) {
    auto sim = Simulation::fromText(
        fmt::format("composite_membrane_{}", elform),
        drivenElement(plyMaterial(), layup(elform, {0, 45, -45, 90, 90, -45, 45, 0}), 1e-3, 0, 0,
                      0.1));
    const double eps = std::log(runDriven(*sim) / 10.0);
    const auto n = membrane(*sim);
    EXPECT_NEAR(n[0] / (76.37395134 * eps), 1.0, 1e-6) << elform;
    EXPECT_NEAR(n[1] / (22.61737507 * eps), 1.0, 1e-6) << elform;
    EXPECT_LT(std::abs(n[2]), 1e-9 * n[0]) << elform;
    std::printf("[ figure ] ELFORM %d N_x / (A11 eps) - 1 = %.2g, N_y / (A12 eps) - 1 = %.2g\n",
                elform, n[0] / (76.37395134 * eps) - 1.0, n[1] / (22.61737507 * eps) - 1.0);
  }
}

// A single ply at 30 degrees under uniaxial stress: CLT (tools/clt.py) gives eps_y / eps_x =
// -0.226852171 and the shear coupling gamma_xy / eps_x = -1.351465143, with N_x / eps_x = 1 / a11
// = 28.78211421. Driven through that strain the ply carries N_x alone; an error in the turned
// stiffness (an angle of the wrong sign, or none) leaves N_xy of the order of N_x.
TEST(VerificationComposite, OffAxisPlyShowsTheShearCoupling) {
  const double r = 1e-3, ry = -0.226852171 * r, g = -1.351465143 * r;
  const auto run = [&](const std::string& name, const std::string& axes, int angle) {
    auto sim = Simulation::fromText(
        name, drivenElement(
                  plyMaterial(54, axes),
                  fmt::format("*SECTION_SHELL\n1,2,0.8333,1,1,0,1\n1.0,1.0,1.0,1.0\n{}\n", angle),
                  r, ry, 0.5 * g, 0.1));
    const double eps = std::log(runDriven(*sim) / 10.0);
    const auto n = membrane(*sim);
    return std::array<double, 4>{n[0], n[1], n[2], eps};
  };
  const auto n = run("composite_off_axis", "0\n0,0,0,0,0,0,0\n0,0,0,0,0,0", 30);
  const double eps = n[3];
  EXPECT_NEAR(n[0] / eps / 28.78211421, 1.0, 1e-3);
  EXPECT_LT(std::abs(n[1]), 1e-3 * n[0]);
  EXPECT_LT(std::abs(n[2]), 1e-3 * n[0]);
  std::printf(
      "[ figure ] 30-degree ply: N_x / (eps_x / a11) %.6f, N_y / N_x %.2g, N_xy / N_x %.2g\n",
      n[0] / eps / 28.78211421, n[1] / n[0], n[2] / n[0]);
  // The same ply by its axes: AOPT 2 with A at 30 degrees (tilted out of the plane: projected),
  // AOPT 3 with V x normal at 30 degrees (V = (-sin 30, cos 30, 0)), AOPT 0 with MANGLE 20 and
  // B1 10.
  const auto a2 =
      run("composite_off_axis_a2", "2\n0,0,0,0.8660254037844386,0.5,0.7,0\n0,0,0,0,0,0", 0);
  const auto a3 =
      run("composite_off_axis_a3", "3\n0,0,0,0,0,0,0\n-0.5,0.8660254037844386,0,0,0,0", 0);
  const auto m0 = run("composite_off_axis_mangle", "0\n0,0,0,0,0,0,20\n0,0,0,0,0,0", 10);
  for (const auto& other : {a2, a3, m0})
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(other[k], n[k], 1e-9 * n[0]) << k;
}

namespace {

// A 20 x 2 strip of 100 x 10 mm in the x-y plane, part 1, clamped at x = 0, with a z velocity
// in the static deflection shape; `extra` holds the material, section and part. Node (i, j)
// has id 1 + i + 21 j (32 the tip's middle).
std::string crossPlyStrip(const std::string& extra) {
  constexpr double kL = 100.0, kB = 10.0;
  std::string s = "*KEYWORD\n" + extra + "*NODE\n";
  constexpr int nx = 20, ny = 2;
  auto id = [&](int i, int j) { return 1 + i + (nx + 1) * j; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      s += fmt::format("{},{},{},0\n", id(i, j), kL * i / nx, kB * j / ny);
  s += "*ELEMENT_SHELL\n";
  for (int j = 0, e = 1; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      s += fmt::format("{},1,{},{},{},{}\n", e++, id(i, j), id(i + 1, j), id(i + 1, j + 1),
                       id(i, j + 1));
  s += "*BOUNDARY_SPC_NODE\n";
  for (int j = 0; j <= ny; ++j) s += fmt::format("{},0,1,1,1,1,1,1\n", id(0, j));
  s += "*INITIAL_VELOCITY_NODE\n";
  for (int j = 0; j <= ny; ++j)
    for (int i = 1; i <= nx; ++i) {
      const double xi = double(i) / nx;
      s += fmt::format("{},0,0,{}\n", id(i, j), 0.05 * 0.5 * xi * xi * (3.0 - xi));
    }
  return s + "*END\n";
}

}  // namespace

// A [0/0/90/90]s strip (20 x 2 shells, 100 x 10 x 1 mm, one point per ply), clamped at x = 0:
// f1 = (1.8751^2 / 2 pi) sqrt((1 / d11) / (rho h L^4)) with 1 / d11 = 13.34314343 GPa mm^3 of
// CLT; one point per ply integrates 13.21765825 (tools/clt.py, "midpoint").
TEST(VerificationComposite, CrossPlyCantileverFrequencyFollowsD11) {
  constexpr double kL = 100.0, kD = 13.34314343, kDmid = 13.21765825;
  const auto f1 = [&](double d) {
    return 1.8751 * 1.8751 / (2.0 * M_PI) * std::sqrt(d / (kRho * 1.0 * std::pow(kL, 4)));
  };
  const double period = 1.0 / f1(kD);
  const auto measure = [&](const std::string& name, const std::string& part) {
    auto sim = Simulation::fromText(name, crossPlyStrip(termination(1.7 * period) + part));
    const double measured = measuredPeriod(*sim, 32);
    EXPECT_NEAR(sim->solver->energies().ratio, 1.0, 0.01);
    return measured;
  };
  const double measured =
      measure("composite_cantilever",
              plyMaterial() + layup(2, {0, 0, 90, 90, 90, 90, 0, 0}) + "*PART\nstrip\n1,1,1\n");
  // *PART_COMPOSITE of the same plies: the same integration points, the same period.
  const double part =
      measure("composite_cantilever_part", plyMaterial() +
                                               "*PART_COMPOSITE\nstrip\n1,2,0.8333\n"
                                               "1,0.125,0,0,1,0.125,0\n1,0.125,90,0,1,0.125,90\n"
                                               "1,0.125,90,0,1,0.125,90\n1,0.125,0,0,1,0.125,0\n");
  EXPECT_EQ(part, measured);
  EXPECT_NEAR(measured / period, 1.0, 0.02);
  std::printf("[ figure ] [0/0/90/90]s cantilever f1 / f1(CLT 1/d11) %.4f, / f1(midpoint) %.4f\n",
              period / measured, 1.0 / (measured * f1(kDmid)));
}

namespace {

// One 0-degree ply (NIP 1) driven in uniaxial strain along x (along = true) or y at the rate
// 0.01 / ms: the largest sigma_xx (or sigma_yy) over the run, the last one, whether the element
// is still active and its point's history flags.
struct PlyPull {
  double peak = 0, last = 0;
  bool active = true;
  double flags[4] = {};
};

PlyPull pullPly(bool along, int crit, double end) {
  const double r = 0.01;
  auto sim = Simulation::fromText(
      fmt::format("composite_pull_{}_{}", along ? "a" : "b", crit),
      drivenElement(plyMaterial(crit), "*SECTION_SHELL\n1,2,0.8333,1,1,0,1\n1.0,1.0,1.0,1.0\n0\n",
                    along ? r : 0.0, along ? 0.0 : r, 0.0, end));
  PlyPull out;
  const auto& blk = sim->sd.shell_blocks.at(0);
  const int k = along ? 0 : 1;
  sim->run(
      [&](const crumple::solver::Solver&) { out.peak = std::max(out.peak, blk.sigAt(k, 0, 0)); });
  out.last = blk.sigAt(k, 0, 0);
  out.active = blk.active[0] != 0;
  for (int h = 0; h < 4; ++h)
    out.flags[h] = blk.hist.at(std::size_t(h) * crumple::elements::kShellBatch);
  return out;
}

}  // namespace

// Along the fibres: sigma_aa rises at Q11 = 181.8 GPa to XT (each step adds 0.1 % of XT), the
// fibre tension criterion (sigma_aa / XT)^2 >= 1 fails the only point and the element erodes.
TEST(VerificationComposite, FibreTensionPeaksAtXtAndErodes) {
  const auto p = pullPly(true, 54, 1.0);
  EXPECT_LE(p.peak, kXt);
  EXPECT_GT(p.peak, 0.997 * kXt);
  EXPECT_EQ(p.last, 0.0);
  EXPECT_FALSE(p.active);
  EXPECT_EQ(p.flags[0], 1.0);
  std::printf("[ figure ] fibre tension peak / XT %.5f, then 0 and eroded\n", p.peak / kXt);
}

// Across the fibres: sigma_bb rises at Q22 = 10.35 GPa to YT (0.2 % of YT a step); the matrix
// tension criterion, Chang-Chang (sigma_bb / YT)^2 >= 1 or Tsai-Wu (whose root in tension is YT
// too), drops sigma_bb; the fibres hold, the element stays.
TEST(VerificationComposite, TransverseTensionFailsTheMatrixAtYt) {
  for (int crit : {54, 55}) {
    const auto p = pullPly(false, crit, 0.6);
    EXPECT_LE(p.peak, kYt) << crit;
    EXPECT_GT(p.peak, 0.995 * kYt) << crit;
    EXPECT_EQ(p.last, 0.0) << crit;
    EXPECT_TRUE(p.active) << crit;
    EXPECT_EQ(p.flags[2], 1.0) << crit;
    EXPECT_EQ(p.flags[0], 0.0) << crit;
    std::printf("[ figure ] CRIT %d transverse tension peak / YT %.5f, then 0, element kept\n",
                crit, p.peak / kYt);
  }
}

// TFAIL 0.01 ms, above the element's step (about 8.4e-4 ms): deleted in the first pass, as a
// *MAT_024 TDEL element; TFAIL 1e-4 ms, below it: kept.
TEST(VerificationComposite, TfailDeletesElementsBelowTheStep) {
  for (double tfail : {0.01, 1e-4}) {
    auto sim = Simulation::fromText(
        "composite_tfail",
        drivenElement(plyMaterial(54, "0\n0,0,0,0,0,0,0\n0,0,0,0,0,0", fmt::format("{}", tfail)),
                      "*SECTION_SHELL\n1,2,0.8333,1,1,0,1\n1.0,1.0,1.0,1.0\n0\n", 1e-3, 0, 0,
                      0.005));
    sim->run();
    EXPECT_EQ(sim->sd.shell_blocks.at(0).active[0] == 0, tfail > 1e-3) << tfail;
  }
}
