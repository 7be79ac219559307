// elout: the stresses of the elements of *DATABASE_HISTORY_SOLID, _SHELL and _BEAM (and their
// _SET forms) at *DATABASE_ELOUT's DT, in LS-DYNA's ASCII layout (ascii.hpp) with a CSV twin.
//
// Solids: the element's stress (global frame), its effective plastic strain and von Mises
// stress. Shells: every integration point through the thickness (global frame, the mean of the
// in-plane points), bottom first. Beams: the section resultants at mid-length (axial, shears,
// moments, torque; elements::beamSectionResultants) and, for integrated beams and trusses, the
// stresses of the cross-section points in the beam's frame.
//
// Each element is computed by one rank; its records travel to rank 0, which writes them in
// ascending element id per family (solids, beams, shells), so the file is the same bytes at any
// rank count.
#pragma once

#include <array>
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

class ElementHistories {
 public:
  ElementHistories(const model::Model& model, const solver::Solver& s,
                   const comm::Communicator& comm);

  // elout.csv's columns: time, element, family (0 solid, 1 shell, 2 beam), point (solids 1,
  // shells 1..NIP from the bottom, beams 0 for the resultants and 1.. for the section points),
  // the stress (a beam point's sigma 11, 12, 31 in sxx, sxy, szx), the effective plastic strain
  // and a beam's resultants (zero for the other rows).
  static const std::vector<std::string>& columns();
  bool wanted() const { return wanted_; }
  CsvWriter& csv() { return csv_; }
  HistoryFile& text() { return txt_; }
  std::string header() const;

  // Writes what is due at the solver's time (collective: every rank calls it each time).
  void write(const solver::Solver& s, bool last);
  void saveState(util::ArchiveWriter& out) const;
  void loadState(util::ArchiveReader& in, double time);

 private:
  struct Held {
    std::size_t block = 0, k = 0;
  };
  std::vector<double> solidRecords(const solver::Solver& s) const;
  std::vector<double> shellRecords(const solver::Solver& s) const;
  std::vector<double> beamRecords(const solver::Solver& s) const;
  int64_t materialType(int32_t part) const;

  const model::Model& model_;
  const comm::Communicator& comm_;
  bool wanted_ = false;
  std::array<std::vector<Held>, 3> held_;  // solids, shells, beams held by this rank
  HistorySchedule schedule_;
  CsvWriter csv_;
  HistoryFile txt_;
};

}  // namespace crumple::output
