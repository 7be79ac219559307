// *MAT_JOHNSON_COOK (015): strain-, rate- and temperature-sensitive von Mises plasticity with
// the Johnson-Cook cumulative damage model (LS-DYNA Keyword Manual vol. II, *MAT_JOHNSON_COOK;
// Theory Manual, "Material Model 15: Johnson and Cook Plasticity Model"; G. R. Johnson and W. H.
// Cook, "A constitutive model and data for metals subjected to large strains, high strain
// rates and high temperatures", Proc. 7th Int. Symp. on Ballistics, The Hague, 1983, 541-547;
// and "Fracture characteristics of three metals subjected to various strains, strain rates,
// temperatures and pressures", Eng. Fract. Mech. 21(1), 1985, 31-48). Solids only.
//
// Flow stress (Johnson & Cook 1983, eq. 1):
//   sigma_y = (A + B eps_p^N) (1 + C ln eps_dot*) (1 - T*^M),
//   eps_dot* = max(eps_dot / EPSO, 1)   (EPSO: the quasi-static threshold rate of the manual),
//   T* = (T - TR) / (TM - TR)           (T* >= 1: melted, no deviatoric strength).
// VP (Keyword Manual, "formulation for rate effects") picks eps_dot:
//   VP = 0: the total effective strain rate of the step, which scales the yield stress;
//   VP = 1: viscoplastic, the effective plastic strain rate x / dt of the step's own plastic
//           increment x, so the consistency condition q - 3 G x = sigma_y(eps_p + x, x / dt) is
//           solved for x with the rate inside (an elastic step yields at the static surface).
// The temperature rises adiabatically with the plastic work, dT = sigma_y deps_p / (RO CP)
// (CP = 0, as real decks without thermal data give it with M = 0: no heating, T = TR);
// the flow stress of a step uses the temperature of its start (the heat of the step softens
// the next one). The deviator is returned radially with the hardening solved by safeguarded
// Newton iteration to round-off (the Theory Manual's one-step linearisation is not used), so
// the stress lands on the surface. The pressure comes from the part's equation of state
// (*PART EOSID, required on solids as the Keyword Manual says) with the energy update of
// *MAT_NULL (eos.hpp, eosEnergyStep).
//
// Spall (Keyword Manual, SPALL and PC; Theory Manual, the spall models of material 15):
//   SPALL = 1: pressure limit, p >= PC; the deviator is unaffected and nothing is remembered;
//   SPALL = 2 (and 0, its default): the point spalls when its largest principal stress
//              exceeds -PC;
//   SPALL = 3: the point spalls when its pressure falls below PC (hydrostatic tension).
// A spalled point is rubble for the rest of the run (history flag): its deviator is zero and
// its pressure, still from the EOS, is held at p >= 0 (no tension). Before the spall, SPALL 2
// and 3 need no cutoff of their own: a point that has not spalled has p >= PC.
//
// Damage (Johnson & Cook 1985, eqs. 2-3): D = sum deps_p / eps_f with
//   eps_f = max(EFMIN, [D1 + D2 exp(D3 sigma*)] [1 + D4 ln eps_dot*] [1 + D5 T*]),
//   sigma* = sigma_m / sigma_eff   (mean stress over von Mises stress, positive in tension:
//                                   the convention of the published, negative, D3 values);
// the point fails (the element erodes) when D >= 1. D1 = D2 = 0 and EFMIN = 0: no damage.
// History (kHistory = 6): h[0..2] the EOS's state (ln(V / V0), E - E0, the least ln(V / V0);
// eos.hpp, kEosHistory, as *MAT_NULL), h[3] = D, h[4] = T - TR, h[5] = 1 once spalled; all
// start at zero.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "materials/eos.hpp"
#include "materials/law.hpp"

namespace crumple::materials {

struct JohnsonCook {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_JOHNSON_COOK", "*MAT_015"};
  static constexpr Cost kCost = Cost::Plastic;
  static constexpr bool kPlastic = true;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  // The history after the EOS's state (kEosHistory): damage D, temperature rise T - TR and
  // the spall flag (1 once spalled).
  static constexpr int kDamage = kEosHistory, kHeat = kEosHistory + 1, kSpall = kEosHistory + 2;
  static constexpr int kHistory = kEosHistory + 3;
  // Its solids take the part's equation of state (required); law.hpp.
  static constexpr bool kEos = true;

  // The spall models of the SPALL field (0 reads as 2, its default).
  enum class Spall : int32_t { PressureLimit = 1, MaxPrincipalStress = 2, HydrostaticTension = 3 };

  struct Params {
    using Law = JohnsonCook;
    double rho = 0, G = 0;
    double a = 0, b = 0, n = 0, c = 0, m = 0, tm = 0, tr = 0, epso = 0;
    double cp = 0, pc = 0;
    std::array<double, 5> d{};  // D1..D5
    double efmin = 0;
    bool viscoplastic = false;  // VP = 1
    Spall spall = Spall::PressureLimit;
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  // `eos`: the part's equation of state (required).
  static JohnsonCook make(const Params& p, const CurveAt& curves, const std::string& at,
                          const Eos* eos = nullptr);

  Moduli moduli;  // K: the EOS's bulk modulus at the initial state; G
  Params par;
  Eos eos;
  void update(PointBatch& b) const;
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return 0.0; }

  // The strain-hardening term A + B eps_p^N and its slope.
  double hardening(double eps_p) const;
  double hardeningSlope(double eps_p) const;
  // The rate factor 1 + C ln eps_dot* and the thermal factor 1 - T*^M at an effective strain
  // rate and a temperature rise T - TR.
  double rateFactor(double rate) const;
  double thermalFactor(double dT) const;
  // The effective plastic strain increment that returns a trial von Mises stress q above the
  // flow stress scale * hardening(eps_p) to the surface: q - 3 G x = scale hardening(eps_p + x).
  double returnIncrement(double q, double eps_p, double scale) const;
  // VP = 1: the increment x with the rate factor at the plastic rate x / dt inside the flow
  // stress, q - 3 G x = scale hardening(eps_p + x) rateFactor(x / dt).
  double viscoplasticIncrement(double q, double eps_p, double scale, double dt) const;
  // The effective plastic strain rate of an increment x over dt (0 when dt is 0).
  static double plasticRate(double x, double dt) { return dt > 0.0 ? x / dt : 0.0; }
  // The fracture strain eps_f at triaxiality sigma* = sigma_m / sigma_eff, rate and T - TR;
  // 0 when the law has no damage (D1 = D2 = 0, EFMIN = 0).
  double fractureStrain(double triax, double rate, double dT) const;
  bool hasDamage() const { return par.d[0] != 0.0 || par.d[1] != 0.0 || par.efmin > 0.0; }

 private:
  // A point's plastic step: plastic strain at its start, increment x, the flow stress's rate
  // and thermal scale, the strain rate, T - TR at its start and the new pressure.
  struct Increment {
    double eps_p, x, scale, rate, dT, p;
  };
  // The heating and damage of point i's plastic increment.
  void heatAndDamage(PointBatch& b, int i, const Increment& in) const;
  // Point i's step before any spall: the return, heating and damage; returns the new pressure.
  double plasticStep(PointBatch& b, int i) const;
  // SPALL 2 and 3: whether point i's new stress (pressure p) spalls it.
  bool spalls(const PointBatch& b, int i, double p) const;
  // A spalled point (or the one spalling now, pressure p): no deviator, no tension.
  static void setRubbleStress(PointBatch& b, int i, double p);
  // The step of a point spalled before: the EOS's pressure held at p >= 0, no deviator.
  void rubbleStep(PointBatch& b, int i) const;
};

}  // namespace crumple::materials
