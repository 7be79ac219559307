#include "materials/laws/mooney_rivlin.hpp"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "materials/hyperelastic.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& MooneyRivlin::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("PR"), R("A"), R("B"), R("REF")}},
       {"card 2", {R("SGL"), R("SW"), R("ST"), I("LCID")}}}};
  return spec;
}

MooneyRivlin::Params MooneyRivlin::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  Params p;
  p.nu = c.real("PR");
  if (!(p.nu > -1.0 && p.nu < 0.5)) c.fail("PR", "Poisson's ratio must lie in (-1, 0.5)");
  p.a = c.real("A");
  p.b = c.real("B");
  if (c.real("REF") != 0.0)
    in.reject(c, "REF", "REF = 1 (stress from *INITIAL_FOAM_REFERENCE_GEOMETRY) is not supported");
  const deck::Card& c2 = in.optionalCard("card 2");
  const int64_t lcid = c2.integer("LCID");
  if (lcid != 0 && (p.a != 0.0 || p.b != 0.0)) {
    in.ignore(c2, "LCID", "A and B are given: the curve fit (A = B = 0) is not made");
  } else if (lcid != 0) {
    p.sgl = c2.real("SGL");
    p.sw = c2.real("SW");
    p.st = c2.real("ST");
    p.curve = in.curveOrReject(c2, "LCID", lcid);
  } else if (p.a + p.b <= 0.0) {
    c.fail("A", "A + B (half the shear modulus) must be positive, or A = B = 0 with LCID");
  }
  return p;
}

MooneyRivlin MooneyRivlin::make(const Params& p, const CurveAt& curves, const std::string& at) {
  MooneyRivlin m;
  m.a = p.a;
  m.b = p.b;
  if (p.curve >= 0) {
    // Nominal stress of the unit terms in incompressible uniaxial stretch.
    const std::vector<std::function<double(double)>> terms{
        [](double l) { return 2.0 * (l - 1.0 / (l * l)); },
        [](double l) { return 2.0 * (l - 1.0 / (l * l)) / l; }};
    const auto fit = fitUniaxial(at, uniaxialTest(at, curves(p.curve), p.sgl, p.sw, p.st), terms);
    m.a = fit[0];
    m.b = fit[1];
  }
  const double G = 2.0 * (m.a + m.b);
  if (!(G > 0.0))
    throw util::InputError(at + "the shear modulus 2 (A + B) = " + std::to_string(G) +
                           " is not positive" + (p.curve >= 0 ? " (from the LCID fit)" : ""));
  if (!(p.nu > -1.0 && p.nu < 0.5))
    throw util::InputError(at + "Poisson's ratio must lie in (-1, 0.5)");
  m.c = 0.5 * m.a + m.b;
  m.d = (m.a * (5.0 * p.nu - 2.0) + m.b * (11.0 * p.nu - 5.0)) / (2.0 * (1.0 - 2.0 * p.nu));
  m.moduli.shear = G;
  m.moduli.bulk = 2.0 * G * (1.0 + p.nu) / (3.0 * (1.0 - 2.0 * p.nu));
  return m;
}

void MooneyRivlin::update(PointBatch& p) const {
  for (int l = 0; l < p.n; ++l) {
    const LeftCauchyGreen k = leftCauchyGreen(p, l);
    // dW/dI3 = -2 C I3^-3 + 2 D (I3 - 1).
    const double w3 = -2.0 * c / (k.I3 * k.I3 * k.I3) + 2.0 * d * (k.I3 - 1.0);
    invariantStress(k, a, b, w3, p, l);
  }
}

}  // namespace crumple::materials
