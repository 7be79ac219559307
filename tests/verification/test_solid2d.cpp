// 2D solids (*SECTION_SHELL ELFORM 13 plane strain, 15 axisymmetric; src/elements/solid2d.hpp)
// against physics: the patch test on a distorted mesh (uniform strain gives uniform stress and
// balanced interior nodes, with the hoop strain of u = a x), sigma_zz = nu (sigma_xx +
// sigma_yy) in plane strain, energy of free vibrations, the stable step on the axis, a
// plane-strain block under compression, Lame's thick-walled cylinder and the 1D bar wave
// rho c0 v0 in an axisymmetric rod beside a hexahedral bar; refusals of what 2D solids do not
// support.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "elements/solid2d.hpp"
#include "harness.hpp"
#include "util/error.hpp"

namespace {

using crumple::testing::brickNodeSet;
using crumple::testing::Simulation;
using crumple::testing::termination;
namespace el = crumple::elements;

// Units mm, ms, kg, GPa (kN).
constexpr double kE = 210.0, kNu = 0.3, kRho = 7.85e-6;
const std::string kSteel = "*MAT_ELASTIC\n         1   7.85e-6     210.0       0.3\n";
const double kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));
const double kMu = kE / (2 * (1 + kNu));

// An nx x ny mesh of quadrilaterals on [x0, x1] x [0, ly] in the x-y plane, part 1 with a
// *SECTION_SHELL of `elform`; node (i, j) has id 1 + i + (nx + 1) j. `shift` moves the
// interior nodes by a fixed pattern (a distorted mesh).
std::string quadDeck(int nx, int ny, double x0, double x1, double ly, int elform, bool distort,
                     const std::string& extra) {
  std::string s = "*KEYWORD\n*TITLE\nverification 2D solids\n" + extra;
  s += fmt::format(
      "*PART\nquads\n         1         1         1\n*SECTION_SHELL\n         1{:10d}\n"
      "       1.0       1.0       1.0       1.0\n*NODE\n",
      elform);
  const double hx = (x1 - x0) / nx, hy = ly / ny;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      double x = x0 + hx * i, y = hy * j;
      if (distort && i > 0 && i < nx && j > 0 && j < ny) {
        x += 0.23 * hx * ((i * 7 + j * 3) % 5 - 2) / 2.0;
        y += 0.19 * hy * ((i * 3 + j * 5) % 7 - 3) / 3.0;
      }
      s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", 1 + i + (nx + 1) * j, x, y, 0.0);
    }
  s += "*ELEMENT_SHELL\n";
  int e = 1;
  auto id = [&](int i, int j) { return 1 + i + (nx + 1) * j; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      s += fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", e++, 1, id(i, j), id(i + 1, j),
                       id(i + 1, j + 1), id(i, j + 1));
  return s + "*END\n";
}

template <class Pred>
std::string quadNodeSet(int set_id, int nx, int ny, Pred pred) {
  return brickNodeSet(set_id, nx, ny, 0, [&](int i, int j, int) { return pred(i, j); });
}

const std::string kProjectedHourglass = "*CONTROL_HOURGLASS\n         2       0.1\n";

// One pass of the kernel with v = (a x, b y) on every node of a distorted mesh: every element
// gets the stress of the strain increment (a, b, a) dt (axisymmetric: the hoop strain of
// u = a x is u / r = a) or (a, b, 0) dt (plane strain), exactly; an interior node's forces
// balance (a uniform stress is in equilibrium); plane strain has sigma_zz = nu (xx + yy).
void patchTest(int elform) {
  const bool axi = elform == 15;
  auto sim = Simulation::fromText(fmt::format("patch2d_{}", elform),
                                  quadDeck(4, 4, axi ? 0.0 : 2.0, 10.0, 8.0, elform, true,
                                           kSteel + kProjectedHourglass + termination(1.0)));
  auto& blk = sim->sd.shell_blocks.at(0);
  ASSERT_TRUE(blk.planar());
  const double a = 1e-3, b = -2e-3, dt = 1e-4;
  std::vector<double> v(sim->sd.x.size(), 0.0);
  for (std::size_t n = 0; n < sim->sd.numNodes(); ++n) {
    v[3 * n] = a * sim->sd.x[3 * n];
    v[3 * n + 1] = b * sim->sd.x[3 * n + 1];
  }
  // No bulk viscosity: its q depends on each element's size.
  const el::BulkViscosity bv{0.0, 0.0};
  el::computeSolid2DForces(blk, sim->sd.x, v, dt, bv, sim->sd.slots.data(), 0, blk.size());
  // The rates at the mid-step geometry x (1 - a dt / 2), y (1 - b dt / 2).
  const double ea = a / (1 - 0.5 * a * dt) * dt, eb = b / (1 - 0.5 * b * dt) * dt;
  const double ezz = axi ? ea : 0.0;
  const double tr = ea + eb + ezz;
  const double want[4] = {kLambda * tr + 2 * kMu * ea, kLambda * tr + 2 * kMu * eb,
                          kLambda * tr + 2 * kMu * ezz, 0.0};
  const double big = std::max(std::abs(want[0]), std::abs(want[1]));
  double worst = 0.0;
  for (std::size_t e = 0; e < blk.size(); ++e)
    for (int k = 0; k < 4; ++k)
      worst = std::max(worst, std::abs(blk.sigAt(k, 0, e) - want[k]) / big);
  EXPECT_LT(worst, 1e-9);
  if (!axi) {
    EXPECT_NEAR(blk.sigAt(2, 0, 0), kNu * (blk.sigAt(0, 0, 0) + blk.sigAt(1, 0, 0)), 1e-12 * big);
  }
  // Node forces: the sum over each interior node's elements.
  std::vector<double> f(sim->sd.x.size(), 0.0);
  double scale = 0.0;
  for (std::size_t e = 0; e < blk.size(); ++e)
    for (int c = 0; c < 4; ++c)
      for (int i = 0; i < 2; ++i) {
        const double fi = sim->sd.slots[3 * (blk.slot_offset + 8 * e + std::size_t(c)) + i];
        f[3 * std::size_t(blk.conn[e][std::size_t(c)]) + std::size_t(i)] += fi;
        scale = std::max(scale, std::abs(fi));
      }
  double unbalanced = 0.0;
  for (int j = 1; j < 4; ++j)
    for (int i = 1; i < 4; ++i) {
      const std::size_t n = sim->local(1 + i + 5 * j);
      unbalanced = std::max({unbalanced, std::abs(f[3 * n]), std::abs(f[3 * n + 1])});
    }
  EXPECT_LT(unbalanced, 1e-9 * scale);
  std::printf("[ figure ] patch test ELFORM %d: stress error %.1e, interior force %.1e of %.1e\n",
              elform, worst, unbalanced, scale);
}

TEST(VerificationSolid2D, PatchTestPlaneStrain) {
  patchTest(13);
}

TEST(VerificationSolid2D, PatchTestAxisymmetricWithHoopStrain) {
  patchTest(15);
}

// The weighted integrals against closed forms on the square [0, h]^2 at the axis: V = h^3 / 2
// (integral of r dA), the corner masses h^3 / 12 on the axis and h^3 / 6 off it, the hoop
// integrals h^2 / 4.
TEST(VerificationSolid2D, AxisymmetricIntegralsOfASquareOnTheAxis) {
  const double h = 2.0;
  const double x[4] = {0, h, h, 0}, y[4] = {0, 0, h, h};
  const auto g = el::solid2DIntegrals(x, y, true);
  EXPECT_NEAR(g.vol, h * h * h / 2, 1e-14);
  const double m[4] = {h * h * h / 12, h * h * h / 6, h * h * h / 6, h * h * h / 12};
  for (int a = 0; a < 4; ++a) {
    EXPECT_NEAR(g.m[a], m[a], 1e-14);
    EXPECT_NEAR(g.h[a], h * h / 4, 1e-14);
  }
}

// Total energy of a freely vibrating thick ring (axisymmetric, started with v_r = v0 r / b,
// y held) and of a free plane-strain block (v_x = v0 x / L): conserved within 1% over several
// periods, and the elements really strain.
void freeVibration(int elform) {
  const bool axi = elform == 15;
  const int nx = 8, ny = 2;
  const std::string held =
      quadNodeSet(1, nx, ny, [](int, int) { return true; }) +
      (axi ? "*BOUNDARY_SPC_SET\n         1         0         0         1         0\n" : "");
  std::string vel = "*INITIAL_VELOCITY_NODE\n";
  const double x0 = axi ? 10.0 : 0.0, x1 = 20.0;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double x = x0 + (x1 - x0) * i / nx;
      vel += fmt::format("{:10d}{:10.6g}{:10.6g}{:10.6g}\n", 1 + i + (nx + 1) * j,
                         axi ? 2.0 * x / x1 : 2.0 * (x - 10.0) / 10.0, 0.0, 0.0);
    }
  auto sim = Simulation::fromText(
      fmt::format("vibration2d_{}", elform),
      quadDeck(nx, ny, x0, x1, 4.0, elform, true, kSteel + termination(0.05) + held + vel));
  const double e0 = sim->solver->energies().kinetic;
  ASSERT_GT(e0, 0.0);
  double worst = 0.0, max_internal = 0.0;
  sim->run([&](const auto& s) {
    if (s.finished()) return;  // the last, cut step's half-step kinetic energy
    const auto e = s.energies();
    worst = std::max(worst, std::abs(e.total - e0) / e0);
    max_internal = std::max(max_internal, e.internal);
  });
  EXPECT_GT(max_internal, 0.5 * e0);
  EXPECT_LT(worst, 0.01);
  std::printf(
      "[ figure ] free vibration ELFORM %d: %lld cycles, worst |E - E0| / E0 = %.2e, "
      "hourglass %.1e of E0\n",
      elform, static_cast<long long>(sim->solver->cycle()), worst,
      sim->solver->energies().hourglass / e0);
}

TEST(VerificationSolid2D, FreeVibrationConservesEnergyAxisymmetric) {
  freeVibration(15);
}

TEST(VerificationSolid2D, FreeVibrationConservesEnergyPlaneStrain) {
  freeVibration(13);
}

// The stable step A / (longest diagonal) holds for axisymmetric elements on the axis, whose
// hoop stiffness adds to the in-plane one: a distorted mesh touching the axis, started with a
// rough velocity field that excites its highest modes, runs 0.2 ms (about 2300 cycles) at
// TSSFAC 1: the energy error stays bounded (an unstable step grows without bound), no larger
// in the second half than in the first. Cycle by cycle it swings by 3% (the half-step kinetic
// energy of modes near the step limit), at the sampled states by 0.17%.
TEST(VerificationSolid2D, AxisymmetricStepIsStableOnTheAxisAtTssfacOne) {
  const int nx = 4, ny = 8;
  std::string vel = "*INITIAL_VELOCITY_NODE\n";
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      vel +=
          fmt::format("{:10d}{:10.6g}{:10.6g}{:10.6g}\n", 1 + i + (nx + 1) * j,
                      i == 0 ? 0.0 : 0.5 * std::sin(1.7 * i * j), 0.7 * std::cos(i + 2.3 * j), 0.0);
  const std::string sets = quadNodeSet(1, nx, ny, [](int i, int) { return i == 0; }) +
                           "*BOUNDARY_SPC_SET\n         1         0         1         0\n" +
                           "*CONTROL_TIMESTEP\n       0.0       1.0\n";
  auto sim = Simulation::fromText("axis_step2d", quadDeck(nx, ny, 0.0, 4.0, 8.0, 15, true,
                                                          kSteel + termination(0.2) + sets + vel));
  const double e0 = sim->solver->energies().kinetic;
  double worst[2] = {0.0, 0.0};  // first and second half
  sim->run([&](const auto& s) {
    if (s.finished()) return;
    double& w = worst[s.time() < 0.1 ? 0 : 1];
    w = std::max(w, std::abs(s.energies().total - e0) / e0);
  });
  EXPECT_GT(sim->solver->cycle(), 1000);
  EXPECT_LT(worst[0], 0.05);
  EXPECT_LE(worst[1], 1.1 * worst[0]);
  std::printf(
      "[ figure ] axis mesh at TSSFAC 1: %lld cycles, worst |E - E0| / E0 = %.2e in the "
      "first half, %.2e in the second\n",
      static_cast<long long>(sim->solver->cycle()), worst[0], worst[1]);
}

// A plane-strain block pressed between a fixed base and a platen moved by a smooth ramp and
// held (both faces free to slide in x): uniaxial stress in the plane, so over the hold
// sigma_yy = E / (1 - nu^2) eps_yy (the plane-strain modulus), sigma_xx = 0 and sigma_zz = nu
// (sigma_xx + sigma_yy), every element, within 1% of sigma_yy.
TEST(VerificationSolid2D, PlaneStrainBlockUnderCompression) {
  const int n = 4;
  const double h = 10.0, d = 0.01, ramp = 0.05, t_end = 0.07;
  std::string curve = "*DEFINE_CURVE\n         1\n";
  for (int k = 0; k <= 40; ++k) {
    const double t = ramp * k / 40.0;
    curve += fmt::format("{:20.10g}{:20.10g}\n", t, -0.5 * (1.0 - std::cos(M_PI * t / ramp)));
  }
  curve += fmt::format("{:20.10g}{:20.10g}\n", 10.0, -1.0);
  const std::string sets =
      quadNodeSet(1, n, n, [](int, int j) { return j == 0; }) +
      quadNodeSet(2, n, n, [&](int, int j) { return j == n; }) +
      "*BOUNDARY_SPC_SET\n         1         0         0         1\n"
      "*BOUNDARY_SPC_NODE\n         1         0         1         1\n" +
      curve +
      fmt::format(
          "*BOUNDARY_PRESCRIBED_MOTION_SET\n         2         2         2         1"
          "{:10.6g}\n",
          d);
  auto sim = Simulation::fromText(
      "compression2d", quadDeck(n, n, 0.0, h, h, 13, false, kSteel + termination(t_end) + sets));
  const auto& blk = sim->sd.shell_blocks.at(0);
  double mean[3] = {0, 0, 0};
  int samples = 0;
  double worst_zz = 0.0;
  sim->run([&](const auto& s) {
    if (s.time() < ramp + 0.005) return;
    ++samples;
    for (std::size_t e = 0; e < blk.size(); ++e) {
      for (int k = 0; k < 3; ++k) mean[k] += blk.sigAt(k, 0, e) / double(blk.size());
      worst_zz = std::max(
          worst_zz, std::abs(blk.sigAt(2, 0, e) - kNu * (blk.sigAt(0, 0, e) + blk.sigAt(1, 0, e))));
    }
  });
  ASSERT_GT(samples, 10);
  for (double& m : mean) m /= samples;
  const double eps = std::log((h - d) / h);  // the logarithmic strain the rate integrates
  const double want = kE / (1 - kNu * kNu) * eps;
  EXPECT_NEAR(mean[1] / want, 1.0, 0.01);
  EXPECT_LT(std::abs(mean[0]), 0.01 * std::abs(want));
  EXPECT_LT(worst_zz, 1e-9 * std::abs(want));
  std::printf(
      "[ figure ] plane-strain block: sigma_yy %.6g vs E eps / (1 - nu^2) %.6g (ratio "
      "%.4f), sigma_xx %.2e, sigma_zz - nu (xx + yy) at most %.1e\n",
      mean[1], want, mean[1] / want, mean[0], worst_zz);
}

// Lame's thick-walled cylinder in plane strain (a slice a <= r <= b with every node held in
// y): the inner radius is moved out by u_a along a smooth ramp and held; the outer radius,
// free, moves u_b = u_a b (1 + (lambda + mu) / mu) / (a + (lambda + mu) b^2 / (mu a))
// (u = A r + B / r with sigma_rr(b) = 0). The mean over the hold within 1%. The nodal masses
// sum to rho (b^2 - a^2) / 2 per unit height: per radian.
TEST(VerificationSolid2D, LameThickCylinderAxisymmetric) {
  const int nx = 20, ny = 1;
  const double a = 10.0, b = 20.0, ua = 0.01, ramp = 0.08, t_end = 0.12;
  std::string curve = "*DEFINE_CURVE\n         1\n";
  for (int k = 0; k <= 40; ++k) {
    const double t = ramp * k / 40.0;
    curve += fmt::format("{:20.10g}{:20.10g}\n", t, 0.5 * (1.0 - std::cos(M_PI * t / ramp)));
  }
  curve += fmt::format("{:20.10g}{:20.10g}\n", 10.0, 1.0);
  const std::string sets =
      quadNodeSet(1, nx, ny, [](int, int) { return true; }) +
      quadNodeSet(2, nx, ny, [](int i, int) { return i == 0; }) +
      "*BOUNDARY_SPC_SET\n         1         0         0         1         0\n" + curve +
      fmt::format(
          "*BOUNDARY_PRESCRIBED_MOTION_SET\n         2         1         2         1"
          "{:10.6g}\n",
          ua);
  auto sim = Simulation::fromText(
      "lame2d", quadDeck(nx, ny, a, b, 1.0, 15, false, kSteel + termination(t_end) + sets));
  // Masses per radian: rho times the integral of r dA.
  double mass = 0.0;
  for (double m : sim->sd.mass) mass += m;
  EXPECT_NEAR(mass / (kRho * 0.5 * (b * b - a * a) * 1.0), 1.0, 1e-12);
  const double k = (kLambda + kMu) / kMu;
  const double ub_exact = ua * b * (1 + k) / (a + k * b * b / a);
  double sum = 0.0;
  int count = 0;
  const int64_t outer = 1 + nx;
  sim->run([&](const auto& s) {
    if (s.time() < ramp + 0.01) return;
    sum += sim->x(outer, 0) - sim->x0(outer, 0);
    ++count;
  });
  ASSERT_GT(count, 10);
  const double ub = sum / count;
  EXPECT_NEAR(ub / ub_exact, 1.0, 0.01);
  std::printf("[ figure ] Lame cylinder a=%g b=%g: u_b %.6g vs %.6g (ratio %.4f)\n", a, b, ub,
              ub_exact, ub / ub_exact);
}

// Mean axial stress over the lower fifth of a rod along y (elements whose top lies below
// 0.2 L), weighted by each element's volume (volume of a hexahedron, or of the axisymmetric
// ring per radian).
double lowerFifthStress(const Simulation& sim, double L) {
  double s = 0.0, vol = 0.0;
  for (const auto& blk : sim.sd.shell_blocks)
    for (std::size_t e = 0; e < blk.size(); ++e) {
      double xc[4], yc[4];
      for (int c = 0; c < 4; ++c) {
        const std::size_t n = std::size_t(blk.conn[e][std::size_t(c)]);
        xc[c] = sim.sd.x[3 * n];
        yc[c] = sim.sd.x[3 * n + 1];
      }
      if (std::max({yc[0], yc[1], yc[2], yc[3]}) > 0.2 * L) continue;
      const double v = el::solid2DIntegrals(xc, yc, true).vol;
      s += blk.sigAt(1, 0, e) * v;
      vol += v;
    }
  for (const auto& blk : sim.sd.solid_blocks)
    for (std::size_t e = 0; e < blk.size(); ++e) {
      double top = 0.0;
      for (int32_t n : blk.conn[e]) top = std::max(top, sim.sd.x[3 * std::size_t(n) + 1]);
      if (top > 0.2 * L) continue;
      s += blk.sigAt(1, e) * blk.vol[e];
      vol += blk.vol[e];
    }
  return s / vol;
}

// A rod of length 100 along y moving at -v0, stopped at y = 0: behind the front the axial
// stress is -rho c0 v0 with the bar speed c0 = sqrt(E / rho) (1D wave). At 0.6 L / c0 the
// lower fifth's mean, within 3%, for an axisymmetric rod of radius 2 (ELFORM 15, the axis held
// in x) and for a 3-D hexahedral bar of 4 x 4 section; the two within 2% of each other.
TEST(VerificationSolid2D, AxisymmetricRodImpactGivesRhoCVAsTheHexBar) {
  const int nx = 2, ny = 50;
  const double R = 2.0, L = 100.0, v0 = 1.0;
  const double c0 = std::sqrt(kE / kRho);
  std::string vel = "*INITIAL_VELOCITY_NODE\n";
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      vel += fmt::format("{:10d}{:10.6g}{:10.6g}{:10.6g}\n", 1 + i + (nx + 1) * j, 0.0, -v0, 0.0);
  const std::string sets = quadNodeSet(1, nx, ny, [](int, int j) { return j == 0; }) +
                           quadNodeSet(2, nx, ny, [](int i, int) { return i == 0; }) +
                           "*BOUNDARY_SPC_SET\n         1         0         0         1\n"
                           "*BOUNDARY_SPC_SET\n         2         0         1         0\n";
  auto axi = Simulation::fromText(
      "rod2d",
      quadDeck(nx, ny, 0.0, R, L, 15, false, kSteel + termination(0.6 * L / c0) + sets + vel));
  axi->run();
  // The hexahedral bar: 2 x 50 x 2 elements on [0, 4] x [0, 100] x [0, 4].
  std::string hvel = "*INITIAL_VELOCITY_NODE\n";
  for (int n = 1; n <= 3 * 51 * 3; ++n)
    hvel += fmt::format("{:10d}{:10.6g}{:10.6g}{:10.6g}\n", n, 0.0, -v0, 0.0);
  const std::string hfixed = brickNodeSet(1, 2, ny, 2, [](int, int j, int) { return j == 0; }) +
                             "*BOUNDARY_SPC_SET\n         1         0         0         1\n";
  auto hex = Simulation::fromText(
      "rod_hex", crumple::testing::brickDeck(2, ny, 2, 4.0, L, 4.0,
                                             kSteel + termination(0.6 * L / c0) + hfixed + hvel));
  hex->run();
  const double want = -kRho * c0 * v0;
  const double s_axi = lowerFifthStress(*axi, L), s_hex = lowerFifthStress(*hex, L);
  EXPECT_NEAR(s_axi / want, 1.0, 0.03);
  EXPECT_NEAR(s_hex / want, 1.0, 0.03);
  EXPECT_NEAR(s_axi / s_hex, 1.0, 0.02);
  std::printf(
      "[ figure ] rod impact: sigma_yy axisymmetric %.5g, hexahedral %.5g, -rho c0 v0 "
      "%.5g (ratios %.4f, %.4f)\n",
      s_axi, s_hex, want, s_axi / want, s_hex / want);
}

// What 2D solids do not support is refused with its keyword.
TEST(VerificationSolid2D, RefusesWhatItDoesNotSupport) {
  auto refused = [](const std::string& name, const std::string& deck, const std::string& what) {
    try {
      Simulation::fromText(name, deck);
      ADD_FAILURE() << name << ": not refused";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refused("axi14", quadDeck(2, 2, 0, 1, 1, 14, false, kSteel + termination(1)), "ELFORM=14");
  refused("axi_stiffness_hg",
          quadDeck(2, 2, 0, 1, 1, 15, false,
                   kSteel + "*CONTROL_HOURGLASS\n         4\n" + termination(1)),
          "IHQ 4");
  refused("axi_negative_radius", quadDeck(2, 2, -1, 1, 1, 15, false, kSteel + termination(1)),
          "x = -1 < 0");
  refused("axi_rigid",
          quadDeck(2, 2, 0, 1, 1, 15, false,
                   "*MAT_RIGID\n         1   7.85e-6     210.0       0.3\n" + termination(1)),
          "no solid update a 2D solid can use");
}

}  // namespace
