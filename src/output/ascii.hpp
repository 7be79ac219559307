// LS-DYNA's ASCII history files (glstat, matsum, nodout, rcforc, rwforc, sleout, secforc) as
// text: the header lines, the legends and one output time's block each, in the fixed-width
// layouts LS-DYNA R13 writes (the samples are the bolted-joint results in
// ../shared/decks/bolted_joint_lsdyna; rwforc and secforc have none, docs/theory.md "LS-DYNA
// ASCII files" says what their layout rests on). The writer knows no physics: ResultsWriter
// fills the plain records below and appends the text to its HistoryFiles.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace crumple::output::ascii {

// Fortran's 1PEw.d ("-1.23450E+00") and Ew.d ("-0.12345E+01") edit descriptors, right
// aligned in `width` characters (never cut: a wider number widens the field).
std::string scientific(double value, int width, int digits);
std::string fractional(double value, int width, int digits);

// The two banner lines every file starts with: the deck's title, and the "ls-dyna" line that
// names the writer (readers skip it by that word).
std::string banner(std::string_view title);

// {BEGIN LEGEND} ... {END LEGEND}: one line per entity, its id (I9), `gap` blanks and its title
// padded to `title_width`.
struct LegendEntry {
  int64_t id = 0;
  std::string title;
};
std::string legend(const std::vector<LegendEntry>& entries, int gap, int title_width);

using Vec3 = std::array<double, 3>;

// ---- glstat ---------------------------------------------------------------------------------
struct GlstatSample {
  int64_t cycle = 1;  // LS-DYNA's count, from 1
  std::string dt_family = "solid";
  int64_t dt_element = 0, dt_part = 0;  // the element controlling the step, its part
  double time = 0, dt = 0, kinetic = 0, internal = 0, spring_damper = 0, hourglass = 0;
  double damping = 0, contact = 0, external_work = 0, eroded_kinetic = 0, eroded_internal = 0;
  double eroded_hourglass = 0, total = 0, ratio = 1, ratio_without_eroded = 1;
  Vec3 velocity{};
  bool stonewall = false;  // a "stonewall energy" line (the model has rigid walls)
  double stonewall_energy = 0;
  bool mass_scaled = false;  // "added mass" and "percentage increase" lines
  double added_mass = 0, percent_increase = 0;
};
std::string glstatBlock(const GlstatSample& s);

// ---- matsum ---------------------------------------------------------------------------------
struct MatsumPart {
  int64_t id = 0;
  double internal = 0, kinetic = 0, eroded_internal = 0, eroded_kinetic = 0, hourglass = 0;
  Vec3 momentum{}, rigid_velocity{};
};
std::string matsumHeader(std::string_view title, const std::vector<LegendEntry>& parts);
std::string matsumBlock(double time, const std::vector<MatsumPart>& parts);

// ---- nodout ---------------------------------------------------------------------------------
struct NodoutRow {
  int64_t id = 0;
  Vec3 disp{}, vel{}, acc{}, coor{};
  Vec3 rot{}, rot_vel{}, rot_acc{};
};
std::string nodoutHeader(std::string_view title, const std::vector<LegendEntry>& nodes);
// The translational block, and the rotational one when `rotations` (a model with shells or
// beams).
std::string nodoutBlock(int64_t cycle, double time, const std::vector<NodoutRow>& rows,
                        bool rotations);

// ---- rcforc and sleout ------------------------------------------------------------------------
struct ContactRecord {
  int64_t id = 0;
  bool single_surface = false;  // resultants undefined, as LS-DYNA prints
  Vec3 slave{}, master{};
  double slave_energy = 0, master_energy = 0, friction_energy = 0;
};
// The header of rcforc, sleout and secforc: the banner and the legend of the interfaces or
// sections (titles from column 16, as LS-DYNA's rcforc).
std::string entityHeader(std::string_view title, const std::vector<LegendEntry>& entities);
std::string rcforcBlock(double time, const std::vector<ContactRecord>& contacts);
std::string sleoutBlock(int64_t cycle, double time, const std::vector<ContactRecord>& contacts);

// ---- rwforc ---------------------------------------------------------------------------------
struct WallRecord {
  int64_t id = 0;
  double normal = 0;
  Vec3 force{};
};
std::string rwforcHeader(std::string_view title);
std::string rwforcBlock(double time, const std::vector<WallRecord>& walls);

// ---- secforc --------------------------------------------------------------------------------
struct SectionRecord {
  int64_t id = 0;
  Vec3 force{}, moment{}, centroid{};
  double area = 0;
};
std::string secforcBlock(double time, const std::vector<SectionRecord>& sections);

}  // namespace crumple::output::ascii

namespace crumple::output::ascii {

// ---- spcforc --------------------------------------------------------------------------------
// One constrained node: the force (and, at nodes with rotations, the moment) the SPCs exert.
struct SpcRecord {
  int64_t id = 0, set = 0;  // node id; the *BOUNDARY_SPC_SET's set id (0: a node's own card)
  Vec3 force{}, moment{};
  bool rotations = false;  // the node has rotational freedoms: a moment line
};
std::string spcforcHeader(std::string_view title);
std::string spcforcBlock(double time, const std::vector<SpcRecord>& nodes);

// ---- bndout ---------------------------------------------------------------------------------
// One node of *BOUNDARY_PRESCRIBED_MOTION: the force imposing the motion and its work so far.
struct BndoutRecord {
  int64_t id = 0, set = 0;
  Vec3 force{}, moment{};
  double energy = 0;
};
std::string bndoutBlock(double time, const std::vector<BndoutRecord>& nodes);

// ---- rbdout ---------------------------------------------------------------------------------
struct RigidBodyRecord {
  int64_t id = 0;
  bool nodal = false;  // *CONSTRAINED_NODAL_RIGID_BODY ("nodal rigid body")
  Vec3 coordinates{}, displacement{}, rotation{}, velocity{}, angular_velocity{};
  Vec3 acceleration{}, angular_acceleration{};
  std::array<Vec3, 3> axes{};  // rows: the principal axes a, b, c in global components
};
std::string rbdoutBlock(int64_t cycle, double time, const std::vector<RigidBodyRecord>& bodies);

// ---- deforc ---------------------------------------------------------------------------------
struct DiscreteRecord {
  int64_t id = 0;
  Vec3 force{};           // the force on the second node, along the element
  double resultant = 0;   // the axial force, tension positive
  double elongation = 0;  // change in length from the initial one (OFFSET not included)
};
std::string deforcHeader(std::string_view title, const std::vector<LegendEntry>& elements);
std::string deforcBlock(double time, const std::vector<DiscreteRecord>& elements);

}  // namespace crumple::output::ascii

namespace crumple::output::ascii {

// ---- elout ----------------------------------------------------------------------------------
// One output time of *DATABASE_HISTORY_SOLID, _SHELL, _BEAM. The beam block is the layout of
// LS-DYNA R13's elout in ../shared/decks/bolted_joint_lsdyna; the solid and shell blocks follow
// the layout of LS-DYNA's binout-to-ASCII translation (docs/theory.md, "LS-DYNA ASCII files").
// `state` is "elastic", "plastic" or "failed" (eroded).
using Stress = std::array<double, 6>;  // Voigt xx, yy, zz, xy, yz, zx (global)
struct EloutSolid {
  int64_t id = 0, material_type = 0;
  std::string state;
  Stress sig{};
  double eps_p = 0;      // effective plastic strain (LS-DYNA's "effsg" column)
  double effective = 0;  // von Mises stress (the "yield function" column)
};
struct EloutShellPoint {
  std::string state;
  Stress sig{};
  double eps_p = 0;
};
struct EloutShell {
  int64_t id = 0, material_type = 0;
  std::vector<EloutShellPoint> points;  // through the thickness, bottom first
};
struct EloutBeamPoint {
  double sigma11 = 0, sigma12 = 0, sigma31 = 0, eps_p = 0;
};
struct EloutBeam {
  int64_t id = 0, part = 0, material_type = 0;
  // axial, shear-s, shear-t, moment-s, moment-t, torsion; the plastic strain (mean of the points)
  std::array<double, 6> resultants{};
  double eps_p = 0;
  std::vector<EloutBeamPoint> points;  // integrated beams and trusses only
};
std::string eloutSolidBlock(int64_t cycle, double time, const std::vector<EloutSolid>& solids);
std::string eloutShellBlock(int64_t cycle, double time, const std::vector<EloutShell>& shells);
std::string eloutBeamBlock(int64_t cycle, double time, const std::vector<EloutBeam>& beams);

}  // namespace crumple::output::ascii
