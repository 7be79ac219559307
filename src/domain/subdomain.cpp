#include "domain/subdomain.hpp"

#include <algorithm>
#include <map>
#include <numeric>

namespace crumple::domain {

void SolidBlock::resize(std::size_t n, bool plastic, bool kinematic, bool stiffness_hourglass) {
  const std::size_t padded = (n + kSolidBatch - 1) / kSolidBatch * kSolidBatch;
  for (auto& s : sig) s.assign(padded, 0.0);
  eps_p.assign(plastic ? padded : 0, 0.0);
  for (auto& s : alpha) s.assign(kinematic ? padded : 0, 0.0);
  for (auto& s : hgq) s.assign(stiffness_hourglass ? padded : 0, 0.0);
  // Padding lanes get a unit volume so that densities stay finite there.
  vol0.assign(padded, 1.0);
  vol.assign(padded, 1.0);
  e_int.assign(padded, 0.0);
  e_hg.assign(padded, 0.0);
  active.assign(padded, 1);
  failed.assign(padded, 0);
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

Subdomain buildSubdomain(const model::Model& model, const std::vector<int32_t>& elements,
                         const std::vector<int32_t>& extra_nodes, int rank, int num_ranks) {
  Subdomain sd;
  sd.rank = rank;
  sd.num_ranks = num_ranks;

  // Nodes: every node referenced by a held element, plus the extra ones, ascending.
  std::vector<int32_t> nodes(extra_nodes);
  for (int32_t e : elements)
    for (int32_t n : model.solids.nodes[static_cast<std::size_t>(e)]) nodes.push_back(n);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  sd.node_model = nodes;
  const std::size_t nn = nodes.size();
  std::vector<int32_t> local_of(model.nodes.size(), model::kNone);
  for (std::size_t i = 0; i < nn; ++i) local_of[static_cast<std::size_t>(nodes[i])] = int32_t(i);

  sd.node_id.resize(nn);
  sd.x0.resize(3 * nn);
  for (std::size_t i = 0; i < nn; ++i) {
    const auto m = static_cast<std::size_t>(nodes[i]);
    sd.node_id[i] = model.nodes.id[m];
    for (int c = 0; c < 3; ++c) sd.x0[3 * i + c] = model.nodes.x[m][c];
  }
  sd.x = sd.x0;
  sd.v.assign(3 * nn, 0.0);
  sd.a.assign(3 * nn, 0.0);
  sd.f.assign(3 * nn, 0.0);
  sd.f_ext.assign(3 * nn, 0.0);
  sd.mass.assign(nn, 0.0);
  sd.mass_added.assign(nn, 0.0);

  // Blocks: one per part, elements ascending within a block.
  std::map<int32_t, std::vector<int32_t>> by_part;
  for (int32_t e : elements) by_part[model.solids.part[static_cast<std::size_t>(e)]].push_back(e);
  std::size_t slot = 0;
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
    b.conn.resize(elems.size());
    for (std::size_t k = 0; k < elems.size(); ++k) {
      const auto& gn = model.solids.nodes[static_cast<std::size_t>(elems[k])];
      for (int a = 0; a < 8; ++a) b.conn[k][a] = local_of[static_cast<std::size_t>(gn[a])];
    }
    const bool plastic = std::visit([](const auto& law) { return law.kPlastic; }, b.law);
    const bool kinematic = std::visit([](const auto& law) { return law.kKinematic; }, b.law);
    b.resize(elems.size(), plastic, kinematic, b.hourglass.ihq >= 4);
    b.slot_offset = slot;
    slot += 8 * elems.size();
    sd.num_elements += elems.size();
    sd.solid_blocks.push_back(std::move(b));
  }
  sd.slots.assign(3 * slot, 0.0);

  // Gather plan: for each node, its (global element, corner) slots in ascending order. This
  // fixed order of summation is what makes nodal forces independent of how elements are
  // split among threads and ranks (ARCHITECTURE.md, Determinism).
  struct Entry {
    int32_t node, elem, corner, slot;
  };
  std::vector<Entry> entries;
  entries.reserve(slot);
  for (const auto& b : sd.solid_blocks)
    for (std::size_t k = 0; k < b.size(); ++k)
      for (int a = 0; a < 8; ++a)
        entries.push_back({b.conn[k][a], b.elem[k], a, int32_t(b.slot_offset + 8 * k + a)});
  std::sort(entries.begin(), entries.end(), [](const Entry& p, const Entry& q) {
    if (p.node != q.node) return p.node < q.node;
    if (p.elem != q.elem) return p.elem < q.elem;
    return p.corner < q.corner;
  });
  sd.gather_ptr.assign(nn + 1, 0);
  sd.gather_slot.resize(entries.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    sd.gather_ptr[static_cast<std::size_t>(entries[i].node) + 1]++;
    sd.gather_slot[i] = entries[i].slot;
  }
  std::partial_sum(sd.gather_ptr.begin(), sd.gather_ptr.end(), sd.gather_ptr.begin());
  return sd;
}

Subdomain buildSerialSubdomain(const model::Model& model) {
  std::vector<int32_t> all(model.solids.size());
  std::iota(all.begin(), all.end(), 0);
  std::vector<int32_t> nodes(model.nodes.size());
  std::iota(nodes.begin(), nodes.end(), 0);
  return buildSubdomain(model, all, nodes, 0, 1);
}

}  // namespace crumple::domain
