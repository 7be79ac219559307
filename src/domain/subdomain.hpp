// A Subdomain is what one rank computes on: its nodes in local numbering, its element blocks,
// the per-element force slots and the plan that gathers them into nodal forces in global
// element order. Serial is one subdomain holding everything.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "domain/blocks.hpp"
#include "materials/materials.hpp"
#include "model/model.hpp"

namespace crumple::domain {

// Nodal values are packed xyz (3 doubles per node): the hex kernel gathers whole nodes, and a
// packed layout keeps the three components of a node on one cache line.
using NodeVector = std::vector<double>;

struct HourglassParams {
  int ihq = 1;      // 1-3 viscous, 4-5 stiffness (Flanagan-Belytschko)
  double qm = 0.1;  // coefficient
};

// Elements are processed in batches of this many; a block's per-element state arrays are
// padded to whole batches so that kernels load and store them as contiguous vectors (padding
// lanes compute on copies of real data and are never read back).
inline constexpr int kSolidBatch = 16;

// Elements of one part and one formulation: one element type x one material x one section. State is
// a structure of arrays owned by the block; element e of the block is global (model) element
// elem[e].
struct SolidBlock : BlockBase {
  static constexpr model::Family kFamily = model::Family::Solid;
  static constexpr int kSlotsPerElement = 8;  // force slot per corner
  materials::Law law;
  double rho0 = 0.0;
  HourglassParams hourglass;
  // The formulation its elements run (model::Model::solidFormulation): 1 one-point
  // hexahedron, 2 fully integrated (8 points), 10 one-point tetrahedron, 15 two-point
  // pentahedron.
  int elform = 1;

  // BlockBase::elem: elements with a node shared with another rank come first (ascending),
  // then the others (ascending): the first group is computed before the shared-node exchange
  // is posted, the second while it travels. Slots: 8 corners per element from slot_offset.
  std::vector<std::array<int32_t, 8>> conn;  // local node indices

  // Per-element state.
  // Cauchy stress (Voigt, tensor shear) and back stress (kinematic hardening laws), stored
  // batch by batch like hgq: 6 x kSolidBatch contiguous values per batch.
  std::vector<double> sig;
  std::vector<double> eps_p;  // effective plastic strain (plastic laws)
  std::vector<double> alpha;
  // The law's further history variables (materials::historyOf), `history` x kSolidBatch values
  // per batch; ELFORM 2 keeps them per Gauss point only, in hist_ip.
  int history = 0;
  std::vector<double> hist;
  // Hourglass force of the last pass, 4 modes x 3 components (the stiffness forms' stored
  // resistance; the viscous forms keep it for the trapezoidal hourglass work), stored batch by
  // batch (12 x kSolidBatch contiguous values per batch): one memory stream instead of twelve.
  // Empty when the block has no hourglass control (ELFORM 2, QM = 0).
  std::vector<double> hgq;
  // Bulk viscosity q of the last pass, for its trapezoidal work (docs/theory.md, "Energy
  // accounting of the viscous forces").
  std::vector<double> q_bulk;
  static std::size_t blocked(int fields, int component, std::size_t e) {
    return (e / kSolidBatch) * std::size_t(fields) * kSolidBatch +
           std::size_t(component) * kSolidBatch + e % kSolidBatch;
  }
  double& sigAt(int k, std::size_t e) { return sig[blocked(6, k, e)]; }
  double sigAt(int k, std::size_t e) const { return sig[blocked(6, k, e)]; }
  double& alphaAt(int k, std::size_t e) { return alpha[blocked(6, k, e)]; }
  double& hgqAt(int component, std::size_t e) {
    return hgq[(e / kSolidBatch) * 12 * kSolidBatch + std::size_t(component) * kSolidBatch +
               e % kSolidBatch];
  }
  std::vector<double> vol0, vol;    // initial and current volume
  std::vector<double> e_int, e_hg;  // internal and hourglass energy
  std::vector<uint8_t> active;      // 0 once eroded
  std::vector<uint8_t> failed;      // material reports failure this cycle
  std::vector<double> mass_scale;   // mass scaling factor (>= 1), padded; empty if none
  std::vector<double> dt_scale;     // stable-step factor (<= 1), padded; empty if none
  // ELFORM 2 and 15 only: the state of the `points` Gauss points (8 and 2), point-major (point
  // q of element e at q * paddedSize() + e). sig and eps_p above then hold the means over the
  // points.
  int points = 0;
  std::array<std::vector<double>, 6> sig_ip, alpha_ip;
  std::vector<double> eps_p_ip;
  std::vector<double> hist_ip;  // variable k of point q of element e at (q history + k) padded + e
  // With strain criteria in BlockBase::erosion (one-point solids): the total strain (Voigt,
  // tensor shear), the rate of deformation integrated and turned with the stress, stored batch
  // by batch like sig; else empty.
  std::vector<double> strain;
  // Laws of the deformation gradient (materials::needsDeformationGradient; one-point solids
  // only): each corner's initial shape-function gradient dN_a/dX_j = B_ja(X) / V0 (the uniform
  // strain gradient at the initial geometry), 24 x kSolidBatch values per batch (corner-major,
  // component-minor rows); else empty. Built from the initial coordinates (initializeSolids).
  std::vector<double> grad0;
  // ELFORM 13 only (else empty): the element's volumetric strain, the mean of ln(V_a / V0_a)
  // over its four nodes' volumes (elements/tet_nodal.hpp), at the last pass.
  std::vector<double> ev_nodal;
  // Thick shells (model::isThickShell(elform); src/elements/tshell.hpp) only: the rule through
  // the thickness (points at zeta in [-1, 1] from the bottom face N1-N4 to the top N5-N8,
  // weights summing to 1; Gauss or Lobatto from `points` = NIP, filled by initializeSolids when
  // the section gives no *INTEGRATION_SHELL rule) and the transverse shear factor. Their points
  // keep the state in the element's lamina frame: sig_ip 0-2 the in-plane stress xx, yy, xy,
  // 3, 4 the transverse shear yz, zx, 5 the thickness-stretch stress (one value per element,
  // kept at every point); alpha_ip 0-2 the plane-stress back stress or shell strain; eps_p_ip.
  // sig and eps_p hold the through-thickness means (sig in the global frame) for output.
  // plane_points: 1 (ELFORM 1, the centre of the plane) or 4 (ELFORM 2, the 2 x 2 Gauss
  // points); `points` = plane_points x NIP, point g NIP + k the in-plane point g at thickness
  // point k. The thickness-stretch stress is one value per in-plane point, kept at each of its
  // thickness points.
  std::vector<double> zeta, weight;
  bool lobatto = false;
  double shear_factor = 1.0;
  int plane_points = 1;
  bool thickShell() const { return model::isThickShell(elform); }

  // Elements plus padding: a whole number of batches.
  std::size_t paddedSize() const {
    return (elem.size() + kSolidBatch - 1) / kSolidBatch * kSolidBatch;
  }
  // gauss_points: the integration points that keep their own state (0, or 8 for ELFORM 2 and
  // 2 for ELFORM 15).
  void resize(std::size_t n, bool plastic, bool kinematic, bool hourglass_state,
              int gauss_points = 0, int history_count = 0);
};

// 10-node tetrahedra (*SECTION_SOLID ELFORM 16; src/elements/tet10.hpp): a block type of its
// own in the solid family. Its elements have ten force-carrying nodes, so ten slots each (the
// corners N1..N4, then the mid-side nodes N5..N10), and four integration points with their own
// stress and history; SolidBlock's eight-slot layout and its hourglass, nodal-pressure and
// deformation-gradient state have nothing to do here.
struct Tet10Block : BlockBase {
  static constexpr model::Family kFamily = model::Family::Solid;
  static constexpr int kSlotsPerElement = 10;  // force slot per node
  static constexpr int kPoints = 4;            // integration points
  materials::Law law;
  double rho0 = 0.0;
  std::vector<std::array<int32_t, 10>> conn;  // local node indices, N1..N10
  // Element-level view for output and sums: the mean over the points of the stress (Voigt,
  // tensor shear, blocked like SolidBlock::sig) and of the effective plastic strain.
  std::vector<double> sig, eps_p;
  // Point state, point-major: point q of element e at q * paddedSize() + e (history variable k
  // at (q history + k) paddedSize() + e).
  std::array<std::vector<double>, 6> sig_ip, alpha_ip;
  std::vector<double> eps_p_ip, hist_ip;
  int history = 0;
  std::vector<double> q_bulk;      // bulk viscosity q of the last pass (trapezoidal work)
  std::vector<double> vol0, vol;   // initial and current volume
  std::vector<double> e_int;       // internal energy
  std::vector<uint8_t> active;     // 0 once eroded
  std::vector<uint8_t> failed;     // eroded because a point failed
  std::vector<double> mass_scale;  // mass scaling factor (>= 1), padded; empty if none
  double& sigAt(int k, std::size_t e) { return sig[SolidBlock::blocked(6, k, e)]; }
  double sigAt(int k, std::size_t e) const { return sig[SolidBlock::blocked(6, k, e)]; }
  std::size_t paddedSize() const {
    return (elem.size() + kSolidBatch - 1) / kSolidBatch * kSolidBatch;
  }
};

// Corner slots this rank sends to, and receives from, one neighbour each cycle (the solver's
// comm::Exchange carries them). Both sides list the slots in ascending (global source, corner)
// order, so the message needs no ids.
struct PeerExchange {
  int rank = 0;
  std::vector<int32_t> send_slots;  // local slots whose node the peer also holds
  std::size_t recv_first = 0;       // first ghost slot filled by this peer
  std::size_t recv_count = 0;
};

// A node gathers, in ascending order of (source, corner), the slots of every element and
// pressure segment at it: local ones and ghost copies received from neighbours. Sources are
// numbered globally: element g (Model's global element order) is g, pressure segment s is
// num_elements + s.
struct GatherPlan {
  std::vector<int32_t> ptr;   // CSR over local nodes
  std::vector<int32_t> slot;  // slot indices (3 doubles each)
};

struct Subdomain {
  int rank = 0;
  int num_ranks = 1;

  // Nodes: local index -> model node index (ascending, so local order == global id order).
  std::vector<int32_t> node_model;
  std::vector<int64_t> node_id;     // user ids, for output
  std::vector<uint8_t> node_owned;  // 1 where this is the lowest rank holding the node
  NodeVector x0, x, v, a, f, f_ext;
  std::vector<double> mass;  // lumped nodal mass (incl. mass added by scaling)
  std::vector<double> mass_added;
  // Rotational freedoms, only when the model has shells or beams (else empty): angular
  // velocity, moment (from the elements) and lumped rotational inertia per node.
  bool rotations = false;
  NodeVector w, moment;
  std::vector<double> inertia;

  std::vector<SolidBlock> solid_blocks;
  std::vector<Tet10Block> tet10_blocks;  // the 10-node tetrahedra of the solid family
  std::vector<ShellBlock> shell_blocks;
  std::vector<BeamBlock> beam_blocks;
  std::vector<DiscreteBlock> discrete_blocks;
  SphBlock sph;  // the SPH particles held here (none on most ranks)
  // Calls visit(blocks, family) for the block list of every element family, in family order (the
  // global element order): code that treats the families alike goes through here, so that a
  // new family is added to it once.
  template <class F>
  void forEachBlockList(F&& visit) {
    visit(solid_blocks, model::Family::Solid);
    visit(tet10_blocks, model::Family::Solid);
    visit(shell_blocks, model::Family::Shell);
    visit(beam_blocks, model::Family::Beam);
    visit(discrete_blocks, model::Family::Discrete);
  }
  template <class F>
  void forEachBlockList(F&& visit) const {
    visit(solid_blocks, model::Family::Solid);
    visit(tet10_blocks, model::Family::Solid);
    visit(shell_blocks, model::Family::Shell);
    visit(beam_blocks, model::Family::Beam);
    visit(discrete_blocks, model::Family::Discrete);
  }
  // Every block of every family, in family order (solids and 10-node tetrahedra, shells,
  // beams, discretes).
  template <class F>
  void forEachBlock(F&& visit) {
    forEachBlockList([&](auto& blocks, model::Family) {
      for (auto& b : blocks) visit(b);
    });
  }
  template <class F>
  void forEachBlock(F&& visit) const {
    forEachBlockList([&](const auto& blocks, model::Family) {
      for (const auto& b : blocks) visit(b);
    });
  }
  std::size_t num_elements = 0;  // held here
  // Global index of the first element of each family (Model::familyOffset).
  std::array<int64_t, model::kFamilies> family_offset{};

  // Pressure segments computed here (model indices into Model::pressure_loads), each with 4
  // corner slots from pressure_slot_offset on; every segment is computed by exactly one rank.
  std::vector<int32_t> pressure_segments;
  std::size_t pressure_slot_offset = 0;

  // Corner slots: slots[3*slot + c]. Local element slots (block.slot_offset + 8 e + corner),
  // then local pressure slots, then ghost slots received from neighbours.
  std::vector<double> slots;
  std::size_t num_local_slots = 0;
  GatherPlan internal;    // element force slots -> nodal internal force (and mass)
  GatherPlan rotational;  // element moment slots -> nodal moment (and rotational inertia)
  GatherPlan pressure;    // pressure slots -> nodal external force
  std::vector<PeerExchange> peers;
  // The nodal-pressure tetrahedra (ELFORM 13, not rigid): the corner slots of theirs at each
  // node, local and ghost, in the same (source, corner) order (a subset of `internal`), and
  // what travels between neighbours for them: the local slots of such corners at nodes the
  // peer holds and the ghost slots filled from it, both in (source, corner) order. Their
  // kernel's first pass writes each corner's share of the initial and current volume there
  // and the nodes sum them (elements/tet_nodal.hpp).
  struct SlotPeer {
    int rank = 0;
    std::vector<int32_t> send_slots, recv_slots;
  };
  GatherPlan nodal_volume;
  std::vector<SlotPeer> nodal_volume_peers;

  // Sizes of the whole model (this rank holds only part of it).
  int64_t global_nodes = 0;
  int64_t global_solids = 0;
  int64_t global_elements = 0;  // every family
  std::array<int64_t, model::kFamilies> global_family{};

  std::size_t numNodes() const { return node_model.size(); }
  // Local index of a model node, or model::kNone if this rank does not hold it.
  int32_t localNode(int32_t model_node) const;
  // User id and part id of an element held here, by global element index; 0 if not held.
  int64_t elementId(int64_t global_index) const;
  int64_t elementPart(int64_t global_index) const;
  // Family of a global element index.
  model::Family familyOf(int64_t global_index) const {
    int k = model::kFamilies - 1;
    while (k > 0 && global_index < family_offset[std::size_t(k)]) --k;
    return static_cast<model::Family>(k);
  }
  // Global index of element `index` of a family.
  int64_t globalElement(model::Family family, int32_t index) const {
    return family_offset[static_cast<std::size_t>(family)] + index;
  }
};

// Builds rank `rank`'s subdomain from the element -> rank map of the whole model (one entry
// per model element, global numbering). Nodes attached to no element are kept by rank 0.
Subdomain buildSubdomain(const model::Model& model, const std::vector<int32_t>& elem_rank, int rank,
                         int num_ranks);

// The single subdomain of a serial run: every node and element of the model.
Subdomain buildSerialSubdomain(const model::Model& model);

}  // namespace crumple::domain
