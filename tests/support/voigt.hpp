// Test helpers for tensors in Voigt order (xx, yy, zz, xy, yz, zx; tensor shear components):
// rotations, Q t Q^T, a norm and the largest component difference.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "materials/principal.hpp"

namespace crumple::testing {

using materials::Voigt;
using Axes = std::array<std::array<double, 3>, 3>;

// R = exp(angle [n]x) for a unit axis n (Rodrigues), as rows.
inline Axes rotation(std::array<double, 3> n, double angle) {
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& v : n) v /= len;
  const double c = std::cos(angle), s = std::sin(angle);
  Axes r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = (1 - c) * n[i] * n[j] + (i == j ? c : 0.0);
  r[0][1] -= s * n[2];
  r[1][0] += s * n[2];
  r[0][2] += s * n[1];
  r[2][0] -= s * n[1];
  r[1][2] -= s * n[0];
  r[2][1] += s * n[0];
  return r;
}

// Q t Q^T in Voigt order.
inline Voigt rotated(const Axes& q, const Voigt& t) {
  const double a[3][3] = {{t[0], t[3], t[5]}, {t[3], t[1], t[4]}, {t[5], t[4], t[2]}};
  double b[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) b[i][j] += q[i][k] * a[k][l] * q[j][l];
  return {b[0][0], b[1][1], b[2][2], b[0][1], b[1][2], b[2][0]};
}

// The Frobenius norm.
inline double norm(const Voigt& t) {
  double n = 0;
  for (int k = 0; k < 6; ++k) n += (k < 3 ? 1.0 : 2.0) * t[k] * t[k];
  return std::sqrt(n);
}

inline double maxDiff(const Voigt& a, const Voigt& b) {
  double d = 0;
  for (int k = 0; k < 6; ++k) d = std::max(d, std::abs(a[k] - b[k]));
  return d;
}

}  // namespace crumple::testing
