// *MAT_SOIL_AND_FOAM (005) at a material point, against the answers worked out by hand from the
// Theory Manual's model (pressure curve, unloading line KUN, cutoff PC, yield surface
// J2 = a0 + a1 p + a2 p^2); and the model builder's refusal of it on beams and shells, which
// it has no update for.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "materials/materials.hpp"
#include "model/build.hpp"
#include "temp_dir.hpp"

namespace m = crumple::materials;

namespace {

// The spec's material M1: G = KUN = 1000, a0 = 1, a1 = 0.4, a2 = 0.02, PC = -2, the curve
// EPS 0, -0.05, -0.10, -0.20 with P 0, 5, 7, 15 (slopes 100, 40, 80 in x = -ln(V/V0)).
const std::vector<double> kX{0.0, 0.05, 0.10, 0.20}, kP{0.0, 5.0, 7.0, 15.0};

m::SoilAndFoam makeSoil(bool crush = true) {
  m::SoilAndFoam::Params p;
  p.G = 1000.0;
  p.kun = 1000.0;
  p.a0 = 1.0;
  p.a1 = 0.4;
  p.a2 = 0.02;
  p.pc = -2.0;
  p.crush = crush;
  p.curve = 0;
  return m::SoilAndFoam::make(
      p,
      [](int32_t) {
        return m::CurveData{-1, kX, kP};
      },
      "");
}

// One point with its two history variables (x, x_max).
struct Point {
  std::array<double, 6> s{};
  double x = 0.0, x_max = 0.0;

  void step(const m::SoilAndFoam& law, const std::array<double, 6>& de) {
    m::PointBatch b;
    b.n = 1;
    for (int k = 0; k < 6; ++k) {
      b.s[k] = &s[k];
      b.de[k] = &de[k];
    }
    b.h[0] = &x;
    b.h[1] = &x_max;
    law.update(b);
  }
  // Hydrostatic straining to the compressive volumetric strain `to` in `n` equal steps.
  void squeezeTo(const m::SoilAndFoam& law, double to, int n = 10) {
    const double d = -(to - x) / (3.0 * n);
    for (int i = 0; i < n; ++i) step(law, {d, d, d, 0, 0, 0});
  }
  double pressure() const { return -(s[0] + s[1] + s[2]) / 3.0; }
  double sqrtJ2() const {
    const double p = pressure();
    double j2 = 0.0;
    for (int k = 0; k < 3; ++k) j2 += 0.5 * (s[k] + p) * (s[k] + p);
    for (int k = 3; k < 6; ++k) j2 += s[k] * s[k];
    return std::sqrt(j2);
  }
};

constexpr double kTol = 1e-9;

}  // namespace

// Test 1 of the spec: loading follows the curve, unloading the line of slope KUN from the
// largest compression, down to the cutoff; reloading retraces the line, then the curve.
TEST(SoilAndFoam, HydrostaticLoadUnloadReload) {
  const m::SoilAndFoam law = makeSoil();
  Point pt;
  const std::vector<std::pair<double, double>> path = {
      {0.025, 2.5}, {0.05, 5.0},  {0.075, 6.0}, {0.10, 7.0},   {0.15, 11.0},
      {0.145, 6.0}, {0.14, 1.0},  {0.139, 0.0}, {0.137, -2.0}, {0.13, -2.0},
      {0.145, 6.0}, {0.15, 11.0}, {0.20, 15.0}};
  for (const auto& [x, p] : path) {
    pt.squeezeTo(law, x);
    EXPECT_NEAR(pt.pressure(), p, kTol) << "x " << x;
    EXPECT_NEAR(pt.sqrtJ2(), 0.0, kTol);
    EXPECT_NEAR(pt.x, x, 1e-14);
  }
  EXPECT_NEAR(pt.x_max, 0.20, 1e-14);
  // Past the last point the curve goes on with its last slope (80).
  pt.squeezeTo(law, 0.25);
  EXPECT_NEAR(pt.pressure(), 19.0, kTol);
}

// Test 2: virgin material in tension follows KUN down to PC and stays there; a deviatoric
// stress is zeroed while the pressure is cut off and does not come back by itself.
TEST(SoilAndFoam, TensionCutoffZeroesTheDeviator) {
  const m::SoilAndFoam law = makeSoil();
  Point pt;
  pt.squeezeTo(law, -0.001);
  EXPECT_NEAR(pt.pressure(), -1.0, kTol);
  pt.squeezeTo(law, -0.01);
  EXPECT_NEAR(pt.pressure(), -2.0, kTol);
  Point q;
  q.squeezeTo(law, 0.05);              // p = 5
  q.step(law, {0, 0, 0, 2e-4, 0, 0});  // s_xy = 2 G de = 0.4, below the cap
  EXPECT_NEAR(q.s[3], 0.4, kTol);
  q.squeezeTo(law, 0.05 - 0.0075);  // p = 5 - 7.5 < PC: cut
  EXPECT_NEAR(q.pressure(), -2.0, kTol);
  EXPECT_EQ(q.s[3], 0.0);
  q.squeezeTo(law, 0.05);  // back to p = 5 along the line: no shear
  EXPECT_NEAR(q.pressure(), 5.0, kTol);
  EXPECT_EQ(q.s[3], 0.0);
}

// Test 3: shear at a fixed pressure is capped at sqrt(a0 + a1 p + a2 p^2); the cap follows
// the pressure down and the stress stays on the smaller surface when the pressure comes back.
TEST(SoilAndFoam, ShearCappedByThePressureDependentSurface) {
  const m::SoilAndFoam law = makeSoil();
  Point pt;
  pt.squeezeTo(law, 0.10);                                       // p = 7
  const double cap7 = std::sqrt(1.0 + 0.4 * 7.0 + 0.02 * 49.0);  // sqrt(4.78)
  for (int i = 0; i < 40; ++i) {
    pt.step(law, {0, 0, 0, 1e-4, 0, 0});
    EXPECT_LE(pt.sqrtJ2(), cap7 * (1 + 1e-15));
    if (2000.0 * 1e-4 * (i + 1) < cap7 - 1e-12) {
      EXPECT_NEAR(pt.s[3], 0.2 * (i + 1), kTol);
    }
  }
  EXPECT_NEAR(pt.sqrtJ2(), 2.186321, 1e-6);
  pt.squeezeTo(law, 0.099, 1);  // unload to p = 6: the stress goes to the smaller surface
  EXPECT_NEAR(pt.pressure(), 6.0, kTol);
  EXPECT_NEAR(pt.sqrtJ2(), std::sqrt(4.12), kTol);
  pt.squeezeTo(law, 0.10, 1);
  EXPECT_NEAR(pt.pressure(), 7.0, kTol);
  EXPECT_NEAR(pt.sqrtJ2(), std::sqrt(4.12), kTol);
}

// Test 4: VCR = 1 unloads along the curve (nonlinear elastic, no residual strain).
TEST(SoilAndFoam, NoCrushingUnloadsAlongTheCurve) {
  const m::SoilAndFoam law = makeSoil(false);
  Point pt;
  for (const auto& [x, p] :
       std::vector<std::pair<double, double>>{{0.15, 11.0}, {0.08, 6.2}, {0.02, 2.0}, {0.0, 0.0}}) {
    pt.squeezeTo(law, x);
    EXPECT_NEAR(pt.pressure(), p, kTol) << "x " << x;
  }
}

// The deck's table becomes the curve (a first point at the origin added), the wave-speed
// bulk modulus is the stiffest of KUN and the slopes, and the law serves solids only: a beam
// or shell part with it is refused, naming the part.
TEST(SoilAndFoam, ReadFromTheDeckAndRefusedOnBeamsAndShells) {
  crumple::testing::TempDir t("crumple_test_soil");
  const std::string mesh =
      "*KEYWORD\n*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
      "*MAT_SOIL_AND_FOAM\n"
      "$ MID RO G KUN A0 A1 A2 PC\n"
      "5,2.0e-9,1000.,3000.,1.,0.4,0.02,-2.\n"
      "0.,0.\n"
      "-0.05,-0.1,-0.2\n\n"
      "5.,7.,15.\n\n"
      "*SECTION_SOLID\n1,1\n*PART\nsoil\n1,1,5\n*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n";
  const auto model = crumple::model::readModel(t.write("s.k", mesh));
  const auto& params = std::get<m::SoilAndFoam::Params>(model.materials.at(0).law);
  EXPECT_EQ(params.G, 1000.0);
  EXPECT_TRUE(params.crush);
  const auto law = std::get<m::SoilAndFoam>(m::makeLaw(
      params,
      [&](int32_t i) {
        const auto& c = model.curves.at(std::size_t(i));
        return m::CurveData{c.id, c.x, c.y};
      },
      ""));
  EXPECT_EQ(law.x, (std::vector<double>{0.0, 0.05, 0.1, 0.2}));
  EXPECT_EQ(law.p, (std::vector<double>{0.0, 5.0, 7.0, 15.0}));
  EXPECT_EQ(law.moduli.bulk, 3000.0);

  const std::string beam = mesh +
                           "*SECTION_BEAM\n2,3\n0.01\n*PART\npost\n2,2,5\n"
                           "*ELEMENT_BEAM\n2,2,1,2\n";
  const auto path = t.write("b.k", beam);
  EXPECT_EQ(crumple::testing::errorOf([&] { crumple::model::readModel(path); }),
            path.string() +
                ":31: *PART card 2 field 3 (MID): part 2 has a *SECTION_BEAM section but "
                "material 5 (*MAT_SOIL_AND_FOAM) has no uniaxial (fibre) update for beam "
                "elements");
}
