// Rigid bodies, spot welds and tied node sets at run time (the Model side is
// src/model/rigid.hpp).
//
// A body (a *MAT_RIGID part with its merged parts and extra nodes, a nodal rigid body, or a
// spot weld until it fails) has a mass, a centre x_cm, a velocity V, an angular momentum L
// about x_cm (global axes) and an orientation q of its principal axes. Each cycle, after the
// nodal velocity update v(n+1/2) = v(n-1/2) + dt a(n) and before SPCs and prescribed nodal
// motion, apply():
//   1. sums the force F and the moment M about x_cm(n) of its nodes (f + f_ext, and nodal
//      moments when the model has rotations);
//   2. kicks V += dt F / m, L += dt M (LS-DYNA Theory Manual, "Rigid Body Dynamics"), imposes
//      CMO constraints and *BOUNDARY_PRESCRIBED_MOTION_RIGID on V and on the angular velocity;
//   3. drifts x_cm += dt V and turns q by the free rotation at fixed L, with the symmetric
//      splitting of Dullweber, Leimkuhler and McLachlan (J. Chem. Phys. 107, 5840, 1997):
//      exact rotations about the principal axes 1, 2, 3, 2, 1 with half, half, full, half,
//      half steps. It is symplectic and time-reversible, L is unchanged by the drift, so a
//      torque-free body keeps L to the last bit and its energy without drift; q stays a unit
//      quaternion. A body with rotations constrained or prescribed turns instead by the exact
//      exponential map of its (constrained) angular velocity, exp(dt omega) q;
//   4. gives each node the velocity that carries it from its place on the body at t(n) to
//      its place at t(n+1): v = V + (R(q(n+1)) - R(q(n))) X / dt, X its body coordinates, so
//      that the solver's x += dt v moves the nodes rigidly (the secant of the rotation: with
//      omega x r instead a spinning body would grow by dt^2 |omega|^2 / 2 a step); w = the
//      body's angular velocity (models with rotations).
// Spot welds check the force they exert on each node after step 2 (from m (v_rigid - v)/dt)
// and let go when the criterion is met; tied node sets share the mass-weighted mean
// velocity in their directions. Joints are penalty springs between node pairs, applied as
// external forces before all this (addJointForces).
//
// Determinism: every sum over the nodes of a body runs in ascending model node order over all
// ranks. Each rank contributes the nodes it owns, as (body, model node, values) records that
// comm.allGather collects on every rank; the records are sorted by (body, node) and summed in
// that order. Every rank then holds the same body states, bit for bit, for any number of ranks
// and threads; a node held by several ranks gets the same velocity on each.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "comm/communicator.hpp"
#include "constraints/step_work.hpp"
#include "domain/subdomain.hpp"
#include "model/model.hpp"
#include "util/archive.hpp"

namespace crumple::constraints {

using Vec3 = std::array<double, 3>;

// One body's state for output (rbdout) and tests, at the end of the last step.
struct RigidBodyState {
  int64_t id = 0;  // master part id, nodal rigid body id, or weld id
  enum class Kind : uint8_t { Part, Nodal, Weld } kind = Kind::Part;
  double mass = 0.0;
  Vec3 cm{};                // centre of mass at t(n+1)
  Vec3 velocity{};          // V(n+1/2)
  Vec3 angular_velocity{};  // rotation of the last step / dt, global axes
  Vec3 angular_momentum{};  // about the centre, global axes, at (n+1/2)
  // Force and moment of the constraints (CMO, prescribed motion) on the body in the last step.
  Vec3 reaction_force{}, reaction_moment{};
  // rbdout: the centre's displacement from t = 0, the rotation accumulated about the global
  // axes, and the accelerations of the last step, (V(n+1/2) - V(n-1/2)) / dt(n) and the same of
  // the angular velocity.
  Vec3 displacement{}, rotation{}, acceleration{}, angular_acceleration{};
  std::array<Vec3, 3> axes{};  // the principal axes at t(n+1), in global components
};

// One joint's resultants for jntforc, from the last addJointForces: the force the joint's
// springs exert on body B (the N2 side), their moment about N2, and the energy of the joint
// (stored in its springs plus what its dampers dissipated).
struct JointState {
  int64_t id = 0;
  Vec3 force{}, moment{};
  double energy = 0.0;
};

struct WeldState {
  int64_t id = 0;
  bool failed = false;
  double failure_time = 0.0;
  // Force of the weld on its most loaded node in the last step it held: normal (tension
  // positive) and shear magnitude.
  double normal_force = 0.0, shear_force = 0.0;
};

class RigidBodies {
 public:
  // Collective (every rank, after the nodal masses are assembled and sd.v holds the initial
  // velocities): mass, centre, inertia tensor and initial motion of every body.
  RigidBodies(const model::Model& model, const domain::Subdomain& sd,
              const comm::Communicator& comm);

  bool empty() const {
    return bodies_.empty() && sets_.empty() && joints_.empty() && loads_.empty() &&
           stiffness_.empty();
  }

  // The bodies' initial velocity fields on their nodes (v, and w with rotations).
  void setInitialVelocities(domain::Subdomain& sd) const;

  // Collective, once per cycle, right after v(n+1/2) = v(n-1/2) + dt_n a: moves the bodies,
  // welds and tied sets and writes their nodes' v, a (and w). t = t(n), dt_n the step centred
  // on t(n), dt_half = dt(n+1/2); v_old = v(n-1/2). Returns the work of the body constraints
  // (CMO, prescribed rigid motion) and body loads on rank 0, in its halves (step_work.hpp),
  // and 0 elsewhere, so a sum over ranks counts it once.
  StepWork apply(double t, double dt_n, double dt_half, domain::Subdomain& sd,
                 const domain::NodeVector& v_old, const comm::Communicator& comm);

  // Collective, once per cycle, after the external forces and before the velocity update:
  // the penalty forces of the joints (*CONSTRAINED_JOINT_SPHERICAL / _REVOLUTE) from x(n) and
  // v(n-1/2), added to f_ext of every copy of their nodes. dt = dt(n+1/2); the first call's
  // step fixes the stiffness, k = RPS m / (2 dt^2) with m = m_a m_b / (m_a + m_b) of the two
  // sides (a node's mass, or for a node of a rigid body the body's mass as felt at the node,
  // 1 / (1/m + |r|^2 / I_min)): the joint's own frequency then stays below the step's limit
  // (omega dt <= sqrt(RPS / 2)), as LS-DYNA scales its joint penalty with the masses and the
  // time step (Theory Manual, "Rigid Body Joints"). Damping is 10% of critical, times DAMP.
  // dt_velocity: the step the velocities take with these forces (the damper's work).
  void addJointForces(double dt, double dt_velocity, domain::Subdomain& sd,
                      const comm::Communicator& comm);
  // The joints' forces on this rank's copies of their nodes in the last addJointForces, as
  // (local node, force): they sit in f_ext, and the solver takes their work back out of the
  // external work (their energy is internal, jointEnergy()).
  const std::vector<std::pair<int32_t, Vec3>>& jointNodeForces() const { return joint_nodal_; }
  // Energy stored in the joint springs plus what their dampers dissipated, and the work of
  // the joint stiffnesses (every rank).
  double jointEnergy() const { return joint_energy_ + stiffness_work_; }

  // Once per cycle, after addJointForces (no communication: the bodies' states are the same
  // on every rank): the *LOAD_RIGID_BODY forces and moments at time t(n), and the moments of
  // the *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED friction springs from the bodies'
  // orientations at t(n). apply() adds them to the bodies' force and moment sums.
  void computeBodyLoads(double t);
  // The phase their loads' and prescribed motions' curves are evaluated in (model::loadFactor).
  void setPhase(model::Phase phase) { phase_ = phase; }
  // Dynamic relaxation: every body's velocities scaled by DRFCTR each cycle, and back to the
  // initial motion when the phase ends (then setInitialVelocities carries it to the nodes).
  void scaleVelocities(double factor);
  void restoreInitialVelocities();
  std::vector<JointState> joints() const;

  // Kinetic energy of the bodies at t(n) (translation and rotation, from the mean of the
  // half-step momenta, like the solver's nodal sum); the same on every rank. The solver
  // reports this for the nodes where countsNode() is true instead of their nodal energy.
  double kineticEnergy() const;
  bool countsNode(std::size_t local_node) const {
    return !in_body_.empty() && in_body_[local_node] != 0;
  }

  // Restart: the bodies' motion, weld failures and joint state (the same on every rank, so
  // rank 0's copy is written); loadState after construction, on every rank.
  void saveState(util::ArchiveWriter& out) const;
  void loadState(util::ArchiveReader& in);

  std::vector<RigidBodyState> states() const;  // bodies, then welds, in model order
  std::vector<WeldState> welds() const;

 private:
  model::Phase phase_ = model::Phase::Transient;
  using Quat = std::array<double, 4>;  // unit quaternion w, x, y, z
  struct Motion {
    int dof;
    model::MotionKind kind;
    const model::Curve* curve;
    double sf, birth, death;
  };
  struct Body {
    int64_t id = 0;
    RigidBodyState::Kind kind = RigidBodyState::Kind::Part;
    double mass = 0.0;
    Vec3 inertia{};                          // principal moments
    Quat q{1, 0, 0, 0}, q_prev{1, 0, 0, 0};  // principal axes -> global, t(n+1) and t(n)
    Vec3 x_cm{}, x_cm_prev{}, x_cm0{};
    Vec3 V{}, V_prev{}, L{}, L_prev{}, omega{};
    Vec3 V_init{}, omega_init{};  // the initial motion (restored after dynamic relaxation)
    Vec3 angle{};  // accumulated rotation about the global axes (prescribed rotations)
    Vec3 reaction_f{}, reaction_m{};
    Vec3 acc{}, angular_acc{};  // of the last step (rbdout)
    uint8_t fixed = 0;
    std::vector<Motion> motions;
    std::vector<int32_t> local;  // local nodes of the body held here
    std::vector<Vec3> X;         // their body coordinates
    // Welds: failure data and the body coordinates of every node (all ranks).
    bool weld = false, active = true;
    double sn = 0, ss = 0, n = 2, m = 2, tfail = 0, failure_time = 0;
    double fn = 0, fs = 0;
    std::vector<Vec3> all_X;
  };
  struct TiedSet {
    double mass = 0.0;
    uint8_t dofs = 0;
    double tfail = 0;
    std::vector<int32_t> local;
  };

  int width(int32_t group) const;
  // Construction steps (see the constructor).
  void makeGroups(const model::Model& m, const domain::Subdomain& sd);
  void initBodies(const model::Model& m, const domain::Subdomain& sd,
                  const comm::Communicator& comm);
  void initBody(Body& b, const model::RigidBodyDef* def, const model::Model& m,
                const domain::Subdomain& sd, const std::vector<std::size_t>& rec,
                const std::vector<double>& all);
  void initJoints(const model::Model& m, const domain::Subdomain& sd,
                  const comm::Communicator& comm);
  // The spatial inverse inertia R diag(1/I) R^T of a body at orientation q (0 on degenerate
  // axes: bodies of collinear point masses have no inertia about their line).
  static void inverseInertia(const Body& b, const Quat& q, double a[3][3]);
  // L = J w = R diag(I) R^T w.
  static Vec3 angularMomentum(const Body& b, const Quat& q, const Vec3& w);
  // Calls f on each field of a body's run-time state (restart save and load).
  template <class B, class F>
  static void visitState(B& b, F&& f);
  // Step 2-3 for one body given F and M; returns the constraint work.
  StepWork advance(Body& b, const Vec3& F, const Vec3& M, double t, double dt_n, double dt_half);

  struct JointPair {
    std::array<int32_t, 2> node{};             // model nodes
    std::array<int32_t, 2> local{};            // local copies, or model::kNone
    double rps = 1.0, damp = 1.0, mass = 0.0;  // mass: m_a m_b / (m_a + m_b)
    double k = 0.0, c = 0.0;
    // Cylindrical and translational joints: only the gap across the axis counts, the axis
    // running from the A node of pair `axis` to that of pair `axis` + 1 (N1 -> N3).
    bool across = false;
    std::size_t axis = 0;
    double dissipated = 0.0;
    // The damper's force of the last call and the velocity step it acted over: the second
    // half of its work is booked at the next call, at the relative velocity it produced.
    Vec3 damper{};
    double dt_last = 0.0;
  };

  // *LOAD_RIGID_BODY components and *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED springs.
  struct BodyLoad {
    int32_t body;
    int dof;
    const model::Curve* curve;
    double sf;
  };
  struct Stiffness {
    int32_t a = 0, b = 0;                    // bodies
    std::array<Vec3, 3> axes_a{}, axes_b{};  // local axes in body (principal) coordinates
    Vec3 es{}, fm{};
    Vec3 angle{};   // phi, theta, psi, followed continuously through +-pi
    Vec3 moment{};  // the springs' moments about A's local axes
  };
  void initLoads(const model::Model& m);
  // The three relative angles of B's local frame to A's (phi about A's x, theta about y, psi
  // about z) and A's current axes.
  Vec3 relativeAngles(const Stiffness& s, std::array<Vec3, 3>& axes_a) const;
  // The external work of the body loads over dt_n on body g (velocities before and after).
  StepWork loadWork(std::size_t g, const Vec3& v_prev, const Vec3& w_prev, double dt_n) const;
  void addJointStiffness();

  std::vector<BodyLoad> loads_;
  std::vector<Stiffness> stiffness_;
  std::vector<Vec3> load_f_, load_m_, joint_m_;  // per body, this cycle
  double stiffness_work_ = 0.0;
  std::vector<JointState> joint_states_;  // per joint of the model
  std::vector<int32_t> pair_joint_;       // per entry of joints_: its joint
  std::vector<std::pair<int32_t, Vec3>> joint_nodal_;

  std::vector<Body> bodies_;  // part and nodal bodies, then welds
  std::vector<TiedSet> sets_;
  std::vector<JointPair> joints_;  // every pair of every joint, in model order
  double joint_dissipated_ = 0.0, joint_energy_ = 0.0;
  std::vector<int32_t> group_;    // per local node: body or nb + set index, or -1
  std::vector<uint8_t> in_body_;  // per local node: in an active body (energy counted here)
  bool stepped_ = false;
};

}  // namespace crumple::constraints
