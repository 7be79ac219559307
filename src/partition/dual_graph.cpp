// The element dual graph in O(N_elements): every face of an element is looked up in the
// incidence list of one of its nodes (the shortest), so the work per element is bounded by
// (faces per element) x (elements per node) x (nodes per element), constants of the mesh,
// never by the mesh size. No hashing and no global sort, hence no dependence on memory order:
// the result is a pure function of the connectivity.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "model/solid_shape.hpp"
#include "partition/incidence.hpp"
#include "partition/partition.hpp"

namespace crumple::partition {

namespace detail {

Incidence nodeElements(const model::Model& model) {
  const std::size_t ne = model.numElements();
  const std::size_t nn = model.nodes.size();
  Incidence inc;
  inc.ptr.assign(nn + 1, 0);
  int32_t d[model::kMaxElementNodes];
  for (std::size_t e = 0; e < ne; ++e) {
    const int k = elementDistinctNodes(model, e, d);
    for (int i = 0; i < k; ++i) {
      if (d[i] < 0 || std::size_t(d[i]) >= nn)
        throw std::invalid_argument("partition: " + model.elementName(e) +
                                    " refers to node index " + std::to_string(d[i]) +
                                    " outside the model");
      ++inc.ptr[std::size_t(d[i]) + 1];
    }
  }
  for (std::size_t n = 0; n < nn; ++n) inc.ptr[n + 1] += inc.ptr[n];
  inc.elem.resize(std::size_t(inc.ptr[nn]));
  std::vector<int64_t> fill(inc.ptr.begin(), inc.ptr.end() - 1);
  // Elements visited in ascending order, so every node's list comes out sorted.
  for (std::size_t e = 0; e < ne; ++e) {
    const int k = elementDistinctNodes(model, e, d);
    for (int i = 0; i < k; ++i) inc.elem[std::size_t(fill[std::size_t(d[i])]++)] = int32_t(e);
  }
  return inc;
}

}  // namespace detail

namespace {

// Faces of any element: a solid's as above; a shell's edges (so shells meeting along an edge
// are neighbours, and a shell lying on a solid's face or edge is the solid's); the two nodes
// of a beam or discrete element (neighbours through a shared node).
int anyElementFaces(const model::Model& model, std::size_t g, int32_t faces[6][4], int sizes[6]) {
  const auto [family, i] = model.element(g);
  if (family == model::Family::Solid)
    return model::solidFaces(model.solids.nodes[std::size_t(i)], faces, sizes);
  int32_t d[model::kMaxElementNodes];
  const int k = detail::elementDistinctNodes(model, g, d);
  if (family == model::Family::Shell) {
    if (k < 3) return 0;
    for (int a = 0; a < k; ++a) {
      faces[a][0] = d[a];
      faces[a][1] = d[(a + 1) % k];
      sizes[a] = 2;
    }
    return k;
  }
  for (int a = 0; a < k; ++a) {
    faces[a][0] = d[a];
    sizes[a] = 1;
  }
  return k;
}

bool containsAll(const int32_t* n, int count, const int32_t* face, int m) {
  for (int i = 0; i < m; ++i)
    if (std::find(n, n + count, face[i]) == n + count) return false;
  return true;
}

}  // namespace

DualGraph buildDualGraph(const model::Model& model) {
  const std::size_t ne = model.numElements();
  const detail::Incidence inc = detail::nodeElements(model);

  // Each element's faces find the elements holding all of the face's nodes. Pairs are recorded
  // in both directions: with mixed shapes (a tetrahedron's triangle lying on a hex's quad) only
  // one side sees the face, and the graph must still be symmetric.
  std::vector<std::pair<int32_t, int32_t>> pairs;
  pairs.reserve(ne * 7);
  int32_t faces[6][4];
  int sizes[6];
  for (std::size_t e = 0; e < ne; ++e) {
    const int nf = anyElementFaces(model, e, faces, sizes);
    for (int f = 0; f < nf; ++f) {
      // Scan the shortest incidence list among the face's nodes.
      int32_t best = faces[f][0];
      for (int i = 1; i < sizes[f]; ++i) {
        const auto len = [&](int32_t v) {
          return inc.ptr[std::size_t(v) + 1] - inc.ptr[std::size_t(v)];
        };
        if (len(faces[f][i]) < len(best)) best = faces[f][i];
      }
      for (int64_t j = inc.ptr[std::size_t(best)]; j < inc.ptr[std::size_t(best) + 1]; ++j) {
        const int32_t c = inc.elem[std::size_t(j)];
        if (std::size_t(c) == e) continue;
        int32_t cn[model::kMaxElementNodes];
        const int cc = model.elementNodes(std::size_t(c), cn);
        if (!containsAll(cn, cc, faces[f], sizes[f])) continue;
        pairs.emplace_back(int32_t(e), c);
        pairs.emplace_back(c, int32_t(e));
      }
    }
  }

  // Counting sort by the first element, then sort and deduplicate each (short) row.
  DualGraph g;
  g.xadj.assign(ne + 1, 0);
  for (const auto& [a, b] : pairs) ++g.xadj[std::size_t(a) + 1];
  for (std::size_t e = 0; e < ne; ++e) g.xadj[e + 1] += g.xadj[e];
  std::vector<int64_t> tmp(pairs.size());
  {
    std::vector<int64_t> fill(g.xadj.begin(), g.xadj.end() - 1);
    for (const auto& [a, b] : pairs) tmp[std::size_t(fill[std::size_t(a)]++)] = b;
  }
  pairs.clear();
  pairs.shrink_to_fit();
  g.adjncy.reserve(tmp.size() / 2);
  int64_t begin = 0;
  for (std::size_t e = 0; e < ne; ++e) {
    const auto first = tmp.begin() + g.xadj[e];
    const auto last = tmp.begin() + g.xadj[e + 1];
    std::sort(first, last);
    const auto end = std::unique(first, last);
    g.xadj[e] = begin;
    g.adjncy.insert(g.adjncy.end(), first, end);
    begin = int64_t(g.adjncy.size());
  }
  g.xadj[ne] = begin;
  return g;
}

}  // namespace crumple::partition
