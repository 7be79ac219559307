#include "contact/geometry.hpp"

#include <algorithm>

namespace crumple::contact {

namespace {

Projection triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double tol) {
  Projection r;
  const Vec3 e1 = sub(b, a), e2 = sub(c, a);
  Vec3 n = cross(e1, e2);
  const double len = norm(n);
  if (!(len > 0.0)) return r;
  n = scale(n, 1.0 / len);
  // Barycentric coordinates of the foot of the perpendicular.
  const Vec3 w = sub(p, a);
  const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
  const double w1 = dot(w, e1), w2 = dot(w, e2);
  const double det = d11 * d22 - d12 * d12;
  double l1 = (d22 * w1 - d12 * w2) / det;  // weight of b
  double l2 = (d11 * w2 - d12 * w1) / det;  // weight of c
  double l0 = 1.0 - l1 - l2;
  r.inside = l0 >= -tol && l1 >= -tol && l2 >= -tol;
  // Clamp onto the triangle so that the weights stay a partition of unity in [0, 1].
  l0 = std::max(l0, 0.0);
  l1 = std::max(l1, 0.0);
  l2 = std::max(l2, 0.0);
  const double s = l0 + l1 + l2;
  r.N = {l0 / s, l1 / s, l2 / s, 0.0};
  for (int i = 0; i < 3; ++i)
    r.point[std::size_t(i)] =
        r.N[0] * a[std::size_t(i)] + r.N[1] * b[std::size_t(i)] + r.N[2] * c[std::size_t(i)];
  r.normal = n;
  r.d = dot(sub(p, r.point), n);
  return r;
}

}  // namespace

Projection project(const Vec3& p, const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3,
                   bool is_triangle, double tolerance) {
  if (is_triangle) return triangle(p, x0, x1, x2, tolerance);
  // Closest point on the bilinear surface x(xi, eta) = sum N_a x_a by Gauss-Newton from the
  // centre; a flat or mildly warped segment converges in two or three iterations.
  constexpr double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  const Vec3* x[4] = {&x0, &x1, &x2, &x3};
  double xi = 0.0, eta = 0.0;
  Vec3 t1{}, t2{}, pt{};
  auto evaluate = [&](double u, double v) {
    t1 = t2 = pt = Vec3{};
    for (int a = 0; a < 4; ++a) {
      const double n = 0.25 * (1 + sx[a] * u) * (1 + sy[a] * v);
      const double nu = 0.25 * sx[a] * (1 + sy[a] * v);
      const double nv = 0.25 * sy[a] * (1 + sx[a] * u);
      for (int i = 0; i < 3; ++i) {
        pt[std::size_t(i)] += n * (*x[a])[std::size_t(i)];
        t1[std::size_t(i)] += nu * (*x[a])[std::size_t(i)];
        t2[std::size_t(i)] += nv * (*x[a])[std::size_t(i)];
      }
    }
  };
  for (int it = 0; it < 6; ++it) {
    evaluate(xi, eta);
    const Vec3 r = sub(p, pt);
    const double a11 = dot(t1, t1), a12 = dot(t1, t2), a22 = dot(t2, t2);
    const double b1 = dot(t1, r), b2 = dot(t2, r);
    const double det = a11 * a22 - a12 * a12;
    if (!(det > 0.0)) break;
    const double dxi = (a22 * b1 - a12 * b2) / det;
    const double deta = (a11 * b2 - a12 * b1) / det;
    // Keep the iterate within reach of the segment: far outside it the answer is "outside".
    xi = std::clamp(xi + dxi, -2.0, 2.0);
    eta = std::clamp(eta + deta, -2.0, 2.0);
    if (std::abs(dxi) + std::abs(deta) < 1e-10) break;
  }
  Projection r;
  r.inside = std::abs(xi) <= 1.0 + tolerance && std::abs(eta) <= 1.0 + tolerance;
  xi = std::clamp(xi, -1.0, 1.0);
  eta = std::clamp(eta, -1.0, 1.0);
  evaluate(xi, eta);
  for (int a = 0; a < 4; ++a) r.N[std::size_t(a)] = 0.25 * (1 + sx[a] * xi) * (1 + sy[a] * eta);
  r.point = pt;
  Vec3 n = cross(t1, t2);
  const double len = norm(n);
  if (!(len > 0.0)) {
    r.inside = false;
    return r;
  }
  r.normal = scale(n, 1.0 / len);
  r.d = dot(sub(p, pt), r.normal);
  return r;
}

namespace {

// Axes within this sine squared of parallel are taken as parallel: the denominator
// |d1|^2 |d2|^2 - (d1.d2)^2 is then round-off.
constexpr double kParallelSine2 = 1e-10;

double clamp01(double v) {
  return std::clamp(v, 0.0, 1.0);
}

// Parallel axes: the middle of the overlap of p's axis with q's along q, or the nearest ends.
EdgePoints parallelEdgePoints(const Vec3& p0, const Vec3& d1, const Vec3& q0, const Vec3& d2) {
  const double e = dot(d2, d2);
  const double along = dot(d1, d2);  // p's axis runs along q (> 0) or against it
  const double t0 = dot(sub(p0, q0), d2) / e;
  const double t1 = t0 + along / e;
  const double lo = std::min(t0, t1), hi = std::max(t0, t1);
  EdgePoints r;
  // Overlapping: the middle of the overlap; apart: the end of q nearest to p's axis.
  if (hi < 0.0)
    r.t = 0.0;
  else if (lo > 1.0)
    r.t = 1.0;
  else
    r.t = 0.5 * (std::max(lo, 0.0) + std::min(hi, 1.0));
  // s of the point of p's axis over q(t), clamped onto p.
  r.s = clamp01((r.t - t0) * e / along);
  return r;
}

}  // namespace

EdgePoints closestEdgePoints(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d1 = sub(p1, p0), d2 = sub(q1, q0), r = sub(p0, q0);
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  EdgePoints out;
  if (!(a > 0.0) && !(e > 0.0)) {
    out.p = p0;
    out.q = q0;
    return out;
  }
  if (!(a > 0.0)) {
    out.t = clamp01(f / e);
  } else {
    const double c = dot(d1, r);
    if (!(e > 0.0)) {
      out.s = clamp01(-c / a);
    } else {
      const double b = dot(d1, d2);
      const double denom = a * e - b * b;
      if (denom <= kParallelSine2 * a * e) {
        out = parallelEdgePoints(p0, d1, q0, d2);
      } else {
        // The unconstrained minimum on p's axis, clamped; then q's point nearest to it,
        // clamped; and p's again if q's was clamped.
        out.s = clamp01((b * f - c * e) / denom);
        out.t = (b * out.s + f) / e;
        if (out.t < 0.0 || out.t > 1.0) {
          out.t = clamp01(out.t);
          out.s = clamp01((b * out.t - c) / a);
        }
      }
    }
  }
  out.p = add(p0, scale(d1, out.s));
  out.q = add(q0, scale(d2, out.t));
  return out;
}

}  // namespace crumple::contact

namespace crumple::contact {

namespace {

// The closest point of triangle (a, b, c) to p as barycentric weights (Ericson 2005, 5.1.5:
// the Voronoi regions of the vertices, the edges and the face).
std::array<double, 3> closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                        const Vec3& c) {
  const Vec3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
  const Vec3 bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return {1.0 - v, v, 0.0};
  }
  const Vec3 cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - w, w};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1.0 - v - w, v, w};
}

using Triangle = std::array<std::size_t, 3>;

std::vector<Triangle> trianglesOf(bool triangle) {
  if (triangle) return {{0, 1, 2}};
  return {{0, 1, 2}, {0, 2, 3}};
}

// Keeps the nearer of the current best and the candidate (p with weights wa, q with wb).
void keepNearer(SegmentPoints& best, const Vec3& p, const Vec3& q, const std::array<double, 4>& wa,
                const std::array<double, 4>& wb) {
  const double d = norm(sub(p, q));
  if (d < best.dist) best = {wa, wb, p, q, d};
}

// Vertices of `from` (weights into fa) against triangle t of `onto` (weights into fb).
void verticesOnto(SegmentPoints& best, const std::array<Vec3, 4>& from, const Triangle& tf,
                  const std::array<Vec3, 4>& onto, const Triangle& t, bool swap) {
  for (std::size_t v : tf) {
    const auto w = closestOnTriangle(from[v], onto[t[0]], onto[t[1]], onto[t[2]]);
    std::array<double, 4> wv{}, wt{};
    wv[v] = 1.0;
    Vec3 q{};
    for (std::size_t i = 0; i < 3; ++i) {
      wt[t[i]] += w[i];
      q = add(q, scale(onto[t[i]], w[i]));
    }
    if (swap)
      keepNearer(best, q, from[v], wt, wv);
    else
      keepNearer(best, from[v], q, wv, wt);
  }
}

}  // namespace

SegmentPoints closestSegmentPoints(const std::array<Vec3, 4>& a, bool tri_a,
                                   const std::array<Vec3, 4>& b, bool tri_b) {
  SegmentPoints best;
  best.dist = 1e300;
  for (const Triangle& ta : trianglesOf(tri_a))
    for (const Triangle& tb : trianglesOf(tri_b)) {
      verticesOnto(best, a, ta, b, tb, false);
      verticesOnto(best, b, tb, a, ta, true);
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
          const std::size_t a0 = ta[i], a1 = ta[(i + 1) % 3], b0 = tb[j], b1 = tb[(j + 1) % 3];
          const EdgePoints e = closestEdgePoints(a[a0], a[a1], b[b0], b[b1]);
          std::array<double, 4> wa{}, wb{};
          wa[a0] += 1.0 - e.s;
          wa[a1] += e.s;
          wb[b0] += 1.0 - e.t;
          wb[b1] += e.t;
          keepNearer(best, e.p, e.q, wa, wb);
        }
    }
  return best;
}

}  // namespace crumple::contact
