#include "output/d3plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>

#include "elements/beam.hpp"
#include "elements/shell.hpp"
#include "elements/tshell.hpp"
#include "util/error.hpp"

namespace crumple::output {

namespace fs = std::filesystem;

namespace {

constexpr float kEndOfFile = -999999.0f;  // the manual's EOF marker
constexpr int64_t kBlockWords = 512;      // files are padded to whole blocks of this many words
constexpr int64_t kPieceWords = int64_t(1) << 20;  // largest piece of state data gathered at once
constexpr int kTitleWords = 18;                    // part and header titles: 72 characters

// The word of an integer; the format has no wider one (8-byte databases aside).
int32_t word(int64_t v, const char* what) {
  if (v < std::numeric_limits<int32_t>::min() || v > std::numeric_limits<int32_t>::max())
    throw util::InputError(
        fmt::format("d3plot: {} {} does not fit a 4-byte word of the database", what, v));
  return static_cast<int32_t>(v);
}

}  // namespace

// Words written to a file from a given word on, through a bounded buffer, or kept in memory.
class WordFile {
 public:
  WordFile(const fs::path& path, int64_t at_word) : path_(path), position_(at_word) {
    if (!fs::exists(path)) std::ofstream(path, std::ios::binary);
    out_.open(path, std::ios::binary | std::ios::in | std::ios::out);
    if (!out_) throw std::runtime_error("cannot open " + path.string() + " for writing");
    out_.seekp(std::streamoff(4 * at_word));
  }
  explicit WordFile(std::vector<char>& memory) : memory_(&memory) {}
  void integer(int32_t v) { put(&v); }
  void real(double v) {
    const float f = static_cast<float>(v);
    put(&f);
  }
  void reals(const float* v, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) put(&v[k]);
  }
  // Characters, blank-padded to `words` words.
  void text(const std::string& s, int words) {
    std::string t = s.substr(0, std::size_t(4 * words));
    t.resize(std::size_t(4 * words), ' ');
    for (int k = 0; k < words; ++k) put(t.data() + 4 * k);
  }
  int64_t position() const { return position_; }
  // Ends the file here: the EOF marker, zeros to a whole block; then flushes and cuts it there.
  void finish() {
    real(kEndOfFile);
    while (position_ % kBlockWords != 0) integer(0);
    if (memory_) return;
    flush();
    out_.close();
    fs::resize_file(path_, std::uintmax_t(4 * position_));
  }

 private:
  void put(const void* p) {
    util::appendBytes(memory_ ? *memory_ : buffer_, p, 4);
    ++position_;
    if (!memory_ && buffer_.size() >= std::size_t(4 * kPieceWords)) flush();
  }
  void flush() {
    out_.write(buffer_.data(), std::streamsize(buffer_.size()));
    if (!out_) throw std::runtime_error("cannot write " + path_.string());
    buffer_.clear();
  }
  fs::path path_;
  std::fstream out_;
  std::vector<char>* memory_ = nullptr;
  std::vector<char> buffer_;
  int64_t position_ = 0;
};

std::string d3plotName(int index) {
  return index == 0 ? std::string("d3plot") : fmt::format("d3plot{:02d}", index);
}

int d3plotIndex(const std::string& name) {
  if (name.rfind("d3plot", 0) != 0) return -1;
  const std::string digits = name.substr(6);
  if (digits.empty()) return 0;
  if (digits.size() < 2 || digits.size() > 6 ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return -1;
  return std::stoi(digits);
}

D3plotLayout d3plotLayout(const model::Model& m) {
  D3plotLayout l;
  l.numnp = int64_t(m.nodes.size());
  // Thick shells (kept with the solids) go to the NELT section, the others stay solids.
  l.solid_place.resize(m.solids.size());
  l.solid_is_tshell.resize(m.solids.size());
  for (std::size_t e = 0; e < m.solids.size(); ++e) {
    const bool thick = m.isThickShellElement(int32_t(e));
    l.solid_is_tshell[e] = thick ? 1 : 0;
    l.solid_place[e] = thick ? l.nelt++ : l.nel8++;
  }
  l.nel4 = int64_t(m.shells.size());
  l.num_beams = int64_t(m.beams.size());
  l.nel2 = l.num_beams + int64_t(m.discretes.size());
  // Material numbers as VTK's vtkLSDynaReader and LS-PrePost list them: solid parts first, then
  // thick-shell parts, shell parts, beam parts (the header's NUMMAT8, NUMMATT, NUMMAT4,
  // NUMMAT2 counts).
  const std::size_t np = m.parts.size();
  std::vector<int> family(np, -1);  // 0 solid, 1 thick shell, 2 shell, 3 beam or discrete
  for (std::size_t e = 0; e < m.solids.size(); ++e)
    family[std::size_t(m.solids.part[e])] = l.solid_is_tshell[e] ? 1 : 0;
  for (int32_t p : m.shells.part) family[std::size_t(p)] = 2;
  for (int32_t p : m.beams.part) family[std::size_t(p)] = 3;
  for (int32_t p : m.discretes.part) family[std::size_t(p)] = 3;
  l.material.assign(np, 0);
  int* counts[4] = {&l.nummat8, &l.nummatt, &l.nummat4, &l.nummat2};
  for (int f = 0; f < 4; ++f)
    for (std::size_t p = 0; p < np; ++p)
      if (family[p] == f) {
        ++*counts[f];
        l.part_of_material.push_back(int32_t(p));
        l.material[p] = int32_t(l.part_of_material.size());
      }
  l.nmmat = int(l.part_of_material.size());
  const auto& e = m.controls.d3plot_extent;
  l.shell_stress = e.shell_stress;
  l.shell_plastic_strain = e.shell_plastic_strain;
  l.shell_resultants = e.shell_resultants;
  l.shell_energy = e.shell_energy;
  return l;
}

namespace {

// The 64 control words (the manual's "Control data"; word numbers from 0 in the comments).
void writeControlWords(WordFile& out, const model::Model& m, const D3plotLayout& l) {
  out.text(m.title, 10);  // 0-9 title
  out.integer(0);         // 10 run time: 0 keeps the file reproducible (LS-DYNA: the clock)
  out.integer(1);         // 11 file type 1: d3plot
  out.integer(0);         // 12 source version
  out.text("CRMP", 1);    // 13 release (character*4)
  out.real(960.0);        // 14 version: 960 says IEEE single precision words
  out.integer(4);         // 15 NDIM 4: 3-D, connectivity unpacked, no material type section
  out.integer(word(l.numnp, "node count"));    // 16 NUMNP
  out.integer(6);                              // 17 ICODE 6: LS-DYNA
  out.integer(l.nglbv());                      // 18 NGLBV
  const int32_t it_iu_iv_ia[] = {0, 1, 1, 1};  // 19-22: no temperature; x, v, a
  for (int32_t v : it_iu_iv_ia) out.integer(v);
  out.integer(word(l.nel8, "solid count"));  // 23 NEL8
  out.integer(l.nummat8);                    // 24 NUMMAT8
  out.integer(0);                            // 25, 26 unused
  out.integer(0);
  out.integer(D3plotLayout::kNv3d);          // 27 NV3D
  out.integer(word(l.nel2, "beam count"));   // 28 NEL2
  out.integer(l.nummat2);                    // 29 NUMMAT2
  out.integer(D3plotLayout::kNv1d);          // 30 NV1D
  out.integer(word(l.nel4, "shell count"));  // 31 NEL4
  out.integer(l.nummat4);                    // 32 NUMMAT4
  out.integer(l.nv2d());                     // 33 NV2D
  out.integer(0);                            // 34 NEIPH
  out.integer(0);                            // 35 NEIPS
  // 36 MAXINT: -(10000 + MAXINT) says element deletion flags follow each state (MDLOPT 2).
  out.integer(-(10000 + D3plotLayout::kMaxint));
  out.integer(0);  // 37 NMSPH
  out.integer(0);  // 38 NGPSPH
  out.integer(word(16 + l.numnp + l.nel8 + l.nel2 + l.nel4 + l.nelt + 3 * int64_t(l.nmmat),
                   "user id count"));              // 39 NARBS
  out.integer(word(l.nelt, "thick shell count"));  // 40 NELT
  out.integer(l.nummatt);                          // 41 NUMMATT
  out.integer(l.nv3dt());                          // 42 NV3DT
  // 43-46 IOSHL(1..4): 1000 written, 999 not (stress, plastic strain, resultants, thickness
  // and energy of shells).
  for (bool on : {l.shell_stress, l.shell_plastic_strain, l.shell_resultants, l.shell_energy})
    out.integer(on ? 1000 : 999);
  out.integer(0);                                // 47 IALEMAT
  out.integer(0);                                // 48 NCFDV1
  out.integer(0);                                // 49 NCFDV2
  out.integer(0);                                // 50 NADAPT
  out.integer(l.nmmat);                          // 51 NMMAT
  for (int k = 52; k < 64; ++k) out.integer(0);  // NUMFLUID, INN, NPEFG, NEL48, IDTDT, EXTRA...
}

// Initial coordinates, then solids (8 nodes, material), thick shells (the same), beams (nodes
// 1, 2, orientation node, two unused words, material), shells (4 nodes, material); node numbers
// from 1.
void writeGeometry(WordFile& out, const model::Model& m, const D3plotLayout& l) {
  for (const auto& x : m.nodes.x)
    for (int c = 0; c < 3; ++c) out.real(x[std::size_t(c)]);
  for (uint8_t thick : {0, 1})
    for (std::size_t e = 0; e < m.solids.size(); ++e) {
      if (l.solid_is_tshell[e] != thick) continue;
      for (int32_t n : m.solids.nodes[e]) out.integer(n + 1);
      out.integer(l.material[std::size_t(m.solids.part[e])]);
    }
  auto beam = [&](const auto& list, std::size_t e, int32_t orientation) {
    const auto& n = list.nodes[e];
    // Without an orientation node the second node stands in (as LS-DYNA writes it).
    const int32_t third = orientation == model::kNone ? n[1] : orientation;
    const int32_t w[6] = {n[0] + 1, n[1] + 1, third + 1,
                          0,        0,        l.material[std::size_t(list.part[e])]};
    for (int32_t v : w) out.integer(v);
  };
  for (std::size_t e = 0; e < m.beams.size(); ++e) beam(m.beams, e, m.beams.orientation[e]);
  for (std::size_t e = 0; e < m.discretes.size(); ++e) beam(m.discretes, e, model::kNone);
  for (std::size_t e = 0; e < m.shells.size(); ++e) {
    for (int32_t n : m.shells.nodes[e]) out.integer(n + 1);
    out.integer(l.material[std::size_t(m.shells.part[e])]);
  }
}

// User ids (NSORT < 0: with the part ids of the material numbers): 16 words of pointers and
// counts, node ids, solid, beam, shell, thick-shell ids, then NORDER (part id of each material
// number),
// the part ids ascending and the material number of each of those.
void writeUserIds(WordFile& out, const model::Model& m, const D3plotLayout& l) {
  const int64_t first = out.position() + 16 + 1;  // word address of the node ids (from 1)
  const int64_t nsrh = first + l.numnp, nsrb = nsrh + l.nel8, nsrs = nsrb + l.nel2,
                nsrt = nsrs + l.nel4, nsrma = nsrt + l.nelt, nsrmu = nsrma + l.nmmat,
                nsrmp = nsrmu + l.nmmat;
  const int64_t head[16] = {-first, nsrh,   nsrb,  nsrs,  nsrt,  l.numnp, l.nel8, l.nel2,
                            l.nel4, l.nelt, nsrma, nsrmu, nsrmp, l.nmmat, 0,      l.nmmat};
  for (int64_t v : head) out.integer(word(v, "user id pointer"));
  for (int64_t id : m.nodes.id) out.integer(word(id, "node id"));
  auto solid_ids = [&](uint8_t thick) {
    for (std::size_t e = 0; e < m.solids.size(); ++e)
      if (l.solid_is_tshell[e] == thick) out.integer(word(m.solids.id[e], "solid id"));
  };
  solid_ids(0);
  for (int64_t id : m.beams.id) out.integer(word(id, "beam id"));
  for (int64_t id : m.discretes.id) out.integer(word(id, "discrete element id"));
  for (int64_t id : m.shells.id) out.integer(word(id, "shell id"));
  solid_ids(1);
  std::vector<int64_t> ids;
  for (int32_t p : l.part_of_material) ids.push_back(m.parts[std::size_t(p)].id);
  for (int64_t id : ids) out.integer(word(id, "part id"));
  std::vector<std::size_t> sorted(ids.size());
  for (std::size_t k = 0; k < sorted.size(); ++k) sorted[k] = k;
  std::sort(sorted.begin(), sorted.end(), [&](auto a, auto b) { return ids[a] < ids[b]; });
  for (std::size_t k : sorted) out.integer(word(ids[k], "part id"));
  for (std::size_t k : sorted) out.integer(int32_t(k + 1));
}

// After the EOF marker: part titles (type 90001) and the header title (type 90000), then the
// EOF marker again (the manual's "Header, part & contact interface titles").
void writeTitles(WordFile& out, const model::Model& m, const D3plotLayout& l) {
  out.real(kEndOfFile);
  out.integer(90001);
  out.integer(l.nmmat);
  for (int32_t p : l.part_of_material) {
    const auto& part = m.parts[std::size_t(p)];
    out.integer(word(part.id, "part id"));
    out.text(part.title, kTitleWords);
  }
  out.integer(90000);
  out.text(m.title, kTitleWords);
}

// A family member's records of one state: `width` floats per item, `count` items in global
// order. `index` lists the items this rank owns (ascending), `fill(k, out)` writes item k's
// record. The items travel to rank 0 in pieces of at most kPieceWords words.
template <class Fill>
void streamRecords(const comm::Communicator& comm, WordFile* out, int64_t count, int width,
                   const std::vector<int64_t>& index, Fill&& fill) {
  const int64_t per_piece = std::max<int64_t>(1, kPieceWords / width);
  const std::size_t record = sizeof(int64_t) + sizeof(float) * std::size_t(width);
  std::size_t next = 0;
  std::vector<float> values(static_cast<std::size_t>(width));
  for (int64_t begin = 0; begin < count; begin += per_piece) {
    const int64_t end = std::min(count, begin + per_piece);
    std::vector<char> mine;
    for (; next < index.size() && index[next] < end; ++next) {
      fill(next, values.data());
      util::appendValue(mine, index[next]);
      util::appendBytes(mine, values.data(), sizeof(float) * values.size());
    }
    const std::vector<char> all = comm.gatherToRoot(mine);
    if (!out) continue;
    std::vector<float> piece(std::size_t((end - begin) * width), 0.0f);
    for (std::size_t at = 0; at + record <= all.size(); at += record) {
      int64_t i = 0;
      std::memcpy(&i, all.data() + at, sizeof i);
      std::memcpy(&piece[std::size_t((i - begin) * width)], all.data() + at + sizeof i,
                  sizeof(float) * std::size_t(width));
    }
    out->reals(piece.data(), piece.size());
  }
}

// The elements of one family this rank holds, ascending by model index; for the solid family
// also which are 10-node tetrahedra (a domain::Tet10Block's, else a domain::SolidBlock's).
struct Held {
  std::vector<int64_t> index;
  std::vector<std::pair<const domain::BlockBase*, std::size_t>> at;
  std::vector<uint8_t> tet10;
};
template <class Block>
Held heldElements(const std::vector<Block>& blocks, int64_t offset) {
  std::vector<std::pair<int64_t, std::pair<const domain::BlockBase*, std::size_t>>> all;
  for (const auto& b : blocks)
    for (std::size_t k = 0; k < b.size(); ++k) all.push_back({offset + b.elem[k], {&b, k}});
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  Held h;
  for (const auto& [i, where] : all) {
    h.index.push_back(i);
    h.at.push_back(where);
  }
  return h;
}

// Deletion flag of element i of `held`, whose blocks are of type Block: 1 in the model, 0 eroded.
template <class Block>
float aliveFlag(const Held& held, std::size_t i) {
  const auto& [blk, k] = held.at[i];
  return static_cast<const Block&>(*blk).active[k] != 0 ? 1.0f : 0.0f;
}

// The solid family: hexahedra, pentahedra and linear tetrahedra, and the 10-node tetrahedra,
// which the geometry section draws as their corner tetrahedra (the model's N1 N2 N3 N4 N4 N4 N4
// N4, as the VTU does) with the mean stress of their points.
Held heldSolids(const domain::Subdomain& sd) {
  Held linear = heldElements(sd.solid_blocks, 0);
  const Held quadratic = heldElements(sd.tet10_blocks, 0);
  if (quadratic.index.empty()) {
    linear.tet10.assign(linear.index.size(), 0);
    return linear;
  }
  Held h;
  std::size_t a = 0, b = 0;
  while (a < linear.index.size() || b < quadratic.index.size()) {
    const bool take_b = a == linear.index.size() ||
                        (b < quadratic.index.size() && quadratic.index[b] < linear.index[a]);
    const Held& from = take_b ? quadratic : linear;
    std::size_t& i = take_b ? b : a;
    h.index.push_back(from.index[i]);
    h.at.push_back(from.at[i]);
    h.tet10.push_back(take_b ? 1 : 0);
    ++i;
  }
  return h;
}

// The held solid-family elements split into the solid and thick-shell sections, each indexed
// by its place in its section (layout.solid_place).
std::pair<Held, Held> splitThickShells(const Held& all, const D3plotLayout& layout) {
  std::pair<Held, Held> out;
  for (std::size_t i = 0; i < all.index.size(); ++i) {
    const auto e = std::size_t(all.index[i]);
    Held& to = layout.solid_is_tshell[e] ? out.second : out.first;
    to.index.push_back(layout.solid_place[e]);
    to.at.push_back(all.at[i]);
    to.tet10.push_back(all.tet10[i]);
  }
  return out;
}

// A solid's record: stress xx, yy, zz, xy, yz, zx in global axes, effective plastic strain.
template <class Block>
void solidRecord(const Block& b, std::size_t k, float* r) {
  for (int c = 0; c < 6; ++c) r[c] = static_cast<float>(b.sigAt(c, k));
  r[6] = b.eps_p.empty() ? 0.0f : static_cast<float>(b.eps_p[k]);
}

}  // namespace

D3plotWriter::D3plotWriter(fs::path dir, const model::Model& model, const comm::Communicator& comm)
    : dir_(std::move(dir)),
      model_(model),
      comm_(comm),
      layout_(d3plotLayout(model)),
      max_words_(model.controls.d3plot_file_words) {
  // Ids must fit the 4-byte words: say so before the run rather than at the first state.
  for (int64_t id : model.nodes.id) word(id, "node id");
  for (const auto* ids : {&model.solids.id, &model.shells.id, &model.beams.id, &model.discretes.id})
    for (int64_t id : *ids) word(id, "element id");
  for (const auto& p : model.parts) word(p.id, "part id");
  word(layout_.stateWords(), "state size (words)");
}

void D3plotWriter::removeMembersAfter(int index) const {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir_, ec)) {
    const int k = d3plotIndex(e.path().filename().string());
    if (k > index) fs::remove(e.path(), ec);
  }
}

void D3plotWriter::writeRoot(WordFile& out) const {
  writeControlWords(out, model_, layout_);
  writeGeometry(out, model_, layout_);
  writeUserIds(out, model_, layout_);
  writeTitles(out, model_, layout_);
  out.finish();
}

bool D3plotWriter::beginFamily() {
  member_ = 0;
  member_words_ = 0;
  states_ = 0;
  if (comm_.isRoot()) removeMembersAfter(0);
  return comm_.isRoot();
}

void D3plotWriter::start() {
  if (!beginFamily()) return;
  WordFile out(dir_ / d3plotName(0), 0);
  writeRoot(out);
  root_words_ = out.position();
}

void D3plotWriter::prepareRestart() {
  if (!comm_.isRoot()) return;
  WordFile out(pending_root_);
  writeRoot(out);
}

void D3plotWriter::startFromPrepared() {
  if (!beginFamily()) return;
  std::ofstream out(dir_ / d3plotName(0), std::ios::binary | std::ios::trunc);
  out.write(pending_root_.data(), std::streamsize(pending_root_.size()));
  if (!out) throw std::runtime_error("cannot write " + (dir_ / d3plotName(0)).string());
  root_words_ = int64_t(pending_root_.size() / 4);
  std::vector<char>().swap(pending_root_);
}

void D3plotWriter::writeState(const solver::Solver& s) {
  const solver::Energies e = s.energies();                   // collective
  const std::vector<solver::PartSums> parts = s.partSums();  // collective
  std::optional<WordFile> out;
  if (comm_.isRoot()) {
    // A new member when this state would take the current one past the size limit (a
    // member holds at least one state).
    auto padded = [](int64_t w) { return (w + kBlockWords - 1) / kBlockWords * kBlockWords; };
    if (member_ == 0 ||
        (member_words_ > 0 && padded(member_words_ + layout_.stateWords() + 1) > max_words_)) {
      ++member_;
      member_words_ = 0;
    }
    out.emplace(dir_ / d3plotName(member_), member_words_);
    out->real(s.time());
    writeGlobals(*out, e, parts);
  }
  WordFile* sink = out ? &*out : nullptr;
  writeNodes(sink, s);
  writeElements(sink, s);
  if (out) {
    member_words_ = out->position();
    out->finish();
  }
  ++states_;
}

// The manual's global variables: kinetic, internal and total energy, the model's velocity,
// then per material number the internal energy, kinetic energy, velocity (x, y, z), mass and
// hourglass energy.
void D3plotWriter::writeGlobals(WordFile& out, const solver::Energies& e,
                                const std::vector<solver::PartSums>& parts) const {
  std::vector<const solver::PartSums*> by_material(std::size_t(layout_.nmmat), nullptr);
  double momentum[3] = {0, 0, 0}, mass = 0.0;
  for (const auto& p : parts) {
    for (int c = 0; c < 3; ++c) momentum[c] += p.momentum[c];
    mass += p.mass;
    for (std::size_t m = 0; m < by_material.size(); ++m)
      if (model_.parts[std::size_t(layout_.part_of_material[m])].id == p.part_id)
        by_material[m] = &p;
  }
  out.real(e.kinetic);
  out.real(e.internal);
  out.real(e.total);
  for (int c = 0; c < 3; ++c) out.real(mass > 0.0 ? momentum[c] / mass : 0.0);
  const solver::PartSums none;
  auto each = [&](auto&& value) {
    for (const auto* p : by_material) value(p ? *p : none);
  };
  each([&](const solver::PartSums& p) { out.real(p.internal); });
  each([&](const solver::PartSums& p) { out.real(p.kinetic); });
  each([&](const solver::PartSums& p) {
    for (int c = 0; c < 3; ++c) out.real(p.mass > 0.0 ? p.momentum[c] / p.mass : 0.0);
  });
  each([&](const solver::PartSums& p) { out.real(p.mass); });
  // The database has no drilling term: the shells' drilling-constraint energy goes with the
  // hourglass energy, as in the ASCII glstat and matsum.
  each([&](const solver::PartSums& p) { out.real(p.hourglass + p.drilling); });
}

// Current coordinates, velocities and accelerations of the nodes, from the ranks owning them.
void D3plotWriter::writeNodes(WordFile* out, const solver::Solver& s) const {
  const auto& sd = s.subdomain();
  std::vector<int64_t> index;
  std::vector<std::size_t> local;
  for (std::size_t n = 0; n < sd.numNodes(); ++n)
    if (sd.node_owned[n]) {
      index.push_back(sd.node_model[n]);
      local.push_back(n);
    }
  for (const domain::NodeVector* field : {&sd.x, &sd.v, &sd.a})
    streamRecords(comm_, out, layout_.numnp, 3, index, [&](std::size_t k, float* r) {
      for (std::size_t c = 0; c < 3; ++c) r[c] = static_cast<float>((*field)[3 * local[k] + c]);
    });
}

// Solid records (stress xx, yy, zz, xy, yz, zx in global axes, effective plastic strain),
// thick-shell records (per layer mid, inner, outer: stress in global axes and effective plastic
// strain), beam records (axial force, shear s, t, moment s, t, torque; discrete elements: the
// axial force), shell records (per layer mid, inner, outer: stress in global axes and
// effective plastic strain; resultants; thickness, two element variables, internal energy),
// deletion flags (solids, thick shells, shells, beams: 1 in the model, 0 eroded).
void D3plotWriter::writeElements(WordFile* out, const solver::Solver& s) const {
  const auto& sd = s.subdomain();
  const std::pair<Held, Held> split = splitThickShells(heldSolids(sd), layout_);
  const Held& solids = split.first;
  const Held& thick = split.second;
  const Held shells = heldElements(sd.shell_blocks, 0);
  Held beams = heldElements(sd.beam_blocks, 0);
  const int64_t num_beams = layout_.num_beams;
  const Held discretes = heldElements(sd.discrete_blocks, num_beams);
  beams.index.insert(beams.index.end(), discretes.index.begin(), discretes.index.end());
  beams.at.insert(beams.at.end(), discretes.at.begin(), discretes.at.end());

  streamRecords(comm_, out, layout_.nel8, D3plotLayout::kNv3d, solids.index,
                [&](std::size_t i, float* r) {
                  const auto& [blk, k] = solids.at[i];
                  if (solids.tet10[i])
                    solidRecord(static_cast<const domain::Tet10Block&>(*blk), k, r);
                  else
                    solidRecord(static_cast<const domain::SolidBlock&>(*blk), k, r);
                });
  streamRecords(comm_, out, layout_.nelt, layout_.nv3dt(), thick.index,
                [&](std::size_t i, float* r) {
                  const auto& [blk, k] = thick.at[i];
                  thickShellRecord(static_cast<const domain::SolidBlock&>(*blk), sd.x, k, r);
                });
  streamRecords(
      comm_, out, layout_.nel2, D3plotLayout::kNv1d, beams.index, [&](std::size_t i, float* r) {
        const auto& [blk, k] = beams.at[i];
        double v[6] = {};
        if (beams.index[i] < num_beams)
          elements::beamSectionResultants(static_cast<const domain::BeamBlock&>(*blk), k, v);
        else if (const auto& d = static_cast<const domain::DiscreteBlock&>(*blk); !d.force.empty())
          v[0] = d.force[k];
        for (int c = 0; c < 6; ++c) r[c] = static_cast<float>(v[c]);
      });
  streamRecords(comm_, out, layout_.nel4, layout_.nv2d(), shells.index,
                [&](std::size_t i, float* r) {
                  const auto& [blk, k] = shells.at[i];
                  shellRecord(static_cast<const domain::ShellBlock&>(*blk), sd.x, k, r);
                });
  streamRecords(comm_, out, layout_.nel8, 1, solids.index, [&](std::size_t i, float* r) {
    r[0] = solids.tet10[i] ? aliveFlag<domain::Tet10Block>(solids, i)
                           : aliveFlag<domain::SolidBlock>(solids, i);
  });
  streamRecords(comm_, out, layout_.nelt, 1, thick.index,
                [&](std::size_t i, float* r) { r[0] = aliveFlag<domain::SolidBlock>(thick, i); });
  streamRecords(comm_, out, layout_.nel4, 1, shells.index,
                [&](std::size_t i, float* r) { r[0] = aliveFlag<domain::ShellBlock>(shells, i); });
  // Discrete elements (after the beams) do not erode.
  streamRecords(comm_, out, layout_.nel2, 1, beams.index, [&](std::size_t i, float* r) {
    r[0] = beams.index[i] < num_beams ? aliveFlag<domain::BeamBlock>(beams, i) : 1.0f;
  });
}

namespace {
// The layers mid, inner (bottom), outer (top) of a shell or thick shell (the manual's MAXINT
// 3): stress and effective plastic strain as IOSHL(1), IOSHL(2) ask; the next word.
float* layerRecords(const D3plotLayout& layout, const double (&layers)[3][6],
                    const double (&eps)[3], float* r) {
  for (int layer : {1, 0, 2}) {
    if (layout.shell_stress)
      for (int c = 0; c < 6; ++c) *r++ = static_cast<float>(layers[layer][c]);
    if (layout.shell_plastic_strain) *r++ = static_cast<float>(eps[layer]);
  }
  return r;
}
}  // namespace

void D3plotWriter::thickShellRecord(const domain::SolidBlock& b, const domain::NodeVector& x,
                                    std::size_t k, float* r) const {
  double layers[3][6], eps[3];
  elements::thickShellLayerStress(b, x, k, layers, eps);
  layerRecords(layout_, layers, eps, r);
}

void D3plotWriter::shellRecord(const domain::ShellBlock& b, const domain::NodeVector& x,
                               std::size_t k, float* r) const {
  double layers[3][6], eps[3];
  elements::shellSurfaceStress(b, x, k, layers, eps);
  r = layerRecords(layout_, layers, eps, r);
  if (layout_.shell_resultants) {
    double m[8];
    elements::shellResultants(b, k, m);
    for (double v : m) *r++ = static_cast<float>(v);
  }
  if (layout_.shell_energy) {
    // Thickness, the two element-dependent variables (none for these formulations),
    // internal energy of the element.
    const double w[4] = {b.thick[k], 0.0, 0.0, b.e_int[k]};
    for (double v : w) *r++ = static_cast<float>(v);
  }
}

std::vector<char> D3plotWriter::save() const {
  util::ArchiveWriter w;
  w.put(member_);
  w.put(member_words_);
  w.put(root_words_);
  w.put(states_);
  return std::move(w.bytes());
}

void D3plotWriter::load(const std::vector<char>& bytes) {
  util::ArchiveReader r(bytes);
  r.get(member_);
  r.get(member_words_);
  r.get(root_words_);
  r.get(states_);
  if (!r.atEnd()) throw util::InputError("restart dump: the d3plot section is inconsistent");
  if (!comm_.isRoot()) return;
  // The folder must hold this run's family: the d3plot file this model writes, the member at
  // least as long as the states the dump counts.
  auto foreign = [&](int index) {
    return util::InputError(fmt::format(
        "'{}' is missing or not the file the restart dump was written with: the results folder "
        "does not hold the run the dump was written by",
        (dir_ / d3plotName(index)).string()));
  };
  std::ifstream in(dir_ / d3plotName(0), std::ios::binary);
  const std::vector<char> root((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
  if (root != pending_root_ || int64_t(root.size()) != 4 * root_words_) throw foreign(0);
  std::error_code ec;
  const auto size = member_ > 0 ? fs::file_size(dir_ / d3plotName(member_), ec) : 0;
  if (ec || size < std::uintmax_t(4 * member_words_)) throw foreign(member_);
}

void D3plotWriter::resume() {
  std::vector<char>().swap(pending_root_);
  if (!comm_.isRoot()) return;
  removeMembersAfter(member_);
  if (member_ == 0) return;
  WordFile out(dir_ / d3plotName(member_), member_words_);
  out.finish();
}
}  // namespace crumple::output
