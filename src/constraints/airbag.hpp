// Control volumes of *AIRBAG_SIMPLE_PRESSURE_VOLUME (LS-DYNA Keyword Manual, *AIRBAG; Theory
// Manual, "Airbags": a uniform pressure inside a closed surface, from the volume the surface
// encloses). Each cycle, at x(n):
//   V = sum over the bag's segments of (1/3) x_mean . A   (divergence theorem, exact for flat
//       and bilinear segments: the flux of x / 3 through the patch; A = (x3 - x1) x (x4 - x2)/2)
//   p = PSCA * BETA * CN(t) / (V / V0)   or   p = PSCA * LCID(V / V0)
// and the pressure acts on the segments as consistent nodal forces
//   F_i = p s integral(N_i n dA) = p s [A / 4 + (xi_i b x d + eta_i d x c) / 3]
// (bilinear patch x = a + b xi + c eta + d xi eta; a flat triangle takes A / 3 per corner),
// which is p dV/dx_i: the gas does the work integral(p dV), booked as external work. s = +1 when
// the segments' right-hand normals point out of the bag (V0 > 0), -1 when all point in.
// V sums per-segment contributions in ascending segment order over every rank, so the bits do
// not depend on the number of ranks or threads.
#pragma once

#include <array>
#include <vector>

#include "comm/communicator.hpp"
#include "domain/subdomain.hpp"
#include "model/model.hpp"

namespace crumple::constraints {

// (1/3) x_mean . A of the segment x1..x4 (x3 == x4: a triangle): its share of the volume
// enclosed by a closed surface.
double segmentVolume(const std::array<const double*, 4>& x);
// The consistent nodal forces integral(N_i q n dA) of the pressure q on the segment (n its
// right-hand normal), 3 per corner; a triangle's fourth corner gets none.
void segmentPressureForces(const std::array<const double*, 4>& x, double q, double out[12]);

class Airbags {
 public:
  Airbags() = default;
  Airbags(const model::Model& model, const domain::Subdomain& sd);
  bool empty() const { return bags_.empty(); }

  // The volumes at sd.x (and, the first time, the initial volumes at sd.x0) and the pressures
  // at time t. Collective: every rank calls it when the model has bags.
  void update(double t, const domain::Subdomain& sd, const comm::Communicator& comm);
  // The force factor q of the bag's segments: s p (see above).
  double segmentPressure(int32_t bag) const { return bags_[std::size_t(bag)].q; }
  double volume(int32_t bag) const { return bags_[std::size_t(bag)].volume; }
  double pressure(int32_t bag) const { return bags_[std::size_t(bag)].pressure; }
  std::size_t size() const { return bags_.size(); }
  // Dynamic relaxation: CN from LCIDDR when the bag has one, else as model::loadFactor says.
  void setPhase(model::Phase phase) { phase_ = phase; }

  // MWD: -D m (v - v_bag) at every local node of the bags that damp, from v(n-1/2), added to
  // f_ext (so its negative work is in the external work). Collective.
  void addDampingForces(domain::Subdomain& sd, const comm::Communicator& comm) const;

 private:
  struct Bag {
    const model::Airbag* def = nullptr;
    const model::Curve *cn_curve = nullptr, *pv_curve = nullptr, *cn_dr_curve = nullptr;
    double initial = 0.0, volume = 0.0, pressure = 0.0, q = 0.0, sign = 1.0;
    std::vector<int32_t> nodes;  // local nodes of the bag's segments, ascending
  };
  // Global segment index and volume share of every bag segment this rank computes.
  struct Share {
    int64_t segment;
    double volume;
  };
  // Every bag's volume at the coordinates x (collective).
  std::vector<double> volumes(const domain::NodeVector& x, const comm::Communicator& comm) const;

  const model::Model* model_ = nullptr;
  std::vector<Bag> bags_;
  // The bag segments this rank computes: model index into pressure_loads, local corner nodes.
  struct Segment {
    int32_t index;
    std::array<int32_t, 4> nodes;
  };
  std::vector<Segment> segments_;
  bool initialised_ = false;
  model::Phase phase_ = model::Phase::Transient;
};

}  // namespace crumple::constraints
