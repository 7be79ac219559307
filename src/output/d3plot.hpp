// LS-DYNA's binary plot database, d3plot (LS-DYNA "Database Binary Output Files" manual,
// "State database (d3plot)"), written beside the VTU states when the deck has
// *DATABASE_BINARY_D3PLOT, as LS-DYNA does. 4-byte words (single precision, host byte order):
//
//   d3plot     control words (64), geometry (initial coordinates; solid, beam and shell
//              connectivity with material numbers), user ids (NARBS: nodes, elements and the
//              part ids of the material numbers), EOF marker, part titles and the header title
//              (types 90001 and 90000), EOF marker; padded to whole 512-word blocks.
//   d3plot01.. states: time, global variables, node coordinates, velocities, accelerations,
//              solid, beam and shell records, element deletion flags; each member ends with the
//              EOF marker and is padded to whole 512-word blocks. A state that would make the
//              member larger than Controls::d3plot_file_words starts the next member.
//
// Rank 0 writes every file. The state data travel to it in global order in pieces of at most
// kPieceWords words (each rank sends the records it owns of the piece's range), so rank 0 holds
// one piece, never the whole model: memory O(kPieceWords) beyond the model itself.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "comm/communicator.hpp"
#include "model/model.hpp"
#include "solver/solver.hpp"
#include "util/archive.hpp"

namespace crumple::output {

// "d3plot" for index 0, then "d3plot01", ..., "d3plot99", "d3plot100" (LS-DYNA's family names).
std::string d3plotName(int index);
// The family index of a file name, or -1 when it is not a d3plot family member.
int d3plotIndex(const std::string& name);

// Words per state and the header's counts, from the model and *DATABASE_EXTENT_BINARY.
struct D3plotLayout {
  static constexpr int kMaxint = 3;  // shell layers written: mid, inner, outer surface
  // nel2: beams, then discrete elements; nel8 the solids but thick shells, nelt those (the
  // model keeps both in its solid family).
  int64_t numnp = 0, nel8 = 0, nel2 = 0, nel4 = 0, nelt = 0;
  int64_t num_beams = 0;
  int nummat8 = 0, nummat2 = 0, nummat4 = 0, nummatt = 0, nmmat = 0;
  // Per solid-family model element: its place in the solid or the thick-shell section.
  std::vector<int64_t> solid_place;
  std::vector<uint8_t> solid_is_tshell;
  // Material number (1..nmmat) of each model part, 0 when the part has no element; material
  // numbers go to parts of solids, then thick shells, then shells, then beams and discretes
  // (each in part order).
  std::vector<int32_t> material;
  std::vector<int32_t> part_of_material;  // material number - 1 -> model part index
  bool shell_stress = true, shell_plastic_strain = true, shell_resultants = true,
       shell_energy = true;  // IOSHL(1..4)
  int nglbv() const { return 6 + 7 * nmmat; }
  int nv2d() const {
    return kMaxint * (6 * shell_stress + shell_plastic_strain) + 8 * shell_resultants +
           4 * shell_energy;
  }
  // Thick shells: per layer (mid, inner, outer) the stress and plastic strain as the shells'
  // (IOSHL(1), IOSHL(2)); no extra variables (NEIPS 0), no strains (ISTRN 0).
  int nv3dt() const { return kMaxint * (6 * shell_stress + shell_plastic_strain); }
  static constexpr int kNv3d = 7, kNv1d = 6;
  int64_t stateWords() const {
    return 1 + nglbv() + 9 * numnp + kNv3d * nel8 + nv3dt() * nelt + kNv1d * nel2 + nv2d() * nel4 +
           nel8 + nelt + nel2 + nel4;
  }
};
D3plotLayout d3plotLayout(const model::Model& model);

class WordFile;  // d3plot.cpp: a file written in 4-byte words

class D3plotWriter {
 public:
  // Takes what it needs of the mesh now (the run releases it after set-up). Throws
  // util::InputError when an id does not fit a 4-byte word.
  D3plotWriter(std::filesystem::path dir, const model::Model& model,
               const comm::Communicator& comm);
  // Rank 0 writes the d3plot file and removes family members of an earlier run.
  void start();
  // One state (collective: every rank calls it at the same cycles).
  void writeState(const solver::Solver& s);

  // Restart (docs/reliability.md "Restart"). Before the mesh is released, prepareRestart()
  // keeps the d3plot file this model writes (rank 0). save() gives where the family stands
  // (valid on rank 0). load() (every rank) restores it and, on rank 0, checks that the folder
  // holds this run's family (the same d3plot file, the member at least as long as the dump
  // says; throws util::InputError naming the file otherwise); resume() then cuts the member
  // back to the dump (its states, the EOF marker, the padding) and removes later members.
  // A dump of a run without d3plot starts a new family: startFromPrepared().
  void prepareRestart();
  std::vector<char> save() const;
  void load(const std::vector<char>& bytes);
  void resume();
  void startFromPrepared();
  int states() const { return states_; }

 private:
  void writeGlobals(WordFile& out, const solver::Energies& e,
                    const std::vector<solver::PartSums>& parts) const;
  void writeNodes(WordFile* out, const solver::Solver& s) const;
  void writeElements(WordFile* out, const solver::Solver& s) const;
  void thickShellRecord(const domain::SolidBlock& b, const domain::NodeVector& x, std::size_t k,
                        float* r) const;
  void shellRecord(const domain::ShellBlock& b, const domain::NodeVector& x, std::size_t k,
                   float* r) const;
  // A new family: no states yet; rank 0 removes the members of an earlier run (true there).
  bool beginFamily();
  void removeMembersAfter(int index) const;
  void writeRoot(WordFile& out) const;

  std::filesystem::path dir_;
  const model::Model& model_;
  const comm::Communicator& comm_;
  D3plotLayout layout_;
  int64_t max_words_;
  int member_ = 0;            // family member holding the last state (0: none yet)
  int64_t member_words_ = 0;  // words of states in it (before the EOF marker)
  int64_t root_words_ = 0;    // size of the d3plot file (checked on restart)
  int states_ = 0;
  std::vector<char> pending_root_;  // restart: the d3plot file of this model (rank 0)
};

}  // namespace crumple::output
