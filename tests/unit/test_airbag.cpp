// Unit tests of the control-volume geometry (constraints/airbag.hpp): the volume a closed
// surface of segments encloses (divergence theorem) and the consistent nodal forces of a
// uniform pressure, which must be the gradient of that volume.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "constraints/airbag.hpp"
#include "model/build.hpp"
#include "temp_dir.hpp"

namespace {

using crumple::constraints::segmentPressureForces;
using crumple::constraints::segmentVolume;

// A hexahedron's corners (LS-DYNA order) and its six faces numbered with outward normals.
constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                              {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
constexpr double kNatural[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

using Corners = std::array<std::array<double, 3>, 8>;

double surfaceVolume(const Corners& x) {
  double v = 0.0;
  for (const auto& f : kFaces)
    v += segmentVolume({x[f[0]].data(), x[f[1]].data(), x[f[2]].data(), x[f[3]].data()});
  return v;
}

// The trilinear hexahedron's volume by 2x2x2 Gauss quadrature of det J (exact: det J has
// degree 2 in each natural coordinate).
double gaussVolume(const Corners& x) {
  const double g = 1.0 / std::sqrt(3.0);
  double vol = 0.0;
  for (double xi : {-g, g})
    for (double eta : {-g, g})
      for (double zeta : {-g, g}) {
        double J[3][3] = {};
        for (int a = 0; a < 8; ++a) {
          const double* n = kNatural[a];
          const double d[3] = {n[0] * (1 + eta * n[1]) * (1 + zeta * n[2]) / 8,
                               n[1] * (1 + xi * n[0]) * (1 + zeta * n[2]) / 8,
                               n[2] * (1 + xi * n[0]) * (1 + eta * n[1]) / 8};
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) J[i][j] += x[std::size_t(a)][std::size_t(i)] * d[j];
        }
        vol += J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
               J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
               J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
      }
  return vol;
}

Corners distortedHex() {
  Corners x{};
  for (std::size_t a = 0; a < 8; ++a)
    for (std::size_t i = 0; i < 3; ++i) x[a][i] = 0.5 * (kNatural[a][i] + 1.0);
  // Warped faces (no face stays planar) and a non-parallelogram shape.
  const double shift[8][3] = {{0.05, -0.02, 0.03}, {0.1, 0.04, -0.06}, {-0.07, 0.12, 0.02},
                              {0.02, -0.05, 0.09}, {-0.04, 0.03, 0.1}, {0.08, -0.09, 0.05},
                              {0.15, 0.07, -0.04}, {-0.03, 0.02, 0.2}};
  for (std::size_t a = 0; a < 8; ++a)
    for (std::size_t i = 0; i < 3; ++i) x[a][i] = 2.0 * x[a][i] + shift[a][i];
  return x;
}

TEST(Airbag, UnitCubeVolumeIsExact) {
  Corners x{};
  for (std::size_t a = 0; a < 8; ++a)
    for (std::size_t i = 0; i < 3; ++i) x[a][i] = 0.5 * (kNatural[a][i] + 1.0);
  EXPECT_NEAR(surfaceVolume(x), 1.0, 1e-15);
}

TEST(Airbag, WarpedHexahedronVolumeMatchesQuadrature) {
  // Bilinear (warped) faces: the face sum is the exact trilinear volume, wherever the origin.
  Corners x = distortedHex();
  const double exact = gaussVolume(x);
  EXPECT_NEAR(surfaceVolume(x), exact, 1e-14 * exact);
  for (auto& p : x) {
    p[0] += 10.0;
    p[1] -= 7.0;
    p[2] += 3.0;
  }
  EXPECT_NEAR(surfaceVolume(x), exact, 1e-12 * exact);
}

TEST(Airbag, TetrahedronOfTrianglesVolume) {
  // Triangles as segments with n3 == n4; V = det / 6.
  const double p[4][3] = {{0.1, 0.2, -0.3}, {1.3, 0.1, 0.2}, {0.2, 1.1, 0.1}, {0.3, 0.4, 0.9}};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  double v = 0.0;
  for (const auto& f : faces) v += segmentVolume({p[f[0]], p[f[1]], p[f[2]], p[f[2]]});
  double a[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a[r][c] = p[r + 1][c] - p[0][c];
  const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                     a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                     a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  EXPECT_NEAR(v, det / 6.0, 1e-15);
}

// Sum of the pressure forces (q = 1) of every face at each corner: must be dV/dx.
Corners pressureForces(const Corners& x) {
  Corners f{};
  for (const auto& face : kFaces) {
    double out[12];
    segmentPressureForces(
        {x[face[0]].data(), x[face[1]].data(), x[face[2]].data(), x[face[3]].data()}, 1.0, out);
    for (int k = 0; k < 4; ++k)
      for (std::size_t i = 0; i < 3; ++i) f[std::size_t(face[k])][i] += out[3 * k + int(i)];
  }
  return f;
}

TEST(Airbag, PressureForcesAreTheVolumeGradient) {
  // Consistent loads: the gas's work p dV equals the work of the nodal forces.
  const Corners x = distortedHex();
  const Corners f = pressureForces(x);
  const double h = 1e-5;
  for (std::size_t a = 0; a < 8; ++a)
    for (std::size_t i = 0; i < 3; ++i) {
      Corners up = x, down = x;
      up[a][i] += h;
      down[a][i] -= h;
      const double grad = (surfaceVolume(up) - surfaceVolume(down)) / (2.0 * h);
      EXPECT_NEAR(f[a][i], grad, 1e-9) << "corner " << a << " component " << i;
    }
  // A closed surface: no net force.
  for (std::size_t i = 0; i < 3; ++i) {
    double sum = 0.0;
    for (const auto& c : f) sum += c[i];
    EXPECT_NEAR(sum, 0.0, 1e-14);
  }
}

TEST(Airbag, TrianglePressureIsAThirdPerCorner) {
  const double p[3][3] = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}};
  double out[12];
  segmentPressureForces({p[0], p[1], p[2], p[2]}, 3.0, out);
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(out[3 * k + 2], 3.0 * 1.0 / 3.0);  // area 1 along +z
    EXPECT_DOUBLE_EQ(out[3 * k], 0.0);
  }
  EXPECT_EQ(out[9] + out[10] + out[11], 0.0);
}

// The deck reader on tests/data/decks/airbag_sphere.k (a part set of 216 shells).
std::string sphereDeck() {
  std::ifstream in(std::string(CRUMPLE_SOURCE_DIR) + "/tests/data/decks/airbag_sphere.k");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(AirbagDeck, ReadsTheBagAndItsSegments) {
  crumple::testing::TempDir t("crumple_test_airbag");
  const auto m = crumple::model::readModel(t.write("bag.k", sphereDeck()));
  ASSERT_EQ(m.airbags.size(), 1u);
  const auto& bag = m.airbags[0];
  EXPECT_EQ(bag.id, 3);  // _ID heading
  EXPECT_EQ(bag.first, 0u);
  EXPECT_EQ(bag.count, 216u);
  EXPECT_DOUBLE_EQ(bag.cn, 3.0e4);
  EXPECT_DOUBLE_EQ(bag.beta, 1.0);
  EXPECT_DOUBLE_EQ(bag.mwd, 756.0);
  ASSERT_EQ(m.pressure_loads.size(), 216u);
  for (const auto& p : m.pressure_loads) EXPECT_EQ(p.airbag, 0);
}

TEST(AirbagDeck, NumberedSuffixIsTheId) {
  crumple::testing::TempDir t("crumple_test_airbag");
  const auto m = crumple::model::readModel(
      t.write("bag.k", replaced(sphereDeck(), "*AIRBAG_SIMPLE_PRESSURE_VOLUME_ID\n         3bag\n",
                                "*AIRBAG_SIMPLE_PRESSURE_VOLUME_1\n")));
  ASSERT_EQ(m.airbags.size(), 1u);
  EXPECT_EQ(m.airbags[0].id, 1);
}

TEST(AirbagDeck, RefusesWhatItDoesNotHonour) {
  crumple::testing::TempDir t("crumple_test_airbag");
  // VINI (card 1 field 6) set: refused, naming the field.
  const std::string card = "         7         1         0         1         1         0";
  const auto msg = crumple::testing::errorOf([&] {
    crumple::model::readModel(t.write(
        "vini.k", replaced(sphereDeck(), card,
                           "         7         1         0         1         1       0.5")));
  });
  EXPECT_NE(msg.find("(VINI)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("not supported"), std::string::npos) << msg;
}

}  // namespace
