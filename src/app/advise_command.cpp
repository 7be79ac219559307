#include "app/advise_command.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "comm/communicator.hpp"
#include "domain/subdomain.hpp"
#include "model/build.hpp"
#include "partition/advice.hpp"
#include "solver/solver.hpp"

namespace crumple::app {

namespace {

// Cycles run before timing starts: the first contact sort and the first-touch of every array
// are not the steady cycle.
constexpr int kWarmUpCycles = 10;

struct Snapshot {
  solver::Timing timing;
  double search_s = 0, replicated_s = 0, wall_s = 0;
};

Snapshot snapshot(const solver::Solver& s, std::chrono::steady_clock::time_point t0) {
  Snapshot out{s.timing(), 0, 0,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
  if (const auto* c = s.contact()) {
    out.search_s = c->statistics().search_s;
    out.replicated_s = c->statistics().replicated_s;
  }
  return out;
}

// The deck's serial cycle on one thread, split as partition::CycleCosts wants it; `cycles`
// is set to the cycles timed (fewer when the deck ends first).
partition::CycleCosts timeSerialCycle(const model::Model& m, int& cycles) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  comm::Communicator serial;
  domain::Subdomain sd = domain::buildSubdomain(m, std::vector<int32_t>(m.numElements(), 0), 0, 1);
  solver::Solver s(m, sd, serial);
  s.initialize();
  for (int i = 0; i < kWarmUpCycles && !s.finished(); ++i) s.step();
  const auto t0 = std::chrono::steady_clock::now();
  const Snapshot a = snapshot(s, t0);
  int done = 0;
  for (; done < cycles && !s.finished(); ++done) s.step();
  const Snapshot b = snapshot(s, t0);
  omp_set_num_threads(threads);
  if (done == 0) throw std::runtime_error("the deck ends before any cycle could be timed");
  cycles = done;
  const double n = done;
  partition::CycleCosts c;
  c.elements_s = (b.timing.elements - a.timing.elements) / n;
  const double contact = (b.timing.contact - a.timing.contact) / n;
  c.contact_replicated_s = std::min(contact, (b.replicated_s - a.replicated_s) / n);
  c.contact_split_s = contact - c.contact_replicated_s;
  c.nodes_s = std::max(0.0, (b.wall_s - a.wall_s) / n - c.elements_s - contact);
  return c;
}

// The serial cycle averaged over a whole run made before (its summary.json): the contact of a
// crash grows as it folds, and a sample of the first cycles sees little of it
// (docs/parallel.md, "How many ranks"). One rank of one thread, so every second is work.
partition::CycleCosts runCycleCosts(const std::string& dir, int& cycles) {
  const std::filesystem::path path = std::filesystem::path(dir) / "summary.json";
  std::ifstream f(path);
  if (!f) throw std::runtime_error("--from-run: cannot read " + path.string());
  nlohmann::json s;
  try {
    s = nlohmann::json::parse(f);
    const int ranks = s.at("ranks").get<int>(), threads = s.at("threads").get<int>();
    if (ranks != 1 || threads != 1)
      throw std::runtime_error(fmt::format(
          "--from-run: {} is a run on {} rank(s) of {} thread(s); the serial cycle needs a run "
          "on 1 rank of 1 thread (crumple run DECK --threads 1)",
          path.string(), ranks, threads));
    const auto n = s.at("cycles").get<double>();
    if (!(n > 0)) throw std::runtime_error("--from-run: " + path.string() + " ran no cycles");
    const auto& t = s.at("timing");
    partition::CycleCosts c;
    c.elements_s = t.at("elements").get<double>() / n;
    const double contact = t.at("contact").get<double>() / n;
    const double search = s.contains("contact") ? s["contact"].at("search_s").get<double>() / n : 0;
    c.contact_split_s = std::min(contact, search);
    c.contact_replicated_s = contact - c.contact_split_s;
    const double loop =
        s.at("wall_s").get<double>() - s.at("setup_s").get<double>() - t.at("output").get<double>();
    c.nodes_s = std::max(0.0, loop / n - c.elements_s - contact);
    cycles = int(n);
    return c;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error("--from-run: " + path.string() + ": " + e.what());
  }
}

std::vector<partition::Prediction> predictAll(const model::Model& m, const AdviseOptions& opt,
                                              const partition::CycleCosts& serial,
                                              const partition::Network& net) {
  partition::Options popt;
  popt.method = partition::parseMethod(opt.method);
  partition::CommModel cm;
  cm.latency_s = net.latency_s;
  cm.bandwidth_bytes_per_s = net.bandwidth_bytes_per_s;
  std::vector<partition::Prediction> out;
  for (int p : partition::candidateRanks(opt.max_ranks)) {
    if (std::size_t(p) > m.numElements()) break;
    const auto rank = partition::partitionElements(m, p, popt);
    out.push_back(partition::predict(partition::computeStats(m, rank, p, cm), serial, net,
                                     !m.contacts.empty()));
  }
  return out;
}

void printAdvice(std::FILE* out, const std::vector<partition::Prediction>& preds, int best,
                 const partition::Network& net) {
  fmt::print(out, "{:>6} {:>10} {:>9} {:>6} {:>11} {:>8} {:>10} {:>8}\n", "ranks", "elem/rank",
             "imbalance", "neigh", "us/cycle", "speed-up", "efficiency", "comm");
  for (const auto& p : preds)
    fmt::print(out, "{:>6} {:>10} {:>8.1f}% {:>6} {:>11.1f} {:>8.2f} {:>9.0f}% {:>7.1f}%{}\n",
               p.ranks, p.max_elements, 100 * p.imbalance, p.max_neighbours, 1e6 * p.cycle_s,
               p.speedup, 100 * p.efficiency, 100 * p.comm_share, p.ranks == best ? "  <-" : "");
  const auto& b =
      *std::find_if(preds.begin(), preds.end(), [&](const auto& p) { return p.ranks == best; });
  fmt::print(out,
             "advice: {} rank{} (the most ranks whose predicted efficiency is at least 80%: "
             "{:.0f}%, communication {:.1f}% of the cycle{})\n",
             best, best == 1 ? "" : "s", 100 * b.efficiency, 100 * b.comm_share,
             b.comm_share <= 0.1 ? ", within the seed's 10% rule" : "");
  fmt::print(out, "network: {}\n",
             net.measured ? fmt::format("measured by ping-pong: latency {:.2f} us, bandwidth "
                                        "{:.2f} GB/s",
                                        1e6 * net.latency_s, 1e-9 * net.bandwidth_bytes_per_s)
                          : fmt::format("not measured (run under `mpirun -np 2` to measure): "
                                        "assumed latency {:.1f} us, bandwidth {:.1f} GB/s",
                                        1e6 * net.latency_s, 1e-9 * net.bandwidth_bytes_per_s));
}

nlohmann::json adviceJson(const std::vector<partition::Prediction>& preds, int best,
                          const partition::CycleCosts& serial, const partition::Network& net,
                          int cycles, const std::string& from_run) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& p : preds)
    rows.push_back({{"ranks", p.ranks},
                    {"max_elements", p.max_elements},
                    {"imbalance", p.imbalance},
                    {"max_neighbours", p.max_neighbours},
                    {"elements_s", p.elements_s},
                    {"nodes_s", p.nodes_s},
                    {"contact_s", p.contact_s},
                    {"comm_s", p.comm_s},
                    {"cycle_s", p.cycle_s},
                    {"speedup", p.speedup},
                    {"efficiency", p.efficiency},
                    {"comm_share", p.comm_share}});
  return {{"recommended_ranks", best},
          {"min_efficiency", 0.8},
          {"serial_cycle",
           {{"source", from_run.empty() ? "sample" : "run"},
            {"run", from_run.empty() ? nlohmann::json() : nlohmann::json(from_run)},
            {"cycles_timed", cycles},
            {"elements_s", serial.elements_s},
            {"nodes_s", serial.nodes_s},
            {"contact_split_s", serial.contact_split_s},
            {"contact_replicated_s", serial.contact_replicated_s}}},
          {"network",
           {{"measured", net.measured},
            {"latency_s", net.latency_s},
            {"bandwidth_bytes_per_s", net.bandwidth_bytes_per_s}}},
          {"predictions", rows}};
}

std::filesystem::path outputFolder(const AdviseOptions& opt) {
  const std::filesystem::path dir =
      opt.out_dir.empty()
          ? std::filesystem::path(std::filesystem::path(opt.deck).stem().string() + ".partition")
          : std::filesystem::path(opt.out_dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw std::runtime_error("cannot create folder " + dir.string() +
                             (ec ? ": " + ec.message() : std::string()));
  return dir;
}

}  // namespace

int adviseCommand(const AdviseOptions& opt, std::FILE* out) {
  const comm::LinkSpeed link = comm::pingPong(comm::world());
  if (!comm::world().isRoot()) return 0;
  try {
    partition::Network net;
    if (link.measured) net = {link.latency_s, link.bandwidth_bytes_per_s, true};
    const model::Model m = model::readModel(opt.deck);
    int cycles = opt.sample_cycles;
    const partition::CycleCosts serial =
        opt.from_run.empty() ? timeSerialCycle(m, cycles) : runCycleCosts(opt.from_run, cycles);
    const auto preds = predictAll(m, opt, serial, net);
    const int best = partition::recommend(preds);
    fmt::print(out,
               "deck: {}\n{} elements, {} nodes; serial cycle {:.1f} us on one thread "
               "(elements {:.1f}, nodes {:.1f}, contact {:.1f}; {} cycles {})\n",
               m.deck_path, m.numElements(), m.nodes.size(), 1e6 * serial.total(),
               1e6 * serial.elements_s, 1e6 * serial.nodes_s,
               1e6 * (serial.contact_split_s + serial.contact_replicated_s), cycles,
               opt.from_run.empty() ? "timed" : "of the run in " + opt.from_run);
    printAdvice(out, preds, best, net);
    const auto path = outputFolder(opt) / "advise.json";
    std::ofstream f(path);
    f << adviceJson(preds, best, serial, net, cycles, opt.from_run).dump(2) << "\n";
    if (!f) throw std::runtime_error("cannot write " + path.string());
    fmt::print(out, "wrote {}\n", path.string());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crumple: error: %s\n", e.what());
    return 1;
  }
}

}  // namespace crumple::app
