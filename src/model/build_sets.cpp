// Meaning of the definitions other keywords refer to: *DEFINE_CURVE, *DEFINE_TABLE, *DEFINE_BOX,
// *DEFINE_COORDINATE_SYSTEM, *SET_NODE_LIST, *SET_NODE_GENERAL, *SET_PART_LIST,
// *SET_SEGMENT (LS-DYNA Keyword Manual Vol. I).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "model/build_context.hpp"
#include "util/vec3.hpp"

namespace crumple::model::build {

namespace {

using deck::Card;
using deck::CardCursor;
using deck::keywordSpec;

constexpr std::string_view kRange[8] = {"B1", "E1", "B2", "E2", "B3", "E3", "B4", "E4"};

using util::cross;
using util::dot;
using util::norm;
using util::sub;
using util::unit;

void sortUnique(std::vector<int32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// Card 1 of a *SET_ keyword (after the _TITLE line): its SID, defined once.
int64_t readSetId(Context& ctx, CardCursor& cur, const deck::KeywordSpec& spec,
                  const KeywordOptions& opts, Kind kind) {
  if (opts.has("TITLE")) cur.read(spec.card("title card"));
  const Card& c = cur.read(spec.card("card 1"));
  const int64_t sid = c.integer("SID");
  if (sid <= 0) c.fail("SID", "the set id must be a positive integer");
  if (opts.has("COLLECT"))
    ctx.defineCollected(kind, sid, c, "SID");
  else
    ctx.define(kind, sid, c, "SID");
  return sid;
}

// _GENERATE: the ids between B and E (inclusive) that exist, from the ascending id list.
template <class Ids, class Add>
void generate(const Card& c, const Ids& ids, Add add) {
  for (int k = 0; k < 8; k += 2) {
    const int64_t b = c.integer(kRange[k]), e = c.integer(kRange[k + 1]);
    if (b == 0 && e == 0) continue;
    if (b > e) c.fail(kRange[k + 1], "the range ends before it begins");
    for (auto it = std::lower_bound(ids.begin(), ids.end(), b); it != ids.end() && *it <= e; ++it)
      add(static_cast<int32_t>(it - ids.begin()));
  }
}

// Members of a set that name a node or part that does not exist make the set unusable, not
// the deck: exported decks carry such leftovers (contact surfaces of deleted meshes), and
// LS-DYNA too only needs the sets something uses. The first bad member is remembered and
// reported if the set is used.
class Members {
 public:
  Members(Context& ctx, Kind kind, int64_t sid) : ctx_(ctx), kind_(kind), sid_(sid) {}
  Kind kind() const { return kind_; }
  // Index of node or part `id`, or kNone after recording the problem.
  int32_t resolve(const Card& c, std::string_view field, int64_t id, bool part) {
    const int32_t i = part ? ctx_.model.partIndex(id) : ctx_.model.nodeIndex(id);
    if (i == kNone)
      problem(c, field, (part ? "part " : "node ") + std::to_string(id) + " is not defined");
    return i;
  }
  // Index of element `id` within family f, or kNone after recording the problem.
  int32_t resolveElement(const Card& c, std::string_view field, int64_t id, Family f) {
    if (const int32_t i = ctx_.model.elementIndex(f, id); i != kNone) return i;
    problem(c, field,
            std::string(familyName(f)) + " element " + std::to_string(id) + " is not defined");
    return kNone;
  }
  // Records a problem of a member (the first is kept).
  void problem(const Card& c, std::string_view field, const std::string& message) {
    if (problem_.empty()) problem_ = c.context(field) + ": " + message;
  }
  // True if the set can be stored; otherwise it is recorded as broken.
  bool finish(const deck::Keyword& kw) {
    if (problem_.empty()) return true;
    ctx_.defineBroken(kind_, sid_, problem_);
    ctx_.ignore(kw.name, "SID",
                std::string(kindName(kind_)) + " " + std::to_string(sid_) +
                    " is skipped (an error if something uses it): " + problem_,
                ctx_.deck.loc(kw));
    return false;
  }

 private:
  Context& ctx_;
  Kind kind_;
  int64_t sid_;
  std::string problem_;
};

// Stores set `sid`'s members, merged with those of the keywords before it with the same id
// (_COLLECT; otherwise there are none), ascending and unique. A member that does not exist
// makes the set unusable, every collected piece of it included.
template <class Sets, class Member>
void storeSet(Context& ctx, Members& members, const deck::Keyword& kw, Sets& sets, int64_t sid,
              std::vector<Member> list) {
  if (!members.finish(kw) || !ctx.brokenMessage(members.kind(), sid).empty()) {
    sets.erase(sid);
    return;
  }
  auto& set = sets[sid];
  set.insert(set.end(), list.begin(), list.end());
  sortUnique(set);
}

}  // namespace

namespace {
// The head shared by *DEFINE_CURVE and *DEFINE_TABLE (which share their ids): the _TITLE line,
// card 1 and its positive id in `field`, recorded as a curve definition.
const Card& curveHead(Context& ctx, CardCursor& cur, const deck::KeywordSpec& spec,
                      const KeywordOptions& opts, std::string_view field, int64_t& id) {
  if (opts.has("TITLE")) cur.read(spec.card("title card"));
  const Card& c = cur.read(spec.card("card 1"));
  id = c.integer(field);
  if (id <= 0)
    c.fail(field, "the " + std::string(field == "LCID" ? "curve" : "table") +
                      " id must be a positive integer");
  ctx.define(Kind::Curve, id, c, field);
  return c;
}
}  // namespace

void readCurve(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*DEFINE_CURVE");
  CardCursor cur(kw, ctx.deck);
  Curve curve;
  const Card& c = curveHead(ctx, cur, spec, opts, "LCID", curve.id);
  // SIDR 1 and 2 apply the curve in a dynamic-relaxation phase (and turn that phase on unless
  // *CONTROL_DYNAMIC_RELAXATION IDRFLG = -999), 1 only there (model::loadFactor).
  const int64_t sidr = c.integer("SIDR");
  if (sidr < 0 || sidr > 2) c.fail("SIDR", "must be 0, 1 or 2");
  curve.sidr = int32_t(sidr);
  if (sidr != 0) ctx.model.controls.relaxation.sidr_curves = true;
  const double sfa = c.real("SFA"), sfo = c.real("SFO"), offa = c.real("OFFA"),
               offo = c.real("OFFO");
  // Keyword Manual, *DEFINE_CURVE, remarks: the values are scaled after the offsets are
  // applied, x = SFA (a + OFFA), y = SFO (o + OFFO); SFA and SFO of 0 mean 1.
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& p = cur.read(spec.card("point card"));
    const double x = sfa * (p.real("A1") + offa);
    if (!curve.x.empty() && x < curve.x.back())
      p.fail("A1", "the abscissa values must not decrease");
    curve.x.push_back(x);
    curve.y.push_back(sfo * (p.real("O1") + offo));
  }
  if (curve.x.empty()) c.fail("LCID", "the curve has no points");
  ctx.model.curves.push_back(std::move(curve));
  ctx.collect(cur);
}

void finishCurves(Context& ctx) {
  auto& curves = ctx.model.curves;
  std::stable_sort(curves.begin(), curves.end(),
                   [](const Curve& a, const Curve& b) { return a.id < b.id; });
  ctx.model.finalize();
}

namespace {

// The LCID of the curve keyword `k` places after the table `kw` (k = 1: the next keyword), or
// 0 when that keyword is not a *DEFINE_CURVE.
int64_t followingCurve(const Context& ctx, const deck::Keyword& kw, std::size_t k) {
  const auto& all = ctx.deck.keywords;
  const auto at = static_cast<std::size_t>(&kw - all.data()) + k;
  if (at >= all.size()) return 0;
  const deck::Keyword& next = all[at];
  if (next.name != "*DEFINE_CURVE" && next.name != "*DEFINE_CURVE_TITLE") return 0;
  return definedId(ctx, next);
}

}  // namespace

// Keyword Manual vol. I, *DEFINE_TABLE: TBID, SFA (0 means 1) and OFFA, then one value per
// card, scaled after offsetting as a curve's abscissae are (SFA (VALUE + OFFA)); a value's
// curve is the one its LCID names, else the next *DEFINE_CURVE following the table (the
// curves follow the table in the order of its values). Tables and curves share their ids.
void readTable(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*DEFINE_TABLE");
  CardCursor cur(kw, ctx.deck);
  Table t;
  const Card& c = curveHead(ctx, cur, spec, opts, "TBID", t.id);
  t.where = ctx.deck.loc(kw);
  const double sfa = c.real("SFA"), offa = c.real("OFFA");
  std::size_t following = 0;  // curves taken from the keywords after the table
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& v = cur.read(spec.card("value card"));
    const double value = sfa * (v.real("VALUE") + offa);
    if (!t.values.empty() && !(value > t.values.back()))
      v.fail("VALUE", "the values must increase (each is a strain rate with its own curve)");
    int64_t lcid = v.integer("LCID");
    if (lcid == 0 && (lcid = followingCurve(ctx, kw, ++following)) == 0)
      v.fail("VALUE",
             "no *DEFINE_CURVE follows the table for this value (without LCID, the curves follow "
             "the table, one per value, in order)");
    t.values.push_back(value);
    t.curve_ids.push_back(lcid);
  }
  if (t.values.empty()) c.fail("TBID", "the table has no values");
  ctx.model.tables.push_back(std::move(t));
  ctx.collect(cur);
}

void finishTables(Context& ctx) {
  auto& tables = ctx.model.tables;
  std::stable_sort(tables.begin(), tables.end(),
                   [](const Table& a, const Table& b) { return a.id < b.id; });
  std::vector<Table> usable;
  for (Table& t : tables) {
    std::string problem;
    for (std::size_t k = 0; k < t.curve_ids.size() && problem.empty(); ++k) {
      const int32_t i = ctx.model.curveIndex(t.curve_ids[k]);
      if (i == kNone)
        problem = t.where.str() + ": *DEFINE_TABLE " + std::to_string(t.id) + ": value " +
                  std::to_string(k + 1) + ": " + ctx.undefinedMessage(Kind::Curve, t.curve_ids[k]);
      t.curves.push_back(i);
    }
    // LS-DYNA needs only the tables something uses: the error is on use.
    if (problem.empty()) {
      usable.push_back(std::move(t));
    } else {
      ctx.defineBroken(Kind::Curve, t.id, problem);
    }
  }
  tables = std::move(usable);
  ctx.model.finalize();
}

void readBox(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*DEFINE_BOX");
  CardCursor cur(kw, ctx.deck);
  if (opts.has("TITLE")) cur.read(spec.card("title card"));
  const Card& c = cur.read(spec.card("card 1"));
  const int64_t id = c.integer("BOXID");
  if (id <= 0) c.fail("BOXID", "the box id must be a positive integer");
  ctx.define(Kind::Box, id, c, "BOXID");
  Box b{{c.real("XMN"), c.real("YMN"), c.real("ZMN")},
        {c.real("XMX"), c.real("YMX"), c.real("ZMX")}};
  static constexpr std::string_view kMax[3] = {"XMX", "YMX", "ZMX"};
  for (int i = 0; i < 3; ++i)
    if (b.hi[i] < b.lo[i]) c.fail(kMax[i], "the maximum is below the minimum");
  ctx.boxes.emplace(id, b);
  ctx.collect(cur);
}

// *DEFINE_VECTOR: the direction from the tail (XT, YT, ZT) to the head (XH, YH, ZH).
void readVector(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*DEFINE_VECTOR");
  CardCursor cur(kw, ctx.deck);
  if (opts.has("TITLE")) cur.read(spec.card("title card"));
  const Card& c = cur.read(spec.card("card 1"));
  const int64_t id = c.integer("VID");
  if (id <= 0) c.fail("VID", "the vector id must be a positive integer");
  if (c.integer("CID") != 0)
    ctx.reject(c, "CID", "a vector in a local coordinate system (CID) is not supported");
  ctx.define(Kind::Vector, id, c, "VID");
  const Vec3 d =
      sub({c.real("XH"), c.real("YH"), c.real("ZH")}, {c.real("XT"), c.real("YT"), c.real("ZT")});
  if (dot(d, d) == 0.0) c.fail("XH", "the head is the tail: the vector has no direction");
  ctx.vectors.emplace(id, unit(d));
  ctx.collect(cur);
}

namespace {

// The right-handed frame with x along ex and z along ez (ez normal to ex), y = z x x.
Frame frameOf(const Vec3& ex, const Vec3& ez) {
  Frame f;
  for (int i = 0; i < 3; ++i) {
    f.axis[0][i] = ex[i] / norm(ex);
    f.axis[2][i] = ez[i] / norm(ez);
  }
  f.axis[1] = cross(f.axis[2], f.axis[0]);
  return f;
}

}  // namespace

// Local x along O->L, z normal to the plane O, L, P, y = z x x (Keyword Manual,
// *DEFINE_COORDINATE_SYSTEM).
void readCoordinateSystem(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*DEFINE_COORDINATE_SYSTEM");
  CardCursor cur(kw, ctx.deck);
  if (opts.has("TITLE")) cur.read(spec.card("title card"));
  const Card& c = cur.read(spec.card("card 1"));
  const Card& c2 = cur.read(spec.card("card 2"));
  const int64_t id = c.integer("CID");
  if (id <= 0) c.fail("CID", "the coordinate system id must be a positive integer");
  ctx.define(Kind::CoordinateSystem, id, c, "CID");
  if (c.integer("CIDL") != 0)
    ctx.reject(c, "CIDL", "points given in another local system (CIDL) are not supported");
  const Vec3 o{c.real("XO"), c.real("YO"), c.real("ZO")};
  const Vec3 ex = sub({c.real("XL"), c.real("YL"), c.real("ZL")}, o);
  const Vec3 ez = cross(ex, sub({c2.real("XP"), c2.real("YP"), c2.real("ZP")}, o));
  if (norm(ex) == 0.0) c.fail("XL", "the point on the local x axis coincides with the origin");
  if (norm(ez) == 0.0) c2.fail("XP", "the point in the local xy plane lies on the local x axis");
  ctx.frames.emplace(id, frameOf(ex, ez));
  ctx.collect(cur);
}

// *DEFINE_COORDINATE_NODE (Keyword Manual vol. I): local x along N1 -> N2, z normal to the
// plane of N1, N2, N3, y = z x x, from the nodes' initial places. FLAG = 1 (the frame follows
// its nodes during the run) is refused; a joint stiffness turns its frames with its bodies
// whatever FLAG says.
void readCoordinateNode(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*DEFINE_COORDINATE_NODE");
  CardCursor cur(kw, ctx.deck);
  if (opts.has("TITLE")) cur.read(spec.card("title card"));
  const Card& c = cur.read(spec.card("card 1"));
  const int64_t id = c.integer("CID");
  if (id <= 0) c.fail("CID", "the coordinate system id must be a positive integer");
  ctx.define(Kind::CoordinateSystem, id, c, "CID");
  if (c.integer("FLAG") != 0)
    ctx.reject(c, "FLAG", "a coordinate system that follows its nodes (FLAG = 1) is not supported");
  if (const std::string dir = c.text("DIR"); !dir.empty() && dir != "X" && dir != "x")
    ctx.reject(c, "DIR", "only DIR = X (local x along N1 -> N2) is supported");
  const auto at = [&](std::string_view f) {
    return ctx.model.nodes.x[std::size_t(ctx.node(c, f, c.integer(f)))];
  };
  const Vec3 o = at("N1");
  const Vec3 ex = sub(at("N2"), o);
  const Vec3 ez = cross(ex, sub(at("N3"), o));
  if (norm(ex) == 0.0) c.fail("N2", "N2 coincides with N1: the local x axis has no direction");
  if (norm(ez) == 0.0) c.fail("N3", "N3 lies on the local x axis N1-N2");
  ctx.frames.emplace(id, frameOf(ex, ez));
  ctx.collect(cur);
}

void readNodeSetList(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*SET_NODE_LIST");
  CardCursor cur(kw, ctx.deck);
  const int64_t sid = readSetId(ctx, cur, spec, opts, Kind::NodeSet);
  Members members(ctx, Kind::NodeSet, sid);
  std::vector<int32_t> nodes;
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    if (opts.has("GENERATE")) {
      generate(cur.read(spec.card("range card")), ctx.model.nodes.id,
               [&](int32_t i) { nodes.push_back(i); });
    } else {
      const Card& c = cur.read(spec.card("card 2"));
      for (int k = 1; k <= 8; ++k) {
        const std::string f = "NID" + std::to_string(k);
        if (const int64_t id = c.integer(f); id != 0)
          nodes.push_back(members.resolve(c, f, id, false));
      }
    }
    ctx.collect(cur);
  }
  storeSet(ctx, members, kw, ctx.model.node_sets, sid, std::move(nodes));
}

void readPartSetList(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*SET_PART_LIST");
  CardCursor cur(kw, ctx.deck);
  const int64_t sid = readSetId(ctx, cur, spec, opts, Kind::PartSet);
  Members members(ctx, Kind::PartSet, sid);
  std::vector<int64_t> part_ids;
  for (const auto& p : ctx.model.parts) part_ids.push_back(p.id);
  std::vector<int32_t> parts;
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    if (opts.has("GENERATE")) {
      generate(cur.read(spec.card("range card")), part_ids, [&](int32_t i) { parts.push_back(i); });
    } else {
      const Card& c = cur.read(spec.card("card 2"));
      for (int k = 1; k <= 8; ++k) {
        const std::string f = "PID" + std::to_string(k);
        if (const int64_t id = c.integer(f); id != 0)
          parts.push_back(members.resolve(c, f, id, true));
      }
    }
    ctx.collect(cur);
  }
  storeSet(ctx, members, kw, ctx.model.part_sets, sid, std::move(parts));
}

void readSegmentSet(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*SET_SEGMENT");
  CardCursor cur(kw, ctx.deck);
  const int64_t sid = readSetId(ctx, cur, spec, opts, Kind::SegmentSet);
  Members members(ctx, Kind::SegmentSet, sid);
  std::vector<std::array<int32_t, 4>> segments;
  static constexpr std::string_view kN[4] = {"N1", "N2", "N3", "N4"};
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec.card("card 2"));
    std::array<int32_t, 4> s{};
    for (int k = 0; k < 4; ++k) {
      int64_t id = c.integer(kN[k]);
      // A triangle repeats N3 as N4 (Keyword Manual, *SET_SEGMENT).
      if (k == 3 && id == 0) id = c.integer("N3");
      // N3 = 0: a line segment of a 2-D (plane or axisymmetric) model; unusable in 3-D, and
      // an error only if something uses the set.
      if (id == 0) {
        members.problem(c, kN[k], "node id missing (a 2-D line segment has no N3)");
        continue;
      }
      s[k] = members.resolve(c, kN[k], id, false);
    }
    segments.push_back(s);
    ctx.collect(cur);
  }
  if (!members.finish(kw)) return;
  ctx.model.segment_sets[sid] = std::move(segments);
}

// Options rows (Keyword Manual, *SET_NODE_GENERAL) applied in order: ALL, NODE, PART, BOX,
// SET add nodes; DNODE, DPART, DBOX remove them.
void readNodeSetGeneral(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*SET_NODE_GENERAL");
  CardCursor cur(kw, ctx.deck);
  const int64_t sid = readSetId(ctx, cur, spec, opts, Kind::NodeSet);
  const Model& m = ctx.model;
  std::vector<char> in(m.nodes.size(), 0);
  static constexpr std::string_view kE[7] = {"E1", "E2", "E3", "E4", "E5", "E6", "E7"};
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec.card("card 2"));
    std::string option = c.text("OPTION");
    std::transform(option.begin(), option.end(), option.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
    const bool remove = option.size() > 1 && option[0] == 'D' && option != "DALL";
    const std::string what = remove ? option.substr(1) : option;
    const char value = remove ? 0 : 1;
    if (what == "ALL" && !remove) {
      std::fill(in.begin(), in.end(), 1);
    } else if (what == "NODE" || what == "PART" || what == "BOX" || (what == "SET" && !remove)) {
      for (auto e : kE) {
        const int64_t id = c.integer(e);
        if (id == 0) continue;
        if (what == "NODE") {
          in[ctx.node(c, e, id)] = value;
        } else if (what == "PART") {
          for (int32_t n : ctx.partNodes(ctx.part(c, e, id))) in[n] = value;
        } else if (what == "BOX") {
          const Box& b = ctx.box(c, e, id);
          for (std::size_t n = 0; n < m.nodes.size(); ++n)
            if (b.contains(m.nodes.x[n])) in[n] = value;
        } else {
          for (int32_t n : ctx.nodeSet(c, e, id)) in[n] = value;
        }
      }
    } else {
      ctx.reject(c, "OPTION",
                 "option '" + option +
                     "' is not supported (ALL, NODE, PART, BOX, SET, DNODE, DPART, DBOX are)");
    }
    ctx.collect(cur);
  }
  std::vector<int32_t> nodes;
  for (std::size_t n = 0; n < in.size(); ++n)
    if (in[n]) nodes.push_back(static_cast<int32_t>(n));
  ctx.model.node_sets[sid] = std::move(nodes);
}

}  // namespace crumple::model::build

namespace crumple::model::build {

namespace {

// *SET_TSHELL (Keyword Manual vol. I): thick shells, kept with the solids (model.hpp), in a set
// id space of their own; its members must be thick shells.
constexpr std::string_view kTShellSet = "*SET_TSHELL";
bool isTShellSet(std::string_view name) {
  return name.substr(0, kTShellSet.size()) == kTShellSet;
}

// The element-set keywords of each family (Keyword Manual vol. I, *SET_SOLID, *SET_SHELL,
// *SET_BEAM, *SET_DISCRETE), in Family order.
constexpr std::string_view kElementSet[kFamilies] = {"*SET_SOLID", "*SET_SHELL", "*SET_BEAM",
                                                     "*SET_DISCRETE"};
constexpr std::string_view kElementSetAdd[kFamilies] = {"*SET_SOLID_ADD", "*SET_SHELL_ADD",
                                                        "*SET_BEAM_ADD", "*SET_DISCRETE_ADD"};

Family elementSetFamily(std::string_view name) {
  if (isTShellSet(name)) return Family::Solid;
  for (int k = 0; k < kFamilies; ++k)
    if (name.substr(0, kElementSet[k].size()) == kElementSet[k]) return static_cast<Family>(k);
  throw std::logic_error("not an element set keyword: " + std::string(name));
}

}  // namespace

namespace {
// The sets a keyword's ids name and their kind: *SET_TSHELL's or the family's.
Kind setKindOf(const deck::Keyword& kw, Family f) {
  return isTShellSet(kw.name) ? Kind::TShellSet : elementSetKind(f);
}
std::map<int64_t, std::vector<int32_t>>& setsOf(Context& ctx, const deck::Keyword& kw, Family f) {
  return isTShellSet(kw.name) ? ctx.model.tshell_sets
                              : ctx.model.element_sets[static_cast<std::size_t>(f)];
}
const deck::KeywordSpec& setSpec(const deck::Keyword& kw, Family f, bool add) {
  if (isTShellSet(kw.name)) return keywordSpec(add ? "*SET_TSHELL_ADD" : kTShellSet);
  return keywordSpec((add ? kElementSetAdd : kElementSet)[static_cast<int>(f)]);
}

// The SID card, then `member(card spec, members, out)` for each card; the set is stored in
// its family's map (*SET_TSHELL: the thick-shell sets) unless a member made it unusable.
template <class Member>
void readElementSet(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts,
                    const deck::KeywordSpec& spec, Family f, Member member) {
  CardCursor cur(kw, ctx.deck);
  const Kind kind = setKindOf(kw, f);
  const int64_t sid = readSetId(ctx, cur, spec, opts, kind);
  Members members(ctx, kind, sid);
  std::vector<int32_t> elements;
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    member(cur, members, elements);
    ctx.collect(cur);
  }
  storeSet(ctx, members, kw, setsOf(ctx, kw, f), sid, std::move(elements));
}
}  // namespace

// Members name elements of the keyword's family by id (_GENERATE: the ids between B and E that
// exist; *SET_TSHELL: the thick shells among them); one that does not exist (*SET_TSHELL: or
// is not a thick shell) makes the set an error where it is used.
void readElementSetList(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const Family f = elementSetFamily(kw.name);
  const bool tshell = isTShellSet(kw.name);
  const auto& spec = setSpec(kw, f, false);
  const std::vector<int64_t>& ids = ctx.model.familyIds(f);
  const Model& m = ctx.model;
  readElementSet(ctx, kw, opts, spec, f,
                 [&](CardCursor& cur, Members& members, std::vector<int32_t>& out) {
                   if (opts.has("GENERATE")) {
                     generate(cur.read(spec.card("range card")), ids, [&](int32_t i) {
                       if (!tshell || m.isThickShellElement(i)) out.push_back(i);
                     });
                     return;
                   }
                   const Card& c = cur.read(spec.card("card 2"));
                   for (int k = 1; k <= 8; ++k) {
                     const std::string field = "K" + std::to_string(k);
                     const int64_t id = c.integer(field);
                     if (id == 0) continue;
                     const int32_t e = members.resolveElement(c, field, id, f);
                     if (tshell && e != kNone && !m.isThickShellElement(e))
                       members.problem(c, field,
                                       "element " + std::to_string(id) +
                                           " is a solid, not a thick shell (*ELEMENT_TSHELL)");
                     out.push_back(e);
                   }
                 });
}

// _ADD: the union of the sets of the same family it names (read after every list; an _ADD
// set it names must come before it in the deck).
void readElementSetAdd(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const Family f = elementSetFamily(kw.name);
  const auto& spec = setSpec(kw, f, true);
  const auto& sets = setsOf(ctx, kw, f);
  readElementSet(ctx, kw, opts, spec, f,
                 [&](CardCursor& cur, Members& members, std::vector<int32_t>& out) {
                   const Card& c = cur.read(spec.card("card 2"));
                   for (int k = 1; k <= 8; ++k) {
                     const std::string field = "DSID" + std::to_string(k);
                     const int64_t id = c.integer(field);
                     if (id == 0) continue;
                     if (const auto it = sets.find(id); it != sets.end()) {
                       out.insert(out.end(), it->second.begin(), it->second.end());
                     } else {
                       members.problem(c, field, ctx.undefinedMessage(setKindOf(kw, f), id));
                     }
                   }
                 });
}

}  // namespace crumple::model::build
