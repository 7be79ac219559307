// *MAT_NULL (009) with *EOS_LINEAR_POLYNOMIAL and *EOS_GRUNEISEN at a material point, against
// the formulas of the LS-DYNA Theory Manual worked by hand (materials/eos.hpp), the energy
// update against an isentrope known in closed form, the cutoff, the viscous shear and the
// erosion limits; and the model builder's reading of *EOS and *PART EOSID with its refusals.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "materials/materials.hpp"
#include "model/build.hpp"
#include "model/serialize.hpp"
#include "temp_dir.hpp"

namespace m = crumple::materials;

namespace {

m::Eos linearPolynomial(std::array<double, 7> c, double e0 = 0.0) {
  m::Eos e;
  e.form = m::Eos::Form::LinearPolynomial;
  e.c = c;
  e.e0 = e0;
  return e;
}

m::MatNull makeNull(const m::Eos& eos, double pc = -1e30, double mu = 0.0, double terod = 0.0,
                    double cerod = 0.0) {
  m::MatNull::Params p;
  p.rho = 2.0;
  p.pc = pc;
  p.mu = mu;
  p.terod = terod;
  p.cerod = cerod;
  return std::get<m::MatNull>(m::makeLaw(p, {}, "", &eos));
}

// One point with its history (ln V, E - E0, least ln V).
struct Point {
  std::array<double, 6> s{};
  double x = 0.0, de = 0.0, x_min = 0.0;
  uint8_t failed = 0;

  void step(const m::MatNull& law, const std::array<double, 6>& d, double dt = 1e-3) {
    m::PointBatch b;
    b.n = 1;
    b.dt = dt;
    for (int k = 0; k < 6; ++k) {
      b.s[k] = &s[k];
      b.de[k] = &d[k];
    }
    b.h[0] = &x;
    b.h[1] = &de;
    b.h[2] = &x_min;
    b.failed = &failed;
    law.update(b);
  }
  // Hydrostatic straining to relative volume v in n equal steps of ln V.
  void volumeTo(const m::MatNull& law, double v, int n = 10) {
    const double d = (std::log(v) - x) / (3.0 * n);
    for (int i = 0; i < n; ++i) step(law, {d, d, d, 0, 0, 0});
  }
  double pressure() const { return -(s[0] + s[1] + s[2]) / 3.0; }
  double v() const { return std::exp(x); }
};

}  // namespace

// EOS 1 without energy terms: p = C1 mu + C2 mu^2 + C3 mu^3 in compression; the C2 term is
// dropped in tension (Theory Manual, "Linear Polynomial").
TEST(MatNull, LinearPolynomialPressureInCompressionAndTension) {
  const auto law = makeNull(linearPolynomial({0.0, 2000.0, 5000.0, 300.0, 0, 0, 0}));
  Point pt;
  pt.volumeTo(law, 0.9);
  const double mu = 1.0 / 0.9 - 1.0;  // 0.1111...
  EXPECT_NEAR(pt.v(), 0.9, 1e-14);
  // 2000 (1/9) + 5000 (1/81) + 300 (1/729) = 222.222 + 61.728 + 0.4115
  EXPECT_NEAR(pt.pressure(), 2000.0 * mu + 5000.0 * mu * mu + 300.0 * mu * mu * mu, 1e-9);
  EXPECT_NEAR(pt.pressure(), 284.3621399, 1e-6);
  EXPECT_NEAR(pt.s[0], pt.s[2], 1e-12);  // no deviator without viscosity
  pt.volumeTo(law, 1.05);
  const double mt = 1.0 / 1.05 - 1.0;
  EXPECT_NEAR(pt.pressure(), 2000.0 * mt + 300.0 * mt * mt * mt, 1e-9);  // no C2 in tension
  // The wave speed's modulus: K = C1 at mu = 0 with no energy terms.
  EXPECT_NEAR(law.moduli.bulk, 2000.0, 1e-3);
  EXPECT_EQ(law.moduli.shear, 0.0);
}

// The energy terms: C4 = C5 = gamma - 1 is the gamma-law gas p = (gamma - 1) E / V (Theory
// Manual, "Linear Polynomial"), whose isentrope dE = -p dV is E = E0 V^-(gamma - 1). Each step
// solves p_new = C4 E_new / V_new together with E_new = E_old - (p_old + p_new) / 2 dV, so the
// path converges to it at second order.
TEST(MatNull, EnergyTermFollowsTheIsentrope) {
  const double c4 = 0.4, e0 = 2.5;
  const auto law = makeNull(linearPolynomial({0, 0, 0, 0, c4, c4, 0}, e0));
  EXPECT_NEAR(law.moduli.bulk, (1.0 + c4) * c4 * e0, 1e-6);  // gamma p at the start
  Point pt;
  pt.step(law, {0, 0, 0, 0, 0, 0});  // the first update sets the initial pressure C4 E0
  EXPECT_NEAR(pt.pressure(), c4 * e0, 1e-14);
  double e_prev = e0 + pt.de, p_prev = pt.pressure();
  const double d = std::log(0.8) / (3.0 * 400);
  for (int i = 0; i < 400; ++i) {
    const double v_mid = std::exp(pt.x + 1.5 * d);
    pt.step(law, {d, d, d, 0, 0, 0});
    const double e = e0 + pt.de;
    // The step's energy balance (per unit reference volume) and the EOS, to round-off.
    EXPECT_NEAR(e - e_prev, -v_mid * 0.5 * (p_prev + pt.pressure()) * 3.0 * d, 1e-13);
    EXPECT_NEAR(pt.pressure(), c4 * e / pt.v(), 1e-13);
    e_prev = e;
    p_prev = pt.pressure();
  }
  EXPECT_NEAR(e0 + pt.de, e0 * std::pow(0.8, -c4), 1e-5);  // 2.5 * 1.09336 = 2.73341
  EXPECT_NEAR(e0 + pt.de, 2.733407, 1e-5);
}

// PC cuts the pressure in tension; blank (0) means no tension at all. Back in compression the
// pressure follows the EOS again.
TEST(MatNull, PressureCutoff) {
  const auto eos = linearPolynomial({0, 1000.0, 0, 0, 0, 0, 0});
  const auto cut = makeNull(eos, -5.0);
  Point pt;
  pt.volumeTo(cut, 1.002);  // p = 1000 (1/1.002 - 1) = -1.996: above the cutoff
  EXPECT_NEAR(pt.pressure(), 1000.0 * (1.0 / 1.002 - 1.0), 1e-9);
  pt.volumeTo(cut, 1.02);  // -19.6 < -5
  EXPECT_NEAR(pt.pressure(), -5.0, 1e-12);
  pt.volumeTo(cut, 0.99);
  EXPECT_NEAR(pt.pressure(), 1000.0 * (1.0 / 0.99 - 1.0), 1e-9);
  const auto none = makeNull(eos, 0.0);
  Point q;
  q.volumeTo(none, 1.01);
  EXPECT_EQ(q.pressure(), 0.0);
}

// The deviatoric stress is the viscous 2 MU e_dot' (Keyword Manual, *MAT_NULL): simple shear
// at the rate gamma_dot gives s_xy = MU gamma_dot and no pressure; its work goes into E.
TEST(MatNull, ViscousShear) {
  const double mu = 0.01, dt = 1e-3, gamma = 2e-4;  // gamma_dot = 0.2
  const auto law = makeNull(linearPolynomial({0, 1000.0, 0, 0, 0, 0, 0}), -1e30, mu);
  Point pt;
  pt.step(law, {0, 0, 0, 0.5 * gamma, 0, 0}, dt);
  EXPECT_NEAR(pt.s[3], mu * gamma / dt, 1e-15);  // 0.002
  EXPECT_NEAR(pt.s[3], 0.002, 1e-15);
  EXPECT_EQ(pt.pressure(), 0.0);
  pt.step(law, {0, 0, 0, 0.5 * gamma, 0, 0}, dt);
  // Work: the first step (0 + 0.002) / 2 gamma, the second 0.002 gamma (V = 1).
  EXPECT_NEAR(pt.de, 0.001 * gamma + 0.002 * gamma, 1e-18);
  // A uniaxial strain rate e_zz: deviator 2 MU (e_zz - e_zz / 3) on zz, -2 MU e_zz / 3 across.
  Point u;
  u.step(law, {0, 0, 1e-6, 0, 0, 0}, dt);
  const double p = 1000.0 * (std::exp(-1e-6) - 1.0);
  EXPECT_NEAR(u.s[2], 2.0 * mu * (2.0 / 3.0) * 1e-3 - p, 1e-12);
  EXPECT_NEAR(u.s[0], -2.0 * mu * (1.0 / 3.0) * 1e-3 - p, 1e-12);
}

// EOS 4 (Theory Manual, "Gruneisen"): copper-like constants (g, cm, us: rho0 8.93, C 0.394,
// S1 1.489, GAMAO 2.02, A 0.47). Compressed to mu = 0.1 and expanded to mu = -0.05, the
// pressure is the Hugoniot-based form plus (GAMAO + A mu) E, with the E the point reached.
TEST(MatNull, GruneisenCompressionAndExpansion) {
  m::Eos eos;
  eos.form = m::Eos::Form::Gruneisen;
  eos.c = {0.394, 1.489, 0.0, 0.0, 2.02, 0.47, 0.0};
  m::MatNull::Params p;
  p.rho = 8.93;
  p.pc = -1e30;
  const auto law = std::get<m::MatNull>(m::makeLaw(p, {}, "", &eos));
  EXPECT_NEAR(law.moduli.bulk, 8.93 * 0.394 * 0.394, 1e-5);  // rho0 C^2 = 1.38626
  Point pt;
  pt.volumeTo(law, 1.0 / 1.1, 50);
  const double mu = 0.1, e = pt.de;
  EXPECT_GT(e, 0.0);  // compression did work
  // 1.38626 * 0.1 (1 - 0.001 - 0.00235) / (1 - 0.0489)^2 = 0.138626 * 0.99665 / 0.904591
  const double hugoniot = 8.93 * 0.394 * 0.394 * mu * (1.0 + (1.0 - 1.01) * mu - 0.235 * mu * mu) /
                          std::pow(1.0 - 0.489 * mu, 2);
  EXPECT_NEAR(hugoniot, 0.152733, 1e-6);
  EXPECT_NEAR(pt.pressure(), hugoniot + (2.02 + 0.47 * mu) * e, 1e-12);
  pt.volumeTo(law, 1.0 / 0.95, 50);
  const double me = -0.05;
  EXPECT_NEAR(pt.pressure(), 8.93 * 0.394 * 0.394 * me + (2.02 + 0.47 * me) * pt.de, 1e-12);
}

// TEROD and CEROD erode the point past those relative volumes, and only then.
TEST(MatNull, ErosionOnRelativeVolume) {
  const auto law = makeNull(linearPolynomial({0, 1000.0, 0, 0, 0, 0, 0}), -1e30, 0.0, 1.1, 0.9);
  Point a;
  a.volumeTo(law, 1.09);
  EXPECT_EQ(a.failed, 0);
  a.volumeTo(law, 1.11);
  EXPECT_EQ(a.failed, 1);
  Point b;
  b.volumeTo(law, 0.91);
  EXPECT_EQ(b.failed, 0);
  b.volumeTo(law, 0.89);
  EXPECT_EQ(b.failed, 1);
}

// A law with its own pressure response takes no equation of state; an EOS without stiffness
// at the initial state gives no wave speed.
TEST(MatNull, MakeLawRefusals) {
  const auto eos = linearPolynomial({0, 1000.0, 0, 0, 0, 0, 0});
  EXPECT_THROW(m::makeLaw(m::Elastic::Params{200.0, 0.3}, {}, "at: ", &eos),
               crumple::util::InputError);
  m::MatNull::Params p;
  p.rho = 1.0;
  const auto soft = linearPolynomial({0, 0, 0, 0, 0, 0, 0});
  EXPECT_THROW(m::makeLaw(p, {}, "at: ", &soft), crumple::util::InputError);
  // Without an EOS (null shells and beams): the moduli of YM and PR, for contact.
  p.E = 210.0;
  p.nu = 0.3;
  const auto shell = std::get<m::MatNull>(m::makeLaw(p, {}, ""));
  EXPECT_NEAR(m::youngOf(shell.moduli), 210.0, 1e-12);
  EXPECT_TRUE(m::massOnlyStructures(p));
  EXPECT_TRUE(m::usesEos(p));
  EXPECT_FALSE(m::usesEos(m::Elastic::Params{200.0, 0.3}));
}

namespace {

const std::string kHex =
    "*KEYWORD\n*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
    "*SECTION_SOLID\n1,1\n*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n";

}  // namespace

// *EOS_LINEAR_POLYNOMIAL and *EOS_GRUNEISEN read into the Model, *PART EOSID resolved, the
// whole carried by the bytes the model travels as; and the refusals, named where written.
TEST(MatNull, ModelReadsEquationsOfStateAndPartEosid) {
  crumple::testing::TempDir t;
  const std::string deck = kHex +
                           "*MAT_NULL\n1,1.0e-6,-1.0e-4,1.0e-9,1.2,0.8\n"
                           "*EOS_LINEAR_POLYNOMIAL\n7,0.0,2.2,9.54,14.57,0.28,0.28\n0.0,0.0\n"
                           "*EOS_GRUNEISEN_TITLE\ncopper\n8,0.394,1.489,0,0,2.02,0.47,0.1\n"
                           "*PART\nwater\n1,1,1,7\n*END\n";
  const auto model = crumple::model::readModel(t.write("w.k", deck));
  ASSERT_EQ(model.eos.size(), 2u);
  EXPECT_EQ(model.eos[0].id, 7);
  EXPECT_EQ(model.eos[0].eos.form, m::Eos::Form::LinearPolynomial);
  EXPECT_EQ(model.eos[0].eos.c[3], 14.57);
  EXPECT_EQ(model.eos[0].eos.v0, 1.0);  // 0: the default
  EXPECT_EQ(model.eos[1].title, "copper");
  EXPECT_EQ(model.eos[1].eos.form, m::Eos::Form::Gruneisen);
  EXPECT_EQ(model.eos[1].eos.e0, 0.1);
  EXPECT_EQ(model.parts.at(0).eos, 0);
  const auto& params = std::get<m::MatNull::Params>(model.materials.at(0).law);
  EXPECT_EQ(params.pc, -1.0e-4);
  EXPECT_EQ(params.terod, 1.2);
  const auto r = crumple::model::deserialize(crumple::model::serialize(model));
  ASSERT_EQ(r.eos.size(), 2u);
  EXPECT_EQ(r.eos[1].eos.c, model.eos[1].eos.c);
  EXPECT_EQ(r.eos[1].where.str(), model.eos[1].where.str());
  EXPECT_EQ(r.parts.at(0).eos, 0);

  const auto no_eos = t.write("n.k", kHex + "*MAT_NULL\n1,1.0e-6\n*PART\nwater\n1,1,1\n*END\n");
  EXPECT_EQ(crumple::testing::errorOf([&] { crumple::model::readModel(no_eos); }),
            no_eos.string() +
                ":19: *PART card 2 field 4 (EOSID): part 1 has solid elements and material 1 "
                "(*MAT_NULL), which needs an equation of state (*EOS_LINEAR_POLYNOMIAL, "
                "*EOS_GRUNEISEN, *EOS_TABULATED_COMPACTION, *EOS_TABULATED)");
  const auto elastic =
      t.write("e.k", kHex +
                         "*MAT_ELASTIC\n1,7.8e-6,210.0,0.3\n*EOS_LINEAR_POLYNOMIAL\n7,0,2.2\n"
                         "*PART\nsteel\n1,1,1,7\n*END\n");
  EXPECT_EQ(crumple::testing::errorOf([&] { crumple::model::readModel(elastic); }),
            elastic.string() +
                ":21: *PART card 2 field 4 (EOSID): part 1 names equation of state 7 but "
                "material 1 (*MAT_ELASTIC) has its own pressure response and cannot use one");
  const auto undefined =
      t.write("u.k", kHex + "*MAT_NULL\n1,1.0e-6\n*PART\nwater\n1,1,1,9\n*END\n");
  EXPECT_NE(crumple::testing::errorOf([&] {
              crumple::model::readModel(undefined);
            }).find("(EOSID): equation of state 9 is not defined"),
            std::string::npos);
  const auto bad_pc =
      t.write("p.k", kHex +
                         "*MAT_NULL\n1,1.0e-6,5.0\n*EOS_LINEAR_POLYNOMIAL\n7,0,2.2\n"
                         "*PART\nwater\n1,1,1,7\n*END\n");
  EXPECT_NE(crumple::testing::errorOf([&] {
              crumple::model::readModel(bad_pc);
            }).find("(PC): the pressure cutoff is a tension limit"),
            std::string::npos);
}
