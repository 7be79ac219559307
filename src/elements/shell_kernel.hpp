// What the shell kernels share (src/elements/shell.cpp, the Belytschko-Lin-Tsay shell and C0
// triangle; src/elements/shell_full.cpp, the fully integrated shell): lane types, the
// corotational frame of an element, batch loading, block constants, the plane-stress update of
// the points through the thickness, their resultants, and the slots. Notation and theory in
// src/elements/shell.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "domain/blocks.hpp"
#include "domain/subdomain.hpp"
#include "elements/hex8.hpp"
#include "elements/shell.hpp"
#include "materials/erosion.hpp"
#include "materials/plane_stress.hpp"

namespace crumple::elements::shell_detail {

using Lanes = double[kShellBatch];
using NodalShell = double[3][4][kShellBatch];  // [component][corner][lane]

constexpr double kH[4] = {1.0, -1.0, 1.0, -1.0};  // hourglass base vector
// Drilling stiffness of a corner as a fraction of the plate's bending rigidity E t^3 / 12
// (see the file comment, "Drilling rotations").
constexpr double kDrillStiffness = 0.01;
constexpr int kMaxPoints = kMaxShellPoints * kShellBatch;

// The corotational frame of one element and the one-point gradient operator in it. Built
// inside the lane loops, where it lives in registers.
struct LaneFrame {
  double e[3][3];       // e[axis][component]
  double xh[4], yh[4];  // in-plane corner coordinates, relative to corner 0
  double b1[4], b2[4];  // dN/dx, dN/dy
  double area;
};

inline LaneFrame frameAt(const NodalShell& x, int l) {
  LaneFrame f;
  const double d20x = x[0][2][l] - x[0][0][l], d20y = x[1][2][l] - x[1][0][l],
               d20z = x[2][2][l] - x[2][0][l];
  const double d31x = x[0][3][l] - x[0][1][l], d31y = x[1][3][l] - x[1][1][l],
               d31z = x[2][3][l] - x[2][1][l];
  double nx = d20y * d31z - d20z * d31y, ny = d20z * d31x - d20x * d31z,
         nz = d20x * d31y - d20y * d31x;
  const double inv_n = 1.0 / std::sqrt(nx * nx + ny * ny + nz * nz);
  nx *= inv_n;
  ny *= inv_n;
  nz *= inv_n;
  const double s1x = x[0][1][l] - x[0][0][l], s1y = x[1][1][l] - x[1][0][l],
               s1z = x[2][1][l] - x[2][0][l];
  const double sn = s1x * nx + s1y * ny + s1z * nz;
  double ax = s1x - sn * nx, ay = s1y - sn * ny, az = s1z - sn * nz;
  const double inv_a = 1.0 / std::sqrt(ax * ax + ay * ay + az * az);
  ax *= inv_a;
  ay *= inv_a;
  az *= inv_a;
  const double bx = ny * az - nz * ay, by = nz * ax - nx * az, bz = nx * ay - ny * ax;
  f.e[0][0] = ax;
  f.e[0][1] = ay;
  f.e[0][2] = az;
  f.e[1][0] = bx;
  f.e[1][1] = by;
  f.e[1][2] = bz;
  f.e[2][0] = nx;
  f.e[2][1] = ny;
  f.e[2][2] = nz;
  f.xh[0] = f.yh[0] = 0.0;
  for (int a = 1; a < 4; ++a) {
    const double dx = x[0][a][l] - x[0][0][l], dy = x[1][a][l] - x[1][0][l],
                 dz = x[2][a][l] - x[2][0][l];
    f.xh[a] = ax * dx + ay * dy + az * dz;
    f.yh[a] = bx * dx + by * dy + bz * dz;
  }
  const double two_a =
      (f.xh[2] - f.xh[0]) * (f.yh[3] - f.yh[1]) - (f.xh[3] - f.xh[1]) * (f.yh[2] - f.yh[0]);
  const double inv = 1.0 / two_a;
  f.area = 0.5 * two_a;
  f.b1[0] = (f.yh[1] - f.yh[3]) * inv;
  f.b1[1] = (f.yh[2] - f.yh[0]) * inv;
  f.b1[2] = (f.yh[3] - f.yh[1]) * inv;
  f.b1[3] = (f.yh[0] - f.yh[2]) * inv;
  f.b2[0] = (f.xh[3] - f.xh[1]) * inv;
  f.b2[1] = (f.xh[0] - f.xh[2]) * inv;
  f.b2[2] = (f.xh[1] - f.xh[3]) * inv;
  f.b2[3] = (f.xh[2] - f.xh[0]) * inv;
  return f;
}

// Components on the frame's axis i of the corner vectors v (velocities or rotation rates).
inline void onAxis(const LaneFrame& f, int i, const NodalShell& v, int l, double out[4]) {
  for (int a = 0; a < 4; ++a)
    out[a] = f.e[i][0] * v[0][a][l] + f.e[i][1] * v[1][a][l] + f.e[i][2] * v[2][a][l];
}

inline std::size_t laneElement(std::size_t first, int n, int l) {
  return first + static_cast<std::size_t>(std::min(l, n - 1));
}

inline void gatherCorners(const domain::ShellBlock& b, std::size_t first, int n,
                          const domain::NodeVector& src, NodalShell& out) {
  for (int l = 0; l < kShellBatch; ++l) {
    const auto& conn = b.conn[laneElement(first, n, l)];
    for (int a = 0; a < 4; ++a) {
      const double* p = &src[3 * static_cast<std::size_t>(conn[a])];
      out[0][a][l] = p[0];
      out[1][a][l] = p[1];
      out[2][a][l] = p[2];
    }
  }
}

// Scratch for one batch, kept per thread.
struct ShellScratch {
  NodalShell x, v, w, xm;
  NodalShell fg, mg;  // corner forces and moments on the nodes, global frame
  double s[3][kMaxPoints], de[3][kMaxPoints], alpha[3][kMaxPoints];
  double dzz[kMaxPoints], ep[kMaxPoints];
  uint8_t failed[kMaxPoints];
  double ply[kMaxPoints];              // the layer angle of each point (laws with kLayered)
  double zeros[5 * kShellBatch] = {};  // the "stored" resistances of the viscous forms
};

// Material constants a kernel needs besides the law.
struct ShellConstants {
  double E = 0, nu = 0, G = 0;
  double wave_speed = 0;  // sqrt(E / (rho (1 - nu^2)))
};

inline ShellConstants constantsOf(const materials::Law& law, double rho0) {
  ShellConstants c;
  const materials::Moduli m = materials::moduliOf(law);
  c.E = materials::youngModulus(m);
  c.nu = materials::poissonRatio(m);
  c.G = m.shear;
  c.wave_speed = std::sqrt(c.E / (rho0 * (1.0 - c.nu * c.nu)));
  return c;
}

// The constants of one block for one call, shared by the phases below.
struct ShellParams {
  ShellConstants mc;
  double dt = 0, inv_c = 0;
  int nip = 0, npts = 0, fields = 0;
  double kappa = 0;
  bool stiffness_hg = false;
  // The block keeps the hourglass forces of the last cycle (ShellBlock::hgq): the stiffness
  // forms accumulate them; the viscous forms keep them for their work.
  bool hg_state = false;
  double qm = 0;
  // Hourglass scale: QM dt for the stiffness forms, QM L_s / c for the viscous ones.
  double hg_dt = 0, hg_visc = 0;
  double bwc = 0, drill_coef = 0;
  bool thickness_update = false, scaled_mass = false, can_fail = false;
  // Failed points that erode an element: all of them (nip x in-plane), or NUMFIP / NUMINT of
  // the erosion criteria.
  int fail_points = 0;
  const materials::Erosion* erosion = nullptr;  // the block's criteria; null when it has none
  double time = 0;
  double zeta[kMaxShellPoints] = {}, weight[kMaxShellPoints] = {};
  // Layered (orthotropic) laws: each point's layer angle, and the transverse shear moduli of
  // the laminate in the element frame (g_xz, g_yz and their coupling: the layers' moduli turned
  // by their angles, weighted by their thickness fractions).
  bool layered = false;
  double ply[kMaxShellPoints] = {};
  double g_xz = 0, g_yz = 0, g_c = 0;
  const double* axis_angle = nullptr;  // ShellBlock::axis_angle, null when empty
  int history = 0;
};

// The layer angles and the laminate's transverse shear moduli of a layered law.
template <class Law>
inline void layersOf(const Law& law, const domain::ShellBlock& blk, ShellParams& p) {
  if constexpr (materials::isLayered<Law>()) {
    p.layered = true;
    p.axis_angle = blk.axis_angle.empty() ? nullptr : blk.axis_angle.data();
    for (int i = 0; i < p.nip; ++i) {
      const auto k = static_cast<std::size_t>(i);
      p.ply[i] = k < blk.ply.size() ? blk.ply[k] : 0.0;
      double g[3];
      law.transverseShear(p.ply[i], g);
      p.g_xz += p.weight[i] * g[0];
      p.g_yz += p.weight[i] * g[1];
      p.g_c += p.weight[i] * g[2];
    }
  }
}

template <class Law>
inline ShellParams shellParamsOf(const Law& law, const domain::ShellBlock& blk, double dt) {
  ShellParams p;
  p.mc = constantsOf(blk.law, blk.rho0);
  p.dt = dt;
  p.inv_c = 1.0 / p.mc.wave_speed;
  p.nip = blk.nip;
  p.npts = p.nip * kShellBatch;
  p.fields = blk.sigFields();
  p.kappa = blk.shear_factor;
  p.stiffness_hg = blk.ihq >= 4 && blk.inPlanePoints() == 1;  // none in ELFORM 16
  p.qm = blk.qm;
  p.hg_state = !blk.hgq.empty();
  p.hg_dt = p.stiffness_hg ? dt : 0.0;
  p.hg_visc = p.stiffness_hg ? 0.0 : p.inv_c;
  p.bwc = blk.bwc ? 1.0 : 0.0;
  p.drill_coef = kDrillStiffness * p.mc.E * (1.0 / 12.0);
  p.thickness_update = blk.thickness_update;
  p.scaled_mass = !blk.mass_scale.empty();
  p.can_fail = law.failureStrain() > 0.0 || blk.erosion.any() || materials::failsPoints<Law>();
  p.fail_points = p.nip * blk.inPlanePoints();
  if (blk.erosion.any()) {
    p.erosion = &blk.erosion;
    p.time = blk.time;
    if (blk.erosion.numfip > 0) p.fail_points = std::min(p.fail_points, blk.erosion.numfip);
  }
  for (int i = 0; i < p.nip; ++i) {
    p.zeta[i] = blk.zeta[static_cast<std::size_t>(i)];
    p.weight[i] = blk.weight[static_cast<std::size_t>(i)];
  }
  p.history = materials::historyOf<Law>();
  layersOf(law, blk, p);
  return p;
}

// One batch's elements: where they are in the block and their per-lane inputs.
struct ShellLanes {
  std::size_t first = 0;
  int n = 0;         // elements in the batch (the lanes beyond repeat the last)
  Lanes tri, thick;  // tri: 1 for a triangle (corners 2 and 3 on one node), else 0
  bool any_tri = false;
};

// Mid-step velocity strains (membrane, curvature, transverse shear), drilling and hourglass
// rates.
struct ShellRates {
  Lanes dxm, dym, gxy, kx, ky, kxy, gxz, gyz, area_mid;
  double qdot[5][kShellBatch], rdrill[4][kShellBatch];
};

// Transverse shear stresses, the step's internal energy, the new thickness and the resultants.
struct ShellResultants {
  Lanes tau_yz, tau_zx, de_int, t_new, ezz, nxx, nyy, nxy, mxx, myy, mxy, qx, qy;
};

// What the force phase leaves for the stores: area, hourglass and drilling-constraint energy,
// stable step, resistances.
struct ShellForcesOut {
  Lanes area, de_hg, de_drill, dte;
  double hg_new[5][kShellBatch], drill_new[4][kShellBatch];
};

// Gathers the batch's corner coordinates, velocities and rotation rates; marks triangles.
inline void loadBatch(const domain::ShellBlock& blk, const domain::NodeVector& x,
                      const domain::NodeVector& v, const domain::NodeVector& w, ShellScratch& s,
                      ShellLanes& ln) {
  constexpr int B = kShellBatch;
  gatherCorners(blk, ln.first, ln.n, x, s.x);
  gatherCorners(blk, ln.first, ln.n, v, s.v);
  gatherCorners(blk, ln.first, ln.n, w, s.w);
  for (int l = 0; l < B; ++l) {
    const auto& c = blk.conn[laneElement(ln.first, ln.n, l)];
    ln.tri[l] = c[2] == c[3] ? 1.0 : 0.0;
    ln.any_tri = ln.any_tri || c[2] == c[3];
  }
  for (int l = 0; l < B; ++l) ln.thick[l] = blk.thick[ln.first + static_cast<std::size_t>(l)];
}

// The erosion criteria at every point through the thickness after the law (ero_batch: the
// points' records of ShellBlock::erosion_state): the total strain advanced by the step's
// in-plane and thickness increments, and a point flagged failed, for good, once a criterion
// holds or the law has failed it.
inline void erodeShellPoints(const ShellParams& p, ShellScratch& s, double* ero_batch) {
  constexpr int B = kShellBatch;
  constexpr int F = domain::ShellBlock::kErosionFields;
  for (int ip = 0; ip < p.nip; ++ip) {
    double* rec = ero_batch + F * ip * B;
    for (int l = 0; l < B; ++l) {
      const int i = ip * B + l;
      const double exx = rec[l] += s.de[0][i];
      const double eyy = rec[B + l] += s.de[1][i];
      const double exy = rec[2 * B + l] += s.de[2][i];
      const double ezz = rec[3 * B + l] += s.dzz[i];
      const bool failed =
          rec[4 * B + l] != 0.0 || s.failed[i] != 0 ||
          materials::pointFails(*p.erosion, {s.s[0][i], s.s[1][i], 0.0, s.s[2][i], 0.0, 0.0},
                                {exx, eyy, ezz, exy, 0.0, 0.0}, p.time);
      rec[4 * B + l] = failed ? 1.0 : 0.0;
      s.failed[i] = failed ? 1 : 0;
    }
  }
}

// The law's plane-stress update of n points held as structure of arrays in q (members s, de,
// alpha, dzz, ep, failed: the shells' ShellScratch, the thick shells' points): stress, back
// stress (or shell strain) and plastic strain advanced by de, the thickness strain returned in
// dzz; failed cleared, then set by a law that can fail.
// hist: the points' law history, kHistory arrays of n (laws with history); ply: each point's
// layer angle (layered laws).
template <class Law, class Points>
inline void planeStressUpdate(const Law& law, int n, double dt, bool can_fail, Points& q,
                              double* hist = nullptr, const double* ply = nullptr) {
  materials::PlaneStressPoints pts;
  pts.n = n;
  pts.dt = dt;
  for (int k = 0; k < 3; ++k) {
    pts.s[k] = q.s[k];
    pts.de[k] = q.de[k];
    pts.alpha[k] = materials::shellAlphaOf<Law>() ? q.alpha[k] : nullptr;
  }
  pts.de_zz = q.dzz;
  pts.eps_p = Law::kPlastic ? q.ep : nullptr;
  pts.failed = can_fail ? q.failed : nullptr;
  std::fill(q.failed, q.failed + n, uint8_t{0});
  if (hist != nullptr)
    for (int k = 0; k < materials::historyOf<Law>(); ++k) pts.h[k] = hist + k * n;
  if constexpr (materials::isLayered<Law>()) pts.ply = ply;
  law.updatePlaneStress(pts);
}

// The plane-stress update at every point through the thickness. The stress work is the
// midpoint rule, (s_old + s) / 2 : de summed over the points: its s_old half is taken here into
// work, as the stresses are loaded. A failed point carries no stress; failed_points counts them.
// ero_batch: the points' erosion records (null without erosion criteria); hist_batch: the
// points' law history (ShellBlock::hist, updated in place; null for laws without).
template <class Law>
inline void pointStresses(const Law& law, const ShellParams& p, ShellScratch& s,
                          const double* sig_batch, const double* ep_batch,
                          const double* alpha_batch, const ShellLanes& ln, const ShellRates& r,
                          Lanes& work, Lanes& failed_points, double* ero_batch,
                          double* hist_batch) {
  constexpr int B = kShellBatch;
  const int nip = p.nip, npts = p.npts;
  const double dt = p.dt;
  for (int l = 0; l < B; ++l) work[l] = 0.0;
  for (int ip = 0; ip < nip; ++ip) {
    const double zp = 0.5 * p.zeta[ip], wp = 0.5 * p.weight[ip];
    const double* rec = sig_batch + 3 * ip * B;
    for (int l = 0; l < B; ++l) {
      const double z = zp * ln.thick[l];
      const int i = ip * B + l;
      const double d0 = (r.dxm[l] + z * r.kx[l]) * dt, d1 = (r.dym[l] + z * r.ky[l]) * dt,
                   d2 = 0.5 * (r.gxy[l] + z * r.kxy[l]) * dt;
      const double s0 = rec[l], s1 = rec[B + l], s2 = rec[2 * B + l];
      s.de[0][i] = d0;
      s.de[1][i] = d1;
      s.de[2][i] = d2;
      s.s[0][i] = s0;
      s.s[1][i] = s1;
      s.s[2][i] = s2;
      work[l] += wp * (s0 * d0 + s1 * d1 + 2.0 * s2 * d2);
    }
  }
  if constexpr (Law::kPlastic)
    for (int i = 0; i < npts; ++i) s.ep[i] = ep_batch[i];
  if constexpr (materials::shellAlphaOf<Law>())
    for (int k = 0; k < 3; ++k)
      for (int ip = 0; ip < nip; ++ip)
        for (int l = 0; l < B; ++l) s.alpha[k][ip * B + l] = alpha_batch[(3 * ip + k) * B + l];
  if constexpr (materials::isLayered<Law>()) {
    for (int ip = 0; ip < nip; ++ip)
      for (int l = 0; l < B; ++l)
        s.ply[ip * B + l] = p.ply[ip] + (p.axis_angle ? p.axis_angle[ln.first + l] : 0.0);
  }
  planeStressUpdate(law, npts, dt, p.can_fail, s, hist_batch, s.ply);
  if (ero_batch != nullptr) erodeShellPoints(p, s, ero_batch);
  for (int l = 0; l < B; ++l) failed_points[l] = 0.0;
  if (p.can_fail) {
    for (int i = 0; i < npts; ++i) {
      const bool f = s.failed[i] != 0;
      for (int k = 0; k < 3; ++k) s.s[k][i] = f ? 0.0 : s.s[k][i];
    }
    for (int ip = 0; ip < nip; ++ip)
      for (int l = 0; l < B; ++l) failed_points[l] += s.failed[ip * B + l] != 0 ? 1.0 : 0.0;
  }
}

// An element deleted at the end of this pass (writeSlots: NUMFIP of its points failed) gives
// no force in it: the stresses of its remaining points are dropped too, so that its internal
// energy books only the old half of the step's trapezoid, the work its last applied force did
// (as a one-point solid's, hex8.cpp dropFailedStress). One in-plane point (ELFORM 2, 4).
inline void dropDeletedPoints(const ShellParams& p, ShellScratch& s, const Lanes& failed_points) {
  constexpr int B = kShellBatch;
  if (!p.can_fail) return;
  for (int ip = 0; ip < p.nip; ++ip)
    for (int l = 0; l < B; ++l) {
      const double keep = failed_points[l] >= static_cast<double>(p.fail_points) ? 0.0 : 1.0;
      for (int k = 0; k < 3; ++k) s.s[k][ip * B + l] *= keep;
    }
}

// Transverse shear (elastic), the step's internal energy (work holds the points' s_old half),
// the thickness update and the resultants N, M, Q.
inline void resultantsOf(const ShellParams& p, const ShellScratch& s, const double* sig_batch,
                         const ShellLanes& ln, const ShellRates& r, Lanes& work,
                         ShellResultants& q) {
  constexpr int B = kShellBatch;
  const int nip = p.nip;
  const double dt = p.dt, kappa = p.kappa;
  {
    const double* rec_yz = sig_batch + (3 * nip) * B;
    const double* rec_zx = sig_batch + (3 * nip + 1) * B;
    for (int l = 0; l < B; ++l) {
      const double old_yz = rec_yz[l], old_zx = rec_zx[l];
      if (p.layered) {  // the laminate's moduli (ShellParams)
        q.tau_yz[l] = old_yz + (p.g_c * r.gxz[l] + p.g_yz * r.gyz[l]) * dt;
        q.tau_zx[l] = old_zx + (p.g_xz * r.gxz[l] + p.g_c * r.gyz[l]) * dt;
      } else {
        q.tau_yz[l] = old_yz + p.mc.G * r.gyz[l] * dt;
        q.tau_zx[l] = old_zx + p.mc.G * r.gxz[l] * dt;
      }
      q.de_int[l] = kappa * 0.5 *
                    ((old_yz + q.tau_yz[l]) * r.gyz[l] + (old_zx + q.tau_zx[l]) * r.gxz[l]) * dt;
      q.ezz[l] = q.nxx[l] = q.nyy[l] = q.nxy[l] = q.mxx[l] = q.myy[l] = q.mxy[l] = 0.0;
    }
  }
  for (int ip = 0; ip < nip; ++ip) {
    const double wp = p.weight[ip], wz = p.weight[ip] * p.zeta[ip], hw = 0.5 * p.weight[ip];
    for (int l = 0; l < B; ++l) {
      const int i = ip * B + l;
      work[l] +=
          hw * (s.s[0][i] * s.de[0][i] + s.s[1][i] * s.de[1][i] + 2.0 * s.s[2][i] * s.de[2][i]);
      q.ezz[l] += wp * s.dzz[i];
      q.nxx[l] += wp * s.s[0][i];
      q.nyy[l] += wp * s.s[1][i];
      q.nxy[l] += wp * s.s[2][i];
      q.mxx[l] += wz * s.s[0][i];
      q.myy[l] += wz * s.s[1][i];
      q.mxy[l] += wz * s.s[2][i];
    }
  }
  for (int l = 0; l < B; ++l) {
    q.de_int[l] = (q.de_int[l] + work[l]) * ln.thick[l] * r.area_mid[l];
    const double t = p.thickness_update ? ln.thick[l] * (1.0 + q.ezz[l]) : ln.thick[l];
    q.t_new[l] = t;
    const double half_t2 = 0.5 * t * t;
    q.nxx[l] *= t;
    q.nyy[l] *= t;
    q.nxy[l] *= t;
    q.mxx[l] *= half_t2;
    q.myy[l] *= half_t2;
    q.mxy[l] *= half_t2;
    q.qx[l] = kappa * t * q.tau_zx[l];
    q.qy[l] = kappa * t * q.tau_yz[l];
  }
}

// Per element: the slots, erosion (FAIL; ERODE or TDEL) and the stable step.
inline void writeSlots(const ShellParams& p, domain::ShellBlock& blk, const ShellScratch& s,
                       const ShellLanes& ln, const Lanes& failed_points, const ShellForcesOut& o,
                       double* slots, BlockStatus& st) {
  for (int l = 0; l < ln.n; ++l) {
    const std::size_t e = ln.first + static_cast<std::size_t>(l);
    double* slot = slots + 3 * (blk.slot_offset + 8 * e);
    if (!blk.active[e]) {
      std::fill(slot, slot + 24, 0.0);
      continue;
    }
    if (!(o.area[l] > 0.0) && (st.bad_elem < 0 || blk.elem[e] < st.bad_elem))
      st.bad_elem = blk.elem[e];
    const bool failed = p.can_fail && failed_points[l] >= static_cast<double>(p.fail_points);
    if (failed || o.dte[l] < blk.erode_dt) {
      blk.active[e] = 0;
      if (failed) blk.failed[e] = 1;
      for (int k = 0; k < p.fields; ++k) blk.sig[domain::ShellBlock::blocked(p.fields, k, e)] = 0.0;
      if (p.hg_state)
        for (int mode = 0; mode < 5; ++mode) blk.hgqAt(mode, e) = 0.0;
      for (int a = 0; a < 4; ++a) blk.drillAt(a, e) = 0.0;
      std::fill(slot, slot + 24, 0.0);
      ++st.eroded;
      continue;
    }
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 3; ++c) {
        slot[3 * a + c] = s.fg[c][a][l];
        slot[12 + 3 * a + c] = s.mg[c][a][l];
      }
    st.observeStep(o.dte[l], blk.elem[e]);
  }
}
// The stored drilling moments of the batch, copied to the stack (no aliasing with the stores:
// the lane loops that read them vectorise).
inline void loadDrill(const domain::ShellBlock& blk, std::size_t first,
                      double (&prev)[4][kShellBatch]) {
  const double* drill_old = blk.drill.data() + first * 4;
  for (int a = 0; a < 4; ++a)
    for (int l = 0; l < kShellBatch; ++l) prev[a][l] = drill_old[a * kShellBatch + l];
}

// The drilling constraint of lane l (src/elements/shell.cpp, "Drilling rotations"): corner
// moments mz about the normal accumulated from the drilling rates with stiffness kd, their
// sum (whose reaction goes to the in-plane forces) and their midpoint work added to e_drill
// (booked apart from the hourglass energy: LS-DYNA's shells have no such term to compare).
inline void drillMoments(const double (&prev)[4][kShellBatch], const double (&rate)[4][kShellBatch],
                         double kd, double dt, int l, double mz[4], double (&next)[4][kShellBatch],
                         double& drill_sum, double& e_drill) {
  for (int a = 0; a < 4; ++a) {
    const double old = prev[a][l];
    mz[a] = old + kd * rate[a][l] * dt;
    next[a][l] = mz[a];
    drill_sum += mz[a];
    e_drill += 0.5 * (old + mz[a]) * rate[a][l] * dt;
  }
}

// Internal corner forces and moments of lane l in the element frame to the slots' scratch: the
// global frame, as the forces on the nodes (minus the internal forces).
inline void cornerLoadsToGlobal(const LaneFrame& f, const double fx[4], const double fy[4],
                                const double fz[4], const double mx[4], const double my[4],
                                const double mz[4], int l, ShellScratch& s) {
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 4; ++a) {
      s.fg[c][a][l] = -(f.e[0][c] * fx[a] + f.e[1][c] * fy[a] + f.e[2][c] * fz[a]);
      s.mg[c][a][l] = -(f.e[0][c] * mx[a] + f.e[1][c] * my[a] + f.e[2][c] * mz[a]);
    }
}

// 1 for a lane whose element is not eroded (as double: the selects that use it vectorise).
inline void aliveLanes(const domain::ShellBlock& blk, std::size_t first, Lanes& alive) {
  for (int l = 0; l < kShellBatch; ++l)
    alive[l] = blk.active[first + static_cast<std::size_t>(l)] ? 1.0 : 0.0;
}

// Stores one in-plane point's state through the thickness (a record of 3 nip + 2 fields at
// sig_batch, nip at ep_batch, 3 nip at alpha_batch): stresses, transverse shear, plastic
// strain, back stress; eroded lanes' stresses zeroed, their plastic strain kept.
template <class Law>
inline void storePoints(const ShellParams& p, const ShellScratch& s, const Lanes& alive,
                        double* sig_batch, double* ep_batch, double* alpha_batch,
                        const ShellResultants& q) {
  constexpr int B = kShellBatch;
  const int nip = p.nip;
  for (int ip = 0; ip < nip; ++ip)
    for (int k = 0; k < 3; ++k) {
      double* rec = sig_batch + (3 * ip + k) * B;
      for (int l = 0; l < B; ++l) rec[l] = alive[l] != 0.0 ? s.s[k][ip * B + l] : 0.0;
    }
  {
    double* rec_yz = sig_batch + (3 * nip) * B;
    double* rec_zx = sig_batch + (3 * nip + 1) * B;
    for (int l = 0; l < B; ++l) {
      rec_yz[l] = alive[l] != 0.0 ? q.tau_yz[l] : 0.0;
      rec_zx[l] = alive[l] != 0.0 ? q.tau_zx[l] : 0.0;
    }
  }
  if constexpr (Law::kPlastic)
    for (int i = 0; i < p.npts; ++i) {
      const int l = i % B;
      ep_batch[i] = alive[l] != 0.0 ? s.ep[i] : ep_batch[i];
    }
  if constexpr (materials::shellAlphaOf<Law>())
    for (int k = 0; k < 3; ++k)
      for (int ip = 0; ip < nip; ++ip)
        for (int l = 0; l < B; ++l) alpha_batch[(3 * ip + k) * B + l] = s.alpha[k][ip * B + l];
}

// 1 / c per lane for the stable step: mass scaling slows the element's waves, c / sqrt(scale)
// enters the stable step only.
inline void slownessOf(const ShellParams& p, const domain::ShellBlock& blk, const ShellLanes& ln,
                       Lanes& inv_c_dt) {
  for (int l = 0; l < kShellBatch; ++l)
    inv_c_dt[l] = p.scaled_mass
                      ? std::sqrt(blk.mass_scale[laneElement(ln.first, ln.n, l)]) * p.inv_c
                      : p.inv_c;
}

// The longest side of lane l's quadrilateral (the characteristic length is area / longest).
inline double longestSide(const NodalShell& x, int l) {
  double m2 = 0.0;
  for (int a = 0; a < 4; ++a) {
    const int b = (a + 1) % 4;
    const double dx = x[0][b][l] - x[0][a][l], dy = x[1][b][l] - x[1][a][l],
                 dz = x[2][b][l] - x[2][a][l];
    m2 = std::max(m2, dx * dx + dy * dy + dz * dz);
  }
  return std::sqrt(m2);
}

}  // namespace crumple::elements::shell_detail
