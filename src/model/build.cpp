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
#include "model/units.hpp"
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
    case Kind::Vector:
      return "vector";
    case Kind::Eos:
      return "equation of state";
    case Kind::SolidSet:
      return "solid set";
    case Kind::ShellSet:
      return "shell set";
    case Kind::BeamSet:
      return "beam set";
    case Kind::DiscreteSet:
      return "discrete set";
    case Kind::TShellSet:
      return "thick shell set";
  }
  return "entity";
}

void Context::reportUnsupported(const deck::Keyword& kw, std::string_view reason,
                                bool changes_answer, std::string feature) {
  const auto key = std::make_pair(kw.name, std::string(reason));
  auto it = unsupported_row_.find(key);
  if (it == unsupported_row_.end()) {
    unsupported_row_.emplace(key, model.unsupported.size());
    if (feature.empty()) feature = kw.name;
    model.unsupported.push_back(
        {kw.name, std::string(reason), 1, deck.loc(kw), changes_answer, std::move(feature)});
  } else {
    ++model.unsupported[it->second].count;
  }
}

void Context::recordError(std::string message) {
  // The same problem met again (every element of a part without a material) is listed once.
  if (!errors_seen_.insert(message).second) return;
  model.errors.push_back({std::move(message)});
}

void Context::fail(std::string message) {
  if (!options.collect_errors) throw util::InputError(message);
  recordError(std::move(message));
}

void Context::reject(const deck::Card& card, std::string_view field, const std::string& message,
                     std::string feature) {
  if (!options.allow_unsupported) card.fail(field, message);
  if (feature.empty()) feature = card.keyword().name + " " + std::string(field);
  reportUnsupported(card.keyword(), std::string(field) + ": " + message, true, std::move(feature));
}

void Context::checkPartUsable(const deck::Card& c, int32_t part) {
  const PartProblem& p = part_problem[static_cast<std::size_t>(part)];
  if (p.empty()) return;
  // The error is where the part or its definition is written; the element says why it matters.
  if (p.feature.empty())
    throw util::InputError(p.message + " (the part is used by " + c.keyword().name + " at " +
                           c.where().str() + ")");
  reject(c, "PID", p.message, p.feature);
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
  for (auto& n : cursor.takeNotes())
    model.ignored.push_back({n.keyword, n.field, n.reason, n.where});
}

void Context::define(Kind kind, int64_t id, const deck::Card& card, std::string_view field) {
  auto [it, inserted] = defined_.emplace(std::make_pair(kind, id), card.where());
  if (!inserted)
    card.fail(field, std::string(kindName(kind)) + " " + std::to_string(id) +
                         " is already defined at " + it->second.str() +
                         (collected_.count({kind, id}) != 0
                              ? " (sets of one id are merged only if each has _COLLECT)"
                              : ""));
  auto u = unsupported_.find({kind, id});
  if (u != unsupported_.end())
    card.fail(field, std::string(kindName(kind)) + " " + std::to_string(id) +
                         " is already defined by " + u->second.first + " at " +
                         u->second.second.str());
}

void Context::defineCollected(Kind kind, int64_t id, const deck::Card& card,
                              std::string_view field) {
  if (collected_.count({kind, id}) != 0) return;
  define(kind, id, card, field);
  collected_.insert({kind, id});
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

std::string Context::unsupportedFeature(Kind kind, int64_t id) const {
  auto u = unsupported_.find({kind, id});
  if (u == unsupported_.end()) return {};
  std::string what = u->second.first;
  if (const auto t = what.find("_TITLE"); t != std::string::npos) what.erase(t, 6);
  return what;
}

bool Context::isDefined(Kind kind, int64_t id) const {
  return defined_.count({kind, id}) > 0 || unsupported_.count({kind, id}) > 0;
}

bool Context::isUnsupported(Kind kind, int64_t id) const {
  return unsupported_.count({kind, id}) > 0;
}

void Context::defineBroken(Kind kind, int64_t id, std::string message) {
  broken_.emplace(std::make_pair(kind, id), std::move(message));
}

std::string Context::brokenMessage(Kind kind, int64_t id) const {
  auto b = broken_.find({kind, id});
  return b == broken_.end() ? std::string{} : b->second;
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

int32_t Context::curve(const deck::Card& card, std::string_view field, int64_t id) {
  if (id == 0) card.fail(field, "a curve id is required");
  const int32_t i = model.curveIndex(id);
  if (i != kNone) return i;
  // A table where a curve is expected: LS-DYNA takes one only in some fields (those that ask
  // for a table, as *MAT_024 LCSS), so Crumple refuses it as a missing feature.
  if (const int32_t t = model.tableIndex(id); t != kNone) {
    reject(card, field,
           "curve " + std::to_string(id) + " is a *DEFINE_TABLE (" +
               model.tables[static_cast<std::size_t>(t)].where.str() +
               "), which is not supported here",
           "*DEFINE_TABLE");
    throw SkipRecord{};
  }
  // A curve of a kind Crumple does not read (*DEFINE_CURVE_SMOOTH, *DEFINE_TABLE_2D): a missing
  // feature, not an input error; `check` lists it and skips the record.
  if (!isUnsupported(Kind::Curve, id)) card.fail(field, undefinedMessage(Kind::Curve, id));
  reject(card, field, undefinedMessage(Kind::Curve, id), unsupportedFeature(Kind::Curve, id));
  throw SkipRecord{};
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
const std::vector<int32_t>& Context::tshellSet(const deck::Card& card, std::string_view field,
                                               int64_t id) const {
  return lookup(*this, model.tshell_sets, Kind::TShellSet, card, field, id);
}
const std::vector<int32_t>& Context::elementSet(Family f, const deck::Card& card,
                                                std::string_view field, int64_t id) const {
  return lookup(*this, model.element_sets[static_cast<std::size_t>(f)], elementSetKind(f), card,
                field, id);
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
  int32_t n[kMaxElementNodes];
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

// The table plus one meaning per keyword name of every law in materials/registry.hpp.
std::vector<Meaning> withLaws(std::vector<Meaning> m) {
  for (const LawReader& law : lawReaders())
    m.push_back({law.keyword, 1, law.read, {"TITLE"}, UnknownOption::Definition, Kind::Material});
  return m;
}

// Phases: 0 curves, boxes, frames, nodes; 1 materials, sections, hourglass; 2 parts;
// 3 elements; 4 lists of sets; 5 general node sets; 6 everything that refers to the above.
const std::vector<Meaning>& meanings() {
  using U = UnknownOption;
  static const std::vector<Meaning> m = withLaws({
      {"*TITLE", 0, readTitle, {}},
      {"*DEFINE_CURVE", 0, readCurve, {"TITLE"}, U::Definition, Kind::Curve},
      {"*DEFINE_TABLE", 0, readTable, {"TITLE"}, U::Definition, Kind::Curve},
      {"*DEFINE_BOX", 0, readBox, {"TITLE"}, U::Definition, Kind::Box},
      {"*DEFINE_VECTOR", 0, readVector, {"TITLE"}, U::Definition, Kind::Vector},
      {"*DEFINE_COORDINATE_SYSTEM",
       0,
       readCoordinateSystem,
       {"TITLE"},
       U::Definition,
       Kind::CoordinateSystem},
      {"*NODE", 0, readNodes, {}},
      // Before the sections that name it (QR/IRID < 0).
      {"*INTEGRATION_BEAM", 0, readIntegrationBeam, {}},
      {"*INTEGRATION_SHELL", 0, readIntegrationShell, {}},
      // After the nodes it is built from; before the parts and loads that use it.
      {"*DEFINE_COORDINATE_NODE",
       1,
       readCoordinateNode,
       {"TITLE"},
       U::Definition,
       Kind::CoordinateSystem},
      {"*MAT",
       1,
       [](Context& c, const deck::Keyword& k, const KeywordOptions&) {
         readUnsupportedDefinition(c, k, Kind::Material);
       },
       {},
       U::Definition,
       Kind::Material},
      {"*SECTION",
       1,
       [](Context& c, const deck::Keyword& k, const KeywordOptions&) {
         readUnsupportedDefinition(c, k, Kind::Section);
       },
       {},
       U::Definition,
       Kind::Section},
      {"*SECTION_SOLID", 1, readSectionSolid, {"TITLE"}, U::Definition, Kind::Section},
      {"*SECTION_SPH", 1, readSectionSph, {"TITLE"}, U::Definition, Kind::Section},
      {"*SECTION_SHELL", 1, readSectionShell, {"TITLE"}, U::Definition, Kind::Section},
      {"*SECTION_TSHELL", 1, readSectionTShell, {"TITLE"}, U::Definition, Kind::Section},
      {"*SECTION_BEAM", 1, readSectionBeam, {"TITLE"}, U::Definition, Kind::Section},
      {"*SECTION_DISCRETE", 1, readSectionDiscrete, {"TITLE"}, U::Definition, Kind::Section},
      {"*HOURGLASS", 1, readHourglass, {"TITLE"}, U::Definition, Kind::Hourglass},
      {"*EOS",
       1,
       [](Context& c, const deck::Keyword& k, const KeywordOptions&) {
         readUnsupportedDefinition(c, k, Kind::Eos);
       },
       {},
       U::Definition,
       Kind::Eos},
      {"*EOS_LINEAR_POLYNOMIAL", 1, readEosLinearPolynomial, {"TITLE"}, U::Definition, Kind::Eos},
      {"*EOS_001", 1, readEosLinearPolynomial, {"TITLE"}, U::Definition, Kind::Eos},
      {"*EOS_GRUNEISEN", 1, readEosGruneisen, {"TITLE"}, U::Definition, Kind::Eos},
      {"*EOS_004", 1, readEosGruneisen, {"TITLE"}, U::Definition, Kind::Eos},
      {"*EOS_TABULATED_COMPACTION",
       1,
       readEosTabulatedCompaction,
       {"TITLE"},
       U::Definition,
       Kind::Eos},
      {"*EOS_008", 1, readEosTabulatedCompaction, {"TITLE"}, U::Definition, Kind::Eos},
      {"*EOS_TABULATED", 1, readEosTabulated, {"TITLE"}, U::Definition, Kind::Eos},
      {"*EOS_009", 1, readEosTabulated, {"TITLE"}, U::Definition, Kind::Eos},
      {"*PART", 2, readParts, {"INERTIA", "CONTACT", "COMPOSITE"}, U::Reject},
      {"*MAT_ADD_EROSION", 2, readAddErosion, {"TITLE"}, U::Reject},
      {"*ELEMENT_SOLID", 3, readSolids, {}, U::Reject},
      {"*ELEMENT_SPH", 3, readElementSph, {}, U::Reject},
      {"*ELEMENT_SHELL", 3, readShells, {"THICKNESS"}, U::Reject},
      {"*ELEMENT_TSHELL", 3, readTShells, {}, U::Reject},
      {"*ELEMENT_BEAM", 3, readBeams, {"THICKNESS"}, U::Reject},
      {"*ELEMENT_DISCRETE", 3, readDiscretes, {}, U::Reject},
      {"*SET_NODE",
       4,
       readNodeSetList,
       {"LIST", "TITLE", "GENERATE", "COLLECT"},
       U::Definition,
       Kind::NodeSet},
      {"*SET_PART",
       4,
       readPartSetList,
       {"LIST", "TITLE", "GENERATE", "COLLECT"},
       U::Definition,
       Kind::PartSet},
      {"*SET_SEGMENT", 4, readSegmentSet, {"TITLE"}, U::Definition, Kind::SegmentSet},
      {"*SET_SOLID",
       4,
       readElementSetList,
       {"LIST", "TITLE", "GENERATE", "COLLECT"},
       U::Definition,
       Kind::SolidSet},
      {"*SET_SHELL",
       4,
       readElementSetList,
       {"LIST", "TITLE", "GENERATE", "COLLECT"},
       U::Definition,
       Kind::ShellSet},
      {"*SET_BEAM",
       4,
       readElementSetList,
       {"LIST", "TITLE", "GENERATE", "COLLECT"},
       U::Definition,
       Kind::BeamSet},
      {"*SET_DISCRETE",
       4,
       readElementSetList,
       {"LIST", "TITLE", "GENERATE", "COLLECT"},
       U::Definition,
       Kind::DiscreteSet},
      {"*SET_TSHELL",
       4,
       readElementSetList,
       {"LIST", "TITLE", "GENERATE", "COLLECT"},
       U::Definition,
       Kind::TShellSet},
      // After the lists they add up (phase 4); an _ADD of an _ADD set follows it in the deck.
      {"*SET_SOLID_ADD", 5, readElementSetAdd, {"TITLE"}, U::Definition, Kind::SolidSet},
      {"*SET_SHELL_ADD", 5, readElementSetAdd, {"TITLE"}, U::Definition, Kind::ShellSet},
      {"*SET_BEAM_ADD", 5, readElementSetAdd, {"TITLE"}, U::Definition, Kind::BeamSet},
      {"*SET_DISCRETE_ADD", 5, readElementSetAdd, {"TITLE"}, U::Definition, Kind::DiscreteSet},
      {"*SET_TSHELL_ADD", 5, readElementSetAdd, {"TITLE"}, U::Definition, Kind::TShellSet},
      {"*SET_NODE_GENERAL", 5, readNodeSetGeneral, {"TITLE"}, U::Definition, Kind::NodeSet},
      {"*BOUNDARY_SPC", 6, readSpc, {"NODE", "SET", "ID"}, U::Reject},
      // _NODES: the spelling of LS-DYNA's older examples (the 1997 Frazer-Nash test deck) for
      // _NODE, with the same card (NID DOF VAD LCID SF VID DEATH BIRTH).
      {"*BOUNDARY_PRESCRIBED_MOTION",
       6,
       readPrescribedMotion,
       {"NODE", "NODES", "SET", "ID"},
       U::Reject},
      {"*INITIAL_VELOCITY", 6, readInitialVelocity, {}, U::Reject},
      {"*INITIAL_VELOCITY_NODE", 6, readInitialVelocityNode, {}, U::Reject},
      {"*INITIAL_VELOCITY_GENERATION", 6, readInitialVelocityGeneration, {}, U::Reject},
      {"*INITIAL_AXIAL_FORCE_BEAM", 6, readInitialAxialForceBeam, {}, U::Reject},
      {"*LOAD_NODE", 6, readLoadNode, {"POINT", "SET"}, U::Reject},
      {"*ELEMENT_MASS", 6, readElementMass, {}, U::Reject},
      {"*LOAD_SEGMENT", 6, readLoadSegment, {}, U::Reject},
      {"*LOAD_SEGMENT_SET", 6, readLoadSegmentSet, {}, U::Reject},
      // The charges before the segments that name them (BID).
      {"*LOAD_BLAST_ENHANCED", 5, readLoadBlastEnhanced, {}, U::Reject},
      {"*LOAD_BLAST_SEGMENT_SET", 6, readLoadBlastSegmentSet, {}, U::Reject},
      {"*LOAD_BODY", 6, readLoadBody, {"X", "Y", "Z"}, U::Reject},
      // "#": a number after the name (*AIRBAG_SIMPLE_PRESSURE_VOLUME_1) is the bag's id.
      {"*AIRBAG_SIMPLE_PRESSURE_VOLUME", 6, readAirbagSimplePressureVolume, {"ID", "#"}, U::Reject},
      {"*RIGIDWALL_PLANAR", 6, readRigidWallPlanar, {"ID", "FINITE", "MOVING"}, U::Reject},
      {"*RIGIDWALL_GEOMETRIC",
       6,
       readRigidWallGeometric,
       {"FLAT", "PRISM", "CYLINDER", "SPHERE", "ID", "MOTION", "DISPLAY"},
       U::Reject},
      {"*BOUNDARY_PRESCRIBED_MOTION_RIGID", 6, readPrescribedMotionRigid, {"ID"}, U::Reject},
      {"*CONSTRAINED_RIGID_BODIES", 6, readRigidBodies, {}, U::Reject},
      {"*CONSTRAINED_EXTRA_NODES", 6, readExtraNodes, {"NODE", "SET"}, U::Reject},
      {"*CONSTRAINED_NODAL_RIGID_BODY", 6, readNodalRigidBody, {"SPC", "TITLE"}, U::Reject},
      {"*CONSTRAINED_SPOTWELD", 6, readSpotweld, {"ID"}, U::Reject},
      {"*CONSTRAINED_GENERALIZED_WELD", 6, readGeneralizedWeld, {"SPOT", "ID"}, U::Reject},
      {"*CONSTRAINED_NODE_SET", 6, readConstrainedNodeSet, {"ID"}, U::Reject},
      {"*CONSTRAINED_JOINT",
       6,
       readJoint,
       {"SPHERICAL", "REVOLUTE", "CYLINDRICAL", "TRANSLATIONAL", "ID"},
       U::Reject},
      {"*CONSTRAINED_JOINT_STIFFNESS", 6, readJointStiffness, {"GENERALIZED"}, U::Reject},
      {"*LOAD_RIGID_BODY", 6, readLoadRigidBody, {}, U::Reject},
      {"*CONTACT", 6, readContact, {"AUTOMATIC", "NODES",      "TO",     "SURFACE", "SINGLE",
                                    "GENERAL",   "TIED",       "OFFSET", "ID",      "TITLE",
                                    "MPP",       "SHELL",      "EDGE",   "BEAM",    "SPOTWELD",
                                    "TIEBREAK",  "ONE",        "WAY",    "FORCE",   "TRANSDUCER",
                                    "PENALTY",   "CONSTRAINT", "ERODING"}},
      {"*CONTROL_TERMINATION", 6, readControlTermination, {}},
      {"*CONTROL_TIMESTEP", 6, readControlTimestep, {}},
      {"*CONTROL_HOURGLASS", 6, readControlHourglass, {}},
      {"*CONTROL_RIGID", 6, readControlRigid, {}},
      {"*CONTROL_BULK_VISCOSITY", 6, readControlBulkViscosity, {}},
      {"*CONTROL_ENERGY", 6, readControlEnergy, {}},
      {"*CONTROL_SOLID", 6, readControlSolid, {}},
      {"*CONTROL_SPH", 6, readControlSph, {}},
      {"*CONTROL_ACCURACY", 6, readIgnoredControl, {}},
      {"*CONTROL_OUTPUT", 6, readIgnoredControl, {}},
      {"*CONTROL_SHELL", 6, readControlShell, {}},
      {"*CONTROL_CONTACT", 5, readControlContact, {}},
      {"*CONTROL_SOLUTION", 6, readControlSolution, {}},
      {"*CONTROL_UNITS", 6, readControlUnits, {}},
      {"*CONTROL_IMPLICIT_GENERAL", 6, readControlImplicitGeneral, {}},
      {"*CONTROL_DYNAMIC_RELAXATION", 6, readControlDynamicRelaxation, {}},
      {"*CONTROL_DAMPING", 6, readControlDynamicRelaxation, {}},
      {"*DAMPING_GLOBAL", 6, readDampingGlobal, {}},
      {"*DAMPING_PART_MASS", 6, readDampingPartMass, {"SET"}, U::Reject},
      {"*DAMPING_PART_STIFFNESS", 6, readDampingPartStiffness, {"SET"}, U::Reject},
      {"*DATABASE_EXTENT_BINARY", 6, readDatabaseExtentBinary, {}},
      {"*DATABASE_GLSTAT", 6, readDatabaseAscii, {}},
      {"*DATABASE_MATSUM", 6, readDatabaseAscii, {}},
      {"*DATABASE_NODOUT", 6, readDatabaseAscii, {}},
      {"*DATABASE_RWFORC", 6, readDatabaseAscii, {}},
      {"*DATABASE_RCFORC", 6, readDatabaseAscii, {}},
      {"*DATABASE_SLEOUT", 6, readDatabaseAscii, {}},
      {"*DATABASE_SECFORC", 6, readDatabaseAscii, {}},
      {"*DATABASE_SPCFORC", 6, readDatabaseAscii, {}},
      {"*DATABASE_BNDOUT", 6, readDatabaseAscii, {}},
      {"*DATABASE_RBDOUT", 6, readDatabaseAscii, {}},
      {"*DATABASE_DEFORC", 6, readDatabaseAscii, {}},
      {"*DATABASE_JNTFORC", 6, readDatabaseAscii, {}},
      {"*DATABASE_CROSS_SECTION_PLANE", 6, readCrossSectionPlane, {"ID"}},
      {"*DATABASE_CROSS_SECTION_SET", 6, readCrossSectionSet, {"ID"}},
      {"*DATABASE_BINARY_D3PLOT", 6, readDatabaseD3plot, {}},
      {"*DATABASE_BINARY_D3DUMP", 6, readDatabaseD3dump, {}},
      {"*DATABASE_HISTORY_NODE", 6, readHistoryNode, {"ID"}},
      {"*DATABASE_HISTORY_NODE_SET", 6, readHistoryNodeSet, {}},
      {"*DATABASE_HISTORY_SOLID", 6, readHistoryElement, {"ID"}},
      {"*DATABASE_HISTORY_SHELL", 6, readHistoryElement, {"ID"}},
      {"*DATABASE_HISTORY_BEAM", 6, readHistoryElement, {"ID"}},
      {"*DATABASE_HISTORY_SOLID_SET", 6, readHistoryElementSet, {}},
      {"*DATABASE_HISTORY_SHELL_SET", 6, readHistoryElementSet, {}},
      {"*DATABASE_HISTORY_BEAM_SET", 6, readHistoryElementSet, {}},
      {"*DATABASE_HISTORY_TSHELL", 6, readHistoryElement, {"ID"}},
      {"*DATABASE_HISTORY_TSHELL_SET", 6, readHistoryElementSet, {}},
      {"*DATABASE_ELOUT", 6, readDatabaseAscii, {}},
  });
  return m;
}
constexpr int kPhases = 7;

// Why a keyword without a meaning is not acted on, and whether skipping it changes the
// answer (first matching prefix wins). What is not listed is "not supported" and changes the
// answer: an element, material, load, constraint or contact left out gives another problem,
// so a run refuses it (unless told to ignore it) while `check` lists it.
struct Unsupported {
  std::string_view reason;
  bool changes_answer;
};
Unsupported unsupportedReason(std::string_view name) {
  static const std::vector<std::pair<std::string_view, Unsupported>> reasons = {
      {"*CONTROL_IMPLICIT", {"implicit controls: not used by an explicit analysis", false}},
      {"*CONTROL_PARALLEL", {"ignored: MPP/SMP option", false}},
      {"*CONTROL_MPP", {"ignored: MPP/SMP option", false}},
      {"*CONTROL_CPU", {"ignored: MPP/SMP option", false}},
      {"*CONTROL_STRUCTURED", {"ignored: structured-file output", false}},
      {"*CONTROL_DEBUG", {"ignored: diagnostic output", false}},
      {"*CONTROL_REPORT", {"ignored: diagnostic output", false}},
      {"*CONTROL_THERMAL", {"thermal analysis not supported", true}},
      {"*MAT_THERMAL", {"thermal analysis not supported", true}},
      {"*BOUNDARY_TEMPERATURE", {"thermal analysis not supported", true}},
      {"*BOUNDARY_CONVECTION", {"thermal analysis not supported", true}},
      {"*BOUNDARY_FLUX", {"thermal analysis not supported", true}},
      {"*BOUNDARY_RADIATION", {"thermal analysis not supported", true}},
      {"*BOUNDARY_THERMAL", {"thermal analysis not supported", true}},
      {"*INITIAL_TEMPERATURE", {"thermal analysis not supported", true}},
      {"*LOAD_THERMAL", {"thermal analysis not supported", true}},
      {"*DUALCESE", {"compressible CFD (DUALCESE) is out of scope", true}},
      {"*MAT_USER_DEFINED", {"user material subroutines are out of scope", true}},
      {"*USER_LOADING", {"user loading subroutines are out of scope", true}},
      // Output requests whose files Crumple does not write (yet): the run is unaffected.
      {"*DATABASE_", {"output not written yet", false}},
      {"*ELEMENT_SEATBELT_ACCELEROMETER", {"output not written yet (accelerometer)", false}},
      {"*ELEMENT_PLOTEL", {"plotting elements carry no force: not drawn yet", false}},
      {"*SENSOR_DEFINE", {"sensors act only through *SENSOR_CONTROL", false}},
      {"*COMMENT", {"comment", false}},
      {"*CASE", {"load cases: Crumple runs the deck without them", false}},
      // Definitions act only through what refers to them; a reference to one is an error.
      {"*DEFINE_", {"definition not supported (an error where it is used)", false}},
      {"*SET_", {"set type not supported (an error where it is used)", false}},
      {"*INTEGRATION_", {"integration rule not supported (an error where it is used)", false}},
  };
  for (const auto& [prefix, reason] : reasons)
    if (name.substr(0, prefix.size()) == prefix) return reason;
  return {"not supported", true};
}

void reportUnknown(Context& ctx, const deck::Keyword& kw) {
  const Unsupported u = unsupportedReason(kw.name);
  ctx.reportUnsupported(kw, u.reason, u.changes_answer);
}

// An option word of digits only (a number written after a keyword's name).
bool isNumber(std::string_view w) {
  return !w.empty() && w.size() < 10 &&
         std::all_of(w.begin(), w.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
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

int64_t definedId(const Context& ctx, const deck::Keyword& kw) {
  std::string_view name = kw.name;
  const bool title = name.size() > 6 && name.substr(name.size() - 6) == "_TITLE";
  std::size_t line = title ? 1 : 0;
  while (line < kw.lines.size() && deck::trim(kw.lines[line].text).empty()) ++line;
  if (line >= kw.lines.size()) return 0;
  // A keyword of that one line (not a copy of all the keyword's lines).
  deck::Keyword one;
  one.name = kw.name;
  one.format = kw.format;
  one.file = kw.file;
  one.line = kw.line;
  one.lines = {kw.lines[line]};
  try {
    deck::CardCursor cur(one, ctx.deck);
    return cur.read(deck::keywordSpec("*UNSUPPORTED_DEFINITION").card("card 1")).integer("ID");
  } catch (const util::InputError&) {
    return 0;
  }
}

void readUnsupportedDefinition(Context& ctx, const deck::Keyword& kw, Kind kind) {
  std::string_view name = kw.name;
  // *MAT_ADD_EROSION, *MAT_THERMAL_* and the like add to a material rather than define one.
  const bool defines = !(name.rfind("*MAT_ADD_", 0) == 0 || name.rfind("*MAT_THERMAL", 0) == 0 ||
                         name.rfind("*MAT_NONLOCAL", 0) == 0);
  const Unsupported u = unsupportedReason(name);
  // A definition acts only through what uses it (a use is refused); an addition to one
  // (erosion, thermal properties) changes the material it adds to.
  ctx.reportUnsupported(
      kw, defines ? "definition not supported (an error where it is used)" : u.reason, !defines);
  if (!defines) return;
  if (const int64_t id = definedId(ctx, kw); id != 0)
    ctx.defineUnsupported(kind, id, kw.name, ctx.deck.loc(kw));
}

// A material, section or hourglass definition with an input error: LS-DYNA reads a deck whose
// unused definitions are incomplete, so the error is kept for the parts that use it (an
// error on use) and noted. Without an id nothing can use it: the error stands.
void readDefinition(Context& ctx, const deck::Keyword& kw, Handler handler,
                    const KeywordOptions& opts, Kind kind) {
  const int64_t id = definedId(ctx, kw);
  // A second definition of an id is an error whether or not anything uses it.
  const bool redefined = id != 0 && ctx.isDefined(kind, id);
  try {
    handler(ctx, kw, opts);
  } catch (const util::FormatError&) {
    throw;  // unreadable text is an error wherever it is
  } catch (const util::InputError& e) {
    if (id == 0 || redefined) throw;
    ctx.defineBroken(kind, id, e.what());
    ctx.ignore(kw.name, "",
               std::string(kindName(kind)) + " " + std::to_string(id) +
                   " cannot be used (an error only if an element's part uses it): " + e.what(),
               ctx.deck.loc(kw));
  }
}

void finishPhase(Context& ctx, int phase) {
  switch (phase) {
    case 0:
      finishNodes(ctx);
      finishCurves(ctx);
      finishTables(ctx);
      break;
    case 1:
      finishDefinitions(ctx);
      break;
    case 2:
      finishParts(ctx);
      break;
    case 3:
      finishSolids(ctx);
      finishSph(ctx);
      break;
    default:
      break;
  }
}

// Parts that could not be run but that no element uses: said, not refused (LS-DYNA reads
// such decks, e.g. a part kept only to label a charge position).
void noteUnusedPartProblems(Context& ctx) {
  const Model& m = ctx.model;
  std::vector<char> used(m.parts.size(), 0);
  for (std::size_t g = 0; g < m.numElements(); ++g)
    used[static_cast<std::size_t>(m.elementPart(g))] = 1;
  for (std::size_t i = 0; i < ctx.part_problem.size() && i < m.parts.size(); ++i)
    if (!ctx.part_problem[i].empty() && !used[i])
      ctx.ignore("*PART", "PID", ctx.part_problem[i].message + "; no element uses the part",
                 m.parts[i].where);
}

}  // namespace build

Model readModel(const std::filesystem::path& path) {
  return readModel(path, ReadOptions{});
}

Model readModel(const std::filesystem::path& path, const ReadOptions& options) {
  return buildModel(deck::readDeck(path, deck::ReadDeckOptions{options.collect_errors}), path,
                    options);
}

Model buildModel(const deck::Deck& deck, const std::filesystem::path& path,
                 const ReadOptions& options) {
  using namespace build;
  Model model;
  model.deck_path = path.string();
  Context ctx(deck, model, options);
  for (const auto& note : deck.notes) ctx.ignore(note.keyword, note.field, note.reason, note.where);
  for (const auto& error : deck.errors) ctx.recordError(error);

  // Match every keyword first, so that unsupported ones are listed in deck order.
  std::vector<Planned> plan;
  for (const auto& kw : deck.keywords) {
    if (!kw.case_block.empty()) {
      ctx.reportUnsupported(
          kw,
          "inside *CASE block (" + kw.case_block + "): Crumple runs the deck without load cases",
          false);
      continue;
    }
    KeywordOptions opts;
    const Meaning* m = match(kw.name, opts);
    if (!m) {
      reportUnknown(ctx, kw);
      continue;
    }
    // A material, section or hourglass definition without its cards is what a file cut short
    // leaves (the handlers read a list of records, and would read none without a word).
    if (m->phase == 1 && std::all_of(kw.lines.begin(), kw.lines.end(),
                                     [](const auto& l) { return deck::trim(l.text).empty(); })) {
      ctx.fail(deck.loc(kw).str() + ": " + kw.name + " has no data cards (is the file cut short?)");
      continue;
    }
    std::string unknown;
    for (const auto& w : opts.words)
      if (std::find(m->options.begin(), m->options.end(), w) == m->options.end() &&
          !(isNumber(w) &&
            std::find(m->options.begin(), m->options.end(), "#") != m->options.end()))
        unknown += (unknown.empty() ? "_" : ", _") + w;
    if (!unknown.empty()) {
      switch (m->unknown) {
        case UnknownOption::Report:
          reportUnknown(ctx, kw);
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
      if (p.meaning->phase != phase) continue;
      ctx.attempt([&] {
        if (p.unsupported_definition)
          readUnsupportedDefinition(ctx, *p.keyword, p.meaning->kind);
        else if (phase == 1)
          readDefinition(ctx, *p.keyword, p.meaning->handler, p.options, p.meaning->kind);
        else
          p.meaning->handler(ctx, *p.keyword, p.options);
      });
    }
    ctx.attempt([&] { finishPhase(ctx, phase); });
  }
  ctx.attempt([&] { finishRigid(ctx); });
  ctx.attempt([&] { finishConditions(ctx); });
  ctx.attempt([&] { finishDamping(ctx); });
  ctx.attempt([&] { finishControls(ctx); });
  ctx.attempt([&] { finishPlanar(ctx); });
  ctx.attempt([&] { finishPlaneSph(ctx); });
  inferUnits(ctx.model);
  ctx.attempt([&] { noteDegenerateSolids(ctx); });
  ctx.attempt([&] { finishQuadraticTets(ctx); });
  if (model.nodes.size() == 0)
    ctx.fail(path.string() + ": the deck defines no nodes (*NODE)");
  else if (model.numElements() == 0 && model.sph.size() == 0 && !options.allow_unsupported)
    ctx.fail(path.string() +
             ": the deck defines no elements Crumple can run (*ELEMENT_SOLID, _SHELL, _BEAM, "
             "_DISCRETE or _SPH)");
  model.finalize();
  noteUnusedPartProblems(ctx);
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
