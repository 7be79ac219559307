#include "contact/erosion.hpp"

#include <algorithm>

namespace crumple::contact {

std::vector<int32_t> SurfaceErosion::slotsOf(const std::vector<int64_t>& elements) const {
  std::vector<int32_t> out(elements.size(), -1);
  for (std::size_t k = 0; k < elements.size(); ++k)
    if (elements[k] >= 0) out[k] = slotOf(elements[k]);
  return out;
}

int32_t SurfaceErosion::slotOf(int64_t element) const {
  const auto it = std::lower_bound(tracked_.begin(), tracked_.end(), element);
  return it != tracked_.end() && *it == element ? int32_t(it - tracked_.begin()) : -1;
}

void SurfaceErosion::build(const model::Model& m, const std::vector<Pass>& passes,
                           const std::vector<int32_t>& cn_model, const domain::Subdomain& sd) {
  for (const Pass& p : passes)
    for (const auto* list :
         {&p.seg_elem, &p.seg_across, &p.check_elem, &p.check_across, &p.own_elem, &p.own_across})
      for (int64_t g : *list)
        if (g >= 0) tracked_.push_back(g);
  trackNodeElements(m, cn_model);
  alive_.assign(tracked_.size(), 1);
  slots_.resize(passes.size());
  for (std::size_t k = 0; k < passes.size(); ++k) {
    const Pass& p = passes[k];
    PassSlots& s = slots_[k];
    s.seg_owner = slotsOf(p.seg_elem);
    s.seg_across = slotsOf(p.seg_across);
    s.check_owner = slotsOf(p.check_elem);
    s.check_across = slotsOf(p.check_across);
    s.own_owner = slotsOf(p.own_elem);
    s.own_across = slotsOf(p.own_across);
  }
  locate(sd);
  refresh(passes);
}

void SurfaceErosion::trackNodeElements(const model::Model& m,
                                       const std::vector<int32_t>& cn_model) {
  // Every element at a contact node, as (node, element) pairs, joins tracked_ (sorted here
  // with the segments' elements build() put there); node_elem_ holds their slots.
  std::vector<int32_t> cn_of(m.nodes.size(), -1);
  for (std::size_t i = 0; i < cn_model.size(); ++i) cn_of[std::size_t(cn_model[i])] = int32_t(i);
  std::vector<std::pair<int32_t, int64_t>> at;
  std::vector<uint8_t> solid(cn_model.size(), 0), shell(cn_model.size(), 0);
  for (std::size_t g = 0; g < m.numElements(); ++g) {
    int32_t n[model::kMaxElementNodes];
    const int count = m.elementNodes(g, n);
    const model::Family family = m.element(g).first;
    for (int k = 0; k < count; ++k) {
      const int32_t cn = cn_of[std::size_t(n[k])];
      if (cn < 0) continue;
      at.push_back({cn, int64_t(g)});
      solid[std::size_t(cn)] |= family == model::Family::Solid;
      shell[std::size_t(cn)] |= family == model::Family::Shell;
    }
  }
  keep_free_.assign(cn_model.size(), 0);
  for (std::size_t i = 0; i < cn_model.size(); ++i)
    keep_free_[i] = keepsFreeNode(m.contact_controls.enmass, solid[i] != 0, shell[i] != 0);
  std::sort(at.begin(), at.end());
  at.erase(std::unique(at.begin(), at.end()), at.end());
  node_ptr_.assign(cn_model.size() + 1, 0);
  for (const auto& [cn, g] : at) {
    ++node_ptr_[std::size_t(cn) + 1];
    tracked_.push_back(g);
  }
  for (std::size_t i = 0; i < cn_model.size(); ++i) node_ptr_[i + 1] += node_ptr_[i];
  std::sort(tracked_.begin(), tracked_.end());
  tracked_.erase(std::unique(tracked_.begin(), tracked_.end()), tracked_.end());
  node_elem_.reserve(at.size());
  for (const auto& [cn, g] : at) node_elem_.push_back(slotOf(g));
}

void SurfaceErosion::locate(const domain::Subdomain& sd) {
  sd.forEachBlockList([&](const auto& blocks, model::Family family) {
    if constexpr (requires { blocks[0].active; }) {
      for (std::size_t b = 0; b < blocks.size(); ++b)
        for (std::size_t e = 0; e < blocks[b].elem.size(); ++e) {
          const int32_t s = slotOf(sd.globalElement(family, blocks[b].elem[e]));
          if (s >= 0) local_.push_back({&blocks[b].active, int32_t(e), s});
        }
    }
  });
  std::sort(local_.begin(), local_.end(),
            [](const Local& a, const Local& b) { return a.slot < b.slot; });
}

std::vector<int64_t> SurfaceErosion::erodedHere() const {
  std::vector<int64_t> out;
  for (const Local& l : local_)
    if (alive_[std::size_t(l.slot)] && !(*l.active)[std::size_t(l.index)])
      out.push_back(tracked_[std::size_t(l.slot)]);
  return out;
}

bool SurfaceErosion::markEroded(std::span<const int64_t> elements,
                                const std::vector<Pass>& passes) {
  bool changed = false;
  for (int64_t g : elements) {
    const int32_t s = slotOf(g);
    if (s < 0 || !alive_[std::size_t(s)]) continue;
    alive_[std::size_t(s)] = 0;
    changed = true;
  }
  if (changed) refresh(passes);
  return changed;
}

void SurfaceErosion::refresh(const std::vector<Pass>& passes) {
  seg_live_.resize(passes.size());
  for (std::size_t k = 0; k < passes.size(); ++k) {
    const PassSlots& s = slots_[k];
    auto& live = seg_live_[k];
    live.assign(passes[k].seg.size(), 1);
    for (std::size_t j = 0; j < s.seg_owner.size(); ++j)
      live[j] = s.seg_owner[j] < 0 || faceLive(s.seg_owner[j], s.seg_across[j]);
  }
  // A node with elements is in contact while one of them lives (a node of no element, such
  // as a lumped mass, always is), and after if ENMASS keeps it.
  node_live_.assign(node_ptr_.empty() ? 0 : node_ptr_.size() - 1, kLive);
  for (std::size_t n = 0; n < node_live_.size(); ++n) {
    const auto first = std::size_t(node_ptr_[n]), last = std::size_t(node_ptr_[n + 1]);
    if (first == last) continue;
    bool any = false;
    for (std::size_t k = first; k < last && !any; ++k)
      any = alive_[std::size_t(node_elem_[k])] != 0;
    node_live_[n] = any ? kLive : keep_free_[n] ? kFree : kDead;
  }
  refreshChecks(passes);
}

void SurfaceErosion::refreshChecks(const std::vector<Pass>& passes) {
  std::size_t total = 0;
  for (const Pass& p : passes) total += p.node.size();
  check_live_.assign(total, 1);
  for (std::size_t k = 0; k < passes.size(); ++k) {
    const Pass& p = passes[k];
    const PassSlots& s = slots_[k];
    uint8_t* live = check_live_.data() + p.first_check;
    if (p.edges) continue;  // beam edges are not tracked: always in contact
    if (p.segpairs) {
      for (std::size_t j = 0; j < s.check_owner.size(); ++j)
        live[j] = s.check_owner[j] < 0 || faceLive(s.check_owner[j], s.check_across[j]);
      continue;
    }
    if (!p.exposure) {
      for (std::size_t j = 0; j < p.node.size(); ++j)
        live[j] = node_live_[std::size_t(p.node[j])] != kDead;
      continue;
    }
    // The nodes on the faces of the own surface that are in contact, and the free nodes
    // ENMASS keeps.
    for (std::size_t j = 0; j < p.node.size(); ++j)
      live[j] = node_live_[std::size_t(p.node[j])] == kFree;
    for (std::size_t f = 0; f < p.own_faces.size(); ++f) {
      if (!faceLive(s.own_owner[f], s.own_across[f])) continue;
      for (int32_t c : p.own_faces[f])
        if (c >= 0) live[std::size_t(c)] = 1;
    }
  }
}

}  // namespace crumple::contact
