#include "solver/damping.hpp"

#include <algorithm>

namespace crumple::solver {

NodalDamping::NodalDamping(const model::Model& model, const domain::Subdomain& sd) {
  const std::size_t nn = sd.numNodes();
  for (const auto& d : model.mass_damping) {
    Source s{d.curve, d.value, d.scale, {}, {}};
    for (std::size_t n = 0; n < nn; ++n) {
      if (d.global) {
        s.nodes.push_back(static_cast<int32_t>(n));
        s.weight.push_back(1.0);
        continue;
      }
      // d.nodes is ascending in model node index.
      const auto it = std::lower_bound(d.nodes.begin(), d.nodes.end(), sd.node_model[n]);
      if (it == d.nodes.end() || *it != sd.node_model[n]) continue;
      s.nodes.push_back(static_cast<int32_t>(n));
      s.weight.push_back(d.weight[static_cast<std::size_t>(it - d.nodes.begin())]);
    }
    if (!s.nodes.empty()) sources_.push_back(std::move(s));
  }
  coef_.assign(6 * nn, 0.0);
  force_.assign(3 * nn, 0.0);
  moment_.assign(3 * nn, 0.0);
}

void NodalDamping::addForces(const model::Model& model, double t, domain::Subdomain& sd) {
  std::fill(coef_.begin(), coef_.end(), 0.0);
  for (const auto& s : sources_) {
    const double D =
        s.value *
        (s.curve == model::kNone ? 1.0 : model.curves[static_cast<std::size_t>(s.curve)].value(t));
    for (std::size_t k = 0; k < s.nodes.size(); ++k)
      for (std::size_t c = 0; c < 6; ++c)
        coef_[6 * static_cast<std::size_t>(s.nodes[k]) + c] += D * s.weight[k] * s.scale[c];
  }
  const std::size_t nn = sd.numNodes();
  const bool rotations = sd.rotations;
  for (std::size_t n = 0; n < nn; ++n)
    for (std::size_t c = 0; c < 3; ++c) {
      const std::size_t i = 3 * n + c;
      force_[i] = -coef_[6 * n + c] * sd.mass[n] * sd.v[i];
      sd.f_ext[i] += force_[i];
      moment_[i] = rotations ? -coef_[6 * n + 3 + c] * sd.inertia[n] * sd.w[i] : 0.0;
      if (rotations) sd.moment[i] += moment_[i];
    }
}

NodalDamping::Work NodalDamping::work(const domain::Subdomain& sd, double dt_n,
                                      const domain::NodeVector& v_old,
                                      const domain::NodeVector& w_old) const {
  Work w;
  const bool rotations = sd.rotations && w_old.size() == sd.w.size();
  for (std::size_t n = 0; n < sd.numNodes(); ++n) {
    if (!sd.node_owned[n]) continue;
    for (std::size_t c = 0; c < 3; ++c) {
      const std::size_t i = 3 * n + c;
      w.translation += constraints::impulseWork(force_[i] * dt_n, v_old[i], sd.v[i]);
      if (rotations) w.rotation += constraints::impulseWork(moment_[i] * dt_n, w_old[i], sd.w[i]);
    }
  }
  return w;
}

}  // namespace crumple::solver
