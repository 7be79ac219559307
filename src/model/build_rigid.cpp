// Meaning of the rigid-body and nodal-constraint keywords (LS-DYNA Keyword Manual Vol. I):
// *PART_INERTIA (cards 3-5 of *PART), *CONSTRAINED_RIGID_BODIES, *CONSTRAINED_EXTRA_NODES_NODE
// and _SET, *CONSTRAINED_NODAL_RIGID_BODY(_SPC), *BOUNDARY_PRESCRIBED_MOTION_RIGID,
// *CONSTRAINED_SPOTWELD, *CONSTRAINED_GENERALIZED_WELD_SPOT, *CONSTRAINED_NODE_SET and
// *CONSTRAINED_JOINT_SPHERICAL / _REVOLUTE.
// The readers collect; finishRigid() builds Model::rigid once every keyword is read: one body
// per *MAT_RIGID part after merges, then the nodal rigid bodies, and checks that no node is
// subject to two constraints.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "model/build_context.hpp"
#include "util/error.hpp"
#include "util/vec3.hpp"

namespace crumple::model::build {

using deck::Card;
using deck::CardCursor;
using deck::keywordSpec;
using util::cross;
using util::norm;
using util::sub;

// *CONSTRAINED_JOINT_STIFFNESS before its parts' bodies are known.
struct JointStiffnessInput {
  JointStiffnessDef def;
  int64_t pid_a = 0, pid_b = 0;
  std::string context_a, context_b;
};

// What the readers collect before the bodies can be formed (parts, sets and merges must all
// be known first).
struct RigidInput {
  struct Inertia {
    RigidBodyDef values;  // inertia_given, mass, cm, tensor, velocity_given, v0, w0
    int32_t cm_node = kNone;
    std::string context;  // "deck.k:12: *PART inertia card 3 field 4 (TM)" for messages
  };
  std::map<int64_t, Inertia> inertia;  // by part id
  struct Merge {
    int32_t master, slave;
    bool iflag;
    std::string context;
  };
  std::vector<Merge> merges;
  struct Extra {
    int32_t part;
    std::vector<int32_t> nodes;
    bool iflag;
    std::string context;
  };
  std::vector<Extra> extras;
  struct Nodal {
    RigidBodyDef body;
    std::string context;
  };
  std::vector<Nodal> nodal;
  struct Motion {
    int64_t pid;
    RigidMotion motion;
    std::string context;
  };
  std::vector<Motion> motions;
  std::vector<bool> weld_explicit_id;
  std::vector<JointStiffnessInput> stiffness;
  struct Load {
    int64_t pid;
    RigidLoad load;
    std::string context;
  };
  std::vector<Load> loads;
};

namespace {

RigidInput& input(Context& ctx) {
  if (!ctx.rigid_input) ctx.rigid_input = std::make_shared<RigidInput>();
  return *ctx.rigid_input;
}

[[noreturn]] void failAt(const std::string& context, const std::string& message) {
  throw util::InputError(context + ": " + message);
}

// CON1/CON2 codes (Keyword Manual, *MAT_RIGID): 1 x, 2 y, 3 z, 4 xy, 5 yz, 6 zx, 7 xyz.
uint8_t codeMask(int code) {
  static constexpr uint8_t masks[8] = {0, 1, 2, 4, 3, 6, 5, 7};
  return masks[code];
}

// CMO, CON1, CON2 of *MAT_RIGID card 2 or the _SPC card of a nodal rigid body, as a mask.
uint8_t constraintMask(Context& ctx, const Card& c) {
  const double cmo = c.real("CMO");
  if (cmo == -1.0) {
    ctx.reject(c, "CMO", "constraints in a local coordinate system (CMO=-1) are not supported");
    return 0;
  }
  if (cmo != 0.0 && cmo != 1.0) c.fail("CMO", "must be 0, 1 or -1");
  const double con1 = c.real("CON1"), con2 = c.real("CON2");
  if (cmo == 0.0) return 0;
  if (con1 < 0 || con1 > 7 || con1 != std::floor(con1)) c.fail("CON1", "must be 0 to 7");
  if (con2 < 0 || con2 > 7 || con2 != std::floor(con2)) c.fail("CON2", "must be 0 to 7");
  return static_cast<uint8_t>(codeMask(int(con1)) | (codeMask(int(con2)) << 3));
}

bool isRigidPart(const Model& m, int32_t part) {
  const Part& p = m.parts[static_cast<std::size_t>(part)];
  return p.material != kNone &&
         std::holds_alternative<RigidLaw>(m.materials[static_cast<std::size_t>(p.material)].law);
}

int32_t rigidPart(Context& ctx, const Card& c, std::string_view field) {
  const int32_t p = ctx.part(c, field, c.integer(field));
  if (!isRigidPart(ctx.model, p))
    c.fail(field, "part " + std::to_string(c.integer(field)) + " is not rigid (*MAT_RIGID)");
  return p;
}

void sortUnique(std::vector<int32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

double failureTime(double tf) {
  return tf >= 1e20 ? std::numeric_limits<double>::infinity() : tf;
}

// SN, SS, N, M of a weld: a term counts when its force is positive, and then needs a positive
// exponent (the manual gives no default).
void readWeldFailure(const Card& c, SpotweldDef& w) {
  w.sn = c.real("SN");
  w.ss = c.real("SS");
  w.n = c.real("N");
  w.m = c.real("M");
  if (w.sn < 0) c.fail("SN", "must not be negative (0: no normal-force failure)");
  if (w.ss < 0) c.fail("SS", "must not be negative (0: no shear-force failure)");
  if (w.sn > 0 && !(w.n > 0)) c.fail("N", "the exponent of the normal force must be positive");
  if (w.ss > 0 && !(w.m > 0)) c.fail("M", "the exponent of the shear force must be positive");
}

}  // namespace

void readPartInertia(Context& ctx, CardCursor& cur, int64_t part_id) {
  const auto& spec = keywordSpec("*PART");
  const Card& c3 = cur.read(spec.card("inertia card 3"));
  const Card& c4 = cur.read(spec.card("inertia card 4"));
  const Card& c5 = cur.read(spec.card("inertia card 5"));
  if (c3.integer("IRCS") != 0) {
    // Card 6 follows; read it so that the next part starts at the right line.
    const Card& c6 = cur.read(spec.card("inertia card 6"));
    for (auto f : {"XL", "YL", "ZL", "XLIP", "YLIP", "ZLIP", "CID"}) c6.real(f);
    ctx.reject(c3, "IRCS", "an inertia tensor in local axes (IRCS=1) is not supported");
  }
  RigidInput::Inertia in;
  RigidBodyDef& b = in.values;
  b.inertia_given = true;
  b.mass = c3.real("TM");
  if (!(b.mass > 0)) c3.fail("TM", "the translational mass must be positive");
  b.cm = {c3.real("XC"), c3.real("YC"), c3.real("ZC")};
  if (const int64_t n = c3.integer("NODEID"); n != 0) {
    in.cm_node = ctx.node(c3, "NODEID", n);
    b.cm = ctx.model.nodes.x[static_cast<std::size_t>(in.cm_node)];
  }
  static constexpr const char* kT[6] = {"IXX", "IXY", "IXZ", "IYY", "IYZ", "IZZ"};
  for (int k = 0; k < 6; ++k) b.tensor[static_cast<std::size_t>(k)] = c4.real(kT[k]);
  // A tensor of inertia is positive definite: its diagonal, and each 2 x 2 minor, positive.
  const auto& t = b.tensor;
  for (int k : {0, 3, 5})
    if (!(t[std::size_t(k)] > 0)) c4.fail(kT[k], "a principal moment must be positive");
  if (!(t[0] * t[3] > t[1] * t[1] && t[3] * t[5] > t[4] * t[4] && t[0] * t[5] > t[2] * t[2]))
    c4.fail("IXY", "the inertia tensor is not positive definite");
  b.v0 = {c5.real("VTX"), c5.real("VTY"), c5.real("VTZ")};
  b.w0 = {c5.real("VRX"), c5.real("VRY"), c5.real("VRZ")};
  for (double v : {b.v0[0], b.v0[1], b.v0[2], b.w0[0], b.w0[1], b.w0[2]})
    if (v != 0.0) b.velocity_given = true;
  in.context = c3.context("TM");
  input(ctx).inertia[part_id] = std::move(in);
}

void readRigidBodies(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*CONSTRAINED_RIGID_BODIES").card("card 1");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec);
    const int32_t master = rigidPart(ctx, c, "PIDM");
    const int32_t slave = rigidPart(ctx, c, "PIDS");
    if (master == slave) c.fail("PIDS", "a part cannot be merged with itself");
    input(ctx).merges.push_back({master, slave, c.integer("IFLAG") != 0, c.context("IFLAG")});
    ctx.collect(cur);
  }
}

void readExtraNodes(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const bool set = opts.has("SET");
  if (set == opts.has("NODE")) {
    ctx.rejectKeyword(kw, "give one of _NODE or _SET");
    return;
  }
  const auto& spec =
      keywordSpec(set ? "*CONSTRAINED_EXTRA_NODES_SET" : "*CONSTRAINED_EXTRA_NODES_NODE")
          .card("card 1");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec);
    RigidInput::Extra e{rigidPart(ctx, c, "PID"), {}, c.integer("IFLAG") != 0, c.context("IFLAG")};
    if (set)
      e.nodes = ctx.nodeSet(c, "NSID", c.integer("NSID"));
    else
      e.nodes = {ctx.node(c, "NID", c.integer("NID"))};
    input(ctx).extras.push_back(std::move(e));
    ctx.collect(cur);
  }
}

void readNodalRigidBody(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*CONSTRAINED_NODAL_RIGID_BODY");
  CardCursor cur(kw, ctx.deck);
  // _TITLE: a heading card (the body's name) precedes every record.
  while (nextRecord(cur, opts.has("TITLE"))) {
    readTitleCard(cur, spec, opts);
    const Card& c = cur.read(spec.card("card 1"));
    RigidInput::Nodal nb;
    RigidBodyDef& b = nb.body;
    b.nodal = true;
    b.id = positiveId(c, "PID");
    b.where = c.where();
    nb.context = c.context("PID");
    if (c.integer("CID") != 0)
      ctx.reject(c, "CID", "output in a local coordinate system (CID) is not supported");
    // NSID 0 means the set whose id is PID (Keyword Manual, *CONSTRAINED_NODAL_RIGID_BODY).
    const int64_t nsid = c.integer("NSID") != 0 ? c.integer("NSID") : b.id;
    b.nodes = ctx.nodeSet(c, "NSID", nsid);
    if (const int64_t pnode = c.integer("PNODE"); pnode != 0) {
      b.nodes.push_back(ctx.node(c, "PNODE", pnode));
      ctx.ignore(kw.name, "PNODE",
                 "node " + std::to_string(pnode) +
                     " joins the body where it is; it is not moved to the centre of mass",
                 c.where());
    }
    sortUnique(b.nodes);
    for (auto f : {"DRFLAG", "RRFLAG"})
      if (c.integer(f) != 0)
        ctx.reject(c, f, "releasing freedoms of nodal rigid bodies is not supported");
    if (opts.has("SPC")) b.fixed = constraintMask(ctx, cur.read(spec.card("spc card")));
    input(ctx).nodal.push_back(std::move(nb));
    ctx.collect(cur);
  }
}

void readPrescribedMotionRigid(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*BOUNDARY_PRESCRIBED_MOTION_RIGID");
  CardCursor cur(kw, ctx.deck);
  // _ID: a heading card precedes every record.
  while (nextRecord(cur, opts.has("ID"))) {
    if (opts.has("ID")) cur.read(spec.card("id card"));
    const Card& c = cur.read(spec.card("card 1"));
    RigidMotion m;
    // DOF 1-3 translations of the centre of mass, 5-7 rotations about the global axes
    // (Keyword Manual, *BOUNDARY_PRESCRIBED_MOTION_RIGID); the others need a direction
    // vector or local axes.
    const int64_t dof = c.integer("DOF");
    if (dof < 1 || dof > 7) {
      ctx.reject(c, "DOF", "DOF " + std::to_string(dof) + " is not supported (1-7 are)");
      ctx.collect(cur);
      continue;
    }
    // Translations 1-4 (4 along a vector) map to axes 0-2; rotations 5-7 to 3-5.
    const auto axis =
        dof <= 4 ? translationAxis(ctx, c, dof) : std::make_pair(static_cast<int>(dof - 2), 1.0);
    if (!axis) {
      ctx.collect(cur);
      continue;
    }
    m.dof = axis->first;
    const double sign = axis->second;
    const auto motion = readMotionCurve(ctx, c);
    if (!motion) {
      ctx.collect(cur);
      continue;
    }
    m.kind = static_cast<uint8_t>(motion->vad);
    m.curve = motion->curve;
    m.sf = sign * motion->sf;
    m.death = motion->death;
    m.birth = motion->birth;
    input(ctx).motions.push_back({c.integer("PID"), m, c.context("PID")});
    ctx.collect(cur);
  }
}

void readSpotweld(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*CONSTRAINED_SPOTWELD");
  CardCursor cur(kw, ctx.deck);
  while (nextRecord(cur, opts.has("ID"))) {
    SpotweldDef w;
    w.id = static_cast<int64_t>(ctx.model.rigid.welds.size()) + 1;
    if (opts.has("ID")) w.id = positiveId(cur.read(spec.card("id card")), "WID");
    const Card& c = cur.read(spec.card("card 1"));
    w.where = c.where();
    const int32_t n1 = ctx.node(c, "N1", c.integer("N1"));
    const int32_t n2 = ctx.node(c, "N2", c.integer("N2"));
    if (n1 == n2) c.fail("N2", "a spot weld needs two different nodes");
    // The normal of the weld runs from node to node, so they must not coincide (Keyword
    // Manual: spot welds join non-contiguous nodal pairs).
    const Vec3& a = ctx.model.nodes.x[static_cast<std::size_t>(n1)];
    const Vec3& b = ctx.model.nodes.x[static_cast<std::size_t>(n2)];
    if (a == b) c.fail("N2", "the welded nodes coincide; a spot weld joins separate nodes");
    w.nodes = {std::min(n1, n2), std::max(n1, n2)};
    readWeldFailure(c, w);
    w.tfail = failureTime(c.real("TF"));
    const double ep = c.real("EP");
    if (ep > 0 && ep < 1e20)
      ctx.reject(c, "EP", "failure by the plastic strain of the welded elements is not supported");
    ctx.model.rigid.welds.push_back(std::move(w));
    input(ctx).weld_explicit_id.push_back(opts.has("ID"));
    ctx.collect(cur);
  }
}

void readGeneralizedWeld(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  if (!opts.has("SPOT")) {
    ctx.rejectKeyword(kw, "only spot welds (_SPOT) are supported");
    return;
  }
  const auto& spec = keywordSpec("*CONSTRAINED_GENERALIZED_WELD_SPOT");
  CardCursor cur(kw, ctx.deck);
  while (nextRecord(cur, opts.has("ID"))) {
    SpotweldDef w;
    w.generalized = true;
    w.id = static_cast<int64_t>(ctx.model.rigid.welds.size()) + 1;
    if (opts.has("ID")) w.id = positiveId(cur.read(spec.card("id card")), "WID");
    const Card& c = cur.read(spec.card("card 1"));
    const Card& c2 = cur.read(spec.card("card 2"));
    w.where = c.where();
    w.nodes = ctx.nodeSet(c, "NSID", c.integer("NSID"));
    if (w.nodes.size() < 2) c.fail("NSID", "a weld needs at least two nodes");
    // Force filtering changes when a weld fails; it is refused rather than left out.
    if (c.integer("FILTER") > 1)
      ctx.reject(c, "FILTER", "filtering of the weld forces is not supported");
    c.integer("WINDOW");
    readWeldFailure(c2, w);
    w.tfail = failureTime(c2.real("TFAIL"));
    const double epsf = c2.real("EPSF");
    if (epsf > 0 && epsf < 1e20)
      ctx.reject(c2, "EPSF",
                 "failure by the plastic strain of the welded elements is not supported");
    ctx.model.rigid.welds.push_back(std::move(w));
    input(ctx).weld_explicit_id.push_back(opts.has("ID"));
    ctx.collect(cur);
  }
}

void readConstrainedNodeSet(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*CONSTRAINED_NODE_SET");
  CardCursor cur(kw, ctx.deck);
  while (nextRecord(cur, opts.has("ID"))) {
    TiedNodeSet t;
    t.id = static_cast<int64_t>(ctx.model.rigid.node_sets.size()) + 1;
    if (opts.has("ID")) t.id = positiveId(cur.read(spec.card("id card")), "CNSID");
    const Card& c = cur.read(spec.card("card 1"));
    t.where = c.where();
    t.nodes = ctx.nodeSet(c, "NSID", c.integer("NSID"));
    const int64_t dof = c.integer("DOF");
    if (dof < 1 || dof > 7) c.fail("DOF", "must be 1 to 7 (x, y, z, xy, yz, zx, xyz)");
    t.dofs = codeMask(static_cast<int>(dof));
    t.tfail = failureTime(c.real("TF"));
    ctx.model.rigid.node_sets.push_back(std::move(t));
    ctx.collect(cur);
  }
}

namespace {

// The joint's node pairs (N1-N2, N3-N4, N5-N6 as its kind uses them), each pair coincident
// (Keyword Manual, *CONSTRAINED_JOINT: the joint's node pairs are coincident).
void readJointPairs(Context& ctx, const Card& c, JointDef& j) {
  static constexpr const char* kN[6] = {"N1", "N2", "N3", "N4", "N5", "N6"};
  const int used = j.kind == JointKind::Spherical ? 2 : j.kind == JointKind::Translational ? 6 : 4;
  for (int p = 0; p < used; p += 2) {
    const int32_t a = ctx.node(c, kN[p], c.integer(kN[p]));
    const int32_t b = ctx.node(c, kN[p + 1], c.integer(kN[p + 1]));
    if (a == b) c.fail(kN[p + 1], "a joint joins two different nodes");
    const Vec3& xa = ctx.model.nodes.x[static_cast<std::size_t>(a)];
    const Vec3& xb = ctx.model.nodes.x[static_cast<std::size_t>(b)];
    const double scale = std::max({1.0, std::abs(xa[0]), std::abs(xa[1]), std::abs(xa[2])});
    if (std::hypot(xa[0] - xb[0], xa[1] - xb[1], xa[2] - xb[2]) > 1e-6 * scale)
      c.fail(kN[p + 1],
             "the joint's nodes " + std::string(kN[p]) + " and " + kN[p + 1] + " must coincide");
    j.pairs.push_back({a, b});
  }
  if (used >= 4) {
    const Vec3& x1 = ctx.model.nodes.x[static_cast<std::size_t>(j.pairs[0][0])];
    const Vec3& x3 = ctx.model.nodes.x[static_cast<std::size_t>(j.pairs[1][0])];
    if (x1 == x3) c.fail("N3", "the joint's axis N1-N3 has no length");
  }
  if (j.kind == JointKind::Translational) {
    // N5 off the axis: otherwise nothing holds the bodies against turning about it.
    const auto x = [&](int p) {
      return ctx.model.nodes.x[std::size_t(j.pairs[std::size_t(p)][0])];
    };
    const Vec3 e = sub(x(1), x(0)), r = sub(x(2), x(0));
    if (norm(cross(e, r)) <= 1e-6 * norm(e) * norm(r))
      c.fail("N5", "N5 lies on the axis N1-N3: it cannot hold the turn about the axis");
  }
  for (int p = used; p < 6; ++p)
    if (c.integer(kN[p]) != 0)
      ctx.reject(c, kN[p], std::string(kN[p]) + " is not used by this joint");
}

}  // namespace

// *CONSTRAINED_JOINT_SPHERICAL, _REVOLUTE, _CYLINDRICAL, _TRANSLATIONAL (Keyword Manual vol.
// I, *CONSTRAINED_JOINT): N1..N6 (nodes of body A odd, body B even), RPS, DAMP.
void readJoint(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  static constexpr std::pair<const char*, JointKind> kKinds[] = {
      {"SPHERICAL", JointKind::Spherical},
      {"REVOLUTE", JointKind::Revolute},
      {"CYLINDRICAL", JointKind::Cylindrical},
      {"TRANSLATIONAL", JointKind::Translational}};
  int given = 0;
  JointKind kind = JointKind::Spherical;
  for (const auto& [word, k] : kKinds)
    if (opts.has(word)) {
      ++given;
      kind = k;
    }
  if (given != 1) {
    ctx.rejectKeyword(kw,
                      "give one of _SPHERICAL, _REVOLUTE, _CYLINDRICAL or _TRANSLATIONAL (other "
                      "joints are not supported)");
    return;
  }
  const auto& spec = keywordSpec("*CONSTRAINED_JOINT");
  CardCursor cur(kw, ctx.deck);
  while (nextRecord(cur, opts.has("ID"))) {
    JointDef j;
    j.id = static_cast<int64_t>(ctx.model.rigid.joints.size()) + 1;
    if (opts.has("ID")) j.id = positiveId(cur.read(spec.card("id card")), "ID");
    const Card& c = cur.read(spec.card("card 1"));
    j.where = c.where();
    j.kind = kind;
    readJointPairs(ctx, c, j);
    j.rps = c.real("RPS");
    j.damp = c.real("DAMP");
    if (!(j.rps > 0)) c.fail("RPS", "must be positive");
    if (j.damp < 0) c.fail("DAMP", "must not be negative");
    ctx.model.rigid.joints.push_back(std::move(j));
    ctx.collect(cur);
  }
}

namespace {

// A local frame of *CONSTRAINED_JOINT_STIFFNESS (CIDA, CIDB).
std::array<Vec3, 3> jointFrame(Context& ctx, const Card& c, std::string_view field, int64_t cid) {
  if (cid == 0) c.fail(field, "a coordinate system is required");
  return ctx.frame(c, field, cid).axis;
}

// Card 2 (moment and damping curves) and card 4 (stop angles): refused by field name.
void rejectStiffnessCurves(Context& ctx, const Card& c2, const Card& c4) {
  for (auto f : {"LCIDPH", "LCIDT", "LCIDPS"})
    if (c2.integer(f) != 0)
      ctx.reject(c2, f, "a moment-rotation curve of a joint stiffness is not supported");
  for (auto f : {"DLCIDPH", "DLCIDT", "DLCIDPS"})
    if (c2.integer(f) != 0)
      ctx.reject(c2, f, "a damping curve of a joint stiffness is not supported");
  for (auto f : {"NSAPH", "PSAPH", "NSAT", "PSAT", "NSAPS", "PSAPS"})
    if (c4.real(f) != 0.0) ctx.reject(c4, f, "stop angles of a joint stiffness are not supported");
}

}  // namespace

// *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED (Keyword Manual vol. I): JSID PIDA PIDB CIDA CIDB
// JID; curves LCIDPH.. DLCIDPS; ESPH FMPH EST FMT ESPS FMPS; stop angles NSAPH..PSAPS. Built:
// the friction springs (ES, FM > 0) about the three local axes; the rest is refused by name.
void readJointStiffness(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  if (!opts.has("GENERALIZED")) {
    ctx.rejectKeyword(kw, "only _GENERALIZED joint stiffness is supported");
    return;
  }
  const auto& spec = keywordSpec("*CONSTRAINED_JOINT_STIFFNESS");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c1 = cur.read(spec.card("card 1"));
    const Card& c2 = cur.readOptional(spec.card("card 2"));
    const Card& c3 = cur.readOptional(spec.card("card 3"));
    const Card& c4 = cur.readOptional(spec.card("card 4"));
    JointStiffnessInput in;
    in.def.id = positiveId(c1, "JSID");
    in.def.where = c1.where();
    in.pid_a = c1.integer("PIDA");
    in.pid_b = c1.integer("PIDB");
    in.context_a = c1.context("PIDA");
    in.context_b = c1.context("PIDB");
    const int64_t cida = c1.integer("CIDA");
    in.def.frame_a = jointFrame(ctx, c1, "CIDA", cida);
    in.def.frame_b =
        c1.integer("CIDB") == 0 ? in.def.frame_a : jointFrame(ctx, c1, "CIDB", c1.integer("CIDB"));
    if (c1.integer("JID") != 0)
      ctx.reject(c1, "JID", "a joint stiffness tied to one joint (JID) is not supported");
    rejectStiffnessCurves(ctx, c2, c4);
    static constexpr const char* kEs[3] = {"ESPH", "EST", "ESPS"};
    static constexpr const char* kFm[3] = {"FMPH", "FMT", "FMPS"};
    for (int k = 0; k < 3; ++k) {
      in.def.stiffness[std::size_t(k)] = c3.real(kEs[k]);
      in.def.friction[std::size_t(k)] = c3.real(kFm[k]);
      if (in.def.stiffness[std::size_t(k)] < 0) c3.fail(kEs[k], "must not be negative");
      if (in.def.friction[std::size_t(k)] < 0)
        ctx.reject(c3, kFm[k], "a friction moment curve (FM < 0) is not supported");
    }
    input(ctx).stiffness.push_back(std::move(in));
    ctx.collect(cur);
  }
}

// *LOAD_RIGID_BODY (Keyword Manual vol. I): PID DOF (1-3 force along x, y, z; 5-7 moment about
// x, y, z; of CID's axes when given, fixed in space) LCID SF CID M1 M2 M3.
void readLoadRigidBody(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*LOAD_RIGID_BODY").card("card 1");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec);
    const int64_t dof = c.integer("DOF");
    if (dof < 1 || dof > 7 || dof == 4) {
      ctx.reject(c, "DOF", "DOF " + std::to_string(dof) + " is not supported (1-3, 5-7 are)");
      ctx.collect(cur);
      continue;
    }
    for (auto f : {"M1", "M2", "M3"})
      if (c.integer(f) != 0) ctx.reject(c, f, "a follower load (M1, M2, M3) is not supported");
    const int axis = static_cast<int>(dof <= 3 ? dof - 1 : dof - 5);
    Vec3 dir{};
    dir[std::size_t(axis)] = 1.0;
    if (const int64_t cid = c.integer("CID"); cid != 0)
      dir = ctx.frame(c, "CID", cid).axis[std::size_t(axis)];
    RigidLoad load;
    load.curve = ctx.curve(c, "LCID", c.integer("LCID"));
    load.where = c.where();
    for (int i = 0; i < 3; ++i)
      if (dir[std::size_t(i)] != 0.0) {
        load.dof = (dof <= 3 ? 0 : 3) + i;
        load.sf = c.real("SF") * dir[std::size_t(i)];
        input(ctx).loads.push_back({c.integer("PID"), load, c.context("PID")});
      }
    ctx.collect(cur);
  }
}

namespace {

// What owns a node: a body, a weld or a tied node set.
struct Owner {
  enum Kind : uint8_t { None, Body, Weld, NodeSet } kind = None;
  int32_t index = kNone;
};

std::string describe(const Model& m, Owner o) {
  switch (o.kind) {
    case Owner::Body: {
      const auto& b = m.rigid.bodies[static_cast<std::size_t>(o.index)];
      return b.nodal ? "nodal rigid body " + std::to_string(b.id) + " (" + b.where.str() + ")"
                     : "the rigid body of part " + std::to_string(b.id);
    }
    case Owner::Weld: {
      const auto& w = m.rigid.welds[static_cast<std::size_t>(o.index)];
      return std::string(w.generalized ? "*CONSTRAINED_GENERALIZED_WELD_SPOT "
                                       : "*CONSTRAINED_SPOTWELD ") +
             std::to_string(w.id) + " (" + w.where.str() + ")";
    }
    case Owner::NodeSet: {
      const auto& t = m.rigid.node_sets[static_cast<std::size_t>(o.index)];
      return "*CONSTRAINED_NODE_SET " + std::to_string(t.id) + " (" + t.where.str() + ")";
    }
    case Owner::None:
      break;
  }
  return "nothing";
}

}  // namespace

namespace {

// Weld ids: explicit ones must be unique (the others are numbered in deck order).
void checkWeldIds(const RigidDefinitions& rd, const RigidInput& in) {
  std::map<int64_t, std::size_t> weld_ids;
  for (std::size_t k = 0; k < rd.welds.size(); ++k) {
    if (!in.weld_explicit_id[k]) continue;
    auto [it, fresh] = weld_ids.emplace(rd.welds[k].id, k);
    if (!fresh)
      throw util::InputError(rd.welds[k].where.str() + ": weld " + std::to_string(rd.welds[k].id) +
                             " is already defined at " + rd.welds[it->second].where.str());
  }
}

// Rigid parts grouped by *CONSTRAINED_RIGID_BODIES (union of merged parts): root part ->
// parts, a group named by its topmost master.
std::map<int32_t, std::vector<int32_t>> mergedGroups(const Model& m, const RigidInput& in) {
  std::vector<int32_t> parent(m.parts.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int32_t p) {
    while (parent[std::size_t(p)] != p) p = parent[std::size_t(p)];
    return p;
  };
  for (const auto& mg : in.merges) {
    const int32_t a = root(mg.master), b = root(mg.slave);
    if (a != b) parent[std::size_t(b)] = a;
  }
  std::map<int32_t, std::vector<int32_t>> groups;
  for (int32_t p = 0; p < int32_t(m.parts.size()); ++p)
    if (isRigidPart(m, p)) groups[root(p)].push_back(p);
  return groups;
}

// One body per group of rigid parts, the master's root first, in ascending root part id;
// returns the body of every part (kNone for deformable ones).
std::vector<int32_t> addPartBodies(Context& ctx, const RigidInput& in) {
  Model& m = ctx.model;
  auto groups = mergedGroups(m, in);
  std::vector<std::pair<int64_t, int32_t>> order;  // (root part id, root)
  for (const auto& [r, parts] : groups) order.emplace_back(m.parts[std::size_t(r)].id, r);
  std::sort(order.begin(), order.end());
  std::vector<int32_t> part_body(m.parts.size(), kNone);
  for (const auto& [id, r] : order) {
    RigidBodyDef b;
    b.id = id;
    b.where = m.parts[std::size_t(r)].where;
    b.parts.push_back(r);
    for (int32_t p : groups[r])
      if (p != r) b.parts.push_back(p);
    for (int32_t p : b.parts) {
      const auto& pn = ctx.partNodes(p);
      b.nodes.insert(b.nodes.end(), pn.begin(), pn.end());
    }
    const Part& master = m.parts[std::size_t(r)];
    const auto& law = std::get<RigidLaw>(m.materials[std::size_t(master.material)].law);
    if (law.cmo == 1)
      b.fixed = static_cast<uint8_t>(codeMask(law.con1) | (codeMask(law.con2) << 3));
    for (int32_t p : b.parts) {
      if (p == r) continue;
      const auto& l =
          std::get<RigidLaw>(m.materials[std::size_t(m.parts[std::size_t(p)].material)].law);
      if (l.cmo != 0)
        ctx.ignore("*MAT_RIGID", "CMO",
                   "part " + std::to_string(m.parts[std::size_t(p)].id) + " is merged into part " +
                       std::to_string(id) + ", whose constraints apply to the whole body",
                   m.parts[std::size_t(p)].where);
    }
    const auto body = static_cast<int32_t>(m.rigid.bodies.size());
    for (int32_t p : b.parts) part_body[std::size_t(p)] = body;
    m.rigid.bodies.push_back(std::move(b));
  }
  return part_body;
}

// *PART_INERTIA belongs to a rigid part that leads its body; IFLAG = 1 (merged parts and
// extra nodes updating a *PART_INERTIA) is not supported; extra nodes join their body.
void addInertiaAndExtras(Model& m, const RigidInput& in, const std::vector<int32_t>& part_body) {
  RigidDefinitions& rd = m.rigid;
  for (const auto& [pid, inertia] : in.inertia) {
    const int32_t p = m.partIndex(pid);
    if (p == kNone || !isRigidPart(m, p))
      failAt(inertia.context, "*PART_INERTIA applies to rigid parts (*MAT_RIGID) only; part " +
                                  std::to_string(pid) + " is not rigid");
    if (part_body[std::size_t(p)] == kNone) continue;
    RigidBodyDef& b = rd.bodies[std::size_t(part_body[std::size_t(p)])];
    if (b.parts.front() != p)
      failAt(inertia.context, "part " + std::to_string(pid) + " is merged into part " +
                                  std::to_string(b.id) +
                                  " (*CONSTRAINED_RIGID_BODIES): its *PART_INERTIA would be "
                                  "lost; give the inertia of the merged body on the master");
    const auto& v = inertia.values;
    b.inertia_given = true;
    b.mass = v.mass;
    b.cm = v.cm;
    b.tensor = v.tensor;
    b.velocity_given = v.velocity_given;
    b.v0 = v.v0;
    b.w0 = v.w0;
    if (inertia.cm_node != kNone) b.nodes.push_back(inertia.cm_node);
  }
  for (const auto& mg : in.merges)
    if (mg.iflag && rd.bodies[std::size_t(part_body[std::size_t(mg.master)])].inertia_given)
      failAt(mg.context,
             "updating the *PART_INERTIA of the master with the merged parts is not supported");
  for (const auto& e : in.extras) {
    RigidBodyDef& b = rd.bodies[std::size_t(part_body[std::size_t(e.part)])];
    if (e.iflag && b.inertia_given)
      failAt(e.context, "updating a *PART_INERTIA with the extra nodes is not supported");
    b.nodes.insert(b.nodes.end(), e.nodes.begin(), e.nodes.end());
  }
  for (auto& b : rd.bodies) sortUnique(b.nodes);
}

// Nodal rigid bodies after the part bodies, in ascending id.
void addNodalBodies(Model& m, RigidInput& in) {
  std::stable_sort(in.nodal.begin(), in.nodal.end(),
                   [](const auto& a, const auto& b) { return a.body.id < b.body.id; });
  for (std::size_t k = 0; k < in.nodal.size(); ++k) {
    const auto& nb = in.nodal[k];
    if (k > 0 && in.nodal[k - 1].body.id == nb.body.id)
      failAt(nb.context, "nodal rigid body " + std::to_string(nb.body.id) +
                             " is already defined at " + in.nodal[k - 1].body.where.str());
    // A PID that is also a *PART id is allowed: pre-processors (Oasys PRIMER) number nodal
    // rigid bodies 1, 2, ... as labels of their own beside parts of the same ids. A
    // reference by that id finds the part when it is rigid, else the nodal body (bodyOf).
    if (nb.body.nodes.empty()) failAt(nb.context, "the nodal rigid body has no nodes");
    m.rigid.bodies.push_back(nb.body);
  }
}

// Rigid parts without elements or extra nodes move nothing: no body. Renumbers part_body.
void dropEmptyBodies(RigidDefinitions& rd, std::vector<int32_t>& part_body) {
  std::vector<int32_t> renumber(rd.bodies.size(), kNone);
  std::vector<RigidBodyDef> kept;
  for (std::size_t k = 0; k < rd.bodies.size(); ++k)
    if (!rd.bodies[k].nodes.empty()) {
      renumber[k] = static_cast<int32_t>(kept.size());
      kept.push_back(std::move(rd.bodies[k]));
    }
  rd.bodies = std::move(kept);
  for (auto& b : part_body)
    if (b != kNone) b = renumber[std::size_t(b)];
}

// The body of a rigid part or nodal rigid body named by `pid` (prescribed motion, loads,
// joint stiffness).
int32_t bodyOf(const Model& m, int64_t pid, const std::vector<int32_t>& part_body,
               const std::string& context) {
  const RigidDefinitions& rd = m.rigid;
  const int32_t p = m.partIndex(pid);
  if (p != kNone && isRigidPart(m, p)) return part_body[std::size_t(p)];
  for (std::size_t k = 0; k < rd.bodies.size(); ++k)
    if (rd.bodies[k].nodal && rd.bodies[k].id == pid) return int32_t(k);
  if (p != kNone) failAt(context, "part " + std::to_string(pid) + " is not rigid (*MAT_RIGID)");
  failAt(context, "part or nodal rigid body " + std::to_string(pid) + " is not defined");
}

// Prescribed rigid motion, body loads and joint stiffnesses find their bodies.
void attachMotions(Model& m, const RigidInput& in, const std::vector<int32_t>& part_body) {
  RigidDefinitions& rd = m.rigid;
  for (const auto& mo : in.motions)
    if (const int32_t body = bodyOf(m, mo.pid, part_body, mo.context); body != kNone)
      rd.bodies[std::size_t(body)].motions.push_back(mo.motion);
  for (const auto& l : in.loads)
    if (const int32_t body = bodyOf(m, l.pid, part_body, l.context); body != kNone) {
      rd.loads.push_back(l.load);
      rd.loads.back().body = body;
    }
  for (const auto& s : in.stiffness) {
    JointStiffnessDef d = s.def;
    d.body_a = bodyOf(m, s.pid_a, part_body, s.context_a);
    d.body_b = bodyOf(m, s.pid_b, part_body, s.context_b);
    if (d.body_a == kNone || d.body_b == kNone)
      failAt(d.body_a == kNone ? s.context_a : s.context_b, "the rigid part has no nodes");
    if (d.body_a == d.body_b)
      failAt(s.context_b, "PIDA and PIDB are the same rigid body: the joint turns nothing");
    rd.joint_stiffness.push_back(d);
  }
}

// One constraint per node: the body, weld or tied set of every node.
std::vector<Owner> claimNodes(const Model& m) {
  const RigidDefinitions& rd = m.rigid;
  std::vector<Owner> owner(m.nodes.size());
  auto claim = [&](const std::vector<int32_t>& nodes, Owner o, const util::SourceLoc& where) {
    for (int32_t n : nodes) {
      Owner& cur = owner[std::size_t(n)];
      if (cur.kind != Owner::None)
        throw util::InputError(where.str() + ": node " +
                               std::to_string(m.nodes.id[std::size_t(n)]) + " belongs to " +
                               describe(m, cur) + " and to " + describe(m, o) +
                               (cur.kind == Owner::Body && o.kind == Owner::Body
                                    ? "; merge rigid bodies with *CONSTRAINED_RIGID_BODIES"
                                    : "; a node may take one rigid-body or nodal constraint only"));
      cur = o;
    }
  };
  for (std::size_t k = 0; k < rd.bodies.size(); ++k)
    claim(rd.bodies[k].nodes, {Owner::Body, int32_t(k)}, rd.bodies[k].where);
  for (std::size_t k = 0; k < rd.welds.size(); ++k)
    claim(rd.welds[k].nodes, {Owner::Weld, int32_t(k)}, rd.welds[k].where);
  for (std::size_t k = 0; k < rd.node_sets.size(); ++k)
    claim(rd.node_sets[k].nodes, {Owner::NodeSet, int32_t(k)}, rd.node_sets[k].where);
  return owner;
}

// SPCs on rigid-body nodes become constraints of the body's centre of mass, as LS-DYNA
// converts them; on weld and tied nodes they would fight the constraint.
void convertSpcs(Context& ctx, const std::vector<Owner>& owner) {
  const Model& m = ctx.model;
  RigidDefinitions& rd = ctx.model.rigid;
  std::vector<char> noted(rd.bodies.size(), 0);
  for (auto it = ctx.spc_masks.begin(); it != ctx.spc_masks.end();) {
    const auto [node, mask] = *it;
    const Owner o = owner[std::size_t(node)];
    const std::string nid = std::to_string(m.nodes.id[std::size_t(node)]);
    if (o.kind == Owner::Body && mask) {
      auto& b = rd.bodies[std::size_t(o.index)];
      b.fixed |= mask;
      if (!noted[std::size_t(o.index)]++)
        ctx.ignore("*BOUNDARY_SPC", "NID",
                   "node " + nid + " of " + describe(m, o) +
                       ": nodal constraints of a rigid body constrain its centre of mass "
                       "instead (as LS-DYNA converts them)",
                   b.where);
      it = ctx.spc_masks.erase(it);
      continue;
    }
    const bool conflict =
        (o.kind == Owner::Weld && mask) ||
        (o.kind == Owner::NodeSet && (mask & rd.node_sets[std::size_t(o.index)].dofs));
    if (conflict)
      throw util::InputError(
          (o.kind == Owner::Weld ? rd.welds[std::size_t(o.index)].where
                                 : rd.node_sets[std::size_t(o.index)].where)
              .str() +
          ": node " + nid + " of " + describe(m, o) +
          " also has a single-point constraint (*BOUNDARY_SPC or *NODE TC/RC); a constrained "
          "node may not take further constraints");
    ++it;
  }
}

// Nodal prescribed motion on a constrained node would fight the constraint.
void checkPrescribedNodes(const Model& m, const std::vector<Owner>& owner) {
  const RigidDefinitions& rd = m.rigid;
  for (const auto& pm : m.prescribed) {
    const Owner o = owner[std::size_t(pm.node)];
    const bool conflict =
        o.kind == Owner::Body || o.kind == Owner::Weld ||
        (o.kind == Owner::NodeSet && (rd.node_sets[std::size_t(o.index)].dofs & (1u << pm.dof)));
    if (!conflict) continue;
    const std::string nid = std::to_string(m.nodes.id[std::size_t(pm.node)]);
    throw util::InputError(
        "*BOUNDARY_PRESCRIBED_MOTION: node " + nid + " belongs to " + describe(m, o) +
        (o.kind == Owner::Body
             ? "; prescribe the motion of a rigid body with *BOUNDARY_PRESCRIBED_MOTION_RIGID"
             : "; a constrained node may not take a prescribed motion"));
  }
}

// A cylindrical or translational joint carries its axis on body A and slides along it on
// body B: both ends of every pair belong to rigid bodies (Keyword Manual, *CONSTRAINED_JOINT:
// a joint between two rigid bodies); spherical and revolute joints also pull deformable nodes.
void checkSlidingJoints(const Model& m, const std::vector<Owner>& owner) {
  for (const JointDef& j : m.rigid.joints) {
    if (!j.slides()) continue;
    for (const auto& pair : j.pairs)
      for (int32_t n : pair)
        if (owner[std::size_t(n)].kind != Owner::Body)
          throw util::InputError(j.where.str() + ": joint " + std::to_string(j.id) + ": node " +
                                 std::to_string(m.nodes.id[std::size_t(n)]) +
                                 " belongs to no rigid body; a cylindrical or translational "
                                 "joint joins two rigid bodies");
  }
}

}  // namespace

void finishRigid(Context& ctx) {
  Model& m = ctx.model;
  RigidInput& in = input(ctx);
  checkWeldIds(m.rigid, in);
  std::vector<int32_t> part_body = addPartBodies(ctx, in);
  addInertiaAndExtras(m, in, part_body);
  addNodalBodies(m, in);
  dropEmptyBodies(m.rigid, part_body);
  attachMotions(m, in, part_body);
  const std::vector<Owner> owner = claimNodes(m);
  convertSpcs(ctx, owner);
  checkPrescribedNodes(m, owner);
  checkSlidingJoints(m, owner);
}

}  // namespace crumple::model::build
