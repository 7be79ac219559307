#include "model/beam_shapes.hpp"

#include <algorithm>
#include <cmath>

namespace crumple::model {

namespace {

// 2 x 2 Gauss points of the rectangle [s0, s1] x [t0, t1].
void addRectangle(BeamPoints& out, double s0, double s1, double t0, double t1) {
  const double g = 0.5 / std::sqrt(3.0);
  const double sc = 0.5 * (s0 + s1), tc = 0.5 * (t0 + t1);
  const double ds = (s1 - s0) * 2.0 * g, dt = (t1 - t0) * 2.0 * g;
  const double w = 0.25 * (s1 - s0) * (t1 - t0);
  for (const double a : {-0.5, 0.5})
    for (const double b : {-0.5, 0.5}) out.push_back({sc + a * ds, tc + b * dt, w});
}

}  // namespace

BeamPoints wSectionPoints(const std::array<double, 6>& d, std::string& error) {
  const double b = d[0], tf = d[1], h = d[2], tw = d[3];
  if (!(b > 0 && tf > 0 && h > 0 && tw > 0)) {
    error =
        "the W section needs positive D1 (flange width), D2 (flange thickness), D3 "
        "(depth) and D4 (web thickness)";
    return {};
  }
  if (!(2.0 * tf < h) || !(tw <= b)) {
    error =
        "the W section's flanges (2 D2) must be thinner than its depth D3 and its web D4 "
        "no wider than the flanges D1";
    return {};
  }
  BeamPoints p;
  const double hw = 0.5 * h - tf;  // half the clear web height
  for (const double sign : {-1.0, 1.0}) {
    const double t0 = sign * hw, t1 = sign * 0.5 * h;
    addRectangle(p, -0.5 * b, 0.0, std::min(t0, t1), std::max(t0, t1));
    addRectangle(p, 0.0, 0.5 * b, std::min(t0, t1), std::max(t0, t1));
    addRectangle(p, -0.5 * tw, 0.0, sign < 0 ? -hw : 0.0, sign < 0 ? 0.0 : hw);
    addRectangle(p, 0.0, 0.5 * tw, sign < 0 ? -hw : 0.0, sign < 0 ? 0.0 : hw);
  }
  return p;
}

}  // namespace crumple::model
