#include "materials/laws/piecewise_linear.hpp"

#include <cstddef>
#include <span>
#include <utility>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "util/error.hpp"

namespace crumple::materials {

deck::KeywordSpec PiecewiseLinear::cardsOf(std::string_view keyword,
                                           std::vector<deck::FieldSpec> card2_extra) {
  using deck::I;
  using deck::R;
  std::vector<deck::FieldSpec> card2{R("C"), R("P"), I("LCSS"), I("LCSR"), R("VP")};
  card2.insert(card2.end(), card2_extra.begin(), card2_extra.end());
  return {
      keyword,
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("E"), R("PR"), R("SIGY"), R("ETAN"), R("FAIL"), R("TDEL")}},
       {"card 2", std::move(card2)},
       {"card 3",
        {R("EPS1"), R("EPS2"), R("EPS3"), R("EPS4"), R("EPS5"), R("EPS6"), R("EPS7"), R("EPS8")}},
       {"card 4",
        {R("ES1"), R("ES2"), R("ES3"), R("ES4"), R("ES5"), R("ES6"), R("ES7"), R("ES8")}}}};
}

const deck::KeywordSpec& PiecewiseLinear::cards() {
  static const deck::KeywordSpec spec = cardsOf(kKeywords[0], {});
  return spec;
}

namespace {

// The EPS1-8 / ES1-8 pairs of cards 3-4 up to the end LS-DYNA reads (Keyword Manual,
// *MAT_024): the first blank or zero pair after the first, or the first strain that does not
// increase (trailing zeros of a partly filled card).
void readTable(const deck::Card& c3, const deck::Card& c4, std::vector<double>& eps,
               std::vector<double>& es) {
  for (int i = 1; i <= 8; ++i) {
    const std::string e = "EPS" + std::to_string(i), s = "ES" + std::to_string(i);
    const double ev = c3.real(e), sv = c4.real(s);
    if (i > 1 && c3.blank(e) && c4.blank(s)) break;
    if (i > 1 && ev == 0.0 && sv == 0.0) break;
    if (i > 1 && ev <= eps.back()) {
      c3.real(e);
      c4.real(s);
      break;
    }
    eps.push_back(ev);
    es.push_back(sv);
  }
}

// Hardening (Keyword Manual, *MAT_024): LCSS (a curve, or a *DEFINE_TABLE of one curve per
// strain rate), else the EPS/ES pairs of cards 3-4, else SIGY and ETAN.
void readHardening(LawInput& in, PiecewiseLinear::Params& p, const deck::Card& c,
                   const deck::Card& c2) {
  const deck::Card& c3 = in.optionalCard("card 3");
  const deck::Card& c4 = in.optionalCard("card 4");
  std::vector<double> eps, es;
  readTable(c3, c4, eps, es);
  // The table needs two points; with EPS2 = 0 it has fewer, and SIGY and ETAN give the
  // hardening (older LSTC decks fill ES1-8 and leave EPS1-8 zero).
  const bool table = es.size() >= 2;
  if (!table && es.size() == 1 && es[0] != 0.0) {
    for (int i = 2; i <= 8; ++i) c4.real("ES" + std::to_string(i));  // covered by the note
    in.ignore(c4, "ES1",
              "the EPS/ES table has fewer than two increasing strains (EPS2 = 0): SIGY and ETAN "
              "define the hardening");
  }
  if (const int64_t lcss = c2.integer("LCSS"); lcss != 0) {
    p.table = in.table(c2, "LCSS", lcss);
    if (p.table < 0) p.lcss = in.curveOrReject(c2, "LCSS", lcss);
  } else if (table) {
    // A curve of its own, id -MID, so that the solver sees one hardening representation.
    p.lcss = in.addCurve(-in.materialId(), std::move(eps), std::move(es));
  } else {
    checkYield(c, p.E, p.sigy, p.etan);
  }
}

// Rate dependence (Keyword Manual, *MAT_024, LCSS and LCSR): a table in LCSS gives it, and C,
// P and LCSR are then ignored; else an LCSR curve scales the yield stress, in place of the
// Cowper-Symonds factor of C and P. VP picks the rate they take: 0 the total effective strain
// rate of the step, 1 (viscoplastic) the plastic strain rate, in the consistency condition;
// VP = -1 (the deviatoric rate of the Cowper-Symonds factor) and 3 (filtered rates) change the
// answer and are refused. Without a rate form VP acts on nothing.
void readRate(LawInput& in, PiecewiseLinear::Params& p, const deck::Card& c2) {
  const int64_t lcsr = c2.integer("LCSR");
  const bool cowper = p.c != 0.0 || p.p != 0.0;
  if (p.table >= 0) {
    if (cowper) in.ignore(c2, "C", "LCSS names a rate table, which gives the rate dependence");
    if (lcsr != 0)
      in.ignore(c2, "LCSR", "LCSS names a rate table, which gives the rate dependence");
  } else if (lcsr != 0) {
    p.lcsr = in.curve(c2, "LCSR", lcsr);
    if (cowper) in.ignore(c2, "C", "LCSR gives the rate dependence: C and P are not used");
  }
  if (p.table >= 0 || p.lcsr >= 0) p.c = p.p = 0.0;
  const double vp = c2.real("VP");
  if (p.table < 0 && p.lcsr < 0 && !(p.c > 0.0 && p.p > 0.0)) {
    if (vp != 0.0) in.ignore(c2, "VP", "no rate dependence (C and P, LCSR or a table) to act on");
    return;
  }
  if (vp == 1.0) {
    p.viscoplastic = true;
  } else if (vp != 0.0) {
    in.reject(c2, "VP",
              "VP is 0 (the yield stress at the total effective strain rate) or 1 "
              "(viscoplastic: at the plastic strain rate); -1 and 3 are not supported");
  }
}

}  // namespace

PiecewiseLinear::Params PiecewiseLinear::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  const deck::Card& c2 = in.optionalCard("card 2");
  Params p;
  readElastic(c, p.E, p.nu);
  p.sigy = c.real("SIGY");
  p.etan = c.real("ETAN");
  p.fail = c.real("FAIL");
  if (p.fail < 0) {
    in.reject(c, "FAIL", "a user failure subroutine (FAIL < 0) is not supported");
    p.fail = 0;
  }
  p.tdel = c.real("TDEL");
  p.c = c2.real("C");
  p.p = c2.real("P");
  readHardening(in, p, c, c2);
  readRate(in, p, c2);
  return p;
}

namespace {

// The LCSR curve: strain rates (non-decreasing, as every curve) and positive factors.
void makeRateCurve(PiecewiseLinear& law, const CurveData& c, const std::string& at) {
  const std::string name = "LCSR curve " + std::to_string(c.id);
  if (c.x.empty() || c.x.size() != c.y.size()) throw util::InputError(at + name + " has no points");
  for (std::size_t k = 0; k < c.y.size(); ++k) {
    if (k > 0 && !(c.x[k] >= c.x[k - 1]))
      throw util::InputError(at + name + " must have non-decreasing strain rates");
    if (!(c.y[k] > 0.0)) throw util::InputError(at + name + " must have positive scale factors");
  }
  law.lcsr_rate.assign(c.x.begin(), c.x.end());
  law.lcsr_factor.assign(c.y.begin(), c.y.end());
}

// The yield curve of LCSS: non-decreasing plastic strains.
void makeCurve(PiecewiseLinear& law, const CurveData& c, const std::string& at) {
  const std::string name = "LCSS curve " + std::to_string(c.id);
  if (c.x.empty() || c.x.size() != c.y.size()) throw util::InputError(at + name + " has no points");
  for (std::size_t k = 1; k < c.x.size(); ++k)
    if (!(c.x[k] >= c.x[k - 1]))
      throw util::InputError(at + name + " must have non-decreasing plastic strains");
  law.curve_eps.assign(c.x.begin(), c.x.end());
  law.curve_sig.assign(c.y.begin(), c.y.end());
}

}  // namespace

PiecewiseLinear PiecewiseLinear::make(const Params& p, const CurveAt& curves,
                                      const std::string& at) {
  checkModuli(at, p.E, p.nu);
  PiecewiseLinear law;
  law.moduli = moduliFromYoung(p.E, p.nu);
  law.linear.sigy = p.sigy;
  // One rate form (Keyword Manual, *MAT_024): a table, else LCSR, else C and P.
  if (p.table >= 0) {
    law.table = makeRateTable(curves, p.table, at);
  } else if (p.lcsr >= 0) {
    makeRateCurve(law, curves(p.lcsr), at);
  } else if (p.c > 0.0 && p.p > 0.0) {
    law.linear.C = p.c;
    law.linear.inv_P = 1.0 / p.p;
  }
  law.fail = p.fail;
  law.tdel = p.tdel;
  law.viscoplastic = p.viscoplastic;
  if (p.table < 0 && p.lcss < 0) {
    checkTangent(at, p.E, p.etan);
    law.linear.Hi = plasticModulus(youngOf(law.moduli), p.etan);
    // VP = 1 runs on the curve returns (the linear ones take the rate factor outside the
    // return): the bilinear hardening as the curve it is, extrapolated past its second point.
    if (law.viscoplastic) {
      law.curve_eps = {0.0, 1.0};
      law.curve_sig = {p.sigy, p.sigy + law.linear.Hi};
    }
    return law;
  }
  // LCSS given: SIGY and ETAN are ignored (Keyword Manual, *MAT_024); the initial yield
  // stress is the curve's value at zero plastic strain (a table's: its first curve's).
  if (p.table < 0) makeCurve(law, curves(p.lcss), at);
  law.linear.sigy = law.yieldStress(0.0);
  return law;
}

double PiecewiseLinear::yieldStress(double eps_p) const {
  if (!table.rates.empty()) {
    CurveHardening first;  // the table's first (lowest-rate) curve
    first.eps = table.eps;
    first.sig = std::span<const double>(table.sig).first(table.eps.size());
    return curveFlowStress(first, eps_p);
  }
  if (curve_eps.empty()) return linear.sigy + linear.Hi * eps_p;
  return curveFlowStress(curve(), eps_p);
}

void PiecewiseLinear::update(PointBatch& b) const {
  if (!hasCurve()) {
    // Bilinear: purely isotropic linear hardening (b.alpha is not required for this law).
    linearHardeningReturn(b, moduli, bilinear(), false);
  } else {
    curveHardeningReturn(b, moduli, curve());
  }
  markFailed(b, fail);
}

void PiecewiseLinear::updatePlaneStress(PlaneStressPoints& b) const {
  if (!hasCurve()) {
    planeStressLinear(b, moduli, bilinear(), false);
  } else {
    planeStressCurve(b, moduli, curve());
  }
  markFailed(b, fail);
}

FibreLaw PiecewiseLinear::fibre() const {
  FibreLaw f;
  f.E = youngOf(moduli);
  f.G = moduli.shear;
  f.plastic = true;
  f.sigy = linear.sigy;  // the curve's value at zero plastic strain when there is a curve
  f.Hi = linear.Hi;
  f.curve_eps = curve_eps;
  f.curve_sig = curve_sig;
  f.C = linear.C;
  f.inv_P = linear.inv_P;
  f.lcsr = rateCurve();
  f.table = table.view();
  f.viscoplastic = viscoplastic;
  f.fail = fail;
  return f;
}

}  // namespace crumple::materials
