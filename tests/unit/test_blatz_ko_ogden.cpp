// The Blatz-Ko rubber (*MAT_007) at a material point: the Cauchy stress against closed forms in
// uniaxial stress, equibiaxial stress and simple shear; against the derivative of the strain
// energy, sigma = (1/J) dW/dF F^T, with W written here from the formulation (central
// differences); frame indifference; the deck reader and its refusals.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>

#include "hyperelastic_point.hpp"
#include "materials/materials.hpp"
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
  const auto law = blatzKo();
  for (const Mat3& F : {kUniaxial, kEquibiaxial, kShear, kGeneral})
    expectStress(stressAt(law, F), stressOfEnergy(blatzKoEnergy, F), 1e-7);
  EXPECT_NEAR(law.energy(kinematicsOf(kGeneral)), blatzKoEnergy(kGeneral), 1e-14);
}

TEST(BlatzKo, RotationTurnsTheStress) {
  expectObjective(blatzKo(), kGeneral, 1e-12);
  expectObjective(blatzKo(), kEquibiaxial, 1e-12);
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
