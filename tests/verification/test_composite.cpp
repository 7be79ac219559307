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

namespace {

// The ply's fibre modulus, its Poisson's ratios and the in-plane shear modulus (GPa).
constexpr double kEa = 181.0, kEb = 10.3, kPrba = 0.016, kGab = 7.17, kXc = 1.5, kSc = 0.068;
constexpr double kNuAb = kPrba * kEa / kEb;  // nu_ab = nu_ba Ea / Eb

// One element of the ply (*MAT_054 with card 4's DFAILM, DFAILS = `dfail_ms`, card 5 and card 8)
// driven with the velocity gradient l (drivenElement) at each section: each cycle while the
// element is active, its first point's stress component k (element frame) and the point's
// history variable h; at the end whether the element is active and its points' history.
struct StrainPath {
  std::vector<double> s, h;
  bool active = true;
  std::vector<double> hist;  // variable v of point ip at v nip + ip
};

std::string limitedPly(const std::string& dfail_ms, const std::string& card5,
                       const std::string& card8 = "0") {
  return fmt::format(
      "*MAT_ENHANCED_COMPOSITE_DAMAGE\n1,{},181,10.3,0,0.016\n7.17,3.0,7.17,0,0\n0,0,0,0,0,0,0\n"
      "0,0,0,0,0,0,{}\n{}\n1.5,1.5,0.246,0.04,0.068\n0\n{}\n",
      kRho, dfail_ms, card5, card8);
}

StrainPath drivePath(const std::string& name, const std::string& material,
                     const std::string& section, std::array<double, 3> l, double end, int k,
                     int h) {
  auto sim = Simulation::fromText(name, drivenElement(material, section, l[0], l[1], l[2], end));
  const auto& blk = sim->sd.shell_blocks.at(0);
  const auto hist = [&](int v, int ip) {
    return blk.hist.at(crumple::domain::ShellBlock::blocked(blk.histFields(), v * blk.nip + ip, 0));
  };
  StrainPath out;
  sim->run([&](const crumple::solver::Solver&) {
    if (blk.active[0] == 0) return;
    out.s.push_back(blk.sigAt(k, 0, 0));
    out.h.push_back(hist(h, 0));
  });
  out.active = blk.active[0] != 0;
  for (int v = 0; v < blk.history; ++v)
    for (int ip = 0; ip < blk.nip; ++ip) out.hist.push_back(hist(v, ip));
  return out;
}

// A path's largest stress, the least and the largest stress of the cycles after it, and their
// number.
struct Plateau {
  double peak = 0, lo = 0, hi = 0;
  long cycles = 0;
};

Plateau plateauAfterPeak(const std::vector<double>& s) {
  const auto peak = std::max_element(s.begin(), s.end());
  Plateau p{*peak, *peak, -*peak, long(s.end() - peak - 1)};
  for (auto it = peak + 1; it != s.end(); ++it) {
    p.lo = std::min(p.lo, *it);
    p.hi = std::max(p.hi, *it);
  }
  return p;
}

const std::string kOnePly = "*SECTION_SHELL\n1,2,0.8333,1,1,0,1\n1.0,1.0,1.0,1.0\n0\n";

}  // namespace

// DFAILT 0.005, below XT / EA = 0.0083: pulled along the fibres in uniaxial stress (eps_b =
// -nu_ab eps_a, so sigma_aa = EA eps_a) at 0.002 / ms, the layer fails when its fibre strain
// passes DFAILT, at sigma_aa = EA DFAILT (each step adds 3.4e-4 of it), before the stress
// criterion; its only point failed, the element erodes.
TEST(VerificationComposite, DfailtFailsTheLayerAtItsFibreStrain) {
  const double r = 0.002, dfailt = 0.005;
  const auto p = drivePath("composite_dfailt", limitedPly("0,0", "0,0,0,0,0,0.005,-0.005"), kOnePly,
                           {r, -kNuAb * r, 0}, 3.0, 0, 4);
  ASSERT_FALSE(p.s.empty());
  const double at_failure = p.s.back() / (kEa * dfailt);
  EXPECT_NEAR(at_failure, 1.0, 1e-3);
  EXPECT_LE(p.h.back(), dfailt);
  EXPECT_FALSE(p.active);
  EXPECT_GT(p.hist.at(4), dfailt);  // the fibre strain that failed it
  EXPECT_EQ(p.hist.at(7), 1.0);     // failed by a strain limit
  EXPECT_EQ(p.hist.at(0), 0.0);     // not by the fibre tension criterion
  std::printf("[ figure ] DFAILT: sigma_aa at failure / (EA DFAILT) %.6f, eroded\n", at_failure);
}

// [0/90] with DFAILT 0.005 and DFAILM 0.008 stretched along x in uniaxial strain at 0.01 / ms:
// the 0-degree layer fails at fibre strain 0.005 and the element stays (one layer left); the
// 90-degree layer (its matrix cracked at YT, the stress criterion, which fails no layer) fails
// at matrix strain 0.008 and the element erodes then, with all its layers failed.
TEST(VerificationComposite, ElementErodesWhenAllLayersHaveFailed) {
  const double r = 0.01;
  const auto layers = [&](double end) {
    return drivePath("composite_layers", limitedPly("0.008,0", "0,0,0,0,0,0.005,-0.005"),
                     layup(2, {0, 90}), {r, 0, 0}, end, 0, 4);
  };
  const auto mid = layers(0.65);  // eps_x 0.0065
  EXPECT_TRUE(mid.active);
  EXPECT_EQ(mid.hist.at(7 * 2 + 0), 1.0);  // the 0-degree layer failed
  EXPECT_EQ(mid.hist.at(7 * 2 + 1), 0.0);
  EXPECT_EQ(mid.hist.at(2 * 2 + 1), 1.0);  // the 90-degree layer's matrix cracked
  const auto all = layers(1.0);
  EXPECT_FALSE(all.active);
  // eps_x (the 0-degree layer's e_aa) in the last cycle before the element erodes.
  const double eps = all.h.back();
  EXPECT_EQ(all.hist.at(7 * 2 + 1), 1.0);
  EXPECT_LE(eps, 0.008);
  EXPECT_GT(eps, 0.008 * (1 - 2e-3));
  std::printf("[ figure ] [0/90]: 0-degree layer failed at 0.005, element erodes at eps_x %.6f\n",
              eps);
}

// DFAILC -0.005, above -XC / EA: compressed along the fibres in uniaxial stress, the layer
// fails at sigma_aa = EA DFAILC and the element erodes.
TEST(VerificationComposite, DfailcFailsTheLayerInFibreCompression) {
  const double r = 0.002, dfailc = -0.005;
  const auto p = drivePath("composite_dfailc", limitedPly("0,0", "0,0,0,0,0,0.05,-0.005"), kOnePly,
                           {-r, kNuAb * r, 0}, 3.0, 0, 4);
  ASSERT_FALSE(p.s.empty());
  const double at_failure = p.s.back() / (kEa * dfailc);
  EXPECT_NEAR(at_failure, 1.0, 1e-3);
  EXPECT_LT(-p.s.back(), 0.7 * kXc);  // below XC: the strain limit, not the stress criterion
  EXPECT_FALSE(p.active);
  EXPECT_EQ(p.hist.at(1), 0.0);  // the fibre compression criterion not reached
  std::printf("[ figure ] DFAILC: sigma_aa at failure / (EA DFAILC) %.6f, eroded\n", at_failure);
}

// DFAILM 0.002, below YT / EB = 0.0039: pulled across the fibres in uniaxial stress (eps_a =
// -nu_ba eps_b, sigma_bb = EB eps_b), the layer fails at sigma_bb = EB DFAILM, before the
// matrix criterion, and the element erodes.
TEST(VerificationComposite, DfailmFailsTheLayerAtItsMatrixStrain) {
  const double r = 0.001, dfailm = 0.002;
  const auto p = drivePath("composite_dfailm", limitedPly("0.002,0", "0,0,0,0,0,0.05,-0.05"),
                           kOnePly, {-kPrba * r, r, 0}, 3.0, 1, 5);
  ASSERT_FALSE(p.s.empty());
  const double at_failure = p.s.back() / (kEb * dfailm);
  EXPECT_NEAR(at_failure, 1.0, 1e-3);
  EXPECT_FALSE(p.active);
  EXPECT_EQ(p.hist.at(2), 0.0);  // the matrix criterion not reached
  std::printf("[ figure ] DFAILM: sigma_bb at failure / (EB DFAILM) %.6f, eroded\n", at_failure);
}

// DFAILS 0.003 (tensor shear), below SC / 2 GAB = 0.0047: in pure shear the layer fails at
// sigma_ab = 2 GAB DFAILS and the element erodes.
TEST(VerificationComposite, DfailsFailsTheLayerAtItsShearStrain) {
  const double r = 0.002, dfails = 0.003;
  const auto p = drivePath("composite_dfails", limitedPly("0,0.003", "0,0,0,0,0,0.05,-0.05"),
                           kOnePly, {0, 0, r}, 2.0, 2, 6);
  ASSERT_FALSE(p.s.empty());
  const double at_failure = p.s.back() / (2.0 * kGab * dfails);
  EXPECT_NEAR(at_failure, 1.0, 1e-3);
  EXPECT_FALSE(p.active);
  EXPECT_EQ(p.hist.at(2) + p.hist.at(3), 0.0);  // the matrix criterion not reached
  std::printf("[ figure ] DFAILS: sigma_ab at failure / (2 GAB DFAILS) %.6f, eroded\n", at_failure);
}

// EFS 0.005 (DFAILT 0): in uniaxial strain along the fibres the volume-preserving effective
// strain is sqrt(4/3) eps_a, so the layer fails at eps_a = EFS sqrt(3) / 2, sigma_aa = Q11 EFS
// sqrt(3) / 2 with Q11 = EA / (1 - nu_ab nu_ba), below XT; the element erodes.
TEST(VerificationComposite, EfsFailsTheLayerAtItsEffectiveStrain) {
  const double r = 0.002, efs = 0.005, q11 = kEa / (1.0 - kNuAb * kPrba);
  const auto p = drivePath("composite_efs", limitedPly("0,0", "0,0,0,0,0,0,0,0.005"), kOnePly,
                           {r, 0, 0}, 3.0, 0, 4);
  ASSERT_FALSE(p.s.empty());
  const double at_failure = p.s.back() / (q11 * efs * std::sqrt(3.0) / 2.0);
  EXPECT_NEAR(at_failure, 1.0, 1e-3);
  EXPECT_FALSE(p.active);
  EXPECT_EQ(p.hist.at(0), 0.0);
  std::printf("[ figure ] EFS: sigma_aa at failure / (Q11 EFS sqrt(3)/2) %.6f, eroded\n",
              at_failure);
}

// SLIMT1 0.3 with DFAILT 0.02: along the fibres in uniaxial stress sigma_aa peaks at XT, the
// fibre tension criterion is reached and the fibre stress then stays at 0.3 XT under further
// stretching (not 0), until the fibre strain passes DFAILT and the element erodes.
TEST(VerificationComposite, Slimt1HoldsTheFibreStressAfterXt) {
  const double r = 0.01, slim = 0.3;
  const auto p = drivePath("composite_slimt1", limitedPly("0,0", "0,0,0,0,0,0.02,-0.02", "0.3"),
                           kOnePly, {r, -kNuAb * r, 0}, 2.5, 0, 4);
  ASSERT_FALSE(p.s.empty());
  const auto q = plateauAfterPeak(p.s);
  EXPECT_LE(q.peak, kXt);
  EXPECT_GT(q.peak, 0.997 * kXt);
  // Every cycle after the peak until the element erodes: 0.3 XT.
  EXPECT_NEAR(q.lo / (slim * kXt), 1.0, 1e-12);
  EXPECT_NEAR(q.hi / (slim * kXt), 1.0, 1e-12);
  EXPECT_GT(q.cycles, 1000);  // held from eps 0.0083 to 0.02
  EXPECT_NEAR(p.h.back() / 0.02, 1.0, 1e-3);
  EXPECT_FALSE(p.active);
  EXPECT_EQ(p.hist.at(0), 1.0);
  std::printf(
      "[ figure ] SLIMT1 0.3: peak / XT %.5f, held at %.6f XT over %ld cycles, eroded at "
      "eps_a %.5f\n",
      q.peak / kXt, q.hi / kXt, q.cycles, p.h.back());
}

// SLIMS 0.4: in pure shear sigma_ab peaks at SC (the matrix criterion, (sigma_ab / SC)^2 >= 1)
// and then stays at 0.4 SC; the matrix failure fails no layer, the element stays.
TEST(VerificationComposite, SlimsHoldsTheShearStressAfterSc) {
  const double r = 0.01, slim = 0.4;
  const auto p = drivePath("composite_slims", limitedPly("0,0", "0,0,0,0,0,0,0,0", "0,0,0,0,0.4"),
                           kOnePly, {0, 0, r}, 1.5, 2, 6);
  ASSERT_FALSE(p.s.empty());
  const auto q = plateauAfterPeak(p.s);
  // The shear of finite strain leaves a small s_bb < 0 in the criterion (the compression
  // branch), which lets s_ab pass SC by a little.
  EXPECT_NEAR(q.peak / kSc, 1.0, 2e-3);
  EXPECT_NEAR(q.lo / (slim * kSc), 1.0, 1e-9);
  EXPECT_NEAR(q.hi / (slim * kSc), 1.0, 1e-9);
  EXPECT_GT(p.h.back(), 0.014);  // sheared on to e_ab 0.015
  EXPECT_TRUE(p.active);
  EXPECT_EQ(p.hist.at(2) + p.hist.at(3), 1.0);
  std::printf("[ figure ] SLIMS 0.4: peak / SC %.5f, then %.9f SC, element kept\n", q.peak / kSc,
              q.hi / kSc);
}
