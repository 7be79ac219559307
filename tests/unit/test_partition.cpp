// Unit tests of src/partition: the dual graph (against METIS's own METIS_MeshToDual), METIS and
// RCB partitions (balance, determinism, every rank non-empty), the statistics and their files,
// and the `crumple partition` command on an example deck.
#include <gtest/gtest.h>
#include <metis.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "app/partition_command.hpp"
#include "partition/advice.hpp"
#include "partition/partition.hpp"
#include "partition_fixtures.hpp"
#include "util/error.hpp"

namespace {

namespace fs = std::filesystem;
using namespace crumple;
using crumple::test::brick;
using crumple::test::brickOf;
using crumple::test::Shape;

class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    dir_ = fs::temp_directory_path() / ("crumple_test_partition_" + std::to_string(::getpid()) +
                                        "_" + std::to_string(counter++));
    fs::create_directories(dir_);
  }
  ~TempDir() { fs::remove_all(dir_); }
  const fs::path& path() const { return dir_; }

 private:
  fs::path dir_;
};

std::vector<int64_t> row(const partition::DualGraph& g, std::size_t e) {
  return {g.adjncy.begin() + g.xadj[e], g.adjncy.begin() + g.xadj[e + 1]};
}

void expectWellFormed(const partition::DualGraph& g, std::size_t ne) {
  ASSERT_EQ(g.xadj.size(), ne + 1);
  ASSERT_EQ(g.xadj.front(), 0);
  ASSERT_EQ(std::size_t(g.xadj.back()), g.adjncy.size());
  for (std::size_t e = 0; e < ne; ++e) {
    const auto r = row(g, e);
    for (std::size_t i = 0; i < r.size(); ++i) {
      ASSERT_NE(r[i], int64_t(e)) << "self loop at " << e;
      if (i) {
        ASSERT_LT(r[i - 1], r[i]) << "row " << e << " not strictly ascending";
      }
      const auto back = row(g, std::size_t(r[i]));
      ASSERT_TRUE(std::binary_search(back.begin(), back.end(), int64_t(e)))
          << "asymmetric edge " << e << "-" << r[i];
    }
  }
}

// METIS_MeshToDual on the distinct nodes of every element, as sorted adjacency rows.
std::vector<std::vector<int64_t>> metisDual(const model::Model& m, idx_t ncommon) {
  std::vector<idx_t> eptr{0}, eind;
  for (const auto& n : m.solids.nodes) {
    std::set<int32_t> d(n.begin(), n.end());
    for (int32_t v : n)
      if (d.erase(v)) eind.push_back(v);
    eptr.push_back(idx_t(eind.size()));
  }
  idx_t ne = idx_t(m.solids.size()), nn = idx_t(m.nodes.size()), numflag = 0;
  idx_t *xadj = nullptr, *adjncy = nullptr;
  EXPECT_EQ(
      METIS_MeshToDual(&ne, &nn, eptr.data(), eind.data(), &ncommon, &numflag, &xadj, &adjncy),
      METIS_OK);
  std::vector<std::vector<int64_t>> rows(m.solids.size());
  for (std::size_t e = 0; e < rows.size(); ++e) {
    rows[e].assign(adjncy + xadj[e], adjncy + xadj[e + 1]);
    std::sort(rows[e].begin(), rows[e].end());
  }
  METIS_Free(xadj);
  METIS_Free(adjncy);
  return rows;
}

void expectSameAsMetis(const model::Model& m, idx_t ncommon) {
  const auto g = partition::buildDualGraph(m);
  expectWellFormed(g, m.solids.size());
  const auto ref = metisDual(m, ncommon);
  int64_t edges = 0;
  for (std::size_t e = 0; e < m.solids.size(); ++e) {
    ASSERT_EQ(row(g, e), ref[e]) << "element " << e;
    edges += int64_t(ref[e].size());
  }
  EXPECT_EQ(g.numEdges(), edges / 2);
}

partition::Options withMethod(partition::Method m) {
  partition::Options o;
  o.method = m;
  return o;
}

double maxOverMean(const std::vector<double>& w) {
  double mx = 0, sum = 0;
  for (double v : w) {
    mx = std::max(mx, v);
    sum += v;
  }
  return mx / (sum / double(w.size())) - 1.0;
}

// ---- dual graph -----------------------------------------------------------------------------

TEST(PartitionDualGraph, BrickCornerHasThreeNeighboursCentreSix) {
  const auto m = brick(3, 3, 3);
  const auto g = partition::buildDualGraph(m);
  expectWellFormed(g, 27);
  EXPECT_EQ(row(g, 0), (std::vector<int64_t>{1, 3, 9}));
  EXPECT_EQ(row(g, 13), (std::vector<int64_t>{4, 10, 12, 14, 16, 22}));
  EXPECT_EQ(g.numEdges(), 3 * 3 * 3 * 2);  // 3 directions x (2 interior faces x 9 lines)
}

TEST(PartitionDualGraph, HexBrickMatchesMetisMeshToDual) {
  expectSameAsMetis(brick(6, 5, 4), 4);
}

TEST(PartitionDualGraph, WedgeBrickMatchesMetisMeshToDual) {
  // Conforming prisms share a quad (4 nodes) or a triangle (3 nodes); elements meeting only
  // along an edge share 2, so ncommon = 3 is face adjacency here.
  const auto m = brickOf(Shape::Wedge, 4, 3, 3);
  expectSameAsMetis(m, 3);
  // An interior prism: two triangles (y neighbours), three quads (its partner and x/z cubes).
  const auto g = partition::buildDualGraph(m);
  for (std::size_t e = 0; e < m.solids.size(); ++e) EXPECT_LE(g.xadj[e + 1] - g.xadj[e], 5);
}

TEST(PartitionDualGraph, TetBrickMatchesMetisMeshToDual) {
  // Both tetrahedron conventions (n4=...=n8 and n3=n4, n5=...=n8) occur in this mesh.
  const auto m = brickOf(Shape::Tet, 3, 3, 2);
  expectSameAsMetis(m, 3);
  const auto g = partition::buildDualGraph(m);
  for (std::size_t e = 0; e < m.solids.size(); ++e) EXPECT_LE(g.xadj[e + 1] - g.xadj[e], 4);
  // Interior tetrahedra of a Kuhn mesh have all four face neighbours.
  int64_t full = 0;
  for (std::size_t e = 0; e < m.solids.size(); ++e) full += g.xadj[e + 1] - g.xadj[e] == 4;
  EXPECT_GT(full, 0);
}

TEST(PartitionDualGraph, LargeBrickHasExactlyTheGridNeighbours) {
  const int n = 40;  // 64,000 elements: the linear-time build keeps this quick
  const auto m = brick(n, n, n);
  const auto g = partition::buildDualGraph(m);
  ASSERT_EQ(g.numVertices(), std::size_t(n) * n * n);
  EXPECT_EQ(g.numEdges(), int64_t(3) * (n - 1) * n * n);
  std::vector<int64_t> expect;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int64_t e = i + int64_t(n) * (j + int64_t(n) * k);
        expect.clear();
        if (k > 0) expect.push_back(e - n * n);
        if (j > 0) expect.push_back(e - n);
        if (i > 0) expect.push_back(e - 1);
        if (i < n - 1) expect.push_back(e + 1);
        if (j < n - 1) expect.push_back(e + n);
        if (k < n - 1) expect.push_back(e + n * n);
        ASSERT_EQ(row(g, std::size_t(e)), expect) << "element " << e;
      }
}

TEST(PartitionDualGraph, EmptyAndDisconnectedMeshes) {
  model::Model empty;
  const auto g0 = partition::buildDualGraph(empty);
  EXPECT_EQ(g0.xadj, std::vector<int64_t>{0});
  EXPECT_TRUE(g0.adjncy.empty());
  const auto m = test::merged(brick(2, 1, 1), brickOf(Shape::Hex, 1, 1, 1, {5, 0, 0}));
  const auto g = partition::buildDualGraph(m);
  EXPECT_EQ(row(g, 0), std::vector<int64_t>{1});
  EXPECT_EQ(row(g, 1), std::vector<int64_t>{0});
  EXPECT_TRUE(row(g, 2).empty());
}

// ---- partitions -----------------------------------------------------------------------------

std::vector<double> rankWeights(const model::Model& m, const std::vector<int32_t>& rank,
                                int parts) {
  const auto w = partition::elementWeights(m);
  std::vector<double> out(std::size_t(parts), 0.0);
  for (std::size_t e = 0; e < rank.size(); ++e) out[std::size_t(rank[e])] += w[e];
  return out;
}

TEST(PartitionMetis, FourPartsOfABrickAreBalancedAndDeterministic) {
  const auto m = brick(20, 20, 20);
  const partition::Options opt;  // METIS
  const auto a = partition::partitionElements(m, 4, opt);
  const auto b = partition::partitionElements(m, 4, opt);
  ASSERT_EQ(a.size(), m.solids.size());
  EXPECT_EQ(a, b);
  const auto w = rankWeights(m, a, 4);
  for (double v : w) EXPECT_GT(v, 0.0);
  EXPECT_LE(maxOverMean(w), 0.03);
  const auto s = partition::computeStats(m, a, 4);
  EXPECT_NEAR(s.load_imbalance, maxOverMean(w), 1e-12);
  // A good 4-way cut of a 20^3 cube is two planes: 2 x 400 faces. Allow METIS some slack.
  EXPECT_LE(s.edge_cut, 1200);
}

TEST(PartitionMetis, TwoPartsAndManyPartsCoverEveryRank) {
  const auto m = brick(12, 10, 8);
  for (int parts : {2, 3, 7, 16, 33}) {
    const auto r = partition::partitionElements(m, parts, {});
    const auto w = rankWeights(m, r, parts);
    for (int p = 0; p < parts; ++p) EXPECT_GT(w[std::size_t(p)], 0.0) << parts << " parts";
    EXPECT_LE(maxOverMean(w), 0.05) << parts << " parts";
  }
}

TEST(PartitionMetis, AsManyPartsAsElementsGivesOneElementEach) {
  const auto m = brick(3, 2, 2);
  for (auto method : {partition::Method::Metis, partition::Method::Rcb}) {
    const auto r = partition::partitionElements(m, 12, withMethod(method));
    std::vector<int32_t> sorted = r;
    std::sort(sorted.begin(), sorted.end());
    for (int p = 0; p < 12; ++p) EXPECT_EQ(sorted[std::size_t(p)], p);
  }
}

TEST(PartitionMetis, DisconnectedBodiesArePartitioned) {
  // Two bodies and a loose element: METIS refuses a contiguity request on such a graph, so the
  // partitioner must not make one.
  auto m = test::merged(brick(10, 6, 4), brickOf(Shape::Hex, 5, 5, 5, {20, 0, 0}));
  m = test::merged(m, brickOf(Shape::Hex, 1, 1, 1, {0, 30, 0}));
  for (int parts : {2, 4, 5}) {
    const auto r = partition::partitionElements(m, parts, {});
    const auto w = rankWeights(m, r, parts);
    for (double v : w) EXPECT_GT(v, 0.0);
    EXPECT_LE(maxOverMean(w), 0.05) << parts << " parts";
    EXPECT_EQ(r, partition::partitionElements(m, parts, {}));
  }
}

TEST(PartitionMetis, MeshWithoutFacesStillPartitions) {
  // Four separate elements: a graph with no edges at all.
  auto m = brickOf(Shape::Hex, 1, 1, 1);
  for (int i = 1; i < 4; ++i) m = test::merged(m, brickOf(Shape::Hex, 1, 1, 1, {3.0 * i, 0, 0}));
  EXPECT_EQ(partition::buildDualGraph(m).numEdges(), 0);
  const auto r = partition::partitionElements(m, 2, {});
  EXPECT_EQ(std::count(r.begin(), r.end(), 0), 2);
  const auto r4 = partition::partitionElements(m, 4, {});
  EXPECT_EQ(std::set<int32_t>(r4.begin(), r4.end()).size(), 4u);
}

TEST(PartitionMetis, PlasticElementsWeighMoreAndBalanceByWeight) {
  // An elastic block and a plastic block of equal size: balance is by weight, not by count.
  const auto m = test::merged(brick(10, 10, 5), brickOf(Shape::Hex, 10, 10, 5, {0, 0, 5}, true));
  const auto w = partition::elementWeights(m);
  EXPECT_EQ(w.front(), partition::kWeightSolidElastic);
  EXPECT_EQ(w.back(), partition::kWeightSolidPlastic);
  const auto r = partition::partitionElements(m, 2, {});
  const auto s = partition::computeStats(m, r, 2);
  EXPECT_LE(s.load_imbalance, 0.02);
  EXPECT_NE(s.ranks[0].elements, s.ranks[1].elements);
}

TEST(PartitionWeights, StiffnessHourglassCostsMore) {
  auto m = test::merged(brick(1, 1, 1), brickOf(Shape::Hex, 1, 1, 1, {2, 0, 0}, true));
  m.controls.hourglass_ihq = 4;  // default for both parts: stiffness
  EXPECT_EQ(partition::elementWeights(m),
            (std::vector<int32_t>{
                partition::kWeightSolidElastic + partition::kWeightStiffnessHourglass,
                partition::kWeightSolidPlastic + partition::kWeightStiffnessHourglass}));
  m.hourglass.push_back({7, 2, 0.1});  // *HOURGLASS 7: viscous, for the plastic part only
  m.parts[1].hourglass = 0;
  EXPECT_EQ(
      partition::elementWeights(m),
      (std::vector<int32_t>{partition::kWeightSolidElastic + partition::kWeightStiffnessHourglass,
                            partition::kWeightSolidPlastic}));
}

TEST(PartitionWeights, ContactBiasScalesFlaggedElements) {
  const auto m = brick(2, 1, 1);
  partition::Options opt;
  opt.contact_bias = 1.5;
  opt.contact_elements = {1, 0};
  EXPECT_EQ(partition::elementWeights(m, opt), (std::vector<int32_t>{15, 10}));
  opt.contact_elements = {1};
  EXPECT_THROW(partition::elementWeights(m, opt), std::invalid_argument);
  opt.contact_elements.clear();
  opt.contact_bias = 0.0;
  EXPECT_THROW(partition::elementWeights(m, opt), std::invalid_argument);
}

TEST(PartitionRcb, ThreePartsWithinOneElementWeight) {
  const auto m = brick(20, 20, 20);
  const partition::Options opt = withMethod(partition::Method::Rcb);
  const auto r = partition::partitionElements(m, 3, opt);
  EXPECT_EQ(r, partition::partitionElements(m, 3, opt));
  const auto w = rankWeights(m, r, 3);
  const double mean = (w[0] + w[1] + w[2]) / 3.0;
  for (double v : w) EXPECT_LE(std::abs(v - mean), partition::kWeightSolidElastic);
}

TEST(PartitionRcb, AnyPartCountIsBalancedAndCutsTheLongestAxis) {
  const auto m = brick(30, 6, 4);  // long in x: RCB should give slabs across x
  for (int parts : {2, 5, 6, 7, 13}) {
    const auto r = partition::partitionElements(m, parts, withMethod(partition::Method::Rcb));
    const auto w = rankWeights(m, r, parts);
    const double mean = double(m.solids.size()) * partition::kWeightSolidElastic / parts;
    for (double v : w) EXPECT_LE(std::abs(v - mean), 2 * partition::kWeightSolidElastic) << parts;
  }
  const auto r2 = partition::partitionElements(m, 2, withMethod(partition::Method::Rcb));
  // Elements are numbered i fastest: the x < 15 half goes to rank 0.
  for (std::size_t e = 0; e < m.solids.size(); ++e) EXPECT_EQ(r2[e], int32_t(e % 30 >= 15));
}

TEST(PartitionElements, MorePartsThanElementsIsAnInputError) {
  const auto m = brick(2, 2, 1);
  try {
    partition::partitionElements(m, 5, {});
    FAIL() << "expected InputError";
  } catch (const util::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot split 4 elements over 5 ranks"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(partition::partitionElements(m, 0, {}), util::InputError);
  EXPECT_THROW(partition::partitionElements(m, 5, withMethod(partition::Method::Rcb)),
               util::InputError);
}

TEST(PartitionElements, OnePartIsAllZeros) {
  const auto m = brick(3, 3, 3);
  EXPECT_EQ(partition::partitionElements(m, 1, {}), std::vector<int32_t>(27, 0));
}

TEST(PartitionElements, MethodNames) {
  EXPECT_EQ(partition::parseMethod("metis"), partition::Method::Metis);
  EXPECT_EQ(partition::parseMethod("RCB"), partition::Method::Rcb);
  EXPECT_THROW(partition::parseMethod("scotch"), util::InputError);
}

// ---- statistics and files -------------------------------------------------------------------

TEST(PartitionStats, TwoElementsSplitInTwo) {
  const auto m = brick(2, 1, 1);
  const auto s = partition::computeStats(m, {0, 1}, 2);
  EXPECT_EQ(s.parts, 2);
  EXPECT_EQ(s.elements, 2);
  EXPECT_EQ(s.nodes, 12);
  EXPECT_EQ(s.shared_nodes_total, 4);
  EXPECT_EQ(s.edge_cut, 1);
  EXPECT_DOUBLE_EQ(s.load_imbalance, 0.0);
  ASSERT_EQ(s.ranks.size(), 2u);
  EXPECT_EQ(s.ranks[0].neighbours, std::vector<int>{1});
  EXPECT_EQ(s.ranks[1].neighbours, std::vector<int>{0});
  for (const auto& r : s.ranks) {
    EXPECT_EQ(r.elements, 1);
    EXPECT_EQ(r.nodes, 8);
    EXPECT_EQ(r.shared_nodes, 4);
    EXPECT_DOUBLE_EQ(r.weight, 1.0);
    // 4 shared nodes x 1 corner x (24 B force + 16 B header), one message.
    EXPECT_EQ(r.bytes_per_cycle, 160);
    EXPECT_DOUBLE_EQ(r.comm_s, 2e-6 + 160 / 5e9);
    EXPECT_DOUBLE_EQ(r.compute_s, 150e-9);
  }
  EXPECT_DOUBLE_EQ(s.comm_to_compute, (2e-6 + 160 / 5e9) / 150e-9);
}

TEST(PartitionStats, OneRankSharesNothingAndImbalanceIsMeasured) {
  const auto m = brick(3, 1, 1);
  const auto one = partition::computeStats(m, {0, 0, 0}, 1);
  EXPECT_EQ(one.shared_nodes_total, 0);
  EXPECT_EQ(one.edge_cut, 0);
  EXPECT_EQ(one.comm_to_compute, 0.0);
  EXPECT_TRUE(one.ranks[0].neighbours.empty());
  const auto s = partition::computeStats(m, {0, 0, 1}, 2);
  EXPECT_DOUBLE_EQ(s.load_imbalance, 2.0 / 1.5 - 1.0);
  EXPECT_THROW(partition::computeStats(m, {0, 0, 2}, 2), std::invalid_argument);
  EXPECT_THROW(partition::computeStats(m, {0, 0}, 2), std::invalid_argument);
}

TEST(PartitionStats, CornerRanksOfAFourWaySplitAreAllNeighbours) {
  // 2x2x1 elements, one per rank: the centre line's two nodes are shared by all four ranks,
  // so every rank neighbours every other, though only edge-adjacent ranks share a face.
  const auto m = brick(2, 2, 1);
  const auto s = partition::computeStats(m, {0, 1, 2, 3}, 4);
  EXPECT_EQ(s.edge_cut, 4);
  EXPECT_EQ(s.shared_nodes_total, 2 * 5);  // the cross of 5 nodes, on 2 levels
  for (const auto& r : s.ranks) {
    EXPECT_EQ(r.neighbours.size(), 3u);
    EXPECT_EQ(r.shared_nodes, 6);
  }
}

TEST(PartitionFiles, JsonAndVtuAreWritten) {
  TempDir t;
  const auto m = brick(4, 2, 2);
  const auto r = partition::partitionElements(m, 2, {});
  const auto s = partition::computeStats(m, r, 2);
  partition::writePartitionJson(t.path() / "partition.json", s, "metis");
  partition::writePartitionVtu(t.path() / "partition.vtu", m, r);
  std::ifstream f(t.path() / "partition.json");
  const auto j = nlohmann::json::parse(f);
  EXPECT_EQ(j["method"], "metis");
  EXPECT_EQ(j["parts"], 2);
  EXPECT_EQ(j["elements"], 16);
  EXPECT_EQ(j["edge_cut"], s.edge_cut);
  ASSERT_EQ(j["ranks"].size(), 2u);
  EXPECT_EQ(j["ranks"][1]["neighbours"], std::vector<int>{0});
  std::ifstream v(t.path() / "partition.vtu");
  std::stringstream text;
  text << v.rdbuf();
  for (const char* name : {"\"rank\"", "\"element_id\"", "\"part\"", "\"ranks\""})
    EXPECT_NE(text.str().find(name), std::string::npos) << name;
}

TEST(PartitionCommand, WritesFilesAndTable) {
  TempDir t;
  const std::string deck = std::string(CRUMPLE_SOURCE_DIR) + "/examples/taylor_bar/taylor_bar.k";
  const fs::path dir = t.path() / "p";
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(app::partitionCommand(deck, 4, dir.string(), "rcb", out), 0);
  // Overwrites its own files on a second run.
  EXPECT_EQ(app::partitionCommand(deck, 3, dir.string(), "metis", out), 0);
  std::rewind(out);
  std::string text;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, out)) text.append(buf, n);
  std::fclose(out);
  EXPECT_NE(text.find("load imbalance"), std::string::npos) << text;
  EXPECT_NE(text.find("edge cut"), std::string::npos) << text;
  std::ifstream f(dir / "partition.json");
  const auto j = nlohmann::json::parse(f);
  EXPECT_EQ(j["parts"], 3);
  EXPECT_EQ(j["method"], "metis");
  EXPECT_TRUE(fs::exists(dir / "partition.vtu"));
  EXPECT_EQ(app::partitionCommand(deck, 2, dir.string(), "nonsense", out = std::tmpfile()), 1);
  std::fclose(out);
  EXPECT_EQ(app::partitionCommand(deck + ".missing", 2, dir.string(), "rcb", out = std::tmpfile()),
            1);
  std::fclose(out);
}

}  // namespace

// ---- How many ranks (partition/advice.hpp) --------------------------------------------------

namespace {
// Stats of a partition into `weights.size()` ranks, each rank holding `nodes` nodes and one
// neighbour message of `comm_s`.
crumple::partition::Stats syntheticStats(const std::vector<double>& weights, int64_t nodes,
                                         int64_t total_nodes, double comm_s) {
  crumple::partition::Stats s;
  s.parts = int(weights.size());
  s.nodes = total_nodes;
  double sum = 0, most = 0;
  for (std::size_t r = 0; r < weights.size(); ++r) {
    crumple::partition::RankStats rs;
    rs.rank = int(r);
    rs.elements = int64_t(weights[r]);
    rs.weight = weights[r];
    rs.nodes = nodes;
    rs.comm_s = s.parts > 1 ? comm_s : 0.0;
    if (s.parts > 1) rs.neighbours = {int(r) == 0 ? 1 : 0};
    s.ranks.push_back(rs);
    sum += weights[r];
    most = std::max(most, weights[r]);
  }
  s.load_imbalance = most / (sum / double(weights.size())) - 1;
  return s;
}
}  // namespace

TEST(PartitionAdvice, PredictionAddsTheSlowestRanksParts) {
  using namespace crumple::partition;
  CycleCosts serial;
  serial.elements_s = 1000e-6;
  serial.nodes_s = 100e-6;
  serial.contact_split_s = 240e-6;
  serial.contact_replicated_s = 10e-6;
  Network net{1e-6, 1e9, true};
  const Prediction one = predict(syntheticStats({1000}, 1000, 1000, 0), serial, net, true);
  EXPECT_DOUBLE_EQ(one.cycle_s, serial.total());
  EXPECT_DOUBLE_EQ(one.efficiency, 1.0);
  EXPECT_DOUBLE_EQ(one.comm_s, 0.0);

  // Four ranks, the heaviest with 300 of 1000 weight units and 260 of 1000 nodes, 5 us of
  // element exchange: 300 + 26 + (240 * 1.4 / 4 + 10) + (5 + 2 + 3 * 2) us.
  const Prediction four =
      predict(syntheticStats({300, 250, 250, 200}, 260, 1000, 5e-6), serial, net, true);
  EXPECT_NEAR(four.elements_s, 300e-6, 1e-15);
  EXPECT_NEAR(four.nodes_s, 26e-6, 1e-15);
  EXPECT_NEAR(four.contact_s, 94e-6, 1e-15);
  EXPECT_NEAR(four.comm_s, 13e-6, 1e-15);
  EXPECT_NEAR(four.cycle_s, 433e-6, 1e-15);
  EXPECT_NEAR(four.efficiency, 1350.0 / 433.0 / 4.0, 1e-12);
  EXPECT_NEAR(four.comm_share, 13.0 / 433.0, 1e-12);
  EXPECT_NEAR(four.imbalance, 0.2, 1e-12);
  // Without contact there are no contact exchanges.
  serial.contact_split_s = serial.contact_replicated_s = 0;
  EXPECT_NEAR(
      predict(syntheticStats({250, 250, 250, 250}, 250, 1000, 5e-6), serial, net, false).comm_s,
      7e-6, 1e-15);
}

TEST(PartitionAdvice, RecommendsTheMostRanksAtEightyPercent) {
  using namespace crumple::partition;
  auto at = [](int ranks, double eff) {
    Prediction p;
    p.ranks = ranks;
    p.efficiency = eff;
    return p;
  };
  EXPECT_EQ(recommend({at(1, 1.0), at(2, 0.95), at(4, 0.81), at(8, 0.79)}), 4);
  EXPECT_EQ(recommend({at(1, 1.0), at(2, 0.7), at(4, 0.85)}), 4);  // the most, not the first
  EXPECT_EQ(recommend({at(1, 1.0), at(2, 0.5)}), 1);
  EXPECT_EQ(candidateRanks(1), (std::vector<int>{1}));
  EXPECT_EQ(candidateRanks(10), (std::vector<int>{1, 2, 3, 4, 6, 8, 10}));
  EXPECT_EQ(candidateRanks(64), (std::vector<int>{1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64}));
}
