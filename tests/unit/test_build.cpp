#include <algorithm>
// Deck -> Model (src/model/build*.cpp): ordering, defaulting, curves, sets, conditions,
// unsupported and ignored reports, exact error messages, and the real decks in ../shared.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "model/build.hpp"
#include "model/serialize.hpp"
#include "temp_dir.hpp"
#include "util/error.hpp"
#include "util/id_index.hpp"

namespace fs = std::filesystem;
using crumple::model::Model;
using crumple::model::readModel;
using crumple::util::InputError;

namespace {

using crumple::testing::errorOf;
// Each test's files in a fresh folder, removed afterwards.
class TempDir : public crumple::testing::TempDir {
 public:
  TempDir() : crumple::testing::TempDir("crumple_test_build") {}
};

// Two unit hexahedra along x, nodes and elements given in descending id order.
const std::string kMesh = R"(*KEYWORD
*NODE
30,2,1,1
29,2,0,1
28,2,1,0
27,2,0,0
8,0,1,1
7,1,1,1
6,1,0,1
5,0,0,1
4,0,1,0
3,1,1,0
2,1,0,0
1,0,0,0
*ELEMENT_SOLID
20,1,2,27,28,3,6,29,30,7
10,1,1,2,3,4,5,6,7,8
*PART
block
1,1,1
*SECTION_SOLID
1,1
*MAT_ELASTIC
1,7.8e-9,2.0e5,0.3
)";

Model build(const TempDir& t, const std::string& extra, const std::string& name = "d.k") {
  return readModel(t.write(name, kMesh + extra));
}

}  // namespace

TEST(BuildModel, IndicesAscendingByUserId) {
  TempDir t;
  const Model m = build(t, "");
  ASSERT_EQ(m.nodes.size(), 12u);
  EXPECT_EQ(m.nodes.id.front(), 1);
  EXPECT_EQ(m.nodes.id.back(), 30);
  ASSERT_EQ(m.solids.size(), 2u);
  EXPECT_EQ(m.solids.id[0], 10);
  EXPECT_EQ(m.solids.id[1], 20);
  EXPECT_EQ(m.solids.nodes[0][0], m.nodeIndex(1));
  EXPECT_EQ(m.solids.nodes[1][1], m.nodeIndex(27));
  EXPECT_EQ(m.solids.part[0], m.partIndex(1));
  EXPECT_EQ(m.parts.at(0).title, "block");
  EXPECT_EQ(m.solid_sections.at(0).elform, 1);
  EXPECT_EQ(m.parts[0].material, 0);
  EXPECT_EQ(m.parts[0].hourglass, crumple::model::kNone);
  EXPECT_EQ(m.initial_velocity.size(), 12u);
  EXPECT_TRUE(m.unsupported.empty());
}

TEST(BuildModel, TwoCardElementsTetsAndWedges) {
  TempDir t;
  const Model m =
      build(t,
            "*ELEMENT_SOLID\n"
            "      30       1\n"
            "       1       2       3       5\n"
            "      31       1       1       2       3       5\n"
            "      32       1       1       2       3       3       5       6       7       7\n");
  ASSERT_EQ(m.solids.size(), 5u);
  const auto n = [&](int64_t id) { return m.nodeIndex(id); };
  const std::array<int32_t, 8> tet{n(1), n(2), n(3), n(5), n(5), n(5), n(5), n(5)};
  EXPECT_EQ(m.solids.nodes[2], tet);
  EXPECT_EQ(m.solids.nodes[3], tet);
  const std::array<int32_t, 8> wedge{n(1), n(2), n(3), n(3), n(5), n(6), n(7), n(7)};
  EXPECT_EQ(m.solids.nodes[4], wedge);
}

TEST(BuildModel, ZeroOrBlankMeansDefault) {
  TempDir t;
  const Model m = build(t,
                        "*CONTROL_TIMESTEP\n0.0,0.0\n"
                        "*CONTROL_BULK_VISCOSITY\n0,0\n"
                        "*CONTROL_HOURGLASS\n0,0\n"
                        "*CONTROL_TERMINATION\n0.5,0,0,0,0\n"
                        "*HOURGLASS\n7,0,0\n"
                        "*DEFINE_CURVE\n1\n0,0\n1,1\n"
                        "*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,3,2,1,0,0,0,0\n");
  const auto& c = m.controls;
  EXPECT_DOUBLE_EQ(c.tssfac, 0.9);
  EXPECT_DOUBLE_EQ(c.q_quadratic, 1.5);
  EXPECT_DOUBLE_EQ(c.q_linear, 0.06);
  EXPECT_EQ(c.hourglass_ihq, 1);
  EXPECT_DOUBLE_EQ(c.hourglass_qh, 0.1);
  EXPECT_DOUBLE_EQ(c.end_time, 0.5);
  EXPECT_DOUBLE_EQ(c.end_mass_ratio, 0.0);
  ASSERT_EQ(m.hourglass.size(), 1u);
  EXPECT_EQ(m.hourglass[0].ihq, 1);
  EXPECT_DOUBLE_EQ(m.hourglass[0].qm, 0.1);
  ASSERT_EQ(m.prescribed.size(), 1u);
  const auto& pm = m.prescribed[0];
  EXPECT_EQ(pm.dof, 2);
  EXPECT_EQ(pm.kind, crumple::model::MotionKind::Displacement);
  EXPECT_DOUBLE_EQ(pm.sf, 1.0);
  EXPECT_EQ(pm.death, std::numeric_limits<double>::infinity());
}

TEST(BuildModel, CurveScaleAndOffset) {
  TempDir t;
  // x = SFA (a + OFFA), y = SFO (o + OFFO); SFO 0 means 1.
  const Model m = build(t,
                        "*DEFINE_CURVE_TITLE\nramp\n"
                        "         5         0       2.0       0.0       1.0      10.0\n"
                        "                 0.0                 1.0\n"
                        "\n"
                        "                 1.0                 3.0\n");
  ASSERT_EQ(m.curves.size(), 1u);
  const auto& c = m.curves[m.curveIndex(5)];
  ASSERT_EQ(c.x.size(), 2u);
  EXPECT_DOUBLE_EQ(c.x[0], 2.0);
  EXPECT_DOUBLE_EQ(c.x[1], 4.0);
  EXPECT_DOUBLE_EQ(c.y[0], 11.0);
  EXPECT_DOUBLE_EQ(c.y[1], 13.0);
}

TEST(BuildModel, SetsListsGenerateGeneralAndSegments) {
  TempDir t;
  const Model m = build(t,
                        "*DEFINE_BOX\n3,1.5,2.5,-1,2,-1,2\n"
                        "*SET_NODE_LIST_TITLE\nends\n1\n30,1,0,0,0,0,0,0\n"
                        "*SET_NODE_LIST_GENERATE\n2\n2,5,27,100\n"
                        "*SET_PART_LIST_GENERATE\n4\n1,9\n"
                        "*SET_PART\n5\n1\n"
                        "*SET_NODE_GENERAL\n6\nPART,1\nDNODE,1,2\nDBOX,3\n"
                        "*SET_NODE_GENERAL\n7\nALL\n"
                        "*SET_NODE_GENERAL\n8\nSET,1,2\n"
                        "*SET_SEGMENT\n9\n1,2,3,4\n5,6,7\n");
  const auto n = [&](int64_t id) { return m.nodeIndex(id); };
  EXPECT_EQ(m.node_sets.at(1), (std::vector<int32_t>{n(1), n(30)}));
  EXPECT_EQ(m.node_sets.at(2),
            (std::vector<int32_t>{n(2), n(3), n(4), n(5), n(27), n(28), n(29), n(30)}));
  EXPECT_EQ(m.part_sets.at(4), std::vector<int32_t>{0});
  EXPECT_EQ(m.part_sets.at(5), std::vector<int32_t>{0});
  EXPECT_EQ(m.node_sets.at(6), (std::vector<int32_t>{n(3), n(4), n(5), n(6), n(7), n(8)}));
  EXPECT_EQ(m.node_sets.at(7).size(), 12u);
  EXPECT_EQ(m.node_sets.at(8).size(), 9u);
  const auto& seg = m.segment_sets.at(9);
  ASSERT_EQ(seg.size(), 2u);
  EXPECT_EQ(seg[1], (std::array<int32_t, 4>{n(5), n(6), n(7), n(7)}));
}

// _COLLECT (Keyword Manual, *SET): the sets of one id are merged, as preprocessors write a
// set in pieces; a repeat without _COLLECT stays an error, and a bad member in any piece
// makes the merged set unusable.
TEST(BuildModel, CollectedSetsOfOneIdAreMerged) {
  TempDir t;
  const Model m = build(t,
                        "*SET_NODE_LIST_COLLECT\n1\n30,1\n*SET_NODE_LIST_COLLECT_TITLE\nmore\n"
                        "1\n2,1\n*SET_PART_LIST_COLLECT_TITLE\nBASE\n5\n1\n"
                        "*SET_PART_LIST_COLLECT\n5\n1\n*SET_SOLID_COLLECT\n3\n20\n"
                        "*SET_SOLID_LIST_COLLECT\n3\n10\n*SET_NODE_LIST_COLLECT\n4\n1\n"
                        "*SET_NODE_LIST_COLLECT\n4\n99\n");
  const auto n = [&](int64_t id) { return m.nodeIndex(id); };
  EXPECT_EQ(m.node_sets.at(1), (std::vector<int32_t>{n(1), n(2), n(30)}));
  EXPECT_EQ(m.part_sets.at(5), std::vector<int32_t>{0});
  EXPECT_EQ(m.element_sets[0].at(3), (std::vector<int32_t>{0, 1}));
  EXPECT_EQ(m.node_sets.count(4), 0u);  // node 99 does not exist: unusable as a whole
  for (const char* repeat : {"*SET_NODE_LIST\n1\n1\n*SET_NODE_LIST_COLLECT\n1\n2\n",
                             "*SET_NODE_LIST_COLLECT\n1\n1\n*SET_NODE_LIST\n1\n2\n"}) {
    const auto d = t.write("dup.k", kMesh + repeat);
    EXPECT_NE(errorOf([&] { readModel(d); }).find("node set 1 is already defined at"),
              std::string::npos)
        << repeat;
  }
}

// *SET_SOLID (_LIST, _GENERATE, _TITLE, _ADD): members as indices within the family, ascending;
// each family has its own ids; an element that does not exist makes the set unusable.
TEST(BuildModel, ElementSetsListGenerateAddAndMissingMembers) {
  TempDir t;
  const Model m = build(t,
                        "*SET_SOLID_TITLE\nsecond\n1\n20\n"
                        "*SET_SOLID_LIST\n2,MECH\n20,10,20\n"
                        "*SET_SOLID_GENERATE\n3\n11,25\n"
                        "*SET_SOLID_ADD\n4\n1,3\n"
                        "*SET_SOLID\n5\n10,99\n"
                        "*SET_SHELL_LIST\n1,1.0\n"
                        "*SET_BEAM_GENERATE\n1\n1,1000\n");
  const auto& solid = m.element_sets[0];
  EXPECT_EQ(solid.at(1), std::vector<int32_t>{1});
  EXPECT_EQ(solid.at(2), (std::vector<int32_t>{0, 1}));
  EXPECT_EQ(solid.at(3), std::vector<int32_t>{1});
  EXPECT_EQ(solid.at(4), std::vector<int32_t>{1});
  EXPECT_EQ(solid.count(5), 0u);  // solid 99 does not exist: skipped, an error on use
  ASSERT_FALSE(m.ignored.empty());
  EXPECT_NE(m.ignored.back().reason.find("d.k:"), std::string::npos);
  EXPECT_NE(m.ignored.back().reason.find("solid element 99 is not defined"), std::string::npos);
  EXPECT_TRUE(m.element_sets[1].at(1).empty());
  EXPECT_TRUE(m.element_sets[2].at(1).empty());
}

// *DATABASE_HISTORY_SOLID (_SET) and *DATABASE_CROSS_SECTION_SET refer to element sets; a set
// that names a missing element is an error there, naming the member's file:line and field.
TEST(BuildModel, HistoryElementsAndSetCrossSections) {
  TempDir t;
  const Model m = build(t,
                        "*SET_SOLID\n2\n10,20\n*SET_NODE_LIST\n3\n2,3\n"
                        "*DATABASE_ELOUT\n0.5\n*DATABASE_HISTORY_SOLID\n20\n"
                        "*DATABASE_HISTORY_SOLID_SET\n2\n"
                        "*DATABASE_CROSS_SECTION_SET_ID\n4,cut\n3,2\n");
  EXPECT_EQ(m.history_elements[0], (std::vector<int32_t>{0, 1}));
  EXPECT_TRUE(m.controls.ascii.elout);
  EXPECT_EQ(m.controls.elout_dt, 0.5);
  ASSERT_EQ(m.cross_sections.size(), 1u);
  const auto& cs = m.cross_sections[0];
  EXPECT_EQ(cs.id, 4);
  EXPECT_TRUE(cs.by_set);
  EXPECT_EQ(cs.set_nodes, (std::vector<int64_t>{2, 3}));
  EXPECT_EQ(cs.set_elements[0], (std::vector<int32_t>{0, 1}));

  const auto bad =
      t.write("bad.k", kMesh + "*SET_SOLID\n5\n10,99\n*DATABASE_HISTORY_SOLID_SET\n5\n");
  const std::string e = errorOf([&] { readModel(bad); });
  EXPECT_NE(e.find("*DATABASE_HISTORY_SOLID_SET card 1 field 1 (ID1): solid set 5 cannot be used"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("*SET_SOLID card 2 field 2 (K2): solid element 99 is not defined"),
            std::string::npos)
      << e;
  const auto missing = t.write("missing.k", kMesh + "*DATABASE_HISTORY_SHELL\n7\n");
  EXPECT_NE(errorOf([&] { readModel(missing); }).find("(ID1): shell element 7 is not defined"),
            std::string::npos);
}

// *SECTION_BEAM ELFORM 9, *MAT_SPOTWELD and *INITIAL_AXIAL_FORCE_BEAM on a *SET_BEAM; what
// they refuse.
// *MAT_SPOTWELD on a hexahedral part: the solid weld runs with EFAIL; TFAIL and the resultant
// limits, which only the spot-weld beam evaluates, are refused naming the part.
TEST(BuildModel, SpotweldOnSolidsTakesEfailOnly) {
  TempDir t;
  const std::string part =
      "*PART\nweld\n2,2,2\n*SECTION_SOLID\n2,1\n*ELEMENT_SOLID\n"
      "30,2,1,2,3,4,5,6,7,8\n";
  const Model m = build(t, part + "*MAT_SPOTWELD\n2,7.8e-9,2e5,0.3,300,1000\n0.1\n");
  EXPECT_EQ(m.solids.size(), 3u);
  auto err = [&](const std::string& extra) { return errorOf([&] { build(t, extra, "e.k"); }); };
  EXPECT_NE(err(part + "*MAT_SPOTWELD\n2,7.8e-9,2e5,0.3,300,1000,0,1e-3\n")
                .find("part 2 has material 2 (*MAT_SPOTWELD) on solid elements: TFAIL"),
            std::string::npos);
  EXPECT_NE(err(part + "*MAT_SPOTWELD\n2,7.8e-9,2e5,0.3,300,1000\n0.1,5\n")
                .find("the resultant failure NRR .. MTT is applied to spot-weld beams only"),
            std::string::npos);
}

// *ELEMENT_BEAM RT1 RR1 RT2 RR2 (0 none, 1 x, 2 y, 3 z, 4 xy, 5 yz, 6 zx, 7 all): the element
// runs with a copy of its section holding the release bits (translations r s t at bits 0-2,
// rotations at 3-5, end 2 six bits up); elements with the same releases share it.
TEST(BuildModel, BeamEndReleasesGoToTheirElementsSection) {
  TempDir t;
  const std::string part = "*PART\nhl\n3,3,1\n*SECTION_BEAM\n3,1,1,2,1\n6.0\n";
  const Model m = build(t, part +
                               "*ELEMENT_BEAM\n42,3,3,29,0,0,3,5,0\n43,3,2,28\n"
                               "44,3,1,27,0,0,3,5,0,2\n");
  EXPECT_TRUE(m.unsupported.empty());
  ASSERT_EQ(m.beam_sections.size(), 2u);
  EXPECT_EQ(m.beam_sections[0].release, 0);
  // End 1 RR 3: rotation about t (bit 5); end 2 RT 5: translations along s and t (bits 7, 8).
  EXPECT_EQ(m.beam_sections[1].release, (1 << 5) | (1 << 7) | (1 << 8));
  EXPECT_EQ(m.beams.section[0], 1);                      // 42
  EXPECT_EQ(m.beams.section[1], crumple::model::kNone);  // 43: its part's section
  EXPECT_EQ(m.beams.section[2], 1);                      // 44 shares 42's
  auto err = [&](const std::string& extra) { return errorOf([&] { build(t, extra, "e.k"); }); };
  EXPECT_NE(err(part + "*ELEMENT_BEAM\n42,3,3,29,0,8\n").find("field 6 (RT1): must be 0 to 7"),
            std::string::npos);
  EXPECT_NE(err(part + "*ELEMENT_BEAM\n42,3,3,29,0,0,0,0,0,3\n").find("(LOCAL): must be 1 or 2"),
            std::string::npos);
  // Global axes, and releases on a truss: refused.
  EXPECT_NE(err(part + "*ELEMENT_BEAM\n42,3,3,29,0,0,3,0,0,1\n").find("global axes (LOCAL 1)"),
            std::string::npos);
  const std::string truss = "*PART\ntruss\n3,3,1\n*SECTION_BEAM\n3,3\n1.0\n";
  EXPECT_NE(err(truss + "*ELEMENT_BEAM\n42,3,3,29,0,0,0,0,2\n")
                .find("(RR2): end releases apply to "
                      "ELFORM 1 and 2 beams"),
            std::string::npos);
}

TEST(BuildModel, SpotweldBeamsAndTheirPreload) {
  TempDir t;
  const std::string weld =
      "*PART\nweld\n2,2,2\n*SECTION_BEAM\n2,9,1,2,1\n6.0\n"
      "*MAT_SPOTWELD\n2,7.8e-9,2e5,0.3,300,1000\n0.1,5,6,6\n"
      "*ELEMENT_BEAM\n40,2,1,27\n41,2,2,28\n*DEFINE_CURVE\n9\n0,0\n1,1\n";
  const Model m = build(t, weld + "*SET_BEAM\n5\n41\n*INITIAL_AXIAL_FORCE_BEAM\n5,9,2.5,1\n");
  ASSERT_EQ(m.beam_preloads.size(), 1u);
  EXPECT_EQ(m.beam_preloads[0].beams, std::vector<int32_t>{1});
  EXPECT_EQ(m.beam_preloads[0].curve, m.curveIndex(9));
  EXPECT_DOUBLE_EQ(m.beam_preloads[0].scale, 2.5);
  EXPECT_TRUE(m.beam_preloads[0].kbend);
  EXPECT_EQ(m.beam_sections[0].elform, 9);
  auto err = [&](const std::string& extra) { return errorOf([&] { build(t, extra, "e.k"); }); };
  auto has = [](const std::string& e, const std::string& what) {
    return e.find(what) != std::string::npos;
  };
  // The weld material on another beam formulation; the preload of a beam that is not a weld,
  // or of one preloaded twice; the fields Crumple does not do.
  const std::string hl =
      "*PART\nhl\n3,3,2\n*SECTION_BEAM\n3,1,1,2,1\n6.0\n*ELEMENT_BEAM\n42,3,3,29\n";
  EXPECT_TRUE(has(err(weld + hl), "which Crumple runs only on spot-weld beams")) << err(weld + hl);
  const std::string elastic =
      "*PART\nhl\n3,3,1\n*SECTION_BEAM\n3,1,1,2,1\n6.0\n"
      "*ELEMENT_BEAM\n42,3,3,29\n*SET_BEAM\n6\n42\n"
      "*INITIAL_AXIAL_FORCE_BEAM\n6,9\n";
  EXPECT_TRUE(has(err(weld + elastic), "beam 42 (part 3) is not a spot-weld beam"));
  const std::string twice = "*SET_BEAM\n5\n41\n*INITIAL_AXIAL_FORCE_BEAM\n5,9\n5,9\n";
  EXPECT_TRUE(has(err(weld + twice), "beam 41 is already preloaded"));
  const std::string dt =
      "*PART\nweld\n2,2,2\n*SECTION_BEAM\n2,9,1,2,1\n6.0\n"
      "*MAT_SPOTWELD\n2,7.8e-9,2e5,0.3,300,1000,1e-6\n"
      "*ELEMENT_BEAM\n40,2,1,27\n";
  EXPECT_TRUE(has(err(dt), "(DT)")) << err(dt);
}

TEST(BuildModel, BoundaryConditionsLoadsAndInitialVelocity) {
  TempDir t;
  const Model m = build(t,
                        "*DEFINE_CURVE\n1\n0,0\n1,1\n"
                        "*SET_NODE_LIST\n1\n1,2\n"
                        "*SET_PART_LIST\n2\n1\n"
                        "*BOUNDARY_SPC_SET\n1,0,1,0,1\n"
                        "*BOUNDARY_SPC_NODE\n1,0,0,1\n"
                        "*BOUNDARY_PRESCRIBED_MOTION_SET_ID\n1,pm\n1,1,0,1,2.0,0,5.0,1.0\n"
                        "*LOAD_NODE_POINT\n3,2,1,4.0\n"
                        "*DEFINE_COORDINATE_SYSTEM\n9,0,0,0,0,1,0\n0,0,1\n"
                        "*LOAD_NODE_SET\n1,1,1,2.0,9\n"
                        "*LOAD_SEGMENT\n1,3.0,0.5,1,2,3,4\n"
                        "*SET_SEGMENT\n4\n5,6,7,8\n"
                        "*LOAD_SEGMENT_SET\n4,1,0,0.1\n"
                        "*LOAD_BODY_Z\n1,9.81\n"
                        "*INITIAL_VELOCITY\n0\n1,2,3\n"
                        "*INITIAL_VELOCITY_GENERATION\n2,1,2.0,0,0,10\n0,0,0,0,0,1\n");
  const auto n = [&](int64_t id) { return m.nodeIndex(id); };
  ASSERT_EQ(m.spcs.size(), 2u);
  EXPECT_EQ(m.spcs[0].node, n(1));
  EXPECT_EQ(m.spcs[0].dofs, 0b111);
  EXPECT_EQ(m.spcs[1].dofs, 0b101);
  ASSERT_EQ(m.prescribed.size(), 2u);
  EXPECT_EQ(m.prescribed[0].dof, 0);
  EXPECT_DOUBLE_EQ(m.prescribed[0].sf, 2.0);
  EXPECT_DOUBLE_EQ(m.prescribed[0].death, 5.0);
  EXPECT_DOUBLE_EQ(m.prescribed[0].birth, 1.0);
  // Load along local x of system 9, which is global y: one global component.
  ASSERT_EQ(m.nodal_loads.size(), 3u);
  EXPECT_EQ(m.nodal_loads[0].dof, 1);
  EXPECT_DOUBLE_EQ(m.nodal_loads[0].sf, 4.0);
  EXPECT_EQ(m.nodal_loads[1].dof, 1);
  EXPECT_DOUBLE_EQ(m.nodal_loads[1].sf, 2.0);
  ASSERT_EQ(m.pressure_loads.size(), 2u);
  EXPECT_DOUBLE_EQ(m.pressure_loads[0].sf, 3.0);
  EXPECT_DOUBLE_EQ(m.pressure_loads[0].at, 0.5);
  EXPECT_DOUBLE_EQ(m.pressure_loads[1].sf, 1.0);
  ASSERT_EQ(m.body_loads.size(), 1u);
  EXPECT_EQ(m.body_loads[0].dof, 2);
  EXPECT_DOUBLE_EQ(m.body_loads[0].sf, 9.81);
  // Generation (part set 2 = part 1, every node) after *INITIAL_VELOCITY: rotation about z
  // at omega 2 plus vz 10; node 2 at (1,0,0) moves with omega z x r = (0, 2, 0).
  const auto& v2 = m.initial_velocity[n(2)];
  EXPECT_DOUBLE_EQ(v2[0], 0.0);
  EXPECT_DOUBLE_EQ(v2[1], 2.0);
  EXPECT_DOUBLE_EQ(v2[2], 10.0);
}

TEST(BuildModel, RigidWallPlanarFiniteMovingWithId) {
  TempDir t;
  const Model m =
      build(t,
            "*SET_NODE_LIST\n1\n1,2,3\n"
            "*RIGIDWALL_PLANAR\n0,1\n0,0,-1,0,0,1,0.2\n"
            "*RIGIDWALL_PLANAR_FINITE_MOVING_ID\n7,wall\n1\n0,0,-1,0,0,-2\n1,0,-1,3,4\n100,2.5\n");
  ASSERT_EQ(m.rigid_walls.size(), 2u);
  const auto& a = m.rigid_walls[0];
  EXPECT_EQ(a.id, 1);
  EXPECT_EQ(a.nodes.size(), 9u);  // all nodes except set 1
  EXPECT_DOUBLE_EQ(a.normal[2], 1.0);
  EXPECT_DOUBLE_EQ(a.fric, 0.2);
  const auto& b = m.rigid_walls[1];
  EXPECT_EQ(b.id, 7);
  EXPECT_EQ(b.nodes.size(), 3u);
  EXPECT_DOUBLE_EQ(b.normal[2], -1.0);
  EXPECT_TRUE(b.finite);
  EXPECT_DOUBLE_EQ(b.l_axis[0], 1.0);
  EXPECT_DOUBLE_EQ(b.lenl, 3.0);
  EXPECT_TRUE(b.moving);
  EXPECT_DOUBLE_EQ(b.mass, 100.0);
  EXPECT_DOUBLE_EQ(b.v0, 2.5);
}

TEST(BuildModel, PiecewiseLinearPointsBecomeACurve) {
  TempDir t;
  const Model m = readModel(
      t.write("d.k", kMesh + "*MAT_PIECEWISE_LINEAR_PLASTICITY\n2,7.8e-9,2e5,0.3,250\n0,0,0\n"
                             "0,0.1,0.5\n250,300,400\n*PART\np2\n2,1,2\n"));
  const auto& law = std::get<crumple::materials::PiecewiseLinear::Params>(m.materials.at(1).law);
  ASSERT_NE(law.lcss, crumple::model::kNone);
  const auto& c = m.curves.at(law.lcss);
  EXPECT_EQ(c.id, -2);
  EXPECT_EQ(c.x, (std::vector<double>{0, 0.1, 0.5}));
  EXPECT_EQ(c.y, (std::vector<double>{250, 300, 400}));
}

TEST(BuildErrors, ExactMessages) {
  TempDir t;
  auto err = [&](const std::string& extra, const std::string& name = "e.k") {
    const auto p = t.write(name, kMesh + extra);
    return errorOf([&] { readModel(p); });
  };
  const std::string file = (t.path() / "e.k").string();
  auto at = [&](int line) { return file + ":" + std::to_string(line) + ": "; };
  // Lines 1-24 are kMesh.
  // A part, material or section no element uses may be incomplete (LS-DYNA reads such
  // decks); an element of it is an error naming the part and, for a definition's own error,
  // that definition's line.
  EXPECT_EQ(err("*PART\nsecond\n2,1,7\n"), "");
  const std::string use = "*PART\nsecond\n2,1,2\n*ELEMENT_SOLID\n3,2,1,2,3,4,5,6,7,8\n";
  auto used = [&](int line) {
    return " (the part is used by *ELEMENT_SOLID at " + file + ":" + std::to_string(line) + ")";
  };
  EXPECT_EQ(err("*PART\nsecond\n2,1,7\n*ELEMENT_SOLID\n3,2,1,2,3,4,5,6,7,8\n"),
            at(27) + "*PART card 2 field 3 (MID): material 7 is not defined" + used(29));
  EXPECT_EQ(err("*ELEMENT_SOLID\n3,1,1,2,3,4,5,6,7,99\n"),
            at(26) + "*ELEMENT_SOLID card 1 field 10 (N8): node 99 is not defined");
  EXPECT_EQ(err("*NODE\n7,0,0,0\n"),
            at(26) + "*NODE card 1 field 1 (NID): node 7 is already defined at " + file + ":8");
  EXPECT_EQ(err("*MAT_ELASTIC\n2,0,1,0.3\n"), "");
  EXPECT_EQ(err("*MAT_ELASTIC\n2,0,1,0.3\n" + use),
            at(26) + "*MAT_ELASTIC card 1 field 2 (RO): the density must be positive" + used(31));
  EXPECT_EQ(err("*MAT_ELASTIC\n2,1,1,0.5\n" + use),
            at(26) + "*MAT_ELASTIC card 1 field 4 (PR): Poisson's ratio must lie in (-1, 0.5)" +
                used(31));
  EXPECT_EQ(err("*MAT_ELASTIC\n1,1,1,0.3\n"),
            at(26) + "*MAT_ELASTIC card 1 field 1 (MID): material 1 is already defined at " + file +
                ":24");
  EXPECT_EQ(err("*RIGIDWALL_PLANAR_ORTHO\n0\n0,0,0,0,0,1\n"),
            at(25) + "*RIGIDWALL_PLANAR_ORTHO: option _ORTHO is not supported");
  EXPECT_EQ(err("*BOUNDARY_SPC_NODE\n1,5,1\n"),
            at(26) +
                "*BOUNDARY_SPC_NODE card 1 field 2 (CID): a local coordinate system is not "
                "supported here");
  EXPECT_EQ(
      err("*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,1,0,3\n"),
      at(26) + "*BOUNDARY_PRESCRIBED_MOTION_NODE card 1 field 4 (LCID): curve 3 is not defined");
  // An unsupported section is an error only when an element uses it.
  EXPECT_EQ(err("*SECTION_SOLID\n2,115\n*PART\nother\n2,2,1\n"), "");
  EXPECT_EQ(
      err("*SECTION_SOLID\n2,115\n*PART\nother\n2,2,1\n*ELEMENT_SOLID\n3,2,1,2,3,4,5,6,7,8\n"),
      at(31) +
          "*ELEMENT_SOLID card 1 field 2 (PID): part 2 uses *SECTION_SOLID ELFORM=115 "
          "(section 2 at " +
          file + ":26), which is not supported yet");
  // A tetrahedron section takes elements of four distinct nodes only.
  EXPECT_EQ(err("*SECTION_SOLID\n2,10\n*PART\nother\n2,2,1\n*ELEMENT_SOLID\n3,2,1,2,3,4,5,6,7,8\n"),
            at(31) +
                "*ELEMENT_SOLID card 1 field 3 (N1): a tetrahedron (*SECTION_SOLID ELFORM 10, 13) "
                "needs 4 distinct nodes, not 8 (N1 N2 N3 N4, N5 to N8 blank or N4)");
  const auto empty = t.write("n.k", "*KEYWORD\n*NODE\n1,0,0,0\n");
  EXPECT_EQ(errorOf([&] { readModel(empty); }),
            empty.string() +
                ": the deck defines no elements Crumple can run (*ELEMENT_SOLID, _SHELL, _BEAM, "
                "_DISCRETE or _SPH)");
}

// *CONTROL_RIGID: defaults accepted; PLOTEL (output only) noted; LMF 1 (Lagrange multiplier
// joints) refused by name. IHQ 8 (the warping stiffness of ELFORM 16 shells) on a part of
// one-point hexahedra is refused; on fully integrated hexahedra (no hourglass control) it is
// accepted; IHQ 9 is refused.
TEST(BuildControls, ControlRigidAndWarpingHourglass) {
  TempDir t;
  auto err = [&](const std::string& mesh, const std::string& extra) {
    return errorOf([&] { readModel(t.write("c.k", mesh + extra)); });
  };
  const Model m = build(t, "*CONTROL_RIGID\n0,0,0,0,0,0,1,0\n0\n");
  ASSERT_FALSE(m.ignored.empty());
  EXPECT_EQ(m.ignored.back().field, "PLOTEL");
  EXPECT_NE(err(kMesh, "*CONTROL_RIGID\n1\n").find("LMF"), std::string::npos);
  EXPECT_NE(err(kMesh, "*CONTROL_RIGID\n0,1\n").find("JNTF"), std::string::npos);
  EXPECT_NE(err(kMesh, "*CONTROL_HOURGLASS\n8\n").find("IHQ 8 (the warping stiffness"),
            std::string::npos);
  std::string full = kMesh;
  const std::string one = "*SECTION_SOLID\n1,1\n";
  full.replace(full.find(one), one.size(), "*SECTION_SOLID\n1,-1\n");
  EXPECT_EQ(err(full, "*CONTROL_HOURGLASS\n8\n"), "");
  EXPECT_EQ(readModel(t.write("f.k", full + "*CONTROL_HOURGLASS\n8\n")).controls.hourglass_ihq, 8);
  EXPECT_NE(err(full, "*CONTROL_HOURGLASS\n9\n").find("(1 to 5 and 8 are)"), std::string::npos);
}

TEST(BuildErrors, RigidPart) {
  TempDir t;
  const auto p = t.write("r.k", kMesh +
                                    "*MAT_RIGID\n2,7.8e-9,2e5,0.3\n"
                                    "*PART\nrigid\n2,1,2\n"
                                    "*ELEMENT_SOLID\n3,2,1,2,3,4,5,6,7,8\n");
  const Model m = readModel(p);
  EXPECT_EQ(m.solids.size(), 3u);
  // *MAT_RIGID is read: the part is a rigid body with the card's constants.
  const auto& rigid = m.materials[std::size_t(m.parts[m.partIndex(2)].material)];
  ASSERT_TRUE(std::holds_alternative<crumple::model::RigidLaw>(rigid.law));
  EXPECT_DOUBLE_EQ(std::get<crumple::model::RigidLaw>(rigid.law).E, 2e5);
}

// ---- *DEFINE_TABLE and *MAT_024 rate dependence -------------------------------------------

namespace {

// Two yield curves (ids 11, 12) after a table of rates; `table` is the *DEFINE_TABLE keyword
// with its cards, `mat` the *MAT_024 card 2. Part 3 (solid 4) uses the material.
std::string rateDeck(const std::string& table, const std::string& card2,
                     const std::string& curves =
                         "*DEFINE_CURVE\n11\n0,200\n0.1,300\n"
                         "*DEFINE_CURVE\n12\n0,260\n0.2,400\n") {
  return kMesh + table + curves + "*MAT_024\n3,7.8e-9,2e5,0.3,1\n" + card2 +
         "*PART\ntable\n3,1,3\n*ELEMENT_SOLID\n4,3,1,2,3,4,5,6,7,8\n";
}

const crumple::materials::PiecewiseLinear::Params& mat024(const Model& m) {
  return std::get<crumple::materials::PiecewiseLinear::Params>(
      m.materials.at(std::size_t(m.parts[std::size_t(m.partIndex(3))].material)).law);
}

}  // namespace

TEST(BuildTables, Mat024LcssNamesARateTable) {
  TempDir t;
  // SFA 10, OFFA 1: the values are 10 (v + 1); the curves follow the table in order.
  const Model m =
      readModel(t.write("t.k", rateDeck("*DEFINE_TABLE\n5,10,1\n-1.0\n9.0\n", "0.04,5,5,0,0\n")));
  ASSERT_EQ(m.tables.size(), 1u);
  const auto& table = m.tables[0];
  EXPECT_EQ(table.id, 5);
  EXPECT_EQ(table.values, (std::vector<double>{0.0, 100.0}));
  EXPECT_EQ(table.curve_ids, (std::vector<int64_t>{11, 12}));
  EXPECT_EQ(table.curves, (std::vector<int32_t>{m.curveIndex(11), m.curveIndex(12)}));
  EXPECT_EQ(table.where.line, 25);
  EXPECT_EQ(m.tableIndex(5), 0);
  const auto& law = mat024(m);
  EXPECT_EQ(law.table, 0);
  EXPECT_EQ(law.lcss, crumple::model::kNone);
  // The table gives the rate dependence: C and P are not used, and said so.
  EXPECT_EQ(law.c, 0.0);
  EXPECT_EQ(law.p, 0.0);
  ASSERT_FALSE(m.ignored.empty());
  EXPECT_EQ(m.ignored.back().field, "C");
  // The model travels to the other ranks with its tables.
  const Model r = crumple::model::deserialize(crumple::model::serialize(m));
  ASSERT_EQ(r.tables.size(), 1u);
  EXPECT_EQ(r.tables[0].values, table.values);
  EXPECT_EQ(r.tables[0].curves, table.curves);
  EXPECT_EQ(r.tables[0].curve_ids, table.curve_ids);
  EXPECT_EQ(r.tables[0].where.str(), table.where.str());
  EXPECT_EQ(r.tableIndex(5), 0);
}

TEST(BuildTables, ValueCardsMayNameTheirCurves) {
  TempDir t;
  // LCID given: the curves may be anywhere (here the second value's curve comes first).
  const Model m = readModel(
      t.write("t.k", rateDeck("*DEFINE_TABLE_TITLE\nrates\n5\n-4.6,12\n2.3,11\n", "0,0,5\n")));
  ASSERT_EQ(m.tables.size(), 1u);
  EXPECT_EQ(m.tables[0].values, (std::vector<double>{-4.6, 2.3}));
  EXPECT_EQ(m.tables[0].curve_ids, (std::vector<int64_t>{12, 11}));
  EXPECT_EQ(mat024(m).table, 0);
}

TEST(BuildTables, BadTablesNameFileLineAndField) {
  TempDir t;
  // Rates that do not increase: the second value card (line 28).
  const auto p = t.write("dec.k", rateDeck("*DEFINE_TABLE\n5\n100.0\n10.0\n", "0,0,5\n"));
  EXPECT_EQ(errorOf([&] { readModel(p); }),
            p.string() +
                ":28: *DEFINE_TABLE value card field 1 (VALUE): the values must increase (each "
                "is a strain rate with its own curve)");
  // Three values, two curves after the table: the third value has none.
  const auto q = t.write("miss.k", rateDeck("*DEFINE_TABLE\n5\n0.0\n1.0\n10.0\n", "0,0,5\n"));
  EXPECT_EQ(errorOf([&] { readModel(q); }),
            q.string() +
                ":29: *DEFINE_TABLE value card field 1 (VALUE): no *DEFINE_CURVE follows the "
                "table for this value (without LCID, the curves follow the table, one per value, "
                "in order)");
  // An LCID that names no curve: the table cannot be used, an error where it is used.
  const auto r = t.write("lcid.k", rateDeck("*DEFINE_TABLE\n5\n0.0,11\n1.0,99\n", "0,0,5\n"));
  EXPECT_EQ(
      errorOf([&] { readModel(r); })
          .rfind(r.string() + ":39: *MAT_024 card 2 field 3 (LCSS): curve 5 cannot be used: " +
                     r.string() + ":25: *DEFINE_TABLE 5: value 2: curve 99 is not defined",
                 0),
      0u);
  // A table where a curve is expected (LCSR) is refused as a missing feature.
  const auto s = t.write("lcsr.k", rateDeck("*DEFINE_TABLE\n5\n0.0\n1.0\n", "0,0,11,5\n"));
  EXPECT_EQ(
      errorOf([&] { readModel(s); })
          .rfind(s.string() + ":39: *MAT_024 card 2 field 4 (LCSR): curve 5 is a *DEFINE_TABLE (" +
                     s.string() + ":25), which is not supported here",
                 0),
      0u);
  // A table and a curve may not share an id.
  const auto d = t.write("dup.k", rateDeck("*DEFINE_TABLE\n11\n0.0\n1.0\n", "0,0,11\n"));
  EXPECT_NE(errorOf([&] { readModel(d); }).find("curve 11 is already defined at"),
            std::string::npos);
}

TEST(BuildTables, Mat024LcsrAndVp) {
  TempDir t;
  // LCSR scales the yield stress; C and P are then not used.
  const Model m = readModel(t.write("lcsr.k", rateDeck("", "40,5,11,12\n",
                                                       "*DEFINE_CURVE\n11\n0,200\n0.1,300\n"
                                                       "*DEFINE_CURVE\n12\n0,1\n100,1.5\n")));
  const auto& law = mat024(m);
  EXPECT_EQ(law.lcss, m.curveIndex(11));
  EXPECT_EQ(law.lcsr, m.curveIndex(12));
  EXPECT_EQ(law.table, crumple::model::kNone);
  EXPECT_EQ(law.c, 0.0);
  ASSERT_FALSE(m.ignored.empty());
  EXPECT_EQ(m.ignored.back().field, "C");
  EXPECT_FALSE(law.viscoplastic);
  // VP = 1 (viscoplastic) with a rate table, with LCSR and with C and P.
  const std::string lcsr = "*DEFINE_CURVE\n11\n0,200\n0.1,300\n*DEFINE_CURVE\n12\n0,1\n100,1.5\n";
  for (const auto& deck : {rateDeck("*DEFINE_TABLE\n5\n0.0\n1.0\n", "0,0,5,0,1\n"),
                           rateDeck("", "0,0,11,12,1\n", lcsr), rateDeck("", "40,5,0,0,1\n")}) {
    const Model v = readModel(t.write("vp.k", deck));
    EXPECT_TRUE(mat024(v).viscoplastic) << deck;
  }
  // VP = 3 (filtered rates) is refused, naming the field; without a rate form VP acts on
  // nothing and is said to be ignored.
  const auto p = t.write("vp3.k", rateDeck("*DEFINE_TABLE\n5\n0.0\n1.0\n", "0,0,5,0,3\n"));
  EXPECT_EQ(
      errorOf([&] { readModel(p); })
          .rfind(p.string() + ":39: *MAT_024 card 2 field 5 (VP): VP is 0 (the yield stress at the "
                              "total effective strain rate) or 1 (viscoplastic: at the plastic "
                              "strain rate); -1 and 3 are not supported",
                 0),
      0u);
  const Model n = readModel(t.write("vp0.k", rateDeck("", "0,0,0,0,1\n")));
  EXPECT_FALSE(mat024(n).viscoplastic);
  ASSERT_FALSE(n.ignored.empty());
  EXPECT_EQ(n.ignored.back().field, "VP");
}

TEST(BuildUnsupported, CountsFirstLocationsReasonsAndIgnoredFields) {
  TempDir t;
  const auto p = t.write("u.k", kMesh +
                                    "*ELEMENT_SEATBELT_ACCELEROMETER\n1\n"
                                    "*DATABASE_BINARY_D3THDT\n0.1\n"
                                    "*element_seatbelt_accelerometer\n2\n"
                                    "*CONTROL_IMPLICIT_SOLVER\n1\n"
                                    "*CONTROL_MPP_IO_NODUMP\n"
                                    "*CONTROL_THERMAL_SOLVER\n1\n"
                                    "*CONTROL_SOLID\n0,1\n"
                                    "*SECTION_SOLID\n3,1,1\n");
  const Model m = readModel(p);
  ASSERT_EQ(m.unsupported.size(), 5u);
  EXPECT_EQ(m.unsupported[0].keyword, "*ELEMENT_SEATBELT_ACCELEROMETER");
  EXPECT_EQ(m.unsupported[0].count, 2);
  EXPECT_EQ(m.unsupported[0].first.line, 25);
  EXPECT_EQ(m.unsupported[0].reason, "output not written yet (accelerometer)");
  EXPECT_EQ(m.unsupported[1].reason, "output not written yet");
  EXPECT_EQ(m.unsupported[2].reason, "implicit controls: not used by an explicit analysis");
  EXPECT_EQ(m.unsupported[3].reason, "ignored: MPP/SMP option");
  EXPECT_EQ(m.unsupported[4].reason, "thermal analysis not supported");
  // Only the thermal solver changes the answer: a run refuses the deck for it alone.
  for (std::size_t k = 0; k < 4; ++k) EXPECT_FALSE(m.unsupported[k].changes_answer) << k;
  EXPECT_TRUE(m.unsupported[4].changes_answer);
  EXPECT_EQ(m.unsupported[4].feature, "*CONTROL_THERMAL_SOLVER");
  ASSERT_EQ(m.ignored.size(), 2u);
  // Definitions are read before controls, so the section comes first.
  EXPECT_EQ(m.ignored[0].keyword, "*SECTION_SOLID");
  EXPECT_EQ(m.ignored[0].field, "AET");
  EXPECT_EQ(m.ignored[1].keyword, "*CONTROL_SOLID");
  EXPECT_EQ(m.ignored[1].field, "FMATRX");
  const std::string table = crumple::model::formatUnsupported(m);
  const std::string loc = p.string() + ":25";
  EXPECT_EQ(table.rfind("keyword ", 0), 0u) << table;
  EXPECT_NE(table.find("*ELEMENT_SEATBELT_ACCELEROMETER      2  " + loc +
                       "  output not written yet (accelerometer)\n"),
            std::string::npos)
      << table;
}

// *PART_CONTACT: SSF scales the penalty stiffness of the part's segments (a single surface
// over the part, against the same deck without it); FS (part-based friction) is reported as
// read but not honoured.
TEST(BuildContact, PartContactScalesStiffnessAndReportsFriction) {
  TempDir t;
  const std::string contact = "*CONTACT_AUTOMATIC_SINGLE_SURFACE\n1,0,3,0\n";
  const Model plain = build(t, contact, "plain.k");
  std::string mesh = kMesh;
  const std::string part = "*PART\nblock\n1,1,1\n";
  ASSERT_NE(mesh.find(part), std::string::npos);
  mesh.replace(mesh.find(part), part.size(), "*PART_CONTACT\nblock\n1,1,1\n0.3,,,,,,2.5\n");
  const Model scaled = readModel(t.write("scaled.k", mesh + contact));
  ASSERT_EQ(plain.contacts.size(), 1u);
  ASSERT_EQ(scaled.contacts.size(), 1u);
  const auto& k0 = plain.contacts[0].a.segment_stiffness;
  const auto& k1 = scaled.contacts[0].a.segment_stiffness;
  ASSERT_EQ(k0.size(), 10u);  // two hexes sharing a face: ten free faces
  ASSERT_EQ(k1.size(), k0.size());
  for (std::size_t i = 0; i < k0.size(); ++i) EXPECT_DOUBLE_EQ(k1[i], 2.5 * k0[i]);
  bool fs_reported = false;
  for (const auto& f : scaled.ignored)
    fs_reported |= f.keyword == "*PART_CONTACT" && f.field == "FS";
  EXPECT_TRUE(fs_reported);
}

// _MPP: the MPP cards come after the id card and before card 1, the second only when it
// starts with '&' (Keyword Manual, *CONTACT); their settings are reported, not honoured.
TEST(BuildContact, MppCardsAreReadInTheirPlace) {
  TempDir t;
  const Model m = build(t,
                        "*CONTACT_AUTOMATIC_SINGLE_SURFACE_MPP_ID\n7,with mpp\n"
                        "0,100,,,,,,2\n&,1\n1,0,3,0\n0.2\n");
  ASSERT_EQ(m.contacts.size(), 1u);
  EXPECT_EQ(m.contacts[0].id, 7);
  EXPECT_EQ(m.contacts[0].fs, 0.2);  // card 2, after the two MPP cards and card 1
  auto reported = [&](std::string_view field) {
    return std::any_of(m.ignored.begin(), m.ignored.end(),
                       [&](const auto& i) { return i.field == field; });
  };
  EXPECT_TRUE(reported("BCKT"));
  EXPECT_TRUE(reported("CPARM8"));
  EXPECT_TRUE(reported("CHKSEGS"));
  // _ID (and _MPP) before the algorithm's last words, as abq2dyn writes them.
  const Model tied = build(t,
                           "*CONTACT_TIED_SHELL_EDGE_TO_SURFACE_ID_BEAM_OFFSET_MPP\n8,tie\n"
                           "0,100\n1,1,3,3\n0.2\n",
                           "tied.k");
  ASSERT_EQ(tied.contacts.size(), 1u);
  EXPECT_EQ(tied.contacts[0].id, 8);
  EXPECT_EQ(tied.contacts[0].kind, crumple::model::ContactKind::Tied);
  EXPECT_TRUE(tied.contacts[0].offset);
  EXPECT_TRUE(tied.contacts[0].tie_rotations);
}

// *CONTACT_AUTOMATIC_GENERAL takes the beams of its parts as capsules: radius OPTT / 2 of
// *PART_CONTACT, else half a tube's outer diameter; stiffness SSF x K x 2r (K = E / (3 (1 - 2
// nu)) = 2e5 / 1.2); MPP CPARM8 1 leaves out pairs of one part. A single surface of beams alone
// is refused unless it is AUTOMATIC_GENERAL.
TEST(BuildContact, GeneralContactTakesBeamsAsCapsules) {
  TempDir t;
  const std::string beams =
      "*PART_CONTACT\nrods\n2,2,1\n0,0,0,0,0.5,0,2.0\n*PART\ntubes\n3,2,1\n"
      "*SECTION_BEAM\n2,1,0.8333,2,1\n0.2,0.2,0,0\n"
      "*ELEMENT_BEAM\n1,2,1,2,4\n2,3,5,6,8\n3,3,27,28,29\n*SET_PART_LIST\n10\n2,3\n";
  const Model m = build(t, beams +
                               "*CONTACT_AUTOMATIC_GENERAL_MPP_ID\n7\n0,200,,,,,,1\n"
                               "10,0,2,0\n");
  ASSERT_EQ(m.contacts.size(), 1u);
  const auto& a = m.contacts[0].a;
  ASSERT_EQ(a.edges.size(), 3u);
  EXPECT_TRUE(a.segments.empty());
  EXPECT_TRUE(m.contacts[0].skip_same_part_edges);
  const double k = 2e5 / 1.2;
  EXPECT_DOUBLE_EQ(a.edge_radius[0], 0.25);
  EXPECT_DOUBLE_EQ(a.edge_stiffness[0], 2.0 * k * 0.5);
  EXPECT_DOUBLE_EQ(a.edge_radius[2], 0.1);
  EXPECT_DOUBLE_EQ(a.edge_stiffness[2], k * 0.2);
  EXPECT_EQ(a.edge_part[1], m.partIndex(3));
  const std::string error =
      errorOf([&] { build(t, beams + "*CONTACT_AUTOMATIC_SINGLE_SURFACE\n10,0,2,0\n", "s.k"); });
  EXPECT_NE(error.find("*CONTACT_AUTOMATIC_GENERAL only"), std::string::npos) << error;
}

// _DISPLAY adds a drawing part's card at the end of a geometric wall: read, noted, no force.
TEST(BuildWalls, DisplayCardIsReadAndNoted) {
  TempDir t;
  const Model m = build(t,
                        "*RIGIDWALL_GEOMETRIC_CYLINDER_DISPLAY\n0\n5,0,0,5,0,1\n0.5,2\n"
                        "99,7.8e-9,2e5,0.3\n");
  ASSERT_EQ(m.rigid_walls.size(), 1u);
  EXPECT_EQ(m.rigid_walls[0].radius, 0.5);
  EXPECT_TRUE(std::any_of(m.ignored.begin(), m.ignored.end(),
                          [](const auto& i) { return i.field == "display card"; }));
}

// The real decks in ../shared/decks, read to the end.
TEST(BuildRealDecks, ReadToTheEnd) {
  const fs::path decks = fs::path(CRUMPLE_SHARED_DIR) / "decks";
  if (!fs::exists(decks)) GTEST_SKIP() << decks << " is absent";
  const auto ball = decks / "ball_plate_pydyna/examples/Explicit/output/ball_plate.k";
  const auto projectile =
      decks / "projectile_plate_lstc/tests/testfiles/run/case-keywords/projectile.k";
  const auto block = decks / "wb_lsdyna_block/tests/testfiles/keywords/test_node_sets.k";

  // A rigid ball (*MAT_RIGID solids) on a shell plate: every keyword but the contact is read.
  crumple::model::ReadOptions lenient;
  lenient.allow_unsupported = true;
  const Model b = readModel(ball, lenient);
  EXPECT_EQ(b.solids.size(), 1512u);
  EXPECT_GT(b.shells.size(), 0u);
  EXPECT_EQ(b.nodes.size(), 1940u);
  EXPECT_EQ(b.node_sets.at(1).size(), 64u);
  // Its automatic single surface over part set 1 (the ball and the plate) is read: one
  // surface holding the shells of both parts and all their nodes.
  ASSERT_EQ(b.contacts.size(), 1u);
  EXPECT_EQ(b.contacts[0].kind, crumple::model::ContactKind::SingleSurface);
  EXPECT_TRUE(b.contacts[0].automatic);
  // The plate's shells (with their thickness) and the free faces of the ball's solids.
  const auto& t = b.contacts[0].a.segment_thickness;
  EXPECT_EQ(std::size_t(std::count_if(t.begin(), t.end(), [](double v) { return v > 0.0; })),
            b.shells.size());
  EXPECT_EQ(b.contacts[0].a.segments.size(), b.shells.size() + 216u);
  for (const auto& u : b.unsupported) EXPECT_NE(u.keyword, "*CONTACT_AUTOMATIC_SINGLE_SURFACE");

  const Model p = readModel(projectile);
  EXPECT_EQ(p.solids.size(), 5664u);
  EXPECT_EQ(p.parts.size(), 2u);
  EXPECT_DOUBLE_EQ(p.controls.end_time, 70.0);
  EXPECT_DOUBLE_EQ(p.controls.d3plot_dt, 5.0);
  // Part 1 (the projectile) starts at (0.1246, 0, -0.03339); the case-block values are not
  // applied.
  const int32_t node = p.solids.nodes[0][0];
  EXPECT_DOUBLE_EQ(p.initial_velocity[node][0], 0.1246);
  EXPECT_DOUBLE_EQ(p.initial_velocity[node][2], -0.03339);

  // Its *CONTROL_SOLID ESORT = 1 runs its 80 pentahedra (N5 = N6, N7 = N8) as ELFORM 15.
  const Model w = readModel(block);
  for (const auto& u : w.unsupported) EXPECT_EQ(u.feature.find("ESORT"), std::string::npos);
  std::size_t pentahedra = 0;
  for (std::size_t e = 0; e < w.solids.size(); ++e) pentahedra += w.solidFormulation(e) == 15;
  EXPECT_EQ(pentahedra, 80u);
  EXPECT_EQ(w.solids.size(), 5680u);
  EXPECT_EQ(w.nodes.size(), 6724u);
  EXPECT_EQ(w.prescribed.size(), 3u * w.node_sets.at(1).size());
  EXPECT_EQ(w.controls.hourglass_ihq, 5);
  EXPECT_TRUE(w.controls.erode_on_dtmin);
  ASSERT_FALSE(w.nodal_loads.empty());
  EXPECT_EQ(w.nodal_loads[0].dof, 1);  // local y of system 23 is global y
}

// Rules of the keyword format that decks written by others rely on (Keyword Manual Vol. I,
// "General card format"; issue "Real decks first").
TEST(BuildRealDeckRules, BlankHeadingIsACardAndIdCardsPrecedeEveryRecord) {
  TempDir t;
  // A *PART whose heading line is blank (LS-PrePost writes one), and _ID records each with
  // their heading card.
  const Model m = build(t,
                        "*PART\n\n2,1,1\n*ELEMENT_SOLID\n11,2,1,2,3,4,5,6,7,8\n"
                        "*SET_NODE_LIST\n1\n1,2\n*SET_NODE_LIST\n2\n3\n"
                        "*BOUNDARY_SPC_SET_ID\n1,first\n1,0,1,1,1\n2,second\n2,0,1,0,0\n");
  ASSERT_NE(m.partIndex(2), crumple::model::kNone);
  EXPECT_EQ(m.parts[std::size_t(m.partIndex(2))].title, "");
  std::map<int64_t, int> mask;
  for (const auto& s : m.spcs) mask[m.nodes.id[std::size_t(s.node)]] |= s.dofs;
  EXPECT_EQ(mask[1], 7);
  EXPECT_EQ(mask[2], 7);
  EXPECT_EQ(mask[3], 1);
}

TEST(BuildRealDeckRules, UnusedDefinitionsMayBeIncomplete) {
  TempDir t;
  // Part 5 names a material and a section that do not exist, and material 6 has no density:
  // nothing uses them, so the deck reads and says so.
  const Model m = build(t, "*PART\nmarker\n5,77,88\n*MAT_ELASTIC\n6,0,1,0.3\n");
  auto noted = [&](std::string_view text) {
    return std::any_of(m.ignored.begin(), m.ignored.end(),
                       [&](const auto& i) { return i.reason.find(text) != std::string::npos; });
  };
  EXPECT_TRUE(noted("no element uses the part"));
  EXPECT_TRUE(noted("material 6 cannot be used"));
  // Unreadable text is an error even in an unused definition.
  const auto bad = t.write("bad.k", kMesh + "*MAT_ELASTIC\n6,1,x,0.3\n");
  EXPECT_EQ(errorOf([&] { readModel(bad); }),
            bad.string() + ":26: *MAT_ELASTIC card 1 field 3 (E): 'x' is not a number");
}

TEST(BuildRealDeckRules, ShellThicknessFromElementsWhenTheSectionGivesNone) {
  TempDir t;
  const std::string shells =
      "*PART\nsheet\n2,2,1\n*SECTION_SHELL\n2,2\n0\n"
      "*ELEMENT_SHELL_THICKNESS\n11,2,1,2,3,4\n1.5,1.5,1.5,1.5\n";
  const Model m = build(t, shells);
  EXPECT_EQ(m.shells.thickness.at(0)[0], 1.5);
  // Without an element thickness the shell has none: an error naming it.
  const auto p = t.write("none.k", kMesh +
                                       "*PART\nsheet\n2,2,1\n*SECTION_SHELL\n2,2\n0\n"
                                       "*ELEMENT_SHELL\n11,2,1,2,3,4\n");
  EXPECT_NE(errorOf([&] {
              readModel(p);
            }).find("shell 11 has no thickness: section 2 gives T1 = 0 and the element none"),
            std::string::npos);
}

// *INTEGRATION_SHELL (QR/IRID < 0): the points as given (ESOP 0) or NIPTS equal layers (ESOP
// 1, point cards optional); NIP is then the rule's. Bad rules name their field.
TEST(BuildRealDeckRules, SectionShellTakesItsUserIntegrationRule) {
  TempDir t;
  const std::string rules =
      "*INTEGRATION_SHELL\n7,3,0\n-0.8,0.25\n0.0,0.5\n0.8,0.25\n*INTEGRATION_SHELL\n8,4,1\n";
  const auto sheet = [](int qr) {
    return "*PART\nsheet\n2,2,1\n*SECTION_SHELL\n2,2,,5,0," + std::to_string(qr) +
           "\n1.0\n*ELEMENT_SHELL\n11,2,1,2,3,4\n";
  };
  const Model m = build(t, rules + sheet(-7));
  const auto& s = m.shell_sections.at(0);
  EXPECT_EQ(s.nip, 3);
  EXPECT_EQ(s.zeta, (std::vector<double>{-0.8, 0.0, 0.8}));
  EXPECT_EQ(s.weight, (std::vector<double>{0.25, 0.5, 0.25}));
  const Model e = build(t, rules + sheet(-8), "e.k");
  EXPECT_EQ(e.shell_sections.at(0).zeta, (std::vector<double>{-0.75, -0.25, 0.25, 0.75}));
  EXPECT_EQ(e.shell_sections.at(0).weight, (std::vector<double>(4, 0.25)));
  const auto fails = [&](const std::string& text, const std::string& message) {
    const auto p = t.write("bad.k", kMesh + text);
    EXPECT_NE(errorOf([&] { readModel(p); }).find(message), std::string::npos) << text;
  };
  fails(sheet(-9), "(QR/IRID): no *INTEGRATION_SHELL with IRID 9");
  fails("*INTEGRATION_SHELL\n7,2,0\n-0.5,0.5\n0.5,0.6\n" + sheet(-7),
        "(NIPTS): the weighting factors WF sum to 1.1");
  fails("*INTEGRATION_SHELL\n7,2,0\n-1.5,0.5\n0.5,0.5\n" + sheet(-7), "(S): the point");
  fails("*INTEGRATION_SHELL\n7,2,0\n-0.5,0.5,3\n0.5,0.5\n" + sheet(-7), "PID");
}

TEST(BuildRealDeckRules, Mat024TableEndsAtTheFirstNonIncreasingStrain) {
  TempDir t;
  // EPS 0, 0.1, 0.2 then trailing zeros with their stresses: a three-point curve.
  const Model m = build(t,
                        "*MAT_024\n2,7.8e-9,2e5,0.3,250\n\n0,0.1,0.2,0,0,0,0,0\n"
                        "250,300,330,400,0,0,0,0\n*PART\np2\n2,1,2\n"
                        "*ELEMENT_SOLID\n11,2,1,2,3,4,5,6,7,8\n");
  const auto& law = std::get<crumple::materials::PiecewiseLinear::Params>(
      m.materials.at(std::size_t(m.parts[std::size_t(m.partIndex(2))].material)).law);
  const auto& c = m.curves.at(std::size_t(law.lcss));
  EXPECT_EQ(c.x, (std::vector<double>{0, 0.1, 0.2}));
  EXPECT_EQ(c.y, (std::vector<double>{250, 300, 330}));
  // EPS2 = 0 (stresses given, strains left zero, as old LSTC decks do): SIGY and ETAN rule.
  const Model old = build(t,
                          "*MAT_024\n2,7.8e-9,2e5,0.3,121\n\n0,0,0,0,0,0,0,0\n"
                          "121,215,257,287,301,320,346,378\n*PART\np2\n2,1,2\n"
                          "*ELEMENT_SOLID\n11,2,1,2,3,4,5,6,7,8\n",
                          "old.k");
  const auto& bilinear = std::get<crumple::materials::PiecewiseLinear::Params>(
      old.materials.at(std::size_t(old.parts[std::size_t(old.partIndex(2))].material)).law);
  EXPECT_EQ(bilinear.lcss, crumple::model::kNone);
  EXPECT_EQ(bilinear.sigy, 121.0);
}

// `check` reads on past a part it cannot run: a contact over that part's shells must not
// touch its missing section (a HyperMesh press deck, then with ELFORM 16, crashed check so;
// ELFORM 6 is one Crumple still refuses).
TEST(BuildRealDeckRules, ContactOverAPartWithoutUsableSection) {
  TempDir t;
  const auto p = t.write("press.k", kMesh +
                                        "*NODE\n41,0,0,2\n42,1,0,2\n43,1,1,2\n44,0,1,2\n"
                                        "*ELEMENT_SHELL_THICKNESS\n31,2,41,42,43,44\n"
                                        "0.1,0.1,0.1,0.1\n*PART\n\n2,2,1\n*SECTION_SHELL\n2,6\n0\n"
                                        "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n1,2,3,3\n");
  crumple::model::ReadOptions tolerant;
  tolerant.allow_unsupported = true;
  tolerant.collect_errors = true;
  const Model m = readModel(p, tolerant);
  EXPECT_TRUE(m.errors.empty());
  ASSERT_EQ(m.contacts.size(), 1u);
  EXPECT_TRUE(std::any_of(m.unsupported.begin(), m.unsupported.end(), [](const auto& u) {
    return u.changes_answer && u.feature == "*SECTION_SHELL ELFORM=6";
  }));
}

// The unit system labels outputs (model/units.hpp): *CONTROL_UNITS names it, else the metals'
// density and Young's modulus give it away, a density scaled tenfold included.
TEST(BuildModel, UnitsFromControlUnitsOrInferredFromTheMetals) {
  TempDir t;
  const Model inferred = build(t, "");  // steel in tonne, mm, s: 7.8e-9, 2e5
  EXPECT_EQ(inferred.units.name, "t-mm-s");
  EXPECT_NE(inferred.units.source.find("inferred from 1 of 1 metal"), std::string::npos)
      << inferred.units.source;

  const Model named = build(t, "*CONTROL_UNITS\n        mm        ms        kg\n");
  EXPECT_EQ(named.units.name, "kg-mm-ms");
  EXPECT_NE(named.units.source.find("*CONTROL_UNITS at"), std::string::npos);
  const Model blank = build(t, "*CONTROL_UNITS\n\n");  // the manual's defaults: m, sec, kg
  EXPECT_EQ(blank.units.name, "kg-m-s");

  const Model odd = build(t, "*CONTROL_UNITS\n        ft       sec      slug\n");
  EXPECT_EQ(odd.units.name, "t-mm-s");
  ASSERT_EQ(odd.ignored.size(), 1u);
  EXPECT_NE(odd.ignored[0].reason.find("LENGTH ft, TIME sec, MASS slug"), std::string::npos);

  std::string scaled = kMesh;
  scaled.replace(scaled.find("7.8e-9"), 6, "7.8e-8");  // mass-scaled tenfold
  EXPECT_EQ(readModel(t.write("scaled.k", scaled)).units.name, "t-mm-s");
  std::string aluminium_si = kMesh;
  aluminium_si.replace(aluminium_si.find("7.8e-9,2.0e5"), 12, "2700,7.0e10");
  EXPECT_EQ(readModel(t.write("si.k", aluminium_si)).units.name, "kg-m-s");
  std::string rubbery = kMesh;  // 1e6 Pa in SI: near no metal in any system
  rubbery.replace(rubbery.find("7.8e-9,2.0e5"), 12, "1100,1.0e6");
  const Model unknown = readModel(t.write("rubber.k", rubbery));
  EXPECT_TRUE(unknown.units.name.empty());
  EXPECT_NE(unknown.units.source.find("not known"), std::string::npos);
}

// Plane-strain SPH (*CONTROL_SPH IDIM 2): particles in one plane z = const, held in it (z and
// the rotations fixed), and no other elements; IDIM -2 (axisymmetric) is refused by name.
TEST(BuildSph, PlaneStrainParticles) {
  TempDir t;
  const std::string particles =
      "*SECTION_SPH\n1\n*MAT_ELASTIC\n1,7.8e-9,2.0e5,0.3\n*PART\nsph\n1,1,1\n"
      "*NODE\n1,0,0,0.5\n2,1,0,0.5\n3,0,1,0.5\n*ELEMENT_SPH\n1,1,1e-9\n2,1,1e-9\n3,1,1e-9\n";
  const auto plane = [](int idim) { return fmt::format("*CONTROL_SPH\n0,0,1e20,{}\n", idim); };
  const Model m = readModel(t.write("p.k", "*KEYWORD\n" + plane(2) + particles));
  EXPECT_EQ(m.sph.dim, 2);
  ASSERT_EQ(m.spcs.size(), 3u);
  for (const auto& s : m.spcs) EXPECT_EQ(s.dofs, crumple::model::DofMask{0b111100});
  EXPECT_EQ(readModel(t.write("q.k", "*KEYWORD\n" + plane(0) + particles)).sph.dim, 3);
  const auto off = t.write("o.k", "*KEYWORD\n" + plane(2) + particles + "*NODE\n4,0,2,0.7\n" +
                                      "*ELEMENT_SPH\n4,1,1e-9\n");
  EXPECT_EQ(errorOf([&] { readModel(off); }),
            "*NODE 4: z = 0.7 but SPH particle node 1 has z = 0.5: with *CONTROL_SPH IDIM 2 "
            "(plane strain) every particle lies in one plane z = const");
  const auto mixed = t.write("m.k", kMesh + plane(2) +
                                        "*SECTION_SPH\n2\n*PART\nsph\n2,2,1\n*NODE\n41,0,0,0.5\n"
                                        "42,1,0,0.5\n*ELEMENT_SPH\n41,2,1e-9\n42,2,1e-9\n");
  EXPECT_EQ(errorOf([&] { readModel(mixed); }),
            "*CONTROL_SPH IDIM 2 (plane-strain SPH) runs only with SPH particles: the deck also "
            "has 2 elements");
  const auto axi = t.write("a.k", "*KEYWORD\n" + plane(-2) + particles);
  EXPECT_NE(errorOf([&] { readModel(axi); })
                .find("only three-dimensional (IDIM 0 or 3) and plane-strain (IDIM 2) SPH are "
                      "supported"),
            std::string::npos);
}

// Id -> position, dense for meshers' numbering and hashed for scattered ids: the first
// position of a repeated id, kAbsent outside, ids of any sign.
TEST(IdIndex, DenseAndScatteredIdsGiveTheFirstPosition) {
  using crumple::util::IdIndex;
  IdIndex dense;
  dense.assign(std::vector<int64_t>{5, 3, 4, 7, 3, -1});
  EXPECT_EQ(dense.find(5), 0);
  EXPECT_EQ(dense.find(3), 1);  // the first of the two
  EXPECT_EQ(dense.find(7), 3);
  EXPECT_EQ(dense.find(-1), 5);
  for (const int64_t absent :
       std::vector<int64_t>{0, 1, 2, 6, 8, -2, std::numeric_limits<int64_t>::min(),
                            std::numeric_limits<int64_t>::max()})
    EXPECT_EQ(dense.find(absent), IdIndex::kAbsent) << absent;
  IdIndex sparse;
  const int64_t big = std::numeric_limits<int64_t>::max();
  sparse.assign(std::vector<int64_t>{big, 10, -big, 1000000000000, 10});
  EXPECT_EQ(sparse.find(big), 0);
  EXPECT_EQ(sparse.find(10), 1);
  EXPECT_EQ(sparse.find(-big), 2);
  EXPECT_EQ(sparse.find(1000000000000), 3);
  EXPECT_EQ(sparse.find(11), IdIndex::kAbsent);
  sparse.assign(std::vector<int64_t>{});
  EXPECT_EQ(sparse.find(10), IdIndex::kAbsent);
}
