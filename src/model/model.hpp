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
#include <utility>
#include <variant>
#include <vector>

#include "materials/erosion.hpp"
#include "materials/materials.hpp"
#include "model/contact.hpp"
#include "model/rigid.hpp"
#include "util/id_index.hpp"
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
  // SIDR (Keyword Manual vol. I, *DEFINE_CURVE): 0 the curve acts in the transient analysis
  // only, 1 in the dynamic-relaxation phase only, 2 in both.
  int32_t sidr = 0;
  // Piecewise-linear value; held constant beyond the end points (time-dependent loads).
  double value(double t) const;
  // Piecewise-linear value; extrapolated with the slope of the end segments (hardening curves).
  double valueExtrapolated(double t) const;
};

// The two phases of a run with dynamic relaxation (*CONTROL_DYNAMIC_RELAXATION): the
// relaxation, on its own time axis from 0, then the transient analysis from t = 0 again.
enum class Phase { Transient, Relaxation };

// The factor of a load whose time curve is `c` in `phase` (SIDR above): the curve's value in
// a phase it acts in, 0 in the other; a load without a curve (nullptr) is constant, 1 in both.
inline double loadFactor(const Curve* c, double t, Phase phase) {
  if (!c) return 1.0;
  const bool acts = phase == Phase::Relaxation ? c->sidr != 0 : c->sidr != 1;
  return acts ? c->value(t) : 0.0;
}

// *DEFINE_TABLE: one curve per value (for *MAT_024 LCSS, one yield curve per strain rate),
// the values SFA (VALUE + OFFA) strictly increasing. Each value's curve is the one its LCID
// names, else the next *DEFINE_CURVE after the table (Keyword Manual vol. I, *DEFINE_TABLE).
struct Table {
  int64_t id = 0;
  std::vector<double> values;
  std::vector<int64_t> curve_ids;  // the curves' LCIDs
  std::vector<int32_t> curves;     // their indices into Model::curves
  util::SourceLoc where;
};

// ---- materials: the deck's parameters of each law, declared by its unit in
// src/materials/laws/ (materials/registry.hpp lists them) ----------------------------------
using MaterialLaw = materials::LawParams;
// The law rigid bodies are built from (model/build_rigid.cpp).
using RigidLaw = materials::Rigid::Params;

// "*MAT_ELASTIC", "*MAT_RIGID", ... for messages and summaries.
const char* materialKeyword(const MaterialLaw& law);

struct Material {
  int64_t id = 0;
  std::string title;
  double rho = 0;
  MaterialLaw law;
  util::SourceLoc where;
  // Erosion criteria: the law's own (*MAT_123 EPSTHIN, EPSMAJ, NUMINT) and *MAT_ADD_EROSION's.
  materials::Erosion erosion;
};

// *EOS_LINEAR_POLYNOMIAL, *EOS_GRUNEISEN, *EOS_TABULATED_COMPACTION, *EOS_TABULATED: the
// pressure of the solids of the parts that name it (*PART EOSID) and whose law takes one
// (materials/eos.hpp).
struct EquationOfState {
  int64_t id = 0;
  std::string title;
  materials::Eos eos;
  util::SourceLoc where;
};

// ---- sections, hourglass, parts -----------------------------------------------------------
struct SectionSolid {
  int64_t id = 0;
  // 1 = constant stress (one point); 2 = selective-reduced (8 points); 10 = constant-strain
  // tetrahedron (its elements stored as N1 N2 N3 N4 N4 N4 N4 N4, model/solid_shape.hpp);
  // 15 = two-point pentahedron (stored as N1 N2 N3 N4 N5 N5 N6 N6); -1, -2 = 2 with the
  // transverse shear correction for poor aspect ratios (src/elements/hex8_full.cpp)
  int elform = 1;
  util::SourceLoc where;
  // *SECTION_TSHELL sections are kept here too (their elements are 8-node bricks of the solid
  // family; src/elements/tshell.hpp) with elform kThickShellOnePoint or kThickShellSelective
  // (ELFORM 1 or 2): NIP points through the
  // thickness on the Gauss (or Lobatto, QR = 0 with *CONTROL_SHELL INTGRD 1) rule, or the
  // *INTEGRATION_SHELL rule's zeta / weight (QR < 0); SHRF the transverse shear factor.
  int nip = 0;
  double shrf = 1.0;
  bool lobatto = false;
  std::vector<double> zeta = {}, weight = {};
};

// The internal formulation codes of *SECTION_TSHELL ELFORM 1 (one point in the plane, NIP
// through the thickness, hourglass control) and ELFORM 2 (selective reduced: 2 x 2 points in
// the plane, the transverse shear at the centre): outside LS-DYNA's *SECTION_SOLID codes.
inline constexpr int kThickShellOnePoint = 101;
inline constexpr int kThickShellSelective = 102;
inline bool isThickShell(int elform) {
  return elform == kThickShellOnePoint || elform == kThickShellSelective;
}

// *SECTION_SPH (Keyword Manual vol. I, *SECTION_SPH): the smoothing length of a part's SPH
// particles. h0 = CSLH x the largest of the part's nearest-neighbour distances (or SPHINI when
// positive); h then follows the particle's volume, held in [HMIN h0, HMAX h0].
struct SectionSph {
  int64_t id = 0;
  double cslh = 1.2;
  double hmin = 0.2, hmax = 2.0;
  double sphini = 0.0;  // 0: h0 from CSLH
  util::SourceLoc where;
};

// *ELEMENT_SPH: one particle per node (the node carries its mass), ascending node index.
struct SphParticles {
  // *CONTROL_SPH IDIM: 3, or 2 for plane strain in the x-y plane (each particle then stands
  // for a prism of unit depth: its MASS is per unit thickness, as LS-DYNA's 2D solids).
  int32_t dim = 3;
  std::vector<int32_t> node;  // model node index
  std::vector<int32_t> part;  // model part index (a part with a *SECTION_SPH)
  std::vector<double> mass;
  std::size_t size() const { return node.size(); }
};

// The 8-point hexahedra: ELFORM 2 and its variants -1 and -2 for poor aspect ratios.
inline bool isFullyIntegratedHex(int elform) {
  return elform == 2 || elform == -1 || elform == -2;
}

// The 4-node tetrahedra: ELFORM 10 (constant strain) and 13 (the same with the pressure
// averaged over the nodes, Bonet & Burton 1998; src/elements/tet_nodal.cpp).
inline bool isTetrahedron(int elform) {
  return elform == 10 || elform == 13;
}

// The 10-node tetrahedron: ELFORM 16 (src/elements/tet10.cpp).
inline bool isQuadraticTetrahedron(int elform) {
  return elform == 16;
}

// *SECTION_SHELL: ELFORM 2 Belytschko-Tsay (default), 4 C0 triangle; NIP points through the
// thickness, Gauss or (QR/IRID = -? / Lobatto) Lobatto; T1-T4 corner thicknesses.
struct SectionShell {
  int64_t id = 0;
  int elform = 2;
  double shrf = 1.0;  // transverse shear factor (LS-DYNA default 1; 5/6 recommended)
  int nip = 2;
  bool lobatto = false;
  std::array<double, 4> t{};
  // QR/IRID < 0: the *INTEGRATION_SHELL rule (points in [-1, 1] of the half thickness, weights
  // summing to 1), nip of them; empty: Gauss or Lobatto.
  std::vector<double> zeta, weight;
  // ICOMP = 1: the material angle of each integration point in degrees (B1..BNIP, about the
  // shell normal from the material's own axes), nip of them; empty: ICOMP = 0.
  std::vector<double> ply_angle;
  util::SourceLoc where;
};

// *SECTION_BEAM: ELFORM 1 Hughes-Liu and 9 spot weld (CST 0 rectangular, 1 tubular: TS/TT
// thicknesses or outer/inner diameters at the two ends), 2 Belytschko-Schwer resultant and 3 truss
// (A, ISS, ITT, J, SA).
// *INTEGRATION_BEAM (Keyword Manual vol. I): a user cross-section of Hughes-Liu beams, its
// points (s, t, area) in the beam's frame. A standard shape (ICST > 0) gives them in length
// units and areas (model/beam_shapes.hpp); user points (ICST 0) are normalised:
// s, t in [-1, 1] of TS / 2, TT / 2 and the area fraction WF of RA TS TT.
struct BeamIntegration {
  int64_t id = 0;  // IRID
  bool normalized = false;
  double ra = 1.0;
  std::vector<std::array<double, 3>> points;
  util::SourceLoc where;
};

struct SectionBeam {
  int64_t id = 0;
  int elform = 1;
  double shrf = 1.0;
  int qr = 2;  // QR/IRID < 0: the rule Model::beam_integrations[integration]
  int32_t integration = kNone;
  int cst = 0;
  double ts1 = 0, ts2 = 0, tt1 = 0, tt2 = 0;
  double a = 0, iss = 0, itt = 0, j = 0, sa = 0;
  // End releases of the elements that run with this section (a copy of the part's section
  // per release pattern, like *ELEMENT_BEAM_THICKNESS's): end a (0, 1) frees its translation
  // along the element's r, s, t at bits 6a .. 6a + 2 and its rotation about them at bits
  // 6a + 3 .. 6a + 5; 0 none.
  int release = 0;
  util::SourceLoc where;
};

// *SECTION_DISCRETE: translational springs and dampers (DRO 0).
struct SectionDiscrete {
  int64_t id = 0;
  int dro = 0;
  util::SourceLoc where;
};

enum class SectionKind : uint8_t { Solid = 0, Shell = 1, Beam = 2, Discrete = 3, Sph = 4 };

// *HOURGLASS / *CONTROL_HOURGLASS. IHQ 1-3 viscous, 4-5 Flanagan-Belytschko stiffness.
struct Hourglass {
  int64_t id = 0;
  int ihq = 1;
  double qm = 0.1;
};

struct Part {
  int64_t id = 0;
  std::string title;
  SectionKind section_kind = SectionKind::Solid;
  int32_t section = kNone;         // index into the Model's sections of that kind
  int32_t material = kNone;        // index into Model::materials
  int32_t hourglass = kNone;       // index into Model::hourglass; kNone = *CONTROL_HOURGLASS
  int32_t eos = kNone;             // index into Model::eos; kNone = none (EOSID 0)
  double contact_ssf = 1.0;        // *PART_CONTACT SSF: penalty scale of the part's segments
  double contact_thickness = 0.0;  // *PART_CONTACT OPTT: shell contact thickness; 0 = the shell's
  // *DAMPING_PART_STIFFNESS: the damping stress beta D_el deps/dt (src/elements/beam.cpp) with
  // beta = stiffness_damping (COEF < 0: its magnitude, time units) + stiffness_fraction x the
  // element's stable step (COEF > 0: the fraction of critical damping at the element's highest
  // frequency); 0 = none.
  double stiffness_damping = 0.0, stiffness_fraction = 0.0;
  util::SourceLoc where;
};

// ---- mesh ----------------------------------------------------------------------------------
struct Nodes {
  std::vector<int64_t> id;  // ascending
  std::vector<Vec3> x;      // initial coordinates
  std::size_t size() const { return id.size(); }
};

// Elements of one family with N nodes each, ascending user id.
template <int N>
struct ElementList {
  static constexpr int kNodes = N;
  std::vector<int64_t> id;                    // ascending
  std::vector<int32_t> part;                  // index into Model::parts
  std::vector<std::array<int32_t, N>> nodes;  // node indices
  std::size_t size() const { return id.size(); }
};

// 8-node hexahedra; wedges and tetrahedra as degenerate hexes (repeated node indices),
// the LS-DYNA convention (tet: n4=n5=n6=n7=n8; wedge: n5=n6, n7=n8).
// 10-node tetrahedra (*SECTION_SOLID ELFORM 16) keep their corners in `nodes` as the
// 4-node tetrahedron N1 N2 N3 N4 N4 N4 N4 N4 (so that faces, shapes and the dual graph see the
// corner tetrahedron) and their mid-side nodes N5..N10 in `mid` (N5 on edge 1-2, N6 2-3, N7 3-1,
// N8 1-4, N9 2-4, N10 3-4; Keyword Manual, *ELEMENT_SOLID). `mid` is empty when the model has
// no 10-node solid, else one entry per solid (kNone for the others).
struct Solids : ElementList<8> {
  std::vector<std::array<int32_t, 6>> mid;
  bool quadratic(std::size_t e) const { return !mid.empty() && mid[e][0] != kNone; }
};

// The most nodes that carry forces of one element (the 10-node tetrahedron's).
inline constexpr int kMaxElementNodes = 10;

// 4-node shells; n3 == n4 is a triangle (LS-DYNA convention).
struct Shells : ElementList<4> {
  // *ELEMENT_SHELL_THICKNESS corner thicknesses; all zero = the section's.
  std::vector<std::array<double, 4>> thickness;
};

// 2-node beams with an optional orientation node (third node, kNone if none).
struct Beams : ElementList<2> {
  std::vector<int32_t> orientation;
  // *ELEMENT_BEAM_THICKNESS: index into Model::beam_sections of the element's own section (its
  // part's with PARM1-5 put in); kNone = the part's.
  std::vector<int32_t> section;
};

// 2-node discrete springs and dampers, with the S (scale) and OFFSET fields.
struct Discretes : ElementList<2> {
  std::vector<double> scale, offset;
};

// Element families. Elements are numbered globally in this order (all solids, then all
// shells, beams and discrete elements), which is the "global element order" of the slots.
enum class Family : uint8_t { Solid = 0, Shell = 1, Beam = 2, Discrete = 3 };
inline constexpr int kFamilies = 4;
const char* familyName(Family f);  // "solid", "shell", "beam", "discrete"

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

// *DAMPING_GLOBAL, *DAMPING_PART_MASS(_SET): the nodal force -D(t) m v on the translations
// (scale[0..2]) and -D(t) I omega on the rotations (scale[3..5]), D(t) = value * curve(t)
// (curve kNone: D = value). Global when `nodes` is empty and `global`; a part's damping acts
// on the nodes of its elements, nodes[k] with weight[k] = the fraction of the node's elements
// that belong to the parts (1 unless parts with other damping share the node).
struct MassDamping {
  bool global = false;
  int32_t curve = kNone;
  double value = 0.0;
  std::array<double, 6> scale{1, 1, 1, 1, 1, 1};
  std::vector<int32_t> nodes;  // ascending node indices
  std::vector<double> weight;
  util::SourceLoc where;
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
  // A segment of the control volume Model::airbags[airbag]: the pressure is the bag's (curve,
  // sf and at unused) and pushes along the outward normal of the bag (constraints/airbag.hpp).
  int32_t airbag = kNone;
  // *LOAD_BLAST_SEGMENT_SET: the charge Model::blasts[blast] loads the segment (sf = SCALEP;
  // curve and at unused; constraints/blast.hpp).
  int32_t blast = kNone;
};

// *LOAD_BLAST_ENHANCED: one TNT charge in the deck's units (constraints/blast.hpp); the
// conversion factors say how many pounds, feet, milliseconds and psi one deck unit of mass,
// length, time and pressure is (UNIT, or CFM, CFL, CFT, CFP).
struct BlastCharge {
  int64_t id = 0;                  // BID
  double mass = 0.0;               // M, TNT equivalent mass
  std::array<double, 3> origin{};  // XBO, YBO, ZBO
  int32_t origin_node = kNone;     // NIDBO: the charge sits at this node's initial position
  double tbo = 0.0;                // TBO, the time of detonation
  double death = 1e20;             // DEATH: no pressure from then on
  double cfm = 1, cfl = 1, cft = 1, cfp = 1;
  bool negative_phase = true;  // NEGPHS 0: the Friedlander negative phase is applied
};

// *AIRBAG_SIMPLE_PRESSURE_VOLUME (Keyword Manual, *AIRBAG): a closed surface, its segments
// Model::pressure_loads[first, first + count), whose gas pressure follows its volume V:
//   p = PSCA * BETA * CN(t) / (V / V0)   (CN < 0 in the deck: CN(t) is the curve |CN|)
//   p = PSCA * LCID(V / V0)               (with LCID: pressure vs relative volume)
// V0 the volume of the initial geometry; MWD (mass weighted damping) adds the nodal force
// -MWD m (v - v_bag) at the bag's nodes, v_bag their mass-weighted mean velocity.
struct Airbag {
  int64_t id = 0;  // _ID option, else 1-based order
  std::size_t first = 0, count = 0;
  double psca = 1.0, vsca = 1.0, mwd = 0.0;
  double cn = 0.0, beta = 1.0;
  int32_t cn_curve = kNone;  // coefficient vs time (CN < 0)
  int32_t pv_curve = kNone;  // LCID: pressure vs relative volume
  // LCIDDR: CN vs time during dynamic relaxation (kNone: CN, or its curve, as in the transient)
  int32_t cn_dr_curve = kNone;
};

// *LOAD_BODY_X/Y/Z: base acceleration a = sf * curve(t) along dof; the body force on a node
// is -m * a (a positive Z acceleration is gravity pointing down, the LS-DYNA convention).
// LCIDDR: the curve of the dynamic-relaxation phase; without it the load does not act there
// (Keyword Manual vol. I, *LOAD_BODY: LCID acts in the transient only).
struct BodyLoad {
  int dof = 0;
  int32_t curve = kNone;
  double sf = 1.0;
  int32_t dr_curve = kNone;
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
  // *RIGIDWALL_GEOMETRIC_FLAT / _PRISM / _CYLINDER / _SPHERE: fixed, frictionless surfaces
  // that slave nodes stay outside of. `tail` is the base point, `normal` the unit vector from
  // tail to head (the flat wall's normal, the prism's depth direction, the cylinder's axis).
  enum class Shape : uint8_t { Plane = 0, Prism = 1, Cylinder = 2, Sphere = 3 };
  Shape shape = Shape::Plane;
  double lenp = 0;    // prism depth along `normal`
  double radius = 0;  // cylinder, sphere
  double length = 0;  // cylinder length along the axis; 0 = infinite
  util::SourceLoc where;
};

// *CONTROL_* values after LS-DYNA defaulting (blank/zero fields mean "default").
// *DATABASE_EXTENT_BINARY card 1 fields that shape the d3plot (Keyword Manual Vol. I): for
// shells, 1 writes and 2 leaves out the stress tensor (SIGFLG), the effective plastic strain
// (EPSFLG), the resultants (RLTFLG) and the thickness and internal energy (ENGFLG). NEIPH, NEIPS,
// MAXINT other than 3 and STRFLG are read but not honoured (reported by the deck reader).
struct D3plotExtent {
  bool shell_stress = true;
  bool shell_plastic_strain = true;
  bool shell_resultants = true;
  bool shell_energy = true;
};

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
  bool erode_on_dtmin = false;    // ERODE = 1 with DTMIN: erode solids and shells
  // *CONTROL_SOLID ESORT = 1: tetrahedra and pentahedra written as degenerate hexahedra
  // under ELFORM 1 or 2 run as ELFORM 10 and 15 (Model::solidFormulation).
  bool solid_esort = false;
  double energy_ratio_min = 0.0;        // `crumple run --energy-band LO,HI`; 0 = no check
  double energy_ratio_max = 0.0;        // HI of --energy-band
  bool shell_bwc = false;               // *CONTROL_SHELL BWC = 1 (warping correction)
  bool shell_thickness_update = false;  // ISTUPD != 0
  bool shell_lobatto = false;           // INTGRD = 1
  double d3plot_dt = 0.0;               // *DATABASE_BINARY_D3PLOT DT; 0 = first and last state
  bool d3plot = false;                  // *DATABASE_BINARY_D3PLOT present: write the d3plot family
  D3plotExtent d3plot_extent;           // *DATABASE_EXTENT_BINARY (the fields Crumple honours)
  // Largest d3plot family member in 4-byte words (`crumple run --d3plot-x`, LS-DYNA's x=).
  int64_t d3plot_file_words = 7 * 512 * 512;
  double glstat_dt = 0.0;  // *DATABASE_GLSTAT; 0 = not requested
  double matsum_dt = 0.0;
  double nodout_dt = 0.0;
  double rwforc_dt = 0.0;
  double rcforc_dt = 0.0;
  double sleout_dt = 0.0;
  double secforc_dt = 0.0;
  double spcforc_dt = 0.0, bndout_dt = 0.0, rbdout_dt = 0.0, deforc_dt = 0.0;
  double jntforc_dt = 0.0;  // *DATABASE_JNTFORC (jntforc.csv and jntforc)
  double elout_dt = 0.0;    // *DATABASE_ELOUT (elout.csv and elout)
  // The *DATABASE_<file> keywords present: Crumple writes those files in LS-DYNA's ASCII
  // layout (src/output/ascii.hpp) beside its CSV histories.
  struct AsciiFiles {
    bool glstat = false, matsum = false, nodout = false, rwforc = false, rcforc = false;
    bool sleout = false, secforc = false, jntforc = false;
    bool spcforc = false, bndout = false, rbdout = false, deforc = false;
    bool elout = false;
  } ascii;
  int64_t d3dump_cycles = 0;  // *DATABASE_BINARY_D3DUMP CYCL; 0 = no cycle-driven dumps
  // *CONTROL_DYNAMIC_RELAXATION (Keyword Manual vol. I; its older name *CONTROL_DAMPING), with
  // the manual's defaults: an explicit relaxation phase before the transient (solver/relax.cpp).
  struct Relaxation {
    int64_t nrcyck = 250;      // cycles between convergence checks
    double drtol = 1e-3;       // converged: distortional kinetic energy < DRTOL x its peak
    double drfctr = 0.995;     // velocities scaled by DRFCTR each cycle
    double drterm = 0.0;       // relaxation time that ends the phase; 0 = none
    double tssfdr = 0.0;       // time step scale factor during the phase; 0 = TSSFAC
    int64_t idrflg = 0;        // 1, -1: on; -999: off even with SIDR curves; 0: on with them
    bool sidr_curves = false;  // a *DEFINE_CURVE with SIDR 1 or 2
    bool active() const { return idrflg != -999 && (idrflg != 0 || sidr_curves); }
  } relaxation;
};

// *DATABASE_CROSS_SECTION_PLANE (Keyword Manual Vol. I): a plane through `center` with
// normal `normal` (XCT.. to XCH..), bounded (LENL, LENM > 0) in the directions `l` (towards
// *INITIAL_AXIAL_FORCE_BEAM: the axial preload of spot-weld beams (ELFORM 9): the force vs
// time curve (model curve index) times SCALE while the curve lasts; KBEND 1 keeps the
// section's bending stress gradient (src/elements/beam.cpp).
struct BeamPreload {
  std::vector<int32_t> beams;  // beam indices (the *SET_BEAM BSID), ascending
  int32_t curve = kNone;
  double scale = 1.0;
  bool kbend = false;
  util::SourceLoc where;
};

// XHEV..) and m = n x l, or to a circle of RADIUS about the tail; PSID's parts (empty: every part).
// The elements cut and the nodes of the cut are found from the initial geometry
// (src/output/sections.hpp).
struct CrossSection {
  int64_t id = 0;  // CSID of _ID, else the 1-based order of definition
  std::string title;
  std::vector<int32_t> parts;  // model part indices, ascending; empty = every part
  Vec3 center{}, normal{}, l{};
  double lenl = 0.0, lenm = 0.0;  // 0 = unbounded
  double radius = 0.0;            // RADIUS > 0: a circular cut about the tail (LENL, LENM unused)
  // *DATABASE_CROSS_SECTION_SET: the cut is the nodes of NSID (user ids, ascending) and the
  // elements of HSID, SSID, BSID, DSID by family (indices within the family, ascending); the
  // plane fields are then unused.
  bool by_set = false;
  std::vector<int64_t> set_nodes;
  std::array<std::vector<int32_t>, kFamilies> set_elements;
  util::SourceLoc where;
};

// A keyword the reader saw but Crumple does not act on, reported once (ARCHITECTURE "Errors").
struct UnsupportedKeyword {
  std::string keyword;  // as written, upper case, options folded as in the deck
  std::string reason;   // e.g. "not supported", "output not written yet", "implicit only"
  int count = 0;
  util::SourceLoc first;
  // Skipping it changes the answer (an element, material, load, constraint, contact...), as
  // opposed to output requests and options without influence: a run refuses such a deck
  // unless told to ignore what is unsupported.
  bool changes_answer = true;
  // What Crumple lacks, for the compatibility matrix: the keyword, or the definition a part
  // uses ("*MAT_JOHNSON_COOK", "*SECTION_SOLID ELFORM=10").
  std::string feature;
};

// An input error found by `crumple check`, which reads on past it to list every problem.
struct InputProblem {
  std::string message;  // "deck.k:12: *PART card 2 field 3 (MID): material 7 is not defined"
};

// A field or option the reader read but does not honour (e.g. a *CONTROL_SOLID option).
struct IgnoredField {
  std::string keyword, field, reason;
  util::SourceLoc where;
};

// The deck's consistent unit system (Keyword Manual vol. I, "Consistent units"): from
// *CONTROL_UNITS, else inferred from the density and Young's modulus of its metals
// (model/units.hpp). It labels outputs only: the solution never uses it.
struct UnitSystem {
  std::string name;    // "t-mm-s", "kg-mm-ms", ... (model/units.hpp); empty: not known
  std::string source;  // how it was found, for run.log and summary.json
};

struct Model {
  std::string title;
  std::string deck_path;
  UnitSystem units;

  Nodes nodes;
  Solids solids;
  Shells shells;
  Beams beams;
  Discretes discretes;
  SphParticles sph;         // *ELEMENT_SPH (src/elements/sph_family.hpp)
  std::vector<Part> parts;  // ascending id
  std::vector<SectionSolid> solid_sections;
  std::vector<SectionShell> shell_sections;
  std::vector<SectionBeam> beam_sections;
  std::vector<BeamIntegration> beam_integrations;
  std::vector<SectionDiscrete> discrete_sections;
  std::vector<SectionSph> sph_sections;
  std::vector<Material> materials;
  std::vector<EquationOfState> eos;  // ascending id
  std::vector<Hourglass> hourglass;
  std::vector<Curve> curves;
  std::vector<Table> tables;  // ascending id

  // Sets keep their members as model indices.
  std::map<int64_t, std::vector<int32_t>> node_sets;
  std::map<int64_t, std::vector<int32_t>> part_sets;
  std::map<int64_t, std::vector<std::array<int32_t, 4>>> segment_sets;
  // *SET_SOLID, *SET_SHELL, *SET_BEAM, *SET_DISCRETE by family (each keyword has its own ids):
  // the members as indices within the family, ascending.
  std::array<std::map<int64_t, std::vector<int32_t>>, kFamilies> element_sets;
  // *SET_TSHELL (an id space of its own): thick shells as solid-family indices, ascending.
  std::map<int64_t, std::vector<int32_t>> tshell_sets;

  std::vector<Spc> spcs;
  std::vector<PrescribedMotion> prescribed;
  std::vector<NodalLoad> nodal_loads;
  std::vector<PressureLoad> pressure_loads;
  std::vector<BlastCharge> blasts;
  std::vector<Airbag> airbags;  // control volumes, in deck order
  std::vector<BodyLoad> body_loads;
  std::vector<RigidWallPlanar> rigid_walls;
  std::vector<Vec3> initial_velocity;  // per node (zero if none given)
  // Per node, for the rotational freedoms of shell and beam nodes (*INITIAL_VELOCITY VXR-VZR,
  // _NODE, _GENERATION OMEGA); empty when no keyword gives one.
  std::vector<Vec3> initial_angular_velocity;
  std::vector<PointMass> point_masses;  // *ELEMENT_MASS, in deck order
  std::vector<int32_t> history_nodes;   // *DATABASE_HISTORY_NODE, in deck order
  // *DATABASE_HISTORY_SOLID, _SHELL, _BEAM (and _SET) by family: indices within the family,
  // ascending (elout lists them in ascending id).
  std::array<std::vector<int32_t>, kFamilies> history_elements;
  std::vector<CrossSection> cross_sections;  // *DATABASE_CROSS_SECTION_PLANE, in deck order
  std::vector<BeamPreload> beam_preloads;    // *INITIAL_AXIAL_FORCE_BEAM, in deck order
  std::vector<MassDamping> mass_damping;     // *DAMPING_GLOBAL, *DAMPING_PART_MASS, deck order
  RigidDefinitions rigid;                    // rigid bodies, spot welds, tied node sets
  std::vector<ContactInterface> contacts;
  ContactControls contact_controls;

  Controls controls;
  std::vector<UnsupportedKeyword> unsupported;
  std::vector<IgnoredField> ignored;
  std::vector<InputProblem> errors;  // only with ReadOptions::collect_errors

  // ---- the global element numbering (solids, shells, beams, discretes) ----------------------
  std::size_t familySize(Family f) const;
  std::size_t familyOffset(Family f) const;  // global index of the family's first element
  std::size_t numElements() const;
  // Family and index within it of global element g.
  std::pair<Family, int32_t> element(std::size_t g) const;
  // The nodes that carry forces of global element g (solid 8, 10-node tetrahedron 10, shell 4,
  // beam and discrete 2), written to out; returns the count.
  int elementNodes(std::size_t g, int32_t out[kMaxElementNodes]) const;
  int32_t elementPart(std::size_t g) const;
  int64_t elementId(std::size_t g) const;
  // The formulation solid e runs: its section's ELFORM (1, 2, 10 or 15), or 10 for a
  // tetrahedron and 15 for a pentahedron under ELFORM 1 or 2 when *CONTROL_SOLID ESORT = 1
  // (the reader made their nodes canonical).
  int solidFormulation(std::size_t e) const;
  // "shell element 12" for messages.
  std::string elementName(std::size_t g) const;

  // Lookups from user id to model index (kNone if absent).
  int32_t nodeIndex(int64_t id) const;
  // Index within family f of element `id` (kNone if absent); the family's ascending ids.
  int32_t elementIndex(Family f, int64_t id) const;
  // True if solid-family element e is a thick shell (its part has a *SECTION_TSHELL).
  bool isThickShellElement(int32_t e) const;
  const std::vector<int64_t>& familyIds(Family f) const;
  int32_t partIndex(int64_t id) const;
  int32_t curveIndex(int64_t id) const;
  int32_t tableIndex(int64_t id) const;

  // Filled by finalize(): id -> index maps. Called by the builder once everything is read.
  void finalize();

  // Frees the global mesh (nodes, solids, sets, per-node initial velocities and the id maps)
  // once every rank has built its subdomain, so that no rank keeps the whole mesh during the
  // run (the seed's distributed-memory premise). What the cycle still reads stays: parts,
  // materials, curves, controls and the load and constraint lists.
  void releaseMesh();

 private:
  util::IdIndex node_index_, part_index_, curve_index_, table_index_;
};

}  // namespace crumple::model
