#include "app/commands.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>

#include "comm/communicator.hpp"
#include "domain/subdomain.hpp"
#include "model/build.hpp"
#include "model/serialize.hpp"
#include "output/files.hpp"
#include "output/results.hpp"
#include "partition/partition.hpp"
#include "solver/solver.hpp"
#include "util/archive.hpp"
#include "util/error.hpp"

namespace crumple::app {

namespace {

std::atomic<bool> g_interrupted{false};
extern "C" void onSignal(int) {
  g_interrupted = true;
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

int checkCommand(const CheckOptions& opt, std::FILE* out) {
  // First the strict read a run would do; if it refuses the deck, read again tolerantly so
  // the user still gets the whole list of what is not supported.
  std::string refusal;
  model::Model m;
  try {
    m = model::readModel(opt.deck);
  } catch (const util::InputError& e) {
    refusal = e.what();
    try {
      m = model::readModel(opt.deck, model::ReadOptions{.allow_unsupported = true});
    } catch (const std::exception& e2) {
      std::fprintf(stderr, "crumple: error: %s\n", e2.what());
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crumple: error: %s\n", e.what());
    return 1;
  }
  try {
    const std::string warn = warningsText(m);
    if (!refusal.empty()) {
      std::fprintf(out, "deck: %s\nnodes: %zu\nsolid elements: %zu\n", m.deck_path.c_str(),
                   m.nodes.size(), m.solids.size());
      std::fputs(warn.c_str(), out);
      std::fprintf(stderr, "crumple: error: this deck cannot run yet: %s\n", refusal.c_str());
      return 1;
    }
    auto sd = domain::buildSerialSubdomain(m);
    solver::Solver s(m, sd, comm::world());
    s.initialize();
    std::fputs(modelSummary(m, s).c_str(), out);
    std::fputs(warn.empty() ? "everything in the deck is supported\n" : warn.c_str(), out);
    if (opt.strict && !m.unsupported.empty()) {
      std::fprintf(stderr, "crumple: error: --strict: the deck uses %zu unsupported keyword(s)\n",
                   m.unsupported.size());
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crumple: error: %s\n", e.what());
    return 1;
  }
}

namespace {

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

int runCommand(const RunOptions& opt) {
  const auto wall0 = std::chrono::steady_clock::now();
  auto& comm = comm::world();
  const bool root = comm.isRoot();
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  const int threads = omp_get_max_threads();

  // Rank 0 reads and validates the deck and partitions it; the others receive the result.
  model::Model m;
  std::vector<int32_t> elem_rank;
  const bool read_ok = rootStep(comm, [&] {
    m = model::readModel(opt.deck);
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
    partition::Options popt;
    popt.method = partition::parseMethod(opt.partition);
    elem_rank = partition::partitionElements(m, comm.size(), popt);
  });
  if (!read_ok) return 1;
  if (comm.distributed()) {
    // One archive: the model's bytes, then the element -> rank map.
    std::vector<char> bytes;
    if (root) {
      util::ArchiveWriter w;
      w.put(model::serialize(m));
      w.put(elem_rank);
      bytes = std::move(w.bytes());
    }
    comm.broadcast(bytes);
    if (!root) {
      util::ArchiveReader r(bytes);
      std::vector<char> model_bytes;
      r.get(model_bytes);
      r.get(elem_rank);
      m = model::deserialize(model_bytes);
    }
  }

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

  const std::filesystem::path dir =
      opt.output_dir.empty()
          ? std::filesystem::path(std::filesystem::path(opt.deck).stem().string() + ".out")
          : std::filesystem::path(opt.output_dir);
  std::error_code dir_ec;
  const bool dir_existed = std::filesystem::exists(dir, dir_ec);
  if (!rootStep(comm, [&] { output::prepareResultsDir(dir, opt.overwrite); })) return 1;

  std::ofstream log;
  if (root) log.open(dir / "run.log");
  auto say = [&](const std::string& text) {
    if (!root) return;
    log << text;
    log.flush();
  };
  say(fmt::format("crumple {} — {} rank(s), {} thread(s) per rank, partition {}\n", CRUMPLE_VERSION,
                  comm.size(), threads, opt.partition));
  const std::string warn = warningsText(m);
  if (!warn.empty() && root) {
    std::fputs(warn.c_str(), stderr);
    say(warn);
  }
  output::RunInfo info;
  info.deck = opt.deck;
  info.ranks = comm.size();
  info.threads = threads;
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);

  std::unique_ptr<output::ResultsWriter> writer;
  int status = 0;
  const bool show = !opt.quiet && root;
  bool started = false;  // the first state is written: from here on, results are kept
  try {
    if (root) output::checkStream(log, dir / "run.log");
    say(modelSummary(m, s));
    writer = std::make_unique<output::ResultsWriter>(dir, m, s, comm);
    // Set-up is over: each rank keeps its subdomain, nobody the whole mesh.
    m.releaseMesh();
    output::Progress progress(stdout, show && isatty(STDOUT_FILENO), s.endTime());
    writer->write(s);
    started = true;
    info.setup_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    while (!s.finished()) {
      s.step();
      writer->write(s);
      // The energy sums cost a pass over every node and element: refresh them sparingly.
      if (s.cycle() % 64 == 0) {
        const double ratio = s.energies().ratio;
        if (show) progress.update(s.cycle(), s.time(), s.dt(), ratio);
      }
      // A signal may reach only some ranks: stop together.
      if (comm.anyAll(g_interrupted)) {
        info.termination = "signal";
        info.message = "interrupted by a signal; the last state was written";
        status = 1;
        break;
      }
    }
    writer->write(s, true);
    const double ratio = s.energies().ratio;
    if (show) progress.finish(s.cycle(), s.time(), s.dt(), ratio);
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
  if (s.cycle() > 0 && info.wall_s > info.setup_s)
    say(fmt::format("set-up {:.3f} s; {:.3g} element-cycles per second in the cycle loop\n",
                    info.setup_s,
                    double(sd.global_elements) * double(s.cycle()) / (info.wall_s - info.setup_s)));
  if (show) std::printf("%s termination; results in %s\n", info.termination.c_str(), dir.c_str());
  if (root && !log) {
    std::fprintf(stderr, "crumple: error: error while writing '%s'\n", (dir / "run.log").c_str());
    status = 1;
  }
  return status;
}

}  // namespace crumple::app
