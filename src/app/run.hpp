// `crumple run`: set-up (read on rank 0, partition, distribute, open the outputs), the cycle
// loop, and the finish (summary, run.log, exit status).
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/run_control.hpp"
#include "comm/communicator.hpp"
#include "domain/subdomain.hpp"
#include "model/model.hpp"
#include "output/files.hpp"
#include "output/restart.hpp"
#include "output/results.hpp"
#include "solver/solver.hpp"
#include "util/error.hpp"
#include "util/timer.hpp"

namespace crumple::app {

// run.log, written by rank 0 (other ranks' lines go nowhere). A restart appends to the dumped
// run's log, but only once the dump and the folder are accepted (a folder of another run is
// left untouched): until the log is opened, lines wait here.
class RunLog {
 public:
  explicit RunLog(bool root) : root_(root) {}
  void open(const std::filesystem::path& path, bool append);
  void say(const std::string& text);
  // Throws std::runtime_error naming the file when a write has failed (a full disk).
  void check(const std::filesystem::path& path) const;
  bool failed() const { return !out_; }
  void close() { out_.close(); }

 private:
  bool root_;
  std::ofstream out_;
  std::string pending_;
};

// One `crumple run` (ARCHITECTURE.md, Commands): setUp, then start, cycleLoop and end under
// the error handling of execute(), then finish. Every rank runs the same sequence.
class Run {
 public:
  explicit Run(const RunOptions& opt);
  // Runs to the end: 0 normal termination (or sw1), 1 error termination, 128 + the signal.
  int execute();

 private:
  // False when the run cannot start: the reason is on stderr, and no results folder was
  // touched (or a refused one left as it was).
  bool setUp();
  // On rank 0: the deck with the options applied, the restart dump, the partition.
  void readModel();
  void readDump();
  void partitionElements();
  // The model, the partition and the dump from rank 0 to every rank.
  void distribute();
  bool initializeSolver();
  bool prepareFolder();
  // run.log's head, signal handlers and the sections of a restart dump.
  void openOutputs();
  void registerDumpSections();

  // The cycle loop and its two ends. Errors are handled in execute().
  void start();
  // The dynamic-relaxation phase of the deck (Solver::relax), reported in run.log.
  void relax();
  void restoreDump();
  void cycleLoop();
  // Writes the histories due now and puts what the energy audit found into run.log.
  void writeResults(bool last = false);
  void stop(const Requests& request);
  void end();
  void endWithError(const util::NumericalError& e);
  int finish();

  void writeDump(const char* why);
  void sayStatus();
  void openLog() { log_.open(dir_ / "run.log", restart_); }

  const RunOptions& opt_;
  util::Clock::time_point wall0_ = util::Clock::now();
  double setup_mark_ = 0.0;  // seconds since wall0_ at the end of the last set-up phase
  // Ends a set-up phase: its time since the previous mark joins info_.setup_phases.
  void endSetupPhase(const char* phase);
  comm::Communicator& comm_;
  const bool root_;
  const bool restart_;
  const bool show_;  // the progress line and the last line on stdout
  int threads_ = 1;

  model::Model model_;
  std::vector<int32_t> elem_rank_;  // element -> rank
  std::filesystem::path dump_path_;
  std::vector<char> dump_bytes_;  // the dump file, until every rank has decoded it
  output::DumpContents dump_;
  domain::Subdomain sd_;
  std::unique_ptr<solver::Solver> solver_;

  std::filesystem::path dir_;
  bool dir_existed_ = false;
  RunLog log_;
  output::RunInfo info_;
  std::unique_ptr<output::ResultsWriter> writer_;
  bool energy_warned_ = false;  // the energy band warning went to stderr
  output::DumpRegistry dumps_;
  std::optional<output::Progress> progress_;
  bool started_ = false;  // the first state is written: from here on, results are kept
  int status_ = 0;
};

}  // namespace crumple::app
