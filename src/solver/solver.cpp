#include "solver/solver.hpp"

#include "elements/family.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "elements/beam.hpp"
#include "elements/discrete.hpp"
#include "elements/shell.hpp"
#include "elements/solid2d.hpp"
#include "elements/sph_family.hpp"
#include "elements/tet_nodal.hpp"
#include "util/error.hpp"
#include "util/timer.hpp"

namespace crumple::solver {

namespace {

// Nodes are processed in fixed chunks whose partial sums are added in chunk order, so
// reductions do not depend on the number of threads.
constexpr std::size_t kNodeChunk = 4096;

// The subdomain's neighbour plan as the exchange's: a neighbour's corners fill a contiguous
// range of ghost slots.
std::vector<comm::Exchange::Peer> sharedSlotPeers(const domain::Subdomain& sd) {
  std::vector<comm::Exchange::Peer> peers;
  for (const auto& p : sd.peers) {
    comm::Exchange::Peer q{p.rank, p.send_slots, std::vector<int32_t>(p.recv_count)};
    std::iota(q.recv.begin(), q.recv.end(), static_cast<int32_t>(p.recv_first));
    peers.push_back(std::move(q));
  }
  return peers;
}

std::vector<comm::Exchange::Peer> nodalVolumePeers(const domain::Subdomain& sd) {
  std::vector<comm::Exchange::Peer> peers;
  for (const auto& p : sd.nodal_volume_peers) peers.push_back({p.rank, p.send_slots, p.recv_slots});
  return peers;
}

// Whether any part runs the nodal-pressure tetrahedron: every rank takes part in its exchange.
bool hasNodalPressureTets(const model::Model& model) {
  return std::any_of(model.solid_sections.begin(), model.solid_sections.end(),
                     [](const model::SectionSolid& s) { return s.elform == 13; });
}

}  // namespace

Solver::Solver(const model::Model& model, domain::Subdomain& sd, comm::Communicator& comm)
    : model_(model),
      sd_(sd),
      comm_(comm),
      shared_slots_(comm, sharedSlotPeers(sd), 3),
      nodal_pressure_(hasNodalPressureTets(model)),
      nodal_volume_slots_(comm, nodalVolumePeers(sd), 3),
      boundary_(model, sd),
      damping_(model, sd) {
  bv_.q1 = model.controls.q_quadratic;
  bv_.q2 = model.controls.q_linear;
  end_time_ = model.controls.end_time;
  if (!model.contacts.empty()) contact_ = std::make_unique<contact::Contact>(model, sd, comm);
}

void Solver::gather(const domain::GatherPlan& plan, std::vector<double>& out,
                    int components) const {
  const std::size_t nn = sd_.numNodes();
  const double* slots = sd_.slots.data();
#pragma omp parallel for schedule(static)
  for (std::size_t n = 0; n < nn; ++n) {
    double s[3] = {0.0, 0.0, 0.0};
    for (int32_t k = plan.ptr[n]; k < plan.ptr[n + 1]; ++k) {
      const double* slot =
          slots + 3 * static_cast<std::size_t>(plan.slot[static_cast<std::size_t>(k)]);
      for (int c = 0; c < components; ++c) s[c] += slot[c];
    }
    for (int c = 0; c < components; ++c) out[components * n + c] = s[c];
  }
}

void Solver::beginSharedExchange() {
  shared_slots_.begin({sd_.slots});
}

void Solver::endSharedExchange() {
  shared_slots_.end({sd_.slots});
}

void Solver::exchangeSharedSlots() {
  beginSharedExchange();
  endSharedExchange();
}

void Solver::computeNodalVolumetricStrain() {
  {
    util::ScopedTimer timer(timing_.elements);
    for (const auto& blk : sd_.solid_blocks)
      if (blk.elform == 13 && !blk.rigid)
        elements::writeNodalVolumes(blk, sd_.x0, sd_.x, sd_.slots.data());
  }
  {
    util::ScopedTimer timer(timing_.communication);
    nodal_volume_slots_.begin({sd_.slots});
    nodal_volume_slots_.end({sd_.slots});
  }
  util::ScopedTimer timer(timing_.elements);
  nodal_volume_.resize(2 * sd_.numNodes());
  gather(sd_.nodal_volume, nodal_volume_, 2);
  elements::nodalVolumetricStrain(nodal_volume_, nodal_ev_);
}

int64_t Solver::controllingElement(int64_t local_best, bool holds_global_min) const {
  // The lowest global index among the elements at the global minimum step: the same element
  // whatever the partition.
  constexpr int64_t kNoElement = std::numeric_limits<int64_t>::max();
  const int64_t g = comm_.minAll(holds_global_min ? local_best : kNoElement);
  return g == kNoElement ? -1 : g;
}

std::string Solver::elementLabel(int64_t global_index) const {
  if (global_index < 0) return "none";
  constexpr int64_t kNoElement = std::numeric_limits<int64_t>::max();
  const int64_t held = sd_.elementId(global_index);
  const int64_t id = comm_.minAll(held != 0 ? held : kNoElement);
  const int64_t part = comm_.minAll(held != 0 ? sd_.elementPart(global_index) : kNoElement);
  return fmt::format("{} element {} (part {})", model::familyName(sd_.familyOf(global_index)), id,
                     part);
}

namespace {
// Keeps the smaller step, and on a tie the lower global element index (the same element
// whatever the partition).
void keepMin(double dt, int64_t elem, double& dt_min, int64_t& dt_elem) {
  if (elem >= 0 && (dt < dt_min || (dt == dt_min && elem < dt_elem))) {
    dt_min = dt;
    dt_elem = elem;
  }
}
template <class Block>
void zeroSlots(const Block& b, std::vector<double>& slots) {
  const std::size_t end = b.slot_offset + std::size_t(Block::kSlotsPerElement) * b.size();
  std::fill(slots.begin() + std::ptrdiff_t(3 * b.slot_offset),
            slots.begin() + std::ptrdiff_t(3 * end), 0.0);
}
}  // namespace

void Solver::initialize() {
  InitialSteps steps = initializeElements();
  checkInitialGeometry(steps.bad);
  computeStructuralMasses();
  assembleNodalMasses();
  // Springs: their step needs the masses of their nodes.
  for (const auto& blk : sd_.discrete_blocks)
    for (std::size_t e = 0; e < blk.size(); ++e)
      keepMin(elements::discreteStableStep(blk, sd_.mass, e),
              sd_.globalElement(model::Family::Discrete, blk.elem[e]), steps.other,
              steps.other_elem);
  const std::vector<double> physical_mass = sd_.mass;
  if (model_.controls.dt2ms != 0.0) scaleMasses(steps);
  keepMin(steps.other, steps.other_elem, steps.dt_min, steps.dt_elem);
  // SPH particles: never mass-scaled; no element index to name when they control the step.
  if (const double sph = elements::initializeSph(sd_.sph, sd_.x0).dt_min; sph < steps.dt_min) {
    steps.dt_min = sph;
    steps.dt_elem = -1;
  }
  // Rigid elements give mass only: their slots stay zero from here on.
  sd_.forEachBlock([&](const auto& blk) {
    if (blk.rigid) zeroSlots(blk, sd_.slots);
  });
  sumMasses(physical_mass);

  setInitialVelocities();
  // Contact before the rigid bodies: moving initially penetrating nodes changes their shape.
  if (contact_)
    contact_->initialize(model_.controls.tssfac *
                         comm_.minAll(std::min(steps.dt_min, steps.rigid)));
  if (!model_.rigid.empty()) {
    rigid_ = std::make_unique<constraints::RigidBodies>(model_, sd_, comm_);
    rigid_->setInitialVelocities(sd_);
  }
  setInitialTimeStep(steps);
  setErosionFloors();
  dt_ = 0.0;
  time_ = 0.0;
  cycle_ = 0;
  initial_energy_ = 0.0;
  initial_energy_ = energies().kinetic;
}

// The deck's nodal velocities; angular ones on the nodes with rotary inertia (shell and beam
// nodes: a solid node has no rotational freedom to set).
void Solver::setInitialVelocities() {
  const auto& w0 = model_.initial_angular_velocity;
  for (std::size_t n = 0; n < sd_.numNodes(); ++n) {
    const auto m = static_cast<std::size_t>(sd_.node_model[n]);
    for (int c = 0; c < 3; ++c) sd_.v[3 * n + c] = model_.initial_velocity[m][c];
    if (!sd_.rotations || w0.empty() || !(sd_.inertia[n] > 0.0)) continue;
    for (int c = 0; c < 3; ++c) sd_.w[3 * n + c] = w0[m][c];
  }
}

Solver::InitialSteps Solver::initializeElements() {
  InitialSteps steps;
  steps.solid.resize(sd_.solid_blocks.size());
  steps.shell.resize(sd_.shell_blocks.size());
  // Checked collectively (checkInitialGeometry), so that every rank stops together and the
  // same element is named whatever the partition.
  auto noteBad = [&](model::Family family, int64_t index) {
    if (index < 0) return;
    const int64_t g = sd_.globalElement(family, static_cast<int32_t>(index));
    if (steps.bad < 0 || g < steps.bad) steps.bad = g;
  };
  for (std::size_t ib = 0; ib < sd_.solid_blocks.size(); ++ib) {
    auto& blk = sd_.solid_blocks[ib];
    elements::markIsolatedElements(blk, sd_.internal);
    const auto st = elements::initializeSolids(blk, sd_.x0, sd_.slots.data(), steps.solid[ib], bv_);
    noteBad(model::Family::Solid, st.bad_elem);
    // Rigid elements give mass only: no time step (unless nothing else sets one), no scaling.
    if (blk.rigid) {
      if (st.dt_elem >= 0 && st.dt_min < steps.rigid) {
        steps.rigid = st.dt_min;
        steps.rigid_elem = st.dt_elem;
      }
      std::fill(steps.solid[ib].begin(), steps.solid[ib].end(), 0.0);
      continue;
    }
    keepMin(st.dt_min, st.dt_elem, steps.dt_min, steps.dt_elem);
  }
  steps.tet10.resize(sd_.tet10_blocks.size());
  for (std::size_t ib = 0; ib < sd_.tet10_blocks.size(); ++ib) {
    auto& blk = sd_.tet10_blocks[ib];
    elements::resizeTet10Block(blk);
    const auto st = elements::initializeTet10(blk, sd_.x0, sd_.slots.data(), steps.tet10[ib], bv_);
    noteBad(model::Family::Solid, st.bad_elem);
    if (blk.rigid) {
      if (st.dt_elem >= 0 && st.dt_min < steps.rigid) {
        steps.rigid = st.dt_min;
        steps.rigid_elem = sd_.globalElement(model::Family::Solid, st.dt_elem);
      }
      std::fill(steps.tet10[ib].begin(), steps.tet10[ib].end(), 0.0);
      continue;
    }
    if (st.dt_elem >= 0)
      keepMin(st.dt_min, sd_.globalElement(model::Family::Solid, st.dt_elem), steps.dt_min,
              steps.dt_elem);
  }
  for (std::size_t ib = 0; ib < sd_.shell_blocks.size(); ++ib) {
    auto& blk = sd_.shell_blocks[ib];
    elements::resizeShellBlock(blk, blk.size());
    const auto st =
        blk.planar()
            ? elements::initializeSolid2D(blk, sd_.x0, sd_.slots.data(), steps.shell[ib], bv_)
            : elements::initializeShells(blk, sd_.x0, sd_.slots.data(), steps.shell[ib]);
    if (blk.rigid) std::fill(steps.shell[ib].begin(), steps.shell[ib].end(), 0.0);
    noteBad(model::Family::Shell, st.bad_elem);
    if (!blk.rigid && st.dt_elem >= 0)
      keepMin(st.dt_min, sd_.globalElement(model::Family::Shell, st.dt_elem), steps.dt_min,
              steps.dt_elem);
  }
  std::vector<double> dts;
  for (auto& blk : sd_.beam_blocks) {
    elements::resizeBeamBlock(blk, blk.size());
    const auto st = elements::initializeBeams(blk, sd_.x0, sd_.slots.data(), dts);
    noteBad(model::Family::Beam, st.bad_elem);
    if (!blk.rigid && st.dt_elem >= 0)
      keepMin(st.dt_min, sd_.globalElement(model::Family::Beam, st.dt_elem), steps.other,
              steps.other_elem);
  }
  for (auto& blk : sd_.discrete_blocks) {
    elements::resizeDiscreteBlock(blk, blk.size());
    elements::initializeDiscretes(blk, sd_.x0, sd_.slots.data());
  }
  return steps;
}

void Solver::checkInitialGeometry(int64_t bad) const {
  constexpr int64_t kNoElement = std::numeric_limits<int64_t>::max();
  const int64_t g = comm_.minAll(bad >= 0 ? bad : kNoElement);
  if (g == kNoElement) return;
  const auto family = sd_.familyOf(g);
  const char* what = family == model::Family::Solid   ? "zero or negative volume"
                     : family == model::Family::Shell ? "zero area or thickness"
                                                      : "zero length";
  const char* hint = family == model::Family::Solid
                         ? "check its node ordering (LS-DYNA: nodes 1-4 one face, 5-8 the "
                           "opposite face, right-handed)"
                     : family == model::Family::Beam
                         ? "check its nodes (zero-length beams, such as spot welds between "
                           "coincident nodes, are not supported)"
                         : "check its nodes";
  throw util::NumericalError(
      fmt::format("{} has {} at cycle 0, time 0: {}", elementLabel(g), what, hint));
}

void Solver::computeStructuralMasses() {
  // The sum of the corners' lumped masses, which the kernels split equally among distinct
  // corners.
  auto elementMasses = [&](const auto& blk, std::size_t per, std::size_t forces) {
    std::vector<double> m(blk.size(), 0.0);
    for (std::size_t e = 0; e < blk.size(); ++e)
      for (std::size_t a = 0; a < forces; ++a)
        m[e] += sd_.slots[3 * (blk.slot_offset + per * e + a)];
    return m;
  };
  shell_mass_.clear();
  for (const auto& blk : sd_.shell_blocks) shell_mass_.push_back(elementMasses(blk, 8, 4));
  beam_mass_.clear();
  for (const auto& blk : sd_.beam_blocks) beam_mass_.push_back(elementMasses(blk, 4, 2));
}

void Solver::assembleNodalMasses() {
  exchangeSharedSlots();
  gather(sd_.internal, sd_.mass, 1);
  if (sd_.rotations) gather(sd_.rotational, sd_.inertia, 1);
  // Point masses (*ELEMENT_MASS) belong to their node on every rank that holds it.
  for (const auto& pm : model_.point_masses)
    if (const int32_t n = sd_.localNode(pm.node); n != model::kNone)
      sd_.mass[static_cast<std::size_t>(n)] += pm.mass;
  // SPH particles (*ELEMENT_SPH) carry their mass at their node.
  for (std::size_t i = 0; i < sd_.sph.size(); ++i)
    sd_.mass[static_cast<std::size_t>(sd_.sph.node[i])] += sd_.sph.mass[i];
}

void Solver::scaleMasses(InitialSteps& steps) {
  // Elements whose step TSSFAC*dt_e is below |DT2MS| get density scaled by
  // (|DT2MS| / (TSSFAC dt_e))^2 so that they run at |DT2MS|. The added mass is reported; it is
  // assembled through the slots like the physical mass.
  const auto& ctl = model_.controls;
  const double target = std::abs(ctl.dt2ms);
  bool any = false;
  // Solids and shells are scaled; beams and springs add nothing to the added mass. The
  // slots still hold each corner's lumped mass (and a shell corner's rotary inertia) from
  // initialisation: they become the added mass, (scale - 1) times that. A shell's inertia
  // grows with its mass, so that its rotational modes slow down with the translational ones.
  for (const auto& blk : sd_.beam_blocks) zeroSlots(blk, sd_.slots);
  for (const auto& blk : sd_.discrete_blocks) zeroSlots(blk, sd_.slots);
  auto scaleBlocks = [&](auto& blocks, const std::vector<std::vector<double>>& dt) {
    constexpr int per = std::decay_t<decltype(blocks)>::value_type::kSlotsPerElement;
    for (std::size_t ib = 0; ib < blocks.size(); ++ib) {
      auto& blk = blocks[ib];
      blk.mass_scale.assign(blk.paddedSize(), 1.0);
      for (std::size_t e = 0; e < blk.size(); ++e) {
        double* slot = sd_.slots.data() + 3 * (blk.slot_offset + per * e);
        const double step = ctl.tssfac * dt[ib][e];
        double factor = 0.0;
        if (step > 0.0 && step < target) {
          blk.mass_scale[e] = (target / step) * (target / step);
          factor = blk.mass_scale[e] - 1.0;
          any = true;
        }
        for (int a = 0; a < per; ++a) slot[3 * a] *= factor;
      }
    }
  };
  scaleBlocks(sd_.solid_blocks, steps.solid);
  scaleBlocks(sd_.tet10_blocks, steps.tet10);
  scaleBlocks(sd_.shell_blocks, steps.shell);
  if (!comm_.anyAll(any)) return;
  exchangeSharedSlots();
  gather(sd_.internal, sd_.mass_added, 1);
  for (std::size_t n = 0; n < sd_.numNodes(); ++n) sd_.mass[n] += sd_.mass_added[n];
  if (sd_.rotations) {
    std::vector<double> inertia_added(sd_.numNodes(), 0.0);
    gather(sd_.rotational, inertia_added, 1);
    for (std::size_t n = 0; n < sd_.numNodes(); ++n) sd_.inertia[n] += inertia_added[n];
  }
  steps.dt_min = 1e300;
  steps.dt_elem = -1;
  auto scaledSteps = [&](const auto& blocks, const std::vector<std::vector<double>>& dt,
                         model::Family family) {
    for (std::size_t ib = 0; ib < blocks.size(); ++ib) {
      const auto& blk = blocks[ib];
      if (blk.rigid) continue;
      for (std::size_t e = 0; e < blk.size(); ++e)
        keepMin(dt[ib][e] * std::sqrt(blk.mass_scale[e]), sd_.globalElement(family, blk.elem[e]),
                steps.dt_min, steps.dt_elem);
    }
  };
  scaledSteps(sd_.solid_blocks, steps.solid, model::Family::Solid);
  scaledSteps(sd_.tet10_blocks, steps.tet10, model::Family::Solid);
  scaledSteps(sd_.shell_blocks, steps.shell, model::Family::Shell);
}

void Solver::sumMasses(const std::vector<double>& physical_mass) {
  total_mass_ = 0.0;
  added_mass_ = 0.0;
  for (std::size_t n = 0; n < sd_.numNodes(); ++n)
    if (sd_.node_owned[n]) {
      total_mass_ += physical_mass[n];
      added_mass_ += sd_.mass_added[n];
    }
  const auto masses = comm_.sumOrdered({total_mass_, added_mass_});
  total_mass_ = masses[0];
  added_mass_ = masses[1];
}

void Solver::setInitialTimeStep(const InitialSteps& steps) {
  const auto& ctl = model_.controls;
  double dt_min = steps.dt_min;
  int64_t dt_elem = steps.dt_elem;
  // A model of rigid parts only runs at the step its rigid elements would have.
  if (comm_.minAll(dt_min) >= 1e300) {
    dt_min = steps.rigid;
    dt_elem = steps.rigid_elem;
  }
  const double dt_global = comm_.minAll(dt_min);
  dt_initial_elem_ = controllingElement(dt_elem, dt_elem >= 0 && dt_min == dt_global);
  dt_initial_label_ = elementLabel(dt_initial_elem_);
  dt_next_ = ctl.tssfac * dt_global;
  if (ctl.dt_init > 0.0) dt_next_ = std::min(dt_next_, ctl.dt_init);
  dt_initial_ = dt_next_;
  dt_elem_ = dt_initial_elem_;
}

void Solver::setErosionFloors() {
  // Before TSSFAC, as the kernels compare them: DTMIN x the initial step with
  // *CONTROL_TIMESTEP ERODE = 1, and a *MAT_024 part's TDEL; such elements are removed instead
  // of ending the run (beams and springs are not).
  const auto& ctl = model_.controls;
  auto erodeFloor = [&](const auto& blk) {
    const double floor = ctl.erode_on_dtmin ? ctl.dt_min_ratio * dt_initial_ / ctl.tssfac : 0.0;
    return blk.rigid ? 0.0 : std::max(floor, materials::deletionStepOf(blk.law) / ctl.tssfac);
  };
  for (auto& blk : sd_.solid_blocks) blk.erode_dt = erodeFloor(blk);
  for (auto& blk : sd_.tet10_blocks) blk.erode_dt = erodeFloor(blk);
  for (auto& blk : sd_.shell_blocks) blk.erode_dt = erodeFloor(blk);
}

bool Solver::finished() const {
  const auto& ctl = model_.controls;
  if (ctl.end_cycle > 0 && cycle_ >= ctl.end_cycle) return true;
  return time_ >= end_time_ * (1.0 - 1e-12);
}

void Solver::step() {
  const int64_t eroded_before = eroded_;
  const ElementPass pass = computeInternalForces();
  StableStep next;
  {
    // Both wait on every rank (global minima): their time is communication.
    util::ScopedTimer timer(timing_.communication);
    checkElementGeometry(pass);
    next = stableTimeStep(pass);
  }
  dt_next_ = next.dt;
  dt_elem_ = next.element;
  // Land exactly on the end time rather than overshoot it.
  double dt_half = dt_next_;
  const double remaining = end_time_ - time_;
  if (remaining > 0.0 && dt_half > remaining) dt_half = remaining;
  // dt(n) centred on t(n); the first cycle starts from v(-1/2) = v(0) with half a step.
  const double dt_n = cycle_ == 0 ? 0.5 * dt_half : 0.5 * (dt_ + dt_half);
  computeExternalForces(dt_n);
  // Elements eroded in this pass leave the contact surfaces before contact is computed.
  if (contact_ && eroded_ != eroded_before) contact_->noteErosion();
  computeContactForces();
  updateVelocities(dt_n);
  addExternalWork(dt_n, applyConstraints(dt_n, dt_half));
  updatePositions(dt_half);
  dt_ = dt_half;
  time_ += dt_half;
  ++cycle_;
  checkFiniteVelocities();
}

Solver::ElementPass Solver::computeInternalForces() {
  // Elements at shared nodes first; their corner forces travel while the others compute.
  ElementPass pass;
  {
    util::ScopedTimer timer(timing_.communication);
    boundary_.updateAirbags(time_, sd_, comm_);  // a global sum of the bags' volumes
  }
  if (nodal_pressure_) computeNodalVolumetricStrain();
  {
    util::ScopedTimer timer(timing_.elements);
    computeElementGroup(Group::Shared, pass);
    boundary_.pressureForces(time_, sd_);
  }
  {
    util::ScopedTimer timer(timing_.communication);
    beginSharedExchange();
  }
  {
    util::ScopedTimer timer(timing_.elements);
    computeElementGroup(Group::Interior, pass);
  }
  {
    util::ScopedTimer timer(timing_.communication);
    endSharedExchange();
  }
  util::ScopedTimer timer(timing_.elements);
  gather(sd_.internal, sd_.f, 3);
  if (sd_.rotations) gather(sd_.rotational, sd_.moment, 3);
  gather(sd_.pressure, sd_.f_ext, 3);
  if (sd_.sph.size() > 0)
    pass.sph_dt = elements::computeSphForces(sd_.sph, sd_.x, sd_.v, dt_, sd_.f).dt_min;
  forces_computed_ = true;
  return pass;
}

void Solver::computeElementGroup(Group group, ElementPass& pass) {
  auto range = [&](const domain::BlockBase& blk) {
    return group == Group::Shared ? std::pair{std::size_t(0), blk.shared_end}
                                  : std::pair{blk.shared_end, blk.size()};
  };
  auto merge = [&](const elements::BlockStatus& st, model::Family family) {
    if (st.dt_elem >= 0)
      keepMin(st.dt_min, sd_.globalElement(family, st.dt_elem), pass.dt_min, pass.dt_elem);
    if (st.bad_elem >= 0) {
      const int64_t bad = sd_.globalElement(family, st.bad_elem);
      if (pass.bad < 0 || bad < pass.bad) pass.bad = bad;
    }
    eroded_ += st.eroded;
  };
  const elements::KernelInputs in{sd_.x,           sd_.v, sd_.w, dt_, bv_, sd_.slots.data(),
                                  nodal_ev_.data()};
  sd_.forEachBlock([&](auto& blk) {
    using Block = std::decay_t<decltype(blk)>;
    const auto [first, last] = range(blk);
    if (first >= last || blk.rigid) return;
    blk.time = time_;  // the erosion criterion FAILTM
    merge(elements::TraitsOf<Block>::forces(blk, in, first, last), Block::kFamily);
    // A spring's step depends on its (tangent) stiffness and its nodes' masses.
    if constexpr (Block::kFamily == model::Family::Discrete)
      for (std::size_t e = first; e < last; ++e)
        keepMin(elements::discreteStableStep(blk, sd_.mass, e),
                sd_.globalElement(model::Family::Discrete, blk.elem[e]), pass.dt_min, pass.dt_elem);
  });
}

void Solver::checkElementGeometry(const ElementPass& pass) const {
  const int64_t bad = pass.bad;
  constexpr int64_t kNoElement = std::numeric_limits<int64_t>::max();
  const int64_t bad_id = comm_.minAll(bad >= 0 ? sd_.elementId(bad) : kNoElement);
  if (bad_id == kNoElement) return;
  // The rank holding the element names its part; user ids ascend with model indices.
  const int64_t part =
      comm_.minAll(bad >= 0 && sd_.elementId(bad) == bad_id ? sd_.elementPart(bad) : kNoElement);
  // The family of the element: the lowest global index with that user id on any rank.
  const int64_t family = comm_.minAll(
      bad >= 0 && sd_.elementId(bad) == bad_id ? int64_t(sd_.familyOf(bad)) : kNoElement);
  const bool solid = family == int64_t(model::Family::Solid);
  throw util::NumericalError(fmt::format("{} in {} element {} (part {}) at cycle {}, time {:.6g}",
                                         solid ? "negative volume" : "collapsed geometry",
                                         model::familyName(static_cast<model::Family>(family)),
                                         bad_id, part, cycle_, time_));
}

Solver::StableStep Solver::stableTimeStep(const ElementPass& pass) const {
  const auto& ctl = model_.controls;
  const double dt_global = comm_.minAll(std::min(pass.dt_min, pass.sph_dt));
  const int64_t element =
      controllingElement(pass.dt_elem, pass.dt_elem >= 0 && pass.dt_min == dt_global);
  // No deformable element anywhere (rigid parts only): the initial step stays.
  const double tssf = dr_tssf_ > 0.0 ? dr_tssf_ : ctl.tssfac;
  double dt = dt_global >= 1e300 ? dt_initial_ : tssf * dt_global;
  if (ctl.dt_max_curve != model::kNone)
    dt = std::min(dt, model_.curves[static_cast<std::size_t>(ctl.dt_max_curve)].value(time_));
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    throw util::NumericalError(
        fmt::format("time step collapsed to {:.3g} at cycle {}, time {:.6g} (controlling {})", dt,
                    cycle_, time_, elementLabel(element)));
  }
  if (ctl.dt_min_ratio > 0.0 && dt < ctl.dt_min_ratio * dt_initial_) {
    throw util::NumericalError(fmt::format(
        "time step {:.3g} fell below DTMIN x initial step ({:.3g}) at cycle {}, time {:.6g} "
        "(controlling {})",
        dt, ctl.dt_min_ratio * dt_initial_, cycle_, time_, elementLabel(element)));
  }
  return {dt, element};
}

void Solver::computeExternalForces(double dt_n) {
  util::ScopedTimer timer(timing_.constraints);
  boundary_.externalForces(time_, sd_, sd_.f_ext);
  boundary_.addAirbagDamping(sd_, comm_);
  if (!damping_.empty()) damping_.addForces(model_, time_, sd_);
  if (rigid_) {
    rigid_->addJointForces(dt_next_, dt_n, sd_, comm_);
    rigid_->computeBodyLoads(time_);
  }
}

void Solver::computeContactForces() {
  // Contact forces join the internal force (a = (f + f_ext) / m), so rigid bodies and
  // constraints see them like any other nodal force.
  if (!contact_) return;
  util::ScopedTimer timer(timing_.contact);
  contact_->computeForces(time_, dt_);
}

void Solver::updateVelocities(double dt_n) {
  // One pass over the nodes: keep v(n-1/2), form a = F/m and v(n+1/2), and look for
  // non-finite values (fused: at a few bytes per flop, node passes are memory-bound).
  // Rotations in the same pass: omega(n+1/2) = omega(n-1/2) + dt M / I with the lumped (scaled)
  // rotary inertia of the shells and beams (Belytschko, Lin & Tsay 1984; the element kernels
  // keep their own frames, so no nodal rotation needs to be integrated).
  const std::size_t nn = sd_.numNodes();
  v_old_.resize(sd_.v.size());
  const bool rotations = sd_.rotations;
  if (rotations) w_old_.resize(sd_.w.size());
  int non_finite = 0;
#pragma omp parallel for schedule(static) reduction(| : non_finite)
  for (std::size_t n = 0; n < nn; ++n) {
    const double m = sd_.mass[n];
    for (int c = 0; c < 3; ++c) {
      const std::size_t i = 3 * n + c;
      const double v_prev = sd_.v[i];
      v_old_[i] = v_prev;
      sd_.a[i] = m > 0.0 ? (sd_.f[i] + sd_.f_ext[i]) / m : 0.0;
      sd_.v[i] = v_prev + dt_n * sd_.a[i];
      non_finite |= std::isfinite(sd_.v[i]) ? 0 : 1;
    }
    if (!rotations) continue;
    const double inertia = sd_.inertia[n];
    for (int c = 0; c < 3; ++c) {
      const std::size_t i = 3 * n + c;
      w_old_[i] = sd_.w[i];
      if (inertia > 0.0) sd_.w[i] += dt_n * sd_.moment[i] / inertia;
      non_finite |= std::isfinite(sd_.w[i]) ? 0 : 1;
    }
  }
  non_finite_ = non_finite != 0;
}

constraints::StepWork Solver::applyConstraints(double dt_n, double dt_half) {
  util::ScopedTimer timer(timing_.constraints);
  // Rigid bodies first: SPCs and prescribed motion act on free nodes only (build_rigid.cpp).
  constraints::StepWork work;
  if (rigid_) work = rigid_->apply(time_, dt_n, dt_half, sd_, v_old_, comm_);
  work += boundary_.applyKinematics(time_, dt_n, dt_half, sd_, v_old_);
  const auto absorbed = boundary_.applyRigidWalls(dt_n, dt_half, sd_, v_old_, comm_);
  rigidwall_energy_ += absorbed.total();
  rigidwall_ahead_ = absorbed.ahead;
  return work;
}

void Solver::addExternalWork(double dt_n, constraints::StepWork work) {
  // Over dt_n at the old and the final (constrained) velocity, in halves (step_work.hpp),
  // counted once per node, by the rank that owns it; in fixed chunks added in order.
  const std::size_t nn = sd_.numNodes();
  const std::size_t nchunk = boundary_.hasExternalForces() ? (nn + kNodeChunk - 1) / kNodeChunk : 0;
  std::vector<constraints::StepWork> chunk_work(nchunk);
#pragma omp parallel for schedule(static)
  for (std::size_t ch = 0; ch < nchunk; ++ch) {
    const std::size_t end = std::min(nn, (ch + 1) * kNodeChunk);
    constraints::StepWork w;
    for (std::size_t n = ch * kNodeChunk; n < end; ++n) {
      if (!sd_.node_owned[n]) continue;
      for (int c = 0; c < 3; ++c) {
        const std::size_t i = 3 * n + c;
        w += constraints::impulseWork(sd_.f_ext[i] * dt_n, v_old_[i], sd_.v[i]);
      }
    }
    chunk_work[ch] = w;
  }
  for (const auto& w : chunk_work) work += w;
  // The joints' penalty forces sit in f_ext too, but their energy is internal (the springs'
  // and dampers', RigidBodies::jointEnergy): their work comes back out.
  if (nchunk > 0 && rigid_)
    for (const auto& [n, f] : rigid_->jointNodeForces()) {
      if (!sd_.node_owned[std::size_t(n)]) continue;
      for (int c = 0; c < 3; ++c) {
        const std::size_t i = 3 * std::size_t(n) + std::size_t(c);
        work += constraints::impulseWork(-f[std::size_t(c)] * dt_n, v_old_[i], sd_.v[i]);
      }
    }
  // The mass damping forces sit in f_ext too: their work is damping energy.
  if (!damping_.empty()) {
    const auto dw = damping_.work(sd_, dt_n, v_old_, w_old_);
    if (nchunk > 0) work += constraints::StepWork{-dw.translation.behind, -dw.translation.ahead};
    damping_work_ += dw.translation.total() + dw.rotation.total();
    damping_ahead_ = dw.translation.ahead + dw.rotation.ahead;
  }
  external_work_ += work.total();
  work_ahead_ = work.ahead;
}

void Solver::updatePositions(double dt_half) {
  const std::size_t n = 3 * sd_.numNodes();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) sd_.x[i] += dt_half * sd_.v[i];
}

void Solver::checkFiniteVelocities() const {
  // The lowest node id is named.
  const int64_t kNoNode = std::numeric_limits<int64_t>::max();
  int64_t bad_node = kNoNode;
  if (non_finite_)
    for (std::size_t i = 0; i < sd_.v.size(); ++i)
      if (!std::isfinite(sd_.v[i])) {
        bad_node = sd_.node_id[i / 3];
        break;
      }
  const int64_t bad_id = comm_.minAll(bad_node);
  if (bad_id == kNoNode) return;
  // Name the element whose forces went non-finite (the usual cause: an element turned inside
  // out or a material update that diverged); none means an external load or a constraint did
  // it.
  const int64_t local = non_finite_ ? nonFiniteElement() : -1;
  const int64_t elem = comm_.minAll(local >= 0 ? local : kNoNode);
  const std::string source = elem != kNoNode
                                 ? "non-finite force in " + elementLabel(elem)
                                 : "non-finite external force or constraint (no element force is)";
  throw util::NumericalError(
      fmt::format("{}: non-finite velocity at node {} at cycle {}, time {:.6g}", source, bad_id,
                  cycle_, time_));
}

int64_t Solver::nonFiniteElement() const {
  int64_t found = -1;
  sd_.forEachBlockList([&](const auto& blocks, model::Family family) {
    constexpr std::size_t per = std::decay_t<decltype(blocks)>::value_type::kSlotsPerElement;
    for (const auto& blk : blocks)
      for (std::size_t e = 0; e < blk.size(); ++e) {
        const double* slot = sd_.slots.data() + 3 * (blk.slot_offset + per * e);
        if (std::all_of(slot, slot + 3 * per, [](double v) { return std::isfinite(v); })) continue;
        const int64_t g = sd_.globalElement(family, blk.elem[e]);
        if (found < 0 || g < found) found = g;
      }
  });
  return found;
}

std::string Solver::mostEnergeticElement() const {
  double most = -1.0;
  int64_t elem = -1;
  sd_.forEachBlockList([&](const auto& blocks, model::Family family) {
    for (const auto& blk : blocks)
      for (std::size_t e = 0; e < blk.size(); ++e) {
        double en = blk.e_int[e];
        if constexpr (requires { blk.e_hg; }) en += blk.e_hg[e];
        const int64_t g = sd_.globalElement(family, blk.elem[e]);
        if (en > most || (en == most && g < elem)) {
          most = en;
          elem = g;
        }
      }
  });
  const double global_most = -comm_.minAll(-most);
  return elementLabel(controllingElement(elem, elem >= 0 && most == global_most));
}

ErodedSums Solver::eroded() const {
  // Per-element values summed in block order, then over ranks in rank order.
  double mass = 0.0, internal = 0.0, hourglass = 0.0, drilling = 0.0;
  auto add = [&](const auto& blk, auto&& element_mass) {
    if (blk.active.empty()) return;
    for (std::size_t e = 0; e < blk.size(); ++e) {
      if (blk.active[e]) continue;
      mass += element_mass(e);
      internal += blk.e_int[e];
      if constexpr (requires { blk.e_hg; }) hourglass += blk.e_hg[e];
      if constexpr (requires { blk.e_drill; }) drilling += blk.e_drill[e];
    }
  };
  for (const auto& blk : sd_.solid_blocks)
    add(blk, [&](std::size_t e) { return blk.rho0 * blk.vol0[e]; });
  for (const auto& blk : sd_.tet10_blocks)
    add(blk, [&](std::size_t e) { return blk.rho0 * blk.vol0[e]; });
  for (std::size_t ib = 0; ib < sd_.shell_blocks.size(); ++ib)
    add(sd_.shell_blocks[ib], [&](std::size_t e) { return shell_mass_[ib][e]; });
  for (std::size_t ib = 0; ib < sd_.beam_blocks.size(); ++ib)
    add(sd_.beam_blocks[ib], [&](std::size_t e) { return beam_mass_[ib][e]; });
  const auto sums = comm_.sumOrdered({mass, internal, hourglass, drilling});
  return {static_cast<int64_t>(comm_.sumAll(eroded_)), sums[0], sums[1], sums[2], sums[3]};
}

namespace {
// The dot product of node n's vectors in a and in b (xyz packed).
double stepProduct(const domain::NodeVector& a, const domain::NodeVector& b, std::size_t n) {
  return a[3 * n] * b[3 * n] + a[3 * n + 1] * b[3 * n + 1] + a[3 * n + 2] * b[3 * n + 2];
}
}  // namespace

Energies Solver::energies() const {
  Energies e;
  sd_.forEachBlockList([&](const auto& blocks, model::Family) {
    for (const auto& blk : blocks)
      for (std::size_t k = 0; k < blk.size(); ++k) {
        e.internal += blk.e_int[k];
        if constexpr (requires { blk.e_hg; }) e.hourglass += blk.e_hg[k];
        if constexpr (requires { blk.e_drill; }) e.drilling += blk.e_drill[k];
      }
  });
  for (double u : sd_.sph.e_int) e.internal += u;
  // Energies are reported at t(n), the time level of the stresses from the last element pass
  // and of the work integrals. The kinetic energy there is the one central differences
  // conserve, 1/2 m v(n-1/2) . v(n+1/2) (docs/theory.md, "Energy balance"): with the
  // trapezoidal internal energy, it plus the internal energy changes by the work of the
  // external and constraint forces, exactly for a linear system. 1/2 m v(n)^2 with v(n) the
  // mean of the half-step velocities exceeds it by m (v(n+1/2) - v(n-1/2))^2 / 8, which is
  // second order in a smooth motion but large for a mesh ringing near the stability limit (a
  // block struck by a wall).
  const bool stepped = v_old_.size() == sd_.v.size();
  const bool spun = w_old_.size() == sd_.w.size();
  for (std::size_t n = 0; n < sd_.numNodes(); ++n) {
    // Nodes of rigid bodies: the bodies' own energy is added below.
    if (!sd_.node_owned[n] || (rigid_ && rigid_->countsNode(n))) continue;
    // Kinetic energy of the mass the equations of motion integrate (mass added by scaling
    // included, as the work of the forces goes into it too); the added mass is reported.
    e.kinetic += 0.5 * sd_.mass[n] * stepProduct(stepped ? v_old_ : sd_.v, sd_.v, n);
    // Rotational kinetic energy of the rotary inertia likewise.
    if (sd_.rotations)
      e.kinetic += 0.5 * sd_.inertia[n] * stepProduct(spun ? w_old_ : sd_.w, sd_.w, n);
  }
  // The work up to t(n): the last step's half at v(n+1/2) belongs to the next balance.
  // Damping: the mass damping forces' work (negated) and the beams' stiffness damping.
  double damping = -(damping_work_ - damping_ahead_);
  for (const auto& blk : sd_.beam_blocks)
    for (double d : blk.e_damp) damping += d;
  const auto sums =
      comm_.sumOrdered({e.kinetic, e.internal, e.hourglass, external_work_ - work_ahead_,
                        rigidwall_energy_ - rigidwall_ahead_, damping, e.drilling});
  e.kinetic = sums[0];
  e.internal = sums[1];
  e.hourglass = sums[2];
  e.external_work = sums[3];
  // *CONTROL_ENERGY RWEN 1: the stonewalls' energy is not computed, so it is left out of the
  // balance (what they take out then shows as a fall of the energy ratio, as in LS-DYNA).
  e.rigidwall = model_.controls.rigidwall_energy ? sums[4] : 0.0;
  e.damping = sums[5];
  e.drilling = sums[6];
  e.kinetic += boundary_.wallKineticEnergy();  // the same on every rank: added once
  // Rigid bodies: translation and rotation of the body (the energy its integrator keeps;
  // with *PART_INERTIA the nodal masses are not the body's), the same on every rank.
  if (rigid_) {
    e.kinetic += rigid_->kineticEnergy();
    e.internal += rigid_->jointEnergy();
  }
  if (contact_) e.contact = contact_->energy();
  e.total = e.kinetic + e.internal + e.hourglass + e.contact + e.rigidwall + e.damping + e.drilling;
  e.initial = initial_energy_;
  const double reference = initial_energy_ + e.external_work;
  e.ratio = reference != 0.0 ? e.total / reference : 1.0;
  return e;
}

std::vector<PartSums> Solver::partSums() const {
  // Nine sums per model part (element count, kinetic, internal, hourglass, momentum, mass,
  // drilling), added over this rank's blocks and then over ranks in rank order.
  constexpr std::size_t kFields = 9;
  std::vector<double> local(kFields * model_.parts.size(), 0.0);
  for (const auto& blk : sd_.solid_blocks) {
    double* p = &local[kFields * static_cast<std::size_t>(blk.part)];
    p[0] += double(blk.size());
    for (std::size_t k = 0; k < blk.size(); ++k) {
      p[2] += blk.e_int[k];
      p[3] += blk.e_hg[k];
      // Kinetic energy and momentum of a part: each corner carries rho0 V0 / 8 at the velocity
      // of its node, which splits shared nodes between parts by the mass each part gives them.
      const double corner_mass = blk.rho0 * blk.vol0[k] / 8.0;
      p[7] += blk.rho0 * blk.vol0[k];
      for (int a = 0; a < 8; ++a) {
        const double* v = &sd_.v[3 * static_cast<std::size_t>(blk.conn[k][a])];
        p[1] += 0.5 * corner_mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (int c = 0; c < 3; ++c) p[4 + c] += corner_mass * v[c];
      }
    }
  }
  // 10-node tetrahedra: each node carries its lumped share of rho0 V0 (elements/tet10.hpp).
  for (const auto& blk : sd_.tet10_blocks) {
    double* p = &local[kFields * static_cast<std::size_t>(blk.part)];
    p[0] += double(blk.size());
    for (std::size_t k = 0; k < blk.size(); ++k) {
      p[2] += blk.e_int[k];
      const double m = blk.rho0 * blk.vol0[k];
      p[7] += m;
      for (int a = 0; a < 10; ++a) {
        const double node_mass = m * elements::tet10MassShare(a);
        const double* v = &sd_.v[3 * static_cast<std::size_t>(blk.conn[k][std::size_t(a)])];
        p[1] += 0.5 * node_mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (int c = 0; c < 3; ++c) p[4 + c] += node_mass * v[c];
      }
    }
  }
  // Shells and beams: the element mass split equally among its distinct nodes.
  auto addStructural = [&](const auto& blocks, const std::vector<std::vector<double>>& masses) {
    for (std::size_t ib = 0; ib < blocks.size(); ++ib) {
      const auto& blk = blocks[ib];
      double* p = &local[kFields * static_cast<std::size_t>(blk.part)];
      p[0] += double(blk.size());
      for (std::size_t k = 0; k < blk.size(); ++k) {
        p[2] += blk.e_int[k];
        if constexpr (std::is_same_v<std::decay_t<decltype(blk)>, domain::ShellBlock>) {
          p[3] += blk.e_hg[k];
          p[8] += blk.e_drill[k];
        }
        const auto& conn = blk.conn[k];
        const std::size_t corners =
            conn.size() == 4 && conn[2] == conn[3] ? 3 : 2 + (conn.size() == 4 ? 2 : 0);
        const double corner_mass = masses[ib][k] / double(corners);
        p[7] += masses[ib][k];
        for (std::size_t a = 0; a < corners; ++a) {
          const double* v = &sd_.v[3 * static_cast<std::size_t>(conn[a])];
          p[1] += 0.5 * corner_mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
          for (int c = 0; c < 3; ++c) p[4 + c] += corner_mass * v[c];
        }
      }
    }
  };
  addStructural(sd_.shell_blocks, shell_mass_);
  addStructural(sd_.beam_blocks, beam_mass_);
  for (const auto& blk : sd_.discrete_blocks) {
    double* p = &local[kFields * static_cast<std::size_t>(blk.part)];
    p[0] += double(blk.size());
    for (std::size_t k = 0; k < blk.size(); ++k) p[2] += blk.e_int[k];
  }
  // SPH particles: each carries its mass at the velocity of its node.
  const auto& sph = sd_.sph;
  for (std::size_t i = 0; i < sph.size(); ++i) {
    double* p =
        &local[kFields * static_cast<std::size_t>(sph.groups[std::size_t(sph.group[i])].part)];
    const double* v = &sd_.v[3 * static_cast<std::size_t>(sph.node[i])];
    p[0] += 1.0;
    p[1] += 0.5 * sph.mass[i] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    p[2] += sph.e_int[i];
    for (int c = 0; c < 3; ++c) p[4 + c] += sph.mass[i] * v[c];
    p[7] += sph.mass[i];
  }
  auto total = comm_.sumOrdered(local);
  if (rigid_) rigidPartSums(total, kFields);
  std::vector<PartSums> out;
  for (std::size_t i = 0; i < model_.parts.size(); ++i) {
    const double* p = &total[kFields * i];
    if (p[0] == 0.0) continue;
    PartSums ps;
    ps.part_id = model_.parts[i].id;
    ps.kinetic = p[1];
    ps.internal = p[2];
    ps.hourglass = p[3];
    for (int c = 0; c < 3; ++c) ps.momentum[c] = p[4 + c];
    ps.mass = p[7];
    ps.drilling = p[8];
    out.push_back(ps);
  }
  return out;
}

void Solver::rigidPartSums(std::vector<double>& total, std::size_t fields) const {
  // With *PART_INERTIA the body's mass is its own, not its nodes' (the element corner sums
  // above), so its kinetic energy (translation and rotation), momentum and mass are the body's,
  // all on its master part; parts merged into it (*CONSTRAINED_RIGID_BODIES) report none of
  // them. Without it the corner sums are right, and the body's own sums would count the mass
  // of its extra nodes (*CONSTRAINED_EXTRA_NODES) twice: with their elements' parts too.
  for (const auto& state : rigid_->states()) {
    if (state.kind != constraints::RigidBodyState::Kind::Part) continue;
    const auto def = std::find_if(model_.rigid.bodies.begin(), model_.rigid.bodies.end(),
                                  [&](const auto& d) { return !d.nodal && d.id == state.id; });
    if (def == model_.rigid.bodies.end() || !def->inertia_given) continue;
    for (std::size_t k = 0; k < def->parts.size(); ++k) {
      double* p = &total[fields * static_cast<std::size_t>(def->parts[k])];
      const bool master = k == 0;
      const auto& V = state.velocity;
      const auto& w = state.angular_velocity;
      const auto& L = state.angular_momentum;
      p[1] = master ? 0.5 * state.mass * (V[0] * V[0] + V[1] * V[1] + V[2] * V[2]) +
                          0.5 * (w[0] * L[0] + w[1] * L[1] + w[2] * L[2])
                    : 0.0;
      for (int c = 0; c < 3; ++c) p[4 + c] = master ? state.mass * V[c] : 0.0;
      p[7] = master ? state.mass : 0.0;
    }
  }
}

}  // namespace crumple::solver
