#include "materials/laws/crushable_foam.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "materials/principal.hpp"
#include "util/curve.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& CrushableFoam::cards() {
  using deck::I;
  using deck::R;
  // MODEL (field 8) came with the elliptical yield surfaces of later versions; its card 2 (PRP,
  // K, RFILTF, BVFLAG, SRCRT, ESCAL, KT) belongs to MODEL 1 and 2 only. NCYCLE, SRCLMT and
  // SFLAG are fields of *MAT_MODIFIED_CRUSHABLE_FOAM (163), not of this keyword.
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1",
        {I("MID"), R("RO"), R("E"), R("PR"), I("LCID"), R("TSC"), R("DAMP"), I("MODEL")}}}};
  return spec;
}

namespace {

// DAMP adds a viscous stress proportional to rho c L times the strain rate (OpenRadioss
// /MAT/LAW163, sigeps163.F90, the port of LS-DYNA's crushable foams; IMPETUS MAT_FOAM). It
// needs the element's characteristic length and a viscous stress kept apart from the stored
// one, neither of which a law sees (law.hpp, PointBatch), so a positive DAMP is refused. LS-DYNA
// is documented to default DAMP to 0.10 (OpenRadioss keyword CFG for *MAT_CRUSHABLE_FOAM); a
// blank or zero DAMP runs undamped here, and check says so.
void readDamping(LawInput& in, const deck::Card& c) {
  const double damp = c.real("DAMP");
  if (damp < 0) c.fail("DAMP", "the damping coefficient must not be negative");
  if (damp > 0)
    in.reject(c, "DAMP",
              "viscous damping (DAMP > 0) is not supported: give DAMP = 0 to run without it");
  else
    in.ignore(c, "DAMP", "blank or 0: run without damping (LS-DYNA's documented default is 0.10)");
}

}  // namespace

CrushableFoam::Params CrushableFoam::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  Params p;
  readElastic(c, p.E, p.nu);
  p.tsc = c.real("TSC");
  if (p.tsc < 0) c.fail("TSC", "the tensile stress cutoff must not be negative (0: no tension)");
  readDamping(in, c);
  if (const int64_t model = c.integer("MODEL"); model != 0)
    in.reject(c, "MODEL",
              "MODEL " + std::to_string(model) +
                  " (elliptical yield surface) is not supported: only MODEL 0 is");
  const int64_t lcid = c.integer("LCID");
  if (lcid == 0) c.fail("LCID", "a curve of yield stress vs volumetric strain is required");
  p.curve = in.curveOrReject(c, "LCID", lcid);
  return p;
}

namespace {

// The curve's checks: at least one segment, volumetric strains increasing, no negative yield
// stress, and a rising last segment, whose slope is the elastic modulus.
double lastSlope(const std::string& at, const CurveData& c) {
  const std::string name = "LCID curve " + std::to_string(c.id);
  if (c.x.size() < 2 || c.x.size() != c.y.size())
    throw util::InputError(at + name + " needs at least two points");
  for (std::size_t k = 0; k < c.x.size(); ++k) {
    if (k > 0 && !(c.x[k] > c.x[k - 1]))
      throw util::InputError(at + name + ": the volumetric strains must increase");
    if (!(c.y[k] >= 0.0))
      throw util::InputError(at + name + ": the yield stresses must not be negative");
  }
  const std::size_t n = c.x.size() - 1;
  const double slope = (c.y[n] - c.y[n - 1]) / (c.x[n] - c.x[n - 1]);
  if (!(slope > 0.0))
    throw util::InputError(at + name +
                           ": the last segment must rise, as its slope is the elastic modulus "
                           "(LS-DYNA MODEL 0 uses E only for contact)");
  return slope;
}

}  // namespace

CrushableFoam CrushableFoam::make(const Params& p, const CurveAt& curves, const std::string& at) {
  checkModuli(at, p.E, p.nu);
  if (!(p.tsc >= 0.0)) throw util::InputError(at + "TSC must not be negative");
  const CurveData c = curves(p.curve);
  CrushableFoam law;
  law.moduli = moduliFromYoung(lastSlope(at, c), p.nu);
  law.tsc = p.tsc;
  law.gamma.assign(c.x.begin(), c.x.end());
  law.yield.assign(c.y.begin(), c.y.end());
  return law;
}

double CrushableFoam::yieldStress(double gamma_max) const {
  const double y = util::onSegment(gamma, yield, util::segmentOf(gamma, gamma_max), gamma_max);
  return std::max(y, 0.0);
}

void CrushableFoam::update(PointBatch& b) const {
  const double G2 = 2.0 * moduli.shear, lambda = moduli.bulk - G2 / 3.0;
  for (int i = 0; i < b.n; ++i) {
    const double tr = b.de[0][i] + b.de[1][i] + b.de[2][i];
    // gamma = 1 - V/V0 from ln(V/V0); the yield stress is that of the largest gamma reached.
    const double ln_v = b.h[0][i] + tr;
    const double gamma_max = std::max(b.h[1][i], -std::expm1(ln_v));
    // Elastic trial (the stress arrives rotated to the end of the step).
    Voigt trial;
    for (int k = 0; k < 6; ++k) trial[k] = b.s[k][i] + G2 * b.de[k][i] + (k < 3 ? lambda * tr : 0);
    // Principal stresses confined to [-Y(gamma_max), TSC] on their axes, as OpenRadioss
    // sigeps163.F90 caps them (compressive at -Y, tensile at TSC).
    const Voigt s = clampPrincipal(trial, -yieldStress(gamma_max), tsc);
    for (int k = 0; k < 6; ++k) b.s[k][i] = s[k];
    b.h[0][i] = ln_v;
    b.h[1][i] = gamma_max;
  }
}

}  // namespace crumple::materials
