// Partition statistics and the partition.json / partition.vtu files of `crumple partition`.
#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "output/vtk.hpp"
#include "partition/incidence.hpp"
#include "partition/partition.hpp"

namespace crumple::partition {

namespace {

void checkRanks(const model::Model& model, const std::vector<int32_t>& elem_rank, int parts) {
  if (parts < 1) throw std::invalid_argument("partition stats: parts must be at least 1");
  if (elem_rank.size() != model.numElements())
    throw std::invalid_argument("partition stats: " + std::to_string(elem_rank.size()) +
                                " ranks given for " + std::to_string(model.numElements()) +
                                " elements");
  for (int32_t r : elem_rank)
    if (r < 0 || r >= parts)
      throw std::invalid_argument("partition stats: rank " + std::to_string(r) + " outside 0.." +
                                  std::to_string(parts - 1));
}

}  // namespace

Stats computeStats(const model::Model& model, const std::vector<int32_t>& elem_rank, int parts) {
  return computeStats(model, elem_rank, parts, CommModel{});
}

Stats computeStats(const model::Model& model, const std::vector<int32_t>& elem_rank, int parts,
                   const CommModel& comm) {
  checkRanks(model, elem_rank, parts);
  const std::size_t ne = model.numElements();
  const std::size_t nn = model.nodes.size();
  Stats s;
  s.parts = parts;
  s.elements = int64_t(ne);
  s.model = comm;
  s.ranks.resize(std::size_t(parts));
  for (int r = 0; r < parts; ++r) s.ranks[std::size_t(r)].rank = r;

  // Weights summed as integers (exact, order-independent), then scaled to elastic-solid units.
  const std::vector<int32_t> w = elementWeights(model);
  std::vector<int64_t> wsum(std::size_t(parts), 0);
  for (std::size_t e = 0; e < ne; ++e) {
    ++s.ranks[std::size_t(elem_rank[e])].elements;
    wsum[std::size_t(elem_rank[e])] += w[e];
  }
  for (int r = 0; r < parts; ++r)
    s.ranks[std::size_t(r)].weight = double(wsum[std::size_t(r)]) / kWeightScale;

  // Edge cut: dual-graph edges (shared faces) whose ends sit on different ranks.
  const DualGraph g = buildDualGraph(model);
  for (std::size_t e = 0; e < g.numVertices(); ++e)
    for (int64_t j = g.xadj[e]; j < g.xadj[e + 1]; ++j) {
      const auto c = std::size_t(g.adjncy[std::size_t(j)]);
      if (c > e && elem_rank[c] != elem_rank[e]) ++s.edge_cut;
    }

  // Per node: the ranks holding it and, per rank, how many element corners touch it there
  // (repeated nodes of a degenerate hex are separate corners: each has its own force slot).
  const detail::Incidence inc = detail::nodeElements(model);
  std::vector<std::map<int, int64_t>> bytes(
      static_cast<std::size_t>(parts));           // rank -> neighbour -> bytes
  std::vector<std::pair<int32_t, int64_t>> held;  // (rank, corners) of a node
  const double per_corner = comm.bytes_per_corner + comm.header_bytes_per_corner;
  for (std::size_t n = 0; n < nn; ++n) {
    held.clear();
    for (int64_t j = inc.ptr[n]; j < inc.ptr[n + 1]; ++j) {
      const auto e = std::size_t(inc.elem[std::size_t(j)]);
      int32_t en[model::kMaxElementNodes];
      const int count = model.elementNodes(e, en);
      const auto corners = int64_t(std::count(en, en + count, int32_t(n)));
      const int32_t r = elem_rank[e];
      auto it = std::find_if(held.begin(), held.end(), [&](const auto& h) { return h.first == r; });
      if (it == held.end())
        held.emplace_back(r, corners);
      else
        it->second += corners;
    }
    if (held.empty()) continue;  // a node no element uses (e.g. a rigid-wall reference)
    ++s.nodes;
    for (const auto& [r, corners] : held) ++s.ranks[std::size_t(r)].nodes;
    if (held.size() < 2) continue;
    ++s.shared_nodes_total;
    for (const auto& [r, corners] : held) {
      ++s.ranks[std::size_t(r)].shared_nodes;
      for (const auto& [q, q_corners] : held)
        if (q != r) bytes[std::size_t(r)][q] += int64_t(double(corners) * per_corner);
    }
  }

  double max_w = 0, sum_w = 0;
  for (auto& rs : s.ranks) {
    max_w = std::max(max_w, rs.weight);
    sum_w += rs.weight;
    const auto& to = bytes[std::size_t(rs.rank)];
    rs.comm_s = 0;
    for (const auto& [q, b] : to) {
      rs.neighbours.push_back(q);  // std::map: ascending
      rs.bytes_per_cycle += b;
      rs.comm_s += comm.latency_s + double(b) / comm.bandwidth_bytes_per_s;
    }
    rs.compute_s = rs.weight * comm.compute_s_per_weight;
    if (rs.compute_s > 0) {
      const double ratio = rs.comm_s / rs.compute_s;
      if (ratio > s.comm_to_compute) {
        s.comm_to_compute = ratio;
        s.comm_to_compute_rank = rs.rank;
      }
    }
  }
  const double mean_w = sum_w / parts;
  s.load_imbalance = mean_w > 0 ? max_w / mean_w - 1.0 : 0.0;
  return s;
}

void writePartitionJson(const std::filesystem::path& path, const Stats& s,
                        const std::string& method) {
  nlohmann::ordered_json j;
  j["method"] = method;
  j["parts"] = s.parts;
  j["elements"] = s.elements;
  j["nodes"] = s.nodes;
  j["load_imbalance"] = s.load_imbalance;
  j["edge_cut"] = s.edge_cut;
  j["shared_nodes_total"] = s.shared_nodes_total;
  j["shared_node_fraction"] = s.nodes > 0 ? double(s.shared_nodes_total) / double(s.nodes) : 0.0;
  j["comm_to_compute"] = s.comm_to_compute;
  j["comm_to_compute_rank"] = s.comm_to_compute_rank;
  j["comm_model"] = {{"compute_s_per_weight", s.model.compute_s_per_weight},
                     {"latency_s", s.model.latency_s},
                     {"bandwidth_bytes_per_s", s.model.bandwidth_bytes_per_s},
                     {"bytes_per_corner", s.model.bytes_per_corner},
                     {"header_bytes_per_corner", s.model.header_bytes_per_corner}};
  j["weights"] = {{"unit", "one element-cycle of an elastic one-point solid, viscous hourglass"},
                  {"solid_elastic", double(kWeightSolidElastic) / kWeightScale},
                  {"solid_plastic", double(kWeightSolidPlastic) / kWeightScale},
                  {"stiffness_hourglass_extra", double(kWeightStiffnessHourglass) / kWeightScale}};
  auto& ranks = j["ranks"] = nlohmann::ordered_json::array();
  for (const auto& r : s.ranks) {
    nlohmann::ordered_json o;
    o["rank"] = r.rank;
    o["elements"] = r.elements;
    o["weight"] = r.weight;
    o["nodes"] = r.nodes;
    o["shared_nodes"] = r.shared_nodes;
    o["neighbours"] = r.neighbours;
    o["bytes_per_cycle"] = r.bytes_per_cycle;
    o["comm_s"] = r.comm_s;
    o["compute_s"] = r.compute_s;
    ranks.push_back(std::move(o));
  }
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  if (!f) throw std::runtime_error("cannot write " + path.string());
  f << j.dump(2) << '\n';
  f.close();
  if (!f) throw std::runtime_error("error writing " + path.string());
}

void writePartitionVtu(const std::filesystem::path& path, const model::Model& model,
                       const std::vector<int32_t>& elem_rank) {
  const std::size_t ne = model.numElements();
  if (elem_rank.size() != ne)
    throw std::invalid_argument("partition VTU: one rank per element expected");
  std::vector<double> points(3 * model.nodes.size());
  for (std::size_t n = 0; n < model.nodes.size(); ++n)
    for (int c = 0; c < 3; ++c) points[3 * n + std::size_t(c)] = model.nodes.x[n][c];
  std::vector<int32_t> cells(8 * ne);
  std::vector<uint8_t> sizes(ne);
  std::vector<int64_t> rank(ne), eid(ne), pid(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    // A 10-node tetrahedron is drawn as its corner tetrahedron, N1 N2 N3 N4 N4 N4 N4 N4.
    int32_t en[model::kMaxElementNodes];
    const int count = model.elementNodes(e, en);
    if (count > 8) std::fill(en + 4, en + 8, en[3]);
    sizes[e] = uint8_t(std::min(count, 8));
    std::copy(en, en + sizes[e], &cells[8 * e]);
    rank[e] = elem_rank[e];
    eid[e] = model.elementId(e);
    const int32_t p = model.elementPart(e);
    pid[e] = p >= 0 && std::size_t(p) < model.parts.size() ? model.parts[std::size_t(p)].id : -1;
  }
  // Point field: number of ranks holding each node (0 for nodes no element uses).
  const detail::Incidence inc = detail::nodeElements(model);
  std::vector<int64_t> node_ranks(model.nodes.size(), 0);
  std::vector<int32_t> seen;
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    seen.clear();
    for (int64_t j = inc.ptr[n]; j < inc.ptr[n + 1]; ++j)
      seen.push_back(elem_rank[std::size_t(inc.elem[std::size_t(j)])]);
    std::sort(seen.begin(), seen.end());
    node_ranks[n] = std::unique(seen.begin(), seen.end()) - seen.begin();
  }
  output::MeshView mesh{model.nodes.size(), points.data(), ne, cells.data(), sizes.data()};
  std::vector<output::FieldView> fields;
  fields.push_back({"rank", output::Association::Cell, 1, nullptr, rank.data()});
  fields.push_back({"element_id", output::Association::Cell, 1, nullptr, eid.data()});
  fields.push_back({"part", output::Association::Cell, 1, nullptr, pid.data()});
  fields.push_back({"ranks", output::Association::Point, 1, nullptr, node_ranks.data()});
  output::writeVtu(path, mesh, fields);
}

}  // namespace crumple::partition
