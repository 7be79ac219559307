// Small 3-vector arithmetic on std::array<double, 3> (positions, normals, forces), shared by
// the model builders and the contact module.
#pragma once

#include <array>
#include <cmath>

namespace crumple::util {

using Vec3 = std::array<double, 3>;

inline Vec3 sub(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3 add(const Vec3& a, const Vec3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3 scale(const Vec3& a, double s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}
inline double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3& a) {
  return std::sqrt(dot(a, a));
}
// The unit vector along a, or zero for a zero vector.
inline Vec3 unit(const Vec3& a) {
  const double n = norm(a);
  return n == 0.0 ? Vec3{} : Vec3{a[0] / n, a[1] / n, a[2] / n};
}

}  // namespace crumple::util
