// Belytschko-Lin-Tsay shell and C0 triangle kernels (see shell.hpp).
//
// Notation: corners a = 0..3 (LS-DYNA nodes 1..4); a triangle has corner 3 on corner 2's node.
// Frame (BLT 1984; LS-DYNA Theory Manual, Belytschko-Lin-Tsay shell, corotational
// coordinates): e3 = r20 x r31 / |r20 x r31| (the diagonals), e1 = side 0-1 minus its e3 part,
// normalised (LS-DYNA's default), e2 = e3 x e1. Components in this frame are "local"; (x_a,
// y_a) are the corners' in-plane coordinates.
// One-point quadrature at the centre: B1 = dN/dx = (y1-y3, y2-y0, y3-y1, y0-y2) / 2A,
// B2 = dN/dy = (x3-x1, x0-x2, x1-x3, x2-x0) / 2A, 2A = (x2-x0)(y3-y1) - (x3-x1)(y2-y0).
// Velocity strains at height z (Mindlin kinematics: the fibre turns with the nodal rotation
// theta, so u_x = z theta_y, u_y = -z theta_x; BLT 1984, velocity strains):
//   d_xx = B1.vx + z B1.ty                   d_yy = B2.vy - z B2.tx
//   2 d_xy = B2.vx + B1.vy + z (B2.ty - B1.tx)
//   2 d_xz = B1.vz + ty_mean                 2 d_yz = B2.vz - tx_mean   (mean of the corners)
// The rates (and the hourglass rates) use the mid-step geometry x(n) - dt/2 v(n-1/2) and its
// frame, as the hex kernel does: a rigid rotation then gives zero strain to round-off however
// large the step's angle (the midpoint rule; the current geometry would give a strain of
// (1 - cos dtheta) a step).
// Resultants over the thickness t with the rule's weights w_i at z_i = zeta_i t / 2:
//   N = t sum w_i s_i,  M = t^2/2 sum w_i zeta_i s_i,  Q = kappa t tau (tau elastic, uniform),
// and the corner forces and moments are the derivatives of the internal power
// A (N.d_m + M.kappa + Q.gamma) with respect to the corner velocities:
//   fx_a = A (B1 Nxx + B2 Nxy)        mx_a = A (-B2 Myy - B1 Mxy - Qy / 4)
//   fy_a = A (B2 Nyy + B1 Nxy)        my_a = A ( B1 Mxx + B2 Mxy + Qx / 4)
//   fz_a = A (B1 Qx + B2 Qy)          (the drilling moment: below)
// (BLT's nodal forces, with M defined here as +sum z s; LS-DYNA writes m = -sum z s), evaluated
// with the geometry and frame at x(n). The slots get minus these, turned to the global frame
// (the force on the node, as the hex kernel writes f_a = -sigma.B_a).
//
// Hourglass control (BLT 1984; LS-DYNA Theory Manual, BT shell hourglass control): the
// projected vector gamma_a = h_a - (h.x) B1_a - (h.y) B2_a, h = (1, -1, 1, -1), is orthogonal to
// every linear field, so rigid motions and the patch test give no hourglass rate. Five modes:
// membrane gamma.vx, gamma.vy; bending gamma.tx, gamma.ty; transverse gamma.vz, with the
// stiffnesses (QM the hourglass coefficient, B.B = sum of B1^2 + B2^2)
//   membrane QM E t A B.B / 8,   bending QM E t^3 A B.B / 192,   transverse QM kappa G t^3 B.B / 12
// (membrane and bending as in the LS-DYNA manual's BT hourglass section; the transverse one
// written so that it is a stiffness, force per length, scaled like the twist stiffness
// G t^3 B.B / 6 of a square plate, the mode the one-point quadrature misses). IHQ 4, 5:
// resistances accumulated from the rates (stored in the element frame, so they turn with it);
// IHQ 1-3: viscous, the same stiffness times L_s / c, a damping ratio of at most QM for every
// hourglass mode (the hex's viscous coefficient is 1.33 times its stiffness times L/c in the
// same sense).
//
// Warping (Belytschko, Wong & Chiang 1992, "Advances in one-point quadrature shell elements",
// CMAME 96:93-107): in a warped element the corners sit at heights z_a = +-z_w h_a off the mean
// plane, and a rigid rotation about the in-plane axes, omega_x = B2.vz, omega_y = -B1.vz,
// moves them in the plane by (omega_y z_a, -omega_x z_a): a membrane hourglass rate without
// deformation (gamma.z_a = 4 z_w), and the hourglass forces then carry a net moment. With BWC
// those in-plane velocities are taken out of the membrane hourglass rates,
//   q_m1 = gamma.vx + (gamma.z) B1.vz,  q_m2 = gamma.vy + (gamma.z) B2.vz,
// and the transpose adds (gamma.z)(Q_m1 B1_a + Q_m2 B2_a) to fz_a, which restores moment
// balance. (The membrane strain is unaffected: B.h = 0.)
//
// Drilling rotations. A node carries three rotation rates and an element uses only their
// in-plane components (tx, ty), so the component along the element normal (the drilling
// rotation) has neither stiffness nor load where the elements at a node are coplanar. Where two
// neighbours meet at an angle s, a rotation rate w of the node about their mean normal turns
// each of them about its own in-plane axis at +-w s / 2: patterns that strain neither element
// and move only the bending hourglass modes (gamma.tx, gamma.ty). A stiffness hourglass form
// (IHQ 4, 5) resists them with a stiffness of order s^2; the viscous forms (IHQ 1-3) cannot hold
// a steady moment, so the node spins up about the normal under a steady torque and the
// structure unloads (measured on a bent strip: docs/theory.md, "Shells").
// The constraint (Hughes & Brezzi 1989, "On drilling degrees of freedom", CMAME 72:105-121,
// as a penalty; the fictitious drilling stiffness of flat shell elements, Kanok-Nukulchai
// 1979, IJNME 14:179-200) ties each corner's rotation about the normal to the membrane's
// spin, with a resistance accumulated like the stiffness hourglass forms (in the element
// frame, midpoint energy):
//   r_a = w_a.e3 - (dvy/dx - dvx/dy) / 2,   m_a += k_d r_a dt,   k_d = 0.01 E t^3 / 12
// (a hundredth of the plate's bending rigidity per corner; it adds at most
// k_d / I_a = 0.04 E / (rho A) to a squared rotational frequency, with the t^2 / 12 floor of the
// inertia, a hundredth of the step's limit 4.4 E / (rho A)). The corner moments m_a act about
// e3, and the reaction of their sum on the membrane spin gives the in-plane forces (the
// transpose of the rate)
//   fx_a += B2_a sum(m) / 2,   fy_a -= B1_a sum(m) / 2,
// so that the element's forces and moments stay self-equilibrated. A rigid motion has r = 0 (a
// spin about the normal turns the nodes and the membrane alike). The constraint's work counts
// as hourglass energy (an artificial stabilisation, like hourglass work). Triangles have none
// (they have no hourglass modes for the drilling rotation to drive).
//
// C0 triangle (Belytschko, Stolarski & Carpenter 1984): the same frame, membrane (constant
// strain: the quadrilateral formulas with corners 2 and 3 on one node give the CST gradients)
// and constant curvature from the linear rotation field. Transverse shear with one-point
// quadrature at the centroid locks in bending (two constraints per triangle, a strip of split
// quadrilaterals cannot bend); BSC avoid locking by a special treatment of the shear. Here the
// transverse shear is built from the tangential shear along the three edges, the Timoshenko
// condition of each edge, (w_j - w_i) / L + mean(beta_i, beta_j).t (beta = (ty, -tx)), through
// the lowest-order edge (Nedelec) field, evaluated at the centroid (the assumed shear of the
// MITC3 triangle: Lee & Bathe 2004, Comput. Struct. 82:945-962):
//   gamma = 1/3 sum_edges [(w_j - w_i) + (beta_i + beta_j)/2 . (x_j - x_i)] (grad N_j - grad N_i).
// It is exact for every field with constant shear and zero for rigid motions; the forces are
// its transpose. No hourglass control (three nodes, one point: no hourglass modes).
//
// Plasticity: the plane-stress return of materials/plane_stress.hpp at every point. A point
// that reaches the failure strain carries no stress; the element erodes when every point
// through the thickness has failed (LS-DYNA erodes shells when all through-thickness points
// have failed; its NUMFIP-type controls are not implemented).
// Thickness update (ISTUPD): t += t sum w_i deps_zz,i with the points' thickness strains.
#include "elements/shell.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "elements/hex8_kernel.hpp"
#include "elements/shell_kernel.hpp"
#include "materials/plane_stress.hpp"
#include "util/error.hpp"

namespace crumple::elements {

namespace {

using namespace shell_detail;  // NOLINT(google-build-using-namespace): the shared kernel pieces

// The projected hourglass vector gamma_a = h_a - (h.x) B1_a - (h.y) B2_a and gamma.z, with z_a
// the corner heights above the plane through the corners' centroid (for BWC).
inline void hourglassOf(const LaneFrame& f, const NodalShell& x, int l, double g[4], double& gz) {
  double hx = 0.0, hy = 0.0;
  for (int a = 0; a < 4; ++a) {
    hx += kH[a] * f.xh[a];
    hy += kH[a] * f.yh[a];
  }
  for (int a = 0; a < 4; ++a) g[a] = kH[a] - hx * f.b1[a] - hy * f.b2[a];
  const double cx = 0.25 * (x[0][0][l] + x[0][1][l] + x[0][2][l] + x[0][3][l]);
  const double cy = 0.25 * (x[1][0][l] + x[1][1][l] + x[1][2][l] + x[1][3][l]);
  const double cz = 0.25 * (x[2][0][l] + x[2][1][l] + x[2][2][l] + x[2][3][l]);
  gz = 0.0;
  for (int a = 0; a < 4; ++a)
    gz += g[a] * (f.e[2][0] * (x[0][a][l] - cx) + f.e[2][1] * (x[1][a][l] - cy) +
                  f.e[2][2] * (x[2][a][l] - cz));
}

// ---- the C0 triangle's edge-based transverse shear (see the file comment) ---------------------
constexpr int kEdge[3][2] = {{0, 1}, {1, 2}, {2, 0}};

// Gradients of the three corner functions: corners 2 and 3 are one node.
inline void triangleGradients(const LaneFrame& f, double gx[3], double gy[3]) {
  gx[0] = f.b1[0];
  gy[0] = f.b2[0];
  gx[1] = f.b1[1];
  gy[1] = f.b2[1];
  gx[2] = f.b1[2] + f.b1[3];
  gy[2] = f.b2[2] + f.b2[3];
}

// gamma_xz, gamma_yz from the corner velocities vz and rotations tx, ty in the frame.
inline void triangleShearRate(const LaneFrame& f, const double vz[4], const double tx[4],
                              const double ty[4], double& gxz, double& gyz) {
  double gx[3], gy[3];
  triangleGradients(f, gx, gy);
  double sx = 0.0, sy = 0.0;
  for (const auto& ed : kEdge) {
    const int i = ed[0], j = ed[1];
    const double dx = f.xh[j] - f.xh[i], dy = f.yh[j] - f.yh[i];
    const double term = (vz[j] - vz[i]) + 0.5 * ((ty[i] + ty[j]) * dx - (tx[i] + tx[j]) * dy);
    sx += term * (gx[j] - gx[i]);
    sy += term * (gy[j] - gy[i]);
  }
  gxz = sx * (1.0 / 3.0);
  gyz = sy * (1.0 / 3.0);
}

// The transpose: internal corner force fz and moments mx, my (frame components) of the shear
// resultants qx, qy.
inline void triangleShearForces(const LaneFrame& f, double qx, double qy, double fz[4],
                                double mx[4], double my[4]) {
  double gx[3], gy[3];
  triangleGradients(f, gx, gy);
  const double area_3 = f.area * (1.0 / 3.0);
  for (int a = 0; a < 4; ++a) fz[a] = mx[a] = my[a] = 0.0;
  for (const auto& ed : kEdge) {
    const int i = ed[0], j = ed[1];
    const double dx = f.xh[j] - f.xh[i], dy = f.yh[j] - f.yh[i];
    const double s = area_3 * (qx * (gx[j] - gx[i]) + qy * (gy[j] - gy[i]));
    fz[j] += s;
    fz[i] -= s;
    const double hx = 0.5 * s * dx, hy = 0.5 * s * dy;
    my[i] += hx;
    my[j] += hx;
    mx[i] -= hy;
    mx[j] -= hy;
  }
}

// Velocity strains and hourglass rates at the mid-step geometry.
inline void midStepRates(const ShellParams& p, ShellScratch& s, const ShellLanes& ln,
                         ShellRates& r) {
  constexpr int B = kShellBatch;
  const double dt = p.dt;
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 4; ++a)
      for (int l = 0; l < B; ++l) s.xm[c][a][l] = s.x[c][a][l] - 0.5 * dt * s.v[c][a][l];
  for (int l = 0; l < B; ++l) {
    const LaneFrame f = frameAt(s.xm, l);
    double vx[4], vy[4], vz[4], tx[4], ty[4], tz[4];
    onAxis(f, 0, s.v, l, vx);
    onAxis(f, 1, s.v, l, vy);
    onAxis(f, 2, s.v, l, vz);
    onAxis(f, 0, s.w, l, tx);
    onAxis(f, 1, s.w, l, ty);
    onAxis(f, 2, s.w, l, tz);
    double sxx = 0, syy = 0, sxy = 0, cx = 0, cy = 0, cxy = 0, sz1 = 0, sz2 = 0, stx = 0, sty = 0,
           spin = 0;
    for (int a = 0; a < 4; ++a) {
      sxx += f.b1[a] * vx[a];
      syy += f.b2[a] * vy[a];
      sxy += f.b2[a] * vx[a] + f.b1[a] * vy[a];
      cx += f.b1[a] * ty[a];
      cy -= f.b2[a] * tx[a];
      cxy += f.b2[a] * ty[a] - f.b1[a] * tx[a];
      sz1 += f.b1[a] * vz[a];
      sz2 += f.b2[a] * vz[a];
      stx += tx[a];
      sty += ty[a];
      spin += f.b1[a] * vy[a] - f.b2[a] * vx[a];
    }
    // Drilling rates: each corner's rotation rate about the normal less the membrane's
    // spin (dvy/dx - dvx/dy) / 2.
    for (int a = 0; a < 4; ++a) r.rdrill[a][l] = tz[a] - 0.5 * spin;
    r.dxm[l] = sxx;
    r.dym[l] = syy;
    r.gxy[l] = sxy;
    r.kx[l] = cx;
    r.ky[l] = cy;
    r.kxy[l] = cxy;
    r.gxz[l] = sz1 + 0.25 * sty;
    r.gyz[l] = sz2 - 0.25 * stx;
    r.area_mid[l] = f.area;
    // Hourglass rates of the five modes: membrane x, y (BWC: less the in-plane motion of
    // the warped corners in a rigid rotation), bending x, y, transverse.
    double g[4], gz;
    hourglassOf(f, s.xm, l, g, gz);
    gz *= p.bwc;
    double r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    for (int a = 0; a < 4; ++a) {
      r0 += g[a] * vx[a];
      r1 += g[a] * vy[a];
      r2 += g[a] * tx[a];
      r3 += g[a] * ty[a];
      r4 += g[a] * vz[a];
    }
    r.qdot[0][l] = r0 + gz * sz1;
    r.qdot[1][l] = r1 + gz * sz2;
    r.qdot[2][l] = r2;
    r.qdot[3][l] = r3;
    r.qdot[4][l] = r4;
  }
  if (ln.any_tri) {
    for (int l = 0; l < B; ++l) {
      if (ln.tri[l] == 0.0) continue;
      const LaneFrame f = frameAt(s.xm, l);
      double vz[4], tx[4], ty[4];
      onAxis(f, 2, s.v, l, vz);
      onAxis(f, 0, s.w, l, tx);
      onAxis(f, 1, s.w, l, ty);
      triangleShearRate(f, vz, tx, ty, r.gxz[l], r.gyz[l]);
    }
  }
}

// Forces, moments and stable step at the current geometry: resultants, hourglass and drilling
// resistances to corner forces and moments (s.fg, s.mg, global frame, the forces on the nodes).
inline void cornerForces(const ShellParams& p, const domain::ShellBlock& blk, ShellScratch& s,
                         const ShellLanes& ln, const double* hg_old, const ShellRates& r,
                         const ShellResultants& q, ShellForcesOut& o) {
  constexpr int B = kShellBatch;
  const double dt = p.dt;
  Lanes inv_c_dt;
  slownessOf(p, blk, ln, inv_c_dt);
  // The stored resistances copied to the stack: the loop below then has no pointer that
  // might alias its stores, and GCC vectorises it.
  double hg_prev[5][B], drill_prev[4][B];
  for (int mode = 0; mode < 5; ++mode)
    for (int l = 0; l < B; ++l) hg_prev[mode][l] = hg_old[mode * B + l];
  loadDrill(blk, ln.first, drill_prev);
  for (int l = 0; l < B; ++l) {
    const LaneFrame f = frameAt(s.x, l);
    const double A = f.area;
    const double ls = A / longestSide(s.x, l);
    o.area[l] = A;
    o.dte[l] = (1.0 + ln.tri[l]) * ls * inv_c_dt[l];
    // Resultants to corner forces (the triangle's transverse shear is added below).
    const double quad = 1.0 - ln.tri[l];
    const double sqx = quad * q.qx[l], sqy = quad * q.qy[l];
    double fx[4], fy[4], fz[4], mx[4], my[4];
    for (int a = 0; a < 4; ++a) {
      const double b1 = f.b1[a], b2 = f.b2[a];
      fx[a] = A * (b1 * q.nxx[l] + b2 * q.nxy[l]);
      fy[a] = A * (b2 * q.nyy[l] + b1 * q.nxy[l]);
      fz[a] = A * (b1 * sqx + b2 * sqy);
      mx[a] = A * (-b2 * q.myy[l] - b1 * q.mxy[l] - 0.25 * sqy);
      my[a] = A * (b1 * q.mxx[l] + b2 * q.mxy[l] + 0.25 * sqx);
    }
    // Hourglass resistances (none for triangles).
    double g[4], gz, bb = 0.0;
    hourglassOf(f, s.x, l, g, gz);
    gz *= p.bwc;
    for (int a = 0; a < 4; ++a) bb += f.b1[a] * f.b1[a] + f.b2[a] * f.b2[a];
    const double t = q.t_new[l];
    const double E = p.mc.E;
    const double scale = quad * p.qm * (p.hg_dt + p.hg_visc * ls);
    const double coef[5] = {scale * E * t * A * bb * 0.125, scale * E * t * A * bb * 0.125,
                            scale * E * t * t * t * A * bb * (1.0 / 192.0),
                            scale * E * t * t * t * A * bb * (1.0 / 192.0),
                            scale * p.kappa * p.mc.G * t * t * t * bb * (1.0 / 12.0)};
    double hf[5], e_hg = 0.0;
    // Work by the trapezoidal rule on the force, for both forms: the force formed now acts
    // half over the last step and half over the next, at v(n) (docs/theory.md, "Energy
    // balance"), so this step's rate meets the mean of the last force and this one. (The
    // viscous force counted whole at this step's rate over-counted the dissipation of ringing
    // modes, as it did for the solids.)
    for (int mode = 0; mode < 5; ++mode) {
      const double old = hg_prev[mode][l];
      hf[mode] = (p.stiffness_hg ? old : 0.0) + coef[mode] * r.qdot[mode][l];
      o.hg_new[mode][l] = hf[mode];
      e_hg += 0.5 * (old + hf[mode]) * r.qdot[mode][l] * dt;
    }
    // Drilling moments (none for triangles), accumulated like the stiffness hourglass
    // resistances; the membrane spin's share goes to the in-plane forces.
    const double kd = quad * p.drill_coef * t * t * t;
    double mz[4], drill_sum = 0.0, e_drill = 0.0;
    drillMoments(drill_prev, r.rdrill, kd, dt, l, mz, o.drill_new, drill_sum, e_drill);
    o.de_hg[l] = e_hg;
    o.de_drill[l] = e_drill;
    for (int a = 0; a < 4; ++a) {
      fx[a] += hf[0] * g[a] + 0.5 * f.b2[a] * drill_sum;
      fy[a] += hf[1] * g[a] - 0.5 * f.b1[a] * drill_sum;
      fz[a] += hf[4] * g[a] + gz * (hf[0] * f.b1[a] + hf[1] * f.b2[a]);
      mx[a] += hf[2] * g[a];
      my[a] += hf[3] * g[a];
    }
    cornerLoadsToGlobal(f, fx, fy, fz, mx, my, mz, l, s);
  }
}

// The triangles' edge-based transverse shear forces, added to s.fg, s.mg; corner 3's share
// moved to corner 2 (one node).
inline void triangleForces(ShellScratch& s, const ShellLanes& ln, const ShellResultants& q) {
  for (int l = 0; l < kShellBatch; ++l) {
    if (ln.tri[l] == 0.0) continue;
    const LaneFrame f = frameAt(s.x, l);
    double fz[4], mx[4], my[4];
    triangleShearForces(f, q.qx[l], q.qy[l], fz, mx, my);
    for (int c = 0; c < 3; ++c) {
      for (int a = 0; a < 4; ++a) {
        s.fg[c][a][l] -= f.e[2][c] * fz[a];
        s.mg[c][a][l] -= f.e[0][c] * mx[a] + f.e[1][c] * my[a];
      }
      s.fg[c][2][l] += s.fg[c][3][l];
      s.mg[c][2][l] += s.mg[c][3][l];
      s.fg[c][3][l] = s.mg[c][3][l] = 0.0;
    }
  }
}

// Stores the batch's state (whole batch, eroded lanes zeroed or kept).
template <class Law>
inline void storeState(const ShellParams& p, domain::ShellBlock& blk, const ShellScratch& s,
                       const ShellLanes& ln, double* sig_batch, double* ep_batch,
                       double* alpha_batch, const ShellResultants& q, const ShellForcesOut& o) {
  constexpr int B = kShellBatch;
  const std::size_t first = ln.first;
  Lanes alive;  // 1 for an element not eroded (as double: the selects below vectorise)
  aliveLanes(blk, first, alive);
  storePoints<Law>(p, s, alive, sig_batch, ep_batch, alpha_batch, q);
  if (p.hg_state) {
    double* hgq_batch = blk.hgq.data() + first * 5;
    for (int mode = 0; mode < 5; ++mode)
      for (int l = 0; l < B; ++l)
        hgq_batch[mode * B + l] = alive[l] != 0.0 ? o.hg_new[mode][l] : 0.0;
  }
  {
    double* drill_batch = blk.drill.data() + first * 4;
    for (int a = 0; a < 4; ++a)
      for (int l = 0; l < B; ++l)
        drill_batch[a * B + l] = alive[l] != 0.0 ? o.drill_new[a][l] : 0.0;
  }
  for (int l = 0; l < B; ++l) {
    const std::size_t e = first + static_cast<std::size_t>(l);
    blk.thick[e] = alive[l] != 0.0 ? q.t_new[l] : blk.thick[e];
    blk.e_int[e] += alive[l] != 0.0 ? q.de_int[l] : 0.0;
    blk.e_hg[e] += alive[l] != 0.0 ? o.de_hg[l] : 0.0;
    blk.e_drill[e] += alive[l] != 0.0 ? o.de_drill[l] : 0.0;
  }
}

// One portable binary, three instruction sets, as the hex kernel (same bits on every path: no
// FMA contraction, no fast-math). The helpers above are inlined into each clone (flatten).
// Each element loop runs over the lanes of the batch with the element's frame built inside it
// (LaneFrame, in registers); GCC vectorises these loops across lanes (checked with
// -fopt-info-vec; `#pragma omp simd` on them made GCC 12 run them scalar: docs/performance.md).
template <class Law>
[[gnu::flatten, gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]] BlockStatus
shellBlockForces(const Law& law, domain::ShellBlock& blk, const domain::NodeVector& x,
                 const domain::NodeVector& v, const domain::NodeVector& w, double dt, double* slots,
                 std::size_t range_first, std::size_t range_last) {
  constexpr int B = kShellBatch;
  const std::size_t ne = range_last;
  const std::size_t batch0 = range_first / B;
  const std::size_t nbatch = range_last > range_first ? (range_last - range_first + B - 1) / B : 0;
  const ShellParams p = shellParamsOf(law, blk, dt);
  std::vector<BlockStatus> status(nbatch);

#pragma omp parallel
  {
    ShellScratch s;
#pragma omp for schedule(static)
    for (std::size_t ib = 0; ib < nbatch; ++ib) {
      ShellLanes ln;
      ln.first = (batch0 + ib) * B;
      ln.n = static_cast<int>(std::min<std::size_t>(B, ne - ln.first));
      const std::size_t first = ln.first;
      loadBatch(blk, x, v, w, s, ln);
      double* sig_batch = blk.sig.data() + first * static_cast<std::size_t>(p.fields);
      double* ep_batch =
          Law::kPlastic ? blk.eps_p.data() + first * static_cast<std::size_t>(p.nip) : nullptr;
      double* alpha_batch = materials::shellAlphaOf<Law>()
                                ? blk.alpha.data() + first * static_cast<std::size_t>(3 * p.nip)
                                : nullptr;
      const double* hg_old = p.hg_state ? blk.hgq.data() + first * 5 : s.zeros;
      ShellRates r;
      midStepRates(p, s, ln, r);
      Lanes work, failed_points;
      double* ero_batch =
          p.erosion ? blk.erosion_state.data() + first * std::size_t(blk.erosionFields()) : nullptr;
      double* hist_batch = materials::historyOf<Law>() > 0
                               ? blk.hist.data() + first * std::size_t(blk.histFields())
                               : nullptr;
      pointStresses(law, p, s, sig_batch, ep_batch, alpha_batch, ln, r, work, failed_points,
                    ero_batch, hist_batch);
      dropDeletedPoints(p, s, failed_points);
      ShellResultants q;
      resultantsOf(p, s, sig_batch, ln, r, work, q);
      ShellForcesOut o;
      cornerForces(p, blk, s, ln, hg_old, r, q, o);
      if (ln.any_tri) triangleForces(s, ln, q);
      storeState<Law>(p, blk, s, ln, sig_batch, ep_batch, alpha_batch, q, o);
      writeSlots(p, blk, s, ln, failed_points, o, slots, status[ib]);
    }
  }
  return detail::mergeStatus(status);
}

// Legendre polynomial P_n and its derivative at x.
void legendre(int n, double x, double& p, double& dp) {
  double p0 = 1.0, p1 = x;
  if (n == 0) {
    p = 1.0;
    dp = 0.0;
    return;
  }
  for (int k = 1; k < n; ++k) {
    const double p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1);
    p0 = p1;
    p1 = p2;
  }
  p = p1;
  dp = n * (x * p1 - p0) / (x * x - 1.0);
}

}  // namespace

void throughThicknessRule(int nip, bool lobatto, std::vector<double>& zeta,
                          std::vector<double>& weight) {
  if (nip < 1 || nip > kMaxShellPoints || (lobatto && nip < 3))
    throw std::invalid_argument("throughThicknessRule: NIP must be 1-10 (Gauss) or 3-10 (Lobatto)");
  zeta.assign(static_cast<std::size_t>(nip), 0.0);
  weight.assign(static_cast<std::size_t>(nip), 0.0);
  if (nip == 1) {
    weight[0] = 1.0;
    return;
  }
  if (!lobatto) {
    // Gauss-Legendre: the roots of P_n by Newton's method from Chebyshev-like guesses; weights
    // 2 / ((1 - x^2) P_n'(x)^2), halved to sum to 1.
    for (int i = 0; i < nip; ++i) {
      double xi = std::cos(M_PI * (i + 0.75) / (nip + 0.5));
      for (int it = 0; it < 100; ++it) {
        double p, dp;
        legendre(nip, xi, p, dp);
        const double dx = p / dp;
        xi -= dx;
        if (std::abs(dx) < 1e-16) break;
      }
      double p, dp;
      legendre(nip, xi, p, dp);
      zeta[static_cast<std::size_t>(nip - 1 - i)] = xi;
      weight[static_cast<std::size_t>(nip - 1 - i)] = 1.0 / ((1.0 - xi * xi) * dp * dp);
    }
  } else {
    // Gauss-Lobatto: the end points and the roots of P_{n-1}'; weights 2 / (n (n-1) P_{n-1}^2),
    // halved. P'' from Legendre's equation (1 - x^2) P'' = 2 x P' - m (m + 1) P.
    const int m = nip - 1;
    const double end_weight = 1.0 / (nip * m);
    zeta.front() = -1.0;
    zeta.back() = 1.0;
    weight.front() = weight.back() = end_weight;
    for (int i = 1; i < m; ++i) {
      double xi = std::cos(M_PI * i / m);
      for (int it = 0; it < 100; ++it) {
        double p, dp;
        legendre(m, xi, p, dp);
        const double d2p = (2.0 * xi * dp - m * (m + 1.0) * p) / (1.0 - xi * xi);
        const double dx = dp / d2p;
        xi -= dx;
        if (std::abs(dx) < 1e-16) break;
      }
      double p, dp;
      legendre(m, xi, p, dp);
      zeta[static_cast<std::size_t>(m - i)] = xi;
      weight[static_cast<std::size_t>(m - i)] = end_weight / (p * p);
    }
  }
  // Symmetrise (exact antisymmetric abscissae and symmetric weights), so that pure bending
  // gives no membrane force to round-off.
  for (int i = 0; i < nip / 2; ++i) {
    const auto lo = static_cast<std::size_t>(i), hi = static_cast<std::size_t>(nip - 1 - i);
    const double z = 0.5 * (zeta[hi] - zeta[lo]), wt = 0.5 * (weight[hi] + weight[lo]);
    zeta[lo] = -z;
    zeta[hi] = z;
    weight[lo] = weight[hi] = wt;
  }
  if (nip % 2 == 1) zeta[static_cast<std::size_t>(nip / 2)] = 0.0;
}

void resizeShellBlock(domain::ShellBlock& blk, std::size_t n) {
  const std::size_t padded = (n + kShellBatch - 1) / kShellBatch * kShellBatch;
  // A user rule (*INTEGRATION_SHELL) comes with the block; the built-in ones from nip.
  if (blk.zeta.size() != std::size_t(blk.nip))
    throughThicknessRule(blk.nip, blk.lobatto, blk.zeta, blk.weight);
  blk.thick.assign(padded, 0.0);
  blk.area0.assign(padded, 0.0);
  blk.e_int.assign(padded, 0.0);
  blk.e_hg.assign(padded, 0.0);
  blk.e_drill.assign(padded, 0.0);
  blk.active.assign(padded, 1);
  blk.failed.assign(padded, 0);
  blk.sig.assign(padded * static_cast<std::size_t>(blk.sigFields()), 0.0);
  if (materials::isPlastic(blk.law)) {
    blk.eps_p.assign(padded * static_cast<std::size_t>(blk.epsFields()), 0.0);
  } else {
    blk.eps_p.clear();
  }
  if (materials::hasShellAlpha(blk.law)) {
    blk.alpha.assign(padded * static_cast<std::size_t>(blk.alphaFields()), 0.0);
  } else {
    blk.alpha.clear();
  }
  // The last hourglass forces: the stiffness forms' state, the viscous forms' work (ELFORM 16
  // has no hourglass modes).
  if (blk.planar() || (blk.inPlanePoints() == 1 && (blk.ihq >= 4 || blk.qm > 0.0))) {
    blk.hgq.assign(padded * 5, 0.0);
  } else {
    blk.hgq.clear();
  }
  blk.drill.assign(padded * 4, 0.0);
  blk.history = blk.planar() ? 0 : materials::historyCount(blk.law);
  blk.hist.assign(padded * static_cast<std::size_t>(blk.histFields()), 0.0);
  blk.erosion_state.assign(blk.erosion.any() && !blk.planar()
                               ? padded * static_cast<std::size_t>(blk.erosionFields())
                               : 0,
                           0.0);
}

double shellTimeStep(double area, double longest_side, bool triangle, double wave_speed) {
  // The kernel's expression: (1 + beta) (A / L) (1 / c).
  return (triangle ? 2.0 : 1.0) * (area / longest_side) * (1.0 / wave_speed);
}

namespace {

// ShellBlock::axis_angle of a law whose axes come from a vector: the angle of its a axis in each
// element's frame at x0; an element in whose plane the vector gives no direction is an input
// error naming it.
template <class L>
void setAxisAngles(const L& law, domain::ShellBlock& blk, const domain::NodeVector& x0) {
  blk.axis_angle.clear();
  if constexpr (requires(const double e[3][3]) { law.axisAngle(e); }) {
    if (!law.elementAxes()) return;
    blk.axis_angle.assign(blk.paddedSize(), 0.0);
    NodalShell xs;
    for (std::size_t e = 0; e < blk.paddedSize(); ++e) {
      const std::size_t r = std::min(e, blk.size() - 1);
      gatherCorners(blk, r, 1, x0, xs);
      const LaneFrame f = frameAt(xs, 0);
      const double angle = law.axisAngle(f.e);
      // A degenerate element (no area) is reported by initializeShells as such.
      if (std::isnan(angle) && f.area > 0.0)
        throw util::InputError("part " + std::to_string(blk.part_id) + ": shell element " +
                               std::to_string(blk.elem_id[r]) +
                               ": the material's AOPT vector has no direction in its plane");
      blk.axis_angle[e] = std::isnan(angle) ? 0.0 : angle;
    }
  }
}

}  // namespace

BlockStatus initializeShells(domain::ShellBlock& blk, const domain::NodeVector& x0, double* slots,
                             std::vector<double>& element_dt) {
  if (!blk.planar() && blk.size() > 0)
    std::visit([&](const auto& l) { setAxisAngles(l, blk, x0); }, blk.law);
  const std::size_t ne = blk.size();
  if (blk.thick.size() != blk.paddedSize()) resizeShellBlock(blk, ne);
  const ShellConstants mc = constantsOf(blk.law, blk.rho0);
  BlockStatus st;
  element_dt.assign(ne, 0.0);
  for (std::size_t e = 0; e < blk.paddedSize(); ++e) {
    // Padding lanes replicate the last element (sane values for the kernel to chew on).
    const std::size_t r = std::min(e, ne - 1);
    const auto& conn = blk.conn[r];
    const bool triangle = blk.isTriangle(r);
    if (triangle && blk.inPlanePoints() != 1)
      throw std::logic_error(
          "initializeShells: a triangle in an ELFORM 16 block (triangles of "
          "ELFORM 16 parts run as C0 triangles in a block of their own)");
    const auto& ct = blk.corner_thickness[r];
    const double t =
        triangle ? (ct[0] + ct[1] + ct[2]) / 3.0 : 0.25 * (ct[0] + ct[1] + ct[2] + ct[3]);
    // Area and longest side as the kernel computes them.
    double p[4][3];
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 3; ++c) p[a][c] = x0[3 * static_cast<std::size_t>(conn[a]) + c];
    const double d20[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    const double d31[3] = {p[3][0] - p[1][0], p[3][1] - p[1][1], p[3][2] - p[1][2]};
    const double nx = d20[1] * d31[2] - d20[2] * d31[1], ny = d20[2] * d31[0] - d20[0] * d31[2],
                 nz = d20[0] * d31[1] - d20[1] * d31[0];
    const double area = 0.5 * std::sqrt(nx * nx + ny * ny + nz * nz);
    double m2 = 0.0;
    for (int a = 0; a < 4; ++a) {
      const int b = (a + 1) % 4;
      double d2 = 0.0;
      for (int c = 0; c < 3; ++c) d2 += (p[b][c] - p[a][c]) * (p[b][c] - p[a][c]);
      m2 = std::max(m2, d2);
    }
    blk.thick[e] = t;
    blk.area0[e] = area;
    if (e >= ne) continue;
    if (!(area > 0.0) || !(t > 0.0)) {
      if (st.bad_elem < 0 || blk.elem[e] < st.bad_elem) st.bad_elem = blk.elem[e];
      continue;
    }
    const double corner_mass = blk.rho0 * t * area * (triangle ? 1.0 / 3.0 : 0.25);
    const double inertia = corner_mass * std::max(area / 8.0, t * t / 12.0);
    double* slot = slots + 3 * (blk.slot_offset + 8 * e);
    std::fill(slot, slot + 24, 0.0);
    for (int a = 0; a < 4; ++a) {
      const bool real = !(triangle && a == 3);
      slot[3 * a] = real ? corner_mass : 0.0;
      slot[12 + 3 * a] = real ? inertia : 0.0;
    }
    const double dte = shellTimeStep(area, std::sqrt(m2), triangle, mc.wave_speed);
    element_dt[e] = dte;
    st.observeStep(dte, blk.elem[e]);
  }
  return st;
}

BlockStatus computeShellForces(domain::ShellBlock& block, const domain::NodeVector& x,
                               const domain::NodeVector& v, const domain::NodeVector& w, double dt,
                               double* slots, std::size_t first, std::size_t last) {
  if (first % kShellBatch != 0 || (last % kShellBatch != 0 && last != block.size()) ||
      last > block.size())
    throw std::logic_error("computeShellForces: range not aligned to batches");
  return std::visit(
      [&](const auto& law) -> BlockStatus {
        if constexpr (materials::ShellLaw<std::decay_t<decltype(law)>>)
          return shellBlockForces(law, block, x, v, w, dt, slots, first, last);
        else
          materials::noUpdateFor(materials::Family::Shell);
      },
      block.law);
}

namespace {
// The transverse shear stresses (yz, zx) of element e: the mean of its in-plane points.
void meanShear(const domain::ShellBlock& blk, std::size_t e, double& tyz, double& tzx) {
  const int nq = blk.inPlanePoints();
  const double inv_nq = 1.0 / nq;  // as the in-plane means (the same bits as before)
  for (int q = 0; q < nq; ++q) {
    tyz += blk.shearAt(0, e, q) * inv_nq;
    tzx += blk.shearAt(1, e, q) * inv_nq;
  }
}
// The stress of in-plane components loc (xx, yy, xy) and transverse shears in the element
// frame fr, in the global frame (Voigt xx, yy, zz, xy, yz, zx).
void toGlobal(const LaneFrame& fr, const double loc[3], double tyz, double tzx, double out[6]) {
  const double sl[3][3] = {{loc[0], loc[2], tzx}, {loc[2], loc[1], tyz}, {tzx, tyz, 0.0}};
  double g[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double sum = 0.0;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) sum += fr.e[a][i] * sl[a][b] * fr.e[b][j];
      g[i][j] = sum;
    }
  out[0] = g[0][0];
  out[1] = g[1][1];
  out[2] = g[2][2];
  out[3] = g[0][1];
  out[4] = g[1][2];
  out[5] = g[2][0];
}
}  // namespace

void shellSurfaceStress(const domain::ShellBlock& blk, const domain::NodeVector& x, std::size_t e,
                        double out[3][6], double eps_p_out[3]) {
  // A 2D solid's one point holds the global 3-D stress (blocks.hpp): the same at every layer.
  if (blk.planar()) {
    for (int surface = 0; surface < 3; ++surface) {
      for (int k = 0; k < 6; ++k) out[surface][k] = blk.sigAt(k, 0, e);
      eps_p_out[surface] = blk.eps_p.empty() ? 0.0 : blk.epsAt(0, e);
    }
    return;
  }
  // The element's frame at x (lane 0 of a batch holding it).
  NodalShell xb;
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 3; ++c) xb[c][a][0] = x[3 * static_cast<std::size_t>(blk.conn[e][a]) + c];
  const LaneFrame fr = frameAt(xb, 0);
  const int nip = blk.nip;
  const bool plastic = !blk.eps_p.empty();
  // Local in-plane stress and plastic strain at the bottom, mid and top: the mean of the
  // in-plane points (one, or the 2 x 2 Gauss points of ELFORM 16, as LS-DYNA writes them).
  const int nq = blk.inPlanePoints();
  const double inv_nq = 1.0 / nq;
  double loc[3][3] = {}, ep[3] = {};
  const int picks[3] = {0, nip / 2, nip - 1};
  for (int q = 0; q < nq; ++q)
    for (int surface = 0; surface < 3; ++surface) {
      if (surface == 1 && nip % 2 == 0) {
        double m[3] = {0, 0, 0}, epm = 0.0;
        for (int p = 0; p < nip; ++p) {
          const double wp = blk.weight[static_cast<std::size_t>(p)];
          for (int k = 0; k < 3; ++k) m[k] += wp * blk.sigAt(k, p, e, q);
          epm += plastic ? wp * blk.epsAt(p, e, q) : 0.0;
        }
        for (int k = 0; k < 3; ++k) loc[surface][k] += m[k] * inv_nq;
        ep[surface] += epm * inv_nq;
        continue;
      }
      const int p = picks[surface];
      for (int k = 0; k < 3; ++k) loc[surface][k] += blk.sigAt(k, p, e, q) * inv_nq;
      ep[surface] += (plastic ? blk.epsAt(p, e, q) : 0.0) * inv_nq;
    }
  double tyz = 0.0, tzx = 0.0;
  meanShear(blk, e, tyz, tzx);
  for (int surface = 0; surface < 3; ++surface) {
    toGlobal(fr, loc[surface], tyz, tzx, out[surface]);
    eps_p_out[surface] = ep[surface];
  }
}

void shellPointStress(const domain::ShellBlock& blk, const domain::NodeVector& x, std::size_t e,
                      double (*out)[6], double* eps_p_out) {
  if (blk.planar()) {
    for (int k = 0; k < 6; ++k) out[0][k] = blk.sigAt(k, 0, e);
    eps_p_out[0] = blk.eps_p.empty() ? 0.0 : blk.epsAt(0, e);
    return;
  }
  NodalShell xb;
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 3; ++c) xb[c][a][0] = x[3 * static_cast<std::size_t>(blk.conn[e][a]) + c];
  const LaneFrame fr = frameAt(xb, 0);
  const int nq = blk.inPlanePoints();
  const double inv_nq = 1.0 / nq;
  double tyz = 0.0, tzx = 0.0;
  meanShear(blk, e, tyz, tzx);
  for (int p = 0; p < blk.nip; ++p) {
    double loc[3] = {}, ep = 0.0;
    for (int q = 0; q < nq; ++q) {
      for (int k = 0; k < 3; ++k) loc[k] += blk.sigAt(k, p, e, q) * inv_nq;
      ep += (blk.eps_p.empty() ? 0.0 : blk.epsAt(p, e, q)) * inv_nq;
    }
    toGlobal(fr, loc, tyz, tzx, out[p]);
    eps_p_out[p] = ep;
  }
}

void shellResultants(const domain::ShellBlock& blk, std::size_t e, double out[8]) {
  // A 2D solid bends nowhere: its in-plane forces per unit depth, N = sigma x 1.
  if (blk.planar()) {
    const double r[8] = {0, 0, 0, 0, 0, blk.sigAt(0, 0, e), blk.sigAt(1, 0, e), blk.sigAt(3, 0, e)};
    std::copy(r, r + 8, out);
    return;
  }
  // Point i sits at z = zeta_i t / 2 with weight w_i (sum 1): integral of f dz = t sum w_i f_i.
  const double t = blk.thick[e];
  const int nq = blk.inPlanePoints();
  double m[3] = {}, n[3] = {}, q[2] = {};
  for (int iq = 0; iq < nq; ++iq) {
    for (int p = 0; p < blk.nip; ++p) {
      const double w = blk.weight[std::size_t(p)] * t / nq;
      const double z = blk.zeta[std::size_t(p)] * 0.5 * t;
      for (int k = 0; k < 3; ++k) {
        n[k] += w * blk.sigAt(k, p, e, iq);
        m[k] -= w * z * blk.sigAt(k, p, e, iq);
      }
    }
    q[0] += t * blk.shearAt(1, e, iq) / nq;  // Qx from tau_zx
    q[1] += t * blk.shearAt(0, e, iq) / nq;  // Qy from tau_yz
  }
  const double r[8] = {m[0], m[1], m[2], q[0], q[1], n[0], n[1], n[2]};
  std::copy(r, r + 8, out);
}

}  // namespace crumple::elements
