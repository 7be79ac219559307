// Element -> rank: METIS multilevel k-way on the dual graph, or recursive coordinate bisection.
#include <metis.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "partition/incidence.hpp"
#include "partition/partition.hpp"
#include "util/error.hpp"

namespace crumple::partition {

Method parseMethod(const std::string& name) {
  std::string s = name;
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (s == "metis") return Method::Metis;
  if (s == "rcb") return Method::Rcb;
  throw util::InputError("unknown partition method '" + name + "' (expected metis or rcb)");
}

const char* methodName(Method m) {
  return m == Method::Metis ? "metis" : "rcb";
}

std::vector<int32_t> elementWeights(const model::Model& model) {
  return elementWeights(model, Options{});
}

std::vector<int32_t> elementWeights(const model::Model& model, const Options& opt) {
  const std::size_t ne = model.numElements();
  if (!(opt.contact_bias > 0.0) || !std::isfinite(opt.contact_bias))
    throw std::invalid_argument("partition: contact_bias must be positive and finite");
  if (!opt.contact_elements.empty() && opt.contact_elements.size() != ne)
    throw std::invalid_argument("partition: contact_elements must have one flag per element");
  // Cost per element-cycle by material law and hourglass form, measured with the one-point
  // hex kernel (docs/parallel.md, "Element weights"): plasticity adds the radial return (and
  // rate effects, a pow) to the elastic update; stiffness hourglass control (IHQ 4-5) adds its
  // hourglass stress update. A part without a material (only in a tolerant `check` read)
  // counts as elastic.
  auto costOfPart = [&](const model::Part& part) {
    const model::MaterialLaw* law =
        part.material != model::kNone && std::size_t(part.material) < model.materials.size()
            ? &model.materials[std::size_t(part.material)].law
            : nullptr;
    // Each law declares its cost class (materials/law.hpp).
    return law ? materials::costOf(*law) : materials::Cost::Elastic;
  };
  auto partWeight = [&](const model::Part& part) -> int32_t {
    const materials::Cost cost = costOfPart(part);
    if (cost == materials::Cost::Rigid) return kWeightRigid;
    const bool plastic = cost == materials::Cost::Plastic;
    switch (part.section_kind) {
      case model::SectionKind::Shell:
        return plastic ? kWeightShellPlastic : kWeightShellElastic;
      case model::SectionKind::Beam:
        return kWeightBeam;
      case model::SectionKind::Discrete:
        return kWeightDiscrete;
      case model::SectionKind::Solid:
      case model::SectionKind::Sph:  // no element: particles live with element-less nodes
        break;
    }
    const int32_t base = plastic ? kWeightSolidPlastic : kWeightSolidElastic;
    const bool full =
        part.section != model::kNone && std::size_t(part.section) < model.solid_sections.size() &&
        model::isFullyIntegratedHex(model.solid_sections[std::size_t(part.section)].elform);
    if (full) return base * kWeightFullyIntegratedFactor / 10;  // 8 points, no hourglass
    const int ihq =
        part.hourglass != model::kNone && std::size_t(part.hourglass) < model.hourglass.size()
            ? model.hourglass[std::size_t(part.hourglass)].ihq
            : model.controls.hourglass_ihq;
    return ihq >= 4 ? base + kWeightStiffnessHourglass : base;
  };
  std::vector<int32_t> part_weight(model.parts.size());
  for (std::size_t p = 0; p < model.parts.size(); ++p) part_weight[p] = partWeight(model.parts[p]);
  std::vector<int32_t> w(ne, kWeightSolidElastic);
  for (std::size_t e = 0; e < ne; ++e) {
    const int32_t p = model.elementPart(e);
    if (p >= 0 && std::size_t(p) < part_weight.size()) w[e] = part_weight[std::size_t(p)];
    // A tetrahedron (ELFORM 10, 13) runs the one-point kernel without hourglass control (not
    // measured apart: it gathers the same eight corners); a pentahedron (ELFORM 15) the
    // multi-point kernel with 2 points instead of 8 (estimated, kWeightPentahedronFactor); a
    // 10-node tetrahedron (ELFORM 16) 4 points on 10 nodes, half the 8-point hexahedron's
    // (estimated, not measured).
    const int form = p >= 0 && e < model.solids.size() ? model.solidFormulation(e) : 0;
    if (w[e] != kWeightRigid &&
        (model::isTetrahedron(form) || form == 15 || model::isQuadraticTetrahedron(form))) {
      const int32_t base = costOfPart(model.parts[std::size_t(p)]) == materials::Cost::Plastic
                               ? kWeightSolidPlastic
                               : kWeightSolidElastic;
      w[e] = model::isTetrahedron(form) ? base
             : form == 15               ? base * kWeightPentahedronFactor / 10
                                        : base * kWeightFullyIntegratedFactor / 20;
    }
    if (!opt.contact_elements.empty() && opt.contact_elements[e] != 0)
      w[e] = std::max<int32_t>(1, int32_t(std::lround(w[e] * opt.contact_bias)));
  }
  return w;
}

namespace {

bool isConnected(const DualGraph& g) {
  const std::size_t n = g.numVertices();
  if (n == 0) return true;
  std::vector<uint8_t> seen(n, 0);
  std::vector<int64_t> stack{0};
  seen[0] = 1;
  std::size_t count = 1;
  while (!stack.empty()) {
    const auto v = std::size_t(stack.back());
    stack.pop_back();
    for (int64_t j = g.xadj[v]; j < g.xadj[v + 1]; ++j) {
      const auto u = std::size_t(g.adjncy[std::size_t(j)]);
      if (!seen[u]) {
        seen[u] = 1;
        ++count;
        stack.push_back(int64_t(u));
      }
    }
  }
  return count == n;
}

idx_t toIdx(int64_t v, const char* what) {
  if (v > int64_t(std::numeric_limits<idx_t>::max()))
    throw std::runtime_error(std::string("METIS: ") + what + " (" + std::to_string(v) +
                             ") exceeds its " + std::to_string(IDXTYPEWIDTH) +
                             "-bit index type; rebuild METIS with IDXTYPEWIDTH 64");
  return idx_t(v);
}

const char* metisStatus(int rc) {
  switch (rc) {
    case METIS_ERROR_INPUT:
      return "input error";
    case METIS_ERROR_MEMORY:
      return "out of memory";
    default:
      return "error";
  }
}

// Multilevel k-way partitioning (Karypis & Kumar 1998, SIAM J. Sci. Comput. 20(1) 359-392):
// coarsen by heavy-edge matching, partition the coarsest graph, project back with greedy
// boundary refinement. Objective: edge cut, i.e. the number of shared faces, which tracks the
// number of shared nodes and so the exchange volume. Balance target 1% (UFACTOR 10) since a
// rank's compute time is the whole cycle's critical path; a fixed seed makes it deterministic.
// Two parts use multilevel recursive bisection, which optimises exactly that one cut.
std::vector<int32_t> metisPartition(const DualGraph& g, const std::vector<int32_t>& weights,
                                    int parts) {
  idx_t nvtxs = toIdx(int64_t(g.numVertices()), "the number of elements");
  toIdx(int64_t(g.adjncy.size()), "the dual graph size");
  std::vector<idx_t> xadj(g.xadj.begin(), g.xadj.end());
  // METIS reads adjncy[0] even for a graph without edges; never hand it a null pointer.
  std::vector<idx_t> adjncy(std::max<std::size_t>(g.adjncy.size(), 1), 0);
  std::copy(g.adjncy.begin(), g.adjncy.end(), adjncy.begin());
  std::vector<idx_t> vwgt(weights.begin(), weights.end());
  int64_t total = 0;
  for (int32_t w : weights) total += w;
  toIdx(total, "the total element weight");

  idx_t ncon = 1, nparts = parts, objval = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 7;
  options[METIS_OPTION_UFACTOR] = 10;
  options[METIS_OPTION_NUMBERING] = 0;
  std::vector<idx_t> part(std::size_t(nvtxs), 0);
  int rc;
  if (parts == 2) {
    rc =
        METIS_PartGraphRecursive(&nvtxs, &ncon, xadj.data(), adjncy.data(), vwgt.data(), nullptr,
                                 nullptr, &nparts, nullptr, nullptr, options, &objval, part.data());
  } else {
    // Contiguous parts keep each rank's exchange partners few; METIS refuses the option (with
    // an error, not a fallback) on a disconnected graph, e.g. separate bodies before contact.
    options[METIS_OPTION_CONTIG] = isConnected(g) ? 1 : 0;
    rc = METIS_PartGraphKway(&nvtxs, &ncon, xadj.data(), adjncy.data(), vwgt.data(), nullptr,
                             nullptr, &nparts, nullptr, nullptr, options, &objval, part.data());
  }
  if (rc != METIS_OK)
    throw std::runtime_error(std::string("METIS_PartGraph") + (parts == 2 ? "Recursive" : "Kway") +
                             " failed (" + metisStatus(rc) + ") partitioning " +
                             std::to_string(nvtxs) + " elements into " + std::to_string(parts) +
                             " parts");
  std::vector<int32_t> out(part.size());
  for (std::size_t e = 0; e < part.size(); ++e) {
    if (part[e] < 0 || part[e] >= nparts)
      throw std::runtime_error("METIS returned part " + std::to_string(part[e]) + " outside 0.." +
                               std::to_string(parts - 1));
    out[e] = int32_t(part[e]);
  }
  return out;
}

// Recursive coordinate bisection (Berger & Bokhari 1987, IEEE Trans. Comput. C-36(5)
// 570-580), generalised to any part count: a set destined for p ranks is cut across its
// longest extent at the weighted point that gives the lower side floor(p/2)/p of the weight,
// then each side is cut again for its own share of ranks. Elements are ordered by
// (centroid coordinate, element index), so equal coordinates never make the result depend on
// the sort algorithm.
void rcb(std::vector<int32_t>& elems, std::size_t lo, std::size_t hi, int parts, int first_rank,
         const std::vector<model::Vec3>& centroid, const std::vector<int32_t>& weights,
         std::vector<int32_t>& rank) {
  if (parts == 1) {
    for (std::size_t i = lo; i < hi; ++i) rank[std::size_t(elems[i])] = first_rank;
    return;
  }
  model::Vec3 mn = centroid[std::size_t(elems[lo])], mx = mn;
  for (std::size_t i = lo; i < hi; ++i)
    for (int c = 0; c < 3; ++c) {
      mn[c] = std::min(mn[c], centroid[std::size_t(elems[i])][c]);
      mx[c] = std::max(mx[c], centroid[std::size_t(elems[i])][c]);
    }
  int axis = 0;
  for (int c = 1; c < 3; ++c)
    if (mx[c] - mn[c] > mx[axis] - mn[axis]) axis = c;
  std::sort(elems.begin() + std::ptrdiff_t(lo), elems.begin() + std::ptrdiff_t(hi),
            [&](int32_t a, int32_t b) {
              const double ca = centroid[std::size_t(a)][axis];
              const double cb = centroid[std::size_t(b)][axis];
              return ca < cb || (ca == cb && a < b);
            });
  const int left_parts = parts / 2, right_parts = parts - left_parts;
  int64_t total = 0;
  for (std::size_t i = lo; i < hi; ++i) total += weights[std::size_t(elems[i])];
  // Target: total * left_parts / parts, compared exactly in integers (scaled by parts).
  const int64_t target_x_parts = total * left_parts;
  // Each side keeps at least one element per rank it still has to feed.
  const std::size_t kmin = lo + std::size_t(left_parts);
  const std::size_t kmax = hi - std::size_t(right_parts);
  std::size_t split = kmin;
  int64_t below = 0;
  for (std::size_t i = lo; i < kmin; ++i) below += weights[std::size_t(elems[i])];
  int64_t best = std::abs(below * parts - target_x_parts);
  for (std::size_t k = kmin; k < kmax; ++k) {
    below += weights[std::size_t(elems[k])];
    const int64_t err = std::abs(below * parts - target_x_parts);
    if (err < best) {
      best = err;
      split = k + 1;
    } else if (below * parts > target_x_parts) {
      break;  // the error only grows from here
    }
  }
  rcb(elems, lo, split, left_parts, first_rank, centroid, weights, rank);
  rcb(elems, split, hi, right_parts, first_rank + left_parts, centroid, weights, rank);
}

std::vector<int32_t> rcbPartition(const model::Model& model, const std::vector<int32_t>& weights,
                                  int parts) {
  const std::size_t ne = model.numElements();
  std::vector<model::Vec3> centroid(ne);
  int32_t d[model::kMaxElementNodes];
  for (std::size_t e = 0; e < ne; ++e) {
    const int k = detail::elementDistinctNodes(model, e, d);
    model::Vec3 c{0, 0, 0};
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < 3; ++j) c[j] += model.nodes.x[std::size_t(d[i])][j];
    for (int j = 0; j < 3; ++j) c[j] /= k;
    centroid[e] = c;
  }
  std::vector<int32_t> elems(ne);
  std::iota(elems.begin(), elems.end(), 0);
  std::vector<int32_t> rank(ne, 0);
  rcb(elems, 0, elems.size(), parts, 0, centroid, weights, rank);
  return rank;
}

// METIS may leave a part empty when parts approach the element count; a rank without elements
// would still have to take part in every exchange, so each empty rank takes one element from
// the rank with most elements: the one with fewest same-rank neighbours (a boundary element,
// so the donor stays connected as far as possible), lowest index on ties.
void fillEmptyRanks(const DualGraph& g, int parts, std::vector<int32_t>& rank) {
  std::vector<int64_t> count(std::size_t(parts), 0);
  for (int32_t r : rank) ++count[std::size_t(r)];
  for (int p = 0; p < parts; ++p) {
    if (count[std::size_t(p)] > 0) continue;
    const auto donor =
        int32_t(std::max_element(count.begin(), count.end()) - count.begin());  // first max
    int64_t best_e = -1, best_same = std::numeric_limits<int64_t>::max();
    for (std::size_t e = 0; e < rank.size(); ++e) {
      if (rank[e] != donor) continue;
      int64_t same = 0;
      for (int64_t j = g.xadj[e]; j < g.xadj[e + 1]; ++j)
        same += rank[std::size_t(g.adjncy[std::size_t(j)])] == donor;
      if (same < best_same) {
        best_same = same;
        best_e = int64_t(e);
      }
    }
    rank[std::size_t(best_e)] = p;
    --count[std::size_t(donor)];
    ++count[std::size_t(p)];
  }
}

}  // namespace

std::vector<int32_t> partitionElements(const model::Model& model, int parts, const Options& opt) {
  const std::size_t ne = model.numElements();
  if (parts < 1)
    throw util::InputError("cannot split " + std::to_string(ne) + " elements over " +
                           std::to_string(parts) + " ranks: the rank count must be at least 1");
  // One rank takes everything, also a deck of SPH particles only (no elements to split).
  if (parts == 1) return std::vector<int32_t>(ne, 0);
  if (std::size_t(parts) > ne)
    throw util::InputError("cannot split " + std::to_string(ne) + " elements over " +
                           std::to_string(parts) + " ranks");
  const std::vector<int32_t> weights = elementWeights(model, opt);
  if (opt.method == Method::Rcb) return rcbPartition(model, weights, parts);
  const DualGraph g = buildDualGraph(model);
  std::vector<int32_t> rank = metisPartition(g, weights, parts);
  fillEmptyRanks(g, parts, rank);
  return rank;
}

}  // namespace crumple::partition
