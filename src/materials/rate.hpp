// Rate dependence of a yield curve beyond Cowper-Symonds, as *MAT_PIECEWISE_LINEAR_PLASTICITY
// (024) has it (LS-DYNA Keyword Manual vol. II, *MAT_024, fields LCSR and LCSS; docs/theory.md,
// "Strain-rate dependent yield curves"):
//   LCSR   a curve of the effective strain rate that scales the yield stress:
//          sigma_y(eps_p, rate) = factor(rate) h(eps_p);
//   LCSS   naming a *DEFINE_TABLE: one yield curve h_k(eps_p) per strain rate r_k; between two
//          rates the yield stress is interpolated linearly in the rate (in ln(rate) when the
//          table's values are natural logarithms, its first value being negative), and below
//          the first / above the last rate the end curves are used.
// With VP = 0 both are evaluated at the point's effective strain rate of the step, which each
// family measures as its Cowper-Symonds path does (return_mapping.cpp, plane_stress.cpp,
// uniaxial.cpp). At that rate the yield curve is piecewise linear in eps_p, so the returns stay
// exact on it (the curve returns take any indexable sequence of ordinates). With VP = 1
// (viscoplastic) they are evaluated at the effective plastic strain rate of the step, inside
// the consistency condition (return_mapping.hpp, viscoplasticFlow), and so need the slopes in
// the rate as well (valueAndSlope, weightSlope).
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "materials/law.hpp"
#include "util/curve.hpp"

namespace crumple::materials {

// LCSR: the scale factor of the yield stress as a function of the effective strain rate,
// piecewise linear and extrapolated with its end slopes, as every curve of a law
// (util/curve.hpp). Empty: no such curve.
struct RateCurve {
  std::span<const double> rate, factor;
  bool empty() const { return rate.empty(); }
  double operator()(double r) const {
    if (rate.size() == 1) return factor[0];
    return util::onSegment(rate, factor, util::segmentOf(rate, r), r);
  }
  // The factor at r and its slope d factor / d rate (0 on a step and for one point).
  void valueAndSlope(double r, double& f, double& df) const {
    util::valueAndSlope(rate, factor, r, f, df);
  }
};

// The yield curve of a table at one strain rate: lo + w (hi - lo), ordinate by ordinate, on
// the table's common plastic-strain grid (lo == hi and w == 0 at and beyond the end rates, so
// the end curves are reproduced exactly).
struct CurveBlend {
  const double* lo = nullptr;
  const double* hi = nullptr;
  double w = 0.0;
  double operator[](std::size_t j) const { return lo[j] + w * (hi[j] - lo[j]); }
};

// LCSS naming a *DEFINE_TABLE, its curves resampled on one plastic-strain grid (the merged
// abscissae of all curves, so that each curve is reproduced exactly: makeRateTable). Empty:
// no table.
struct RateTable {
  std::span<const double> rates;  // strictly increasing; natural logarithms when log_rates
  bool log_rates = false;
  std::span<const double> eps;  // the common grid
  std::span<const double> sig;  // rates.size() rows of eps.size() yield stresses
  bool empty() const { return rates.empty(); }
  // The yield curve at an effective strain rate (a rate of 0 with log_rates: the first curve).
  CurveBlend at(double rate) const {
    const std::size_t n = eps.size(), m = rates.size();
    const double x =
        log_rates ? (rate > 0.0 ? std::log(rate) : -std::numeric_limits<double>::infinity()) : rate;
    if (m == 1 || !(x > rates[0])) return {sig.data(), sig.data(), 0.0};
    if (x >= rates[m - 1]) {
      const double* last = sig.data() + (m - 1) * n;
      return {last, last, 0.0};
    }
    const std::size_t k = util::segmentOf(rates, x);
    return {sig.data() + k * n, sig.data() + (k + 1) * n,
            (x - rates[k]) / (rates[k + 1] - rates[k])};
  }
  // d w / d rate of the blend at(rate): 0 at and beyond the end rates, where the end curves
  // hold; 1 / (r_k+1 - r_k) between two rates, divided by the rate when the values are ln(rate).
  double weightSlope(double rate) const {
    const std::size_t m = rates.size();
    if (m == 1 || !(rate > 0.0)) return 0.0;
    const double x = log_rates ? std::log(rate) : rate;
    if (!(x > rates[0]) || x >= rates[m - 1]) return 0.0;
    const std::size_t k = util::segmentOf(rates, x);
    const double dw_dx = 1.0 / (rates[k + 1] - rates[k]);
    return log_rates ? dw_dx / rate : dw_dx;
  }
};

// The storage behind a RateTable, owned by the law.
struct RateTableData {
  std::vector<double> rates, eps, sig;
  bool log_rates = false;
  RateTable view() const { return {rates, log_rates, eps, sig}; }
};

// The table with model table index `table`: its values (strictly increasing; natural
// logarithms of the rates when the first is negative) and its curves resampled on their merged
// abscissae. util::InputError prefixed by `at` for a table or curve that cannot be used.
RateTableData makeRateTable(const CurveAt& curves, int32_t table, const std::string& at);

}  // namespace crumple::materials
