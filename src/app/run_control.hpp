// Run control (docs/reliability.md): what dumps, reports or stops a run besides its end time.
// Signals, the sense switches of the stop file, --checkpoint-every and *DATABASE_BINARY_D3DUMP
// are requests that every rank acts on at the same cycle; --energy-band ends the run when the
// energy ratio leaves the band.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "comm/communicator.hpp"
#include "model/model.hpp"
#include "solver/solver.hpp"
#include "util/timer.hpp"

namespace crumple::app {

// Requests agreed by all ranks once per cycle (Communicator::orAll): whatever rank saw a
// signal, and whatever rank 0 found in the stop file or on its clock, every rank acts on at
// the same cycle. Acting never changes the state, so results stay bitwise the same.
enum Request : uint64_t {
  kSigInt = 1,       // SIGINT: dump, final state, exit 130
  kSigTerm = 2,      // SIGTERM: dump, final state, exit 143
  kSigUsr1 = 4,      // SIGUSR1: dump and continue (like sw3)
  kStop = 8,         // sense switch sw1: dump, final state, exit 0
  kStatus = 16,      // sense switch sw2: status line
  kDump = 32,        // sense switch sw3: dump and continue
  kCheckpoint = 64,  // --checkpoint-every: due by rank 0's wall clock
  kCycleDump = 128   // *DATABASE_BINARY_D3DUMP: due by the cycle count (the same on every rank)
};

// One cycle's requests, the same on every rank.
struct Requests {
  uint64_t bits = 0;
  bool stop() const { return (bits & (kSigInt | kSigTerm | kStop)) != 0; }
  bool status() const { return (bits & kStatus) != 0; }
  // Why a dump is due, the most pressing reason first ("SIGTERM", "sense switch sw3"...);
  // null when none is.
  const char* dumpReason() const;
  // A stop's exit status (128 + the signal, 0 for sw1) and its message for run.log and
  // summary.json.
  int exitStatus() const;
  std::string stopMessage() const;
};

// Handlers for SIGINT and SIGTERM (dump and stop) and SIGUSR1 (dump and go on). They only set
// flags, which RunControl::poll reads; a second SIGINT or SIGTERM ends the process at once.
void installSignalHandlers();

// --energy-band LO,HI into the controls (empty: no band); util::InputError unless
// 0 < LO < 1 < HI.
void setEnergyBand(const std::vector<double>& band, model::Controls& controls);

class RunControl {
 public:
  // `warn` reports (on rank 0) a stop file that holds no sense switch. Constructed when the
  // cycle loop starts: the checkpoint clock runs from then.
  RunControl(const comm::Communicator& comm, std::filesystem::path dir,
             const model::Controls& controls, double checkpoint_every,
             std::function<void(const std::string&)> warn);

  // Collective, once per cycle after the step: the requests every rank acts on now.
  Requests poll(const solver::Solver& s);
  // --energy-band: a util::NumericalError when the energy ratio has left the band, naming the
  // element with the most energy (collective; every 64 cycles).
  void checkEnergyBand(const solver::Solver& s) const;

 private:
  // Rank 0's requests: the checkpoint clock and the stop file.
  uint64_t rootRequests(int64_t cycle);

  const comm::Communicator& comm_;
  std::filesystem::path dir_;
  int64_t dump_cycles_;
  double ratio_min_, ratio_max_;
  double checkpoint_every_;
  std::function<void(const std::string&)> warn_;
  util::Clock::time_point last_checkpoint_ = util::Clock::now();
  util::Clock::time_point last_stop_check_ = last_checkpoint_;
};

}  // namespace crumple::app
