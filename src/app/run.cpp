#include "app/run.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "app/report.hpp"
#include "model/build.hpp"
#include "model/serialize.hpp"
#include "partition/partition.hpp"
#include "util/archive.hpp"

namespace crumple::app {

namespace {

// A keyword skipped that changes the answer (an element, a material, a load...): the run is
// refused, or with --ignore-unsupported run without it, as run.log and summary.json then say.
void refuseUnsupported(const model::Model& m, const RunOptions& opt) {
  if (answerChanging(m).empty() || opt.ignore_unsupported) return;
  throw util::InputError(
      opt.deck +
      ": the deck uses what Crumple does not support, and leaving it out would change the "
      "answer:\n" +
      answerChangingText(m) +
      "(`crumple check` lists every problem; --ignore-unsupported runs without them)");
}

// Runs `step` on rank 0 and tells every rank whether it succeeded; on failure rank 0 prints
// the message and every rank gets false (so all end together, with one message).
template <class F>
bool rootStep(const comm::Communicator& comm, F&& step) {
  std::string error;
  if (comm.isRoot()) {
    try {
      step();
    } catch (const std::exception& e) {
      error = e.what();
      if (error.empty()) error = "unknown error";
    }
  }
  const bool failed = comm.anyAll(!error.empty());
  if (failed && comm.isRoot()) std::fprintf(stderr, "crumple: error: %s\n", error.c_str());
  return !failed;
}

// -o, else a restart continues the dumped run in its own folder (the history files are cut
// back to the dump and continued: ResultsWriter::loadState checks that they are that run's),
// else <deck stem>.out. A restart's -o naming a new or empty folder gets a copy of the dumped
// run's results first (Run::prepareFolder).
std::filesystem::path resultsFolder(const RunOptions& opt, const std::filesystem::path& dump) {
  if (!opt.output_dir.empty()) return opt.output_dir;
  if (!opt.restart.empty()) return dump.parent_path().empty() ? "." : dump.parent_path();
  return std::filesystem::path(opt.deck).stem().string() + ".out";
}

std::string timingTable(const solver::Timing& t, double output_s, double setup_s, double wall) {
  auto row = [&](const char* name, double v) {
    return fmt::format("  {:<14} {:10.3f} s {:6.1f}%\n", name, v,
                       wall > 0 ? 100.0 * v / wall : 0.0);
  };
  const double other = t.rest(wall, setup_s, output_s);
  return "timing:\n" + row("set-up", setup_s) + row("elements", t.elements) +
         row("contact", t.contact) + row("constraints", t.constraints) +
         row("communication", t.communication) + row("output", output_s) + row("other", other) +
         row("total", wall);
}

}  // namespace

void RunLog::open(const std::filesystem::path& path, bool append) {
  if (!root_) return;
  out_.open(path, append ? std::ios::app : std::ios::trunc);
  out_ << pending_;
  out_.flush();
  pending_.clear();
}

void RunLog::say(const std::string& text) {
  if (!root_) return;
  if (!out_.is_open()) {
    pending_ += text;
    return;
  }
  out_ << text;
  out_.flush();
}

void RunLog::check(const std::filesystem::path& path) const {
  if (root_) output::checkStream(out_, path);
}

Run::Run(const RunOptions& opt)
    : opt_(opt),
      comm_(comm::world()),
      root_(comm_.isRoot()),
      restart_(!opt.restart.empty()),
      show_(!opt.quiet && root_),
      log_(root_) {
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  threads_ = omp_get_max_threads();
}

int Run::execute() {
  if (!setUp()) return 1;
  try {
    start();
    cycleLoop();
    end();
  } catch (const util::InputError& e) {
    // Restart problems (a dump of another deck, a results folder of another run) are found
    // by every rank together (DumpRegistry::restore), before the first cycle.
    if (root_) std::fprintf(stderr, "crumple: error: %s\n", e.what());
    log_.say(fmt::format("error: {}\n", e.what()));
    return 1;
  } catch (const util::NumericalError& e) {
    endWithError(e);
  } catch (const std::exception& e) {
    // Anything else (an I/O failure on one rank) may leave the others waiting in a
    // collective: end them all. Before the first state nothing worth keeping was written:
    // what this run created goes (serially; under MPI the abort leaves no time to agree).
    std::fprintf(stderr, "crumple: error (rank %d): %s\n", comm_.rank(), e.what());
    if (!started_ && !comm_.distributed()) {
      log_.close();
      output::removeRunOutput(dir_, !dir_existed_);
      return 1;
    }
    if (comm_.distributed()) comm_.abort(1);
    info_.termination = "error";
    info_.message = e.what();
    status_ = 1;
  }
  return finish();
}

bool Run::setUp() {
  // Rank 0 reads and validates the deck (and the dump) and partitions it; the others receive
  // the result.
  // Rank 0's phases are timed (the others wait in the first of distribute).
  const bool read = rootStep(comm_, [&] {
    readModel();
    if (restart_) readDump();
    endSetupPhase("validate");
    if (elem_rank_.empty()) partitionElements();
  });
  if (!read) return false;
  if (root_)
    endSetupPhase("partition");
  else  // the other ranks wait for rank 0 until distribute: their wait is counted there
    info_.setup_phases = {{"read", 0.0}, {"validate", 0.0}, {"partition", 0.0}};
  distribute();
  endSetupPhase("distribute");
  if (!initializeSolver()) return false;
  endSetupPhase("initialise");
  if (!prepareFolder()) return false;
  openOutputs();
  return true;
}

void Run::endSetupPhase(const char* phase) {
  const double now = util::secondsSince(wall0_);
  info_.setup_phases.emplace_back(phase, now - setup_mark_);
  setup_mark_ = now;
}

void Run::readModel() {
  const model::ReadOptions options{.implicit_as_explicit = opt_.implicit_as_explicit};
  const deck::Deck deck = deck::readDeck(opt_.deck, deck::ReadDeckOptions{options.collect_errors});
  endSetupPhase("read");
  model_ = model::buildModel(deck, opt_.deck, options);
  refuseUnsupported(model_, opt_);
  auto& ctl = model_.controls;
  if (opt_.cycles > 0) ctl.end_cycle = opt_.cycles;
  if (!opt_.restart_deck.empty()) model::readRestartDeck(opt_.restart_deck, ctl);
  if (opt_.end_time) ctl.end_time = *opt_.end_time;
  setEnergyBand(opt_.energy_band, ctl);
  if (opt_.d3plot_x > 0.0)
    ctl.d3plot_file_words = std::max<int64_t>(1, std::llround(opt_.d3plot_x * 512.0 * 512.0));
  if (opt_.strict && !model_.unsupported.empty()) {
    throw util::InputError("--strict: the deck uses unsupported keywords:\n" +
                           model::formatUnsupported(model_));
  }
  if (!(ctl.end_time > 0.0) && ctl.end_cycle <= 0)
    throw util::InputError(opt_.deck +
                           ": *CONTROL_TERMINATION gives no end time (ENDTIM) or "
                           "cycle count (ENDCYC); pass --endtime to run anyway");
}

void Run::readDump() {
  dump_path_ = output::resolveDump(opt_.restart);
  std::ifstream in(dump_path_, std::ios::binary);
  if (!in) throw util::InputError("cannot open restart dump '" + dump_path_.string() + "'");
  dump_bytes_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  // Checked here, before anything is partitioned or any rank waits on it.
  const auto dump = output::decodeDump(dump_bytes_, dump_path_.string());
  // The dump's partition is reused at the same number of ranks: each rank then continues
  // its own partial energy sums, and glstat.csv stays bitwise that of the uninterrupted run.
  if (const auto it = dump.sections.find("partition"); it != dump.sections.end()) {
    util::ArchiveReader r(it->second);
    int32_t ranks = 0;
    std::vector<int32_t> owners;
    r.get(ranks);
    r.get(owners);
    if (ranks == comm_.size() && owners.size() == model_.numElements()) elem_rank_ = owners;
  }
}

void Run::partitionElements() {
  partition::Options popt;
  popt.method = partition::parseMethod(opt_.partition);
  // Elements under contact segments carry the contact work too (docs/parallel.md).
  if (opt_.contact_bias != 1.0 && !model_.contacts.empty()) {
    popt.contact_bias = opt_.contact_bias;
    popt.contact_elements.assign(model_.numElements(), 0);
    for (const auto& c : model_.contacts)
      for (const auto* side : {&c.a, &c.b})
        for (int64_t e : side->segment_element) popt.contact_elements[std::size_t(e)] = 1;
  }
  elem_rank_ = partition::partitionElements(model_, comm_.size(), popt);
}

void Run::distribute() {
  if (comm_.distributed()) {
    // One archive: the model's bytes, then the element -> rank map.
    std::vector<char> bytes;
    if (root_) {
      util::ArchiveWriter w;
      w.put(model::serialize(model_));
      w.put(elem_rank_);
      w.put(dump_path_.string());
      bytes = std::move(w.bytes());
    }
    comm_.broadcast(bytes);
    if (!root_) {
      util::ArchiveReader r(bytes);
      std::vector<char> model_bytes;
      std::string path;
      r.get(model_bytes);
      r.get(elem_rank_);
      r.get(path);
      dump_path_ = path;
      model_ = model::deserialize(model_bytes);
    }
    // Every rank takes its part from the same bytes (no shared file system needed).
    if (restart_) comm_.broadcast(dump_bytes_);
  }
  if (restart_) dump_ = output::decodeDump(dump_bytes_, dump_path_.string());
  dump_bytes_.clear();
  dump_bytes_.shrink_to_fit();
}

bool Run::initializeSolver() {
  try {
    sd_ = domain::buildSubdomain(model_, elem_rank_, comm_.rank(), comm_.size());
  } catch (const std::exception& e) {
    // Every rank sees the same model and partition, so every rank fails alike.
    if (root_) std::fprintf(stderr, "crumple: error: %s\n", e.what());
    return false;
  }
  solver_ = std::make_unique<solver::Solver>(model_, sd_, comm_);
  // Initialisation checks the initial geometry (inverted or degenerate elements) collectively:
  // a deck that cannot start fails here, before the results folder is touched.
  try {
    solver_->initialize();
  } catch (const util::NumericalError& e) {
    if (root_) std::fprintf(stderr, "crumple: error: %s\n", e.what());
    return false;
  } catch (const std::exception& e) {
    // Not known to be collective: the other ranks may wait in a collective.
    std::fprintf(stderr, "crumple: error (rank %d): %s\n", comm_.rank(), e.what());
    if (comm_.distributed()) comm_.abort(1);
    return false;
  }
  return true;
}

bool Run::prepareFolder() {
  dir_ = resultsFolder(opt_, dump_path_);
  std::error_code ec;
  dir_existed_ = std::filesystem::exists(dir_, ec);
  if (!restart_) return rootStep(comm_, [&] { output::prepareResultsDir(dir_, opt_.overwrite); });
  // -o naming a new or empty folder: the restart continues there, from a copy of the dumped
  // run's results, and leaves the dumped run's folder as it was.
  const std::filesystem::path dumped =
      dump_path_.parent_path().empty() ? std::filesystem::path(".") : dump_path_.parent_path();
  const bool fresh = !std::filesystem::exists(dir_, ec) || std::filesystem::is_empty(dir_, ec);
  if (!opt_.output_dir.empty() && fresh)
    return rootStep(comm_, [&] {
      output::prepareResultsDir(dir_, false);
      output::copyRunFolder(dumped, dir_);
    });
  return rootStep(comm_, [&] {
    if (!std::filesystem::is_directory(dir_))
      throw util::InputError("results folder '" + dir_.string() +
                             "' of the restarted run does not exist");
  });
}

void Run::openOutputs() {
  if (!restart_) openLog();
  log_.say(fmt::format("crumple {} — {} rank(s), {} thread(s) per rank, partition {}\n",
                       CRUMPLE_VERSION, comm_.size(), threads_, opt_.partition));
  const std::string warn = warningsText(model_);
  if (!warn.empty() && root_) {
    std::fputs(warn.c_str(), stderr);
    log_.say(warn);
  }
  info_.deck = opt_.deck;
  for (const auto* u : answerChanging(model_)) info_.ignored_unsupported.push_back(u->feature);
  if (!info_.ignored_unsupported.empty())
    log_.say(
        "--ignore-unsupported: this run leaves out what Crumple does not support, and its "
        "answer differs from the deck's:\n" +
        answerChangingText(model_));
  info_.ranks = comm_.size();
  info_.threads = threads_;
  installSignalHandlers();
  registerDumpSections();
}

void Run::registerDumpSections() {
  // The sections of a restart dump (docs/reliability.md, "Restart"). Other state joins with one
  // add() each, e.g. contact: dumps_.add({"contact", save, load, true}).
  auto& s = *solver_;
  dumps_.add({"partition",
              [&] {
                util::ArchiveWriter w;
                w.put<int32_t>(comm_.size());
                w.put(elem_rank_);
                return std::move(w.bytes());
              },
              // Read before the subdomain is built (readDump); nothing left to restore.
              [](const std::vector<char>&) {}});
  using Section = solver::Solver::StateSection;
  for (const auto& [name, section] :
       {std::pair{"solver", Section::Scalars}, std::pair{"nodes", Section::Nodes},
        std::pair{"elements", Section::Elements}, std::pair{"constraints", Section::Constraints}})
    dumps_.add({name, [&s, section] { return s.saveState(section); },
                [&s, section](const std::vector<char>& b) { s.loadState(section, b); }});
  // Contact state is the same on every rank: rank 0's copy is dumped, every rank loads it.
  if (s.contact())
    dumps_.add({"contact", [&s] { return s.contact()->saveState(); },  // collective; rank 0's
                [&s](const std::vector<char>& b) { s.contact()->loadState(b); }});
  // Last: its load cuts the history files back, after every other section was accepted.
  dumps_.add({"output", [this] { return writer_->saveState(); },
              [this](const std::vector<char>& b) { writer_->loadState(b, solver_->time()); }});
}

void Run::start() {
  auto& s = *solver_;
  log_.check(dir_ / "run.log");
  log_.say(modelSummary(model_, s));
  if (root_ && s.contact() && !s.contact()->initialPenetrations().empty())
    std::fprintf(stderr,
                 "crumple: note: %zu initial contact penetration(s) %s (listed in run.log)\n",
                 s.contact()->initialPenetrations().size(),
                 s.contact()->movedInitialPenetrations() ? "moved back onto the surface"
                                                         : "kept as an offset (IGNORE)");
  // A restart continues the transient: a dump is written only in the cycle loop, after the
  // relaxation phase.
  if (!restart_ && model_.controls.relaxation.active()) relax();
  writer_ = std::make_unique<output::ResultsWriter>(dir_, model_, s, comm_, restart_);
  // Set-up is over: each rank keeps its subdomain, nobody the whole mesh.
  model_.releaseMesh();
  if (restart_) restoreDump();
  progress_.emplace(stdout, show_ && isatty(STDOUT_FILENO), s.endTime());
  // Set-up ends here: the first state's output is counted as output, so that set-up, the
  // timing rows and the wall time add up.
  endSetupPhase("output");
  info_.setup_s = setup_mark_;
  // The state at the dump was written by the dumped run.
  if (!restart_) writeResults();
  started_ = true;
}

void Run::relax() {
  auto& s = *solver_;
  log_.say("dynamic relaxation (*CONTROL_DYNAMIC_RELAXATION, SIDR curves) ...\n");
  const solver::Solver::Relaxation r = s.relax();
  const auto& dr = model_.controls.relaxation;
  log_.say(fmt::format(
      "dynamic relaxation {} after {} cycles at relaxation time {:.6g}: distortional kinetic "
      "energy {:.4g} x its peak {:.6g} (DRTOL {:.4g}); relaxed internal + hourglass + drilling "
      "energy "
      "{:.6g}; the transient starts at t = 0 from the relaxed state, its energy balance "
      "from there\n",
      r.converged ? "converged" : "ended by DRTERM", r.cycles, r.time, r.ratio, r.peak, dr.drtol,
      r.energy));
  info_.relaxation_cycles = r.cycles;
  // The phase's element, contact and constraint time is set-up time ("relax"), not the
  // transient's.
  s.timing() = {};
  endSetupPhase("relax");
}

void Run::restoreDump() {
  const auto& s = *solver_;
  dumps_.restore(dump_, comm_);
  dump_ = {};
  openLog();
  info_.first_cycle = s.cycle();
  log_.say(fmt::format("restart from {} at cycle {}, time {:.6g}\n", dump_path_.string(), s.cycle(),
                       s.time()));
  // Dumps of later cycles belong to the continuation this restart replaces.
  if (root_)
    for (const auto& p : output::dumpFiles(dir_))
      if (output::dumpCycle(p) > s.cycle()) {
        std::error_code ec;
        std::filesystem::remove(p, ec);
        log_.say(fmt::format("removed {}: written after the restart point\n", p.string()));
      }
}

void Run::cycleLoop() {
  auto& s = *solver_;
  RunControl control(comm_, dir_, model_.controls, opt_.checkpoint_every,
                     [this](const std::string& note) {
                       std::fputs(("crumple: warning: " + note).c_str(), stderr);
                       log_.say("warning: " + note);
                     });
  while (!s.finished()) {
    s.step();
    control.checkEnergyBand(s);
    writeResults();
    // The energy sums cost a pass over every node and element: refresh them sparingly.
    if (s.cycle() % 64 == 0) {
      const double ratio = s.energies().ratio;
      if (show_) progress_->update(s.cycle(), s.time(), s.dt(), ratio);
    }
    const Requests request = control.poll(s);
    if (request.status()) sayStatus();
    if (const char* why = request.dumpReason()) writeDump(why);
    if (request.stop()) {
      stop(request);
      return;
    }
  }
}

void Run::writeResults(bool last) {
  writer_->write(*solver_, last);
  const std::string notes = writer_->takeNotes();
  if (notes.empty()) return;
  log_.say(notes);
  // Once on the terminal, the first time: the analyst watching the run learns it at once.
  if (!energy_warned_ && root_)
    std::fprintf(stderr,
                 "crumple: warning: the energy ratio left [%g, %g] at time %.6g (energy audit in "
                 "run.log)\n",
                 output::EnergyAudit::kLow, output::EnergyAudit::kHigh,
                 writer_->energyAudit().summary().first_outside_time);
  energy_warned_ = true;
}

void Run::stop(const Requests& request) {
  info_.termination = "signal";
  status_ = request.exitStatus();
  info_.message = request.stopMessage();
  log_.say(info_.message + "\n");
}

void Run::end() {
  auto& s = *solver_;
  // A run that ends normally leaves a dump of its end state when dumps were asked for: a
  // restart deck with a later ENDTIM extends the run from it.
  const bool dumping = model_.controls.d3dump_cycles > 0 || opt_.checkpoint_every > 0.0;
  if (dumping && info_.termination == "normal") writeDump("end of run");
  writeResults(true);
  const double ratio = s.energies().ratio;
  if (show_) progress_->finish(s.cycle(), s.time(), s.dt(), ratio);
}

void Run::endWithError(const util::NumericalError& e) {
  // Numerical failures are detected collectively: every rank is here together.
  info_.termination = "error";
  info_.message = e.what();
  status_ = 1;
  if (root_) std::fprintf(stderr, "crumple: error: %s\n", e.what());
  log_.say(fmt::format("error termination: {}\n", e.what()));
  if (!writer_) return;
  try {
    writeResults(true);
  } catch (const std::exception& e2) {
    log_.say(fmt::format("could not write the last state: {}\n", e2.what()));
  }
  // And a dump of the state at the failure (collective, like the failure): an analyst can
  // look at it, or continue from the last periodic dump with a restart deck.
  if (started_) writeDump("error termination");
}

int Run::finish() {
  const auto& s = *solver_;
  info_.wall_s = util::secondsSince(wall0_);
  const double output_s = writer_ ? writer_->seconds() : 0.0;
  if (writer_) {
    try {
      writer_->writeSummary(s, info_);
    } catch (const std::exception& e) {
      // A full disk: the summary is lost; say so and fail rather than end silently.
      if (root_) std::fprintf(stderr, "crumple: error: %s\n", e.what());
      status_ = 1;
    }
  }
  const auto e = s.energies();
  log_.say(fmt::format(
      "{} termination at time {:.6g}, cycle {}\nenergy: kinetic {:.6g} internal {:.6g} hourglass "
      "{:.6g} drilling {:.6g} rigidwall {:.6g} external work {:.6g} ratio {:.6f}\n",
      info_.termination, s.time(), s.cycle(), e.kinetic, e.internal, e.hourglass, e.drilling,
      e.rigidwall, e.external_work, e.ratio));
  if (writer_) log_.say(writer_->energyAudit().verdict());
  if (const auto er = s.eroded(); er.elements > 0)
    log_.say(
        fmt::format("eroded: {} element(s), mass {:.6g}, internal energy {:.6g}, hourglass energy "
                    "{:.6g}, drilling energy {:.6g}\n",
                    er.elements, er.mass, er.internal, er.hourglass, er.drilling));
  log_.say(timingTable(s.timing(), output_s, info_.setup_s, info_.wall_s));
  std::string phases;
  for (const auto& [phase, seconds] : info_.setup_phases)
    phases += fmt::format("{}{} {:.3f} s", phases.empty() ? "" : ", ", phase, seconds);
  log_.say("set-up by phase (rank 0): " + phases + "\n");
  if (s.cycle() > info_.first_cycle && info_.wall_s > info_.setup_s)
    log_.say(fmt::format("set-up {:.3f} s; {:.3g} element-cycles per second in the cycle loop\n",
                         info_.setup_s,
                         double(sd_.global_elements) * double(s.cycle() - info_.first_cycle) /
                             (info_.wall_s - info_.setup_s)));
  if (show_)
    std::printf("%s termination; results in %s\n", info_.termination.c_str(), dir_.c_str());
  if (root_ && log_.failed()) {
    std::fprintf(stderr, "crumple: error: error while writing '%s'\n", (dir_ / "run.log").c_str());
    status_ = 1;
  }
  return status_;
}

void Run::writeDump(const char* why) {
  // A failure to write it is reported and the run goes on (the earlier dumps are intact: dumps
  // are renamed into place only when complete).
  const auto& s = *solver_;
  const auto t0 = util::Clock::now();
  const auto bytes = dumps_.save(comm_);
  const auto t1 = util::Clock::now();
  if (!root_) return;
  try {
    const auto path = output::writeDumpFile(dir_, s.cycle(), bytes);
    log_.say(fmt::format(
        "restart dump {} ({}) at cycle {}, time {:.6g}: {:.1f} MB, {:.3f} s to gather, {:.3f} s "
        "to write\n",
        path.filename().string(), why, s.cycle(), s.time(), double(bytes.size()) / 1e6,
        std::chrono::duration<double>(t1 - t0).count(), util::secondsSince(t1)));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crumple: warning: %s; the run goes on\n", e.what());
    log_.say(fmt::format("warning: {}; the run goes on\n", e.what()));
  }
}

void Run::sayStatus() {
  const auto& s = *solver_;
  const auto e = s.energies();
  const std::string line = fmt::format(
      "sw2: cycle {} time {:.6g} dt {:.4g} of end time {:.6g}; energy kinetic {:.6g} "
      "internal {:.6g} ratio {:.6f}; wall {:.1f} s\n",
      s.cycle(), s.time(), s.dt(), s.endTime(), e.kinetic, e.internal, e.ratio,
      util::secondsSince(wall0_));
  if (root_) {
    std::fputs(line.c_str(), stdout);
    std::fflush(stdout);
  }
  log_.say(line);
}

}  // namespace crumple::app
