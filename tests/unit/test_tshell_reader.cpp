// *SECTION_TSHELL and *ELEMENT_TSHELL (src/model/build_structures.cpp): cards, defaults, the
// refused options and their messages.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "model/build.hpp"
#include "temp_dir.hpp"

using crumple::model::Model;
using crumple::model::readModel;

namespace {

using crumple::testing::errorOf;

class TempDir : public crumple::testing::TempDir {
 public:
  TempDir() : crumple::testing::TempDir("crumple_test_tshell_reader") {}
};

// One thick shell on the unit cube, part 1 with section 1 (the section card comes from the
// test).
std::string deck(const std::string& section,
                 const std::string& element = "10,1,1,2,3,4,5,6,7,8\n") {
  return "*KEYWORD\n*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n"
         "8,0,1,1\n*PART\nplate\n1,1,1\n*MAT_ELASTIC\n1,7.8e-9,2.0e5,0.3\n" +
         section + "*ELEMENT_TSHELL\n" + element;
}

TEST(TShellReader, DefaultsAreElform1TwoGaussPointsShearFactorOne) {
  TempDir t;
  const Model m = readModel(t.write("d.k", deck("*SECTION_TSHELL\n1\n")));
  ASSERT_EQ(m.solid_sections.size(), 1u);
  const auto& s = m.solid_sections[0];
  EXPECT_TRUE(crumple::model::isThickShell(s.elform));
  EXPECT_EQ(s.nip, 2);
  EXPECT_EQ(s.shrf, 1.0);
  EXPECT_TRUE(s.zeta.empty());
  ASSERT_EQ(m.solids.size(), 1u);
  EXPECT_EQ(m.solids.id[0], 10);
  EXPECT_EQ(m.solids.nodes[0][4], m.nodeIndex(5));
}

// ELFORM 2 (selective reduced, 2 x 2 in the plane) reads as its own formulation.
TEST(TShellReader, Elform2IsTheSelectiveReducedFormulation) {
  TempDir t;
  const Model m = readModel(t.write("d.k", deck("*SECTION_TSHELL\n1,2,0.8333,3\n")));
  const auto& s = m.solid_sections[0];
  EXPECT_EQ(s.elform, crumple::model::kThickShellSelective);
  EXPECT_TRUE(crumple::model::isThickShell(s.elform));
  EXPECT_EQ(s.nip, 3);
}

TEST(TShellReader, FieldsAndTitle) {
  TempDir t;
  const Model m =
      readModel(t.write("d.k", deck("*SECTION_TSHELL_TITLE\nthick\n1,1,0.8333,5,1.0,0,0,0\n")));
  const auto& s = m.solid_sections[0];
  EXPECT_EQ(s.nip, 5);
  EXPECT_NEAR(s.shrf, 0.8333, 1e-12);
}

TEST(TShellReader, IntegrationShellRule) {
  TempDir t;
  const Model m = readModel(
      t.write("d.k", deck("*INTEGRATION_SHELL\n7,3,1\n*SECTION_TSHELL\n1,1,1.0,2,1.0,-7\n")));
  const auto& s = m.solid_sections[0];
  EXPECT_EQ(s.nip, 3);
  ASSERT_EQ(s.zeta.size(), 3u);
  EXPECT_NEAR(s.weight[1], 1.0 / 3.0, 1e-15);
}

TEST(TShellReader, RefusedOptionsNameTheField) {
  TempDir t;
  auto err = [&](const std::string& section,
                 const std::string& element = "10,1,1,2,3,4,5,6,7,8\n") {
    return errorOf([&] { readModel(t.write("e.k", deck(section, element))); });
  };
  EXPECT_NE(err("*SECTION_TSHELL\n1,1,1.0,1\n").find("field 4 (NIP)"), std::string::npos);
  EXPECT_NE(err("*SECTION_TSHELL\n1,1,1.0,2,1.0,0,0,1\n").find("(TSHEAR)"), std::string::npos);
  const std::string angles = err("*SECTION_TSHELL\n1,1,1.0,2,1.0,0,1\n30.0,0.0\n");
  EXPECT_NE(angles.find("(B1)"), std::string::npos) << angles;
  // Zero angles run as ICOMP 0.
  EXPECT_EQ(err("*SECTION_TSHELL\n1,1,1.0,2,1.0,0,1\n0.0,0.0\n"), "");
  const std::string form = err("*SECTION_TSHELL\n1,3\n");
  EXPECT_NE(form.find("*SECTION_TSHELL ELFORM=3"), std::string::npos) << form;
  const std::string prism = err("*SECTION_TSHELL\n1\n", "10,1,1,2,3,3,5,6,7,7\n");
  EXPECT_NE(prism.find("(N4)"), std::string::npos) << prism;
  EXPECT_NE(prism.find("degenerate thick shells"), std::string::npos) << prism;
  const std::string solid = err("*SECTION_SOLID\n1,1\n");
  EXPECT_NE(solid.find("needs a *SECTION_TSHELL"), std::string::npos) << solid;
}

TEST(TShellReader, SolidElementOnAThickShellPartIsRefused) {
  TempDir t;
  std::string d = deck("*SECTION_TSHELL\n1\n");
  d.replace(d.find("*ELEMENT_TSHELL"), 15, "*ELEMENT_SOLID");
  const std::string e = errorOf([&] { readModel(t.write("s.k", d)); });
  EXPECT_NE(e.find("has a *SECTION_TSHELL section, but *ELEMENT_SOLID needs a *SECTION_SOLID"),
            std::string::npos)
      << e;
}

TEST(TShellReader, LawWithoutPlaneStressUpdateIsRefused) {
  TempDir t;
  std::string d = deck("*SECTION_TSHELL\n1\n");
  d.replace(d.find("*MAT_ELASTIC\n1,7.8e-9,2.0e5,0.3\n"), 31, "*MAT_NULL\n1,7.8e-9\n");
  const std::string e = errorOf([&] { readModel(t.write("n.k", d)); });
  EXPECT_NE(e.find("*SECTION_TSHELL section but material 1"), std::string::npos) << e;
}

// A law whose points keep history (the layered composite *MAT_054) on thick shells: refused,
// thick shells do not store it.
TEST(TShellReader, LawWithPointHistoryIsRefused) {
  TempDir t;
  std::string d = deck("*SECTION_TSHELL\n1\n");
  d.replace(d.find("*MAT_ELASTIC\n1,7.8e-9,2.0e5,0.3\n"), 31,
            "*MAT_054\n1,1.6e-6,181,10.3,0,0.016\n7.17,3.0,7.17\n0\n0\n0\n"
            "1.5,1.5,0.246,0.04,0.068\n");
  const std::string e = errorOf([&] { readModel(t.write("c.k", d)); });
  EXPECT_NE(e.find("whose points keep history variables: thick shells do not store them yet"),
            std::string::npos)
      << e;
}

}  // namespace

// *SET_TSHELL (_LIST, _GENERATE, _ADD, _TITLE) names thick shells; *DATABASE_HISTORY_TSHELL
// (_SET) puts them on elout's list and *DATABASE_CROSS_SECTION_SET's TSID in the cut's elements
// (with the solids: thick shells are kept with them). A solid in a *SET_TSHELL, or an undefined
// set, is an error where the set is used, naming the field.
TEST(TShellReader, TShellSetsNameThickShells) {
  TempDir t;
  // A second thick shell (11) on top of the first, and a solid (20) of part 2 beside it.
  const std::string more =
      "11,1,5,6,7,8,9,10,11,12\n*NODE\n9,0,0,2\n10,1,0,2\n11,1,1,2\n12,0,1,2\n13,2,0,0\n"
      "14,2,1,0\n15,2,0,1\n16,2,1,1\n*PART\nblock\n2,2,1\n*SECTION_SOLID\n2,1\n*ELEMENT_SOLID\n"
      "20,2,2,13,14,3,6,15,16,7\n";
  const std::string sets =
      "*SET_TSHELL_LIST_TITLE\nplate\n5\n11,10\n*SET_TSHELL_GENERATE\n6\n1,100\n"
      "*SET_TSHELL_ADD\n7\n5\n*SET_NODE_LIST\n3\n5,6,7,8\n*DATABASE_ELOUT\n0.5\n"
      "*DATABASE_HISTORY_TSHELL\n11\n*DATABASE_HISTORY_TSHELL_SET\n7\n"
      "*DATABASE_CROSS_SECTION_SET\n3,0,0,0,6\n";
  const Model m = readModel(
      t.write("s.k", deck("*SECTION_TSHELL\n1\n", "10,1,1,2,3,4,5,6,7,8\n" + more) + sets));
  const int32_t e10 = m.elementIndex(crumple::model::Family::Solid, 10);
  const int32_t e11 = m.elementIndex(crumple::model::Family::Solid, 11);
  const int32_t e20 = m.elementIndex(crumple::model::Family::Solid, 20);
  EXPECT_TRUE(m.isThickShellElement(e10));
  EXPECT_FALSE(m.isThickShellElement(e20));
  const std::vector<int32_t> both = {std::min(e10, e11), std::max(e10, e11)};
  EXPECT_EQ(m.tshell_sets.at(5), both);
  EXPECT_EQ(m.tshell_sets.at(6), both);  // _GENERATE leaves the solid out
  EXPECT_EQ(m.tshell_sets.at(7), both);
  EXPECT_TRUE(m.element_sets[0].empty());
  EXPECT_EQ(m.history_elements[0], both);
  ASSERT_EQ(m.cross_sections.size(), 1u);
  EXPECT_EQ(m.cross_sections[0].set_elements[0], both);

  const std::string solid_in_set = errorOf([&] {
    readModel(t.write("e.k", deck("*SECTION_TSHELL\n1\n", "10,1,1,2,3,4,5,6,7,8\n" + more) +
                                 "*SET_TSHELL\n5\n10,20\n*DATABASE_HISTORY_TSHELL_SET\n5\n"));
  });
  EXPECT_NE(solid_in_set.find("(K2): element 20 is a solid, not a thick shell"), std::string::npos)
      << solid_in_set;
  const std::string undefined = errorOf([&] {
    readModel(t.write("u.k", deck("*SECTION_TSHELL\n1\n") + "*DATABASE_HISTORY_TSHELL_SET\n9\n"));
  });
  EXPECT_NE(undefined.find("(ID1): thick shell set 9"), std::string::npos) << undefined;
  const std::string solid_history = errorOf([&] {
    readModel(t.write("h.k", deck("*SECTION_TSHELL\n1\n", "10,1,1,2,3,4,5,6,7,8\n" + more) +
                                 "*DATABASE_HISTORY_TSHELL\n20\n"));
  });
  EXPECT_NE(solid_history.find("(ID1): thick shell element 20 is not defined"), std::string::npos)
      << solid_history;
}
