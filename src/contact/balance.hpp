// The contact partition (docs/parallel.md, "Contact"): which checks each rank computes,
// separate from the element partition. Recursive coordinate bisection of the checks' node
// positions, cut again, with the measured cost of every check as its weight, when the busiest
// rank does more than ContactControls::rebalance_threshold times the mean.
#pragma once

#include <cstdint>
#include <vector>

#include "comm/communicator.hpp"

namespace crumple::contact {

class CheckPartition {
 public:
  explicit CheckPartition(comm::Communicator& comm) : comm_(comm) {}

  // Cuts the checks among the ranks by their node positions (check_node: the contact node of
  // every check; x: 3 per contact node), check c weighing weight[c]. Every rank computes the
  // same cut.
  void cut(const std::vector<int32_t>& check_node, const std::vector<double>& x,
           const std::vector<double>& weight);
  // The same with every check weighing one.
  void cutEvenly(const std::vector<int32_t>& check_node, const std::vector<double>& x);
  // Node-segment tests a check of this rank did (its measured cost).
  void addCost(int32_t check, int64_t tests) {
    check_cost_[std::size_t(check)] += double(tests);
    tests_since_balance_ += tests;
  }
  // Re-cuts with the measured costs when the busiest rank is over the threshold (collective);
  // true if it did.
  bool maybeRebalance(const std::vector<int32_t>& check_node, const std::vector<double>& x,
                      double threshold);

  // The checks this rank computes, ascending.
  const std::vector<int32_t>& mine() const { return mine_; }

 private:
  comm::Communicator& comm_;
  std::vector<int32_t> mine_;
  std::vector<double> check_cost_;  // tests per check since the last balance (this rank's)
  int64_t tests_since_balance_ = 0;
};

}  // namespace crumple::contact
