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
  m.moduli = moduliFromShear(G, p.nu);
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

namespace {

// lambda_3^2 with sigma_33 = 0 in B = diag(b1, b2, b3): 2/J times
//   g(b3) = b3 (A + B (b1 + b2)) + I3 W3,   I3 W3 = -2 C / (p^2 b3^2) + 2 D p b3 (p b3 - 1),
// p = b1 b2, is zero (the b3^2 terms of (W1 + I1 W2) b3 - W2 b3^2 cancel). g rises from -inf
// at b3 -> 0 (C > 0); Newton's method from the incompressible 1 / p inside a bracket that
// bisection keeps.
double thicknessSquare(double A, double B, double C, double D, double b1, double b2) {
  const double p = b1 * b2, k = A + B * (b1 + b2);
  auto g = [&](double x) {
    return x * k - 2.0 * C / (p * p * x * x) + 2.0 * D * p * x * (p * x - 1.0);
  };
  auto dg = [&](double x) {
    return k + 4.0 * C / (p * p * x * x * x) + 2.0 * D * p * (2.0 * p * x - 1.0);
  };
  double lo = 1.0 / p, hi = 1.0 / p;
  while (g(lo) > 0.0) lo *= 0.5;
  while (g(hi) < 0.0) hi *= 2.0;
  double x = 1.0 / p;
  for (int it = 0; it < 200; ++it) {
    const double gx = g(x);
    if (gx == 0.0) return x;
    (gx < 0.0 ? lo : hi) = x;
    double next = x - gx / dg(x);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - x) <= 1e-15 * x) return next;
    x = next;
  }
  return x;
}

}  // namespace

double MooneyRivlin::principalStress(double b1, double b2, double b3, double bi) const {
  const double I1 = b1 + b2 + b3, I3 = b1 * b2 * b3, J = std::sqrt(I3);
  const double w3 = -2.0 * c / (I3 * I3 * I3) + 2.0 * d * (I3 - 1.0);
  return 2.0 / J * ((a + I1 * b) * bi - b * bi * bi + I3 * w3);
}

double MooneyRivlin::planeStress(const double (&e)[3], double (&s)[3]) const {
  // Principal strains of [[exx, exy], [exy, eyy]] and the direction of the first.
  const double mean = 0.5 * (e[0] + e[1]), half = 0.5 * (e[0] - e[1]);
  const double r = std::hypot(half, e[2]);
  const double theta = 0.5 * std::atan2(e[2], half);
  const double cs = std::cos(theta), sn = std::sin(theta);
  const double b1 = std::exp(2.0 * (mean + r)), b2 = std::exp(2.0 * (mean - r));
  const double b3 = thicknessSquare(a, b, c, d, b1, b2);
  const double s1 = principalStress(b1, b2, b3, b1), s2 = principalStress(b1, b2, b3, b2);
  s[0] = s1 * cs * cs + s2 * sn * sn;
  s[1] = s1 * sn * sn + s2 * cs * cs;
  s[2] = (s1 - s2) * cs * sn;
  return std::sqrt(b3);
}

void MooneyRivlin::updatePlaneStress(PlaneStressPoints& pts) const {
  for (int i = 0; i < pts.n; ++i) {
    double e_old[3], e_new[3], s_old[3], s_new[3];
    for (int k = 0; k < 3; ++k) {
      e_old[k] = pts.alpha[k][i];
      e_new[k] = e_old[k] + pts.de[k][i];
    }
    const double l3_old = planeStress(e_old, s_old);
    const double l3_new = planeStress(e_new, s_new);
    pts.de_zz[i] = l3_new / l3_old - 1.0;
    for (int k = 0; k < 3; ++k) {
      pts.alpha[k][i] = e_new[k];
      pts.s[k][i] = s_new[k];
    }
    if (pts.failed) pts.failed[i] = 0;
  }
}

}  // namespace crumple::materials
