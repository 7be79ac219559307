// Erosion criteria at a point (materials/erosion.hpp) against the Keyword Manual's definitions
// worked by hand, and the readers of *MAT_ADD_EROSION and *MAT_123: values, exclusions,
// refusals by field and by element family.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>

#include "materials/erosion.hpp"
#include "materials/materials.hpp"
#include "model/build.hpp"
#include "temp_dir.hpp"

namespace m = crumple::materials;
using m::Criterion;
using m::pointFails;
using m::Voigt;

namespace {

m::Erosion with(Criterion c, double v) {
  m::Erosion er;
  er.set(c, v);
  return er;
}

const Voigt kZero{};

}  // namespace

// Each criterion on a state just below and just above its limit, worked by hand.
TEST(Erosion, EachCriterionAtItsLimit) {
  // Pressure: p = -tr(sigma) / 3.
  const Voigt squeeze{-300.0, -300.0, -300.0, 0, 0, 0};  // p = 300
  EXPECT_TRUE(pointFails(with(Criterion::MaxPressure, 300.0), squeeze, kZero, 0.0));
  EXPECT_FALSE(pointFails(with(Criterion::MaxPressure, 300.1), squeeze, kZero, 0.0));
  const Voigt pull{100.0, 100.0, 100.0, 0, 0, 0};  // p = -100
  EXPECT_TRUE(pointFails(with(Criterion::MinPressure, -100.0), pull, kZero, 0.0));
  EXPECT_FALSE(pointFails(with(Criterion::MinPressure, -100.1), pull, kZero, 0.0));
  // Pure shear tau = 100 (tensor component xy): principal stresses +-100, von Mises
  // sqrt(3) 100 = 173.2.
  const Voigt shear{0, 0, 0, 100.0, 0, 0};
  EXPECT_TRUE(pointFails(with(Criterion::MaxPrincipalStress, 99.99), shear, kZero, 0.0));
  EXPECT_FALSE(pointFails(with(Criterion::MaxPrincipalStress, 100.01), shear, kZero, 0.0));
  EXPECT_TRUE(pointFails(with(Criterion::VonMises, 173.2), shear, kZero, 0.0));
  EXPECT_FALSE(pointFails(with(Criterion::VonMises, 173.21), shear, kZero, 0.0));
  // Strain: isochoric uniaxial e = (0.1, -0.05, -0.05): effective strain 0.1, principal 0.1
  // and -0.05, tensorial shear (0.1 + 0.05) / 2 = 0.075, volume 0.
  const Voigt e{0.1, -0.05, -0.05, 0, 0, 0};
  EXPECT_TRUE(pointFails(with(Criterion::EffectiveStrain, 0.0999999), kZero, e, 0.0));
  EXPECT_FALSE(pointFails(with(Criterion::EffectiveStrain, 0.1000001), kZero, e, 0.0));
  EXPECT_TRUE(pointFails(with(Criterion::MaxPrincipalStrain, 0.0999999), kZero, e, 0.0));
  EXPECT_FALSE(pointFails(with(Criterion::MaxPrincipalStrain, 0.1000001), kZero, e, 0.0));
  EXPECT_TRUE(pointFails(with(Criterion::MinPrincipalStrain, -0.0499999), kZero, e, 0.0));
  EXPECT_FALSE(pointFails(with(Criterion::MinPrincipalStrain, -0.0500001), kZero, e, 0.0));
  EXPECT_TRUE(pointFails(with(Criterion::ShearStrain, 0.0749999), kZero, e, 0.0));
  EXPECT_FALSE(pointFails(with(Criterion::ShearStrain, 0.0750001), kZero, e, 0.0));
  // Volumetric strain: a positive limit in expansion, a negative one in compression.
  const Voigt grow{0.01, 0.01, 0.01, 0, 0, 0}, shrink{-0.01, -0.01, -0.01, 0, 0, 0};
  EXPECT_TRUE(pointFails(with(Criterion::VolumetricStrain, 0.03), kZero, grow, 0.0));
  EXPECT_FALSE(pointFails(with(Criterion::VolumetricStrain, 0.03), kZero, shrink, 0.0));
  EXPECT_TRUE(pointFails(with(Criterion::VolumetricStrain, -0.0299), kZero, shrink, 0.0));
  EXPECT_FALSE(pointFails(with(Criterion::VolumetricStrain, -0.0301), kZero, shrink, 0.0));
  EXPECT_TRUE(pointFails(with(Criterion::FailureTime, 1e-3), kZero, kZero, 1e-3));
  EXPECT_FALSE(pointFails(with(Criterion::FailureTime, 1e-3), kZero, kZero, 0.999e-3));
  // *MAT_123 on shells: thinning -e_zz; major in-plane strain of (0.05, 0.01, xy 0.02):
  // 0.03 + hypot(0.02, 0.02) = 0.058284.
  EXPECT_TRUE(pointFails(with(Criterion::Thinning, 0.1), kZero, {0, 0, -0.1, 0, 0, 0}, 0.0));
  EXPECT_FALSE(pointFails(with(Criterion::Thinning, 0.1), kZero, {0, 0, -0.0999, 0, 0, 0}, 0.0));
  const Voigt plane{0.05, 0.01, 0.0, 0.02, 0, 0};
  EXPECT_TRUE(pointFails(with(Criterion::MajorStrain, 0.05828), kZero, plane, 0.0));
  EXPECT_FALSE(pointFails(with(Criterion::MajorStrain, 0.05829), kZero, plane, 0.0));
}

// NCS: the criteria that must hold at once; *MAT_123's own criteria act alone.
TEST(Erosion, CriteriaHeldAtOnce) {
  m::Erosion er;
  er.set(Criterion::VonMises, 100.0);
  er.set(Criterion::MaxPrincipalStrain, 0.1);
  er.ncs = 2;
  const Voigt s{200.0, 0, 0, 0, 0, 0}, small{0.05, 0, 0, 0, 0, 0}, large{0.2, 0, 0, 0, 0, 0};
  EXPECT_FALSE(pointFails(er, s, small, 0.0));
  EXPECT_FALSE(pointFails(er, kZero, large, 0.0));
  EXPECT_TRUE(pointFails(er, s, large, 0.0));
  er.set(Criterion::Thinning, 0.1);
  EXPECT_TRUE(pointFails(er, kZero, {0, 0, -0.2, 0, 0, 0}, 0.0));
  EXPECT_TRUE(er.needsStrain());
  EXPECT_FALSE(er.forSolids().has(Criterion::Thinning));
  EXPECT_FALSE(with(Criterion::VonMises, 1.0).needsStrain());
}

namespace {

const std::string kHex =
    "*KEYWORD\n*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
    "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n*PART\nhex\n1,1,1\n";
const std::string kMat = "*MAT_024\n1,7.85e-9,210000.0,0.3,300.0,1000.0\n";

std::string errorOf(crumple::testing::TempDir& t, const std::string& text) {
  const auto f = t.write("e.k", text + "*END\n");
  return crumple::testing::errorOf([&] { crumple::model::readModel(f); });
}

}  // namespace

// *MAT_ADD_EROSION: EXCL and the zero exclusions, NUMFIP and NCS, the criteria it refuses by
// field and the element families it refuses by part.
TEST(Erosion, AddErosionReader) {
  crumple::testing::TempDir t;
  const auto ok =
      t.write("ok.k", kHex + "*SECTION_SOLID\n1,1\n" + kMat +
                          "*MAT_ADD_EROSION\n1,99.0,99.0,0.0,0.15,99.0,3,2\n0.0,99.0,400.0,99.0,"
                          "99.0,99.0,99.0,-2e-3\n*END\n");
  const auto model = crumple::model::readModel(ok);
  const m::Erosion& er = model.materials.at(0).erosion;
  EXPECT_FALSE(er.has(Criterion::MaxPressure));         // = EXCL
  EXPECT_FALSE(er.has(Criterion::MinPrincipalStrain));  // 0 on card 1: excluded
  EXPECT_EQ(er.at(Criterion::EffectiveStrain), 0.15);
  EXPECT_TRUE(er.has(Criterion::MinPressure));  // 0 on card 2 with EXCL 99: a limit
  EXPECT_EQ(er.at(Criterion::VonMises), 400.0);
  EXPECT_EQ(er.at(Criterion::FailureTime), 2e-3);  // |FAILTM|
  EXPECT_EQ(er.numfip, 3);
  EXPECT_EQ(er.ncs, 2);

  const std::string base = kHex + "*SECTION_SOLID\n1,1\n" + kMat + "*MAT_ADD_EROSION\n";
  EXPECT_NE(errorOf(t, base + "1\n0,0,0,0,0,100.0,1.0\n").find("card 2 field 6 (SIGTH)"),
            std::string::npos);
  EXPECT_NE(errorOf(t, base + "1\n0,0,-5\n").find("card 2 field 3 (SIGVM)"), std::string::npos);
  EXPECT_NE(errorOf(t, base + "1,0,0,0,0.1\n\n7\n").find("card 3 field 1 (IDAM)"),
            std::string::npos);
  EXPECT_NE(errorOf(t, base + "1,0,0,0,0.1\n\n\n0,0,0.2\n").find("card 4 field 3 (EPSTHIN)"),
            std::string::npos);
  EXPECT_NE(errorOf(t, base + "5,0,0,0,0.1\n").find("(MID): material 5 is not defined"),
            std::string::npos);
  // Fully integrated solids do not evaluate the criteria: refused at the element's part.
  EXPECT_NE(errorOf(t, kHex + "*SECTION_SOLID\n1,2\n" + kMat + "*MAT_ADD_EROSION\n1,0,0,0,0.1\n")
                .find("not on ELFORM 2 solids"),
            std::string::npos);
}

// *MAT_123: *MAT_024's parameters (the same Params) plus EPSTHIN, EPSMAJ, NUMINT, which become
// the material's shell criteria; negative forms refused by field.
TEST(Erosion, Mat123Reader) {
  crumple::testing::TempDir t;
  const std::string head = kHex +
                           "*SECTION_SOLID\n1,1\n*MAT_123\n1,7.85e-9,210000.0,0.3,300.0,"
                           "1000.0,0.25,1e-9\n";
  const auto ok = t.write("ok.k", head + "0,0,0,0,0,0.1,0.2,2\n*END\n");
  const auto model = crumple::model::readModel(ok);
  const auto& p = std::get<m::ModifiedPiecewiseLinear::Params>(model.materials.at(0).law);
  EXPECT_EQ(p.base.fail, 0.25);
  EXPECT_EQ(p.base.tdel, 1e-9);
  EXPECT_EQ(p.base.sigy, 300.0);
  const m::Erosion& er = model.materials.at(0).erosion;
  EXPECT_EQ(er.at(Criterion::Thinning), 0.1);
  EXPECT_EQ(er.at(Criterion::MajorStrain), 0.2);
  EXPECT_EQ(er.numfip, 2);
  // The kernels run *MAT_024's law.
  const m::Law law = m::makeLaw(model.materials.at(0).law, {}, "");
  EXPECT_TRUE(std::holds_alternative<m::PiecewiseLinear>(law));
  EXPECT_NE(errorOf(t, head + "0,0,0,0,0,-0.1\n").find("card 2 field 6 (EPSTHIN)"),
            std::string::npos);
  EXPECT_NE(errorOf(t, head + "0,0,0,0,0,0,-3\n").find("card 2 field 7 (EPSMAJ)"),
            std::string::npos);
  EXPECT_NE(errorOf(t, head + "0,0,0,0,0,0,0,-50\n").find("card 2 field 8 (NUMINT)"),
            std::string::npos);
}
