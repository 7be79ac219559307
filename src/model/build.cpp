// Deck -> Model driver: matches each keyword to its meaning (a table below), runs the
// meanings in dependency order (definitions before the things that refer to them), and
// collects what is not supported. The meanings live in build_mesh.cpp, build_sets.cpp,
// build_conditions.cpp, build_controls.cpp, build_structures.cpp and build_rigid.cpp.
#include "model/build.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "deck/deck.hpp"
#include "deck/number.hpp"
#include "model/build_context.hpp"
#include "util/error.hpp"

namespace crumple::model {

namespace build {

std::string_view kindName(Kind kind) {
  switch (kind) {
    case Kind::Material:
      return "material";
    case Kind::Section:
      return "section";
    case Kind::Hourglass:
      return "hourglass";
    case Kind::Curve:
      return "curve";
    case Kind::NodeSet:
      return "node set";
    case Kind::PartSet:
      return "part set";
    case Kind::SegmentSet:
      return "segment set";
    case Kind::Box:
      return "box";
    case Kind::CoordinateSystem:
      return "coordinate system";
  }
  return "entity";
}

void Context::reportUnsupported(const deck::Keyword& kw, std::string_view reason) {
  const auto key = std::make_pair(kw.name, std::string(reason));
  auto it = unsupported_row_.find(key);
  if (it == unsupported_row_.end()) {
    unsupported_row_.emplace(key, model.unsupported.size());
    model.unsupported.push_back({kw.name, std::string(reason), 1, deck.loc(kw)});
  } else {
    ++model.unsupported[it->second].count;
  }
}

void Context::reject(const deck::Card& card, std::string_view field, const std::string& message) {
  if (!options.allow_unsupported) card.fail(field, message);
  reportUnsupported(card.keyword(), std::string(field) + ": " + message);
}

void Context::rejectKeyword(const deck::Keyword& kw, const std::string& message) {
  if (!options.allow_unsupported)
    throw util::InputError(deck.loc(kw).str() + ": " + kw.name + ": " + message);
  reportUnsupported(kw, message);
}

void Context::ignore(std::string keyword, std::string_view field, std::string reason,
                     util::SourceLoc where) {
  model.ignored.push_back(
      {std::move(keyword), std::string(field), std::move(reason), std::move(where)});
}

void Context::collect(deck::CardCursor& cursor) {
  for (auto& u : cursor.flush())
    model.ignored.push_back(
        {u.keyword, u.field, "value " + u.value + " is read but not honoured", u.where});
}

void Context::define(Kind kind, int64_t id, const deck::Card& card, std::string_view field) {
  auto [it, inserted] = defined_.emplace(std::make_pair(kind, id), card.where());
  if (!inserted)
    card.fail(field, std::string(kindName(kind)) + " " + std::to_string(id) +
                         " is already defined at " + it->second.str());
  auto u = unsupported_.find({kind, id});
  if (u != unsupported_.end())
    card.fail(field, std::string(kindName(kind)) + " " + std::to_string(id) +
                         " is already defined by " + u->second.first + " at " +
                         u->second.second.str());
}

void Context::defineUnsupported(Kind kind, int64_t id, std::string what, util::SourceLoc where) {
  unsupported_.emplace(std::make_pair(kind, id), std::make_pair(std::move(what), std::move(where)));
}

std::string Context::unsupportedDefinition(Kind kind, int64_t id) const {
  auto u = unsupported_.find({kind, id});
  if (u == unsupported_.end()) return {};
  return u->second.first + " (" + std::string(kindName(kind)) + " " + std::to_string(id) + " at " +
         u->second.second.str() + ")";
}

bool Context::isUnsupported(Kind kind, int64_t id) const {
  return unsupported_.count({kind, id}) > 0;
}

void Context::defineBroken(Kind kind, int64_t id, std::string message) {
  broken_.emplace(std::make_pair(kind, id), std::move(message));
}

std::string Context::undefinedMessage(Kind kind, int64_t id) const {
  const std::string what = std::string(kindName(kind)) + " " + std::to_string(id);
  if (auto b = broken_.find({kind, id}); b != broken_.end())
    return what + " cannot be used: " + b->second;
  auto u = unsupported_.find({kind, id});
  if (u != unsupported_.end())
    return what + " is defined by " + u->second.first + " (" + u->second.second.str() +
           "), which is not supported yet";
  return what + " is not defined";
}

int32_t Context::node(const deck::Card& card, std::string_view field, int64_t id) const {
  const int32_t i = model.nodeIndex(id);
  if (i == kNone) card.fail(field, "node " + std::to_string(id) + " is not defined");
  return i;
}

int32_t Context::part(const deck::Card& card, std::string_view field, int64_t id) const {
  const int32_t i = model.partIndex(id);
  if (i == kNone) card.fail(field, "part " + std::to_string(id) + " is not defined");
  return i;
}

int32_t Context::curve(const deck::Card& card, std::string_view field, int64_t id) const {
  if (id == 0) card.fail(field, "a curve id is required");
  const int32_t i = model.curveIndex(id);
  if (i == kNone) card.fail(field, undefinedMessage(Kind::Curve, id));
  return i;
}

namespace {
template <class Map>
const auto& lookup(const Context& ctx, const Map& map, Kind kind, const deck::Card& card,
                   std::string_view field, int64_t id) {
  auto it = map.find(id);
  if (it == map.end()) card.fail(field, ctx.undefinedMessage(kind, id));
  return it->second;
}
}  // namespace

const std::vector<int32_t>& Context::nodeSet(const deck::Card& card, std::string_view field,
                                             int64_t id) const {
  return lookup(*this, model.node_sets, Kind::NodeSet, card, field, id);
}
const std::vector<int32_t>& Context::partSet(const deck::Card& card, std::string_view field,
                                             int64_t id) const {
  return lookup(*this, model.part_sets, Kind::PartSet, card, field, id);
}
const std::vector<std::array<int32_t, 4>>& Context::segmentSet(const deck::Card& card,
                                                               std::string_view field,
                                                               int64_t id) const {
  return lookup(*this, model.segment_sets, Kind::SegmentSet, card, field, id);
}
const Box& Context::box(const deck::Card& card, std::string_view field, int64_t id) const {
  return lookup(*this, boxes, Kind::Box, card, field, id);
}
const Frame& Context::frame(const deck::Card& card, std::string_view field, int64_t id) const {
  return lookup(*this, frames, Kind::CoordinateSystem, card, field, id);
}

const std::vector<int32_t>& Context::partNodes(int32_t part) {
  auto it = part_nodes_.find(part);
  if (it != part_nodes_.end()) return it->second;
  std::vector<int32_t> nodes;
  int32_t n[8];
  for (std::size_t g = 0; g < model.numElements(); ++g)
    if (model.elementPart(g) == part) nodes.insert(nodes.end(), n, n + model.elementNodes(g, n));
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return part_nodes_.emplace(part, std::move(nodes)).first->second;
}

namespace {

// What happens to options (the words after the base name) a meaning does not know.
enum class UnknownOption : uint8_t {
  Report,      // the keyword is reported as not supported and skipped
  Reject,      // InputError (allow_unsupported: reported): dropping it would change the answer
  Definition,  // reported; the id it defines is remembered for messages on use
};

struct Meaning {
  std::string_view base;
  int phase;  // definitions first: see readModel
  Handler handler;
  std::vector<std::string_view> options;  // the option words the meaning handles
  UnknownOption unknown = UnknownOption::Report;
  Kind kind = Kind::Material;  // for UnknownOption::Definition
};

// Phases: 0 curves, boxes, frames, nodes; 1 materials, sections, hourglass; 2 parts;
// 3 elements; 4 lists of sets; 5 general node sets; 6 everything that refers to the above.
const std::vector<Meaning>& meanings() {
  using U = UnknownOption;
  static const std::vector<Meaning> m = {
      {"*TITLE", 0, readTitle, {}},
      {"*DEFINE_CURVE", 0, readCurve, {"TITLE"}, U::Definition, Kind::Curve},
      {"*DEFINE_TABLE",
       0,
       [](Context& c, const deck::Keyword& k, const KeywordOptions&) {
         readUnsupportedDefinition(c, k, Kind::Curve);
       },
       {},
       U::Definition,
       Kind::Curve},
      {"*DEFINE_BOX", 0, readBox, {"TITLE"}, U::Definition, Kind::Box},
      {"*DEFINE_COORDINATE_SYSTEM",
       0,
       readCoordinateSystem,
       {"TITLE"},
       U::Definition,
       Kind::CoordinateSystem},
      {"*NODE", 0, readNodes, {}},
      {"*MAT",
       1,
       [](Context& c, const deck::Keyword& k, const KeywordOptions&) {
         readUnsupportedDefinition(c, k, Kind::Material);
       },
       {},
       U::Definition,
       Kind::Material},
      {"*MAT_ELASTIC", 1, readMatElastic, {"TITLE"}, U::Definition, Kind::Material},
      {"*MAT_001", 1, readMatElastic, {"TITLE"}, U::Definition, Kind::Material},
      {"*MAT_PLASTIC_KINEMATIC",
       1,
       readMatPlasticKinematic,
       {"TITLE"},
       U::Definition,
       Kind::Material},
      {"*MAT_003", 1, readMatPlasticKinematic, {"TITLE"}, U::Definition, Kind::Material},
      {"*MAT_PIECEWISE_LINEAR_PLASTICITY",
       1,
       readMatPiecewiseLinear,
       {"TITLE"},
       U::Definition,
       Kind::Material},
      {"*MAT_024", 1, readMatPiecewiseLinear, {"TITLE"}, U::Definition, Kind::Material},
      {"*SECTION",
       1,
       [](Context& c, const deck::Keyword& k, const KeywordOptions&) {
         readUnsupportedDefinition(c, k, Kind::Section);
       },
       {},
       U::Definition,
       Kind::Section},
      {"*SECTION_SOLID", 1, readSectionSolid, {"TITLE"}, U::Definition, Kind::Section},
      {"*SECTION_SHELL", 1, readSectionShell, {"TITLE"}, U::Definition, Kind::Section},
      {"*SECTION_BEAM", 1, readSectionBeam, {"TITLE"}, U::Definition, Kind::Section},
      {"*SECTION_DISCRETE", 1, readSectionDiscrete, {"TITLE"}, U::Definition, Kind::Section},
      {"*MAT_RIGID", 1, readMatRigid, {"TITLE"}, U::Definition, Kind::Material},
      {"*MAT_020", 1, readMatRigid, {"TITLE"}, U::Definition, Kind::Material},
      {"*MAT_SPRING_ELASTIC", 1, readMatSpringElastic, {"TITLE"}, U::Definition, Kind::Material},
      {"*MAT_S01", 1, readMatSpringElastic, {"TITLE"}, U::Definition, Kind::Material},
      {"*MAT_DAMPER_VISCOUS", 1, readMatDamperViscous, {"TITLE"}, U::Definition, Kind::Material},
      {"*MAT_S02", 1, readMatDamperViscous, {"TITLE"}, U::Definition, Kind::Material},
      {"*MAT_SPRING_NONLINEAR_ELASTIC",
       1,
       readMatSpringNonlinear,
       {"TITLE"},
       U::Definition,
       Kind::Material},
      {"*MAT_S04", 1, readMatSpringNonlinear, {"TITLE"}, U::Definition, Kind::Material},
      {"*HOURGLASS", 1, readHourglass, {"TITLE"}, U::Definition, Kind::Hourglass},
      {"*PART", 2, readParts, {"INERTIA", "CONTACT"}, U::Reject},
      {"*ELEMENT_SOLID", 3, readSolids, {}, U::Reject},
      {"*ELEMENT_SHELL", 3, readShells, {"THICKNESS"}, U::Reject},
      {"*ELEMENT_BEAM", 3, readBeams, {}, U::Reject},
      {"*ELEMENT_DISCRETE", 3, readDiscretes, {}, U::Reject},
      {"*SET_NODE",
       4,
       readNodeSetList,
       {"LIST", "TITLE", "GENERATE"},
       U::Definition,
       Kind::NodeSet},
      {"*SET_PART",
       4,
       readPartSetList,
       {"LIST", "TITLE", "GENERATE"},
       U::Definition,
       Kind::PartSet},
      {"*SET_SEGMENT", 4, readSegmentSet, {"TITLE"}, U::Definition, Kind::SegmentSet},
      {"*SET_NODE_GENERAL", 5, readNodeSetGeneral, {"TITLE"}, U::Definition, Kind::NodeSet},
      {"*BOUNDARY_SPC", 6, readSpc, {"NODE", "SET", "ID"}, U::Reject},
      {"*BOUNDARY_PRESCRIBED_MOTION", 6, readPrescribedMotion, {"NODE", "SET", "ID"}, U::Reject},
      {"*INITIAL_VELOCITY", 6, readInitialVelocity, {}, U::Reject},
      {"*INITIAL_VELOCITY_NODE", 6, readInitialVelocityNode, {}, U::Reject},
      {"*INITIAL_VELOCITY_GENERATION", 6, readInitialVelocityGeneration, {}, U::Reject},
      {"*LOAD_NODE", 6, readLoadNode, {"POINT", "SET"}, U::Reject},
      {"*ELEMENT_MASS", 6, readElementMass, {}, U::Reject},
      {"*LOAD_SEGMENT", 6, readLoadSegment, {}, U::Reject},
      {"*LOAD_SEGMENT_SET", 6, readLoadSegmentSet, {}, U::Reject},
      {"*LOAD_BODY", 6, readLoadBody, {"X", "Y", "Z"}, U::Reject},
      {"*RIGIDWALL_PLANAR", 6, readRigidWallPlanar, {"ID", "FINITE", "MOVING"}, U::Reject},
      {"*RIGIDWALL_GEOMETRIC",
       6,
       readRigidWallGeometric,
       {"FLAT", "PRISM", "CYLINDER", "SPHERE", "ID", "MOTION"},
       U::Reject},
      {"*BOUNDARY_PRESCRIBED_MOTION_RIGID", 6, readPrescribedMotionRigid, {"ID"}, U::Reject},
      {"*CONSTRAINED_RIGID_BODIES", 6, readRigidBodies, {}, U::Reject},
      {"*CONSTRAINED_EXTRA_NODES", 6, readExtraNodes, {"NODE", "SET"}, U::Reject},
      {"*CONSTRAINED_NODAL_RIGID_BODY", 6, readNodalRigidBody, {"SPC"}, U::Reject},
      {"*CONSTRAINED_SPOTWELD", 6, readSpotweld, {"ID"}, U::Reject},
      {"*CONSTRAINED_GENERALIZED_WELD", 6, readGeneralizedWeld, {"SPOT", "ID"}, U::Reject},
      {"*CONSTRAINED_NODE_SET", 6, readConstrainedNodeSet, {"ID"}, U::Reject},
      {"*CONSTRAINED_JOINT", 6, readJoint, {"SPHERICAL", "REVOLUTE", "ID"}, U::Reject},
      {"*CONTACT",
       6,
       readContact,
       {"AUTOMATIC", "NODES", "TO", "SURFACE", "SINGLE", "GENERAL", "TIED", "OFFSET", "ID",
        "TITLE"}},
      {"*CONTROL_TERMINATION", 6, readControlTermination, {}},
      {"*CONTROL_TIMESTEP", 6, readControlTimestep, {}},
      {"*CONTROL_HOURGLASS", 6, readControlHourglass, {}},
      {"*CONTROL_BULK_VISCOSITY", 6, readControlBulkViscosity, {}},
      {"*CONTROL_ENERGY", 6, readControlEnergy, {}},
      {"*CONTROL_SOLID", 6, readIgnoredControl, {}},
      {"*CONTROL_ACCURACY", 6, readIgnoredControl, {}},
      {"*CONTROL_OUTPUT", 6, readIgnoredControl, {}},
      {"*CONTROL_SHELL", 6, readControlShell, {}},
      {"*CONTROL_CONTACT", 5, readControlContact, {}},
      {"*CONTROL_SOLUTION", 6, readIgnoredControl, {}},
      {"*DATABASE_EXTENT_BINARY", 6, readIgnoredControl, {}},
      {"*DATABASE_GLSTAT", 6, readDatabaseAscii, {}},
      {"*DATABASE_MATSUM", 6, readDatabaseAscii, {}},
      {"*DATABASE_NODOUT", 6, readDatabaseAscii, {}},
      {"*DATABASE_RWFORC", 6, readDatabaseAscii, {}},
      {"*DATABASE_RCFORC", 6, readDatabaseAscii, {}},
      {"*DATABASE_BINARY_D3PLOT", 6, readDatabaseD3plot, {}},
      {"*DATABASE_BINARY_D3DUMP", 6, readDatabaseD3dump, {}},
      {"*DATABASE_HISTORY_NODE", 6, readHistoryNode, {"ID"}},
      {"*DATABASE_HISTORY_NODE_SET", 6, readHistoryNodeSet, {}},
  };
  return m;
}
constexpr int kPhases = 7;

// Why a keyword without a meaning is not acted on (first matching prefix wins).
std::string_view unsupportedReason(std::string_view name) {
  static const std::vector<std::pair<std::string_view, std::string_view>> reasons = {
      {"*CONTROL_IMPLICIT", "implicit analysis only"},
      {"*CONTROL_PARALLEL", "ignored: MPP/SMP option"},
      {"*CONTROL_MPP", "ignored: MPP/SMP option"},
      {"*CONTROL_CPU", "ignored: MPP/SMP option"},
      {"*CONTROL_THERMAL", "thermal analysis not supported"},
      {"*MAT_THERMAL", "thermal analysis not supported"},
      {"*BOUNDARY_TEMPERATURE", "thermal analysis not supported"},
      {"*BOUNDARY_CONVECTION", "thermal analysis not supported"},
      {"*BOUNDARY_FLUX", "thermal analysis not supported"},
      {"*BOUNDARY_RADIATION", "thermal analysis not supported"},
      {"*INITIAL_TEMPERATURE", "thermal analysis not supported"},
      {"*LOAD_THERMAL", "thermal analysis not supported"},
      // Output requests whose files Crumple does not write (yet): the run is unaffected.
      {"*DATABASE_", "output not written yet"},
  };
  for (const auto& [prefix, reason] : reasons)
    if (name.substr(0, prefix.size()) == prefix) return reason;
  return "not supported";
}

// The meaning whose base is the longest prefix of `name` ending at a '_' boundary.
const Meaning* match(std::string_view name, KeywordOptions& options) {
  const Meaning* best = nullptr;
  for (const auto& m : meanings()) {
    if (name.substr(0, m.base.size()) != m.base) continue;
    if (name.size() > m.base.size() && name[m.base.size()] != '_') continue;
    if (!best || m.base.size() > best->base.size()) best = &m;
  }
  if (!best) return nullptr;
  std::string_view rest = name.substr(best->base.size());
  while (!rest.empty()) {
    rest.remove_prefix(1);  // '_'
    const auto end = rest.find('_');
    options.words.emplace(rest.substr(0, end));
    rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end);
  }
  return best;
}

struct Planned {
  const deck::Keyword* keyword;
  const Meaning* meaning;
  KeywordOptions options;
  // A definition with options Crumple does not know (*MAT_ELASTIC_FLUID, *SET_NODE_ADD):
  // reported, its id remembered for messages on use.
  bool unsupported_definition = false;
};

}  // namespace

void readUnsupportedDefinition(Context& ctx, const deck::Keyword& kw, Kind kind) {
  std::string_view name = kw.name;
  // *MAT_ADD_EROSION, *MAT_THERMAL_* and the like add to a material rather than define one.
  const bool defines = !(name.rfind("*MAT_ADD_", 0) == 0 || name.rfind("*MAT_THERMAL", 0) == 0 ||
                         name.rfind("*MAT_NONLOCAL", 0) == 0);
  ctx.reportUnsupported(kw, unsupportedReason(name));
  if (!defines) return;
  // The id is the first field of the first card after the title line of _TITLE.
  const bool title = name.size() > 6 && name.substr(name.size() - 6) == "_TITLE";
  std::size_t line = title ? 1 : 0;
  while (line < kw.lines.size() && deck::trim(kw.lines[line].text).empty()) ++line;
  if (line >= kw.lines.size()) return;
  deck::Keyword one = kw;
  one.lines = {kw.lines[line]};
  try {
    deck::CardCursor cur(one, ctx.deck);
    const int64_t id =
        cur.read(deck::keywordSpec("*UNSUPPORTED_DEFINITION").card("card 1")).integer("ID");
    if (id != 0) ctx.defineUnsupported(kind, id, kw.name, ctx.deck.loc(kw));
  } catch (const util::InputError&) {
    // An id that is not a number (a character label): nothing can refer to it numerically.
  }
}

}  // namespace build

Model readModel(const std::filesystem::path& path) {
  return readModel(path, ReadOptions{});
}

Model readModel(const std::filesystem::path& path, const ReadOptions& options) {
  return buildModel(deck::readDeck(path), path, options);
}

Model buildModel(const deck::Deck& deck, const std::filesystem::path& path,
                 const ReadOptions& options) {
  using namespace build;
  Model model;
  model.deck_path = path.string();
  Context ctx(deck, model, options);
  for (const auto& note : deck.notes) ctx.ignore(note.keyword, note.field, note.reason, note.where);

  // Match every keyword first, so that unsupported ones are listed in deck order.
  std::vector<Planned> plan;
  for (const auto& kw : deck.keywords) {
    if (!kw.case_block.empty()) {
      ctx.reportUnsupported(kw, "inside *CASE block (" + kw.case_block + "), not supported");
      continue;
    }
    KeywordOptions opts;
    const Meaning* m = match(kw.name, opts);
    if (!m) {
      ctx.reportUnsupported(kw, unsupportedReason(kw.name));
      continue;
    }
    // A material, section or hourglass definition without its cards is what a file cut short
    // leaves (the handlers read a list of records, and would read none without a word).
    if (m->phase == 1 && std::all_of(kw.lines.begin(), kw.lines.end(),
                                     [](const auto& l) { return deck::trim(l.text).empty(); })) {
      throw util::InputError(deck.loc(kw).str() + ": " + kw.name +
                             " has no data cards (is the file cut short?)");
    }
    std::string unknown;
    for (const auto& w : opts.words)
      if (std::find(m->options.begin(), m->options.end(), w) == m->options.end())
        unknown += (unknown.empty() ? "_" : ", _") + w;
    if (!unknown.empty()) {
      switch (m->unknown) {
        case UnknownOption::Report:
          ctx.reportUnsupported(kw, unsupportedReason(kw.name));
          continue;
        case UnknownOption::Reject:
          ctx.rejectKeyword(kw, "option " + unknown + " is not supported");
          continue;
        case UnknownOption::Definition:
          plan.push_back({&kw, m, {}, true});
          continue;
      }
    }
    plan.push_back({&kw, m, std::move(opts)});
  }

  for (int phase = 0; phase < kPhases; ++phase) {
    for (const auto& p : plan) {
      if (p.unsupported_definition) {
        if (p.meaning->phase == phase) readUnsupportedDefinition(ctx, *p.keyword, p.meaning->kind);
        continue;
      }
      if (p.meaning->phase == phase) p.meaning->handler(ctx, *p.keyword, p.options);
    }
    switch (phase) {
      case 0:
        finishNodes(ctx);
        finishCurves(ctx);
        break;
      case 1:
        finishDefinitions(ctx);
        break;
      case 2:
        finishParts(ctx);
        break;
      case 3:
        finishSolids(ctx);
        break;
      default:
        break;
    }
  }
  finishRigid(ctx);
  finishConditions(ctx);
  finishControls(ctx);
  if (model.nodes.size() == 0)
    throw util::InputError(path.string() + ": the deck defines no nodes (*NODE)");
  if (model.numElements() == 0 && !options.allow_unsupported)
    throw util::InputError(path.string() +
                           ": the deck defines no elements Crumple can run (*ELEMENT_SOLID, "
                           "_SHELL, _BEAM or _DISCRETE)");
  model.finalize();
  return model;
}

std::string formatUnsupported(const Model& model) {
  if (model.unsupported.empty()) return {};
  std::size_t wk = 7, wc = 5, wl = 5;
  for (const auto& u : model.unsupported) {
    wk = std::max(wk, u.keyword.size());
    wc = std::max(wc, std::to_string(u.count).size());
    wl = std::max(wl, u.first.str().size());
  }
  std::ostringstream out;
  auto row = [&](std::string_view k, std::string_view c, std::string_view l, std::string_view r) {
    out << k << std::string(wk - k.size() + 2, ' ') << std::string(wc - c.size(), ' ') << c << "  "
        << l << std::string(wl - l.size() + 2, ' ') << r << '\n';
  };
  row("keyword", "count", "first", "reason");
  for (const auto& u : model.unsupported)
    row(u.keyword, std::to_string(u.count), u.first.str(), u.reason);
  return out.str();
}

std::string formatIgnored(const Model& model) {
  std::ostringstream out;
  for (const auto& i : model.ignored)
    out << i.where.str() << ": " << i.keyword << " " << i.field << ": " << i.reason << '\n';
  return out.str();
}

}  // namespace crumple::model
