// One material point of any law driven through a prescribed path, in each element family's
// state (solid: 3-D stress, shell: plane stress, beam: fibre), for the unit tests of the laws.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <variant>

#include "materials/materials.hpp"

namespace crumple::testing {

namespace mp {

namespace m = crumple::materials;
using Strain = std::array<double, 6>;

// The point a step `lateral(dl)` gives when its lateral strain increment dl is chosen so that
// the lateral stress s[1] is zero after the step (dx: the axial increment), by the secant
// method.
template <class P, class Step>
P withZeroLateralStress(const Step& lateral, double dx) {
  double a = -0.5 * dx, b = -0.3 * dx;
  double fa = lateral(a).s[1], fb = lateral(b).s[1];
  for (int it = 0; it < 60 && fb != fa && std::abs(fb) > 1e-11; ++it) {
    const double c = b - fb * (b - a) / (fb - fa);
    a = b;
    fa = fb;
    b = c;
    fb = lateral(b).s[1];
  }
  return lateral(b);
}

// A solid point with every history a law may keep.
struct SolidPoint {
  Strain s{};
  Strain alpha{};
  double eps_p = 0.0;
  std::array<double, m::kMaxHistory> h{};
  uint8_t failed = 0;

  // `law`: an m::Law, or a law unit with a solid update.
  template <class L>
  void step(const L& law, const Strain& de, double dt) {
    m::PointBatch b;
    b.n = 1;
    b.dt = dt;
    for (int k = 0; k < 6; ++k) {
      b.s[k] = &s[static_cast<std::size_t>(k)];
      b.de[k] = &de[static_cast<std::size_t>(k)];
      b.alpha[k] = &alpha[static_cast<std::size_t>(k)];
    }
    for (int k = 0; k < m::kMaxHistory; ++k) b.h[k] = &h[static_cast<std::size_t>(k)];
    b.eps_p = &eps_p;
    b.failed = &failed;
    if constexpr (std::is_same_v<L, m::Law>) {
      std::visit(
          [&](const auto& l) {
            if constexpr (m::SolidLaw<std::decay_t<decltype(l)>>) l.update(b);
          },
          law);
    } else {
      law.update(b);
    }
  }
  // A step of axial strain dx in uniaxial stress: the equal lateral strains that leave the
  // lateral stress zero.
  template <class L>
  void uniaxialStep(const L& law, double dx, double dt) {
    *this = withZeroLateralStress<SolidPoint>(
        [&](double dl) {
          SolidPoint p = *this;
          p.step(law, {dx, dl, dl, 0, 0, 0}, dt);
          return p;
        },
        dx);
  }
  double mises() const {
    const double p = (s[0] + s[1] + s[2]) / 3.0;
    const double a = s[0] - p, b = s[1] - p, c = s[2] - p;
    return std::sqrt(1.5 * (a * a + b * b + c * c) +
                     3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
  }
};

// A shell point (plane stress, xx yy xy).
struct ShellPoint {
  std::array<double, 3> s{}, alpha{};
  double eps_p = 0.0, de_zz = 0.0;
  uint8_t failed = 0;

  void step(const m::Law& law, double dxx, double dyy, double dxy, double dt) {
    const double de[3] = {dxx, dyy, dxy};
    m::PlaneStressPoints b;
    b.n = 1;
    b.dt = dt;
    for (int k = 0; k < 3; ++k) {
      b.s[k] = &s[static_cast<std::size_t>(k)];
      b.de[k] = &de[k];
      b.alpha[k] = &alpha[static_cast<std::size_t>(k)];
    }
    b.de_zz = &de_zz;
    b.eps_p = &eps_p;
    b.failed = &failed;
    std::visit(
        [&](const auto& l) {
          if constexpr (m::ShellLaw<std::decay_t<decltype(l)>>) l.updatePlaneStress(b);
        },
        law);
  }
  // A step of in-plane strain dx along x in uniaxial stress (s_yy = 0 after it); returns the
  // lateral strain increment used.
  double uniaxialStep(const m::Law& law, double dx, double dt) {
    double used = 0.0;
    *this = withZeroLateralStress<ShellPoint>(
        [&](double dy) {
          ShellPoint c = *this;
          c.step(law, dx, dy, 0.0, dt);
          used = dy;
          return c;
        },
        dx);
    return used;
  }
  double mises() const {
    return std::sqrt(s[0] * s[0] - s[0] * s[1] + s[1] * s[1] + 3.0 * s[2] * s[2]);
  }
};

}  // namespace mp

}  // namespace crumple::testing
