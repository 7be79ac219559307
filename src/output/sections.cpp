#include "output/sections.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "util/vec3.hpp"

namespace crumple::output {

namespace {

using model::Vec3;
using util::add;
using util::cross;
using util::dot;
using util::scale;
using util::sub;

Vec3 at(const domain::NodeVector& x, int32_t n) {
  const std::size_t i = 3 * static_cast<std::size_t>(n);
  return {x[i], x[i + 1], x[i + 2]};
}

// Where the corners of an element of each family have their force and moment slots
// (domain/blocks.hpp, "Slot layout"): corners, and the offset of the moment slots (0: none).
template <class Block>
constexpr int forceCorners() {
  if constexpr (std::is_same_v<Block, domain::SolidBlock>) return 8;
  if constexpr (std::is_same_v<Block, domain::ShellBlock>) return 4;
  return 2;
}
template <class Block>
constexpr int momentOffset() {
  if constexpr (std::is_same_v<Block, domain::ShellBlock>) return 4;
  if constexpr (std::is_same_v<Block, domain::BeamBlock>) return 2;
  return 0;
}

template <class Block>
bool isActive(const Block& b, std::size_t k) {
  if constexpr (requires { b.active; })
    return b.active.empty() || b.active[k] != 0;
  else
    return true;
}

// The points where the plane cuts the segments a-b of `edges`, without repeats.
template <std::size_t N>
std::vector<Vec3> cutPoints(const Vec3* x, const double* d, const std::array<int[2], N>& edges) {
  std::vector<Vec3> points;
  for (const auto& e : edges) {
    const double da = d[e[0]], db = d[e[1]];
    if ((da >= 0.0) == (db >= 0.0)) continue;
    const Vec3 p = add(x[e[0]], scale(sub(x[e[1]], x[e[0]]), da / (da - db)));
    const bool seen = std::any_of(points.begin(), points.end(), [&](const Vec3& q) {
      return dot(sub(p, q), sub(p, q)) <= 1e-24 * (1.0 + dot(p, p));
    });
    if (!seen) points.push_back(p);
  }
  return points;
}

constexpr std::array<int[2], 12> kHexEdges = {{{0, 1},
                                               {1, 2},
                                               {2, 3},
                                               {3, 0},
                                               {4, 5},
                                               {5, 6},
                                               {6, 7},
                                               {7, 4},
                                               {0, 4},
                                               {1, 5},
                                               {2, 6},
                                               {3, 7}}};
constexpr std::array<int[2], 4> kQuadEdges = {{{0, 1}, {1, 2}, {2, 3}, {3, 0}}};

// The area of a cut through element k of a block: a solid's `solid_area`, a shell's cut length
// (between the two points of `edge`) times its thickness, a beam's section area.
template <class Block>
double familyArea(const Block& b, std::size_t k, double solid_area, const std::vector<Vec3>& edge) {
  if constexpr (std::is_same_v<Block, domain::SolidBlock>) {
    return solid_area;
  } else if constexpr (std::is_same_v<Block, domain::ShellBlock>) {
    const double thick = b.thick.size() > k ? b.thick[k] : 0.0;
    return edge.size() == 2 ? util::norm(sub(edge[1], edge[0])) * thick : 0.0;
  } else if constexpr (std::is_same_v<Block, domain::BeamBlock>) {
    return b.section.a;
  } else {
    return 0.0;
  }
}

// The plane cut's area through element k of a block, from the initial coordinates.
template <class Block>
double cutArea(const Block& b, std::size_t k, const Vec3* x, const model::CrossSection& cs) {
  if constexpr (std::is_same_v<Block, domain::SolidBlock>) {
    std::array<Vec3, 8> corners;
    std::copy(x, x + 8, corners.begin());
    return familyArea(b, k, hexCutArea(corners, cs.center, cs.normal), {});
  } else if constexpr (std::is_same_v<Block, domain::ShellBlock>) {
    double d[4];
    for (int a = 0; a < 4; ++a) d[a] = dot(sub(x[a], cs.center), cs.normal);
    return familyArea(b, k, 0.0, cutPoints(x, d, kQuadEdges));
  } else {
    return familyArea(b, k, 0.0, {});
  }
}

// Inside the circle of RADIUS about the tail, or the LENL x LENM rectangle from it (an
// unbounded direction always is).
bool withinBounds(const Vec3& p, const model::CrossSection& cs) {
  const Vec3 r = sub(p, cs.center);
  if (cs.radius > 0.0) {
    const Vec3 in_plane = sub(r, scale(cs.normal, dot(r, cs.normal)));
    return dot(in_plane, in_plane) <= cs.radius * cs.radius;
  }
  const Vec3 m = cross(cs.normal, cs.l);
  const double u = dot(r, cs.l), v = dot(r, m);
  return (cs.lenl <= 0.0 || (u >= 0.0 && u <= cs.lenl)) &&
         (cs.lenm <= 0.0 || (v >= 0.0 && v <= cs.lenm));
}

// A plane cut: element k of the block has corners on both sides of the plane and its centre
// within the bounds; `on` marks the corners on the positive side, `area` the cut's area.
template <class Block, int N>
bool planeCut(const Block& b, std::size_t k, const model::CrossSection& cs, const Vec3 (&x)[N],
              bool (&on)[N], double& area) {
  double d[N];
  Vec3 centre{};
  for (int a = 0; a < N; ++a) {
    d[a] = dot(sub(x[a], cs.center), cs.normal);
    centre = add(centre, scale(x[a], 1.0 / N));
    on[a] = d[a] >= 0.0;
  }
  const auto [lo, hi] = std::minmax_element(d, d + N);
  if (!(*lo < 0.0 && *hi >= 0.0) || !withinBounds(centre, cs)) return false;
  area = cutArea(b, k, x, cs);
  return true;
}

// The area of the face the cut nodes `on` of an element make, from the initial coordinates
// (*DATABASE_CROSS_SECTION_SET): a solid's face (the polygon of its cut nodes), a shell's edge
// times its thickness, a beam's section area.
template <class Block, int N>
double setCutArea(const Block& b, std::size_t k, const Vec3 (&x)[N], const bool (&on)[N]) {
  std::vector<Vec3> p;
  for (int a = 0; a < N; ++a)
    if (on[a] && std::none_of(p.begin(), p.end(), [&](const Vec3& q) { return q == x[a]; }))
      p.push_back(x[a]);
  // A solid's cut nodes are a face: its plane's normal from three of them.
  const Vec3 n = p.size() >= 3 ? cross(sub(p[1], p[0]), sub(p[2], p[0])) : Vec3{};
  const double length = util::norm(n);
  const double solid = length > 0.0 ? polygonArea(p, scale(n, 1.0 / length)) : 0.0;
  return familyArea(b, k, solid, p);
}

// A cut by sets: element k is in the section's set of its family and has nodes of the cut.
template <class Block, int N>
bool setCut(const domain::Subdomain& sd, const Block& b, std::size_t k,
            const model::CrossSection& cs, const Vec3 (&x)[N], bool (&on)[N], double& area) {
  const auto& members = cs.set_elements[static_cast<std::size_t>(Block::kFamily)];
  if (!std::binary_search(members.begin(), members.end(), b.elem[k])) return false;
  bool any = false;
  for (int a = 0; a < N; ++a) {
    const int64_t id = sd.node_id[std::size_t(b.conn[k][std::size_t(a)])];
    on[a] = std::binary_search(cs.set_nodes.begin(), cs.set_nodes.end(), id);
    any = any || on[a];
  }
  if (any) area = setCutArea(b, k, x, on);
  return any;
}

// One corner's record sent to rank 0: section, element, corner, node id, x, force, moment,
// area (the element's first record only).
constexpr std::size_t kRecord = 14;

}  // namespace

double hexCutArea(const std::array<Vec3, 8>& x, const Vec3& c, const Vec3& n) {
  double d[8];
  for (int a = 0; a < 8; ++a) d[a] = dot(sub(x[std::size_t(a)], c), n);
  return polygonArea(cutPoints(x.data(), d, kHexEdges), n);
}

double polygonArea(const std::vector<Vec3>& p, const Vec3& n) {
  if (p.size() < 3) return 0.0;
  // The points are the corners of a convex polygon in the plane: ordered by angle about their
  // mean, its area is half the sum of the cross products of successive corners.
  Vec3 mid{};
  for (const auto& q : p) mid = add(mid, scale(q, 1.0 / double(p.size())));
  Vec3 u = sub(p[0], mid);
  u = scale(u, 1.0 / util::norm(u));
  const Vec3 v = cross(n, u);
  std::vector<std::pair<double, Vec3>> ordered;
  for (const auto& q : p)
    ordered.emplace_back(std::atan2(dot(sub(q, mid), v), dot(sub(q, mid), u)), q);
  std::sort(ordered.begin(), ordered.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  Vec3 sum{};
  for (std::size_t i = 0; i < ordered.size(); ++i)
    sum = add(sum, cross(sub(ordered[i].second, mid),
                         sub(ordered[(i + 1) % ordered.size()].second, mid)));
  return 0.5 * std::abs(dot(sum, n));
}

SectionForces::SectionForces(const model::Model& model, const domain::Subdomain& sd)
    : sections_(model.cross_sections) {
  findCuts(model, sd, sd.solid_blocks);
  findCuts(model, sd, sd.shell_blocks);
  findCuts(model, sd, sd.beam_blocks);
  findCuts(model, sd, sd.discrete_blocks);
  std::sort(cuts_.begin(), cuts_.end(), [](const Cut& a, const Cut& b) {
    return a.section != b.section ? a.section < b.section : a.element < b.element;
  });
}

template <class Block>
void SectionForces::findCuts(const model::Model&, const domain::Subdomain& sd,
                             const std::vector<Block>& blocks) {
  constexpr int kCorners = forceCorners<Block>();
  for (std::size_t bi = 0; bi < blocks.size(); ++bi) {
    const Block& b = blocks[bi];
    if (b.rigid) continue;  // no force: rigid parts pass theirs through the rigid body
    for (std::size_t s = 0; s < sections_.size(); ++s) {
      const auto& cs = sections_[s];
      if (!cs.by_set && !cs.parts.empty() &&
          !std::binary_search(cs.parts.begin(), cs.parts.end(), b.part))
        continue;
      for (std::size_t k = 0; k < b.size(); ++k) {
        Vec3 x[kCorners];
        bool on[kCorners];  // the corner is a node of the cut (its force counts)
        double area = 0.0;
        for (int a = 0; a < kCorners; ++a) x[a] = at(sd.x0, b.conn[k][std::size_t(a)]);
        if (!(cs.by_set ? setCut(sd, b, k, cs, x, on, area) : planeCut(b, k, cs, x, on, area)))
          continue;
        Cut cut;
        cut.section = int32_t(s);
        cut.element = sd.globalElement(Block::kFamily, b.elem[k]);
        cut.family = Block::kFamily;
        cut.block = bi;
        cut.k = k;
        cut.area = area;
        const std::size_t first = b.slot_offset + std::size_t(Block::kSlotsPerElement) * k;
        for (int a = 0; a < kCorners; ++a) {
          if (!on[a]) continue;
          const int32_t moment =
              momentOffset<Block>() ? int32_t(first) + momentOffset<Block>() + a : -1;
          cut.corners.push_back({b.conn[k][std::size_t(a)], int32_t(first) + a, moment});
        }
        cuts_.push_back(std::move(cut));
      }
    }
  }
}

bool SectionForces::active(const domain::Subdomain& sd, const Cut& c) {
  switch (c.family) {
    case model::Family::Solid:
      return isActive(sd.solid_blocks[c.block], c.k);
    case model::Family::Shell:
      return isActive(sd.shell_blocks[c.block], c.k);
    case model::Family::Beam:
      return isActive(sd.beam_blocks[c.block], c.k);
    case model::Family::Discrete:
      return true;
  }
  return true;
}

std::vector<double> SectionForces::records(const domain::Subdomain& sd, bool forces_valid) const {
  std::vector<double> out;
  for (const Cut& c : cuts_) {
    // An eroded element transmits nothing; its nodes still count for the centroid.
    const bool carries = forces_valid && active(sd, c);
    for (std::size_t i = 0; i < c.corners.size(); ++i) {
      const Corner& k = c.corners[i];
      const Vec3 x = at(sd.x, k.node);
      Vec3 f{}, m{};
      if (carries) {
        // The slots hold the force the element exerts on the node; the section force is its
        // reaction on the element (the positive side's pull on the negative side).
        for (int j = 0; j < 3; ++j)
          f[std::size_t(j)] = -sd.slots[3 * std::size_t(k.slot) + std::size_t(j)];
        if (k.moment_slot >= 0)
          for (int j = 0; j < 3; ++j)
            m[std::size_t(j)] = -sd.slots[3 * std::size_t(k.moment_slot) + std::size_t(j)];
      }
      const double rec[kRecord] = {double(c.section),
                                   double(c.element),
                                   double(i),
                                   double(sd.node_id[std::size_t(k.node)]),
                                   x[0],
                                   x[1],
                                   x[2],
                                   f[0],
                                   f[1],
                                   f[2],
                                   m[0],
                                   m[1],
                                   m[2],
                                   i == 0 ? c.area : 0.0};
      out.insert(out.end(), rec, rec + kRecord);
    }
  }
  return out;
}

std::vector<ascii::SectionRecord> SectionForces::compute(const domain::Subdomain& sd,
                                                         const comm::Communicator& comm,
                                                         bool forces_valid) const {
  const auto all = comm.allGather(records(sd, forces_valid));
  if (!comm.isRoot()) return {};
  const std::size_t n = all.size() / kRecord;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  auto rec = [&](std::size_t r) { return all.data() + kRecord * r; };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(rec(a), rec(a) + 3, rec(b), rec(b) + 3);
  });
  std::vector<ascii::SectionRecord> out;
  std::size_t r = 0;
  for (std::size_t s = 0; s < sections_.size(); ++s) {
    std::size_t end = r;
    while (end < n && rec(order[end])[0] == double(s)) ++end;
    out.push_back(sum(s, order, r, end, all));
    r = end;
  }
  return out;
}

ascii::SectionRecord SectionForces::sum(std::size_t s, const std::vector<std::size_t>& order,
                                        std::size_t begin, std::size_t end,
                                        const std::vector<double>& all) const {
  ascii::SectionRecord out;
  out.id = sections_[s].id;
  auto rec = [&](std::size_t i) { return all.data() + kRecord * order[i]; };
  // The centroid: the mean of the cut nodes, each once, in ascending node id.
  std::vector<std::pair<double, Vec3>> nodes;
  for (std::size_t i = begin; i < end; ++i)
    nodes.push_back({rec(i)[3], {rec(i)[4], rec(i)[5], rec(i)[6]}});
  std::sort(nodes.begin(), nodes.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  nodes.erase(std::unique(nodes.begin(), nodes.end(),
                          [](const auto& a, const auto& b) { return a.first == b.first; }),
              nodes.end());
  for (const auto& [id, x] : nodes) out.centroid = add(out.centroid, x);
  if (!nodes.empty()) out.centroid = scale(out.centroid, 1.0 / double(nodes.size()));
  for (std::size_t i = begin; i < end; ++i) {
    const double* q = rec(i);
    const Vec3 x{q[4], q[5], q[6]}, f{q[7], q[8], q[9]}, m{q[10], q[11], q[12]};
    out.force = add(out.force, f);
    out.moment = add(out.moment, add(cross(sub(x, out.centroid), f), m));
    out.area += q[13];
  }
  return out;
}

}  // namespace crumple::output
