// Reading a keyword deck: bytes of keyword text per second, for the reader alone (lines,
// keywords, *INCLUDE; deck::readDeck) and for the whole model build that `crumple check`
// starts with (every card parsed, ids resolved, model::readModel). The deck is the whole-run
// benchmark deck of tools/make_bench_deck.py (an elastic-plastic block of NX x NY x NZ hexes
// on a stonewall, *NODE I8,3E16.9,2I8 and *ELEMENT_SOLID 10I8), written here to a temp file.
// Run (docs/performance.md quotes its output):
//   build/release/bench/crumple_bench --benchmark_filter=Deck
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "deck/deck.hpp"
#include "model/build.hpp"
#include "temp_dir.hpp"

namespace {

using namespace crumple;

// The deck of make_bench_deck.py for an nx x ny x nz block of 1 mm hexes.
std::string benchDeck(int nx, int ny, int nz) {
  std::string s =
      "*KEYWORD\n*TITLE\nbenchmark block\n*CONTROL_TERMINATION\n 0.0282493\n"
      "*CONTROL_HOURGLASS\n         2       0.1\n*PART\nsteel block\n         1         1         "
      "1\n*SECTION_SOLID\n         1         1\n*MAT_PIECEWISE_LINEAR_PLASTICITY\n         1   "
      "7.85e-6     210.0       0.3      0.25       2.0\n*RIGIDWALL_PLANAR\n         0\n       "
      "0.0       0.0       0.0       0.0       0.0       1.0       0.0\n*NODE\n";
  const auto id = [&](int i, int j, int k) { return 1 + i + (nx + 1) * (j + (ny + 1) * k); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}{:8d}{:8d}\n", id(i, j, k), double(i),
                         double(j), double(k), 0, 0);
  s += "*ELEMENT_SOLID\n";
  int e = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        s +=
            fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", ++e, 1, id(i, j, k),
                        id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                        id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1));
  return s + "*END\n";
}

// The 40 x 31 x 25 block (31,000 hexes, 5 MB), written once per process.
const std::filesystem::path& deckFile() {
  static const testing::TempDir dir("crumple_bench_deck");
  static const std::filesystem::path path = [] {
    const auto p = dir.path() / "block.k";
    std::ofstream(p) << benchDeck(40, 31, 25);
    return p;
  }();
  return path;
}

// `read(path)` once per iteration, counted as the deck's bytes.
template <class Read>
void readDeckBench(benchmark::State& state, Read read) {
  const auto& path = deckFile();
  const auto bytes = static_cast<int64_t>(std::filesystem::file_size(path));
  for (auto _ : state) benchmark::DoNotOptimize(read(path));
  state.SetBytesProcessed(state.iterations() * bytes);
}

void BM_DeckRead(benchmark::State& state) {
  readDeckBench(state, [](const auto& p) { return deck::readDeck(p); });
}
BENCHMARK(BM_DeckRead)->Unit(benchmark::kMillisecond);

void BM_DeckReadModel(benchmark::State& state) {
  readDeckBench(state, [](const auto& p) { return model::readModel(p); });
}
BENCHMARK(BM_DeckReadModel)->Unit(benchmark::kMillisecond);

}  // namespace
