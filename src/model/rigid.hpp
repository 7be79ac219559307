// Rigid bodies and nodal constraints of the Model, as the builder resolves them
// (src/model/build_rigid.cpp); the runtime is src/constraints/rigid.hpp.
//
//   rigid bodies   one per *MAT_RIGID part after *CONSTRAINED_RIGID_BODIES merges, with the
//                  nodes of *CONSTRAINED_EXTRA_NODES_NODE/_SET; plus one per
//                  *CONSTRAINED_NODAL_RIGID_BODY (nodes only)
//   spot welds     *CONSTRAINED_SPOTWELD and *CONSTRAINED_GENERALIZED_WELD_SPOT: a small nodal
//                  rigid body that fails on a force criterion or at a time
//   tied node sets *CONSTRAINED_NODE_SET: a common velocity in some global directions
//   joints         *CONSTRAINED_JOINT_SPHERICAL, _REVOLUTE, _CYLINDRICAL, _TRANSLATIONAL:
//                  penalty springs between coincident node pairs (the one exception to the
//                  rule below), with *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED on their bodies
//   body loads     *LOAD_RIGID_BODY: a force or moment on a body's centre of mass
//
// Every node list holds model node indices, ascending and without repeats. A node belongs to
// at most one of all these (LS-DYNA Keyword Manual, *CONSTRAINED_SPOTWELD remarks: nodes may
// not be subject to several, possibly conflicting, constraints).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "util/source_loc.hpp"

namespace crumple::model {

// *BOUNDARY_PRESCRIBED_MOTION_RIGID: motion of a body's centre of mass along a global axis
// (dof 0-2) or its rotation about one (dof 3-5), LS-DYNA DOF 1-3 and 5-7.
struct RigidMotion {
  int dof = 0;
  uint8_t kind = 0;    // MotionKind: 0 velocity, 1 acceleration, 2 displacement
  int32_t curve = -1;  // index into Model::curves
  double sf = 1.0;
  double birth = 0.0;
  double death = std::numeric_limits<double>::infinity();
};

struct RigidBodyDef {
  int64_t id = 0;              // part id of the master part, or the nodal rigid body's PID
  bool nodal = false;          // *CONSTRAINED_NODAL_RIGID_BODY: no part, mass of its nodes
  std::vector<int32_t> parts;  // model part indices (master first, then merged parts)
  std::vector<int32_t> nodes;  // every node of the body, extra nodes included
  // Fixed global freedoms of the centre of mass: bits 0-2 translations x, y, z, bits 3-5
  // rotations (*MAT_RIGID CMO=1 CON1/CON2, *CONSTRAINED_NODAL_RIGID_BODY_SPC, and nodal SPCs
  // converted as LS-DYNA does).
  uint8_t fixed = 0;
  // *PART_INERTIA: mass, centre and inertia tensor (xx, xy, xz, yy, yz, zz, global axes, about
  // the centre) replace the values summed from the nodes.
  bool inertia_given = false;
  double mass = 0.0;
  std::array<double, 3> cm{};
  std::array<double, 6> tensor{};
  // *PART_INERTIA VTX..VRZ: initial velocity of the centre and angular velocity; otherwise the
  // body takes the momentum and angular momentum of its nodes' initial velocities.
  bool velocity_given = false;
  std::array<double, 3> v0{}, w0{};
  std::vector<RigidMotion> motions;
  util::SourceLoc where;
};

// A spot weld: its nodes move as one rigid body until, at any of them, the weld's force on
// the node (normal component along the node -> centroid direction, tension only, and the
// shear rest) meets (fn/SN)^N + (fs/SS)^M >= 1, or until time TFAIL; then they are free.
struct SpotweldDef {
  int64_t id = 0;
  std::vector<int32_t> nodes;  // at least two
  double sn = 0, ss = 0;       // failure forces; 0 = that term is absent
  double n = 2, m = 2;         // exponents
  double tfail = std::numeric_limits<double>::infinity();
  bool generalized = false;  // *CONSTRAINED_GENERALIZED_WELD_SPOT (else _SPOTWELD)
  util::SourceLoc where;
};

// *CONSTRAINED_NODE_SET: the nodes share the mass-weighted mean velocity in `dofs`
// (bits 0-2 = x, y, z) until time tfail.
struct TiedNodeSet {
  int64_t id = 0;
  std::vector<int32_t> nodes;
  uint8_t dofs = 0;
  double tfail = std::numeric_limits<double>::infinity();
  util::SourceLoc where;
};

// *CONSTRAINED_JOINT_: penalty springs pull each pair of coincident nodes (N1-N2, N3-N4,
// N5-N6) back together. Spherical: N1-N2; revolute: N1-N2 and N3-N4 on the axis; cylindrical:
// the same pairs, free to slide along the axis N1 -> N3; translational: as cylindrical, plus
// N5-N6 off the axis against turning about it.
enum class JointKind : uint8_t { Spherical, Revolute, Cylindrical, Translational };
struct JointDef {
  int64_t id = 0;
  JointKind kind = JointKind::Spherical;
  std::vector<std::array<int32_t, 2>> pairs;
  double rps = 1.0;   // relative penalty stiffness
  double damp = 1.0;  // scale of the default damping
  util::SourceLoc where;
  // Pairs whose gap counts only across the axis (cylindrical and translational joints).
  bool slides() const { return kind == JointKind::Cylindrical || kind == JointKind::Translational; }
};

// *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED: about the axes of a local frame of body A (phi
// about x, theta about y, psi about z), an elastic-plastic (friction) spring of stiffness
// ES and limit moment FM resists the rotation of body B's frame relative to A's.
struct JointStiffnessDef {
  int64_t id = 0;
  int32_t body_a = -1, body_b = -1;  // indices into RigidDefinitions::bodies
  // Local axes (rows, global components) at time 0; they turn with their bodies.
  std::array<std::array<double, 3>, 3> frame_a{}, frame_b{};
  std::array<double, 3> stiffness{};  // ESPH, ESTH, ESPS
  std::array<double, 3> friction{};   // FMPH, FMTH, FMPS (0: elastic)
  util::SourceLoc where;
};

// *LOAD_RIGID_BODY: a force along a global axis (dof 0-2) or a moment about one (dof 3-5) on
// a body's centre of mass, SF times a curve of time.
struct RigidLoad {
  int32_t body = -1;
  int dof = 0;
  int32_t curve = -1;  // index into Model::curves
  double sf = 1.0;
  util::SourceLoc where;
};

struct RigidDefinitions {
  // Part bodies in ascending master part id, then nodal rigid bodies in ascending id.
  std::vector<RigidBodyDef> bodies;
  std::vector<SpotweldDef> welds;  // in deck order
  std::vector<TiedNodeSet> node_sets;
  std::vector<JointDef> joints;  // in deck order
  std::vector<JointStiffnessDef> joint_stiffness;
  std::vector<RigidLoad> loads;
  bool empty() const {
    return bodies.empty() && welds.empty() && node_sets.empty() && joints.empty() &&
           joint_stiffness.empty() && loads.empty();
  }
};

}  // namespace crumple::model
