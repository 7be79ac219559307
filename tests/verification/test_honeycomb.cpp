// *MAT_HONEYCOMB (026) in whole runs. One ELFORM 1 hexahedron (the unit cube) whose eight nodes
// all follow a prescribed homogeneous motion x = (I + s(t) G) X, so that the element's F is
// known exactly at every pass:
// - a crush along the material axis a (uniaxial strain, G = -e_x e_x) follows the curve LCA in
//   magnitude while loading (to 1e-6), unloads elastically with the interpolated modulus
//   E_aa = E_aau + beta (E - E_aau), reloads to the curve, and at V = VF stiffens to the
//   compacted isotropic material (the lateral stresses appear, K - 2G/3 times the strain; the
//   deviator is held at SIGY by the radial return); the curve given in relative volume and in
//   volumetric strain gives the same answer;
// - simple shear in the c-a plane is limited by LCS;
// - the same crush along a rotated material axis (AOPT 2 and AOPT 0 on a rotated cube) gives the
//   rotated stress of the crush along x;
// - a tensile strain TSEF erodes the element.
// Then a honeycomb block struck by a falling mass (a barrier-like curve: peak, plateau,
// compaction; MU 0.05): the internal energy is the kinetic energy lost, to 1%; and the run
// continues bitwise through a restart (tests/data/decks/honeycomb_barrier.k also runs at 1-4
// ranks in tests/parallel).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "harness.hpp"
#include "materials/laws/honeycomb.hpp"

using crumple::testing::Simulation;
using crumple::testing::termination;

namespace {

using Mat3 = std::array<double, 9>;  // row-major

// The compacted material: E 1000, PR 0.3 (K = 833.3, G = 384.6), SIGY 5, VF 0.2.
constexpr double kE = 1000.0, kNu = 0.3, kSigy = 5.0, kVf = 0.2;
constexpr double kK = kE / (3.0 * (1.0 - 2.0 * kNu)), kG = kE / (2.0 * (1.0 + kNu));
// Uncompacted moduli: E_aau 50, E_bbu 40, E_ccu 30, G_abu 10, G_bcu 8, G_cau 6.
constexpr double kEu[3] = {50.0, 40.0, 30.0}, kGu[3] = {10.0, 8.0, 6.0};

// LCA: the limit vs volumetric strain 1 - V (first abscissa <= 0): 1 in tension and to 0.5, then
// rising to 1.5 at 0.7 and 4 at VF (0.8). The same curve vs relative volume V.
const std::vector<double> kStrainX{-1.0, 0.0, 0.5, 0.7, 0.8, 1.0},
    kStrainY{1.0, 1.0, 1.0, 1.5, 4.0, 20.0};
const std::vector<double> kVolumeX{0.0001, 0.2, 0.3, 0.5, 1.0, 2.0},
    kVolumeY{20.0 - 0.0001 * 80.0, 4.0, 1.5, 1.0, 1.0, 1.0};
// LCS: shear limit 0.3 at every volume.
constexpr double kShearLimit = 0.3;

double limitAt(double v) {
  const double e = 1.0 - v;
  std::size_t k = 0;
  while (k + 2 < kStrainX.size() && e >= kStrainX[k + 1]) ++k;
  return kStrainY[k] +
         (kStrainY[k + 1] - kStrainY[k]) * (e - kStrainX[k]) / (kStrainX[k + 1] - kStrainX[k]);
}

double beta(double v) {
  return std::clamp((1.0 - v) / (1.0 - kVf), 0.0, 1.0);
}

std::string curveCard(int id, const std::vector<double>& x, const std::vector<double>& y) {
  std::string s = fmt::format("*DEFINE_CURVE\n{:10d}\n", id);
  for (std::size_t k = 0; k < x.size(); ++k) s += fmt::format("{:20.12g}{:20.12g}\n", x[k], y[k]);
  return s;
}

struct HoneycombInput {
  int aopt = 2;
  std::array<double, 3> a{1, 0, 0}, d{0, 1, 0};
  bool volume_curve = false;  // LCA vs relative volume
  std::string mu = "       0.0";
  double tsef = 0.0;
};

// *MAT_HONEYCOMB 1 with LCA 7 (or 8, the relative-volume form), LCS 9, RO 1e-3.
std::string honeycombCards(const HoneycombInput& in) {
  std::string s = "*MAT_HONEYCOMB\n";
  s += fmt::format("{:10d}{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}{}{:10.4g}\n", 1, 1e-3, kE, kNu,
                   kSigy, kVf, in.mu, 0.0);
  s += fmt::format("{:10d}{:10d}{:10d}{:10d}{:10d}{:10d}{:10d}{:10d}\n", in.volume_curve ? 8 : 7, 0,
                   0, 9, 0, 0, 0, 0);
  s += fmt::format("{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10d}{:10d}\n", kEu[0], kEu[1],
                   kEu[2], kGu[0], kGu[1], kGu[2], in.aopt, 1);
  // Cards 4 and 5 free (comma) format, for the vectors' full precision.
  s += fmt::format("0.0,0.0,0.0,{:.17g},{:.17g},{:.17g}\n", in.a[0], in.a[1], in.a[2]);
  s += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},0.0\n", in.d[0], in.d[1], in.d[2], in.tsef);
  s += curveCard(7, kStrainX, kStrainY) + curveCard(8, kVolumeX, kVolumeY);
  s += curveCard(9, {0.0, 1.0}, {kShearLimit, kShearLimit});
  return s;
}

// The unit cube turned by R (nodes R X), its eight nodes driven along x = R (I + s(t) G) X
// (curve 90 is s(t) through the points `path`), no bulk viscosity.
std::string drivenCube(const std::string& material, const Mat3& R, const Mat3& G,
                       const std::vector<std::pair<double, double>>& path) {
  std::string s = "*KEYWORD\n" + material + termination(path.back().first);
  s += "*CONTROL_BULK_VISCOSITY\n       0.0       0.0\n";
  s += "*DEFINE_CURVE\n        90\n";
  for (const auto& [t, u] : path) s += fmt::format("{:20.12g}{:20.12g}\n", t, u);
  s += "*PART\nhoneycomb\n         1         1         1\n*SECTION_SOLID\n         1         1\n";
  s += "*NODE\n";
  std::string motion = "*BOUNDARY_PRESCRIBED_MOTION_NODE\n", spc = "*BOUNDARY_SPC_NODE\n";
  const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                            {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int n = 0; n < 8; ++n) {
    const double X[3] = {double(corner[n][0]), double(corner[n][1]), double(corner[n][2])};
    double x[3], u[3], gx[3];
    for (int i = 0; i < 3; ++i) gx[i] = G[3 * i] * X[0] + G[3 * i + 1] * X[1] + G[3 * i + 2] * X[2];
    for (int i = 0; i < 3; ++i) {
      x[i] = R[3 * i] * X[0] + R[3 * i + 1] * X[1] + R[3 * i + 2] * X[2];
      u[i] = R[3 * i] * gx[0] + R[3 * i + 1] * gx[1] + R[3 * i + 2] * gx[2];
    }
    s += fmt::format("{},{:.17g},{:.17g},{:.17g}\n", n + 1, x[0], x[1], x[2]);
    for (int i = 0; i < 3; ++i) {
      if (std::abs(u[i]) < 1e-14)
        spc += fmt::format("{},0,{},{},{}\n", n + 1, int(i == 0), int(i == 1), int(i == 2));
      else
        motion += fmt::format("{},{},2,90,{:.17g}\n", n + 1, i + 1, u[i]);
    }
  }
  s += "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n";
  return s + motion + spc + "*END\n";
}

constexpr Mat3 kIdentity{1, 0, 0, 0, 1, 0, 0, 0, 1};
const Mat3 kCrushX{-1, 0, 0, 0, 0, 0, 0, 0, 0};

// Load to s = 0.6 (the plateau), unload slowly to 0.597 (about 60 passes: the stress crosses
// from -1 to the tension limit +1 elastically), reload through VF (s = 0.8) and slowly on to
// 0.84 (the compacted material's elastic passes before it yields).
const std::vector<std::pair<double, double>> kCrushPath{
    {0.0, 0.0}, {0.6, 0.6}, {0.65, 0.597}, {0.9, 0.8}, {1.3, 0.84}};

// The element's global stress at each pass and the relative volume of that pass (the positions
// the pass started from, those the previous cycle left).
struct Pass {
  double v;
  std::array<double, 6> s;
};

std::vector<Pass> runPasses(Simulation& sim, const std::function<double(const Simulation&)>& vol) {
  std::vector<Pass> passes;
  double v_prev = vol(sim);
  sim.run([&](const crumple::solver::Solver&) {
    Pass p{v_prev, {}};
    for (int k = 0; k < 6; ++k) p.s[std::size_t(k)] = sim.sd.solid_blocks.at(0).sigAt(k, 0);
    passes.push_back(p);
    v_prev = vol(sim);
  });
  return passes;
}

double lengthX(const Simulation& sim) {
  return sim.x(2, 0) - sim.x(1, 0);
}

}  // namespace

// The crush along a: the curve in magnitude while loading; elastic unloading and reloading with
// E_aa(beta(V)) (the strain increment of a pass is that of the mid-step length, 2 dx / (x_n +
// x_n-1)); at VF the compacted isotropic material.
TEST(VerificationHoneycomb, CrushAlongAFollowsTheCurveAndCompacts) {
  auto sim = Simulation::fromText("hc_crush",
                                  drivenCube(honeycombCards({}), kIdentity, kCrushX, kCrushPath));
  const auto passes = runPasses(*sim, lengthX);
  ASSERT_GT(passes.size(), 500u);
  double worst_plateau = 0.0, worst_unload = 0.0, worst_lateral = 0.0;
  int on_plateau = 0, unloaded = 0;
  bool touched = false, compacted = false;
  double sigma_vf = 0.0, sum_de = 0.0;  // stress at the last uncompacted pass, strain since
  double v_min = 1.0;
  for (std::size_t n = 1; n < passes.size(); ++n) {
    const double v = passes[n].v, v_old = passes[n - 1].v;
    const double sxx = passes[n].s[0];
    const double de = 2.0 * (v - v_old) / (v + v_old);
    if (v <= kVf) {
      if (!compacted) sigma_vf = passes[n - 1].s[0];
      compacted = true;
      sum_de += de;
      continue;
    }
    worst_lateral =
        std::max({worst_lateral, std::abs(passes[n].s[1]), std::abs(passes[n].s[2]),
                  std::abs(passes[n].s[3]), std::abs(passes[n].s[4]), std::abs(passes[n].s[5])});
    const double limit = limitAt(v);
    if (v < v_min) {  // loading beyond the furthest crush: on the curve once it reached it
      v_min = v;
      touched = touched || std::abs(sxx) >= limit * (1.0 - 1e-12);
      if (touched) {
        worst_plateau = std::max(worst_plateau, std::abs(-sxx - limit) / limit);
        ++on_plateau;
      }
    } else if (v > v_old) {  // unloading: the interpolated modulus, until the tension limit
      const double want = passes[n - 1].s[0] + (kEu[0] + beta(v) * (kE - kEu[0])) * de;
      if (std::abs(want) < limit * (1.0 - 1e-9)) {
        worst_unload = std::max(worst_unload, std::abs(sxx - want) / limit);
        ++unloaded;
      }
    }
  }
  EXPECT_GT(on_plateau, 300);
  EXPECT_GT(unloaded, 20);
  EXPECT_LT(worst_plateau, 1e-6);
  EXPECT_LT(worst_unload, 1e-6);
  EXPECT_EQ(worst_lateral, 0.0);  // uncoupled: no stress but sigma_aa before compaction
  ASSERT_TRUE(compacted);
  EXPECT_NEAR(sigma_vf, -limitAt(kVf + 1e-9), 0.1);
  // Compacted: sigma = sigma(VF) + isotropic increments; with SIGY 5 and 2G de reaching it after
  // de = 0.0065, the end state has sigma_xx - sigma_yy = -SIGY and the mean stress
  // sigma(VF) / 3 + K sum(de).
  const auto& end = passes.back().s;
  EXPECT_LT(sum_de, -0.03);
  EXPECT_NEAR(end[0] - end[1], -kSigy, 1e-9 * kSigy);
  EXPECT_NEAR(end[1], end[2], 1e-12);
  const double mean = (end[0] + end[1] + end[2]) / 3.0;
  EXPECT_NEAR(mean, sigma_vf / 3.0 + kK * sum_de, 1e-6 * std::abs(mean));
  // Far stiffer than the curve's 25 per unit strain before VF: the compacted material.
  EXPECT_LT(end[0], sigma_vf - 20.0);
  EXPECT_GT(sim->sd.solid_blocks.at(0).eps_p[0], 0.0);
}

// Right after VF the compacted material is elastic: sigma_yy = (K - 2G/3) sum(de) (no lateral
// stress before), sigma_xx - sigma(VF) = (K + 4G/3) sum(de), until the deviator reaches SIGY
// (the curve's 4 at VF is already most of SIGY 5).
TEST(VerificationHoneycomb, CompactedMaterialIsIsotropicElastic) {
  auto sim = Simulation::fromText("hc_compact",
                                  drivenCube(honeycombCards({}), kIdentity, kCrushX, kCrushPath));
  const auto passes = runPasses(*sim, lengthX);
  double sigma_vf = 0.0, sum_de = 0.0;
  int checked = 0;
  bool compacted = false;
  for (std::size_t n = 1; n < passes.size(); ++n) {
    const double v = passes[n].v, v_old = passes[n - 1].v;
    if (v > kVf) continue;
    if (!compacted) sigma_vf = passes[n - 1].s[0];
    compacted = true;
    sum_de += 2.0 * (v - v_old) / (v + v_old);
    // sigma_xx - sigma_yy = sigma(VF) + 2 G sum(de): elastic until it reaches -SIGY.
    if (std::abs(sigma_vf + 2.0 * kG * sum_de) >= 0.999 * kSigy) break;
    EXPECT_NEAR(passes[n].s[1], (kK - 2.0 * kG / 3.0) * sum_de, 1e-9);
    EXPECT_NEAR(passes[n].s[0], sigma_vf + (kK + 4.0 * kG / 3.0) * sum_de, 1e-9);
    ++checked;
  }
  EXPECT_GT(checked, 3);
}

// LCA given vs relative volume (first abscissa > 0) and vs volumetric strain: the same run.
TEST(VerificationHoneycomb, CurveOfRelativeVolumeOrVolumetricStrain) {
  const std::vector<std::pair<double, double>> path{{0.0, 0.0}, {0.75, 0.75}};
  HoneycombInput by_volume;
  by_volume.volume_curve = true;
  auto a = Simulation::fromText("hc_strain_curve",
                                drivenCube(honeycombCards({}), kIdentity, kCrushX, path));
  auto b = Simulation::fromText("hc_volume_curve",
                                drivenCube(honeycombCards(by_volume), kIdentity, kCrushX, path));
  const auto pa = runPasses(*a, lengthX), pb = runPasses(*b, lengthX);
  ASSERT_EQ(pa.size(), pb.size());
  double worst = 0.0;
  for (std::size_t n = 0; n < pa.size(); ++n)
    worst = std::max(worst, std::abs(pa[n].s[0] - pb[n].s[0]));
  EXPECT_LT(worst, 1e-12);
  EXPECT_NEAR(pa.back().s[0], -limitAt(pa.back().v), 1e-12);
}

// Simple shear x = X + s Z (V = 1, beta = 0): sigma_ca = G_cau s up to LCS's 0.3, then held
// there; no other component.
TEST(VerificationHoneycomb, ShearIsLimitedByLcs) {
  const Mat3 shear_zx{0, 0, 1, 0, 0, 0, 0, 0, 0};
  auto sim = Simulation::fromText(
      "hc_shear", drivenCube(honeycombCards({}), kIdentity, shear_zx, {{0.0, 0.0}, {0.5, 0.1}}));
  // The shear of the pass: the x offset of the top face.
  const auto passes = runPasses(*sim, [](const Simulation& s) { return s.x(5, 0) - s.x(1, 0); });
  double worst = 0.0, worst_other = 0.0;
  int capped = 0;
  for (const auto& p : passes) {
    const double want = std::min(kGu[2] * p.v, kShearLimit);
    worst = std::max(worst, std::abs(p.s[5] - want));
    capped += p.s[5] == kShearLimit;
    for (int k : {0, 1, 2, 3, 4})
      worst_other = std::max(worst_other, std::abs(p.s[std::size_t(k)]));
  }
  EXPECT_LT(worst, 1e-9 * kShearLimit);
  EXPECT_GT(capped, 100);
  EXPECT_LT(worst_other, 1e-12);
}

namespace {

// A rotation by 40 degrees about (1, 2, 3) / |.|.
Mat3 rotation() {
  const double n = std::sqrt(14.0), ax = 1.0 / n, ay = 2.0 / n, az = 3.0 / n;
  const double t = 40.0 * M_PI / 180.0, c = std::cos(t), s = std::sin(t), C = 1.0 - c;
  return {c + ax * ax * C,      ax * ay * C - az * s, ax * az * C + ay * s,
          ay * ax * C + az * s, c + ay * ay * C,      ay * az * C - ax * s,
          az * ax * C - ay * s, az * ay * C + ax * s, c + az * az * C};
}

// R s R^T in Voigt order.
std::array<double, 6> turned(const Mat3& R, const std::array<double, 6>& s) {
  const double m[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  double out[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) out[i][j] += R[3 * i + k] * m[k][l] * R[3 * j + l];
  return {out[0][0], out[1][1], out[2][2], out[0][1], out[1][2], out[2][0]};
}

}  // namespace

// The crush of the first test on the cube turned by R, along R e_x: with AOPT 2 (A = R e_x,
// D = R e_y) and with AOPT 0 (the edges 1-2, 1-4 of the turned cube) the stress is R sigma R^T
// of the unturned run at every pass, through the plateau, unloading and compaction.
TEST(VerificationHoneycomb, RotatedMaterialAxesGiveTheRotatedCrush) {
  const Mat3 R = rotation();
  auto ref = Simulation::fromText("hc_frame_ref",
                                  drivenCube(honeycombCards({}), kIdentity, kCrushX, kCrushPath));
  const auto base = runPasses(*ref, lengthX);
  for (int aopt : {2, 0}) {
    HoneycombInput in;
    in.aopt = aopt;
    in.a = {R[0], R[3], R[6]};
    in.d = {R[1], R[4], R[7]};
    auto sim = Simulation::fromText("hc_frame_aopt" + std::to_string(aopt),
                                    drivenCube(honeycombCards(in), R, kCrushX, kCrushPath));
    const auto passes = runPasses(*sim, [](const Simulation& s) {
      double d2 = 0.0;
      for (int c = 0; c < 3; ++c) d2 += std::pow(s.x(2, c) - s.x(1, c), 2);
      return std::sqrt(d2);
    });
    ASSERT_EQ(passes.size(), base.size()) << "AOPT " << aopt;
    double worst = 0.0, scale = 0.0;
    for (std::size_t n = 0; n < passes.size(); ++n) {
      const auto want = turned(R, base[n].s);
      for (std::size_t k = 0; k < 6; ++k) {
        worst = std::max(worst, std::abs(passes[n].s[k] - want[k]));
        scale = std::max(scale, std::abs(want[k]));
      }
    }
    EXPECT_GT(scale, 20.0);
    EXPECT_LT(worst, 1e-9 * scale) << "AOPT " << aopt;
  }
}

// TSEF 0.1: a pull along a erodes the element when the stretch of a reaches 1.1, not before.
TEST(VerificationHoneycomb, TensileStrainErodes) {
  HoneycombInput in;
  in.tsef = 0.1;
  const Mat3 pull{1, 0, 0, 0, 0, 0, 0, 0, 0};
  auto sim = Simulation::fromText(
      "hc_tsef", drivenCube(honeycombCards(in), kIdentity, pull, {{0.0, 0.0}, {0.2, 0.2}}));
  double stretch_at_erosion = 0.0, v_prev = 1.0;
  sim->run([&](const crumple::solver::Solver&) {
    if (stretch_at_erosion == 0.0 && !sim->sd.solid_blocks.at(0).active[0])
      stretch_at_erosion = v_prev;
    v_prev = lengthX(*sim);
  });
  EXPECT_GE(stretch_at_erosion, 1.1);
  EXPECT_LT(stretch_at_erosion, 1.1 + 1e-3);
}

namespace {

// A 2 x 2 x 3 block of honeycomb (0.1 x 0.1 x 0.15: the a axis along z, AOPT 2) on its base
// (the face z = 0 held), struck on its top face by a rigid plate of mass 0.02 (the 9 top nodes
// as one nodal rigid body) falling at 2.345: KE 0.055. A barrier-like curve vs volumetric strain: a
// peak of 60 at 0.02, a plateau of 50 to 0.6, compaction rising to 200 at 0.7 and 2000 at VF 0.2
// (strain 0.8); the lateral directions 5 to 10, the shears 8 to 30 (LCB = LCC 12, LCS 13). With no
// Poisson coupling before compaction the block crushes in uniaxial strain: the work per unit
// volume to strain e is the area under the curve, 29.75 at 0.6 and 42.25 at 0.7 (V0 = 0.0015:
// 0.045, 0.063), so the mass stops in the rising part, near e = 0.665. MU 0.05 (blank), no bulk
// viscosity (BULK 0).
std::string fallingMass(double end_time) {
  std::string s = termination(end_time);
  s += "*MAT_HONEYCOMB\n";
  // MID RO E PR SIGY VF MU (blank: 0.05) BULK; LCA 11; the uncompacted moduli, AOPT 2; A = e_z,
  // D = e_x.
  s += fmt::format("{:10d}{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10}{:10.4g}\n", 1, 2.0e-4,
                   5.0e3, 0.3, 200.0, 0.2, "", 0.0);
  s += fmt::format("{:10d}{:10d}{:10d}{:10d}\n", 11, 12, 12, 13);
  s += fmt::format("{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10d}{:10d}\n", 4000.0, 500.0,
                   500.0, 200.0, 200.0, 200.0, 2, 1);
  s += fmt::format("{:10}{:10}{:10}{:10.4g}{:10.4g}{:10.4g}\n", "", "", "", 0.0, 0.0, 1.0);
  s += fmt::format("{:10.4g}{:10.4g}{:10.4g}\n", 1.0, 0.0, 0.0);
  s += curveCard(11, {-0.5, 0.0, 0.02, 0.05, 0.6, 0.7, 0.8},
                 {40.0, 0.0, 60.0, 50.0, 50.0, 200.0, 2000.0});
  s += curveCard(12, {0.0, 0.7, 0.8}, {5.0, 10.0, 500.0});  // the lateral directions
  s += curveCard(13, {0.0, 0.8}, {8.0, 30.0});              // the shears
  const int nx = 2, ny = 2, nz = 3;
  auto id = [&](int i, int j, int k) { return 1 + i + (nx + 1) * (j + (ny + 1) * k); };
  std::string mass = "*ELEMENT_MASS\n", vel = "*INITIAL_VELOCITY_NODE\n";
  int m = 1;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      mass += fmt::format("{:8d}{:8d}{:16.9g}\n", m++, id(i, j, nz), 0.02 / 9.0);
      vel += fmt::format("{:8d}{:10.4g}{:10.4g}{:10.4g}\n", id(i, j, nz), 0.0, 0.0, -2.345);
    }
  s += mass + vel;
  // The base held; the mass is a rigid plate: the top nodes form one nodal rigid body.
  s += crumple::testing::brickNodeSet(11, nx, ny, nz, [](int, int, int k) { return k == 0; });
  s += "*BOUNDARY_SPC_SET\n        11         0         1         1         1\n";
  s += crumple::testing::brickNodeSet(12, nx, ny, nz, [](int, int, int k) { return k == nz; });
  s += "*CONSTRAINED_NODAL_RIGID_BODY\n        70         0        12\n";
  return crumple::testing::brickDeck(nx, ny, nz, 0.1, 0.1, 0.15, s);
}

}  // namespace

TEST(VerificationHoneycomb, FallingMassEnergyBalance) {
  auto sim = Simulation::fromText("hc_falling_mass", fallingMass(0.12));
  const double ke0 = sim->solver->energies().kinetic;
  EXPECT_NEAR(ke0, 0.5 * 0.02 * 2.345 * 2.345, 1e-6);
  double top_min = 1.0;
  // Node 32: the middle of the top face.
  sim->run([&](const crumple::solver::Solver&) { top_min = std::min(top_min, sim->x(32, 2)); });
  const auto e = sim->solver->energies();
  const double lost = ke0 - e.kinetic;
  EXPECT_GT(lost, 0.9 * ke0);  // stopped: what comes back is the small elastic unloading
  EXPECT_NEAR(e.internal, lost, 0.01 * lost);
  EXPECT_LT(e.hourglass, 0.01 * lost);
  // Crushed into the curve's rising part, short of compaction.
  const double strain = 1.0 - top_min / 0.15;
  EXPECT_GT(strain, 0.6);
  EXPECT_LT(strain, 0.72);
}
