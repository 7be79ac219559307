// A model built in code, for unit tests and benchmarks: an nx x ny x nz brick of 8-node hexes
// (one part, one material), node (i, j, k) with id 1 + i + (nx+1)(j + (ny+1) k).
#pragma once

#include <functional>

#include "model/model.hpp"

namespace crumple::testing {

struct BrickOptions {
  model::MaterialLaw law = materials::Elastic::Params{210.0, 0.3};  // steel in mm, ms, kg, GPa
  double rho = 7.85e-6;
  int ihq = 1;  // *CONTROL_HOURGLASS
  double qh = 0.1;
  // Node position from its grid indices; default: the unit grid.
  std::function<model::Vec3(int, int, int)> position;
};

inline model::Model brickModel(int nx, int ny, int nz, const BrickOptions& opt = {}) {
  model::Model m;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        m.nodes.id.push_back(1 + int64_t(i) + int64_t(nx + 1) * (j + int64_t(ny + 1) * k));
        m.nodes.x.push_back(opt.position ? opt.position(i, j, k)
                                         : model::Vec3{double(i), double(j), double(k)});
      }
  auto id = [&](int i, int j, int k) { return int32_t(i + (nx + 1) * (j + (ny + 1) * k)); };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        m.solids.id.push_back(int64_t(m.solids.id.size()) + 1);
        m.solids.part.push_back(0);
        m.solids.nodes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
                                  id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1),
                                  id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
      }
  model::Material mat;
  mat.id = 1;
  mat.rho = opt.rho;
  mat.law = opt.law;
  m.materials.push_back(mat);
  m.solid_sections.push_back({1, 1, {}});
  model::Part p;
  p.id = 1;
  p.section = 0;
  p.material = 0;
  m.parts.push_back(p);
  m.controls.hourglass_ihq = opt.ihq;
  m.controls.hourglass_qh = opt.qh;
  m.initial_velocity.assign(m.nodes.size(), {0, 0, 0});
  m.finalize();
  return m;
}

}  // namespace crumple::testing
