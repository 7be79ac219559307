// Piecewise-linear curves: the segment search and interpolation that every user of a curve
// (loads, yield curves, spring laws, soil pressure curves) shares, so that they all agree on
// where a segment ends and how the curve goes on past its ends.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>

namespace crumple::util {

// Segment k of x (ascending, at least 2 points) holds [x[k], x[k+1]), clamped to the first and
// last segments, so that values beyond the ends follow the end slopes.
inline std::size_t segmentOf(std::span<const double> x, double t) {
  const auto it = std::upper_bound(x.begin(), x.end(), t);
  const std::size_t k = it == x.begin() ? 0 : static_cast<std::size_t>(it - x.begin()) - 1;
  return std::min(k, x.size() - 2);
}

// The value at t of segment k; a zero-length segment (a step) gives its upper value. Y is any
// indexable sequence of ordinates (a span, or a blend of two curves on the same abscissae).
template <class Y = std::span<const double>>
inline double onSegment(std::span<const double> x, const Y& y, std::size_t k, double t) {
  const double dx = x[k + 1] - x[k];
  if (dx <= 0.0) return y[k + 1];
  return y[k] + (y[k + 1] - y[k]) * (t - x[k]) / dx;
}

// Value and slope at t of a curve with at least one point (one point: a constant), the end
// slopes continued past the ends; on a zero-length segment (a step) the value is the step's
// upper value and the slope 0.
template <class Y = std::span<const double>>
inline void valueAndSlope(std::span<const double> x, const Y& y, double t, double& value,
                          double& slope) {
  if (x.size() == 1) {
    value = y[0];
    slope = 0.0;
    return;
  }
  const std::size_t k = segmentOf(x, t);
  const double dx = x[k + 1] - x[k];
  slope = dx > 0.0 ? (y[k + 1] - y[k]) / dx : 0.0;
  value = dx > 0.0 ? y[k] + slope * (t - x[k]) : y[k + 1];
}

}  // namespace crumple::util
