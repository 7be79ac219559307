// LS-DYNA ASCII number formats (src/output/ascii.hpp) and the cut area of a hexahedron
// (src/output/sections.hpp), against values worked by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "output/ascii.hpp"
#include "output/sections.hpp"

namespace crumple::output {
namespace {

TEST(AsciiFormat, FortranEditDescriptors) {
  // 1PE14.5: one digit before the point; E14.7 / E10.4: the unscaled 0.ddd form.
  EXPECT_EQ(ascii::scientific(2.1187e-4, 14, 5), "   2.11870E-04");
  EXPECT_EQ(ascii::scientific(-7.9, 12, 5), "-7.90000E+00");
  EXPECT_EQ(ascii::scientific(-0.0, 13, 4), "   0.0000E+00");
  EXPECT_EQ(ascii::fractional(22.92167, 14, 7), " 0.2292167E+02");
  EXPECT_EQ(ascii::fractional(4.87301e-3, 14, 7), " 0.4873010E-02");
  EXPECT_EQ(ascii::fractional(0.0, 10, 4), "0.0000E+00");
  EXPECT_EQ(ascii::fractional(-1.5, 11, 4), "-0.1500E+01");
  // Rounding up to the next power of ten moves the exponent: 9.99996 -> 0.1000E+02.
  EXPECT_EQ(ascii::fractional(9.99996, 10, 4), "0.1000E+02");
}

TEST(AsciiFormat, BannerAndLegendWidths) {
  const std::string b = ascii::banner("deck title");
  EXPECT_EQ(b.substr(0, b.find('\n')).size(), 73u);  // ' ' + A72
  EXPECT_EQ(b.find("ls-dyna", b.find('\n')), b.find('\n') + 21);
  const std::string l = ascii::legend({{10, "Plate 1"}}, 5, 72);
  EXPECT_NE(l.find("\n       10     Plate 1"), std::string::npos);
}

std::array<model::Vec3, 8> unitCube() {
  return {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
}

TEST(SectionCut, HexahedronCutAreas) {
  const auto x = unitCube();
  // A face-parallel cut: the unit square.
  EXPECT_NEAR(hexCutArea(x, {0.3, 0, 0}, {1, 0, 0}), 1.0, 1e-14);
  // The diagonal plane x = y: a rectangle of sides sqrt(2) and 1.
  const double s = 1.0 / std::sqrt(2.0);
  EXPECT_NEAR(hexCutArea(x, {0.5, 0.5, 0.5}, {s, -s, 0}), std::sqrt(2.0), 1e-14);
  // Through the centre normal to the main diagonal: the regular hexagon of side 1/sqrt(2),
  // area 3 sqrt(3) / 2 * (1/2) = 3 sqrt(3) / 4.
  const double t = 1.0 / std::sqrt(3.0);
  EXPECT_NEAR(hexCutArea(x, {0.5, 0.5, 0.5}, {t, t, t}), 3.0 * std::sqrt(3.0) / 4.0, 1e-14);
  // Near a corner: the triangle x + y + z = 0.3, area sqrt(3)/2 * 0.3^2.
  EXPECT_NEAR(hexCutArea(x, {0.1, 0.1, 0.1}, {t, t, t}), std::sqrt(3.0) / 2.0 * 0.09, 1e-14);
  // A plane that misses the element.
  EXPECT_EQ(hexCutArea(x, {2, 0, 0}, {1, 0, 0}), 0.0);
  // A tetrahedron as a degenerate hexahedron (n4 = n3, n5..n8 = apex): the cut z = 0.5 is
  // the base triangle scaled by 1/2, area 1/2 * 1/4.
  std::array<model::Vec3, 8> tet = {
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}}};
  EXPECT_NEAR(hexCutArea(tet, {0, 0, 0.5}, {0, 0, 1}), 0.125, 1e-14);
}

}  // namespace
}  // namespace crumple::output
