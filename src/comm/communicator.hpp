// The only place that will call MPI. Physics code talks to this interface; a serial run is
// one rank and every call below is then a local no-op or identity.
#pragma once

#include <vector>

namespace crumple::comm {

class Communicator {
 public:
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool isRoot() const { return rank_ == 0; }

  // Exact global minimum (min is order-independent, so this is deterministic).
  double minAll(double local) const;
  // Global sum of integers.
  long long sumAll(long long local) const;
  // Element-wise sums of per-rank partial diagnostics, added in rank order on every rank so
  // the result does not depend on message arrival order.
  std::vector<double> sumOrdered(const std::vector<double>& local) const;
  // True on every rank if any rank passes true (used to end all ranks on one rank's error).
  bool anyAll(bool local) const;

 private:
  int rank_ = 0;
  int size_ = 1;
};

// The communicator of this process (serial: a single rank).
Communicator& world();

}  // namespace crumple::comm
