// Meaning of the mesh and its definitions: *NODE, *ELEMENT_SOLID, *PART, *SECTION_SOLID,
// *HOURGLASS (LS-DYNA Keyword Manual Vol. I and II); the material laws read their own cards
// (build_materials.cpp).
#include <algorithm>
#include <map>
#include <numeric>
#include <type_traits>
#include <utility>

#include <fmt/format.h>

#include "deck/number.hpp"
#include "model/build_context.hpp"
#include "model/solid_shape.hpp"
#include "util/error.hpp"

namespace crumple::model::build {

using deck::Card;
using deck::CardCursor;
using deck::keywordSpec;

namespace {

// *NODE TC/RC codes (Keyword Manual, *NODE): 1 x, 2 y, 3 z, 4 x+y, 5 y+z, 6 z+x, 7 all.
DofMask codeMask(int code) {
  static constexpr DofMask masks[8] = {0, 1, 2, 4, 3, 6, 5, 7};
  return masks[code];
}

// Order of `ids` ascending (stable for equal ids, so the first definition comes first).
// Pre-processors mostly number in order: ids already ascending keep theirs, which is what the
// sort would give, known in one pass (the sorts were 7 % of reading the 19 MB bench deck).
template <class Get>
std::vector<std::size_t> ascending(std::size_t n, Get id) {
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::size_t i = 1;
  while (i < n && !(id(i) < id(i - 1))) ++i;
  if (i == n) return order;
  // (id, position) pairs sorted: the position breaks ties as the stable sort would, and each id
  // is read once, not at each comparison (a stable sort of positions by their ids took a quarter
  // longer).
  std::vector<std::pair<std::decay_t<decltype(id(0))>, std::size_t>> keyed(n);
  for (std::size_t k = 0; k < n; ++k) keyed[k] = {id(k), k};
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t k = 0; k < n; ++k) order[k] = keyed[k].second;
  return order;
}

// Room for `more` records at the end of `list`, growing geometrically (a keyword's lines bound
// its records): no copies of the list as it grows record by record, and none per keyword of a
// deck of many small ones.
template <class T>
void reserveMore(std::vector<T>& list, std::size_t more) {
  if (list.size() + more > list.capacity())
    list.reserve(std::max(list.size() + more, 2 * list.capacity()));
}

materials::Family lawFamily(SectionKind k) {
  switch (k) {
    case SectionKind::Solid:
    case SectionKind::Sph:  // particles take the 3-D stress update
      return materials::Family::Solid;
    case SectionKind::Shell:
      return materials::Family::Shell;
    case SectionKind::Beam:
      return materials::Family::Beam;
    case SectionKind::Discrete:
      return materials::Family::Discrete;
  }
  return materials::Family::Solid;
}

const char* sectionName(SectionKind k) {
  static constexpr const char* kNames[] = {"a *SECTION_SOLID", "a *SECTION_SHELL",
                                           "a *SECTION_BEAM", "a *SECTION_DISCRETE",
                                           "a *SECTION_SPH"};
  return kNames[static_cast<int>(k)];
}

// What the law lacks for elements of the section kind.
const char* updateName(SectionKind k) {
  static constexpr const char* kNames[] = {
      "update for solid elements", "plane-stress update for shell elements",
      "uniaxial (fibre) update for beam elements",
      "force law for discrete elements (they need a *MAT_S01, S02 or S04 law)",
      "update for solid elements (SPH particles take the 3-D stress update)"};
  return kNames[static_cast<int>(k)];
}

}  // namespace

namespace {
int64_t checkedPositive(const Card& c, std::string_view field, int64_t id) {
  if (id <= 0) c.fail(field, "the id must be a positive integer, not " + std::to_string(id));
  return id;
}
}  // namespace

int64_t positiveId(const Card& c, std::string_view field) {
  return checkedPositive(c, field, c.integer(field));
}

int64_t positiveId(const Card& c, const deck::FieldSlot& field) {
  return checkedPositive(c, field.name, c.integer(field));
}

bool nextRecord(CardCursor& cur, bool starts_with_heading) {
  const auto& lines = cur.keyword().lines;
  const bool data_left =
      std::any_of(lines.end() - static_cast<std::ptrdiff_t>(cur.remaining()), lines.end(),
                  [](const deck::DataLine& l) { return !deck::trim(l.text).empty(); });
  if (!data_left) return false;
  if (!starts_with_heading) cur.skipBlankLines();
  return true;
}

std::string readTitleCard(CardCursor& cur, const deck::KeywordSpec& spec,
                          const KeywordOptions& opts) {
  return opts.has("TITLE") ? cur.read(spec.card("title card")).text("TITLE") : std::string{};
}

// MID and RO of card 1, shared by the materials, checked as LS-DYNA requires.
Material readMaterialBase(Context& ctx, const Card& c, std::string t, bool density) {
  Material m;
  m.id = positiveId(c, "MID");
  ctx.define(Kind::Material, m.id, c, "MID");
  m.title = std::move(t);
  m.where = c.where();
  if (!density) return m;
  m.rho = c.real("RO");
  if (m.rho <= 0) c.fail("RO", "the density must be positive");
  return m;
}

namespace {

std::string title(CardCursor& cur, const deck::KeywordSpec& spec, const KeywordOptions& opts) {
  return readTitleCard(cur, spec, opts);
}

}  // namespace

void readNodes(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*NODE").card("card 1");
  // The fields found once, not by name per line.
  const deck::FieldSlot nid = spec.slot("NID"), fx = spec.slot("X"), fy = spec.slot("Y"),
                        fz = spec.slot("Z"), ftc = spec.slot("TC"), frc = spec.slot("RC");
  CardCursor cur(kw, ctx.deck);
  deck::PlainRecord plain(spec, kw.format);
  reserveMore(ctx.node_input, kw.lines.size());
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    // The usual node line needs no card; any other, or one with a message, is read below.
    const deck::DataLine& line = cur.peek();
    if (plain.read(line.text)) {
      const int64_t id = plain.integer(nid), tc = plain.integer(ftc), rc = plain.integer(frc);
      if (id > 0 && tc >= 0 && tc <= 7 && rc >= 0 && rc <= 7) {
        ctx.node_input.push_back({id,
                                  {plain.real(fx), plain.real(fy), plain.real(fz)},
                                  static_cast<int>(tc),
                                  static_cast<int>(rc),
                                  line.file,
                                  line.line});
        cur.skipLine();
        continue;
      }
    }
    const auto& c = cur.read(spec);
    const int64_t id = positiveId(c, nid);
    const Vec3 x{c.real(fx), c.real(fy), c.real(fz)};
    const auto tc = c.integer(ftc), rc = c.integer(frc);
    if (tc < 0 || tc > 7) c.fail(ftc.name, "must be 0 to 7");
    if (rc < 0 || rc > 7) c.fail(frc.name, "must be 0 to 7");
    ctx.node_input.push_back(
        {id, x, static_cast<int>(tc), static_cast<int>(rc), c.fileIndex(), c.lineNumber()});
    ctx.collect(cur);
  }
}

void finishNodes(Context& ctx) {
  auto& in = ctx.node_input;
  const auto order = ascending(in.size(), [&](std::size_t i) { return in[i].id; });
  Nodes& nodes = ctx.model.nodes;
  nodes.id.reserve(in.size());
  nodes.x.reserve(in.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto& n = in[order[k]];
    if (k > 0 && in[order[k - 1]].id == n.id) {
      const auto& first = in[order[k - 1]];
      ctx.fail(ctx.deck.loc(n.file, n.line).str() + ": *NODE card 1 field 1 (NID): node " +
               std::to_string(n.id) + " is already defined at " +
               ctx.deck.loc(first.file, first.line).str());
      continue;
    }
    const auto index = static_cast<int32_t>(nodes.id.size());
    nodes.id.push_back(n.id);
    nodes.x.push_back(n.x);
    // TC/RC constrain the node like *BOUNDARY_SPC_NODE (Keyword Manual, *NODE).
    const DofMask mask = static_cast<DofMask>(codeMask(n.tc) | (codeMask(n.rc) << 3));
    if (mask) ctx.spc_masks[index] |= mask;
  }
  in.clear();
  in.shrink_to_fit();
  ctx.model.initial_velocity.assign(nodes.size(), Vec3{});
  ctx.model.finalize();
}

namespace {

// The ELFORM of the part's solid section (0 when the part has none usable).
int sectionElform(const Context& ctx, int32_t part) {
  if (part == kNone) return 0;
  const auto& p = ctx.model.parts[static_cast<std::size_t>(part)];
  if (p.section == kNone || p.section_kind != SectionKind::Solid) return 0;
  return ctx.model.solid_sections[static_cast<std::size_t>(p.section)].elform;
}

// An element of an ELFORM 10 or 13 section: four distinct nodes, stored as N1 N2 N3 N4 N4 N4 N4 N4.
std::array<int32_t, 8> tetrahedronNodes(const Card& c, const std::array<int32_t, 8>& n) {
  int32_t d[8];
  const int k = distinctNodes(n, d);
  if (k != 4)
    c.fail("N1", "a tetrahedron (*SECTION_SOLID ELFORM 10, 13) needs 4 distinct nodes, not " +
                     std::to_string(k) + " (N1 N2 N3 N4, N5 to N8 blank or N4)");
  return canonicalTet(n);
}

// An element of an ELFORM 15 section: a pentahedron written as a hexahedron with two opposite
// faces collapsed to triangles, stored as N1 N2 N3 N4 N5 N5 N6 N6 (model/solid_shape.hpp).
std::array<int32_t, 8> pentahedronNodes(const Card& c, const std::array<int32_t, 8>& n) {
  std::array<int32_t, 8> out{};
  if (!canonicalPrism(n, out))
    c.fail("N1",
           "a pentahedron (*SECTION_SOLID ELFORM 15) needs 6 distinct nodes with two opposite "
           "faces collapsed to triangles (N1 N2 N3 N4 N5 N5 N6 N6, or N3 = N4 and N7 = N8)");
  return out;
}

// A tetrahedron given by N1..N4 alone: LS-DYNA's degenerate form repeats N4 (n4=...=n8).
void repeatFourthNode(std::array<int64_t, 8>& ids) {
  if (ids[3] != 0 && std::all_of(ids.begin() + 4, ids.end(), [](int64_t n) { return n == 0; }))
    std::fill(ids.begin() + 4, ids.end(), ids[3]);
}

// The usual *ELEMENT_SOLID line (EID PID N1..N8, plainly written, every check passed) read
// without a card (deck::PlainRecord) into the solids; false, nothing recorded, for any other
// line (the two-card form, a 10-node tetrahedron, anything the general reading reports), which
// readSolids then reads with its cards and messages.
bool readPlainSolid(Context& ctx, std::string_view keyword, deck::PlainRecord& plain,
                    const deck::DataLine& line, const deck::FieldSlot& eid,
                    const deck::FieldSlot& pid, const std::array<deck::FieldSlot, 8>& n) {
  if (!plain.read(line.text)) return false;
  const int32_t part = ctx.model.partIndex(plain.integer(pid));
  if (plain.integer(eid) <= 0 || part == kNone ||
      !ctx.part_problem[static_cast<std::size_t>(part)].empty() ||
      !sectionKindFits(ctx, keyword, part, SectionKind::Solid))
    return false;
  const int elform = sectionElform(ctx, part);
  if (isQuadraticTetrahedron(elform)) return false;
  std::array<int64_t, 8> ids{};
  for (std::size_t i = 0; i < 8; ++i) ids[i] = plain.integer(n[i]);
  repeatFourthNode(ids);
  Context::ElementInput<8> s{plain.integer(eid), part, {}, line.file, line.line};
  for (std::size_t i = 0; i < 8; ++i) {
    s.nodes[i] = ids[i] == 0 ? kNone : ctx.model.nodeIndex(ids[i]);
    if (s.nodes[i] == kNone) return false;
  }
  int32_t distinct[8];
  if (isTetrahedron(elform) && distinctNodes(s.nodes, distinct) != 4) return false;
  if (isTetrahedron(elform)) s.nodes = canonicalTet(s.nodes);
  if (elform == 15 && !canonicalPrism(std::array<int32_t, 8>(s.nodes), s.nodes)) return false;
  ctx.solid_input.push_back(s);
  return true;
}

}  // namespace

void readSolids(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*ELEMENT_SOLID");
  static constexpr std::string_view kN[10] = {"N1", "N2", "N3", "N4", "N5",
                                              "N6", "N7", "N8", "N9", "N10"};
  // The fields of both cards found once, not by name per line.
  const auto& card1 = spec.card("card 1");
  const auto& card2 = spec.card("card 2");
  const deck::FieldSlot eid_slot = card1.slot("EID"), pid_slot = card1.slot("PID");
  std::array<deck::FieldSlot, 8> n1{};
  std::array<deck::FieldSlot, 10> n2{};
  for (std::size_t i = 0; i < 10; ++i) {
    if (i < 8) n1[i] = card1.slot(kN[i]);
    n2[i] = card2.slot(kN[i]);
  }
  CardCursor cur(kw, ctx.deck);
  deck::PlainRecord plain(card1, kw.format);
  reserveMore(ctx.solid_input, kw.lines.size());
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    if (readPlainSolid(ctx, kw.name, plain, cur.peek(), eid_slot, pid_slot, n1)) {
      cur.skipLine();
      continue;
    }
    const Card& c = cur.read(card1);
    const int64_t eid = positiveId(c, eid_slot);
    const int32_t part = ctx.part(c, "PID", c.integer(pid_slot));
    ctx.checkPartUsable(c, part);
    checkSectionKind(ctx, c, part, SectionKind::Solid);
    // Card 1 with EID and PID only: the nodes follow on a second card of ten 8-character
    // fields (Keyword Manual, *ELEMENT_SOLID, the format of 10-node tetrahedra that
    // pre-processors also use for hexahedra).
    std::array<int64_t, 8> ids{};
    for (std::size_t i = 0; i < 8; ++i) ids[i] = c.integer(n1[i]);
    // Blank fields read as 0: only then can the card be the two-card form (a look at each
    // field's blankness per element was a tenth of reading the card).
    const bool two_cards =
        std::all_of(ids.begin(), ids.end(), [](int64_t n) { return n == 0; }) &&
        std::all_of(n1.begin(), n1.end(), [&](const deck::FieldSlot& n) { return c.blank(n); });
    const Card* nc = &c;
    const int elform = sectionElform(ctx, part);
    std::array<int64_t, 2> n9_n10{};
    if (two_cards) {
      if (cur.atEnd()) c.fail("N1", "the element has no nodes");
      nc = &cur.read(card2);
      for (std::size_t i = 0; i < 2; ++i) n9_n10[i] = nc->integer(n2[8 + i]);
      if (!isQuadraticTetrahedron(elform) && (n9_n10[0] != 0 || n9_n10[1] != 0))
        ctx.reject(*nc, n9_n10[0] != 0 ? kN[8] : kN[9],
                   "a 10-node tetrahedron needs a *SECTION_SOLID with ELFORM 16 (its part's "
                   "section has ELFORM " +
                       std::to_string(elform) + ")");
      for (std::size_t i = 0; i < 8; ++i) ids[i] = nc->integer(n2[i]);
    }
    Context::ElementInput<8> s{eid, part, {}, c.fileIndex(), c.lineNumber()};
    if (isQuadraticTetrahedron(elform)) {
      // 10 nodes on the two-card form: corners N1..N4, mid-side nodes N5..N10.
      if (!two_cards)
        c.fail("N1",
               "a 10-node tetrahedron (*SECTION_SOLID ELFORM 16) is written on two cards: EID "
               "PID on the first, N1..N10 on the second");
      for (int i = 0; i < 10; ++i) {
        const int64_t id = i < 8 ? ids[std::size_t(i)] : n9_n10[std::size_t(i - 8)];
        if (id == 0)
          nc->fail(kN[i],
                   "node id missing: a 10-node tetrahedron (*SECTION_SOLID ELFORM 16) needs "
                   "N1..N10");
        const int32_t n = ctx.node(*nc, kN[i], id);
        if (i < 4)
          s.nodes[std::size_t(i)] = n;
        else
          s.mid[std::size_t(i - 4)] = n;
      }
      for (int i = 4; i < 8; ++i) s.nodes[std::size_t(i)] = s.nodes[3];
      int32_t all[10];
      for (int i = 0; i < 4; ++i) all[i] = s.nodes[std::size_t(i)];
      for (int i = 0; i < 6; ++i) all[4 + i] = s.mid[std::size_t(i)];
      for (int i = 0; i < 10; ++i)
        for (int j = 0; j < i; ++j)
          if (all[i] == all[j])
            nc->fail(kN[i], "a 10-node tetrahedron needs 10 distinct nodes (" + std::string(kN[i]) +
                                " repeats " + std::string(kN[j]) + ")");
      ctx.solid_input.push_back(s);
      ctx.collect(cur);
      continue;
    }
    repeatFourthNode(ids);
    for (int i = 0; i < 8; ++i) {
      if (ids[i] == 0) nc->fail(kN[i], "node id missing");
      s.nodes[i] = ctx.node(*nc, kN[i], ids[i]);
    }
    if (isTetrahedron(elform)) s.nodes = tetrahedronNodes(*nc, s.nodes);
    if (elform == 15) s.nodes = pentahedronNodes(*nc, s.nodes);
    ctx.solid_input.push_back(s);
    ctx.collect(cur);
  }
}

namespace {

// Sorts one family's elements by id, refuses duplicates and moves them into the model list;
// `extra(list, input)` appends what the family adds.
template <int N, class List, class Extra>
void finishFamily(Context& ctx, std::vector<Context::ElementInput<N>>& in, List& list,
                  std::string_view keyword, Extra&& extra) {
  const auto order = ascending(in.size(), [&](std::size_t i) { return in[i].id; });
  list.id.reserve(in.size());
  list.part.reserve(in.size());
  list.nodes.reserve(in.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto& e = in[order[k]];
    if (k > 0 && in[order[k - 1]].id == e.id) {
      const auto& first = in[order[k - 1]];
      ctx.fail(ctx.deck.loc(e.file, e.line).str() + ": " + std::string(keyword) +
               " card 1 field 1 (EID): element " + std::to_string(e.id) +
               " is already defined at " + ctx.deck.loc(first.file, first.line).str());
      continue;
    }
    list.id.push_back(e.id);
    list.part.push_back(e.part);
    list.nodes.push_back(e.nodes);
    extra(list, e);
  }
  in.clear();
  in.shrink_to_fit();
}

}  // namespace

void finishSolids(Context& ctx) {
  const bool quadratic = std::any_of(ctx.solid_input.begin(), ctx.solid_input.end(),
                                     [](const auto& e) { return e.mid[0] != kNone; });
  finishFamily(ctx, ctx.solid_input, ctx.model.solids, "*ELEMENT_SOLID",
               [quadratic](Solids& s, const Context::ElementInput<8>& e) {
                 if (quadratic) s.mid.push_back(e.mid);
               });
  finishFamily(ctx, ctx.shell_input, ctx.model.shells, "*ELEMENT_SHELL",
               [](Shells& s, const Context::ElementInput<4>& e) { s.thickness.push_back(e.real); });
  finishFamily(ctx, ctx.beam_input, ctx.model.beams, "*ELEMENT_BEAM",
               [](Beams& b, const Context::ElementInput<2>& e) {
                 b.orientation.push_back(e.aux);
                 b.section.push_back(e.section);
               });
  finishFamily(ctx, ctx.discrete_input, ctx.model.discretes, "*ELEMENT_DISCRETE",
               [](Discretes& d, const Context::ElementInput<2>& e) {
                 d.scale.push_back(e.real[0]);
                 d.offset.push_back(e.real[1]);
               });
}

namespace {

// The model index of the definition a part's field names, or kNone with the first problem kept
// in `problem` (a part no element uses may be incomplete, as LS-DYNA accepts: the problem is an
// error on use).
int32_t resolvePartField(Context& ctx, const Card& c, std::string_view field, Kind kind,
                         const std::unordered_map<int64_t, int32_t>& index, int64_t part_id,
                         Context::PartProblem& problem) {
  const int64_t id = c.integer(field);
  const std::string part = "part " + std::to_string(part_id);
  auto it = index.find(id);
  if (it != index.end()) return it->second;
  if (!problem.empty()) return kNone;
  if (id == 0) {
    problem.message = c.context(field) + ": a " + std::string(kindName(kind)) + " id is required";
  } else if (const std::string broken = ctx.brokenMessage(kind, id); !broken.empty()) {
    problem.message = broken;
  } else if (ctx.isUnsupported(kind, id)) {
    problem = {
        part + " uses " + ctx.unsupportedDefinition(kind, id) + ", which is not supported yet",
        ctx.unsupportedFeature(kind, id)};
  } else {
    problem.message = c.context(field) + ": " + ctx.undefinedMessage(kind, id);
  }
  return kNone;
}

void resolveHourglass(Context& ctx, const Card& c, Part& p, Context::PartProblem& problem) {
  if (const int64_t hg = c.integer("HGID"); hg != 0) {
    auto it = ctx.hourglass_index.find(hg);
    if (it != ctx.hourglass_index.end())
      p.hourglass = it->second;
    else if (problem.empty())
      problem.message = c.context("HGID") + ": " + ctx.undefinedMessage(Kind::Hourglass, hg);
  }
}

// A part's heading card and card 2 (*PART, *PART_COMPOSITE): its id, title and place; gives
// card 2.
const Card& readPartHeading(CardCursor& cur, const deck::KeywordSpec& spec, Part& p) {
  p.title = cur.read(spec.card("card 1")).text("HEADING");
  const Card& c = cur.read(spec.card("card 2"));
  p.id = positiveId(c, "PID");
  p.where = c.where();
  return c;
}

// The section of *PART_COMPOSITE card 2 (ELFORM, SHRF, NLOC) and its ply cards; sets the part's
// material (MID1). Empty (no points) when the section cannot run.
SectionShell readPlies(Context& ctx, CardCursor& cur, const deck::KeywordSpec& spec, const Card& c,
                       Part& p, Context::PartProblem& problem) {
  SectionShell s;
  s.id = p.id;
  s.where = c.where();
  const int64_t elform = c.integer("ELFORM");
  if (elform != 2 && elform != 4 && elform != 10 && elform != 16)
    ctx.reject(c, "ELFORM", "composite parts run ELFORM 2, 4, 10 and 16");
  s.elform = static_cast<int>(elform);
  s.shrf = c.real("SHRF");
  if (!(s.shrf > 0)) c.fail("SHRF", "the shear factor must be positive");
  if (c.real("NLOC") != 0)
    ctx.reject(c, "NLOC", "reference surfaces off the mid-surface are not supported");
  std::vector<double> thick;
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& ply = cur.read(spec.card("ply card"));
    for (int k = 1; k <= 2; ++k) {
      const std::string n = std::to_string(k);
      if (ply.integer("MID" + n) == 0 && ply.real("THICK" + n) == 0) continue;
      const int32_t mat =
          resolvePartField(ctx, ply, "MID" + n, Kind::Material, ctx.material_index, p.id, problem);
      if (thick.empty())
        p.material = mat;
      else if (mat != p.material)
        ctx.reject(ply, "MID" + n, "a material per ply is not supported (every MIDi the same)");
      if (!(ply.real("THICK" + n) > 0)) ply.fail("THICK" + n, "the ply thickness must be positive");
      thick.push_back(ply.real("THICK" + n));
      s.ply_angle.push_back(ply.real("B" + n));
    }
  }
  if (thick.empty()) c.fail("PID", "a *PART_COMPOSITE needs at least one ply card");
  if (thick.size() > 10) {
    ctx.reject(c, "PID", "more than 10 plies (integration points) are not supported");
    return {};
  }
  double total = 0.0;
  for (const double t : thick) total += t;
  double below = 0.0;
  for (const double t : thick) {
    s.zeta.push_back(-1.0 + (2.0 * below + t) / total);
    s.weight.push_back(t / total);
    below += t;
  }
  s.nip = static_cast<int>(thick.size());
  s.t = {total, total, total, total};
  return s;
}

// *PART_COMPOSITE (Keyword Manual vol. I): a shell part whose section is its plies, MIDi
// THICKi Bi TMIDi two a card: one integration point per ply at its mid-thickness, weighted by
// its share of the thickness (sum THICKi), at its angle Bi (as *SECTION_SHELL ICOMP 1 with a
// user rule). One material for all plies (a material per ply is refused).
void readPartComposite(Context& ctx, const deck::Keyword& kw) {
  const auto& spec = keywordSpec("*PART_COMPOSITE");
  CardCursor cur(kw, ctx.deck);
  Part p;
  const Card& c = readPartHeading(cur, spec, p);
  Context::PartProblem problem;
  SectionShell sec = readPlies(ctx, cur, spec, c, p, problem);
  if (!sec.zeta.empty()) {
    p.section = static_cast<int32_t>(ctx.model.shell_sections.size());
    p.section_kind = SectionKind::Shell;
    ctx.model.shell_sections.push_back(std::move(sec));
  }
  resolveHourglass(ctx, c, p, problem);
  ctx.model.parts.push_back(std::move(p));
  ctx.part_problem.push_back(std::move(problem));
  ctx.collect(cur);
}

}  // namespace

void readParts(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  if (opts.has("COMPOSITE")) {
    if (opts.has("CONTACT") || opts.has("INERTIA"))
      ctx.fail(ctx.deck.loc(kw.file, kw.line).str() + ": " + kw.name +
               ": _COMPOSITE with other options is not supported");
    readPartComposite(ctx, kw);
    return;
  }
  const auto& spec = keywordSpec("*PART");
  CardCursor cur(kw, ctx.deck);
  // One keyword may hold several parts, each a heading card and card 2.
  while (nextRecord(cur, true)) {
    Part p;
    const Card& c = readPartHeading(cur, spec, p);
    // A part no element uses may be incomplete (no section, an undefined or unusable
    // material), as LS-DYNA accepts: the first problem is kept and is an error on use.
    Context::PartProblem problem;
    auto resolve = [&](std::string_view field, Kind kind,
                       const std::unordered_map<int64_t, int32_t>& index) {
      return resolvePartField(ctx, c, field, kind, index, p.id, problem);
    };
    p.section = resolve("SECID", Kind::Section, ctx.section_index);
    if (p.section != kNone) p.section_kind = ctx.section_kind.at(c.integer("SECID"));
    p.material = resolve("MID", Kind::Material, ctx.material_index);
    resolveHourglass(ctx, c, p, problem);
    if (c.integer("EOSID") != 0) p.eos = resolve("EOSID", Kind::Eos, ctx.eos_index);
    if (opts.has("CONTACT")) {
      // _CONTACT (Keyword Manual, *PART_CONTACT): SSF scales the penalty stiffness of the
      // part's segments and OPTT replaces its shells' contact thickness; part-based friction
      // (FS, FD, DC, VC, used by interfaces whose FS is -1) is reported as not honoured.
      const Card& cc = cur.read(spec.card("contact card"));
      p.contact_ssf = cc.real("SSF");
      p.contact_thickness = cc.real("OPTT");
      if (p.contact_ssf <= 0) cc.fail("SSF", "must be positive");
      if (p.contact_thickness < 0) cc.fail("OPTT", "must not be negative");
    }
    if (opts.has("INERTIA")) readPartInertia(ctx, cur, p.id);
    ctx.model.parts.push_back(std::move(p));
    ctx.part_problem.push_back(std::move(problem));
    ctx.collect(cur);
  }
}

// Whether a solid part runs the one-point kernel, the only one that computes the deformation
// gradient hyperelastic laws need: ELFORM 1 or 10, and without *CONTROL_SOLID ESORT = 1 (which
// may run its pentahedra as ELFORM 15).
bool oneSolidPoint(const Model& m, const Part& p) {
  const int elform = m.solid_sections[static_cast<std::size_t>(p.section)].elform;
  return elform == 10 || (elform == 1 && !m.controls.solid_esort);
}

// A law that runs on one beam formulation only (its kBeamOnly: *MAT_SPOTWELD on spot-weld
// beams, whose resultant and time failure live in that kernel; *MAT_MUSCLE on trusses) on a
// part of another section. False (reported) then.
bool onItsBeams(Context& ctx, const Part& p, const Material& m) {
  const materials::BeamOnly* only = materials::beamOnlyOf(m.law);
  if (!only) return true;
  const std::string head = p.where.str() + ": *PART card 2 field 3 (MID): part " +
                           std::to_string(p.id) + " has material " + std::to_string(m.id) + " (" +
                           std::string(materialKeyword(m.law)) + ")";
  if (only->solids && p.section_kind == SectionKind::Solid) {
    const std::string why = materials::solidRefusalOf(m.law);
    if (!why.empty()) ctx.fail(head + " on solid elements: " + why);
    return why.empty();
  }
  const bool ok =
      p.section_kind == SectionKind::Beam &&
      ctx.model.beam_sections[static_cast<std::size_t>(p.section)].elform == only->elform;
  if (!ok)
    ctx.fail(head + ", which Crumple runs only on " + std::string(only->what) +
             (only->solids ? " and solids" : "") + "; other sections are not supported");
  return ok;
}

void finishParts(Context& ctx) {
  auto& parts = ctx.model.parts;
  const auto order = ascending(parts.size(), [&](std::size_t i) { return parts[i].id; });
  std::vector<Part> sorted;
  std::vector<Context::PartProblem> problems;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Part& p = parts[order[k]];
    if (k > 0 && parts[order[k - 1]].id == p.id) {
      ctx.fail(p.where.str() + ": *PART card 2 field 1 (PID): part " + std::to_string(p.id) +
               " is already defined at " + parts[order[k - 1]].where.str());
      continue;
    }
    sorted.push_back(p);
    problems.push_back(ctx.part_problem[order[k]]);
  }
  parts = std::move(sorted);
  ctx.part_problem = std::move(problems);
  // A part's elements need their law's update for their family (materials/law.hpp), and the
  // law takes the part's equation of state exactly when it declares kEos.
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Part& p = parts[i];
    if (p.section == kNone || p.material == kNone) continue;
    const Material& m = ctx.model.materials[static_cast<std::size_t>(p.material)];
    checkPartErosion(ctx, i);
    // 2D solids (*SECTION_SHELL ELFORM 13, 15) take the solid update: finishPlanar checks them.
    if (p.section_kind == SectionKind::Shell &&
        (ctx.model.shell_sections[static_cast<std::size_t>(p.section)].elform == 13 ||
         ctx.model.shell_sections[static_cast<std::size_t>(p.section)].elform == 15))
      continue;
    // Thick shells (a *SECTION_TSHELL, kept among the solid sections) take the plane-stress
    // update of the shells.
    const bool tshell = p.section_kind == SectionKind::Solid &&
                        isThickShell(ctx.model.solid_sections[std::size_t(p.section)].elform);
    // *MAT_NULL's shells are bypassed (mass only); its thick shells would have no update. Thick
    // shells keep no law history (the layered composite laws' failure flags).
    if (!materials::supports(m.law,
                             tshell ? materials::Family::Shell : lawFamily(p.section_kind)) ||
        (tshell && materials::massOnlyStructures(m.law)))
      ctx.fail(p.where.str() + ": *PART card 2 field 3 (MID): part " + std::to_string(p.id) +
               " has " + (tshell ? "a *SECTION_TSHELL" : sectionName(p.section_kind)) +
               " section but material " + std::to_string(m.id) + " (" + materialKeyword(m.law) +
               ") has no " +
               (tshell ? "plane-stress update (thick shells take the shells' laws)"
                       : updateName(p.section_kind)));
    else if (tshell && materials::historyCountOf(m.law) > 0)
      ctx.fail(p.where.str() + ": *PART card 2 field 3 (MID): part " + std::to_string(p.id) +
               " has a *SECTION_TSHELL section and material " + std::to_string(m.id) + " (" +
               materialKeyword(m.law) +
               "), whose points keep history variables: thick shells do not store them yet");
    else if (tshell)
      continue;
    else if (p.section_kind == SectionKind::Solid && materials::needsDeformationGradient(m.law) &&
             ctx.model.solid_sections[static_cast<std::size_t>(p.section)].elform == 13)
      ctx.fail(p.where.str() + ": *PART card 2 field 3 (MID): part " + std::to_string(p.id) +
               " has material " + std::to_string(m.id) + " (" + materialKeyword(m.law) +
               "), a law of the deformation gradient, on an ELFORM 13 section: the "
               "nodal-pressure tetrahedron replaces the volumetric part of the strain increment "
               "a rate law receives, which F would contradict (use ELFORM 10)");
    else if (p.section_kind == SectionKind::Solid && materials::needsDeformationGradient(m.law) &&
             !oneSolidPoint(ctx.model, p))
      ctx.fail(
          p.where.str() + ": *PART card 2 field 3 (MID): part " + std::to_string(p.id) +
          " has material " + std::to_string(m.id) + " (" + materialKeyword(m.law) +
          "), a law of the deformation gradient (hyperelastic, foam or honeycomb), which only "
          "the one-point solids (*SECTION_SOLID ELFORM 1, 10; not with *CONTROL_SOLID "
          "ESORT = 1) support yet; its section has ELFORM " +
          std::to_string(ctx.model.solid_sections[static_cast<std::size_t>(p.section)].elform));
    else if (!onItsBeams(ctx, p, m))
      continue;
    else if (ctx.part_problem[i].empty())  // an unusable EOSID is that part's problem
      checkPartEos(ctx, p);
  }
  ctx.model.finalize();
}

void readSectionSolid(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*SECTION_SOLID");
  CardCursor cur(kw, ctx.deck);
  while (nextRecord(cur, opts.has("TITLE"))) {
    title(cur, spec, opts);
    const Card& c = cur.read(spec.card("card 1"));
    SectionSolid s;
    s.id = positiveId(c, "SECID");
    s.where = c.where();
    const auto elform = c.integer("ELFORM");
    // ELFORM (Keyword Manual, *SECTION_SOLID): 1 constant stress (default), 2 fully integrated
    // selective-reduced, -1 and -2 the same for poor aspect ratios ("accurate" and "efficient";
    // both run one formulation here, src/elements/hex8_full.cpp), 10 one-point tetrahedron,
    // 13 one-point nodal-pressure tetrahedron, 15 two-point pentahedron; 0 is the one-point
    // corotational form of *MAT_MODIFIED_HONEYCOMB, run here as 1 with a note; 16 the 10-node
    // tetrahedron (src/elements/tet10.cpp). 17, the 10-node composite tetrahedron, is not 16
    // with another rule (its strain field is assembled from 12 linear sub-tetrahedra) and is
    // refused with the rest rather than silently run as something else.
    if (elform == 1 || isFullyIntegratedHex(static_cast<int>(elform)) ||
        isTetrahedron(static_cast<int>(elform)) || elform == 15 ||
        isQuadraticTetrahedron(static_cast<int>(elform))) {
      s.elform = static_cast<int>(elform);
    } else if (elform == 0) {
      s.elform = 1;
      ctx.ignore(kw.name, "ELFORM", "ELFORM 0 is run as ELFORM 1", c.where());
    } else {
      // A definition Crumple cannot run: an error only when an element uses it.
      ctx.define(Kind::Section, s.id, c, "SECID");
      ctx.defineUnsupported(Kind::Section, s.id,
                            kw.name + " ELFORM=" + std::to_string(elform) +
                                (elform == 17 ? " (the 10-node composite tetrahedron, whose strain "
                                                "field is not ELFORM 16's)"
                                              : ""),
                            c.where());
      ctx.reportUnsupported(
          kw,
          "ELFORM " + std::to_string(elform) +
              (elform == 17 ? " (the 10-node composite tetrahedron) not supported: its "
                              "strain field is not ELFORM 16's, so it does not run as "
                              "16 (1, 2, -1, -2, 10, 13, 15 and 16 are; 0 runs as 1)"
                            : " not supported yet (1, 2, -1, -2, 10, 13, 15 and 16 "
                              "are; 0 runs as 1)"),
          false);
      ctx.collect(cur);
      continue;
    }
    ctx.define(Kind::Section, s.id, c, "SECID");
    ctx.model.solid_sections.push_back(s);
    ctx.collect(cur);
  }
}

void readHourglass(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*HOURGLASS");
  CardCursor cur(kw, ctx.deck);
  while (nextRecord(cur, opts.has("TITLE"))) {
    title(cur, spec, opts);
    const Card& c = cur.read(spec.card("card 1"));
    Hourglass h;
    h.id = positiveId(c, "HGID");
    ctx.define(Kind::Hourglass, h.id, c, "HGID");
    h.ihq = static_cast<int>(c.integer("IHQ"));
    if (!isSupportedIhq(h.ihq))
      ctx.reject(c, "IHQ", "IHQ " + std::to_string(h.ihq) + " is not supported (1 to 5 and 8 are)");
    h.qm = c.real("QM");
    if (h.qm < 0) c.fail("QM", "must not be negative");
    // QB and QW default to QM (Keyword Manual, *HOURGLASS); Crumple uses QM throughout.
    for (std::string_view f : {"QB", "QW"}) {
      const double v = c.real(f);
      if (v != 0.0 && v != h.qm)
        ctx.ignore(kw.name, f, "value " + std::to_string(v) + " is read but QM is used", c.where());
    }
    if (h.ihq == 8) ctx.ihq8_hourglass[ctx.model.hourglass.size()] = &kw;
    ctx.model.hourglass.push_back(h);
    ctx.collect(cur);
  }
}

void finishDefinitions(Context& ctx) {
  auto sortById = [](auto& v, auto& index) {
    std::stable_sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
    index.clear();
    for (std::size_t i = 0; i < v.size(); ++i) index.emplace(v[i].id, static_cast<int32_t>(i));
  };
  sortById(ctx.model.materials, ctx.material_index);
  // Section ids are one name space over every *SECTION kind (Keyword Manual, *PART SECID).
  std::unordered_map<int64_t, int32_t> index;
  ctx.section_index.clear();
  ctx.section_kind.clear();
  auto sections = [&](auto& list, SectionKind kind) {
    sortById(list, index);
    for (const auto& [id, i] : index) {
      ctx.section_index[id] = i;
      ctx.section_kind[id] = kind;
    }
  };
  sections(ctx.model.solid_sections, SectionKind::Solid);
  sections(ctx.model.shell_sections, SectionKind::Shell);
  sections(ctx.model.beam_sections, SectionKind::Beam);
  sections(ctx.model.discrete_sections, SectionKind::Discrete);
  sections(ctx.model.sph_sections, SectionKind::Sph);
  sortById(ctx.model.hourglass, ctx.hourglass_index);
  sortById(ctx.model.eos, ctx.eos_index);
}

}  // namespace crumple::model::build

namespace crumple::model::build {

namespace {

// What a degenerate solid is, from its distinct nodes (Keyword Manual, *ELEMENT_SOLID).
enum class Degenerate { None, Tetrahedron, Pentahedron, Other };
Degenerate degenerateShape(const std::array<int32_t, 8>& n) {
  if (allDistinct(n)) return Degenerate::None;
  int32_t d[8];
  switch (distinctNodes(n, d)) {
    case 8:
      return Degenerate::None;
    case 4:
      return Degenerate::Tetrahedron;
    case 6: {
      // N1 N2 N3 N4 N5 N5 N6 N6 (triangles N1 N5 N2 and N4 N6 N3), or N3 = N4 and N7 = N8.
      std::array<int32_t, 8> prism{};
      return canonicalPrism(n, prism) ? Degenerate::Pentahedron : Degenerate::Other;
    }
    default:
      return Degenerate::Other;
  }
}

}  // namespace

void readControlSolid(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*CONTROL_SOLID");
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.readOptional(spec.card("card 1"));
  if (!cur.atEnd()) cur.read(spec.card("card 2"));
  const int64_t esort = c.integer("ESORT");
  if (esort != 0 && esort != 1)
    ctx.reject(c, "ESORT",
               "only 0 (no sorting) and 1 (tetrahedra to ELFORM 10, pentahedra to ELFORM 15) are "
               "supported");
  ctx.model.controls.solid_esort = esort == 1;
  ctx.collect(cur);
  if (esort != 1) return;
  // ESORT = 1 (Keyword Manual, *CONTROL_SOLID): degenerate hexahedra of the one-point and
  // fully integrated forms run as the tetrahedron (ELFORM 10) and the pentahedron (ELFORM 15).
  // The nodes are rewritten in the canonical forms (model/solid_shape.hpp), which
  // Model::solidFormulation recognises.
  Solids& s = ctx.model.solids;
  for (std::size_t e = 0; e < s.size(); ++e) {
    const int form = sectionElform(ctx, s.part[e]);
    if (form != 1 && !isFullyIntegratedHex(form)) continue;
    const Degenerate shape = degenerateShape(s.nodes[e]);
    if (shape == Degenerate::Tetrahedron) s.nodes[e] = canonicalTet(s.nodes[e]);
    if (shape == Degenerate::Pentahedron) canonicalPrism(s.nodes[e], s.nodes[e]);
  }
}

void noteDegenerateSolids(Context& ctx) {
  const Model& m = ctx.model;
  // Per part: tetrahedra, pentahedra and other collapsed hexahedra that run as hexahedra.
  std::map<int32_t, std::array<std::size_t, 3>> count;
  for (std::size_t e = 0; e < m.solids.size(); ++e) {
    const Degenerate shape = degenerateShape(m.solids.nodes[e]);
    if (shape == Degenerate::None) continue;  // the usual hexahedron: no formulation to look up
    const int form = m.solidFormulation(e);
    if (isTetrahedron(form) || form == 15 || isQuadraticTetrahedron(form)) continue;
    ++count[m.solids.part[e]][static_cast<std::size_t>(shape) - 1];
  }
  for (const auto& [part, n] : count) {
    const Part& p = m.parts[static_cast<std::size_t>(part)];
    const int form = sectionElform(ctx, part);
    ctx.ignore(
        "*CONTROL_SOLID", "ESORT",
        fmt::format("part {}: {} degenerate solid(s) ({} tetrahedra, {} pentahedra, {} other) "
                    "run as ELFORM {} hexahedra with collapsed nodes, a poor element (too stiff "
                    "or too soft, lumped mass piled on the repeated node){}",
                    p.id, n[0] + n[1] + n[2], n[0], n[1], n[2], form,
                    n[0] + n[1] > 0 && !m.controls.solid_esort
                        ? "; *CONTROL_SOLID ESORT = 1 runs the tetrahedra as ELFORM 10 and the "
                          "pentahedra as ELFORM 15"
                        : ""),
        p.where);
  }
}

namespace {

// The mid-side node of 10-node tetrahedron e on the edge between corner nodes a and b (model.hpp:
// N5 on edge 1-2, N6 2-3, N7 3-1, N8 1-4, N9 2-4, N10 3-4).
int32_t edgeMidNode(const Model& m, std::size_t e, int32_t a, int32_t b) {
  static constexpr int kMid[4][4] = {{-1, 0, 2, 3}, {0, -1, 1, 4}, {2, 1, -1, 5}, {3, 4, 5, -1}};
  const auto& n = m.solids.nodes[e];
  auto corner = [&](int32_t node) {
    return static_cast<int>(std::find(n.begin(), n.begin() + 4, node) - n.begin());
  };
  return m.solids.mid[e][std::size_t(kMid[corner(a)][corner(b)])];
}

using CornerKey = std::array<int32_t, 3>;
CornerKey cornerKey(int32_t a, int32_t b, int32_t c) {
  CornerKey k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

// Each face of a 10-node tetrahedron by its sorted corners, with the first element (in
// element order) it bounds.
std::map<CornerKey, std::size_t> quadraticFaces(const Model& m) {
  static constexpr int kFace[4][3] = {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}};
  std::map<CornerKey, std::size_t> faces;
  for (std::size_t e = 0; e < m.solids.size(); ++e) {
    if (!m.solids.quadratic(e)) continue;
    const auto& n = m.solids.nodes[e];
    for (const auto& f : kFace)
      faces.emplace(cornerKey(n[std::size_t(f[0])], n[std::size_t(f[1])], n[std::size_t(f[2])]), e);
  }
  return faces;
}

// Pressure, airbag and blast segments on 10-node tetrahedra: a segment naming the three corners
// of a face (N4 = N3, as preprocessors write them) becomes the four flat triangles the mid-side
// nodes cut the face into, in its place and with its load, so that the mid-side nodes carry
// their share (a uniform pressure puts 1/4 of the face's load on each triangle, 1/12 on each of
// its nodes: 1/12 on a corner and 1/4 on a mid-side node, the face's total force and centre
// kept; docs/theory.md, "The 10-node tetrahedron"). Airbags keep their range of segments.
void splitQuadraticPressureSegments(Context& ctx, const std::vector<char>& on_tet10,
                                    const std::string& element) {
  Model& m = ctx.model;
  const auto faces = quadraticFaces(m);
  std::vector<PressureLoad> out;
  std::vector<std::size_t> start(m.pressure_loads.size() + 1, 0);
  for (std::size_t i = 0; i < m.pressure_loads.size(); ++i) {
    start[i] = out.size();
    const PressureLoad& p = m.pressure_loads[i];
    const auto& n = p.nodes;
    if (std::none_of(n.begin(), n.end(), [&](int32_t k) { return on_tet10[std::size_t(k)]; })) {
      out.push_back(p);
      continue;
    }
    const auto face = n[2] == n[3] ? faces.find(cornerKey(n[0], n[1], n[2])) : faces.end();
    if (face == faces.end()) {
      ctx.fail(m.deck_path + ": " +
               (p.airbag != kNone  ? "*AIRBAG"
                : p.blast != kNone ? "*LOAD_BLAST_SEGMENT_SET"
                                   : "*LOAD_SEGMENT") +
               ": a segment on 10-node tetrahedra must name the three corner nodes of an "
               "element face (N4 = N3); segment " +
               fmt::format("{} {} {} {}", m.nodes.id[std::size_t(n[0])],
                           m.nodes.id[std::size_t(n[1])], m.nodes.id[std::size_t(n[2])],
                           m.nodes.id[std::size_t(n[3])]) +
               " is not (" + element + ")");
      return;
    }
    for (const auto& t : quadraticFaceTriangles(m, face->second, n[0], n[1], n[2])) {
      PressureLoad q = p;
      q.nodes = t;
      out.push_back(q);
    }
  }
  start.back() = out.size();
  for (auto& bag : m.airbags) {
    const std::size_t last = bag.first + bag.count;
    bag.first = start[bag.first];
    bag.count = start[last] - bag.first;
  }
  m.pressure_loads = std::move(out);
}

}  // namespace

std::array<std::array<int32_t, 4>, 4> quadraticFaceTriangles(const Model& m, std::size_t e,
                                                             int32_t a, int32_t b, int32_t c) {
  const int32_t ab = edgeMidNode(m, e, a, b), bc = edgeMidNode(m, e, b, c),
                ca = edgeMidNode(m, e, c, a);
  return {std::array<int32_t, 4>{a, ab, ca, ca}, std::array<int32_t, 4>{ab, b, bc, bc},
          std::array<int32_t, 4>{ca, bc, c, c}, std::array<int32_t, 4>{ab, bc, ca, ca}};
}

void finishQuadraticTets(Context& ctx) {
  const Model& m = ctx.model;
  if (m.solids.mid.empty()) return;
  std::size_t first = m.solids.size();  // the first 10-node tetrahedron
  std::vector<char> on_tet10(m.nodes.size(), 0);
  for (std::size_t e = 0; e < m.solids.size(); ++e) {
    if (!m.solids.quadratic(e)) continue;
    first = std::min(first, e);
    for (int a = 0; a < 4; ++a) on_tet10[std::size_t(m.solids.nodes[e][std::size_t(a)])] = 1;
    for (int32_t n : m.solids.mid[e]) on_tet10[std::size_t(n)] = 1;
  }
  if (first == m.solids.size()) return;
  const std::string element = "solid element " + std::to_string(m.solids.id[first]) +
                              " is a 10-node tetrahedron (*SECTION_SOLID ELFORM 16)";
  splitQuadraticPressureSegments(ctx, on_tet10, element);
  if (!m.cross_sections.empty())
    ctx.fail(m.deck_path + ": *DATABASE_CROSS_SECTION: section forces through 10-node " +
             "tetrahedra are not supported (" + element + ")");
  for (int32_t e : m.history_elements[std::size_t(Family::Solid)])
    if (m.solids.quadratic(std::size_t(e))) {
      ctx.fail(m.deck_path + ": *DATABASE_HISTORY_SOLID: element histories of 10-node " +
               "tetrahedra are not written yet (solid element " +
               std::to_string(m.solids.id[std::size_t(e)]) + ")");
      break;
    }
}

}  // namespace crumple::model::build
