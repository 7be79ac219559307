// Meaning of boundary conditions, loads, initial conditions and rigid walls:
// *BOUNDARY_SPC, *BOUNDARY_PRESCRIBED_MOTION, *INITIAL_VELOCITY(_NODE, _GENERATION),
// *LOAD_NODE, *LOAD_SEGMENT(_SET), *LOAD_BODY_X/Y/Z, *RIGIDWALL_PLANAR (LS-DYNA Keyword
// Manual Vol. I).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include "model/build_context.hpp"
#include "util/vec3.hpp"

namespace crumple::model::build {

namespace {

using deck::Card;
using deck::CardCursor;
using deck::keywordSpec;

using util::cross;
using util::dot;
using util::scale;
using util::sub;
using util::unit;

std::vector<int32_t> allNodes(const Model& m) {
  std::vector<int32_t> v(m.nodes.size());
  std::iota(v.begin(), v.end(), 0);
  return v;
}

// The nodes a _NODE or _SET card names in its first field.
std::vector<int32_t> nodesOf(Context& ctx, const Card& c, std::string_view field, bool set) {
  const int64_t id = c.integer(field);
  if (set) return ctx.nodeSet(c, field, id);
  return {ctx.node(c, field, id)};
}

// A vector given by its components in a local system: sum_i v_i e_i.
Vec3 toGlobal(const Frame& f, const Vec3& v) {
  Vec3 g{};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) g[k] += v[i] * f.axis[std::size_t(i)][std::size_t(k)];
  return g;
}

void checkNoLocalSystem(Context& ctx, const Card& c, std::string_view field) {
  if (c.integer(field) != 0)
    ctx.reject(c, field, "a local coordinate system is not supported here");
}

}  // namespace

void readSpc(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const bool set = opts.has("SET");
  const auto& spec = keywordSpec(set ? "*BOUNDARY_SPC_SET" : "*BOUNDARY_SPC");
  const std::string_view first = set ? "NSID" : "NID";
  CardCursor cur(kw, ctx.deck);
  static constexpr std::string_view kDof[6] = {"DOFX", "DOFY", "DOFZ", "DOFRX", "DOFRY", "DOFRZ"};
  // _ID: a heading card precedes every record (Keyword Manual, *BOUNDARY_SPC).
  while (nextRecord(cur, opts.has("ID"))) {
    if (opts.has("ID")) cur.read(spec.card("id card"));
    const Card& c = cur.read(spec.card("card 1"));
    checkNoLocalSystem(ctx, c, "CID");
    DofMask mask = 0;
    for (int k = 0; k < 6; ++k) {
      const int64_t v = c.integer(kDof[k]);
      if (v != 0 && v != 1) c.fail(kDof[k], "must be 0 (free) or 1 (constrained)");
      if (v) mask = static_cast<DofMask>(mask | (1u << k));
    }
    for (int32_t n : nodesOf(ctx, c, first, set)) ctx.spc_masks[n] |= mask;
    ctx.collect(cur);
  }
}

std::optional<MotionCurve> readMotionCurve(Context& ctx, const Card& c) {
  // VAD 0 velocity, 1 acceleration, 2 displacement.
  const int64_t vad = c.integer("VAD");
  if (vad < 0 || vad > 2) {
    ctx.reject(c, "VAD", "VAD " + std::to_string(vad) + " is not supported (0, 1, 2 are)");
    return std::nullopt;
  }
  MotionCurve m;
  m.vad = static_cast<int>(vad);
  m.curve = ctx.curve(c, "LCID", c.integer("LCID"));
  m.sf = c.real("SF");
  c.integer("VID");  // DOF 4 reads it (translationAxis); marked here for the other DOFs
  const double death = c.real("DEATH");
  m.death = death >= 1e28 ? std::numeric_limits<double>::infinity() : death;
  m.birth = c.real("BIRTH");
  if (m.birth >= m.death) c.fail("DEATH", "the motion ends before it begins (BIRTH)");
  return m;
}

std::optional<std::pair<int, double>> translationAxis(Context& ctx, const Card& c, int64_t dof) {
  if (dof != 4) return std::make_pair(static_cast<int>(dof - 1), 1.0);
  const int64_t vid = c.integer("VID");
  if (vid == 0) c.fail("VID", "DOF 4 moves along a vector: VID is required");
  const auto it = ctx.vectors.find(vid);
  if (it == ctx.vectors.end()) c.fail("VID", ctx.undefinedMessage(Kind::Vector, vid));
  const Vec3& v = it->second;
  for (int axis = 0; axis < 3; ++axis)
    if (v[(axis + 1) % 3] == 0.0 && v[(axis + 2) % 3] == 0.0)
      return std::make_pair(axis, v[axis] > 0 ? 1.0 : -1.0);
  ctx.reject(c, "VID",
             "DOF 4 along a vector that is not a global axis is not supported (motion normal to "
             "it would need local axes)");
  return std::nullopt;
}

void readPrescribedMotion(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const bool set = opts.has("SET");
  const auto& spec =
      keywordSpec(set ? "*BOUNDARY_PRESCRIBED_MOTION_SET" : "*BOUNDARY_PRESCRIBED_MOTION");
  const std::string_view first = set ? "NSID" : "NID";
  CardCursor cur(kw, ctx.deck);
  // _ID: a heading card precedes every record (Keyword Manual, *BOUNDARY_PRESCRIBED_MOTION).
  while (nextRecord(cur, opts.has("ID"))) {
    if (opts.has("ID")) cur.read(spec.card("id card"));
    const Card& c = cur.read(spec.card("card 1"));
    PrescribedMotion pm;
    // DOF 1-3: x, y, z translation. The others (motion along a vector, rotations, radial
    // motion) are not supported.
    const int64_t dof = c.integer("DOF");
    if (dof < 1 || dof > 4) {
      ctx.reject(c, "DOF", "DOF " + std::to_string(dof) + " is not supported (1 to 4 are)");
      ctx.collect(cur);
      continue;
    }
    const auto axis = translationAxis(ctx, c, dof);
    if (!axis) {
      ctx.collect(cur);
      continue;
    }
    pm.dof = axis->first;
    const double sign = axis->second;
    const auto motion = readMotionCurve(ctx, c);
    if (!motion) {
      ctx.collect(cur);
      continue;
    }
    pm.kind = static_cast<MotionKind>(motion->vad);
    pm.curve = motion->curve;
    pm.sf = sign * motion->sf;
    pm.death = motion->death;
    pm.birth = motion->birth;
    for (int32_t n : nodesOf(ctx, c, first, set)) {
      pm.node = n;
      ctx.model.prescribed.push_back(pm);
    }
    ctx.collect(cur);
  }
}

namespace {

// The angular velocity of a node's rotational freedoms (those of shell and beam nodes; a solid
// node has none, and the solver leaves it out).
void setAngularVelocity(Model& m, int32_t node, const Vec3& w) {
  if (m.initial_angular_velocity.empty()) {
    if (w == Vec3{}) return;
    m.initial_angular_velocity.assign(m.nodes.size(), Vec3{});
  }
  m.initial_angular_velocity[static_cast<std::size_t>(node)] = w;
}

}  // namespace

// NSID 0 means all nodes; the nodes of NSIDEX take the velocities of card 3 instead
// (Keyword Manual, *INITIAL_VELOCITY). VXR-VZR set the rotational freedoms (shell and beam
// nodes).
void readInitialVelocity(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*INITIAL_VELOCITY");
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.read(spec.card("card 1"));
  const Card& c2 = cur.readOptional(spec.card("card 2"));
  const int64_t nsid = c.integer("NSID"), nsidex = c.integer("NSIDEX");
  const Card& c3 = nsidex != 0 ? cur.readOptional(spec.card("card 3")) : c2;
  checkNoLocalSystem(ctx, c, "ICID");
  std::vector<int32_t> nodes = nsid == 0 ? allNodes(ctx.model) : ctx.nodeSet(c, "NSID", nsid);
  std::vector<char> exempt(ctx.model.nodes.size(), 0);
  if (nsidex != 0)
    for (int32_t n : ctx.nodeSet(c, "NSIDEX", nsidex)) exempt[n] = 1;
  const Box* box = nullptr;
  if (const int64_t b = c.integer("BOXID"); b != 0) box = &ctx.box(c, "BOXID", b);
  const Vec3 v{c2.real("VX"), c2.real("VY"), c2.real("VZ")};
  const Vec3 w{c2.real("VXR"), c2.real("VYR"), c2.real("VZR")};
  const Vec3 ve = nsidex != 0 ? Vec3{c3.real("VXE"), c3.real("VYE"), c3.real("VZE")} : v;
  const Vec3 we = nsidex != 0 ? Vec3{c3.real("VXRE"), c3.real("VYRE"), c3.real("VZRE")} : w;
  for (int32_t n : nodes) {
    if (box && !box->contains(ctx.model.nodes.x[n])) continue;
    ctx.model.initial_velocity[n] = exempt[n] ? ve : v;
    setAngularVelocity(ctx.model, n, exempt[n] ? we : w);
  }
  ctx.collect(cur);
}

void readInitialVelocityNode(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*INITIAL_VELOCITY_NODE").card("card 1");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec);
    checkNoLocalSystem(ctx, c, "ICID");
    const int32_t n = ctx.node(c, "NID", c.integer("NID"));
    ctx.model.initial_velocity[n] = {c.real("VX"), c.real("VY"), c.real("VZ")};
    setAngularVelocity(ctx.model, n, {c.real("VXR"), c.real("VYR"), c.real("VZR")});
    ctx.collect(cur);
  }
}

// v = (VX, VY, VZ) + OMEGA n x (x - xc), n the unit axis through (XC, YC, ZC), and the
// rotational freedoms spin at OMEGA n (Keyword Manual, *INITIAL_VELOCITY_GENERATION: "both
// translational and rotational initial velocities": the body turns as a rigid one, so a shell
// or beam starts without bending rate); STYP 1 part set, 2 part, 3 node set. With
// ICID the velocity (VX, VY, VZ) and the axis direction (NX, NY, NZ) are components in that
// *DEFINE_COORDINATE_SYSTEM; the centre (XC, YC, ZC) stays global (Keyword Manual, ICID).
void readInitialVelocityGeneration(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*INITIAL_VELOCITY_GENERATION");
  CardCursor cur(kw, ctx.deck);
  const Card& c = cur.read(spec.card("card 1"));
  const Card& c2 = cur.readOptional(spec.card("card 2"));
  const int64_t id = c.integer("ID");
  std::vector<int32_t> nodes;
  switch (c.integer("STYP")) {
    case 1:
      for (int32_t p : ctx.partSet(c, "ID", id)) {
        const auto& pn = ctx.partNodes(p);
        nodes.insert(nodes.end(), pn.begin(), pn.end());
      }
      break;
    case 2:
      nodes = ctx.partNodes(ctx.part(c, "ID", id));
      break;
    case 3:
      nodes = ctx.nodeSet(c, "ID", id);
      break;
    default:
      c.fail("STYP", "must be 1 (part set), 2 (part) or 3 (node set)");
  }
  const double omega = c.real("OMEGA");
  Vec3 vt{c.real("VX"), c.real("VY"), c.real("VZ")};
  const Vec3 xc{c2.real("XC"), c2.real("YC"), c2.real("ZC")};
  Vec3 dir{c2.real("NX"), c2.real("NY"), c2.real("NZ")};
  if (const int64_t icid = c.integer("ICID"); icid != 0) {
    const Frame& f = ctx.frame(c, "ICID", icid);
    vt = toGlobal(f, vt);
    dir = toGlobal(f, dir);
  }
  const Vec3 axis = unit(dir);
  if (omega != 0.0 && dot(axis, axis) == 0.0)
    c2.fail("NX", "the rotation axis (NX, NY, NZ) is zero");
  for (int32_t n : nodes) {
    const Vec3 w = cross(axis, sub(ctx.model.nodes.x[n], xc));
    ctx.model.initial_velocity[n] = {vt[0] + omega * w[0], vt[1] + omega * w[1],
                                     vt[2] + omega * w[2]};
    setAngularVelocity(ctx.model, n, scale(axis, omega));
  }
  ctx.collect(cur);
}

// DOF 1-3: force along x, y, z, or along the local axis of CID (split into global
// components, which is exact for a load of fixed direction).
void readLoadNode(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const bool set = opts.has("SET");
  const auto& spec = keywordSpec(set ? "*LOAD_NODE_SET" : "*LOAD_NODE").card("card 1");
  const std::string_view first = set ? "NSID" : "NID";
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec);
    const int64_t dof = c.integer("DOF");
    if (dof < 1 || dof > 3) {
      ctx.reject(c, "DOF", "DOF " + std::to_string(dof) + " is not supported (1, 2, 3 are)");
      ctx.collect(cur);
      continue;
    }
    const int32_t curve = ctx.curve(c, "LCID", c.integer("LCID"));
    const double sf = c.real("SF");
    Vec3 dir{};
    dir[dof - 1] = 1.0;
    if (const int64_t cid = c.integer("CID"); cid != 0)
      dir = ctx.frame(c, "CID", cid).axis[dof - 1];
    for (int32_t n : nodesOf(ctx, c, first, set))
      for (int i = 0; i < 3; ++i)
        if (dir[i] != 0.0) ctx.model.nodal_loads.push_back({n, i, curve, sf * dir[i]});
    ctx.collect(cur);
  }
}

// *ELEMENT_MASS: a lumped mass on a node (Keyword Manual, *ELEMENT_MASS). The part id only
// groups masses for LS-DYNA's own summaries; Crumple adds the mass to the node.
void readElementMass(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*ELEMENT_MASS").card("card 1");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec);
    if (c.integer("EID") <= 0) c.fail("EID", "must be a positive id");
    const int32_t node = ctx.node(c, "NID", c.integer("NID"));
    const double mass = c.real("MASS");
    if (!(mass >= 0.0)) c.fail("MASS", "must not be negative");
    if (c.integer("PID") != 0)
      ctx.ignore(kw.name, "PID", "mass elements are not grouped by part in matsum", c.where());
    ctx.model.point_masses.push_back({node, mass});
    ctx.collect(cur);
  }
}

namespace {
std::array<int32_t, 4> segmentNodes(Context& ctx, const Card& c) {
  static constexpr std::string_view kN[4] = {"N1", "N2", "N3", "N4"};
  std::array<int32_t, 4> s{};
  for (int k = 0; k < 4; ++k) {
    int64_t id = c.integer(kN[k]);
    if (k == 3 && id == 0) id = c.integer("N3");  // triangle: N4 = N3
    if (id == 0) c.fail(kN[k], "node id missing");
    s[k] = ctx.node(c, kN[k], id);
  }
  return s;
}
}  // namespace

void readLoadSegment(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*LOAD_SEGMENT").card("card 1");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec);
    PressureLoad p;
    p.curve = ctx.curve(c, "LCID", c.integer("LCID"));
    p.sf = c.real("SF");
    p.at = c.real("AT");
    p.nodes = segmentNodes(ctx, c);
    ctx.model.pressure_loads.push_back(p);
    ctx.collect(cur);
  }
}

void readLoadSegmentSet(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*LOAD_SEGMENT_SET").card("card 1");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec);
    PressureLoad p;
    p.curve = ctx.curve(c, "LCID", c.integer("LCID"));
    p.sf = c.real("SF");
    p.at = c.real("AT");
    for (const auto& s : ctx.segmentSet(c, "SSID", c.integer("SSID"))) {
      p.nodes = s;
      ctx.model.pressure_loads.push_back(p);
    }
    ctx.collect(cur);
  }
}

void readLoadBody(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const int dof = opts.has("X") ? 0 : opts.has("Y") ? 1 : opts.has("Z") ? 2 : -1;
  if (dof < 0 || opts.words.size() != 1) {
    ctx.rejectKeyword(kw, "give exactly one direction: *LOAD_BODY_X, _Y or _Z");
    return;
  }
  const auto& spec = keywordSpec("*LOAD_BODY").card("card 1");
  CardCursor cur(kw, ctx.deck);
  cur.skipBlankLines();
  const Card& c = cur.read(spec);
  checkNoLocalSystem(ctx, c, "CID");
  model::BodyLoad load;
  load.dof = dof;
  load.curve = ctx.curve(c, "LCID", c.integer("LCID"));
  load.sf = c.real("SF");
  if (const int64_t lciddr = c.integer("LCIDDR"); lciddr != 0)
    load.dr_curve = ctx.curve(c, "LCIDDR", lciddr);
  ctx.model.body_loads.push_back(load);
  ctx.collect(cur);
}

// Cards in the manual's order: _ID heading, cards 1-2, the _FINITE card, the _MOVING card
// (Keyword Manual, *RIGIDWALL_PLANAR).
namespace {
// Slave nodes of a rigid wall: NSID (0 = every node) less NSIDEX, inside BOXID if given.
std::vector<int32_t> wallNodes(Context& ctx, const Card& c) {
  const Model& m = ctx.model;
  const int64_t nsid = c.integer("NSID"), nsidex = c.integer("NSIDEX");
  std::vector<char> take(m.nodes.size(), nsid == 0 ? 1 : 0);
  if (nsid != 0)
    for (int32_t n : ctx.nodeSet(c, "NSID", nsid)) take[n] = 1;
  if (nsidex != 0)
    for (int32_t n : ctx.nodeSet(c, "NSIDEX", nsidex)) take[n] = 0;
  const Box* box = nullptr;
  if (const int64_t b = c.integer("BOXID"); b != 0) box = &ctx.box(c, "BOXID", b);
  std::vector<int32_t> nodes;
  for (std::size_t n = 0; n < take.size(); ++n)
    if (take[n] && (!box || box->contains(m.nodes.x[n]))) nodes.push_back(static_cast<int32_t>(n));
  return nodes;
}

// The cards every rigid wall starts with: the _ID heading, card 1 (slave nodes) and card 2
// (tail, head, FRIC). Returns card 1 for the reader's own fields.
const Card& readWallStart(Context& ctx, CardCursor& cur, const deck::KeywordSpec& spec,
                          const KeywordOptions& opts, RigidWallPlanar& w,
                          std::string_view head_problem) {
  ++ctx.rigid_wall_count;
  w.id = ctx.rigid_wall_count;
  if (opts.has("ID")) {
    const Card& id = cur.read(spec.card("id card"));
    if (!id.blank("ID")) w.id = id.integer("ID");
  }
  const Card& c = cur.read(spec.card("card 1"));
  const Card& c2 = cur.read(spec.card("card 2"));
  w.where = c.where();
  w.nodes = wallNodes(ctx, c);
  w.tail = {c2.real("XT"), c2.real("YT"), c2.real("ZT")};
  w.normal = unit(sub({c2.real("XH"), c2.real("YH"), c2.real("ZH")}, w.tail));
  if (dot(w.normal, w.normal) == 0.0) c2.fail("XH", head_problem);
  w.fric = c2.real("FRIC");
  if (w.fric < 0) c2.fail("FRIC", "must not be negative");
  return c;
}

// A finite rectangle in the wall: edge l from XHEV (its part normal to the wall normal), LENL
// along l and LENM along n x l (the _FINITE card of planar walls, card 3 of flat and prism).
void readFiniteEdge(const Card& f, RigidWallPlanar& w) {
  Vec3 l = sub({f.real("XHEV"), f.real("YHEV"), f.real("ZHEV")}, w.tail);
  const double ln = dot(l, w.normal);
  l = unit({l[0] - ln * w.normal[0], l[1] - ln * w.normal[1], l[2] - ln * w.normal[2]});
  if (dot(l, l) == 0.0) f.fail("XHEV", "the edge vector l is zero or along the normal");
  w.finite = true;
  w.l_axis = l;
  w.lenl = f.real("LENL");
  w.lenm = f.real("LENM");
  if (w.lenl <= 0) f.fail("LENL", "must be positive");
  if (w.lenm <= 0) f.fail("LENM", "must be positive");
}
}  // namespace

void readRigidWallPlanar(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*RIGIDWALL_PLANAR");
  CardCursor cur(kw, ctx.deck);
  RigidWallPlanar w;
  readWallStart(ctx, cur, spec, opts, w, "the head of the normal coincides with its tail");
  if (opts.has("FINITE")) readFiniteEdge(cur.read(spec.card("finite card")), w);
  if (opts.has("MOVING")) {
    const Card& mv = cur.read(spec.card("moving card"));
    w.moving = true;
    w.mass = mv.real("MASS");
    w.v0 = mv.real("V0");
    if (w.mass <= 0) mv.fail("MASS", "must be positive");
  }
  ctx.model.rigid_walls.push_back(std::move(w));
  ctx.collect(cur);
}

void readRigidWallGeometric(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  using Shape = RigidWallPlanar::Shape;
  std::string shape_word;
  for (auto w : {"FLAT", "PRISM", "CYLINDER", "SPHERE"})
    if (opts.has(w)) shape_word = w;
  if (shape_word.empty()) {
    ctx.rejectKeyword(kw, "a shape option (_FLAT, _PRISM, _CYLINDER or _SPHERE) is required");
    return;
  }
  if (opts.has("MOTION"))
    ctx.rejectKeyword(kw, "moving geometric walls (_MOTION) are not supported");
  const auto& spec = keywordSpec("*RIGIDWALL_GEOMETRIC_" + shape_word);
  CardCursor cur(kw, ctx.deck);
  RigidWallPlanar w;
  const Card& c = readWallStart(ctx, cur, spec, opts, w, "the head coincides with the tail");
  const Card& c3 = cur.read(spec.card("card 3"));
  if (c.real("BIRTH") != 0 || c.real("DEATH") != 1e20)
    ctx.reject(c, c.real("BIRTH") != 0 ? "BIRTH" : "DEATH",
               "birth and death times of geometric walls are not supported");
  if (shape_word == "FLAT" || shape_word == "PRISM") {
    readFiniteEdge(c3, w);
    if (shape_word == "PRISM") {
      w.shape = Shape::Prism;
      w.lenp = c3.real("LENP");
      if (w.lenp <= 0) c3.fail("LENP", "must be positive");
    }
  } else if (shape_word == "CYLINDER") {
    w.shape = Shape::Cylinder;
    w.radius = c3.real("RADCYL");
    w.length = c3.real("LENCYL");
    if (w.radius <= 0) c3.fail("RADCYL", "must be positive");
    if (w.length < 0) c3.fail("LENCYL", "must not be negative");
  } else {
    w.shape = Shape::Sphere;
    w.radius = c3.real("RADSPH");
    if (w.radius <= 0) c3.fail("RADSPH", "must be positive");
  }
  if (opts.has("DISPLAY")) {
    const Card& d = cur.readOptional(spec.card("display card"));
    ctx.ignore(kw.name, "display card", "drawing only: the wall is drawn by nothing here",
               d.where());
  }
  ctx.model.rigid_walls.push_back(std::move(w));
  ctx.collect(cur);
}

void finishConditions(Context& ctx) {
  for (const auto& [node, mask] : ctx.spc_masks)
    if (mask) ctx.model.spcs.push_back({node, mask});
}

}  // namespace crumple::model::build

namespace crumple::model::build {

namespace {

// The preload applies to spot-weld beams (ELFORM 9) of *MAT_SPOTWELD (Keyword Manual,
// *INITIAL_AXIAL_FORCE_BEAM); a beam of the set that is not one, or that an earlier preload
// already holds, makes the card an error naming it.
void checkPreloadedBeams(Context& ctx, const deck::Card& c, const std::vector<int32_t>& beams) {
  const Model& m = ctx.model;
  for (int32_t b : beams) {
    const Part& part = m.parts[static_cast<std::size_t>(m.beams.part[static_cast<std::size_t>(b)])];
    const bool weld =
        part.section != kNone && part.material != kNone &&
        m.beam_sections[static_cast<std::size_t>(part.section)].elform == 9 &&
        std::string_view(materialKeyword(
            m.materials[static_cast<std::size_t>(part.material)].law)) == "*MAT_SPOTWELD";
    const std::string label = "beam " + std::to_string(m.beams.id[static_cast<std::size_t>(b)]);
    if (!weld)
      c.fail("BSID", label + " (part " + std::to_string(part.id) +
                         ") is not a spot-weld beam (*SECTION_BEAM ELFORM 9 with *MAT_SPOTWELD), "
                         "the only beams the preload applies to");
    for (const auto& p : m.beam_preloads)
      if (std::binary_search(p.beams.begin(), p.beams.end(), b))
        c.fail("BSID", label + " is already preloaded at " + p.where.str());
  }
}

}  // namespace

// *INITIAL_AXIAL_FORCE_BEAM: BSID a *SET_BEAM, LCID the force vs time, SCALE its factor, KBEND
// 0 or 1 (model::BeamPreload; the kernel in src/elements/beam.cpp).
void readInitialAxialForceBeam(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*INITIAL_AXIAL_FORCE_BEAM").card("card 1");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec);
    BeamPreload p;
    p.where = c.where();
    p.beams = ctx.elementSet(Family::Beam, c, "BSID", c.integer("BSID"));
    std::sort(p.beams.begin(), p.beams.end());
    p.curve = ctx.curve(c, "LCID", c.integer("LCID"));
    p.scale = c.real("SCALE");
    const auto kbend = c.integer("KBEND");
    if (kbend != 0 && kbend != 1) c.fail("KBEND", "must be 0 or 1");
    p.kbend = kbend == 1;
    checkPreloadedBeams(ctx, c, p.beams);
    ctx.model.beam_preloads.push_back(std::move(p));
    ctx.collect(cur);
  }
}

}  // namespace crumple::model::build
