// The principal-stress helper of src/materials (principal.hpp): exact on diagonal and known
// tensors, orthonormal axes that rebuild random and nearly repeated tensors to round-off, and
// clamping that keeps the axes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "materials/principal.hpp"
#include "voigt.hpp"

namespace m = crumple::materials;
using namespace crumple::testing;  // voigt.hpp: Axes, rotation, rotated, norm, maxDiff
using m::Voigt;

// A diagonal tensor is its own decomposition: exact values, ascending, along the axes.
TEST(Principal, DiagonalIsExactAndAscending) {
  const m::Principal p = m::principalOf({3.0, -1.0, 2.0, 0.0, 0.0, 0.0});
  EXPECT_EQ(p.value, (std::array<double, 3>{-1.0, 2.0, 3.0}));
  EXPECT_EQ(std::abs(p.axis[0][1]), 1.0);
  EXPECT_EQ(std::abs(p.axis[1][2]), 1.0);
  EXPECT_EQ(std::abs(p.axis[2][0]), 1.0);
}

// [[2, 1, 0], [1, 2, 0], [0, 0, 3]]: values 1, 3, 3; the axis of 1 is (1, -1, 0) / sqrt 2.
TEST(Principal, RepeatedValueAndKnownAxis) {
  const m::Principal p = m::principalOf({2.0, 2.0, 3.0, 1.0, 0.0, 0.0});
  EXPECT_NEAR(p.value[0], 1.0, 1e-15);
  EXPECT_NEAR(p.value[1], 3.0, 1e-15);
  EXPECT_NEAR(p.value[2], 3.0, 1e-15);
  EXPECT_NEAR(std::abs(p.axis[0][0]), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(p.axis[0][0] + p.axis[0][1], 0.0, 1e-15);
  EXPECT_NEAR(p.axis[0][2], 0.0, 1e-15);
}

// Random tensors, and rotated ones with repeated or nearly repeated values (where the cubic's
// eigenvectors are ill-conditioned): orthonormal axes that rebuild the tensor to round-off, and
// the values of the rotated diagonal back.
TEST(Principal, RebuildsRandomAndNearlyRepeatedTensors) {
  std::mt19937_64 rng(63);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n = 0; n < 2000; ++n) {
    Voigt t;
    std::array<double, 3> d{u(rng), u(rng), u(rng)};
    if (n % 2 == 0) {
      for (double& v : t) v = u(rng) * 100.0;
    } else {
      if (n % 4 == 1) d[1] = d[0] * (1.0 + 1e-12);
      if (n % 8 == 3) d = {0.5, 0.5, 0.5};
      t = rotated(rotation({u(rng), u(rng), u(rng)}, 3.0 * u(rng)), {d[0], d[1], d[2], 0, 0, 0});
    }
    const m::Principal p = m::principalOf(t);
    const double scale = std::max(norm(t), 1e-300);
    EXPECT_LE(maxDiff(m::fromPrincipal(p.value, p.axis), t), 4e-15 * scale) << n;
    EXPECT_LE(p.value[0], p.value[1]);
    EXPECT_LE(p.value[1], p.value[2]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double dot = 0;
        for (int k = 0; k < 3; ++k) dot += p.axis[i][k] * p.axis[j][k];
        EXPECT_NEAR(dot, i == j ? 1.0 : 0.0, 4e-15) << n;
      }
    if (n % 2 == 1) {
      std::sort(d.begin(), d.end());
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.value[k], d[k], 4e-15) << n;
    }
  }
}

// Clamping keeps the axes: Q diag(-5, 1, 2) Q^T into [-3, 1.5] is Q diag(-3, 1, 1.5) Q^T; a
// tensor already inside comes back bit for bit.
TEST(Principal, ClampKeepsTheAxes) {
  const Axes q = rotation({1.0, 2.0, -0.5}, 0.7);
  const Voigt t = rotated(q, {-5.0, 1.0, 2.0, 0, 0, 0});
  EXPECT_LE(maxDiff(m::clampPrincipal(t, -3.0, 1.5), rotated(q, {-3.0, 1.0, 1.5, 0, 0, 0})), 1e-14);
  const Voigt inside = rotated(q, {-2.0, 1.0, 1.2, 0, 0, 0});
  EXPECT_EQ(m::clampPrincipal(inside, -3.0, 1.5), inside);
  EXPECT_EQ(m::clampPrincipal(t, -10.0, 10.0), t);
}
