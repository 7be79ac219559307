// The warping stiffness of the fully integrated shell (ELFORM 16 with *CONTROL_HOURGLASS IHQ 8,
// src/elements/shell_full.cpp) on the pretwisted beam of MacNeal & Harder ("A proposed standard
// set of problems to test finite element accuracy", Finite Elements in Analysis and Design 1
// (1985) 3-20): L = 12, width 1.1, thickness 0.32, twisted 90 degrees from root to tip,
// E = 29e6, nu = 0.22, clamped at the root, a unit tip load along y or z; reference tip
// deflections along the load 5.424e-3 (load in the tip's plane, along z) and 1.754e-3 (normal
// to it, along y). On the 24 x 4 mesh here each element is warped by 3.75 degrees of twist.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "harness.hpp"

namespace {

using crumple::testing::Simulation;
using crumple::testing::termination;

constexpr double kL = 12.0, kW = 1.1, kT = 0.32, kE = 29.0e6, kNu = 0.22, kRho = 7.3e-4;
constexpr int kNx = 24, kNy = 4;

// The first bending period of the flat strip about its weak axis (an upper bound of the
// twisted beam's): the load ramps over 4 of them and holds for 2.
double weakPeriod() {
  const double I = kW * kT * kT * kT / 12.0, A = kW * kT;
  const double f1 =
      1.8751 * 1.8751 / (2.0 * M_PI) * std::sqrt(kE * I / (kRho * A * std::pow(kL, 4)));
  return 1.0 / f1;
}

int nodeId(int i, int j) {
  return 1 + i + (kNx + 1) * j;
}

// The twisted beam with the tip load along `dof` (2: y, 3: z) and `control` added.
std::string twistedBeam(int dof, const std::string& control, double twist = 0.5 * M_PI) {
  const double period = weakPeriod();
  std::string s = "*KEYWORD\n*TITLE\ntwisted beam\n" + control + termination(6.0 * period);
  s += fmt::format("*MAT_ELASTIC\n         1{:10.4g}{:10.4g}{:10.4g}\n", kRho, kE, kNu);
  s += fmt::format(
      "*SECTION_SHELL\n         1        16{:10.6g}         3\n{:10.4g}{:10.4g}{:10.4g}{:10.4g}\n",
      5.0 / 6.0, kT, kT, kT, kT);
  s += "*PART\nbeam\n         1         1         1\n*NODE\n";
  for (int j = 0; j <= kNy; ++j)
    for (int i = 0; i <= kNx; ++i) {
      const double x = kL * i / kNx, th = twist * i / kNx, w = kW * (double(j) / kNy - 0.5);
      s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", nodeId(i, j), x, w * std::cos(th),
                       w * std::sin(th));
    }
  s += "*ELEMENT_SHELL\n";
  int e = 1;
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i < kNx; ++i)
      s += fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", e++, 1, nodeId(i, j), nodeId(i + 1, j),
                       nodeId(i + 1, j + 1), nodeId(i, j + 1));
  s += "*BOUNDARY_SPC_NODE\n";
  for (int j = 0; j <= kNy; ++j)
    s += fmt::format(
        "{:10d}         0         1         1         1         1         1         1\n",
        nodeId(0, j));
  s += fmt::format(
      "*DEFINE_CURVE\n         1\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n", 0.0, 0.0,
      4.0 * period, 1.0, 1000.0, 1.0);
  s += "*LOAD_NODE_POINT\n";
  for (int j = 0; j <= kNy; ++j)
    s += fmt::format("{:10d}{:10d}         1{:10.4g}\n", nodeId(kNx, j), dof,
                     (j == 0 || j == kNy) ? 0.125 : 0.25);
  return s + "*END\n";
}

// The tip centre's mean deflection along the load over the hold.
double tipDeflection(const char* label, int dof, const std::string& control,
                     double twist = 0.5 * M_PI) {
  auto sim = Simulation::fromText(label, twistedBeam(dof, control, twist));
  const double hold = 4.0 * weakPeriod();
  const int64_t tip = nodeId(kNx, kNy / 2);
  double sum = 0.0, time = 0.0;
  sim->run([&](const crumple::solver::Solver& s) {
    if (s.time() <= hold) return;
    sum += (sim->x(tip, dof - 1) - sim->x0(tip, dof - 1)) * s.dt();
    time += s.dt();
  });
  // ELFORM 16 has no hourglass modes: its hourglass energy is nil, and the work of its one
  // stabilisation, the drilling constraint, is booked apart (docs/theory.md, "Drilling
  // constraint") and worked where the twisted mesh's neighbours meet at an angle.
  const auto e = sim->solver->energies();
  EXPECT_EQ(e.hourglass, 0.0) << label;
  if (twist != 0.0) {
    EXPECT_GT(e.drilling, 0.0) << label;
  }
  EXPECT_NEAR(e.ratio, 1.0, 0.01) << label;
  return sum / time;
}

// The tip's in-plane load is along z (the tip's width direction), its out-of-plane load along
// y. Figures (tip deflection / reference) on this 24 x 4 mesh: IHQ 8 1.047 (in-plane) and
// 1.018 (out-of-plane); without the warping stiffness (IHQ 1, the element flat-projected)
// 0.549 and 0.630. On 12 x 2 (MacNeal & Harder's mesh) IHQ 8 gives 1.177 and 1.089, flat 0.268
// and 0.433. The same mesh untwisted gives 0.996 of Timoshenko's cantilever (the harness).
TEST(VerificationShellWarping, TwistedBeamTipDeflection) {
  const std::string warping = "*CONTROL_HOURGLASS\n         8\n";
  const double I = kW * kT * kT * kT / 12.0, G = kE / (2 * (1 + kNu));
  const double straight = kL * kL * kL / (3 * kE * I) + kL / (5.0 / 6.0 * G * kW * kT);
  const double untwisted = tipDeflection("untwisted_z", 3, warping, 0.0) / straight;
  const double in_plane = tipDeflection("twisted_z_ihq8", 3, warping) / 5.424e-3;
  const double out_plane = tipDeflection("twisted_y_ihq8", 2, warping) / 1.754e-3;
  const double in_flat = tipDeflection("twisted_z_ihq1", 3, "") / 5.424e-3;
  const double out_flat = tipDeflection("twisted_y_ihq1", 2, "") / 1.754e-3;
  std::printf(
      "[ figure ] untwisted %.4f; twisted beam tip / reference: IHQ 8 in-plane %.4f "
      "out-of-plane %.4f; flat (IHQ 1) %.4f %.4f\n",
      untwisted, in_plane, out_plane, in_flat, out_flat);
  EXPECT_NEAR(untwisted, 1.0, 0.02);
  EXPECT_NEAR(in_plane, 1.0, 0.06);
  EXPECT_NEAR(out_plane, 1.0, 0.06);
  EXPECT_LT(in_flat, 0.7);
  EXPECT_LT(out_flat, 0.75);
}

}  // namespace
