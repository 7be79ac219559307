// *MAT_CRUSHABLE_FOAM (063) at a material point, against answers worked out by hand from the
// model (elastic trial with the last slope of the curve as Young's modulus, principal stresses
// confined to [-Y(largest gamma), TSC]); frame indifference and batch-position independence;
// and the deck reader's checks and refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "materials/materials.hpp"
#include "materials/principal.hpp"
#include "model/build.hpp"
#include "temp_dir.hpp"
#include "voigt.hpp"

namespace m = crumple::materials;
using namespace crumple::testing;  // voigt.hpp: Axes, rotation, rotated, norm, maxDiff
using m::Voigt;

// ---- the law at a point --------------------------------------------------------------------

namespace {

// Yield stress Y(gamma): 2, 3, 4, 40 at gamma 0, 0.2, 0.5, 0.8 (slopes 5, 10/3, 120): the
// elastic modulus is the last slope, 120 (E = 123 sets only the contact stiffness).
const std::vector<double> kGamma{0.0, 0.2, 0.5, 0.8}, kYield{2.0, 3.0, 4.0, 40.0};
constexpr double kEe = 120.0;

double yieldOf(double g) {
  if (g < 0.2) return 2.0 + 5.0 * g;
  if (g < 0.5) return 3.0 + (g - 0.2) / 0.3;
  return 4.0 + 120.0 * (g - 0.5);
}

m::CrushableFoam makeFoam(double nu, double tsc) {
  m::CrushableFoam::Params p;
  p.E = 123.0;
  p.nu = nu;
  p.tsc = tsc;
  p.curve = 0;
  return m::CrushableFoam::make(
      p,
      [](int32_t) {
        return m::CurveData{7, kGamma, kYield};
      },
      "");
}

// One point with its history (ln(V/V0), largest gamma).
struct Point {
  Voigt s{};
  double ln_v = 0.0, gamma_max = 0.0;

  void step(const m::CrushableFoam& law, const Voigt& de) {
    m::PointBatch b;
    b.n = 1;
    for (int k = 0; k < 6; ++k) {
      b.s[k] = &s[k];
      b.de[k] = &de[k];
    }
    b.h[0] = &ln_v;
    b.h[1] = &gamma_max;
    law.update(b);
  }
  // Uniaxial strain along x (y, z held) in n equal steps to the log strain ln(V/V0) = `to`.
  void strainTo(const m::CrushableFoam& law, double to, int n = 20) {
    const double d = (to - ln_v) / n;
    for (int i = 0; i < n; ++i) step(law, {d, 0, 0, 0, 0, 0});
  }
  // The same to the volumetric strain gamma = 1 - V/V0.
  void squeezeTo(const m::CrushableFoam& law, double gamma) {
    strainTo(law, std::log(1.0 - gamma));
  }
};

constexpr double kTol = 1e-12;

}  // namespace

// Uniaxial strain (PR = 0, so no lateral stress): elastic with Ee = 120, then s_xx = -Y(gamma)
// along the curve, past its end with the last slope.
TEST(CrushableFoam, UniaxialStrainFollowsTheCurve) {
  const m::CrushableFoam law = makeFoam(0.0, 1.0);
  EXPECT_NEAR(m::youngOf(law.moduli), kEe, 1e-12);
  Point pt;
  pt.squeezeTo(law, 0.01);  // 120 ln 0.99 = -1.206 > -Y(0.01) = -2.05: still elastic
  EXPECT_NEAR(pt.s[0], kEe * std::log(0.99), kTol);
  for (const double g : {0.1, 0.35, 0.65, 0.8, 0.85}) {
    pt.squeezeTo(law, g);
    EXPECT_NEAR(pt.s[0], -yieldOf(g), kTol) << g;  // -2.5, -3.5, -22, -40, -46
    EXPECT_NEAR(pt.gamma_max, g, 1e-14);
    for (int k = 1; k < 6; ++k) EXPECT_EQ(pt.s[k], 0.0) << k;
  }
}

// Unloading is elastic (slope Ee) from -Y(gamma_max) = -22 to the cutoff TSC = 1; reloading is
// elastic from the cutoff and then perfectly plastic at -Y(gamma_max) until gamma passes
// gamma_max: the yield stress is that of the largest compression reached, not of the current.
TEST(CrushableFoam, UnloadsElasticallyAndYieldsAtTheLargestCompression) {
  const m::CrushableFoam law = makeFoam(0.0, 1.0);
  Point pt;
  pt.squeezeTo(law, 0.65);
  const double top = std::log(0.35);
  const std::vector<std::pair<double, double>> path = {
      {top + 0.1, -10.0},   // -22 + 120 * 0.1
      {top + 0.2, 1.0},     // -22 + 24 = 2: cut at TSC
      {top + 0.25, 1.0},    // stays at the cutoff
      {top + 0.15, -11.0},  // reloaded from the cutoff: 1 - 120 * 0.1
      {top + 0.03, -22.0},  // gamma = 0.6397 < 0.65: perfectly plastic at Y(0.65)
      {top, -22.0},        {std::log(0.3), -28.0}};  // past gamma_max on the curve again: Y(0.7)
  for (const auto& [ln_v, s] : path) {
    pt.strainTo(law, ln_v);
    EXPECT_NEAR(pt.s[0], s, kTol) << ln_v - top;
  }
  EXPECT_NEAR(pt.gamma_max, 0.7, 1e-14);
}

// PR = 0.25 (G = 48, lambda = 48, lambda + 2G = 144): the lateral stresses grow with lambda
// until they too reach -Y, after which the stress is hydrostatic at -Y(gamma).
TEST(CrushableFoam, LateralStressesReachTheYieldStressToo) {
  const m::CrushableFoam law = makeFoam(0.25, 1.0);
  Point pt;
  pt.strainTo(law, -0.005);  // elastic
  EXPECT_NEAR(pt.s[0], -0.72, kTol);
  EXPECT_NEAR(pt.s[1], -0.24, kTol);
  pt.strainTo(law, -0.03);  // axial on the curve, lateral still elastic
  EXPECT_NEAR(pt.s[0], -yieldOf(1.0 - std::exp(-0.03)), kTol);  // -2.14777
  EXPECT_NEAR(pt.s[1], -1.44, kTol);
  EXPECT_EQ(pt.s[1], pt.s[2]);
  pt.strainTo(law, -0.2);  // all three at -Y(0.18127) = -2.90635
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(pt.s[k], -yieldOf(1.0 - std::exp(-0.2)), kTol) << k;
}

// Tension: each principal stress stops at TSC (elastic-perfectly plastic); TSC = 0 carries no
// tension at all, so pure shear keeps only its compressive principal stress.
TEST(CrushableFoam, TensionCutoffOnPrincipalStresses) {
  const m::CrushableFoam law = makeFoam(0.25, 1.0);
  Point pt;
  pt.strainTo(law, 0.004);
  EXPECT_NEAR(pt.s[0], 0.576, kTol);
  EXPECT_NEAR(pt.s[1], 0.192, kTol);
  pt.strainTo(law, 0.02);  // s_xx cut at 1; s_yy = 48 * 0.02
  EXPECT_NEAR(pt.s[0], 1.0, kTol);
  EXPECT_NEAR(pt.s[1], 0.96, kTol);
  pt.strainTo(law, 0.03);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(pt.s[k], 1.0, kTol) << k;
  EXPECT_EQ(pt.gamma_max, 0.0);

  const m::CrushableFoam none = makeFoam(0.0, 0.0);
  Point t;
  t.strainTo(none, 0.01);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(t.s[k], 0.0) << k;
  // de_xy = 0.001: trial s_xy = 2 G de_xy = 0.12, principal +-0.12 on (1, +-1, 0) / sqrt 2; the
  // tensile one is cut: -0.12 n n^T with n = (1, -1, 0) / sqrt 2.
  Point sh;
  sh.step(none, {0, 0, 0, 0.001, 0, 0});
  EXPECT_NEAR(sh.s[0], -0.06, 1e-15);
  EXPECT_NEAR(sh.s[1], -0.06, 1e-15);
  EXPECT_NEAR(sh.s[3], 0.06, 1e-15);
  EXPECT_EQ(sh.s[2], 0.0);
  EXPECT_NEAR(sh.s[4], 0.0, 1e-17);
  EXPECT_NEAR(sh.s[5], 0.0, 1e-17);
}

// A strain path and the same path seen in a rotated frame give rotated stresses, the same
// principal stresses and the same history; the path crushes, shears and unloads, so both the
// yield and the cutoff act.
TEST(CrushableFoam, FrameIndifference) {
  const m::CrushableFoam law = makeFoam(0.25, 0.5);
  const Axes q = rotation({0.3, -1.0, 0.6}, 2.1);
  Point a, b;
  int clamped = 0;
  for (int st = 0; st < 120; ++st) {
    const double sgn = st < 80 ? 1.0 : -1.5;
    const Voigt de{sgn * -4e-3, sgn * -1e-3, sgn * 5e-4, 8e-4, -3e-4, 2e-4};
    a.step(law, de);
    b.step(law, rotated(q, de));
    EXPECT_LE(maxDiff(b.s, rotated(q, a.s)), 1e-12 * std::max(1.0, norm(a.s))) << st;
    const m::Principal pa = m::principalOf(a.s), pb = m::principalOf(b.s);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(pa.value[k], pb.value[k], 1e-12) << st;
    EXPECT_NEAR(a.gamma_max, b.gamma_max, 1e-15);
    EXPECT_NEAR(a.ln_v, b.ln_v, 1e-15);
    clamped += std::abs(pa.value[0] + law.yieldStress(a.gamma_max)) < 1e-12 ||
               std::abs(pa.value[2] - 0.5) < 1e-12;
  }
  EXPECT_GT(clamped, 60);
}

// A point gives the same bits alone and at any position of a batch of 13.
TEST(CrushableFoam, ResultsIndependentOfPositionInBatch) {
  const m::CrushableFoam law = makeFoam(0.25, 1.0);
  const int N = 13;
  for (int pos : {0, 5, 12}) {
    SCOPED_TRACE(pos);
    std::mt19937_64 rng(1234);
    std::vector<double> s(6 * N), de(6 * N), h0(N, 0.0), h1(N, 0.0);
    for (double& v : s) v = std::uniform_real_distribution<double>(-3.0, 3.0)(rng);
    Point lone;
    for (int k = 0; k < 6; ++k) lone.s[k] = s[k * N + pos];
    m::PointBatch big;
    big.n = N;
    for (int k = 0; k < 6; ++k) {
      big.s[k] = &s[k * N];
      big.de[k] = &de[k * N];
    }
    big.h[0] = h0.data();
    big.h[1] = h1.data();
    for (int st = 0; st < 40; ++st) {
      for (double& v : de) v = std::uniform_real_distribution<double>(-6e-3, 2e-3)(rng);
      law.update(big);
      Voigt d;
      for (int k = 0; k < 6; ++k) d[k] = de[k * N + pos];
      lone.step(law, d);
    }
    for (int k = 0; k < 6; ++k) EXPECT_EQ(std::memcmp(&s[k * N + pos], &lone.s[k], 8), 0) << k;
    EXPECT_EQ(std::memcmp(&h0[pos], &lone.ln_v, 8), 0);
    EXPECT_EQ(std::memcmp(&h1[pos], &lone.gamma_max, 8), 0);
    EXPECT_GT(lone.gamma_max, 0.05);
  }
}

// ---- the deck ------------------------------------------------------------------------------

namespace {

const std::string kMesh =
    "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
    "*DEFINE_CURVE\n7\n0.0,2.0\n0.2,3.0\n0.5,4.0\n0.8,40.0\n"
    "*SECTION_SOLID\n1,1\n*PART\nfoam\n1,1,5\n*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n";

std::string foamDeck(const std::string& card1, const std::string& keyword = "*MAT_CRUSHABLE_FOAM") {
  return "*KEYWORD\n" + keyword + "\n$ MID RO E PR LCID TSC DAMP MODEL\n" + card1 + "\n" + kMesh;
}

}  // namespace

// The deck's fields become the parameters (E, PR, TSC, the curve), the law takes its modulus
// from the curve's last slope, a blank DAMP is noted as not applied, and the law serves solids
// only: a beam or a shell part with it is refused, naming the part.
TEST(CrushableFoam, ReadFromTheDeckAndRefusedOnBeamsAndShells) {
  crumple::testing::TempDir t("crumple_test_foam");
  const std::string deck = foamDeck("5,1.0e-9,123.,0.25,7,1.0");
  const auto model = crumple::model::readModel(t.write("f.k", deck));
  const auto& params = std::get<m::CrushableFoam::Params>(model.materials.at(0).law);
  EXPECT_EQ(params.E, 123.0);
  EXPECT_EQ(params.nu, 0.25);
  EXPECT_EQ(params.tsc, 1.0);
  const auto law = std::get<m::CrushableFoam>(m::makeLaw(
      params,
      [&](int32_t i) {
        const auto& c = model.curves.at(std::size_t(i));
        return m::CurveData{c.id, c.x, c.y};
      },
      ""));
  EXPECT_EQ(law.gamma, kGamma);
  EXPECT_EQ(law.yield, kYield);
  EXPECT_NEAR(m::youngOf(law.moduli), kEe, 1e-12);
  bool noted = false;
  for (const auto& f : model.ignored) noted = noted || (f.field == "DAMP");
  EXPECT_TRUE(noted);
  EXPECT_NO_THROW(
      crumple::model::readModel(t.write("n.k", foamDeck("5,1e-9,123.,0.,7", "*MAT_063"))));

  const auto beam = t.write("b.k", deck +
                                       "*SECTION_BEAM\n2,3\n0.01\n*PART\npost\n2,2,5\n"
                                       "*ELEMENT_BEAM\n2,2,1,2\n");
  EXPECT_EQ(crumple::testing::errorOf([&] { crumple::model::readModel(beam); }),
            beam.string() +
                ":32: *PART card 2 field 3 (MID): part 2 has a *SECTION_BEAM section but "
                "material 5 (*MAT_CRUSHABLE_FOAM) has no uniaxial (fibre) update for beam "
                "elements");
  const auto shell = t.write("s.k", deck +
                                        "*SECTION_SHELL\n2\n1.0\n*PART\nskin\n2,2,5\n"
                                        "*ELEMENT_SHELL\n2,2,1,2,3,4\n");
  EXPECT_NE(crumple::testing::errorOf([&] {
              crumple::model::readModel(shell);
            }).find("part 2 has a *SECTION_SHELL section but material 5 (*MAT_CRUSHABLE_FOAM)"),
            std::string::npos);
}

// What cannot be honoured or makes no sense is an error naming file:line, card and field (the
// builder then adds where the part is used).
TEST(CrushableFoam, BadOrUnsupportedFieldsAreErrors) {
  crumple::testing::TempDir t("crumple_test_foam_bad");
  const auto error = [&](const std::string& card1) {
    const auto path = t.write("bad.k", foamDeck(card1));
    const std::string e = crumple::testing::errorOf([&] { crumple::model::readModel(path); });
    const std::string tail = " (the part is used by *ELEMENT_SOLID at " + path.string() + ":26)";
    EXPECT_EQ(e.substr(e.size() - std::min(e.size(), tail.size())), tail);
    return e.substr(path.string().size(), e.size() - path.string().size() - tail.size());
  };
  EXPECT_EQ(error("5,1e-9,123.,0.25,7,1.0,0.1"),
            ":4: *MAT_CRUSHABLE_FOAM card 1 field 7 (DAMP): viscous damping (DAMP > 0) is not "
            "supported: give DAMP = 0 to run without it");
  EXPECT_EQ(error("5,1e-9,123.,0.25,7,1.0,0.,1"),
            ":4: *MAT_CRUSHABLE_FOAM card 1 field 8 (MODEL): MODEL 1 (elliptical yield "
            "surface) is not supported: only MODEL 0 is");
  EXPECT_EQ(error("5,1e-9,123.,0.25,0,1.0"),
            ":4: *MAT_CRUSHABLE_FOAM card 1 field 5 (LCID): a curve of yield stress vs "
            "volumetric strain is required");
  EXPECT_EQ(error("5,1e-9,123.,0.25,7,-1.0"),
            ":4: *MAT_CRUSHABLE_FOAM card 1 field 6 (TSC): the tensile stress cutoff must not be "
            "negative (0: no tension)");
  EXPECT_EQ(error("5,1e-9,123.,0.5,7"),
            ":4: *MAT_CRUSHABLE_FOAM card 1 field 4 (PR): Poisson's ratio must lie in (-1, 0.5)");
  // A curve that ends flat gives no elastic modulus.
  m::CrushableFoam::Params p;
  p.E = 1.0;
  p.curve = 0;
  const std::vector<double> x{0.0, 0.5, 0.9}, y{1.0, 2.0, 2.0};
  EXPECT_EQ(crumple::testing::errorOf([&] {
              m::CrushableFoam::make(
                  p,
                  [&](int32_t) {
                    return m::CurveData{9, x, y};
                  },
                  "at: ");
            }),
            "at: LCID curve 9: the last segment must rise, as its slope is the elastic modulus "
            "(LS-DYNA MODEL 0 uses E only for contact)");
}
