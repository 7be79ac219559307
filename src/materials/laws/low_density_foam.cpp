#include "materials/laws/low_density_foam.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "materials/hyperelastic.hpp"
#include "materials/principal.hpp"
#include "util/curve.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& LowDensityFoam::cards() {
  using deck::I;
  using deck::R;
  // Defaults of the Keyword Manual. LS-DYNA's fixed-format reader cannot tell a blank from a
  // zero, so TC, HU and SHAPE take theirs for 0 too (TC = 0 would forbid all tension, SHAPE = 0
  // switch HU off). DAMP's 0.05 is kept for a blank only: an explicit 0 asks for no damping.
  const auto Z = deck::kZeroIsDefault;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1",
        {I("MID"), R("RO"), R("E"), I("LCID"), R("TC", 1e20, Z), R("HU", 1.0, Z), R("BETA"),
         R("DAMP", 0.05)}},
       {"card 2",
        {R("SHAPE", 1.0, Z), R("FAIL"), R("BVFLAG"), R("ED"), R("BETA1"), R("KCON"), R("REF")}}}};
  return spec;
}

namespace {

// Card 1's checks: E, TC, HU and the curve.
void readCard1(LawInput& in, const deck::Card& c, LowDensityFoam::Params& p) {
  p.young = c.real("E");
  if (!(p.young > 0)) c.fail("E", "Young's modulus (the tensile stiffness) must be positive");
  p.tc = c.real("TC");
  if (!(p.tc > 0)) c.fail("TC", "the tension cutoff must be positive (0 or blank: 1e20)");
  p.hu = c.real("HU");
  if (!(p.hu > 0 && p.hu <= 1)) c.fail("HU", "the hysteretic unloading factor must lie in (0, 1]");
  const int64_t lcid = c.integer("LCID");
  if (lcid == 0) c.fail("LCID", "a curve of nominal stress vs strain in compression is required");
  p.curve = in.curveOrReject(c, "LCID", lcid);
}

// The options of card 1 Crumple does not have: the creep of the unloading curve and the
// viscous damping.
void readCard1Options(LawInput& in, const deck::Card& c) {
  if (c.real("BETA") != 0.0)
    in.reject(c, "BETA",
              "the decay of the unloading curve back to the loading curve (BETA != 0) is not "
              "supported: give BETA = 0 (reloading follows the unloading curve)");
  // DAMP's stress needs the element's length and wave speed, which a law does not see
  // (PointBatch), as for *MAT_CRUSHABLE_FOAM. Following that law, a blank DAMP runs undamped and
  // is noted, an explicit 0 is honoured, and a value is refused.
  const double damp = c.real("DAMP");
  if (c.blank("DAMP"))
    in.ignore(c, "DAMP", "blank: run without viscous damping (LS-DYNA's default is 0.05)");
  else if (damp < 0.0)
    in.reject(c, "DAMP", "a damping curve (DAMP < 0) is not supported: give DAMP = 0");
  else if (damp > 0.0)
    in.reject(c, "DAMP",
              "viscous damping (DAMP > 0) is not supported: give DAMP = 0 to run without it");
}

// Card 2: SHAPE, FAIL, BVFLAG honoured; ED (rate effects) and REF refused; KCON the contact
// modulus.
void readCard2(LawInput& in, const deck::Card& c, LowDensityFoam::Params& p) {
  p.shape = c.real("SHAPE");
  if (!(p.shape > 0)) c.fail("SHAPE", "the unloading shape factor must be positive");
  const double fail = c.real("FAIL"), bv = c.real("BVFLAG");
  if (fail != 0.0 && fail != 1.0) c.fail("FAIL", "must be 0 (stay at TC) or 1 (tear)");
  if (bv != 0.0 && bv != 1.0) c.fail("BVFLAG", "must be 0 (no bulk viscosity) or 1");
  p.tear = fail == 1.0;
  p.bulk_viscosity = bv == 1.0;
  if (c.real("ED") != 0.0)
    in.reject(c, "ED",
              "rate effects (the Maxwell element ED, BETA1) are not supported: give ED = 0");
  else if (c.real("BETA1") != 0.0)
    in.ignore(c, "BETA1", "the decay constant of ED, which is 0: no rate effects");
  const double kcon = c.real("KCON");
  if (kcon < 0.0) c.fail("KCON", "the contact stiffness modulus must not be negative");
  p.E = kcon > 0.0 ? kcon : p.young;
  if (kcon > 0.0)
    in.ignore(c, "KCON", "sets the contact stiffness only: the time step keeps E_max");
  if (c.real("REF") != 0.0)
    in.reject(c, "REF", "REF = 1 (stress from *INITIAL_FOAM_REFERENCE_GEOMETRY) is not supported");
}

}  // namespace

LowDensityFoam::Params LowDensityFoam::read(LawInput& in) {
  const deck::Card& c1 = in.card("card 1");
  Params p;
  readCard1(in, c1, p);
  readCard1Options(in, c1);
  readCard2(in, in.optionalCard("card 2"), p);
  return p;
}

namespace {

// The compressive part of LCID (strain >= 0, ascending) from the origin: a curve starting
// past zero strain gets the point (0, 0) (as *MAT_SOIL_AND_FOAM's table does); one with a
// point at zero strain must have zero stress there (else the unstrained foam is stressed).
// Points at negative strain (tension) are not used: the Theory Manual takes the tensile nominal
// stress as E (lambda - 1).
void compressionBranch(const std::string& at, const CurveData& c, std::vector<double>& x,
                       std::vector<double>& y) {
  const std::string name = "LCID curve " + std::to_string(c.id);
  for (std::size_t k = 0; k < c.x.size(); ++k) {
    if (k > 0 && !(c.x[k] > c.x[k - 1]))
      throw util::InputError(at + name + ": the strains must increase");
    if (c.x[k] < 0.0) continue;
    if (!(c.y[k] >= 0.0))
      throw util::InputError(at + name +
                             ": the nominal stress in compression (strain >= 0) must not be "
                             "negative");
    x.push_back(c.x[k]);
    y.push_back(c.y[k]);
  }
  if (x.empty()) throw util::InputError(at + name + " has no point in compression (strain > 0)");
  if (x.front() > 0.0) {
    x.insert(x.begin(), 0.0);
    y.insert(y.begin(), 0.0);
  } else if (y.front() != 0.0) {
    throw util::InputError(at + name + ": the nominal stress at zero strain must be 0");
  }
  if (x.size() < 2) throw util::InputError(at + name + " needs a point at a strain above 0");
}

}  // namespace

LowDensityFoam LowDensityFoam::make(const Params& p, const CurveAt& curves, const std::string& at) {
  if (!(p.young > 0.0)) throw util::InputError(at + "E must be positive");
  if (!(p.tc > 0.0)) throw util::InputError(at + "TC must be positive");
  if (!(p.hu > 0.0 && p.hu <= 1.0)) throw util::InputError(at + "HU must lie in (0, 1]");
  if (!(p.shape > 0.0)) throw util::InputError(at + "SHAPE must be positive");
  LowDensityFoam law;
  law.young = p.young;
  law.tc = p.tc;
  law.hu = p.hu;
  law.shape = p.shape;
  law.tear = p.tear;
  law.bulk_visc = p.bulk_viscosity;
  compressionBranch(at, curves(p.curve), law.strain, law.stress);
  // The time step must hold for the stiffest slope the curve reaches (LS-DYNA takes the
  // larger of E and the curve's largest slope, unless KCON is given: Keyword Manual, KCON).
  double e_max = p.young;
  law.energy.assign(1, 0.0);
  for (std::size_t k = 1; k < law.strain.size(); ++k) {
    const double dx = law.strain[k] - law.strain[k - 1];
    e_max = std::max(e_max, (law.stress[k] - law.stress[k - 1]) / dx);
    law.energy.push_back(law.energy.back() + 0.5 * dx * (law.stress[k] + law.stress[k - 1]));
  }
  law.moduli = Moduli{e_max / 3.0, e_max / 2.0};
  return law;
}

double LowDensityFoam::nominal(double lambda, bool torn) const {
  if (lambda >= 1.0) return torn ? 0.0 : std::min(young * (lambda - 1.0), tc);
  const double eps = 1.0 - lambda;
  return -util::onSegment(strain, stress, util::segmentOf(strain, eps), eps);
}

double LowDensityFoam::work(double lambda, bool torn) const {
  if (lambda >= 1.0) {
    if (torn) return 0.0;
    // E e^2 / 2 up to the cutoff strain TC / E, then TC per unit strain.
    const double e = lambda - 1.0, ec = tc / young;
    return e <= ec ? 0.5 * young * e * e : 0.5 * tc * ec + tc * (e - ec);
  }
  const double eps = 1.0 - lambda;
  const std::size_t k = util::segmentOf(strain, eps);
  const double f = util::onSegment(strain, stress, k, eps);
  return energy[k] + 0.5 * (eps - strain[k]) * (stress[k] + f);
}

double LowDensityFoam::unloadingFactor(double w, double w_max) const {
  if (hu >= 1.0 || !(w_max > 0.0) || w >= w_max) return 1.0;
  return 1.0 - (1.0 - hu) * (1.0 - std::pow(std::max(w, 0.0) / w_max, shape));
}

double LowDensityFoam::slopeNear(double lambda) const {
  if (lambda >= 1.0) return young;
  const std::size_t k = util::segmentOf(strain, 1.0 - lambda);
  auto slope = [&](std::size_t j) {
    return (stress[j + 1] - stress[j]) / (strain[j + 1] - strain[j]);
  };
  return k + 2 < strain.size() ? std::max(slope(k), slope(k + 1)) : slope(k);
}

double LowDensityFoam::waveModulus(const std::array<double, 3>& lambda) const {
  // The spatial wave speed along n_i is lambda_i c0, c0^2 = slope / rho0 (the nominal stress of
  // direction i depends on lambda_i alone), and rho = rho0 / J: rho c^2 = slope lambda_i^2 / J.
  double m = 0.0;
  for (int i = 0; i < 3; ++i)
    m = std::max(m, slopeNear(lambda[i]) * lambda[i] / (lambda[(i + 1) % 3] * lambda[(i + 2) % 3]));
  return m;
}

void LowDensityFoam::update(PointBatch& p) const {
  for (int l = 0; l < p.n; ++l) {
    const LeftCauchyGreen k = leftCauchyGreen(p, l);
    const Principal b = principalOf({k.b[0], k.b[1], k.b[2], k.b[3], k.b[4], k.b[5]});
    // Principal stretches of V (the eigenvalues of B are their squares), kept off zero so an
    // element crushed flat gives a large finite stress; the kernel reports the inverted element.
    std::array<double, 3> lambda;
    for (int i = 0; i < 3; ++i) lambda[i] = std::sqrt(std::max(b.value[i], 1e-24));
    bool torn = p.h[1][l] != 0.0;
    if (tear && !torn)
      for (int i = 0; i < 3; ++i) torn = torn || young * (lambda[i] - 1.0) >= tc;
    double w = 0.0;
    for (int i = 0; i < 3; ++i) w += work(lambda[i], torn);
    const double w_max = std::max(p.h[0][l], w);
    const double factor = unloadingFactor(w, w_max);
    // sigma_i = tau_i lambda_i / J = tau_i / (lambda_j lambda_k) (Theory Manual, Material 57).
    std::array<double, 3> sigma;
    for (int i = 0; i < 3; ++i)
      sigma[i] = factor * nominal(lambda[i], torn) / (lambda[(i + 1) % 3] * lambda[(i + 2) % 3]);
    const Voigt s = fromPrincipal(sigma, b.axis);
    for (int c = 0; c < 6; ++c) p.s[c][l] = s[std::size_t(c)];
    p.h[0][l] = w_max;
    p.h[1][l] = torn ? 1.0 : 0.0;
    if (p.modulus) p.modulus[l] = waveModulus(lambda);
  }
}

}  // namespace crumple::materials
