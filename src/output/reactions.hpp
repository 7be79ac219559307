// The histories of constraint reactions, rigid bodies and discrete elements: spcforc (the
// forces of the SPCs), bndout (the forces and work of the prescribed motions), rbdout (rigid
// body motion) and deforc (spring and damper forces), each in LS-DYNA's ASCII layout
// (ascii.hpp) with a CSV twin, written when the deck has *DATABASE_SPCFORC, _BNDOUT, _RBDOUT
// or _DEFORC and the model the entities they report, at the keyword's DT.
//
// The node and element values are gathered to rank 0 from the ranks that own the nodes
// (compute the elements) and written in ascending node (element) id, so the files are the
// same bytes at any rank count; rigid bodies are the same on every rank (rank 0's are written).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "comm/communicator.hpp"
#include "model/model.hpp"
#include "output/ascii.hpp"
#include "output/files.hpp"
#include "solver/solver.hpp"
#include "util/archive.hpp"

namespace crumple::output {

// The DT of a *DATABASE_ history, or without one (0) a sample every 1/200 of the run.
double historyInterval(double requested, double end_time);
// Rank 0's view of every rank's records of `width` numbers, the first the id, ordered by id
// (a stable sort: one entity's records come from the one rank that owns it, in its order);
// empty on the other ranks. Collective.
std::vector<std::vector<double>> gatherById(const comm::Communicator& comm,
                                            const std::vector<double>& local, std::size_t width);

class ReactionHistories {
 public:
  ReactionHistories(const model::Model& model, const solver::Solver& s,
                    const comm::Communicator& comm);

  // A file of this group: its name, the writer, the CSV columns (null for an ASCII file) and
  // whether this run writes it.
  struct File {
    const char* name;
    HistoryFile* file;
    const std::vector<std::string>* columns;
    bool wanted;
  };
  std::vector<File> files();
  // The header of the ASCII file `name` (files()).
  std::string header(std::string_view name) const;

  // Writes what is due at the solver's time (collective: every rank calls it each time).
  void write(const solver::Solver& s, bool last);
  // Restart: the schedules (rank 0's bytes are kept; every rank loads them). A schedule whose
  // interval the deck changed starts anew at `time`.
  void saveState(util::ArchiveWriter& out) const;
  void loadState(util::ArchiveReader& in, double time);

 private:
  void writeSpcforc(const solver::Solver& s);
  void writeBndout(const solver::Solver& s);
  void writeRbdout(const solver::Solver& s);
  void writeDeforc(const solver::Solver& s);

  const model::Model& model_;
  const comm::Communicator& comm_;
  bool spc_ = false, motion_ = false, rigid_ = false, discrete_ = false;  // entities present
  HistorySchedule spcforc_, bndout_, rbdout_, deforc_;
  CsvWriter spcforc_csv_, bndout_csv_, rbdout_csv_, deforc_csv_;
  HistoryFile spcforc_txt_, bndout_txt_, rbdout_txt_, deforc_txt_;
};

}  // namespace crumple::output
