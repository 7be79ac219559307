#include "materials/laws/soil_foam.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "util/curve.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& SoilAndFoam::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("G"), R("KUN"), R("A0"), R("A1"), R("A2"), R("PC")}},
       {"card 2", {R("VCR"), R("REF"), I("LCID")}},
       {"card 3",
        {R("EPS1"), R("EPS2"), R("EPS3"), R("EPS4"), R("EPS5"), R("EPS6"), R("EPS7"), R("EPS8")}},
       {"card 4", {R("EPS9"), R("EPS10")}},
       {"card 5", {R("P1"), R("P2"), R("P3"), R("P4"), R("P5"), R("P6"), R("P7"), R("P8")}},
       {"card 6", {R("P9"), R("P10")}}}};
  return spec;
}

namespace {

// The EPS/P pairs of cards 3-6 as (x = -EPS, P), up to the first blank or zero pair after the
// first (unused slots of the ten).
void readTable(LawInput& in, std::vector<double>& x, std::vector<double>& p) {
  const deck::Card* eps[2] = {&in.optionalCard("card 3"), &in.optionalCard("card 4")};
  const deck::Card* prs[2] = {&in.optionalCard("card 5"), &in.optionalCard("card 6")};
  for (int i = 1; i <= 10; ++i) {
    const deck::Card& ce = *eps[i > 8 ? 1 : 0];
    const deck::Card& cp = *prs[i > 8 ? 1 : 0];
    const std::string e = "EPS" + std::to_string(i), f = "P" + std::to_string(i);
    const double ev = ce.real(e), pv = cp.real(f);
    if (i > 1 && ev == 0.0 && pv == 0.0) break;
    if (ev > 0.0) ce.fail(e, "volumetric strains are ln(V/V0): negative in compression");
    if (!x.empty() && -ev <= x.back())
      ce.fail(e, "the volumetric strains must grow in compression (decrease) point by point");
    x.push_back(-ev);
    p.push_back(pv);
  }
}

void checkParams(const deck::Card& c, const SoilAndFoam::Params& p) {
  if (!(p.G > 0)) c.fail("G", "the shear modulus must be positive");
  if (p.crush && !(p.kun > 0)) c.fail("KUN", "the unloading bulk modulus must be positive");
  if (p.kun < 0) c.fail("KUN", "must not be negative");
  if (p.pc > 0) c.fail("PC", "the tensile cutoff is a pressure: zero or negative");
  if (p.a0 < 0) c.fail("A0", "must not be negative");
}

}  // namespace

SoilAndFoam::Params SoilAndFoam::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  const deck::Card& c2 = in.optionalCard("card 2");
  Params p;
  p.G = c.real("G");
  p.kun = c.real("KUN");
  p.a0 = c.real("A0");
  p.a1 = c.real("A1");
  p.a2 = c.real("A2");
  p.pc = c.real("PC");
  const double vcr = c2.real("VCR");
  if (vcr != 0.0 && vcr != 1.0) c2.fail("VCR", "must be 0 or 1");
  p.crush = vcr == 0.0;
  if (c2.real("REF") != 0.0)
    in.reject(c2, "REF",
              "a reference geometry (*INITIAL_FOAM_REFERENCE_GEOMETRY) is not supported");
  checkParams(c, p);
  std::vector<double> x, pr;
  readTable(in, x, pr);
  // LCID (abscissa ln(V/V0), ordinate pressure) replaces the table (Keyword Manual).
  if (const int64_t lcid = c2.integer("LCID"); lcid != 0) {
    p.curve = in.curveOrReject(c2, "LCID", lcid);
    return p;
  }
  if (x.size() < 2 && !(x.size() == 1 && x[0] > 0.0))
    c.fail("MID", "*MAT_SOIL_AND_FOAM needs at least two points EPS/P (or LCID)");
  p.curve = in.addCurve(-in.materialId(), std::move(x), std::move(pr));
  return p;
}

SoilAndFoam SoilAndFoam::make(const Params& p, const CurveAt& curves, const std::string& at) {
  SoilAndFoam law;
  law.G = p.G;
  law.kun = p.kun;
  law.a0 = p.a0;
  law.a1 = p.a1;
  law.a2 = p.a2;
  law.pc = p.pc;
  law.crush = p.crush;
  const CurveData c = curves(p.curve);
  // The table (id -MID) holds x = -EPS already; a curve of the deck (LCID) holds ln(V/V0),
  // written in either order.
  const bool table = c.id < 0;
  std::vector<std::pair<double, double>> points;
  for (std::size_t i = 0; i < c.x.size(); ++i)
    points.emplace_back(table ? c.x[i] : -c.x[i], c.y[i]);
  std::sort(points.begin(), points.end());
  for (const auto& [xi, pi] : points) {
    law.x.push_back(xi);
    law.p.push_back(pi);
  }
  if (law.x.empty() || law.x.front() < 0.0)
    throw util::InputError(at +
                           "the pressure curve must start at zero volumetric strain or in "
                           "compression");
  // LS-DYNA puts a first point at the origin when the table starts in compression.
  if (law.x.front() > 0.0) {
    law.x.insert(law.x.begin(), 0.0);
    law.p.insert(law.p.begin(), 0.0);
  }
  double stiffest = law.kun;
  for (std::size_t i = 1; i < law.x.size(); ++i) {
    if (!(law.x[i] > law.x[i - 1]))
      throw util::InputError(at + "the volumetric strains of the pressure curve must increase");
    stiffest = std::max(stiffest, (law.p[i] - law.p[i - 1]) / (law.x[i] - law.x[i - 1]));
  }
  // Without crushing (VCR = 1) KUN only sets the dilatation response; blank: the stiffest slope.
  if (!(law.kun > 0.0)) law.kun = stiffest;
  law.moduli = Moduli{stiffest, p.G};
  return law;
}

double SoilAndFoam::pressure(double x_new, double& x_max) const {
  const auto curve = [&](double t) { return util::onSegment(x, p, util::segmentOf(x, t), t); };
  if (!crush) return x_new >= 0.0 ? curve(x_new) : kun * x_new;
  if (x_new >= x_max) {
    x_max = x_new;
    return curve(x_new);
  }
  return curve(x_max) - kun * (x_max - x_new);
}

void SoilAndFoam::update(PointBatch& b) const {
  const double G2 = 2.0 * G;
  for (int i = 0; i < b.n; ++i) {
    const double d0 = b.de[0][i], d1 = b.de[1][i], d2 = b.de[2][i];
    const double tr = d0 + d1 + d2;
    // Volumetric part: x = -ln(V/V0) grows by -tr(de); pressure from the curve, cut at PC.
    const double x_new = b.h[0][i] - tr;
    double x_max = b.h[1][i];
    const double p_trial = pressure(x_new, x_max);
    const bool cut = p_trial < pc;
    const double pr = cut ? pc : p_trial;
    // Deviatoric trial (the stress arrives rotated), returned radially onto the surface of the
    // new pressure.
    const double p_old = -(b.s[0][i] + b.s[1][i] + b.s[2][i]) / 3.0;
    const double em = tr / 3.0;
    double s[6] = {b.s[0][i] + p_old + G2 * (d0 - em), b.s[1][i] + p_old + G2 * (d1 - em),
                   b.s[2][i] + p_old + G2 * (d2 - em), b.s[3][i] + G2 * b.de[3][i],
                   b.s[4][i] + G2 * b.de[4][i],        b.s[5][i] + G2 * b.de[5][i]};
    const double j2 =
        0.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) + s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
    const double g = std::max(a0 + a1 * pr + a2 * pr * pr, 0.0);
    const double scale = cut || g == 0.0 ? 0.0 : (j2 > g ? std::sqrt(g / j2) : 1.0);
    for (int k = 0; k < 6; ++k) b.s[k][i] = scale * s[k] - (k < 3 ? pr : 0.0);
    b.h[0][i] = x_new;
    b.h[1][i] = x_max;
  }
}

}  // namespace crumple::materials
