// Thick shells (*SECTION_TSHELL ELFORM 1, *ELEMENT_TSHELL; src/elements/tshell.hpp) through the
// whole pipeline: the membrane patch test on a distorted mesh, a free rigid spin, a cantilever
// strip's first frequency and tip deflection against Euler-Bernoulli beam theory, a short thick
// cantilever against Timoshenko's, and plastic tension against the Belytschko-Tsay shell.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "harness.hpp"

namespace {

using crumple::testing::measuredPeriod;
using crumple::testing::quasiStaticTip;
using crumple::testing::Simulation;
using crumple::testing::staticShape;
using crumple::testing::termination;
using crumple::testing::tipLoad;

// Steel in mm, ms, kg, GPa (kN), as test_structures.cpp.
constexpr double kE = 210.0, kRho = 7.85e-6;

// A strip of thick shells on [0, L] x [0, b], one element through the thickness t (z from
// -t/2, the bottom face N1-N4, to t/2).
struct Strip {
  int nx = 20, ny = 2;
  // 2.5 mm thick: the step (the thickness over c) and so the run length stay moderate.
  double L = 100.0, b = 10.0, t = 2.5;
  int nip = 3;
  int elform = 1;  // *SECTION_TSHELL ELFORM: 1 or 2
  double nu = 0.0;
  std::string material;  // empty: *MAT_ELASTIC with E and nu
  // In-plane node offsets (distorted meshes): dx(i, j), dy(i, j).
  double (*offset)(int i, int j, int c) = nullptr;
};

int nodeId(const Strip& s, int i, int j, int k) {
  return 1 + i + (s.nx + 1) * (j + (s.ny + 1) * k);
}

double nodeX(const Strip& s, int i, int j, int c) {
  const double base = c == 0 ? s.L * i / s.nx : s.b * j / s.ny;
  return base + (s.offset ? s.offset(i, j, c) : 0.0);
}

std::string stripDeck(const Strip& s, const std::string& extra) {
  std::string d = "*KEYWORD\n*TITLE\nthick shell strip\n" + extra;
  d += s.material.empty()
           ? fmt::format("*MAT_ELASTIC\n         1{:10.4g}{:10.4g}{:10.4g}\n", kRho, kE, s.nu)
           : s.material;
  d += fmt::format("*SECTION_TSHELL\n         1{:10d}{:10.6f}{:10d}\n", s.elform, 5.0 / 6.0, s.nip);
  d += "*PART\nstrip\n         1         1         1\n*NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= s.ny; ++j)
      for (int i = 0; i <= s.nx; ++i)
        d += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", nodeId(s, i, j, k), nodeX(s, i, j, 0),
                         nodeX(s, i, j, 1), (k - 0.5) * s.t);
  d += "*ELEMENT_TSHELL\n";
  int e = 1;
  for (int j = 0; j < s.ny; ++j)
    for (int i = 0; i < s.nx; ++i) {
      d += fmt::format("{:8d}{:8d}", e++, 1);
      for (int k = 0; k <= 1; ++k)
        d += fmt::format("{:8d}{:8d}{:8d}{:8d}", nodeId(s, i, j, k), nodeId(s, i + 1, j, k),
                         nodeId(s, i + 1, j + 1, k), nodeId(s, i, j + 1, k));
      d += "\n";
    }
  return d + "*END\n";
}

// Every node at x = 0 held in x, y and z.
std::string clampedRoot(const Strip& s) {
  std::string d = "*BOUNDARY_SPC_NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= s.ny; ++j)
      d += fmt::format("{:10d}         0         1         1         1\n", nodeId(s, 0, j, k));
  return d;
}

// The tip load P in z over the tip nodes: trapezoidal across the width, half on each face.
std::string tipNodeLoads(const Strip& s, double p) {
  std::string d;
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= s.ny; ++j) {
      const double w = (j == 0 || j == s.ny ? 0.5 : 1.0) / s.ny * 0.5;
      d += fmt::format("{:10d}         3         1{:10.4g}\n", nodeId(s, s.nx, j, k), p * w);
    }
  return d;
}

// z velocity in the static deflection shape (mostly mode 1).
std::string modeVelocity(const Strip& s, double speed) {
  std::string d = "*INITIAL_VELOCITY_NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= s.ny; ++j)
      for (int i = 1; i <= s.nx; ++i)
        d += fmt::format("{:10d}{:10.4g}{:10.4g}{:10.4g}\n", nodeId(s, i, j, k), 0.0, 0.0,
                         speed * staticShape(double(i) / s.nx));
  return d;
}

// Euler-Bernoulli cantilever: f1 = (1.8751^2 / 2 pi) sqrt(E I / (rho A L^4)), nu = 0.
double cantileverPeriod(const Strip& s) {
  const double ei_per_mass = kE * s.t * s.t / (12.0 * kRho);
  return 1.0 / (1.8751 * 1.8751 / (2.0 * M_PI) * std::sqrt(ei_per_mass) / (s.L * s.L));
}

double bendingDeflection(const Strip& s, double p) {
  return p * s.L * s.L * s.L / (3.0 * kE * s.b * s.t * s.t * s.t / 12.0);
}

void figure(const char* what, double value) {
  std::printf("[ figure ] %s %s %.4f\n",
              ::testing::UnitTest::GetInstance()->current_test_info()->name(), what, value);
}

// 100 x 10 x 2.5 mm, 20 x 2 thick shells, NIP 3: within 2% of the Euler-Bernoulli frequency
// (the transverse shear lengthens the period by 0.02% at L / t = 40); the energy stays in
// balance and the hourglass control takes little of it.
// The strip's first period, from its static deflection shape, against Euler-Bernoulli's within
// `tolerance`, with the energy in balance; the energies for the caller.
auto firstFrequency(const Strip& s, const std::string& name, double tolerance) {
  const double period = cantileverPeriod(s);
  auto sim = Simulation::fromText(
      name, stripDeck(s, termination(1.7 * period) + clampedRoot(s) + modeVelocity(s, 0.05)));
  const double measured = measuredPeriod(*sim, nodeId(s, s.nx, 1, 0));
  EXPECT_NEAR(measured / period, 1.0, tolerance)
      << "measured " << measured << ", theory " << period;
  figure("f1 ratio", period / measured);
  const auto e = sim->solver->energies();
  EXPECT_NEAR(e.ratio, 1.0, 0.01);
  figure("energy ratio", e.ratio);
  return e;
}

TEST(VerificationTShell, CantileverFirstFrequency) {
  const auto e = firstFrequency(Strip{}, "tshell_cantilever_f1", 0.02);
  EXPECT_LT(e.hourglass, 0.01 * e.initial);
}

constexpr double kP = 1e-2;  // kN: tip deflection 1.2 mm on the 100 mm strip

TEST(VerificationTShell, CantileverTipDeflection) {
  const Strip s;
  const double period = cantileverPeriod(s);
  auto sim = Simulation::fromText(
      "tshell_cantilever_tip", stripDeck(s, tipLoad(period, tipNodeLoads(s, kP)) + clampedRoot(s)));
  const double tip = quasiStaticTip(*sim, nodeId(s, s.nx, 1, 0), 4.0 * period);
  EXPECT_NEAR(tip / bendingDeflection(s, kP), 1.0, 0.02) << "tip " << tip;
  figure("tip ratio", tip / bendingDeflection(s, kP));
}

// A short thick cantilever, L / t = 2.5: the transverse shear adds P L / (kappa G A) to the
// bending deflection (Timoshenko), 9.6% of it at nu = 0 and SHRF 5/6. The tip is within 2% of
// Timoshenko's and clearly beyond Euler-Bernoulli's.
TEST(VerificationTShell, ThickCantileverFollowsTimoshenko) {
  Strip s;
  s.L = 10.0;
  s.t = 4.0;
  const double p = 5.0;
  const double period = cantileverPeriod(s);
  auto sim =
      Simulation::fromText("tshell_thick_cantilever",
                           stripDeck(s, tipLoad(period, tipNodeLoads(s, p)) + clampedRoot(s)));
  const double tip = quasiStaticTip(*sim, nodeId(s, s.nx, 1, 0), 4.0 * period);
  const double shear = p * s.L / (5.0 / 6.0 * (kE / 2.0) * s.b * s.t);
  const double timoshenko = bendingDeflection(s, p) + shear;
  EXPECT_NEAR(tip / timoshenko, 1.0, 0.02) << "tip " << tip << ", Timoshenko " << timoshenko;
  EXPECT_GT(tip / bendingDeflection(s, p), 1.06);
  figure("tip / Timoshenko", tip / timoshenko);
  figure("Timoshenko / Euler-Bernoulli", timoshenko / bendingDeflection(s, p));
}

// A 2 x 2 patch of distorted quadrilaterals (nodes moved along x off the grid: trapezoids with
// sides 1-2 along x, so that the stretch below turns no element's corotational frame, which
// would rotate its stress as the Belytschko-Tsay shell's), nu = 0.3: the boundary nodes follow
// the linear velocity field (a x, b y, c z), c the plane-stress thickness rate, and the centre
// column is free. Every element has the same stress to round-off, the centre nodes follow the
// field (no net force), and the stress is plane-stress Hooke's law of the strain.
double patchOffset(int i, int j, int c) {
  static constexpr double dx[3][3] = {{0.0, 0.05, 0.0}, {0.0, 0.13, -0.07}, {0.0, 0.06, 0.0}};
  return c == 0 ? dx[j][i] : 0.0;
}

// Every node moved in x and y (for the rigid spin).
double spinOffset(int i, int j, int c) {
  static constexpr double d[3][3][2] = {{{0.0, 0.0}, {0.05, 0.0}, {0.0, 0.0}},
                                        {{0.0, 0.08}, {0.13, -0.11}, {-0.07, 0.0}},
                                        {{0.0, 0.0}, {0.06, 0.0}, {0.0, 0.0}}};
  return d[j][i][c];
}

// The patch of PatchTestUniformMembraneStress with *SECTION_TSHELL ELFORM `elform`: ELFORM 1
// with *CONTROL_HOURGLASS IHQ 2, ELFORM 2 with no hourglass control (it needs none). Every
// point of every element carries the same stress (the mean too), the free centre nodes follow
// the field, the stress is Hooke's; no hourglass energy without hourglass control.
void checkPatch(int elform) {
  Strip s;
  s.elform = elform;
  s.nx = s.ny = 2;
  s.L = s.b = 1.0;
  s.t = 0.1;
  s.nu = 0.3;
  s.offset = patchOffset;
  const double a = 0.01, b = -0.004, c = -s.nu / (1.0 - s.nu) * (a + b), t_end = 0.5;
  // The Flanagan-Belytschko hourglass vectors (IHQ 2) are orthogonal to linear fields; IHQ 1's
  // are not, on a distorted mesh.
  std::string bc = std::string(elform == 1 ? "*CONTROL_HOURGLASS\n2,0.1\n" : "") +
                   "*DEFINE_CURVE\n         1\n0.0,1.0\n1000.0,1.0\n";
  std::string motion = "*BOUNDARY_PRESCRIBED_MOTION_NODE\n", held = "*BOUNDARY_SPC_NODE\n";
  std::string init = "*INITIAL_VELOCITY_NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i) {
        const int n = nodeId(s, i, j, k);
        const double v[3] = {a * nodeX(s, i, j, 0), b * nodeX(s, i, j, 1), c * (k - 0.5) * s.t};
        init += fmt::format("{},{:.17g},{:.17g},{:.17g}\n", n, v[0], v[1], v[2]);
        if (i == 1 && j == 1) continue;
        // A zero velocity is a hold (SF = 0 reads as 1).
        held +=
            fmt::format("{},0,{},{},{}\n", n, int(v[0] == 0.0), int(v[1] == 0.0), int(v[2] == 0.0));
        for (int dof = 0; dof < 3; ++dof)
          if (v[dof] != 0.0) motion += fmt::format("{},{},0,1,{:.17g}\n", n, dof + 1, v[dof]);
      }
  auto sim = Simulation::fromText(fmt::format("tshell{}_patch", elform),
                                  stripDeck(s, termination(t_end) + bc + motion + held + init));
  sim->run();
  const auto& blk = sim->sd.solid_blocks.at(0);
  ASSERT_EQ(blk.size(), 4u);
  ASSERT_EQ(blk.points, (elform == 2 ? 4 : 1) * s.nip);
  const double sxx = blk.sigAt(0, 0);
  for (std::size_t e = 0; e < 4; ++e)
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(blk.sigAt(k, e), blk.sigAt(k, 0), 1e-9 * std::abs(sxx)) << e << " " << k;
  const std::size_t padded = blk.paddedSize();
  for (std::size_t e = 0; e < 4; ++e)
    for (std::size_t q = 0; q < std::size_t(blk.points); ++q)
      EXPECT_NEAR(blk.sig_ip[0][q * padded + e], blk.sig_ip[0][e], 1e-9 * std::abs(sxx));
  for (int k = 0; k <= 1; ++k) {
    const int n = nodeId(s, 1, 1, k);
    EXPECT_NEAR(sim->v(n, 0), a * nodeX(s, 1, 1, 0), 1e-9 * a);
    EXPECT_NEAR(sim->v(n, 1), b * nodeX(s, 1, 1, 1), 1e-9 * a);
  }
  // Logarithmic strains of the constant nodal velocities: x = x0 (1 + a t).
  const double ex = std::log1p(a * t_end), ey = std::log1p(b * t_end);
  const double hooke = kE / (1.0 - s.nu * s.nu) * (ex + s.nu * ey);
  EXPECT_NEAR(sxx / hooke, 1.0, 2e-3) << sxx << " vs " << hooke;
  // sigma_zz: the constant nodal velocities make the thickness rate c / (1 + c t) and the law's
  // plane-stress rate follow a / (1 + a t), b / (1 + b t): they part at second order in the
  // strain (measured 1.3e-5 of sigma_xx at 0.5% strain with ELFORM 1). The centre nodes, free
  // in z, do not keep the boundary's thickness rate (their z velocity ends 2-4% off it, ringing
  // in the thickness mode, no damping): ELFORM 2 keeps a thickness-stretch stress per in-plane
  // point, which then differs among the 2 x 2 points (mean 6.4e-4 of sigma_xx).
  EXPECT_LT(std::abs(blk.sigAt(2, 0)), (elform == 2 ? 1e-3 : 1e-4) * std::abs(sxx));
  if (elform == 2) {
    EXPECT_EQ(sim->solver->energies().hourglass, 0.0);
  }
  figure("sxx / Hooke", sxx / hooke);
}

TEST(VerificationTShell, PatchTestUniformMembraneStress) {
  checkPatch(1);
}

// A free distorted plate spinning about an in-plane axis (v = omega x r) is a rigid motion: it
// stays unstrained while it turns a quarter of a radian (ELFORM 1: Flanagan-Belytschko
// hourglass vectors, IHQ 2, orthogonal to the rotation's linear field; ELFORM 2: no hourglass
// control, no hourglass energy).
void checkSpin(int elform) {
  Strip s;
  s.elform = elform;
  s.nx = s.ny = 2;
  s.L = s.b = 1.0;
  s.t = 0.2;
  s.offset = spinOffset;
  const double omega = 1.0;  // rad / ms about the y axis through the origin
  std::string init = "*INITIAL_VELOCITY_NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i) {
        const double x = nodeX(s, i, j, 0), z = (k - 0.5) * s.t;
        init += fmt::format("{},{:.17g},0,{:.17g}\n", nodeId(s, i, j, k), omega * z, -omega * x);
      }
  const std::string hg = elform == 1 ? "*CONTROL_HOURGLASS\n2,0.1\n" : "";
  auto sim = Simulation::fromText(fmt::format("tshell{}_spin", elform),
                                  stripDeck(s, termination(0.25) + hg + init));
  sim->run();
  const auto e = sim->solver->energies();
  EXPECT_LT(e.internal, 1e-6 * e.kinetic) << e.internal << " of " << e.kinetic;
  if (elform == 2) {
    EXPECT_EQ(e.hourglass, 0.0);
  }
  figure("internal / kinetic", e.internal / e.kinetic);
}

TEST(VerificationTShell, RigidSpinLeavesNoStress) {
  checkSpin(1);
}

// Uniaxial tension to 5% of one element with *MAT_PLASTIC_KINEMATIC (isotropic): the thick
// shell's stress and plastic strain are the Belytschko-Tsay shell's.
const char* kPlastic =
    "*MAT_PLASTIC_KINEMATIC\n         1   7.85e-6     210.0       0.3      0.25       2.0       "
    "1.0\n";

std::string pull(const std::string& holds, const std::string& pulled_nodes) {
  std::string d = termination(1.0) + "*DEFINE_CURVE\n         1\n0.0,0.5\n1000.0,0.5\n" + holds;
  return d + "*BOUNDARY_PRESCRIBED_MOTION_NODE\n" + pulled_nodes;
}

// One thick shell of ELFORM `elform`, 10 x 10 x 2.5 mm, pulled to 5% in x, free to contract.
std::unique_ptr<Simulation> pulledThickShell(int elform) {
  Strip s;
  s.elform = elform;
  s.nx = s.ny = 1;
  s.L = s.b = 10.0;
  s.material = kPlastic;
  std::string holds = "*BOUNDARY_SPC_NODE\n";
  std::string pulled;
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j) {
      const bool corner = j == 0;
      holds += fmt::format("{},0,1,{},{}\n", nodeId(s, 0, j, k), int(corner),
                           int(corner && k == 0) + int(j == 1 && k == 0));
      pulled += fmt::format("{},1,0,1,1.0\n", nodeId(s, 1, j, k));
    }
  auto sim = Simulation::fromText(fmt::format("tshell{}_tension", elform),
                                  stripDeck(s, pull(holds, pulled)));
  sim->run();
  return sim;
}

TEST(VerificationTShell, PlasticTensionMatchesBelytschkoTsay) {
  auto thick = pulledThickShell(1);
  const std::string shell =
      "*KEYWORD\n" + std::string(kPlastic) +
      "*SECTION_SHELL\n         1         2    0.8333         3\n       1.0       1.0       1.0"
      "       1.0\n*PART\nstrip\n         1         1         1\n*NODE\n1,0,0,0\n2,10,0,0\n"
      "3,10,10,0\n4,0,10,0\n*ELEMENT_SHELL\n1,1,1,2,3,4\n" +
      pull("*BOUNDARY_SPC_NODE\n1,0,1,1,1\n4,0,1,0,1\n", "2,1,0,1,1.0\n3,1,0,1,1.0\n") + "*END\n";
  auto bt = Simulation::fromText("bt_tension", shell);
  bt->run();
  const auto& tb = thick->sd.solid_blocks.at(0);
  const auto& sb = bt->sd.shell_blocks.at(0);
  const double s_bt = sb.sigAt(0, 1, 0), ep_bt = sb.epsAt(1, 0);
  EXPECT_GT(ep_bt, 0.03);
  EXPECT_NEAR(tb.sigAt(0, 0) / s_bt, 1.0, 2e-3) << tb.sigAt(0, 0) << " vs " << s_bt;
  EXPECT_NEAR(tb.eps_p[0] / ep_bt, 1.0, 2e-3) << tb.eps_p[0] << " vs " << ep_bt;
  figure("sxx thick / BT", tb.sigAt(0, 0) / s_bt);
}

// ---- ELFORM 2: selective reduced, 2 x 2 points in the plane, no hourglass control ----------

// The patch test with ELFORM 2 and no *CONTROL_HOURGLASS (checkPatch): the 2 x 2 points of
// the distorted elements all see the uniform strain.
TEST(VerificationTShell, Selective2x2PatchTest) {
  checkPatch(2);
}

// The free distorted plate's rigid spin with ELFORM 2 and no hourglass control (checkSpin).
TEST(VerificationTShell, Selective2x2RigidSpinLeavesNoStress) {
  checkSpin(2);
}

// A coarse strip, 8 x 1 elements on 100 x 10 x 2.5 mm: ELFORM 2's element bends with constant
// curvature and takes its transverse shear at the centre, as a reduced-integrated linear
// Timoshenko beam. Under a tip load P its element moments are the exact moments at the element
// centres, so the nodal rotations are exact, and the deflection adds h (theta_i +
// theta_i+1) / 2 per element: the trapezoidal rule on the concave rotation, short of the
// integral by P h^3 / (12 E I) per element. The tip is the Euler-Bernoulli deflection times
// 1 - 1 / (4 N^2) (0.39% less at N = 8) plus Timoshenko's shear term P L / (kappa G A). No
// hourglass energy.
Strip coarseStrip() {
  Strip s;
  s.elform = 2;
  s.nx = 8;
  s.ny = 1;
  return s;
}

TEST(VerificationTShell, Selective2x2CoarseCantileverTip) {
  const Strip s = coarseStrip();
  const double period = cantileverPeriod(s);
  auto sim =
      Simulation::fromText("tshell2_cantilever_tip",
                           stripDeck(s, tipLoad(period, tipNodeLoads(s, kP)) + clampedRoot(s)));
  const double tip = quasiStaticTip(*sim, nodeId(s, s.nx, 1, 0), 4.0 * period);
  const double eb = bendingDeflection(s, kP);
  const double shear = kP * s.L / (5.0 / 6.0 * (kE / 2.0) * s.b * s.t);
  const double discrete = eb * (1.0 - 1.0 / (4.0 * s.nx * s.nx)) + shear;
  EXPECT_NEAR(tip / eb, 1.0, 0.01) << "tip " << tip;
  EXPECT_NEAR(tip / discrete, 1.0, 0.005) << "tip " << tip << ", discrete " << discrete;
  EXPECT_EQ(sim->solver->energies().hourglass, 0.0);
  figure("tip / Euler-Bernoulli", tip / eb);
  figure("tip / (EB (1 - 1/4N^2) + shear)", tip / discrete);
}

TEST(VerificationTShell, Selective2x2CoarseCantileverFrequency) {
  EXPECT_EQ(firstFrequency(coarseStrip(), "tshell2_cantilever_f1", 0.015).hourglass, 0.0);
}

// ELFORM 2's uniaxial plastic tension (*MAT_003, isotropic hardening): on the hardening line
// sigma = sigma_y + E_t E / (E - E_t) eps_p of the law's parameters.
TEST(VerificationTShell, Selective2x2PlasticTensionOnTheHardeningLine) {
  auto thick = pulledThickShell(2);
  const auto& tb = thick->sd.solid_blocks.at(0);
  const double sy = 0.25, et = 2.0, h = et * kE / (kE - et);
  EXPECT_GT(tb.eps_p[0], 0.03);
  EXPECT_NEAR(tb.sigAt(0, 0) / (sy + h * tb.eps_p[0]), 1.0, 2e-3) << tb.sigAt(0, 0);
  EXPECT_EQ(thick->solver->energies().hourglass, 0.0);
  figure("sxx / (sy + H eps_p)", tb.sigAt(0, 0) / (sy + h * tb.eps_p[0]));
}

}  // namespace
