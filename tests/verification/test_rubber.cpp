// Hyperelastic rubbers in whole runs (*MAT_027 Mooney-Rivlin, *MAT_031 Frazer-Nash, *MAT_007
// Blatz-Ko, *MAT_077_O Ogden on one-point hexahedra): one hex in uniaxial stretch, simple shear
// and equibiaxial stretch, its Cauchy stress (and for Blatz-Ko and Ogden the force on the pulled
// face) against the law's closed form at the deformation the nodes show; a stretched block
// turned rigidly keeps its principal stresses and its energy (objectivity); the internal energy
// after a slow stretch is W V0, the work of the boundary forces; and the LSTC Frazer-Nash test
// deck (../shared/decks/dynakw_fn_rubber, the corpus) runs to its end and gives its energy back.
#include <gtest/gtest.h>

#include <filesystem>

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "harness.hpp"
#include "materials/hyperelastic.hpp"
#include "materials/laws/blatz_ko.hpp"
#include "materials/laws/frazer_nash.hpp"
#include "materials/laws/mooney_rivlin.hpp"
#include "materials/laws/ogden.hpp"

using crumple::testing::brickDeck;
using crumple::testing::brickNodeSet;
using crumple::testing::Simulation;
using crumple::testing::termination;
using crumple::testing::uniaxialPull;

namespace {

// A = 0.5, B = 0.2 (G = 1.4), PR = 0.49, RO = 1e-3: shear waves cross the unit cube in
// 0.027, so stretches over a time of 1 are quasi-static.
const std::string kMooney =
    "*MAT_MOONEY-RIVLIN_RUBBER\n"
    "         1     0.001      0.49       0.5       0.2\n"
    "       0.0       0.0       0.0         0\n";
constexpr double kA = 0.5, kB = 0.2, kNu = 0.49;

// Mooney-Rivlin's Cauchy stress at a diagonal F = diag(l) (Theory Manual, Material Model 27):
// sigma_i = 2/J [(A + I1 B) l_i^2 - B l_i^4 + I3 W3], W3 = -2 C I3^-3 + 2 D (I3 - 1).
std::array<double, 3> mooneyPrincipal(const std::array<double, 3>& l) {
  const double C = 0.5 * kA + kB;
  const double D = (kA * (5 * kNu - 2) + kB * (11 * kNu - 5)) / (2 * (1 - 2 * kNu));
  const double J = l[0] * l[1] * l[2], I3 = J * J;
  const double b[3] = {l[0] * l[0], l[1] * l[1], l[2] * l[2]};
  const double I1 = b[0] + b[1] + b[2];
  const double w3 = -2 * C / (I3 * I3 * I3) + 2 * D * (I3 - 1);
  std::array<double, 3> s{};
  for (int i = 0; i < 3; ++i) s[i] = 2 / J * ((kA + I1 * kB) * b[i] - kB * b[i] * b[i] + I3 * w3);
  return s;
}

// W of Mooney-Rivlin at principal stretches l.
double mooneyEnergy(const std::array<double, 3>& l) {
  const double C = 0.5 * kA + kB;
  const double D = (kA * (5 * kNu - 2) + kB * (11 * kNu - 5)) / (2 * (1 - 2 * kNu));
  const double b[3] = {l[0] * l[0], l[1] * l[1], l[2] * l[2]};
  const double I1 = b[0] + b[1] + b[2], I2 = b[0] * b[1] + b[1] * b[2] + b[2] * b[0];
  const double I3 = b[0] * b[1] * b[2];
  return kA * (I1 - 3) + kB * (I2 - 3) + C * (1 / (I3 * I3) - 1) + D * (I3 - 1) * (I3 - 1);
}

double stressOf(const Simulation& sim, int k) {
  return sim.sd.solid_blocks.at(0).sigAt(k, 0);
}

// Node 8 of the unit cube sits at (1, 1, 1): its position is the diagonal of F.
std::array<double, 3> stretchesOf(const Simulation& sim) {
  return {sim.x(8, 0), sim.x(8, 1), sim.x(8, 2)};
}

// A unit cube whose faces x = 1 (and y = 1 when `biaxial`) move out by `stretch` - 1 over time
// 1 (displacement ramp), then held for `hold`, on rollers on x = 0, y = 0, z = 0, the other faces
// free.
std::string stretchDeck(const std::string& material, double stretch, bool biaxial,
                        double hold = 0.0) {
  std::string s = material + termination(1.0 + hold);
  s += fmt::format("*DEFINE_CURVE\n{:10d}\n{:20.12g}{:20.12g}\n{:20.12g}{:20.12g}\n", 90, 0.0, 0.0,
                   1.0, stretch - 1.0);
  if (hold > 0.0) s += fmt::format("{:20.12g}{:20.12g}\n", 1.0 + hold, stretch - 1.0);
  for (int d = 0; d < (biaxial ? 2 : 1); ++d) {
    s += brickNodeSet(1 + d, 1, 1, 1, [d](int i, int j, int) { return (d == 0 ? i : j) == 1; });
    s += fmt::format("*BOUNDARY_PRESCRIBED_MOTION_SET\n{:10d}{:10d}{:10d}{:10d}{:10.1f}\n", 1 + d,
                     1 + d, 2, 90, 1.0);
  }
  return brickDeck(1, 1, 1, 1.0, 1.0, 1.0, s + crumple::testing::rollersOnLowFaces());
}

}  // namespace

// Uniaxial stretch to 1.5: the lateral stress vanishes, sigma_xx is the law's at the stretches
// the nodes show, and close to the incompressible closed form 2 (l^2 - 1/l)(A + B/l) = 2.0056 at
// l = 1.5 (PR = 0.49 lets the volume grow a little). The internal energy is W V0 and equals the
// work of the pulling face (external work), the kinetic energy being negligible.
TEST(VerificationRubber, MooneyRivlinUniaxialStretchAndEnergy) {
  auto sim = Simulation::fromText("mr_uniaxial", stretchDeck(kMooney, 1.5, false));
  sim->run();
  const auto l = stretchesOf(*sim);
  EXPECT_NEAR(l[0], 1.5, 1e-9);
  const auto want = mooneyPrincipal(l);
  EXPECT_NEAR(stressOf(*sim, 0), want[0], 2e-3 * want[0]);
  EXPECT_LT(std::abs(stressOf(*sim, 1)), 5e-3 * want[0]);
  EXPECT_LT(std::abs(stressOf(*sim, 2)), 5e-3 * want[0]);
  const double closed = 2 * (1.5 * 1.5 - 1 / 1.5) * (kA + kB / 1.5);
  EXPECT_NEAR(closed, 2.00556, 1e-5);
  EXPECT_NEAR(stressOf(*sim, 0), closed, 0.02 * closed);
  const auto e = sim->solver->energies();
  const double stored = mooneyEnergy(l);  // V0 = 1
  EXPECT_NEAR(e.internal, stored, 0.01 * stored);
  EXPECT_NEAR(e.external_work, e.internal + e.kinetic + e.hourglass, 0.01 * stored);
}

// Equibiaxial stretch to 1.3 in x and y: sigma_xx = sigma_yy, sigma_zz free (zero), each the
// law's answer; within 3% of the incompressible 2 (l^2 - l^-4)(A + B l^2) = 2.2456 (PR = 0.49).
TEST(VerificationRubber, MooneyRivlinEquibiaxialStretch) {
  auto sim = Simulation::fromText("mr_biaxial", stretchDeck(kMooney, 1.3, true));
  sim->run();
  const auto l = stretchesOf(*sim);
  const auto want = mooneyPrincipal(l);
  EXPECT_NEAR(stressOf(*sim, 0), want[0], 2e-3 * want[0]);
  EXPECT_NEAR(stressOf(*sim, 1), want[1], 2e-3 * want[0]);
  EXPECT_LT(std::abs(stressOf(*sim, 2)), 5e-3 * want[0]);
  const double closed = 2 * (1.3 * 1.3 - std::pow(1.3, -4)) * (kA + kB * 1.3 * 1.3);
  EXPECT_NEAR(closed, 2.24563, 1e-5);
  EXPECT_NEAR(stressOf(*sim, 0), closed, 0.03 * closed);
  const double stored = mooneyEnergy(l);
  EXPECT_NEAR(sim->solver->energies().internal, stored, 0.01 * stored);
}

namespace {

// Every node of the unit cube driven (displacement curves, VAD = 2) through x(t) = M(t) X with
// M(t) given at `times`: homogeneous deformation, no inertia question.
std::string drivenCube(const std::string& material, const std::vector<double>& times,
                       const std::vector<std::array<double, 9>>& M) {
  std::string s = material + termination(times.back());
  std::string motion = "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i) {
        const int node = 1 + i + 2 * j + 4 * k;
        const double X[3] = {double(i), double(j), double(k)};
        for (int c = 0; c < 3; ++c) {
          const int lcid = 100 + 3 * node + c;
          s += fmt::format("*DEFINE_CURVE\n{:10d}\n", lcid);
          for (std::size_t t = 0; t < times.size(); ++t) {
            const auto& m = M[t];
            const double x = m[3 * c] * X[0] + m[3 * c + 1] * X[1] + m[3 * c + 2] * X[2];
            s += fmt::format("{:20.12g}{:20.12g}\n", times[t], x - X[c]);
          }
          motion += fmt::format("{:10d}{:10d}{:10d}{:10d}{:10.1f}\n", node, c + 1, 2, lcid, 1.0);
        }
      }
  return brickDeck(1, 1, 1, 1.0, 1.0, 1.0, s + motion);
}

// The cube of `material` in simple shear x += gamma z, gamma 0.04 t over [0, 1] to 0.4, held to
// 1.2 (every node driven), run to its end.
std::unique_ptr<Simulation> simpleShear(const std::string& name, const std::string& material) {
  std::vector<double> times;
  std::vector<std::array<double, 9>> M;
  for (int t = 0; t <= 12; ++t) {
    times.push_back(0.1 * t);
    M.push_back({1, 0, 0.04 * std::min(t, 10), 0, 1, 0, 0, 0, 1});
  }
  auto sim = Simulation::fromText(name, drivenCube(material, times, M));
  sim->run();
  return sim;
}

}  // namespace

// Simple shear x += gamma z to gamma = 0.4 over [0, 1], held to 1.2 (every node driven):
// Mooney-Rivlin's closed form (J = 1) sigma_xz = 2 (A + B) gamma = 0.56, sigma_xx - sigma_zz =
// 2 (A + B) gamma^2 = 0.224, sigma_yy - sigma_zz = 2 B gamma^2 = 0.064, at the gamma the nodes
// show.
TEST(VerificationRubber, MooneyRivlinSimpleShear) {
  auto sim = simpleShear("mr_shear", kMooney);
  const double gamma = sim->x(5, 0);  // node 5 starts at (0, 0, 1)
  EXPECT_NEAR(gamma, 0.4, 1e-9);
  EXPECT_NEAR(stressOf(*sim, 5), 2 * (kA + kB) * gamma, 1e-9);
  EXPECT_NEAR(stressOf(*sim, 0) - stressOf(*sim, 2), 2 * (kA + kB) * gamma * gamma, 1e-9);
  EXPECT_NEAR(stressOf(*sim, 1) - stressOf(*sim, 2), 2 * kB * gamma * gamma, 1e-9);
  EXPECT_NEAR(stressOf(*sim, 3), 0.0, 1e-12);
  EXPECT_NEAR(stressOf(*sim, 4), 0.0, 1e-12);
}

// Objectivity: a block stretched to diag(1.4, 0.9, 1.1) over [0, 1] and held to 1.25, then
// turned rigidly by 90 degrees about (1, 1, 1)/sqrt(3) over [1.25, 2.25] and held to 2.5. The
// stress at the end is R sigma R^T of the stress in the first hold (its principal values
// unchanged), and the internal energy has not moved: the hyperelastic stress is a function of F,
// with no rotation integrated step by step to drift.
TEST(VerificationRubber, RigidRotationKeepsThePrincipalStresses) {
  const double st[3] = {1.4, 0.9, 1.1};
  auto rotation = [](double a) {
    const double n = 1 / std::sqrt(3.0), c = std::cos(a), s = std::sin(a), v = 1 - c;
    return std::array<double, 9>{c + n * n * v,     n * n * v - n * s, n * n * v + n * s,
                                 n * n * v + n * s, c + n * n * v,     n * n * v - n * s,
                                 n * n * v - n * s, n * n * v + n * s, c + n * n * v};
  };
  std::vector<double> times;
  std::vector<std::array<double, 9>> M;
  auto add = [&](double t, double f, double a) {
    const auto R = rotation(a);
    std::array<double, 9> m{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[3 * i + j] = R[3 * i + j] * (1 + f * (st[j] - 1));
    times.push_back(t);
    M.push_back(m);
  };
  for (int t = 0; t <= 20; ++t) add(0.05 * t, t / 20.0, 0.0);
  for (int t = 0; t <= 40; ++t) add(1.25 + 0.025 * t, 1.0, t / 40.0 * M_PI / 2);
  add(2.5, 1.0, M_PI / 2);
  auto sim = Simulation::fromText("mr_rotate", drivenCube(kMooney, times, M));
  std::array<double, 6> before{};
  double e_before = 0.0;
  sim->run([&](const auto& solver) {
    if (solver.time() > 1.1 && solver.time() < 1.25) {
      for (int k = 0; k < 6; ++k) before[std::size_t(k)] = stressOf(*sim, k);
      e_before = solver.energies().internal;
    }
  });
  const auto want = mooneyPrincipal({st[0], st[1], st[2]});
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(before[std::size_t(k)], want[std::size_t(k)], 1e-6);
  for (int k = 3; k < 6; ++k) EXPECT_NEAR(before[std::size_t(k)], 0.0, 1e-6);
  // R sigma R^T with sigma diagonal: sum_k R_ik R_jk sigma_k.
  const auto R = rotation(M_PI / 2);
  const int comp[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  for (int v = 0; v < 6; ++v) {
    const int i = comp[v][0], j = comp[v][1];
    double s = 0.0;
    for (int k = 0; k < 3; ++k) s += R[3 * i + k] * R[3 * j + k] * want[std::size_t(k)];
    EXPECT_NEAR(stressOf(*sim, v), s, 1e-6) << "component " << v;
  }
  const double stored = mooneyEnergy({st[0], st[1], st[2]});
  EXPECT_NEAR(e_before, stored, 0.01 * stored);
  EXPECT_NEAR(sim->solver->energies().internal, stored, 0.01 * stored);
}

namespace {

// The law's stress and energy at F = diag(l) (a batch of one point).
template <class Law>
std::pair<std::array<double, 6>, crumple::materials::LeftCauchyGreen> lawAt(
    const Law& law, const std::array<double, 3>& l) {
  double f[9][1] = {{l[0]}, {0}, {0}, {0}, {l[1]}, {0}, {0}, {0}, {l[2]}}, s[6][1] = {},
         de[6][1] = {};
  crumple::materials::PointBatch pb;
  pb.n = 1;
  for (int k = 0; k < 6; ++k) pb.s[k] = s[k], pb.de[k] = de[k];
  for (int k = 0; k < 9; ++k) pb.F[k] = f[k];
  law.update(pb);
  std::array<double, 6> out{};
  for (int k = 0; k < 6; ++k) out[std::size_t(k)] = s[k][0];
  return {out, crumple::materials::leftCauchyGreen(pb, 0)};
}

}  // namespace

// Frazer-Nash in uniaxial stretch: the stress is the law's at the nodes' stretches, the lateral
// stress vanishes and the stored energy equals the work done.
TEST(VerificationRubber, FrazerNashUniaxialStretchAndEnergy) {
  const std::string fn =
      "*MAT_FRAZER_NASH_RUBBER_MODEL\n"
      "         1     0.001      0.49       1.0       0.3       0.0       0.0\n"
      "       0.0       0.0       0.4       0.0       1.0       0.0       0.0\n"
      "       0.0       0.0       0.0         0\n";
  auto sim = Simulation::fromText("fn_uniaxial", stretchDeck(fn, 1.4, false));
  sim->run();
  const auto l = stretchesOf(*sim);
  crumple::materials::FrazerNash::Params p;
  p.nu = 0.49;
  p.c[0] = 1.0;
  p.c[1] = 0.3;
  p.c[6] = 0.4;
  const auto law = crumple::materials::FrazerNash::make(p, {}, "");
  const auto [want, kin] = lawAt(law, l);
  EXPECT_NEAR(stressOf(*sim, 0), want[0], 2e-3 * want[0]);
  EXPECT_LT(std::abs(stressOf(*sim, 1)), 5e-3 * want[0]);
  const double stored = law.energy(kin);
  const auto e = sim->solver->energies();
  EXPECT_NEAR(e.internal, stored, 0.01 * stored);
  EXPECT_NEAR(e.external_work, e.internal + e.kinetic + e.hourglass, 0.01 * stored);
}

// The LSTC Frazer-Nash deck: one hex, C100, C110, C010, C020 fitted to its force curve, squeezed
// by 0.92 mm of its 10 mm height at t = 10 ms (*BOUNDARY_PRESCRIBED_MOTION_NODES along -z) and
// let back by t = 20. It runs to its end; at the peak its axial stress is the fitted law's at
// the stretches of the nodes (lateral faces free, so nearly uniaxial); at the end the elastic
// energy is given back.
TEST(VerificationRubber, FrazerNashLstcDeckRunsAndGivesItsEnergyBack) {
  // The corpus deck as published (never copied into the project).
  const std::filesystem::path deck =
      std::filesystem::path(CRUMPLE_SHARED_DIR) /
      "decks/dynakw_fn_rubber/test/full_files/mat_fn_rubber.element.k";
  if (!std::filesystem::exists(deck)) GTEST_SKIP() << deck << " is absent";
  Simulation sim(deck);
  double peak_energy = 0.0, peak_szz = 0.0;
  std::array<double, 3> peak_l{};
  // Nodes 1-4 are the top face (z = 10), 5-8 the bottom; node 2 sits at (7.5, 7.5, 10).
  sim.run([&](const auto& solver) {
    const double e = solver.energies().internal;
    if (e > peak_energy) {
      peak_energy = e;
      peak_szz = stressOf(sim, 2);
      peak_l = {(sim.x(2, 0) - sim.x(3, 0)) / 7.5, (sim.x(2, 1) - sim.x(1, 1)) / 7.5,
                (sim.x(2, 2) - sim.x(6, 2)) / 10.0};
    }
  });
  EXPECT_GE(sim.solver->time(), 20.0);
  EXPECT_NEAR(peak_l[2], 1.0 - 0.092, 2e-3);
  EXPECT_LT(peak_szz, 0.0);
  EXPECT_GT(peak_energy, 0.0);
  EXPECT_LT(std::abs(sim.solver->energies().internal), 0.01 * peak_energy);
  const auto& law = std::get<crumple::materials::FrazerNash>(sim.sd.solid_blocks.at(0).law);
  const auto [want, kin] = lawAt(law, peak_l);
  EXPECT_NEAR(peak_szz, want[2], 0.01 * std::abs(want[2]));
  EXPECT_LT(std::abs(want[0]), 0.05 * std::abs(want[2]));
  EXPECT_NEAR(peak_energy, law.energy(kin) * 7.5 * 7.5 * 10.0, 0.01 * peak_energy);
}

namespace {

// The x force on the pulled face x = 1 of the unit cube: the corners 1, 2, 5, 6 of its hex
// (nodes 2, 4, 6, 8) carry it.
double pulledFaceForce(const Simulation& sim) {
  const auto& b = sim.sd.solid_blocks.at(0);
  double f = 0.0;
  for (std::size_t corner : {1, 2, 5, 6}) f += sim.sd.slots[3 * (b.slot_offset + corner)];
  return std::abs(f);
}

// G = 1, RO = 1e-3 (Poisson's ratio 0.463 fixed: K = 13.2): waves cross the unit cube in 0.01.
const std::string kBlatzKo =
    "*MAT_BLATZ-KO_RUBBER\n"
    "         1     0.001       1.0\n";

}  // namespace

// Blatz-Ko stretched to 1.5 over [0, 1] and held to 1.2, its lateral faces free: the closed form of
// uniaxial stress (blatz_ko.hpp) has lateral stretches l^-nu, the force on the face G (l - l^(-1-2
// nu)) (nominal stress times the initial area 1) and the stored energy G/2 (l^2 - 1 + (l^-2nu - 1)
// / nu); the work of the pulling face equals it.
TEST(VerificationRubber, BlatzKoUniaxialForceAndEnergy) {
  auto sim = Simulation::fromText("bk_uniaxial", stretchDeck(kBlatzKo, 1.5, false, 0.2));
  sim->run();
  const auto l = stretchesOf(*sim);
  const double nu = crumple::materials::BlatzKo::kNu, L = 1.5;
  EXPECT_NEAR(l[0], L, 1e-9);
  EXPECT_NEAR(l[1], std::pow(L, -nu), 1e-3);
  EXPECT_NEAR(l[2], std::pow(L, -nu), 1e-3);
  const double force = L - std::pow(L, -1 - 2 * nu);
  EXPECT_NEAR(pulledFaceForce(*sim), force, 0.005 * force);
  EXPECT_NEAR(stressOf(*sim, 0) * l[1] * l[2], pulledFaceForce(*sim), 2e-3 * force);
  EXPECT_LT(std::abs(stressOf(*sim, 1)), 5e-3 * force);
  const double stored = 0.5 * (L * L - 1 + (std::pow(L, -2 * nu) - 1) / nu);
  const auto e = sim->solver->energies();
  EXPECT_NEAR(e.internal, stored, 0.01 * stored);
  EXPECT_NEAR(e.external_work, e.internal + e.kinetic + e.hourglass, 0.01 * stored);
}

namespace {

// MU 1.2, -0.1 and ALPHA 2.5, -2 (G = 1.6), PR = 0.49 (K = 79.5), RO = 1e-3.
const std::string kOgden =
    "*MAT_OGDEN_RUBBER\n"
    "         1     0.001      0.49\n"
    "       1.2      -0.1\n"
    "       2.5      -2.0\n";
constexpr std::array<double, 2> kOgdenMu{1.2, -0.1}, kOgdenAlpha{2.5, -2.0};

crumple::materials::Ogden ogdenLaw() {
  crumple::materials::Ogden::Params p;
  p.nu = 0.49;
  for (std::size_t t = 0; t < 2; ++t) p.mu[t] = kOgdenMu[t], p.alpha[t] = kOgdenAlpha[t];
  return crumple::materials::Ogden::make(p, {}, "");
}

}  // namespace

// Ogden stretched to 1.5 over [0, 1] and held to 1.2, its lateral faces free: sigma_xx is the
// closed form on the axes, [sum mu_j (lbar_1^alpha_j - mean_j) + K (J - 1)] / J, at the stretches
// the nodes show, the lateral stress vanishes, the face force is sigma_xx times the current area,
// within 1.5 % of the incompressible sum mu_j (l^(alpha_j - 1) - l^(-alpha_j/2 - 1)) (PR = 0.49),
// and the internal energy is W V0, the work of the pulling face.
TEST(VerificationRubber, OgdenUniaxialForceAndEnergy) {
  auto sim = Simulation::fromText("ogden_uniaxial", stretchDeck(kOgden, 1.5, false, 0.2));
  sim->run();
  const auto l = stretchesOf(*sim);
  EXPECT_NEAR(l[0], 1.5, 1e-9);
  const auto law = ogdenLaw();
  const double J = l[0] * l[1] * l[2];
  double sxx = law.moduli.bulk * (J - 1);
  for (std::size_t t = 0; t < 2; ++t) {
    double pw[3], mean = 0;
    for (std::size_t i = 0; i < 3; ++i)
      mean += (pw[i] = std::pow(l[i] / std::cbrt(J), kOgdenAlpha[t])) / 3;
    sxx += kOgdenMu[t] * (pw[0] - mean);
  }
  sxx /= J;
  EXPECT_NEAR(stressOf(*sim, 0), sxx, 2e-3 * sxx);
  EXPECT_LT(std::abs(stressOf(*sim, 1)), 5e-3 * sxx);
  EXPECT_LT(std::abs(stressOf(*sim, 2)), 5e-3 * sxx);
  EXPECT_NEAR(pulledFaceForce(*sim), sxx * l[1] * l[2], 2e-3 * sxx);
  double incompressible = 0.0;
  for (std::size_t t = 0; t < 2; ++t)
    incompressible +=
        kOgdenMu[t] * (std::pow(1.5, kOgdenAlpha[t] - 1) - std::pow(1.5, -kOgdenAlpha[t] / 2 - 1));
  EXPECT_NEAR(pulledFaceForce(*sim), incompressible, 0.015 * incompressible);
  const auto [want, kin] = lawAt(law, l);
  EXPECT_NEAR(want[0], sxx, 1e-12 * sxx);
  const double stored = law.energy(kin);  // V0 = 1
  const auto e = sim->solver->energies();
  EXPECT_NEAR(e.internal, stored, 0.01 * stored);
  EXPECT_NEAR(e.external_work, e.internal + e.kinetic + e.hourglass, 0.01 * stored);
}

// Simple shear x += gamma z to gamma = 0.4 (every node driven, J = 1): sigma_xz = D / (l1 + 1/l1),
// D = sum mu_j (l1^alpha_j - l1^-alpha_j), l1 = gamma/2 + sqrt(1 + gamma^2/4); sigma_xx -
// sigma_zz = gamma sigma_xz; sigma_yy = sum mu_j (1 - (l1^alpha_j + l1^-alpha_j + 1) / 3).
TEST(VerificationRubber, OgdenSimpleShear) {
  auto sim = simpleShear("ogden_shear", kOgden);
  const double gamma = sim->x(5, 0);
  EXPECT_NEAR(gamma, 0.4, 1e-9);
  const double l1 = gamma / 2 + std::sqrt(1 + gamma * gamma / 4);
  double d = 0.0, syy = 0.0;
  for (std::size_t t = 0; t < 2; ++t) {
    const double a = kOgdenAlpha[t], up = std::pow(l1, a), down = std::pow(l1, -a);
    d += kOgdenMu[t] * (up - down);
    syy += kOgdenMu[t] * (1 - (up + down + 1) / 3);
  }
  const double sxz = d / (l1 + 1 / l1);
  EXPECT_NEAR(stressOf(*sim, 5), sxz, 1e-9);
  EXPECT_NEAR(stressOf(*sim, 0) - stressOf(*sim, 2), gamma * sxz, 1e-9);
  EXPECT_NEAR(stressOf(*sim, 1), syy, 1e-9);
  EXPECT_NEAR(stressOf(*sim, 3), 0.0, 1e-12);
  EXPECT_NEAR(stressOf(*sim, 4), 0.0, 1e-12);
}
