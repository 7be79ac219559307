#include "app/partition_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>
#include <numeric>
#include <vector>

#include "model/build.hpp"
#include "partition/partition.hpp"

namespace crumple::app {

namespace {

// At most this many neighbour ranks are listed in a table cell; the rest are counted.
constexpr std::size_t kListedNeighbours = 8;
// Beyond this many ranks the table shows the heaviest and lightest ranks only.
constexpr int kFullTableRanks = 64;

std::string neighbourList(const std::vector<int>& nb) {
  std::string s;
  for (std::size_t i = 0; i < nb.size() && i < kListedNeighbours; ++i)
    s += fmt::format("{}{}", i ? "," : "", nb[i]);
  if (nb.size() > kListedNeighbours) s += fmt::format(",+{}", nb.size() - kListedNeighbours);
  return s.empty() ? "-" : s;
}

void printTable(const partition::Stats& s, std::FILE* out) {
  fmt::print(out, "{:>6} {:>10} {:>10} {:>9} {:>8}  {}\n", "rank", "elements", "weight", "nodes",
             "shared", "neighbours");
  auto row = [&](const partition::RankStats& r) {
    fmt::print(out, "{:>6} {:>10} {:>10.1f} {:>9} {:>8}  {}\n", r.rank, r.elements, r.weight,
               r.nodes, r.shared_nodes, neighbourList(r.neighbours));
  };
  if (s.parts <= kFullTableRanks) {
    for (const auto& r : s.ranks) row(r);
    return;
  }
  // Five heaviest and five lightest, in rank order within each group.
  std::vector<std::size_t> order(s.ranks.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return s.ranks[a].weight > s.ranks[b].weight;
  });
  fmt::print(out, "  heaviest:\n");
  for (std::size_t i = 0; i < 5; ++i) row(s.ranks[order[i]]);
  fmt::print(out, "  lightest:\n");
  for (std::size_t i = order.size() - 5; i < order.size(); ++i) row(s.ranks[order[i]]);
  fmt::print(out, "  ({} more ranks in partition.json)\n", s.parts - 10);
}

}  // namespace

int partitionCommand(const std::string& deck, int parts, const std::string& out_dir,
                     const std::string& method, std::FILE* out) {
  try {
    partition::Options opt;
    opt.method = partition::parseMethod(method);
    const model::Model m = model::readModel(deck);
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<int32_t> rank = partition::partitionElements(m, parts, opt);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const partition::Stats s = partition::computeStats(m, rank, parts);

    const std::filesystem::path dir =
        out_dir.empty()
            ? std::filesystem::path(std::filesystem::path(deck).stem().string() + ".partition")
            : std::filesystem::path(out_dir);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
      throw std::runtime_error("cannot create folder " + dir.string() +
                               (ec ? ": " + ec.message() : std::string()));
    const std::string name = partition::methodName(opt.method);
    partition::writePartitionJson(dir / "partition.json", s, name);
    partition::writePartitionVtu(dir / "partition.vtu", m, rank);

    fmt::print(out, "deck: {}\n{} elements, {} nodes over {} ranks ({}, {:.3f} s)\n", m.deck_path,
               s.elements, s.nodes, parts, name, seconds);
    printTable(s, out);
    fmt::print(out, "load imbalance: {:.2f}% (max weight / mean - 1)\n", 100.0 * s.load_imbalance);
    fmt::print(out, "edge cut: {} shared faces\n", s.edge_cut);
    fmt::print(out, "shared nodes: {} of {} ({:.1f}%)\n", s.shared_nodes_total, s.nodes,
               s.nodes > 0 ? 100.0 * double(s.shared_nodes_total) / double(s.nodes) : 0.0);
    fmt::print(out, "modelled communication/compute: {:.1f}% (rank {}; docs/parallel.md)\n",
               100.0 * s.comm_to_compute, s.comm_to_compute_rank);
    fmt::print(out, "wrote {} and {}\n", (dir / "partition.json").string(),
               (dir / "partition.vtu").string());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crumple: error: %s\n", e.what());
    return 1;
  }
}

}  // namespace crumple::app
