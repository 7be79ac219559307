#include "domain/subdomain.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <numbers>
#include <numeric>
#include <set>
#include <stdexcept>
#include <tuple>
#include <type_traits>

#include "util/error.hpp"

namespace crumple::domain {

void SolidBlock::resize(std::size_t n, bool plastic, bool kinematic, bool hourglass_state,
                        int gauss_points, int history_count) {
  const std::size_t padded = (n + kSolidBatch - 1) / kSolidBatch * kSolidBatch;
  sig.assign(6 * padded, 0.0);
  eps_p.assign(plastic ? padded : 0, 0.0);
  alpha.assign(kinematic ? 6 * padded : 0, 0.0);
  hgq.assign(hourglass_state ? 12 * padded : 0, 0.0);
  q_bulk.assign(padded, 0.0);
  // Padding lanes get a unit volume so that densities stay finite there.
  vol0.assign(padded, 1.0);
  vol.assign(padded, 1.0);
  e_int.assign(padded, 0.0);
  e_hg.assign(padded, 0.0);
  active.assign(padded, 1);
  failed.assign(padded, 0);
  points = gauss_points;
  const std::size_t point_values = std::size_t(gauss_points) * padded;
  for (auto& s : sig_ip) s.assign(point_values, 0.0);
  for (auto& s : alpha_ip) s.assign(kinematic ? point_values : 0, 0.0);
  eps_p_ip.assign(plastic ? point_values : 0, 0.0);
  history = history_count;
  const auto h = static_cast<std::size_t>(history_count);
  hist.assign(gauss_points > 0 ? 0 : h * padded, 0.0);
  hist_ip.assign(h * point_values, 0.0);
  strain.assign(erosion.needsStrain() ? 6 * padded : 0, 0.0);
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
  bool shared(std::size_t node) const { return ptr[node + 1] - ptr[node] > 1; }
};

// Bucketed by node (a count per node, then each node's few ranks sorted and made distinct):
// the same CSR a sort of (node, rank) pairs gives, without sorting 8 pairs per element.
NodeRanks nodeRanks(const model::Model& model, const std::vector<int32_t>& elem_rank) {
  const std::size_t nn = model.nodes.size();
  std::vector<int32_t> count(nn + 1, 0);
  int32_t en[model::kMaxElementNodes];
  for (std::size_t g = 0; g < model.numElements(); ++g) {
    const int k = model.elementNodes(g, en);
    for (int a = 0; a < k; ++a) count[static_cast<std::size_t>(en[a]) + 1]++;
  }
  for (std::size_t n = 0; n < nn; ++n)
    if (count[n + 1] == 0) count[n + 1] = 1;  // element-less nodes live on rank 0
  std::partial_sum(count.begin(), count.end(), count.begin());
  std::vector<int32_t> rank(static_cast<std::size_t>(count[nn]), 0);
  std::vector<int32_t> fill(count.begin(), count.end() - 1);
  for (std::size_t g = 0; g < model.numElements(); ++g) {
    const int k = model.elementNodes(g, en);
    for (int a = 0; a < k; ++a)
      rank[static_cast<std::size_t>(fill[std::size_t(en[a])]++)] = elem_rank[g];
  }
  NodeRanks nr;
  nr.ptr.assign(nn + 1, 0);
  nr.rank.reserve(rank.size());
  for (std::size_t n = 0; n < nn; ++n) {
    const auto first = rank.begin() + count[n], last = rank.begin() + count[n + 1];
    std::sort(first, last);
    nr.rank.insert(nr.rank.end(), first, std::unique(first, last));
    nr.ptr[n + 1] = static_cast<int32_t>(nr.rank.size());
  }
  return nr;
}

// One corner of a force source (element or pressure segment) at a node.
struct Corner {
  int32_t node;    // model node
  int64_t source;  // global source number (element g, or num_elements + segment)
  int32_t corner;
  int32_t slot;     // local or ghost slot
  bool rotational;  // a moment corner (shells, beams)
  bool operator<(const Corner& o) const {
    if (node != o.node) return node < o.node;
    if (source != o.source) return source < o.source;
    return corner < o.corner;
  }
};

// The corners of global element g: shells and beams have a force corner and a moment corner
// at each node (blocks.hpp, "Slot layout").
constexpr int kMaxCorners = std::max(8, model::kMaxElementNodes);
int elementCorners(const model::Model& model, std::size_t g, Corner out[kMaxCorners]) {
  int32_t en[model::kMaxElementNodes];
  const int k = model.elementNodes(g, en);
  const auto family = model.element(g).first;
  const bool rot = family == model::Family::Shell || family == model::Family::Beam;
  int n = 0;
  for (int a = 0; a < k; ++a) out[n++] = {en[a], int64_t(g), a, -1, false};
  if (rot)
    for (int a = 0; a < k; ++a) out[n++] = {en[a], int64_t(g), k + a, -1, true};
  return n;
}

// Corners ordered by (node, source, corner): bucketed by node, then each node's few corners
// sorted (no two corners share source and corner, so the order is the one a sort of the whole
// list gives).
void sortCorners(std::vector<Corner>& corners) {
  if (corners.empty()) return;
  const auto top =
      std::max_element(corners.begin(), corners.end(), [](const Corner& a, const Corner& b) {
        return a.node < b.node;
      })->node;
  std::vector<std::size_t> start(static_cast<std::size_t>(top) + 2, 0);
  for (const Corner& c : corners) start[static_cast<std::size_t>(c.node) + 1]++;
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Corner> out(corners.size());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (const Corner& c : corners) out[fill[static_cast<std::size_t>(c.node)]++] = c;
  for (std::size_t n = 0; n + 1 < start.size(); ++n)
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(start[n]),
              out.begin() + static_cast<std::ptrdiff_t>(start[n + 1]));
  corners.swap(out);
}

GatherPlan gatherPlan(std::vector<Corner> corners, const std::vector<int32_t>& local_of,
                      std::size_t num_nodes) {
  sortCorners(corners);
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

// The model's curve with a model curve index, as the law units see it.
materials::CurveData curveOf(const model::Model& model, int32_t index) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.curves.size())
    throw util::InputError("curve index " + std::to_string(index) + " does not name a curve");
  const model::Curve& c = model.curves[static_cast<std::size_t>(index)];
  return {c.id, c.x, c.y};
}

// "deck.k:12: *MAT_ELASTIC 3: ", the prefix of a law's messages.
std::string materialAt(const model::Material& mat) {
  return mat.where.str() + ": " + model::materialKeyword(mat.law) + " " + std::to_string(mat.id) +
         ": ";
}

// The model's table with a model table index, as the law units see it.
materials::TableData tableOf(const model::Model& model, int32_t index) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.tables.size())
    throw util::InputError("table index " + std::to_string(index) + " does not name a table");
  const model::Table& t = model.tables[static_cast<std::size_t>(index)];
  return {t.id, t.values, t.curves};
}

// The kernel law of a part's block; solids get the part's equation of state (*PART EOSID).
materials::Law lawOf(const model::Model& model, const model::Part& part, bool solid) {
  const auto& mat = model.materials[static_cast<std::size_t>(part.material)];
  const materials::Eos* eos = solid && part.eos != model::kNone
                                  ? &model.eos[static_cast<std::size_t>(part.eos)].eos
                                  : nullptr;
  const materials::CurveAt curves([&](int32_t i) { return curveOf(model, i); },
                                  [&](int32_t i) { return tableOf(model, i); });
  return materials::makeLaw(mat.law, curves, materialAt(mat), eos);
}

bool isRigid(const model::Model& model, const model::Part& part) {
  return part.material != model::kNone &&
         std::holds_alternative<model::RigidLaw>(
             model.materials[static_cast<std::size_t>(part.material)].law);
}

// A shell or beam part whose elements give mass only: rigid (their body moves them) or of a
// law whose shells and beams are bypassed (*MAT_NULL).
bool massOnly(const model::Model& model, const model::Part& part) {
  return isRigid(model, part) ||
         (part.material != model::kNone &&
          materials::massOnlyStructures(
              model.materials[static_cast<std::size_t>(part.material)].law));
}

// Fills the part of a block every family shares; `conn` gets the local nodes of element k.
template <class Block, class List>
void fillBase(Block& b, const model::Model& model, int32_t part_index,
              const std::vector<int32_t>& elems, std::size_t shared_count, int batch,
              const List& list, const std::vector<int32_t>& local_of) {
  const auto& part = model.parts[static_cast<std::size_t>(part_index)];
  b.part = part_index;
  b.part_id = part.id;
  b.elem = elems;
  b.shared_count = shared_count;
  b.shared_end = std::min(elems.size(), (shared_count + std::size_t(batch) - 1) /
                                            std::size_t(batch) * std::size_t(batch));
  b.elem_id.resize(elems.size());
  b.conn.resize(elems.size());
  for (std::size_t k = 0; k < elems.size(); ++k) {
    const auto e = static_cast<std::size_t>(elems[k]);
    b.elem_id[k] = list.id[e];
    for (std::size_t a = 0; a < list.nodes[e].size(); ++a)
      b.conn[k][a] = local_of[static_cast<std::size_t>(list.nodes[e][a])];
  }
}

}  // namespace

namespace {

// Builds one rank's Subdomain step by step (buildSubdomain below reads as the steps). The
// slots are numbered as the steps run: element corners block by block, then pressure
// segments, then what the neighbours send.
class SubdomainBuilder {
 public:
  SubdomainBuilder(const model::Model& m, const std::vector<int32_t>& ranks, int r, int nr_ranks)
      : model(m),
        elem_rank(ranks),
        rank(r),
        num_ranks(nr_ranks),
        nr(nodeRanks(m, ranks)),
        num_elements(int64_t(m.numElements())) {}

  Subdomain build() {
    counts();
    nodes();
    // A part's solids split by formulation (*CONTROL_SOLID ESORT sorts its tetrahedra out).
    // The 10-node tetrahedra (ELFORM 16) make blocks of their own type (Tet10Block).
    for (auto& [key, elems, shared] :
         groupByPart(model::Family::Solid, model.solids,
                     [&](std::size_t e) { return model.solidFormulation(e); })) {
      if (model::isQuadraticTetrahedron(key.second))
        addBlock(tet10Block(key.first, elems, shared), model::Family::Solid, sd.tet10_blocks);
      else
        addBlock(solidBlock(key.first, key.second, elems, shared), model::Family::Solid,
                 sd.solid_blocks);
    }
    for (auto& [key, elems, shared] : groupByPart(model::Family::Shell, model.shells))
      for (auto& [triangles, sub, sub_shared] : sortTriangles(key.first, elems, shared))
        addBlock(shellBlock(key.first, sub, sub_shared, triangles), model::Family::Shell,
                 sd.shell_blocks);
    // A part's beams split by their own sections (*ELEMENT_BEAM_THICKNESS; kNone: the part's).
    for (auto& [key, elems, shared] :
         groupByPart(model::Family::Beam, model.beams,
                     [&](std::size_t e) { return int(model.beams.section[e]); }))
      addBlock(beamBlock(key.first, key.second, elems, shared), model::Family::Beam,
               sd.beam_blocks);
    for (auto& [key, elems, shared] : groupByPart(model::Family::Discrete, model.discretes))
      addBlock(discreteBlock(key.first, elems, shared), model::Family::Discrete,
               sd.discrete_blocks);
    sphParticles();
    pressureSegments();
    if (num_ranks > 1) neighbours();
    sd.slots.assign(3 * slot, 0.0);
    gatherPlans();
    return std::move(sd);
  }

 private:
  // (part, formulation), elems, shared
  using Group = std::tuple<std::pair<int32_t, int>, std::vector<int32_t>, std::size_t>;

  void counts() {
    sd.rank = rank;
    sd.num_ranks = num_ranks;
    sd.global_nodes = static_cast<int64_t>(model.nodes.size());
    sd.global_solids = static_cast<int64_t>(model.solids.size());
    sd.global_elements = num_elements;
    for (int f = 0; f < model::kFamilies; ++f) {
      sd.family_offset[std::size_t(f)] =
          static_cast<int64_t>(model.familyOffset(static_cast<model::Family>(f)));
      sd.global_family[std::size_t(f)] =
          static_cast<int64_t>(model.familySize(static_cast<model::Family>(f)));
    }
  }

  // The SPH particles at nodes held here (all on the rank of the element-less nodes), one group
  // per part in ascending part order.
  void sphParticles() {
    const auto& in = model.sph;
    auto& out = sd.sph;
    out.alpha = model.controls.q_linear;
    out.beta = model.controls.q_quadratic;
    out.dim = in.dim;
    std::vector<int32_t> group_of(model.parts.size(), model::kNone);
    for (std::size_t k = 0; k < in.size(); ++k) {
      const int32_t n = local_of[std::size_t(in.node[k])];
      if (n == model::kNone) continue;
      const auto part = std::size_t(in.part[k]);
      if (group_of[part] == model::kNone) {
        const auto& p = model.parts[part];
        const auto& s = model.sph_sections[std::size_t(p.section)];
        SphBlock::Group g;
        g.part = in.part[k];
        g.part_id = p.id;
        g.law = lawOf(model, p, true);
        g.rho0 = model.materials[std::size_t(p.material)].rho;
        g.cslh = s.cslh;
        g.hmin = s.hmin;
        g.hmax = s.hmax;
        g.sphini = s.sphini;
        group_of[part] = int32_t(out.groups.size());
        out.groups.push_back(std::move(g));
      }
      out.node.push_back(n);
      out.group.push_back(group_of[part]);
      out.mass.push_back(in.mass[k]);
    }
  }

  // Nodes held here, ascending model index, and their arrays.
  void nodes() {
    const std::size_t n_model = model.nodes.size();
    local_of.assign(n_model, model::kNone);
    for (std::size_t n = 0; n < n_model; ++n)
      if (nr.holds(n, rank)) {
        local_of[n] = static_cast<int32_t>(sd.node_model.size());
        sd.node_model.push_back(static_cast<int32_t>(n));
      }
    nn = sd.node_model.size();
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
    sd.rotations = model.shells.size() + model.beams.size() > 0;
    if (sd.rotations) {
      sd.w.assign(3 * nn, 0.0);
      sd.moment.assign(3 * nn, 0.0);
      sd.inertia.assign(nn, 0.0);
    }
  }

  // Blocks: one per family, part and formulation, in that order. Elements touching a node
  // that another rank also holds come first, so their forces can be sent while the others are
  // computed; each group ascending.
  template <class List, class Form = int (*)(std::size_t)>
  std::vector<Group> groupByPart(
      model::Family family, const List& list, Form form = [](std::size_t) { return 0; }) const {
    using Key = std::pair<int32_t, int>;
    const std::size_t offset = model.familyOffset(family);
    std::map<Key, std::vector<int32_t>> rest, first;
    for (std::size_t e = 0; e < list.part.size(); ++e) {
      if (elem_rank[offset + e] != rank) continue;
      bool shared = false;
      for (int32_t n : list.nodes[e]) shared = shared || nr.shared(static_cast<std::size_t>(n));
      if constexpr (std::is_same_v<List, model::Solids>)
        if (list.quadratic(e))
          for (int32_t n : list.mid[e]) shared = shared || nr.shared(static_cast<std::size_t>(n));
      (shared ? first : rest)[Key{list.part[e], form(e)}].push_back(int32_t(e));
    }
    std::vector<Group> out;
    std::set<Key> keys;
    for (const auto& [p, v] : rest) keys.insert(p);
    for (const auto& [p, v] : first) keys.insert(p);
    for (const Key& p : keys) {
      std::vector<int32_t> elems = first.count(p) ? first[p] : std::vector<int32_t>{};
      const std::size_t shared_count = elems.size();
      if (rest.count(p)) elems.insert(elems.end(), rest[p].begin(), rest[p].end());
      out.emplace_back(p, std::move(elems), shared_count);
    }
    return out;
  }

  // The shells of an ELFORM 16 part as two groups, quadrilaterals and then triangles (n3 ==
  // n4), each keeping its shared elements first: the triangles run as C0 triangles, as all
  // degenerate quadrilaterals do in Crumple (ESORT = 1; src/elements/shell_full.cpp). Other
  // parts: the group as it is (the one-point kernel sorts its triangles per lane).
  std::vector<std::tuple<bool, std::vector<int32_t>, std::size_t>> sortTriangles(
      int32_t part_index, const std::vector<int32_t>& elems, std::size_t shared_count) const {
    const auto& part = model.parts[static_cast<std::size_t>(part_index)];
    if (model.shell_sections[static_cast<std::size_t>(part.section)].elform != 16)
      return {{false, elems, shared_count}};
    std::vector<int32_t> sub[2];
    std::size_t shared[2] = {0, 0};
    for (std::size_t k = 0; k < elems.size(); ++k) {
      const auto& n = model.shells.nodes[static_cast<std::size_t>(elems[k])];
      const int tri = n[2] == n[3] ? 1 : 0;
      sub[tri].push_back(elems[k]);
      if (k < shared_count) ++shared[tri];
    }
    std::vector<std::tuple<bool, std::vector<int32_t>, std::size_t>> out;
    for (int tri = 0; tri < 2; ++tri)
      if (!sub[tri].empty()) out.emplace_back(tri == 1, std::move(sub[tri]), shared[tri]);
    return out;
  }

  // Records the corners of a block's elements, gives the block its slots and keeps it.
  template <class Block>
  void addBlock(Block b, model::Family family, std::vector<Block>& blocks) {
    const std::size_t offset = model.familyOffset(family);
    const int per = Block::kSlotsPerElement;
    b.slot_offset = slot;
    Corner cs[kMaxCorners];
    for (std::size_t k = 0; k < b.size(); ++k) {
      const int n = elementCorners(model, offset + std::size_t(b.elem[k]), cs);
      for (int i = 0; i < n; ++i) {
        cs[i].slot = int32_t(slot + std::size_t(per) * k + std::size_t(cs[i].corner));
        internal.push_back(cs[i]);
      }
    }
    slot += std::size_t(per) * b.size();
    sd.num_elements += b.size();
    blocks.push_back(std::move(b));
  }

  SolidBlock solidBlock(int32_t part_index, int elform, const std::vector<int32_t>& elems,
                        std::size_t shared_count) const {
    const auto& part = model.parts[static_cast<std::size_t>(part_index)];
    const auto& mat = model.materials[static_cast<std::size_t>(part.material)];
    SolidBlock b;
    fillBase(b, model, part_index, elems, shared_count, kSolidBatch, model.solids, local_of);
    b.law = lawOf(model, part, true);
    b.rho0 = mat.rho;
    b.rigid = isRigid(model, part);
    b.erosion = mat.erosion.forSolids();
    b.hourglass = hourglassOf(model, part);
    const bool plastic = materials::isPlastic(b.law);
    const bool kinematic = materials::isKinematic(b.law);
    b.elform = elform;
    if (b.thickShell()) return thickShellBlock(std::move(b), part, plastic);
    // A fully integrated element has no hourglass modes to control.
    b.resize(b.size(), plastic, kinematic, b.elform == 1 && b.hourglass.qm > 0.0,
             model::isFullyIntegratedHex(b.elform) ? 8 : (b.elform == 15 ? 2 : 0),
             materials::historyCount(b.law));
    if (b.elform == 13) b.ev_nodal.assign(b.paddedSize(), 0.0);
    return b;
  }

  // Thick shells: NIP points of state through the thickness (SolidBlock), the section's rule
  // and shear factor; the plane-stress laws' back stress or strain in alpha_ip.
  SolidBlock thickShellBlock(SolidBlock b, const model::Part& part, bool plastic) const {
    const auto& sec = model.solid_sections[static_cast<std::size_t>(part.section)];
    b.shear_factor = sec.shrf;
    b.lobatto = sec.zeta.empty() && model.controls.shell_lobatto;
    b.zeta = sec.zeta;
    b.weight = sec.weight;
    b.erosion = {};  // refused on thick-shell parts (model/build_erosion.cpp)
    // ELFORM 2 (2 x 2 in the plane) has no hourglass modes to control.
    const bool selective = b.elform == model::kThickShellSelective;
    b.plane_points = selective ? 4 : 1;
    b.resize(b.size(), plastic, materials::hasShellAlpha(b.law), !selective && b.hourglass.qm > 0.0,
             sec.nip * b.plane_points, 0);
    return b;
  }

  Tet10Block tet10Block(int32_t part_index, const std::vector<int32_t>& elems,
                        std::size_t shared_count) const {
    const auto& part = model.parts[static_cast<std::size_t>(part_index)];
    const auto& mat = model.materials[static_cast<std::size_t>(part.material)];
    Tet10Block b;
    b.part = part_index;
    b.part_id = part.id;
    b.elem = elems;
    b.shared_count = shared_count;
    b.shared_end =
        std::min(elems.size(), (shared_count + kSolidBatch - 1) / kSolidBatch * kSolidBatch);
    b.elem_id.resize(elems.size());
    b.conn.resize(elems.size());
    for (std::size_t k = 0; k < elems.size(); ++k) {
      const auto e = static_cast<std::size_t>(elems[k]);
      b.elem_id[k] = model.solids.id[e];
      for (std::size_t a = 0; a < 4; ++a)
        b.conn[k][a] = local_of[static_cast<std::size_t>(model.solids.nodes[e][a])];
      for (std::size_t a = 0; a < 6; ++a)
        b.conn[k][4 + a] = local_of[static_cast<std::size_t>(model.solids.mid[e][a])];
    }
    b.law = lawOf(model, part, true);
    b.rho0 = mat.rho;
    b.rigid = isRigid(model, part);
    b.erosion = mat.erosion.forSolids();
    if (b.erosion.needsStrain())
      throw util::InputError(part.where.str() + ": part " + std::to_string(part.id) +
                             ": strain erosion criteria (*MAT_ADD_EROSION) are not supported "
                             "on 10-node tetrahedra (*SECTION_SOLID ELFORM 16)");
    return b;
  }

  ShellBlock shellBlock(int32_t part_index, const std::vector<int32_t>& elems,
                        std::size_t shared_count, bool triangles) const {
    const auto& part = model.parts[static_cast<std::size_t>(part_index)];
    const auto& mat = model.materials[static_cast<std::size_t>(part.material)];
    const auto& sec = model.shell_sections[static_cast<std::size_t>(part.section)];
    ShellBlock b;
    fillBase(b, model, part_index, elems, shared_count, kShellBatch, model.shells, local_of);
    b.law = lawOf(model, part, false);
    b.rho0 = mat.rho;
    b.rigid = massOnly(model, part);
    b.erosion = mat.erosion;
    // ELFORM 10 runs as 2 with the warping correction; the triangles of an ELFORM 16 part as
    // C0 triangles (sortTriangles).
    b.elform = sec.elform == 10 ? 2 : (triangles ? 4 : sec.elform);
    // 2D solids (ELFORM 13, 15) have one point and no thickness direction.
    b.nip = b.planar() ? 1 : sec.nip;
    b.lobatto = !b.planar() && model.controls.shell_lobatto;
    if (!b.planar() && !sec.zeta.empty()) {  // *INTEGRATION_SHELL (resizeShellBlock keeps it)
      b.zeta = sec.zeta;
      b.weight = sec.weight;
    }
    if (!b.planar())
      for (const double deg : sec.ply_angle) b.ply.push_back(deg * (std::numbers::pi / 180.0));
    b.shear_factor = sec.shrf;
    const auto hg = hourglassOf(model, part);
    b.ihq = hg.ihq;
    // IHQ 8: the fully integrated shell's warping projection (LS-DYNA *HOURGLASS IHQ 8).
    b.warping = b.elform == 16 && hg.ihq == 8;
    b.qm = hg.qm;
    // ELFORM 10 is Belytschko-Tsay with the Belytschko-Wong-Chiang warping correction.
    b.bwc = model.controls.shell_bwc || sec.elform == 10;
    b.thickness_update = model.controls.shell_thickness_update;
    b.corner_thickness.resize(b.size());
    for (std::size_t k = 0; k < b.size(); ++k) {
      const auto& t = model.shells.thickness[static_cast<std::size_t>(b.elem[k])];
      b.corner_thickness[k] = t[0] > 0 ? t : sec.t;
    }
    return b;
  }

  BeamBlock beamBlock(int32_t part_index, int32_t section, const std::vector<int32_t>& elems,
                      std::size_t shared_count) const {
    const auto& part = model.parts[static_cast<std::size_t>(part_index)];
    const auto& mat = model.materials[static_cast<std::size_t>(part.material)];
    const auto& sec = model.beam_sections[static_cast<std::size_t>(
        section == model::kNone ? part.section : section)];
    BeamBlock b;
    fillBase(b, model, part_index, elems, shared_count, 1, model.beams, local_of);
    b.law = lawOf(model, part, false);
    b.rho0 = materials::massDensityOf(b.law, mat.rho);
    b.rigid = massOnly(model, part);
    b.erosion = mat.erosion;  // EFFEPS alone (model/build_erosion.cpp), elements/beam.cpp
    b.section.elform = sec.elform;
    b.section.cst = sec.cst;
    b.section.ts1 = sec.ts1;
    b.section.ts2 = sec.ts2;
    b.section.tt1 = sec.tt1;
    b.section.tt2 = sec.tt2;
    b.section.a = sec.a;
    b.section.iss = sec.iss;
    b.section.itt = sec.itt;
    b.section.j = sec.j;
    b.section.sa = sec.sa;
    b.section.shear_factor = sec.shrf;
    b.section.qr = sec.qr;
    b.section.release = sec.release;
    if (sec.integration != model::kNone) {
      const auto& rule = model.beam_integrations[static_cast<std::size_t>(sec.integration)];
      b.section.user_points = rule.points;
      b.section.user_normalized = rule.normalized;
      b.section.user_ra = rule.ra;
    }
    b.stiffness_damping = part.stiffness_damping;
    b.stiffness_fraction = part.stiffness_fraction;
    b.orientation.resize(b.size());
    for (std::size_t k = 0; k < b.size(); ++k) {
      const auto e = static_cast<std::size_t>(b.elem[k]);
      const int32_t n3 = model.beams.orientation[e];
      b.conn[k][2] = n3 == model::kNone ? model::kNone : local_of[static_cast<std::size_t>(n3)];
      if (n3 != model::kNone)
        b.orientation[k] = model.nodes.x[static_cast<std::size_t>(n3)];
      else
        b.orientation[k] = {std::nan(""), std::nan(""), std::nan("")};
    }
    addPreloads(b);
    return b;
  }

  // *INITIAL_AXIAL_FORCE_BEAM of the block's elements (model::BeamPreload): the block keeps
  // the curves of the preloads that reach it and each element's index into them.
  void addPreloads(BeamBlock& b) const {
    for (const auto& p : model.beam_preloads) {
      int32_t index = model::kNone;
      for (std::size_t k = 0; k < b.size(); ++k) {
        if (!std::binary_search(p.beams.begin(), p.beams.end(), b.elem[k])) continue;
        if (index == model::kNone) {
          const auto& c = model.curves[static_cast<std::size_t>(p.curve)];
          index = static_cast<int32_t>(b.preloads.size());
          b.preloads.push_back({c.x, c.y, p.scale, p.kbend});
        }
        if (b.preload.empty()) b.preload.assign(b.size(), model::kNone);
        b.preload[k] = index;
      }
    }
  }

  DiscreteBlock discreteBlock(int32_t part_index, const std::vector<int32_t>& elems,
                              std::size_t shared_count) const {
    const auto& part = model.parts[static_cast<std::size_t>(part_index)];
    const auto& mat = model.materials[static_cast<std::size_t>(part.material)];
    DiscreteBlock b;
    fillBase(b, model, part_index, elems, shared_count, 1, model.discretes, local_of);
    b.law = materials::makeDiscreteLaw(
        mat.law, [&](int32_t i) { return curveOf(model, i); }, materialAt(mat));
    b.scale.resize(b.size());
    b.offset.resize(b.size());
    for (std::size_t k = 0; k < b.size(); ++k) {
      const auto e = static_cast<std::size_t>(b.elem[k]);
      b.scale[k] = model.discretes.scale[e];
      b.offset[k] = model.discretes.offset[e];
    }
    return b;
  }

  // Pressure segments: computed by the lowest rank that holds all four nodes.
  void pressureSegments() {
    auto segmentOwner = [&](std::size_t s) {
      const auto& nodes = model.pressure_loads[s].nodes;
      for (int r = 0; r < num_ranks; ++r) {
        bool all = true;
        for (int32_t n : nodes) all = all && nr.holds(static_cast<std::size_t>(n), r);
        if (all) return r;
      }
      return -1;
    };
    segment_owner.resize(model.pressure_loads.size());
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
        pressure.push_back({model.pressure_loads[s].nodes[a], num_elements + int64_t(s), a,
                            int32_t(slot + a), false});
      slot += 4;
    }
    sd.num_local_slots = slot;
  }

  // Neighbours: for each other rank sharing a node, what I send (my corners at nodes it
  // holds) and what I receive (its corners at nodes I hold), both in (source, corner) order.
  // Every rank knows the whole partition during set-up, so both sides derive the same lists
  // without a handshake.
  void neighbours() {
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
    Corner cs[kMaxCorners];
    for (std::size_t g = 0; g < model.numElements(); ++g) {
      const int q = elem_rank[g];
      if (q == rank) continue;
      const int n = elementCorners(model, g, cs);
      for (int i = 0; i < n; ++i)
        if (local_of[static_cast<std::size_t>(cs[i].node)] != model::kNone)
          recv[static_cast<std::size_t>(q)].push_back({{cs[i].source, cs[i].corner}, cs[i]});
    }
    for (std::size_t s = 0; s < model.pressure_loads.size(); ++s) {
      const int q = segment_owner[s];
      if (q == rank) continue;
      for (int a = 0; a < 4; ++a) {
        const int32_t n = model.pressure_loads[s].nodes[a];
        if (local_of[static_cast<std::size_t>(n)] != model::kNone)
          recv[static_cast<std::size_t>(q)].push_back(
              {{num_elements + int64_t(s), a}, {n, num_elements + int64_t(s), a, -1, false}});
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
      Subdomain::SlotPeer nodal{q, {}, {}};
      p.rank = q;
      for (const auto& [key, s_local] : sq) {
        p.send_slots.push_back(s_local);
        if (nodalPressureSource(key.first)) nodal.send_slots.push_back(s_local);
      }
      p.recv_first = slot;
      p.recv_count = rq.size();
      for (auto& [key, c] : rq) {
        if (nodalPressureSource(c.source)) nodal.recv_slots.push_back(int32_t(slot));
        c.slot = int32_t(slot++);
        (c.source < num_elements ? internal : pressure).push_back(c);
      }
      sd.peers.push_back(std::move(p));
      if (!nodal.send_slots.empty() || !nodal.recv_slots.empty())
        sd.nodal_volume_peers.push_back(std::move(nodal));
    }
  }

  // Whether global source g is a nodal-pressure tetrahedron (ELFORM 13) that computes forces.
  bool nodalPressureSource(int64_t g) const {
    if (g >= num_elements) return false;
    const auto [family, index] = model.element(std::size_t(g));
    if (family != model::Family::Solid) return false;
    const auto e = static_cast<std::size_t>(index);
    return model.solidFormulation(e) == 13 &&
           !isRigid(model, model.parts[static_cast<std::size_t>(model.solids.part[e])]);
  }

  // Gather plans: this fixed order of summation is what makes nodal forces independent of
  // how elements are split among threads and ranks (ARCHITECTURE.md, Determinism).
  void gatherPlans() {
    std::vector<Corner> moments;
    const auto split = std::stable_partition(internal.begin(), internal.end(),
                                             [](const Corner& c) { return !c.rotational; });
    moments.assign(split, internal.end());
    internal.erase(split, internal.end());
    std::vector<Corner> nodal;
    std::copy_if(internal.begin(), internal.end(), std::back_inserter(nodal),
                 [&](const Corner& c) { return nodalPressureSource(c.source); });
    sd.nodal_volume = gatherPlan(std::move(nodal), local_of, nn);
    sd.internal = gatherPlan(std::move(internal), local_of, nn);
    sd.rotational = gatherPlan(std::move(moments), local_of, nn);
    sd.pressure = gatherPlan(std::move(pressure), local_of, nn);
  }

  const model::Model& model;
  const std::vector<int32_t>& elem_rank;
  const int rank, num_ranks;
  const NodeRanks nr;
  const int64_t num_elements;
  Subdomain sd;
  std::vector<int32_t> local_of;  // local index of each model node, or kNone
  std::size_t nn = 0;             // local nodes
  std::size_t slot = 0;           // next force slot
  std::vector<Corner> internal, pressure;
  std::vector<int32_t> segment_owner;
};

}  // namespace

Subdomain buildSubdomain(const model::Model& model, const std::vector<int32_t>& elem_rank, int rank,
                         int num_ranks) {
  if (elem_rank.size() != model.numElements())
    throw std::invalid_argument("buildSubdomain: one rank per element expected");
  return SubdomainBuilder(model, elem_rank, rank, num_ranks).build();
}

namespace {
// The block holding element `index` of one family, and its position there: two ascending
// runs per block (the shared group, then the rest).
template <class Blocks, class F>
int64_t findIn(const Blocks& blocks, int32_t index, F&& value) {
  for (const auto& b : blocks) {
    const auto mid = b.elem.begin() + static_cast<long>(b.shared_count);
    for (auto [lo, hi] : {std::pair{b.elem.begin(), mid}, std::pair{mid, b.elem.end()}}) {
      auto it = std::lower_bound(lo, hi, index);
      if (it != hi && *it == index) return value(b, std::size_t(it - b.elem.begin()));
    }
  }
  return 0;
}
template <class F>
int64_t findElement(const Subdomain& sd, int64_t global_index, F&& value) {
  const model::Family f = sd.familyOf(global_index);
  const auto index = static_cast<int32_t>(global_index - sd.family_offset[std::size_t(f)]);
  switch (f) {
    case model::Family::Shell:
      return findIn(sd.shell_blocks, index, value);
    case model::Family::Beam:
      return findIn(sd.beam_blocks, index, value);
    case model::Family::Discrete:
      return findIn(sd.discrete_blocks, index, value);
    default:
      if (const int64_t found = findIn(sd.solid_blocks, index, value); found != 0) return found;
      return findIn(sd.tet10_blocks, index, value);
  }
}
}  // namespace

int32_t Subdomain::localNode(int32_t model_node) const {
  auto it = std::lower_bound(node_model.begin(), node_model.end(), model_node);
  if (it == node_model.end() || *it != model_node) return model::kNone;
  return static_cast<int32_t>(it - node_model.begin());
}

int64_t Subdomain::elementId(int64_t global_index) const {
  return findElement(*this, global_index,
                     [](const BlockBase& b, std::size_t k) { return b.elem_id[k]; });
}

int64_t Subdomain::elementPart(int64_t global_index) const {
  return findElement(*this, global_index,
                     [](const BlockBase& b, std::size_t) { return b.part_id; });
}

Subdomain buildSerialSubdomain(const model::Model& model) {
  return buildSubdomain(model, std::vector<int32_t>(model.numElements(), 0), 0, 1);
}

}  // namespace crumple::domain
