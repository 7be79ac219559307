#include "app/run_control.hpp"

#include <fmt/format.h>

#include <atomic>
#include <cctype>
#include <cmath>
#include <csignal>
#include <fstream>

#include "util/error.hpp"

namespace crumple::app {

namespace {

// The first SIGINT or SIGTERM received (0: none), and a pending SIGUSR1. Handlers only set
// flags; RunControl::poll turns them into requests.
std::atomic<int> g_signal{0};
std::atomic<bool> g_usr1{false};
extern "C" void onSignal(int sig) {
  if (sig == SIGUSR1) {
    g_usr1 = true;
    return;
  }
  int none = 0;
  // A second SIGINT or SIGTERM ends the process at once (a run stuck writing its dump can
  // still be stopped); signal() and raise() are async-signal-safe.
  if (!g_signal.compare_exchange_strong(none, sig)) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
  }
}

// Rank 0 looks for DIR/stop every kStopFileCycles cycles, and at least every kStopFilePeriod
// seconds of wall time (large models take long over 100 cycles); a stat() is cheap either way.
constexpr int64_t kStopFileCycles = 100;
constexpr double kStopFilePeriod = 0.5;

// The energy ratio is checked when the progress line refreshes the energy sums.
constexpr int64_t kEnergyBandCycles = 64;

// The sense switch in DIR/stop, or DIR/d3kil as LS-DYNA names it (sw1..sw3;
// docs/reliability.md), read by rank 0; the file is removed once read, so one request is acted
// on once. Anything else is reported.
uint64_t readStopFile(const std::filesystem::path& dir, std::string& note) {
  uint64_t request = 0;
  for (const char* name : {"stop", "d3kil"}) {
    const auto path = dir / name;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) continue;
    std::ifstream in(path);
    std::string word;
    in >> word;
    in.close();
    std::filesystem::remove(path, ec);
    for (auto& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (word == "sw1") {
      request |= kStop;
    } else if (word == "sw2") {
      request |= kStatus;
    } else if (word == "sw3") {
      request |= kDump;
    } else {
      note += fmt::format(
          "{}: '{}' is not a sense switch (sw1 dump and stop, sw2 status, sw3 dump and "
          "continue); removed without action\n",
          path.string(), word);
    }
  }
  return request;
}

}  // namespace

const char* Requests::dumpReason() const {
  return bits & kSigTerm      ? "SIGTERM"
         : bits & kSigInt     ? "SIGINT"
         : bits & kStop       ? "sense switch sw1"
         : bits & kDump       ? "sense switch sw3"
         : bits & kSigUsr1    ? "SIGUSR1"
         : bits & kCheckpoint ? "--checkpoint-every"
         : bits & kCycleDump  ? "*DATABASE_BINARY_D3DUMP"
                              : nullptr;
}

int Requests::exitStatus() const {
  return bits & kSigTerm ? 128 + SIGTERM : bits & kSigInt ? 128 + SIGINT : 0;
}

std::string Requests::stopMessage() const {
  if (bits & (kSigInt | kSigTerm))
    return fmt::format("interrupted by {}; a restart dump and the last state were written",
                       bits & kSigTerm ? "SIGTERM" : "SIGINT");
  return "stopped by sense switch sw1; a restart dump and the last state were written";
}

void installSignalHandlers() {
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  std::signal(SIGUSR1, onSignal);
}

void setEnergyBand(const std::vector<double>& band, model::Controls& controls) {
  if (band.empty()) return;
  const auto& b = band;
  if (b.size() != 2 || !(b[0] > 0.0) || !(b[0] < 1.0) || !(b[1] > 1.0) || !std::isfinite(b[1]))
    throw util::InputError("--energy-band LO,HI: needs 0 < LO < 1 < HI");
  controls.energy_ratio_min = b[0];
  controls.energy_ratio_max = b[1];
}

RunControl::RunControl(const comm::Communicator& comm, std::filesystem::path dir,
                       const model::Controls& controls, double checkpoint_every,
                       std::function<void(const std::string&)> warn)
    : comm_(comm),
      dir_(std::move(dir)),
      dump_cycles_(controls.d3dump_cycles),
      ratio_min_(controls.energy_ratio_min),
      ratio_max_(controls.energy_ratio_max),
      checkpoint_every_(checkpoint_every),
      warn_(std::move(warn)) {}

Requests RunControl::poll(const solver::Solver& s) {
  uint64_t request = 0;
  if (const int sig = g_signal.load(); sig != 0) request |= sig == SIGTERM ? kSigTerm : kSigInt;
  if (g_usr1.exchange(false)) request |= kSigUsr1;
  if (comm_.isRoot()) request |= rootRequests(s.cycle());
  // The last cycle's dump is the end-of-run dump (Run::end).
  if (dump_cycles_ > 0 && s.cycle() % dump_cycles_ == 0 && !s.finished()) request |= kCycleDump;
  // A signal may reach only some ranks, the stop file is read by rank 0: agree.
  return {comm_.orAll(request)};
}

uint64_t RunControl::rootRequests(int64_t cycle) {
  uint64_t request = 0;
  const auto now = util::Clock::now();
  if (checkpoint_every_ > 0.0 &&
      std::chrono::duration<double>(now - last_checkpoint_).count() >= checkpoint_every_) {
    request |= kCheckpoint;
    last_checkpoint_ = now;
  }
  if (cycle % kStopFileCycles == 0 ||
      std::chrono::duration<double>(now - last_stop_check_).count() >= kStopFilePeriod) {
    std::string note;
    request |= readStopFile(dir_, note);
    if (!note.empty()) warn_(note);
    last_stop_check_ = now;
  }
  return request;
}

void RunControl::checkEnergyBand(const solver::Solver& s) const {
  if (!(ratio_max_ > 0.0) || s.cycle() % kEnergyBandCycles != 0) return;
  const double ratio = s.energies().ratio;
  if (ratio >= ratio_min_ && ratio <= ratio_max_) return;
  // No element is "the" culprit of an energy error; the one holding the most internal plus
  // hourglass energy is where spurious energy (hourglassing, a diverging material) shows.
  throw util::NumericalError(fmt::format(
      "energy ratio {:.4f} left the band [{:g}, {:g}] (--energy-band) at cycle {}, time {:.6g}; "
      "most internal + hourglass energy in {}",
      ratio, ratio_min_, ratio_max_, s.cycle(), s.time(), s.mostEnergeticElement()));
}

}  // namespace crumple::app
