// The fully integrated shell (*SECTION_SHELL ELFORM 16): LS-DYNA Theory Manual, "Fully
// integrated shell (type 16)", after Engelmann, Whirley & Goudreau (1989), "A simple shell
// element formulation for large-scale elastoplastic analysis" (in Analytical and Computational
// Models of Shells, ASME CED-3), with the assumed natural transverse shear strain of Bathe &
// Dvorkin (1985), "A four-node plate bending element based on Mindlin/Reissner plate theory and
// a mixed interpolation", IJNME 21:367-383 (MITC4).
//
// Kinematics as the Belytschko-Lin-Tsay element (src/elements/shell.cpp, whose notation this
// file uses): one corotational frame per element (normal from the diagonals, first axis along
// side 1-2), the corners projected on its plane, Mindlin velocity strains, NIP points through
// the thickness with the plane-stress law, rates at the mid-step geometry and forces at x(n).
// What differs:
//  - 2 x 2 Gauss points in the plane (xi, eta = +-1/sqrt 3, weight det J each), each with its
//    own membrane strain rate, curvature rate and transverse shear, and its own stresses and
//    history through the thickness (4 x NIP points). Bilinear shape functions N_a = (1 + xi_a
//    xi)(1 + eta_a eta) / 4 on the projected corners; B1, B2 = dN/dx, dN/dy at each point:
//      d_xx = B1.vx + z B1.ty,  d_yy = B2.vy - z B2.tx,  2 d_xy = B2.vx + B1.vy + z (B2.ty - B1.tx)
//    and the corner forces and moments are the sums over the points of the one-point element's
//    expressions with A replaced by det J.
//  - Transverse shear from the covariant shear strains at the edge midpoints (Bathe-Dvorkin):
//      g_A = gamma_xi(0, -1), g_B = gamma_xi(0, 1), g_C = gamma_eta(-1, 0), g_D = gamma_eta(1, 0),
//      gamma_xi along an edge i -> j: (w_j - w_i) / 2 + (beta_i + beta_j) / 2 . (x_j - x_i) / 2,
//    beta = (ty, -tx) (so that gamma_xz = dw/dx + ty as in the one-point element); at a point
//      gamma_xi = (1 - eta) g_A / 2 + (1 + eta) g_B / 2,  gamma_eta = (1 - xi) g_C / 2 + (1 + xi)
//      g_D / 2, (gamma_xz, gamma_yz) = J^-1 (gamma_xi, gamma_eta).
//    Exact for constant shear, zero for pure bending of a rectangle: no shear locking, and
//    with the 2 x 2 membrane and bending no zero-energy mode but the six rigid motions (tested
//    by the element stiffness's eigenvalues), so no hourglass control: IHQ and QM are ignored
//    (as in LS-DYNA, where they apply to the under-integrated elements).
//  - Warping (LS-DYNA: IHQ 8 "activates warping stiffness for types 16 and -16"; with another
//    IHQ the element is flat, projected). With it the rigid rotation of a warped element about
//    its in-plane axes, whose corners at heights z_a move in the plane by (omega_y z_a,
//    -omega_x z_a), is taken out of the in-plane velocities before the strains,
//      vx_a' = vx_a + z_a B1.vz,   vy_a' = vy_a + z_a B2.vz   (B1, B2 at the centre),
//    and the transpose adds B1_b sum_a z_a fx_a + B2_b sum_a z_a fy_a to fz_b, which restores the
//    moment balance the projection breaks (the Belytschko-Wong-Chiang correction of the
//    one-point element applied to all four points). Flat elements are unaffected (z = 0).
//  - The drilling constraint and the lumped mass, rotary inertia and stable step of the
//    one-point element, unchanged (shared code).
//  - Thickness update (ISTUPD): each point's thickness strain; the element keeps the mean.
//  - Erosion when every point (4 x NIP) has failed.
// Triangles (n3 == n4) in an ELFORM 16 part run as C0 triangles in a block of their own
// (src/domain/subdomain.cpp; Crumple always sorts degenerate quadrilaterals, as ESORT = 1).
#include <cmath>
#include <stdexcept>
#include <variant>
#include <vector>

#include "elements/hex8_kernel.hpp"
#include "elements/shell.hpp"
#include "elements/shell_kernel.hpp"

namespace crumple::elements {

namespace {

using namespace shell_detail;  // the pieces shared with the one-point element

constexpr int kPoints = 4;                         // in-plane Gauss points
constexpr double kGauss = 0.57735026918962576451;  // 1 / sqrt(3)
// Natural coordinates of the corners; Gauss point q sits at kGauss (kXi[q], kEta[q]).
constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};
// Bathe-Dvorkin tying edges (corner i -> j): A (eta = -1) and B (eta = +1) carry gamma_xi,
// C (xi = -1) and D (xi = +1) carry gamma_eta.
constexpr int kTie[4][2] = {{0, 1}, {3, 2}, {0, 3}, {1, 2}};

// Gradients and Jacobian at one in-plane Gauss point of the projected element.
struct PointGradient {
  double b1[4], b2[4];  // dN/dx, dN/dy
  double det;           // det J, the point's weight (Gauss weights 1)
  double jinv[2][2];    // (d/dx, d/dy) = jinv (d/dxi, d/deta)
};

inline PointGradient gradientAt(const LaneFrame& f, int q) {
  PointGradient g;
  const double xi = kGauss * kXi[q], eta = kGauss * kEta[q];
  double dxi[4], deta[4];
  double j11 = 0.0, j12 = 0.0, j21 = 0.0, j22 = 0.0;
  for (int a = 0; a < 4; ++a) {
    dxi[a] = 0.25 * kXi[a] * (1.0 + kEta[a] * eta);
    deta[a] = 0.25 * kEta[a] * (1.0 + kXi[a] * xi);
    j11 += dxi[a] * f.xh[a];
    j12 += dxi[a] * f.yh[a];
    j21 += deta[a] * f.xh[a];
    j22 += deta[a] * f.yh[a];
  }
  g.det = j11 * j22 - j12 * j21;
  const double inv = 1.0 / g.det;
  g.jinv[0][0] = j22 * inv;
  g.jinv[0][1] = -j12 * inv;
  g.jinv[1][0] = -j21 * inv;
  g.jinv[1][1] = j11 * inv;
  for (int a = 0; a < 4; ++a) {
    g.b1[a] = g.jinv[0][0] * dxi[a] + g.jinv[0][1] * deta[a];
    g.b2[a] = g.jinv[1][0] * dxi[a] + g.jinv[1][1] * deta[a];
  }
  return g;
}

// Heights of the corners above the plane through their centroid (z_a = +-z_w h_a with the
// diagonals' normal), for the warping projection.
inline void cornerHeights(const LaneFrame& f, const NodalShell& x, int l, double z[4]) {
  double c[3];
  for (int k = 0; k < 3; ++k) c[k] = 0.25 * (x[k][0][l] + x[k][1][l] + x[k][2][l] + x[k][3][l]);
  for (int a = 0; a < 4; ++a)
    z[a] = f.e[2][0] * (x[0][a][l] - c[0]) + f.e[2][1] * (x[1][a][l] - c[1]) +
           f.e[2][2] * (x[2][a][l] - c[2]);
}

// The Bathe-Dvorkin covariant shears at the four tying points from the corner velocities vz
// and rotation rates tx, ty (frame components).
inline void tyingShears(const LaneFrame& f, const double vz[4], const double tx[4],
                        const double ty[4], double g[4]) {
  for (int k = 0; k < 4; ++k) {
    const int i = kTie[k][0], j = kTie[k][1];
    const double dx = f.xh[j] - f.xh[i], dy = f.yh[j] - f.yh[i];
    g[k] = 0.5 * (vz[j] - vz[i]) + 0.25 * ((ty[i] + ty[j]) * dx - (tx[i] + tx[j]) * dy);
  }
}

// Cartesian transverse shear at Gauss point q from the tying shears.
inline void shearAtPoint(const PointGradient& pg, const double g[4], int q, double& gxz,
                         double& gyz) {
  const double eta = kGauss * kEta[q], xi = kGauss * kXi[q];
  const double gxi = 0.5 * (1.0 - eta) * g[0] + 0.5 * (1.0 + eta) * g[1];
  const double geta = 0.5 * (1.0 - xi) * g[2] + 0.5 * (1.0 + xi) * g[3];
  gxz = pg.jinv[0][0] * gxi + pg.jinv[0][1] * geta;
  gyz = pg.jinv[1][0] * gxi + pg.jinv[1][1] * geta;
}

// The rates of one lane at the mid-step geometry: per Gauss point q, membrane, curvature and
// transverse shear (r[q]), the point's area weight; the drilling rates in r[0].
inline void laneRates(const ShellScratch& s, bool warping, int l, ShellRates (&r)[kPoints]) {
  const LaneFrame f = frameAt(s.xm, l);
  double vx[4], vy[4], vz[4], tx[4], ty[4], tz[4];
  onAxis(f, 0, s.v, l, vx);
  onAxis(f, 1, s.v, l, vy);
  onAxis(f, 2, s.v, l, vz);
  onAxis(f, 0, s.w, l, tx);
  onAxis(f, 1, s.w, l, ty);
  onAxis(f, 2, s.w, l, tz);
  if (warping) {
    double z[4], sz1 = 0.0, sz2 = 0.0;
    cornerHeights(f, s.xm, l, z);
    for (int a = 0; a < 4; ++a) {
      sz1 += f.b1[a] * vz[a];
      sz2 += f.b2[a] * vz[a];
    }
    for (int a = 0; a < 4; ++a) {
      vx[a] += z[a] * sz1;
      vy[a] += z[a] * sz2;
    }
  }
  double spin = 0.0;
  for (int a = 0; a < 4; ++a) spin += f.b1[a] * vy[a] - f.b2[a] * vx[a];
  for (int a = 0; a < 4; ++a) r[0].rdrill[a][l] = tz[a] - 0.5 * spin;
  double g[4];
  tyingShears(f, vz, tx, ty, g);
  for (int q = 0; q < kPoints; ++q) {
    const PointGradient pg = gradientAt(f, q);
    double sxx = 0, syy = 0, sxy = 0, cx = 0, cy = 0, cxy = 0;
    for (int a = 0; a < 4; ++a) {
      sxx += pg.b1[a] * vx[a];
      syy += pg.b2[a] * vy[a];
      sxy += pg.b2[a] * vx[a] + pg.b1[a] * vy[a];
      cx += pg.b1[a] * ty[a];
      cy -= pg.b2[a] * tx[a];
      cxy += pg.b2[a] * ty[a] - pg.b1[a] * tx[a];
    }
    ShellRates& rq = r[q];
    rq.dxm[l] = sxx;
    rq.dym[l] = syy;
    rq.gxy[l] = sxy;
    rq.kx[l] = cx;
    rq.ky[l] = cy;
    rq.kxy[l] = cxy;
    shearAtPoint(pg, g, q, rq.gxz[l], rq.gyz[l]);
    rq.area_mid[l] = pg.det;
  }
}

// Forces and moments of one lane at x(n) from the points' resultants (frame components),
// before the drilling moments: membrane and bending per point, the Bathe-Dvorkin shear's
// transpose. Returns the element area (sum of det J).
inline double laneForces(const LaneFrame& f, const ShellResultants (&q)[kPoints], int l,
                         double fx[4], double fy[4], double fz[4], double mx[4], double my[4]) {
  for (int a = 0; a < 4; ++a) fx[a] = fy[a] = fz[a] = mx[a] = my[a] = 0.0;
  double tie[4] = {0.0, 0.0, 0.0, 0.0}, area = 0.0;
  for (int p = 0; p < kPoints; ++p) {
    const PointGradient pg = gradientAt(f, p);
    const ShellResultants& r = q[p];
    const double w = pg.det;
    area += w;
    for (int a = 0; a < 4; ++a) {
      const double b1 = pg.b1[a], b2 = pg.b2[a];
      fx[a] += w * (b1 * r.nxx[l] + b2 * r.nxy[l]);
      fy[a] += w * (b2 * r.nyy[l] + b1 * r.nxy[l]);
      mx[a] += w * (-b2 * r.myy[l] - b1 * r.mxy[l]);
      my[a] += w * (b1 * r.mxx[l] + b2 * r.mxy[l]);
    }
    // Shear power w Q.J^-1 (gamma_xi, gamma_eta): the resultants conjugate to the tying shears.
    const double pxi = w * (pg.jinv[0][0] * r.qx[l] + pg.jinv[1][0] * r.qy[l]);
    const double peta = w * (pg.jinv[0][1] * r.qx[l] + pg.jinv[1][1] * r.qy[l]);
    const double eta = kGauss * kEta[p], xi = kGauss * kXi[p];
    tie[0] += 0.5 * (1.0 - eta) * pxi;
    tie[1] += 0.5 * (1.0 + eta) * pxi;
    tie[2] += 0.5 * (1.0 - xi) * peta;
    tie[3] += 0.5 * (1.0 + xi) * peta;
  }
  for (int k = 0; k < 4; ++k) {
    const int i = kTie[k][0], j = kTie[k][1];
    const double dx = f.xh[j] - f.xh[i], dy = f.yh[j] - f.yh[i];
    fz[j] += 0.5 * tie[k];
    fz[i] -= 0.5 * tie[k];
    const double hx = 0.25 * tie[k] * dx, hy = 0.25 * tie[k] * dy;
    my[i] += hx;
    my[j] += hx;
    mx[i] -= hy;
    mx[j] -= hy;
  }
  return area;
}

// What the kernel's phases share for one batch besides the one-point element's parameters.
struct FullBatch {
  ShellRates r[kPoints];
  ShellResultants q[kPoints];
  Lanes work, failed_points, t_mean, de_int;
};

// Corner forces, moments, drilling, warping transpose and stable step of every lane.
inline void fullCornerForces(const ShellParams& p, const domain::ShellBlock& blk, ShellScratch& s,
                             const ShellLanes& ln, FullBatch& fb, ShellForcesOut& o) {
  constexpr int B = kShellBatch;
  Lanes inv_c_dt;
  slownessOf(p, blk, ln, inv_c_dt);
  double drill_prev[4][B];
  loadDrill(blk, ln.first, drill_prev);
  for (int l = 0; l < B; ++l) {
    const LaneFrame f = frameAt(s.x, l);
    double fx[4], fy[4], fz[4], mx[4], my[4], mz[4];
    const double A = laneForces(f, fb.q, l, fx, fy, fz, mx, my);
    o.area[l] = A;
    o.dte[l] = A / longestSide(s.x, l) * inv_c_dt[l];
    const double t = fb.t_mean[l];
    double drill_sum = 0.0, e_drill = 0.0;
    drillMoments(drill_prev, fb.r[0].rdrill, p.drill_coef * t * t * t, p.dt, l, mz, o.drill_new,
                 drill_sum, e_drill);
    o.de_drill[l] = e_drill;
    for (int a = 0; a < 4; ++a) {
      fx[a] += 0.5 * f.b2[a] * drill_sum;
      fy[a] -= 0.5 * f.b1[a] * drill_sum;
    }
    if (blk.warping) {
      double z[4], zfx = 0.0, zfy = 0.0;
      cornerHeights(f, s.x, l, z);
      for (int a = 0; a < 4; ++a) {
        zfx += z[a] * fx[a];
        zfy += z[a] * fy[a];
      }
      for (int a = 0; a < 4; ++a) fz[a] += f.b1[a] * zfx + f.b2[a] * zfy;
    }
    cornerLoadsToGlobal(f, fx, fy, fz, mx, my, mz, l, s);
  }
}

// The points of the batch, in-plane point by in-plane point: plane-stress update through the
// thickness, resultants, stores; the element's thickness (mean) and internal energy.
template <class Law>
inline void fullPointStresses(const Law& law, const ShellParams& p, domain::ShellBlock& blk,
                              ShellScratch& s, const ShellLanes& ln, FullBatch& fb) {
  constexpr int B = kShellBatch;
  const auto first = ln.first;
  double* sig_batch = blk.sig.data() + first * static_cast<std::size_t>(p.fields);
  double* ep_batch = Law::kPlastic
                         ? blk.eps_p.data() + first * static_cast<std::size_t>(blk.epsFields())
                         : nullptr;
  double* alpha_batch = materials::shellAlphaOf<Law>()
                            ? blk.alpha.data() + first * static_cast<std::size_t>(blk.alphaFields())
                            : nullptr;
  Lanes alive;
  aliveLanes(blk, first, alive);
  for (int l = 0; l < B; ++l) fb.failed_points[l] = fb.t_mean[l] = fb.de_int[l] = 0.0;
  for (int q = 0; q < kPoints; ++q) {
    double* sig_q = sig_batch + q * blk.pointFields() * B;
    double* ep_q = Law::kPlastic ? ep_batch + q * p.nip * B : nullptr;
    double* alpha_q = materials::shellAlphaOf<Law>() ? alpha_batch + q * 3 * p.nip * B : nullptr;
    Lanes failed_q;
    double* ero_q = p.erosion
                        ? blk.erosion_state.data() + first * std::size_t(blk.erosionFields()) +
                              std::size_t(q * domain::ShellBlock::kErosionFields * p.nip * B)
                        : nullptr;
    double* hist_q = materials::historyOf<Law>() > 0
                         ? blk.hist.data() + first * std::size_t(blk.histFields()) +
                               std::size_t(q * p.history * p.nip * B)
                         : nullptr;
    pointStresses(law, p, s, sig_q, ep_q, alpha_q, ln, fb.r[q], fb.work, failed_q, ero_q, hist_q);
    resultantsOf(p, s, sig_q, ln, fb.r[q], fb.work, fb.q[q]);
    storePoints<Law>(p, s, alive, sig_q, ep_q, alpha_q, fb.q[q]);
    for (int l = 0; l < B; ++l) {
      fb.failed_points[l] += failed_q[l];
      fb.t_mean[l] += 0.25 * fb.q[q].t_new[l];
      fb.de_int[l] += fb.q[q].de_int[l];
    }
  }
}

// The element-level state: thickness, energies, drilling moments.
inline void storeFull(domain::ShellBlock& blk, const ShellLanes& ln, const FullBatch& fb,
                      const ShellForcesOut& o) {
  constexpr int B = kShellBatch;
  Lanes alive;
  aliveLanes(blk, ln.first, alive);
  double* drill_batch = blk.drill.data() + ln.first * 4;
  for (int a = 0; a < 4; ++a)
    for (int l = 0; l < B; ++l) drill_batch[a * B + l] = alive[l] != 0.0 ? o.drill_new[a][l] : 0.0;
  for (int l = 0; l < B; ++l) {
    const std::size_t e = ln.first + static_cast<std::size_t>(l);
    blk.thick[e] = alive[l] != 0.0 ? fb.t_mean[l] : blk.thick[e];
    blk.e_int[e] += alive[l] != 0.0 ? fb.de_int[l] : 0.0;
    blk.e_drill[e] += alive[l] != 0.0 ? o.de_drill[l] : 0.0;
  }
}

// One portable binary, three instruction sets, as the one-point kernel (same bits on every
// path: no FMA contraction, no fast-math).
template <class Law>
[[gnu::flatten, gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]] BlockStatus
fullShellBlockForces(const Law& law, domain::ShellBlock& blk, const domain::NodeVector& x,
                     const domain::NodeVector& v, const domain::NodeVector& w, double dt,
                     double* slots, std::size_t range_first, std::size_t range_last) {
  constexpr int B = kShellBatch;
  const std::size_t batch0 = range_first / B;
  const std::size_t nbatch = range_last > range_first ? (range_last - range_first + B - 1) / B : 0;
  const ShellParams p = shellParamsOf(law, blk, dt);
  std::vector<BlockStatus> status(nbatch);

#pragma omp parallel
  {
    ShellScratch s;
    FullBatch fb;
#pragma omp for schedule(static)
    for (std::size_t ib = 0; ib < nbatch; ++ib) {
      ShellLanes ln;
      ln.first = (batch0 + ib) * B;
      ln.n = static_cast<int>(std::min<std::size_t>(B, range_last - ln.first));
      loadBatch(blk, x, v, w, s, ln);
      for (int c = 0; c < 3; ++c)
        for (int a = 0; a < 4; ++a)
          for (int l = 0; l < B; ++l) s.xm[c][a][l] = s.x[c][a][l] - 0.5 * dt * s.v[c][a][l];
      for (int l = 0; l < B; ++l) laneRates(s, blk.warping, l, fb.r);
      fullPointStresses(law, p, blk, s, ln, fb);
      ShellForcesOut o;
      fullCornerForces(p, blk, s, ln, fb, o);
      storeFull(blk, ln, fb, o);
      writeSlots(p, blk, s, ln, fb.failed_points, o, slots, status[ib]);
    }
  }
  return detail::mergeStatus(status);
}

}  // namespace

BlockStatus computeFullShellForces(domain::ShellBlock& block, const domain::NodeVector& x,
                                   const domain::NodeVector& v, const domain::NodeVector& w,
                                   double dt, double* slots, std::size_t first, std::size_t last) {
  if (first % kShellBatch != 0 || (last % kShellBatch != 0 && last != block.size()) ||
      last > block.size())
    throw std::logic_error("computeFullShellForces: range not aligned to batches");
  if (block.elform != 16)
    throw std::logic_error("computeFullShellForces: the block is not ELFORM 16");
  return std::visit(
      [&](const auto& law) -> BlockStatus {
        if constexpr (materials::ShellLaw<std::decay_t<decltype(law)>>)
          return fullShellBlockForces(law, block, x, v, w, dt, slots, first, last);
        else
          materials::noUpdateFor(materials::Family::Shell);
      },
      block.law);
}

}  // namespace crumple::elements
