// The rate tables of rate.hpp: a *DEFINE_TABLE's curves on one plastic-strain grid.
#include "materials/rate.hpp"

#include <algorithm>
#include <map>

#include "util/error.hpp"

namespace crumple::materials {

namespace {

// A yield curve of a table, checked as the curve of LCSS is (laws/piecewise_linear.cpp).
CurveData checkedCurve(const CurveAt& curves, int32_t index, const std::string& at) {
  const CurveData c = curves(index);
  const std::string name = "LCSS table curve " + std::to_string(c.id);
  if (c.x.empty() || c.x.size() != c.y.size()) throw util::InputError(at + name + " has no points");
  for (std::size_t k = 1; k < c.x.size(); ++k)
    if (!(c.x[k] >= c.x[k - 1]))
      throw util::InputError(at + name + " must have non-decreasing plastic strains");
  return c;
}

// The merged abscissae: each plastic strain of any curve, repeated as often as the curve that
// repeats it most (a repeated abscissa is a step in that curve, which needs both of its
// values on the grid).
std::vector<double> mergedGrid(const std::vector<CurveData>& cs) {
  std::map<double, std::size_t> copies;
  for (const CurveData& c : cs) {
    for (std::size_t k = 0; k < c.x.size();) {
      const std::size_t run = static_cast<std::size_t>(
          std::upper_bound(c.x.begin() + static_cast<std::ptrdiff_t>(k), c.x.end(), c.x[k]) -
          (c.x.begin() + static_cast<std::ptrdiff_t>(k)));
      std::size_t& n = copies[c.x[k]];
      n = std::max(n, run);
      k += run;
    }
  }
  std::vector<double> grid;
  for (const auto& [x, n] : copies) grid.insert(grid.end(), n, x);
  return grid;
}

// The curve's value at copy `copy` of abscissa v of the grid: its own ordinates where it has
// points at v (the last one for later copies: the upper value of a step), else the value of
// its segment there (continuous, extrapolated past its ends as the single-curve law does).
double valueAt(const CurveData& c, double v, std::size_t copy) {
  const auto [first, last] = std::equal_range(c.x.begin(), c.x.end(), v);
  if (first != last) {
    const auto i = static_cast<std::size_t>(first - c.x.begin()) +
                   std::min(copy, static_cast<std::size_t>(last - first) - 1);
    return c.y[i];
  }
  if (c.x.size() == 1) return c.y[0];
  return util::onSegment(c.x, c.y, util::segmentOf(c.x, v), v);
}

}  // namespace

RateTableData makeRateTable(const CurveAt& curves, int32_t table, const std::string& at) {
  const TableData t = curves.table(table);
  const std::string name = "LCSS table " + std::to_string(t.id);
  if (t.values.empty() || t.values.size() != t.curves.size())
    throw util::InputError(at + name + " has no curves");
  for (std::size_t k = 1; k < t.values.size(); ++k)
    if (!(t.values[k] > t.values[k - 1]))
      throw util::InputError(at + name + " must have strictly increasing strain rates");
  std::vector<CurveData> cs;
  for (const int32_t i : t.curves) cs.push_back(checkedCurve(curves, i, at));
  RateTableData d;
  d.rates.assign(t.values.begin(), t.values.end());
  // Keyword Manual, *MAT_024 LCSS: a table whose first value is negative holds the natural
  // logarithms of the strain rates.
  d.log_rates = d.rates.front() < 0.0;
  d.eps = mergedGrid(cs);
  for (const CurveData& c : cs) {
    for (std::size_t j = 0; j < d.eps.size(); ++j) {
      const auto first = std::lower_bound(d.eps.begin(), d.eps.end(), d.eps[j]) - d.eps.begin();
      const std::size_t copy = j - static_cast<std::size_t>(first);
      d.sig.push_back(valueAt(c, d.eps[j], copy));
    }
  }
  return d;
}

}  // namespace crumple::materials
