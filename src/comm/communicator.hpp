// The only place that calls MPI. Physics code talks to this interface; a serial run is one
// rank, and every call below is then a local identity. MPI is initialised only when the
// process was started by mpirun (or when forced), so plain runs never touch it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <string>
#include <type_traits>
#include <vector>

namespace crumple::comm {

class Communicator {
 public:
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool isRoot() const { return rank_ == 0; }
  bool distributed() const { return size_ > 1; }

  // Exact global minimum (min is order-independent, so this is deterministic).
  double minAll(double local) const;
  int64_t minAll(int64_t local) const;
  int64_t maxAll(int64_t local) const;
  long long sumAll(long long local) const;
  // Element-wise sums of per-rank partial diagnostics, added in rank order on every rank so
  // the result does not depend on message arrival order.
  std::vector<double> sumOrdered(const std::vector<double>& local) const;
  // True on every rank if any rank passes true (used to end all ranks on one rank's error).
  bool anyAll(bool local) const;
  // Bitwise OR over all ranks: several yes/no requests (signals, sense switches, a dump due by
  // the root's wall clock) agreed in one collective, so every rank acts at the same cycle.
  uint64_t orAll(uint64_t local) const;
  // Every rank's vector, concatenated in rank order, on every rank. Items travel as their
  // bytes (every rank runs this binary on the same kind of machine), so a struct of ids and
  // values keeps its ids integers instead of sending them as doubles.
  template <class T>
  std::vector<T> allGather(const std::vector<T>& local) const {
    static_assert(std::is_trivially_copyable_v<T>, "items travel as their bytes");
    if (!mpi_) return local;
    const std::vector<int> counts = itemCounts(local.size());
    std::vector<T> out(std::accumulate(counts.begin(), counts.end(), std::size_t(0)));
    gatherItems(local.data(), sizeof(T), counts, out.data());
    return out;
  }
  // Every rank's bytes, concatenated in rank order, on the root only (empty elsewhere).
  std::vector<char> gatherToRoot(const std::vector<char>& local) const;
  // The root's bytes on every rank.
  void broadcast(std::vector<char>& bytes) const;
  void barrier() const;
  // Ends every rank at once after an error only this rank saw (no collective possible).
  [[noreturn]] void abort(int code) const;

  // Seconds spent inside communication calls (waiting included), for the timing table.
  double seconds() const { return seconds_; }

 private:
  friend void initialize(int* argc, char*** argv);
  friend void finalize();
  friend class Exchange;  // point-to-point messages (exchange.hpp) count in seconds()
  // allGather's two steps: every rank's item count, then every rank's items of `size` bytes.
  std::vector<int> itemCounts(std::size_t local) const;
  void gatherItems(const void* local, std::size_t size, const std::vector<int>& counts,
                   void* out) const;
  int rank_ = 0;
  int size_ = 1;
  bool mpi_ = false;
  mutable double seconds_ = 0.0;
};

// The communicator of this process.
Communicator& world();

// Message latency and bandwidth between ranks 0 and 1, from a ping-pong (the cost model of
// `crumple partition --advise`, docs/parallel.md). Collective: every rank calls it; ranks
// above 1 only wait. `measured` is false on one rank (nothing to measure).
struct LinkSpeed {
  double latency_s = 0;              // half the round trip of an 8-byte message
  double bandwidth_bytes_per_s = 0;  // a 1 MiB message, latency taken off
  bool measured = false;
};
LinkSpeed pingPong(const Communicator& c, int repetitions = 200);

// Starts MPI when the process was launched by mpirun (OMPI_COMM_WORLD_SIZE, PMI_SIZE or
// CRUMPLE_FORCE_MPI in the environment); otherwise world() stays serial.
void initialize(int* argc, char*** argv);
void finalize();

}  // namespace crumple::comm
