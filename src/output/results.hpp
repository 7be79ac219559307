// Writes what a run produces (ARCHITECTURE.md Part 2, "Output files"): histories when they
// fall due, plot states for ParaView, and summary.json at the end.
#pragma once

#include <filesystem>
#include <string>

#include "model/model.hpp"
#include "output/files.hpp"
#include "output/vtk.hpp"
#include "solver/solver.hpp"

namespace crumple::output {

struct RunInfo {
  std::string deck;
  int ranks = 1;
  int threads = 1;
  std::string termination = "normal";  // "normal", "error", "signal"
  std::string message;                 // the error, if any
  double wall_s = 0.0;
};

class ResultsWriter {
 public:
  ResultsWriter(std::filesystem::path dir, const model::Model& model, const solver::Solver& s);

  // Writes the histories and plot states that are due at the solver's current time; `last`
  // forces a final sample of everything (end of run or error).
  void write(const solver::Solver& s, bool last = false);
  void writeSummary(const solver::Solver& s, const RunInfo& info) const;
  double seconds() const { return seconds_; }

 private:
  struct Schedule {
    double interval = 0.0;
    double next = 0.0;
    bool due(double t, bool last) const {
      return interval > 0.0 && (last || t >= next * (1 - 1e-9));
    }
    void advance(double t) {
      while (next <= t * (1 + 1e-9)) next += interval;
    }
  };
  void writePlotState(const solver::Solver& s);

  std::filesystem::path dir_;
  const model::Model& model_;
  Schedule glstat_, matsum_, nodout_, rwforc_, plot_;
  CsvWriter glstat_csv_, matsum_csv_, nodout_csv_, rwforc_csv_;
  std::vector<int32_t> history_local_;  // local node of each history node
  PvdWriter pvd_;
  int plot_count_ = 0;
  double last_plot_time_ = -1.0;
  double seconds_ = 0.0;
};

}  // namespace crumple::output
