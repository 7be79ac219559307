#include "materials/principal.hpp"

#include <algorithm>
#include <cmath>

namespace crumple::materials {

namespace {

using Matrix = std::array<std::array<double, 3>, 3>;

// Sweeps far beyond what convergence needs (3 x 3 converges to round-off in about five); the
// cap only guarantees termination for non-finite input.
constexpr int kMaxSweeps = 32;

// The rotation J = [[c, s], [-s, c]] in the (p, q) plane that makes (J^T A J)_pq zero, applied
// to A (symmetric, both triangles kept) and accumulated into V <- V J (Golub and Van Loan,
// sec. 8.5, the 2 x 2 symmetric Schur decomposition). t = tan(theta) is the smaller root of
// t^2 + 2 tau t - 1 = 0, so |theta| <= pi/4: the rotation stays near the identity and the
// updates stay stable.
void rotate(Matrix& a, Matrix& v, int p, int q) {
  const double apq = a[p][q];
  if (apq == 0.0) return;
  const double tau = (a[q][q] - a[p][p]) / (2.0 * apq);
  // For |tau| beyond 1e150, tau^2 would overflow; there t = 1 / (2 tau) to working precision.
  const double t = std::abs(tau) > 1e150
                       ? 0.5 / tau
                       : (tau >= 0.0 ? 1.0 : -1.0) / (std::abs(tau) + std::sqrt(1.0 + tau * tau));
  const double c = 1.0 / std::sqrt(1.0 + t * t), s = t * c;
  const int r = 3 - p - q;  // the third index
  a[p][p] -= t * apq;
  a[q][q] += t * apq;
  a[p][q] = a[q][p] = 0.0;
  const double arp = a[r][p], arq = a[r][q];
  a[r][p] = a[p][r] = c * arp - s * arq;
  a[r][q] = a[q][r] = s * arp + c * arq;
  for (int k = 0; k < 3; ++k) {
    const double vkp = v[k][p], vkq = v[k][q];
    v[k][p] = c * vkp - s * vkq;
    v[k][q] = s * vkp + c * vkq;
  }
}

// Converged when the off-diagonal part is below round-off of the whole (squared norms).
bool diagonal(const Matrix& a) {
  const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
  const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
  return off == 0.0 || !(off > 1e-34 * (diag + off));
}

// Gershgorin: every principal value lies in a disc a_ii +- sum_j!=i |a_ij|, so when all discs
// lie in [lo, hi] nothing is clamped and the decomposition can be skipped.
bool inside(const Voigt& t, double lo, double hi) {
  const double r[3] = {std::abs(t[3]) + std::abs(t[5]), std::abs(t[3]) + std::abs(t[4]),
                       std::abs(t[4]) + std::abs(t[5])};
  for (int i = 0; i < 3; ++i)
    if (!(t[i] - r[i] >= lo && t[i] + r[i] <= hi)) return false;
  return true;
}

}  // namespace

Principal principalOf(const Voigt& t) {
  Matrix a{{{t[0], t[3], t[5]}, {t[3], t[1], t[4]}, {t[5], t[4], t[2]}}};
  Matrix v{{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
  for (int sweep = 0; sweep < kMaxSweeps && !diagonal(a); ++sweep) {
    rotate(a, v, 0, 1);
    rotate(a, v, 0, 2);
    rotate(a, v, 1, 2);
  }
  // Ascending order; ties keep the Jacobi order (a fixed rule, so the result is reproducible).
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int i, int j) { return a[i][i] < a[j][j]; });
  Principal out;
  for (int k = 0; k < 3; ++k) {
    const int c = order[k];
    out.value[k] = a[c][c];
    for (int i = 0; i < 3; ++i) out.axis[k][i] = v[i][c];
  }
  return out;
}

Voigt fromPrincipal(const std::array<double, 3>& value,
                    const std::array<std::array<double, 3>, 3>& axis) {
  Voigt t{};
  // Voigt slot k holds the tensor component (i, j) = kPair[k].
  constexpr int kPair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  for (int k = 0; k < 6; ++k)
    for (int n = 0; n < 3; ++n) t[k] += value[n] * axis[n][kPair[k][0]] * axis[n][kPair[k][1]];
  return t;
}

Voigt clampPrincipal(const Voigt& t, double lo, double hi) {
  if (inside(t, lo, hi)) return t;
  Principal p = principalOf(t);
  bool clamped = false;
  for (double& v : p.value) {
    const double c = std::clamp(v, lo, hi);
    clamped = clamped || c != v;
    v = c;
  }
  return clamped ? fromPrincipal(p.value, p.axis) : t;
}

}  // namespace crumple::materials
