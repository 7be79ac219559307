#include "contact/balance.hpp"

#include <algorithm>
#include <array>
#include <numeric>

#include "contact/geometry.hpp"

namespace crumple::contact {

void CheckPartition::cut(const std::vector<int32_t>& check_node, const std::vector<double>& x,
                         const std::vector<double>& weight) {
  // Recursive coordinate bisection (Berger & Bokhari 1987), cutting the longest extent at the
  // weighted median.
  const int P = comm_.size();
  const auto num_checks = int32_t(check_node.size());
  check_cost_.resize(check_node.size(), 0.0);
  std::vector<int32_t> ids(check_node.size());
  std::iota(ids.begin(), ids.end(), 0);
  std::vector<int32_t> owner(check_node.size(), 0);
  auto nodeOf = [&](int32_t c) { return std::size_t(check_node[std::size_t(c)]); };
  struct Range {
    std::size_t begin, end;
    int first, parts;
  };
  std::vector<Range> stack{{0, ids.size(), 0, P}};
  while (!stack.empty()) {
    const Range r = stack.back();
    stack.pop_back();
    if (r.parts == 1 || r.end - r.begin <= 1) {
      for (std::size_t i = r.begin; i < r.end; ++i) owner[std::size_t(ids[i])] = r.first;
      continue;
    }
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (std::size_t i = r.begin; i < r.end; ++i) {
      const Vec3 xi = at(x, nodeOf(ids[i]));
      for (std::size_t d = 0; d < 3; ++d) {
        lo[d] = std::min(lo[d], xi[d]);
        hi[d] = std::max(hi[d], xi[d]);
      }
    }
    std::size_t axis = 0;
    for (std::size_t d = 1; d < 3; ++d)
      if (hi[d] - lo[d] > hi[axis] - lo[axis]) axis = d;
    std::sort(ids.begin() + std::ptrdiff_t(r.begin), ids.begin() + std::ptrdiff_t(r.end),
              [&](int32_t a, int32_t b) {
                const double xa = x[3 * nodeOf(a) + axis];
                const double xb = x[3 * nodeOf(b) + axis];
                return xa < xb || (xa == xb && a < b);
              });
    const int left = r.parts / 2;
    double total = 0.0;
    for (std::size_t i = r.begin; i < r.end; ++i) total += weight[std::size_t(ids[i])];
    const double target = total * double(left) / double(r.parts);
    std::size_t cut = r.begin;
    double acc = 0.0;
    while (cut < r.end && acc + 0.5 * weight[std::size_t(ids[cut])] < target)
      acc += weight[std::size_t(ids[cut++])];
    stack.push_back({r.begin, cut, r.first, left});
    stack.push_back({cut, r.end, r.first + left, r.parts - left});
  }
  mine_.clear();
  for (int32_t c = 0; c < num_checks; ++c)
    if (owner[std::size_t(c)] == comm_.rank()) mine_.push_back(c);
}

void CheckPartition::cutEvenly(const std::vector<int32_t>& check_node,
                               const std::vector<double>& x) {
  cut(check_node, x, std::vector<double>(check_node.size(), 1.0));
}

bool CheckPartition::maybeRebalance(const std::vector<int32_t>& check_node,
                                    const std::vector<double>& x, double threshold) {
  if (!comm_.distributed()) return false;
  // The tests each rank did since the last look.
  const auto loads = comm_.allGather(std::vector<int64_t>{tests_since_balance_});
  tests_since_balance_ = 0;
  double mx = 0.0, sum = 0.0;
  for (const int64_t l : loads) {
    mx = std::max(mx, double(l));
    sum += double(l);
  }
  const double mean = sum / double(loads.size());
  const bool unbalanced = mean > 0.0 && !(mx <= threshold * mean);
  if (unbalanced) {
    // Every rank's measured costs, one weight per check on top of one.
    struct Cost {
      int64_t check = 0;  // 64 bits: no padding travels
      double tests = 0.0;
    };
    std::vector<Cost> costs;
    for (int32_t c : mine_) costs.push_back({c, check_cost_[std::size_t(c)]});
    std::vector<double> weight(check_node.size(), 1.0);
    for (const Cost& c : comm_.allGather(costs)) weight[std::size_t(c.check)] += c.tests;
    cut(check_node, x, weight);
  }
  std::fill(check_cost_.begin(), check_cost_.end(), 0.0);
  return unbalanced;
}

}  // namespace crumple::contact
