// Loads, kinematic constraints and rigid walls of one subdomain, in local node numbering.
// External forces enter before accelerations are formed; kinematic conditions act on the
// predicted velocities v(n+1/2) (DYNA3D cycle, ARCHITECTURE.md steps 3-5).
#pragma once

#include <vector>

#include "domain/subdomain.hpp"
#include "model/model.hpp"

namespace crumple::constraints {

struct WallState {
  const model::RigidWallPlanar* def = nullptr;
  std::vector<int32_t> nodes;  // local slave nodes
  double displacement = 0.0;   // along the normal (moving walls)
  double velocity = 0.0;       // along the normal (moving walls)
  model::Vec3 force{};         // force of the wall on the structure in the last cycle
  double normal_force = 0.0;   // its component along the wall normal
};

struct KinematicWork {
  double reaction = 0.0;  // work of SPC / prescribed-motion reactions (enters external work)
  double wall = 0.0;      // energy absorbed at rigid walls (stonewall energy)
};

class Boundary {
 public:
  Boundary(const model::Model& model, const domain::Subdomain& sd);

  // f_ext at time t on the current configuration: nodal loads, follower pressure, gravity.
  void externalForces(double t, const domain::Subdomain& sd, domain::NodeVector& f_ext) const;

  // Enforces SPCs and prescribed motion on v(n+1/2) = sd.v, given v(n-1/2) in v_old;
  // t is t(n), dt_n the step centred on t(n), dt_half = dt(n+1/2). Returns reaction work.
  double applyKinematics(double t, double dt_n, double dt_half, domain::Subdomain& sd,
                         const domain::NodeVector& v_old) const;

  // Stonewalls: no slave node ends the step behind a wall (DYNA3D stonewall: the normal
  // velocity is corrected so the node lands on the plane; Coulomb friction acts on the
  // tangential velocity with the normal impulse as its bound). Returns absorbed energy.
  double applyRigidWalls(double dt_n, double dt_half, domain::Subdomain& sd,
                         const domain::NodeVector& v_old);

  const std::vector<WallState>& walls() const { return walls_; }
  // Kinetic energy of moving walls (part of the system's kinetic energy).
  double wallKineticEnergy() const;
  bool hasBodyLoads() const { return !body_.empty(); }

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
    std::array<int32_t, 4> nodes;
    const model::Curve* curve;
    double sf, at;
  };
  struct Body {
    int dof;
    const model::Curve* curve;
    double sf;
  };
  std::vector<std::pair<int32_t, model::DofMask>> spc_;
  std::vector<Motion> motion_;
  std::vector<NodalLoad> loads_;
  std::vector<Pressure> pressure_;
  std::vector<Body> body_;
  std::vector<WallState> walls_;
};

}  // namespace crumple::constraints
