// The hyperelastic rubbers (*MAT_027 Mooney-Rivlin, *MAT_031 Frazer-Nash) at a material point:
// the Cauchy stress against closed forms (simple shear of Mooney-Rivlin) and against the
// derivative of the Theory Manual's strain energy, sigma = (1/J) dW/dF F^T, taken by central
// differences on W written here from the manual (uniaxial, equibiaxial, simple shear, a general
// F); frame indifference; the least-squares fits of the LCID option; the refusals.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "hyperelastic_point.hpp"
#include "materials/hyperelastic.hpp"
#include "materials/materials.hpp"
#include "model/build.hpp"
#include "temp_dir.hpp"

namespace m = crumple::materials;

namespace {

using crumple::testing::hyper::det;
using crumple::testing::hyper::expectObjective;
using crumple::testing::hyper::expectSmallStrainModuli;
using crumple::testing::hyper::expectStress;
using crumple::testing::hyper::kEquibiaxial;
using crumple::testing::hyper::kGeneral;
using crumple::testing::hyper::kinematicsOf;
using crumple::testing::hyper::kShear;
using crumple::testing::hyper::kUniaxial;
using crumple::testing::hyper::Mat3;
using crumple::testing::hyper::mul;
using crumple::testing::hyper::Stress;
using crumple::testing::hyper::stressAt;
using crumple::testing::hyper::stressOfEnergy;
using crumple::testing::hyper::transpose;

// W of *MAT_027 (Theory Manual): invariants of C = F^T F.
std::function<double(const Mat3&)> mooneyEnergy(double A, double B, double nu) {
  const double C = 0.5 * A + B;
  const double D = (A * (5 * nu - 2) + B * (11 * nu - 5)) / (2 * (1 - 2 * nu));
  return [=](const Mat3& F) {
    const Mat3 c = mul(transpose(F), F);
    const Mat3 c2 = mul(c, c);
    const double i1 = c[0] + c[4] + c[8];
    const double i2 = 0.5 * (i1 * i1 - (c2[0] + c2[4] + c2[8]));
    const double i3 = det(c);
    return A * (i1 - 3) + B * (i2 - 3) + C * (1 / (i3 * i3) - 1) + D * (i3 - 1) * (i3 - 1);
  };
}

// U of *MAT_031 (Theory Manual) in the invariants of the Green strain of C_bar = J^-2/3 C, with
// this code's hydrostatic term f(J) = K (J - 1)^2 / 2 (frazer_nash.hpp).
std::function<double(const Mat3&)> frazerEnergy(const std::array<double, 8>& c, double K) {
  return [=](const Mat3& F) {
    const double J = det(F);
    Mat3 e = mul(transpose(F), F);
    for (int i = 0; i < 9; ++i)
      e[std::size_t(i)] = 0.5 * (std::pow(J, -2.0 / 3.0) * e[std::size_t(i)] - (i % 4 == 0));
    const Mat3 e2 = mul(e, e);
    const double i1 = e[0] + e[4] + e[8];
    const double i2 = 0.5 * (i1 * i1 - (e2[0] + e2[4] + e2[8]));
    return c[0] * i1 + c[1] * i1 * i1 + c[2] * i1 * i1 * i1 + c[3] * i1 * i1 * i1 * i1 +
           c[4] * i1 * i2 + c[5] * i1 * i1 * i2 + c[6] * i2 + c[7] * i2 * i2 +
           0.5 * K * (J - 1) * (J - 1);
  };
}

m::MooneyRivlin mooney(double A = 0.5, double B = 0.2, double nu = 0.45) {
  m::MooneyRivlin::Params p;
  p.a = A;
  p.b = B;
  p.nu = nu;
  return m::MooneyRivlin::make(p, {}, "");
}

const std::array<double, 8> kFrazer{1.0, 0.3, 0.1, 0.05, 0.2, 0.1, 0.4, 0.2};
m::FrazerNash frazer(double nu = 0.45) {
  m::FrazerNash::Params p;
  p.nu = nu;
  for (int t = 0; t < 8; ++t) p.c[t] = kFrazer[std::size_t(t)];
  return m::FrazerNash::make(p, {}, "");
}

}  // namespace

// Simple shear (J = 1) of Mooney-Rivlin, closed form (Holzapfel 2000, sec. 6.3): sigma_xy =
// 2 (A + B) gamma, sigma_xx - sigma_yy = 2 (A + B) gamma^2, sigma_yy - sigma_zz = -2 B gamma^2.
// A = 0.5, B = 0.2, gamma = 0.4: 0.56, 0.224, -0.064.
TEST(Hyperelastic, MooneyRivlinSimpleShearClosedForm) {
  const Stress s = stressAt(mooney(), kShear);
  EXPECT_NEAR(s[3], 0.56, 1e-13);
  EXPECT_NEAR(s[0] - s[1], 0.224, 1e-13);
  EXPECT_NEAR(s[1] - s[2], -0.064, 1e-13);
  EXPECT_NEAR(s[4], 0.0, 1e-15);
  EXPECT_NEAR(s[5], 0.0, 1e-15);
}

// The small-strain answer: G = 2 (A + B) = 1.4, and with nu = 0.45 K = 2G (1 + nu) /
// (3 (1 - 2 nu)) = 13.533: a stretch 1 + e gives sigma_xx = (K + 4G/3) e, sigma_yy = (K - 2G/3) e.
TEST(Hyperelastic, MooneyRivlinSmallStrainModuli) {
  expectSmallStrainModuli(mooney(), 1.4, 2.0 * 1.4 * 1.45 / (3.0 * 0.1));
}

// Uniaxial, equibiaxial, shear and a general F: the stress is the derivative of the manual's W.
TEST(Hyperelastic, StressIsTheDerivativeOfTheEnergy) {
  const auto mr = mooney();
  const auto w_mr = mooneyEnergy(0.5, 0.2, 0.45);
  const auto fn = frazer();
  const auto w_fn = frazerEnergy(kFrazer, fn.moduli.bulk);
  for (const Mat3& F : {kUniaxial, kEquibiaxial, kShear, kGeneral}) {
    expectStress(stressAt(mr, F), stressOfEnergy(w_mr, F), 1e-7);
    expectStress(stressAt(fn, F), stressOfEnergy(w_fn, F), 1e-7);
  }
  // The law's own energy (used by the whole-run energy checks) is the same function.
  EXPECT_NEAR(fn.energy(kinematicsOf(kGeneral)), w_fn(kGeneral), 1e-14);
}

// The Frazer-Nash small-strain moduli: G = C100 - C010/2 = 0.8; nu = 0.45 gives K = 7.733.
TEST(Hyperelastic, FrazerNashSmallStrainModuli) {
  expectSmallStrainModuli(frazer(), 0.8, 2.0 * 0.8 * 1.45 / (3.0 * 0.1));
}

// Frame indifference: F -> R F turns the stress into R sigma R^T (so its principal values stay).
TEST(Hyperelastic, RotationTurnsTheStress) {
  expectObjective(mooney(), kGeneral, 1e-12);
  expectObjective(frazer(), kGeneral, 1e-12);
}

// The LCID fits recover the coefficients of a curve made from known ones (nominal stress of the
// incompressible uniaxial stretch, force = P SW ST at dl = (lambda - 1) SGL).
TEST(Hyperelastic, CurveFitsRecoverTheCoefficients) {
  const double sgl = 2.0, sw = 0.5, st = 0.25;
  std::vector<double> x, y_mr, y_fn;
  for (int i = 0; i <= 20; ++i) {
    const double l = 0.7 + 0.05 * i;
    x.push_back((l - 1) * sgl);
    y_mr.push_back(2 * (l - 1 / (l * l)) * (0.5 + 0.2 / l) * sw * st);
    // Frazer-Nash with C100 = 1, C200 = 0.3, C010 = 0.4: dU/dl along F = diag(l, l^-1/2, l^-1/2).
    const double h = 1e-6;
    auto u = [](double s) {
      const double a = 0.5 * (s * s - 1), b = 0.5 * (1 / s - 1);
      const double e1 = a + 2 * b, e2 = 0.5 * (e1 * e1 - (a * a + 2 * b * b));
      return 1.0 * e1 + 0.3 * e1 * e1 + 0.4 * e2;
    };
    y_fn.push_back((u(l + h) - u(l - h)) / (2 * h) * sw * st);
  }
  m::MooneyRivlin::Params pm;
  pm.nu = 0.49;
  pm.curve = 0;
  pm.sgl = sgl, pm.sw = sw, pm.st = st;
  const auto mr = m::MooneyRivlin::make(
      pm,
      [&](int32_t) {
        return m::CurveData{7, x, y_mr};
      },
      "");
  EXPECT_NEAR(mr.a, 0.5, 1e-10);
  EXPECT_NEAR(mr.b, 0.2, 1e-10);
  m::FrazerNash::Params pf;
  pf.nu = 0.49;
  pf.curve = 0;
  pf.sgl = sgl, pf.sw = sw, pf.st = st;
  pf.c[0] = pf.c[1] = pf.c[6] = 1.0;  // flags: C100, C200, C010 in the fit
  const auto fn = m::FrazerNash::make(
      pf,
      [&](int32_t) {
        return m::CurveData{7, x, y_fn};
      },
      "");
  EXPECT_NEAR(fn.c100, 1.0, 1e-7);
  EXPECT_NEAR(fn.c200, 0.3, 1e-7);
  EXPECT_NEAR(fn.c010, 0.4, 1e-7);
  EXPECT_EQ(fn.c300, 0.0);
  EXPECT_EQ(fn.c020, 0.0);
}

// Read from the deck; refused on shells (no plane-stress update) and on the fully integrated
// hexahedron (no deformation gradient there), each naming the part and the law.
TEST(Hyperelastic, ReadOnShellsAndRefusedOnElform2) {
  crumple::testing::TempDir t("crumple_test_rubber");
  const std::string nodes =
      "*KEYWORD\n*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
      "*MAT_MOONEY-RIVLIN_RUBBER\n5,1.0e-6,0.495,0.5,0.2\n0,0,0,0\n";
  const auto model =
      crumple::model::readModel(t.write("r.k", nodes + "*SECTION_SOLID\n1,1\n*PART\nrubber\n1,1,5\n"
                                                       "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n"));
  const auto& params = std::get<m::MooneyRivlin::Params>(model.materials.at(0).law);
  EXPECT_EQ(params.a, 0.5);
  EXPECT_EQ(params.b, 0.2);
  EXPECT_EQ(params.nu, 0.495);

  // Shells take the plane-stress update (MooneyRivlinShell* tests below).
  const auto shell = t.write("s.k", nodes +
                                        "*SECTION_SHELL\n1,2\n0.1,0.1,0.1,0.1\n"
                                        "*PART\nskin\n1,1,5\n*ELEMENT_SHELL\n1,1,1,2,3,4\n");
  EXPECT_EQ(crumple::model::readModel(shell).shells.size(), 1u);
  const auto full = t.write("f.k", nodes +
                                       "*SECTION_SOLID\n1,2\n*PART\nrubber\n1,1,5\n"
                                       "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n");
  EXPECT_NE(crumple::testing::errorOf([&] { crumple::model::readModel(full); })
                .find("(*MAT_MOONEY-RIVLIN_RUBBER), a law of the deformation gradient "
                      "(hyperelastic, foam or honeycomb), which only the one-point solids"),
            std::string::npos);
}

namespace {

// The in-plane stretch V = exp(e) of the logarithmic strain e (xx, yy, xy) as a 3x3 F with
// F_33 = l3: exp of a 2x2 symmetric tensor, e^m (cosh(r) I + sinh(r) / r (e - m I)).
Mat3 stretchOf(const double (&e)[3], double l3) {
  const double mean = 0.5 * (e[0] + e[1]), h = 0.5 * (e[0] - e[1]);
  const double r = std::hypot(h, e[2]);
  const double ch = std::cosh(r), sh = r > 0.0 ? std::sinh(r) / r : 1.0, em = std::exp(mean);
  return {em * (ch + sh * h), em * sh * e[2], 0, em * sh * e[2], em * (ch - sh * h), 0, 0, 0, l3};
}

// sigma_yy = 0 in a uniaxial membrane stretch lambda along x: e_yy by bisection.
double uniaxialLateralStrain(const m::MooneyRivlin& law, double lambda) {
  double lo = -std::log(lambda), hi = 0.0;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    double s[3];
    law.planeStress({std::log(lambda), mid, 0.0}, s);
    (s[1] > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

// *MAT_027 on shells: the plane-stress stress at an in-plane strain is the solid law's at
// F = diag(V, lambda_3), with sigma_33 = 0 there.
TEST(Hyperelastic, MooneyRivlinShellIsTheSolidLawInPlaneStress) {
  const auto law = mooney(0.5, 0.2, 0.45);
  for (const auto& e :
       {std::array<double, 3>{0.2, -0.05, 0.1}, {0.3, 0.3, 0.0}, {-0.1, 0.15, -0.2}}) {
    const double ev[3] = {e[0], e[1], e[2]};
    double s[3];
    const double l3 = law.planeStress(ev, s);
    const Stress solid = stressAt(law, stretchOf(ev, l3));
    const double scale = std::fabs(s[0]) + std::fabs(s[1]) + std::fabs(s[2]);
    EXPECT_NEAR(solid[2], 0.0, 1e-12 * scale);
    EXPECT_NEAR(s[0], solid[0], 1e-12 * scale);
    EXPECT_NEAR(s[1], solid[1], 1e-12 * scale);
    EXPECT_NEAR(s[2], solid[3], 1e-12 * scale);
  }
}

// Nearly incompressible (PR = 0.49999): the membrane's Cauchy stress against the incompressible
// Mooney-Rivlin closed forms (Holzapfel 2000, sec. 6.5): equibiaxial
// sigma = 2 (lambda^2 - lambda^-4)(A + B lambda^2), uniaxial sigma = 2 (lambda^2 - 1/lambda)
// (A + B / lambda), within 1e-3; lambda_3 = 1 / (lambda_1 lambda_2).
TEST(Hyperelastic, MooneyRivlinMembraneIncompressibleLimit) {
  const double A = 0.5, B = 0.2;
  const auto law = mooney(A, B, 0.49999);
  for (double l : {1.1, 1.5, 2.0}) {
    double s[3];
    const double l3 = law.planeStress({std::log(l), std::log(l), 0.0}, s);
    const double biaxial = 2.0 * (l * l - std::pow(l, -4.0)) * (A + B * l * l);
    EXPECT_NEAR(s[0], biaxial, 1e-3 * biaxial) << "lambda " << l;
    EXPECT_NEAR(s[1], biaxial, 1e-3 * biaxial);
    EXPECT_NEAR(l3, 1.0 / (l * l), 1e-3 / (l * l));
    const double eyy = uniaxialLateralStrain(law, l);
    const double l3u = law.planeStress({std::log(l), eyy, 0.0}, s);
    const double uniaxial = 2.0 * (l * l - 1.0 / l) * (A + B / l);
    EXPECT_NEAR(s[0], uniaxial, 1e-3 * uniaxial) << "lambda " << l;
    EXPECT_NEAR(std::exp(eyy), 1.0 / std::sqrt(l), 1e-3);
    EXPECT_NEAR(l3u, 1.0 / std::sqrt(l), 1e-3);
  }
}

// The shell update accumulates the strain increments in the points' alpha fields and returns
// thickness increments whose product is the final lambda_3.
TEST(Hyperelastic, MooneyRivlinShellUpdateAccumulatesStrainAndThickness) {
  const auto law = mooney(0.5, 0.2, 0.45);
  double s[3][1] = {}, de[3][1] = {}, al[3][1] = {}, dzz[1] = {};
  m::PlaneStressPoints pts;
  pts.n = 1;
  for (int k = 0; k < 3; ++k) {
    pts.s[k] = s[k];
    pts.de[k] = de[k];
    pts.alpha[k] = al[k];
  }
  pts.de_zz = dzz;
  const int steps = 40;
  double thickness = 1.0;
  de[0][0] = 0.4 / steps;
  de[1][0] = 0.1 / steps;
  de[2][0] = -0.05 / steps;
  for (int i = 0; i < steps; ++i) {
    law.updatePlaneStress(pts);
    thickness *= 1.0 + dzz[0];
  }
  double want[3];
  const double l3 = law.planeStress({0.4, 0.1, -0.05}, want);
  EXPECT_NEAR(al[0][0], 0.4, 1e-14);
  EXPECT_NEAR(al[1][0], 0.1, 1e-14);
  EXPECT_NEAR(al[2][0], -0.05, 1e-14);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(s[k][0], want[k], 1e-12);
  EXPECT_NEAR(thickness, l3, 1e-12);
}
