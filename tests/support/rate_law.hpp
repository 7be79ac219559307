// *MAT_024 laws with rate dependence for the unit tests of the three families (solids,
// shells, beam fibres): a rate table of three yield curves (1, 10, 100 /s, linear or in
// ln(rate)) and an LCSR curve, with the yield stress they must give written out by hand,
// independently of materials/rate.hpp (Keyword Manual vol. II, *MAT_024 LCSS and LCSR).
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "materials/materials.hpp"

namespace crumple::testing {

namespace rate_law {

namespace m = crumple::materials;

// The curves of the rates 1, 10 and 100 /s, with different plastic strains (so that the
// merged grid of the table matters), the LCSR curve (factor 1 at rest, 1.5 at 100 /s).
inline const std::vector<double> kEpsA{0.0, 0.05, 0.2}, kSigA{200.0, 300.0, 360.0};
inline const std::vector<double> kEpsB{0.0, 0.1}, kSigB{230.0, 330.0};
inline const std::vector<double> kEpsC{0.0, 0.02, 0.3}, kSigC{260.0, 300.0, 420.0};
inline const std::vector<double> kLcsrRate{0.0, 100.0}, kLcsrFactor{1.0, 1.5};
inline const std::vector<double> kRates{1.0, 10.0, 100.0};
// The same table in ln(rate): 1e-3, 1 and 1e3 /s (the first value negative).
inline const std::vector<double> kLogRates{std::log(1e-3), 0.0, std::log(1e3)};
inline const std::vector<int32_t> kTableCurves{0, 1, 2};

// The curves written out (each extrapolated with its last slope).
inline double hA(double e) {
  return e < 0.05 ? 200.0 + 2000.0 * e : 300.0 + 400.0 * (e - 0.05);
}
inline double hB(double e) {
  return 230.0 + 1000.0 * e;
}
inline double hC(double e) {
  return e < 0.02 ? 260.0 + 2000.0 * e : 300.0 + 120.0 / 0.28 * (e - 0.02);
}

// The yield stress of the linear table at a strain rate: the end curves outside [1, 100],
// linear in the rate between neighbouring rates.
inline double tableYield(double e, double rate) {
  if (rate <= 1.0) return hA(e);
  if (rate >= 100.0) return hC(e);
  if (rate < 10.0) return hA(e) + (rate - 1.0) / 9.0 * (hB(e) - hA(e));
  return hB(e) + (rate - 10.0) / 90.0 * (hC(e) - hB(e));
}

// The yield stress of the logarithmic table: linear in ln(rate) between 1e-3, 1 and 1e3 /s.
inline double logTableYield(double e, double rate) {
  const double x = std::log(rate) / std::log(1e3);  // -1, 0, 1 at the table's rates
  if (x <= -1.0) return hA(e);
  if (x >= 1.0) return hC(e);
  if (x < 0.0) return hA(e) + (x + 1.0) * (hB(e) - hA(e));
  return hB(e) + x * (hC(e) - hB(e));
}

inline double lcsrFactor(double rate) {
  return 1.0 + 0.005 * rate;
}

// The model's curves 0-3 and tables 0 (rates) and 1 (ln rates), as make() sees them.
inline m::CurveAt rateCurves() {
  return m::CurveAt(
      [](int32_t i) -> m::CurveData {
        switch (i) {
          case 0:
            return {101, kEpsA, kSigA};
          case 1:
            return {102, kEpsB, kSigB};
          case 2:
            return {103, kEpsC, kSigC};
          case 3:
            return {104, kLcsrRate, kLcsrFactor};
          default:
            throw std::out_of_range("no curve " + std::to_string(i));
        }
      },
      [](int32_t t) -> m::TableData {
        if (t == 0) return {5, kRates, kTableCurves};
        if (t == 1) return {6, kLogRates, kTableCurves};
        throw std::out_of_range("no table " + std::to_string(t));
      });
}

// Aluminium-like elasticity (MPa).
constexpr double kE = 70000.0, kNu = 0.33;

// MAT_024 with LCSS naming table 0 (rates) or 1 (ln rates); vp: VP = 1.
inline m::PiecewiseLinear tableLaw(int32_t table = 0, bool vp = false) {
  m::PiecewiseLinear::Params p;
  p.E = kE;
  p.nu = kNu;
  p.table = table;
  p.viscoplastic = vp;
  return m::PiecewiseLinear::make(p, rateCurves(), "");
}

// MAT_024 with LCSR: on the curve hA (LCSS) or bilinear from SIGY 250, ETAN 2100.
inline m::PiecewiseLinear lcsrLaw(bool curve, bool vp = false) {
  m::PiecewiseLinear::Params p;
  p.E = kE;
  p.nu = kNu;
  p.sigy = 250.0;
  p.etan = 2100.0;
  p.lcss = curve ? 0 : -1;
  p.lcsr = 3;
  p.viscoplastic = vp;
  return m::PiecewiseLinear::make(p, rateCurves(), "");
}

// MAT_024 with the Cowper-Symonds factor C, P on SIGY 250 and ETAN (bilinear), VP = 1.
constexpr double kCsC = 40.0, kCsP = 5.0;
inline m::PiecewiseLinear cowperSymondsLaw(double etan = 2100.0, double C = kCsC, double P = kCsP) {
  m::PiecewiseLinear::Params p;
  p.E = kE;
  p.nu = kNu;
  p.sigy = 250.0;
  p.etan = etan;
  p.c = C;
  p.p = P;
  p.viscoplastic = true;
  return m::PiecewiseLinear::make(p, rateCurves(), "");
}

// The static yield stress of lcsrLaw(curve) at a plastic strain.
inline double lcsrStatic(bool curve, double e) {
  return curve ? hA(e) : 250.0 + kE * 2100.0 / (kE - 2100.0) * e;
}

// Every rate-dependent law above with the yield stress (plastic strain, strain rate) it must
// give: the table in rates and in ln(rate), LCSR on the curve and on SIGY/ETAN.
// vp: the same laws with VP = 1 (their yield stress then at the plastic strain rate), and
// the Cowper-Symonds law.
using Yield = double (*)(double, double);
inline std::vector<std::pair<m::Law, Yield>> allLaws(bool vp = false) {
  const Yield lcsr_curve = [](double e, double r) { return lcsrFactor(r) * lcsrStatic(true, e); };
  const Yield lcsr_bilinear = [](double e, double r) {
    return lcsrFactor(r) * lcsrStatic(false, e);
  };
  std::vector<std::pair<m::Law, Yield>> laws{{tableLaw(0, vp), tableYield},
                                             {tableLaw(1, vp), logTableYield},
                                             {lcsrLaw(true, vp), lcsr_curve},
                                             {lcsrLaw(false, vp), lcsr_bilinear}};
  if (vp) {
    const Yield cs = [](double e, double r) {
      return (1.0 + std::pow(r / kCsC, 1.0 / kCsP)) * lcsrStatic(false, e);
    };
    laws.emplace_back(cowperSymondsLaw(), cs);
  }
  return laws;
}

// VP = 1 with the Cowper-Symonds factor of P = 1 on a flat yield curve (SIGY, ETAN 0) is the
// overstress law of Perzyna (1966): eps_p' = C (q / SIGY - 1). Driven from the yield surface at
// a constant effective strain rate `rate` in a state whose von Mises stress grows elastically
// with modulus M (3 G in shear, E in a truss), q' = M (rate - eps_p'), so
//   q(t) = q_inf + (SIGY - q_inf) exp(-k t),  q_inf = SIGY (1 + rate / C),  k = M C / SIGY.
struct Overstress {
  double sigy = 250.0, C = 100.0, M = 0.0, rate = 200.0;
  double steady() const { return sigy * (1.0 + rate / C); }
  double rateConstant() const { return M * C / sigy; }
  double exact(double t) const {
    return steady() + (sigy - steady()) * std::exp(-rateConstant() * t);
  }
  // The backward-Euler step of the law, which the return is: from q, a step dt of effective
  // strain rate dt, q + M (rate dt - x) = SIGY (1 + x / (C dt)).
  double backwardEuler(double q, double dt) const {
    const double x = (q + M * rate * dt - sigy) / (M + sigy / (C * dt));
    return sigy * (1.0 + x / (C * dt));
  }
};

}  // namespace rate_law

}  // namespace crumple::testing
