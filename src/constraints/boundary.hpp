// Loads, kinematic constraints and rigid walls of one subdomain, in local node numbering.
// External forces enter before accelerations are formed; kinematic conditions act on the
// predicted velocities v(n+1/2) (DYNA3D cycle, ARCHITECTURE.md steps 3-5).
#pragma once

#include <array>
#include <vector>

#include "comm/communicator.hpp"
#include "constraints/airbag.hpp"
#include "constraints/step_work.hpp"
#include "domain/subdomain.hpp"
#include "model/model.hpp"
#include "util/archive.hpp"

namespace crumple::constraints {

// The force a kinematic constraint exerted on one node in the last step (spcforc, bndout): the
// impulse it imposed over the step, m (v_imposed - v_predicted) / dt(n), and for the
// rotational SPCs I (0 - w_predicted) / dt(n); `work` sums the impulse times the mean velocity
// over every step so far (prescribed motion only).
struct NodeReaction {
  int32_t node = 0;  // local
  model::Vec3 force{}, moment{};
  double work = 0.0;
};

struct WallState {
  const model::RigidWallPlanar* def = nullptr;
  std::vector<int32_t> nodes;  // local slave nodes
  double displacement = 0.0;   // along the normal (moving walls)
  double velocity = 0.0;       // along the normal (moving walls), v(n+1/2)
  double velocity_prev = 0.0;  // v(n-1/2)
  model::Vec3 force{};         // force of the wall on the structure in the last cycle
  double normal_force = 0.0;   // its component along the wall normal
};

class Boundary {
 public:
  Boundary(const model::Model& model, const domain::Subdomain& sd);

  // The control volumes' volumes and pressures at sd.x and time t (collective; nothing
  // without bags). Before pressureForces.
  void updateAirbags(double t, const domain::Subdomain& sd, const comm::Communicator& comm) {
    if (!airbags_.empty()) airbags_.update(t, sd, comm);
  }
  // The bags' mass weighted damping (MWD) into sd.f_ext, after externalForces (collective).
  void addAirbagDamping(domain::Subdomain& sd, const comm::Communicator& comm) const {
    if (!airbags_.empty()) airbags_.addDampingForces(sd, comm);
  }
  const Airbags& airbags() const { return airbags_; }

  // The phase the loads' and motions' curves are evaluated in (model::loadFactor): dynamic
  // relaxation or the transient analysis.
  void setPhase(model::Phase phase) {
    phase_ = phase;
    airbags_.setPhase(phase);
  }

  // Follower pressure of the segments this rank computes, into their corner slots (they are
  // exchanged and gathered like element forces, so every rank sums them in the same order).
  void pressureForces(double t, domain::Subdomain& sd) const;

  // f_ext at time t: nodal loads and gravity, plus the gathered pressure already in f_ext.
  void externalForces(double t, const domain::Subdomain& sd, domain::NodeVector& f_ext) const;

  // Enforces SPCs and prescribed motion on v(n+1/2) = sd.v, given v(n-1/2) in v_old;
  // t is t(n), dt_n the step centred on t(n), dt_half = dt(n+1/2). Returns the reaction work
  // of the nodes this rank owns, in its halves (step_work.hpp).
  // Keeps the reactions of the SPCs and prescribed motions (spcReactions, motionReactions).
  StepWork applyKinematics(double t, double dt_n, double dt_half, domain::Subdomain& sd,
                           const domain::NodeVector& v_old);

  // Stonewalls: no slave node ends the step behind a wall (DYNA3D stonewall: the normal
  // velocity is corrected so the node lands on the plane; Coulomb friction acts on the
  // tangential velocity with the normal impulse as its bound). Returns the energy absorbed at
  // the nodes this rank owns, in the halves of step_work.hpp. Wall force totals are summed over all
  // ranks in ascending global node order, so a moving wall moves identically for any number of
  // ranks.
  StepWork applyRigidWalls(double dt_n, double dt_half, domain::Subdomain& sd,
                           const domain::NodeVector& v_old, const comm::Communicator& comm);

  const std::vector<WallState>& walls() const { return walls_; }
  // The reactions of the last step at this rank's constrained nodes (every local node that has
  // one, owned or not), one entry per node in the order the deck's constraints first name them.
  const std::vector<NodeReaction>& spcReactions() const { return spc_reaction_; }
  const std::vector<NodeReaction>& motionReactions() const { return motion_reaction_; }
  // Restart: the walls' motion and last forces (the same on every rank), and the work of the
  // prescribed motions: (global node id, work) pairs of every rank's owned nodes, gathered by
  // the caller from ownedMotionWork; loadState takes this rank's nodes from them.
  std::vector<double> ownedMotionWork(const domain::Subdomain& sd) const;
  void saveState(util::ArchiveWriter& out, const std::vector<double>& motion_work) const;
  void loadState(util::ArchiveReader& in, const domain::Subdomain& sd);
  // Kinetic energy of moving walls (part of the system's kinetic energy).
  double wallKineticEnergy() const;
  // Whether any external force (nodal, pressure, gravity) exists anywhere in the model; the
  // same on every rank, so collective sums that depend on it stay matched.
  bool hasExternalForces() const { return has_external_; }

 private:
  struct Motion {
    int32_t node;
    int dof;
    model::MotionKind kind;
    const model::Curve* curve;
    double sf, birth, death;
  };
  struct NodalLoad {
    int32_t node;
    int dof;
    const model::Curve* curve;
    double sf;
  };
  struct Pressure {
    std::array<int32_t, 4> nodes;  // local nodes
    const model::Curve* curve;
    double sf, at;
    std::size_t first_slot;
    int32_t airbag;                   // model::kNone: a *LOAD_SEGMENT
    const model::BlastCharge* blast;  // *LOAD_BLAST_SEGMENT_SET, else nullptr
  };
  struct Body {
    int dof;
    const model::Curve* curve;
    double sf;
    const model::Curve* dr_curve;  // LCIDDR
  };
  // The wall's resultant and normal force from its nodes' (fx, fy, fz, fn) on every rank,
  // added in node id order (the same bits at any rank count).
  static void sumWallForce(WallState& w, const std::vector<int64_t>& ids,
                           const std::vector<double>& forces, const comm::Communicator& comm,
                           bool plane);

  std::vector<std::pair<int32_t, model::DofMask>> spc_;
  std::vector<std::pair<int32_t, model::DofMask>> spc_rot_;  // rotational SPC (bits: rx, ry, rz)
  std::vector<Motion> motion_;
  // For each spc_ entry, per translational freedom, the motion_ prescribing the same node and
  // freedom (-1: none): while that motion is active it holds the freedom, not the SPC.
  std::vector<std::array<int32_t, 3>> spc_motion_;
  // Reactions per constrained node; spc_at_ / motion_at_ give each constraint's entry.
  std::vector<NodeReaction> spc_reaction_, motion_reaction_;
  std::vector<std::size_t> spc_at_, spc_rot_at_, motion_at_;
  std::vector<NodalLoad> loads_;
  std::vector<Pressure> pressure_;
  std::vector<Body> body_;
  std::vector<WallState> walls_;
  Airbags airbags_;
  bool has_external_ = false;
  model::Phase phase_ = model::Phase::Transient;
};

}  // namespace crumple::constraints
