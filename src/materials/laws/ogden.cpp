#include "materials/laws/ogden.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "materials/principal.hpp"
#include "util/error.hpp"

namespace crumple::materials {

namespace {

constexpr std::array<std::string_view, Ogden::kTerms> kMu{"MU1", "MU2", "MU3", "MU4",
                                                          "MU5", "MU6", "MU7", "MU8"};
constexpr std::array<std::string_view, Ogden::kTerms> kAlpha{
    "ALPHA1", "ALPHA2", "ALPHA3", "ALPHA4", "ALPHA5", "ALPHA6", "ALPHA7", "ALPHA8"};
// The optional viscoelastic cards (GI BETAI VFLAG), up to 12, ended by the next keyword.
constexpr int kViscoCards = 12;
constexpr std::array<std::string_view, kViscoCards> kVisco{
    "viscoelastic card 1", "viscoelastic card 2",  "viscoelastic card 3",  "viscoelastic card 4",
    "viscoelastic card 5", "viscoelastic card 6",  "viscoelastic card 7",  "viscoelastic card 8",
    "viscoelastic card 9", "viscoelastic card 10", "viscoelastic card 11", "viscoelastic card 12"};

std::vector<deck::FieldSpec> realFields(const std::array<std::string_view, Ogden::kTerms>& names) {
  std::vector<deck::FieldSpec> fields;
  for (std::string_view name : names) fields.push_back(deck::R(name));
  return fields;
}

// The cards as the Keyword Manual numbers them: card 2 only when PR < 0, card 3a when N > 0,
// cards 3b.1 and 3b.2 when N <= 0.
deck::KeywordSpec makeSpec() {
  using deck::I;
  using deck::R;
  deck::KeywordSpec spec{
      Ogden::kKeywords[0],
      {deck::titleCard(),
       {"card 1",
        {I("MID"), R("RO"), R("PR"), I("N"), I("NV", 6, deck::kZeroIsDefault), R("G"), R("SIGF"),
         R("REF")}},
       {"card 2",
        {R("TBHYS"), R("LCBI"), R("LCPL"), R("WBI"), R("WPL"), R("D1"), R("D2"), R("D3")}},
       {"card 3a",
        {R("SGL"), R("SW"), R("ST"), I("LCID1"), R("DATA", 1.0), I("LCID2"), R("BSTART"),
         R("TRAMP")}},
       {"card 3b.1", realFields(kMu)},
       {"card 3b.2", realFields(kAlpha)}}};
  for (std::string_view label : kVisco)
    spec.cards.push_back({label, {R("GI"), R("BETAI"), I("VFLAG")}});
  return spec;
}

// MU_j and ALPHA_j (cards 3b.1 and 3b.2, N = 0); a term needs a non-zero exponent, and the terms
// a positive shear modulus.
void readTerms(LawInput& in, Ogden::Params& p) {
  const deck::Card& c2 = in.card("card 3b.1");
  const deck::Card& c3 = in.card("card 3b.2");
  double twice_g = 0.0;
  for (int t = 0; t < Ogden::kTerms; ++t) {
    p.mu[t] = c2.real(kMu[t]);
    p.alpha[t] = c3.real(kAlpha[t]);
    if (p.mu[t] != 0.0 && p.alpha[t] == 0.0)
      c3.fail(kAlpha[t], "a term with MU != 0 needs a non-zero exponent ALPHA");
    twice_g += p.mu[t] * p.alpha[t];
  }
  if (!(twice_g > 0.0)) c2.fail(kMu[0], "the shear modulus sum(MU_i ALPHA_i) / 2 must be positive");
}

// PR < 0: Poisson's ratio is |PR| and card 2 follows. Its hysteresis table and compression
// compliances change the answer (D1 > 0 replaces PR); LCBI, LCPL, WBI, WPL feed only the fit.
void readExtraCard(LawInput& in) {
  const deck::Card& c = in.card("card 2");
  if (c.real("TBHYS") != 0.0) in.reject(c, "TBHYS", "the hysteresis table TBHYS is not supported");
  for (std::string_view d : {"D1", "D2", "D3"})
    if (c.real(d) != 0.0)
      in.reject(c, d, "the compression compliances D1-D3 are not supported: K is taken from PR");
}

// The order N of the fit: N > 0 fits MU_j, ALPHA_j to test curves, N = -1 reads them as curves
// of temperature; only N = 0 (the constants given) is honoured.
void readOrder(LawInput& in, const deck::Card& c, Ogden::Params& p) {
  const int64_t n = c.integer("N");
  if (n < -1 || n > Ogden::kTerms) c.fail("N", "the order of the fit must lie in [-1, 8]");
  if (n > 0) {
    in.reject(c, "N",
              "N > 0 (the nonlinear least-squares fit of MU_i, ALPHA_i to the test curve LCID1) "
              "is not supported: give MU1-MU8 and ALPHA1-ALPHA8 with N = 0");
    in.card("card 3a");
  } else if (n == -1) {
    in.reject(c, "N", "N = -1 (MU_i and ALPHA_i as curves of temperature) is not supported");
    in.card("card 3b.1");
    in.card("card 3b.2");
  } else {
    readTerms(in, p);
  }
}

// The frictional damping of card 1 and the viscoelastic cards change the answer: refused.
void readDamping(LawInput& in, const deck::Card& c1) {
  if (c1.real("G") != 0.0)
    in.reject(c1, "G",
              "frequency-independent (frictional) damping, G != 0 with SIGF, is not supported: "
              "give G = 0 to run without it");
  else if (c1.real("SIGF") != 0.0)
    in.ignore(c1, "SIGF", "G = 0: there is no frictional damping for SIGF to limit");
  for (std::string_view label : kVisco) {
    const deck::Card& v = in.optionalCard(label);
    if (v.real("GI") != 0.0)
      in.reject(v, "GI",
                "viscoelasticity (Prony terms GI, BETAI) is not supported: give GI = 0 to run "
                "without it");
  }
}

}  // namespace

const deck::KeywordSpec& Ogden::cards() {
  static const deck::KeywordSpec spec = makeSpec();
  return spec;
}

Ogden::Params Ogden::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  Params p;
  const double pr = c.real("PR");
  p.nu = std::abs(pr);
  if (!(p.nu < 0.5)) c.fail("PR", "Poisson's ratio |PR| must be below 0.5");
  if (c.real("REF") != 0.0)
    in.reject(c, "REF", "REF = 1 (stress from *INITIAL_FOAM_REFERENCE_GEOMETRY) is not supported");
  if (pr < 0.0) readExtraCard(in);
  readOrder(in, c, p);
  readDamping(in, c);
  return p;
}

Ogden Ogden::make(const Params& p, const CurveAt&, const std::string& at) {
  Ogden m;
  double twice_g = 0.0;
  for (int t = 0; t < kTerms; ++t) {
    if (p.mu[t] == 0.0) continue;
    if (p.alpha[t] == 0.0) throw util::InputError(at + "a term with MU != 0 needs ALPHA != 0");
    m.mu[m.terms] = p.mu[t];
    m.alpha[m.terms++] = p.alpha[t];
    twice_g += p.mu[t] * p.alpha[t];
  }
  if (!(twice_g > 0.0))
    throw util::InputError(at + "the shear modulus sum(MU_i ALPHA_i) / 2 = " +
                           std::to_string(0.5 * twice_g) + " is not positive");
  if (!(p.nu >= 0.0 && p.nu < 0.5))
    throw util::InputError(at + "Poisson's ratio must lie in [0, 0.5)");
  m.moduli = moduliFromShear(0.5 * twice_g, p.nu);
  return m;
}

std::array<double, 3> Ogden::principalStress(const std::array<double, 3>& b, double J) const {
  // lbar_i^alpha = (J^-2/3 b_i)^(alpha/2).
  const double scale = 1.0 / std::cbrt(J * J);
  const double bbar[3] = {scale * b[0], scale * b[1], scale * b[2]};
  std::array<double, 3> tau{};
  for (int t = 0; t < terms; ++t) {
    double pw[3];
    for (int i = 0; i < 3; ++i) pw[i] = std::pow(bbar[i], 0.5 * alpha[t]);
    const double mean = (pw[0] + pw[1] + pw[2]) / 3.0;
    for (int i = 0; i < 3; ++i) tau[static_cast<std::size_t>(i)] += mu[t] * (pw[i] - mean);
  }
  const double volumetric = moduli.bulk * (J - 1.0);  // J dU/dJ of U = K (J - 1 - ln J)
  for (double& s : tau) s = (s + volumetric) / J;
  return tau;
}

void Ogden::update(PointBatch& p) const {
  for (int l = 0; l < p.n; ++l) {
    const LeftCauchyGreen k = leftCauchyGreen(p, l);
    const Principal axes = principalOf({k.b[0], k.b[1], k.b[2], k.b[3], k.b[4], k.b[5]});
    const Voigt s = fromPrincipal(principalStress(axes.value, k.J), axes.axis);
    for (int i = 0; i < 6; ++i) p.s[i][l] = s[static_cast<std::size_t>(i)];
  }
}

double Ogden::energy(const LeftCauchyGreen& k) const {
  const Principal axes = principalOf({k.b[0], k.b[1], k.b[2], k.b[3], k.b[4], k.b[5]});
  const double scale = 1.0 / std::cbrt(k.J * k.J);
  double w = moduli.bulk * (k.J - 1.0 - std::log(k.J));
  for (int t = 0; t < terms; ++t)
    for (double b : axes.value) w += mu[t] / alpha[t] * (std::pow(scale * b, 0.5 * alpha[t]) - 1.0);
  return w;
}

}  // namespace crumple::materials
