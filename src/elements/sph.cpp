#include "elements/sph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace crumple::elements::sph {

namespace {

// C_d / h^d of the cubic B-spline (Monaghan 1992, eq. 2.6, normalised in d dimensions).
double normalisation(int dim, double h) {
  switch (dim) {
    case 1:
      return 2.0 / 3.0 / h;
    case 2:
      return 10.0 / (7.0 * std::numbers::pi * h * h);
    case 3:
      return 1.0 / (std::numbers::pi * h * h * h);
    default:
      throw std::invalid_argument("SPH kernel: the dimension must be 1, 2 or 3");
  }
}

}  // namespace

double kernel(int dim, double r, double h) {
  const double q = r / h, c = normalisation(dim, h);
  if (q <= 1.0) return c * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
  if (q <= 2.0) return c * 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
  return 0.0;
}

double kernelSlope(int dim, double r, double h) {
  const double q = r / h, c = normalisation(dim, h) / h;
  if (q <= 1.0) return c * (-3.0 * q + 2.25 * q * q);
  if (q <= 2.0) return c * -0.75 * (2.0 - q) * (2.0 - q);
  return 0.0;
}

namespace {

// Particles binned into cubic cells of side `cell` (CSR: cell_start, members ascending).
struct Grid {
  Vec3 lo{};
  double cell = 1.0;
  std::array<int64_t, 3> dims{1, 1, 1};
  std::vector<int32_t> start, member;

  std::array<int64_t, 3> cellOf(const Vec3& x) const {
    std::array<int64_t, 3> c{};
    for (int k = 0; k < 3; ++k)
      c[k] = std::clamp<int64_t>(static_cast<int64_t>((x[k] - lo[k]) / cell), 0, dims[k] - 1);
    return c;
  }
  int64_t index(const std::array<int64_t, 3>& c) const {
    return c[0] + dims[0] * (c[1] + dims[1] * c[2]);
  }
};

Grid binParticles(std::span<const Vec3> x, double cell) {
  Grid g;
  g.cell = cell;
  Vec3 hi{};
  for (int k = 0; k < 3; ++k) {
    g.lo[k] = std::numeric_limits<double>::max();
    hi[k] = std::numeric_limits<double>::lowest();
  }
  for (const Vec3& p : x)
    for (int k = 0; k < 3; ++k) {
      g.lo[k] = std::min(g.lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  // At most about one cell per particle along each side (a scattered cloud stays small).
  const auto cap = static_cast<int64_t>(x.size()) + 1;
  for (int k = 0; k < 3; ++k)
    g.dims[k] = std::clamp<int64_t>(static_cast<int64_t>((hi[k] - g.lo[k]) / cell) + 1, 1, cap);
  g.start.assign(static_cast<std::size_t>(g.dims[0] * g.dims[1] * g.dims[2] + 1), 0);
  for (const Vec3& p : x) ++g.start[static_cast<std::size_t>(g.index(g.cellOf(p)) + 1)];
  for (std::size_t c = 1; c < g.start.size(); ++c) g.start[c] += g.start[c - 1];
  g.member.resize(x.size());
  std::vector<int32_t> fill(g.start.begin(), g.start.end() - 1);
  for (std::size_t i = 0; i < x.size(); ++i)  // ascending i: members ascending in each cell
    g.member[static_cast<std::size_t>(fill[static_cast<std::size_t>(g.index(g.cellOf(x[i])))]++)] =
        static_cast<int32_t>(i);
  return g;
}

// Calls f(j) for the particles of the cell of x and the 26 around it.
template <class F>
void forEachNear(const Grid& g, const Vec3& x, F&& f) {
  const auto c = g.cellOf(x);
  for (int64_t dz = -1; dz <= 1; ++dz)
    for (int64_t dy = -1; dy <= 1; ++dy)
      for (int64_t dx = -1; dx <= 1; ++dx) {
        const std::array<int64_t, 3> n{c[0] + dx, c[1] + dy, c[2] + dz};
        if (n[0] < 0 || n[1] < 0 || n[2] < 0 || n[0] >= g.dims[0] || n[1] >= g.dims[1] ||
            n[2] >= g.dims[2])
          continue;
        const auto k = static_cast<std::size_t>(g.index(n));
        for (int32_t m = g.start[k]; m < g.start[k + 1]; ++m)
          f(g.member[static_cast<std::size_t>(m)]);
      }
}

}  // namespace

std::vector<std::pair<int32_t, int32_t>> neighbourPairs(std::span<const Vec3> x,
                                                        std::span<const double> h) {
  std::vector<std::pair<int32_t, int32_t>> pairs;
  if (x.empty()) return pairs;
  const double h_max = *std::max_element(h.begin(), h.end());
  const Grid g = binParticles(x, 2.0 * h_max);
  std::vector<int32_t> near;
  for (std::size_t i = 0; i < x.size(); ++i) {
    near.clear();
    forEachNear(g, x[i], [&](int32_t j) {
      if (static_cast<std::size_t>(j) <= i) return;
      const double hij = 0.5 * (h[i] + h[static_cast<std::size_t>(j)]);
      const Vec3 d = util::sub(x[i], x[static_cast<std::size_t>(j)]);
      if (util::dot(d, d) < 4.0 * hij * hij) near.push_back(j);
    });
    std::sort(near.begin(), near.end());
    for (int32_t j : near) pairs.emplace_back(static_cast<int32_t>(i), j);
  }
  return pairs;
}

double initialSmoothingLength(std::span<const Vec3> x, double cslh) {
  if (x.size() < 2) throw std::invalid_argument("SPH: a part needs two particles or more");
  // Grow the search cell until every particle has a neighbour within it (a coarse first
  // guess from the bounding box, then doubled).
  Vec3 lo = x[0], hi = x[0];
  for (const Vec3& p : x)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  for (double cell = extent / std::cbrt(static_cast<double>(x.size())) + 1e-300;; cell *= 2.0) {
    const Grid g = binParticles(x, cell);
    double largest = 0.0;
    bool all = true;
    for (std::size_t i = 0; i < x.size() && all; ++i) {
      double nearest = std::numeric_limits<double>::max();
      forEachNear(g, x[i], [&](int32_t j) {
        if (static_cast<std::size_t>(j) != i)
          nearest = std::min(nearest, util::norm(util::sub(x[i], x[static_cast<std::size_t>(j)])));
      });
      // Only a neighbour within one cell is sure to be the nearest.
      all = nearest <= cell;
      largest = std::max(largest, nearest);
    }
    if (all) return cslh * largest;
  }
}

void computeRates(const Particles& p, std::span<const std::pair<int32_t, int32_t>> pairs,
                  std::vector<double>& drho, std::vector<std::array<double, 9>>& grad_v) {
  const std::size_t n = p.x.size();
  drho.assign(n, 0.0);
  grad_v.assign(n, std::array<double, 9>{});
  for (const auto& [a, b] : pairs) {
    const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
    const Vec3 d = util::sub(p.x[i], p.x[j]);
    const double r = util::norm(d), hij = 0.5 * (p.h[i] + p.h[j]);
    if (r == 0.0) continue;
    const double f = kernelSlope(p.dim, r, hij) / r;  // grad_i W_ij = f d = -grad_j W_ij
    const Vec3 dv = util::sub(p.v[i], p.v[j]);
    const double dvdw = f * util::dot(dv, d);
    drho[i] += p.mass[j] * dvdw;
    drho[j] += p.mass[i] * dvdw;
    // L_i -= (m_j / rho_j) dv (x) f d;  L_j -= (m_i / rho_i) (-dv) (x) (-f d): the same sign.
    const double wi = p.mass[j] / p.rho[j] * f, wj = p.mass[i] / p.rho[i] * f;
    for (int r_ = 0; r_ < 3; ++r_)
      for (int c = 0; c < 3; ++c) {
        grad_v[i][static_cast<std::size_t>(3 * r_ + c)] -= wi * dv[r_] * d[c];
        grad_v[j][static_cast<std::size_t>(3 * r_ + c)] -= wj * dv[r_] * d[c];
      }
  }
}

namespace {

// sig . d for a Voigt stress (tensor shear).
Vec3 stressTimes(const std::array<double, 6>& s, const Vec3& d) {
  return {s[0] * d[0] + s[3] * d[1] + s[5] * d[2], s[3] * d[0] + s[1] * d[1] + s[4] * d[2],
          s[5] * d[0] + s[4] * d[1] + s[2] * d[2]};
}

// Monaghan's Pi_ij of a pair (0 when the particles separate).
double viscosity(const Particles& p, std::size_t i, std::size_t j, const Vec3& d, double hij) {
  const double vx = util::dot(util::sub(p.v[i], p.v[j]), d);
  if (vx >= 0.0) return 0.0;
  const double mu = hij * vx / (util::dot(d, d) + 0.01 * hij * hij);
  const double c = 0.5 * (p.c[i] + p.c[j]), rho = 0.5 * (p.rho[i] + p.rho[j]);
  return (-p.alpha * c * mu + p.beta * mu * mu) / rho;
}

}  // namespace

void computeForces(const Particles& p, std::span<const std::pair<int32_t, int32_t>> pairs,
                   std::vector<Vec3>& force, std::vector<double>* heat) {
  force.assign(p.x.size(), Vec3{});
  if (heat) heat->assign(p.x.size(), 0.0);
  for (const auto& [a, b] : pairs) {
    const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
    const Vec3 d = util::sub(p.x[i], p.x[j]);
    const double r = util::norm(d), hij = 0.5 * (p.h[i] + p.h[j]);
    if (r == 0.0) continue;
    const Vec3 gw = util::scale(d, kernelSlope(p.dim, r, hij) / r);  // grad_i W_ij
    const double ri = 1.0 / (p.rho[i] * p.rho[i]), rj = 1.0 / (p.rho[j] * p.rho[j]);
    const Vec3 si = stressTimes(p.sig[i], gw), sj = stressTimes(p.sig[j], gw);
    const double pi = viscosity(p, i, j, d, hij), mm = p.mass[i] * p.mass[j];
    for (int k = 0; k < 3; ++k) {
      const double fk = mm * (si[k] * ri + sj[k] * rj - pi * gw[k]);
      force[i][k] += fk;
      force[j][k] -= fk;
    }
    if (heat && pi != 0.0) {
      const double q = 0.5 * mm * pi * util::dot(util::sub(p.v[i], p.v[j]), gw);
      (*heat)[i] += q;
      (*heat)[j] += q;
    }
  }
}

}  // namespace crumple::elements::sph
