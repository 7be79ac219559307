// The explicit cycle of DYNA3D (Hallquist, DYNA3D User Manual, UCRL-MA-107254, sec. 2):
// central differences on a lumped mass, element by element, no matrix inversion. Solver::step
// is the cycle, in this order:
//
//   computeInternalForces   element kernels write corner forces to their slots: first the
//                           elements at nodes shared with other ranks, then (while their
//                           forces travel: begin/endSharedExchange) all the others; nodes sum
//                           their slots, local and received, in global element order (gather;
//                           follower pressure travels the same way); SPH particles add their
//                           pair forces (elements/sph_family.hpp)
//   checkElementGeometry    an inverted or collapsed element ends every rank
//   stableTimeStep          next step = TSSFAC x global min of the element steps
//   computeExternalForces   nodal loads, gravity (Boundary), joint forces (RigidBodies)
//   computeContactForces    penalty forces of the contact interfaces
//   updateVelocities        a = F/m, v(n+1/2), omega(n+1/2)
//   applyConstraints        rigid bodies and nodal constraints, SPC, prescribed motion,
//                           stonewalls correct v(n+1/2)
//   updatePositions         x(n+1) = x(n) + dt(n+1/2) v(n+1/2)
//   checkFiniteVelocities   a NaN or infinity ends every rank, naming its source
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "comm/communicator.hpp"
#include "comm/exchange.hpp"
#include "constraints/boundary.hpp"
#include "constraints/rigid.hpp"
#include "contact/contact.hpp"
#include "domain/subdomain.hpp"
#include "elements/hex8.hpp"
#include "model/model.hpp"
#include "solver/damping.hpp"

namespace crumple::solver {

struct Energies {
  double kinetic = 0, internal = 0, hourglass = 0, contact = 0, external_work = 0;
  double rigidwall = 0;  // energy absorbed by stonewalls
  double damping = 0;    // energy taken out by *DAMPING_ mass and stiffness damping
  // Work of the shells' drilling-rotation constraint (src/elements/shell.cpp): Crumple's own
  // penalty, booked apart from the hourglass energy (LS-DYNA's shells have no such term).
  double drilling = 0;
  double total = 0, initial = 0, ratio = 1;
};

// Per-part sums for matsum.
struct PartSums {
  int64_t part_id = 0;
  double kinetic = 0, internal = 0, hourglass = 0, drilling = 0;
  double momentum[3] = {0, 0, 0};
  double mass = 0;  // the mass the kinetic energy and momentum above count (d3plot part mass)
};

// Elements removed by failure (erosion) so far: their count, their (physical) mass, and the
// internal and hourglass energy they held when they were removed.
struct ErodedSums {
  int64_t elements = 0;
  double mass = 0, internal = 0, hourglass = 0, drilling = 0;
};

struct Timing {
  double elements = 0, contact = 0, constraints = 0, communication = 0, output = 0, other = 0;
  // What no row names: the wall time less set-up, these rows and `output_s` (the writer's
  // seconds), so that set-up + rows + rest = wall (run.log and summary.json alike).
  double rest(double wall_s, double setup_s, double output_s) const {
    const double named = elements + contact + constraints + communication + output_s;
    return wall_s - setup_s - named > 0.0 ? wall_s - setup_s - named : 0.0;
  }
};

class Solver {
 public:
  Solver(const model::Model& model, domain::Subdomain& sd, comm::Communicator& comm);

  // Masses (with mass scaling), initial velocities, the first stable time step.
  void initialize();
  // Dynamic relaxation (*CONTROL_DYNAMIC_RELAXATION; src/solver/relax.cpp, docs/theory.md
  // "Dynamic relaxation"): the explicit cycle on the relaxation phase's loads (SIDR, LCIDDR)
  // with the step scaled by TSSFDR and the velocities by DRFCTR each cycle, until the
  // distortional kinetic energy at a check (every NRCYCK cycles) is below DRTOL x its peak, or
  // the phase's time reaches DRTERM. Then the transient starts at t = 0 from the relaxed
  // displacements, stresses and element state, with the deck's initial velocities, and its
  // energy balance starts there (external work 0, initial energy = the total energy then).
  // Collective; after initialize(), before the first step.
  struct Relaxation {
    int64_t cycles = 0;
    double time = 0.0;       // the phase's time at its end
    double ratio = 0.0;      // distortional kinetic energy / peak at the last check
    double peak = 0.0;       // the peak distortional kinetic energy
    double energy = 0.0;     // internal + hourglass energy at the end
    bool converged = false;  // false: DRTERM ended it
  };
  Relaxation relax();
  // The kinetic energy of the deformable nodes less that of their mean translation,
  // sum 1/2 m v.v + 1/2 I w.w - |sum m v|^2 / (2 sum m), summed exactly (the same bits for any
  // number of ranks and threads). Collective.
  double distortionalKineticEnergy() const;
  // Advances one cycle: t(n) -> t(n+1).
  void step();

  double time() const { return time_; }
  int64_t cycle() const { return cycle_; }
  double dt() const { return dt_; }  // the step just taken, dt(n+1/2)
  double endTime() const { return end_time_; }
  bool finished() const;

  Energies energies() const;
  std::vector<PartSums> partSums() const;
  double addedMass() const { return added_mass_; }
  // Global index of the element controlling the next step (-1: none).
  int64_t stepElement() const { return dt_elem_; }
  // True once a cycle has computed element forces into the slots (before, they hold the
  // corner masses of the initialisation): what section forces read.
  bool forcesComputed() const { return forces_computed_; }
  double totalMass() const { return total_mass_; }
  double initialDt() const { return dt_initial_; }
  // "shell element 12 (part 3)": the element controlling the initial step.
  const std::string& initialDtElement() const { return dt_initial_label_; }
  int64_t erodedElements() const { return eroded_; }
  // The element holding the most internal plus hourglass energy, as "solid element 7 (part
  // 2)" (collective): where spurious energy (hourglassing, a diverging material) shows.
  std::string mostEnergeticElement() const;
  // Sums over every rank (collective).
  ErodedSums eroded() const;
  const Timing& timing() const { return timing_; }
  Timing& timing() { return timing_; }
  const domain::Subdomain& subdomain() const { return sd_; }
  const constraints::Boundary& boundary() const { return boundary_; }
  // Rigid bodies, spot welds and tied node sets; null when the model has none.
  const constraints::RigidBodies* rigidBodies() const { return rigid_.get(); }
  // Contact interfaces; null when the model has none.
  const contact::Contact* contact() const { return contact_.get(); }
  contact::Contact* contact() { return contact_.get(); }

  // Restart (src/solver/state.cpp, docs/reliability.md "Restart"): the solver's state in
  // sections keyed by global ids, so that a dump written at N ranks continues at M. saveState
  // is collective and returns the bytes on rank 0 (empty elsewhere). loadState runs on every
  // rank after initialize(), which recomputes masses and initial steps from the deck; the
  // dump's are checked against them (util::InputError if the dump is from another deck).
  enum class StateSection { Scalars, Nodes, Elements, Constraints };
  std::vector<char> saveState(StateSection which) const;
  void loadState(StateSection which, const std::vector<char>& bytes);

 private:
  // partSums' rigid parts: the body's kinetic energy, momentum and mass on its master part.
  void rigidPartSums(std::vector<double>& total, std::size_t fields) const;
  // One element pass: the minimum stable step found and any inverted element.
  struct ElementPass {
    double dt_min = 1e300;
    int64_t dt_elem = -1;   // global element index
    int64_t bad = -1;       // global element index
    double sph_dt = 1e300;  // the SPH particles' smallest step (elements/sph_family.hpp)
  };
  enum class Group { Shared, Interior };
  // Element kernels over one group of every block (elements at shared nodes, or the rest).
  void computeElementGroup(Group group, ElementPass& pass);
  // Every element's corner forces, exchanged at shared nodes and summed at the nodes (f,
  // moments, follower pressure into f_ext).
  ElementPass computeInternalForces();
  // Inverted or collapsed elements of the pass end every rank (collective).
  void checkElementGeometry(const ElementPass& pass) const;
  // The next step dt(n+1/2) and the element controlling it (collective); a collapsed step
  // ends the run.
  struct StableStep {
    double dt = 0.0;
    int64_t element = -1;  // global element index; -1: none
  };
  StableStep stableTimeStep(const ElementPass& pass) const;
  // dt_n: the velocity step these forces act over (half a step in the first cycle).
  void computeExternalForces(double dt_n);
  void computeContactForces();
  // a = F/m and v(n+1/2), omega(n+1/2) over dt(n); keeps v(n-1/2) and notes non-finite values.
  void updateVelocities(double dt_n);
  // Rigid bodies, spot welds, tied sets, SPC, prescribed motion and stonewalls correct
  // v(n+1/2); returns the work of the constraints over dt(n).
  constraints::StepWork applyConstraints(double dt_n, double dt_half);
  // Adds the work of the external forces over dt(n) to `work` and that to the total.
  void addExternalWork(double dt_n, constraints::StepWork work);
  void updatePositions(double dt_half);
  // A non-finite velocity ends every rank (collective), naming the node and its source.
  void checkFiniteVelocities() const;
  // Sends this rank's corner slots at shared nodes to the neighbours and receives theirs into
  // the ghost slots (non-blocking: work may go on between begin and end).
  void beginSharedExchange();
  void endSharedExchange();
  void exchangeSharedSlots();
  // ELFORM 13: the nodal volumetric strains of this pass (nodal_ev_) from the volumes of the
  // nodal-pressure tetrahedra around each node, summed over ranks (elements/tet_nodal.hpp).
  void computeNodalVolumetricStrain();
  void gather(const domain::GatherPlan& plan, std::vector<double>& out, int components) const;

  // The steps of initialize(). Element steps are before TSSFAC.
  struct InitialSteps {
    // Per block and element (solids, 10-node tetrahedra, shells); 0 when rigid.
    std::vector<std::vector<double>> solid, tet10, shell;
    double dt_min = 1e300;  // solids and shells (mass scaling)
    int64_t dt_elem = -1;
    double other = 1e300;  // beams and springs: never mass-scaled
    int64_t other_elem = -1;
    double rigid = 1e300;  // rigid solids: the step of a model of rigid parts only
    int64_t rigid_elem = -1;
    // The lowest global index of an element whose initial geometry cannot run (inverted
    // solid, zero-area shell, zero-length beam).
    int64_t bad = -1;
  };
  // Element state from the initial geometry: corner masses in the slots, element steps.
  InitialSteps initializeElements();
  void setInitialVelocities();
  // The end of dynamic relaxation: t = 0, the initial velocities, the energy balance restarted.
  void startTransient();
  // v and omega of every node and rigid body scaled by `factor`.
  void scaleVelocities(double factor);
  void checkInitialGeometry(int64_t bad) const;
  // Element masses of shells and beams (matsum), from their corner masses in the slots.
  void computeStructuralMasses();
  // Nodal masses and rotary inertias from the slots; point masses.
  void assembleNodalMasses();
  // *CONTROL_TIMESTEP DT2MS: added mass where an element's step is below the target.
  void scaleMasses(InitialSteps& steps);
  // Total and added mass over all ranks; `physical_mass` is the mass before scaling.
  void sumMasses(const std::vector<double>& physical_mass);
  void setInitialTimeStep(const InitialSteps& steps);
  // Erosion floors of the element steps (DTMIN with ERODE, *MAT_024 TDEL).
  void setErosionFloors();

  // Global index of the element controlling the step, agreed by all ranks (collective).
  int64_t controllingElement(int64_t local_best, bool holds_global_min) const;
  // "solid element 7 (part 2)" for a global element index (collective).
  std::string elementLabel(int64_t global_index) const;
  // The lowest global index of an element of this rank whose corner forces or moments are not
  // finite (-1: none): the source of a non-finite velocity.
  int64_t nonFiniteElement() const;
  const model::Model& model_;
  domain::Subdomain& sd_;
  comm::Communicator& comm_;
  comm::Exchange shared_slots_;  // corner slots at shared nodes, to and from the neighbours
  // ELFORM 13 in the model: its corner volumes at shared nodes (Subdomain::nodal_volume_peers),
  // the nodal volumes (V0_a, V_a) and strains ln(V_a / V0_a) of each pass.
  bool nodal_pressure_ = false;
  comm::Exchange nodal_volume_slots_;
  std::vector<double> nodal_volume_, nodal_ev_;
  constraints::Boundary boundary_;
  elements::BulkViscosity bv_;
  std::unique_ptr<constraints::RigidBodies> rigid_;  // built in initialize(), after the masses
  std::unique_ptr<contact::Contact> contact_;
  NodalDamping damping_;  // *DAMPING_GLOBAL, *DAMPING_PART_MASS

  double time_ = 0.0, end_time_ = 0.0;
  int64_t cycle_ = 0;
  double dr_tssf_ = 0.0;  // TSSFDR while relaxing (relax.cpp), else 0: TSSFAC
  double dt_ = 0.0;       // dt(n-1/2): the step that brought the state to time_
  double dt_next_ = 0.0;  // dt(n+1/2) from the latest element pass
  double dt_initial_ = 0.0;
  int64_t dt_initial_elem_ = -1;
  std::string dt_initial_label_;
  int64_t dt_elem_ = -1;  // global index of the element controlling the step
  bool forces_computed_ = false;
  double total_mass_ = 0.0, added_mass_ = 0.0;
  int64_t eroded_ = 0;

  // Work and wall energy of the nodes this rank owns; summed over ranks when reported.
  double external_work_ = 0.0, rigidwall_energy_ = 0.0, initial_energy_ = 0.0;
  // This rank's share of the last step's external work at v(n+1/2) (step_work.hpp): reported
  // energies leave it to the next balance.
  double work_ahead_ = 0.0;
  // The work of the mass damping forces (negative) on the nodes this rank owns, and its half
  // ahead like work_ahead_.
  double damping_work_ = 0.0, damping_ahead_ = 0.0;
  // This rank's share of the last step's stonewall energy at v(n+1/2), left to the next
  // balance like work_ahead_.
  double rigidwall_ahead_ = 0.0;
  domain::NodeVector v_old_, w_old_;
  // Element masses per shell / beam block (matsum).
  std::vector<std::vector<double>> shell_mass_, beam_mass_;
  bool non_finite_ = false;  // the last velocity update produced a NaN or an infinity
  Timing timing_;
};

}  // namespace crumple::solver
