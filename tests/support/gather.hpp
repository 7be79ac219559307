// Nodal sums of a subdomain's slots (forces, or masses at initialisation) through its gather
// plan, in the plan's order: what the solver's gather gives, for unit tests.
#pragma once

#include <cstdint>
#include <vector>

#include "domain/subdomain.hpp"

namespace crumple::testing {

inline std::vector<double> gatheredForces(const domain::Subdomain& sd) {
  std::vector<double> f(3 * sd.numNodes(), 0.0);
  for (std::size_t n = 0; n < sd.numNodes(); ++n)
    for (int32_t k = sd.internal.ptr[n]; k < sd.internal.ptr[n + 1]; ++k)
      for (std::size_t c = 0; c < 3; ++c)
        f[3 * n + c] += sd.slots[3 * std::size_t(sd.internal.slot[std::size_t(k)]) + c];
  return f;
}

}  // namespace crumple::testing
