// *EOS_TABULATED (EOS 9) and *EOS_TABULATED_COMPACTION (EOS 8) at a material point of
// *MAT_NULL and *MAT_ELASTIC_PLASTIC_HYDRO, against the table interpolated by hand (a reference
// written here from the deck's points, in the deck's descending order): the pressure at and
// between the points and past both ends, the energy term GAMA T(eps_V) E, EOS 8's unloading
// and reloading along K(eps_min), the wave-speed modulus; *MAT_SOIL_AND_FOAM with the same
// curve and KUN gives EOS 8's pressures; and the builder's reading of the cards with its
// refusals, named where written.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "material_point.hpp"
#include "materials/materials.hpp"
#include "model/build.hpp"
#include "model/serialize.hpp"
#include "temp_dir.hpp"

namespace m = crumple::materials;

namespace {

// The table as a deck gives it (EV = ln V descending): slopes of C in -eps_V 1000, 600, 2200.
const std::vector<double> kEv{0.0, -0.05, -0.1, -0.2}, kC{0.0, 50.0, 80.0, 300.0},
    kT{1.0, 1.2, 1.5, 2.0}, kK{1500.0, 2000.0, 2500.0, 5000.0};

// Linear interpolation of a column in the deck's descending EV, the end segments continued.
double ref(const std::vector<double>& y, double e) {
  std::size_t k = 0;  // segment [EV_k, EV_k+1] holding e, clamped to the first and last
  while (k + 2 < kEv.size() && e < kEv[k + 1]) ++k;
  return y[k] + (y[k + 1] - y[k]) * (e - kEv[k]) / (kEv[k + 1] - kEv[k]);
}
// EOS 8's unloading modulus: K interpolated, held at its end values past the table.
double refK(double e) {
  return ref(kK, std::clamp(e, kEv.back(), kEv.front()));
}

m::Eos table(m::Eos::Form form, double gamma = 0.0, double e0 = 0.0, double v0 = 1.0) {
  m::Eos eos;
  eos.form = form;
  eos.e0 = e0;
  eos.v0 = v0;
  m::EosTable& t = eos.table;
  t.n = static_cast<int32_t>(kEv.size());
  t.gamma = gamma;
  for (std::size_t i = 0; i < kEv.size(); ++i) {  // stored ascending in ln V
    const std::size_t j = kEv.size() - 1 - i;
    t.ln_v[j] = kEv[i];
    t.c[j] = kC[i];
    t.t[j] = kT[i];
    t.k[j] = kK[i];
  }
  return eos;
}

m::Law makeNull(const m::Eos& eos, double pc = -1e30) {
  m::MatNull::Params p;
  p.rho = 2.0;
  p.pc = pc;
  return m::makeLaw(p, {}, "", &eos);
}

using Point = crumple::testing::mp::SolidPoint;

double pressureOf(const Point& pt) {
  return -(pt.s[0] + pt.s[1] + pt.s[2]) / 3.0;
}
// A hydrostatic step of volumetric strain d (tr(de) = d).
void squeeze(Point& pt, const m::Law& law, double d) {
  pt.step(law, {d / 3.0, d / 3.0, d / 3.0, 0, 0, 0}, 1e-3);
}

// 1e-9 relative to the pressure, or to 1 near zero pressure.
void expectPressure(double got, double want, const std::string& where) {
  EXPECT_NEAR(got, want, 1e-9 * std::max(1.0, std::abs(want))) << where;
}

}  // namespace

// EOS 9 without energy: p = C(eps_V) at the points, linearly between them, along the end
// segments past them (compression past EV4, tension past EV1), and the same values on the way
// back (nonlinear elastic).
TEST(EosTabulated, PressureAtAndBetweenThePointsBothWays) {
  const auto law = makeNull(table(m::Eos::Form::Tabulated));
  Point pt;
  std::vector<double> loading;
  for (int i = 1; i <= 30; ++i) {  // eps_V to -0.30 by -0.01 (the points at -0.05, -0.1, -0.2)
    squeeze(pt, law, -0.01);
    const double e = -0.01 * i;
    EXPECT_NEAR(pt.h[0], e, 1e-15);
    expectPressure(pressureOf(pt), ref(kC, e), "loading to " + std::to_string(e));
    loading.push_back(pressureOf(pt));
  }
  EXPECT_NEAR(loading[4], 50.0, 1e-9);    // EV2
  EXPECT_NEAR(loading[9], 80.0, 1e-9);    // EV3
  EXPECT_NEAR(loading[14], 190.0, 1e-9);  // midway between EV3 and EV4
  EXPECT_NEAR(loading[19], 300.0, 1e-9);  // EV4
  EXPECT_NEAR(loading[29], 520.0, 1e-9);  // past EV4: 300 + 2200 x 0.1
  for (int i = 29; i >= -3; --i) {        // back, and into tension past EV1
    squeeze(pt, law, 0.01);
    const double e = -0.01 * i;
    expectPressure(pressureOf(pt), ref(kC, e), "unloading to " + std::to_string(e));
    if (i >= 1) {
      EXPECT_NEAR(pressureOf(pt), loading[std::size_t(i) - 1], 1e-9);
    }
  }
  EXPECT_NEAR(pressureOf(pt), -30.0, 1e-9);  // tension: first segment's slope, -1000 x 0.03
  EXPECT_NEAR(pt.h[2], -0.30, 1e-14);        // the least ln(V / V0), kept by every form
}

// GAMA T(eps_V) E: the first update at the initial state gives C(0) + GAMA T(0) E0; along a
// compression the pressure is C + GAMA T E with the energy of the time-centred update, and the
// step's energy balance holds to round-off; back at V0 the energy is E0 again (reversible).
TEST(EosTabulated, EnergyTermAndReversibleCycle) {
  const double gamma = 0.5, e0 = 10.0;
  const auto law = makeNull(table(m::Eos::Form::Tabulated, gamma, e0));
  Point pt;
  squeeze(pt, law, 0.0);
  EXPECT_NEAR(pressureOf(pt), gamma * 1.0 * e0, 1e-13);  // C(0) = 0, T(0) = 1
  double e_prev = e0, p_prev = pressureOf(pt), peak = 0.0;
  auto step = [&](double d) {
    const double v_mid = std::exp(pt.h[0] + 0.5 * d);
    squeeze(pt, law, d);
    const double e = e0 + pt.h[1], x = pt.h[0];
    EXPECT_NEAR(e - e_prev, -v_mid * 0.5 * (p_prev + pressureOf(pt)) * d, 1e-12);
    expectPressure(pressureOf(pt), ref(kC, x) + gamma * ref(kT, x) * e, "at " + std::to_string(x));
    e_prev = e;
    p_prev = pressureOf(pt);
    peak = std::max(peak, e - e0);
  };
  for (int i = 0; i < 250; ++i) step(-0.001);
  EXPECT_GT(peak, 25.0);  // the compression work per unit reference volume
  // At ln V = -0.25, past EV4: C = 300 + 2200 x 0.05, T = 2 + 5 x 0.05.
  EXPECT_NEAR(pressureOf(pt), 410.0 + gamma * 2.25 * (e0 + pt.h[1]), 1e-9);
  for (int i = 0; i < 250; ++i) step(0.001);
  EXPECT_NEAR(pt.h[1], 0.0, 1e-9 * peak);
  EXPECT_NEAR(pressureOf(pt), gamma * e0, 1e-9);
}

// V0 < 1: the material starts compressed, at eps_V = ln V0 on the table.
TEST(EosTabulated, InitialRelativeVolume) {
  const double v0 = 0.95;
  const auto law = makeNull(table(m::Eos::Form::Tabulated, 0.0, 0.0, v0));
  Point pt;
  squeeze(pt, law, 0.0);
  expectPressure(pressureOf(pt), ref(kC, std::log(v0)), "at V0");
  EXPECT_NEAR(pressureOf(pt), 50.0 + 600.0 * (-std::log(v0) - 0.05), 1e-9);
}

// EOS 8: loading on the curve; unloading from eps_min = -0.15 along K(-0.15) = 3750 (between
// K3 and K4), into tension; reloading on the same line back to eps_min, then the curve again;
// past the table's end the unloading modulus is K4's.
TEST(EosTabulatedCompaction, UnloadsAndReloadsAlongTheBulkModulusOfTheLargestCompression) {
  const auto law = makeNull(table(m::Eos::Form::TabulatedCompaction));
  Point pt;
  for (int i = 1; i <= 15; ++i) {
    squeeze(pt, law, -0.01);
    expectPressure(pressureOf(pt), ref(kC, -0.01 * i), "loading");
  }
  EXPECT_NEAR(pressureOf(pt), 190.0, 1e-9);
  EXPECT_NEAR(refK(-0.15), 3750.0, 1e-9);
  const auto line = [](double e) { return 190.0 - 3750.0 * (e + 0.15); };
  for (int i = 14; i >= 5; --i) {  // unloading to eps_V = -0.05
    squeeze(pt, law, 0.01);
    expectPressure(pressureOf(pt), line(-0.01 * i), "unloading");
    EXPECT_NEAR(pt.h[2], -0.15, 1e-14);
  }
  EXPECT_NEAR(pressureOf(pt), -185.0, 1e-9);  // 190 - 3750 x 0.1: tension, no cutoff here
  for (int i = 6; i <= 15; ++i) {             // reloading on the line
    squeeze(pt, law, -0.01);
    expectPressure(pressureOf(pt), line(-0.01 * i), "reloading");
  }
  for (int i = 16; i <= 25; ++i) {  // past eps_min: the curve, and past EV4 its last segment
    squeeze(pt, law, -0.01);
    expectPressure(pressureOf(pt), ref(kC, -0.01 * i), "loading again");
  }
  EXPECT_NEAR(pressureOf(pt), 410.0, 1e-9);  // 300 + 2200 x 0.05
  squeeze(pt, law, 0.01);
  EXPECT_NEAR(pressureOf(pt), 410.0 - 5000.0 * 0.01, 1e-9);  // K held at K4 past the table
  EXPECT_NEAR(pt.h[2], -0.25, 1e-14);
}

// EOS 8 with the energy term: the unloading line carries GAMA T(eps_V) E as loading does.
TEST(EosTabulatedCompaction, EnergyTermOnTheUnloadingLine) {
  const double gamma = 0.2, e0 = 5.0;
  const auto law = makeNull(table(m::Eos::Form::TabulatedCompaction, gamma, e0));
  Point pt;
  for (int i = 0; i < 15; ++i) squeeze(pt, law, -0.01);
  for (int i = 0; i < 5; ++i) squeeze(pt, law, 0.01);
  const double e = e0 + pt.h[1], x = pt.h[0];
  EXPECT_NEAR(x, -0.10, 1e-14);
  expectPressure(pressureOf(pt), 190.0 - 3750.0 * 0.05 + gamma * ref(kT, x) * e, "unloaded");
}

// The wave speed's modulus: the stiffest of the table's segments (with GAMA T E0) and, for
// EOS 8, of its K; and the refusals of a table that came through no reader.
TEST(EosTabulated, BulkModulusAndChecks) {
  EXPECT_NEAR(m::eosBulkModulus(table(m::Eos::Form::Tabulated), 2.0), 2200.0, 1e-6);
  EXPECT_NEAR(m::eosBulkModulus(table(m::Eos::Form::TabulatedCompaction), 2.0), 5000.0, 1e-6);
  // GAMA T E0 stiffens the last segment by 0.5 x 10 x (2 - 1.5) / 0.1 = 25.
  EXPECT_NEAR(m::eosBulkModulus(table(m::Eos::Form::Tabulated, 0.5, 10.0), 2.0), 2225.0, 1e-6);
  const auto lawOf = [](const m::Law& l) { return std::get<m::MatNull>(l); };
  EXPECT_EQ(lawOf(makeNull(table(m::Eos::Form::TabulatedCompaction))).moduli.bulk,
            m::eosBulkModulus(table(m::Eos::Form::TabulatedCompaction), 2.0));
  auto one = table(m::Eos::Form::Tabulated);
  one.table.n = 1;
  EXPECT_NE(crumple::testing::errorOf([&] { makeNull(one); }).find("2 to 10 points"),
            std::string::npos);
  auto unordered = table(m::Eos::Form::Tabulated);
  std::swap(unordered.table.ln_v[1], unordered.table.ln_v[2]);
  EXPECT_NE(crumple::testing::errorOf([&] { makeNull(unordered); }).find("must decrease"),
            std::string::npos);
  auto soft = table(m::Eos::Form::TabulatedCompaction);
  soft.table.k[2] = 0.0;
  EXPECT_NE(crumple::testing::errorOf([&] { makeNull(soft); }).find("K must be positive"),
            std::string::npos);
}

// *MAT_SOIL_AND_FOAM (EPS = ln(V/V0), P, KUN) and *MAT_ELASTIC_PLASTIC_HYDRO with EOS 8 of the
// same curve (EV = ln V, V0 = 1: the same strains; C = P, T = 0, every K = KUN): the same
// pressures through loading, unloading and reloading (the two laws' ln V are the same sums of
// tr(de), negated in *MAT_005).
TEST(EosTabulatedCompaction, SameAsSoilAndFoam) {
  const std::vector<double> x{0.0, 0.05, 0.1, 0.2}, p{0.0, 50.0, 80.0, 300.0};
  m::SoilAndFoam::Params sp;
  sp.G = 1000.0;
  sp.kun = 4000.0;
  sp.a0 = 1e12;  // no deviatoric limit: the path is hydrostatic anyway
  sp.pc = -1e6;
  sp.curve = 0;
  const m::Law soil = m::SoilAndFoam::make(
      sp,
      [&](int32_t) {
        return m::CurveData{-1, x, p};
      },
      "");
  auto eos = table(m::Eos::Form::TabulatedCompaction);
  eos.table.k.fill(4000.0);
  eos.table.t.fill(0.0);
  m::ElasticPlasticHydro::Params hp;
  hp.rho = 2.0;
  hp.G = 1000.0;
  hp.sig0 = 1e12;
  hp.pc = -1e6;
  const m::Law hydro = m::makeLaw(hp, {}, "", &eos);
  EXPECT_EQ(std::get<m::SoilAndFoam>(soil).moduli.bulk,
            std::get<m::ElasticPlasticHydro>(hydro).moduli.bulk);
  Point a, b;
  const double path[] = {-0.004, -0.013, 0.007, 0.011, -0.02, -0.031, 0.05, -0.06, -0.011};
  int checked = 0;
  for (int round = 0; round < 4; ++round)
    for (double d : path) {
      squeeze(a, soil, d);
      squeeze(b, hydro, d);
      EXPECT_NEAR(pressureOf(a), pressureOf(b), 1e-11 * std::max(1.0, std::abs(pressureOf(a))));
      EXPECT_EQ(a.h[0], -b.h[0]);  // x = -ln(V/V0) and ln(V/V0)
      ++checked;
    }
  EXPECT_EQ(checked, 36);
  EXPECT_GT(a.h[0], 0.2);  // past the last point
}

namespace {

const std::string kHex =
    "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
    "*SECTION_SOLID\n1,1\n*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n";

// The cards of a table in fixed format: EV, C, T (and K) rows of five fields of width 16.
std::string rows(const std::vector<std::vector<double>>& columns) {
  std::string s;
  for (const auto& col : columns)
    for (int half = 0; half < 2; ++half) {
      for (int i = 5 * half; i < 5 * half + 5; ++i) {
        char f[17];
        std::snprintf(f, sizeof f, "%16.6g", std::size_t(i) < col.size() ? col[i] : 0.0);
        s += f;
      }
      s += "\n";
    }
  return s;
}

}  // namespace

// The cards read into the Model (the deck's descending order stored ascending), the aliases
// *EOS_008 and *EOS_009, the whole carried by the model's bytes; and the refusals, each
// naming the line and field: strains out of order, a non-positive K, a single point, a curve
// in place of the table.
TEST(EosTabulated, ModelReadsTheCardsAndRefuses) {
  crumple::testing::TempDir t;
  const std::string deck = kHex +
                           "*MAT_NULL\n1,1.0e-6\n"
                           "*EOS_TABULATED_COMPACTION_TITLE\nsoil\n"
                           "         7       0.3       2.0      0.98\n" +
                           rows({kEv, kC, kT, kK}) + "*EOS_009\n         8       0.1\n" +
                           rows({kEv, kC, kT}) + "*PART\nsoil\n1,1,1,7\n*END\n";
  const auto model = crumple::model::readModel(t.write("w.k", deck));
  ASSERT_EQ(model.eos.size(), 2u);
  const m::Eos& e8 = model.eos[0].eos;
  EXPECT_EQ(model.eos[0].title, "soil");
  EXPECT_EQ(e8.form, m::Eos::Form::TabulatedCompaction);
  EXPECT_EQ(e8.table.n, 4);
  EXPECT_EQ(e8.table.gamma, 0.3);
  EXPECT_EQ(e8.e0, 2.0);
  EXPECT_EQ(e8.v0, 0.98);
  EXPECT_EQ(e8.table.ln_v[0], -0.2);
  EXPECT_EQ(e8.table.ln_v[3], 0.0);
  EXPECT_EQ(e8.table.c[0], 300.0);
  EXPECT_EQ(e8.table.t[1], 1.5);
  EXPECT_EQ(e8.table.k[3], 1500.0);
  const m::Eos& e9 = model.eos[1].eos;
  EXPECT_EQ(e9.form, m::Eos::Form::Tabulated);
  EXPECT_EQ(e9.v0, 1.0);  // blank: the default
  EXPECT_EQ(e9.table.n, 4);
  EXPECT_EQ(e9.table.k[0], 0.0);
  const auto r = crumple::model::deserialize(crumple::model::serialize(model));
  ASSERT_EQ(r.eos.size(), 2u);
  EXPECT_EQ(r.eos[0].eos.table.ln_v, e8.table.ln_v);
  EXPECT_EQ(r.eos[0].eos.table.k, e8.table.k);
  EXPECT_EQ(r.eos[1].eos.table.n, 4);

  // The deck's path and error with the line of card `card` (1: card 1) of the *EOS.
  const auto refused = [&](const std::string& name, const std::string& cards, int card) {
    const std::string head = kHex + "*MAT_NULL\n1,1.0e-6\n";
    const auto path = t.write(name, head + cards + "*PART\nsoil\n1,1,1,7\n*END\n");
    const auto line = 1 + std::count(head.begin(), head.end(), '\n') + card;
    return std::make_pair(path.string() + ":" + std::to_string(line),
                          crumple::testing::errorOf([&] { crumple::model::readModel(path); }));
  };
  {
    const auto [path, err] = refused(
        "order.k", "*EOS_TABULATED\n         7\n" + rows({{0.0, -0.1, -0.05, -0.2}, kC, kT}), 2);
    EXPECT_NE(err.find(path + ": *EOS_TABULATED card 2 field 3 (EV3): the volumetric strains "
                              "ln V must decrease point by point"),
              std::string::npos)
        << err;
  }
  {
    const auto [path, err] = refused("k.k",
                                     "*EOS_TABULATED_COMPACTION\n         7\n" +
                                         rows({kEv, kC, kT, {1500.0, 2000.0, 0.0, 5000.0}}),
                                     8);
    EXPECT_NE(err.find(path + ": *EOS_TABULATED_COMPACTION card 8 field 3 (K3): the unloading "
                              "bulk modulus must be positive"),
              std::string::npos)
        << err;
  }
  {
    const auto [path, err] =
        refused("one.k", "*EOS_TABULATED\n         7\n" + rows({{-0.1}, {40.0}, {0.0}}), 2);
    EXPECT_NE(err.find(path + ": *EOS_TABULATED card 2 field 1 (EV1): the table needs at "
                              "least two points"),
              std::string::npos)
        << err;
  }
  {
    const auto [path, err] =
        refused("lcc.k",
                "*EOS_TABULATED_COMPACTION\n         7       0.0       0.0       1.0        12\n" +
                    rows({kEv, kC, kT, kK}),
                1);
    EXPECT_NE(err.find(path + ": *EOS_TABULATED_COMPACTION card 1 field 5 (LCC): a curve in "
                              "place of the EV/C/T/K table is not supported"),
              std::string::npos)
        << err;
  }
}
