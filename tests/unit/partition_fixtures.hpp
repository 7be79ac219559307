// Programmatic meshes for the partitioner tests: structured bricks of hexahedra, of wedges and
// of tetrahedra (both written as degenerate hexes, LS-DYNA style), and their unions.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model/model.hpp"

namespace crumple::test {

enum class Shape { Hex, Wedge, Tet };

// One part, one elastic (or plastic) material; nodes on a unit grid from `origin`.
// Element ids ascend with (i fastest, then j, then k, then the sub-element of a split hex).
inline model::Model brickOf(Shape shape, int nx, int ny, int nz, model::Vec3 origin = {0, 0, 0},
                            bool plastic = false) {
  using namespace crumple::model;
  Model m;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        m.nodes.id.push_back(1 + int64_t(i) + (nx + 1) * (j + int64_t(ny + 1) * k));
        m.nodes.x.push_back({origin[0] + i, origin[1] + j, origin[2] + k});
      }
  auto id = [&](int i, int j, int k) { return int32_t(i + (nx + 1) * (j + (ny + 1) * k)); };
  auto add = [&](std::array<int32_t, 8> n) {
    m.solids.id.push_back(int64_t(m.solids.id.size()) + 1);
    m.solids.part.push_back(0);
    m.solids.nodes.push_back(n);
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const std::array<int32_t, 8> a = {
            id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
            id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        switch (shape) {
          case Shape::Hex:
            add(a);
            break;
          case Shape::Wedge:
            // Two prisms along y, cut by the plane through a0 a3 a5 a6; LS-DYNA pentahedron
            // n1 n2 n3 n4 n5 n5 n6 n6 (triangles n1 n2 n5 and n4 n3 n6).
            add({a[0], a[1], a[2], a[3], a[5], a[5], a[6], a[6]});
            add({a[0], a[4], a[7], a[3], a[5], a[5], a[6], a[6]});
            break;
          case Shape::Tet: {
            // Kuhn's six tetrahedra around the diagonal a0-a6 (conforming between cubes),
            // alternately in the two degenerate-hex conventions n4=..=n8 and n3=n4, n5=..=n8.
            const int ring[7] = {1, 2, 3, 7, 4, 5, 1};
            for (int t = 0; t < 6; ++t) {
              const int32_t p = a[0], q = a[std::size_t(ring[t])], r = a[std::size_t(ring[t + 1])],
                            s = a[6];
              if (t % 2 == 0)
                add({p, q, r, s, s, s, s, s});
              else
                add({p, q, r, r, s, s, s, s});
            }
            break;
          }
        }
      }
  Material mat;
  mat.id = 1;
  mat.rho = 7.85e-6;
  if (plastic)
    mat.law =
        crumple::materials::PlasticKinematic::Params{210.0, 0.3, 0.3, 1.0, 0.0, 0.0, 0.0, 0.0};
  else
    mat.law = crumple::materials::Elastic::Params{210.0, 0.3};
  m.materials.push_back(mat);
  m.solid_sections.push_back({1, 1, {}});
  Part p;
  p.id = 1;
  p.section = 0;
  p.material = 0;
  m.parts.push_back(p);
  m.initial_velocity.assign(m.nodes.size(), {0, 0, 0});
  m.finalize();
  return m;
}

inline model::Model brick(int nx, int ny, int nz) {
  return brickOf(Shape::Hex, nx, ny, nz);
}

// `b` appended to `a` as a second part (and material) with renumbered ids; no shared nodes.
inline model::Model merged(model::Model a, const model::Model& b) {
  const auto node_base = int32_t(a.nodes.size());
  const int64_t node_id_base = a.nodes.id.empty() ? 0 : a.nodes.id.back();
  const int64_t elem_id_base = a.solids.id.empty() ? 0 : a.solids.id.back();
  const auto part_base = int32_t(a.parts.size());
  const auto mat_base = int32_t(a.materials.size());
  for (std::size_t n = 0; n < b.nodes.size(); ++n) {
    a.nodes.id.push_back(node_id_base + b.nodes.id[n]);
    a.nodes.x.push_back(b.nodes.x[n]);
  }
  for (std::size_t e = 0; e < b.solids.size(); ++e) {
    a.solids.id.push_back(elem_id_base + b.solids.id[e]);
    a.solids.part.push_back(part_base + b.solids.part[e]);
    auto n = b.solids.nodes[e];
    for (auto& v : n) v += node_base;
    a.solids.nodes.push_back(n);
  }
  for (auto mat : b.materials) {
    mat.id += mat_base;
    a.materials.push_back(mat);
  }
  for (auto p : b.parts) {
    p.id += part_base;
    p.material += mat_base;
    a.parts.push_back(p);
  }
  a.initial_velocity.assign(a.nodes.size(), {0, 0, 0});
  a.finalize();
  return a;
}

}  // namespace crumple::test
