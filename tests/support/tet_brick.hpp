// The brick model of brick_model.hpp with each hexahedron cut into Kuhn's six tetrahedra, for
// the unit tests of the tetrahedra (ELFORM 10 and 13), and the same with a mid-side node on
// every edge for the 10-node tetrahedra (ELFORM 16).
#pragma once

#include <map>
#include <utility>

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

// The edges of a 10-node tetrahedron (corner pairs, 0-based) whose mid-side nodes are N5..N10.
inline constexpr int kTet10Edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

// tetBrick with a mid-side node on every edge (shared by the tetrahedra around it), under
// *SECTION_SOLID ELFORM 16. The mid-side nodes get ids after the corners', in order of first
// use, at the edge midpoints moved by `bow(midpoint)` (curved edges; default none).
inline model::Model tet10Brick(int nx, int ny, int nz, const BrickOptions& opt = {},
                               const std::function<model::Vec3(const model::Vec3&)>& bow = {}) {
  auto m = tetBrick(nx, ny, nz, opt, 16);
  std::map<std::pair<int32_t, int32_t>, int32_t> mid_of;
  m.solids.mid.resize(m.solids.size());
  for (std::size_t e = 0; e < m.solids.size(); ++e)
    for (int k = 0; k < 6; ++k) {
      const int32_t a = m.solids.nodes[e][std::size_t(kTet10Edges[k][0])];
      const int32_t b = m.solids.nodes[e][std::size_t(kTet10Edges[k][1])];
      const auto key = std::minmax(a, b);
      auto it = mid_of.find(key);
      if (it == mid_of.end()) {
        const auto& xa = m.nodes.x[std::size_t(a)];
        const auto& xb = m.nodes.x[std::size_t(b)];
        model::Vec3 x{(xa[0] + xb[0]) / 2, (xa[1] + xb[1]) / 2, (xa[2] + xb[2]) / 2};
        if (bow) {
          const auto d = bow(x);
          for (int c = 0; c < 3; ++c) x[std::size_t(c)] += d[std::size_t(c)];
        }
        it = mid_of.emplace(key, int32_t(m.nodes.size())).first;
        m.nodes.id.push_back(int64_t(m.nodes.size()) + 1);
        m.nodes.x.push_back(x);
      }
      m.solids.mid[e][std::size_t(k)] = it->second;
    }
  m.initial_velocity.assign(m.nodes.size(), {0, 0, 0});
  m.finalize();
  return m;
}

}  // namespace crumple::testing
