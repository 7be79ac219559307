// *MAT_HONEYCOMB (026) at a material point (Honeycomb::advance on the material axes; the axes
// of AOPT 2 and MACF) against the Theory Manual's update worked out by hand, then the deck
// reader: the curve defaults (LCB, LCC, LCS from LCA; LCAB, LCBC, LCCA from LCS), MU's default
// and BULK, the refusals (AOPT 1, 3, 4, < 0; shells) and the errors naming the field.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "materials/materials.hpp"
#include "model/build.hpp"
#include "temp_dir.hpp"

namespace m = crumple::materials;

namespace {

// E 1000, PR 0.25 (K = 666.7, G = 400), SIGY 5, VF 0.2; E_u 50, 40, 30; G_u 10, 8, 6; MU as given.
// Curves vs volumetric strain: LCA 1 (constant 2), LCB 3, LCC 4, the shears 0.5.
m::Honeycomb makeHoneycomb(double mu = 0.0) {
  m::Honeycomb::Params p;
  p.E = 1000.0;
  p.nu = 0.25;
  p.ro = 1e-3;
  p.sigy = 5.0;
  p.vf = 0.2;
  p.mu = mu;
  p.curve = {0, 1, 2, 3, 3, 3};
  p.eu = {50.0, 40.0, 30.0};
  p.gu = {10.0, 8.0, 6.0};
  static const std::vector<double> x{0.0, 1.0};
  static const std::vector<std::vector<double>> y{{2.0, 2.0}, {3.0, 3.0}, {4.0, 4.0}, {0.5, 0.5}};
  return m::Honeycomb::make(
      p,
      [](int32_t i) {
        return m::CurveData{i + 1, x, y[std::size_t(i)]};
      },
      "");
}

}  // namespace

// Uncoupled components, each elastic with E_ii = E_iiu + beta (E - E_iiu) (2 G_ij for the tensor
// shears), each limited by its own curve.
TEST(Honeycomb, ComponentsAreUncoupledWithInterpolatedModuli) {
  const auto law = makeHoneycomb();
  m::Honeycomb::Point pt;
  std::array<double, 6> visc{};
  const double v = 0.6, beta = 0.4 / 0.8;
  const std::array<double, 6> de{-1e-3, 2e-3, 0.0, 1e-3, 0.0, -0.5e-3};
  law.advance(pt, de, 1e-3, v, 1.0, visc);
  const double g = 400.0;
  EXPECT_NEAR(pt.s[0], -(50.0 + beta * 950.0) * 1e-3, 1e-12);
  EXPECT_NEAR(pt.s[1], (40.0 + beta * 960.0) * 2e-3, 1e-12);
  EXPECT_EQ(pt.s[2], 0.0);
  EXPECT_NEAR(pt.s[3], 2.0 * (10.0 + beta * (g - 10.0)) * 1e-3, 1e-12);
  EXPECT_EQ(pt.s[4], 0.0);
  EXPECT_NEAR(pt.s[5], -2.0 * (6.0 + beta * (g - 6.0)) * 0.5e-3, 1e-12);
  EXPECT_FALSE(pt.compacted);
  EXPECT_EQ(visc, (std::array<double, 6>{}));  // MU 0
  // Further strain: each component stops at its curve (2, 3 for aa, bb; 0.5 for the shears).
  law.advance(pt, {-0.1, 0.1, 0.0, 0.1, 0.0, -0.1}, 1e-3, v, 1.0, visc);
  EXPECT_EQ(pt.s[0], -2.0);
  EXPECT_EQ(pt.s[1], 3.0);
  EXPECT_EQ(pt.s[3], 0.5);
  EXPECT_EQ(pt.s[5], -0.5);
}

// At V <= VF the point is compacted for good: isotropic elastic with E, PR from the stress it
// had, the deviator returned to SIGY, the pressure K tr(de); MU's stress is deviatoric.
TEST(Honeycomb, CompactionIsPermanentAndIsotropic) {
  const auto law = makeHoneycomb(0.1);
  m::Honeycomb::Point pt;
  pt.s = {-2.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  std::array<double, 6> visc{};
  const std::array<double, 6> de{-1e-3, 0, 0, 0, 0, 0};
  law.advance(pt, de, 1e-3, 0.19, 2.0, visc);
  EXPECT_TRUE(pt.compacted);
  const double K = 1000.0 / 1.5, G = 400.0;
  EXPECT_NEAR(pt.s[0], -2.0 - (K + 4.0 * G / 3.0) * 1e-3, 1e-12);
  EXPECT_NEAR(pt.s[1], -(K - 2.0 * G / 3.0) * 1e-3, 1e-12);
  // mu rho c L = 0.1 * 2 times the deviatoric rate (-2/3, 1/3, 1/3).
  EXPECT_NEAR(visc[0], -0.2 * 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(visc[1], 0.2 / 3.0, 1e-12);
  // Back above VF: still compacted; a large deviatoric strain is returned to SIGY.
  law.advance(pt, {-0.05, 0.05, 0, 0, 0, 0}, 1e-3, 0.25, 2.0, visc);
  EXPECT_TRUE(pt.compacted);
  const double mean = (pt.s[0] + pt.s[1] + pt.s[2]) / 3.0;
  std::array<double, 6> dev = pt.s;
  for (int k = 0; k < 3; ++k) dev[std::size_t(k)] -= mean;
  double j2 = 0.0;
  for (int k = 0; k < 6; ++k) j2 += (k < 3 ? 1.0 : 2.0) * dev[std::size_t(k)] * dev[std::size_t(k)];
  EXPECT_NEAR(std::sqrt(1.5 * j2), 5.0, 1e-12);
  EXPECT_GT(pt.eps_p, 0.0);
}

// Before compaction MU's stress is mu rho c L times each rate, scaled by E_ij / E (G_ij / G).
TEST(Honeycomb, ViscousStressScalesWithTheInterpolatedModuli) {
  const auto law = makeHoneycomb(0.05);
  m::Honeycomb::Point pt;
  std::array<double, 6> visc{};
  law.advance(pt, {-1e-3, 0, 0, 1e-3, 0, 0}, 1e-4, 1.0, 3.0, visc);
  EXPECT_NEAR(visc[0], 0.05 * 3.0 * (50.0 / 1000.0) * -10.0, 1e-12);
  EXPECT_NEAR(visc[3], 0.05 * 3.0 * (10.0 / 400.0) * 10.0, 1e-12);
}

// AOPT 2 axes: a along A, c normal to A and D, b = c x a; MACF swaps.
TEST(Honeycomb, AxesFromTheVectorsAndMacf) {
  auto law = makeHoneycomb();
  const double a[3] = {0.0, 2.0, 0.0}, d[3] = {1.0, 1.0, 0.0};
  double q[9];
  law.axes(a, d, q);
  // a = e_y, c = e_y x (1, 1, 0) / |.| = -e_z, b = c x a = e_x.
  const double want[9] = {0, 1, 0, 1, 0, 0, 0, 0, -1};
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(q[k], want[k], 1e-15) << k;
  law.macf = 3;  // swap a and c
  law.axes(a, d, q);
  const double swapped[9] = {0, 1, 0, 0, 0, 1, -1, 0, 0};
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(q[k], swapped[k], 1e-15) << k;
}

namespace {

const std::string kMesh =
    "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
    "*DEFINE_CURVE\n7\n0.0,1.0\n1.0,1.0\n*DEFINE_CURVE\n8\n0.0,0.5\n1.0,0.5\n"
    "*DEFINE_CURVE\n9\n0.0,2.0\n1.0,2.0\n"
    "*SECTION_SOLID\n1,1\n*PART\ncore\n1,1,5\n*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n";

// Cards 1-5 of *MAT_HONEYCOMB 5 (fixed-format card 1 so that MU can be blank).
std::string honeycombDeck(const std::string& card1, const std::string& card2,
                          const std::string& card3, const std::string& card4 = "0,0,0,1,0,0",
                          const std::string& card5 = "0,1,0") {
  return "*KEYWORD\n*MAT_HONEYCOMB\n" + card1 + "\n" + card2 + "\n" + card3 + "\n" + card4 + "\n" +
         card5 + "\n" + kMesh;
}

const std::string kCard1 = "5,1e-3,1000.0,0.3,5.0,0.2,0.1,0";
const std::string kCard3 = "50,40,30,10,8,6,2,0";

bool noted(const crumple::model::Model& model, const std::string& field) {
  for (const auto& f : model.ignored)
    if (f.field == field) return true;
  return false;
}

int64_t curveId(const crumple::model::Model& model, int32_t index) {
  return model.curves.at(std::size_t(index)).id;
}

}  // namespace

TEST(Honeycomb, ReadFromTheDeck) {
  crumple::testing::TempDir t("crumple_test_honeycomb");
  // LCA 7 only: every component takes it; LCS 8: the shears take LCS.
  auto model = crumple::model::readModel(t.write("a.k", honeycombDeck(kCard1, "7", kCard3)));
  auto p = std::get<m::Honeycomb::Params>(model.materials.at(0).law);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(curveId(model, p.curve[std::size_t(k)]), 7) << k;
  EXPECT_EQ(p.rate_curve, -1);
  EXPECT_EQ(p.mu, 0.1);
  EXPECT_FALSE(p.bulk);
  EXPECT_EQ(p.aopt, 2);
  EXPECT_EQ(p.macf, 1);
  EXPECT_EQ(p.a, (std::array<double, 3>{1, 0, 0}));
  EXPECT_EQ(p.d, (std::array<double, 3>{0, 1, 0}));
  model = crumple::model::readModel(
      t.write("b.k", honeycombDeck(kCard1, "7,0,9,8,0,7,0,9", "50,40,30,10,8,6,0,-3")));
  p = std::get<m::Honeycomb::Params>(model.materials.at(0).law);
  const int64_t want[6] = {7, 7, 9, 8, 7, 8};
  for (int k = 0; k < 6; ++k) EXPECT_EQ(curveId(model, p.curve[std::size_t(k)]), want[k]) << k;
  EXPECT_EQ(curveId(model, p.rate_curve), 9);
  EXPECT_EQ(p.aopt, 0);
  EXPECT_EQ(p.macf, 3);
  // MU blank: 0.05; BULK 1: no MU (noted when given).
  model = crumple::model::readModel(t.write(
      "c.k",
      honeycombDeck("         5     0.001    1000.0       0.3       5.0       0.2", "7", kCard3)));
  EXPECT_EQ(std::get<m::Honeycomb::Params>(model.materials.at(0).law).mu, 0.05);
  EXPECT_FALSE(noted(model, "MU"));
  model = crumple::model::readModel(
      t.write("d.k", honeycombDeck("5,1e-3,1000.0,0.3,5.0,0.2,0.1,1", "7", kCard3)));
  p = std::get<m::Honeycomb::Params>(model.materials.at(0).law);
  EXPECT_EQ(p.mu, 0.0);
  EXPECT_TRUE(p.bulk);
  EXPECT_TRUE(noted(model, "MU"));
  const auto law = std::get<m::Honeycomb>(m::makeLaw(
      p,
      [&](int32_t i) {
        const auto& c = model.curves.at(std::size_t(i));
        return m::CurveData{c.id, c.x, c.y};
      },
      ""));
  EXPECT_TRUE(law.bulkViscosity());
  // A shell part is refused, naming the part.
  const auto shell = t.write("s.k", honeycombDeck(kCard1, "7", kCard3) +
                                        "*SECTION_SHELL\n2\n1.0\n*PART\nskin\n2,2,5\n"
                                        "*ELEMENT_SHELL\n2,2,1,2,3,4\n");
  EXPECT_NE(crumple::testing::errorOf([&] {
              crumple::model::readModel(shell);
            }).find("part 2 has a *SECTION_SHELL section but material 5 (*MAT_HONEYCOMB)"),
            std::string::npos);
  // So is a fully integrated solid (the law needs F, which the one-point solids give).
  const auto full = t.write(
      "f.k",
      "*KEYWORD\n*MAT_HONEYCOMB\n" + kCard1 + "\n7\n" + kCard3 + "\n0,0,0,1,0,0\n0,1,0\n" + [] {
        std::string s = kMesh;
        s.replace(s.find("*SECTION_SOLID\n1,1"), 18, "*SECTION_SOLID\n1,2");
        return s;
      }());
  EXPECT_NE(crumple::testing::errorOf([&] {
              crumple::model::readModel(full);
            }).find("(*MAT_HONEYCOMB), a law of the deformation gradient"),
            std::string::npos);
}

TEST(Honeycomb, BadOrRefusedFieldsAreErrors) {
  crumple::testing::TempDir t("crumple_test_honeycomb_bad");
  const auto error = [&](const std::string& card1, const std::string& card2,
                         const std::string& card3, const std::string& card4 = "0,0,0,1,0,0",
                         const std::string& card5 = "0,1,0") {
    const auto path = t.write("bad.k", honeycombDeck(card1, card2, card3, card4, card5));
    return crumple::testing::errorOf([&] { crumple::model::readModel(path); });
  };
  const auto has = [](const std::string& e, const std::string& what) {
    return e.find(what) != std::string::npos;
  };
  EXPECT_TRUE(has(error(kCard1, "7", "50,40,30,10,8,6,1"),
                  "*MAT_HONEYCOMB card 3 field 7 (AOPT): AOPT 1 (a from a point P through the "
                  "element centre) is not supported: give AOPT 0"));
  EXPECT_TRUE(has(error(kCard1, "7", "50,40,30,10,8,6,3"), "AOPT 3 (a vector V and the element"));
  EXPECT_TRUE(has(error(kCard1, "7", "50,40,30,10,8,6,-4"), "AOPT < 0 (a coordinate system id)"));
  EXPECT_TRUE(has(error(kCard1, "0", kCard3), "card 2 field 1 (LCA): a curve of sigma-aa"));
  EXPECT_TRUE(
      has(error("5,1e-3,1000.0,0.3,5.0,1.2,0.1,0", "7", kCard3),
          "card 1 field 6 (VF): the relative volume at full compaction must lie in (0, 1)"));
  EXPECT_TRUE(has(error("5,1e-3,1000.0,0.3,0.0,0.2,0.1,0", "7", kCard3), "(SIGY)"));
  EXPECT_TRUE(has(error(kCard1, "7", kCard3, "0,0,0,0,0,0"), "AOPT 2 needs a non-zero vector A"));
  EXPECT_TRUE(
      has(error(kCard1, "7", kCard3, "0,0,0,1,0,0", "2,0,0"), "D must not be parallel to A"));
  EXPECT_TRUE(has(error(kCard1, "7", "50,40,30,10,8,6,2,5"), "(MACF): must be 1"));
  EXPECT_TRUE(has(error(kCard1, "7", "0,40,30,10,8,6,2"), "(EAAU)"));
  EXPECT_TRUE(has(error(kCard1, "7", kCard3, "0,0,0,1,0,0", "0,1,0,-0.1"), "(TSEF)"));
}

// SSEF: in the simple shear F = I + g e_x e_z the starting axes a = e_x and c = e_z make an angle
// whose cosine is g / sqrt(1 + g^2); SSEF 0.2 fails from g = 0.2041 on. With AOPT 0 the
// starting axes come back from the current ones through F^-1: the same verdict.
TEST(Honeycomb, ShearStrainFailsAtSsef) {
  auto law = makeHoneycomb();
  law.ssef = 0.2;
  for (int aopt : {2, 0}) {
    law.aopt = aopt;
    for (const double g : {0.2, 0.21}) {
      const double f[9] = {1, 0, g, 0, 1, 0, 0, 0, 1};
      // The current axes: F e_x = e_x and F e_y = e_y span the a-d plane.
      const double a[3] = {1, 0, 0}, d[3] = {0, 1, 0};
      double q[9];
      law.axes(a, d, q);
      EXPECT_EQ(law.strainFails(f, q, 1.0), g > 0.2041) << "AOPT " << aopt << " g " << g;
    }
  }
  // TSEF alone: a stretch of 1.05 along b passes TSEF 0.04.
  law.ssef = 0.0;
  law.tsef = 0.04;
  const double f[9] = {1, 0, 0, 0, 1.05, 0, 0, 0, 1};
  double q[9];
  const double a[3] = {1, 0, 0}, d[3] = {0, 1, 0};
  law.axes(a, d, q);
  EXPECT_TRUE(law.strainFails(f, q, 1.05));
  law.tsef = 0.06;
  EXPECT_FALSE(law.strainFails(f, q, 1.05));
}
