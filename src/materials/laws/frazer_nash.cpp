#include "materials/laws/frazer_nash.hpp"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "materials/hyperelastic.hpp"
#include "util/error.hpp"

namespace crumple::materials {

namespace {
constexpr std::array<std::string_view, FrazerNash::kTerms> kNames{"C100", "C200", "C300", "C400",
                                                                  "C110", "C210", "C010", "C020"};
}  // namespace

const deck::KeywordSpec& FrazerNash::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("PR"), R("C100"), R("C200"), R("C300"), R("C400")}},
       {"card 2",
        {R("C110"), R("C210"), R("C010"), R("C020"), R("EXIT"), R("EMAX"), R("EMIN"), R("REF")}},
       {"card 3", {R("SGL"), R("SW"), R("ST"), I("LCID")}}}};
  return spec;
}

FrazerNash::Params FrazerNash::read(LawInput& in) {
  const deck::Card& c1 = in.card("card 1");
  const deck::Card& c2 = in.card("card 2");
  Params p;
  p.nu = c1.real("PR");
  if (!(p.nu > -1.0 && p.nu < 0.5)) c1.fail("PR", "Poisson's ratio must lie in (-1, 0.5)");
  for (int t = 0; t < kTerms; ++t) p.c[t] = (t < 4 ? c1 : c2).real(kNames[t]);
  if (c2.real("EXIT") == 0.0)
    in.reject(c2, "EXIT",
              "EXIT = 0 (stop when the strain limits EMIN, EMAX are exceeded) is not supported: "
              "give EXIT = 1 to run past them");
  else
    in.ignore(c2, "EMAX", "EXIT != 0: the fitted energy is used past the strain limits");
  if (c2.real("REF") != 0.0)
    in.reject(c2, "REF", "REF = 1 (stress from *INITIAL_FOAM_REFERENCE_GEOMETRY) is not supported");
  const deck::Card& c3 = in.optionalCard("card 3");
  if (const int64_t lcid = c3.integer("LCID"); lcid != 0) {
    p.sgl = c3.real("SGL");
    p.sw = c3.real("SW");
    p.st = c3.real("ST");
    p.curve = in.curveOrReject(c3, "LCID", lcid);
  }
  return p;
}

namespace {

// The Green-strain invariants of the incompressible uniaxial stretch F = diag(l, l^-1/2,
// l^-1/2) and their derivatives in l: E = diag((l^2 - 1)/2, (1/l - 1)/2, (1/l - 1)/2).
struct UniaxialInvariants {
  double e1, e2, de1, de2;
};
UniaxialInvariants uniaxialInvariants(double l) {
  const double a = 0.5 * (l * l - 1.0), b = 0.5 * (1.0 / l - 1.0);
  const double da = l, db = -0.5 / (l * l);
  const double e1 = a + 2.0 * b, de1 = da + 2.0 * db;
  const double ee = a * a + 2.0 * b * b, dee = 2.0 * a * da + 4.0 * b * db;
  return {e1, 0.5 * (e1 * e1 - ee), de1, e1 * de1 - 0.5 * dee};
}

// The nominal stress dU/dl of each unit term along that stretch (the lateral stresses are zero
// and J = 1, so the work P dl is the energy's change).
std::function<double(double)> uniaxialTerm(int t) {
  return [t](double l) {
    const auto [e1, e2, de1, de2] = uniaxialInvariants(l);
    switch (t) {
      case 0:
        return de1;
      case 1:
        return 2.0 * e1 * de1;
      case 2:
        return 3.0 * e1 * e1 * de1;
      case 3:
        return 4.0 * e1 * e1 * e1 * de1;
      case 4:
        return de1 * e2 + e1 * de2;
      case 5:
        return 2.0 * e1 * de1 * e2 + e1 * e1 * de2;
      case 6:
        return de2;
      default:
        return 2.0 * e2 * de2;
    }
  };
}

}  // namespace

FrazerNash FrazerNash::make(const Params& p, const CurveAt& curves, const std::string& at) {
  double c[kTerms];
  for (int t = 0; t < kTerms; ++t) c[t] = p.c[t];
  if (p.curve >= 0) {
    std::vector<int> fitted;
    std::vector<std::function<double(double)>> terms;
    for (int t = 0; t < kTerms; ++t)
      if (p.c[t] != 0.0) {
        fitted.push_back(t);
        terms.push_back(uniaxialTerm(t));
      }
    const auto fit = fitUniaxial(at, uniaxialTest(at, curves(p.curve), p.sgl, p.sw, p.st), terms);
    for (int t = 0; t < kTerms; ++t) c[t] = 0.0;
    for (std::size_t i = 0; i < fitted.size(); ++i) c[fitted[i]] = fit[i];
  }
  FrazerNash m;
  m.c100 = c[0], m.c200 = c[1], m.c300 = c[2], m.c400 = c[3];
  m.c110 = c[4], m.c210 = c[5], m.c010 = c[6], m.c020 = c[7];
  const double G = m.c100 - 0.5 * m.c010;
  if (!(G > 0.0))
    throw util::InputError(at +
                           "the small-strain shear modulus C100 - C010/2 = " + std::to_string(G) +
                           " is not positive" + (p.curve >= 0 ? " (from the LCID fit)" : ""));
  if (!(p.nu > -1.0 && p.nu < 0.5))
    throw util::InputError(at + "Poisson's ratio must lie in (-1, 0.5)");
  m.moduli = moduliFromShear(G, p.nu);
  return m;
}

namespace {

// The isochoric part of a point's deformation: B_bar = J^-2/3 B and the invariants of the
// Green strain of C_bar, e1 = tr E_bar and e2 = ((tr E_bar)^2 - E_bar:E_bar) / 2, from those of
// B_bar (E_bar:E_bar = (tr C_bar^2 - 2 tr C_bar + 3) / 4, tr C_bar^2 = I1^2 - 2 I2).
struct Isochoric {
  double b[6];
  double e1, e2;
};
Isochoric isochoric(const LeftCauchyGreen& k) {
  Isochoric iso;
  const double s = 1.0 / std::cbrt(k.J * k.J);
  for (int i = 0; i < 6; ++i) iso.b[i] = s * k.b[i];
  const double i1 = s * k.I1, i2 = s * s * k.I2;
  iso.e1 = 0.5 * (i1 - 3.0);
  const double ee = 0.25 * (i1 * i1 - 2.0 * i2 - 2.0 * i1 + 3.0);
  iso.e2 = 0.5 * (iso.e1 * iso.e1 - ee);
  return iso;
}

}  // namespace

double FrazerNash::energy(const LeftCauchyGreen& k) const {
  const auto [b, e1, e2] = isochoric(k);
  return c100 * e1 + c200 * e1 * e1 + c300 * e1 * e1 * e1 + c400 * e1 * e1 * e1 * e1 +
         c110 * e1 * e2 + c210 * e1 * e1 * e2 + c010 * e2 + c020 * e2 * e2 +
         0.5 * moduli.bulk * (k.J - 1.0) * (k.J - 1.0);
}

void FrazerNash::update(PointBatch& p) const {
  for (int l = 0; l < p.n; ++l) {
    const LeftCauchyGreen kin = leftCauchyGreen(p, l);
    const Isochoric iso = isochoric(kin);
    const double e1 = iso.e1, e2 = iso.e2;
    // dU/de1 and dU/de2.
    const double u1 = c100 + e1 * (2.0 * c200 + e1 * (3.0 * c300 + 4.0 * c400 * e1)) + c110 * e2 +
                      2.0 * c210 * e1 * e2;
    const double u2 = c110 * e1 + c210 * e1 * e1 + c010 + 2.0 * c020 * e2;
    // S_bar = u1 I + u2 (e1 I - E_bar) pushed forward by F_bar (F_bar E_bar F_bar^T =
    // (B_bar^2 - B_bar) / 2): tau_bar = (u1 + u2 (e1 + 1/2)) B_bar - u2 B_bar^2 / 2; sigma =
    // dev(tau_bar) / J + K (J - 1) I (Holzapfel 2000, eq. 6.103 and 6.105).
    double b2[6];
    squareOf(iso.b, b2);
    const double cb = u1 + u2 * (e1 + 0.5), cb2 = -0.5 * u2;
    double tau[6];
    for (int i = 0; i < 6; ++i) tau[i] = cb * iso.b[i] + cb2 * b2[i];
    const double mean = (tau[0] + tau[1] + tau[2]) / 3.0;
    const double pressure = moduli.bulk * (kin.J - 1.0);
    for (int i = 0; i < 6; ++i)
      p.s[i][l] = (tau[i] - (i < 3 ? mean : 0.0)) / kin.J + (i < 3 ? pressure : 0.0);
  }
}

}  // namespace crumple::materials
