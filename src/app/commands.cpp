#include "app/commands.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "comm/communicator.hpp"
#include "domain/subdomain.hpp"
#include "model/build.hpp"
#include "model/serialize.hpp"
#include "output/files.hpp"
#include "output/restart.hpp"
#include "output/results.hpp"
#include "partition/partition.hpp"
#include "solver/solver.hpp"
#include "util/archive.hpp"
#include "util/error.hpp"

namespace crumple::app {

namespace {

// The first SIGINT or SIGTERM received (0: none), and a pending SIGUSR1. Handlers only set
// flags; the cycle loop acts on them (see Request in runCommand).
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

// The model summary shared by `crumple check` and run.log.
std::string modelSummary(const model::Model& m, const solver::Solver& s) {
  std::string out;
  out += fmt::format("deck: {}\n", m.deck_path);
  if (!m.title.empty()) out += fmt::format("title: {}\n", m.title);
  out += fmt::format("nodes: {}\nsolid elements: {}\n", m.nodes.size(), m.solids.size());
  if (m.shells.size() > 0) out += fmt::format("shell elements: {}\n", m.shells.size());
  if (m.beams.size() > 0) out += fmt::format("beam elements: {}\n", m.beams.size());
  if (m.discretes.size() > 0) out += fmt::format("discrete elements: {}\n", m.discretes.size());
  std::map<std::pair<int32_t, int>, std::size_t> per_part;
  for (std::size_t g = 0; g < m.numElements(); ++g)
    ++per_part[{m.elementPart(g), int(m.element(g).first)}];
  static constexpr const char* kPlural[] = {"solids", "shells", "beams", "discretes"};
  static constexpr const char* kSingular[] = {"solid", "shell", "beam", "discrete"};
  for (const auto& [key, count] : per_part) {
    const auto& part = m.parts[static_cast<std::size_t>(key.first)];
    const auto& mat = m.materials[static_cast<std::size_t>(part.material)];
    out += fmt::format("  part {}{}: {} {}, {} {} (density {:g})\n", part.id,
                       part.title.empty() ? "" : " \"" + part.title + "\"", count,
                       count == 1 ? kSingular[key.second] : kPlural[key.second],
                       model::materialKeyword(mat.law), mat.id, mat.rho);
  }
  out += fmt::format("total mass: {:.6g}\n", s.totalMass());
  if (s.addedMass() > 0.0)
    out += fmt::format("mass added by scaling (DT2MS): {:.6g} ({:.3g}%)\n", s.addedMass(),
                       100.0 * s.addedMass() / s.totalMass());
  out += fmt::format("initial time step: {:.6g} ({}, TSSFAC {:g})\n", s.initialDt(),
                     s.initialDtElement(), m.controls.tssfac);
  out += fmt::format("end time: {:g}\n", m.controls.end_time);
  if (!m.contacts.empty()) {
    static constexpr const char* kKind[] = {"nodes to surface", "surface to surface",
                                            "single surface", "tied"};
    for (const auto& c : m.contacts)
      out += fmt::format(
          "contact {}{}: {}{}, {} nodes / {} segments against {} segments\n", c.id,
          c.title.empty() ? "" : " \"" + c.title + "\"", c.automatic ? "automatic " : "",
          kKind[int(c.kind)], c.a.nodes.size(), c.a.segments.size(),
          c.kind == model::ContactKind::SingleSurface ? c.a.segments.size() : c.b.segments.size());
    // Initial penetrations: DYNA3D moves the nodes back onto the surface (IGNORE 0), and
    // says so; with IGNORE 1 or 2 they are kept as an offset.
    if (const auto* c = s.contact()) {
      const auto& pen = c->initialPenetrations();
      if (!pen.empty()) {
        out += fmt::format("initial penetrations: {} ({})\n", pen.size(),
                           c->movedInitialPenetrations()
                               ? "moved back onto the surface before the first cycle"
                               : "kept as an offset (IGNORE)");
        const std::size_t shown = std::min<std::size_t>(pen.size(), 20);
        for (std::size_t k = 0; k < shown; ++k)
          out += fmt::format("  contact {} node {}: depth {:.4g}\n", pen[k].interface_id,
                             pen[k].node_id, pen[k].depth);
        if (shown < pen.size()) out += fmt::format("  ... and {} more\n", pen.size() - shown);
      }
    }
  }
  return out;
}

std::string warningsText(const model::Model& m) {
  std::string out;
  if (!m.unsupported.empty())
    out += "keywords read but not acted on:\n" + model::formatUnsupported(m);
  if (!m.ignored.empty()) out += "fields read but not honoured:\n" + model::formatIgnored(m);
  return out;
}

std::string timingTable(const solver::Timing& t, double output_s, double wall) {
  auto row = [&](const char* name, double v) {
    return fmt::format("  {:<14} {:10.3f} s {:6.1f}%\n", name, v,
                       wall > 0 ? 100.0 * v / wall : 0.0);
  };
  const double other =
      std::max(0.0, wall - t.elements - t.contact - t.constraints - t.communication - output_s);
  return "timing:\n" + row("elements", t.elements) + row("contact", t.contact) +
         row("constraints", t.constraints) + row("communication", t.communication) +
         row("output", output_s) + row("other", other) + row("total", wall);
}

}  // namespace

namespace {

// The unsupported entries whose absence changes the answer: a run refuses the deck for them.
std::vector<const model::UnsupportedKeyword*> answerChanging(const model::Model& m) {
  std::vector<const model::UnsupportedKeyword*> out;
  for (const auto& u : m.unsupported)
    if (u.changes_answer) out.push_back(&u);
  return out;
}

std::size_t featureCount(const model::Model& m) {
  std::set<std::string> features;
  for (const auto* u : answerChanging(m)) features.insert(u->feature);
  return features.size();
}

// One line per feature (every element of every part of a missing material is one feature),
// in order of first appearance.
std::string answerChangingText(const model::Model& m) {
  std::vector<std::string> order;
  std::map<std::string, std::pair<int, const model::UnsupportedKeyword*>> by_feature;
  for (const auto* u : answerChanging(m)) {
    auto [it, added] = by_feature.try_emplace(u->feature, 0, u);
    if (added) order.push_back(u->feature);
    it->second.first += u->count;
  }
  std::string out;
  for (const auto& f : order) {
    const auto& [count, u] = by_feature.at(f);
    out += fmt::format("  {} ({}x, first at {}): {}\n", f, count, u->first.str(), u->reason);
  }
  return out;
}

// `crumple check --json`: the same report as data (docs/compatibility.md is built from it).
nlohmann::json checkJson(const model::Model& m, const std::string& status,
                         const std::optional<std::pair<double, double>>& dt_end) {
  nlohmann::json j;
  j["deck"] = m.deck_path;
  j["status"] = status;
  j["errors"] = nlohmann::json::array();
  for (const auto& e : m.errors) {
    const auto colon = e.message.find(": ");
    j["errors"].push_back({{"where", colon == std::string::npos ? "" : e.message.substr(0, colon)},
                           {"message", e.message},
                           {"feature", nullptr}});
  }
  j["unsupported"] = nlohmann::json::array();
  for (const auto& u : m.unsupported)
    j["unsupported"].push_back({{"keyword", u.keyword},
                                {"count", u.count},
                                {"first", u.first.str()},
                                {"reason", u.reason},
                                {"changes_answer", u.changes_answer},
                                {"feature", u.feature}});
  j["ignored"] = nlohmann::json::array();
  for (const auto& i : m.ignored)
    j["ignored"].push_back({{"where", i.where.str()},
                            {"keyword", i.keyword},
                            {"field", i.field},
                            {"reason", i.reason}});
  j["counts"] = {{"nodes", m.nodes.size()},
                 {"solids", m.solids.size()},
                 {"shells", m.shells.size()},
                 {"beams", m.beams.size()},
                 {"discretes", m.discretes.size()}};
  j["initial_dt"] = dt_end ? nlohmann::json(dt_end->first) : nlohmann::json(nullptr);
  j["end_time"] = m.controls.end_time;
  return j;
}

// Every input error, as a compiler lists them (the first kMaxShown; --json has all).
void printErrors(const model::Model& m, std::FILE* out) {
  constexpr std::size_t kMaxShown = 200;
  std::fprintf(out, "input errors: %zu\n", m.errors.size());
  for (std::size_t k = 0; k < m.errors.size() && k < kMaxShown; ++k)
    std::fprintf(out, "  %s\n", m.errors[k].message.c_str());
  if (m.errors.size() > kMaxShown)
    std::fprintf(out, "  ... and %zu more (crumple check --json lists them all)\n",
                 m.errors.size() - kMaxShown);
}

}  // namespace

int checkCommand(const CheckOptions& opt, std::FILE* out) {
  // One tolerant read that goes on past every problem, so that a user fixes a deck in one
  // round trip: input errors, then what Crumple lacks, then what it reads and does not use.
  model::Model m;
  try {
    m = model::readModel(opt.deck,
                         model::ReadOptions{.allow_unsupported = true,
                                            .collect_errors = true,
                                            .implicit_as_explicit = opt.implicit_as_explicit});
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crumple: error: %s\n", e.what());
    return 1;
  }
  const auto changing = answerChanging(m);
  std::string status = !m.errors.empty() ? "error" : !changing.empty() ? "refused" : "ok";
  std::string summary;
  std::optional<std::pair<double, double>> dt_end;
  if (status == "ok") {
    try {
      auto sd = domain::buildSerialSubdomain(m);
      solver::Solver s(m, sd, comm::world());
      s.initialize();
      summary = modelSummary(m, s);
      dt_end = std::make_pair(s.initialDt(), m.controls.end_time);
    } catch (const std::exception& e) {
      m.errors.push_back({e.what()});
      status = "error";
    }
  }
  if (opt.json) {
    std::fputs((checkJson(m, status, dt_end).dump(1) + "\n").c_str(), out);
  } else {
    if (summary.empty())
      std::fprintf(out, "deck: %s\nnodes: %zu\nsolid elements: %zu\n", m.deck_path.c_str(),
                   m.nodes.size(), m.solids.size());
    std::fputs(summary.c_str(), out);
    if (!m.errors.empty()) printErrors(m, out);
    if (!changing.empty())
      std::fprintf(out, "not supported, and leaving it out would change the answer:\n%s",
                   answerChangingText(m).c_str());
    const std::string warn = warningsText(m);
    std::fputs(warn.empty() ? "everything in the deck is supported\n" : warn.c_str(), out);
  }
  if (status == "error") {
    // Each error on stderr too, as a compiler lists them (stdout has the whole report).
    for (const auto& e : m.errors) std::fprintf(stderr, "crumple: error: %s\n", e.message.c_str());
    std::fprintf(stderr, "crumple: error: the deck has %zu input error(s)%s\n", m.errors.size(),
                 changing.empty()
                     ? ""
                     : fmt::format(" and uses {} unsupported feature(s)", featureCount(m)).c_str());
    return 1;
  }
  if (status == "refused") {
    std::fprintf(stderr,
                 "crumple: error: this deck cannot run yet: it uses %zu feature(s) Crumple does "
                 "not support, and leaving them out would change the answer\n",
                 featureCount(m));
    return 1;
  }
  if (opt.strict && !m.unsupported.empty()) {
    std::fprintf(stderr, "crumple: error: --strict: the deck uses %zu unsupported keyword(s)\n",
                 m.unsupported.size());
    return 1;
  }
  return 0;
}

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

}  // namespace

namespace {

// Requests agreed by all ranks once per cycle (Communicator::orAll): whatever rank saw a
// signal, and whatever rank 0 found in the stop file or on its clock, every rank acts on at
// the same cycle. Acting never changes the state, so results stay bitwise the same.
enum Request : uint64_t {
  kSigInt = 1,      // SIGINT: dump, final state, exit 130
  kSigTerm = 2,     // SIGTERM: dump, final state, exit 143
  kSigUsr1 = 4,     // SIGUSR1: dump and continue (like sw3)
  kStop = 8,        // sense switch sw1: dump, final state, exit 0
  kStatus = 16,     // sense switch sw2: status line
  kDump = 32,       // sense switch sw3: dump and continue
  kCheckpoint = 64  // --checkpoint-every: due by rank 0's wall clock
};
// Rank 0 looks for DIR/stop every kStopFileCycles cycles, and at least every kStopFilePeriod
// seconds of wall time (large models take long over 100 cycles); a stat() is cheap either way.
constexpr int64_t kStopFileCycles = 100;
constexpr double kStopFilePeriod = 0.5;

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

int runCommand(const RunOptions& opt) {
  const auto wall0 = std::chrono::steady_clock::now();
  auto& comm = comm::world();
  const bool root = comm.isRoot();
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  const int threads = omp_get_max_threads();
  const bool restart = !opt.restart.empty();

  // Rank 0 reads and validates the deck (and the dump) and partitions it; the others receive
  // the result.
  model::Model m;
  std::vector<int32_t> elem_rank;
  std::vector<char> dump_bytes;
  std::filesystem::path dump_path;
  const bool read_ok = rootStep(comm, [&] {
    m = model::readModel(opt.deck,
                         model::ReadOptions{.implicit_as_explicit = opt.implicit_as_explicit});
    refuseUnsupported(m, opt);
    if (opt.cycles > 0) m.controls.end_cycle = opt.cycles;
    if (!opt.restart_deck.empty()) model::readRestartDeck(opt.restart_deck, m.controls);
    if (opt.end_time) m.controls.end_time = *opt.end_time;
    if (!opt.energy_band.empty()) {
      const auto& b = opt.energy_band;
      if (b.size() != 2 || !(b[0] > 0.0) || !(b[0] < 1.0) || !(b[1] > 1.0) || !std::isfinite(b[1]))
        throw util::InputError("--energy-band LO,HI: needs 0 < LO < 1 < HI");
      m.controls.energy_ratio_min = b[0];
      m.controls.energy_ratio_max = b[1];
    }
    if (opt.strict && !m.unsupported.empty()) {
      throw util::InputError("--strict: the deck uses unsupported keywords:\n" +
                             model::formatUnsupported(m));
    }
    if (!(m.controls.end_time > 0.0) && m.controls.end_cycle <= 0)
      throw util::InputError(opt.deck +
                             ": *CONTROL_TERMINATION gives no end time (ENDTIM) or "
                             "cycle count (ENDCYC); pass --endtime to run anyway");
    if (restart) {
      dump_path = output::resolveDump(opt.restart);
      std::ifstream in(dump_path, std::ios::binary);
      if (!in) throw util::InputError("cannot open restart dump '" + dump_path.string() + "'");
      dump_bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      // Checked here, before anything is partitioned or any rank waits on it.
      const auto dump = output::decodeDump(dump_bytes, dump_path.string());
      // The dump's partition is reused at the same number of ranks: each rank then continues
      // its own partial energy sums, and glstat.csv stays bitwise that of the uninterrupted run.
      if (const auto it = dump.sections.find("partition"); it != dump.sections.end()) {
        util::ArchiveReader r(it->second);
        int32_t ranks = 0;
        std::vector<int32_t> owners;
        r.get(ranks);
        r.get(owners);
        if (ranks == comm.size() && owners.size() == m.numElements()) elem_rank = owners;
      }
    }
    if (elem_rank.empty()) {
      partition::Options popt;
      popt.method = partition::parseMethod(opt.partition);
      // Elements under contact segments carry the contact work too (docs/parallel.md).
      if (opt.contact_bias != 1.0 && !m.contacts.empty()) {
        popt.contact_bias = opt.contact_bias;
        popt.contact_elements.assign(m.numElements(), 0);
        for (const auto& c : m.contacts)
          for (const auto* side : {&c.a, &c.b})
            for (int64_t e : side->segment_element) popt.contact_elements[std::size_t(e)] = 1;
      }
      elem_rank = partition::partitionElements(m, comm.size(), popt);
    }
  });
  if (!read_ok) return 1;
  if (comm.distributed()) {
    // One archive: the model's bytes, then the element -> rank map.
    std::vector<char> bytes;
    if (root) {
      util::ArchiveWriter w;
      w.put(model::serialize(m));
      w.put(elem_rank);
      w.put(dump_path.string());
      bytes = std::move(w.bytes());
    }
    comm.broadcast(bytes);
    if (!root) {
      util::ArchiveReader r(bytes);
      std::vector<char> model_bytes;
      std::string path;
      r.get(model_bytes);
      r.get(elem_rank);
      r.get(path);
      dump_path = path;
      m = model::deserialize(model_bytes);
    }
    // Every rank takes its part from the same bytes (no shared file system needed).
    if (restart) comm.broadcast(dump_bytes);
  }
  output::DumpContents dump;
  if (restart) dump = output::decodeDump(dump_bytes, dump_path.string());
  dump_bytes.clear();
  dump_bytes.shrink_to_fit();

  domain::Subdomain sd;
  try {
    sd = domain::buildSubdomain(m, elem_rank, comm.rank(), comm.size());
  } catch (const std::exception& e) {
    // Every rank sees the same model and partition, so every rank fails alike.
    if (root) std::fprintf(stderr, "crumple: error: %s\n", e.what());
    return 1;
  }
  solver::Solver s(m, sd, comm);
  // Initialisation checks the initial geometry (inverted or degenerate elements) collectively:
  // a deck that cannot start fails here, before the results folder is touched.
  try {
    s.initialize();
  } catch (const util::NumericalError& e) {
    if (root) std::fprintf(stderr, "crumple: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    // Not known to be collective: the other ranks may wait in a collective.
    std::fprintf(stderr, "crumple: error (rank %d): %s\n", comm.rank(), e.what());
    if (comm.distributed()) comm.abort(1);
    return 1;
  }

  // A restart continues the dumped run in its own folder: the history files are cut back to
  // the dump and continued (ResultsWriter::loadState checks that they are that run's).
  const std::filesystem::path dir =
      !opt.output_dir.empty() ? std::filesystem::path(opt.output_dir)
      : restart
          ? dump_path.parent_path().empty() ? std::filesystem::path(".") : dump_path.parent_path()
          : std::filesystem::path(std::filesystem::path(opt.deck).stem().string() + ".out");
  std::error_code dir_ec;
  const bool dir_existed = std::filesystem::exists(dir, dir_ec);
  if (!restart && !rootStep(comm, [&] { output::prepareResultsDir(dir, opt.overwrite); })) return 1;
  if (restart && !rootStep(comm, [&] {
        if (!std::filesystem::is_directory(dir))
          throw util::InputError("results folder '" + dir.string() +
                                 "' of the restarted run does not exist");
      }))
    return 1;

  // run.log: a restart appends to the dumped run's log, but only once the dump and the folder
  // are accepted (a folder of another run is left untouched); until then lines wait here.
  std::ofstream log;
  std::string pending_log;
  auto openLog = [&] {
    if (!root) return;
    log.open(dir / "run.log", restart ? std::ios::app : std::ios::trunc);
    log << pending_log;
    log.flush();
    pending_log.clear();
  };
  auto say = [&](const std::string& text) {
    if (!root) return;
    if (!log.is_open()) {
      pending_log += text;
      return;
    }
    log << text;
    log.flush();
  };
  if (!restart) openLog();
  say(fmt::format("crumple {} — {} rank(s), {} thread(s) per rank, partition {}\n", CRUMPLE_VERSION,
                  comm.size(), threads, opt.partition));
  const std::string warn = warningsText(m);
  if (!warn.empty() && root) {
    std::fputs(warn.c_str(), stderr);
    say(warn);
  }
  output::RunInfo info;
  info.deck = opt.deck;
  for (const auto* u : answerChanging(m)) info.ignored_unsupported.push_back(u->feature);
  if (!info.ignored_unsupported.empty())
    say("--ignore-unsupported: this run leaves out what Crumple does not support, and its "
        "answer differs from the deck's:\n" +
        answerChangingText(m));
  info.ranks = comm.size();
  info.threads = threads;
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  std::signal(SIGUSR1, onSignal);

  std::unique_ptr<output::ResultsWriter> writer;
  // The sections of a restart dump (docs/reliability.md, "Restart"). Other state joins with one
  // add() each, e.g. contact: dumps.add({"contact", save, load, true}).
  output::DumpRegistry dumps;
  using Section = solver::Solver::StateSection;
  dumps.add({"partition",
             [&] {
               util::ArchiveWriter w;
               w.put<int32_t>(comm.size());
               w.put(elem_rank);
               return std::move(w.bytes());
             },
             // Read before the subdomain is built (above); nothing left to restore.
             [](const std::vector<char>&) {}});
  for (const auto& [name, section] :
       {std::pair{"solver", Section::Scalars}, std::pair{"nodes", Section::Nodes},
        std::pair{"elements", Section::Elements}, std::pair{"constraints", Section::Constraints}})
    dumps.add({name, [&s, section] { return s.saveState(section); },
               [&s, section](const std::vector<char>& b) { s.loadState(section, b); }});
  // Contact state is the same on every rank: rank 0's copy is dumped, every rank loads it.
  if (s.contact())
    dumps.add({"contact", [&] { return s.contact()->saveState(); },  // collective; rank 0's bytes
               [&](const std::vector<char>& b) { s.contact()->loadState(b); }});
  // Last: its load cuts the history files back, after every other section was accepted.
  dumps.add({"output", [&] { return writer->saveState(); },
             [&](const std::vector<char>& b) { writer->loadState(b, s.time()); }});
  // Writes a dump; a failure to write it is reported and the run goes on (the earlier dumps
  // are intact: dumps are renamed into place only when complete).
  auto writeDump = [&](const char* why) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto bytes = dumps.save(comm);
    const auto t1 = std::chrono::steady_clock::now();
    if (!root) return;
    try {
      const auto path = output::writeDumpFile(dir, s.cycle(), bytes);
      const auto t2 = std::chrono::steady_clock::now();
      say(fmt::format(
          "restart dump {} ({}) at cycle {}, time {:.6g}: {:.1f} MB, {:.3f} s to gather, {:.3f} s "
          "to write\n",
          path.filename().string(), why, s.cycle(), s.time(), double(bytes.size()) / 1e6,
          std::chrono::duration<double>(t1 - t0).count(),
          std::chrono::duration<double>(t2 - t1).count()));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "crumple: warning: %s; the run goes on\n", e.what());
      say(fmt::format("warning: {}; the run goes on\n", e.what()));
    }
  };

  int status = 0;
  const bool show = !opt.quiet && root;
  bool started = false;  // the first state is written: from here on, results are kept
  try {
    if (root) output::checkStream(log, dir / "run.log");
    say(modelSummary(m, s));
    if (root && s.contact() && !s.contact()->initialPenetrations().empty())
      std::fprintf(stderr,
                   "crumple: note: %zu initial contact penetration(s) %s (listed in run.log)\n",
                   s.contact()->initialPenetrations().size(),
                   s.contact()->movedInitialPenetrations() ? "moved back onto the surface"
                                                           : "kept as an offset (IGNORE)");
    writer = std::make_unique<output::ResultsWriter>(dir, m, s, comm, restart);
    // Set-up is over: each rank keeps its subdomain, nobody the whole mesh.
    m.releaseMesh();
    if (restart) {
      dumps.restore(dump, comm);
      dump = {};
      openLog();
      info.first_cycle = s.cycle();
      say(fmt::format("restart from {} at cycle {}, time {:.6g}\n", dump_path.string(), s.cycle(),
                      s.time()));
      // Dumps of later cycles belong to the continuation this restart replaces.
      if (root)
        for (const auto& p : output::dumpFiles(dir))
          if (output::dumpCycle(p) > s.cycle()) {
            std::error_code ec;
            std::filesystem::remove(p, ec);
            say(fmt::format("removed {}: written after the restart point\n", p.string()));
          }
    }
    output::Progress progress(stdout, show && isatty(STDOUT_FILENO), s.endTime());
    // The state at the dump was written by the dumped run.
    if (!restart) writer->write(s);
    started = true;
    info.setup_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    const int64_t dump_cycles = m.controls.d3dump_cycles;
    const bool dumping = dump_cycles > 0 || opt.checkpoint_every > 0.0;
    auto last_checkpoint = std::chrono::steady_clock::now();
    auto last_stop_check = last_checkpoint;
    while (!s.finished()) {
      s.step();
      writer->write(s);
      // The energy sums cost a pass over every node and element: refresh them sparingly.
      if (s.cycle() % 64 == 0) {
        const double ratio = s.energies().ratio;
        if (show) progress.update(s.cycle(), s.time(), s.dt(), ratio);
      }
      uint64_t request = 0;
      if (const int sig = g_signal.load(); sig != 0) request |= sig == SIGTERM ? kSigTerm : kSigInt;
      if (g_usr1.exchange(false)) request |= kSigUsr1;
      if (root) {
        const auto now = std::chrono::steady_clock::now();
        if (opt.checkpoint_every > 0.0 &&
            std::chrono::duration<double>(now - last_checkpoint).count() >= opt.checkpoint_every) {
          request |= kCheckpoint;
          last_checkpoint = now;
        }
        if (s.cycle() % kStopFileCycles == 0 ||
            std::chrono::duration<double>(now - last_stop_check).count() >= kStopFilePeriod) {
          std::string note;
          request |= readStopFile(dir, note);
          if (!note.empty()) {
            std::fputs(("crumple: warning: " + note).c_str(), stderr);
            say("warning: " + note);
          }
          last_stop_check = now;
        }
      }
      // A signal may reach only some ranks, the stop file is read by rank 0: agree.
      request = comm.orAll(request);
      if (request & kStatus) {
        const auto e = s.energies();
        const std::string line = fmt::format(
            "sw2: cycle {} time {:.6g} dt {:.4g} of end time {:.6g}; energy kinetic {:.6g} "
            "internal {:.6g} ratio {:.6f}; wall {:.1f} s\n",
            s.cycle(), s.time(), s.dt(), s.endTime(), e.kinetic, e.internal, e.ratio,
            std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count());
        if (root) {
          std::fputs(line.c_str(), stdout);
          std::fflush(stdout);
        }
        say(line);
      }
      const bool stop = (request & (kSigInt | kSigTerm | kStop)) != 0;
      const bool cycle_due = dump_cycles > 0 && s.cycle() % dump_cycles == 0 && !s.finished();
      if (stop || cycle_due || (request & (kSigUsr1 | kDump | kCheckpoint)))
        writeDump(request & kSigTerm      ? "SIGTERM"
                  : request & kSigInt     ? "SIGINT"
                  : request & kStop       ? "sense switch sw1"
                  : request & kDump       ? "sense switch sw3"
                  : request & kSigUsr1    ? "SIGUSR1"
                  : request & kCheckpoint ? "--checkpoint-every"
                                          : "*DATABASE_BINARY_D3DUMP");
      if (stop) {
        info.termination = "signal";
        if (request & (kSigInt | kSigTerm)) {
          status = request & kSigTerm ? 128 + SIGTERM : 128 + SIGINT;
          info.message = fmt::format(
              "interrupted by {}; a restart dump and the last state were "
              "written",
              request & kSigTerm ? "SIGTERM" : "SIGINT");
        } else {
          info.message =
              "stopped by sense switch sw1; a restart dump and the last state were "
              "written";
        }
        say(info.message + "\n");
        break;
      }
    }
    // A run that ends normally leaves a dump of its end state when dumps were asked for: a
    // restart deck with a later ENDTIM extends the run from it.
    if (dumping && info.termination == "normal") writeDump("end of run");
    writer->write(s, true);
    const double ratio = s.energies().ratio;
    if (show) progress.finish(s.cycle(), s.time(), s.dt(), ratio);
  } catch (const util::InputError& e) {
    // Restart problems (a dump of another deck, a results folder of another run) are found
    // by every rank together (DumpRegistry::restore), before the first cycle.
    if (root) std::fprintf(stderr, "crumple: error: %s\n", e.what());
    say(fmt::format("error: {}\n", e.what()));
    return 1;
  } catch (const util::NumericalError& e) {
    // Numerical failures are detected collectively: every rank is here together.
    info.termination = "error";
    info.message = e.what();
    status = 1;
    if (root) std::fprintf(stderr, "crumple: error: %s\n", e.what());
    say(fmt::format("error termination: {}\n", e.what()));
    if (writer) {
      try {
        writer->write(s, true);
      } catch (const std::exception& e2) {
        say(fmt::format("could not write the last state: {}\n", e2.what()));
      }
      // And a dump of the state at the failure (collective, like the failure): an analyst can
      // look at it, or continue from the last periodic dump with a restart deck.
      if (started) writeDump("error termination");
    }
  } catch (const std::exception& e) {
    // Anything else (an I/O failure on one rank) may leave the others waiting in a
    // collective: end them all. Before the first state nothing worth keeping was written:
    // what this run created goes (serially; under MPI the abort leaves no time to agree).
    std::fprintf(stderr, "crumple: error (rank %d): %s\n", comm.rank(), e.what());
    if (!started && !comm.distributed()) {
      log.close();
      output::removeRunOutput(dir, !dir_existed);
      return 1;
    }
    if (comm.distributed()) comm.abort(1);
    info.termination = "error";
    info.message = e.what();
    status = 1;
  }
  info.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const double output_s = writer ? writer->seconds() : 0.0;
  if (writer) {
    try {
      writer->writeSummary(s, info);
    } catch (const std::exception& e) {
      // A full disk: the summary is lost; say so and fail rather than end silently.
      if (root) std::fprintf(stderr, "crumple: error: %s\n", e.what());
      status = 1;
    }
  }
  const auto e = s.energies();
  say(fmt::format(
      "{} termination at time {:.6g}, cycle {}\nenergy: kinetic {:.6g} internal {:.6g} hourglass "
      "{:.6g} rigidwall {:.6g} external work {:.6g} ratio {:.6f}\n",
      info.termination, s.time(), s.cycle(), e.kinetic, e.internal, e.hourglass, e.rigidwall,
      e.external_work, e.ratio));
  if (const auto er = s.eroded(); er.elements > 0)
    say(
        fmt::format("eroded: {} element(s), mass {:.6g}, internal energy {:.6g}, hourglass energy "
                    "{:.6g}\n",
                    er.elements, er.mass, er.internal, er.hourglass));
  say(timingTable(s.timing(), output_s, info.wall_s));
  if (s.cycle() > info.first_cycle && info.wall_s > info.setup_s)
    say(fmt::format("set-up {:.3f} s; {:.3g} element-cycles per second in the cycle loop\n",
                    info.setup_s,
                    double(sd.global_elements) * double(s.cycle() - info.first_cycle) /
                        (info.wall_s - info.setup_s)));
  if (show) std::printf("%s termination; results in %s\n", info.termination.c_str(), dir.c_str());
  if (root && !log) {
    std::fprintf(stderr, "crumple: error: error while writing '%s'\n", (dir / "run.log").c_str());
    status = 1;
  }
  return status;
}

}  // namespace crumple::app
