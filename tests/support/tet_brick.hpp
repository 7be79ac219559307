// The brick model of brick_model.hpp with each hexahedron cut into Kuhn's six tetrahedra, for
// the unit tests of the tetrahedra (ELFORM 10 and 13).
#pragma once

#include "brick_model.hpp"

namespace crumple::testing {

// Kuhn's six tetrahedra of a hexahedron (tools/deckgen.py KUHN_TETS), 0-based corners.
inline constexpr int kKuhn[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                    {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};

// The brick with each hexahedron cut into six tetrahedra under *SECTION_SOLID ELFORM `elform`.
inline model::Model tetBrick(int nx, int ny, int nz, const BrickOptions& opt = {},
                             int elform = 10) {
  auto m = brickModel(nx, ny, nz, opt);
  model::Solids tets;
  for (std::size_t e = 0; e < m.solids.size(); ++e)
    for (const auto& t : kKuhn) {
      tets.id.push_back(int64_t(tets.id.size()) + 1);
      tets.part.push_back(0);
      const auto& h = m.solids.nodes[e];
      const int32_t d = h[std::size_t(t[3])];
      tets.nodes.push_back(
          {h[std::size_t(t[0])], h[std::size_t(t[1])], h[std::size_t(t[2])], d, d, d, d, d});
    }
  m.solids = tets;
  m.solid_sections[0].elform = elform;
  m.finalize();
  return m;
}

}  // namespace crumple::testing
