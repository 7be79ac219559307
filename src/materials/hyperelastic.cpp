#include "materials/hyperelastic.hpp"

#include <cmath>
#include <cstddef>
#include <utility>

#include "util/error.hpp"

namespace crumple::materials {

LeftCauchyGreen leftCauchyGreen(const PointBatch& p, int l) {
  double f[9];
  for (int k = 0; k < 9; ++k) f[k] = p.F[k][l];
  LeftCauchyGreen k;
  auto row = [&](int i, int j) {
    return f[3 * i] * f[3 * j] + f[3 * i + 1] * f[3 * j + 1] + f[3 * i + 2] * f[3 * j + 2];
  };
  k.b[0] = row(0, 0);
  k.b[1] = row(1, 1);
  k.b[2] = row(2, 2);
  k.b[3] = row(0, 1);
  k.b[4] = row(1, 2);
  k.b[5] = row(2, 0);
  k.J = f[0] * (f[4] * f[8] - f[5] * f[7]) - f[1] * (f[3] * f[8] - f[5] * f[6]) +
        f[2] * (f[3] * f[7] - f[4] * f[6]);
  k.I1 = k.b[0] + k.b[1] + k.b[2];
  const double bb = k.b[0] * k.b[0] + k.b[1] * k.b[1] + k.b[2] * k.b[2] +
                    2.0 * (k.b[3] * k.b[3] + k.b[4] * k.b[4] + k.b[5] * k.b[5]);
  k.I2 = 0.5 * (k.I1 * k.I1 - bb);
  k.I3 = k.J * k.J;
  return k;
}

void squareOf(const double (&b)[6], double (&b2)[6]) {
  const double xx = b[0], yy = b[1], zz = b[2], xy = b[3], yz = b[4], zx = b[5];
  b2[0] = xx * xx + xy * xy + zx * zx;
  b2[1] = xy * xy + yy * yy + yz * yz;
  b2[2] = zx * zx + yz * yz + zz * zz;
  b2[3] = xx * xy + xy * yy + zx * yz;
  b2[4] = xy * zx + yy * yz + yz * zz;
  b2[5] = zx * xx + yz * xy + zz * zx;
}

void invariantStress(const LeftCauchyGreen& k, double w1, double w2, double w3, PointBatch& p,
                     int l) {
  double b2[6];
  squareOf(k.b, b2);
  const double c = 2.0 / k.J;
  for (int i = 0; i < 6; ++i) {
    const double iso = i < 3 ? k.I3 * w3 : 0.0;
    p.s[i][l] = c * ((w1 + k.I1 * w2) * k.b[i] - w2 * b2[i] + iso);
  }
}

UniaxialTest uniaxialTest(const std::string& at, const CurveData& c, double sgl, double sw,
                          double st) {
  if (!(sgl > 0.0) || !(sw > 0.0) || !(st > 0.0))
    throw util::InputError(at +
                           "the curve fit needs a positive specimen gauge length, width and "
                           "thickness (SGL, SW, ST)");
  UniaxialTest t;
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    const double stretch = 1.0 + c.x[i] / sgl;
    if (!(stretch > 0.0))
      throw util::InputError(at + "LCID curve " + std::to_string(c.id) +
                             ": a change in gauge length of -SGL or less");
    t.stretch.push_back(stretch);
    t.nominal.push_back(c.y[i] / (sw * st));
  }
  return t;
}

namespace {

// Solves the symmetric system a x = r in place (partial pivoting); false when singular.
bool solve(std::vector<std::vector<double>>& a, std::vector<double>& r) {
  const std::size_t n = r.size();
  double scale = 0.0;
  for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, std::abs(a[i][i]));
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t piv = col;
    for (std::size_t i = col + 1; i < n; ++i)
      if (std::abs(a[i][col]) > std::abs(a[piv][col])) piv = i;
    if (!(std::abs(a[piv][col]) > 1e-12 * scale)) return false;
    std::swap(a[piv], a[col]);
    std::swap(r[piv], r[col]);
    for (std::size_t i = col + 1; i < n; ++i) {
      const double m = a[i][col] / a[col][col];
      for (std::size_t j = col; j < n; ++j) a[i][j] -= m * a[col][j];
      r[i] -= m * r[col];
    }
  }
  for (std::size_t i = n; i-- > 0;) {
    double s = r[i];
    for (std::size_t j = i + 1; j < n; ++j) s -= a[i][j] * r[j];
    r[i] = s / a[i][i];
  }
  return true;
}

}  // namespace

std::vector<double> fitUniaxial(const std::string& at, const UniaxialTest& test,
                                const std::vector<std::function<double(double)>>& terms) {
  const std::size_t n = terms.size();
  std::vector<std::vector<double>> a(n, std::vector<double>(n, 0.0));
  std::vector<double> r(n, 0.0), g(n);
  for (std::size_t i = 0; i < test.stretch.size(); ++i) {
    for (std::size_t k = 0; k < n; ++k) g[k] = terms[k](test.stretch[i]);
    for (std::size_t k = 0; k < n; ++k) {
      for (std::size_t j = 0; j < n; ++j) a[k][j] += g[k] * g[j];
      r[k] += g[k] * test.nominal[i];
    }
  }
  if (n == 0 || !solve(a, r))
    throw util::InputError(at +
                           "the least-squares fit to the LCID curve is singular: the curve has "
                           "too few distinct points for the terms asked for");
  return r;
}

}  // namespace crumple::materials
