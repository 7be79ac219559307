// Wall-clock time of the phases of a run, for the time breakdown every run
// reports.
#pragma once

#include <chrono>

namespace crumple::util {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Adds the wall time of its scope to `total` (e.g. a solver::Timing field): a
// timed phase is one declaration instead of a pair of clock reads, and its time
// counts on every way out.
class ScopedTimer {
 public:
  explicit ScopedTimer(double& total) : total_(total) {}
  ~ScopedTimer() { total_ += secondsSince(start_); }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  double& total_;
  Clock::time_point start_ = Clock::now();
};

}  // namespace crumple::util
