#include "comm/communicator.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <numeric>

#include "comm/mpi_check.hpp"
#include "util/timer.hpp"

namespace crumple::comm {

std::vector<int> Communicator::itemCounts(std::size_t local) const {
  util::ScopedTimer timer(seconds_);
  const int n = static_cast<int>(local);
  std::vector<int> counts(static_cast<std::size_t>(size_));
  check(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "Allgather");
  return counts;
}

void Communicator::gatherItems(const void* local, std::size_t size, const std::vector<int>& counts,
                               void* out) const {
  util::ScopedTimer timer(seconds_);
  std::vector<int> displs(counts.size(), 0);
  std::partial_sum(counts.begin(), counts.end() - 1, displs.begin() + 1);
  // One datatype of `size` bytes: counts stay in items, so an int reaches 2^31 items, not
  // 2^31 bytes.
  MPI_Datatype item;
  check(MPI_Type_contiguous(static_cast<int>(size), MPI_BYTE, &item), "Type_contiguous");
  check(MPI_Type_commit(&item), "Type_commit");
  check(MPI_Allgatherv(local, counts[static_cast<std::size_t>(rank_)], item, out, counts.data(),
                       displs.data(), item, MPI_COMM_WORLD),
        "Allgatherv");
  MPI_Type_free(&item);
}

namespace {
// One value reduced over all ranks (min, max and sum of one value are exact and
// order-independent for these types, so the result is the same whatever the message order).
template <class T>
T allReduce(T local, MPI_Datatype type, MPI_Op op, double& seconds) {
  util::ScopedTimer t(seconds);
  T out = local;
  check(MPI_Allreduce(&local, &out, 1, type, op, MPI_COMM_WORLD), "Allreduce");
  return out;
}
}  // namespace

double Communicator::minAll(double local) const {
  return mpi_ ? allReduce(local, MPI_DOUBLE, MPI_MIN, seconds_) : local;
}

int64_t Communicator::minAll(int64_t local) const {
  return mpi_ ? allReduce(local, MPI_INT64_T, MPI_MIN, seconds_) : local;
}

int64_t Communicator::maxAll(int64_t local) const {
  return mpi_ ? allReduce(local, MPI_INT64_T, MPI_MAX, seconds_) : local;
}

long long Communicator::sumAll(long long local) const {
  return mpi_ ? allReduce(local, MPI_LONG_LONG, MPI_SUM, seconds_) : local;
}

std::vector<double> Communicator::sumOrdered(const std::vector<double>& local) const {
  if (!mpi_) return local;
  // Gather every rank's partials and add them in rank order: MPI_SUM may associate in any
  // order, which would make diagnostics differ from run to run.
  const auto all = allGather(local);
  std::vector<double> out(local.size(), 0.0);
  for (int r = 0; r < size_; ++r)
    for (std::size_t i = 0; i < local.size(); ++i) out[i] += all[r * local.size() + i];
  return out;
}

bool Communicator::anyAll(bool local) const {
  return mpi_ ? allReduce(local ? 1 : 0, MPI_INT, MPI_MAX, seconds_) != 0 : local;
}

uint64_t Communicator::orAll(uint64_t local) const {
  return mpi_ ? allReduce(local, MPI_UINT64_T, MPI_BOR, seconds_) : local;
}

std::vector<char> Communicator::gatherToRoot(const std::vector<char>& local) const {
  if (!mpi_) return local;
  util::ScopedTimer t(seconds_);
  const auto n = static_cast<long long>(local.size());
  std::vector<long long> counts(static_cast<std::size_t>(size_));
  check(MPI_Gather(&n, 1, MPI_LONG_LONG, counts.data(), 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD),
        "Gather");
  std::vector<char> out;
  if (rank_ == 0) {
    out = local;
    for (int r = 1; r < size_; ++r) {
      std::vector<char> buf(static_cast<std::size_t>(counts[static_cast<std::size_t>(r)]));
      check(MPI_Recv(buf.data(), static_cast<int>(buf.size()), MPI_CHAR, r, 7, MPI_COMM_WORLD,
                     MPI_STATUS_IGNORE),
            "Recv");
      out.insert(out.end(), buf.begin(), buf.end());
    }
  } else {
    check(MPI_Send(local.data(), static_cast<int>(local.size()), MPI_CHAR, 0, 7, MPI_COMM_WORLD),
          "Send");
  }
  return out;
}

void Communicator::broadcast(std::vector<char>& bytes) const {
  if (!mpi_) return;
  util::ScopedTimer t(seconds_);
  long long n = static_cast<long long>(bytes.size());
  check(MPI_Bcast(&n, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD), "Bcast");
  bytes.resize(static_cast<std::size_t>(n));
  // In chunks: an MPI count is an int.
  constexpr long long kChunk = 1 << 30;
  for (long long off = 0; off < n; off += kChunk) {
    const int len = static_cast<int>(std::min(kChunk, n - off));
    check(MPI_Bcast(bytes.data() + off, len, MPI_CHAR, 0, MPI_COMM_WORLD), "Bcast");
  }
}

void Communicator::barrier() const {
  if (!mpi_) return;
  util::ScopedTimer t(seconds_);
  MPI_Barrier(MPI_COMM_WORLD);
}

void Communicator::abort(int code) const {
  if (mpi_) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

Communicator& world() {
  static Communicator instance;
  return instance;
}

namespace {
// Seconds per round trip of `bytes` between ranks 0 and 1, the fastest of `repetitions`
// (the least disturbed by other work on a shared machine).
double roundTrip(int rank, std::vector<char>& buffer, int repetitions) {
  const int n = static_cast<int>(buffer.size());
  double best = 1e30;
  for (int i = 0; i < repetitions; ++i) {
    const double t0 = MPI_Wtime();
    if (rank == 0) {
      check(MPI_Send(buffer.data(), n, MPI_BYTE, 1, 7, MPI_COMM_WORLD), "Send");
      check(MPI_Recv(buffer.data(), n, MPI_BYTE, 1, 7, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "Recv");
    } else {
      check(MPI_Recv(buffer.data(), n, MPI_BYTE, 0, 7, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "Recv");
      check(MPI_Send(buffer.data(), n, MPI_BYTE, 0, 7, MPI_COMM_WORLD), "Send");
    }
    best = std::min(best, MPI_Wtime() - t0);
  }
  return best;
}
}  // namespace

LinkSpeed pingPong(const Communicator& c, int repetitions) {
  LinkSpeed out;
  if (!c.distributed()) return out;
  if (c.rank() <= 1) {
    std::vector<char> small(8), large(std::size_t(1) << 20);
    roundTrip(c.rank(), small, 10);  // connection set-up
    const double t_small = roundTrip(c.rank(), small, repetitions);
    const double t_large = roundTrip(c.rank(), large, std::max(4, repetitions / 10));
    out.latency_s = 0.5 * t_small;
    out.bandwidth_bytes_per_s = double(large.size()) / std::max(1e-9, 0.5 * (t_large - t_small));
    out.measured = true;
  }
  c.barrier();
  return out;
}

void initialize(int* argc, char*** argv) {
  const bool launched = std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") ||
                        std::getenv("PMIX_RANK") || std::getenv("CRUMPLE_FORCE_MPI");
  if (!launched) return;
  int provided = 0;
  // Threads compute between MPI calls, never inside them: FUNNELED is enough.
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  auto& w = world();
  MPI_Comm_rank(MPI_COMM_WORLD, &w.rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &w.size_);
  w.mpi_ = true;
}

void finalize() {
  auto& w = world();
  if (w.mpi_) {
    MPI_Finalize();
    w.mpi_ = false;
  }
}

}  // namespace crumple::comm
