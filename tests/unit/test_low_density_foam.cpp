// *MAT_LOW_DENSITY_FOAM (057) at a material point, driven by its deformation gradient, against
// the Theory Manual's model worked out by hand: the nominal stress of each principal direction
// from the curve (compression) or E (tension, cut off at TC), sigma_i = tau_i / (lambda_j
// lambda_k); hysteretic unloading by 1 - (1 - HU) (1 - (W / W_max)^SHAPE); no lateral stress in
// uniaxial compression; frame indifference. Then the deck reader: fields, defaults, the notes,
// the refusals and the errors naming file, line, card and field.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "hyperelastic_point.hpp"
#include "materials/materials.hpp"
#include "model/build.hpp"
#include "temp_dir.hpp"

namespace m = crumple::materials;

namespace {

using Mat3 = std::array<double, 9>;  // row-major
using Stress = std::array<double, 6>;

// The curve (engineering strain, nominal stress; compression positive): slopes 1, 0.125, 1.75,
// 10. E = 1 in tension.
const std::vector<double> kStrain{0.0, 0.1, 0.5, 0.7, 0.8}, kStress{0.0, 0.1, 0.15, 0.5, 1.5};

m::LowDensityFoam makeFoam(double hu = 1.0, double shape = 1.0, double tc = 1e20,
                           bool tear = false) {
  m::LowDensityFoam::Params p;
  p.young = p.E = 1.0;
  p.tc = tc;
  p.hu = hu;
  p.shape = shape;
  p.tear = tear;
  p.curve = 0;
  return m::LowDensityFoam::make(
      p,
      [](int32_t) {
        return m::CurveData{7, kStrain, kStress};
      },
      "");
}

// One point with its history (W_max, torn).
struct Point {
  double w_max = 0.0, torn = 0.0;

  // The stress at F; `modulus`, when given, receives the wave modulus the update reports.
  Stress at(const m::LowDensityFoam& law, const Mat3& F, double* modulus = nullptr) {
    return crumple::testing::hyper::stressAt(law, F, {&w_max, &torn}, modulus);
  }
  Stress diagonal(const m::LowDensityFoam& law, double l1, double l2 = 1.0, double l3 = 1.0) {
    return at(law, {l1, 0, 0, 0, l2, 0, 0, 0, l3});
  }
};

Mat3 mul(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return c;
}

// Rotation by angle a about the unit axis n (Rodrigues).
Mat3 rotation(const std::array<double, 3>& n, double a) {
  const double c = std::cos(a), s = std::sin(a), v = 1 - c;
  return {c + n[0] * n[0] * v,        n[0] * n[1] * v - n[2] * s, n[0] * n[2] * v + n[1] * s,
          n[1] * n[0] * v + n[2] * s, c + n[1] * n[1] * v,        n[1] * n[2] * v - n[0] * s,
          n[2] * n[0] * v - n[1] * s, n[2] * n[1] * v + n[0] * s, c + n[2] * n[2] * v};
}

// The symmetric tensor of Voigt s as a 3x3 matrix.
Mat3 matrixOf(const Stress& s) {
  return {s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2]};
}

}  // namespace

// Uniaxial compression F = diag(lambda, 1, 1), loading only: sigma_xx (= the nominal stress,
// the lateral stretches being 1) is the curve at eps = 1 - lambda, beyond its last point too
// (continued with the last slope), worked out by hand; the lateral stresses are zero.
TEST(LowDensityFoam, UniaxialCompressionFollowsTheCurveWithoutLateralStress) {
  const auto law = makeFoam();
  // (eps, nominal stress) by hand on the segments of kStrain/kStress.
  const std::vector<std::array<double, 2>> want{{0.05, 0.05}, {0.3, 0.125}, {0.45, 0.14375},
                                                {0.6, 0.325}, {0.75, 1.0},  {0.8, 1.5},
                                                {0.85, 2.0}};
  Point pt;
  for (const auto& [eps, nominal] : want) {
    const Stress s = pt.diagonal(law, 1.0 - eps);
    EXPECT_NEAR(s[0], -nominal, 1e-6 * nominal) << "eps " << eps;
    for (int k = 1; k < 6; ++k) EXPECT_EQ(s[std::size_t(k)], 0.0) << "eps " << eps;
  }
  // The step's modulus: the curve's stiffest slope (10) over E (1): lambda + 2 mu = 10.
  EXPECT_NEAR(law.moduli.bulk + 4.0 / 3.0 * law.moduli.shear, 10.0, 1e-12);
  EXPECT_NEAR(m::youngOf(law.moduli), 10.0, 1e-12);  // zero Poisson's ratio
}

// Each principal direction on its own, the Cauchy stress the nominal one over the area ratio:
// F = diag(0.7, 0.9, 1.2) gives sigma_x = -f(0.3) / (0.9 1.2), sigma_y = -f(0.1) / (0.7 1.2),
// sigma_z = E 0.2 / (0.7 0.9).
TEST(LowDensityFoam, PrincipalDirectionsAreUncoupled) {
  const auto law = makeFoam();
  Point pt;
  const Stress s = pt.diagonal(law, 0.7, 0.9, 1.2);
  EXPECT_NEAR(s[0], -0.125 / (0.9 * 1.2), 1e-14);
  EXPECT_NEAR(s[1], -0.1 / (0.7 * 1.2), 1e-14);
  EXPECT_NEAR(s[2], 0.2 / (0.7 * 0.9), 1e-14);
}

// HU = 0.2, SHAPE = 2: loading to eps = 0.6 stores W_max = Phi(0.6) = 0.005 + 0.05 + 0.02375
// (the trapezoids under the curve); unloading to eps = 0.3 (Phi = 0.0275) scales the curve's
// 0.125 by 1 - 0.8 (1 - (0.0275 / 0.07875)^2); reloading to 0.45 (Phi = 0.04765625) stays on
// that unloading law (BETA = 0), and back at eps = 0.6 the curve is met again; further loading
// follows the curve.
TEST(LowDensityFoam, HystereticUnloadingScalesTheCurveByTheEnergyRatio) {
  const auto law = makeFoam(0.2, 2.0);
  Point pt;
  EXPECT_NEAR(pt.diagonal(law, 0.4)[0], -0.325, 1e-12);
  const double w_max = 0.005 + 0.05 + 0.02375;
  EXPECT_NEAR(pt.w_max, w_max, 1e-14);
  auto factor = [&](double w) { return 1.0 - 0.8 * (1.0 - (w / w_max) * (w / w_max)); };
  EXPECT_NEAR(pt.diagonal(law, 0.7)[0], -0.125 * factor(0.0275), 1e-12);
  EXPECT_NEAR(-0.125 * factor(0.0275), -0.0371945074326027, 1e-15);
  EXPECT_NEAR(pt.diagonal(law, 0.55)[0], -0.14375 * factor(0.04765625), 1e-12);
  EXPECT_NEAR(pt.diagonal(law, 0.4)[0], -0.325, 1e-12);
  EXPECT_NEAR(pt.diagonal(law, 0.25)[0], -1.0, 1e-12);
  EXPECT_NEAR(pt.w_max, 0.15750, 1e-12);
  // Fully unloaded: no stress, W_max kept.
  EXPECT_EQ(pt.diagonal(law, 1.0)[0], 0.0);
  EXPECT_NEAR(pt.w_max, 0.15750, 1e-12);
}

// Tension: E (lambda - 1) up to TC = 0.08, then TC (FAIL = 0), back to E (lambda - 1) below
// it. FAIL = 1: the point tears at TC and carries no tension after, but still compression.
TEST(LowDensityFoam, TensionIsLinearUpToTheCutoff) {
  const auto stay = makeFoam(1.0, 1.0, 0.08, false);
  Point a;
  EXPECT_NEAR(a.diagonal(stay, 1.05)[0], 0.05, 1e-14);
  EXPECT_NEAR(a.diagonal(stay, 1.1)[0], 0.08, 1e-14);
  EXPECT_NEAR(a.diagonal(stay, 1.3)[0], 0.08, 1e-14);
  EXPECT_NEAR(a.diagonal(stay, 1.05)[0], 0.05, 1e-14);
  EXPECT_EQ(a.torn, 0.0);

  const auto tear = makeFoam(1.0, 1.0, 0.08, true);
  Point b;
  EXPECT_NEAR(b.diagonal(tear, 1.05)[0], 0.05, 1e-14);
  EXPECT_EQ(b.diagonal(tear, 1.1)[0], 0.0);
  EXPECT_EQ(b.torn, 1.0);
  EXPECT_EQ(b.diagonal(tear, 1.05)[0], 0.0);
  EXPECT_NEAR(b.diagonal(tear, 0.9)[0], -0.1, 1e-14);
}

// A rigid rotation Q after a general F: the stress at Q F is Q sigma Q^T (same principal
// values), to 1e-10 of its size; with hysteresis the history W_max is the same too.
TEST(LowDensityFoam, RigidRotationTurnsTheStress) {
  const auto law = makeFoam(0.3, 1.5);
  const Mat3 F{0.8, 0.1, 0.0, 0.05, 0.9, 0.1, 0.0, 0.02, 0.7};
  const double n = 1.0 / std::sqrt(14.0);
  const Mat3 Q = rotation({n, 2 * n, 3 * n}, 1.1);
  Point p0, p1;
  const Mat3 s0 = matrixOf(p0.at(law, F));
  const Mat3 s1 = matrixOf(p1.at(law, mul(Q, F)));
  const Mat3 Qt{Q[0], Q[3], Q[6], Q[1], Q[4], Q[7], Q[2], Q[5], Q[8]};
  const Mat3 turned = mul(mul(Q, s0), Qt);
  double size = 0.0;
  for (double v : s0) size = std::max(size, std::abs(v));
  ASSERT_GT(size, 0.05);
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(s1[std::size_t(k)], turned[std::size_t(k)], 1e-10 * size);
  EXPECT_NEAR(p1.w_max, p0.w_max, 1e-14);
}

// The wave modulus each point reports (kWaveModulus): rho c^2 = slope lambda_i / (lambda_j
// lambda_k) in the stiffest direction, the slope the larger of the curve's segment and the next.
// Uniaxial lambda = 0.5: max(10 x 0.5, E x 1 / 0.5) = 5; hydrostatic lambda = 0.25: 10 x 0.25 /
// 0.0625 = 40; unstrained: E = 1.
TEST(LowDensityFoam, WaveModulusFollowsTheStretches) {
  const auto law = makeFoam();
  EXPECT_NEAR(law.waveModulus({0.5, 1.0, 1.0}), 5.0, 1e-12);
  EXPECT_NEAR(law.waveModulus({0.25, 0.25, 0.25}), 40.0, 1e-12);
  EXPECT_NEAR(law.waveModulus({1.0, 1.0, 1.0}), 1.0, 1e-12);
  // The update reports it.
  double modulus = 0.0;
  Point p;
  const Stress s = p.at(law, {0.25, 0, 0, 0, 0.25, 0, 0, 0, 0.25}, &modulus);
  EXPECT_NEAR(modulus, 40.0, 1e-9);
  EXPECT_NEAR(s[0], -1.0 / 0.0625, 1e-9);
}

namespace {

const std::string kMesh =
    "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
    "*DEFINE_CURVE\n7\n0.0,0.0\n0.1,0.1\n0.5,0.15\n0.7,0.5\n0.8,1.5\n"
    "*SECTION_SOLID\n1,1\n*PART\nfoam\n1,1,5\n*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n";

std::string foamDeck(const std::string& card1, const std::string& card2 = "",
                     const std::string& keyword = "*MAT_LOW_DENSITY_FOAM") {
  return "*KEYWORD\n" + keyword + "\n$ MID RO E LCID TC HU BETA DAMP\n" + card1 +
         "\n$ SHAPE FAIL BVFLAG ED BETA1 KCON REF\n" + card2 + "\n" + kMesh;
}

bool noted(const crumple::model::Model& model, const std::string& field) {
  for (const auto& f : model.ignored)
    if (f.field == field) return true;
  return false;
}

}  // namespace

// The fields become the parameters with the Keyword Manual's defaults (TC 1e20, HU 1, SHAPE 1
// for blank or 0; BVFLAG 0: no bulk viscosity); a blank DAMP is noted as not applied; KCON sets
// the contact modulus; and the law serves solids only: a shell part with it is refused, naming
// the part.
TEST(LowDensityFoam, ReadFromTheDeck) {
  crumple::testing::TempDir t("crumple_test_ldf");
  const auto model = crumple::model::readModel(t.write("f.k", foamDeck("5,1e-9,2.0,7")));
  const auto& p = std::get<m::LowDensityFoam::Params>(model.materials.at(0).law);
  EXPECT_EQ(p.young, 2.0);
  EXPECT_EQ(p.E, 2.0);
  EXPECT_EQ(p.nu, 0.0);
  EXPECT_EQ(p.tc, 1e20);
  EXPECT_EQ(p.hu, 1.0);
  EXPECT_EQ(p.shape, 1.0);
  EXPECT_FALSE(p.tear);
  EXPECT_FALSE(p.bulk_viscosity);
  EXPECT_TRUE(noted(model, "DAMP"));

  const auto full = crumple::model::readModel(
      t.write("g.k", foamDeck("5,1e-9,2.0,7,0.5,0.1,0,0", "3.0,1,1,0,0,40.0", "*MAT_057")));
  const auto& q = std::get<m::LowDensityFoam::Params>(full.materials.at(0).law);
  EXPECT_EQ(q.tc, 0.5);
  EXPECT_EQ(q.hu, 0.1);
  EXPECT_EQ(q.shape, 3.0);
  EXPECT_TRUE(q.tear);
  EXPECT_TRUE(q.bulk_viscosity);
  EXPECT_EQ(q.E, 40.0);
  EXPECT_FALSE(noted(full, "DAMP"));
  EXPECT_TRUE(noted(full, "KCON"));
  const auto law = std::get<m::LowDensityFoam>(m::makeLaw(
      q,
      [&](int32_t i) {
        const auto& c = full.curves.at(std::size_t(i));
        return m::CurveData{c.id, c.x, c.y};
      },
      ""));
  EXPECT_TRUE(law.bulkViscosity());
  EXPECT_NEAR(m::youngOf(law.moduli), 10.0, 1e-12);

  const auto shell = t.write("s.k", foamDeck("5,1e-9,2.0,7") +
                                        "*SECTION_SHELL\n2\n1.0\n*PART\nskin\n2,2,5\n"
                                        "*ELEMENT_SHELL\n2,2,1,2,3,4\n");
  EXPECT_NE(crumple::testing::errorOf([&] {
              crumple::model::readModel(shell);
            }).find("part 2 has a *SECTION_SHELL section but material 5 (*MAT_LOW_DENSITY_FOAM)"),
            std::string::npos);
}

// A missing or bad field is an error naming file:line, keyword, card and field; what Crumple
// cannot honour (BETA, DAMP > 0, ED, REF) is refused the same way.
TEST(LowDensityFoam, BadOrRefusedFieldsAreErrors) {
  crumple::testing::TempDir t("crumple_test_ldf_bad");
  const auto error = [&](const std::string& card1, const std::string& card2 = "") {
    const auto path = t.write("bad.k", foamDeck(card1, card2));
    const std::string e = crumple::testing::errorOf([&] { crumple::model::readModel(path); });
    const std::string tail = " (the part is used by *ELEMENT_SOLID at " + path.string() + ":29)";
    EXPECT_EQ(e.substr(e.size() - std::min(e.size(), tail.size())), tail) << e;
    return e.substr(path.string().size(), e.size() - path.string().size() - tail.size());
  };
  EXPECT_EQ(error("5,1e-9,2.0,0"),
            ":4: *MAT_LOW_DENSITY_FOAM card 1 field 4 (LCID): a curve of nominal stress vs "
            "strain in compression is required");
  EXPECT_EQ(error("5,1e-9,0.0,7"),
            ":4: *MAT_LOW_DENSITY_FOAM card 1 field 3 (E): Young's modulus (the tensile "
            "stiffness) must be positive");
  EXPECT_EQ(error("5,1e-9,2.0,7,0,1.5"),
            ":4: *MAT_LOW_DENSITY_FOAM card 1 field 6 (HU): the hysteretic unloading factor "
            "must lie in (0, 1]");
  EXPECT_EQ(error("5,1e-9,2.0,7,0,0.5,0.2,0"),
            ":4: *MAT_LOW_DENSITY_FOAM card 1 field 7 (BETA): the decay of the unloading curve "
            "back to the loading curve (BETA != 0) is not supported: give BETA = 0 (reloading "
            "follows the unloading curve)");
  EXPECT_EQ(error("5,1e-9,2.0,7,0,1,0,0.1"),
            ":4: *MAT_LOW_DENSITY_FOAM card 1 field 8 (DAMP): viscous damping (DAMP > 0) is not "
            "supported: give DAMP = 0 to run without it");
  EXPECT_EQ(error("5,1e-9,2.0,7,0,1,0,0", "1,0,0,5.0"),
            ":6: *MAT_LOW_DENSITY_FOAM card 2 field 4 (ED): rate effects (the Maxwell element "
            "ED, BETA1) are not supported: give ED = 0");
  EXPECT_EQ(error("5,1e-9,2.0,7,0,1,0,0", "1,0,0,0,0,0,1"),
            ":6: *MAT_LOW_DENSITY_FOAM card 2 field 7 (REF): REF = 1 (stress from "
            "*INITIAL_FOAM_REFERENCE_GEOMETRY) is not supported");
  EXPECT_EQ(error("5,1e-9,2.0,7,0,1,0,0", "1,2"),
            ":6: *MAT_LOW_DENSITY_FOAM card 2 field 2 (FAIL): must be 0 (stay at TC) or 1 "
            "(tear)");
  // A curve whose stress at zero strain is not zero.
  m::LowDensityFoam::Params p;
  p.young = 1.0;
  p.curve = 0;
  const std::vector<double> x{0.0, 0.5}, y{0.2, 1.0};
  EXPECT_EQ(crumple::testing::errorOf([&] {
              m::LowDensityFoam::make(
                  p,
                  [&](int32_t) {
                    return m::CurveData{9, x, y};
                  },
                  "at: ");
            }),
            "at: LCID curve 9: the nominal stress at zero strain must be 0");
}
