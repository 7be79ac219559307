// Shared state of the Deck -> Model build (build.cpp drives it; build_*.cpp give keywords
// their meaning). Internal to src/model.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "deck/card.hpp"
#include "deck/deck.hpp"
#include "model/build.hpp"
#include "model/model.hpp"
#include "util/error.hpp"

namespace crumple::model::build {

// The options of a keyword after its base name: *SET_NODE_LIST_GENERATE_TITLE on the base
// *SET_NODE gives {LIST, GENERATE, TITLE}.
struct KeywordOptions {
  std::set<std::string, std::less<>> words;
  bool has(std::string_view w) const { return words.count(w) > 0; }
};

// Entities that other keywords refer to by id.
enum class Kind : uint8_t {
  Material,
  Section,
  Hourglass,
  Curve,
  NodeSet,
  PartSet,
  SegmentSet,
  Box,
  CoordinateSystem,
  Vector,
  Eos,
  SolidSet,  // *SET_SOLID, *SET_SHELL, *SET_BEAM, *SET_DISCRETE: one id space per family
  ShellSet,
  BeamSet,
  DiscreteSet,
  TShellSet,  // *SET_TSHELL: thick shells (kept with the solids), an id space of its own
};
// The set kind of an element family.
inline Kind elementSetKind(Family f) {
  return static_cast<Kind>(static_cast<int>(Kind::SolidSet) + static_cast<int>(f));
}
std::string_view kindName(Kind kind);  // "material", "node set", ...

// *DEFINE_BOX
struct Box {
  Vec3 lo{}, hi{};
  bool contains(const Vec3& x) const {
    for (int i = 0; i < 3; ++i)
      if (x[i] < lo[i] || x[i] > hi[i]) return false;
    return true;
  }
};

// *DEFINE_COORDINATE_SYSTEM: orthonormal local axes (rows) in global components.
struct Frame {
  std::array<Vec3, 3> axis{};
};

struct RigidInput;  // build_rigid.cpp

// Thrown (only with ReadOptions::allow_unsupported, after the reason is reported) to skip the
// rest of a record that depends on something Crumple does not support.
struct SkipRecord {};

class Context {
 public:
  Context(const deck::Deck& d, Model& m, ReadOptions o) : deck(d), model(m), options(o) {}

  const deck::Deck& deck;
  Model& model;
  const ReadOptions options;

  // ---- reporting ------------------------------------------------------------------------
  // A keyword not acted on: counted once per keyword name and reason. `changes_answer`: see
  // UnsupportedKeyword; `feature` (default: the keyword) names what Crumple lacks.
  void reportUnsupported(const deck::Keyword& kw, std::string_view reason,
                         bool changes_answer = true, std::string feature = {});
  // Something the solution needs but Crumple does not support: an InputError at the field,
  // or with ReadOptions::allow_unsupported an entry in Model::unsupported.
  // `feature` names what is lacking for the compatibility matrix (default: keyword and field).
  void reject(const deck::Card& card, std::string_view field, const std::string& message,
              std::string feature = {});
  // A keyword option of that kind (no field to name).
  void rejectKeyword(const deck::Keyword& kw, const std::string& message);
  // Read but not honoured.
  void ignore(std::string keyword, std::string_view field, std::string reason,
              util::SourceLoc where);
  // Moves the cursor's unused non-default values into Model::ignored.
  void collect(deck::CardCursor& cursor);
  // Runs `step`; with ReadOptions::collect_errors an InputError it throws is recorded in
  // Model::errors and false returned, so that reading goes on with the next record or
  // keyword. Without it the error propagates.
  template <class F>
  bool attempt(F&& step) {
    if (!options.collect_errors) {
      step();
      return true;
    }
    try {
      step();
      return true;
    } catch (const util::InputError& e) {
      recordError(e.what());
      return false;
    } catch (const SkipRecord&) {
      return false;  // already reported as unsupported
    }
  }
  void recordError(std::string message);
  // An input error found after reading (a duplicate id): thrown, or with collect_errors
  // recorded, after which the caller skips the offending item.
  void fail(std::string message);

  // ---- definitions and references -----------------------------------------------------------
  // Records that `id` of `kind` is defined by the card's field; a second definition is an
  // InputError naming the first.
  void define(Kind kind, int64_t id, const deck::Card& card, std::string_view field);
  // The same for a set keyword with _COLLECT (Keyword Manual, *SET: "multiple sets with the
  // same ID are merged"): a repeat is allowed when every definition of the id has _COLLECT.
  void defineCollected(Kind kind, int64_t id, const deck::Card& card, std::string_view field);
  // Records that `id` of `kind` is defined by a keyword Crumple does not support, so that a
  // reference to it can say so.
  void defineUnsupported(Kind kind, int64_t id, std::string what, util::SourceLoc where);
  // "*MAT_RIGID (material 2 at ball.k:92)" for an id defined by an unsupported keyword.
  std::string unsupportedDefinition(Kind kind, int64_t id) const;
  // "*MAT_JOHNSON_COOK", "*SECTION_SOLID ELFORM=10": the unsupported definition's keyword
  // without _TITLE, for the compatibility matrix.
  std::string unsupportedFeature(Kind kind, int64_t id) const;
  // Records that `id` of `kind` was read but cannot be used (a set naming a node that does
  // not exist): an error only if something refers to it.
  void defineBroken(Kind kind, int64_t id, std::string message);
  // The message for a reference to an id that has no supported definition: "material 7 is
  // not defined" or "curve 5 is defined by *DEFINE_TABLE (t.k:9), which is not supported".
  std::string undefinedMessage(Kind kind, int64_t id) const;
  // The error that made `id` unusable (defineBroken), or empty.
  std::string brokenMessage(Kind kind, int64_t id) const;
  bool isUnsupported(Kind kind, int64_t id) const;
  bool isDefined(Kind kind, int64_t id) const;  // by a supported or an unsupported keyword

  // Model index of the node (InputError at the field if it is not defined).
  int32_t node(const deck::Card& card, std::string_view field, int64_t id) const;
  int32_t part(const deck::Card& card, std::string_view field, int64_t id) const;
  // Curve index; `id` 0 is an error ("a curve is required").
  // A curve Crumple cannot read is refused (reject): with allow_unsupported the record that
  // uses it is skipped (SkipRecord).
  int32_t curve(const deck::Card& card, std::string_view field, int64_t id);
  const std::vector<int32_t>& nodeSet(const deck::Card& card, std::string_view field,
                                      int64_t id) const;
  const std::vector<int32_t>& partSet(const deck::Card& card, std::string_view field,
                                      int64_t id) const;
  // Members (indices within family f) of the element set `id` of that family.
  // *SET_TSHELL id -> its thick shells as solid-family indices.
  const std::vector<int32_t>& tshellSet(const deck::Card& card, std::string_view field,
                                        int64_t id) const;
  const std::vector<int32_t>& elementSet(Family f, const deck::Card& card, std::string_view field,
                                         int64_t id) const;
  const std::vector<std::array<int32_t, 4>>& segmentSet(const deck::Card& card,
                                                        std::string_view field, int64_t id) const;
  const Box& box(const deck::Card& card, std::string_view field, int64_t id) const;
  const Frame& frame(const deck::Card& card, std::string_view field, int64_t id) const;
  // Nodes of the elements of a part (every family), ascending.
  const std::vector<int32_t>& partNodes(int32_t part);

  // ---- build state -------------------------------------------------------------------------
  std::unordered_map<int64_t, int32_t> material_index, section_index, hourglass_index, eos_index;
  std::map<int64_t, Box> boxes;
  std::map<int64_t, Frame> frames;
  // *INTEGRATION_SHELL rules by IRID: points and weights (SectionShell::zeta, weight).
  struct ShellRule {
    std::vector<double> zeta, weight;
  };
  std::map<int64_t, ShellRule> shell_rules;
  std::map<int64_t, Vec3> vectors;  // *DEFINE_VECTOR: unit direction tail -> head
  // Per part index: nothing, or why an element of the part cannot be run. A part no element
  // uses may be incomplete, as LS-DYNA allows: the problem is an error only on use.
  struct PartProblem {
    // With a feature: "part 2 uses *MAT_JOHNSON_COOK (material 2 at b.k:92), which ...";
    // without: the input error where it is written, "b.k:7: *PART card 2 field 3 (MID): ...".
    std::string message;
    std::string feature;  // "*MAT_JOHNSON_COOK" when Crumple lacks it; empty for an input error
    bool empty() const { return message.empty(); }
  };
  std::vector<PartProblem> part_problem;
  // An element card of `part` (field PID): refuses it when the part cannot be run.
  void checkPartUsable(const deck::Card& c, int32_t part);
  // Raw inputs collected before sorting.
  struct NodeInput {
    int64_t id;
    Vec3 x;
    int tc, rc;
    int32_t file, line;
  };
  std::vector<NodeInput> node_input;
  // Elements as read, before sorting by id. `real` and `aux` carry what a family adds:
  // shell corner thicknesses, the beam orientation node, discrete scale and offset.
  template <int N>
  struct ElementInput {
    int64_t id;
    int32_t part;
    std::array<int32_t, N> nodes;
    int32_t file, line;
    std::array<double, 4> real{};
    int32_t aux = kNone;
    int32_t section = kNone;  // *ELEMENT_BEAM_THICKNESS: the element's own beam section
    // *ELEMENT_SOLID of an ELFORM 16 section: the mid-side nodes N5..N10 (Solids::mid); else
    // mid[0] == kNone.
    std::array<int32_t, 6> mid{kNone, kNone, kNone, kNone, kNone, kNone};
  };
  std::vector<ElementInput<8>> solid_input;
  std::vector<ElementInput<4>> shell_input;
  std::vector<ElementInput<2>> beam_input, discrete_input;
  std::unordered_map<int64_t, SectionKind> section_kind;  // by section id
  std::map<int32_t, DofMask> spc_masks;
  int64_t d3plot_npltc = 0;
  int64_t erode_flag = 0;  // *CONTROL_TIMESTEP ERODE
  // Where IHQ 8 was given: *CONTROL_HOURGLASS, and *HOURGLASS by its Model::hourglass index
  // (refused for parts that need hourglass control, finishControls).
  const deck::Keyword* ihq8_control = nullptr;
  std::map<std::size_t, const deck::Keyword*> ihq8_hourglass;
  int rigid_wall_count = 0;
  // What the rigid-body keywords collected (build_rigid.cpp), made into Model::rigid last.
  std::shared_ptr<RigidInput> rigid_input;

 private:
  std::map<std::pair<Kind, int64_t>, util::SourceLoc> defined_;
  std::set<std::pair<Kind, int64_t>> collected_;  // defined by _COLLECT keywords only
  std::map<std::pair<Kind, int64_t>, std::pair<std::string, util::SourceLoc>> unsupported_;
  std::map<std::pair<std::string, std::string>, std::size_t> unsupported_row_;
  std::map<std::pair<Kind, int64_t>, std::string> broken_;
  std::unordered_map<int32_t, std::vector<int32_t>> part_nodes_;
  std::set<std::string, std::less<>> errors_seen_;
};

// ---- keyword meanings (one function per keyword family) ------------------------------------
using Handler = void (*)(Context&, const deck::Keyword&, const KeywordOptions&);

// build_mesh.cpp
void readNodes(Context&, const deck::Keyword&, const KeywordOptions&);
void readSolids(Context&, const deck::Keyword&, const KeywordOptions&);
void readParts(Context&, const deck::Keyword&, const KeywordOptions&);
void readSectionSolid(Context&, const deck::Keyword&, const KeywordOptions&);
void readHourglass(Context&, const deck::Keyword&, const KeywordOptions&);
// Definitions Crumple does not support (*MAT_RIGID, *SECTION_SHELL, *DEFINE_TABLE, ...):
// reported, and their id remembered so that a use of it can say what it is.
void readUnsupportedDefinition(Context&, const deck::Keyword&, Kind kind);
// The id a definition keyword defines: the first field of its first card after the title
// line of _TITLE; 0 when there is none or it is not a number (nothing can refer to it).
int64_t definedId(const Context& ctx, const deck::Keyword& kw);
void finishNodes(Context&);
void finishDefinitions(Context&);
void finishParts(Context&);
void finishSolids(Context&);  // sorts and checks every element family

// build_structures.cpp: shells, beams, discrete elements, their sections and materials
void readShells(Context&, const deck::Keyword&, const KeywordOptions&);
void readBeams(Context&, const deck::Keyword&, const KeywordOptions&);
void readDiscretes(Context&, const deck::Keyword&, const KeywordOptions&);
void readSectionShell(Context&, const deck::Keyword&, const KeywordOptions&);
void readSectionTShell(Context&, const deck::Keyword&, const KeywordOptions&);
void readTShells(Context&, const deck::Keyword&, const KeywordOptions&);
void readSectionBeam(Context&, const deck::Keyword&, const KeywordOptions&);
void readSectionDiscrete(Context&, const deck::Keyword&, const KeywordOptions&);

void readControlShell(Context&, const deck::Keyword&, const KeywordOptions&);

// build_sph.cpp: SPH particles, their sections and controls
void readSectionSph(Context&, const deck::Keyword&, const KeywordOptions&);
void readElementSph(Context&, const deck::Keyword&, const KeywordOptions&);
void readControlSph(Context&, const deck::Keyword&, const KeywordOptions&);
// After the elements: the particles sorted by node, one per node, at nodes of no element.
void finishSph(Context&);
// After every keyword (*CONTROL_SPH is read late): the checks and constraints of plane SPH.
void finishPlaneSph(Context&);
// *CONTROL_SOLID: ESORT sorts tetrahedra and pentahedra written as hexahedra into ELFORM 10
// and 15; the other fields are reported when set.
void readControlSolid(Context&, const deck::Keyword&, const KeywordOptions&);
// After every keyword: the degenerate solids that run as hexahedra, noted per part.
void noteDegenerateSolids(Context&);
// Pressure, airbag and blast segments on the faces of 10-node tetrahedra (ELFORM 16) become
// the face's four flat triangles (quadraticFaceTriangles); refuses what needs the element
// records of 10-node tetrahedra and Crumple does not give them yet: cross sections and element
// histories (build_mesh.cpp).
void finishQuadraticTets(Context&);
// The four flat triangles (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca) that the
// mid-side nodes ab, bc, ca of 10-node tetrahedron e cut its face (a, b, c) into, each turned as
// the face and written as a 3-node segment (N4 = N3); build_mesh.cpp.
std::array<std::array<int32_t, 4>, 4> quadraticFaceTriangles(const Model& m, std::size_t e,
                                                             int32_t a, int32_t b, int32_t c);
// After every keyword (build_planar.cpp): the checks of 2D solids (*SECTION_SHELL ELFORM 13,
// 15): their laws and hourglass types, a model of 2D solids only, radii x >= 0; their nodes'
// z and rotational freedoms are held by SPCs.
void finishPlanar(Context&);

// build_materials.cpp: the reader of every law of materials/registry.hpp, by keyword name
struct LawReader {
  std::string_view keyword;
  Handler read;
};
const std::vector<LawReader>& lawReaders();

// build_eos.cpp: *EOS_LINEAR_POLYNOMIAL, *EOS_GRUNEISEN, *EOS_TABULATED_COMPACTION and
// *EOS_TABULATED
void readEosLinearPolynomial(Context&, const deck::Keyword&, const KeywordOptions&);
void readEosGruneisen(Context&, const deck::Keyword&, const KeywordOptions&);
void readEosTabulatedCompaction(Context&, const deck::Keyword&, const KeywordOptions&);
void readEosTabulated(Context&, const deck::Keyword&, const KeywordOptions&);
// The equation of state a part names and its law (solids only): the law must take one exactly
// when its unit declares kEos (InputError naming the part's EOSID or MID field otherwise).
void checkPartEos(Context& ctx, const Part& p);
// *MAT_ADD_EROSION (build_erosion.cpp), and the check that a part's elements can honour its
// material's erosion criteria.
void readAddErosion(Context&, const deck::Keyword&, const KeywordOptions&);
void checkPartErosion(Context& ctx, std::size_t part);

// build_contact.cpp
void readContact(Context&, const deck::Keyword&, const KeywordOptions&);
void readControlContact(Context&, const deck::Keyword&, const KeywordOptions&);
// An element of `kind` in a part whose section is of another kind: InputError at PID.
void checkSectionKind(Context& ctx, const deck::Card& c, int32_t part, SectionKind kind);
// Whether checkSectionKind passes for an element of `keyword` (no card needed to ask).
bool sectionKindFits(const Context& ctx, std::string_view keyword, int32_t part, SectionKind kind);

// Helpers shared by the build_*.cpp readers (build_mesh.cpp).
// Moves to the next record of a keyword that holds several; false at its end. A record that
// starts with a heading card (a *PART heading, a _TITLE title, an _ID card) starts at the next
// line even when that line is blank: an empty heading is a card (Keyword Manual Vol. I,
// "General card format"). One that starts with a data card skips blank lines. Trailing blank
// lines end the keyword either way.
bool nextRecord(deck::CardCursor& cur, bool starts_with_heading);
// Hourglass types Crumple runs (*HOURGLASS, *CONTROL_HOURGLASS IHQ): the viscous 1-3, the
// stiffness 4-5, and 8, the warping stiffness of fully integrated shells (ELFORM 16).
inline bool isSupportedIhq(int64_t ihq) {
  return (ihq >= 1 && ihq <= 5) || ihq == 8;
}
int64_t positiveId(const deck::Card& c, std::string_view field);
int64_t positiveId(const deck::Card& c, const deck::FieldSlot& field);
std::string readTitleCard(deck::CardCursor& cur, const deck::KeywordSpec& spec,
                          const KeywordOptions& opts);
// MID and RO of card 1 (the definition is recorded; RO must be positive). Spring and damper
// laws have no RO (`density` false).
Material readMaterialBase(Context& ctx, const deck::Card& c, std::string title,
                          bool density = true);

// build_controls.cpp: *DATABASE_HISTORY_SOLID, _SHELL, _BEAM (_ID) and their _SET
void readHistoryElement(Context&, const deck::Keyword&, const KeywordOptions&);
void readHistoryElementSet(Context&, const deck::Keyword&, const KeywordOptions&);

// build_sets.cpp
void readCurve(Context&, const deck::Keyword&, const KeywordOptions&);
void readBox(Context&, const deck::Keyword&, const KeywordOptions&);
void readCoordinateSystem(Context&, const deck::Keyword&, const KeywordOptions&);
void readCoordinateNode(Context&, const deck::Keyword&, const KeywordOptions&);
void readVector(Context&, const deck::Keyword&, const KeywordOptions&);
void readNodeSetList(Context&, const deck::Keyword&, const KeywordOptions&);
void readNodeSetGeneral(Context&, const deck::Keyword&, const KeywordOptions&);
void readPartSetList(Context&, const deck::Keyword&, const KeywordOptions&);
void readSegmentSet(Context&, const deck::Keyword&, const KeywordOptions&);
// *SET_SOLID, *SET_SHELL, *SET_BEAM, *SET_DISCRETE (_LIST, _GENERATE, _TITLE) and their _ADD.
void readElementSetList(Context&, const deck::Keyword&, const KeywordOptions&);
void readElementSetAdd(Context&, const deck::Keyword&, const KeywordOptions&);
void finishCurves(Context&);
void readTable(Context&, const deck::Keyword&, const KeywordOptions&);
// Resolves the tables' curves (after finishCurves): a curve that is not defined makes the
// table unusable, an error where it is used.
void finishTables(Context&);

// build_conditions.cpp
void readSpc(Context&, const deck::Keyword&, const KeywordOptions&);
void readPrescribedMotion(Context&, const deck::Keyword&, const KeywordOptions&);
// VAD (0 velocity, 1 acceleration, 2 displacement), LCID, SF, DEATH (1e28 and above: never)
// and BIRTH of a prescribed-motion card, nodal or rigid; nothing (the card rejected) for
// another VAD.
struct MotionCurve {
  int vad = 0;
  int32_t curve = kNone;
  double sf = 1.0, birth = 0.0, death = 0.0;
};
std::optional<MotionCurve> readMotionCurve(Context& ctx, const deck::Card& c);
// The translation axis (0-2) and sign of prescribed-motion DOF 1-4 (Keyword Manual,
// *BOUNDARY_PRESCRIBED_MOTION). DOF 4 is translation along the vector VID with the motion
// normal to it free: along a global axis that is the axis' DOF with the vector's sign. A skew
// vector would need a constraint in local axes: refused (nothing returned).
std::optional<std::pair<int, double>> translationAxis(Context& ctx, const deck::Card& c,
                                                      int64_t dof);
void readInitialVelocity(Context&, const deck::Keyword&, const KeywordOptions&);
void readInitialVelocityNode(Context&, const deck::Keyword&, const KeywordOptions&);
void readInitialVelocityGeneration(Context&, const deck::Keyword&, const KeywordOptions&);
void readInitialAxialForceBeam(Context&, const deck::Keyword&, const KeywordOptions&);
void readLoadNode(Context&, const deck::Keyword&, const KeywordOptions&);
void readElementMass(Context&, const deck::Keyword&, const KeywordOptions&);
void readLoadSegment(Context&, const deck::Keyword&, const KeywordOptions&);
void readLoadSegmentSet(Context&, const deck::Keyword&, const KeywordOptions&);
void readIntegrationBeam(Context&, const deck::Keyword&, const KeywordOptions&);
void readIntegrationShell(Context&, const deck::Keyword&, const KeywordOptions&);
void readLoadBlastEnhanced(Context&, const deck::Keyword&, const KeywordOptions&);
void readLoadBlastSegmentSet(Context&, const deck::Keyword&, const KeywordOptions&);
void readLoadBody(Context&, const deck::Keyword&, const KeywordOptions&);
void readRigidWallPlanar(Context&, const deck::Keyword&, const KeywordOptions&);
void readRigidWallGeometric(Context&, const deck::Keyword&, const KeywordOptions&);
void finishConditions(Context&);

// build_damping.cpp: *DAMPING_GLOBAL, *DAMPING_PART_MASS(_SET), *DAMPING_PART_STIFFNESS(_SET);
// finishDamping gives the parts' mass damping its nodes (after the elements are read).
void readDampingGlobal(Context&, const deck::Keyword&, const KeywordOptions&);
void readDampingPartMass(Context&, const deck::Keyword&, const KeywordOptions&);
void readDampingPartStiffness(Context&, const deck::Keyword&, const KeywordOptions&);
void finishDamping(Context&);

// build_rigid.cpp: rigid bodies, spot welds, tied node sets (finishRigid before
// finishConditions: it turns SPCs on rigid-body nodes into constraints of the body)
void readPartInertia(Context&, deck::CardCursor& cur, int64_t part_id);  // *PART_INERTIA cards
void readRigidBodies(Context&, const deck::Keyword&, const KeywordOptions&);
void readExtraNodes(Context&, const deck::Keyword&, const KeywordOptions&);
void readNodalRigidBody(Context&, const deck::Keyword&, const KeywordOptions&);
void readPrescribedMotionRigid(Context&, const deck::Keyword&, const KeywordOptions&);
void readSpotweld(Context&, const deck::Keyword&, const KeywordOptions&);
void readGeneralizedWeld(Context&, const deck::Keyword&, const KeywordOptions&);
void readConstrainedNodeSet(Context&, const deck::Keyword&, const KeywordOptions&);
void readJoint(Context&, const deck::Keyword&, const KeywordOptions&);
void readJointStiffness(Context&, const deck::Keyword&, const KeywordOptions&);
void readLoadRigidBody(Context&, const deck::Keyword&, const KeywordOptions&);
void finishRigid(Context&);

// build_controls.cpp
void readTitle(Context&, const deck::Keyword&, const KeywordOptions&);
void readControlTermination(Context&, const deck::Keyword&, const KeywordOptions&);
void readControlTimestep(Context&, const deck::Keyword&, const KeywordOptions&);
void readControlHourglass(Context&, const deck::Keyword&, const KeywordOptions&);
void readControlRigid(Context&, const deck::Keyword&, const KeywordOptions&);
void readControlBulkViscosity(Context&, const deck::Keyword&, const KeywordOptions&);
void readControlEnergy(Context&, const deck::Keyword&, const KeywordOptions&);
void readControlImplicitGeneral(Context&, const deck::Keyword&, const KeywordOptions&);
void readControlSolution(Context&, const deck::Keyword&, const KeywordOptions&);
void readControlUnits(Context&, const deck::Keyword&, const KeywordOptions&);
void readControlDynamicRelaxation(Context&, const deck::Keyword&, const KeywordOptions&);

// build_airbag.cpp: *AIRBAG_SIMPLE_PRESSURE_VOLUME (its segments join Model::pressure_loads).
void readAirbagSimplePressureVolume(Context&, const deck::Keyword&, const KeywordOptions&);
// Keywords read only to report their non-default fields (*CONTROL_SOLID, ...).
void readIgnoredControl(Context&, const deck::Keyword&, const KeywordOptions&);
void readDatabaseAscii(Context&, const deck::Keyword&, const KeywordOptions&);
void readCrossSectionSet(Context&, const deck::Keyword&, const KeywordOptions&);
void readCrossSectionPlane(Context&, const deck::Keyword&, const KeywordOptions&);
void readDatabaseD3plot(Context&, const deck::Keyword&, const KeywordOptions&);
void readDatabaseExtentBinary(Context&, const deck::Keyword&, const KeywordOptions&);
void readDatabaseD3dump(Context&, const deck::Keyword&, const KeywordOptions&);
void readHistoryNode(Context&, const deck::Keyword&, const KeywordOptions&);
void readHistoryNodeSet(Context&, const deck::Keyword&, const KeywordOptions&);
void finishControls(Context&);

}  // namespace crumple::model::build
