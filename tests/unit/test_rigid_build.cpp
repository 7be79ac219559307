// Deck -> Model::rigid (src/model/build_rigid.cpp): rigid bodies from *MAT_RIGID parts, merges,
// extra nodes, *PART_INERTIA, nodal rigid bodies, prescribed rigid motion, spot welds, tied
// node sets; the one-constraint-per-node rule and its messages; the archive round trip.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <string>

#include "model/build.hpp"
#include "model/serialize.hpp"
#include "temp_dir.hpp"
#include "util/error.hpp"

namespace {

using crumple::model::Model;
using crumple::model::readModel;
using crumple::testing::errorOf;

class TempDir : public crumple::testing::TempDir {
 public:
  TempDir() : crumple::testing::TempDir("crumple_test_rigid_build") {}
};

// Three unit cubes along x: part 1 (nodes 1-8), part 2 (11-18), part 3 (21-28); parts 1 and
// 2 are rigid (material 1 with CMO = 1, CON1 = 4, CON2 = 7; material 2 free), part 3 elastic.
// Nodes 31-34 belong to no element.
std::string mesh() {
  std::string s = "*KEYWORD\n*NODE\n";
  for (int b = 0; b < 3; ++b)
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
          s += fmt::format("{},{},{},{}\n", 10 * b + 1 + i + 2 * j + 4 * k, 2 * b + i, j, k);
  s += "31,10,0,0\n32,11,0,0\n33,12,0,0\n34,13,0,0\n*ELEMENT_SOLID\n";
  for (int b = 0; b < 3; ++b) {
    const int o = 10 * b;
    s += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", b + 1, b + 1, o + 1, o + 2, o + 4, o + 3,
                     o + 5, o + 6, o + 8, o + 7);
  }
  return s +
         "*PART\nrigid one\n1,1,1\n*PART\nrigid two\n2,1,2\n*PART\nelastic\n3,1,3\n"
         "*SECTION_SOLID\n1,1\n"
         "*MAT_RIGID\n1,7.8e-9,2e5,0.3\n1.0,4.0,7.0\n"
         "*MAT_RIGID\n2,2.0e-9,2e5,0.3\n"
         "*MAT_ELASTIC\n3,7.8e-9,2e5,0.3\n"
         "*DEFINE_CURVE\n9\n0,1\n10,1\n";
}

Model build(const TempDir& t, const std::string& extra) {
  return readModel(t.write("d.k", mesh() + extra));
}

std::vector<int32_t> indices(const Model& m, std::initializer_list<int64_t> ids) {
  std::vector<int32_t> v;
  for (int64_t id : ids) v.push_back(m.nodeIndex(id));
  return v;
}

TEST(RigidBuild, OneBodyPerRigidPartWithItsConstraints) {
  TempDir t;
  const Model m = build(t, "");
  const auto& r = m.rigid;
  ASSERT_EQ(r.bodies.size(), 2u);
  EXPECT_EQ(r.bodies[0].id, 1);
  EXPECT_FALSE(r.bodies[0].nodal);
  EXPECT_EQ(r.bodies[0].parts, std::vector<int32_t>{m.partIndex(1)});
  EXPECT_EQ(r.bodies[0].nodes, indices(m, {1, 2, 3, 4, 5, 6, 7, 8}));
  // CON1 = 4: x and y (bits 0, 1); CON2 = 7: every rotation (bits 3-5).
  EXPECT_EQ(r.bodies[0].fixed, 0b111011);
  EXPECT_EQ(r.bodies[1].id, 2);
  EXPECT_EQ(r.bodies[1].fixed, 0);
  EXPECT_FALSE(r.bodies[1].inertia_given);
  EXPECT_TRUE(r.welds.empty());
  EXPECT_TRUE(r.node_sets.empty());
}

TEST(RigidBuild, MergedPartsAndExtraNodesFormOneBody) {
  TempDir t;
  const Model m = build(t,
                        "*CONSTRAINED_RIGID_BODIES\n2,1\n"
                        "*CONSTRAINED_EXTRA_NODES_NODE\n1,31\n"
                        "*SET_NODE_LIST\n5\n32,33\n"
                        "*CONSTRAINED_EXTRA_NODES_SET\n2,5\n");
  const auto& r = m.rigid;
  ASSERT_EQ(r.bodies.size(), 1u);
  // Part 2 is the master: the body is named after it and its (free) constraints apply.
  EXPECT_EQ(r.bodies[0].id, 2);
  EXPECT_EQ(r.bodies[0].parts, (std::vector<int32_t>{m.partIndex(2), m.partIndex(1)}));
  EXPECT_EQ(r.bodies[0].fixed, 0);
  EXPECT_EQ(r.bodies[0].nodes,
            indices(m, {1, 2, 3, 4, 5, 6, 7, 8, 11, 12, 13, 14, 15, 16, 17, 18, 31, 32, 33}));
  // The slave's CMO is reported as not applied.
  bool noted = false;
  for (const auto& i : m.ignored) noted = noted || (i.keyword == "*MAT_RIGID" && i.field == "CMO");
  EXPECT_TRUE(noted);
}

TEST(RigidBuild, PartInertiaGivesMassCentreTensorAndVelocity) {
  TempDir t;
  auto deck = mesh();
  const std::string part2 = "*PART\nrigid two\n2,1,2\n";
  deck.replace(deck.find(part2), part2.size(),
               "*PART_INERTIA\nrigid two\n2,1,2\n"
               "2.5,0.5,0.5,0.01,0,0\n"
               "1.0,0.1,0.0,2.0,0.0,3.0\n"
               "1.0,2.0,3.0,0.1,0.2,0.3\n");
  const Model m = readModel(t.write("i.k", deck));
  const auto& b = m.rigid.bodies.at(1);
  EXPECT_TRUE(b.inertia_given);
  EXPECT_EQ(b.mass, 0.01);
  EXPECT_EQ(b.cm, (std::array<double, 3>{2.5, 0.5, 0.5}));
  EXPECT_EQ(b.tensor, (std::array<double, 6>{1.0, 0.1, 0.0, 2.0, 0.0, 3.0}));
  EXPECT_TRUE(b.velocity_given);
  EXPECT_EQ(b.v0, (std::array<double, 3>{1.0, 2.0, 3.0}));
  EXPECT_EQ(b.w0, (std::array<double, 3>{0.1, 0.2, 0.3}));
  // NODEID puts the centre on a node, which then moves with the body.
  deck = mesh();
  deck.replace(deck.find(part2), part2.size(),
               "*PART_INERTIA\nrigid two\n2,1,2\n0,0,0,0.01,0,34\n1,0,0,1,0,1\n\n");
  const Model n = readModel(t.write("j.k", deck));
  EXPECT_EQ(n.rigid.bodies.at(1).cm, (std::array<double, 3>{13, 0, 0}));
  EXPECT_FALSE(n.rigid.bodies.at(1).velocity_given);
  EXPECT_EQ(n.rigid.bodies.at(1).nodes.back(), n.nodeIndex(34));
  // The mass and the tensor are checked.
  deck = mesh();
  deck.replace(deck.find(part2), part2.size(),
               "*PART_INERTIA\nrigid two\n2,1,2\n0,0,0,0.01\n1,2,0,1,0,1\n\n");
  const auto bad = t.write("k.k", deck);
  EXPECT_EQ(
      errorOf([&] { readModel(bad); }),
      bad.string() +
          ":42: *PART_INERTIA inertia card 4 field 2 (IXY): the inertia tensor is not positive "
          "definite");
}

TEST(RigidBuild, NodalRigidBodyWithSpcOption) {
  TempDir t;
  const Model m = build(t,
                        "*SET_NODE_LIST\n7\n21,22,23\n*SET_NODE_LIST\n6\n24,25\n"
                        "*CONSTRAINED_NODAL_RIGID_BODY_SPC\n70,0,6,31\n1.0,7.0,0.0\n"
                        "*CONSTRAINED_NODAL_RIGID_BODY\n7\n");
  const auto& r = m.rigid;
  ASSERT_EQ(r.bodies.size(), 4u);
  // Part bodies first, then nodal ones in ascending id; NSID 0 means the set numbered PID.
  EXPECT_TRUE(r.bodies[2].nodal);
  EXPECT_EQ(r.bodies[2].id, 7);
  EXPECT_EQ(r.bodies[2].nodes, indices(m, {21, 22, 23}));
  EXPECT_EQ(r.bodies[3].id, 70);
  EXPECT_EQ(r.bodies[3].nodes, indices(m, {24, 25, 31}));  // PNODE joins the body
  EXPECT_EQ(r.bodies[3].fixed, 7);
  EXPECT_TRUE(r.bodies[3].parts.empty());
}

TEST(RigidBuild, NodalRigidBodyTitleCardPrecedesEachRecord) {
  // _TITLE (as preprocessors write it, a name with ';' and '-' before every record).
  TempDir t;
  const Model m = build(t,
                        "*SET_NODE_LIST\n7\n21,22,23\n*SET_NODE_LIST\n6\n24,25\n"
                        "*CONSTRAINED_NODAL_RIGID_BODY_TITLE\nS7;RB_ELSET_7 - ref node 21\n"
                        "7\n$\nS70;RB_ELSET_70\n70,0,6\n");
  const auto& r = m.rigid;
  ASSERT_EQ(r.bodies.size(), 4u);
  EXPECT_EQ(r.bodies[2].id, 7);
  EXPECT_EQ(r.bodies[2].nodes, indices(m, {21, 22, 23}));
  EXPECT_EQ(r.bodies[3].id, 70);
  EXPECT_EQ(r.bodies[3].nodes, indices(m, {24, 25}));
}

TEST(RigidBuild, PrescribedRigidMotion) {
  TempDir t;
  const Model m = build(t,
                        "*BOUNDARY_PRESCRIBED_MOTION_RIGID_ID\n5,pull\n"
                        "2,1,0,9,2.0\n6,turn\n2,7,2,9,0.5,0,3.0,1.0\n");
  const auto& mo = m.rigid.bodies.at(1).motions;
  ASSERT_EQ(mo.size(), 2u);
  EXPECT_EQ(mo[0].dof, 0);
  EXPECT_EQ(mo[0].kind, 0);
  EXPECT_EQ(mo[0].sf, 2.0);
  EXPECT_EQ(mo[0].curve, m.curveIndex(9));
  EXPECT_EQ(mo[0].death, std::numeric_limits<double>::infinity());
  // DOF 7 is the rotation about z: index 5.
  EXPECT_EQ(mo[1].dof, 5);
  EXPECT_EQ(mo[1].kind, 2);
  EXPECT_EQ(mo[1].death, 3.0);
  EXPECT_EQ(mo[1].birth, 1.0);
  const auto p = t.write("p.k", mesh() + "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n3,1,0,9\n");
  EXPECT_EQ(errorOf([&] { readModel(p); }),
            p.string() +
                ":58: *BOUNDARY_PRESCRIBED_MOTION_RIGID card 1 field 1 (PID): part 3 "
                "is not rigid (*MAT_RIGID)");
  const auto q = t.write("q.k", mesh() + "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n1,8,0,9\n");
  EXPECT_EQ(errorOf([&] { readModel(q); }),
            q.string() +
                ":58: *BOUNDARY_PRESCRIBED_MOTION_RIGID card 1 field 2 (DOF): DOF 8 is "
                "not supported (1-7 are)");
  // DOF 4: along *DEFINE_VECTOR VID, the motion normal to it free. A vector along -z is the
  // z translation with the scale factor's sign turned.
  const Model v = build(t,
                        "*DEFINE_VECTOR\n3,1,1,1,1,1,-4\n"
                        "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n2,4,0,9,2.0,3\n");
  const auto& along = v.rigid.bodies.at(1).motions;
  ASSERT_EQ(along.size(), 1u);
  EXPECT_EQ(along[0].dof, 2);
  EXPECT_EQ(along[0].sf, -2.0);
  const auto skew = t.write("skew.k", mesh() +
                                          "*DEFINE_VECTOR\n3,0,0,0,1,0,1\n"
                                          "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n2,4,0,9,1.0,3\n");
  EXPECT_NE(errorOf([&] {
              readModel(skew);
            }).find("(VID): DOF 4 along a vector that is not a global axis is not supported"),
            std::string::npos);
}

TEST(RigidBuild, SpotweldsGeneralizedWeldsAndTiedSets) {
  TempDir t;
  const Model m = build(t,
                        "*CONSTRAINED_SPOTWELD\n22,21,1.5,2.5,2.0,3.0,4.0\n"
                        "*CONSTRAINED_SPOTWELD_ID\n40\n31,32\n"
                        "*SET_NODE_LIST\n8\n25,26,27\n"
                        "*CONSTRAINED_GENERALIZED_WELD_SPOT_ID\n41\n8\n0.5,0,3.0,0,2.0\n"
                        "*SET_NODE_LIST\n9\n33,34\n"
                        "*CONSTRAINED_NODE_SET_ID\n3\n9,5,2.0\n");
  const auto& w = m.rigid.welds;
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[0].id, 1);
  EXPECT_EQ(w[0].nodes, indices(m, {21, 22}));
  EXPECT_EQ(w[0].sn, 1.5);
  EXPECT_EQ(w[0].ss, 2.5);
  EXPECT_EQ(w[0].n, 2.0);
  EXPECT_EQ(w[0].m, 3.0);
  EXPECT_EQ(w[0].tfail, 4.0);
  EXPECT_FALSE(w[0].generalized);
  EXPECT_EQ(w[1].id, 40);
  EXPECT_EQ(w[1].tfail, std::numeric_limits<double>::infinity());
  EXPECT_EQ(w[1].sn, 0.0);
  EXPECT_EQ(w[2].id, 41);
  EXPECT_TRUE(w[2].generalized);
  EXPECT_EQ(w[2].nodes, indices(m, {25, 26, 27}));
  EXPECT_EQ(w[2].tfail, 0.5);
  EXPECT_EQ(w[2].sn, 3.0);
  ASSERT_EQ(m.rigid.node_sets.size(), 1u);
  EXPECT_EQ(m.rigid.node_sets[0].id, 3);
  EXPECT_EQ(m.rigid.node_sets[0].dofs, 0b110);  // DOF 5: y and z
  EXPECT_EQ(m.rigid.node_sets[0].tfail, 2.0);
}

TEST(RigidBuild, SphericalAndRevoluteJoints) {
  TempDir t;
  // Nodes 40 and 41 coincide with nodes 8 (1, 1, 1) and 4 (1, 1, 0) of the first cube; joints
  // may join rigid-body nodes (the exception to one constraint per node).
  const std::string nodes = "*NODE\n40,1,1,1\n41,1,1,0\n";
  const Model m =
      build(t, nodes +
                   "*CONSTRAINED_JOINT_SPHERICAL\n8,40\n"
                   "*CONSTRAINED_JOINT_REVOLUTE_ID\n9,hinge\n8,40,4,41,0.0,0.0,2.0,0.5\n");
  const auto& j = m.rigid.joints;
  ASSERT_EQ(j.size(), 2u);
  EXPECT_EQ(j[0].id, 1);
  EXPECT_EQ(j[0].kind, crumple::model::JointKind::Spherical);
  ASSERT_EQ(j[0].pairs.size(), 1u);
  EXPECT_EQ(j[0].pairs[0], (std::array<int32_t, 2>{m.nodeIndex(8), m.nodeIndex(40)}));
  EXPECT_EQ(j[0].rps, 1.0);
  EXPECT_EQ(j[0].damp, 1.0);
  EXPECT_EQ(j[1].id, 9);
  EXPECT_EQ(j[1].kind, crumple::model::JointKind::Revolute);
  ASSERT_EQ(j[1].pairs.size(), 2u);
  EXPECT_EQ(j[1].pairs[1], (std::array<int32_t, 2>{m.nodeIndex(4), m.nodeIndex(41)}));
  EXPECT_EQ(j[1].rps, 2.0);
  EXPECT_EQ(j[1].damp, 0.5);
  const Model r = crumple::model::deserialize(crumple::model::serialize(m));
  ASSERT_EQ(r.rigid.joints.size(), 2u);
  EXPECT_EQ(r.rigid.joints[1].pairs, j[1].pairs);
  EXPECT_EQ(r.rigid.joints[1].rps, 2.0);

  const auto apart = t.write("a.k", mesh() + nodes + "*CONSTRAINED_JOINT_SPHERICAL\n8,41\n");
  EXPECT_EQ(errorOf([&] { readModel(apart); }),
            apart.string() +
                ":61: *CONSTRAINED_JOINT_SPHERICAL card 1 field 2 (N2): the joint's nodes N1 and "
                "N2 must coincide");
  const auto other = t.write("o.k", mesh() + "*CONSTRAINED_JOINT_UNIVERSAL\n8,40\n");
  EXPECT_EQ(
      errorOf([&] { readModel(other); }),
      other.string() + ":57: *CONSTRAINED_JOINT_UNIVERSAL: option _UNIVERSAL is not supported");
}

TEST(RigidBuild, TranslationalJointStiffnessAndBodyLoads) {
  TempDir t;
  // Nodes 40-42 sit on nodes 2 (1, 0, 0), 4 (1, 1, 0) and 6 (1, 0, 1) of rigid part 1; 40 and 41
  // join part 2's body, 42 does so only in the second deck.
  const std::string nodes =
      "*NODE\n40,1,0,0\n41,1,1,0\n42,1,0,1\n*CONSTRAINED_EXTRA_NODES_NODE\n2,40\n2,41\n";
  const std::string joint = "*CONSTRAINED_JOINT_TRANSLATIONAL_ID\n5\n2,40,4,41,6,42\n";
  const auto loose = t.write("l.k", mesh() + nodes + joint);
  const std::string why = errorOf([&] { readModel(loose); });
  EXPECT_NE(why.find("joint 5: node 42 belongs to no rigid body"), std::string::npos) << why;
  EXPECT_NE(why.find("l.k:66: joint 5"), std::string::npos) << why;  // names the joint line

  const Model m = build(t, nodes + "*CONSTRAINED_EXTRA_NODES_NODE\n2,42\n" + joint +
                               "*DEFINE_COORDINATE_NODE\n5,1,2,3\n"
                               "*CONSTRAINED_JOINT_STIFFNESS_GENERALIZED\n3,1,2,5\n0,0\n10.0,2.0\n"
                               "*LOAD_RIGID_BODY\n2,5,9,3.0\n");
  ASSERT_EQ(m.rigid.joints.size(), 1u);
  EXPECT_EQ(m.rigid.joints[0].kind, crumple::model::JointKind::Translational);
  EXPECT_TRUE(m.rigid.joints[0].slides());
  ASSERT_EQ(m.rigid.joints[0].pairs.size(), 3u);
  ASSERT_EQ(m.rigid.joint_stiffness.size(), 1u);
  const auto& js = m.rigid.joint_stiffness[0];
  EXPECT_EQ(m.rigid.bodies[std::size_t(js.body_a)].id, 1);
  EXPECT_EQ(m.rigid.bodies[std::size_t(js.body_b)].id, 2);
  EXPECT_EQ(js.frame_a[0], (std::array<double, 3>{1, 0, 0}));  // N1 -> N2
  EXPECT_EQ(js.frame_a[2], (std::array<double, 3>{0, 0, 1}));
  EXPECT_EQ(js.frame_b, js.frame_a);  // CIDB 0: CIDA
  EXPECT_EQ(js.stiffness, (std::array<double, 3>{10, 0, 0}));
  EXPECT_EQ(js.friction, (std::array<double, 3>{2, 0, 0}));
  ASSERT_EQ(m.rigid.loads.size(), 1u);
  EXPECT_EQ(m.rigid.bodies[std::size_t(m.rigid.loads[0].body)].id, 2);
  EXPECT_EQ(m.rigid.loads[0].dof, 3);  // DOF 5: moment about x
  EXPECT_EQ(m.rigid.loads[0].sf, 3.0);
  const Model r = crumple::model::deserialize(crumple::model::serialize(m));
  EXPECT_EQ(r.rigid.joint_stiffness[0].friction, js.friction);
  EXPECT_EQ(r.rigid.loads[0].curve, m.rigid.loads[0].curve);

  // What is not built is refused by field name.
  const auto curve =
      t.write("c.k", mesh() +
                         "*DEFINE_COORDINATE_NODE\n5,1,2,3\n"
                         "*CONSTRAINED_JOINT_STIFFNESS_GENERALIZED\n3,1,2,5\n9,0\n10.0,2.0\n");
  EXPECT_NE(errorOf([&] { readModel(curve); }).find("field 1 (LCIDPH)"), std::string::npos);
  const auto follower = t.write("f.k", mesh() + "*LOAD_RIGID_BODY\n2,4,9,3.0\n");
  EXPECT_NE(errorOf([&] { readModel(follower); }).find("(DOF): DOF 4 is not supported"),
            std::string::npos);
}

TEST(RigidBuild, ErrorsNameTheConflict) {
  TempDir t;
  auto error = [&](const std::string& extra) {
    const auto p = t.write("e.k", mesh() + extra);
    std::string e = errorOf([&] { readModel(p); });
    const std::string prefix = p.string();
    for (std::size_t at = e.find(prefix); at != std::string::npos; at = e.find(prefix))
      e.replace(at, prefix.size(), "deck");
    return e;
  };
  EXPECT_EQ(error("*CONSTRAINED_EXTRA_NODES_NODE\n1,11\n"),
            "deck:40: node 11 belongs to the rigid body of part 1 and to the rigid body of part "
            "2; merge rigid bodies with *CONSTRAINED_RIGID_BODIES");
  EXPECT_EQ(error("*CONSTRAINED_SPOTWELD\n1,21\n"),
            "deck:58: node 1 belongs to the rigid body of part 1 and to *CONSTRAINED_SPOTWELD 1 "
            "(deck:58); a node may take one rigid-body or nodal constraint only");
  EXPECT_EQ(error("*CONSTRAINED_SPOTWELD\n21,21\n"),
            "deck:58: *CONSTRAINED_SPOTWELD card 1 field 2 (N2): a spot weld needs two different "
            "nodes");
  EXPECT_EQ(error("*NODE\n99,4,0,0\n*CONSTRAINED_SPOTWELD\n21,99\n"),
            "deck:60: *CONSTRAINED_SPOTWELD card 1 field 2 (N2): the welded nodes coincide; a spot "
            "weld joins separate nodes");
  EXPECT_EQ(error("*CONSTRAINED_SPOTWELD\n21,22,1.0\n"),
            "deck:58: *CONSTRAINED_SPOTWELD card 1 field 5 (N): the exponent of the normal force "
            "must be positive");
  EXPECT_EQ(error("*CONSTRAINED_SPOTWELD\n21,22,0,0,0,0,0,0.3\n"),
            "deck:58: *CONSTRAINED_SPOTWELD card 1 field 8 (EP): failure by the plastic strain of "
            "the welded elements is not supported");
  EXPECT_EQ(error("*CONSTRAINED_SPOTWELD\n21,22\n*BOUNDARY_SPC_NODE\n22,0,1\n"),
            "deck:58: node 22 of *CONSTRAINED_SPOTWELD 1 (deck:58) also has a single-point "
            "constraint (*BOUNDARY_SPC or *NODE TC/RC); a constrained node may not take further "
            "constraints");
  EXPECT_EQ(error("*BOUNDARY_PRESCRIBED_MOTION_NODE\n3,1,0,9\n"),
            "*BOUNDARY_PRESCRIBED_MOTION: node 3 belongs to the rigid body of part 1; prescribe "
            "the motion of a rigid body with *BOUNDARY_PRESCRIBED_MOTION_RIGID");
  EXPECT_EQ(
      error("*PART_INERTIA\nx\n4,1,3\n0,0,0,1\n1,0,0,1,0,1\n\n"),
      "deck:60: *PART_INERTIA inertia card 3 field 4 (TM): *PART_INERTIA applies to rigid parts "
      "(*MAT_RIGID) only; part 4 is not rigid");
  // A nodal rigid body may share its id with a part (PRIMER numbers them so): no error.
  EXPECT_EQ(error("*SET_NODE_LIST\n1\n31\n*CONSTRAINED_NODAL_RIGID_BODY\n3,0,1\n"), "");
  EXPECT_EQ(error("*CONSTRAINED_RIGID_BODIES\n1,3\n"),
            "deck:58: *CONSTRAINED_RIGID_BODIES card 1 field 2 (PIDS): part 3 is not rigid "
            "(*MAT_RIGID)");
  EXPECT_EQ(error("*SET_NODE_LIST\n1\n21,22\n*CONSTRAINED_NODE_SET\n1,8\n"),
            "deck:61: *CONSTRAINED_NODE_SET card 1 field 2 (DOF): must be 1 to 7 (x, y, z, xy, yz, "
            "zx, xyz)");
}

// An SPC on a rigid-body node constrains the body's centre instead (as LS-DYNA converts it);
// the node's SPC is gone and the conversion is reported.
TEST(RigidBuild, SpcOnRigidNodeConstrainsTheBody) {
  TempDir t;
  const Model m = build(t, "*BOUNDARY_SPC_NODE\n12,0,0,0,1,0,1,0\n21,0,1\n");
  // DOFZ (bit 2) and DOFRY (bit 4).
  EXPECT_EQ(m.rigid.bodies.at(1).fixed, 0b010100);
  ASSERT_EQ(m.spcs.size(), 1u);
  EXPECT_EQ(m.spcs[0].node, m.nodeIndex(21));
  bool noted = false;
  for (const auto& i : m.ignored)
    noted = noted || i.reason.find("constrain its centre of mass") != std::string::npos;
  EXPECT_TRUE(noted);
}

TEST(RigidBuild, ModelRoundTripKeepsRigidDefinitions) {
  TempDir t;
  const Model m = build(t,
                        "*CONSTRAINED_EXTRA_NODES_NODE\n1,31\n"
                        "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n2,6,1,9,2.0\n"
                        "*CONSTRAINED_SPOTWELD\n22,21,1.5,2.5,2.0,3.0,4.0\n"
                        "*SET_NODE_LIST\n9\n33,34\n*CONSTRAINED_NODE_SET\n9,7\n");
  const Model r = crumple::model::deserialize(crumple::model::serialize(m));
  ASSERT_EQ(r.rigid.bodies.size(), m.rigid.bodies.size());
  for (std::size_t k = 0; k < m.rigid.bodies.size(); ++k) {
    const auto &a = m.rigid.bodies[k], &b = r.rigid.bodies[k];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.parts, b.parts);
    EXPECT_EQ(a.nodes, b.nodes);
    EXPECT_EQ(a.fixed, b.fixed);
    EXPECT_EQ(a.motions.size(), b.motions.size());
    EXPECT_EQ(a.where.str(), b.where.str());
  }
  EXPECT_EQ(r.rigid.bodies[1].motions.at(0).dof, 4);
  ASSERT_EQ(r.rigid.welds.size(), 1u);
  EXPECT_EQ(r.rigid.welds[0].nodes, m.rigid.welds[0].nodes);
  EXPECT_EQ(r.rigid.welds[0].tfail, 4.0);
  ASSERT_EQ(r.rigid.node_sets.size(), 1u);
  EXPECT_EQ(r.rigid.node_sets[0].dofs, 7);
  EXPECT_EQ(crumple::model::serialize(r), crumple::model::serialize(m));
}

}  // namespace
