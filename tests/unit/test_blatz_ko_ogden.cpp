// The Blatz-Ko (*MAT_007) and Ogden (*MAT_077_O) rubbers at a material point: the Cauchy
// stress against closed forms in uniaxial stress, equibiaxial stress and simple shear; against
// the derivative of the strain energy, sigma = (1/J) dW/dF F^T, with W written here from the
// formulation (central differences); frame indifference; Ogden with alpha = 2 (and -2) against
// the Mooney-Rivlin law of this code; the deck readers and their refusals.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>

#include "hyperelastic_point.hpp"
#include "materials/materials.hpp"
#include "materials/principal.hpp"
#include "model/build.hpp"
#include "temp_dir.hpp"

namespace m = crumple::materials;
using namespace crumple::testing::hyper;  // NOLINT(google-build-using-namespace)

namespace {

constexpr double kG = 1.5;  // Blatz-Ko shear modulus
constexpr double kNu = 0.463;

m::BlatzKo blatzKo() {
  return m::BlatzKo::make({kG}, {}, "");
}

// W of Blatz-Ko (f = 1, blatz_ko.hpp) from F: G/2 [(I1 - 3) + (I3^-beta - 1) / beta].
double blatzKoEnergy(const Mat3& F) {
  const double beta = kNu / (1 - 2 * kNu);
  const Mat3 c = mul(transpose(F), F);
  const double i3 = det(c);
  return 0.5 * kG * ((c[0] + c[4] + c[8] - 3) + (std::pow(i3, -beta) - 1) / beta);
}

}  // namespace

// Uniaxial stress: with F = diag(l, l^-nu, l^-nu) the lateral stresses of sigma = G (B/J -
// J^(-1/(1-2 nu)) I) vanish exactly (J = l^(1-2 nu)), and sigma_xx = G (l^(1+2 nu) - 1/l).
TEST(BlatzKo, UniaxialStressClosedForm) {
  const auto law = blatzKo();
  for (double l : {0.7, 1.3, 2.0}) {
    const double lat = std::pow(l, -kNu);
    const Stress s = stressAt(law, {l, 0, 0, 0, lat, 0, 0, 0, lat});
    EXPECT_NEAR(s[0], kG * (std::pow(l, 1 + 2 * kNu) - 1 / l), 1e-10) << "stretch " << l;
    EXPECT_NEAR(s[1], 0.0, 1e-10);
    EXPECT_NEAR(s[2], 0.0, 1e-10);
  }
}

// Equibiaxial stress: F = diag(l, l, l3) with l3 = l^(-2 nu / (1 - nu)) leaves sigma_zz = 0, and
// then sigma_xx = sigma_yy = G (l^2 - l3^2) / J.
TEST(BlatzKo, EquibiaxialStressClosedForm) {
  const auto law = blatzKo();
  for (double l : {0.8, 1.2, 1.6}) {
    const double l3 = std::pow(l, -2 * kNu / (1 - kNu)), J = l * l * l3;
    const Stress s = stressAt(law, {l, 0, 0, 0, l, 0, 0, 0, l3});
    EXPECT_NEAR(s[0], kG * (l * l - l3 * l3) / J, 1e-10) << "stretch " << l;
    EXPECT_NEAR(s[1], s[0], 1e-12);
    EXPECT_NEAR(s[2], 0.0, 1e-10);
  }
}

// Simple shear (J = 1): sigma = G (B - I): sigma_xy = G gamma, sigma_xx = G gamma^2, the other
// normal stresses zero.
TEST(BlatzKo, SimpleShearClosedForm) {
  const Stress s = stressAt(blatzKo(), kShear);
  expectStress(s, {kG * 0.16, 0, 0, kG * 0.4, 0, 0}, 1e-12);
}

// The small-strain moduli: G and Poisson's ratio 0.463, K = 2 G (1 + nu) / (3 (1 - 2 nu)).
TEST(BlatzKo, SmallStrainModuli) {
  expectSmallStrainModuli(blatzKo(), kG, 2 * kG * (1 + kNu) / (3 * (1 - 2 * kNu)));
}

// The stress is the derivative of W; the law's own energy is the same W.
TEST(BlatzKo, StressIsTheDerivativeOfTheEnergy) {
  expectStressOfEnergy(blatzKo(), blatzKoEnergy);
}

TEST(BlatzKo, RotationTurnsTheStress) {
  expectObjective(blatzKo(), kGeneral, 1e-12);
  expectObjective(blatzKo(), kEquibiaxial, 1e-12);
}

namespace {

// Two terms with exponents of both signs: G = (1.2 * 2.5 + 0.1 * 2) / 2 = 1.6.
constexpr std::array<double, 2> kMu{1.2, -0.1}, kAlpha{2.5, -2.0};
constexpr double kOgdenNu = 0.45;

m::Ogden ogden(const std::array<double, 2>& mu = kMu, const std::array<double, 2>& alpha = kAlpha,
               double nu = kOgdenNu) {
  m::Ogden::Params p;
  p.nu = nu;
  for (std::size_t t = 0; t < 2; ++t) {
    p.mu[t] = mu[t];
    p.alpha[t] = alpha[t];
  }
  return m::Ogden::make(p, {}, "");
}

// sum_j mu_j (l^alpha_j - l^-alpha_j) along the stretch pair (l, 1/l) of a J = 1 deformation:
// the principal stress difference of the pair.
double pairDifference(double l) {
  double d = 0.0;
  for (std::size_t t = 0; t < 2; ++t)
    d += kMu[t] * (std::pow(l, kAlpha[t]) - std::pow(l, -kAlpha[t]));
  return d;
}

// W of Ogden from F (ogden.hpp): the principal values of C = F^T F (equal to those of B).
double ogdenEnergy(const Mat3& F) {
  const Mat3 c = mul(transpose(F), F);
  const auto pr = m::principalOf({c[0], c[4], c[8], c[1], c[5], c[2]}).value;
  const double J = det(F), K = 2 * 1.6 * (1 + kOgdenNu) / (3 * (1 - 2 * kOgdenNu));
  double w = K * (J - 1 - std::log(J));
  for (std::size_t t = 0; t < 2; ++t)
    for (double ci : pr)
      w += kMu[t] / kAlpha[t] * (std::pow(ci / std::cbrt(J * J), kAlpha[t] / 2) - 1);
  return w;
}

Stress deviator(Stress s) {
  const double mean = (s[0] + s[1] + s[2]) / 3;
  for (std::size_t k = 0; k < 3; ++k) s[k] -= mean;
  return s;
}

// F scaled to J = 1.
Mat3 isochoric(Mat3 F) {
  const double s = 1 / std::cbrt(det(F));
  for (double& v : F) v *= s;
  return F;
}

}  // namespace

// Isochoric uniaxial stretch F = diag(l, l^-1/2, l^-1/2): no pressure (J = 1), sigma_xx -
// sigma_yy = sum mu_j (l^alpha_j - l^(-alpha_j/2)) (Ogden 1972), sigma_yy = sigma_zz, trace 0.
TEST(Ogden, IsochoricUniaxialClosedForm) {
  const auto law = ogden();
  for (double l : {0.6, 1.5, 3.0}) {
    double d = 0.0;
    for (std::size_t t = 0; t < 2; ++t)
      d += kMu[t] * (std::pow(l, kAlpha[t]) - std::pow(l, -kAlpha[t] / 2));
    const double lat = 1 / std::sqrt(l);
    const Stress s = stressAt(law, {l, 0, 0, 0, lat, 0, 0, 0, lat});
    expectStress(s, {2 * d / 3, -d / 3, -d / 3, 0, 0, 0}, 1e-10);
  }
}

// Isochoric equibiaxial stretch F = diag(l, l, l^-2): sigma_xx - sigma_zz = sum mu_j (l^alpha_j -
// l^(-2 alpha_j)).
TEST(Ogden, IsochoricEquibiaxialClosedForm) {
  const auto law = ogden();
  for (double l : {0.8, 1.3, 2.0}) {
    double d = 0.0;
    for (std::size_t t = 0; t < 2; ++t)
      d += kMu[t] * (std::pow(l, kAlpha[t]) - std::pow(l, -2 * kAlpha[t]));
    const Stress s = stressAt(law, {l, 0, 0, 0, l, 0, 0, 0, 1 / (l * l)});
    expectStress(s, {d / 3, d / 3, -2 * d / 3, 0, 0, 0}, 1e-10);
  }
}

// Simple shear x += gamma y: principal stretches l1 = gamma/2 + sqrt(1 + gamma^2/4), 1/l1, 1;
// the major axis at theta, tan 2 theta = 2 / gamma, so sigma_xy = D / (l1 + 1/l1) with D the
// pair difference, sigma_xx - sigma_yy = gamma sigma_xy (Rivlin's universal relation) and
// sigma_zz = sum mu_j (1 - (l1^alpha_j + l1^-alpha_j + 1) / 3).
TEST(Ogden, SimpleShearClosedForm) {
  const auto law = ogden();
  for (double gamma : {0.1, 0.4, 1.5}) {
    const double l1 = gamma / 2 + std::sqrt(1 + gamma * gamma / 4);
    const double sxy = pairDifference(l1) / (l1 + 1 / l1);
    double szz = 0.0;
    for (std::size_t t = 0; t < 2; ++t)
      szz += kMu[t] * (1 - (std::pow(l1, kAlpha[t]) + std::pow(l1, -kAlpha[t]) + 1) / 3);
    const Stress s = stressAt(law, {1, gamma, 0, 0, 1, 0, 0, 0, 1});
    EXPECT_NEAR(s[3], sxy, 1e-10) << "gamma " << gamma;
    EXPECT_NEAR(s[0] - s[1], gamma * sxy, 1e-10);
    EXPECT_NEAR(s[2], szz, 1e-10);
    EXPECT_NEAR(s[0] + s[1] + s[2], 0.0, 1e-10);
    EXPECT_NEAR(s[4], 0.0, 1e-12);
    EXPECT_NEAR(s[5], 0.0, 1e-12);
  }
}

// With volume change, on the axes: sigma_i = [sum mu_j (lbar_i^alpha_j - mean_j) + K (J - 1)] / J.
TEST(Ogden, CompressibleStretchClosedForm) {
  const auto law = ogden();
  const double l[3] = {1.2, 0.95, 0.9}, J = l[0] * l[1] * l[2];
  Stress want{};
  for (std::size_t t = 0; t < 2; ++t) {
    double pw[3], mean = 0;
    for (int i = 0; i < 3; ++i) mean += (pw[i] = std::pow(l[i] / std::cbrt(J), kAlpha[t])) / 3;
    for (std::size_t i = 0; i < 3; ++i) want[i] += kMu[t] * (pw[i] - mean) / J;
  }
  for (std::size_t i = 0; i < 3; ++i) want[i] += law.moduli.bulk * (J - 1) / J;
  expectStress(stressAt(law, {l[0], 0, 0, 0, l[1], 0, 0, 0, l[2]}), want, 1e-10);
}

// G = sum mu_j alpha_j / 2 = 1.6, K from PR; a small stretch gives K + 4G/3 and K - 2G/3.
TEST(Ogden, SmallStrainModuli) {
  expectSmallStrainModuli(ogden(), 1.6, 2 * 1.6 * (1 + kOgdenNu) / (3 * (1 - 2 * kOgdenNu)));
}

TEST(Ogden, StressIsTheDerivativeOfTheEnergy) {
  expectStressOfEnergy(ogden(), ogdenEnergy);
}

TEST(Ogden, RotationTurnsTheStress) {
  expectObjective(ogden(), kGeneral, 1e-12);
  expectObjective(ogden(), kUniaxial, 1e-12);  // a repeated principal stretch
}

// LS-DYNA's coefficient is mu_j / alpha_j: one term alpha = 2 is the neo-Hookean solid with
// G = mu, and the terms {mu = 2A, alpha = 2; mu = -2B, alpha = -2} are Mooney-Rivlin A, B. At
// J = 1 their deviatoric stresses equal those of this code's *MAT_027 law (whose pressure term
// differs, so the pressures are not compared).
TEST(Ogden, AlphaTwoIsMooneyRivlin) {
  const double A = 0.5, B = 0.2;
  m::MooneyRivlin::Params mr;
  mr.a = A;
  mr.nu = 0.45;
  const auto neo = m::MooneyRivlin::make(mr, {}, "");
  mr.b = B;
  const auto mooney = m::MooneyRivlin::make(mr, {}, "");
  const auto one = ogden({2 * A, 0}, {2, 0});
  const auto two = ogden({2 * A, -2 * B}, {2, -2});
  EXPECT_NEAR(one.moduli.shear, neo.moduli.shear, 1e-15);
  EXPECT_NEAR(two.moduli.shear, mooney.moduli.shear, 1e-15);
  for (const Mat3& F :
       {kShear, isochoric(kUniaxial), isochoric(kEquibiaxial), isochoric(kGeneral)}) {
    expectStress(deviator(stressAt(one, F)), deviator(stressAt(neo, F)), 1e-12);
    expectStress(deviator(stressAt(two, F)), deviator(stressAt(mooney, F)), 1e-12);
  }
}

namespace {

const std::string kNodes =
    "*KEYWORD\n*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n";
const std::string kHex =
    "*SECTION_SOLID\n1,1\n*PART\nrubber\n1,1,5\n*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n";
const std::string kShell =
    "*SECTION_SHELL\n1,2\n0.1,0.1,0.1,0.1\n*PART\nskin\n1,1,5\n*ELEMENT_SHELL\n1,1,1,2,3,4\n";

// The error of reading the deck with this material on the hex ("" when it reads).
std::string errorWith(const std::string& material, const std::string& part = kHex) {
  crumple::testing::TempDir t("crumple_test_blatz_ogden");
  const auto path = t.write("r.k", kNodes + material + part);
  return crumple::testing::errorOf([&] { crumple::model::readModel(path); });
}

bool says(const std::string& error, const std::string& what) {
  return error.find(what) != std::string::npos;
}

}  // namespace

TEST(BlatzKo, ReadAndRefused) {
  crumple::testing::TempDir t("crumple_test_blatz_ko");
  const auto model =
      crumple::model::readModel(t.write("r.k", kNodes + "*MAT_007\n5,1.0e-6,2.5\n" + kHex));
  EXPECT_EQ(std::get<m::BlatzKo::Params>(model.materials.at(0).law).G, 2.5);
  EXPECT_TRUE(says(errorWith("*MAT_BLATZ-KO_RUBBER\n5,1.0e-6,0.0\n"),
                   "*MAT_BLATZ-KO_RUBBER card 1 field 3 (G): the shear modulus must be positive"));
  EXPECT_TRUE(says(errorWith("*MAT_BLATZ-KO_RUBBER\n5,1.0e-6,2.5,1.0\n"),
                   "card 1 field 4 (REF): REF = 1 (stress from *INITIAL_FOAM_REFERENCE_GEOMETRY) "
                   "is not supported"));
  EXPECT_TRUE(says(errorWith("*MAT_BLATZ-KO_RUBBER\n5,1.0e-6,2.5\n", kShell),
                   "part 1 has a *SECTION_SHELL section but material 5 (*MAT_BLATZ-KO_RUBBER)"));
}

TEST(Ogden, ReadTermsAndDefaults) {
  crumple::testing::TempDir t("crumple_test_ogden");
  const auto model = crumple::model::readModel(
      t.write("r.k", kNodes + "*MAT_OGDEN_RUBBER\n5,1.0e-6,0.49\n1.2,-0.1\n2.5,-2.0\n" + kHex));
  const auto& p = std::get<m::Ogden::Params>(model.materials.at(0).law);
  EXPECT_EQ(p.nu, 0.49);
  EXPECT_EQ(p.mu[0], 1.2);
  EXPECT_EQ(p.mu[1], -0.1);
  EXPECT_EQ(p.alpha[0], 2.5);
  EXPECT_EQ(p.alpha[1], -2.0);
  EXPECT_EQ(p.mu[2], 0.0);
  // PR < 0: Poisson's ratio |PR| and card 2 (here without hysteresis or compliances).
  const auto negative = crumple::model::readModel(
      t.write("n.k", kNodes + "*MAT_OGDEN_RUBBER\n5,1.0e-6,-0.495\n0\n1.2\n2.5\n" + kHex));
  EXPECT_EQ(std::get<m::Ogden::Params>(negative.materials.at(0).law).nu, 0.495);
  // Viscoelastic cards with GI = 0 change nothing.
  EXPECT_EQ(errorWith("*MAT_077_O\n5,1.0e-6,0.49\n1.2\n2.5\n0.0,10.0\n"), "");
}

TEST(Ogden, BadOrUnsupportedFieldsAreErrors) {
  const std::string head = "*MAT_OGDEN_RUBBER\n";
  EXPECT_TRUE(says(errorWith(head + "5,1.0e-6,0.5\n1.2\n2.5\n"),
                   "card 1 field 3 (PR): Poisson's ratio |PR| must be below 0.5"));
  EXPECT_TRUE(says(errorWith(head + "5,1.0e-6,0.49,2\n10.,1.,1.,7\n"),
                   "card 1 field 4 (N): N > 0 (the nonlinear least-squares fit"));
  EXPECT_TRUE(says(errorWith(head + "5,1.0e-6,0.49,-1\n1\n2\n"),
                   "card 1 field 4 (N): N = -1 (MU_i and ALPHA_i as curves of temperature)"));
  EXPECT_TRUE(says(errorWith(head + "5,1.0e-6,-0.49\n0,0,0,0,0,0.001\n1.2\n2.5\n"),
                   "card 2 field 6 (D1): the compression compliances D1-D3 are not supported"));
  EXPECT_TRUE(says(errorWith(head + "5,1.0e-6,0.49,0,0,0.1,0.01\n1.2\n2.5\n"),
                   "card 1 field 6 (G): frequency-independent (frictional) damping"));
  EXPECT_TRUE(says(errorWith(head + "5,1.0e-6,0.49,0,0,0,0,1\n1.2\n2.5\n"),
                   "card 1 field 8 (REF): REF = 1"));
  EXPECT_TRUE(
      says(errorWith(head + "5,1.0e-6,0.49\n1.2,0.3\n2.5\n"),
           "card 3b.2 field 2 (ALPHA2): a term with MU != 0 needs a non-zero exponent ALPHA"));
  EXPECT_TRUE(
      says(errorWith(head + "5,1.0e-6,0.49\n-1.2\n2.5\n"),
           "card 3b.1 field 1 (MU1): the shear modulus sum(MU_i ALPHA_i) / 2 must be positive"));
  EXPECT_TRUE(says(errorWith(head + "5,1.0e-6,0.49\n1.2\n2.5\n0.0,1.0\n0.3,10.0\n"),
                   "viscoelastic card 2 field 1 (GI): viscoelasticity (Prony terms GI, BETAI) is "
                   "not supported"));
  EXPECT_TRUE(says(errorWith(head + "5,1.0e-6,0.49\n1.2\n2.5\n", kShell),
                   "part 1 has a *SECTION_SHELL section but material 5 (*MAT_OGDEN_RUBBER)"));
}
