// The d3plot layout (src/output/d3plot.hpp): family names, material numbering and the word
// counts the LS-DYNA "Database Binary Output Files" manual derives from the control words.
#include <gtest/gtest.h>

#include "model/model.hpp"
#include "output/d3plot.hpp"

namespace {

using crumple::output::d3plotIndex;
using crumple::output::d3plotLayout;
using crumple::output::D3plotLayout;
using crumple::output::d3plotName;

TEST(D3plotFamily, NamesAndIndicesRoundTrip) {
  EXPECT_EQ(d3plotName(0), "d3plot");
  EXPECT_EQ(d3plotName(1), "d3plot01");
  EXPECT_EQ(d3plotName(99), "d3plot99");
  EXPECT_EQ(d3plotName(100), "d3plot100");  // LS-DYNA's third digit
  for (int k : {0, 1, 7, 10, 99, 100, 1234}) EXPECT_EQ(d3plotIndex(d3plotName(k)), k);
  for (const char* other : {"d3plo", "d3plot1", "d3plotx1", "d3plot01.bak", "xd3plot01", "d3dump"})
    EXPECT_EQ(d3plotIndex(other), -1) << other;
}

// Parts 10 (shells), 20 (solids), 30 (discretes), 40 (no element), 50 (beams), 60 (solids).
crumple::model::Model mixedModel() {
  crumple::model::Model m;
  for (int64_t id : {10, 20, 30, 40, 50, 60}) {
    crumple::model::Part p;
    p.id = id;
    m.parts.push_back(p);
  }
  m.nodes.id = {1, 2, 3};
  m.nodes.x.resize(3);
  m.solids.id = {1, 2, 3};
  m.solids.part = {5, 1, 5};
  m.solids.nodes.resize(3);
  m.shells.id = {1};
  m.shells.part = {0};
  m.shells.nodes.resize(1);
  m.beams.id = {1, 2};
  m.beams.part = {4, 4};
  m.beams.nodes.resize(2);
  m.discretes.id = {7};
  m.discretes.part = {2};
  m.discretes.nodes.resize(1);
  return m;
}

TEST(D3plotLayout, MaterialNumbersGoToSolidThenShellThenBeamParts) {
  const D3plotLayout l = d3plotLayout(mixedModel());
  EXPECT_EQ(l.nummat8, 2);
  EXPECT_EQ(l.nummat4, 1);
  EXPECT_EQ(l.nummat2, 2);
  EXPECT_EQ(l.nmmat, 5);
  // Model parts 1 (20) and 5 (60) hold solids, 0 (10) shells, 2 (30) and 4 (50) beams and
  // discretes; part 3 (40) has no element.
  EXPECT_EQ(l.part_of_material, (std::vector<int32_t>{1, 5, 0, 2, 4}));
  EXPECT_EQ(l.material, (std::vector<int32_t>{3, 1, 4, 0, 5, 2}));
  EXPECT_EQ(l.nel2, 3);  // beams, then the discrete element
  EXPECT_EQ(l.num_beams, 2);
}

TEST(D3plotLayout, StateWordsFollowTheControlWords) {
  crumple::model::Model m = mixedModel();
  D3plotLayout l = d3plotLayout(m);
  // NV2D = MAXINT (6 IOSHL1 + IOSHL2) + 8 IOSHL3 + 4 IOSHL4 with MAXINT 3.
  EXPECT_EQ(l.nv2d(), 3 * 7 + 8 + 4);
  EXPECT_EQ(l.nglbv(), 6 + 7 * 5);
  // time, globals, x v a of 3 nodes, 3 solids x 7, 3 beams x 6, 1 shell x NV2D, deletion.
  EXPECT_EQ(l.stateWords(), 1 + 41 + 27 + 21 + 18 + 33 + 7);
  m.controls.d3plot_extent.shell_stress = false;
  m.controls.d3plot_extent.shell_resultants = false;
  l = d3plotLayout(m);
  EXPECT_EQ(l.nv2d(), 3 * 1 + 4);
}

}  // namespace
