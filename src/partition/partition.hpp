// Element partition for the distributed run (ARCHITECTURE.md "Parallel model"): the dual
// graph of the mesh, built in O(N_elements) from node->element incidence, split by METIS
// (multilevel k-way, Karypis & Kumar 1998) or by recursive coordinate bisection (Berger &
// Bokhari 1987), with element weights by cost, and the statistics a user needs to judge a
// partition before running on it (load imbalance, edge cut, shared nodes, modelled
// communication/compute ratio). docs/parallel.md explains the choices and gives figures.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace crumple::partition {

// Elements adjacent when they share a face (solids: 4 distinct nodes of a quad face, 3 for a
// triangular face of a degenerate hex). CSR over model element indices, neighbours ascending.
// The relation is symmetric and has no self loops. Faces come from the element's shape: an
// 8-node hex has its 6 quad faces; wedges and pyramids written as degenerate hexes keep the
// hex faces that still have >= 3 distinct nodes; a tetrahedron (4 distinct nodes, however the
// repeats are written) has its 4 triangles.
struct DualGraph {
  std::vector<int64_t> xadj;    // size N_elements + 1
  std::vector<int64_t> adjncy;  // size xadj.back() = 2 x number of face adjacencies
  std::size_t numVertices() const { return xadj.empty() ? 0 : xadj.size() - 1; }
  int64_t numEdges() const { return adjncy.empty() ? 0 : int64_t(adjncy.size()) / 2; }
};
DualGraph buildDualGraph(const model::Model& model);

enum class Method { Metis, Rcb };

struct Options {
  Method method = Method::Metis;
  // Weight multiplier for elements flagged in `contact_elements` (contact search and forces
  // make them dearer). The Model has no contact definitions yet, so nothing is flagged by
  // default and the bias has no effect until the contact module fills the flags.
  double contact_bias = 1.0;
  // Per model solid, nonzero = on a contact surface; empty = none. ({} so that designated
  // initialisers such as Options{.method = Method::Rcb} compile cleanly under -Wextra.)
  std::vector<uint8_t> contact_elements = {};
};

// Parses "metis" / "rcb" (case-insensitive); throws util::InputError otherwise.
Method parseMethod(const std::string& name);
const char* methodName(Method m);

// Element -> rank (0..parts-1) for every model element (global numbering: solids, shells,
// beams, discretes). Deterministic (same input, same output).
// parts == 1: all zeros. Throws util::InputError if parts < 1 or parts > number of elements
// ("cannot split N elements over P ranks"); std::runtime_error if METIS fails. Every rank
// receives at least one element.
std::vector<int32_t> partitionElements(const model::Model& model, int parts, const Options& opt);

// Integer element cost weights in units of 1/kWeightScale of an elastic one-point solid's
// element-cycle with viscous hourglass control: solid elastic 1.0, solid plastic 1.2, plus 0.4
// for stiffness hourglass control (IHQ 4, 5). Measured, not guessed: docs/parallel.md
// "Element weights". Future shells and beams get their own entries.
inline constexpr int32_t kWeightScale = 10;
inline constexpr int32_t kWeightSolidElastic = 10;
inline constexpr int32_t kWeightSolidPlastic = 12;
inline constexpr int32_t kWeightStiffnessHourglass = 4;
// The fully integrated hex (ELFORM 2) runs 8 Gauss points: measured 2.4x the one-point
// element's cost on the bar impact example (1.17 M against 2.8 M element-cycles per second).
inline constexpr int32_t kWeightFullyIntegratedFactor = 24;  // in tenths
// ELFORM 15 (2 points): 1 + (2.4 - 1) / 4, not measured apart.
inline constexpr int32_t kWeightPentahedronFactor = 14;  // in tenths
// Shells, beams, springs and rigid elements, in the same units (docs/parallel.md). Shells from
// the kernel benchmarks: a plastic Belytschko-Tsay shell with 5 points costs 0.93 of the
// plastic hex (167-184 against 180-199 ns), an elastic one 124 ns. Beams and springs are
// estimates (a scalar loop of about a shell's work; a few flops), rarely a large share.
inline constexpr int32_t kWeightShellElastic = 7;
inline constexpr int32_t kWeightShellPlastic = 11;
inline constexpr int32_t kWeightBeam = 6;
inline constexpr int32_t kWeightDiscrete = 1;
inline constexpr int32_t kWeightRigid = 1;  // mass only: a rigid element computes no force
std::vector<int32_t> elementWeights(const model::Model& model);
// As above, with Options::contact_bias applied to Options::contact_elements.
std::vector<int32_t> elementWeights(const model::Model& model, const Options& opt);

// Parameters of the communication model behind Stats::comm_to_compute (docs/parallel.md).
struct CommModel {
  double compute_s_per_weight = 150e-9;  // one elastic solid element-cycle
  double latency_s = 2e-6;               // per message (one per neighbour per cycle)
  double bandwidth_bytes_per_s = 5e9;
  double bytes_per_corner = 3 * 8;      // a force contribution: 3 doubles per element corner
  double header_bytes_per_corner = 16;  // global element id + corner/node id
};

struct RankStats {
  int rank = 0;
  int64_t elements = 0;
  double weight = 0;            // in elastic-solid units (sum of elementWeights / kWeightScale)
  int64_t nodes = 0;            // nodes referenced by this rank's elements
  int64_t shared_nodes = 0;     // of those, nodes also referenced by another rank
  std::vector<int> neighbours;  // ranks sharing a node with this one, ascending
  int64_t bytes_per_cycle = 0;  // sent to all neighbours per cycle (model)
  double comm_s = 0;            // modelled message time per cycle
  double compute_s = 0;         // modelled element time per cycle
};

struct Stats {
  int parts = 0;
  int64_t elements = 0;
  int64_t nodes = 0;               // nodes referenced by at least one element
  double load_imbalance = 0;       // max weight / mean weight - 1
  int64_t edge_cut = 0;            // dual-graph edges (shared faces) between ranks
  int64_t shared_nodes_total = 0;  // nodes held by > 1 rank
  double comm_to_compute = 0;      // max over ranks of modelled comm time / compute time
  int comm_to_compute_rank = 0;    // the rank where that maximum occurs
  CommModel model;
  std::vector<RankStats> ranks;
};

// Throws std::invalid_argument if elem_rank does not hold one rank in [0, parts) per solid.
Stats computeStats(const model::Model& model, const std::vector<int32_t>& elem_rank, int parts);
Stats computeStats(const model::Model& model, const std::vector<int32_t>& elem_rank, int parts,
                   const CommModel& comm);

// nlohmann::json, keys in a fixed order; throws std::runtime_error naming the path on failure.
void writePartitionJson(const std::filesystem::path& path, const Stats& s,
                        const std::string& method);

// VTU of the mesh coloured by rank (cell fields "rank", "element_id", "part" (part id), and the
// point field "ranks": how many ranks hold each node, > 1 on shared nodes), using
// output::writeVtu.
void writePartitionVtu(const std::filesystem::path& path, const model::Model& model,
                       const std::vector<int32_t>& elem_rank);

}  // namespace crumple::partition
