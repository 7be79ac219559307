// Element blocks other than solids: shells, beams and discrete elements. Like SolidBlock, a
// block is the elements of one part on one rank, with its state as structure of arrays, and
// writes its corner forces (and moments) to per-element slots that the nodes gather in global
// element order (ARCHITECTURE.md, Determinism).
//
// Slot layout (3 doubles per slot, slots[3 * slot + c]):
//   shell element e:    force corner a (0..3) at slot_offset + 8 e + a,
//                       moment corner a      at slot_offset + 8 e + 4 + a
//   beam element e:     force at node a (0..1) at slot_offset + 4 e + a,
//                       moment at node a      at slot_offset + 4 e + 2 + a
//   discrete element e: force at node a (0..1) at slot_offset + 2 e + a
// Initialisation writes each corner's lumped mass into the x component of its force slot and
// its rotational inertia into the x component of its moment slot, so that masses and inertias
// are assembled by the same ordered gather as forces and moments.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "materials/erosion.hpp"
#include "materials/materials.hpp"
#include "model/model.hpp"

namespace crumple::domain {

// What every block has: the part, the elements (model indices within their family) and
// where their slots start.
struct BlockBase {
  int32_t part = model::kNone;  // model part index
  int64_t part_id = 0;
  // Model element index within the element family (solids, shells, beams or discretes).
  // Elements with a node shared with another rank come first (ascending), then the others.
  std::vector<int32_t> elem;
  std::size_t shared_count = 0;  // elements in the first group
  std::size_t shared_end = 0;    // shared_count rounded up to whole batches (kernel range)
  std::vector<int64_t> elem_id;  // user element id
  std::size_t slot_offset = 0;   // first slot of the block
  // *MAT_RIGID part: the elements give the rigid body their mass and inertia and compute no
  // force; their kernels run only at initialisation (the state arrays are allocated by the
  // solver, which calls the kernels' resize functions). Shells and beams of a law declaring
  // kMassOnlyStructures (*MAT_NULL: LS-DYNA bypasses them in the element processing) are
  // flagged the same: mass and inertia only, no force and no time step.
  bool rigid = false;
  // Solids and shells: an element whose stable step (before TSSFAC) falls below this is eroded
  // like a failed one (*CONTROL_TIMESTEP ERODE = 1 with DTMIN, *MAT_024 TDEL); 0 = never. Set
  // by the solver once the initial step is known.
  double erode_dt = 0.0;
  // Solids and shells: the erosion criteria of the part's material (materials/erosion.hpp;
  // none for most parts) and the time of the pass, t(n), set by the solver (FAILTM).
  materials::Erosion erosion;
  double time = 0.0;
  std::size_t size() const { return elem.size(); }
};

// Elements per batch for shells (state arrays padded to whole batches).
inline constexpr int kShellBatch = 16;

// Belytschko-Tsay shells (ELFORM 2; ELFORM 4 / degenerate quads as C0 triangles).
struct ShellBlock : BlockBase {
  static constexpr model::Family kFamily = model::Family::Shell;
  static constexpr int kSlotsPerElement = 8;  // force and moment slot per corner
  materials::Law law;
  double rho0 = 0.0;
  int elform = 2;        // 2 Belytschko-Tsay (10 runs as 2 with bwc), 4 C0 triangle, 16 fully
                         // integrated (src/elements/shell_full.cpp); 13 plane strain and 15
                         // volume-weighted axisymmetric 2D solids (src/elements/solid2d.cpp)
  int nip = 2;           // integration points through the thickness
  bool lobatto = false;  // QR/IRID: Gauss (default) or Lobatto
  double shear_factor = 5.0 / 6.0;
  int ihq = 1;       // hourglass type (viscous 1-3, stiffness 4-5)
  double qm = 0.1;   // hourglass coefficient
  bool bwc = false;  // Belytschko-Wong-Chiang warping correction (*CONTROL_SHELL BWC=1)
  bool thickness_update = false;  // *CONTROL_SHELL ISTUPD
  bool warping = false;           // ELFORM 16 with IHQ 8: the warping projection (shell_full.cpp)
  std::vector<std::array<int32_t, 4>> conn;             // local node indices; n3 == n4: triangle
  std::vector<std::array<double, 4>> corner_thickness;  // initial thickness at the 4 corners
  // Per-element state, defined and allocated by the kernel (src/elements/shell.cpp,
  // resizeShellBlock), padded to whole batches (padding lanes replicate the block's last
  // element and are never read back).
  std::vector<double> thick;        // current thickness
  std::vector<double> area0;        // initial mid-surface area
  std::vector<double> e_int, e_hg;  // internal and hourglass energy
  // Work of the drilling-rotation constraint (src/elements/shell.cpp, "Drilling rotations"):
  // a penalty of Crumple's own, reported apart from the hourglass energy.
  std::vector<double> e_drill;
  std::vector<uint8_t> active;     // 0 once eroded
  std::vector<uint8_t> failed;     // eroded because every point reached the failure strain
  std::vector<double> mass_scale;  // empty if none
  // Through-thickness rule: point i at z = zeta[i] t / 2, weight[i] (the weights sum to 1);
  // Gauss or Lobatto from nip, or a section's *INTEGRATION_SHELL rule.
  std::vector<double> zeta, weight;
  // *SECTION_SHELL ICOMP 1: the material angle of each point through the thickness in radians
  // (nip of them); empty: every point at angle 0. Only orthotropic laws use them.
  std::vector<double> ply;
  // Laws whose a axis comes from a vector (*MAT_054 AOPT 2, 3): per element (padded), the angle
  // of that axis about the normal from the element frame's first axis at the initial geometry
  // (set by initializeShells); empty otherwise.
  std::vector<double> axis_angle;
  // Integration-point state in the corotational element frame, stored batch by batch (one
  // contiguous record of `fields` x kShellBatch values per batch, like SolidBlock::sig). An
  // element has inPlanePoints() in-plane points q (1; 4 for ELFORM 16, 2 x 2 Gauss), each with
  // its own record of 3 nip + 2 fields at field q (3 nip + 2):
  //   sig:   in-plane stress (xx, yy, xy) of point i at fields 3 i + k, then the transverse
  //          shear stresses yz, zx (elastic, uniform through the thickness) at 3 nip, 3 nip + 1
  //   eps_p: nip fields per in-plane point, effective plastic strain (plastic laws), else empty
  //   alpha: 3 nip fields per in-plane point, back stress in plane-stress form (kinematic laws),
  //          else empty
  //   hgq:   5 fields, the hourglass forces of the last cycle (membrane x, y, bending x, y,
  //          transverse): the stiffness forms' resistances, the viscous forms' forces (for
  //          their work); empty without hourglass control and for ELFORM 16
  //   drill: 4 fields, the corners' drilling moments (about the element normal) of the
  //          drilling-rotation constraint (src/elements/shell.cpp, "Drilling rotations")
  // 2D solids (planar(): ELFORM 13, 15) keep one point with the full 3-D state in the global
  // frame: sig and alpha 6 fields (Voigt xx, yy, zz, xy, yz, zx; zz is the out-of-plane or hoop
  // component), eps_p 1; hgq fields 0, 1 the hourglass force (x, y) of the last pass and field
  // 2 the bulk viscosity q of the last pass (both for their trapezoidal work); area0 the
  // initial volume (per radian for ELFORM 15, per unit thickness for 13), thick 1.
  std::vector<double> sig, eps_p, alpha, hgq, drill;
  //   erosion_state: with erosion criteria (BlockBase::erosion), kErosionFields per point
  //          through the thickness and in-plane point: the total strain in the element frame
  //          (xx, yy, xy tensor shear, zz) and 1 once the point has failed; else empty
  static constexpr int kErosionFields = 5;
  std::vector<double> erosion_state;
  //   hist:  the law's history variables (materials::historyOf, `history` of them) per point,
  //          nip x history fields per in-plane point q, variable k of point i at field
  //          q nip history + k nip + i (so that one variable of all a point set's points is
  //          contiguous); empty for laws without
  int history = 0;
  std::vector<double> hist;
  int histFields() const { return inPlanePoints() * nip * history; }
  int erosionFields() const { return inPlanePoints() * kErosionFields * nip; }
  static std::size_t blocked(int fields, int field, std::size_t e) {
    return (e / kShellBatch) * std::size_t(fields) * kShellBatch +
           std::size_t(field) * kShellBatch + e % kShellBatch;
  }
  int inPlanePoints() const { return elform == 16 ? 4 : 1; }
  // A 2D solid in the x-y plane (*SECTION_SHELL ELFORM 13 plane strain, 15 axisymmetric).
  bool planar() const { return elform == 13 || elform == 15; }
  bool axisymmetric() const { return elform == 15; }
  int pointFields() const { return planar() ? 6 : 3 * nip + 2; }
  int sigFields() const { return inPlanePoints() * pointFields(); }
  int epsFields() const { return inPlanePoints() * nip; }
  int alphaFields() const { return planar() ? 6 : inPlanePoints() * 3 * nip; }
  double& sigAt(int k, int point, std::size_t e, int q = 0) {
    return sig[blocked(sigFields(), q * pointFields() + 3 * point + k, e)];
  }
  double sigAt(int k, int point, std::size_t e, int q = 0) const {
    return sig[blocked(sigFields(), q * pointFields() + 3 * point + k, e)];
  }
  // Transverse shear stress: k = 0 yz, 1 zx.
  double& shearAt(int k, std::size_t e, int q = 0) {
    return sig[blocked(sigFields(), q * pointFields() + 3 * nip + k, e)];
  }
  double shearAt(int k, std::size_t e, int q = 0) const {
    return sig[blocked(sigFields(), q * pointFields() + 3 * nip + k, e)];
  }
  double& epsAt(int point, std::size_t e, int q = 0) {
    return eps_p[blocked(epsFields(), q * nip + point, e)];
  }
  double epsAt(int point, std::size_t e, int q = 0) const {
    return eps_p[blocked(epsFields(), q * nip + point, e)];
  }
  double& alphaAt(int k, int point, std::size_t e, int q = 0) {
    return alpha[blocked(alphaFields(), q * 3 * nip + 3 * point + k, e)];
  }
  double& hgqAt(int mode, std::size_t e) { return hgq[blocked(5, mode, e)]; }
  double& drillAt(int corner, std::size_t e) { return drill[blocked(4, corner, e)]; }
  double drillAt(int corner, std::size_t e) const { return drill[blocked(4, corner, e)]; }
  bool isTriangle(std::size_t e) const { return conn[e][2] == conn[e][3]; }
  std::size_t paddedSize() const {
    return (elem.size() + kShellBatch - 1) / kShellBatch * kShellBatch;
  }
};

// Beam cross-section (*SECTION_BEAM).
struct BeamSection {
  int elform = 2;  // 1 Hughes-Liu, 2 Belytschko-Schwer resultant, 3 truss, 9 spot weld
  int cst = 0;     // Hughes-Liu and spot-weld cross-section: 0 rectangular, 1 tubular
  // Hughes-Liu thicknesses at nodes 1, 2: rectangular TS (s direction), TT (t direction);
  // tubular TS outer and TT inner diameter.
  double ts1 = 0, ts2 = 0, tt1 = 0, tt2 = 0;
  double a = 0, iss = 0, itt = 0, j = 0, sa = 0;  // resultant / truss properties
  double shear_factor = 1.0;                      // SHRF (Hughes-Liu transverse shear)
  // QR: Hughes-Liu rectangular section quadrature: 1 one point, 2 2x2 Gauss (default),
  // 3 3x3 Gauss, 4 3x3 Lobatto, 5 4x4 Gauss. Tubular sections use a 16-point ring.
  int qr = 2;
  // QR/IRID < 0, *INTEGRATION_BEAM: the points (s, t, area); when user_normalized, s and t in
  // units of TS / 2 and TT / 2 and the area as the fraction WF of RA TS TT.
  std::vector<std::array<double, 3>> user_points;
  bool user_normalized = false;
  double user_ra = 1.0;
  // End releases (*ELEMENT_BEAM RT1 RR1 RT2 RR2; elements/beam_release.hpp), model::SectionBeam's
  // bits: end a (0, 1) frees its translation along r, s, t at bits 6a .. 6a + 2 and its
  // rotation about r, s, t at bits 6a + 3 .. 6a + 5; 0 none.
  int release = 0;
};

struct BeamBlock : BlockBase {
  static constexpr model::Family kFamily = model::Family::Beam;
  static constexpr int kSlotsPerElement = 4;  // force and moment slot per end
  materials::Law law;
  double rho0 = 0.0;
  BeamSection section;
  std::vector<std::array<int32_t, 3>> conn;  // local nodes 1, 2 and orientation node 3
                                             // (model::kNone: default orientation)
  // Orientation node coordinates (the third node may be held by no element; its position is
  // fixed): one entry per element.
  std::vector<std::array<double, 3>> orientation;
  // Per-element state, sized by elements::resizeBeamBlock (src/elements/beam.cpp).
  std::vector<double> length0;  // initial length
  std::vector<double> e_int;    // internal energy
  std::vector<uint8_t> active;  // 0 once eroded
  // *DAMPING_PART_STIFFNESS: Rayleigh beta of the part and the fraction of critical damping at
  // each element's highest frequency (model::Part; 0: none), and each element's damping work
  // (the energy it has taken out) with the damping resultants of the last cycle (ELFORM 2: the
  // six of `resultant`; trusses: the axial stress first) for its trapezoidal rule; empty when
  // the block is not damped.
  double stiffness_damping = 0.0, stiffness_fraction = 0.0;
  std::vector<double> e_damp;
  std::vector<std::array<double, 6>> damping_resultant;
  // ELFORM 1, 2: the frame of each end node as a unit quaternion (w, x, y, z), node 1 then
  // node 2: it turns the global axes into the node's (r, s, t) axes, and the node's angular
  // velocity turns it every cycle.
  std::vector<std::array<double, 8>> triad;
  // ELFORM 1, 2: deformation at the last cycle in the corotational frame: elongation, twist
  // (rotation about r of node 2 relative to node 1), rotations about s and t at node 1, about
  // s and t at node 2.
  std::vector<std::array<double, 6>> deformation;
  // The conjugate resultants at the last cycle: axial force, torque, moments about s and t at
  // node 1 and at node 2 (ELFORM 2: the state; ELFORM 1, 3: output).
  std::vector<std::array<double, 6>> resultant;
  // ELFORM 1, 3, 9: integration point state, point i of element e at point[e * points + i].
  int points = 0;
  std::vector<materials::FibrePoint> point;
  // *INITIAL_AXIAL_FORCE_BEAM (ELFORM 9): while t(n) lies before the end of its curve, the
  // axial force of a preloaded element is the curve's value times SCALE; KBEND keeps the
  // section's stress gradient (elements/beam.cpp). preload[e] indexes preloads, or
  // model::kNone (empty: no element of the block is preloaded).
  struct AxialPreload {
    std::vector<double> t, force;  // the curve (abscissae ascending)
    double scale = 1.0;
    bool kbend = false;
  };
  std::vector<AxialPreload> preloads;
  std::vector<int32_t> preload;
};

// Discrete springs and dampers (*ELEMENT_DISCRETE, *SECTION_DISCRETE).
struct DiscreteBlock : BlockBase {
  static constexpr model::Family kFamily = model::Family::Discrete;
  static constexpr int kSlotsPerElement = 2;  // force slot per end
  using Kind = materials::DiscreteLaw::Kind;
  materials::DiscreteLaw law;
  std::vector<std::array<int32_t, 2>> conn;
  std::vector<double> scale;    // *ELEMENT_DISCRETE S (force scale factor)
  std::vector<double> offset;   // *ELEMENT_DISCRETE OFFSET (initial elongation)
  std::vector<double> length0;  // initial length
  std::vector<double> e_int;
  std::vector<double> force;       // axial force at the last cycle (tension positive)
  std::vector<double> elongation;  // elongation at the last cycle (energy increments)
};

// SPH particles (*ELEMENT_SPH; src/elements/sph_family.hpp): those at the nodes this rank
// holds, ascending node. A particle is a node of its own (no element uses it), so all of them
// live on the rank that holds the element-less nodes, and their pair sums run there in one
// fixed order (ARCHITECTURE.md, Determinism).
struct SphBlock {
  // One per SPH part: its law and *SECTION_SPH smoothing-length rule.
  struct Group {
    int32_t part = model::kNone;  // model part index
    int64_t part_id = 0;
    materials::Law law;
    double rho0 = 0.0;
    double cslh = 1.2, hmin = 0.2, hmax = 2.0, sphini = 0.0;
    double h0 = 0.0;  // the part's initial smoothing length (set by initializeSph)
  };
  std::vector<Group> groups;
  double alpha = 1.0, beta = 1.0;  // Monaghan's viscosity (linear, quadratic)
  int dim = 3;                     // 3, or 2: plane strain in the x-y plane (model::SphParticles)
  std::vector<int32_t> node;       // local node
  std::vector<int32_t> group;      // index into groups
  std::vector<double> mass;
  // State at the last pass (initializeSph sizes it): density, smoothing length, sound speed,
  // internal energy, effective plastic strain; Cauchy stress, back stress and law history.
  std::vector<double> rho, h, c, e_int, eps_p;
  std::vector<std::array<double, 6>> sig, alpha_back;
  std::vector<std::array<double, materials::kMaxHistory>> hist;
  std::size_t size() const { return node.size(); }
};

}  // namespace crumple::domain
