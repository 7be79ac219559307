// Pieces shared by the hex kernels (one-point hex8.cpp, fully integrated hex8_full.cpp):
// batch scratch, the node gather, volume and face areas of a batch, the Jaumann rotation, and
// the merge of per-batch results. Internal to src/elements.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "elements/hex8.hpp"
#include "materials/materials.hpp"

namespace crumple::elements::detail {

using LaneArray = double[kBatch];

// Faces for the characteristic length, each as 4 corners.
constexpr int kFaces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                              {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

// Sums over the 8 nodes sit inside the lane loop: GCC unrolls them and vectorises across
// lanes with the partial sums in registers (an accumulator array per node pass would go
// through memory on every node).
inline void volumeOf(const NodalBatch& x, const NodalBatch& b, LaneArray& vol) {
  for (int l = 0; l < kBatch; ++l) {
    double v = 0.0;
    for (int c = 0; c < 3; ++c)
      for (int a = 0; a < 8; ++a) v += x[c][a][l] * b[c][a][l];
    vol[l] = v * (1.0 / 3.0);
  }
}

// Largest face area: each face as half the cross product of its diagonals.
inline void maxFaceArea(const NodalBatch& x, LaneArray& area) {
  for (int l = 0; l < kBatch; ++l) area[l] = 0.0;
  for (const auto& f : kFaces) {
    for (int l = 0; l < kBatch; ++l) {
      const double d1x = x[0][f[2]][l] - x[0][f[0]][l], d1y = x[1][f[2]][l] - x[1][f[0]][l],
                   d1z = x[2][f[2]][l] - x[2][f[0]][l];
      const double d2x = x[0][f[3]][l] - x[0][f[1]][l], d2y = x[1][f[3]][l] - x[1][f[1]][l],
                   d2z = x[2][f[3]][l] - x[2][f[1]][l];
      const double cx = d1y * d2z - d1z * d2y, cy = d1z * d2x - d1x * d2z,
                   cz = d1x * d2y - d1y * d2x;
      const double a2 = 0.25 * (cx * cx + cy * cy + cz * cz);
      area[l] = std::max(area[l], a2);
    }
  }
  for (int l = 0; l < kBatch; ++l) area[l] = std::sqrt(area[l]);
}

// The constant-strain tetrahedron (ELFORM 10) in the canonical node order N1 N2 N3 N4 (corners
// 4-7 repeat N4, model/solid_shape.hpp): with V = (x2 - x1) . ((x3 - x1) x (x4 - x1)) / 6,
// B_a = dV/dx_a is a third of the area vector of the face opposite node a, pointing at a
// (LS-DYNA Theory Manual, "Solid elements"; Zienkiewicz & Taylor, vol. 1, the linear
// tetrahedron). The repeated corners get B = 0, so every sum over the hexahedron's eight
// corners gives the tetrahedron's, and x . B / 3 its volume.
inline void tetVolumeGradient(const NodalBatch& x, NodalBatch& b) {
  constexpr double sixth = 1.0 / 6.0;
  for (int l = 0; l < kBatch; ++l) {
    const double ax = x[0][1][l] - x[0][0][l], ay = x[1][1][l] - x[1][0][l],
                 az = x[2][1][l] - x[2][0][l];
    const double bx = x[0][2][l] - x[0][0][l], by = x[1][2][l] - x[1][0][l],
                 bz = x[2][2][l] - x[2][0][l];
    const double cx = x[0][3][l] - x[0][0][l], cy = x[1][3][l] - x[1][0][l],
                 cz = x[2][3][l] - x[2][0][l];
    // dV/dx2 = (b x c) / 6, dV/dx3 = (c x a) / 6, dV/dx4 = (a x b) / 6, dV/dx1 = -(sum).
    const double g[3][3] = {{by * cz - bz * cy, bz * cx - bx * cz, bx * cy - by * cx},
                            {cy * az - cz * ay, cz * ax - cx * az, cx * ay - cy * ax},
                            {ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx}};
    for (int c = 0; c < 3; ++c) {
      for (int a = 1; a < 4; ++a) b[c][a][l] = sixth * g[a - 1][c];
      b[c][0][l] = -(b[c][1][l] + b[c][2][l] + b[c][3][l]);
      for (int a = 4; a < 8; ++a) b[c][a][l] = 0.0;
    }
  }
}

// The area A for the tetrahedron's characteristic length L = V / A: with |B_a| a third of the
// area of the face opposite a, V / max|B_a| = 3 V / A_max is its minimum altitude, the length
// LS-DYNA takes for 4-node tetrahedra (Theory Manual, "Time step control").
inline void tetLengthArea(const NodalBatch& b, LaneArray& area) {
  for (int l = 0; l < kBatch; ++l) {
    double m = 0.0;
    for (int a = 0; a < 4; ++a)
      m = std::max(m, b[0][a][l] * b[0][a][l] + b[1][a][l] * b[1][a][l] + b[2][a][l] * b[2][a][l]);
    area[l] = std::sqrt(m);
  }
}

// The isoparametric gradients of one integration point of the multi-point solids (hex8_full.cpp,
// tet10.cpp): from the natural derivatives d[a][i] = dN_a / dxi_i of the N shape functions at
// the point and the nodal coordinates x[c][a][lane], the Jacobian J_ij = d x_j / d xi_i, its
// determinant times the rule's `weight` (the point's volume weight, det) and grad[j][a] =
// dN_a / dx_j = sum_i (J^-1)_ji dN_a / dxi_i.
template <int N>
inline void isoparametricGradients(const double (&d)[N][3], double weight,
                                   const double (&x)[3][N][kBatch], double (&grad)[3][N][kBatch],
                                   LaneArray& det) {
  for (int l = 0; l < kBatch; ++l) {
    double J[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double s = 0.0;
        for (int a = 0; a < N; ++a) s += d[a][i] * x[j][a][l];
        J[i][j] = s;
      }
    const double c00 = J[1][1] * J[2][2] - J[1][2] * J[2][1];
    const double c01 = J[1][2] * J[2][0] - J[1][0] * J[2][2];
    const double c02 = J[1][0] * J[2][1] - J[1][1] * J[2][0];
    const double dj = J[0][0] * c00 + J[0][1] * c01 + J[0][2] * c02;
    det[l] = weight * dj;
    const double r = dj != 0.0 ? 1.0 / dj : 0.0;
    // inverse: inv[j][i] with dN/dx_j = sum_i inv[j][i] dN/dxi_i
    const double inv[3][3] = {{c00 * r, (J[0][2] * J[2][1] - J[0][1] * J[2][2]) * r,
                               (J[0][1] * J[1][2] - J[0][2] * J[1][1]) * r},
                              {c01 * r, (J[0][0] * J[2][2] - J[0][2] * J[2][0]) * r,
                               (J[0][2] * J[1][0] - J[0][0] * J[1][2]) * r},
                              {c02 * r, (J[0][1] * J[2][0] - J[0][0] * J[2][1]) * r,
                               (J[0][0] * J[1][1] - J[0][1] * J[1][0]) * r}};
    for (int a = 0; a < N; ++a)
      for (int j = 0; j < 3; ++j)
        grad[j][a][l] = inv[j][0] * d[a][0] + inv[j][1] * d[a][1] + inv[j][2] * d[a][2];
  }
}

// Lane l of a batch starting at `first` with `n` live elements reads element first+min(l,n-1).
inline std::size_t laneElement(std::size_t first, int n, int l) {
  return first + static_cast<std::size_t>(std::min(l, n - 1));
}

inline void gatherNodal(const domain::SolidBlock& b, std::size_t first, int n,
                        const domain::NodeVector& src, NodalBatch& out) {
  for (int l = 0; l < kBatch; ++l) {
    const auto& conn = b.conn[laneElement(first, n, l)];
    for (int a = 0; a < 8; ++a) {
      const double* p = &src[3 * static_cast<std::size_t>(conn[a])];
      out[0][a][l] = p[0];
      out[1][a][l] = p[1];
      out[2][a][l] = p[2];
    }
  }
}

// Jaumann rotation of a symmetric tensor over one step: t += W t - t W, with the spin
// increments W_xy, W_yz, W_zx (times dt) and W skew.
inline void rotateJaumann(double (&t)[6][kBatch], int l, double wxy, double wyz, double wzx) {
  const double txx = t[0][l], tyy = t[1][l], tzz = t[2][l];
  const double txy = t[3][l], tyz = t[4][l], tzx = t[5][l];
  t[0][l] = txx + 2.0 * (wxy * txy - wzx * tzx);
  t[1][l] = tyy + 2.0 * (-wxy * txy + wyz * tyz);
  t[2][l] = tzz + 2.0 * (wzx * tzx - wyz * tyz);
  t[3][l] = txy + wxy * (tyy - txx) - wzx * tyz + wyz * tzx;
  t[4][l] = tyz + wyz * (tzz - tyy) - wxy * tzx + wzx * txy;
  t[5][l] = tzx + wzx * (txx - tzz) - wyz * txy + wxy * tyz;
}

// Scratch for one batch, kept per thread.
struct BatchScratch {
  NodalBatch x, v, xm, b, f;
  double s[6][kBatch], s_old[6][kBatch], de[6][kBatch], alpha[6][kBatch];
  double eps_p[kBatch];
  double hist[materials::kMaxHistory][kBatch];
  double F[9][kBatch];     // deformation gradient (laws that need it; deformationGradient)
  double modulus[kBatch];  // the points' wave modulus (laws that report it: kWaveModulus)
  double edge[6][kBatch];  // x2 - x1, x4 - x1 at x(n) (laws that need them: kElementGeometry)
  double length[kBatch];   // characteristic length at x(n-1/2) (the same laws)
  uint8_t failed[kBatch];
};

// The deformation gradient of the batch's one-point elements at x: F_ij = sum_a x_ia dN_a/dX_j
// with the initial gradients the block keeps (SolidBlock::grad0). For the uniform-strain
// element this is the volume average of F over the initial element, as B / V is of the velocity
// gradient (Flanagan & Belytschko 1981, eq. 14 with x in place of v).
inline void deformationGradient(const domain::SolidBlock& blk, std::size_t first, BatchScratch& w) {
  const double* g = blk.grad0.data() + first * 24;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int l = 0; l < kBatch; ++l) {
        double s = 0.0;
        for (int a = 0; a < 8; ++a) s += w.x[i][a][l] * g[(3 * a + j) * kBatch + l];
        w.F[3 * i + j][l] = s;
      }
}

// The element's edges x2 - x1 and x4 - x1 at x(n) (corners 0, 1, 3: the hexahedron's nodes 1,
// 2, 4 and the tetrahedron's N1, N2, N4), for laws that declare kElementGeometry.
inline void nodeEdges(BatchScratch& w) {
  for (int c = 0; c < 3; ++c)
    for (int l = 0; l < kBatch; ++l) {
      w.edge[c][l] = w.x[c][1][l] - w.x[c][0][l];
      w.edge[3 + c][l] = w.x[c][3][l] - w.x[c][0][l];
    }
}

// Stores the initial gradients dN_a/dX = B(X) / V0 of one batch (every lane, the padding
// lanes' replicas too, so the kernel reads whole batches) for laws that need F.
inline void storeInitialGradient(domain::SolidBlock& blk, std::size_t first, const NodalBatch& b,
                                 const LaneArray& vol0) {
  double* g = blk.grad0.data() + first * 24;
  for (int a = 0; a < 8; ++a)
    for (int j = 0; j < 3; ++j)
      for (int l = 0; l < kBatch; ++l)
        g[(3 * a + j) * kBatch + l] = vol0[l] > 0.0 ? b[j][a][l] / vol0[l] : 0.0;
}

// The material update of one batch of points: keeps the rotated stress in s_old (for the
// energy), clears the failure flags and lets the law advance s (and eps_p, alpha) by de.
template <class Law>
inline void updateMaterial(const Law& law, BatchScratch& w, double dt) {
  for (int k = 0; k < 6; ++k)
    for (int l = 0; l < kBatch; ++l) w.s_old[k][l] = w.s[k][l];
  for (int l = 0; l < kBatch; ++l) w.failed[l] = 0;
  materials::PointBatch pb;
  pb.n = kBatch;
  pb.dt = dt;
  for (int k = 0; k < 6; ++k) {
    pb.s[k] = w.s[k];
    pb.de[k] = w.de[k];
    pb.alpha[k] = Law::kKinematic ? w.alpha[k] : nullptr;
  }
  pb.eps_p = Law::kPlastic ? w.eps_p : nullptr;
  for (int k = 0; k < materials::historyOf<Law>(); ++k) pb.h[k] = w.hist[k];
  if constexpr (materials::needsDeformationGradient<Law>())
    for (int k = 0; k < 9; ++k) pb.F[k] = w.F[k];
  if constexpr (materials::reportsWaveModulus<Law>()) pb.modulus = w.modulus;
  if constexpr (materials::needsElementGeometry<Law>()) {
    for (int k = 0; k < 6; ++k) pb.edge[k] = w.edge[k];
    pb.length = w.length;
  }
  pb.failed = w.failed;
  law.update(pb);
}

// Stress work per unit volume over the step at lane l: the midpoint rule
// (s_old + s) / 2 : de, tensor shear components counted twice.
inline double stressWork(const BatchScratch& w, int l) {
  double p = 0.0;
  for (int k = 0; k < 6; ++k) p += (k < 3 ? 0.5 : 1.0) * (w.s_old[k][l] + w.s[k][l]) * w.de[k][l];
  return p;
}

// Work per unit volume of the bulk viscosity over the step at lane l of the batch from
// `first`, and q kept for the next pass. The force of this pass, -q B at x(n), was formed from
// v(n-1/2) and acts over dt(n) at v(n) = (v(n-1/2) + v(n+1/2)) / 2 in the equations of motion,
// so half of its work falls in this step and half in the next: the trapezoidal rule on q,
// (q_old + q) / 2 tr(D) dt, as for the stress (the energy identity in docs/theory.md, "Energy
// balance"). Counting q tr(D) dt instead over-counts the dissipation of a ringing element
// whose velocity changes sign between steps.
inline double bulkViscosityWork(domain::SolidBlock& blk, std::size_t first, int l, double q,
                                double trace_d, double dt) {
  double& q_old = blk.q_bulk[first + static_cast<std::size_t>(l)];
  const double work = -0.5 * (q_old + q) * trace_d * dt;
  q_old = q;
  return work;
}

// The end of an element's pass, shared by the kernels: an inverted element is noted; a failed
// one, or one whose stable step fell below blk.erode_dt, is eroded (LS-DYNA FAIL, ERODE,
// TDEL: the element is removed, its slots zeroed); otherwise its corner forces go to its
// slots and its stable step enters the batch minimum.
inline void finishElement(domain::SolidBlock& blk, std::size_t e, int l, const NodalBatch& f,
                          double vol, bool failed, double len, double c_dt, double trace_d,
                          const BulkViscosity& bv, double* slot, BlockStatus& st) {
  if (vol <= 0.0 && (st.bad_elem < 0 || blk.elem[e] < st.bad_elem)) st.bad_elem = blk.elem[e];
  double dte = solidTimeStep(len, c_dt, trace_d, bv);
  if (!blk.dt_scale.empty()) dte *= blk.dt_scale[e];
  if (failed || dte < blk.erode_dt) {
    blk.active[e] = 0;
    if (failed) blk.failed[e] = 1;
    for (int k = 0; k < 6; ++k) blk.sigAt(k, e) = 0.0;
    std::fill(slot, slot + 24, 0.0);
    ++st.eroded;
    return;
  }
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) slot[3 * a + i] = f[i][a][l];
  st.observeStep(dte, blk.elem[e]);
}

// Hourglass base vectors Gamma (FB 1981 eq. 43): eta*zeta, zeta*xi, xi*eta, xi*eta*zeta at
// the nodes of the LS-DYNA ordering (1-4 bottom face, 5-8 top face).
constexpr double kHexGamma[4][8] = {{1, 1, -1, -1, -1, -1, 1, 1},
                                    {1, -1, -1, 1, -1, 1, 1, -1},
                                    {1, -1, 1, -1, 1, -1, 1, -1},
                                    {-1, 1, -1, 1, 1, -1, 1, -1}};

// The constants of one block for one call.
struct SolidParams {
  double dt = 0, lam2mu = 0, qm = 0;
  bool stiffness_hg = false;
  bool projected_hg = false;  // FB orthogonal hourglass vectors gamma; type 1 uses Gamma
};

// The spin increments (for the stress and the stored hourglass resistances) and the trace of
// the rate of deformation (for the bulk viscosity).
struct SolidSpin {
  LaneArray trace_d, spin_xy, spin_yz, spin_zx;
};

// The current geometry and what follows from it: volume, density, wave speed, characteristic
// length, bulk viscosity.
struct SolidGeometry {
  LaneArray vol, area, rho, c, c_dt, len, q, cbrt_vol;
};

// Hourglass control (FB 1981 sec. 4; LS-DYNA Theory Manual "Hourglass control"), QM > 0:
// adds the hourglass forces of modes first_mode..3 to w.f and their work to de_hg (the hexahedron
// controls all four; the one-point thick shell, whose points through the thickness see modes 0
// and 1, the last two: src/elements/tshell.cpp). Every loop runs over lanes innermost so it
// vectorises.
inline void hourglassForces(const SolidParams& p, domain::SolidBlock& blk, std::size_t first,
                            BatchScratch& w, const SolidSpin& sp, const SolidGeometry& geo,
                            LaneArray& de_hg, int first_mode = 0) {
  const double dt = p.dt;
  const bool stiffness_hg = p.stiffness_hg;
  LaneArray coef, inv_vol;
  for (int l = 0; l < kBatch; ++l) {
    double bb = 0.0;
    for (int cc = 0; cc < 3; ++cc)
      for (int a = 0; a < 8; ++a) bb += w.b[cc][a][l] * w.b[cc][a][l];
    inv_vol[l] = 1.0 / geo.vol[l];
    // Viscous: a_h = QM rho V^(2/3) c / 4 on the unnormalised vectors (LS-DYNA).
    // Stiffness: QM (lambda + 2 mu) B:B / V per mode, integrated incrementally; FB
    // normalise the hourglass vectors by 1/sqrt(8), hence the 1/8 on the +-1 vectors.
    coef[l] = stiffness_hg
                  ? 0.125 * p.qm * p.lam2mu * bb * inv_vol[l] * dt
                  : 0.25 * p.qm * geo.rho[l] * geo.cbrt_vol[l] * geo.cbrt_vol[l] * geo.c[l];
  }
  // This batch's record of the last pass's hourglass forces.
  double* hgq_batch = blk.hgq.data() + first * 12;
  if (stiffness_hg) {
    // The stored resistance of each mode is a vector in the global frame: it turns with
    // the element, by the same spin increment as the stress (FB 1981 sec. 4.2), or a
    // rotated element would be pushed along its old directions.
    for (int alpha = 0; alpha < 4; ++alpha) {
      double* qx = hgq_batch + (3 * alpha) * kBatch;
      double* qy = hgq_batch + (3 * alpha + 1) * kBatch;
      double* qz = hgq_batch + (3 * alpha + 2) * kBatch;
      for (int l = 0; l < kBatch; ++l) {
        const double x0 = qx[l], y0 = qy[l], z0 = qz[l];
        qx[l] = x0 + sp.spin_xy[l] * y0 - sp.spin_zx[l] * z0;
        qy[l] = y0 - sp.spin_xy[l] * x0 + sp.spin_yz[l] * z0;
        qz[l] = z0 + sp.spin_zx[l] * x0 - sp.spin_yz[l] * y0;
      }
    }
  }
  // All four modes first (vectors gamma and resistances), then one pass that adds their
  // forces to the nodes: f_ia -= sum_alpha Q_i,alpha gamma_a,alpha.
  double g[4][8][kBatch];
  double force[4][3][kBatch];
  for (int alpha = 0; alpha < first_mode; ++alpha)
    for (int i = 0; i < 3; ++i)
      for (int l = 0; l < kBatch; ++l) force[alpha][i][l] = 0.0;
  for (int alpha = 0; alpha < 4; ++alpha) {
    for (int a = 0; a < 8; ++a)
      for (int l = 0; l < kBatch; ++l) g[alpha][a][l] = kHexGamma[alpha][a];
    if (alpha < first_mode) continue;
    if (p.projected_hg) {
      // gamma_a = Gamma_a - (1/V) (sum_b x_b Gamma_b) . B_a: orthogonal to linear fields.
      double h[3][kBatch];
      for (int cc = 0; cc < 3; ++cc)
        for (int l = 0; l < kBatch; ++l) {
          double sum = 0.0;
          for (int a = 0; a < 8; ++a) sum += w.x[cc][a][l] * kHexGamma[alpha][a];
          h[cc][l] = sum * inv_vol[l];
        }
      for (int a = 0; a < 8; ++a)
        for (int l = 0; l < kBatch; ++l)
          g[alpha][a][l] -=
              h[0][l] * w.b[0][a][l] + h[1][l] * w.b[1][a][l] + h[2][l] * w.b[2][a][l];
    }
    for (int i = 0; i < 3; ++i) {
      double qdot[kBatch], mean_force[kBatch];
      for (int l = 0; l < kBatch; ++l) {
        double sum = 0.0;
        for (int a = 0; a < 8; ++a) sum += w.v[i][a][l] * g[alpha][a][l];
        qdot[l] = sum;
      }
      // Work by the trapezoidal rule on the force, as for the stress: the force of the last
      // pass acts over half of this step in the equations of motion (as the bulk viscosity's
      // does: detail::bulkViscosityWork). The viscous force is new each pass, the stiffness
      // resistance adds to the stored one.
      double* fq = force[alpha][i];
      double* stored = hgq_batch + (3 * alpha + i) * kBatch;
      for (int l = 0; l < kBatch; ++l) {
        const double old = stored[l];
        // A failing element gives no force in its last pass (finishElement): its resistance
        // ends, and only the old half of the trapezoid is work.
        fq[l] = w.failed[l] ? 0.0 : (stiffness_hg ? old : 0.0) + coef[l] * qdot[l];
        mean_force[l] = 0.5 * (old + fq[l]);
        stored[l] = fq[l];
      }
      for (int l = 0; l < kBatch; ++l) de_hg[l] += mean_force[l] * qdot[l] * dt;
    }
  }
  for (int i = 0; i < 3; ++i)
    for (int a = 0; a < 8; ++a)
      for (int l = 0; l < kBatch; ++l)
        w.f[i][a][l] -= force[0][i][l] * g[0][a][l] + force[1][i][l] * g[1][a][l] +
                        force[2][i][l] * g[2][a][l] + force[3][i][l] * g[3][a][l];
}

// Per-batch results merged in batch order: the result does not depend on the thread count.
inline BlockStatus mergeStatus(const std::vector<BlockStatus>& status) {
  BlockStatus total;
  for (const auto& s : status) {
    if (s.dt_elem >= 0 &&
        (s.dt_min < total.dt_min || (s.dt_min == total.dt_min && s.dt_elem < total.dt_elem))) {
      total.dt_min = s.dt_min;
      total.dt_elem = s.dt_elem;
    }
    if (s.bad_elem >= 0 && (total.bad_elem < 0 || s.bad_elem < total.bad_elem))
      total.bad_elem = s.bad_elem;
    total.eroded += s.eroded;
  }
  return total;
}

}  // namespace crumple::elements::detail
