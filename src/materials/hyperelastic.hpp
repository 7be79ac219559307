// What the hyperelastic (rubber) laws share: the left Cauchy-Green tensor B = F F^T of a point
// and its invariants, the Cauchy stress of a strain energy W(I1, I2, I3) of those invariants,
// and the least-squares fit of strain-energy coefficients to a uniaxial test curve (LS-DYNA
// Keyword Manual vol. II, *MAT_027 and *MAT_031, SGL SW ST LCID; Theory Manual, "Material
// Model 27: Mooney-Rivlin Rubber" and "Material Model 31: Frazer-Nash Rubber").
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "materials/law.hpp"

namespace crumple::materials {

// B = F F^T (Voigt: xx yy zz xy yz zx), J = det F and the invariants of B (equal to those of
// C = F^T F): I1 = tr B, I2 = (I1^2 - B:B) / 2, I3 = J^2.
struct LeftCauchyGreen {
  double b[6] = {};
  double J = 1.0, I1 = 3.0, I2 = 3.0, I3 = 1.0;
};
LeftCauchyGreen leftCauchyGreen(const PointBatch& p, int l);

// B^2 in Voigt order.
void squareOf(const double (&b)[6], double (&b2)[6]);

// The Cauchy stress of W(I1, I2, I3) with W_k = dW/dIk (Holzapfel, "Nonlinear Solid Mechanics",
// 2000, eq. 6.29 with the invariants of B; LS-DYNA Theory Manual, "Hyperelastic Materials"):
//   sigma = 2/J [ (W1 + I1 W2) B - W2 B^2 + I3 W3 I ].
void invariantStress(const LeftCauchyGreen& k, double w1, double w2, double w3, PointBatch& p,
                     int l);

// A uniaxial test as the curve-fit options give it: force vs change in gauge length (LCID),
// with the specimen's gauge length, width and thickness (SGL, SW, ST). Stretch
// lambda = 1 + dl / SGL, nominal stress P = force / (SW ST).
struct UniaxialTest {
  std::vector<double> stretch, nominal;
};
UniaxialTest uniaxialTest(const std::string& at, const CurveData& c, double sgl, double sw,
                          double st);

// The least-squares coefficients c minimising sum_i (sum_k c_k g_k(lambda_i) - P_i)^2 over the
// test's points, where g_k(lambda) is the nominal stress of the term k with unit coefficient
// (normal equations, Gaussian elimination with partial pivoting). util::InputError (prefixed
// by `at`) when the terms cannot be told apart by the points.
std::vector<double> fitUniaxial(const std::string& at, const UniaxialTest& test,
                                const std::vector<std::function<double(double)>>& terms);

}  // namespace crumple::materials
