#include "domain/subdomain.hpp"

#include <algorithm>
#include <map>
#include <numeric>

#include "util/error.hpp"

namespace crumple::domain {

void SolidBlock::resize(std::size_t n, bool plastic, bool kinematic, bool stiffness_hourglass,
                        bool gauss_points) {
  const std::size_t padded = (n + kSolidBatch - 1) / kSolidBatch * kSolidBatch;
  sig.assign(6 * padded, 0.0);
  eps_p.assign(plastic ? padded : 0, 0.0);
  alpha.assign(kinematic ? 6 * padded : 0, 0.0);
  hgq.assign(stiffness_hourglass ? 12 * padded : 0, 0.0);
  // Padding lanes get a unit volume so that densities stay finite there.
  vol0.assign(padded, 1.0);
  vol.assign(padded, 1.0);
  e_int.assign(padded, 0.0);
  e_hg.assign(padded, 0.0);
  active.assign(padded, 1);
  failed.assign(padded, 0);
  const std::size_t points = gauss_points ? 8 * padded : 0;
  for (auto& s : sig_ip) s.assign(points, 0.0);
  for (auto& s : alpha_ip) s.assign(kinematic ? points : 0, 0.0);
  eps_p_ip.assign(plastic ? points : 0, 0.0);
}

namespace {

HourglassParams hourglassOf(const model::Model& model, const model::Part& part) {
  HourglassParams hg{model.controls.hourglass_ihq, model.controls.hourglass_qh};
  if (part.hourglass != model::kNone) {
    const auto& h = model.hourglass[static_cast<std::size_t>(part.hourglass)];
    hg.ihq = h.ihq;
    hg.qm = h.qm;
  }
  return hg;
}

}  // namespace

namespace {

// CSR of the distinct ranks that hold each model node (sorted ascending).
struct NodeRanks {
  std::vector<int32_t> ptr, rank;
  bool holds(std::size_t node, int r) const {
    return std::binary_search(rank.begin() + ptr[node], rank.begin() + ptr[node + 1], r);
  }
  int lowest(std::size_t node) const { return rank[static_cast<std::size_t>(ptr[node])]; }
};

NodeRanks nodeRanks(const model::Model& model, const std::vector<int32_t>& elem_rank) {
  const std::size_t nn = model.nodes.size();
  std::vector<std::pair<int32_t, int32_t>> pairs;  // (node, rank)
  pairs.reserve(8 * model.solids.size() + nn);
  std::vector<uint8_t> touched(nn, 0);
  for (std::size_t e = 0; e < model.solids.size(); ++e)
    for (int32_t n : model.solids.nodes[e]) {
      pairs.emplace_back(n, elem_rank[e]);
      touched[static_cast<std::size_t>(n)] = 1;
    }
  for (std::size_t n = 0; n < nn; ++n)
    if (!touched[n]) pairs.emplace_back(int32_t(n), 0);  // element-less nodes live on rank 0
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  NodeRanks nr;
  nr.ptr.assign(nn + 1, 0);
  nr.rank.resize(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    nr.ptr[static_cast<std::size_t>(pairs[i].first) + 1]++;
    nr.rank[i] = pairs[i].second;
  }
  std::partial_sum(nr.ptr.begin(), nr.ptr.end(), nr.ptr.begin());
  return nr;
}

// One corner of a force source (solid or pressure segment) at a node.
struct Corner {
  int32_t node;    // model node
  int64_t source;  // global source number (solid e, or num_solids + segment)
  int32_t corner;
  int32_t slot;  // local or ghost slot
  bool operator<(const Corner& o) const {
    if (node != o.node) return node < o.node;
    if (source != o.source) return source < o.source;
    return corner < o.corner;
  }
};

GatherPlan gatherPlan(std::vector<Corner> corners, const std::vector<int32_t>& local_of,
                      std::size_t num_nodes) {
  std::sort(corners.begin(), corners.end());
  GatherPlan plan;
  plan.ptr.assign(num_nodes + 1, 0);
  plan.slot.resize(corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i) {
    plan.ptr[static_cast<std::size_t>(local_of[static_cast<std::size_t>(corners[i].node)]) + 1]++;
    plan.slot[i] = corners[i].slot;
  }
  std::partial_sum(plan.ptr.begin(), plan.ptr.end(), plan.ptr.begin());
  return plan;
}

}  // namespace

Subdomain buildSubdomain(const model::Model& model, const std::vector<int32_t>& elem_rank, int rank,
                         int num_ranks) {
  Subdomain sd;
  sd.rank = rank;
  sd.num_ranks = num_ranks;
  sd.global_nodes = static_cast<int64_t>(model.nodes.size());
  sd.global_solids = static_cast<int64_t>(model.solids.size());
  const NodeRanks nr = nodeRanks(model, elem_rank);
  const std::size_t n_model = model.nodes.size();
  const int64_t num_solids = static_cast<int64_t>(model.solids.size());

  // Nodes held here, ascending model index.
  std::vector<int32_t> local_of(n_model, model::kNone);
  for (std::size_t n = 0; n < n_model; ++n)
    if (nr.holds(n, rank)) {
      local_of[n] = static_cast<int32_t>(sd.node_model.size());
      sd.node_model.push_back(static_cast<int32_t>(n));
    }
  const std::size_t nn = sd.node_model.size();
  sd.node_id.resize(nn);
  sd.node_owned.resize(nn);
  sd.x0.resize(3 * nn);
  for (std::size_t i = 0; i < nn; ++i) {
    const auto m = static_cast<std::size_t>(sd.node_model[i]);
    sd.node_id[i] = model.nodes.id[m];
    sd.node_owned[i] = nr.lowest(m) == rank ? 1 : 0;
    for (int c = 0; c < 3; ++c) sd.x0[3 * i + c] = model.nodes.x[m][c];
  }
  sd.x = sd.x0;
  sd.v.assign(3 * nn, 0.0);
  sd.a.assign(3 * nn, 0.0);
  sd.f.assign(3 * nn, 0.0);
  sd.f_ext.assign(3 * nn, 0.0);
  sd.mass.assign(nn, 0.0);
  sd.mass_added.assign(nn, 0.0);

  // Blocks: one per part. Elements touching a node that another rank also holds come first, so
  // their forces can be sent while the others are computed; each group ascending.
  auto shared = [&](std::size_t e) {
    for (int32_t n : model.solids.nodes[e])
      if (nr.ptr[static_cast<std::size_t>(n) + 1] - nr.ptr[static_cast<std::size_t>(n)] > 1)
        return true;
    return false;
  };
  std::map<int32_t, std::vector<int32_t>> by_part, shared_by_part;
  for (std::size_t e = 0; e < model.solids.size(); ++e)
    if (elem_rank[e] == rank)
      (shared(e) ? shared_by_part : by_part)[model.solids.part[e]].push_back(int32_t(e));
  for (auto& [part_index, first] : shared_by_part) {
    auto& rest = by_part[part_index];
    rest.insert(rest.begin(), first.begin(), first.end());
  }
  std::size_t slot = 0;
  std::vector<Corner> internal, pressure;
  for (auto& [part_index, elems] : by_part) {
    const auto& part = model.parts[static_cast<std::size_t>(part_index)];
    const auto& mat = model.materials[static_cast<std::size_t>(part.material)];
    SolidBlock b;
    b.part = part_index;
    b.part_id = part.id;
    b.law = materials::makeLaw(mat, model);
    b.rho0 = mat.rho;
    b.hourglass = hourglassOf(model, part);
    b.elem = elems;
    b.shared_count = shared_by_part.count(part_index) ? shared_by_part[part_index].size() : 0;
    b.shared_end =
        std::min(elems.size(), (b.shared_count + kSolidBatch - 1) / kSolidBatch * kSolidBatch);
    b.elem_id.resize(elems.size());
    for (std::size_t k = 0; k < elems.size(); ++k)
      b.elem_id[k] = model.solids.id[static_cast<std::size_t>(elems[k])];
    b.conn.resize(elems.size());
    for (std::size_t k = 0; k < elems.size(); ++k) {
      const auto& gn = model.solids.nodes[static_cast<std::size_t>(elems[k])];
      for (int a = 0; a < 8; ++a) {
        b.conn[k][a] = local_of[static_cast<std::size_t>(gn[a])];
        internal.push_back({gn[a], elems[k], a, int32_t(slot + 8 * k + a)});
      }
    }
    const bool plastic = std::visit([](const auto& law) { return law.kPlastic; }, b.law);
    const bool kinematic = std::visit([](const auto& law) { return law.kKinematic; }, b.law);
    b.elform = model.solid_sections[static_cast<std::size_t>(part.section)].elform;
    // A fully integrated element has no hourglass modes to control.
    b.resize(elems.size(), plastic, kinematic, b.elform == 1 && b.hourglass.ihq >= 4,
             b.elform == 2);
    b.slot_offset = slot;
    slot += 8 * elems.size();
    sd.num_elements += elems.size();
    sd.solid_blocks.push_back(std::move(b));
  }

  // Pressure segments: computed by the lowest rank that holds all four nodes.
  auto segmentOwner = [&](std::size_t s) {
    const auto& nodes = model.pressure_loads[s].nodes;
    for (int r = 0; r < num_ranks; ++r) {
      bool all = true;
      for (int32_t n : nodes) all = all && nr.holds(static_cast<std::size_t>(n), r);
      if (all) return r;
    }
    return -1;
  };
  std::vector<int32_t> segment_owner(model.pressure_loads.size());
  for (std::size_t s = 0; s < model.pressure_loads.size(); ++s) {
    segment_owner[s] = segmentOwner(s);
    if (segment_owner[s] < 0)
      throw util::InputError(
          "a *LOAD_SEGMENT segment is not a face of any element held by one "
          "rank; pressure segments must lie on element faces in a parallel run");
  }
  sd.pressure_slot_offset = slot;
  for (std::size_t s = 0; s < model.pressure_loads.size(); ++s) {
    if (segment_owner[s] != rank) continue;
    sd.pressure_segments.push_back(int32_t(s));
    for (int a = 0; a < 4; ++a)
      pressure.push_back(
          {model.pressure_loads[s].nodes[a], num_solids + int64_t(s), a, int32_t(slot + a)});
    slot += 4;
  }
  sd.num_local_slots = slot;

  // Neighbours: for each other rank sharing a node, what I send (my corners at nodes it
  // holds) and what I receive (its corners at nodes I hold), both in (source, corner) order.
  // Every rank knows the whole partition during set-up, so both sides derive the same lists
  // without a handshake.
  if (num_ranks > 1) {
    std::vector<std::vector<std::pair<std::pair<int64_t, int32_t>, int32_t>>> send(num_ranks);
    std::vector<std::vector<std::pair<std::pair<int64_t, int32_t>, Corner>>> recv(num_ranks);
    auto addSend = [&](const Corner& c) {
      const auto n = static_cast<std::size_t>(c.node);
      for (int32_t k = nr.ptr[n]; k < nr.ptr[n + 1]; ++k)
        if (nr.rank[static_cast<std::size_t>(k)] != rank)
          send[static_cast<std::size_t>(nr.rank[static_cast<std::size_t>(k)])].push_back(
              {{c.source, c.corner}, c.slot});
    };
    for (const auto& c : internal) addSend(c);
    for (const auto& c : pressure) addSend(c);
    for (std::size_t e = 0; e < model.solids.size(); ++e) {
      const int q = elem_rank[e];
      if (q == rank) continue;
      const auto& gn = model.solids.nodes[e];
      for (int a = 0; a < 8; ++a)
        if (local_of[static_cast<std::size_t>(gn[a])] != model::kNone)
          recv[static_cast<std::size_t>(q)].push_back(
              {{int64_t(e), a}, {gn[a], int64_t(e), a, -1}});
    }
    for (std::size_t s = 0; s < model.pressure_loads.size(); ++s) {
      const int q = segment_owner[s];
      if (q == rank) continue;
      for (int a = 0; a < 4; ++a) {
        const int32_t n = model.pressure_loads[s].nodes[a];
        if (local_of[static_cast<std::size_t>(n)] != model::kNone)
          recv[static_cast<std::size_t>(q)].push_back(
              {{num_solids + int64_t(s), a}, {n, num_solids + int64_t(s), a, -1}});
      }
    }
    for (int q = 0; q < num_ranks; ++q) {
      auto& sq = send[static_cast<std::size_t>(q)];
      auto& rq = recv[static_cast<std::size_t>(q)];
      if (sq.empty() && rq.empty()) continue;
      std::sort(sq.begin(), sq.end());
      std::sort(rq.begin(), rq.end(),
                [](const auto& x, const auto& y) { return x.first < y.first; });
      PeerExchange p;
      p.rank = q;
      for (const auto& [key, s_local] : sq) p.send_slots.push_back(s_local);
      p.send_buffer.assign(3 * p.send_slots.size(), 0.0);
      p.recv_first = slot;
      p.recv_count = rq.size();
      for (auto& [key, c] : rq) {
        c.slot = int32_t(slot++);
        (c.source < num_solids ? internal : pressure).push_back(c);
      }
      sd.peers.push_back(std::move(p));
    }
  }
  sd.slots.assign(3 * slot, 0.0);

  // Gather plans: this fixed order of summation is what makes nodal forces independent of
  // how elements are split among threads and ranks (ARCHITECTURE.md, Determinism).
  sd.internal = gatherPlan(std::move(internal), local_of, nn);
  sd.pressure = gatherPlan(std::move(pressure), local_of, nn);
  return sd;
}

namespace {
template <class F>
int64_t findElement(const Subdomain& sd, int32_t model_index, F&& value) {
  // Two ascending runs per block: the shared group, then the rest.
  for (const auto& b : sd.solid_blocks) {
    const auto mid = b.elem.begin() + static_cast<long>(b.shared_count);
    for (auto [lo, hi] : {std::pair{b.elem.begin(), mid}, std::pair{mid, b.elem.end()}}) {
      auto it = std::lower_bound(lo, hi, model_index);
      if (it != hi && *it == model_index) return value(b, std::size_t(it - b.elem.begin()));
    }
  }
  return 0;
}
}  // namespace

int32_t Subdomain::localNode(int32_t model_node) const {
  auto it = std::lower_bound(node_model.begin(), node_model.end(), model_node);
  if (it == node_model.end() || *it != model_node) return model::kNone;
  return static_cast<int32_t>(it - node_model.begin());
}

int64_t Subdomain::elementId(int32_t model_index) const {
  return findElement(*this, model_index,
                     [](const SolidBlock& b, std::size_t k) { return b.elem_id[k]; });
}

int64_t Subdomain::elementPart(int32_t model_index) const {
  return findElement(*this, model_index,
                     [](const SolidBlock& b, std::size_t) { return b.part_id; });
}

Subdomain buildSerialSubdomain(const model::Model& model) {
  return buildSubdomain(model, std::vector<int32_t>(model.solids.size(), 0), 0, 1);
}

}  // namespace crumple::domain
