// Mass-weighted damping (*DAMPING_GLOBAL, *DAMPING_PART_MASS): the nodal force
//   f_d = -D(t) m v(n-1/2)  on the translations,  m_d = -D(t) I omega(n-1/2)  on the rotations,
// each component scaled by the keyword's STX..SRZ (LS-DYNA Theory Manual, "Damping": mass
// weighted damping D_s m v; a mode of circular frequency omega then has the fraction of
// critical damping xi = D / (2 omega)). The force joins the external forces of step n (so
// rigid bodies receive it too) and its work is booked as damping energy, not external work.
#pragma once

#include <vector>

#include "constraints/step_work.hpp"
#include "domain/subdomain.hpp"
#include "model/model.hpp"

namespace crumple::solver {

class NodalDamping {
 public:
  NodalDamping() = default;
  NodalDamping(const model::Model& model, const domain::Subdomain& sd);
  bool empty() const { return sources_.empty(); }

  // Adds f_d to sd.f_ext and m_d to sd.moment at time t from v = v(n-1/2), omega(n-1/2).
  void addForces(const model::Model& model, double t, domain::Subdomain& sd);
  // The work of f_d and m_d over dt_n at the nodes this rank owns, in halves (step_work.hpp):
  // translations and rotations; the translational part is what the external work counted.
  struct Work {
    constraints::StepWork translation, rotation;
  };
  Work work(const domain::Subdomain& sd, double dt_n, const domain::NodeVector& v_old,
            const domain::NodeVector& w_old) const;

 private:
  struct Source {
    int32_t curve = model::kNone;
    double value = 0.0;
    std::array<double, 6> scale{};
    std::vector<int32_t> nodes;  // local nodes
    std::vector<double> weight;
  };
  std::vector<Source> sources_;
  std::vector<double> coef_;           // D per local node and component (6 per node)
  domain::NodeVector force_, moment_;  // f_d and m_d of the last addForces
};

}  // namespace crumple::solver
