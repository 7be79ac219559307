// *MAT_STRAIN_RATE_DEPENDENT_PLASTICITY (019) at a material point of each family against
// sigma_y = sigma_0(rate) + Ep eps_p, Ep = E ETAN / (E - ETAN), worked by hand (Keyword Manual
// vol. II, *MAT_019): the yield stress below, between and beyond the rates of LC1 in pure shear
// (solid and shell) and in a truss, the uniaxial slope ETAN after yield, and the reader's
// refusals of LC2, LC3, LC4 and VP = 1.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "material_point.hpp"
#include "materials/materials.hpp"
#include "model/build.hpp"
#include "temp_dir.hpp"

namespace m = crumple::materials;
using crumple::testing::mp::ShellPoint;
using crumple::testing::mp::SolidPoint;

namespace {

// mm s t MPa: E 200 GPa, ETAN 2 GPa (Ep = 2020.2 MPa); LC1 200, 250, 400 MPa at 0, 10, 100 /s.
constexpr double kE = 200000.0, kNu = 0.3, kEtan = 2000.0;
const std::vector<double> kRate{0.0, 10.0, 100.0}, kSig{200.0, 250.0, 400.0};

m::Law makeLaw() {
  m::StrainRatePlasticity::Params p;
  p.E = kE;
  p.nu = kNu;
  p.etan = kEtan;
  p.lc1 = 0;
  return m::makeLaw(
      p,
      [](int32_t) {
        return m::CurveData{7, kRate, kSig};
      },
      "");
}

// LC1 written out: linear between its points, its end slopes beyond them.
double sigma0(double r) {
  if (r < 10.0) return 200.0 + 5.0 * r;
  return 250.0 + 150.0 / 90.0 * (r - 10.0);
}
double yield(double e, double r) {
  return sigma0(r) + kE * kEtan / (kE - kEtan) * e;
}

}  // namespace

// Pure shear at 4, 40 and 200 /s (below the middle point, between, beyond the last: the end
// slope): the von Mises stress on the surface is sigma_0(rate) + Ep eps_p to round-off in the
// solid and the shell, which agree.
TEST(StrainRatePlasticity, YieldStressAtTheRateInSolidAndShell) {
  const m::Law law = makeLaw();
  EXPECT_NEAR(sigma0(40.0), 300.0, 1e-12);
  EXPECT_NEAR(sigma0(200.0), 566.6666666666667, 1e-9);
  for (const double rate : {4.0, 40.0, 200.0}) {
    SCOPED_TRACE(rate);
    const double dxy = 2e-4, dt = 2.0 * dxy / (std::sqrt(3.0) * rate);
    SolidPoint solid;
    ShellPoint shell;
    for (int i = 0; i < 150; ++i) {
      solid.step(law, {0, 0, 0, dxy, 0, 0}, dt);
      shell.step(law, 0.0, 0.0, dxy, dt);
      if (solid.eps_p == 0.0) {
        EXPECT_LT(solid.mises(), sigma0(rate) * (1.0 + 1e-12));
        continue;
      }
      EXPECT_NEAR(solid.mises(), yield(solid.eps_p, rate), 1e-12 * solid.mises());
      EXPECT_NEAR(shell.mises(), yield(shell.eps_p, rate), 1e-12 * shell.mises());
    }
    EXPECT_GT(solid.eps_p, 0.02);
    EXPECT_NEAR(shell.eps_p, solid.eps_p, 1e-12);
  }
}

// A truss pulled at 40 /s: yield at sigma_0(40) = 300 MPa, then the slope dsigma / deps is ETAN.
TEST(StrainRatePlasticity, TrussYieldsAtTheRateAndHardensWithEtan) {
  const m::Law law = makeLaw();  // the fibre law views its curve
  const m::FibreLaw fl = m::fibreLawOf(law);
  m::FibrePoint p;
  const double de = 1e-4, dt = de / 40.0;
  double strain = 0.0, s_prev = 0.0;
  for (int i = 0; i < 400; ++i) {
    const double e_prev = p.eps_p;
    s_prev = p.sig;
    m::updateFibre(fl, p, de, 0.0, 0.0, dt);
    strain += de;
    if (e_prev > 0.0) {
      EXPECT_NEAR((p.sig - s_prev) / de, kEtan, 1e-6 * kEtan);
    }
  }
  EXPECT_NEAR(p.sig, yield(p.eps_p, 40.0), 1e-11 * p.sig);
  EXPECT_NEAR(p.sig, 300.0 + kEtan * (strain - 300.0 / kE), 1e-9 * p.sig);
}

// The reader: LC1 into a curve; LC2, LC3, LC4 and VP = 1 refused naming the field, a missing
// LC1 an input error.
TEST(StrainRatePlasticity, DeckReadingAndRefusals) {
  crumple::testing::TempDir t;
  const std::string hex =
      "*KEYWORD\n*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
      "*SECTION_SOLID\n1,1\n*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n*PART\nbar\n1,1,1\n"
      "*DEFINE_CURVE\n7\n0,200\n10,250\n100,400\n";
  auto error = [&](const std::string& name, const std::string& mat) {
    const auto f = t.write(name, hex + mat + "*END\n");
    return crumple::testing::errorOf([&] { crumple::model::readModel(f); });
  };
  const auto ok =
      t.write("ok.k", hex + "*MAT_019\n1,7.85e-9,200000,0.3\n7,2000,0,0,0,1e-9\n*END\n");
  const auto model = crumple::model::readModel(ok);
  const auto& p = std::get<m::StrainRatePlasticity::Params>(model.materials.at(0).law);
  EXPECT_EQ(p.etan, 2000.0);
  EXPECT_EQ(p.tdel, 1e-9);
  EXPECT_GE(p.lc1, 0);
  const std::string card1 = "*MAT_STRAIN_RATE_DEPENDENT_PLASTICITY\n1,7.85e-9,200000,0.3\n";
  EXPECT_NE(error("lc2.k", card1 + "7,2000,8\n").find("card 2 field 3 (LC2): Young's modulus"),
            std::string::npos);
  EXPECT_NE(error("lc3.k", card1 + "7,2000,0,8\n").find("card 2 field 4 (LC3): the tangent"),
            std::string::npos);
  EXPECT_NE(error("lc4.k", card1 + "7,2000,0,0,8\n").find("card 2 field 5 (LC4): failure"),
            std::string::npos);
  EXPECT_NE(error("vp.k", "*MAT_019\n1,7.85e-9,200000,0.3,1\n7,2000\n")
                .find("card 1 field 5 (VP): only VP = 0"),
            std::string::npos);
  EXPECT_NE(error("lc1.k", card1 + "0,2000\n").find("(LC1): the curve of yield stress"),
            std::string::npos);
}
