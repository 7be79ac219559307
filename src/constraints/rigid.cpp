#include "constraints/rigid.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>

#include "util/error.hpp"

namespace crumple::constraints {

namespace {

Vec3 add(const Vec3& a, const Vec3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
Vec3 sub(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 scaled(const Vec3& a, double s) {
  return {s * a[0], s * a[1], s * a[2]};
}
double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 at(const std::vector<double>& v, std::size_t i) {
  return {v[i], v[i + 1], v[i + 2]};
}
Vec3 matVec(const double a[3][3], const Vec3& v) {
  return {a[0][0] * v[0] + a[0][1] * v[1] + a[0][2] * v[2],
          a[1][0] * v[0] + a[1][1] * v[1] + a[1][2] * v[2],
          a[2][0] * v[0] + a[2][1] * v[1] + a[2][2] * v[2]};
}
Vec3 matTVec(const double a[3][3], const Vec3& v) {
  return {a[0][0] * v[0] + a[1][0] * v[1] + a[2][0] * v[2],
          a[0][1] * v[0] + a[1][1] * v[1] + a[2][1] * v[2],
          a[0][2] * v[0] + a[1][2] * v[1] + a[2][2] * v[2]};
}

// Eigenvalues (ascending) and unit eigenvectors (columns of e, a right-handed frame) of a
// symmetric 3 x 3 matrix by cyclic Jacobi rotations (Golub and Van Loan, Matrix Computations,
// sec. 8.5): a pure function of its input, so every rank gets the same frame.
void eigenSymmetric(double a[3][3], Vec3& values, double e[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) e[i][j] = i == j ? 1.0 : 0.0;
  for (int sweep = 0; sweep < 64; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off == 0.0 || off <= 1e-36 * diag) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        // A <- J^T A J with J the rotation in the (p, q) plane; E <- E J.
        for (int k = 0; k < 3; ++k) {
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {
          const double ekp = e[k][p], ekq = e[k][q];
          e[k][p] = c * ekp - s * ekq;
          e[k][q] = s * ekp + c * ekq;
        }
      }
  }
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return a[i][i] < a[j][j]; });
  double sorted[3][3];
  for (int k = 0; k < 3; ++k) {
    values[std::size_t(k)] = a[order[k]][order[k]];
    for (int i = 0; i < 3; ++i) sorted[i][k] = e[i][order[k]];
  }
  const Vec3 c0{sorted[0][0], sorted[1][0], sorted[2][0]};
  const Vec3 c1{sorted[0][1], sorted[1][1], sorted[2][1]};
  const Vec3 c2{sorted[0][2], sorted[1][2], sorted[2][2]};
  const double sign = dot(cross(c0, c1), c2) < 0 ? -1.0 : 1.0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) e[i][k] = sorted[i][k] * (k == 2 ? sign : 1.0);
}

}  // namespace

namespace {

// The work of a body's impulse (momentum change p, angular momentum change l) over a step in
// its halves (step_work.hpp): translation at V before and after, rotation at omega.
StepWork bodyWork(const Vec3& p, const Vec3& l, const Vec3& v_before, const Vec3& v_after,
                  const Vec3& w_before, const Vec3& w_after) {
  return {0.5 * (dot(p, v_before) + dot(l, w_before)), 0.5 * (dot(p, v_after) + dot(l, w_after))};
}

using Quat = std::array<double, 4>;  // w, x, y, z: q = (cos(a/2), sin(a/2) n)

Quat mul(const Quat& a, const Quat& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}
Quat normalized(const Quat& q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}
// The rotation matrix of a unit quaternion.
void matrix(const Quat& q, double r[3][3]) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  r[0][0] = 1 - 2 * (y * y + z * z);
  r[0][1] = 2 * (x * y - w * z);
  r[0][2] = 2 * (x * z + w * y);
  r[1][0] = 2 * (x * y + w * z);
  r[1][1] = 1 - 2 * (x * x + z * z);
  r[1][2] = 2 * (y * z - w * x);
  r[2][0] = 2 * (x * z - w * y);
  r[2][1] = 2 * (y * z + w * x);
  r[2][2] = 1 - 2 * (x * x + y * y);
}
// The unit quaternion of a rotation matrix (Shepperd's method: the largest of the four
// candidate divisors keeps it accurate for any angle).
Quat fromMatrix(const double r[3][3]) {
  const double tr = r[0][0] + r[1][1] + r[2][2];
  Quat q;
  if (tr >= r[0][0] && tr >= r[1][1] && tr >= r[2][2]) {
    const double s = 2.0 * std::sqrt(1.0 + tr);
    q = {0.25 * s, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s};
  } else if (r[0][0] >= r[1][1] && r[0][0] >= r[2][2]) {
    const double s = 2.0 * std::sqrt(1.0 + r[0][0] - r[1][1] - r[2][2]);
    q = {(r[2][1] - r[1][2]) / s, 0.25 * s, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s};
  } else if (r[1][1] >= r[2][2]) {
    const double s = 2.0 * std::sqrt(1.0 + r[1][1] - r[0][0] - r[2][2]);
    q = {(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, 0.25 * s, (r[1][2] + r[2][1]) / s};
  } else {
    const double s = 2.0 * std::sqrt(1.0 + r[2][2] - r[0][0] - r[1][1]);
    q = {(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, 0.25 * s};
  }
  return normalized(q);
}
// exp of a rotation vector theta (angle |theta| about theta / |theta|) as a unit quaternion;
// sin(a/2)/a by its series near 0, where the quotient loses digits.
Quat fromRotationVector(const Vec3& theta) {
  const double a = std::sqrt(dot(theta, theta));
  const double s = a < 1e-4 ? 0.5 - a * a / 48.0 : std::sin(0.5 * a) / a;
  return {std::cos(0.5 * a), s * theta[0], s * theta[1], s * theta[2]};
}
// log of a unit quaternion: the rotation vector, angle in [0, pi].
Vec3 toRotationVector(Quat q) {
  if (q[0] < 0) q = {-q[0], -q[1], -q[2], -q[3]};
  const double v = std::sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double angle = 2.0 * std::atan2(v, q[0]);
  const double f = v < 1e-12 ? 2.0 / q[0] : angle / v;
  return {f * q[1], f * q[2], f * q[3]};
}
Quat conjugate(const Quat& q) {
  return {q[0], -q[1], -q[2], -q[3]};
}

// The symmetric tensor (xx, xy, xz, yy, yz, zz) as a matrix.
void tensorMatrix(const std::array<double, 6>& t, double j[3][3]) {
  const double m[3][3] = {{t[0], t[1], t[2]}, {t[1], t[3], t[4]}, {t[2], t[4], t[5]}};
  std::copy(&m[0][0], &m[0][0] + 9, &j[0][0]);
}

// Records are keyed (group, model node) so that one sort gives every group its nodes in
// ascending model node order.
int64_t recordKey(int32_t group, int32_t node) {
  return (int64_t(group) << 32) | int64_t(uint32_t(node));
}
int32_t recordGroup(int64_t key) {
  return static_cast<int32_t>(key >> 32);
}

// Every rank's records on every rank; per group, the offsets of its records' values in
// ascending model node order. width(group) is the number of values of a record.
template <class Width>
std::vector<std::vector<std::size_t>> gatherRecords(const std::vector<int64_t>& keys,
                                                    const std::vector<double>& values,
                                                    std::size_t groups, Width width,
                                                    const comm::Communicator& comm,
                                                    std::vector<double>& all_values) {
  const std::vector<int64_t> all_keys = comm.allGather(keys);
  all_values = comm.allGather(values);
  std::vector<std::size_t> first(all_keys.size());
  std::size_t offset = 0;
  for (std::size_t k = 0; k < all_keys.size(); ++k) {
    first[k] = offset;
    offset += std::size_t(width(recordGroup(all_keys[k])));
  }
  if (offset != all_values.size())
    throw std::logic_error("rigid bodies: gathered records and values disagree");
  std::vector<std::size_t> order(all_keys.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return all_keys[a] < all_keys[b]; });
  std::vector<std::vector<std::size_t>> per_group(groups);
  for (std::size_t k : order)
    per_group[static_cast<std::size_t>(recordGroup(all_keys[k]))].push_back(first[k]);
  return per_group;
}

const model::Curve* curveOf(const model::Model& m, int32_t index) {
  return index < 0 ? nullptr : &m.curves[static_cast<std::size_t>(index)];
}

std::string bodyName(const model::RigidBodyDef& d) {
  return d.nodal ? "nodal rigid body " + std::to_string(d.id)
                 : "the rigid body of part " + std::to_string(d.id);
}

// Values per node gathered at set-up: mass, x (3), v (3), rotational inertia.
constexpr int kSetupWidth = 8;
// Per cycle: a body's node sends f (3) and its moment about the centre (3); a weld's node
// also its v(n-1/2) (3) and mass, from which every rank finds the weld's force on it; a tied
// node sends m v (3).
constexpr int kBodyWidth = 6, kWeldWidth = 10, kSetWidth = 3;

}  // namespace

Vec3 RigidBodies::angularMomentum(const Body& b, const Quat& q, const Vec3& w) {
  double r[3][3];
  matrix(q, r);
  const Vec3 wb = matTVec(r, w);
  return matVec(r, {b.inertia[0] * wb[0], b.inertia[1] * wb[1], b.inertia[2] * wb[2]});
}

void RigidBodies::inverseInertia(const Body& b, const Quat& q, double a[3][3]) {
  double r[3][3];
  matrix(q, r);
  const double largest = std::max({b.inertia[0], b.inertia[1], b.inertia[2]});
  Vec3 inv{};
  for (int k = 0; k < 3; ++k)
    inv[std::size_t(k)] = b.inertia[std::size_t(k)] > 1e-12 * largest && largest > 0.0
                              ? 1.0 / b.inertia[std::size_t(k)]
                              : 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      a[i][j] =
          r[i][0] * inv[0] * r[j][0] + r[i][1] * inv[1] * r[j][1] + r[i][2] * inv[2] * r[j][2];
}

int RigidBodies::width(int32_t group) const {
  if (static_cast<std::size_t>(group) >= bodies_.size()) return kSetWidth;
  return bodies_[static_cast<std::size_t>(group)].weld ? kWeldWidth : kBodyWidth;
}

RigidBodies::RigidBodies(const model::Model& m, const domain::Subdomain& sd,
                         const comm::Communicator& comm) {
  if (m.rigid.empty()) return;
  makeGroups(m, sd);
  initBodies(m, sd, comm);
  initJoints(m, sd, comm);
  initLoads(m);
}

// The bodies, welds and tied sets of the model, and the group (body or set) of every local
// node with the nodes of each group.
void RigidBodies::makeGroups(const model::Model& m, const domain::Subdomain& sd) {
  const auto& rd = m.rigid;
  const std::size_t nn = sd.numNodes();
  group_.assign(nn, -1);
  in_body_.assign(nn, 0);
  auto mark = [&](const std::vector<int32_t>& nodes, std::size_t group) {
    for (int32_t mn : nodes)
      if (const int32_t n = sd.localNode(mn); n != model::kNone)
        group_[static_cast<std::size_t>(n)] = static_cast<int32_t>(group);
  };
  for (const auto& d : rd.bodies) {
    Body b;
    b.id = d.id;
    b.kind = d.nodal ? RigidBodyState::Kind::Nodal : RigidBodyState::Kind::Part;
    b.fixed = d.fixed;
    for (const auto& mo : d.motions)
      b.motions.push_back({mo.dof, static_cast<model::MotionKind>(mo.kind), curveOf(m, mo.curve),
                           mo.sf, mo.birth, mo.death});
    mark(d.nodes, bodies_.size());
    bodies_.push_back(std::move(b));
  }
  for (const auto& w : rd.welds) {
    Body b;
    b.id = w.id;
    b.kind = RigidBodyState::Kind::Weld;
    b.weld = true;
    b.sn = w.sn;
    b.ss = w.ss;
    b.n = w.n;
    b.m = w.m;
    b.tfail = w.tfail;
    mark(w.nodes, bodies_.size());
    bodies_.push_back(std::move(b));
  }
  for (const auto& t : rd.node_sets) {
    TiedSet ts;
    ts.dofs = t.dofs;
    ts.tfail = t.tfail;
    mark(t.nodes, bodies_.size() + sets_.size());
    sets_.push_back(std::move(ts));
  }
  const std::size_t nb = bodies_.size();
  for (std::size_t n = 0; n < nn; ++n) {
    const int32_t g = group_[n];
    if (g < 0) continue;
    if (static_cast<std::size_t>(g) < nb)
      bodies_[static_cast<std::size_t>(g)].local.push_back(int32_t(n));
    else
      sets_[static_cast<std::size_t>(g) - nb].local.push_back(int32_t(n));
  }
}

// Mass, centre, inertia and momenta of every body from all its nodes, in node order (the
// same sums on every rank).
void RigidBodies::initBodies(const model::Model& m, const domain::Subdomain& sd,
                             const comm::Communicator& comm) {
  const std::size_t nn = sd.numNodes();
  const std::size_t nb = bodies_.size(), groups = nb + sets_.size();
  std::vector<int64_t> keys;
  std::vector<double> values;
  for (std::size_t n = 0; n < nn; ++n) {
    if (group_[n] < 0 || !sd.node_owned[n]) continue;
    keys.push_back(recordKey(group_[n], sd.node_model[n]));
    values.push_back(sd.mass[n]);
    for (int c = 0; c < 3; ++c) values.push_back(sd.x[3 * n + std::size_t(c)]);
    for (int c = 0; c < 3; ++c) values.push_back(sd.v[3 * n + std::size_t(c)]);
    values.push_back(sd.rotations ? sd.inertia[n] : 0.0);
  }
  std::vector<double> all;
  const auto recs = gatherRecords(
      keys, values, groups, [](int32_t) { return kSetupWidth; }, comm, all);

  for (std::size_t g = 0; g < nb; ++g) {
    const model::RigidBodyDef* def = g < m.rigid.bodies.size() ? &m.rigid.bodies[g] : nullptr;
    initBody(bodies_[g], def, m, sd, recs[g], all);
  }
  for (std::size_t k = 0; k < sets_.size(); ++k)
    for (std::size_t off : recs[nb + k]) sets_[k].mass += all[off];
}

void RigidBodies::initBody(Body& b, const model::RigidBodyDef* def, const model::Model& m,
                           const domain::Subdomain& sd, const std::vector<std::size_t>& rec,
                           const std::vector<double>& all) {
  const auto& rd = m.rigid;
  const std::size_t g = static_cast<std::size_t>(&b - bodies_.data());
  const std::string name = def ? bodyName(*def)
                               : "spot weld " + std::to_string(b.id) + " (" +
                                     rd.welds[g - rd.bodies.size()].where.str() + ")";
  double mass = 0.0;
  Vec3 s{}, p{};
  for (std::size_t off : rec) {
    const double mi = all[off];
    mass += mi;
    for (int c = 0; c < 3; ++c) {
      s[std::size_t(c)] += mi * all[off + 1 + std::size_t(c)];
      p[std::size_t(c)] += mi * all[off + 4 + std::size_t(c)];
    }
  }
  const bool given = def && def->inertia_given;
  if (!(mass > 0.0) && !given)
    throw util::InputError(name + " has no mass: its nodes carry no element or *ELEMENT_MASS");
  const Vec3 cm_nodes = mass > 0.0 ? scaled(s, 1.0 / mass) : Vec3{};
  // J = sum m (|r|^2 I - r r^T) + nodal rotational inertia, about the centre
  // (LS-DYNA Theory Manual, "Rigid Body Dynamics"); L = sum m r x v.
  double j[3][3] = {};
  Vec3 l_nodes{};
  for (std::size_t off : rec) {
    const double mi = all[off];
    const Vec3 r = sub(at(all, off + 1), cm_nodes);
    const double r2 = dot(r, r);
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        j[a][c] += mi * ((a == c ? r2 : 0.0) - r[std::size_t(a)] * r[std::size_t(c)]) +
                   (a == c ? all[off + 7] : 0.0);
    l_nodes = add(l_nodes, scaled(cross(r, at(all, off + 4)), mi));
  }
  Vec3 V0 = mass > 0.0 ? scaled(p, 1.0 / mass) : Vec3{};
  if (given) {
    // *PART_INERTIA: the nodes' motion (V0, omega0 about their own centre) carried over to
    // the given centre and inertia.
    double jn[3][3];
    std::copy(&j[0][0], &j[0][0] + 9, &jn[0][0]);
    Body nodes_body;
    double e[3][3];
    eigenSymmetric(jn, nodes_body.inertia, e);
    nodes_body.q = fromMatrix(e);
    double a[3][3];
    inverseInertia(nodes_body, nodes_body.q, a);
    const Vec3 w0 = matVec(a, l_nodes);
    b.mass = def->mass;
    b.x_cm = def->cm;
    tensorMatrix(def->tensor, j);
    V0 = add(V0, cross(w0, sub(b.x_cm, cm_nodes)));
    b.L = matVec(j, w0);
  } else {
    b.mass = mass;
    b.x_cm = cm_nodes;
    b.L = l_nodes;
  }
  b.V = V0;
  if (def && def->velocity_given) {
    b.V = def->v0;
    b.L = matVec(j, def->w0);
  }
  double e[3][3];
  eigenSymmetric(j, b.inertia, e);
  b.q = fromMatrix(e);
  // CMO constraints hold from the start: L = J w with the constrained components of w zero.
  for (int c = 0; c < 3; ++c)
    if (b.fixed & (1u << c)) b.V[std::size_t(c)] = 0.0;
  if (b.fixed & 070) {
    double a[3][3];
    inverseInertia(b, b.q, a);
    Vec3 w = matVec(a, b.L);
    for (int c = 0; c < 3; ++c)
      if (b.fixed & (8u << c)) w[std::size_t(c)] = 0.0;
    b.L = angularMomentum(b, b.q, w);
  }
  b.x_cm0 = b.x_cm;
  b.x_cm_prev = b.x_cm;
  b.q_prev = b.q;
  b.V_prev = b.V;
  b.L_prev = b.L;
  double ainv[3][3];
  inverseInertia(b, b.q, ainv);
  b.omega = matVec(ainv, b.L);
  b.V_init = b.V;
  b.omega_init = b.omega;
  double r[3][3];
  matrix(b.q, r);
  for (int32_t n : b.local) {
    b.X.push_back(matTVec(r, sub(at(sd.x, 3 * std::size_t(n)), b.x_cm)));
    in_body_[static_cast<std::size_t>(n)] = 1;
  }
  if (b.weld)
    for (std::size_t off : rec) b.all_X.push_back(matTVec(r, sub(at(all, off + 1), b.x_cm)));
}

// Joints: the mass behind each side of each pair (its body's, or the node's own).
void RigidBodies::initJoints(const model::Model& m, const domain::Subdomain& sd,
                             const comm::Communicator& comm) {
  const std::size_t nb = bodies_.size();
  std::vector<int64_t> keys;
  std::vector<double> values, all;
  for (const auto& j : m.rigid.joints) {
    const std::size_t first = joints_.size();
    for (const auto& pair : j.pairs) {
      JointPair jp;
      jp.node = pair;
      for (int s = 0; s < 2; ++s) jp.local[std::size_t(s)] = sd.localNode(pair[std::size_t(s)]);
      jp.rps = j.rps;
      jp.damp = j.damp;
      jp.across = j.slides();
      jp.axis = first;
      pair_joint_.push_back(int32_t(joint_states_.size()));
      joints_.push_back(jp);
    }
    joint_states_.push_back({j.id, {}, {}, 0.0});
  }
  if (joints_.empty()) return;
  for (std::size_t p = 0; p < joints_.size(); ++p)
    for (int s = 0; s < 2; ++s) {
      const int32_t n = joints_[p].local[std::size_t(s)];
      if (n == model::kNone || !sd.node_owned[std::size_t(n)]) continue;
      const int32_t g = group_[std::size_t(n)];
      double side_mass = sd.mass[std::size_t(n)];
      if (g >= 0 && static_cast<std::size_t>(g) < nb) {
        // A body resists a push at the node with its mass and, turning about its centre,
        // with at least I_min / |r|^2: 1 / m_point <= 1 / m + |r|^2 / I_min.
        const Body& b = bodies_[std::size_t(g)];
        const double largest = std::max({b.inertia[0], b.inertia[1], b.inertia[2]});
        double smallest = largest;
        for (double ik : b.inertia)
          if (ik > 1e-12 * largest) smallest = std::min(smallest, ik);
        const Vec3 r = sub(at(sd.x, 3 * std::size_t(n)), b.x_cm);
        side_mass = 1.0 / (1.0 / b.mass + (smallest > 0.0 ? dot(r, r) / smallest : 0.0));
        if (b.fixed == 077) side_mass = 0.0;  // a body held fixed: the other side moves alone
      }
      keys.push_back(recordKey(int32_t(2 * p) + s, joints_[p].node[std::size_t(s)]));
      values.push_back(side_mass);
    }
  const auto masses = gatherRecords(
      keys, values, 2 * joints_.size(), [](int32_t) { return 1; }, comm, all);
  for (std::size_t p = 0; p < joints_.size(); ++p) {
    const double ma = all[masses[2 * p].at(0)], mb = all[masses[2 * p + 1].at(0)];
    // 1 / m = 1 / m_a + 1 / m_b; a side of no mass (or held fixed) leaves the other's.
    joints_[p].mass = ma > 0.0 && mb > 0.0 ? ma * mb / (ma + mb) : std::max(ma, mb);
  }
}

void RigidBodies::addJointForces(double dt, double dt_velocity, domain::Subdomain& sd,
                                 const comm::Communicator& comm) {
  if (joints_.empty()) return;
  if (joints_.front().k == 0.0 && dt > 0.0)
    for (JointPair& jp : joints_) {
      jp.k = 0.5 * jp.rps * jp.mass / (dt * dt);
      jp.c = 0.2 * jp.damp * std::sqrt(jp.k * jp.mass);  // 2 zeta sqrt(k m), zeta = 0.1
    }
  std::vector<int64_t> keys;
  std::vector<double> values;
  for (std::size_t p = 0; p < joints_.size(); ++p)
    for (int s = 0; s < 2; ++s) {
      const int32_t n = joints_[p].local[std::size_t(s)];
      if (n == model::kNone || !sd.node_owned[std::size_t(n)]) continue;
      keys.push_back(recordKey(int32_t(2 * p) + s, joints_[p].node[std::size_t(s)]));
      for (int c = 0; c < 3; ++c) values.push_back(sd.x[3 * std::size_t(n) + std::size_t(c)]);
      for (int c = 0; c < 3; ++c) values.push_back(sd.v[3 * std::size_t(n) + std::size_t(c)]);
    }
  std::vector<double> all;
  const auto recs = gatherRecords(
      keys, values, 2 * joints_.size(), [](int32_t) { return 6; }, comm, all);
  double stored = 0.0;
  for (JointState& js : joint_states_) js = {js.id, {}, {}, 0.0};
  joint_nodal_.clear();
  for (std::size_t p = 0; p < joints_.size(); ++p) {
    JointPair& jp = joints_[p];
    const std::size_t a = recs[2 * p].at(0), b = recs[2 * p + 1].at(0);
    Vec3 gap = sub(at(all, b), at(all, a)), dv = sub(at(all, b + 3), at(all, a + 3));
    Vec3 couple{};  // on N3, and its opposite on N1: the axis's share of the spring's force
    if (jp.across) {
      // Free along the axis N1 -> N3 (body A's, as it is now): only the rest pulls.
      const Vec3 axis =
          sub(at(all, recs[2 * (jp.axis + 1)].at(0)), at(all, recs[2 * jp.axis].at(0)));
      const double length = std::sqrt(dot(axis, axis));
      const Vec3 e = scaled(axis, 1.0 / length);
      const double along = dot(gap, e);
      gap = sub(gap, scaled(e, along));
      dv = sub(dv, scaled(e, dot(dv, e)));
      // The spring's energy k |P g|^2 / 2 (P = I - e e) depends on the axis too: turning the
      // axis with an offset along it (nodes slid apart) changes it. Its gradient with respect
      // to u = x3 - x1, -k (e . g) P g / |u|, is a couple on body A through N1 and N3; without
      // it the spring is not conservative and a joint that slides and turns at once makes
      // energy (the corpus deck dynakw_joint_translational: +2.8% in its first cycles).
      couple = scaled(gap, jp.k * along / length);
    }
    // The spring and the damper pull a towards b and b towards a.
    const Vec3 f = add(scaled(gap, jp.k), scaled(dv, jp.c));
    // The damper's work over a step, c dv(n-1/2) . (dv(n-1/2) + dv(n+1/2)) / 2 dt(n), booked
    // half now, at the velocity the force is formed from, and half at the next call, at the
    // velocity it produced: the halves the kinetic energy's product form 1/2 m v(n-1/2) .
    // v(n+1/2) has taken at each balance (Solver::energies). Booked whole one call late, the
    // ratio dipped by a step's damping at every sample (7% on a joint snapping shut); dt(n) is
    // the velocity step (half a step in the first cycle: with the full step that cycle's
    // damping was booked twice, energy from nowhere).
    const double spring = 0.5 * jp.k * dot(gap, gap);
    double damped = 0.5 * dot(jp.damper, dv) * jp.dt_last;
    jp.damper = scaled(dv, jp.c);
    jp.dt_last = dt_velocity;
    damped += 0.5 * dot(jp.damper, dv) * jp.dt_last;
    stored += spring;
    joint_dissipated_ += damped;
    jp.dissipated += damped;
    JointState& js = joint_states_[std::size_t(pair_joint_[p])];
    const std::size_t n2 = recs[2 * jp.axis + 1].at(0);  // the joint's N2
    js.force = sub(js.force, f);
    js.moment = sub(js.moment, cross(sub(at(all, b), at(all, n2)), f));
    js.energy += spring + jp.dissipated;
    for (int s = 0; s < 2; ++s) {
      const int32_t n = jp.local[std::size_t(s)];
      if (n == model::kNone) continue;
      const double sign = s == 0 ? 1.0 : -1.0;
      for (int c = 0; c < 3; ++c) sd.f_ext[3 * std::size_t(n) + std::size_t(c)] += sign * f[c];
      joint_nodal_.emplace_back(n, scaled(f, sign));
    }
    if (jp.across)
      for (int s = 0; s < 2; ++s) {
        const int32_t n = joints_[jp.axis + std::size_t(1 - s)].local[0];  // N3, then N1
        if (n == model::kNone) continue;
        const double sign = s == 0 ? 1.0 : -1.0;
        for (int c = 0; c < 3; ++c)
          sd.f_ext[3 * std::size_t(n) + std::size_t(c)] += sign * couple[c];
        joint_nodal_.emplace_back(n, scaled(couple, sign));
      }
  }
  joint_energy_ = stored + joint_dissipated_;
}

// *LOAD_RIGID_BODY and *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED: their bodies, and each
// stiffness frame in its body's principal coordinates (it turns with the body).
void RigidBodies::initLoads(const model::Model& m) {
  for (const auto& l : m.rigid.loads) loads_.push_back({l.body, l.dof, curveOf(m, l.curve), l.sf});
  for (const auto& d : m.rigid.joint_stiffness) {
    Stiffness st;
    st.a = d.body_a;
    st.b = d.body_b;
    double ra[3][3], rb[3][3];
    matrix(bodies_[std::size_t(d.body_a)].q, ra);
    matrix(bodies_[std::size_t(d.body_b)].q, rb);
    for (std::size_t i = 0; i < 3; ++i) {
      st.axes_a[i] = matTVec(ra, d.frame_a[i]);
      st.axes_b[i] = matTVec(rb, d.frame_b[i]);
    }
    st.es = d.stiffness;
    st.fm = d.friction;
    stiffness_.push_back(st);
  }
  if (loads_.empty() && stiffness_.empty()) return;
  load_f_.assign(bodies_.size(), Vec3{});
  load_m_.assign(bodies_.size(), Vec3{});
  joint_m_.assign(bodies_.size(), Vec3{});
}

void RigidBodies::computeBodyLoads(double t) {
  if (load_f_.empty()) return;
  std::fill(load_f_.begin(), load_f_.end(), Vec3{});
  std::fill(load_m_.begin(), load_m_.end(), Vec3{});
  for (const BodyLoad& l : loads_) {
    const double value = l.sf * model::loadFactor(l.curve, t, phase_);
    Vec3& target = l.dof < 3 ? load_f_[std::size_t(l.body)] : load_m_[std::size_t(l.body)];
    target[std::size_t(l.dof % 3)] += value;
  }
  addJointStiffness();
}

// Euler-type angles of B's frame relative to A's: phi = atan2(b_y . a_z, b_y . a_y) (the turn
// about a_x that carries a_y to b_y), theta = atan2(b_z . a_x, b_z . a_z) about a_y, psi =
// atan2(b_x . a_y, b_x . a_x) about a_z. Exact for a turn about one local axis (a revolute
// joint), first order for turns about several.
Vec3 RigidBodies::relativeAngles(const Stiffness& s, std::array<Vec3, 3>& a) const {
  double ra[3][3], rb[3][3];
  matrix(bodies_[std::size_t(s.a)].q, ra);
  matrix(bodies_[std::size_t(s.b)].q, rb);
  std::array<Vec3, 3> b;
  for (std::size_t i = 0; i < 3; ++i) {
    a[i] = matVec(ra, s.axes_a[i]);
    b[i] = matVec(rb, s.axes_b[i]);
  }
  return {std::atan2(dot(b[1], a[2]), dot(b[1], a[1])),
          std::atan2(dot(b[2], a[0]), dot(b[2], a[2])),
          std::atan2(dot(b[0], a[1]), dot(b[0], a[0]))};
}

// Friction springs (Keyword Manual, *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED ESPH, FMPH):
// elastic-plastic, M += ES d(angle) capped at +-FM, on each axis with ES > 0 and FM > 0
// (ES alone serves stop angles, which are refused). The moment acts on B against its turn
// relative to A and on A the opposite way; its work (stored and slipped) is internal energy.
void RigidBodies::addJointStiffness() {
  std::fill(joint_m_.begin(), joint_m_.end(), Vec3{});
  for (Stiffness& s : stiffness_) {
    std::array<Vec3, 3> axes;
    const Vec3 raw = relativeAngles(s, axes);
    Vec3 m{};
    for (std::size_t k = 0; k < 3; ++k) {
      // The change since the last step, wrapped to (-pi, pi]: the angle goes on past a turn.
      const double d = std::remainder(raw[k] - std::remainder(s.angle[k], 2 * M_PI), 2 * M_PI);
      s.angle[k] += d;
      if (!(s.es[k] > 0.0 && s.fm[k] > 0.0)) continue;
      const double before = s.moment[k];
      s.moment[k] = std::clamp(before + s.es[k] * d, -s.fm[k], s.fm[k]);
      stiffness_work_ += 0.5 * (before + s.moment[k]) * d;
      m = add(m, scaled(axes[k], s.moment[k]));
    }
    joint_m_[std::size_t(s.b)] = sub(joint_m_[std::size_t(s.b)], m);
    joint_m_[std::size_t(s.a)] = add(joint_m_[std::size_t(s.a)], m);
  }
}

StepWork RigidBodies::loadWork(std::size_t g, const Vec3& v_prev, const Vec3& w_prev,
                               double dt_n) const {
  const Body& b = bodies_[g];
  return bodyWork(scaled(load_f_[g], dt_n), scaled(load_m_[g], dt_n), v_prev, b.V, w_prev, b.omega);
}

std::vector<JointState> RigidBodies::joints() const {
  return joint_states_;
}

void RigidBodies::scaleVelocities(double factor) {
  for (Body& b : bodies_) {
    b.V = scaled(b.V, factor);
    b.L = scaled(b.L, factor);
    b.omega = scaled(b.omega, factor);
  }
}

void RigidBodies::restoreInitialVelocities() {
  for (Body& b : bodies_) {
    b.V = b.V_prev = b.V_init;
    b.omega = b.omega_init;
    b.L = b.L_prev = angularMomentum(b, b.q, b.omega);
  }
}

void RigidBodies::setInitialVelocities(domain::Subdomain& sd) const {
  for (const Body& b : bodies_) {
    for (int32_t node : b.local) {
      const auto n = static_cast<std::size_t>(node);
      const Vec3 v = add(b.V, cross(b.omega, sub(at(sd.x, 3 * n), b.x_cm)));
      for (int c = 0; c < 3; ++c) {
        sd.v[3 * n + std::size_t(c)] = v[std::size_t(c)];
        if (sd.rotations) sd.w[3 * n + std::size_t(c)] = b.omega[std::size_t(c)];
      }
    }
  }
}

StepWork RigidBodies::advance(Body& b, const Vec3& F, const Vec3& M, double t, double dt_n,
                              double dt_half) {
  b.V_prev = b.V;
  b.L_prev = b.L;
  b.q_prev = b.q;
  b.x_cm_prev = b.x_cm;
  const Vec3 omega_prev = b.omega;
  // Kick: dV = dt F / m, dL = dt M.
  const Vec3 V_free = add(b.V, scaled(F, dt_n / b.mass));
  const Vec3 L_free = add(b.L, scaled(M, dt_n));

  // Constrained (CMO) and prescribed freedoms, with their target velocities at t(n+1/2).
  bool set[6] = {};
  double target[6] = {};
  for (int c = 0; c < 6; ++c)
    if (b.fixed & (1u << c)) set[c] = true;
  const double t_half = t + 0.5 * dt_half, t_next = t + dt_half;
  for (const Motion& mo : b.motions) {
    if (t_half < mo.birth || t_half > mo.death) continue;
    const auto d = static_cast<std::size_t>(mo.dof % 3);
    const bool rot = mo.dof >= 3;
    auto value = [&](double time) { return mo.sf * model::loadFactor(mo.curve, time, phase_); };
    double v = 0.0;
    switch (mo.kind) {
      case model::MotionKind::Velocity:
        v = value(t_half);
        break;
      case model::MotionKind::Acceleration:
        v = (rot ? omega_prev[d] : b.V_prev[d]) + dt_n * value(t);
        break;
      case model::MotionKind::Displacement: {
        // From the curve's value at t = 0 (as the nodal displacement, boundary.cpp).
        const double now = rot ? b.angle[d] : b.x_cm[d] - b.x_cm0[d];
        v = dt_half > 0.0 ? (value(t_next) - value(0.0) - now) / dt_half : 0.0;
        break;
      }
    }
    set[mo.dof] = true;
    target[mo.dof] = v;
  }
  b.V = V_free;
  for (int c = 0; c < 3; ++c)
    if (set[c]) b.V[std::size_t(c)] = target[c];

  const bool rotation_set = set[3] || set[4] || set[5];
  if (rotation_set) {
    // omega = A L, A the spatial inverse inertia at t(n). The constraint moment acts about
    // the set axes only: L = L_free + D, D_c = 0 on the free axes, with the set components of
    // A (L_free + D) equal to their targets; then q turns by exp(dt omega).
    double a[3][3];
    inverseInertia(b, b.q, a);
    const Vec3 w_free = matVec(a, L_free);
    int idx[3], k = 0;
    for (int c = 0; c < 3; ++c)
      if (set[3 + c]) idx[k++] = c;
    double sys[3][4] = {};
    for (int i = 0; i < k; ++i) {
      for (int jj = 0; jj < k; ++jj) sys[i][jj] = a[idx[i]][idx[jj]];
      sys[i][k] = target[3 + idx[i]] - w_free[std::size_t(idx[i])];
    }
    // Gaussian elimination with partial pivoting; an axis without inertia (a null pivot)
    // takes no constraint moment.
    double scale = 0.0;
    for (int i = 0; i < 3; ++i) scale = std::max(scale, std::abs(a[i][i]));
    Vec3 delta{};
    int piv_col[3];
    bool used[3] = {};
    for (int col = 0, row = 0; col < k; ++col) {
      int best = -1;
      for (int i = row; i < k; ++i)
        if (best < 0 || std::abs(sys[i][col]) > std::abs(sys[best][col])) best = i;
      piv_col[col] = -1;
      if (best < 0 || std::abs(sys[best][col]) <= 1e-12 * scale) continue;
      std::swap(sys[row], sys[best]);
      for (int i = 0; i < k; ++i) {
        if (i == row) continue;
        const double f = sys[i][col] / sys[row][col];
        for (int jj = col; jj <= k; ++jj) sys[i][jj] -= f * sys[row][jj];
      }
      piv_col[col] = row;
      used[col] = true;
      ++row;
    }
    for (int col = 0; col < k; ++col)
      if (used[col]) delta[std::size_t(idx[col])] = sys[piv_col[col]][k] / sys[piv_col[col]][col];
    b.L = add(L_free, delta);
    Vec3 w = matVec(a, b.L);
    for (int c = 0; c < 3; ++c)
      if (set[3 + c]) w[std::size_t(c)] = target[3 + c];
    // Every rotation given: L = J omega exactly (a body held still keeps L = 0).
    if (k == 3) b.L = angularMomentum(b, b.q, w);
    b.q = normalized(mul(fromRotationVector(scaled(w, dt_half)), b.q));
  } else {
    // Free rotation at fixed L over dt: the DLM splitting in the principal frame (body
    // momentum pi = R^T L). The flow of pi_k^2 / 2 I_k is the exact rotation of the body by
    // theta = h pi_k / I_k about its axis k: q <- q (cos theta/2, sin theta/2 e_k), while pi
    // turns by -theta about e_k (Euler's equations, dpi/dt = pi x omega).
    b.L = L_free;
    double r[3][3];
    matrix(b.q, r);
    Vec3 pi = matTVec(r, b.L);
    const double largest = std::max({b.inertia[0], b.inertia[1], b.inertia[2]});
    auto turn = [&](int k, double h) {
      const double ik = b.inertia[std::size_t(k)];
      if (!(ik > 1e-12 * largest)) return;  // no inertia about this axis: no rotation about it
      const double theta = h * pi[std::size_t(k)] / ik;
      if (theta == 0.0) return;
      Quat e{std::cos(0.5 * theta), 0.0, 0.0, 0.0};
      e[std::size_t(k) + 1] = std::sin(0.5 * theta);
      b.q = mul(b.q, e);
      const auto i = std::size_t((k + 1) % 3), j = std::size_t((k + 2) % 3);
      const double c = std::cos(theta), s = std::sin(theta);
      const double pi_i = pi[i], pi_j = pi[j];
      pi[i] = c * pi_i + s * pi_j;
      pi[j] = -s * pi_i + c * pi_j;
    };
    turn(0, 0.5 * dt_half);
    turn(1, 0.5 * dt_half);
    turn(2, dt_half);
    turn(1, 0.5 * dt_half);
    turn(0, 0.5 * dt_half);
    b.q = normalized(b.q);
  }
  b.x_cm = add(b.x_cm, scaled(b.V, dt_half));
  b.omega = dt_half > 0.0 ? scaled(toRotationVector(mul(b.q, conjugate(b.q_prev))), 1.0 / dt_half)
                          : Vec3{};
  b.angle = add(b.angle, scaled(b.omega, dt_half));
  const Vec3 dV = sub(b.V, V_free), dL = sub(b.L, L_free);
  b.reaction_f = dt_n > 0.0 ? scaled(dV, b.mass / dt_n) : Vec3{};
  b.reaction_m = dt_n > 0.0 ? scaled(dL, 1.0 / dt_n) : Vec3{};
  b.acc = dt_n > 0.0 ? scaled(sub(b.V, b.V_prev), 1.0 / dt_n) : Vec3{};
  b.angular_acc = dt_n > 0.0 ? scaled(sub(b.omega, omega_prev), 1.0 / dt_n) : Vec3{};
  // The constraint impulse times the mean velocity over dt_n.
  return bodyWork(scaled(dV, b.mass), dL, b.V_prev, b.V, omega_prev, b.omega);
}

StepWork RigidBodies::apply(double t, double dt_n, double dt_half, domain::Subdomain& sd,
                            const domain::NodeVector& v_old, const comm::Communicator& comm) {
  if (empty()) return {};
  const std::size_t nb = bodies_.size(), groups = nb + sets_.size();
  // Welds reach their failure time.
  for (Body& b : bodies_)
    if (b.weld && b.active && t >= b.tfail) {
      b.active = false;
      b.failure_time = t;
      for (int32_t n : b.local) in_body_[static_cast<std::size_t>(n)] = 0;
    }

  // This rank's records: the owned nodes of active bodies and tied sets.
  std::vector<int64_t> keys;
  std::vector<double> values;
  for (std::size_t n = 0; n < sd.numNodes(); ++n) {
    const int32_t g = group_[n];
    if (g < 0 || !sd.node_owned[n]) continue;
    if (static_cast<std::size_t>(g) < nb) {
      const Body& b = bodies_[static_cast<std::size_t>(g)];
      if (!b.active) continue;
      const Vec3 f = add(at(sd.f, 3 * n), at(sd.f_ext, 3 * n));
      Vec3 mo = cross(sub(at(sd.x, 3 * n), b.x_cm), f);
      if (sd.rotations) mo = add(mo, at(sd.moment, 3 * n));
      const bool zero = f == Vec3{} && mo == Vec3{};
      // A zero record adds nothing to the sums (0 + x == x bit for bit): only welds, whose
      // nodes' data is used node by node, always send theirs.
      if (zero && !b.weld) continue;
      keys.push_back(recordKey(g, sd.node_model[n]));
      values.insert(values.end(), f.begin(), f.end());
      values.insert(values.end(), mo.begin(), mo.end());
      if (b.weld) {
        for (int c = 0; c < 3; ++c) values.push_back(v_old[3 * n + std::size_t(c)]);
        values.push_back(sd.mass[n]);
      }
    } else {
      const TiedSet& s = sets_[static_cast<std::size_t>(g) - nb];
      if (t >= s.tfail) continue;
      const Vec3 p = scaled(at(sd.v, 3 * n), sd.mass[n]);
      if (p == Vec3{}) continue;
      keys.push_back(recordKey(g, sd.node_model[n]));
      values.insert(values.end(), p.begin(), p.end());
    }
  }
  std::vector<double> all;
  const auto recs = gatherRecords(
      keys, values, groups, [&](int32_t g) { return width(g); }, comm, all);

  StepWork work;
  for (std::size_t g = 0; g < nb; ++g) {
    Body& b = bodies_[g];
    if (!b.active) continue;
    Vec3 F{}, M{};
    for (std::size_t off : recs[g]) {
      F = add(F, at(all, off));
      M = add(M, at(all, off + 3));
    }
    const bool loaded = g < load_f_.size();
    if (loaded) {
      F = add(F, load_f_[g]);
      M = add(M, add(load_m_[g], joint_m_[g]));
    }
    const Vec3 v_prev = b.V, w_prev = b.omega;
    work += advance(b, F, M, t, dt_n, dt_half);
    if (loaded) work += loadWork(g, v_prev, w_prev, dt_n);
    if (!b.weld) continue;
    // The weld's force on each node: the change of the node's momentum the weld made, less
    // the force the node felt, F_c = m (v_rigid - v(n-1/2)) / dt_n - f; normal along the
    // node -> centre direction (tension positive; only tension counts) and shear the rest
    // (Keyword Manual, *CONSTRAINED_SPOTWELD: (fn/SN)^N + (fs/SS)^M >= 1 fails the weld).
    double r_prev[3][3], r_next[3][3];
    matrix(b.q_prev, r_prev);
    matrix(b.q, r_next);
    double worst = -1.0;
    for (std::size_t i = 0; i < recs[g].size() && i < b.all_X.size(); ++i) {
      const std::size_t off = recs[g][i];
      const Vec3 x_now = add(b.x_cm_prev, matVec(r_prev, b.all_X[i]));
      const Vec3 v_rigid =
          add(b.V, scaled(sub(matVec(r_next, b.all_X[i]), matVec(r_prev, b.all_X[i])),
                          dt_half > 0.0 ? 1.0 / dt_half : 0.0));
      const double mi = all[off + 9];
      const Vec3 fc = dt_n > 0.0
                          ? sub(scaled(sub(v_rigid, at(all, off + 6)), mi / dt_n), at(all, off))
                          : Vec3{};
      Vec3 d = sub(b.x_cm_prev, x_now);
      const double len = std::sqrt(dot(d, d));
      d = len > 0.0 ? scaled(d, 1.0 / len) : Vec3{};
      const double fn = dot(fc, d);
      const double fs = std::sqrt(dot(sub(fc, scaled(d, fn)), sub(fc, scaled(d, fn))));
      double crit = 0.0;
      if (b.sn > 0.0) crit += std::pow(std::max(fn, 0.0) / b.sn, b.n);
      if (b.ss > 0.0) crit += std::pow(fs / b.ss, b.m);
      if (crit > worst) {
        worst = crit;
        b.fn = fn;
        b.fs = fs;
      }
    }
    if (worst >= 1.0) {
      // The weld breaks in this step: its nodes keep the velocities of their own forces.
      b.active = false;
      b.failure_time = t;
      for (int32_t n : b.local) in_body_[static_cast<std::size_t>(n)] = 0;
    }
  }

  // The bodies' nodes move with them: v = V + (R(n+1) - R(n)) X / dt takes a node from its
  // place on the body at t(n) to its place at t(n+1) (the exact secant of the rotation, not
  // omega x r, which would stretch the body by dt^2 |omega|^2 / 2 each step). A body at rest
  // or in pure translation gives its nodes exactly V.
  for (const Body& b : bodies_) {
    if (!b.active) continue;
    double r_next[3][3], r_now[3][3];
    matrix(b.q, r_next);
    matrix(b.q_prev, r_now);
    const bool turning = b.q != b.q_prev;
    for (std::size_t k = 0; k < b.local.size(); ++k) {
      const auto n = static_cast<std::size_t>(b.local[k]);
      Vec3 vel = b.V;
      if (turning && dt_half > 0.0)
        vel = add(vel, scaled(sub(matVec(r_next, b.X[k]), matVec(r_now, b.X[k])), 1.0 / dt_half));
      for (int c = 0; c < 3; ++c) {
        const std::size_t i = 3 * n + std::size_t(c);
        const double v = vel[std::size_t(c)];
        sd.v[i] = v;
        sd.a[i] = dt_n > 0.0 ? (v - v_old[i]) / dt_n : 0.0;
        if (sd.rotations) sd.w[i] = b.omega[std::size_t(c)];
      }
    }
  }
  // Tied sets: the mass-weighted mean velocity in their directions, which keeps their
  // momentum (Keyword Manual, *CONSTRAINED_NODE_SET).
  for (std::size_t k = 0; k < sets_.size(); ++k) {
    const TiedSet& s = sets_[k];
    if (t >= s.tfail || !(s.mass > 0.0)) continue;
    Vec3 p{};
    for (std::size_t off : recs[nb + k]) p = add(p, at(all, off));
    for (int32_t node : s.local) {
      const auto n = static_cast<std::size_t>(node);
      for (int c = 0; c < 3; ++c) {
        if (!(s.dofs & (1u << c))) continue;
        const std::size_t i = 3 * n + std::size_t(c);
        sd.v[i] = p[std::size_t(c)] / s.mass;
        sd.a[i] = dt_n > 0.0 ? (sd.v[i] - v_old[i]) / dt_n : 0.0;
      }
    }
  }
  stepped_ = true;
  return comm.rank() == 0 ? work : StepWork{};
}

double RigidBodies::kineticEnergy() const {
  double e = 0.0;
  for (const Body& b : bodies_) {
    if (!b.active) continue;
    // 1/2 m V(n-1/2) . V(n+1/2) and 1/2 L(n-1/2) . omega(n+1/2) (omega = A L with the inverse
    // inertia of the old orientation), the products central differences conserve, as for the
    // nodes (Solver::energies); the means overstate a body ringing on a stiff joint.
    double a[3][3];
    inverseInertia(b, stepped_ ? b.q_prev : b.q, a);
    e += 0.5 * b.mass * dot(stepped_ ? b.V_prev : b.V, b.V) +
         0.5 * dot(stepped_ ? b.L_prev : b.L, matVec(a, b.L));
  }
  return e;
}

std::vector<RigidBodyState> RigidBodies::states() const {
  std::vector<RigidBodyState> out;
  for (const Body& b : bodies_) {
    double r[3][3];
    matrix(b.q, r);  // body to global: its columns are the principal axes
    std::array<Vec3, 3> axes;
    for (std::size_t k = 0; k < 3; ++k) axes[k] = {r[0][k], r[1][k], r[2][k]};
    out.push_back({b.id, b.kind, b.mass, b.x_cm, b.V, b.omega, b.L, b.reaction_f, b.reaction_m,
                   sub(b.x_cm, b.x_cm0), b.angle, b.acc, b.angular_acc, axes});
  }
  return out;
}

std::vector<WeldState> RigidBodies::welds() const {
  std::vector<WeldState> out;
  for (const Body& b : bodies_)
    if (b.weld) out.push_back({b.id, !b.active, b.failure_time, b.fn, b.fs});
  return out;
}

// The state of a body that changes during the run, for save and load alike (mass, inertia,
// body coordinates and weld data come from the deck and are rebuilt by the constructor).
template <class B, class F>
void RigidBodies::visitState(B& b, F&& f) {
  f(b.q);
  f(b.q_prev);
  for (auto* v : {&b.x_cm, &b.x_cm_prev, &b.V, &b.V_prev, &b.L, &b.L_prev, &b.omega, &b.angle,
                  &b.reaction_f, &b.reaction_m, &b.acc, &b.angular_acc})
    f(*v);
  f(b.active);
  f(b.failure_time);
  f(b.fn);
  f(b.fs);
}

void RigidBodies::saveState(util::ArchiveWriter& out) const {
  out.put<uint64_t>(bodies_.size());
  for (const Body& b : bodies_) visitState(b, [&](const auto& v) { out.put(v); });
  out.put<uint64_t>(joints_.size());
  for (const JointPair& j : joints_) {
    out.put(j.k);
    out.put(j.c);
  }
  out.put(joint_dissipated_);
  out.put(joint_energy_);
  out.put(stepped_);
  for (const JointPair& j : joints_)
    for (const auto& v : {Vec3{j.dissipated, j.dt_last, 0.0}, j.damper}) out.put(v);
  for (const Stiffness& st : stiffness_) {
    out.put(st.angle);
    out.put(st.moment);
  }
  out.put(stiffness_work_);
}

void RigidBodies::loadState(util::ArchiveReader& in) {
  util::expectCount(in, bodies_.size(), "rigid bodies and welds");
  for (Body& b : bodies_) {
    visitState(b, [&](auto& v) { in.get(v); });
    // A failed weld's nodes are free again: their energy is the solver's (as in apply()).
    if (!b.active)
      for (int32_t node : b.local) in_body_[static_cast<std::size_t>(node)] = 0;
  }
  util::expectCount(in, joints_.size(), "joint node pairs");
  for (JointPair& j : joints_) {
    in.get(j.k);
    in.get(j.c);
  }
  in.get(joint_dissipated_);
  in.get(joint_energy_);
  in.get(stepped_);
  for (JointPair& j : joints_) {
    Vec3 d{};
    in.get(d);
    j.dissipated = d[0];
    j.dt_last = d[1];
    in.get(j.damper);
  }
  for (Stiffness& st : stiffness_) {
    in.get(st.angle);
    in.get(st.moment);
  }
  in.get(stiffness_work_);
}

}  // namespace crumple::constraints
