// *MAT_POWER_LAW_PLASTICITY (018) at a material point of each family against the power law
// sigma_y = k (eps_yp + eps_p)^n worked by hand (Keyword Manual vol. II, *MAT_018): the strain at
// yield of each SIGY form, the first yield in uniaxial stress, the return on the surface, the
// additive split and the plastic work in uniaxial stress, the Cowper-Symonds factor, the shell
// and beam returns, erosion at EPSF; and the deck reader's refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "material_point.hpp"
#include "materials/materials.hpp"
#include "model/build.hpp"
#include "temp_dir.hpp"

namespace m = crumple::materials;
using crumple::testing::mp::ShellPoint;
using crumple::testing::mp::SolidPoint;

namespace {

// Steel-like, mm s t MPa: E 210 GPa, k 500 MPa, n 0.2, so the elastic line meets k eps^n at
// eps_yp = (E / k)^(1 / (n - 1)) = 420^-1.25 = 5.2594e-4, a yield stress of 110.45 MPa.
constexpr double kE = 210000.0, kNu = 0.3, kK = 500.0, kN = 0.2;

m::PowerLaw::Params params(double sigy = 0.0, double src = 0.0, double srp = 0.0,
                           double epsf = 0.0) {
  m::PowerLaw::Params p;
  p.E = kE;
  p.nu = kNu;
  p.k = kK;
  p.n = kN;
  p.sigy = sigy;
  p.src = src;
  p.srp = srp;
  p.epsf = epsf;
  return p;
}

m::Law makeLaw(const m::PowerLaw::Params& p) {
  return m::makeLaw(p, {}, "");
}

// The power law written out, and its plastic work from eps_p = 0 to e.
double flow(double e, double eps0) {
  return kK * std::pow(eps0 + e, kN);
}
double plasticWork(double e, double eps0) {
  return kK / (kN + 1.0) * (std::pow(eps0 + e, kN + 1.0) - std::pow(eps0, kN + 1.0));
}

}  // namespace

// The strain at yield of each SIGY form (Keyword Manual, *MAT_018 remarks).
TEST(PowerLaw, StrainAtYieldOfEachSigyForm) {
  EXPECT_NEAR(m::PowerLaw::yieldStrain(params()), std::pow(420.0, -1.25), 1e-18);
  EXPECT_NEAR(m::PowerLaw::yieldStrain(params()), 5.2594e-4, 1e-8);
  EXPECT_EQ(m::PowerLaw::yieldStrain(params(0.01)), 0.01);
  EXPECT_NEAR(m::PowerLaw::yieldStrain(params(200.0)), std::pow(0.4, 5.0), 1e-16);
  auto p = params();
  p.n = 1.0;  // linear hardening never meets the elastic line
  EXPECT_TRUE(std::isnan(m::PowerLaw::yieldStrain(p)));
  EXPECT_THROW(makeLaw(p), std::exception);
}

// Uniaxial stress, quasi-static: elastic (sigma = E eps) up to eps_yp, then the axial stress is
// the power law at the plastic strain to round-off, the axial strain is sigma / E + eps_p, and
// the plastic work summed by the trapezoidal rule is k / (n + 1) [(eps_yp + e)^(n+1) - eps_yp^
// (n+1)].
TEST(PowerLaw, UniaxialStressYieldHardeningAndPlasticWork) {
  const m::Law law = makeLaw(params());
  const double eps0 = std::pow(420.0, -1.25), dx = 2e-5;
  SolidPoint pt;
  double strain = 0.0, work = 0.0;
  bool yielded = false;
  for (int i = 0; i < 5000; ++i) {
    const double e_old = pt.eps_p, s_old = pt.s[0];
    pt.uniaxialStep(law, dx, 1.0);
    strain += dx;
    if (pt.eps_p == 0.0) {
      ASSERT_LT(strain, eps0 * (1.0 + 1e-9));
      EXPECT_NEAR(pt.s[0], kE * strain, 1e-9 * pt.s[0]);
      continue;
    }
    if (!yielded) {
      // The step that crosses eps_yp.
      EXPECT_GT(strain, eps0);
      EXPECT_LT(strain - dx, eps0);
      yielded = true;
      work += 0.5 * (flow(0.0, eps0) + pt.s[0]) * pt.eps_p;
      continue;
    }
    work += 0.5 * (s_old + pt.s[0]) * (pt.eps_p - e_old);
    EXPECT_NEAR(pt.s[0], flow(pt.eps_p, eps0), 1e-11 * pt.s[0]);
    EXPECT_NEAR(pt.s[1], 0.0, 1e-8);
  }
  EXPECT_GT(pt.eps_p, 0.09);
  EXPECT_NEAR(strain, pt.s[0] / kE + pt.eps_p, 1e-9);
  EXPECT_NEAR(work, plasticWork(pt.eps_p, eps0), 1e-5 * work);
}

// The return lands on the surface for large steps and from the virgin state, in pure shear:
// sqrt(3) tau = k (eps_yp + eps_p)^n to 1e-13.
TEST(PowerLaw, ReturnLandsOnTheSurface) {
  const m::Law law = makeLaw(params(200.0));
  const double eps0 = std::pow(0.4, 5.0);
  SolidPoint pt;
  for (double dxy : {3e-2, 1e-5, 1e-3, 8e-2}) {
    pt.step(law, {0, 0, 0, dxy, 0, 0}, 1.0);
    EXPECT_GT(pt.eps_p, 0.0);
    EXPECT_NEAR(pt.mises(), flow(pt.eps_p, eps0), 1e-13 * pt.mises());
  }
}

// Cowper-Symonds (SRC 40 /s, SRP 5) in pure shear at 100 /s: the von Mises stress on the
// surface is 1 + (100 / 40)^(1/5) = 2.2011 times the static flow stress; the solid, the shell
// (in-plane shear) and the truss (axial, at the same effective rate) agree.
TEST(PowerLaw, CowperSymondsScalesTheYieldStressInEachFamily) {
  const m::Law law = makeLaw(params(0.0, 40.0, 5.0));
  const double eps0 = std::pow(420.0, -1.25);
  const double rf = 1.0 + std::pow(100.0 / 40.0, 0.2);
  EXPECT_NEAR(rf, 2.2011, 1e-4);
  const double dxy = 2e-4, dt = 2.0 * dxy / (std::sqrt(3.0) * 100.0);
  SolidPoint solid;
  ShellPoint shell;
  for (int i = 0; i < 200; ++i) {
    solid.step(law, {0, 0, 0, dxy, 0, 0}, dt);
    shell.step(law, 0.0, 0.0, dxy, dt);
  }
  EXPECT_GT(solid.eps_p, 0.02);
  EXPECT_NEAR(solid.mises(), rf * flow(solid.eps_p, eps0), 1e-12 * solid.mises());
  EXPECT_NEAR(shell.mises(), rf * flow(shell.eps_p, eps0), 1e-12 * shell.mises());
  EXPECT_NEAR(shell.eps_p, solid.eps_p, 1e-12);
  EXPECT_NEAR(shell.s[2], solid.s[3], 1e-9 * solid.s[3]);
  // A truss pulled at 100 /s.
  const m::FibreLaw fl = m::fibreLawOf(law);
  m::FibrePoint p;
  const double de = 2e-4;
  for (int i = 0; i < 300; ++i) m::updateFibre(fl, p, de, 0.0, 0.0, de / 100.0);
  EXPECT_GT(p.eps_p, 0.05);
  EXPECT_NEAR(p.sig, rf * flow(p.eps_p, eps0), 1e-11 * p.sig);
  EXPECT_NEAR(300 * de, p.sig / kE + p.eps_p, 1e-12);
}

// Plane stress in uniaxial tension (s_yy = 0 by secant on de_yy): s_xx follows the power law,
// and the thickness strain makes the plastic flow incompressible.
TEST(PowerLaw, ShellUniaxialStressFollowsThePowerLaw) {
  const m::Law law = makeLaw(params());
  const double eps0 = std::pow(420.0, -1.25), dx = 5e-4;
  ShellPoint pt;
  double ezz = 0.0, eyy = 0.0;
  for (int i = 0; i < 100; ++i) {
    eyy += pt.uniaxialStep(law, dx, 1.0);
    ezz += pt.de_zz;
  }
  EXPECT_GT(pt.eps_p, 0.04);
  EXPECT_NEAR(pt.s[0], flow(pt.eps_p, eps0), 1e-11 * pt.s[0]);
  // Lateral strains: elastic -nu sigma / E and plastic -eps_p / 2 each.
  EXPECT_NEAR(eyy, -kNu * pt.s[0] / kE - 0.5 * pt.eps_p, 1e-9);
  EXPECT_NEAR(ezz, -kNu * pt.s[0] / kE - 0.5 * pt.eps_p, 1e-9);
}

// Erosion at EPSF: the flag rises in the step in which eps_p reaches EPSF (solid and shell).
TEST(PowerLaw, FailureAtEpsf) {
  const m::Law law = makeLaw(params(0.0, 0.0, 0.0, 0.05));
  EXPECT_EQ(m::failureStrainOf(law), 0.05);
  SolidPoint solid;
  ShellPoint shell;
  for (int i = 0; i < 100 && !solid.failed; ++i) {
    const double before = solid.eps_p;
    solid.step(law, {0, 0, 0, 1e-3, 0, 0}, 1.0);
    shell.step(law, 0.0, 0.0, 1e-3, 1.0);
    EXPECT_EQ(solid.failed, shell.failed);
    if (solid.failed) {
      EXPECT_LT(before, 0.05);
      EXPECT_GE(solid.eps_p, 0.05);
    }
  }
  EXPECT_EQ(solid.failed, 1);
}

// The reader: cards into Params; VP = 1, SIGY = 0 with N >= 1 and a non-positive K refused,
// naming file, line and field.
TEST(PowerLaw, DeckReadingAndRefusals) {
  crumple::testing::TempDir t;
  const std::string hex =
      "*KEYWORD\n*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
      "*SECTION_SOLID\n1,1\n*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n*PART\nbar\n1,1,1\n";
  auto deck = [&](const std::string& name, const std::string& mat) {
    return t.write(name, hex + mat + "*END\n");
  };
  const auto ok = deck("ok.k",
                       "*MAT_POWER_LAW_PLASTICITY\n1,7.85e-9,210000,0.3,500,0.2,40,5\n"
                       "0,0,0.3\n");
  const auto model = crumple::model::readModel(ok);
  const auto& p = std::get<m::PowerLaw::Params>(model.materials.at(0).law);
  EXPECT_EQ(p.k, 500.0);
  EXPECT_EQ(p.n, 0.2);
  EXPECT_EQ(p.src, 40.0);
  EXPECT_EQ(p.srp, 5.0);
  EXPECT_EQ(p.epsf, 0.3);
  auto error = [&](const std::string& name, const std::string& mat) {
    const auto f = deck(name, mat);
    return crumple::testing::errorOf([&] { crumple::model::readModel(f); });
  };
  EXPECT_NE(error("vp.k", "*MAT_018\n1,7.85e-9,210000,0.3,500,0.2\n0,1\n")
                .find("vp.k:20: *MAT_018 card 2 field 2 (VP): only VP = 0"),
            std::string::npos);
  EXPECT_NE(error("n.k", "*MAT_018\n1,7.85e-9,210000,0.3,500,1.0\n")
                .find("(SIGY): with N >= 1 the elastic line meets"),
            std::string::npos);
  EXPECT_NE(error("k.k", "*MAT_018\n1,7.85e-9,210000,0.3,0,0.2\n").find("(K): the strength"),
            std::string::npos);
}
