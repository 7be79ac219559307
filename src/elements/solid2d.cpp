// 2D solid kernels (plane strain ELFORM 13, axisymmetric ELFORM 15); formulation in solid2d.hpp,
// theory notes in docs/theory.md ("2D solids").
#include "elements/solid2d.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "elements/hex8_kernel.hpp"

namespace crumple::elements {

namespace {

constexpr int B = domain::kShellBatch;
static_assert(B == kBatch, "the 2D kernel shares the hex kernel's material batch");
using Lanes = double[B];

// Corner a of the parent square (-1..1)^2 in LS-DYNA order (counter-clockwise from n1).
constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};
// The one 2D hourglass base vector (Flanagan & Belytschko 1981 in two dimensions).
constexpr double kGamma[4] = {1.0, -1.0, 1.0, -1.0};

// One batch's nodal data (x, y components of corners 0..3) and the material scratch.
struct Scratch2D {
  double x[2][4][B], v[2][4][B];
  double s[6][B], s_old[6][B], de[6][B], alpha[6][B];
  double eps_p[B];
  uint8_t failed[B];
  double f[2][4][B];
  Lanes vol_mid, trace_d, spin, vol, len, rho, c, c_dt, q, de_int, de_hg;
};

// What one batch is: its first element and how many lanes are real.
struct Batch2D {
  std::size_t first = 0;
  int n = 0;
};

struct Params2D {
  double dt = 0.0, lam2mu = 0.0, qm = 0.0;
  bool projected = false;
  bool axisymmetric = false;
};

void loadBatch(const domain::ShellBlock& blk, const domain::NodeVector& x,
               const domain::NodeVector& v, const Batch2D& bt, Scratch2D& s) {
  for (int l = 0; l < B; ++l) {
    const auto& conn = blk.conn[detail::laneElement(bt.first, bt.n, l)];
    for (int a = 0; a < 4; ++a) {
      const std::size_t p = 3 * static_cast<std::size_t>(conn[std::size_t(a)]);
      for (int c = 0; c < 2; ++c) {
        s.x[c][a][l] = x[p + std::size_t(c)];
        s.v[c][a][l] = v[p + std::size_t(c)];
      }
    }
  }
}

// Lane l's corner coordinates, optionally moved back by dt/2 along v (the mid-step geometry).
void laneCorners(const Scratch2D& s, int l, double back, double xc[4], double yc[4]) {
  for (int a = 0; a < 4; ++a) {
    xc[a] = s.x[0][a][l] - back * s.v[0][a][l];
    yc[a] = s.x[1][a][l] - back * s.v[1][a][l];
  }
}

// Mean rate of deformation at the mid-step geometry x(n-1/2) = x(n) - dt/2 v(n-1/2): strain
// increments for the law, spin, trace (bulk viscosity) and the mid-step volume (energy).
void midStepRates(const Params2D& p, Scratch2D& s) {
  for (int l = 0; l < B; ++l) {
    double xc[4], yc[4];
    laneCorners(s, l, 0.5 * p.dt, xc, yc);
    const Solid2DIntegrals g = solid2DIntegrals(xc, yc, p.axisymmetric);
    const double inv = g.vol > 0.0 ? 1.0 / g.vol : 0.0;
    double L[2][2] = {{0, 0}, {0, 0}}, dzz = 0.0;
    for (int a = 0; a < 4; ++a) {
      for (int i = 0; i < 2; ++i) {
        L[i][0] += s.v[i][a][l] * g.bx[a];
        L[i][1] += s.v[i][a][l] * g.by[a];
      }
      dzz += s.v[0][a][l] * g.h[a];
    }
    for (auto& row : L)
      for (double& e : row) e *= inv;
    dzz *= inv;
    s.vol_mid[l] = g.vol;
    s.spin[l] = 0.5 * (L[0][1] - L[1][0]) * p.dt;
    s.trace_d[l] = L[0][0] + L[1][1] + dzz;
    s.de[0][l] = L[0][0] * p.dt;
    s.de[1][l] = L[1][1] * p.dt;
    s.de[2][l] = dzz * p.dt;
    s.de[3][l] = 0.5 * (L[0][1] + L[1][0]) * p.dt;
    s.de[4][l] = s.de[5][l] = 0.0;
  }
}

// The stress: this batch's records, the Jaumann rotation about z, then the 3-D law.
template <class Law>
void updateStress(const Law& law, const Params2D& p, const domain::ShellBlock& blk,
                  const Batch2D& bt, Scratch2D& s) {
  const double* sig = blk.sig.data() + bt.first * 6;
  for (int k = 0; k < 6; ++k)
    for (int l = 0; l < B; ++l) s.s[k][l] = sig[k * B + l];
  if constexpr (Law::kPlastic)
    for (int l = 0; l < B; ++l) s.eps_p[l] = blk.eps_p[bt.first + std::size_t(l)];
  if constexpr (Law::kKinematic) {
    const double* alpha = blk.alpha.data() + bt.first * 6;
    for (int k = 0; k < 6; ++k)
      for (int l = 0; l < B; ++l) s.alpha[k][l] = alpha[k * B + l];
  }
  for (int l = 0; l < B; ++l) {
    detail::rotateJaumann(s.s, l, s.spin[l], 0.0, 0.0);
    if constexpr (Law::kKinematic) detail::rotateJaumann(s.alpha, l, s.spin[l], 0.0, 0.0);
    s.failed[l] = 0;
  }
  for (int k = 0; k < 6; ++k)
    for (int l = 0; l < B; ++l) s.s_old[k][l] = s.s[k][l];
  materials::PointBatch pb;
  pb.n = B;
  pb.dt = p.dt;
  for (int k = 0; k < 6; ++k) {
    pb.s[k] = s.s[k];
    pb.de[k] = s.de[k];
    pb.alpha[k] = Law::kKinematic ? s.alpha[k] : nullptr;
  }
  pb.eps_p = Law::kPlastic ? s.eps_p : nullptr;
  pb.failed = s.failed;
  law.update(pb);
}

// Plane area and longest diagonal of a quadrilateral (a triangle: n3 == n4).
void areaAndDiagonal(const double xc[4], const double yc[4], double& area, double& diag) {
  const double d1x = xc[2] - xc[0], d1y = yc[2] - yc[0];
  const double d2x = xc[3] - xc[1], d2y = yc[3] - yc[1];
  area = 0.5 * (d1x * d2y - d1y * d2x);
  diag = std::sqrt(std::max(d1x * d1x + d1y * d1y, d2x * d2x + d2y * d2y));
}

// Viscous hourglass forces of lane l (added to s.f) and their work (s.de_hg); hg holds the
// last pass's force per direction (trapezoidal work, as the solids' hourglass).
void hourglass(const Params2D& p, const double xc[4], const double yc[4], double area, int l,
               double* hg_x, double* hg_y, Scratch2D& s) {
  double g[4];
  for (int a = 0; a < 4; ++a) g[a] = kGamma[a];
  if (p.projected && area > 0.0) {
    // gamma = Gamma - (sum x Gamma) dA/dx / A - (sum y Gamma) dA/dy / A.
    const double bx[4] = {0.5 * (yc[1] - yc[3]), 0.5 * (yc[2] - yc[0]), 0.5 * (yc[3] - yc[1]),
                          0.5 * (yc[0] - yc[2])};
    const double by[4] = {0.5 * (xc[3] - xc[1]), 0.5 * (xc[0] - xc[2]), 0.5 * (xc[1] - xc[3]),
                          0.5 * (xc[2] - xc[0])};
    double hx = 0.0, hy = 0.0;
    for (int a = 0; a < 4; ++a) {
      hx += xc[a] * kGamma[a];
      hy += yc[a] * kGamma[a];
    }
    for (int a = 0; a < 4; ++a) g[a] -= (hx * bx[a] + hy * by[a]) / area;
  }
  const double coef =
      area > 0.0 ? 0.25 * p.qm * s.rho[l] * s.c[l] * s.vol[l] / std::sqrt(area) : 0.0;
  double* stored[2] = {hg_x, hg_y};
  for (int i = 0; i < 2; ++i) {
    double qdot = 0.0;
    for (int a = 0; a < 4; ++a) qdot += s.v[i][a][l] * g[a];
    const double force = coef * qdot;
    s.de_hg[l] += 0.5 * (*stored[i] + force) * qdot * p.dt;
    *stored[i] = force;
    for (int a = 0; a < 4; ++a) s.f[i][a][l] -= force * g[a];
  }
}

// Geometry at x(n), bulk viscosity, stress divergence, hourglass forces and energies.
void cornerForces(const Params2D& p, domain::ShellBlock& blk, const BulkViscosity& bv,
                  const Batch2D& bt, Scratch2D& s) {
  for (int l = 0; l < B; ++l) {
    const std::size_t e = bt.first + std::size_t(l);
    double xc[4], yc[4];
    laneCorners(s, l, 0.0, xc, yc);
    const Solid2DIntegrals g = solid2DIntegrals(xc, yc, p.axisymmetric);
    double area = 0.0, diag = 0.0;
    areaAndDiagonal(xc, yc, area, diag);
    s.vol[l] = g.vol;
    const double v_safe = g.vol > 0.0 ? g.vol : 1.0;
    s.rho[l] = blk.rho0 * blk.area0[e] / v_safe;
    s.c[l] = std::sqrt(p.lam2mu / s.rho[l]);
    s.c_dt[l] = blk.mass_scale.empty() ? s.c[l] : s.c[l] / std::sqrt(blk.mass_scale[e]);
    s.len[l] = area > 0.0 ? area / diag : 0.0;
    // Bulk viscosity as the solids' (LS-DYNA Theory Manual, "Bulk viscosity"), compression only.
    const double td = s.trace_d[l];
    s.q[l] =
        td < 0.0 ? s.rho[l] * s.len[l] * (bv.q1 * s.len[l] * td * td - bv.q2 * s.c[l] * td) : 0.0;
    double& q_old = blk.hgq[domain::ShellBlock::blocked(5, 2, e)];
    double work = 0.0;
    for (int k = 0; k < 6; ++k)
      work += (k < 3 ? 0.5 : 1.0) * (s.s_old[k][l] + s.s[k][l]) * s.de[k][l];
    work -= 0.5 * (q_old + s.q[l]) * td * p.dt;
    q_old = s.q[l];
    s.de_int[l] = work * s.vol_mid[l];
    const double sxx = s.s[0][l] - s.q[l], syy = s.s[1][l] - s.q[l], szz = s.s[2][l] - s.q[l];
    const double sxy = s.s[3][l];
    for (int a = 0; a < 4; ++a) {
      s.f[0][a][l] = -(sxx * g.bx[a] + sxy * g.by[a] + szz * g.h[a]);
      s.f[1][a][l] = -(sxy * g.bx[a] + syy * g.by[a]);
    }
    s.de_hg[l] = 0.0;
    if (p.qm > 0.0)
      hourglass(p, xc, yc, area, l, &blk.hgq[domain::ShellBlock::blocked(5, 0, e)],
                &blk.hgq[domain::ShellBlock::blocked(5, 1, e)], s);
  }
}

// Stores the state, then per element: erosion, slots and stable step.
template <class Law>
void storeBatch(domain::ShellBlock& blk, const BulkViscosity& bv, const Batch2D& bt,
                const Scratch2D& s, double* slots, BlockStatus& st) {
  double* sig = blk.sig.data() + bt.first * 6;
  const uint8_t* alive = &blk.active[bt.first];
  for (int k = 0; k < 6; ++k)
    for (int l = 0; l < B; ++l) sig[k * B + l] = alive[l] ? s.s[k][l] : 0.0;
  if constexpr (Law::kPlastic)
    for (int l = 0; l < B; ++l)
      if (alive[l]) blk.eps_p[bt.first + std::size_t(l)] = s.eps_p[l];
  if constexpr (Law::kKinematic) {
    double* alpha = blk.alpha.data() + bt.first * 6;
    for (int k = 0; k < 6; ++k)
      for (int l = 0; l < B; ++l) alpha[k * B + l] = s.alpha[k][l];
  }
  for (int l = 0; l < bt.n; ++l) {
    const std::size_t e = bt.first + std::size_t(l);
    double* slot = slots + 3 * (blk.slot_offset + 8 * e);
    if (!blk.active[e]) {
      std::fill(slot, slot + 24, 0.0);
      continue;
    }
    blk.e_int[e] += s.de_int[l];
    blk.e_hg[e] += s.de_hg[l];
    if (s.vol[l] <= 0.0 && (st.bad_elem < 0 || blk.elem[e] < st.bad_elem))
      st.bad_elem = blk.elem[e];
    const double dte = s.len[l] > 0.0 ? solidTimeStep(s.len[l], s.c_dt[l], s.trace_d[l], bv) : 0.0;
    if (s.failed[l] || dte < blk.erode_dt) {
      blk.active[e] = 0;
      if (s.failed[l]) blk.failed[e] = 1;
      for (int k = 0; k < 6; ++k) blk.sigAt(k, 0, e) = 0.0;
      std::fill(slot, slot + 24, 0.0);
      ++st.eroded;
      continue;
    }
    std::fill(slot, slot + 24, 0.0);
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 2; ++i) slot[3 * a + i] = s.f[i][a][l];
    st.observeStep(dte, blk.elem[e]);
  }
}

template <class Law>
BlockStatus solid2DBlockForces(const Law& law, domain::ShellBlock& blk, const domain::NodeVector& x,
                               const domain::NodeVector& v, double dt, const BulkViscosity& bv,
                               double* slots, std::size_t range_first, std::size_t range_last) {
  const std::size_t batch0 = range_first / B;
  const std::size_t nbatch = range_last > range_first ? (range_last - range_first + B - 1) / B : 0;
  const materials::Moduli mod = law.moduli;
  Params2D p;
  p.dt = dt;
  p.lam2mu = mod.bulk + 4.0 / 3.0 * mod.shear;
  p.qm = blk.qm;
  p.projected = blk.ihq >= 2;
  p.axisymmetric = blk.axisymmetric();
  std::vector<BlockStatus> status(nbatch);
#pragma omp parallel
  {
    Scratch2D s;
#pragma omp for schedule(static)
    for (std::size_t ib = 0; ib < nbatch; ++ib) {
      Batch2D bt;
      bt.first = (batch0 + ib) * B;
      bt.n = static_cast<int>(std::min<std::size_t>(B, range_last - bt.first));
      loadBatch(blk, x, v, bt, s);
      midStepRates(p, s);
      updateStress(law, p, blk, bt, s);
      cornerForces(p, blk, bv, bt, s);
      storeBatch<Law>(blk, bv, bt, s, slots, status[ib]);
    }
  }
  return detail::mergeStatus(status);
}

}  // namespace

Solid2DIntegrals solid2DIntegrals(const double x[4], const double y[4], bool axisymmetric) {
  Solid2DIntegrals out{};
  const double gp = 1.0 / std::sqrt(3.0);
  for (int q = 0; q < 4; ++q) {
    // 2 x 2 Gauss, weights 1: exact for every integrand here (degree <= 3 in xi and in eta).
    const double xi = gp * kXi[q], eta = gp * kEta[q];
    double n[4], dxi[4], deta[4];
    double xxi = 0, xeta = 0, yxi = 0, yeta = 0, r = 0;
    for (int a = 0; a < 4; ++a) {
      n[a] = 0.25 * (1.0 + kXi[a] * xi) * (1.0 + kEta[a] * eta);
      dxi[a] = 0.25 * kXi[a] * (1.0 + kEta[a] * eta);
      deta[a] = 0.25 * kEta[a] * (1.0 + kXi[a] * xi);
      xxi += x[a] * dxi[a];
      xeta += x[a] * deta[a];
      yxi += y[a] * dxi[a];
      yeta += y[a] * deta[a];
      r += n[a] * x[a];
    }
    const double j = xxi * yeta - xeta * yxi;
    const double w = axisymmetric ? r : 1.0;
    out.vol += w * j;
    for (int a = 0; a < 4; ++a) {
      // J dN/dx and J dN/dy by the inverse of the 2 x 2 Jacobian.
      out.bx[a] += w * (dxi[a] * yeta - deta[a] * yxi);
      out.by[a] += w * (deta[a] * xxi - dxi[a] * xeta);
      out.h[a] += axisymmetric ? n[a] * j : 0.0;
      out.m[a] += n[a] * w * j;
    }
  }
  return out;
}

BlockStatus initializeSolid2D(domain::ShellBlock& blk, const domain::NodeVector& x0, double* slots,
                              std::vector<double>& element_dt, const BulkViscosity& bv) {
  const materials::Moduli mod = materials::moduliOf(blk.law);
  const double c = std::sqrt((mod.bulk + 4.0 / 3.0 * mod.shear) / blk.rho0);
  BlockStatus st;
  element_dt.assign(blk.size(), 0.0);
  for (std::size_t e = 0; e < blk.size(); ++e) {
    double xc[4], yc[4];
    bool negative_radius = false;
    for (int a = 0; a < 4; ++a) {
      const std::size_t p = 3 * static_cast<std::size_t>(blk.conn[e][std::size_t(a)]);
      xc[a] = x0[p];
      yc[a] = x0[p + 1];
      negative_radius = negative_radius || (blk.axisymmetric() && xc[a] < 0.0);
    }
    const Solid2DIntegrals g = solid2DIntegrals(xc, yc, blk.axisymmetric());
    double area = 0.0, diag = 0.0;
    areaAndDiagonal(xc, yc, area, diag);
    blk.area0[e] = g.vol;
    blk.thick[e] = 1.0;
    if (!(g.vol > 0.0) || !(area > 0.0) || negative_radius) {
      if (st.bad_elem < 0) st.bad_elem = blk.elem[e];
      continue;
    }
    double* slot = slots + 3 * (blk.slot_offset + 8 * e);
    std::fill(slot, slot + 24, 0.0);
    for (int a = 0; a < 4; ++a) {
      slot[3 * a] = blk.rho0 * g.m[a];
      slot[3 * (4 + a)] = blk.rho0 * g.m[a] * area / 8.0;
    }
    const double dte = solidTimeStep(area / diag, c, 0.0, bv);
    element_dt[e] = dte;
    st.observeStep(dte, blk.elem[e]);
  }
  return st;
}

BlockStatus computeSolid2DForces(domain::ShellBlock& block, const domain::NodeVector& x,
                                 const domain::NodeVector& v, double dt, const BulkViscosity& bv,
                                 double* slots, std::size_t first, std::size_t last) {
  if (first % B != 0 || (last % B != 0 && last != block.size()) || last > block.size())
    throw std::logic_error("computeSolid2DForces: range not aligned to batches");
  return std::visit(
      [&](const auto& law) -> BlockStatus {
        using L = std::decay_t<decltype(law)>;
        // Laws with history variables are refused for 2D parts when the model is built
        // (model/build_mesh.cpp, finishParts): the shell block does not store them.
        // So are laws of the deformation gradient (model/build_planar.cpp).
        if constexpr (materials::SolidLaw<L> && materials::historyOf<L>() == 0 &&
                      !materials::needsDeformationGradient<L>()) {
          return solid2DBlockForces<L>(law, block, x, v, dt, bv, slots, first, last);
        } else {
          materials::noUpdateFor(materials::Family::Solid);
        }
      },
      block.law);
}

}  // namespace crumple::elements
