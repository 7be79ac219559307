#include "output/results.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string_view>

#include "elements/shell.hpp"
#include "output/jntforc.hpp"
#include "util/archive.hpp"
#include "util/error.hpp"
#include "util/timer.hpp"

namespace crumple::output {

namespace {

// Without a *DATABASE_ request a history is still sampled, this many times per run.
constexpr double kDefaultSamples = 200.0;
constexpr double kDefaultPlotStates = 20.0;

double intervalOr(double requested, double end_time, double samples) {
  if (requested > 0.0) return requested;
  return end_time > 0.0 ? end_time / samples : 0.0;
}

long peakMemoryBytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss * 1024L;  // Linux reports kilobytes
}

}  // namespace

namespace {
const std::vector<std::string> kGlstatColumns = {
    "time",          "cycle", "dt",           "kinetic",   "internal",   "hourglass", "contact",
    "external_work", "total", "energy_ratio", "rigidwall", "added_mass", "damping",   "drilling"};
const std::vector<std::string> kMatsumColumns = {"time",       "part",       "kinetic",
                                                 "internal",   "hourglass",  "x_momentum",
                                                 "y_momentum", "z_momentum", "drilling"};
const std::vector<std::string> kNodoutColumns = {"time", "node", "x",  "y",  "z",  "dx", "dy",
                                                 "dz",   "vx",   "vy", "vz", "ax", "ay", "az"};
const std::vector<std::string> kRwforcColumns = {"time", "wall", "fn", "fx", "fy", "fz"};
// side 1 = SURFA (slave), 2 = SURFB (master); energy is the interface's contact energy.
const std::vector<std::string> kRcforcColumns = {"time", "contact", "side",   "fx",
                                                 "fy",   "fz",      "energy", "pairs"};
// Section forces (sections.hpp): force and moment about the centroid (cx, cy, cz), cut area.
const std::vector<std::string> kSecforcColumns = {"time", "section", "fx", "fy", "fz", "mx",
                                                  "my",   "mz",      "cx", "cy", "cz", "area"};
// The glstat sample the energy audit takes: the global terms and each interface's energy.
EnergySample energySample(const solver::Solver& s, const solver::Energies& e) {
  EnergySample out{s.time(), s.cycle(), e, {}, {}};
  if (const auto* c = s.contact())
    for (const auto& f : c->interfaceForces()) {
      out.contact_id.push_back(f.id);
      out.contact_energy.push_back(f.energy);
    }
  return out;
}

}  // namespace

ResultsWriter::ResultsWriter(std::filesystem::path dir, const model::Model& model,
                             const solver::Solver& s, const comm::Communicator& comm, bool restart)
    : dir_(std::move(dir)), model_(model), comm_(comm), pvd_(dir_ / "results.pvd") {
  const auto& ctl = model.controls;
  const double end = s.endTime();
  requested_ = {ctl.glstat_dt, ctl.matsum_dt, ctl.nodout_dt, ctl.rwforc_dt,
                ctl.rcforc_dt, ctl.d3plot_dt, ctl.sleout_dt, ctl.secforc_dt};
  glstat_.interval = intervalOr(ctl.glstat_dt, end, kDefaultSamples);
  matsum_.interval = intervalOr(ctl.matsum_dt, end, kDefaultSamples);
  plot_.interval = intervalOr(ctl.d3plot_dt, end, kDefaultPlotStates);
  const auto& sd = s.subdomain();
  history_count_ = model.history_nodes.size();
  for (std::size_t k = 0; k < model.history_nodes.size(); ++k) {
    const int32_t local = sd.localNode(model.history_nodes[k]);
    if (local != model::kNone && sd.node_owned[static_cast<std::size_t>(local)])
      history_local_.emplace_back(int32_t(k), local);
  }
  if (history_count_ > 0) nodout_.interval = intervalOr(ctl.nodout_dt, end, kDefaultSamples);
  if (!model.rigid_walls.empty())
    rwforc_.interval = intervalOr(ctl.rwforc_dt, end, kDefaultSamples);
  if (!model.contacts.empty()) {
    rcforc_.interval = intervalOr(ctl.rcforc_dt, end, kDefaultSamples);
    if (ctl.ascii.sleout) sleout_.interval = intervalOr(ctl.sleout_dt, end, kDefaultSamples);
  }
  if (!model.rigid.joints.empty())
    jntforc_.interval = intervalOr(ctl.jntforc_dt, end, kDefaultSamples);
  if (!model.cross_sections.empty()) {
    secforc_.interval = intervalOr(ctl.secforc_dt, end, kDefaultSamples);
    sections_.emplace(model, sd);
  }
  reactions_.emplace(model, s, comm);
  elout_.emplace(model, s, comm);
  // On restart the files are opened by loadState, which knows where the dump left them.
  if (comm.isRoot() && !restart) openStreams();
  if (comm.isRoot()) std::filesystem::create_directories(dir_ / kStatesFolder);
  // The d3plot family beside the VTU states, as LS-DYNA writes it when the deck asks; a
  // restarted run continues the family from loadState.
  if (ctl.d3plot) {
    d3plot_.emplace(dir_, model, comm);
    if (restart)
      d3plot_->prepareRestart();
    else
      d3plot_->start();
  }
  comm.barrier();
}

std::vector<ResultsWriter::Stream> ResultsWriter::streams() {
  const auto& ascii = model_.controls.ascii;
  const bool nodes = history_count_ > 0, walls = !model_.rigid_walls.empty();
  const bool contacts = !model_.contacts.empty(), sections = !model_.cross_sections.empty();
  const bool joints = !model_.rigid.joints.empty();
  std::vector<Stream> out = {{"glstat.csv", &glstat_csv_, &kGlstatColumns, true},
                             {"matsum.csv", &matsum_csv_, &kMatsumColumns, true},
                             {"nodout.csv", &nodout_csv_, &kNodoutColumns, nodes},
                             {"rwforc.csv", &rwforc_csv_, &kRwforcColumns, walls},
                             {"rcforc.csv", &rcforc_csv_, &kRcforcColumns, contacts},
                             {"secforc.csv", &secforc_csv_, &kSecforcColumns, sections},
                             {"glstat", &glstat_txt_, nullptr, ascii.glstat},
                             {"matsum", &matsum_txt_, nullptr, ascii.matsum},
                             {"nodout", &nodout_txt_, nullptr, ascii.nodout && nodes},
                             {"rwforc", &rwforc_txt_, nullptr, ascii.rwforc && walls},
                             {"rcforc", &rcforc_txt_, nullptr, ascii.rcforc && contacts},
                             {"sleout", &sleout_txt_, nullptr, ascii.sleout && contacts},
                             {"secforc", &secforc_txt_, nullptr, ascii.secforc && sections},
                             {"jntforc.csv", &jntforc_csv_, &jntforcColumns(), joints},
                             {"jntforc", &jntforc_txt_, nullptr, ascii.jntforc && joints}};
  for (const auto& f : reactions_->files()) out.push_back({f.name, f.file, f.columns, f.wanted});
  out.push_back({"elout.csv", &elout_->csv(), &ElementHistories::columns(), elout_->wanted()});
  out.push_back({"elout", &elout_->text(), nullptr, elout_->wanted()});
  return out;
}

void ResultsWriter::openStreams() {
  const std::string& title = model_.title;
  std::vector<ascii::LegendEntry> parts, nodes, contacts, sections;
  for (const auto& p : model_.parts) parts.push_back({p.id, p.title});
  for (int32_t n : model_.history_nodes)
    nodes.push_back({model_.nodes.id[static_cast<std::size_t>(n)], {}});
  for (const auto& c : model_.contacts) contacts.push_back({c.id, c.title});
  for (const auto& c : model_.cross_sections) sections.push_back({c.id, c.title});
  const std::map<std::string_view, std::string> headers = {
      {"glstat", ascii::banner(title)},
      {"matsum", ascii::matsumHeader(title, parts)},
      {"nodout", ascii::nodoutHeader(title, nodes)},
      {"rwforc", ascii::rwforcHeader(title)},
      {"rcforc", ascii::entityHeader(title, contacts)},
      {"sleout", ascii::entityHeader(title, contacts)},
      {"secforc", ascii::entityHeader(title, sections)},
      {"jntforc", ascii::banner(title)},
      {"elout", elout_->header()}};
  for (const Stream& st : streams()) {
    if (!st.wanted) continue;
    if (st.columns)
      *static_cast<CsvWriter*>(st.file) = CsvWriter(dir_ / st.name, *st.columns);
    else
      *st.file = HistoryFile(dir_ / st.name, headers.count(st.name) ? headers.at(st.name)
                                                                    : reactions_->header(st.name));
  }
}

std::vector<char> ResultsWriter::saveState() const {
  util::ArchiveWriter w;
  const Schedule* schedules[] = {&glstat_, &matsum_, &nodout_, &rwforc_,
                                 &rcforc_, &plot_,   &sleout_, &secforc_};
  for (std::size_t k = 0; k < requested_.size(); ++k) {
    w.put(requested_[k]);
    w.put(schedules[k]->interval);
    w.put(schedules[k]->next);
  }
  w.put(plot_count_);
  w.put(last_plot_time_);
  audit_.save(w);
  std::vector<double> times;
  std::vector<std::string> names;
  for (const auto& [t, name] : pvd_.states()) {
    times.push_back(t);
    names.push_back(name);
  }
  w.put(times);
  w.put(names);
  // streams() hands out the files for writing; here they are only read.
  for (const Stream& st : const_cast<ResultsWriter*>(this)->streams()) {
    w.put<uint8_t>(st.file->isOpen() ? 1 : 0);
    w.put(st.file->position());
  }
  w.put(d3plot_ ? d3plot_->save() : std::vector<char>());  // empty: no d3plot
  reactions_->saveState(w);
  elout_->saveState(w);
  return std::move(w.bytes());
}

void ResultsWriter::loadState(const std::vector<char>& bytes, double time) {
  util::ArchiveReader r(bytes);
  Schedule* schedules[] = {&glstat_, &matsum_, &nodout_, &rwforc_,
                           &rcforc_, &plot_,   &sleout_, &secforc_};
  for (std::size_t k = 0; k < requested_.size(); ++k) {
    double requested = 0.0;
    Schedule dumped;
    r.get(requested);
    r.get(dumped.interval);
    r.get(dumped.next);
    // A history without output (no history nodes, no walls) keeps its zero interval.
    if (schedules[k]->interval == 0.0) continue;
    if (requested == requested_[k]) {
      *schedules[k] = dumped;
    } else {
      // The restart deck changed the interval: the next sample is one new interval on.
      schedules[k]->next = time + schedules[k]->interval;
    }
  }
  r.get(plot_count_);
  r.get(last_plot_time_);
  audit_.load(r);
  std::vector<double> times;
  std::vector<std::string> names;
  r.get(times);
  r.get(names);
  const std::vector<Stream> files = streams();
  std::vector<std::pair<uint8_t, HistoryFile::Position>> dumped(files.size());
  for (auto& [open, pos] : dumped) {
    r.get(open);
    r.get(pos);
  }
  std::vector<char> d3plot;
  r.get(d3plot);
  reactions_->loadState(r, time);
  elout_->loadState(r, time);
  if (!r.atEnd() || times.size() != names.size())
    throw util::InputError("restart dump: the output section is inconsistent");
  // A dump of a run without d3plot, restarted with *DATABASE_BINARY_D3PLOT: a new family.
  const bool d3plot_continues = d3plot_ && !d3plot.empty();
  if (d3plot_continues) d3plot_->load(d3plot);
  if (d3plot_ && !d3plot_continues) d3plot_->startFromPrepared();
  if (!comm_.isRoot()) return;
  resumeStreams(files, dumped);
  if (d3plot_continues) d3plot_->resume();
  std::vector<std::pair<double, std::string>> states;
  for (std::size_t k = 0; k < times.size(); ++k) states.emplace_back(times[k], names[k]);
  pvd_.restore(std::move(states));
  // Plot states numbered from plot_count_ on were written after the dump (the continuation
  // that was interrupted, or its final state): the restarted run writes its own.
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir_ / kStatesFolder, ec)) {
    const std::string name = e.path().filename().string();
    int state = -1;
    if (std::sscanf(name.c_str(), "state_%d", &state) == 1 && state >= plot_count_)
      std::filesystem::remove(e.path(), ec);
  }
}

void ResultsWriter::resumeStreams(
    const std::vector<Stream>& files,
    const std::vector<std::pair<uint8_t, HistoryFile::Position>>& dumped) {
  // Every file is checked before any is cut back: a folder of another run stays untouched.
  for (std::size_t k = 0; k < files.size(); ++k) {
    const bool wanted = files[k].wanted;
    if ((dumped[k].first != 0) != wanted)
      throw util::InputError(
          std::string("the restart dump does not belong to this deck: it wrote ") + files[k].name +
          (wanted ? " not" : "") + ", this deck would" + (wanted ? "" : " not"));
    if (wanted) HistoryFile::checkResume(dir_ / files[k].name, dumped[k].second);
  }
  for (std::size_t k = 0; k < files.size(); ++k) {
    if (!files[k].wanted) continue;
    const auto path = dir_ / files[k].name;
    if (files[k].columns)
      *static_cast<CsvWriter*>(files[k].file) =
          CsvWriter(path, *files[k].columns, dumped[k].second);
    else
      *files[k].file = HistoryFile(path, dumped[k].second);
  }
}

void ResultsWriter::write(const solver::Solver& s, bool last) {
  util::ScopedTimer timer(seconds_);
  const double t = s.time();
  if (glstat_.due(t, last)) {
    writeGlstat(s);
    glstat_.advance(t);
  }
  if (matsum_.due(t, last)) {
    writeMatsum(s);
    matsum_.advance(t);
  }
  if (nodout_.due(t, last)) {
    writeNodout(s);
    nodout_.advance(t);
  }
  if (rwforc_.due(t, last)) {
    writeRwforc(s);
    rwforc_.advance(t);
  }
  const bool rcforc = s.contact() && rcforc_.due(t, last);
  const bool sleout = s.contact() && sleout_.due(t, last);
  if (rcforc || sleout) writeContact(s, rcforc, sleout);
  if (rcforc) rcforc_.advance(t);
  if (sleout) sleout_.advance(t);
  if (sections_ && secforc_.due(t, last)) {
    writeSecforc(s);
    secforc_.advance(t);
  }
  if (jntforc_.interval > 0.0 && jntforc_.due(t, last)) {
    writeJntforc(s);
    jntforc_.advance(t);
  }
  reactions_->write(s, last);
  elout_->write(s, last);
  if ((s.cycle() == 0 || plot_.due(t, last)) && t != last_plot_time_) {
    writePlotState(s);
    plot_.advance(t);
    last_plot_time_ = t;
  }
}

ascii::GlstatSample ResultsWriter::glstatSample(const solver::Solver& s,
                                                const solver::Energies& e) const {
  const auto& sd = s.subdomain();
  ascii::GlstatSample g;
  g.cycle = s.cycle() + 1;  // LS-DYNA counts its cycles from 1
  const int64_t elem = s.stepElement();
  if (elem >= 0) {
    static constexpr const char* kFamilies[] = {"solid", "shell", "beam", "spring"};
    g.dt_family = kFamilies[static_cast<std::size_t>(sd.familyOf(elem))];
    g.dt_element = comm_.maxAll(sd.elementId(elem));  // the rank holding it knows its ids
    g.dt_part = comm_.maxAll(sd.elementPart(elem));
  }
  const solver::ErodedSums eroded = s.eroded();  // collective
  const auto parts = s.partSums();               // collective
  double mass = 0.0;
  for (const auto& p : parts) {
    mass += p.mass;
    for (std::size_t c = 0; c < 3; ++c) g.velocity[c] += p.momentum[c];
  }
  if (mass > 0.0)
    for (double& v : g.velocity) v /= mass;
  g.time = s.time();
  g.dt = s.dt();
  g.kinetic = e.kinetic;
  g.internal = e.internal;
  // LS-DYNA's glstat has no drilling term: the shells' drilling-constraint energy is shown
  // with the hourglass energy there (stabilisation energy), so that its total adds up.
  g.hourglass = e.hourglass + e.drilling;
  g.contact = e.contact;
  g.external_work = e.external_work;
  g.eroded_internal = eroded.internal;
  g.eroded_hourglass = eroded.hourglass + eroded.drilling;
  g.total = e.total;
  g.ratio = e.ratio;
  // The eroded energies stay in Crumple's sums (summary.json "eroded_internal_energy").
  g.ratio_without_eroded =
      e.total != 0.0 ? e.ratio * (e.total - eroded.internal - g.eroded_hourglass) / e.total
                     : e.ratio;
  g.stonewall = !model_.rigid_walls.empty();
  g.stonewall_energy = e.rigidwall;
  g.damping = e.damping;
  g.mass_scaled = model_.controls.dt2ms != 0.0;
  g.added_mass = s.addedMass();
  g.percent_increase = s.totalMass() > 0.0 ? 100.0 * s.addedMass() / s.totalMass() : 0.0;
  return g;
}

void ResultsWriter::writeGlstat(const solver::Solver& s) {
  const bool root = comm_.isRoot();
  const auto e = s.energies();
  const double t = s.time();
  if (root)
    glstat_csv_.row({t, double(s.cycle()), s.dt(), e.kinetic, e.internal, e.hourglass, e.contact,
                     e.external_work, e.total, e.ratio, e.rigidwall, s.addedMass(), e.damping,
                     e.drilling});
  if (root) glstat_csv_.flush();
  if (model_.controls.ascii.glstat) {
    const ascii::GlstatSample g = glstatSample(s, e);  // collective
    if (root) {
      glstat_txt_.write(ascii::glstatBlock(g));
      glstat_txt_.flush();
    }
  }
  if (root) notes_ += audit_.observe(energySample(s, e));
}

void ResultsWriter::writeMatsum(const solver::Solver& s) {
  const auto sums = s.partSums();  // collective
  if (!comm_.isRoot()) return;
  const double t = s.time();
  std::vector<ascii::MatsumPart> parts;
  for (const auto& p : sums) {
    matsum_csv_.row({t, double(p.part_id), p.kinetic, p.internal, p.hourglass, p.momentum[0],
                     p.momentum[1], p.momentum[2], p.drilling});
    ascii::MatsumPart m;
    m.id = p.part_id;
    m.internal = p.internal;
    m.kinetic = p.kinetic;
    m.hourglass = p.hourglass + p.drilling;  // as glstat's: LS-DYNA's files know no drilling
    m.momentum = {p.momentum[0], p.momentum[1], p.momentum[2]};
    parts.push_back(m);
  }
  matsum_csv_.flush();
  if (matsum_txt_.isOpen()) {
    matsum_txt_.write(ascii::matsumBlock(t, parts));
    matsum_txt_.flush();
  }
}

void ResultsWriter::writeNodout(const solver::Solver& s) {
  // Rows of the history nodes this rank owns, gathered and written in deck order: the deck
  // order, the 14 nodout.csv columns and the angular velocity.
  const auto& sd = s.subdomain();
  constexpr std::size_t kRow = 18;
  std::vector<double> rows;
  for (const auto& [order, n] : history_local_) {
    const std::size_t i = 3 * static_cast<std::size_t>(n);
    double row[kRow] = {double(order), s.time(), double(sd.node_id[static_cast<std::size_t>(n)])};
    for (std::size_t c = 0; c < 3; ++c) {
      row[3 + c] = sd.x[i + c];
      row[6 + c] = sd.x[i + c] - sd.x0[i + c];
      row[9 + c] = sd.v[i + c];
      row[12 + c] = sd.a[i + c];
      row[15 + c] = sd.rotations ? sd.w[i + c] : 0.0;
    }
    rows.insert(rows.end(), row, row + kRow);
  }
  const auto all = comm_.allGather(rows);
  if (!comm_.isRoot()) return;
  std::vector<std::size_t> idx(all.size() / kRow);
  for (std::size_t k = 0; k < idx.size(); ++k) idx[k] = k;
  std::sort(idx.begin(), idx.end(),
            [&](std::size_t a, std::size_t b) { return all[kRow * a] < all[kRow * b]; });
  std::vector<ascii::NodoutRow> text;
  for (std::size_t k : idx) {
    const double* r = all.data() + kRow * k;
    nodout_csv_.row(std::vector<double>(r + 1, r + 15));
    ascii::NodoutRow n;
    n.id = int64_t(r[2]);
    for (std::size_t c = 0; c < 3; ++c) {
      n.coor[c] = r[3 + c];
      n.disp[c] = r[6 + c];
      n.vel[c] = r[9 + c];
      n.acc[c] = r[12 + c];
      n.rot_vel[c] = r[15 + c];
    }
    text.push_back(n);
  }
  nodout_csv_.flush();
  if (nodout_txt_.isOpen()) {
    nodout_txt_.write(ascii::nodoutBlock(s.cycle() + 1, s.time(), text, sd.rotations));
    nodout_txt_.flush();
  }
}

void ResultsWriter::writeRwforc(const solver::Solver& s) {
  if (!comm_.isRoot()) return;
  std::vector<ascii::WallRecord> walls;
  for (const auto& w : s.boundary().walls()) {
    rwforc_csv_.row(
        {s.time(), double(w.def->id), w.normal_force, w.force[0], w.force[1], w.force[2]});
    walls.push_back({w.def->id, w.normal_force, {w.force[0], w.force[1], w.force[2]}});
  }
  rwforc_csv_.flush();
  if (rwforc_txt_.isOpen()) {
    rwforc_txt_.write(ascii::rwforcBlock(s.time(), walls));
    rwforc_txt_.flush();
  }
}

void ResultsWriter::writeContact(const solver::Solver& s, bool rcforc, bool sleout) {
  const auto forces = s.contact()->interfaceForces();  // collective
  if (!comm_.isRoot()) return;
  const double t = s.time();
  std::vector<ascii::ContactRecord> records;
  for (const auto& f : forces) {
    if (rcforc) {
      rcforc_csv_.row(
          {t, double(f.id), 1.0, f.side_a[0], f.side_a[1], f.side_a[2], f.energy, double(f.pairs)});
      rcforc_csv_.row(
          {t, double(f.id), 2.0, f.side_b[0], f.side_b[1], f.side_b[2], f.energy, double(f.pairs)});
    }
    ascii::ContactRecord c;
    c.id = f.id;
    c.slave = f.side_a;
    c.master = f.side_b;
    // Crumple keeps one energy per interface: written as the slave side's (docs/theory.md).
    c.slave_energy = f.energy;
    for (const auto& def : model_.contacts)
      if (def.id == f.id) c.single_surface = def.kind == model::ContactKind::SingleSurface;
    records.push_back(c);
  }
  if (rcforc) rcforc_csv_.flush();
  if (rcforc && rcforc_txt_.isOpen()) {
    rcforc_txt_.write(ascii::rcforcBlock(t, records));
    rcforc_txt_.flush();
  }
  if (sleout && sleout_txt_.isOpen()) {
    sleout_txt_.write(ascii::sleoutBlock(s.cycle() + 1, t, records));
    sleout_txt_.flush();
  }
}

void ResultsWriter::writeSecforc(const solver::Solver& s) {
  const auto sections = sections_->compute(s.subdomain(), comm_, s.forcesComputed());
  if (!comm_.isRoot()) return;
  for (const auto& c : sections)
    secforc_csv_.row({s.time(), double(c.id), c.force[0], c.force[1], c.force[2], c.moment[0],
                      c.moment[1], c.moment[2], c.centroid[0], c.centroid[1], c.centroid[2],
                      c.area});
  secforc_csv_.flush();
  if (secforc_txt_.isOpen()) {
    secforc_txt_.write(ascii::secforcBlock(s.time(), sections));
    secforc_txt_.flush();
  }
}

void ResultsWriter::writeJntforc(const solver::Solver& s) {
  if (!comm_.isRoot() || !s.rigidBodies()) return;  // the same on every rank
  const auto joints = s.rigidBodies()->joints();
  for (const auto& row : jntforcRows(s.time(), joints)) jntforc_csv_.row(row);
  jntforc_csv_.flush();
  if (jntforc_txt_.isOpen()) {
    jntforc_txt_.write(ascii::jntforcBlock(s.time(), joints));
    jntforc_txt_.flush();
  }
}

void ResultsWriter::writePlotState(const solver::Solver& s) {
  if (d3plot_) d3plot_->writeState(s);  // collective
  const auto& sd = s.subdomain();
  const std::size_t nn = sd.numNodes();
  std::vector<double> disp(3 * nn);
  for (std::size_t i = 0; i < 3 * nn; ++i) disp[i] = sd.x[i] - sd.x0[i];

  // Cells: active elements in global element order across blocks and families. Shells give
  // their mid-surface stress as "stress" and the outer surfaces as stress_top/_bottom
  // (solids give the same tensor in all three), in global axes.
  struct Cell {
    int64_t elem;  // global element index
    model::Family family;
    const domain::BlockBase* blk;
    std::size_t k;
    bool tet10 = false;  // a domain::Tet10Block's (else the family's block type)
  };
  std::vector<Cell> cells;
  sd.forEachBlockList([&](const auto& blocks, model::Family family) {
    for (const auto& blk : blocks)
      for (std::size_t k = 0; k < blk.size(); ++k) {
        // Eroded elements are not drawn (discrete elements do not erode).
        if constexpr (requires { blk.active; })
          if (!blk.active[k]) continue;
        cells.push_back({sd.globalElement(family, blk.elem[k]), family, &blk, k,
                         std::is_same_v<std::decay_t<decltype(blk)>, domain::Tet10Block>});
      }
  });
  std::sort(cells.begin(), cells.end(),
            [](const Cell& a, const Cell& b) { return a.elem < b.elem; });
  const std::size_t nc = cells.size();
  // Arrays hold at least one cell: FieldView tells Float64 from Int64 by the pointer that is
  // set, and an empty vector's data() may be null (every element eroded, or none on this rank).
  const std::size_t na = std::max<std::size_t>(nc, 1);
  std::vector<int32_t> conn(8 * na, 0);
  std::vector<uint8_t> sizes(na);
  std::vector<double> stress(6 * na, 0.0), stress_top(6 * na, 0.0), stress_bottom(6 * na, 0.0);
  std::vector<double> eps(na, 0.0), eps_top(na, 0.0), eps_bottom(na, 0.0), von_mises(na);
  std::vector<double> thickness(na, 0.0), axial_force(na, 0.0);
  std::vector<int64_t> part(na), rank(na, sd.rank), elem_id(na);
  for (std::size_t i = 0; i < nc; ++i) {
    const auto& c = cells[i];
    double layers[3][6] = {};
    double eps_layers[3] = {};
    switch (c.family) {
      case model::Family::Solid: {
        if (c.tet10) {
          // Drawn as its corner tetrahedron (N1 N2 N3 N4 N4 N4 N4 N4) with the points' mean
          // stress.
          const auto& t = static_cast<const domain::Tet10Block&>(*c.blk);
          sizes[i] = 8;
          for (int a = 0; a < 8; ++a) conn[8 * i + a] = t.conn[c.k][std::size_t(std::min(a, 3))];
          for (int l = 0; l < 3; ++l) {
            for (int k = 0; k < 6; ++k) layers[l][k] = t.sigAt(k, c.k);
            eps_layers[l] = t.eps_p.empty() ? 0.0 : t.eps_p[c.k];
          }
          break;
        }
        const auto& b = static_cast<const domain::SolidBlock&>(*c.blk);
        sizes[i] = 8;
        for (int a = 0; a < 8; ++a) conn[8 * i + a] = b.conn[c.k][a];
        for (int l = 0; l < 3; ++l) {
          for (int k = 0; k < 6; ++k) layers[l][k] = b.sigAt(k, c.k);
          eps_layers[l] = b.eps_p.empty() ? 0.0 : b.eps_p[c.k];
        }
        break;
      }
      case model::Family::Shell: {
        const auto& b = static_cast<const domain::ShellBlock&>(*c.blk);
        sizes[i] = 4;
        for (int a = 0; a < 4; ++a) conn[8 * i + a] = b.conn[c.k][a];
        elements::shellSurfaceStress(b, sd.x, c.k, layers, eps_layers);
        thickness[i] = b.thick[c.k];
        break;
      }
      case model::Family::Beam: {
        const auto& b = static_cast<const domain::BeamBlock&>(*c.blk);
        sizes[i] = 2;
        for (int a = 0; a < 2; ++a) conn[8 * i + a] = b.conn[c.k][a];
        break;
      }
      case model::Family::Discrete: {
        const auto& b = static_cast<const domain::DiscreteBlock&>(*c.blk);
        sizes[i] = 2;
        for (int a = 0; a < 2; ++a) conn[8 * i + a] = b.conn[c.k][a];
        axial_force[i] = b.force.empty() ? 0.0 : b.force[c.k];
        break;
      }
    }
    for (int k = 0; k < 6; ++k) {
      stress_bottom[6 * i + k] = layers[0][k];
      stress[6 * i + k] = layers[1][k];
      stress_top[6 * i + k] = layers[2][k];
    }
    eps_bottom[i] = eps_layers[0];
    eps[i] = eps_layers[1];
    eps_top[i] = eps_layers[2];
    const double* sg = layers[1];
    const double p = (sg[0] + sg[1] + sg[2]) / 3.0;
    const double j2 =
        0.5 * ((sg[0] - p) * (sg[0] - p) + (sg[1] - p) * (sg[1] - p) + (sg[2] - p) * (sg[2] - p)) +
        sg[3] * sg[3] + sg[4] * sg[4] + sg[5] * sg[5];
    von_mises[i] = std::sqrt(3.0 * j2);
    part[i] = c.blk->part_id;
    elem_id[i] = c.blk->elem_id[c.k];
  }
  MeshView mesh{nn, sd.x.data(), nc, conn.data(), sizes.data()};
  std::vector<FieldView> fields = {
      {"node_id", Association::Point, 1, nullptr, sd.node_id.data()},
      {"displacement", Association::Point, 3, disp.data(), nullptr},
      {"velocity", Association::Point, 3, sd.v.data(), nullptr},
      {"acceleration", Association::Point, 3, sd.a.data(), nullptr},
      {"element_id", Association::Cell, 1, nullptr, elem_id.data()},
      {"part", Association::Cell, 1, nullptr, part.data()},
      {"rank", Association::Cell, 1, nullptr, rank.data()},
      {"stress", Association::Cell, 6, stress.data(), nullptr},
      {"von_mises", Association::Cell, 1, von_mises.data(), nullptr},
      {"effective_plastic_strain", Association::Cell, 1, eps.data(), nullptr},
      {"stress_top", Association::Cell, 6, stress_top.data(), nullptr},
      {"stress_bottom", Association::Cell, 6, stress_bottom.data(), nullptr},
      {"effective_plastic_strain_top", Association::Cell, 1, eps_top.data(), nullptr},
      {"effective_plastic_strain_bottom", Association::Cell, 1, eps_bottom.data(), nullptr},
      {"thickness", Association::Cell, 1, thickness.data(), nullptr},
      {"axial_force", Association::Cell, 1, axial_force.data(), nullptr},
  };
  if (sd.rotations)
    fields.push_back({"angular_velocity", Association::Point, 3, sd.w.data(), nullptr});
  const int state = plot_count_++;
  if (!comm_.distributed()) {
    const std::string name = fmt::format("{}/state_{:05d}.vtu", kStatesFolder, state);
    writeVtu(dir_ / name, mesh, fields);
    pvd_.addState(s.time(), name);
    return;
  }
  // One piece per rank and a .pvtu that names them; ParaView shows the rank field as the
  // partition (the seed paper's Figure 2).
  auto piece = [&](int r) { return fmt::format("state_{:05d}_r{:04d}.vtu", state, r); };
  writeVtu(dir_ / kStatesFolder / piece(sd.rank), mesh, fields);
  comm_.barrier();
  if (comm_.isRoot()) {
    std::vector<std::string> pieces;
    for (int r = 0; r < comm_.size(); ++r) pieces.push_back(piece(r));
    const std::string name = fmt::format("{}/state_{:05d}.pvtu", kStatesFolder, state);
    writePvtu(dir_ / name, pieces, fields);
    pvd_.addState(s.time(), name);
  }
}

std::string ResultsWriter::stateDigestGlobal(const solver::Solver& s) const {
  // Every rank sends (id, x, v) of the nodes it owns; rank 0 orders them by id.
  const auto& sd = s.subdomain();
  // With shells or beams the angular velocities join the velocities in the digest.
  struct Record {
    int64_t id;
    double x[3], v[3], w[3];
  };
  std::vector<char> mine;
  for (std::size_t n = 0; n < sd.numNodes(); ++n) {
    if (!sd.node_owned[n]) continue;
    Record r{sd.node_id[n],
             {sd.x[3 * n], sd.x[3 * n + 1], sd.x[3 * n + 2]},
             {sd.v[3 * n], sd.v[3 * n + 1], sd.v[3 * n + 2]},
             {0.0, 0.0, 0.0}};
    if (sd.rotations)
      for (int c = 0; c < 3; ++c) r.w[c] = sd.w[3 * n + std::size_t(c)];
    const auto* p = reinterpret_cast<const char*>(&r);
    mine.insert(mine.end(), p, p + sizeof(Record));
  }
  const auto all = comm_.gatherToRoot(mine);
  if (!comm_.isRoot()) return {};
  std::vector<Record> recs(all.size() / sizeof(Record));
  std::memcpy(recs.data(), all.data(), recs.size() * sizeof(Record));
  std::sort(recs.begin(), recs.end(), [](const Record& a, const Record& b) { return a.id < b.id; });
  std::vector<double> x, v;
  x.reserve(3 * recs.size());
  v.reserve(3 * recs.size());
  for (const auto& r : recs) {
    x.insert(x.end(), r.x, r.x + 3);
    v.insert(v.end(), r.v, r.v + 3);
    if (sd.rotations) v.insert(v.end(), r.w, r.w + 3);
  }
  return stateDigest(x, v);
}

// Every rank's own seconds (collective), for the load balance the one-rank "timing" hides:
// at a collective the faster ranks wait, and that wait is counted where it happens (in
// "communication" or the contact exchange), not as work (docs/parallel.md, "How many ranks").
nlohmann::json ResultsWriter::timingByRank(const solver::Solver& s) const {
  const auto& t = s.timing();
  const contact::Statistics* c = s.contact() ? &s.contact()->statistics() : nullptr;
  const std::vector<double> mine = {t.elements,
                                    t.contact,
                                    c ? c->search_s : 0,
                                    c ? c->replicated_s : 0,
                                    c ? c->exchange_s : 0,
                                    t.constraints,
                                    t.communication};
  const std::vector<double> all = comm_.allGather(mine);
  nlohmann::json out = nlohmann::json::array();
  if (!comm_.isRoot()) return out;
  for (std::size_t r = 0; r < all.size(); r += mine.size())
    out.push_back({{"elements", all[r]},
                   {"contact", all[r + 1]},
                   {"contact_search", all[r + 2]},
                   {"contact_replicated", all[r + 3]},
                   {"contact_exchange", all[r + 4]},
                   {"constraints", all[r + 5]},
                   {"communication", all[r + 6]}});
  return out;
}

void ResultsWriter::writeSummary(const solver::Solver& s, const RunInfo& info) const {
  const auto e = s.energies();
  const std::string digest = stateDigestGlobal(s);
  const long peak = static_cast<long>(comm_.maxAll(int64_t(peakMemoryBytes())));
  const long long eroded = comm_.sumAll(s.erodedElements());  // each rank erodes its own
  // Every rank sees every contact record: the largest penetration is the same everywhere.
  const double max_pen = s.contact() ? s.contact()->statistics().max_penetration_ratio : 0.0;
  const solver::ErodedSums eroded_sums = s.eroded();
  const nlohmann::json by_rank = timingByRank(s);
  if (!comm_.isRoot()) return;
  const auto& t = s.timing();
  nlohmann::json j;
  j["version"] = CRUMPLE_VERSION;
  j["deck"] = info.deck;
  j["ranks"] = info.ranks;
  j["threads"] = info.threads;
  j["termination"] = info.termination;
  if (!info.message.empty()) j["message"] = info.message;
  if (!info.ignored_unsupported.empty()) j["ignored_unsupported"] = info.ignored_unsupported;
  j["end_time"] = s.time();
  j["cycles"] = s.cycle();
  if (info.relaxation_cycles > 0) j["relaxation_cycles"] = info.relaxation_cycles;
  j["wall_s"] = info.wall_s;
  const auto& sd = s.subdomain();
  const double element_cycles = double(sd.global_elements) * double(s.cycle() - info.first_cycle);
  // The rate of the time-stepping loop: set-up (reading the deck, partitioning) is reported
  // apart, as setup_s, and would otherwise hide the solver's speed on short runs.
  const double loop_s = info.wall_s - info.setup_s;
  j["element_cycles_per_s"] = loop_s > 0.0 ? element_cycles / loop_s : 0.0;
  j["setup_s"] = info.setup_s;
  j["setup"] = nlohmann::json::object();
  for (const auto& [phase, seconds] : info.setup_phases) j["setup"][phase] = seconds;
  j["timing"] = {
      {"elements", t.elements},       {"contact", t.contact},
      {"constraints", t.constraints}, {"communication", t.communication},
      {"output", seconds_},           {"other", t.rest(info.wall_s, info.setup_s, seconds_)}};
  j["timing_by_rank"] = by_rank;
  j["counts"] = {{"nodes", sd.global_nodes},
                 {"solids", sd.global_solids},
                 {"shells", sd.global_family[std::size_t(model::Family::Shell)]},
                 {"beams", sd.global_family[std::size_t(model::Family::Beam)]},
                 {"discretes", sd.global_family[std::size_t(model::Family::Discrete)]}};
  j["energy"] = {{"kinetic", e.kinetic},     {"internal", e.internal},
                 {"hourglass", e.hourglass}, {"drilling", e.drilling},
                 {"contact", e.contact},     {"external_work", e.external_work},
                 {"rigidwall", e.rigidwall}, {"damping", e.damping},
                 {"total", e.total},         {"ratio", e.ratio}};
  const auto& audit = audit_.summary();
  j["energy_audit"] = {{"band", {EnergyAudit::kLow, EnergyAudit::kHigh}},
                       {"min_ratio", audit.min_ratio},
                       {"max_ratio", audit.max_ratio},
                       {"samples", audit.samples},
                       {"samples_outside", audit.samples_outside},
                       {"first_outside_time", audit.first_outside_time >= 0.0
                                                  ? nlohmann::json(audit.first_outside_time)
                                                  : nlohmann::json()}};
  j["mass"] = {{"physical", s.totalMass()}, {"added", s.addedMass()}};
  // The deck's unit system, for labels (`crumple plot`); null when not known.
  j["units"] = {
      {"system", model_.units.name.empty() ? nlohmann::json() : nlohmann::json(model_.units.name)},
      {"source", model_.units.source}};
  j["eroded_elements"] = eroded;
  // What erosion took out of the model: the elements' physical mass (their nodes keep theirs,
  // lumped) and the internal and hourglass energy they held, which stay in the energy sums.
  j["eroded_mass"] = eroded_sums.mass;
  j["eroded_internal_energy"] = eroded_sums.internal;
  j["eroded_hourglass_energy"] = eroded_sums.hourglass;
  j["eroded_drilling_energy"] = eroded_sums.drilling;
  j["initial_dt"] = s.initialDt();
  j["peak_memory_bytes"] = peak;  // the largest rank
  j["communication_s"] = s.timing().communication;
  if (const auto* c = s.contact()) {
    const auto& st = c->statistics();
    j["contact"] = {{"interfaces", model_.contacts.size()},
                    {"checks", st.checks},
                    {"bucket_sorts", st.sorts},
                    {"rebalances", st.rebalances},
                    {"tied_nodes", st.tied_nodes},
                    // Rank 0's split of its contact time (docs/parallel.md, "Contact").
                    {"search_s", st.search_s},
                    {"replicated_s", st.replicated_s},
                    {"exchange_s", st.exchange_s},
                    {"records_per_cycle", st.cycles ? double(st.records) / double(st.cycles) : 0.0},
                    {"initial_penetrations", c->initialPenetrations().size()},
                    {"max_penetration_ratio", max_pen}};
  }
  j["state_digest"] = digest;
  writeTextFile(dir_ / "summary.json", j.dump(2) + "\n");
}

}  // namespace crumple::output
