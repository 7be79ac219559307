#include "materials/laws/elastic_plastic_hydro.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "materials/eos_return.hpp"
#include "materials/return_mapping.hpp"
#include "util/error.hpp"

namespace crumple::materials {

namespace {

// The fields of a card of eight EPS or ES values: EPS1-8, EPS9-16, ES1-8, ES9-16 (names with
// static storage: the specs keep views of them).
std::vector<deck::FieldSpec> pointFields(int card) {
  static constexpr const char* kNames[4][8] = {
      {"EPS1", "EPS2", "EPS3", "EPS4", "EPS5", "EPS6", "EPS7", "EPS8"},
      {"EPS9", "EPS10", "EPS11", "EPS12", "EPS13", "EPS14", "EPS15", "EPS16"},
      {"ES1", "ES2", "ES3", "ES4", "ES5", "ES6", "ES7", "ES8"},
      {"ES9", "ES10", "ES11", "ES12", "ES13", "ES14", "ES15", "ES16"}};
  std::vector<deck::FieldSpec> f;
  for (const char* name : kNames[card]) f.push_back(deck::R(name));
  return f;
}

}  // namespace

const deck::KeywordSpec& ElasticPlasticHydro::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("G"), R("SIG0"), R("EH"), R("PC"), R("FS"), R("CHARL")}},
       {"card 2", pointFields(0)},
       {"card 3", pointFields(1)},
       {"card 4", pointFields(2)},
       {"card 5", pointFields(3)}}};
  return spec;
}

namespace {

// The EPS/ES pairs (Keyword Manual, *MAT_010: up to 16 points) up to the first blank or zero
// pair after the first, or the first strain that does not increase (trailing zeros).
void readTable(const deck::Card* eps_cards[2], const deck::Card* es_cards[2],
               std::vector<double>& eps, std::vector<double>& es) {
  for (int i = 1; i <= 16; ++i) {
    const deck::Card& ce = *eps_cards[(i - 1) / 8];
    const deck::Card& cs = *es_cards[(i - 1) / 8];
    const std::string e = "EPS" + std::to_string(i), s = "ES" + std::to_string(i);
    const double ev = ce.real(e), sv = cs.real(s);
    if (i > 1 && ((ce.blank(e) && cs.blank(s)) || (ev == 0.0 && sv == 0.0) || ev <= eps.back()))
      break;
    eps.push_back(ev);
    es.push_back(sv);
  }
}

// The hardening: the EPS/ES table when it has two points or more (a curve of its own, id
// -MID), else SIG0 and EH.
void readHardening(LawInput& in, ElasticPlasticHydro::Params& p, const deck::Card& c1) {
  const deck::Card* eps_cards[2] = {&in.optionalCard("card 2"), &in.optionalCard("card 3")};
  const deck::Card* es_cards[2] = {&in.optionalCard("card 4"), &in.optionalCard("card 5")};
  std::vector<double> eps, es;
  readTable(eps_cards, es_cards, eps, es);
  for (int i = 1; i <= 16; ++i) {  // every field is read; the ones past the table are zeros
    eps_cards[(i - 1) / 8]->real("EPS" + std::to_string(i));
    es_cards[(i - 1) / 8]->real("ES" + std::to_string(i));
  }
  if (es.size() >= 2) {
    if (std::any_of(es.begin(), es.end(), [](double s) { return !(s > 0.0); }))
      es_cards[0]->fail("ES1", "the yield stresses of the EPS/ES table must be positive");
    p.curve = in.addCurve(-in.materialId(), std::move(eps), std::move(es));
    return;
  }
  if (!(p.sig0 > 0.0)) c1.fail("SIG0", "the yield stress must be positive (no EPS/ES table)");
  if (p.eh < 0.0) c1.fail("EH", "the plastic hardening modulus must not be negative");
}

}  // namespace

ElasticPlasticHydro::Params ElasticPlasticHydro::read(LawInput& in) {
  const deck::Card& c1 = in.card("card 1");
  Params p;
  p.rho = c1.real("RO");
  p.G = c1.real("G");
  p.sig0 = c1.real("SIG0");
  p.eh = c1.real("EH");
  p.pc = c1.real("PC");
  p.fs = c1.real("FS");
  if (!(p.G > 0.0)) c1.fail("G", "the shear modulus must be positive");
  if (p.pc > 0.0) c1.fail("PC", "the pressure cutoff is a tension limit: zero or negative");
  if (p.fs < 0.0) c1.fail("FS", "the failure strain must not be negative (0: none)");
  // CHARL deletes thinned boundary elements of 2D solids only (Keyword Manual): no effect on
  // the 3-D solids and SPH particles Crumple gives this law.
  if (c1.real("CHARL") != 0.0) in.ignore(c1, "CHARL", "used by 2D solids only");
  readHardening(in, p, c1);
  return p;
}

ElasticPlasticHydro ElasticPlasticHydro::make(const Params& p, const CurveAt& curves,
                                              const std::string& at, const Eos* eos) {
  if (!(p.rho > 0.0)) throw util::InputError(at + "RO must be positive");
  if (!(p.G > 0.0)) throw util::InputError(at + "G must be positive");
  if (p.pc > 0.0) throw util::InputError(at + "PC must be zero or negative");
  if (p.curve < 0 && !(p.sig0 > 0.0 && p.eh >= 0.0))
    throw util::InputError(at + "SIG0 must be positive and EH not negative");
  if (!eos) throw util::InputError(at + "needs an equation of state (*PART EOSID) on its solids");
  checkEos(at, *eos, p.rho);
  ElasticPlasticHydro law;
  law.par = p;
  law.eos = *eos;
  law.moduli = Moduli{eosBulkModulus(*eos, p.rho), p.G};
  if (p.curve >= 0) {
    const CurveData c = curves(p.curve);
    if (c.x.size() < 2 || c.x.size() != c.y.size())
      throw util::InputError(at + "the EPS/ES table needs two points or more");
    law.curve_eps.assign(c.x.begin(), c.x.end());
    law.curve_sig.assign(c.y.begin(), c.y.end());
  }
  return law;
}

void ElasticPlasticHydro::flow(double eps_p, double& y, double& h) const {
  if (curve_eps.empty()) {
    y = par.sig0 + par.eh * eps_p;
    h = par.eh;
    return;
  }
  // The segment holding eps_p (the end segments extended): its value and slope.
  const auto it = std::upper_bound(curve_eps.begin() + 1, curve_eps.end() - 1, eps_p);
  const std::size_t k = static_cast<std::size_t>(it - curve_eps.begin());
  const double x0 = curve_eps[k - 1], x1 = curve_eps[k];
  h = (curve_sig[k] - curve_sig[k - 1]) / (x1 - x0);
  y = curve_sig[k - 1] + h * (eps_p - x0);
}

double ElasticPlasticHydro::cutoff() const {
  return par.pc < 0.0 ? par.pc : -std::numeric_limits<double>::infinity();
}

void ElasticPlasticHydro::update(PointBatch& b) const {
  const double pc = cutoff();
  const auto yield = [this](double e, double& y, double& h) { flow(e, y, h); };
  for (int i = 0; i < b.n; ++i) {
    const double e = b.eps_p[i];
    const EosReturn r =
        eosRadialReturn(b, i, par.G, eos, par.rho, pc, [&](double q, const double*) {
          double y = 0.0, h = 0.0;
          flow(e, y, h);
          return q > y ? radialReturnIncrement(q, e, 3.0 * par.G, yield) : 0.0;
        });
    b.eps_p[i] = e + r.x;
  }
  if (par.fs > 0.0) markFailed(b, par.fs);
}

}  // namespace crumple::materials
