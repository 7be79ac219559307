// *MAT_ENHANCED_COMPOSITE_DAMAGE (054 / 055) at a material point (EnhancedComposite's
// plane-stress update) against classical lamination theory and the failure criteria worked out
// by hand, then the deck reader: *SECTION_SHELL ICOMP 1 angles, the law's cards and defaults,
// the refused fields and the errors naming them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "materials/materials.hpp"
#include "model/build.hpp"
#include "temp_dir.hpp"

namespace m = crumple::materials;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The ply of tools/clt.py (GPa, mm): EA 181, EB 10.3, PRBA 0.016, GAB 7.17; strengths XT 1.5,
// XC 1.5, YT 0.04, YC 0.246, SC 0.068.
m::EnhancedComposite::Params plyParams(int crit = 54, double beta = 0.0) {
  m::EnhancedComposite::Params p;
  p.ea = 181.0;
  p.eb = 10.3;
  p.prba = 0.016;
  p.gab = 7.17;
  p.gbc = 3.0;
  p.gca = 7.17;
  p.xt = 1.5;
  p.xc = 1.5;
  p.yt = 0.04;
  p.yc = 0.246;
  p.sc = 0.068;
  p.crit = crit;
  p.beta = beta;
  return p;
}

// One point: stress (xx, yy, xy) in, strain increment (tensor shear) in, at layer angle ply.
struct Point {
  double s[3] = {}, de[3] = {}, dzz = 0, h[m::EnhancedComposite::kHistory] = {}, ply = 0;
  uint8_t failed = 0;
  void update(const m::EnhancedComposite& law) {
    m::PlaneStressPoints b;
    b.n = 1;
    for (int k = 0; k < 3; ++k) {
      b.s[k] = &s[k];
      b.de[k] = &de[k];
    }
    for (int k = 0; k < m::EnhancedComposite::kHistory; ++k) b.h[k] = &h[k];
    b.de_zz = &dzz;
    b.ply = &ply;
    b.failed = &failed;
    law.updatePlaneStress(b);
  }
};

m::EnhancedComposite lawOf(const m::EnhancedComposite::Params& p) {
  return m::EnhancedComposite::make(p, {}, "");
}

}  // namespace

// A ply at 30 degrees: the stress of a small strain is Qbar eps, Qbar from tools/clt.py (the A
// matrix of the single ply of unit thickness), engineering shear gamma = 2 de_xy.
TEST(EnhancedComposite, OffAxisStiffnessIsQbar) {
  const auto law = lawOf(plyParams());
  const double qbar[3][3] = {{109.3876543, 32.47151914, 54.19252274},
                             {32.47151914, 23.65196023, 20.05676636},
                             {54.19252274, 20.05676636, 36.7324322}};
  for (int j = 0; j < 3; ++j) {
    Point p;
    p.ply = 30.0 * kPi / 180.0;
    const double eps = 1e-5;
    p.de[j] = j == 2 ? 0.5 * eps : eps;
    p.update(law);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(p.s[i] / eps / qbar[i][j], 1.0, 1e-9) << i << j;
  }
  // MANGLE adds to the layer's angle: 10 + 20 degrees is the same ply.
  auto params = plyParams();
  params.mangle = 10.0;
  Point p;
  p.ply = 20.0 * kPi / 180.0;
  p.de[0] = 1e-5;
  p.update(lawOf(params));
  EXPECT_NEAR(p.s[2] / 1e-5 / qbar[2][0], 1.0, 1e-9);
}

// sigma_bb = -0.1, sigma_ab = 0.09: the Chang-Chang matrix compression criterion
// (s/2Sc)^2 + ((Yc/2Sc)^2 - 1) s/Yc + (t/Sc)^2 = 1.369 fails; Tsai-Wu
// s^2/(Yc Yt) + (t/Sc)^2 + (Yc - Yt) s/(Yc Yt) = 0.674 does not (its threshold is t = 0.098).
TEST(EnhancedComposite, MatrixCompressionChangChangAgainstTsaiWu) {
  for (int crit : {54, 55}) {
    Point p;
    p.s[1] = -0.1;
    p.s[2] = 0.09;
    p.update(lawOf(plyParams(crit)));
    if (crit == 54) {
      EXPECT_EQ(p.h[3], 1.0);
      EXPECT_EQ(p.s[1], 0.0);  // Eb = Gab = 0: sigma_bb and sigma_ab dropped
      EXPECT_EQ(p.s[2], 0.0);
    } else {
      EXPECT_EQ(p.h[3], 0.0);
      EXPECT_EQ(p.s[1], -0.1);
    }
    EXPECT_EQ(p.failed, 0);
  }
}

// Fibre tension with the shear term: (1.4/1.5)^2 + beta (0.05/0.068)^2 = 0.871 + 0.541 beta.
TEST(EnhancedComposite, FibreTensionWeighsShearByBeta) {
  for (double beta : {0.0, 1.0}) {
    Point p;
    p.s[0] = 1.4;
    p.s[2] = 0.05;
    p.update(lawOf(plyParams(54, beta)));
    EXPECT_EQ(p.h[0], beta);
    EXPECT_EQ(p.failed, beta == 1.0 ? 1 : 0);
    if (beta == 1.0) {
      EXPECT_EQ(p.s[0], 0.0);
      // Failed for good: a later strain makes no stress.
      p.de[0] = 1e-3;
      p.update(lawOf(plyParams(54, beta)));
      EXPECT_EQ(p.s[0], 0.0);
      EXPECT_EQ(p.failed, 1);
    }
  }
}

// After matrix failure the ply keeps Ea alone (nu = 0): a strain along b makes no stress, one
// along a makes Ea eps. After compressive matrix failure the fibre compressive strength is
// YCFAC Yc = 0.492 (XC 1.5 before), and with FBRT 0.5 the tensile one 0.75.
TEST(EnhancedComposite, DegradedModuliAndStrengths) {
  auto params = plyParams();
  params.fbrt = 0.5;
  const auto law = lawOf(params);
  Point p;
  p.h[3] = 1.0;
  p.de[0] = 1e-4;
  p.de[1] = 1e-3;
  p.update(law);
  EXPECT_NEAR(p.s[0], 181.0 * 1e-4, 1e-15);
  EXPECT_EQ(p.s[1], 0.0);
  Point c = p;
  c.s[0] = -0.5;
  c.de[0] = c.de[1] = 0.0;
  c.update(law);
  EXPECT_EQ(c.h[1], 1.0);
  EXPECT_EQ(c.s[0], 0.0);
  Point t = p;
  t.s[0] = 0.76;
  t.de[0] = t.de[1] = 0.0;
  t.update(law);
  EXPECT_EQ(t.failed, 1);
  // Intact, the same stresses are safe.
  Point intact;
  intact.s[0] = 0.76;
  intact.update(law);
  EXPECT_EQ(intact.failed, 0);
}

// AOPT 2: A projected on the element's plane; AOPT 3: V x the normal; the angle from the
// frame's first axis about the normal (frame rows e1, e2, n).
TEST(EnhancedComposite, AxesFromVectors) {
  const double e[3][3] = {{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}};  // e1 = y, e2 = -x
  auto p = plyParams();
  p.aopt = 2;
  p.a = {1.0, 1.0, 5.0};  // projected: (1, 1, 0), 45 degrees from x, -45 from e1 = y
  EXPECT_NEAR(lawOf(p).axisAngle(e), -kPi / 4, 1e-15);
  p.aopt = 3;
  p.v = {1.0, 0.0, 0.0};  // V x n = (0, -1, 0) = -e1
  EXPECT_NEAR(std::abs(lawOf(p).axisAngle(e)), kPi, 1e-15);
  p.v = {0.0, 0.0, 2.0};  // along the normal: no direction
  EXPECT_TRUE(std::isnan(lawOf(p).axisAngle(e)));
}

// The laminate's transverse shear moduli turn with the layer: at 90 degrees xz takes GBC.
TEST(EnhancedComposite, TransverseShearTurnsWithTheLayer) {
  const auto law = lawOf(plyParams());
  double g[3];
  law.transverseShear(0.0, g);
  EXPECT_EQ(g[0], 7.17);
  EXPECT_EQ(g[1], 3.0);
  law.transverseShear(kPi / 2, g);
  EXPECT_NEAR(g[0], 3.0, 1e-14);
  EXPECT_NEAR(g[1], 7.17, 1e-14);
  law.transverseShear(kPi / 4, g);
  EXPECT_NEAR(g[2], 0.5 * (7.17 - 3.0), 1e-14);
}

namespace {

// *MAT_054 5 and a section with NIP points and ICOMP 1; `card5`, `card6` replace the defaults.
std::string compositeDeck(const std::string& card5 = "0,0,0,0,0,0,0,0",
                          const std::string& card6 = "1.5,1.5,0.246,0.04,0.068",
                          const std::string& section =
                              "1,2,0.833,10,1,0,1\n1.0\n"
                              "0,45,-45,90,90,-45,45,0\n0,90\n",
                          const std::string& card2 = "7.17,3.0,7.17,0,0") {
  return "*KEYWORD\n*MAT_ENHANCED_COMPOSITE_DAMAGE\n5,1.6e-6,181,10.3,0,0.016\n" + card2 +
         "\n0,0,0,0,0,0,15\n0,0,0,0,0,0,0,0\n" + card5 + "\n" + card6 + "\n*SECTION_SHELL\n" +
         section +
         "*PART\nply\n1,1,5\n*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n"
         "*ELEMENT_SHELL\n1,1,1,2,3,4\n*END\n";
}

}  // namespace

TEST(EnhancedComposite, ReadFromTheDeck) {
  crumple::testing::TempDir t("crumple_test_composite");
  const auto model = crumple::model::readModel(t.write("a.k", compositeDeck()));
  const auto p = std::get<m::EnhancedComposite::Params>(model.materials.at(0).law);
  EXPECT_EQ(p.ea, 181.0);
  EXPECT_EQ(p.prba, 0.016);
  EXPECT_EQ(p.gbc, 3.0);
  EXPECT_EQ(p.mangle, 15.0);
  EXPECT_EQ(p.crit, 54);    // CRIT blank: 54
  EXPECT_EQ(p.ycfac, 2.0);  // YCFAC blank: 2
  EXPECT_EQ(p.sc, 0.068);
  EXPECT_EQ(p.tfail, 0.0);
  // NIP 10: the angles on two cards, B1..B8 then B9, B10.
  const auto& sec = model.shell_sections.at(0);
  ASSERT_EQ(sec.ply_angle.size(), 10u);
  EXPECT_EQ(sec.ply_angle[1], 45.0);
  EXPECT_EQ(sec.ply_angle[9], 90.0);
  // CRIT 55 (the *MAT_055 form), and *MAT_054 spelled by number.
  auto deck = compositeDeck("0,0,0,0,0,0,0,0", "1.5,1.5,0.246,0.04,0.068,55");
  deck.replace(deck.find("*MAT_ENHANCED_COMPOSITE_DAMAGE"), 30, "*MAT_054");
  const auto m55 = crumple::model::readModel(t.write("b.k", deck));
  EXPECT_EQ(std::get<m::EnhancedComposite::Params>(m55.materials.at(0).law).crit, 55);
  // TFAIL <= 0.1: the law's deletion step (the element erodes below it).
  const auto tf =
      crumple::model::readModel(t.write("c.k", compositeDeck("1e-6", "1.5,1.5,0.246,0.04,0.068")));
  const auto pt = std::get<m::EnhancedComposite::Params>(tf.materials.at(0).law);
  EXPECT_EQ(pt.tfail, 1e-6);
  EXPECT_EQ(lawOf(pt).deletionStep(), 1e-6);
}

// The strain limits DFAILM, DFAILS (card 4), DFAILT, DFAILC, EFS (card 5) and the residual
// strengths SLIMT1, SLIMC1, SLIMT2, SLIMC2, SLIMS (card 8) are read into their parameters. With
// DFAILT = 0, DFAILC, DFAILM and DFAILS act not (the manual: only with DFAILT > 0): noted and
// dropped; with CRIT 55 all of them are (*MAT_054 only).
TEST(EnhancedComposite, StrainLimitsAndResidualStrengthsAreRead) {
  crumple::testing::TempDir t("crumple_test_composite_limits");
  const std::string c6 = "1.5,1.5,0.246,0.04,0.068", c8 = "\n0,0,0,0\n0.1,0.2,0.3,0.4,0.5";
  const auto deck = [&](const std::string& c5, const std::string& card6) {
    auto d = compositeDeck(c5, card6 + c8);
    d.replace(d.find("0,0,0,0,0,0,0,0\n"), 16, "0,0,0,0,0,0,0.01,0.015\n");
    return d;
  };
  const auto read = [&](const std::string& name, const std::string& d) {
    return std::get<m::EnhancedComposite::Params>(
        crumple::model::readModel(t.write(name, d)).materials.at(0).law);
  };
  const auto p = read("a.k", deck("0,0,0,0,0,0.02,-0.03,0.05", c6));
  EXPECT_EQ(p.lim.dfailm, 0.01);
  EXPECT_EQ(p.lim.dfails, 0.015);
  EXPECT_EQ(p.lim.dfailt, 0.02);
  EXPECT_EQ(p.lim.dfailc, -0.03);
  EXPECT_EQ(p.lim.efs, 0.05);
  EXPECT_EQ(p.lim.slimt1, 0.1);
  EXPECT_EQ(p.lim.slimc1, 0.2);
  EXPECT_EQ(p.lim.slimt2, 0.3);
  EXPECT_EQ(p.lim.slimc2, 0.4);
  EXPECT_EQ(p.lim.slims, 0.5);
  const auto law = lawOf(p);
  EXPECT_EQ(law.lim.dfailc, -0.03);
  EXPECT_EQ(law.lim.slims, 0.5);
  const auto off = read("b.k", deck("0,0,0,0,0,0,-0.03,0.05", c6));
  EXPECT_EQ(off.lim.dfailm, 0.0);
  EXPECT_EQ(off.lim.dfails, 0.0);
  EXPECT_EQ(off.lim.dfailc, 0.0);
  EXPECT_EQ(off.lim.efs, 0.05);  // EFS acts alone
  EXPECT_EQ(off.lim.slimt1, 0.1);
  const auto p55 = read("c.k", deck("0,0,0,0,0,0.02,-0.03,0.05", c6 + ",55"));
  for (const double v :
       {p55.lim.dfailm, p55.lim.dfails, p55.lim.dfailt, p55.lim.dfailc, p55.lim.efs, p55.lim.slimt1,
        p55.lim.slimc1, p55.lim.slimt2, p55.lim.slimc2, p55.lim.slims})
    EXPECT_EQ(v, 0.0);
}

// Errors and refusals name the file, the line, the card and the field.
TEST(EnhancedComposite, BadOrRefusedFieldsAreErrors) {
  crumple::testing::TempDir t("crumple_test_composite_bad");
  const auto error = [&](const std::string& deck) {
    const auto path = t.write("bad.k", deck);
    return crumple::testing::errorOf([&] { crumple::model::readModel(path); });
  };
  const auto has = [](const std::string& e, const std::string& what) {
    const bool found = e.find(what) != std::string::npos;
    if (!found) ADD_FAILURE() << "'" << what << "' not in: " << e;
    return found;
  };
  const std::string k = "bad.k:", c5 = "0,0,0,0,0,0,0,0", c6 = "1.5,1.5,0.246,0.04,0.068";
  const std::string sec = "1,2,0.833,10,1,0,1\n1.0\n0,45,-45,90,90,-45,45,0\n0,90\n";
  const std::string mat = " *MAT_ENHANCED_COMPOSITE_DAMAGE card ";
  has(error(compositeDeck(c5, c6, sec, "7.17,3.0,7.17,0,1")),
      k + "4:" + mat + "2 field 5 (AOPT): only AOPT 0 (the element's side 1-2), 2 (vector A)");
  has(error(compositeDeck(c5, c6, sec, "7.17,3.0,7.17,0,2")),
      k + "5:" + mat + "3 field 4 (A1): AOPT 2 needs a non-zero vector");
  has(error(compositeDeck(c5, c6, sec, "7.17,3.0,7.17,0,3")),
      k + "6:" + mat + "4 field 1 (V1): AOPT 3 needs a non-zero vector");
  has(error(compositeDeck(c5, c6, sec, "7.17,0,7.17")), k + "4:" + mat + "2 field 2 (GBC)");
  has(error(compositeDeck("0,0,0,0,0,-0.02,-0.02", c6)),
      k + "7:" + mat + "5 field 6 (DFAILT): must not be negative");
  has(error(compositeDeck("0,0,0,0,0,0.02", c6)),
      k + "7:" + mat + "5 field 7 (DFAILC): must be negative when DFAILT > 0");
  has(error(compositeDeck("0,0,0,0,0,0,0,-0.1", c6)),
      k + "7:" + mat + "5 field 8 (EFS): EFS < 0 (the effective strain of the full strain");
  auto bad_dfailm = compositeDeck("0,0,0,0,0,0.02,-0.02", c6);
  bad_dfailm.replace(bad_dfailm.find("0,0,0,0,0,0,0,0\n"), 16, "0,0,0,0,0,0,-0.1,0\n");
  has(error(bad_dfailm), k + "6:" + mat + "4 field 7 (DFAILM): must not be negative");
  has(error(compositeDeck("0.5", c6)), k + "7:" + mat + "5 field 1 (TFAIL): TFAIL > 0.1");
  has(error(compositeDeck("0,0.3", c6)), k + "7:" + mat + "5 field 2 (ALPH)");
  has(error(compositeDeck("0,0,0.8", c6)), k + "7:" + mat + "5 field 3 (SOFT)");
  has(error(compositeDeck(c5, "1.5,1.5,0.246,0.04,0.068,22")),
      k + "8:" + mat + "6 field 6 (CRIT): must be 54 (Chang-Chang) or 55 (Tsai-Wu)");
  has(error(compositeDeck(c5, "1.5,0,0.246,0.04,0.068")),
      k + "8:" + mat + "6 field 2 (XT): the strength must be positive");
  has(error(compositeDeck(c5, c6 + "\n0,0,0,0\n1.5")),
      k + "10:" + mat + "8 field 1 (SLIMT1): must lie in [0, 1]");
  has(error(compositeDeck(c5, c6 + "\n0,0,0,0\n0,0,0,0,-0.1")),
      k + "10:" + mat + "8 field 5 (SLIMS): must lie in [0, 1]");
  // Still refused, by name: NCYRED, transverse shear damage, the strength curves.
  has(error(compositeDeck(c5, c6 + "\n0,0,0,0\n0,0,0,0,0,3")),
      k + "10:" + mat + "8 field 6 (NCYRED): the cycle reduction");
  has(error(compositeDeck(c5, c6 + "\n0,0.1")), k + "9:" + mat + "7 field 2 (EPSF)");
  has(error(compositeDeck(c5, c6 + "\n0\n0\n5")), k + "11:" + mat + "9 field 1 (LCXC)");
  auto bad_ea = compositeDeck();
  bad_ea.replace(bad_ea.find("181,"), 4, "-1,");
  has(error(bad_ea), k + "3:" + mat + "1 field 3 (EA): must be positive");
  // ICOMP: 0 or 1; NIP 10 needs two angle cards.
  has(error(compositeDeck(c5, c6, "1,2,0.833,10,1,0,2\n1.0\n")),
      k + "10: *SECTION_SHELL card 1 field 7 (ICOMP): must be 0 or 1");
  has(error(compositeDeck(c5, c6, "1,2,0.833,10,1,0,1\n1.0\n0,45,-45,90,90,-45,45,0\n")),
      "(ICOMP): ICOMP 1 needs 10 angles");
  // Solids and 2D solids are refused, naming the part.
  auto solid = compositeDeck();
  solid.replace(solid.find("*SECTION_SHELL"), solid.find("*PART") - solid.find("*SECTION_SHELL"),
                "*SECTION_SHELL\n1,13\n1.0\n");
  has(error(solid), "part 1");
}

// *PART_COMPOSITE: one point per ply at its mid-thickness, weighted by its share; the angles
// B_i; one material for all plies (another MID is refused, naming the field); TMID noted.
TEST(EnhancedComposite, PartCompositeIsOnePointPerPly) {
  crumple::testing::TempDir t("crumple_test_part_composite");
  const std::string mat =
      "*KEYWORD\n*MAT_054\n5,1.6e-6,181,10.3,0,0.016\n7.17,3.0,7.17\n0\n0\n0\n"
      "1.5,1.5,0.246,0.04,0.068\n*MAT_ELASTIC\n6,1e-6,10,0.3\n";
  const std::string mesh =
      "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n*ELEMENT_SHELL\n1,3,1,2,3,4\n*END\n";
  const auto model = crumple::model::readModel(
      t.write("a.k", mat +
                         "*PART_COMPOSITE\nlaminate\n3,16,0.8333\n5,0.1,0,0,5,0.3,90,7\n"
                         "5,0.3,90,0,5,0.1,0\n" +
                         mesh));
  const auto& part = model.parts.at(0);
  EXPECT_EQ(part.id, 3);
  EXPECT_EQ(part.material, 0);
  const auto& sec = model.shell_sections.at(std::size_t(part.section));
  EXPECT_EQ(sec.elform, 16);
  EXPECT_EQ(sec.nip, 4);
  EXPECT_NEAR(sec.t[0], 0.8, 1e-15);
  const double zeta[4] = {-0.875, -0.375, 0.375, 0.875}, weight[4] = {0.125, 0.375, 0.375, 0.125};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(sec.zeta.at(i), zeta[i], 1e-15) << i;
    EXPECT_NEAR(sec.weight.at(i), weight[i], 1e-15) << i;
    EXPECT_EQ(sec.ply_angle.at(i), i == 1 || i == 2 ? 90.0 : 0.0) << i;
  }
  bool tmid = false;
  for (const auto& f : model.ignored) tmid = tmid || f.field == "TMID2";
  EXPECT_TRUE(tmid);
  const auto path =
      t.write("b.k", mat + "*PART_COMPOSITE\nlaminate\n3,2\n5,0.1,0,0,6,0.3,90\n" + mesh);
  const auto e = crumple::testing::errorOf([&] { crumple::model::readModel(path); });
  EXPECT_NE(e.find("b.k:14: *PART_COMPOSITE ply card field 5 (MID2): a material per ply"),
            std::string::npos)
      << e;
}
