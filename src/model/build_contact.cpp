// Meaning of *CONTACT_... and *CONTROL_CONTACT (LS-DYNA Keyword Manual Vol. I, "*CONTACT"):
// each interface's two sides resolved to nodes and segments, with the penalty stiffness of
// every segment taken from the element it bounds (Hallquist, LS-DYNA Theory Manual,
// "Contact-Impact Algorithm": k = f K A^2 / V for solids, f K A / (max diagonal) for shells).
#include <algorithm>
#include <cmath>
#include <map>

#include "deck/number.hpp"
#include "model/build_context.hpp"
#include "model/solid_shape.hpp"
#include "util/vec3.hpp"

namespace crumple::model::build {

namespace {
using deck::Card;
using deck::CardCursor;
using deck::keywordSpec;

using util::cross;
using util::dot;
using util::norm;
using util::sub;

// Bulk modulus of the part's material (rigid parts give theirs for contact only).
double bulkModulus(const Model& m, int32_t part) {
  // A part without a usable material exists only in a deck `crumple check` reads on past.
  const Part& p = m.parts[std::size_t(part)];
  const int32_t mat = p.material;
  if (mat == kNone) return 0.0;
  // Solids whose pressure comes from an equation of state: its bulk modulus at the initial
  // state, the one that sets their wave speed (*MAT_NULL: YM and PR serve shells and beams).
  if (p.eos != kNone &&
      (p.section_kind == SectionKind::Solid || p.section_kind == SectionKind::Sph))
    return materials::eosBulkModulus(m.eos[std::size_t(p.eos)].eos,
                                     m.materials[std::size_t(mat)].rho);
  const auto& law = m.materials[static_cast<std::size_t>(mat)].law;
  return std::visit(
      [](const auto& l) -> double {
        if constexpr (requires { l.E, l.nu; })
          return l.E / (3.0 * (1.0 - 2.0 * l.nu));
        else
          return 0.0;
      },
      law);
}

// Area vector of a quadrilateral (or triangle with n3 == n4): half the cross product of its
// diagonals, exact for a bilinear face.
Vec3 areaVector(const Model& m, const std::array<int32_t, 4>& s) {
  const auto& x = m.nodes.x;
  const auto c = cross(sub(x[std::size_t(s[2])], x[std::size_t(s[0])]),
                       sub(x[std::size_t(s[3])], x[std::size_t(s[1])]));
  return {0.5 * c[0], 0.5 * c[1], 0.5 * c[2]};
}
Vec3 centroid(const Model& m, const int32_t* n, int count) {
  Vec3 c{};
  for (int k = 0; k < count; ++k)
    for (int i = 0; i < 3; ++i) c[std::size_t(i)] += m.nodes.x[std::size_t(n[k])][std::size_t(i)];
  for (auto& v : c) v /= count;
  return c;
}

// Mean thickness of shell e: its part's *PART_CONTACT OPTT, else its own corner thicknesses,
// or its section's when it gives none.
double shellThickness(const Model& m, std::size_t e) {
  const double optt = m.parts[std::size_t(m.shells.part[e])].contact_thickness;
  if (optt > 0.0) return optt;
  auto t = m.shells.thickness[e];
  const auto& part = m.parts[std::size_t(m.shells.part[e])];
  if (t[0] == 0.0 && t[1] == 0.0 && t[2] == 0.0 && t[3] == 0.0 && part.section != kNone)
    t = m.shell_sections[std::size_t(part.section)].t;
  double sum = 0.0;
  int n = 0;
  for (double v : t)
    if (v > 0.0) {
      sum += v;
      ++n;
    }
  return n > 0 ? sum / n : 0.0;
}

// The shortest edge of shell e in the initial geometry (a triangle's repeated corner makes no
// edge).
double shortestEdge(const Model& m, std::size_t e) {
  const auto& n = m.shells.nodes[e];
  double shortest = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    const int32_t a = n[k], b = n[(k + 1) % 4];
    if (a == b) continue;
    const double len = norm(sub(m.nodes.x[std::size_t(a)], m.nodes.x[std::size_t(b)]));
    if (shortest == 0.0 || len < shortest) shortest = len;
  }
  return shortest;
}

// Shell e's contact thickness t (shellThickness) as single surface contacts with SSTHK 0 take
// it: at most 40% of the shell's shortest edge unless its part gives OPTT. LS-DYNA does this
// for its single surface contacts (types 4, 13, 15, 26) so that a thick shell on a fine mesh
// does not touch its own neighbours; a thickness given for contact (OPTT, SST) is taken as it
// is (dynasupport, "Contact thickness"; Keyword Manual, *CONTROL_CONTACT SSTHK).
double edgeLimited(const Model& m, std::size_t e, double t) {
  if (m.parts[std::size_t(m.shells.part[e])].contact_thickness > 0.0) return t;
  return std::min(t, 0.4 * shortestEdge(m, e));
}

using FaceKey = std::array<int32_t, 4>;
// The face's distinct nodes, sorted (a triangle padded with kNone): a triangle turned round
// (a c b b) is the same face as (a b c c).
FaceKey keyOf(std::array<int32_t, 4> f) {
  std::sort(f.begin(), f.end());
  std::fill(std::unique(f.begin(), f.end()), f.end(), kNone);
  return f;
}

struct Segment {
  std::array<int32_t, 4> nodes;
  int64_t element;
  double thickness, stiffness, depth;
  int64_t neighbour;  // the solid across the face (eroding surfaces), else -1
  // The element face the segment lies on, when that is not the segment itself (the four
  // triangles of a 10-node tetrahedron's face: its corners); else kNone.
  std::array<int32_t, 4> face{kNone, kNone, kNone, kNone};
};

// Which solid faces a side takes (Keyword Manual, *CONTACT, the ERODING option's card).
struct FaceRule {
  bool interior = false;    // EROSOP 1: faces with a solid across them too, for erosion to expose
  bool across_all = false;  // IADJ 0: a solid of any part across a face makes it interior
};

// The solids on each face (FaceKey): how many, and the first two.
struct FaceUse {
  int count = 0;
  std::array<int64_t, 2> solid{-1, -1};
};

// Solid e's faces as segments, turned outwards (by the geometry, so that a mirrored element
// still faces out), each a quadrilateral or a triangle with n3 == n4 as shells write it.
std::vector<std::array<int32_t, 4>> outwardFaces(const Model& m, std::size_t e) {
  const auto& n = m.solids.nodes[e];
  const Vec3 ce = centroid(m, n.data(), 8);
  int32_t sf[6][4];
  int sizes[6];
  const int nf = solidFaces(n, sf, sizes);
  std::vector<std::array<int32_t, 4>> out;
  for (int k = 0; k < nf; ++k) {
    std::array<int32_t, 4> f{sf[k][0], sf[k][1], sf[k][2], sf[k][sizes[k] == 4 ? 3 : 2]};
    const Vec3 cf = centroid(m, f.data(), f[2] == f[3] ? 3 : 4);
    if (dot(areaVector(m, f), sub(cf, ce)) < 0.0)
      f = f[2] == f[3] ? std::array<int32_t, 4>{f[0], f[2], f[1], f[1]}
                       : std::array<int32_t, 4>{f[0], f[3], f[2], f[1]};
    out.push_back(f);
  }
  return out;
}

// Segment f of solid e: its stiffness K A^2 / V and its depth V / A, V from the divergence
// theorem over the element's faces (exact for planar faces).
Segment solidSegment(const Model& m, const std::array<int32_t, 4>& f, int64_t e,
                     int64_t neighbour) {
  int32_t sf[6][4];
  int sizes[6];
  const int nf = solidFaces(m.solids.nodes[std::size_t(e)], sf, sizes);
  double vol = 0.0;
  for (int k = 0; k < nf; ++k) {
    std::array<int32_t, 4> g{sf[k][0], sf[k][1], sf[k][2], sf[k][sizes[k] == 4 ? 3 : 2]};
    vol += dot(centroid(m, g.data(), 4), areaVector(m, g)) / 3.0;
  }
  const Vec3 av = areaVector(m, f);
  const double area2 = dot(av, av);
  const int32_t part = m.solids.part[std::size_t(e)];
  const double k =
      vol > 0.0 ? m.parts[std::size_t(part)].contact_ssf * bulkModulus(m, part) * area2 / vol : 0.0;
  return {f, e, 0.0, k, area2 > 0.0 ? vol / std::sqrt(area2) : 0.0, neighbour};
}

// A face (a, b, c) of a 10-node tetrahedron as the four flat triangles its mid-side nodes cut
// it into, each turned as the face: a contact segment of 3 or 4 nodes is flat, and the six-node
// face's corners alone would leave its mid-side nodes out of contact (docs/theory.md, "The
// 10-node tetrahedron"). Each triangle is the face of one of the eight tetrahedra of volume V / 8
// that the mid-side nodes cut the element into (exactly so for straight edges): its stiffness
// K A^2 / (V / 8) and depth (V / 8) / A are that tetrahedron's.
void appendQuadraticFace(const Model& m, const Segment& face, std::vector<Segment>& out) {
  const auto e = static_cast<std::size_t>(face.element);
  // K / V of the element from the face's K A^2 / V.
  const Vec3 face_area = areaVector(m, face.nodes);
  const double face_a2 = dot(face_area, face_area);
  const double k_per_a2 = face_a2 > 0.0 ? face.stiffness / face_a2 : 0.0;
  const double volume = face.depth * std::sqrt(face_a2);
  for (const std::array<int32_t, 4>& t :
       quadraticFaceTriangles(m, e, face.nodes[0], face.nodes[1], face.nodes[2])) {
    const Vec3 av = areaVector(m, t);
    const double a2 = dot(av, av);
    out.push_back({t, face.element, 0.0, 8.0 * k_per_a2 * a2,
                   a2 > 0.0 ? volume / (8.0 * std::sqrt(a2)) : 0.0, face.neighbour, face.nodes});
  }
}

// The faces of the solids of the given parts (flags per part index) that `rule` takes: those
// with no solid across them (counting the solids of the parts, or of every part with
// rule.across_all), and with rule.interior those with one solid across, in element order.
std::vector<Segment> solidSegments(const Model& m, const std::vector<uint8_t>& in_part,
                                   FaceRule rule) {
  std::map<FaceKey, FaceUse> use;
  std::vector<std::pair<std::array<int32_t, 4>, int64_t>> faces;
  for (std::size_t e = 0; e < m.solids.size(); ++e) {
    const bool mine = in_part[std::size_t(m.solids.part[e])] != 0;
    if (!mine && !rule.across_all) continue;
    for (const auto& f : outwardFaces(m, e)) {
      FaceUse& u = use[keyOf(f)];
      if (u.count < 2) u.solid[std::size_t(u.count)] = int64_t(e);
      ++u.count;
      if (mine) faces.push_back({f, int64_t(e)});
    }
  }
  std::vector<Segment> out;
  for (const auto& [f, e] : faces) {
    const FaceUse& u = use[keyOf(f)];
    int64_t neighbour = -1;
    if (u.count == 2 && rule.interior)
      neighbour = u.solid[0] == e ? u.solid[1] : u.solid[0];
    else if (u.count != 1)
      continue;
    const Segment s = solidSegment(m, f, e, neighbour);
    if (m.solids.quadratic(std::size_t(e)))
      appendQuadraticFace(m, s, out);
    else
      out.push_back(s);
  }
  return out;
}

// The exterior faces of the solids and the shells of the given parts (flags per part index),
// in global element order. A solid face shared by two solids of the parts is interior (unless
// `rule` says otherwise: eroding surfaces).
std::vector<Segment> partSegments(const Model& m, const std::vector<uint8_t>& in_part,
                                  FaceRule rule = {}) {
  std::vector<Segment> out = solidSegments(m, in_part, rule);
  const auto shell0 = int64_t(m.familyOffset(Family::Shell));
  for (std::size_t e = 0; e < m.shells.size(); ++e) {
    const int32_t p = m.shells.part[e];
    if (!in_part[std::size_t(p)]) continue;
    auto f = m.shells.nodes[e];
    const double thick = shellThickness(m, e);
    const auto& x = m.nodes.x;
    const Vec3 d1 = sub(x[std::size_t(f[2])], x[std::size_t(f[0])]);
    const Vec3 d2 = sub(x[std::size_t(f[3])], x[std::size_t(f[1])]);
    const double diag = std::sqrt(std::max(dot(d1, d1), dot(d2, d2)));
    const Vec3 av = areaVector(m, f);
    const double area = std::sqrt(dot(av, av));
    const double k =
        diag > 0.0 ? m.parts[std::size_t(p)].contact_ssf * bulkModulus(m, p) * area / diag : 0.0;
    out.push_back({f, shell0 + int64_t(e), thick, k, thick, -1});
  }
  return out;
}

// Contact radius of beam e (*CONTACT_AUTOMATIC_GENERAL takes beams as cylinders): half its
// part's *PART_CONTACT OPTT (a contact thickness, the diameter), else from its section: half
// the outer diameter of a tube (ELFORM 1 CST 1, TS1 and TS2 averaged), else the radius of the
// circle of the section's area (rectangle TS x TT; A of ELFORM 2 and 3). 0 if none is known.
double beamContactRadius(const Model& m, std::size_t e) {
  const Part& part = m.parts[std::size_t(m.beams.part[e])];
  if (part.contact_thickness > 0.0) return 0.5 * part.contact_thickness;
  if (part.section == kNone) return 0.0;
  const SectionBeam& sec = m.beam_sections[std::size_t(part.section)];
  if (sec.elform != 1) return sec.a > 0.0 ? std::sqrt(sec.a / M_PI) : 0.0;
  const double ts = 0.5 * (sec.ts1 + (sec.ts2 > 0.0 ? sec.ts2 : sec.ts1));
  const double tt = 0.5 * (sec.tt1 + (sec.tt2 > 0.0 ? sec.tt2 : sec.tt1));
  if (sec.cst == 1) return 0.5 * ts;
  return std::sqrt(ts * tt / M_PI);
}

struct Edge {
  std::array<int32_t, 2> nodes;
  double radius, stiffness;
  int32_t part;
};

// The beams of the given parts as capsules: radius and penalty stiffness
// k = SSF K d (d = 2 r), the shell's f K A / (longest diagonal) with the beam's projected area
// d L over its length L.
std::vector<Edge> partEdges(const Model& m, const std::vector<uint8_t>& in_part, const Card& c,
                            std::string_view field) {
  std::vector<Edge> out;
  for (std::size_t e = 0; e < m.beams.size(); ++e) {
    const int32_t p = m.beams.part[e];
    if (!in_part[std::size_t(p)]) continue;
    const double r = beamContactRadius(m, e);
    if (!(r > 0.0))
      c.fail(field, "part " + std::to_string(m.parts[std::size_t(p)].id) +
                        ": its beams have no contact radius (no *PART_CONTACT OPTT and no section "
                        "dimensions)");
    const double k = m.parts[std::size_t(p)].contact_ssf * bulkModulus(m, p) * 2.0 * r;
    out.push_back({m.beams.nodes[e], r, k, p});
  }
  return out;
}

// Surface type codes of card 1 (SSTYP / MSTYP, "SURFATYP"): 0 segment set, 2 part set,
// 3 part, 4 node set, 5 every part, 6 every part but a part set.
struct Side {
  std::vector<Segment> segments;
  std::vector<Edge> edges;
  std::vector<int32_t> nodes;
  bool nodes_only = false;
};

// The segments of *SET_SEGMENT id: each a free face of a solid or a shell, in the user's
// orientation, with the stiffness and depth of the element it bounds; the face of a 10-node
// tetrahedron (its corners) gives its four triangles (appendQuadraticFace), turned as the user's.
std::vector<Segment> setSegments(Context& ctx, const Card& c, std::string_view id_field,
                                 int64_t id) {
  const Model& m = ctx.model;
  std::multimap<FaceKey, std::size_t> owner;
  const auto all = partSegments(m, std::vector<uint8_t>(m.parts.size(), 1));
  for (std::size_t k = 0; k < all.size(); ++k)
    owner.insert({keyOf(all[k].face[0] == kNone ? all[k].nodes : all[k].face), k});
  std::vector<Segment> out;
  for (const auto& s : ctx.segmentSet(c, id_field, id)) {
    const auto [first, last] = owner.equal_range(keyOf(s));
    if (first == last)
      c.fail(id_field, "segment set " + std::to_string(id) +
                           " has a segment that is not a free face of a solid or a shell");
    for (auto it = first; it != last; ++it) {
      Segment seg = all[it->second];
      seg.neighbour = -1;
      if (seg.face[0] == kNone)
        seg.nodes = s;
      else if (dot(areaVector(m, seg.nodes), areaVector(m, s)) < 0.0) {
        std::swap(seg.nodes[1], seg.nodes[2]);
        seg.nodes[3] = seg.nodes[2];
      }
      out.push_back(seg);
    }
  }
  return out;
}

Side readSide(Context& ctx, const Card& c, std::string_view id_field, std::string_view type_field,
              bool beam_edges, FaceRule rule = {}) {
  const Model& m = ctx.model;
  const int64_t id = c.integer(id_field);
  const int64_t type = c.integer(type_field);
  Side side;
  std::vector<uint8_t> in_part(m.parts.size(), 0);
  switch (type) {
    case 0: {
      if (id == 0) c.fail(id_field, "a segment set id is required for type 0");
      side.segments = setSegments(ctx, c, id_field, id);
      break;
    }
    case 2:
      for (int32_t p : ctx.partSet(c, id_field, id)) in_part[std::size_t(p)] = 1;
      break;
    case 3:
      in_part[std::size_t(ctx.part(c, id_field, id))] = 1;
      break;
    case 4:
      side.nodes = ctx.nodeSet(c, id_field, id);
      side.nodes_only = true;
      break;
    case 5:
      std::fill(in_part.begin(), in_part.end(), 1);
      break;
    case 6:
      std::fill(in_part.begin(), in_part.end(), 1);
      if (id != 0)
        for (int32_t p : ctx.partSet(c, id_field, id)) in_part[std::size_t(p)] = 0;
      break;
    default:
      c.fail(type_field, "surface type " + std::to_string(type) +
                             " is not supported (0 segment set, 2 part set, 3 part, 4 node set, "
                             "5 all parts, 6 all but a part set)");
  }
  if (type != 0 && type != 4) side.segments = partSegments(m, in_part, rule);
  if (beam_edges && type != 0 && type != 4) side.edges = partEdges(m, in_part, c, id_field);
  if (!side.nodes_only) {
    for (const auto& s : side.segments)
      side.nodes.insert(side.nodes.end(), s.nodes.begin(), s.nodes.end());
    // Beam and spring nodes of the parts take part as nodes (they carry no segment).
    for (std::size_t g = m.familyOffset(Family::Beam); g < m.numElements(); ++g)
      if (in_part[std::size_t(m.elementPart(g))] && type != 0) {
        int32_t n[kMaxElementNodes];
        side.nodes.insert(side.nodes.end(), n, n + m.elementNodes(g, n));
      }
  }
  std::sort(side.nodes.begin(), side.nodes.end());
  side.nodes.erase(std::unique(side.nodes.begin(), side.nodes.end()), side.nodes.end());
  return side;
}

// Keeps the nodes inside the box and the segments whose centroid is inside it (SBOXID and
// MBOXID act on the initial geometry, as in LS-DYNA).
void applyBox(const Context& ctx, const Card& c, std::string_view field, Side& side) {
  const int64_t id = c.integer(field);
  if (id == 0) return;
  const Box& box = ctx.box(c, field, id);
  const Model& m = ctx.model;
  std::erase_if(side.nodes, [&](int32_t n) { return !box.contains(m.nodes.x[std::size_t(n)]); });
  std::erase_if(side.segments, [&](const Segment& s) {
    return !box.contains(centroid(m, s.nodes.data(), s.nodes[2] == s.nodes[3] ? 3 : 4));
  });
  std::erase_if(side.edges,
                [&](const Edge& e) { return !box.contains(centroid(m, e.nodes.data(), 2)); });
}

// The contact surface of a side. A thickness_override (SST, MST) replaces every shell's
// contact thickness; else `limit_to_edges` (single surface contacts, SSTHK 0) applies
// edgeLimited's 40% rule.
ContactSurface makeSurface(const Model& m, const Side& side, double thickness_override,
                           bool limit_to_edges) {
  ContactSurface s;
  s.nodes = side.nodes;
  const auto shell0 = int64_t(m.familyOffset(Family::Shell));
  for (const auto& seg : side.segments) {
    s.segments.push_back(seg.nodes);
    s.segment_element.push_back(seg.element);
    double t = seg.thickness;
    if (t > 0.0 && thickness_override > 0.0)
      t = thickness_override;
    else if (t > 0.0 && limit_to_edges && seg.element >= shell0)
      t = edgeLimited(m, std::size_t(seg.element - shell0), t);
    s.segment_thickness.push_back(t);
    s.segment_stiffness.push_back(seg.stiffness);
    s.segment_depth.push_back(seg.depth);
    s.segment_neighbour.push_back(seg.neighbour);
  }
  // Half the thickest shell at each node: every shell at a node offsets it, whether or not
  // the shell is on this side (a node set side has no segments of its own).
  std::vector<double> half(m.nodes.size(), 0.0);
  for (std::size_t e = 0; e < m.shells.size(); ++e) {
    double t = thickness_override;
    if (!(t > 0.0))
      t = limit_to_edges ? edgeLimited(m, e, shellThickness(m, e)) : shellThickness(m, e);
    const double h = 0.5 * t;
    for (int32_t n : m.shells.nodes[e]) half[std::size_t(n)] = std::max(half[std::size_t(n)], h);
  }
  // A beam node of a capsule side meets segments with the beam's radius (its spherical end).
  for (const auto& e : side.edges) {
    s.edges.push_back(e.nodes);
    s.edge_radius.push_back(e.radius);
    s.edge_stiffness.push_back(e.stiffness);
    s.edge_part.push_back(e.part);
    for (int32_t n : e.nodes) half[std::size_t(n)] = std::max(half[std::size_t(n)], e.radius);
  }
  for (int32_t n : s.nodes) s.node_half_thickness.push_back(half[std::size_t(n)]);
  return s;
}

void readSegmentBased(Context& ctx, const deck::Keyword& kw, const deck::Card& ca,
                      ContactInterface& ci) {
  if (ci.kind != ContactKind::SurfaceToSurface && ci.kind != ContactKind::SingleSurface)
    ctx.reject(ca, "SOFT",
               "SOFT = 2 (segment-based contact) is supported for surface-to-surface and single "
               "surface contacts only");
  // SOFT = 2 (LS-DYNA Keyword Manual, *CONTACT optional card A): SBOPT 0 and 2 are planar
  // segments, 3 warped segments; Crumple's pair check splits quads into triangles, so 3 is
  // honoured by the same check. 4 and 5 (the sliding option) are not done.
  const double sbopt = ca.real("SBOPT");
  ci.sbopt = sbopt == 0.0 ? 2 : int(sbopt);
  if (double(ci.sbopt) != (sbopt == 0.0 ? 2.0 : sbopt) || ci.sbopt < 2 || ci.sbopt > 3)
    ctx.reject(ca, "SBOPT", "only SBOPT 0, 2 and 3 are supported with SOFT = 2");
  // DEPTH 0 and 2 (default): surface and edge-to-edge penetration, what the pair check does
  // for shells; other values change which pairs are checked and are reported.
  ci.depth = int(ca.integer("DEPTH"));
  if (ci.depth == 0) ci.depth = 2;
  if (ci.depth != 2)
    ctx.ignore(kw.name, "DEPTH",
               "value " + std::to_string(ci.depth) +
                   " is read but not honoured: Crumple checks surface and edge-to-edge "
                   "penetration (DEPTH 2)",
               ca.where());
  if (ca.integer("LCIDAB") != 0)
    ctx.reject(ca, "LCIDAB", "airbag fabric edge curves (LCIDAB) are not supported");
  if (ca.real("MAXPAR") != 1.025)
    ctx.ignore(kw.name, "MAXPAR",
               "read but not honoured: Crumple's pair search uses the segments' boxes", ca.where());
}

// Optional card C (Keyword Manual, *CONTACT): IGNORE, the interface's own initial penetration
// treatment (0: *CONTROL_CONTACT's); DTSTIF, the step of SOFT = 1's stiffness (read for
// SOFT = 1 only: elsewhere it stays reported as not honoured).
void readCardC(const Card& cc, const Card& ca, ContactInterface& ci) {
  const int64_t ignore = cc.integer("IGNORE");
  if (ignore < 0 || ignore > 2) cc.fail("IGNORE", "must be 0, 1 or 2");
  ci.ignore = int(ignore);
  if (ca.integer("SOFT") != 1) return;
  ci.dtstif = cc.real("DTSTIF");
  if (ci.dtstif < 0.0) cc.fail("DTSTIF", "a time step from a curve (< 0) is not supported");
}

// The tiebreak card (Keyword Manual, *CONTACT_..._TIEBREAK): OPTION 1 of the automatic type
// (failure stresses NFLS, SFLS; the exponents 2), or the failure forces NFLF, SFLF and the
// exponents NEN, MES of TIEBREAK_NODES_TO_SURFACE.
void readTiebreak(Context& ctx, CardCursor& cur, ContactInterface& ci) {
  const auto& spec = keywordSpec("*CONTACT");
  auto& tb = ci.tiebreak;
  const char* normal = tb.stress ? "NFLS" : "NFLF";
  const char* shear = tb.stress ? "SFLS" : "SFLF";
  const Card& c = cur.read(spec.card(tb.stress ? "tiebreak card" : "tiebreak force card"));
  if (tb.stress) {
    const int64_t option = c.integer("OPTION");
    if (option != 1)
      ctx.reject(c, "OPTION",
                 "only OPTION 1 (tied until the stress criterion, then penalty contact) is "
                 "supported");
  } else {
    tb.nen = c.real("NEN");
    tb.mes = c.real("MES");
    if (!(tb.nen > 0.0)) c.fail("NEN", "must be positive");
    if (!(tb.mes > 0.0)) c.fail("MES", "must be positive");
  }
  tb.normal = c.real(normal);
  tb.shear = c.real(shear);
  if (!(tb.normal > 0.0)) c.fail(normal, "the failure value must be positive");
  if (!(tb.shear > 0.0)) c.fail(shear, "the failure value must be positive");
}

}  // namespace

// The ERODING option's card (Keyword Manual, *CONTACT, after card 3): EROSOP 1 keeps the
// interior faces of the solids so that erosion can expose them (0: the surface is the
// exterior, which loses the faces of eroded elements); IADJ 1 takes faces on the boundary of
// the contact's parts (a solid of another part across counts as nothing), 0 only faces with no
// solid of any part across; ISYM 1 (faces on symmetry planes left out) is not supported.
FaceRule readErodingCard(Context& ctx, CardCursor& cur) {
  const Card& c = cur.read(keywordSpec("*CONTACT").card("eroding card"));
  const int64_t isym = c.integer("ISYM"), erosop = c.integer("EROSOP"), iadj = c.integer("IADJ");
  if (isym != 0)
    ctx.reject(c, "ISYM", "only ISYM 0 is supported (faces on symmetry planes stay in contact)");
  if (erosop != 0 && erosop != 1) c.fail("EROSOP", "must be 0 or 1");
  if (iadj != 0 && iadj != 1) c.fail("IADJ", "must be 0 or 1");
  return {erosop == 1, iadj == 0};
}

// The algorithm of *CONTACT_<name> (the words before _ID/_TITLE/_MPP): the kind and options
// of `ci`; false for a type Crumple does not have.
bool readContactType(const std::string& name, ContactInterface& ci) {
  if (name == "*CONTACT_NODES_TO_SURFACE") {
    ci.kind = ContactKind::NodesToSurface;
  } else if (name == "*CONTACT_AUTOMATIC_NODES_TO_SURFACE" ||
             name == "*CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE") {
    // ONE_WAY_SURFACE_TO_SURFACE (Keyword Manual, *CONTACT): the nodes of the SURFA segments
    // against the SURFB segments only, with the automatic search (both sides of shells, the
    // contact thickness): what the automatic nodes-to-surface pass does.
    ci.kind = ContactKind::NodesToSurface;
    ci.automatic = true;
  } else if (name == "*CONTACT_SURFACE_TO_SURFACE") {
    ci.kind = ContactKind::SurfaceToSurface;
  } else if (name == "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE") {
    ci.kind = ContactKind::SurfaceToSurface;
    ci.automatic = true;
  } else if (name == "*CONTACT_SINGLE_SURFACE") {
    ci.kind = ContactKind::SingleSurface;
  } else if (name == "*CONTACT_AUTOMATIC_SINGLE_SURFACE" || name == "*CONTACT_AUTOMATIC_GENERAL") {
    ci.kind = ContactKind::SingleSurface;
    ci.automatic = true;
  } else if (name == "*CONTACT_TIED_NODES_TO_SURFACE" ||
             name == "*CONTACT_TIED_SURFACE_TO_SURFACE" ||
             name == "*CONTACT_TIED_NODES_TO_SURFACE_OFFSET" ||
             name == "*CONTACT_TIED_SURFACE_TO_SURFACE_OFFSET") {
    ci.kind = ContactKind::Tied;
    ci.offset = name.find("_OFFSET") != std::string::npos;
  } else if (name == "*CONTACT_TIED_SHELL_EDGE_TO_SURFACE" ||
             name == "*CONTACT_TIED_SHELL_EDGE_TO_SURFACE_OFFSET" ||
             name == "*CONTACT_TIED_SHELL_EDGE_TO_SURFACE_BEAM_OFFSET" ||
             name == "*CONTACT_SPOTWELD") {
    // Keyword Manual, *CONTACT_TIED_SHELL_EDGE_TO_SURFACE: the SURFA nodes (shell edges, beam
    // ends) are tied in translation and rotation, so the tie carries moments; _OFFSET and
    // _BEAM_OFFSET keep the initial gap (the moment of the force about it goes to the
    // segment). *CONTACT_SPOTWELD ties weld beam ends to the sheets alike (docs/theory.md,
    // "Tied shell edges").
    ci.kind = ContactKind::Tied;
    ci.offset = name.find("_OFFSET") != std::string::npos;
    ci.tie_rotations = true;
  } else if (name == "*CONTACT_FORCE_TRANSDUCER_PENALTY" ||
             name == "*CONTACT_FORCE_TRANSDUCER_CONSTRAINT") {
    // Keyword Manual, *CONTACT_FORCE_TRANSDUCER_PENALTY: measures the contact forces between
    // its surfaces that the other interfaces find; it adds none (docs/theory.md, "Force
    // transducers"). Friction, scale factors and optional cards do nothing here.
    ci.kind = ContactKind::Transducer;
  } else if (name == "*CONTACT_ERODING_NODES_TO_SURFACE" ||
             name == "*CONTACT_ERODING_SURFACE_TO_SURFACE" ||
             name == "*CONTACT_ERODING_SINGLE_SURFACE") {
    // Keyword Manual, *CONTACT_ERODING_...: the automatic contacts whose surfaces follow the
    // erosion of solids, taking the faces it exposes (docs/theory.md, "Eroding contact").
    ci.kind = name == "*CONTACT_ERODING_NODES_TO_SURFACE" ? ContactKind::NodesToSurface
              : name == "*CONTACT_ERODING_SINGLE_SURFACE" ? ContactKind::SingleSurface
                                                          : ContactKind::SurfaceToSurface;
    ci.automatic = true;
    ci.eroding = true;
  } else if (name == "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK" ||
             name == "*CONTACT_TIEBREAK_NODES_TO_SURFACE") {
    // The SURFA nodes that touch SURFB are tied (where they are) until the bond fails, then
    // the interface is the ordinary one: two-way for the surface-to-surface type.
    ci.kind = name == "*CONTACT_TIEBREAK_NODES_TO_SURFACE" ? ContactKind::NodesToSurface
                                                           : ContactKind::SurfaceToSurface;
    ci.automatic = ci.kind == ContactKind::SurfaceToSurface;
    ci.tiebreak.on = true;
    ci.tiebreak.stress = ci.kind == ContactKind::SurfaceToSurface;
  } else {
    return false;
  }
  return true;
}

namespace {

// SST, MST: contact thicknesses, or, negative in a tied interface, the distance within which
// its nodes are tied (Keyword Manual, *CONTACT card 3); the thicknesses are then the shells'.
void readTieDistance(const Card& c3, ContactInterface& ci) {
  for (auto [field, value] : {std::pair{"SST", &ci.sst}, std::pair{"MST", &ci.mst}}) {
    if (*value >= 0) continue;
    if (ci.kind != ContactKind::Tied)
      c3.fail(field, "must not be negative (a negative value is a tie distance of tied contacts)");
    ci.tie_distance = std::max(ci.tie_distance, -*value);
    *value = 0;
  }
}

std::string algorithmName(std::string_view keyword) {
  std::string name;
  for (std::size_t start = 0; start <= keyword.size();) {
    std::size_t end = keyword.find('_', start);
    if (end == std::string_view::npos) end = keyword.size();
    const std::string_view word = keyword.substr(start, end - start);
    if (start == 0 || (word != "ID" && word != "TITLE" && word != "MPP")) {
      if (start != 0) name += '_';
      name += word;
    }
    start = end + 1;
  }
  return name;
}

}  // namespace

void readContact(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  // The words of the name other than ID, TITLE and MPP name the algorithm. Those three may
  // stand anywhere after it: _MPP_ID, _ID_MPP, and _ID_BEAM_OFFSET_MPP as abq2dyn writes it.
  const std::string name = algorithmName(kw.name);
  ContactInterface ci;
  if (!readContactType(name, ci)) {
    ctx.reportUnsupported(kw, "contact type not supported");
    return;
  }
  const auto& spec = keywordSpec("*CONTACT");
  CardCursor cur(kw, ctx.deck);
  ci.id = int64_t(ctx.model.contacts.size()) + 1;
  ci.keyword = kw.name;
  if (opts.has("ID") || opts.has("TITLE")) {
    const Card& idc = cur.read(spec.card("id card"));
    if (!idc.blank("CID")) ci.id = idc.integer("CID");
    ci.title = idc.text("HEADING");
  }
  if (opts.has("MPP")) {
    const Card& mpp = cur.read(spec.card("mpp card 1"));
    // CPARM8 1 or 2: AUTOMATIC_GENERAL leaves out beam-to-beam contact within one part
    // (Keyword Manual, *CONTACT, MPP card 1); 2 also lets spot weld beams in, and Crumple
    // takes every beam of the parts in any case.
    // Read only there: elsewhere the value stays reported as ignored.
    if (name == "*CONTACT_AUTOMATIC_GENERAL") {
      const int64_t cparm8 = mpp.integer("CPARM8");
      if (cparm8 < 0 || cparm8 > 2)
        ctx.reject(mpp, "CPARM8", "only CPARM8 0, 1 and 2 are supported");
      ci.skip_same_part_edges = cparm8 == 1 || cparm8 == 2;
    }
    if (!cur.atEnd() && deck::trim(cur.peek().text).rfind('&', 0) == 0)
      cur.read(spec.card("mpp card 2"));
  }
  for (const auto& other : ctx.model.contacts)
    if (other.id == ci.id)
      ctx.rejectKeyword(
          kw, "contact id " + std::to_string(ci.id) + " is already used at " + other.where.str());
  const Card& c1 = cur.read(spec.card("card 1"));
  const Card& c2 = cur.readOptional(spec.card("card 2"));
  const Card& c3 = cur.readOptional(spec.card("card 3"));
  if (ci.tiebreak.on) readTiebreak(ctx, cur, ci);
  const FaceRule faces = ci.eroding ? readErodingCard(ctx, cur) : FaceRule{};
  const Card& ca = cur.readOptional(spec.card("card A"));
  if (!cur.atEnd()) cur.read(spec.card("card B"));
  if (!cur.atEnd()) readCardC(cur.read(spec.card("card C")), ca, ci);
  if (!cur.atEnd()) cur.read(spec.card("card D"));
  if (!cur.atEnd())
    ctx.ignore(kw.name, "cards E and after", "not read (Crumple reads the optional cards A to D)",
               ctx.deck.loc(cur.peek()));
  ci.where = c1.where();
  ci.fs = c2.real("FS");
  ci.fd = c2.blank("FD") || c2.real("FD") == 0.0 ? ci.fs : c2.real("FD");
  ci.dc = c2.real("DC");
  ci.vdc = c2.real("VDC");
  if (ci.fs < 0) c2.fail("FS", "must not be negative");
  if (ci.fd < 0) c2.fail("FD", "must not be negative");
  if (ci.dc < 0) c2.fail("DC", "must not be negative");
  if (ci.vdc < 0 || ci.vdc > 100) c2.fail("VDC", "must lie in [0, 100] (% of critical)");
  ci.birth = c2.real("BT");
  ci.death = c2.real("DT");
  if (ci.death <= ci.birth) c2.fail("DT", "the death time must come after the birth time");
  ci.sfs = c3.real("SFS");
  ci.sfm = c3.real("SFM");
  ci.sst = c3.real("SST");
  ci.mst = c3.real("MST");
  if (ci.sfs <= 0) c3.fail("SFS", "must be positive");
  if (ci.sfm <= 0) c3.fail("SFM", "must be positive");
  readTieDistance(c3, ci);
  ci.soft = int(ca.integer("SOFT"));
  if (ci.soft < 0 || ci.soft > 2) ctx.reject(ca, "SOFT", "only SOFT 0, 1 and 2 are supported");
  ci.sofscl = ca.real("SOFSCL");
  if (ci.soft == 2 && ci.tiebreak.on)
    ctx.reject(ca, "SOFT", "SOFT = 2 (segment-based contact) is not supported with a tiebreak");
  else if (ci.soft == 2)
    readSegmentBased(ctx, kw, ca, ci);
  ci.bsort = int(ca.integer("BSORT"));
  if (ci.bsort < 0) ca.fail("BSORT", "must not be negative");
  if (ci.sofscl <= 0) ca.fail("SOFSCL", "must be positive");

  // AUTOMATIC_GENERAL takes beams as capsules, edge against edge (LS-DYNA Keyword Manual,
  // *CONTACT_AUTOMATIC_GENERAL); the other types take beam nodes as nodes.
  const bool general = name == "*CONTACT_AUTOMATIC_GENERAL";
  Side a = readSide(ctx, c1, "SSID", "SSTYP", general, faces);
  applyBox(ctx, c1, "SBOXID", a);
  Side b;
  if (ci.kind == ContactKind::SingleSurface) {
    if (a.nodes_only) c1.fail("SSTYP", "a single surface needs segments, not a node set");
    if (c1.integer("MSID") != 0 || c1.integer("MSTYP") != 0)
      ctx.ignore(kw.name, "MSID", "a single surface has one side", c1.where());
  } else if (ci.kind != ContactKind::Transducer || c1.integer("MSID") != 0 ||
             c1.integer("MSTYP") != 0) {
    b = readSide(ctx, c1, "MSID", "MSTYP", false, faces);
    applyBox(ctx, c1, "MBOXID", b);
  }
  if (ci.kind == ContactKind::Transducer) {
    // A side B of no segments (MSID 0, a node set) is fine: it is its nodes that count.
    if (a.nodes.empty()) c1.fail("SSID", "the transducer's side A has no nodes");
    ci.a = makeSurface(ctx.model, a, 0.0, false);
    ci.b = makeSurface(ctx.model, b, 0.0, false);
    ctx.model.contacts.push_back(std::move(ci));
    ctx.collect(cur);
    return;
  }
  if (ci.kind != ContactKind::SingleSurface) {
    if (b.nodes_only) c1.fail("MSTYP", "the master side needs segments, not a node set");
    if (ci.kind == ContactKind::SurfaceToSurface && a.nodes_only)
      c1.fail("SSTYP", "a surface-to-surface contact needs segments on both sides");
    if (b.segments.empty()) c1.fail("MSID", "the master side has no segments");
  }
  if (a.nodes.empty()) c1.fail("SSID", "the slave side has no nodes");
  if (ci.kind == ContactKind::SingleSurface && a.segments.empty() && a.edges.empty()) {
    // Beams make no segments: a surface of beams alone asks for beam contact.
    if (ctx.model.beams.size() == 0) c1.fail("SSID", "the surface has no segments");
    ctx.reject(c1, "SSID",
               "the surface has no segments, only beam nodes: beam-to-beam contact is supported "
               "in *CONTACT_AUTOMATIC_GENERAL only",
               "beam contact");
    throw SkipRecord{};
  }
  const bool single = ci.kind == ContactKind::SingleSurface;
  ci.a = makeSurface(ctx.model, a, ci.sst, single && ctx.model.contact_controls.ssthk == 0);
  if (!single) ci.b = makeSurface(ctx.model, b, ci.mst, false);
  ctx.model.contacts.push_back(std::move(ci));
  ctx.collect(cur);
}

void readControlContact(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*CONTROL_CONTACT");
  CardCursor cur(kw, ctx.deck);
  const Card& c1 = cur.readOptional(spec.card("card 1"));
  ContactControls& k = ctx.model.contact_controls;
  k.slsfac = c1.real("SLSFAC");
  if (k.slsfac <= 0) c1.fail("SLSFAC", "must be positive");
  k.enmass = int(c1.integer("ENMASS"));
  if (k.enmass < 0 || k.enmass > 2) c1.fail("ENMASS", "must be 0, 1 or 2");
  if (!cur.atEnd()) {
    const Card& c2 = cur.read(spec.card("card 2"));
    k.ssthk = int(c2.integer("SSTHK"));
    if (k.ssthk < 0 || k.ssthk > 1) c2.fail("SSTHK", "must be 0 or 1");
  }
  if (!cur.atEnd()) cur.read(spec.card("card 3"));
  if (!cur.atEnd()) {
    const Card& c4 = cur.read(spec.card("card 4"));
    k.ignore = int(c4.integer("IGNORE"));
    if (k.ignore < 0 || k.ignore > 2) c4.fail("IGNORE", "must be 0, 1 or 2");
  }
  while (!cur.atEnd()) cur.read(spec.card("card 5"));
  ctx.collect(cur);
}

}  // namespace crumple::model::build
