// Belytschko-Lin-Tsay shell and C0 triangle kernels (see shell.hpp).
//
// Notation: corners a = 0..3 (LS-DYNA nodes 1..4); a triangle has corner 3 on corner 2's node.
// Frame (BLT 1984 sec. 2; LS-DYNA Theory Manual, BLT shell, "co-rotational coordinates"):
//   e3 = r20 x r31 / |r20 x r31| (the diagonals), e1 = side 0-1 minus its e3 part, normalised,
//   e2 = e3 x e1. Hatted quantities are components in this frame; (x_a, y_a) the corners'
//   in-plane coordinates.
// One-point quadrature at the centre (BLT eq. 13): B1 = dN/dx = (y1-y3, y2-y0, y3-y1, y0-y2)/2A,
// B2 = dN/dy = (x3-x1, x0-x2, x1-x3, x2-x0)/2A, 2A = (x2-x0)(y3-y1) - (x3-x1)(y2-y0).
// Velocity strains at height z (Mindlin kinematics: the fibre turns with the nodal rotation
// theta, so u_x = z theta_y, u_y = -z theta_x), BLT eqs. 17-21:
//   d_xx = B1.vx + z B1.ty                   d_yy = B2.vy - z B2.tx
//   2 d_xy = B2.vx + B1.vy + z (B2.ty - B1.tx)
//   2 d_xz = B1.vz + ty_mean                 2 d_yz = B2.vz - tx_mean   (mean of the corners)
// The rates use the mid-step geometry x(n) - dt/2 v(n-1/2) and its frame, as the hex kernel
// does: a rigid rotation then gives zero strain to round-off however large the step's angle
// (the midpoint rule; the current geometry would give a strain of (1 - cos dtheta) a step).
// Resultants over the thickness t with the rule's weights w_i at z_i = zeta_i t / 2:
//   N = t sum w_i s_i,  M = t^2/2 sum w_i zeta_i s_i,  Q = kappa t tau (tau elastic, uniform),
// and the corner forces and moments are the derivatives of the internal power
// A (N.d_m + M.kappa + Q.gamma) with respect to the corner velocities (BLT eq. 26):
//   fx_a = A (B1 Nxx + B2 Nxy)        mx_a = A (-B2 Myy - B1 Mxy - Qy / 4)
//   fy_a = A (B2 Nyy + B1 Nxy)        my_a = A ( B1 Mxx + B2 Mxy + Qx / 4)
//   fz_a = A (B1 Qx + B2 Qy)          (no drilling moment)
// evaluated with the geometry and frame at x(n). The slots get minus these, turned to the
// global frame (the force on the node, as the hex kernel writes f_a = -sigma.B_a).
//
// Hourglass control (BLT sec. 4; LS-DYNA Theory Manual, BLT shell, "hourglass control"): the
// projected vector gamma_a = h_a - (h.x) B1_a - (h.y) B2_a, h = (1, -1, 1, -1), is orthogonal to
// every linear field, so rigid motions and the patch test give no hourglass rate. Five modes:
// membrane gamma.vx, gamma.vy; bending gamma.tx, gamma.ty; transverse gamma.vz, with the
// stiffnesses (QM the hourglass coefficient, B.B = sum of B1^2 + B2^2)
//   membrane QM E t A B.B / 8,   bending QM E t^3 A B.B / 192,   transverse QM kappa G t^3 B.B / 12
// (LS-DYNA's forms for membrane and bending; the transverse one written so that it is a
// stiffness, like the twist stiffness G t^3 B.B / 6 of a square plate that the one-point
// quadrature misses). IHQ 4, 5: resistances accumulated from the rates (stored in the element
// frame, so they turn with it); IHQ 1-3: viscous, the same stiffness times L_s / c (a damping
// ratio of at most QM for every hourglass mode; the hex's viscous coefficient is 1.33 times its
// stiffness times L/c in the same sense).
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
// C0 triangle (BSC 1984): the same frame, membrane (constant strain: the quadrilateral formulas
// with corners 2 and 3 on one node give the CST gradients) and constant curvature from the
// linear rotation field. Transverse shear with one-point quadrature at the centroid would lock
// in bending (two constraints per triangle); as in BSC's treatment it is built from the
// tangential shear along the three edges, which for a bending mode is the exact Timoshenko
// condition of each edge: the edge value (w_j - w_i) / L + mean(beta_i, beta_j).t (beta =
// (ty, -tx)) and the lowest-order edge (Nedelec) field through the three edge values,
// evaluated at the centroid:
//   gamma = 1/3 sum_edges [(w_j - w_i) + (beta_i + beta_j)/2 . (x_j - x_i)] (grad N_j - grad N_i).
// It is exact for every field with constant shear and zero for rigid motions; the forces are
// its transpose. No hourglass control (none needed: three nodes, one point).
//
// Plasticity: the plane-stress return of materials/plane_stress.hpp at every point. A point
// that reaches the failure strain carries no stress; the element erodes when every point
// through the thickness has failed (LS-DYNA's default for shells with a failure strain).
// Thickness update (ISTUPD): t += t sum w_i deps_zz,i with the points' thickness strains.
#include "elements/shell.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <variant>
#include <vector>

#include "elements/hex8_kernel.hpp"
#include "materials/plane_stress.hpp"

namespace crumple::elements {

namespace {

using Lanes = double[kShellBatch];
using Corners = double[4][kShellBatch];
using NodalShell = double[3][4][kShellBatch];  // [component][corner][lane]

constexpr double kH[4] = {1.0, -1.0, 1.0, -1.0};  // hourglass base vector
constexpr int kMaxPoints = kMaxShellPoints * kShellBatch;

// The corotational frame of a batch and the one-point gradient operator in it.
struct Frame {
  double e[3][3][kShellBatch];  // e[axis][component][lane]
  Corners xh, yh;               // in-plane corner coordinates, relative to corner 0
  Corners b1, b2;               // dN/dx, dN/dy
  Lanes area;
};

inline void computeFrame(const NodalShell& x, Frame& f) {
  for (int l = 0; l < kShellBatch; ++l) {
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
    f.e[0][0][l] = ax;
    f.e[0][1][l] = ay;
    f.e[0][2][l] = az;
    f.e[1][0][l] = bx;
    f.e[1][1][l] = by;
    f.e[1][2][l] = bz;
    f.e[2][0][l] = nx;
    f.e[2][1][l] = ny;
    f.e[2][2][l] = nz;
    double xh[4], yh[4];
    xh[0] = yh[0] = 0.0;
    for (int a = 1; a < 4; ++a) {
      const double dx = x[0][a][l] - x[0][0][l], dy = x[1][a][l] - x[1][0][l],
                   dz = x[2][a][l] - x[2][0][l];
      xh[a] = ax * dx + ay * dy + az * dz;
      yh[a] = bx * dx + by * dy + bz * dz;
    }
    const double two_a = (xh[2] - xh[0]) * (yh[3] - yh[1]) - (xh[3] - xh[1]) * (yh[2] - yh[0]);
    const double inv = 1.0 / two_a;
    f.area[l] = 0.5 * two_a;
    f.b1[0][l] = (yh[1] - yh[3]) * inv;
    f.b1[1][l] = (yh[2] - yh[0]) * inv;
    f.b1[2][l] = (yh[3] - yh[1]) * inv;
    f.b1[3][l] = (yh[0] - yh[2]) * inv;
    f.b2[0][l] = (xh[3] - xh[1]) * inv;
    f.b2[1][l] = (xh[0] - xh[2]) * inv;
    f.b2[2][l] = (xh[1] - xh[3]) * inv;
    f.b2[3][l] = (xh[2] - xh[0]) * inv;
    for (int a = 0; a < 4; ++a) {
      f.xh[a][l] = xh[a];
      f.yh[a][l] = yh[a];
    }
  }
}

// Corner velocities (or rotations) in the frame: out[axis][a][l] for the first n_axes axes.
inline void toFrame(const Frame& f, const NodalShell& v, int n_axes, NodalShell& out) {
  for (int i = 0; i < n_axes; ++i)
    for (int a = 0; a < 4; ++a)
      for (int l = 0; l < kShellBatch; ++l)
        out[i][a][l] =
            f.e[i][0][l] * v[0][a][l] + f.e[i][1][l] * v[1][a][l] + f.e[i][2][l] * v[2][a][l];
}

// Edge-based transverse shear of the C0 triangle at the centroid (see the file comment):
// gamma_xz, gamma_yz from the corner velocities vz and rotations tx, ty in the frame.
constexpr int kEdge[3][2] = {{0, 1}, {1, 2}, {2, 0}};

inline void triangleGradients(const Frame& f, int l, double gx[3], double gy[3]) {
  gx[0] = f.b1[0][l];
  gy[0] = f.b2[0][l];
  gx[1] = f.b1[1][l];
  gy[1] = f.b2[1][l];
  gx[2] = f.b1[2][l] + f.b1[3][l];
  gy[2] = f.b2[2][l] + f.b2[3][l];
}

inline void triangleShearRate(const Frame& f, const NodalShell& vl, const NodalShell& tl, int l,
                              double& gxz, double& gyz) {
  double gx[3], gy[3];
  triangleGradients(f, l, gx, gy);
  double sx = 0.0, sy = 0.0;
  for (const auto& ed : kEdge) {
    const int i = ed[0], j = ed[1];
    const double dx = f.xh[j][l] - f.xh[i][l], dy = f.yh[j][l] - f.yh[i][l];
    const double term = (vl[2][j][l] - vl[2][i][l]) +
                        0.5 * ((tl[1][i][l] + tl[1][j][l]) * dx - (tl[0][i][l] + tl[0][j][l]) * dy);
    sx += term * (gx[j] - gx[i]);
    sy += term * (gy[j] - gy[i]);
  }
  gxz = sx * (1.0 / 3.0);
  gyz = sy * (1.0 / 3.0);
}

// Transpose: corner force fz and moments mx, my of the shear resultants Qx, Qy on area A.
inline void triangleShearForces(const Frame& f, int l, double qx, double qy, double fz[4],
                                double mx[4], double my[4]) {
  double gx[3], gy[3];
  triangleGradients(f, l, gx, gy);
  const double area_3 = f.area[l] * (1.0 / 3.0);
  for (int a = 0; a < 4; ++a) fz[a] = mx[a] = my[a] = 0.0;
  for (const auto& ed : kEdge) {
    const int i = ed[0], j = ed[1];
    const double dx = f.xh[j][l] - f.xh[i][l], dy = f.yh[j][l] - f.yh[i][l];
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

// The projected hourglass vector gamma_a = h_a - (h.x) B1_a - (h.y) B2_a of a frame and, with
// BWC, gamma.z: the corner heights z_a above the plane through the corners' centroid.
inline void hourglassVector(const Frame& f, const NodalShell& x, bool bwc, Corners& g, Lanes& gz) {
  for (int l = 0; l < kShellBatch; ++l) {
    double hx = 0.0, hy = 0.0;
    for (int a = 0; a < 4; ++a) {
      hx += kH[a] * f.xh[a][l];
      hy += kH[a] * f.yh[a][l];
    }
    for (int a = 0; a < 4; ++a) g[a][l] = kH[a] - hx * f.b1[a][l] - hy * f.b2[a][l];
    gz[l] = 0.0;
  }
  if (!bwc) return;
  for (int l = 0; l < kShellBatch; ++l) {
    double cx = 0, cy = 0, cz = 0;
    for (int a = 0; a < 4; ++a) {
      cx += x[0][a][l];
      cy += x[1][a][l];
      cz += x[2][a][l];
    }
    cx *= 0.25;
    cy *= 0.25;
    cz *= 0.25;
    double sum = 0.0;
    for (int a = 0; a < 4; ++a) {
      const double z = f.e[2][0][l] * (x[0][a][l] - cx) + f.e[2][1][l] * (x[1][a][l] - cy) +
                       f.e[2][2][l] * (x[2][a][l] - cz);
      sum += g[a][l] * z;
    }
    gz[l] = sum;
  }
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
  NodalShell x, v, w, xm, vl, tl, f, m;
  Frame fr;
  Corners g;  // hourglass vector
  Lanes gz;   // gamma.z (BWC)
  double s[3][kMaxPoints], s_old[3][kMaxPoints], de[3][kMaxPoints], alpha[3][kMaxPoints];
  double dzz[kMaxPoints], ep[kMaxPoints];
  uint8_t failed[kMaxPoints];
};

// Material constants a kernel needs besides the law.
struct ShellConstants {
  double E = 0, nu = 0, G = 0;
  double wave_speed = 0;  // sqrt(E / (rho (1 - nu^2)))
};

ShellConstants constantsOf(const materials::Law& law, double rho0) {
  ShellConstants c;
  const materials::Moduli m = std::visit([](const auto& l) { return l.moduli; }, law);
  c.E = materials::youngModulus(m);
  c.nu = materials::poissonRatio(m);
  c.G = m.shear;
  c.wave_speed = std::sqrt(c.E / (rho0 * (1.0 - c.nu * c.nu)));
  return c;
}

bool lawIsPlastic(const materials::Law& law) {
  return std::visit([](const auto& l) { return std::decay_t<decltype(l)>::kPlastic; }, law);
}
bool lawIsKinematic(const materials::Law& law) {
  return std::visit([](const auto& l) { return std::decay_t<decltype(l)>::kKinematic; }, law);
}

// One portable binary, three instruction sets, as the hex kernel (same bits on every path: no
// FMA contraction, no fast-math).
template <class Law>
[[gnu::flatten, gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]] BlockStatus
shellBlockForces(const Law& law, domain::ShellBlock& blk, const domain::NodeVector& x,
                 const domain::NodeVector& v, const domain::NodeVector& w, double dt, double* slots,
                 std::size_t range_first, std::size_t range_last) {
  constexpr int B = kShellBatch;
  const std::size_t ne = range_last;
  const std::size_t batch0 = range_first / B;
  const std::size_t nbatch = range_last > range_first ? (range_last - range_first + B - 1) / B : 0;
  const ShellConstants mc = constantsOf(blk.law, blk.rho0);
  const int nip = blk.nip;
  const int npts = nip * B;
  const int fields = blk.sigFields();
  const double kappa = blk.shear_factor;
  const bool stiffness_hg = blk.ihq >= 4;
  const double qm = blk.qm;
  const bool hourglass = qm > 0.0;
  const bool bwc = blk.bwc;
  const bool thickness_update = blk.thickness_update;
  double zeta[kMaxShellPoints], weight[kMaxShellPoints];
  for (int i = 0; i < nip; ++i) {
    zeta[i] = blk.zeta[static_cast<std::size_t>(i)];
    weight[i] = blk.weight[static_cast<std::size_t>(i)];
  }
  std::vector<BlockStatus> status(nbatch);

#pragma omp parallel
  {
    ShellScratch s;
#pragma omp for schedule(static)
    for (std::size_t ib = 0; ib < nbatch; ++ib) {
      const std::size_t first = (batch0 + ib) * B;
      const int n = static_cast<int>(std::min<std::size_t>(B, ne - first));
      BlockStatus& st = status[ib];
      gatherCorners(blk, first, n, x, s.x);
      gatherCorners(blk, first, n, v, s.v);
      gatherCorners(blk, first, n, w, s.w);
      Lanes tri;  // 1 for a triangle (corners 2 and 3 on one node), else 0
      bool any_tri = false;
      for (int l = 0; l < B; ++l) {
        const auto& c = blk.conn[laneElement(first, n, l)];
        tri[l] = c[2] == c[3] ? 1.0 : 0.0;
        any_tri = any_tri || c[2] == c[3];
      }
      double* sig_batch = blk.sig.data() + first * static_cast<std::size_t>(fields);
      double* ep_batch =
          Law::kPlastic ? blk.eps_p.data() + first * static_cast<std::size_t>(nip) : nullptr;
      double* alpha_batch =
          Law::kKinematic ? blk.alpha.data() + first * static_cast<std::size_t>(3 * nip) : nullptr;
      double* hgq_batch = stiffness_hg ? blk.hgq.data() + first * 5 : nullptr;
      const double* thick = &blk.thick[first];

      // --- velocity strains at the mid-step geometry ------------------------------------------
      for (int c = 0; c < 3; ++c)
        for (int a = 0; a < 4; ++a)
          for (int l = 0; l < B; ++l) s.xm[c][a][l] = s.x[c][a][l] - 0.5 * dt * s.v[c][a][l];
      computeFrame(s.xm, s.fr);
      toFrame(s.fr, s.v, 3, s.vl);
      toFrame(s.fr, s.w, 2, s.tl);
      Lanes dxm, dym, gxy, kx, ky, kxy, gxz, gyz, area_mid;
      for (int l = 0; l < B; ++l) {
        double sxx = 0, syy = 0, sxy = 0, cx = 0, cy = 0, cxy = 0, sz1 = 0, sz2 = 0, tx = 0, ty = 0;
        for (int a = 0; a < 4; ++a) {
          const double b1 = s.fr.b1[a][l], b2 = s.fr.b2[a][l];
          sxx += b1 * s.vl[0][a][l];
          syy += b2 * s.vl[1][a][l];
          sxy += b2 * s.vl[0][a][l] + b1 * s.vl[1][a][l];
          cx += b1 * s.tl[1][a][l];
          cy -= b2 * s.tl[0][a][l];
          cxy += b2 * s.tl[1][a][l] - b1 * s.tl[0][a][l];
          sz1 += b1 * s.vl[2][a][l];
          sz2 += b2 * s.vl[2][a][l];
          tx += s.tl[0][a][l];
          ty += s.tl[1][a][l];
        }
        dxm[l] = sxx;
        dym[l] = syy;
        gxy[l] = sxy;
        kx[l] = cx;
        ky[l] = cy;
        kxy[l] = cxy;
        gxz[l] = sz1 + 0.25 * ty;
        gyz[l] = sz2 - 0.25 * tx;
        area_mid[l] = s.fr.area[l];
      }
      if (any_tri) {
        for (int l = 0; l < B; ++l) {
          if (tri[l] == 0.0) continue;
          triangleShearRate(s.fr, s.vl, s.tl, l, gxz[l], gyz[l]);
        }
      }
      // Hourglass rates of the five modes (membrane x, y; bending x, y; transverse), at the
      // mid-step geometry like the strains, so that rigid motions give none.
      double qdot[5][B];
      if (hourglass) {
        hourglassVector(s.fr, s.xm, bwc, s.g, s.gz);
        for (int l = 0; l < B; ++l) {
          double r[5] = {0, 0, 0, 0, 0}, bz1 = 0.0, bz2 = 0.0;
          for (int a = 0; a < 4; ++a) {
            const double ga = s.g[a][l];
            r[0] += ga * s.vl[0][a][l];
            r[1] += ga * s.vl[1][a][l];
            r[2] += ga * s.tl[0][a][l];
            r[3] += ga * s.tl[1][a][l];
            r[4] += ga * s.vl[2][a][l];
            bz1 += s.fr.b1[a][l] * s.vl[2][a][l];
            bz2 += s.fr.b2[a][l] * s.vl[2][a][l];
          }
          qdot[0][l] = r[0] + s.gz[l] * bz1;
          qdot[1][l] = r[1] + s.gz[l] * bz2;
          qdot[2][l] = r[2];
          qdot[3][l] = r[3];
          qdot[4][l] = r[4];
        }
      }

      // --- plane-stress update at every point through the thickness ---------------------------
      for (int p = 0; p < nip; ++p) {
        const double zp = 0.5 * zeta[p];
        for (int l = 0; l < B; ++l) {
          const double z = zp * thick[l];
          const int i = p * B + l;
          s.de[0][i] = (dxm[l] + z * kx[l]) * dt;
          s.de[1][i] = (dym[l] + z * ky[l]) * dt;
          s.de[2][i] = 0.5 * (gxy[l] + z * kxy[l]) * dt;
        }
        for (int k = 0; k < 3; ++k) {
          const double* rec = sig_batch + (3 * p + k) * B;
          for (int l = 0; l < B; ++l) s.s[k][p * B + l] = s.s_old[k][p * B + l] = rec[l];
        }
      }
      if constexpr (Law::kPlastic)
        for (int i = 0; i < npts; ++i) s.ep[i] = ep_batch[i];
      if constexpr (Law::kKinematic)
        for (int k = 0; k < 3; ++k)
          for (int p = 0; p < nip; ++p)
            for (int l = 0; l < B; ++l) s.alpha[k][p * B + l] = alpha_batch[(3 * p + k) * B + l];
      {
        materials::PlaneStressPoints pts;
        pts.n = npts;
        pts.dt = dt;
        for (int k = 0; k < 3; ++k) {
          pts.s[k] = s.s[k];
          pts.de[k] = s.de[k];
          pts.alpha[k] = Law::kKinematic ? s.alpha[k] : nullptr;
        }
        pts.de_zz = s.dzz;
        pts.eps_p = Law::kPlastic ? s.ep : nullptr;
        pts.failed = s.failed;
        materials::updatePlaneStress(law, pts);
      }
      // A failed point carries no stress; the element erodes when all its points have failed.
      Lanes failed_points;
      for (int l = 0; l < B; ++l) failed_points[l] = 0.0;
      if constexpr (Law::kPlastic) {
        for (int p = 0; p < nip; ++p)
          for (int l = 0; l < B; ++l) {
            const int i = p * B + l;
            const bool f = s.failed[i] != 0;
            failed_points[l] += f ? 1.0 : 0.0;
            for (int k = 0; k < 3; ++k) s.s[k][i] = f ? 0.0 : s.s[k][i];
          }
      }

      // --- transverse shear (elastic), energy, thickness, resultants --------------------------
      Lanes tau_yz, tau_zx, de_int, t_new, nxx, nyy, nxy, mxx, myy, mxy, qx, qy;
      {
        double* rec_yz = sig_batch + (3 * nip) * B;
        double* rec_zx = sig_batch + (3 * nip + 1) * B;
        for (int l = 0; l < B; ++l) {
          const double old_yz = rec_yz[l], old_zx = rec_zx[l];
          tau_yz[l] = old_yz + mc.G * gyz[l] * dt;
          tau_zx[l] = old_zx + mc.G * gxz[l] * dt;
          de_int[l] =
              kappa * 0.5 * ((old_yz + tau_yz[l]) * gyz[l] + (old_zx + tau_zx[l]) * gxz[l]) * dt;
        }
      }
      for (int l = 0; l < B; ++l) {
        double work = 0.0, ezz = 0.0;
        double sn[3] = {0, 0, 0}, sm[3] = {0, 0, 0};
        for (int p = 0; p < nip; ++p) {
          const int i = p * B + l;
          const double wp = weight[p];
          work += wp * (0.5 * ((s.s_old[0][i] + s.s[0][i]) * s.de[0][i] +
                               (s.s_old[1][i] + s.s[1][i]) * s.de[1][i]) +
                        (s.s_old[2][i] + s.s[2][i]) * s.de[2][i]);
          ezz += wp * s.dzz[i];
          for (int k = 0; k < 3; ++k) {
            sn[k] += wp * s.s[k][i];
            sm[k] += wp * zeta[p] * s.s[k][i];
          }
        }
        de_int[l] = (de_int[l] + work) * thick[l] * area_mid[l];
        const double t = thickness_update ? thick[l] * (1.0 + ezz) : thick[l];
        t_new[l] = t;
        const double half_t2 = 0.5 * t * t;
        nxx[l] = t * sn[0];
        nyy[l] = t * sn[1];
        nxy[l] = t * sn[2];
        mxx[l] = half_t2 * sm[0];
        myy[l] = half_t2 * sm[1];
        mxy[l] = half_t2 * sm[2];
        qx[l] = kappa * t * tau_zx[l];
        qy[l] = kappa * t * tau_yz[l];
      }

      // --- forces and moments at the current geometry ----------------------------------------
      computeFrame(s.x, s.fr);
      Lanes longest, area;
      for (int l = 0; l < B; ++l) {
        double m2 = 0.0;
        for (int a = 0; a < 4; ++a) {
          const int b = (a + 1) % 4;
          const double dx = s.x[0][b][l] - s.x[0][a][l], dy = s.x[1][b][l] - s.x[1][a][l],
                       dz = s.x[2][b][l] - s.x[2][a][l];
          m2 = std::max(m2, dx * dx + dy * dy + dz * dz);
        }
        longest[l] = std::sqrt(m2);
        area[l] = s.fr.area[l];
      }
      for (int a = 0; a < 4; ++a)
        for (int l = 0; l < B; ++l) {
          const double b1 = s.fr.b1[a][l], b2 = s.fr.b2[a][l], A = area[l];
          s.f[0][a][l] = A * (b1 * nxx[l] + b2 * nxy[l]);
          s.f[1][a][l] = A * (b2 * nyy[l] + b1 * nxy[l]);
          s.f[2][a][l] = A * (b1 * qx[l] + b2 * qy[l]);
          s.m[0][a][l] = A * (-b2 * myy[l] - b1 * mxy[l] - 0.25 * qy[l]);
          s.m[1][a][l] = A * (b1 * mxx[l] + b2 * mxy[l] + 0.25 * qx[l]);
        }
      if (any_tri) {
        for (int l = 0; l < B; ++l) {
          if (tri[l] == 0.0) continue;
          double fz[4], mx[4], my[4];
          triangleShearForces(s.fr, l, qx[l], qy[l], fz, mx, my);
          for (int a = 0; a < 4; ++a) {
            const double b1 = s.fr.b1[a][l], b2 = s.fr.b2[a][l], A = area[l];
            s.f[2][a][l] = fz[a];
            s.m[0][a][l] = A * (-b2 * myy[l] - b1 * mxy[l]) + mx[a];
            s.m[1][a][l] = A * (b1 * mxx[l] + b2 * mxy[l]) + my[a];
          }
        }
      }

      // --- hourglass control (quadrilaterals) --------------------------------------------------
      Lanes de_hg;
      for (int l = 0; l < B; ++l) de_hg[l] = 0.0;
      if (hourglass) {
        hourglassVector(s.fr, s.x, bwc, s.g, s.gz);
        Lanes coef_m, coef_b, coef_w;
        for (int l = 0; l < B; ++l) {
          double bb = 0.0;
          for (int a = 0; a < 4; ++a)
            bb += s.fr.b1[a][l] * s.fr.b1[a][l] + s.fr.b2[a][l] * s.fr.b2[a][l];
          const double t = t_new[l], A = area[l];
          // Viscous forms: the stiffness times L_s / c (see the file comment); none for
          // triangles.
          const double scale =
              (1.0 - tri[l]) * qm * (stiffness_hg ? dt : A / longest[l] / mc.wave_speed);
          coef_m[l] = scale * mc.E * t * A * bb * 0.125;
          coef_b[l] = scale * mc.E * t * t * t * A * bb * (1.0 / 192.0);
          coef_w[l] = scale * kappa * mc.G * t * t * t * bb * (1.0 / 12.0);
        }
        double force[5][B];
        for (int mode = 0; mode < 5; ++mode) {
          const double* coef = mode < 2 ? coef_m : (mode < 4 ? coef_b : coef_w);
          if (stiffness_hg) {
            double* stored = hgq_batch + mode * B;
            for (int l = 0; l < B; ++l) {
              const double old = stored[l];
              force[mode][l] = old + coef[l] * qdot[mode][l];
              de_hg[l] += 0.5 * (old + force[mode][l]) * qdot[mode][l] * dt;
            }
          } else {
            for (int l = 0; l < B; ++l) {
              force[mode][l] = coef[l] * qdot[mode][l];
              de_hg[l] += force[mode][l] * qdot[mode][l] * dt;
            }
          }
        }
        if (stiffness_hg) {
          const uint8_t* alive = &blk.active[first];
          for (int mode = 0; mode < 5; ++mode)
            for (int l = 0; l < B; ++l) hgq_batch[mode * B + l] = alive[l] ? force[mode][l] : 0.0;
        }
        for (int a = 0; a < 4; ++a)
          for (int l = 0; l < B; ++l) {
            const double ga = s.g[a][l];
            s.f[0][a][l] += force[0][l] * ga;
            s.f[1][a][l] += force[1][l] * ga;
            s.f[2][a][l] += force[4][l] * ga +
                            s.gz[l] * (force[0][l] * s.fr.b1[a][l] + force[1][l] * s.fr.b2[a][l]);
            s.m[0][a][l] += force[2][l] * ga;
            s.m[1][a][l] += force[3][l] * ga;
          }
      }

      // --- to the global frame, as forces on the nodes ----------------------------------------
      // Reuse s.xm / s.vl as the global force and moment of each corner.
      NodalShell& fg = s.xm;
      NodalShell& mg = s.vl;
      for (int c = 0; c < 3; ++c)
        for (int a = 0; a < 4; ++a)
          for (int l = 0; l < B; ++l) {
            fg[c][a][l] = -(s.fr.e[0][c][l] * s.f[0][a][l] + s.fr.e[1][c][l] * s.f[1][a][l] +
                            s.fr.e[2][c][l] * s.f[2][a][l]);
            mg[c][a][l] = -(s.fr.e[0][c][l] * s.m[0][a][l] + s.fr.e[1][c][l] * s.m[1][a][l]);
          }
      if (any_tri) {
        // A triangle's corners 2 and 3 are one node: all of it at corner 2.
        for (int c = 0; c < 3; ++c)
          for (int l = 0; l < B; ++l) {
            if (tri[l] == 0.0) continue;
            fg[c][2][l] += fg[c][3][l];
            mg[c][2][l] += mg[c][3][l];
            fg[c][3][l] = mg[c][3][l] = 0.0;
          }
      }

      // --- store state (whole batch), then per element: slots, erosion, stable step ----------
      const uint8_t* alive = &blk.active[first];
      for (int p = 0; p < nip; ++p)
        for (int k = 0; k < 3; ++k) {
          double* rec = sig_batch + (3 * p + k) * B;
          for (int l = 0; l < B; ++l) rec[l] = alive[l] ? s.s[k][p * B + l] : 0.0;
        }
      {
        double* rec_yz = sig_batch + (3 * nip) * B;
        double* rec_zx = sig_batch + (3 * nip + 1) * B;
        for (int l = 0; l < B; ++l) {
          rec_yz[l] = alive[l] ? tau_yz[l] : 0.0;
          rec_zx[l] = alive[l] ? tau_zx[l] : 0.0;
        }
      }
      if constexpr (Law::kPlastic)
        for (int p = 0; p < nip; ++p)
          for (int l = 0; l < B; ++l)
            ep_batch[p * B + l] = alive[l] ? s.ep[p * B + l] : ep_batch[p * B + l];
      if constexpr (Law::kKinematic)
        for (int k = 0; k < 3; ++k)
          for (int p = 0; p < nip; ++p)
            for (int l = 0; l < B; ++l) alpha_batch[(3 * p + k) * B + l] = s.alpha[k][p * B + l];
      for (int l = 0; l < B; ++l) {
        const std::size_t e = first + static_cast<std::size_t>(l);
        blk.thick[e] = alive[l] ? t_new[l] : blk.thick[e];
        blk.e_int[e] += alive[l] ? de_int[l] : 0.0;
        blk.e_hg[e] += alive[l] ? de_hg[l] : 0.0;
      }
      for (int l = 0; l < n; ++l) {
        const std::size_t e = first + static_cast<std::size_t>(l);
        double* slot = slots + 3 * (blk.slot_offset + 8 * e);
        if (!blk.active[e]) {
          std::fill(slot, slot + 24, 0.0);
          continue;
        }
        if (!(area[l] > 0.0) && (st.bad_elem < 0 || blk.elem[e] < st.bad_elem))
          st.bad_elem = blk.elem[e];
        if (Law::kPlastic && failed_points[l] == static_cast<double>(nip)) {
          blk.active[e] = 0;
          blk.failed[e] = 1;
          for (int k = 0; k < fields; ++k) blk.sig[domain::ShellBlock::blocked(fields, k, e)] = 0.0;
          std::fill(slot, slot + 24, 0.0);
          ++st.eroded;
          continue;
        }
        for (int a = 0; a < 4; ++a)
          for (int c = 0; c < 3; ++c) {
            slot[3 * a + c] = fg[c][a][l];
            slot[12 + 3 * a + c] = mg[c][a][l];
          }
        const double c_dt =
            blk.mass_scale.empty() ? mc.wave_speed : mc.wave_speed / std::sqrt(blk.mass_scale[e]);
        const double dte = shellTimeStep(area[l], longest[l], tri[l] != 0.0, c_dt);
        if (dte < st.dt_min) {
          st.dt_min = dte;
          st.dt_elem = blk.elem[e];
        }
      }
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
  throughThicknessRule(blk.nip, blk.lobatto, blk.zeta, blk.weight);
  blk.thick.assign(padded, 0.0);
  blk.area0.assign(padded, 0.0);
  blk.e_int.assign(padded, 0.0);
  blk.e_hg.assign(padded, 0.0);
  blk.active.assign(padded, 1);
  blk.failed.assign(padded, 0);
  blk.sig.assign(padded * static_cast<std::size_t>(blk.sigFields()), 0.0);
  const std::size_t nip = static_cast<std::size_t>(blk.nip);
  if (lawIsPlastic(blk.law)) {
    blk.eps_p.assign(padded * nip, 0.0);
  } else {
    blk.eps_p.clear();
  }
  if (lawIsKinematic(blk.law)) {
    blk.alpha.assign(padded * 3 * nip, 0.0);
  } else {
    blk.alpha.clear();
  }
  if (blk.ihq >= 4) {
    blk.hgq.assign(padded * 5, 0.0);
  } else {
    blk.hgq.clear();
  }
}

double shellTimeStep(double area, double longest_side, bool triangle, double wave_speed) {
  return (triangle ? 2.0 : 1.0) * area / longest_side / wave_speed;
}

BlockStatus initializeShells(domain::ShellBlock& blk, const domain::NodeVector& x0, double* slots,
                             std::vector<double>& element_dt) {
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
    if (dte < st.dt_min) {
      st.dt_min = dte;
      st.dt_elem = blk.elem[e];
    }
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
      [&](const auto& law) {
        return shellBlockForces(law, block, x, v, w, dt, slots, first, last);
      },
      block.law);
}

void shellSurfaceStress(const domain::ShellBlock& blk, const domain::NodeVector& x, std::size_t e,
                        double out[3][6], double eps_p_out[3]) {
  // The element's frame at x: one lane of the batch frame.
  NodalShell xb;
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 3; ++c)
      for (int l = 0; l < kShellBatch; ++l)
        xb[c][a][l] = x[3 * static_cast<std::size_t>(blk.conn[e][a]) + c];
  Frame fr;
  computeFrame(xb, fr);
  const int nip = blk.nip;
  const bool plastic = !blk.eps_p.empty();
  // Local in-plane stress and plastic strain at the bottom, mid and top.
  double loc[3][3], ep[3];
  const int picks[3] = {0, nip / 2, nip - 1};
  for (int surface = 0; surface < 3; ++surface) {
    if (surface == 1 && nip % 2 == 0) {
      double m[3] = {0, 0, 0}, epm = 0.0;
      for (int p = 0; p < nip; ++p) {
        const double wp = blk.weight[static_cast<std::size_t>(p)];
        for (int k = 0; k < 3; ++k) m[k] += wp * blk.sigAt(k, p, e);
        epm += plastic ? wp * blk.epsAt(p, e) : 0.0;
      }
      for (int k = 0; k < 3; ++k) loc[surface][k] = m[k];
      ep[surface] = epm;
      continue;
    }
    const int p = picks[surface];
    for (int k = 0; k < 3; ++k) loc[surface][k] = blk.sigAt(k, p, e);
    ep[surface] = plastic ? blk.epsAt(p, e) : 0.0;
  }
  const double tyz = blk.shearAt(0, e), tzx = blk.shearAt(1, e);
  for (int surface = 0; surface < 3; ++surface) {
    const double sl[3][3] = {{loc[surface][0], loc[surface][2], tzx},
                             {loc[surface][2], loc[surface][1], tyz},
                             {tzx, tyz, 0.0}};
    double g[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double sum = 0.0;
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) sum += fr.e[a][i][0] * sl[a][b] * fr.e[b][j][0];
        g[i][j] = sum;
      }
    out[surface][0] = g[0][0];
    out[surface][1] = g[1][1];
    out[surface][2] = g[2][2];
    out[surface][3] = g[0][1];
    out[surface][4] = g[1][2];
    out[surface][5] = g[2][0];
    eps_p_out[surface] = ep[surface];
  }
}

}  // namespace crumple::elements
