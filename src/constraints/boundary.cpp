#include "constraints/boundary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "constraints/blast.hpp"

namespace crumple::constraints {

namespace {

const model::Curve* curveOf(const model::Model& m, int32_t index) {
  return index == model::kNone ? nullptr : &m.curves[static_cast<std::size_t>(index)];
}

double dot(const model::Vec3& a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Signed distance from point p to a geometric wall (positive outside) and the outward unit
// normal of the nearest surface point (*RIGIDWALL_GEOMETRIC, Keyword Manual): a prism is the
// box spanned from the tail by l (LENL), m = n x l (LENM) and -n (LENP); a cylinder of radius R
// around the axis from the tail along n, of length LENCYL (0: infinite; its end caps are not
// walls); a sphere of radius R about the tail. Points a finite cylinder does not span are
// outside (+infinity).
double surfaceGap(const model::RigidWallPlanar& d, const model::Vec3& m_axis, const double* p,
                  double* normal) {
  using Shape = model::RigidWallPlanar::Shape;
  const double rel[3] = {p[0] - d.tail[0], p[1] - d.tail[1], p[2] - d.tail[2]};
  if (d.shape == Shape::Sphere) {
    const double r = std::sqrt(rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2]);
    if (r == 0.0) return std::numeric_limits<double>::infinity();
    for (int c = 0; c < 3; ++c) normal[c] = rel[c] / r;
    return r - d.radius;
  }
  if (d.shape == Shape::Cylinder) {
    const double along = dot(d.normal, rel);
    if (d.length > 0.0 && (along < 0.0 || along > d.length))
      return std::numeric_limits<double>::infinity();
    const double radial[3] = {rel[0] - along * d.normal[0], rel[1] - along * d.normal[1],
                              rel[2] - along * d.normal[2]};
    const double r =
        std::sqrt(radial[0] * radial[0] + radial[1] * radial[1] + radial[2] * radial[2]);
    if (r == 0.0) return std::numeric_limits<double>::infinity();
    for (int c = 0; c < 3; ++c) normal[c] = radial[c] / r;
    return r - d.radius;
  }
  // Prism: the finite flat wall at the tail with depth LENP behind it (along -n), so that its
  // top face acts as the flat wall. Inside when all three box coordinates are within range;
  // the nearest face wins.
  const double s = dot(d.l_axis, rel), t = dot(m_axis, rel), q = -dot(d.normal, rel);
  const double depth[6] = {s, d.lenl - s, t, d.lenm - t, d.lenp - q, q};
  int best = 0;
  for (int k = 1; k < 6; ++k)
    if (depth[k] < depth[best]) best = k;
  if (depth[best] < 0.0) return std::numeric_limits<double>::infinity();  // outside the box
  const model::Vec3& axis = best < 2 ? d.l_axis : best < 4 ? m_axis : d.normal;
  const double sign = best % 2 == 0 ? -1.0 : 1.0;
  for (int c = 0; c < 3; ++c) normal[c] = sign * axis[c];
  return -depth[best];
}

}  // namespace

Boundary::Boundary(const model::Model& m, const domain::Subdomain& sd) {
  has_external_ = !m.nodal_loads.empty() || !m.pressure_loads.empty() || !m.body_loads.empty();
  for (const auto& s : m.spcs) {
    const int32_t n = sd.localNode(s.node);
    if (n != model::kNone && (s.dofs & 7)) spc_.emplace_back(n, s.dofs);
    // Rotational freedoms exist only at nodes of shells and beams (sd.rotations).
    if (n != model::kNone && (s.dofs >> 3) && sd.rotations) spc_rot_.emplace_back(n, s.dofs >> 3);
  }
  for (const auto& p : m.prescribed) {
    const int32_t n = sd.localNode(p.node);
    if (n != model::kNone)
      motion_.push_back({n, p.dof, p.kind, curveOf(m, p.curve), p.sf, p.birth, p.death});
  }
  // One reaction entry per constrained node, whichever constraints name it.
  auto entry = [](std::vector<NodeReaction>& list, int32_t n) {
    const auto it =
        std::find_if(list.begin(), list.end(), [&](const auto& r) { return r.node == n; });
    if (it != list.end()) return std::size_t(it - list.begin());
    list.push_back({n, {}, {}, 0.0});
    return list.size() - 1;
  };
  // The first motion of each prescribed (node, freedom), looked up by node: one pass over the
  // motions and one over the SPCs.
  std::unordered_map<int32_t, std::array<int32_t, 3>> first_motion;
  for (std::size_t k = motion_.size(); k-- > 0;) {
    auto [it, added] =
        first_motion.try_emplace(motion_[k].node, std::array<int32_t, 3>{-1, -1, -1});
    it->second[std::size_t(motion_[k].dof)] = int32_t(k);
  }
  for (const auto& [n, mask] : spc_) {
    spc_at_.push_back(entry(spc_reaction_, n));
    std::array<int32_t, 3> on{-1, -1, -1};
    if (const auto it = first_motion.find(n); it != first_motion.end())
      for (std::size_t c = 0; c < 3; ++c)
        if (mask & (1u << c)) on[c] = it->second[c];
    spc_motion_.push_back(on);
  }
  for (const auto& [n, mask] : spc_rot_) spc_rot_at_.push_back(entry(spc_reaction_, n));
  for (const auto& mo : motion_) motion_at_.push_back(entry(motion_reaction_, mo.node));
  for (const auto& l : m.nodal_loads) {
    const int32_t n = sd.localNode(l.node);
    if (n != model::kNone) loads_.push_back({n, l.dof, curveOf(m, l.curve), l.sf});
  }
  for (std::size_t k = 0; k < sd.pressure_segments.size(); ++k) {
    const auto& p = m.pressure_loads[static_cast<std::size_t>(sd.pressure_segments[k])];
    Pressure q{{},
               curveOf(m, p.curve),
               p.sf,
               p.at,
               sd.pressure_slot_offset + 4 * k,
               p.airbag,
               p.blast == model::kNone ? nullptr : &m.blasts[std::size_t(p.blast)]};
    for (int c = 0; c < 4; ++c) q.nodes[c] = sd.localNode(p.nodes[c]);
    pressure_.push_back(q);
  }
  for (const auto& b : m.body_loads)
    body_.push_back({b.dof, curveOf(m, b.curve), b.sf, curveOf(m, b.dr_curve)});
  if (!m.airbags.empty()) airbags_ = Airbags(m, sd);
  for (const auto& w : m.rigid_walls) {
    WallState ws;
    ws.def = &w;
    if (w.nodes.empty()) {
      for (std::size_t i = 0; i < sd.numNodes(); ++i) ws.nodes.push_back(int32_t(i));
    } else {
      for (int32_t mn : w.nodes)
        if (int32_t n = sd.localNode(mn); n != model::kNone) ws.nodes.push_back(n);
    }
    ws.velocity = ws.velocity_prev = w.moving ? w.v0 : 0.0;
    walls_.push_back(std::move(ws));
  }
}

namespace {
// The blast pressure on a segment at time t (constraints/blast.hpp): the range and the angle
// of incidence at its centroid, the angle between its normal (along area) and the charge.
double segmentBlastPressure(const model::BlastCharge& charge, const std::array<const double*, 4>& x,
                            const double area[3], int corners, double t) {
  double centre[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < corners; ++k)
    for (int c = 0; c < 3; ++c) centre[c] += x[static_cast<std::size_t>(k)][c] / corners;
  const double to[3] = {charge.origin[0] - centre[0], charge.origin[1] - centre[1],
                        charge.origin[2] - centre[2]};
  const double range = std::sqrt(to[0] * to[0] + to[1] * to[1] + to[2] * to[2]);
  const double a = std::sqrt(area[0] * area[0] + area[1] * area[1] + area[2] * area[2]);
  if (!(range > 0.0) || !(a > 0.0)) return 0.0;
  const double cos_angle = (to[0] * area[0] + to[1] * area[1] + to[2] * area[2]) / (range * a);
  return blastPressure(charge, blastPulse(charge, range), t, cos_angle);
}
}  // namespace

void Boundary::pressureForces(double t, domain::Subdomain& sd) const {
  // Follower pressure on the current geometry: F = -p A, A = (x3 - x1) x (x4 - x2) / 2 the
  // area vector along the right-hand normal of n1..n4 (LS-DYNA: positive pressure pushes
  // against the segment normal). Triangles (n3 == n4) share it in thirds.
  for (const auto& p : pressure_) {
    double* slot = &sd.slots[3 * p.first_slot];
    if (p.airbag != model::kNone) {
      std::array<const double*, 4> corner{};
      for (std::size_t k = 0; k < 4; ++k)
        corner[k] = &sd.x[3 * static_cast<std::size_t>(p.nodes[k])];
      segmentPressureForces(corner, airbags_.segmentPressure(p.airbag), slot);
      continue;
    }
    std::fill(slot, slot + 12, 0.0);
    // A blast acts in the transient only (it has no SIDR); a curve's pressure follows its SIDR.
    if (p.blast != nullptr ? phase_ == model::Phase::Relaxation : t < p.at) continue;
    const double* x1 = &sd.x[3 * static_cast<std::size_t>(p.nodes[0])];
    const double* x2 = &sd.x[3 * static_cast<std::size_t>(p.nodes[1])];
    const double* x3 = &sd.x[3 * static_cast<std::size_t>(p.nodes[2])];
    const double* x4 = &sd.x[3 * static_cast<std::size_t>(p.nodes[3])];
    const double d1[3] = {x3[0] - x1[0], x3[1] - x1[1], x3[2] - x1[2]};
    const double d2[3] = {x4[0] - x2[0], x4[1] - x2[1], x4[2] - x2[2]};
    const double area[3] = {0.5 * (d1[1] * d2[2] - d1[2] * d2[1]),
                            0.5 * (d1[2] * d2[0] - d1[0] * d2[2]),
                            0.5 * (d1[0] * d2[1] - d1[1] * d2[0])};
    const bool triangle = p.nodes[2] == p.nodes[3];
    const int corners = triangle ? 3 : 4;
    const double pr = p.blast != nullptr ? p.sf * segmentBlastPressure(*p.blast, {x1, x2, x3, x4},
                                                                       area, corners, t)
                                         : p.sf * model::loadFactor(p.curve, t - p.at, phase_);
    if (pr == 0.0) continue;
    const double share = -pr / corners;
    for (int k = 0; k < corners; ++k)
      for (int c = 0; c < 3; ++c) slot[3 * k + c] = share * area[c];
  }
}

void Boundary::externalForces(double t, const domain::Subdomain& sd,
                              domain::NodeVector& f_ext) const {
  for (const auto& l : loads_)
    f_ext[3 * static_cast<std::size_t>(l.node) + l.dof] +=
        l.sf * model::loadFactor(l.curve, t, phase_);
  // Base acceleration: body force -m a on every node.
  for (const auto& b : body_) {
    // Dynamic relaxation: the LCIDDR curve, or no load without one.
    const double acc = phase_ == model::Phase::Relaxation
                           ? (b.dr_curve ? b.sf * b.dr_curve->value(t) : 0.0)
                           : b.sf * model::loadFactor(b.curve, t, phase_);
    if (acc == 0.0) continue;
    for (std::size_t n = 0; n < sd.numNodes(); ++n) f_ext[3 * n + b.dof] -= sd.mass[n] * acc;
  }
}

StepWork Boundary::applyKinematics(double t, double dt_n, double dt_half, domain::Subdomain& sd,
                                   const domain::NodeVector& v_old) {
  StepWork work;
  for (auto* list : {&spc_reaction_, &motion_reaction_})
    for (auto& r : *list) r.force = r.moment = {};
  // Reaction work: the velocity change a constraint imposes is an impulse m dv acting while
  // the node moves at the mean of its old and new velocities over dt_n. The impulse over dt_n
  // is the constraint's force on the node (-(the residual) when the node is held at rest).
  auto impose = [&](std::size_t i, double v_new, NodeReaction& r) {
    const double m = sd.mass[i / 3];
    const double dv = v_new - sd.v[i];
    const StepWork w = impulseWork(m * dv, v_old[i], v_new);
    if (sd.node_owned[i / 3]) work += w;
    r.work += w.total();
    if (dt_n > 0.0) r.force[i % 3] += m * dv / dt_n;
    sd.v[i] = v_new;
  };
  const double t_half = t + 0.5 * dt_half;
  const double t_next = t + dt_half;
  auto active = [&](const Motion& m) { return !(t_half < m.birth || t_half > m.death); };
  for (std::size_t k = 0; k < spc_.size(); ++k) {
    const auto [n, mask] = spc_[k];
    for (int c = 0; c < 3; ++c)
      if (mask & (1u << c)) {
        // A freedom both held and prescribed (a node card's TC = 7 with a prescribed motion,
        // say) goes with the motion, as in LS-DYNA; zeroing it first split the one impulse in
        // two and booked half the motion's work (the corpus muscle deck: ratio 1.9).
        const int32_t mo = spc_motion_[k][std::size_t(c)];
        if (mo >= 0 && active(motion_[std::size_t(mo)])) continue;
        impose(3 * static_cast<std::size_t>(n) + c, 0.0, spc_reaction_[spc_at_[k]]);
        sd.a[3 * static_cast<std::size_t>(n) + c] = 0.0;
      }
  }
  for (std::size_t k = 0; k < spc_rot_.size(); ++k) {
    const auto [n, mask] = spc_rot_[k];
    for (int c = 0; c < 3; ++c)
      if (mask & (1u << c)) {
        const std::size_t i = 3 * static_cast<std::size_t>(n) + c;
        // The moment that stops the rotation: I (0 - w) / dt(n) about the global axis.
        if (dt_n > 0.0)
          spc_reaction_[spc_rot_at_[k]].moment[c] -= sd.inertia[i / 3] * sd.w[i] / dt_n;
        sd.w[i] = 0.0;
      }
  }
  for (std::size_t k = 0; k < motion_.size(); ++k) {
    const Motion& m = motion_[k];
    if (!active(m)) continue;
    const std::size_t i = 3 * static_cast<std::size_t>(m.node) + m.dof;
    double v_new = sd.v[i];
    switch (m.kind) {
      case model::MotionKind::Velocity:
        v_new = m.sf * model::loadFactor(m.curve, t_half, phase_);
        break;
      case model::MotionKind::Acceleration:
        v_new = v_old[i] + dt_n * m.sf * model::loadFactor(m.curve, t, phase_);
        break;
      case model::MotionKind::Displacement: {
        // The displacement since t = 0 is the curve's change since then, sf (f(t) - f(0)):
        // LS-DYNA moves the node by the curve's increments, so a curve that starts at a
        // non-zero value (the node's coordinate, say) does not make it jump at the first
        // step (docs/theory.md, "Loads and constraints").
        const double u_next = m.sf * (model::loadFactor(m.curve, t_next, phase_) -
                                      model::loadFactor(m.curve, 0.0, phase_));
        v_new = dt_half > 0.0 ? (u_next - (sd.x[i] - sd.x0[i])) / dt_half : 0.0;
        break;
      }
    }
    impose(i, v_new, motion_reaction_[motion_at_[k]]);
    sd.a[i] = dt_n > 0.0 ? (v_new - v_old[i]) / dt_n : 0.0;
  }
  return work;
}

StepWork Boundary::applyRigidWalls(double dt_n, double dt_half, domain::Subdomain& sd,
                                   const domain::NodeVector& v_old,
                                   const comm::Communicator& comm) {
  // The energy the walls take out: the work of their impulses on the nodes, negated, in the
  // two halves of step_work.hpp (the half at v(n+1/2) belongs to the next balance, as the
  // kinetic energy's product form takes it: booked whole at once, a node stopped on the wall
  // counted up to a quarter of its kinetic energy twice until the next step, energy ratio
  // 1.05 on the corpus deck lasso_sph_wall), plus the reaction's work on a moving wall.
  StepWork absorbed;
  for (auto& w : walls_) {
    const auto& d = *w.def;
    const model::Vec3& nrm = d.normal;
    // Forces of the owned nodes in contact, as (global node id, fx, fy, fz), to be summed in
    // ascending node id over all ranks.
    std::vector<int64_t> ids;
    std::vector<double> forces;
    double impulse_n = 0.0;  // normal impulse of the wall on this rank's owned nodes
    w.velocity_prev = w.velocity;
    model::Vec3 m_axis{};
    if (d.finite) {
      m_axis = {nrm[1] * d.l_axis[2] - nrm[2] * d.l_axis[1],
                nrm[2] * d.l_axis[0] - nrm[0] * d.l_axis[2],
                nrm[0] * d.l_axis[1] - nrm[1] * d.l_axis[0]};
    }
    const bool plane = d.shape == model::RigidWallPlanar::Shape::Plane;
    for (int32_t node : w.nodes) {
      const std::size_t n = static_cast<std::size_t>(node);
      const double m = sd.mass[n];
      if (m <= 0.0) continue;
      double* v = &sd.v[3 * n];
      const double* x = &sd.x[3 * n];
      const double rel[3] = {x[0] - d.tail[0], x[1] - d.tail[1], x[2] - d.tail[2]};
      double gap_next = 0.0;
      double normal[3] = {nrm[0], nrm[1], nrm[2]};
      if (plane) {
        const double gap_now = dot(nrm, rel) - w.displacement;
        gap_next = gap_now + dt_half * (dot(nrm, v) - w.velocity);
        if (gap_next >= 0.0) continue;
        // Only nodes in front of the wall at the start of the step are stopped by it; a node
        // already far behind (outside a finite wall's edge, or a sign slip) is left alone.
        if (gap_now < -1e-3 * std::max(1.0, std::abs(dot(nrm, rel)))) continue;
        if (d.finite) {
          const double s = dot(d.l_axis, rel), r = dot(m_axis, rel);
          if (s < 0.0 || s > d.lenl || r < 0.0 || r > d.lenm) continue;
        }
      } else {
        // Prism, cylinder, sphere: the signed distance of the predicted position to the
        // surface and the outward normal there; a node already inside at the start of the
        // step is left alone, as for the plane.
        const double p[3] = {x[0] + dt_half * v[0], x[1] + dt_half * v[1], x[2] + dt_half * v[2]};
        double unused[3];
        gap_next = surfaceGap(d, m_axis, p, normal);
        if (gap_next >= 0.0) continue;
        if (surfaceGap(d, m_axis, x, unused) < -1e-3 * std::max(1.0, d.radius + d.lenp)) continue;
      }
      // Normal correction that puts the node on the surface at the end of the step.
      const double dvn = -gap_next / dt_half;
      const double* nrm_node = normal;
      double v_new[3] = {v[0] + dvn * nrm_node[0], v[1] + dvn * nrm_node[1],
                         v[2] + dvn * nrm_node[2]};
      if (d.fric > 0.0) {
        const double vn = nrm_node[0] * v_new[0] + nrm_node[1] * v_new[1] + nrm_node[2] * v_new[2];
        double vt[3] = {v_new[0] - vn * nrm_node[0], v_new[1] - vn * nrm_node[1],
                        v_new[2] - vn * nrm_node[2]};
        const double vt_mag = std::sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]);
        const double limit = d.fric * dvn;  // Coulomb: |tangential impulse| <= mu * normal one
        const double scale = vt_mag > limit ? limit / vt_mag : 1.0;
        for (int c = 0; c < 3; ++c) v_new[c] -= scale * vt[c];
      }
      const bool owned = sd.node_owned[n] != 0;
      if (owned) ids.push_back(sd.node_id[n]);
      for (int c = 0; c < 3; ++c) {
        const double dv = v_new[c] - v[c];
        if (owned) {
          absorbed +=
              impulseWork(-m * dv, v_old[3 * n + c], v_new[c]);  // work on the node, negated
          impulse_n += m * dv * nrm[c];
          forces.push_back(dt_n > 0.0 ? m * dv / dt_n : 0.0);
        }
        v[c] = v_new[c];
      }
      // The node's force along its own surface normal (friction is tangential): on a curved
      // wall the normals differ from node to node, and rwforc's normal force is their sum.
      if (owned) forces.push_back(dt_n > 0.0 ? m * dvn / dt_n : 0.0);
    }
    sumWallForce(w, ids, forces, comm, plane);
    if (d.moving && d.mass > 0.0) {
      // The structure pushes back on a wall of finite mass (Newton's third law).
      w.velocity -= dt_n * w.normal_force / d.mass;
    }
    // The work the nodes' reaction did on the moving wall, at the wall's velocities before and
    // after the step; what is left is the energy the stonewall took out.
    absorbed += impulseWork(impulse_n, w.velocity_prev, w.velocity);
    w.displacement += dt_half * w.velocity;
  }
  return absorbed;
}

void Boundary::sumWallForce(WallState& w, const std::vector<int64_t>& ids,
                            const std::vector<double>& forces, const comm::Communicator& comm,
                            bool plane) {
  const auto all_ids = comm.allGather(ids);
  const auto all_forces = comm.allGather(forces);
  std::vector<std::size_t> order(all_ids.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return all_ids[a] < all_ids[b]; });
  w.force = {0.0, 0.0, 0.0};
  double normal_sum = 0.0;
  for (std::size_t k : order) {
    for (int c = 0; c < 3; ++c) w.force[c] += all_forces[4 * k + static_cast<std::size_t>(c)];
    normal_sum += all_forces[4 * k + 3];
  }
  // A plane's normal is one vector: the resultant's component along it (as before, to the bit).
  w.normal_force = plane ? dot(w.def->normal, w.force.data()) : normal_sum;
}

double Boundary::wallKineticEnergy() const {
  double e = 0.0;
  for (const auto& w : walls_)
    if (w.def->moving) {
      // At t(n), like the structure's kinetic energy: the product of the half-step velocities.
      e += 0.5 * w.def->mass * w.velocity_prev * w.velocity;
    }
  return e;
}

namespace {
// The state of a wall that changes during the run, for save and load alike.
template <class W, class F>
void visitWall(W& w, F&& f) {
  f(w.displacement);
  f(w.velocity);
  f(w.velocity_prev);
  f(w.force);
  f(w.normal_force);
}
}  // namespace

std::vector<double> Boundary::ownedMotionWork(const domain::Subdomain& sd) const {
  std::vector<double> out;
  for (const auto& r : motion_reaction_)
    if (sd.node_owned[std::size_t(r.node)])
      out.insert(out.end(), {double(sd.node_id[std::size_t(r.node)]), r.work});
  return out;
}

void Boundary::saveState(util::ArchiveWriter& out, const std::vector<double>& motion_work) const {
  out.put<uint64_t>(walls_.size());
  for (const auto& w : walls_) visitWall(w, [&](const auto& v) { out.put(v); });
  // The work of the prescribed motions so far (bndout), gathered from every rank by the
  // caller, in ascending node id (the same bytes at any rank count).
  std::vector<std::pair<double, double>> pairs;
  for (std::size_t k = 0; k + 1 < motion_work.size(); k += 2)
    pairs.emplace_back(motion_work[k], motion_work[k + 1]);
  std::sort(pairs.begin(), pairs.end());
  std::vector<double> sorted;
  for (const auto& [id, w] : pairs) sorted.insert(sorted.end(), {id, w});
  out.put(sorted);
}

void Boundary::loadState(util::ArchiveReader& in, const domain::Subdomain& sd) {
  util::expectCount(in, walls_.size(), "rigid walls");
  for (auto& w : walls_) visitWall(w, [&](auto& v) { in.get(v); });
  std::vector<double> work;  // (global node id, work) pairs, ascending id
  in.get(work);
  for (auto& r : motion_reaction_) {
    const double id = double(sd.node_id[std::size_t(r.node)]);
    std::size_t lo = 0, hi = work.size() / 2;
    while (lo < hi) {  // binary search of the pair with this id
      const std::size_t mid = (lo + hi) / 2;
      if (work[2 * mid] < id)
        lo = mid + 1;
      else
        hi = mid;
    }
    if (lo < work.size() / 2 && work[2 * lo] == id) r.work = work[2 * lo + 1];
  }
}

}  // namespace crumple::constraints
