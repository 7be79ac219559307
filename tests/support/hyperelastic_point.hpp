// One point of a hyperelastic law (a function of the deformation gradient F) for the unit tests
// of the rubbers: the law's Cauchy stress at F, the stress of an energy W(F) by central
// differences, sigma = (1/J) dW/dF F^T, and frame indifference under F -> R F.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>

#include "materials/hyperelastic.hpp"
#include "materials/law.hpp"

namespace crumple::testing::hyper {

using Mat3 = std::array<double, 9>;  // row-major
using Stress = std::array<double, 6>;

// The law's stress at F (a batch of one point); `history` the law's history variables of the
// point (in/out), `modulus`, when given, receives the wave modulus a law reports.
template <class Law>
Stress stressAt(const Law& law, const Mat3& F,
                std::array<double*, materials::kMaxHistory> history = {},
                double* modulus = nullptr) {
  double f[9][1], s[6][1] = {}, de[6][1] = {};
  for (int k = 0; k < 9; ++k) f[k][0] = F[std::size_t(k)];
  materials::PointBatch pb;
  pb.n = 1;
  for (int k = 0; k < 6; ++k) {
    pb.s[k] = s[k];
    pb.de[k] = de[k];
  }
  for (int k = 0; k < 9; ++k) pb.F[k] = f[k];
  for (int k = 0; k < materials::kMaxHistory; ++k) pb.h[k] = history[std::size_t(k)];
  pb.modulus = modulus;
  law.update(pb);
  Stress out;
  for (int k = 0; k < 6; ++k) out[std::size_t(k)] = s[k][0];
  return out;
}

inline Mat3 mul(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return c;
}
inline Mat3 transpose(const Mat3& a) {
  return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]};
}
inline double det(const Mat3& f) {
  return f[0] * (f[4] * f[8] - f[5] * f[7]) - f[1] * (f[3] * f[8] - f[5] * f[6]) +
         f[2] * (f[3] * f[7] - f[4] * f[6]);
}

// B, J and the invariants the laws compute from F.
inline materials::LeftCauchyGreen kinematicsOf(const Mat3& F) {
  double f[9][1];
  for (int k = 0; k < 9; ++k) f[k][0] = F[std::size_t(k)];
  materials::PointBatch pb;
  pb.n = 1;
  for (int k = 0; k < 9; ++k) pb.F[k] = f[k];
  return materials::leftCauchyGreen(pb, 0);
}

// sigma = (1/J) P F^T with P = dW/dF by central differences.
inline Stress stressOfEnergy(const std::function<double(const Mat3&)>& W, const Mat3& F) {
  Mat3 P{};
  const double h = 1e-6;
  for (std::size_t k = 0; k < 9; ++k) {
    Mat3 fp = F, fm = F;
    fp[k] += h;
    fm[k] -= h;
    P[k] = (W(fp) - W(fm)) / (2 * h);
  }
  const Mat3 s = mul(P, transpose(F));
  const double J = det(F);
  return {s[0] / J, s[4] / J, s[8] / J, s[1] / J, s[5] / J, s[2] / J};
}

inline void expectStress(const Stress& got, const Stress& want, double tol) {
  for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(got[k], want[k], tol) << "component " << k;
}

// The small-strain response: the law's moduli are G and K, a stretch 1 +- e gives (central
// differences) d sigma_xx / de = K + 4G/3 and d sigma_yy / de = K - 2G/3, and F = I no stress.
template <class Law>
void expectSmallStrainModuli(const Law& law, double G, double K) {
  EXPECT_NEAR(law.moduli.shear, G, 1e-14 * G);
  EXPECT_NEAR(law.moduli.bulk, K, 1e-12 * K);
  const double e = 1e-6;
  const Stress up = stressAt(law, {1 + e, 0, 0, 0, 1, 0, 0, 0, 1});
  const Stress down = stressAt(law, {1 - e, 0, 0, 0, 1, 0, 0, 0, 1});
  EXPECT_NEAR((up[0] - down[0]) / (2 * e), K + 4.0 / 3.0 * G, 1e-6 * K);
  EXPECT_NEAR((up[1] - down[1]) / (2 * e), K - 2.0 / 3.0 * G, 1e-6 * K);
  for (double v : stressAt(law, {1, 0, 0, 0, 1, 0, 0, 0, 1})) EXPECT_NEAR(v, 0.0, 1e-15 * K);
}

// Deformations the rubber tests share: uniaxial and equibiaxial stretch (not stress-free
// laterally), simple shear and a general F with J != 1.
inline const Mat3 kUniaxial{1.3, 0, 0, 0, 0.9, 0, 0, 0, 0.9};
inline const Mat3 kEquibiaxial{1.2, 0, 0, 0, 1.2, 0, 0, 0, 0.72};
inline const Mat3 kShear{1, 0.4, 0, 0, 1, 0, 0, 0, 1};
inline const Mat3 kGeneral{1.1, 0.2, -0.05, 0.1, 0.95, 0.15, -0.08, 0.05, 1.05};

// At those deformations the law's stress is the derivative of W (1e-7), and its own energy()
// (used by the whole-run energy checks) is W.
template <class Law>
void expectStressOfEnergy(const Law& law, const std::function<double(const Mat3&)>& W) {
  for (const Mat3& F : {kUniaxial, kEquibiaxial, kShear, kGeneral})
    expectStress(stressAt(law, F), stressOfEnergy(W, F), 1e-7);
  EXPECT_NEAR(law.energy(kinematicsOf(kGeneral)), W(kGeneral), 1e-14);
}

// A rotation about an oblique axis (Rz(0.7) Rx(-0.4)).
inline Mat3 obliqueRotation() {
  const double a = 0.7, b = -0.4;
  const Mat3 Rz{std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1};
  const Mat3 Rx{1, 0, 0, 0, std::cos(b), -std::sin(b), 0, std::sin(b), std::cos(b)};
  return mul(Rz, Rx);
}

// Frame indifference: F -> R F turns the stress into R sigma R^T (to `tol`).
template <class Law>
void expectObjective(const Law& law, const Mat3& F, double tol) {
  const Mat3 R = obliqueRotation();
  auto full = [](const Stress& s) {
    return Mat3{s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2]};
  };
  const Mat3 turned = mul(mul(R, full(stressAt(law, F))), transpose(R));
  const Mat3 s1 = full(stressAt(law, mul(R, F)));
  for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(s1[k], turned[k], tol) << "component " << k;
}

}  // namespace crumple::testing::hyper
