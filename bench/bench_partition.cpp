// Partition quality and cost at the seed's scale: a 250k-element model over 32..1024 ranks.
// Until shells exist, the "250k-shell-equivalent" model is a 500x500x1 plate of hexahedra
// (one layer, so its dual graph is planar like a shell mesh's); a 64^3 brick (262k solids)
// gives the solid case. Timing is the partition call (dual graph + METIS/RCB); counters are
// the partition statistics (computeStats, not timed):
//   load_imbalance         max rank weight / mean - 1
//   shared_node_fraction   nodes held by > 1 rank / all nodes
//   comm_to_compute        modelled, max over ranks (docs/parallel.md)
//   elements_per_rank, edge_cut, max_neighbours
// Run (docs/parallel.md quotes its output):
//   build/release/bench/crumple_bench --benchmark_filter=Partition
#include <benchmark/benchmark.h>

#include <algorithm>

#include "brick_model.hpp"
#include "model/model.hpp"
#include "partition/partition.hpp"

namespace {

using namespace crumple;

model::Model hexGrid(int nx, int ny, int nz) {
  return testing::brickModel(nx, ny, nz);
}

const model::Model& plate() {
  static const model::Model m = hexGrid(500, 500, 1);
  return m;
}
const model::Model& cube() {
  static const model::Model m = hexGrid(64, 64, 64);
  return m;
}

void run(benchmark::State& state, const model::Model& m, partition::Method method) {
  const int parts = int(state.range(0));
  partition::Options opt;
  opt.method = method;
  std::vector<int32_t> rank;
  for (auto _ : state) {
    rank = partition::partitionElements(m, parts, opt);
    benchmark::DoNotOptimize(rank.data());
  }
  const auto s = partition::computeStats(m, rank, parts);
  std::size_t max_nb = 0;
  for (const auto& r : s.ranks) max_nb = std::max(max_nb, r.neighbours.size());
  state.counters["elements_per_rank"] = double(s.elements) / parts;
  state.counters["load_imbalance"] = s.load_imbalance;
  state.counters["shared_node_fraction"] = double(s.shared_nodes_total) / double(s.nodes);
  state.counters["comm_to_compute"] = s.comm_to_compute;
  state.counters["edge_cut"] = double(s.edge_cut);
  state.counters["max_neighbours"] = double(max_nb);
}

void PartitionPlateMetis(benchmark::State& s) {
  run(s, plate(), partition::Method::Metis);
}
void PartitionPlateRcb(benchmark::State& s) {
  run(s, plate(), partition::Method::Rcb);
}
void PartitionCubeMetis(benchmark::State& s) {
  run(s, cube(), partition::Method::Metis);
}
void PartitionCubeRcb(benchmark::State& s) {
  run(s, cube(), partition::Method::Rcb);
}

void PartitionDualGraphPlate(benchmark::State& state) {
  for (auto _ : state) {
    auto g = partition::buildDualGraph(plate());
    benchmark::DoNotOptimize(g.adjncy.data());
  }
  state.counters["ns_per_element"] =
      benchmark::Counter(double(plate().solids.size()) * double(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// 32..256 ranks as the seed's study asks; 1024 puts ~250 elements on a rank (the shell rule).
void rankCounts(benchmark::internal::Benchmark* b) {
  for (int parts : {32, 64, 128, 256, 1024}) b->Arg(parts);
  b->Iterations(2)->Unit(benchmark::kMillisecond);
}
BENCHMARK(PartitionPlateMetis)->Apply(rankCounts);
BENCHMARK(PartitionPlateRcb)->Apply(rankCounts);
BENCHMARK(PartitionCubeMetis)->Apply(rankCounts);
BENCHMARK(PartitionCubeRcb)->Apply(rankCounts);
BENCHMARK(PartitionDualGraphPlate)->Unit(benchmark::kMillisecond);

}  // namespace
