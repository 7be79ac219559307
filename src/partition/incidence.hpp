// Internal to src/partition: node -> element incidence and the distinct nodes of a possibly
// degenerate hexahedron. Shared by the dual graph and the partition statistics.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model/model.hpp"

namespace crumple::partition::detail {

// Distinct force-carrying nodes of global element g (any family), in order of appearance.
inline int elementDistinctNodes(const model::Model& model, std::size_t g,
                                int32_t out[model::kMaxElementNodes]) {
  int32_t n[model::kMaxElementNodes];
  const int count = model.elementNodes(g, n);
  int k = 0;
  for (int a = 0; a < count; ++a) {
    bool seen = false;
    for (int i = 0; i < k; ++i) seen = seen || out[i] == n[a];
    if (!seen) out[k++] = n[a];
  }
  return k;
}

// CSR node -> elements (global numbering) holding it, each element once per node, ascending.
struct Incidence {
  std::vector<int64_t> ptr;   // size num_nodes + 1
  std::vector<int32_t> elem;  // size ptr.back()
};

// Throws std::invalid_argument if an element names a node index outside the model.
Incidence nodeElements(const model::Model& model);

}  // namespace crumple::partition::detail
