// Writes what a run produces (ARCHITECTURE.md Part 2, "Output files"): histories when they
// fall due, plot states for ParaView, and summary.json at the end.
#pragma once

#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>

#include "comm/communicator.hpp"
#include "model/model.hpp"
#include "output/d3plot.hpp"
#include "output/elout.hpp"
#include "output/energy_audit.hpp"
#include "output/files.hpp"
#include "output/reactions.hpp"
#include "output/sections.hpp"
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
  double setup_s = 0.0;  // reading, partitioning, distributing and initialising
  // setup_s by phase, in order, adding up to it (summary.json "setup"): read (deck text to
  // keywords), validate (keywords to the checked model), partition, distribute, initialise
  // (subdomain and solver), output (results folder, log, writers; a restart's dump restored).
  std::vector<std::pair<std::string, double>> setup_phases;
  int64_t first_cycle = 0;  // a restarted run's first cycle: the rate counts this run's cycles
  // Cycles of the dynamic-relaxation phase before the transient (summary.json
  // "relaxation_cycles" when there was one; its time is set-up phase "relax").
  int64_t relaxation_cycles = 0;
  // --ignore-unsupported: the features left out (summary.json "ignored_unsupported").
  std::vector<std::string> ignored_unsupported;
};

class ResultsWriter {
 public:
  // Every rank constructs one and calls write() at the same cycles (the sums are collective);
  // rank 0 writes the histories, the .pvtu/.pvd and the summary, every rank its VTU piece.
  // With `restart`, the history files are left as they are until loadState() continues them.
  ResultsWriter(std::filesystem::path dir, const model::Model& model, const solver::Solver& s,
                const comm::Communicator& comm, bool restart = false);

  // Restart (docs/reliability.md "Restart"): the output schedules, the plot states written and
  // how far each history file is written. saveState's bytes are valid on rank 0. loadState
  // (every rank, after the solver's state) restores the schedules (one whose interval the
  // restart deck changed starts anew at the dump's time), cuts every history file back to the
  // dump and appends to it, and removes plot states written after the dump.
  std::vector<char> saveState() const;
  void loadState(const std::vector<char>& bytes, double time);

  // Writes the histories and plot states that are due at the solver's current time; `last`
  // forces a final sample of everything (end of run or error).
  void write(const solver::Solver& s, bool last = false);
  void writeSummary(const solver::Solver& s, const RunInfo& info) const;
  nlohmann::json timingByRank(const solver::Solver& s) const;
  // SHA-256 of x then v of every node in ascending global id (collective; valid on rank 0).
  std::string stateDigestGlobal(const solver::Solver& s) const;
  double seconds() const { return seconds_; }
  // What the energy audit found since the last call (rank 0; empty on the others), for run.log.
  std::string takeNotes() { return std::exchange(notes_, std::string()); }
  const EnergyAudit& energyAudit() const { return audit_; }

 private:
  using Schedule = HistorySchedule;
  void writePlotState(const solver::Solver& s);
  // One history each, when due (collective where their sums are).
  void writeGlstat(const solver::Solver& s);
  void writeMatsum(const solver::Solver& s);
  void writeNodout(const solver::Solver& s);
  void writeRwforc(const solver::Solver& s);
  void writeContact(const solver::Solver& s, bool rcforc, bool sleout);
  void writeSecforc(const solver::Solver& s);
  void writeJntforc(const solver::Solver& s);  // src/output/jntforc.hpp
  // The glstat record of LS-DYNA's layout (collective).
  ascii::GlstatSample glstatSample(const solver::Solver& s, const solver::Energies& e) const;
  // Every history file, CSV and LS-DYNA ASCII: its name, the file and whether this run writes
  // it (a restart dump records how far each is written).
  struct Stream {
    const char* name;
    HistoryFile* file;
    const std::vector<std::string>* columns;  // CSV columns; null for an ASCII file
    bool wanted;
  };
  std::vector<Stream> streams();
  void openStreams();
  void resumeStreams(const std::vector<Stream>& files,
                     const std::vector<std::pair<uint8_t, HistoryFile::Position>>& dumped);

  std::filesystem::path dir_;
  const model::Model& model_;
  const comm::Communicator& comm_;
  Schedule glstat_, matsum_, nodout_, rwforc_, rcforc_, plot_, sleout_, secforc_;
  // The intervals the deck asked for (0: the default), to tell a restart deck's change.
  std::array<double, 8> requested_{};
  CsvWriter glstat_csv_, matsum_csv_, nodout_csv_, rwforc_csv_, rcforc_csv_, secforc_csv_;
  // LS-DYNA's ASCII files, for the *DATABASE_<file> keywords of the deck.
  HistoryFile glstat_txt_, matsum_txt_, nodout_txt_, rwforc_txt_, rcforc_txt_, sleout_txt_,
      secforc_txt_;
  // Joint forces (*DATABASE_JNTFORC, or by default when the deck has joints); its schedule
  // is not in restart dumps: a restarted run writes it from its first cycle on.
  Schedule jntforc_;
  CsvWriter jntforc_csv_;
  HistoryFile jntforc_txt_;
  std::optional<SectionForces> sections_;                   // when the deck has cross sections
  std::optional<ElementHistories> elout_;                   // elout, elout.csv
  std::optional<ReactionHistories> reactions_;              // spcforc, bndout, rbdout, deforc
  std::vector<std::pair<int32_t, int32_t>> history_local_;  // (deck order, local node), owned
  std::size_t history_count_ = 0;
  PvdWriter pvd_;
  std::optional<D3plotWriter> d3plot_;  // when the deck has *DATABASE_BINARY_D3PLOT
  int plot_count_ = 0;
  double last_plot_time_ = -1.0;
  double seconds_ = 0.0;
  EnergyAudit audit_;
  std::string notes_;
};

}  // namespace crumple::output
