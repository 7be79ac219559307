#include "materials/laws/johnson_cook.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "materials/eos_return.hpp"
#include "materials/principal.hpp"
#include "materials/return_mapping.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& JohnsonCook::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("G"), R("E"), R("PR"), R("DTF"), R("VP"), R("RATEOP")}},
       {"card 2", {R("A"), R("B"), R("N"), R("C"), R("M"), R("TM"), R("TR"), R("EPSO")}},
       {"card 3", {R("CP"), R("PC"), R("SPALL"), R("IT"), R("D1"), R("D2"), R("D3"), R("D4")}},
       {"card 4", {R("D5"), R("C2/P"), R("EROD"), R("EFMIN"), R("NUMINT")}}}};
  return spec;
}

namespace {

// Fields of the Keyword Manual that only shells use, or that select formulations Crumple does
// not have: noted when set to no effect, refused when they would change the answer.
void readOptions(LawInput& in, const deck::Card& c1, const deck::Card& c3, const deck::Card& c4) {
  for (const char* f : {"E", "PR", "DTF"})
    if (c1.real(f) != 0.0) in.ignore(c1, f, "used by shells only; solids are supported");
  if (const double vp = c1.real("VP"); vp != 0.0 && vp != 1.0)
    in.reject(c1, "VP", "VP is 0 (rate effects scale the yield stress) or 1 (viscoplastic)");
  if (c1.real("RATEOP") != 0.0)
    in.reject(c1, "RATEOP", "only RATEOP = 0 (the log-linear Johnson-Cook rate term) is supported");
  if (const double sp = c3.real("SPALL"); sp != 0.0 && sp != 1.0 && sp != 2.0 && sp != 3.0)
    in.reject(c3, "SPALL",
              "the spall model is 0 (= 2), 1 (pressure limit p >= PC), 2 (maximum principal "
              "stress) or 3 (hydrostatic tension)");
  if (c3.real("IT") != 0.0) in.ignore(c3, "IT", "the plastic strain iteration of shells");
  if (c4.real("C2/P") != 0.0) in.ignore(c4, "C2/P", "a parameter of RATEOP = 1 or 3");
  if (c4.real("EROD") != 0.0)
    in.reject(c4, "EROD", "only EROD = 0 (the element erodes when D reaches 1) is supported");
  if (c4.real("NUMINT") != 0.0) in.ignore(c4, "NUMINT", "used by shells only");
}

// The checks of the fields the law uses (Card::fail names file, line and field).
void checkFields(const JohnsonCook::Params& p, const deck::Card& c1, const deck::Card& c2,
                 const deck::Card& c3, const deck::Card& c4) {
  if (!(p.G > 0.0)) c1.fail("G", "the shear modulus must be positive");
  if (p.a < 0.0) c2.fail("A", "the yield stress must not be negative");
  if (p.b < 0.0) c2.fail("B", "the hardening modulus must not be negative");
  if (!(p.a > 0.0 || p.b > 0.0)) c2.fail("A", "A or B must be positive");
  if (p.n < 0.0) c2.fail("N", "the hardening exponent must not be negative");
  if (p.c < 0.0) c2.fail("C", "the rate coefficient must not be negative");
  if (p.m < 0.0 || (p.cp > 0.0 && !(p.m > 0.0)))
    c2.fail("M", "the thermal softening exponent must be positive when CP heats the material");
  if (!(p.tm > p.tr)) c2.fail("TM", "the melt temperature must exceed the room temperature TR");
  if (!(p.epso > 0.0) && (p.c != 0.0 || p.d[3] != 0.0))
    c2.fail("EPSO", "the reference strain rate must be positive when C or D4 is used");
  if (p.cp < 0.0) c3.fail("CP", "the specific heat must not be negative (0: no heating)");
  if (p.pc > 0.0) c3.fail("PC", "the pressure cutoff is a tension limit: zero or negative");
  if (p.efmin < 0.0)
    c4.fail("EFMIN", "the lower bound of the fracture strain must not be negative");
}

}  // namespace

JohnsonCook::Params JohnsonCook::read(LawInput& in) {
  const deck::Card& c1 = in.card("card 1");
  const deck::Card& c2 = in.card("card 2");
  const deck::Card& c3 = in.card("card 3");
  const deck::Card& c4 = in.optionalCard("card 4");
  Params p;
  p.rho = c1.real("RO");
  p.G = c1.real("G");
  p.a = c2.real("A");
  p.b = c2.real("B");
  p.n = c2.real("N");
  p.c = c2.real("C");
  p.m = c2.real("M");
  p.tm = c2.real("TM");
  p.tr = c2.real("TR");
  p.epso = c2.real("EPSO");
  p.cp = c3.real("CP");
  p.pc = c3.real("PC");
  static constexpr const char* kD[4] = {"D1", "D2", "D3", "D4"};
  for (int i = 0; i < 4; ++i) p.d[static_cast<std::size_t>(i)] = c3.real(kD[i]);
  p.d[4] = c4.real("D5");
  p.efmin = c4.real("EFMIN");
  p.viscoplastic = c1.real("VP") == 1.0;
  // SPALL = 0 is the Keyword Manual's default, "set to 2.0".
  const double spall = c3.real("SPALL");
  p.spall = spall == 1.0   ? Spall::PressureLimit
            : spall == 3.0 ? Spall::HydrostaticTension
                           : Spall::MaxPrincipalStress;
  checkFields(p, c1, c2, c3, c4);
  readOptions(in, c1, c3, c4);
  if (!(p.epso > 0.0)) p.epso = 1.0;  // unused (C = D4 = 0): any positive rate
  return p;
}

JohnsonCook JohnsonCook::make(const Params& p, const CurveAt&, const std::string& at,
                              const Eos* eos) {
  if (!(p.rho > 0.0)) throw util::InputError(at + "RO must be positive");
  if (!(p.G > 0.0)) throw util::InputError(at + "G must be positive");
  if (!(p.tm > p.tr)) throw util::InputError(at + "TM must exceed TR");
  if (p.cp < 0.0 || !(p.epso > 0.0) || p.m < 0.0 || (p.cp > 0.0 && !(p.m > 0.0)))
    throw util::InputError(at + "EPSO must be positive, CP >= 0 and M > 0 when CP > 0");
  if (p.pc > 0.0) throw util::InputError(at + "PC must be zero or negative");
  if (!eos) throw util::InputError(at + "needs an equation of state (*PART EOSID) on its solids");
  checkEos(at, *eos, p.rho);
  JohnsonCook law;
  law.par = p;
  law.eos = *eos;
  law.moduli = Moduli{eosBulkModulus(*eos, p.rho), p.G};
  return law;
}

double JohnsonCook::hardening(double eps_p) const {
  return par.a + par.b * std::pow(eps_p, par.n);
}

double JohnsonCook::hardeningSlope(double eps_p) const {
  // d/deps (B eps^N) = B N eps^(N-1); infinite at 0 for N < 1, where Newton is not evaluated.
  return eps_p > 0.0 && par.b > 0.0 && par.n > 0.0 ? par.b * par.n * std::pow(eps_p, par.n - 1.0)
                                                   : 0.0;
}

double JohnsonCook::rateFactor(double rate) const {
  return 1.0 + par.c * std::log(std::max(rate / par.epso, 1.0));
}

double JohnsonCook::thermalFactor(double dT) const {
  // At room temperature (always so with CP = 0) no softening, whatever M (0^0 would be 1).
  const double t = dT / (par.tm - par.tr);
  if (!(t > 0.0)) return 1.0;
  return t >= 1.0 ? 0.0 : 1.0 - std::pow(t, par.m);
}

double JohnsonCook::returnIncrement(double q, double eps_p, double scale) const {
  // The hardening does not decrease, so the safeguarded Newton return of return_mapping.hpp
  // converges to round-off whatever the sign of k'' (N < 1 or > 1).
  return radialReturnIncrement(q, eps_p, 3.0 * par.G, [&](double e, double& y, double& h) {
    y = scale * hardening(e);
    h = scale * hardeningSlope(e);
  });
}

double JohnsonCook::fractureStrain(double triax, double rate, double dT) const {
  if (!hasDamage()) return 0.0;
  const double t = dT / (par.tm - par.tr);
  const double f = (par.d[0] + par.d[1] * std::exp(par.d[2] * triax)) *
                   (1.0 + par.d[3] * std::log(std::max(rate / par.epso, 1.0))) *
                   (1.0 + par.d[4] * t);
  return std::max(par.efmin, f);
}

double JohnsonCook::viscoplasticIncrement(double q, double eps_p, double scale, double dt) const {
  // The flow stress rises with x both through the hardening and through the rate factor at
  // x / dt (d/dx C ln(x / (dt EPSO)) = C / x above the threshold), so the residual still falls
  // monotonically from x = 0 and the safeguarded Newton return of return_mapping.hpp applies.
  return radialReturnIncrement(q, eps_p, 3.0 * par.G, [&](double e, double& y, double& h) {
    const double x = e - eps_p, rate = plasticRate(x, dt), rf = rateFactor(rate);
    y = scale * hardening(e) * rf;
    h = scale * (hardeningSlope(e) * rf + (rate > par.epso ? hardening(e) * par.c / x : 0.0));
  });
}

void JohnsonCook::update(PointBatch& b) const {
  for (int i = 0; i < b.n; ++i) {
    if (par.spall == Spall::PressureLimit) {
      plasticStep(b, i);
    } else if (b.h[kSpall][i] != 0.0) {
      rubbleStep(b, i);
    } else if (const double p = plasticStep(b, i); spalls(b, i, p)) {
      // Spalled for good (the flag goes through restart dumps with the other history).
      b.h[kSpall][i] = 1.0;
      setRubbleStress(b, i, p);
    }
  }
}

double JohnsonCook::plasticStep(PointBatch& b, int i) const {
  const double dT = b.h[kHeat][i], e = b.eps_p[i];
  double rate = 0.0, scale = 1.0;
  // The radial return to the Johnson-Cook surface at the step's rate and starting temperature;
  // the pressure cut off at PC with SPALL = 1 only (SPALL 2 and 3 spall the point instead).
  const double pc =
      par.spall == Spall::PressureLimit ? par.pc : -std::numeric_limits<double>::infinity();
  const EosReturn r =
      eosRadialReturn(b, i, par.G, eos, par.rho, pc, [&](double q, const double* d) {
        if (par.viscoplastic) {
          // VP = 1: yield at the static surface; the rate factor at the plastic rate x / dt.
          const double thermal = thermalFactor(dT);
          const double x =
              q > thermal * hardening(e) ? viscoplasticIncrement(q, e, thermal, b.dt) : 0.0;
          rate = plasticRate(x, b.dt);
          scale = rateFactor(rate) * thermal;
          return x;
        }
        rate = effectiveStrainRate(d, b.dt);
        scale = rateFactor(rate) * thermalFactor(dT);
        return q > scale * hardening(e) ? returnIncrement(q, e, scale) : 0.0;
      });
  b.eps_p[i] = e + r.x;
  if (r.x > 0.0) heatAndDamage(b, i, Increment{e, r.x, scale, rate, dT, r.p});
  return r.p;
}

bool JohnsonCook::spalls(const PointBatch& b, int i, double p) const {
  // The Keyword Manual's tests: sigma_max >= -PC (SPALL 2), p < PC (SPALL 3); strict for
  // SPALL 2 as well, so that with PC = 0 a stress-free point does not spall.
  if (par.spall == Spall::HydrostaticTension) return p < par.pc;
  const Voigt s{b.s[0][i], b.s[1][i], b.s[2][i], b.s[3][i], b.s[4][i], b.s[5][i]};
  return principalOf(s).value[2] > -par.pc;
}

void JohnsonCook::setRubbleStress(PointBatch& b, int i, double p) {
  const double held = std::max(p, 0.0);
  for (int k = 0; k < 6; ++k) b.s[k][i] = k < 3 ? -held : 0.0;
}

void JohnsonCook::rubbleStep(PointBatch& b, int i) const {
  // No deviator, hence no deviatoric work; the EOS's pressure cut off at 0 (its energy update
  // does the step's work at the cutoff when it holds).
  const double tr = b.de[0][i] + b.de[1][i] + b.de[2][i];
  const double p_old = -(b.s[0][i] + b.s[1][i] + b.s[2][i]) / 3.0;
  setRubbleStress(b, i,
                  eosPointStep(eos, par.rho, 0.0, b.h[0][i], b.h[1][i], b.h[2][i], 0.0, p_old, tr));
}

void JohnsonCook::heatAndDamage(PointBatch& b, int i, const Increment& in) const {
  // Adiabatic heating by the plastic work of the step at the new flow stress (CP = 0: none).
  const double sigma_y = in.scale * hardening(in.eps_p + in.x);
  if (par.cp > 0.0) b.h[kHeat][i] = in.dT + sigma_y * in.x / (par.rho * par.cp);
  // Damage at the new state's triaxiality sigma_m / sigma_eff = -p / sigma_y.
  if (!hasDamage()) return;
  const double ef = fractureStrain(sigma_y > 0.0 ? -in.p / sigma_y : 0.0, in.rate, in.dT);
  b.h[kDamage][i] += ef > 0.0 ? in.x / ef : std::numeric_limits<double>::infinity();
  if (b.failed && b.h[kDamage][i] >= 1.0) b.failed[i] = 1;
}

}  // namespace crumple::materials
