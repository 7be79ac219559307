// The physical problem as the deck describes it, after validation: every entity is indexed
// by a dense "model index" in ascending order of its user id, so that "global element order"
// and "ascending global node id" are simply index order everywhere downstream.
// The Model is built once (by src/model/build.cpp from a Deck) and then only read.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

#include "util/source_loc.hpp"

namespace crumple::model {

using Vec3 = std::array<double, 3>;
inline constexpr int32_t kNone = -1;

// *ELEMENT_MASS: a lumped mass added to a node.
struct PointMass {
  int32_t node = kNone;
  double mass = 0.0;
};

// *DEFINE_CURVE after SFA/SFO/OFFA/OFFO have been applied; LS-DYNA scales after offsetting:
// x = SFA*(a + OFFA), y = SFO*(o + OFFO).
struct Curve {
  int64_t id = 0;
  std::vector<double> x, y;
  // Piecewise-linear value; held constant beyond the end points (time-dependent loads).
  double value(double t) const;
  // Piecewise-linear value; extrapolated with the slope of the end segments (hardening curves).
  double valueExtrapolated(double t) const;
};

// ---- materials: a plain struct of parameters per law ------------------------------------
struct ElasticLaw {  // *MAT_ELASTIC (001)
  double E = 0, nu = 0;
};
struct PlasticKinematicLaw {  // *MAT_PLASTIC_KINEMATIC (003)
  double E = 0, nu = 0, sigy = 0, etan = 0;
  double beta = 0;          // 0 kinematic, 1 isotropic hardening, in between mixed
  double src = 0, srp = 0;  // Cowper-Symonds C and P; 0 = rate independent
  double fs = 0;            // effective plastic strain at failure (erosion); 0 = none
};
struct PiecewiseLinearLaw {  // *MAT_PIECEWISE_LINEAR_PLASTICITY (024)
  double E = 0, nu = 0, sigy = 0, etan = 0;
  double fail = 0;       // effective plastic strain at failure (erosion); 0 = none
  double c = 0, p = 0;   // Cowper-Symonds rate parameters; 0 = rate independent
  int32_t lcss = kNone;  // curve index: yield stress vs effective plastic strain
  double tdel = 0;       // minimum time step for automatic element deletion
};
using MaterialLaw = std::variant<ElasticLaw, PlasticKinematicLaw, PiecewiseLinearLaw>;

struct Material {
  int64_t id = 0;
  std::string title;
  double rho = 0;
  MaterialLaw law;
  util::SourceLoc where;
};

// ---- sections, hourglass, parts -----------------------------------------------------------
struct SectionSolid {
  int64_t id = 0;
  int elform = 1;  // 1 = constant stress (one point); 2 = selective-reduced (8 points)
  util::SourceLoc where;
};

// *HOURGLASS / *CONTROL_HOURGLASS. IHQ 1-3 viscous, 4-5 Flanagan-Belytschko stiffness.
struct Hourglass {
  int64_t id = 0;
  int ihq = 1;
  double qm = 0.1;
};

struct Part {
  int64_t id = 0;
  std::string title;
  int32_t section = kNone;    // index into Model::solid_sections
  int32_t material = kNone;   // index into Model::materials
  int32_t hourglass = kNone;  // index into Model::hourglass; kNone = *CONTROL_HOURGLASS
  util::SourceLoc where;
};

// ---- mesh ----------------------------------------------------------------------------------
struct Nodes {
  std::vector<int64_t> id;  // ascending
  std::vector<Vec3> x;      // initial coordinates
  std::size_t size() const { return id.size(); }
};

// 8-node hexahedra; wedges and tetrahedra as degenerate hexes (repeated node indices),
// the LS-DYNA convention (tet: n4=n5=n6=n7=n8; wedge: n5=n6, n7=n8).
struct Solids {
  std::vector<int64_t> id;                    // ascending
  std::vector<int32_t> part;                  // index into Model::parts
  std::vector<std::array<int32_t, 8>> nodes;  // node indices
  std::size_t size() const { return id.size(); }
};

// ---- loads, constraints and initial conditions ---------------------------------------------
enum class Dof : uint8_t { X = 0, Y = 1, Z = 2 };
// Bit mask of constrained translational (bits 0-2) and rotational (bits 3-5) freedoms.
using DofMask = uint8_t;

struct Spc {
  int32_t node = kNone;
  DofMask dofs = 0;
};

enum class MotionKind : uint8_t { Velocity = 0, Acceleration = 1, Displacement = 2 };

// *BOUNDARY_PRESCRIBED_MOTION_NODE/_SET, one entry per node and freedom.
struct PrescribedMotion {
  int32_t node = kNone;
  int dof = 0;  // 0,1,2 = x,y,z translation
  MotionKind kind = MotionKind::Velocity;
  int32_t curve = kNone;  // index into Model::curves
  double sf = 1.0;
  double birth = 0.0;
  double death = std::numeric_limits<double>::infinity();
};

// *LOAD_NODE_POINT/_SET: F = sf * curve(t) in a global direction.
struct NodalLoad {
  int32_t node = kNone;
  int dof = 0;
  int32_t curve = kNone;
  double sf = 1.0;
};

// *LOAD_SEGMENT/_SET: pressure p = sf * curve(t - at) on a quadrilateral (n3 == n4 for a
// triangle). Positive pressure pushes against the outward normal of the ordering n1..n4
// (right-hand rule), as in LS-DYNA. The normal follows the deformation (follower load).
struct PressureLoad {
  std::array<int32_t, 4> nodes{};
  int32_t curve = kNone;
  double sf = 1.0;
  double at = 0.0;  // arrival time
};

// *LOAD_BODY_X/Y/Z: base acceleration a = sf * curve(t) along dof; the body force on a node
// is -m * a (a positive Z acceleration is gravity pointing down, the LS-DYNA convention).
struct BodyLoad {
  int dof = 0;
  int32_t curve = kNone;
  double sf = 1.0;
};

// *RIGIDWALL_PLANAR (stonewall), fixed or _MOVING, infinite or _FINITE.
struct RigidWallPlanar {
  int64_t id = 0;              // 1-based order of definition unless the deck gives one
  std::vector<int32_t> nodes;  // slave nodes (NSID; empty in the deck = all nodes)
  Vec3 tail{};                 // point on the wall
  Vec3 normal{};               // unit normal pointing into the allowed half-space
  double fric = 0.0;           // Coulomb friction coefficient (FRIC)
  bool finite = false;         // _FINITE: a rectangle of lengths lenl (along l) x lenm
  Vec3 l_axis{};               // unit edge direction (from XHEV..ZHEV), finite walls only
  double lenl = 0, lenm = 0;
  bool moving = false;      // _MOVING: a wall of mass `mass` with initial speed v0
  double mass = 0, v0 = 0;  //   along its normal
  util::SourceLoc where;
};

// *CONTROL_* values after LS-DYNA defaulting (blank/zero fields mean "default").
struct Controls {
  double end_time = 0.0;          // *CONTROL_TERMINATION ENDTIM
  int64_t end_cycle = 0;          // ENDCYC; 0 = none
  double dt_min_ratio = 0.0;      // DTMIN (fraction of the initial step); 0 = none
  double end_mass_ratio = 0.0;    // ENDMAS (% mass increase for termination); 0 = none
  double tssfac = 0.9;            // *CONTROL_TIMESTEP
  double dt_init = 0.0;           // DTINIT; 0 = from the elements
  double dt2ms = 0.0;             // mass scaling; negative: only elements below |DT2MS|
  int32_t dt_max_curve = kNone;   // LCTM
  double q_quadratic = 1.5;       // *CONTROL_BULK_VISCOSITY Q1
  double q_linear = 0.06;         // Q2
  int hourglass_ihq = 1;          // *CONTROL_HOURGLASS IHQ
  double hourglass_qh = 0.1;      // QH
  bool hourglass_energy = false;  // *CONTROL_ENERGY HGEN == 2
  bool rigidwall_energy = true;   // RWEN == 2 (default)
  bool erode_on_dtmin = false;    // derived from TDEL of any material
  double d3plot_dt = 0.0;         // *DATABASE_BINARY_D3PLOT DT; 0 = first and last state
  double glstat_dt = 0.0;         // *DATABASE_GLSTAT; 0 = not requested
  double matsum_dt = 0.0;
  double nodout_dt = 0.0;
  double rwforc_dt = 0.0;
};

// A keyword the reader saw but Crumple does not act on, reported once (ARCHITECTURE "Errors").
struct UnsupportedKeyword {
  std::string keyword;  // as written, upper case, options folded as in the deck
  std::string reason;   // e.g. "not supported", "output not written yet", "implicit only"
  int count = 0;
  util::SourceLoc first;
};

// A field or option the reader read but does not honour (e.g. a *CONTROL_SOLID option).
struct IgnoredField {
  std::string keyword, field, reason;
  util::SourceLoc where;
};

struct Model {
  std::string title;
  std::string deck_path;

  Nodes nodes;
  Solids solids;
  std::vector<Part> parts;  // ascending id
  std::vector<SectionSolid> solid_sections;
  std::vector<Material> materials;
  std::vector<Hourglass> hourglass;
  std::vector<Curve> curves;

  // Sets keep their members as model indices.
  std::map<int64_t, std::vector<int32_t>> node_sets;
  std::map<int64_t, std::vector<int32_t>> part_sets;
  std::map<int64_t, std::vector<std::array<int32_t, 4>>> segment_sets;

  std::vector<Spc> spcs;
  std::vector<PrescribedMotion> prescribed;
  std::vector<NodalLoad> nodal_loads;
  std::vector<PressureLoad> pressure_loads;
  std::vector<BodyLoad> body_loads;
  std::vector<RigidWallPlanar> rigid_walls;
  std::vector<Vec3> initial_velocity;   // per node (zero if none given)
  std::vector<PointMass> point_masses;  // *ELEMENT_MASS, in deck order
  std::vector<int32_t> history_nodes;   // *DATABASE_HISTORY_NODE, in deck order

  Controls controls;
  std::vector<UnsupportedKeyword> unsupported;
  std::vector<IgnoredField> ignored;

  // Lookups from user id to model index (kNone if absent).
  int32_t nodeIndex(int64_t id) const;
  int32_t partIndex(int64_t id) const;
  int32_t curveIndex(int64_t id) const;

  // Filled by finalize(): id -> index maps. Called by the builder once everything is read.
  void finalize();

  // Frees the global mesh (nodes, solids, sets, per-node initial velocities and the id maps)
  // once every rank has built its subdomain, so that no rank keeps the whole mesh during the
  // run (the seed's distributed-memory premise). What the cycle still reads stays: parts,
  // materials, curves, controls and the load and constraint lists.
  void releaseMesh();

 private:
  std::unordered_map<int64_t, int32_t> node_index_, part_index_, curve_index_;
};

}  // namespace crumple::model
