// The patch test of the solid elements (tests/unit/test_tet4.cpp, test_penta6.cpp): a mesh whose
// interior nodes are moved off the unit grid, a linear velocity field over one step, and the
// stress it must give exactly.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "domain/subdomain.hpp"
#include "model/model.hpp"

namespace crumple::testing {

// Node (i, j, k) of a grid with the nodes on the planes i, j or k = 1 moved off it, so that
// every element of a 2 x 2 x 2 brick is distorted.
inline model::Vec3 distortedPatchNode(int i, int j, int k) {
  const bool inner = i == 1 || j == 1 || k == 1;
  const double s = inner ? 0.13 : 0.0;
  return model::Vec3{i + s * std::sin(3.0 * j + k), j + s * std::cos(2.0 * i + k), k + s * 0.7};
}

// The patch-test field: linear velocity v = G x (stretch, shear and spin), over a step dt.
inline constexpr double kPatchG[3][3] = {
    {1e-3, 4e-4, -2e-4}, {-1e-4, -3e-4, 5e-4}, {3e-4, 2e-4, 6e-4}};

// v = G x0 at every node and the geometry x = x0 + dt/2 v of the cycle that follows.
inline void setPatchVelocity(domain::Subdomain& sd, double dt) {
  for (std::size_t n = 0; n < sd.numNodes(); ++n)
    for (int i = 0; i < 3; ++i) {
      double v = 0.0;
      for (int j = 0; j < 3; ++j) v += kPatchG[i][j] * sd.x0[3 * n + std::size_t(j)];
      sd.v[3 * n + std::size_t(i)] = v;
    }
  for (std::size_t i = 0; i < sd.x.size(); ++i) sd.x[i] = sd.x0[i] + 0.5 * dt * sd.v[i];
}

// The stress of isotropic elasticity after that step from zero stress: lambda tr(D dt) I +
// 2 mu D dt (no Jaumann term from zero stress), Voigt order xx yy zz xy yz zx.
inline std::array<double, 6> patchStress(double E, double nu, double dt) {
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const auto& G = kPatchG;
  const double tr = (G[0][0] + G[1][1] + G[2][2]) * dt;
  return {lambda * tr + 2 * mu * G[0][0] * dt, lambda * tr + 2 * mu * G[1][1] * dt,
          lambda * tr + 2 * mu * G[2][2] * dt, mu * (G[0][1] + G[1][0]) * dt,
          mu * (G[1][2] + G[2][1]) * dt,       mu * (G[2][0] + G[0][2]) * dt};
}

}  // namespace crumple::testing
