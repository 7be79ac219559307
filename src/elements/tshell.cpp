// The one-point thick shell (*SECTION_TSHELL ELFORM 1): see tshell.hpp for the formulation and
// docs/theory.md, "Thick shells", for the derivation and the tests.
//
// Notation: lanes l of a batch of kBatch elements (hex8_kernel.hpp), through-thickness points
// ip at (xi, eta, zeta) = (0, 0, zeta_ip) with weights w_ip summing to 1, the point's volume
// weight 8 w_ip det J (4 for the one-point rule over the square of the plane, 2 w_ip over the
// thickness). Primed quantities are in the element's lamina frame (e1, e2 in the mid-surface,
// e3 its normal).
#include "elements/tshell.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "elements/hex8_kernel.hpp"
#include "elements/shell.hpp"
#include "elements/shell_kernel.hpp"
#include "materials/plane_stress.hpp"

namespace crumple::elements {

namespace {

using detail::BatchScratch;
using detail::LaneArray;

static_assert(kBatch == kShellBatch, "the lamina frames reuse the shell kernel's lanes");
// In-plane points: 1 (ELFORM 1, the centre) or 4 (ELFORM 2, the 2 x 2 Gauss rule).
constexpr int kMaxPlanePoints = 4;
constexpr int kMaxElementPoints = kMaxPlanePoints * kMaxShellPoints;
constexpr int kMaxPoints = kMaxElementPoints * kBatch;

// Natural coordinates of the brick's nodes (N1-N4 bottom, zeta = -1; N5-N8 top).
constexpr double kXi[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
constexpr double kEta[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
constexpr double kZeta[8] = {-1, -1, -1, -1, 1, 1, 1, 1};

// The hourglass modes the points on the element's axis do not see: xi eta and xi eta zeta
// (modes 2 and 3 of hex8_kernel.hpp; eta zeta and zeta xi give strains at zeta != 0).
constexpr int kFirstHourglassMode = 2;

// dN_a / dxi_i of the trilinear brick at (xi, eta, zeta) (at xi = eta = 0 the factors
// 1 + xi xi_a and 1 + eta eta_a are exactly 1).
void naturalDerivatives(double xi, double eta, double zeta, double (&d)[8][3]) {
  for (int a = 0; a < 8; ++a) {
    const double fz = 0.125 * (1.0 + zeta * kZeta[a]);
    const double fx = 1.0 + xi * kXi[a], fy = 1.0 + eta * kEta[a];
    d[a][0] = kXi[a] * fy * fz;
    d[a][1] = kEta[a] * fx * fz;
    d[a][2] = 0.125 * kZeta[a] * (fx * fy);
  }
}

// The constants of one block for one call. Point ip = g nip + k of an element is in-plane
// point g (of `plane`) at thickness point k; weight[ip] = w_g w_k sums to 1.
struct TShellParams {
  double dt = 0, E = 0, G = 0, kappa = 1, c_plate = 0;
  int nip = 0, plane = 1, points = 0;
  std::size_t padded = 0;
  bool can_fail = false;
  double weight[kMaxElementPoints] = {};
  double thickness_weight[kMaxShellPoints] = {};  // w_k
  double d[kMaxElementPoints][8][3] = {};         // natural derivatives at each point
  // At (0, 0, zeta_k): the transverse shear's one in-plane point (selective reduced, ELFORM 2).
  double dc[kMaxShellPoints][8][3] = {};
  detail::SolidParams hg;  // the hourglass control's constants
};

// The lamina frame of each lane (the Belytschko-Tsay frame of the mid-surface quadrilateral,
// shell_kernel.hpp frameAt), with the mid-surface's area and longest side.
struct LaminaFrames {
  double e[3][3][kBatch];  // axis, component, lane
  LaneArray area, side;
};

// The state of a batch's points: in-plane stress, strain increments, back stress, thickness
// strain from the law, plastic strain; transverse shear stress and strain increments, the
// kinematic thickness strain increment, the points' volume weights at x(n-1/2); the
// thickness-stretch stress and the stress work of the step per element.
struct TShellPoints {
  double s[3][kMaxPoints], de[3][kMaxPoints], alpha[3][kMaxPoints], dzz[kMaxPoints];
  double ep[kMaxPoints];
  double tau[2][kMaxPoints], gam[2][kMaxPoints], dzz_kin[kMaxPoints], vol_mid[kMaxPoints];
  uint8_t failed[kMaxPoints];
  LaneArray szz[kMaxPlanePoints], work;  // the thickness-stretch stress at each in-plane point
};

void laminaFrames(const NodalBatch& x, LaminaFrames& fr) {
  shell_detail::NodalShell mid;
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 4; ++a)
      for (int l = 0; l < kBatch; ++l) mid[c][a][l] = 0.5 * (x[c][a][l] + x[c][a + 4][l]);
  for (int l = 0; l < kBatch; ++l) {
    const shell_detail::LaneFrame f = shell_detail::frameAt(mid, l);
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) fr.e[i][c][l] = f.e[i][c];
    fr.area[l] = f.area;
    fr.side[l] = shell_detail::longestSide(mid, l);
  }
}

// Components of nodal vectors on the lamina axes.
void toLamina(const LaminaFrames& fr, const NodalBatch& in, NodalBatch& out) {
  for (int i = 0; i < 3; ++i)
    for (int a = 0; a < 8; ++a)
      for (int l = 0; l < kBatch; ++l)
        out[i][a][l] =
            fr.e[i][0][l] * in[0][a][l] + fr.e[i][1][l] * in[1][a][l] + fr.e[i][2][l] * in[2][a][l];
}

// The smaller of the thickness V / A and the in-plane length A / (longest side).
void lengthsOf(const LaminaFrames& fr, const LaneArray& vol, double (&length)[kBatch]) {
  for (int l = 0; l < kBatch; ++l)
    length[l] = std::min(vol[l] / fr.area[l], fr.area[l] / fr.side[l]);
}

template <class Law>
TShellParams paramsOf(const Law& law, const domain::SolidBlock& blk, double dt) {
  TShellParams p;
  const materials::Moduli m = law.moduli;
  const double nu = materials::poissonRatio(m);
  p.dt = dt;
  p.E = materials::youngModulus(m);
  p.G = m.shear;
  p.kappa = blk.shear_factor;
  p.c_plate = std::sqrt(p.E / (blk.rho0 * (1.0 - nu * nu)));
  p.plane = blk.plane_points;
  p.nip = blk.points / p.plane;
  p.points = blk.points;
  p.padded = blk.paddedSize();
  p.can_fail = law.failureStrain() > 0.0;
  if (blk.zeta.size() != std::size_t(p.nip) || p.nip < 1 || p.nip > kMaxShellPoints ||
      (p.plane != 1 && p.plane != 4) || p.nip * p.plane != blk.points)
    throw std::logic_error(
        "computeThickShellForces: no through-thickness rule (setThickShellRule)");
  // The 2 x 2 Gauss points of the plane (ELFORM 2), each a quarter of it; else the centre.
  const double g = 1.0 / std::sqrt(3.0);
  const double gxi[4] = {-g, g, g, -g}, geta[4] = {-g, -g, g, g};
  const double wg = p.plane == 1 ? 1.0 : 0.25;
  for (int k = 0; k < p.nip; ++k) {
    const double zeta = blk.zeta[std::size_t(k)];
    p.thickness_weight[k] = blk.weight[std::size_t(k)];
    naturalDerivatives(0.0, 0.0, zeta, p.dc[k]);
    for (int ig = 0; ig < p.plane; ++ig) {
      const int ip = ig * p.nip + k;
      p.weight[ip] = wg * blk.weight[std::size_t(k)];
      naturalDerivatives(p.plane == 1 ? 0.0 : gxi[ig], p.plane == 1 ? 0.0 : geta[ig], zeta,
                         p.d[ip]);
    }
  }
  p.hg.dt = dt;
  p.hg.lam2mu = m.bulk + 4.0 / 3.0 * m.shear;
  p.hg.qm = blk.hourglass.qm;
  p.hg.stiffness_hg = blk.hourglass.ihq >= 4;
  p.hg.projected_hg = blk.hourglass.ihq >= 2;
  return p;
}

// The velocity gradient L_jk = sum_a v_j,a dN_a / dx_k of lane l.
void velocityGradient(const NodalBatch& vl, const NodalBatch& grad, int l, double (&L)[3][3]) {
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) {
      double s = 0.0;
      for (int a = 0; a < 8; ++a) s += vl[j][a][l] * grad[k][a][l];
      L[j][k] = s;
    }
}

// The strain increments of every point at the mid-step geometry x(n-1/2) = x(n) - dt/2 v, in
// the lamina frame of that geometry: in-plane (tensor shear) and the kinematic thickness strain
// at the point, the transverse shear (engineering) at the plane's centre (0, 0, zeta_k), the
// same for every in-plane point of thickness point k (selective reduced integration: with
// ELFORM 2's 2 x 2 points the transverse shear would lock in bending); the volume weights.
void midStepStrains(const TShellParams& p, BatchScratch& w, TShellPoints& q) {
  const double dt = p.dt;
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 8; ++a)
      for (int l = 0; l < kBatch; ++l) w.xm[c][a][l] = w.x[c][a][l] - 0.5 * dt * w.v[c][a][l];
  LaminaFrames fr;
  laminaFrames(w.xm, fr);
  NodalBatch xl, vl, grad;
  toLamina(fr, w.xm, xl);
  toLamina(fr, w.v, vl);
  LaneArray det;
  for (int k = 0; k < p.nip; ++k) {
    LaneArray gam_yz, gam_zx;
    if (p.plane > 1) {
      detail::isoparametricGradients<8>(p.dc[k], 1.0, xl, grad, det);
      for (int l = 0; l < kBatch; ++l) {
        double L[3][3];
        velocityGradient(vl, grad, l, L);
        gam_yz[l] = (L[1][2] + L[2][1]) * dt;
        gam_zx[l] = (L[2][0] + L[0][2]) * dt;
      }
    }
    for (int ig = 0; ig < p.plane; ++ig) {
      const int ip = ig * p.nip + k;
      detail::isoparametricGradients<8>(p.d[ip], 8.0 * p.weight[ip], xl, grad, det);
      for (int l = 0; l < kBatch; ++l) {
        double L[3][3];
        velocityGradient(vl, grad, l, L);
        const int i = ip * kBatch + l;
        q.de[0][i] = L[0][0] * dt;
        q.de[1][i] = L[1][1] * dt;
        q.de[2][i] = 0.5 * (L[0][1] + L[1][0]) * dt;
        q.gam[0][i] = p.plane > 1 ? gam_yz[l] : (L[1][2] + L[2][1]) * dt;
        q.gam[1][i] = p.plane > 1 ? gam_zx[l] : (L[2][0] + L[0][2]) * dt;
        q.dzz_kin[i] = L[2][2] * dt;
        q.vol_mid[i] = det[l];
      }
    }
  }
}

// Stress work density of point i times its volume weight (the midpoint rule takes half of it
// with the old stresses and half with the new).
double pointWork(const TShellPoints& q, int i, double szz) {
  return q.vol_mid[i] *
         (q.s[0][i] * q.de[0][i] + q.s[1][i] * q.de[1][i] + 2.0 * q.s[2][i] * q.de[2][i] +
          q.tau[0][i] * q.gam[0][i] + q.tau[1][i] * q.gam[1][i] + szz * q.dzz_kin[i]);
}

// The batch's point state from the block (point ip of element e at ip * padded + e).
template <class Law>
void loadPoints(const TShellParams& p, const domain::SolidBlock& blk, std::size_t first,
                TShellPoints& q) {
  for (int ip = 0; ip < p.points; ++ip)
    for (int l = 0; l < kBatch; ++l) {
      const std::size_t idx = std::size_t(ip) * p.padded + first + std::size_t(l);
      const int i = ip * kBatch + l;
      for (int k = 0; k < 3; ++k) q.s[k][i] = blk.sig_ip[std::size_t(k)][idx];
      q.tau[0][i] = blk.sig_ip[3][idx];
      q.tau[1][i] = blk.sig_ip[4][idx];
      if constexpr (Law::kPlastic)
        q.ep[i] = blk.eps_p_ip[idx];
      else
        q.ep[i] = 0.0;
      if constexpr (materials::shellAlphaOf<Law>())
        for (int k = 0; k < 3; ++k) q.alpha[k][i] = blk.alpha_ip[std::size_t(k)][idx];
    }
  for (int ig = 0; ig < p.plane; ++ig)
    for (int l = 0; l < kBatch; ++l)
      q.szz[ig][l] = blk.sig_ip[5][std::size_t(ig * p.nip) * p.padded + first + std::size_t(l)];
}

// The plane-stress law at every point; a failed point carries no stress. w.failed: every
// point of the element has failed (the element is deleted at the end of the pass).
template <class Law>
void lawUpdate(const Law& law, const TShellParams& p, TShellPoints& q, BatchScratch& w) {
  shell_detail::planeStressUpdate(law, p.points * kBatch, p.dt, p.can_fail, q);
  for (int l = 0; l < kBatch; ++l) w.failed[l] = p.can_fail ? 1 : 0;
  for (int ip = 0; ip < p.points; ++ip)
    for (int l = 0; l < kBatch; ++l) {
      const int i = ip * kBatch + l;
      const bool f = q.failed[i] != 0;
      for (int k = 0; k < 3; ++k) q.s[k][i] = f ? 0.0 : q.s[k][i];
      w.failed[l] = w.failed[l] && f ? 1 : 0;
    }
}

// The stress work of every point (pointWork), summed per element with factor `half`.
void addWork(const TShellParams& p, const TShellPoints& q, double half, LaneArray& work) {
  for (int ip = 0; ip < p.points; ++ip)
    for (int l = 0; l < kBatch; ++l)
      work[l] += half * pointWork(q, ip * kBatch + l, q.szz[ip / p.nip][l]);
}

// One step of every point: the old half of the work, the law, the transverse shear (elastic,
// kappa G), the thickness-stretch stress of each in-plane point (E times the kinematic
// thickness strain less the one the law asks for, both through-thickness means at that
// in-plane point) and the new half of the work.
template <class Law>
void updatePoints(const Law& law, const TShellParams& p, TShellPoints& q, BatchScratch& w) {
  for (int l = 0; l < kBatch; ++l) q.work[l] = 0.0;
  addWork(p, q, 0.5, q.work);
  lawUpdate(law, p, q, w);
  const double kg = p.kappa * p.G;
  LaneArray stretch;
  for (int ig = 0; ig < p.plane; ++ig) {
    for (int l = 0; l < kBatch; ++l) stretch[l] = 0.0;
    for (int k = 0; k < p.nip; ++k)
      for (int l = 0; l < kBatch; ++l) {
        const int i = (ig * p.nip + k) * kBatch + l;
        const double keep = q.failed[i] ? 0.0 : 1.0;
        q.tau[0][i] = keep * (q.tau[0][i] + kg * q.gam[0][i]);
        q.tau[1][i] = keep * (q.tau[1][i] + kg * q.gam[1][i]);
        stretch[l] += p.thickness_weight[k] * (q.dzz_kin[i] - q.dzz[i]);
      }
    for (int l = 0; l < kBatch; ++l)
      q.szz[ig][l] = w.failed[l] ? 0.0 : q.szz[ig][l] + p.E * stretch[l];
  }
  addWork(p, q, 0.5, q.work);
}

// Corner forces at x(n): f_a = -sum_ip (8 w_ip det J) sigma' . grad N_a in the lamina frame of
// x(n), turned to the global frame into w.f; vol the sum of the points' volume weights.
// ELFORM 2: the transverse shear's part, at the plane's centre with the one-point rule
// (8 w_k det J there) and the mean over the in-plane points of their shear stress (the same
// unless a point has failed); the in-plane and thickness-stretch parts at the 2 x 2 points.
void selectiveForces(const TShellParams& p, const NodalBatch& xl, const TShellPoints& q,
                     NodalBatch& fl, LaneArray& vol) {
  NodalBatch grad;
  LaneArray det;
  const double share = 1.0 / p.plane;
  for (int k = 0; k < p.nip; ++k) {
    detail::isoparametricGradients<8>(p.dc[k], 8.0 * p.thickness_weight[k], xl, grad, det);
    for (int l = 0; l < kBatch; ++l) {
      double tyz = 0.0, tzx = 0.0;
      for (int ig = 0; ig < p.plane; ++ig) {
        const int i = (ig * p.nip + k) * kBatch + l;
        tyz += share * q.tau[0][i];
        tzx += share * q.tau[1][i];
      }
      tyz *= det[l];
      tzx *= det[l];
      for (int a = 0; a < 8; ++a) {
        fl[0][a][l] -= tzx * grad[2][a][l];
        fl[1][a][l] -= tyz * grad[2][a][l];
        fl[2][a][l] -= tzx * grad[0][a][l] + tyz * grad[1][a][l];
      }
    }
  }
  for (int ip = 0; ip < p.points; ++ip) {
    detail::isoparametricGradients<8>(p.d[ip], 8.0 * p.weight[ip], xl, grad, det);
    for (int l = 0; l < kBatch; ++l) {
      const int i = ip * kBatch + l;
      const double s0 = det[l] * q.s[0][i], s1 = det[l] * q.s[1][i], s2 = det[l] * q.s[2][i];
      const double szz = det[l] * q.szz[ip / p.nip][l];
      for (int a = 0; a < 8; ++a) {
        const double gx = grad[0][a][l], gy = grad[1][a][l], gz = grad[2][a][l];
        fl[0][a][l] -= s0 * gx + s2 * gy;
        fl[1][a][l] -= s2 * gx + s1 * gy;
        fl[2][a][l] -= szz * gz;
      }
      vol[l] += det[l];
    }
  }
}

void internalForces(const TShellParams& p, BatchScratch& w, const TShellPoints& q, LaminaFrames& fr,
                    LaneArray& vol) {
  laminaFrames(w.x, fr);
  NodalBatch xl, grad, fl = {};
  toLamina(fr, w.x, xl);
  LaneArray det;
  for (int l = 0; l < kBatch; ++l) vol[l] = 0.0;
  if (p.plane > 1) selectiveForces(p, xl, q, fl, vol);
  for (int ip = 0; ip < (p.plane > 1 ? 0 : p.nip); ++ip) {
    detail::isoparametricGradients<8>(p.d[ip], 8.0 * p.weight[ip], xl, grad, det);
    for (int l = 0; l < kBatch; ++l) {
      const int i = ip * kBatch + l;
      const double s0 = det[l] * q.s[0][i], s1 = det[l] * q.s[1][i], s2 = det[l] * q.s[2][i];
      const double tyz = det[l] * q.tau[0][i], tzx = det[l] * q.tau[1][i];
      const double szz = det[l] * q.szz[0][l];
      for (int a = 0; a < 8; ++a) {
        const double gx = grad[0][a][l], gy = grad[1][a][l], gz = grad[2][a][l];
        fl[0][a][l] -= s0 * gx + s2 * gy + tzx * gz;
        fl[1][a][l] -= s2 * gx + s1 * gy + tyz * gz;
        fl[2][a][l] -= tzx * gx + tyz * gy + szz * gz;
      }
      vol[l] += det[l];
    }
  }
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 8; ++a)
      for (int l = 0; l < kBatch; ++l)
        w.f[c][a][l] =
            fr.e[0][c][l] * fl[0][a][l] + fr.e[1][c][l] * fl[1][a][l] + fr.e[2][c][l] * fl[2][a][l];
}

// The spin increments of the uniform velocity gradient at x(n-1/2), for the stiffness forms'
// stored resistances (hex8_kernel.hpp hourglassForces).
void midStepSpin(const TShellParams& p, BatchScratch& w, detail::SolidSpin& sp) {
  volumeGradient(w.xm, w.b);
  LaneArray vm;
  detail::volumeOf(w.xm, w.b, vm);
  for (int l = 0; l < kBatch; ++l) {
    double L[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double s = 0.0;
        for (int a = 0; a < 8; ++a) s += w.v[i][a][l] * w.b[j][a][l];
        L[i][j] = s / vm[l];
      }
    sp.spin_xy[l] = 0.5 * (L[0][1] - L[1][0]) * p.dt;
    sp.spin_yz[l] = 0.5 * (L[1][2] - L[2][1]) * p.dt;
    sp.spin_zx[l] = 0.5 * (L[2][0] - L[0][2]) * p.dt;
    sp.trace_d[l] = L[0][0] + L[1][1] + L[2][2];
  }
}

// Flanagan-Belytschko control of the modes xi eta and xi eta zeta, as the hexahedron's
// (QM > 0): forces into w.f, work into de_hg.
void hourglassControl(const TShellParams& p, domain::SolidBlock& blk, std::size_t first,
                      BatchScratch& w, LaneArray& de_hg) {
  for (int l = 0; l < kBatch; ++l) de_hg[l] = 0.0;
  // ELFORM 2's 2 x 2 points see every mode: no hourglass control.
  if (!(p.hg.qm > 0.0) || p.plane > 1) return;
  detail::SolidSpin sp;
  midStepSpin(p, w, sp);
  volumeGradient(w.x, w.b);
  detail::SolidGeometry g;
  detail::volumeOf(w.x, w.b, g.vol);
  for (int l = 0; l < kBatch; ++l) {
    const double v_safe = g.vol[l] > 0.0 ? g.vol[l] : 1.0;
    g.rho[l] = blk.rho0 * blk.vol0[first + std::size_t(l)] / v_safe;
    g.c[l] = std::sqrt(p.hg.lam2mu / g.rho[l]);
    g.cbrt_vol[l] = p.hg.stiffness_hg ? 0.0 : std::cbrt(v_safe);
  }
  detail::hourglassForces(p.hg, blk, first, w, sp, g, de_hg, kFirstHourglassMode);
}

// The through-thickness means for output: the stress turned to the global frame (Voigt xx,
// yy, zz, xy, yz, zx) and the effective plastic strain.
void storeMeans(const TShellParams& p, domain::SolidBlock& blk, std::size_t e, int l,
                const LaminaFrames& fr, const TShellPoints& q) {
  double m[3][3] = {};
  double ep = 0.0;
  for (int ip = 0; ip < p.points; ++ip) {
    const int i = ip * kBatch + l;
    const double wt = p.weight[ip];
    m[0][0] += wt * q.s[0][i];
    m[1][1] += wt * q.s[1][i];
    m[0][1] += wt * q.s[2][i];
    m[1][2] += wt * q.tau[0][i];
    m[0][2] += wt * q.tau[1][i];
    ep += wt * q.ep[i];
  }
  m[2][2] = q.szz[0][l];
  for (int ig = 1; ig < p.plane; ++ig) m[2][2] += q.szz[ig][l];
  m[2][2] /= p.plane;
  m[1][0] = m[0][1];
  m[2][1] = m[1][2];
  m[2][0] = m[0][2];
  constexpr int kVoigt[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  for (int k = 0; k < 6; ++k) {
    const int c = kVoigt[k][0], d = kVoigt[k][1];
    double s = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s += fr.e[i][c][l] * m[i][j] * fr.e[j][d][l];
    blk.sigAt(k, e) = s;
  }
  if (!blk.eps_p.empty()) blk.eps_p[e] = ep;
}

// The batch's point state back to the block, for the elements still active.
template <class Law>
void storePoints(const TShellParams& p, domain::SolidBlock& blk, std::size_t first,
                 const TShellPoints& q) {
  for (int ip = 0; ip < p.points; ++ip)
    for (int l = 0; l < kBatch; ++l) {
      const std::size_t e = first + std::size_t(l), idx = std::size_t(ip) * p.padded + e;
      if (!blk.active[e]) continue;
      const int i = ip * kBatch + l;
      for (int k = 0; k < 3; ++k) blk.sig_ip[std::size_t(k)][idx] = q.s[k][i];
      blk.sig_ip[3][idx] = q.tau[0][i];
      blk.sig_ip[4][idx] = q.tau[1][i];
      blk.sig_ip[5][idx] = q.szz[ip / p.nip][l];
      if constexpr (Law::kPlastic) blk.eps_p_ip[idx] = q.ep[i];
      if constexpr (materials::shellAlphaOf<Law>())
        for (int k = 0; k < 3; ++k) blk.alpha_ip[std::size_t(k)][idx] = q.alpha[k][i];
    }
}

// Energies, volumes and output means of the batch, then per element its slots, erosion and
// stable step (hex8_kernel.hpp finishElement, with no bulk viscosity: dt = L / c).
void finishBatch(const TShellParams& p, domain::SolidBlock& blk, std::size_t first, int n,
                 const BatchScratch& w, const TShellPoints& q, const LaminaFrames& fr,
                 const LaneArray& vol, const LaneArray& de_hg, double* slots, BlockStatus& st) {
  LaneArray len;
  lengthsOf(fr, vol, len);
  for (int l = 0; l < n; ++l) {
    const std::size_t e = first + static_cast<std::size_t>(l);
    double* slot = slots + 3 * (blk.slot_offset + 8 * e);
    if (!blk.active[e]) {
      std::fill(slot, slot + 24, 0.0);
      continue;
    }
    blk.vol[e] = vol[l];
    blk.e_int[e] += q.work[l];
    blk.e_hg[e] += de_hg[l];
    storeMeans(p, blk, e, l, fr, q);
    const double c_dt =
        blk.mass_scale.empty() ? p.c_plate : p.c_plate / std::sqrt(blk.mass_scale[e]);
    detail::finishElement(blk, e, l, w.f, vol[l], w.failed[l] != 0, len[l], c_dt, 0.0,
                          BulkViscosity{0.0, 0.0}, slot, st);
  }
}

template <class Law>
BlockStatus thickShellBlockForces(const Law& law, domain::SolidBlock& blk,
                                  const domain::NodeVector& x, const domain::NodeVector& v,
                                  double dt, double* slots, std::size_t range_first,
                                  std::size_t range_last) {
  const TShellParams p = paramsOf(law, blk, dt);
  const std::size_t batch0 = range_first / kBatch;
  const std::size_t nbatch =
      range_last > range_first ? (range_last - range_first + kBatch - 1) / kBatch : 0;
  std::vector<BlockStatus> status(nbatch);
#pragma omp parallel
  {
    BatchScratch w;
    std::vector<TShellPoints> scratch(1);
    TShellPoints& q = scratch[0];
#pragma omp for schedule(static)
    for (std::size_t ib = 0; ib < nbatch; ++ib) {
      const std::size_t first = (batch0 + ib) * kBatch;
      const int n = static_cast<int>(std::min<std::size_t>(kBatch, range_last - first));
      detail::gatherNodal(blk, first, n, x, w.x);
      detail::gatherNodal(blk, first, n, v, w.v);
      midStepStrains(p, w, q);
      loadPoints<Law>(p, blk, first, q);
      updatePoints(law, p, q, w);
      LaminaFrames fr;
      LaneArray vol, de_hg;
      internalForces(p, w, q, fr, vol);
      hourglassControl(p, blk, first, w, de_hg);
      storePoints<Law>(p, blk, first, q);
      finishBatch(p, blk, first, n, w, q, fr, vol, de_hg, slots, status[ib]);
    }
  }
  return detail::mergeStatus(status);
}

}  // namespace

BlockStatus computeThickShellForces(domain::SolidBlock& block, const domain::NodeVector& x,
                                    const domain::NodeVector& v, double dt, double* slots,
                                    std::size_t first, std::size_t last) {
  if (first % kBatch != 0 || (last % kBatch != 0 && last != block.size()) || last > block.size())
    throw std::logic_error("computeThickShellForces: range not aligned to batches");
  return std::visit(
      [&](const auto& law) -> BlockStatus {
        using Law = std::decay_t<decltype(law)>;
        if constexpr (!materials::ShellLaw<Law>)
          materials::noUpdateFor(materials::Family::Shell);
        else
          return thickShellBlockForces(law, block, x, v, dt, slots, first, last);
      },
      block.law);
}

void setThickShellRule(domain::SolidBlock& block) {
  if (block.zeta.empty())
    throughThicknessRule(block.points / block.plane_points, block.lobatto, block.zeta,
                         block.weight);
}

void thickShellLengths(const NodalBatch& x, double (&length)[kBatch]) {
  LaminaFrames fr;
  laminaFrames(x, fr);
  NodalBatch b;
  volumeGradient(x, b);
  LaneArray vol;
  detail::volumeOf(x, b, vol);
  lengthsOf(fr, vol, length);
}

void thickShellLayerStress(const domain::SolidBlock& block, const domain::NodeVector& x,
                           std::size_t e, double (&layers)[3][6], double (&eps)[3]) {
  NodalBatch xb;
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 8; ++a)
      for (int l = 0; l < kBatch; ++l)
        xb[c][a][l] = x[3 * std::size_t(block.conn[e][std::size_t(a)]) + std::size_t(c)];
  LaminaFrames fr;
  laminaFrames(xb, fr);
  const int plane = block.plane_points, nip = block.points / plane;
  const std::size_t padded = block.paddedSize();
  const auto lowest = std::min_element(block.zeta.begin(), block.zeta.end());
  const auto highest = std::max_element(block.zeta.begin(), block.zeta.end());
  const int level[2] = {int(lowest - block.zeta.begin()), int(highest - block.zeta.begin())};
  constexpr int kVoigt[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  for (int side = 0; side < 2; ++side) {
    double m[3][3] = {}, ep = 0.0;
    for (int g = 0; g < plane; ++g) {
      const std::size_t idx = std::size_t(g * nip + level[side]) * padded + e;
      const double w = 1.0 / plane;
      m[0][0] += w * block.sig_ip[0][idx];
      m[1][1] += w * block.sig_ip[1][idx];
      m[0][1] += w * block.sig_ip[2][idx];
      m[1][2] += w * block.sig_ip[3][idx];
      m[0][2] += w * block.sig_ip[4][idx];
      m[2][2] += w * block.sig_ip[5][idx];
      ep += block.eps_p_ip.empty() ? 0.0 : w * block.eps_p_ip[idx];
    }
    m[1][0] = m[0][1];
    m[2][1] = m[1][2];
    m[2][0] = m[0][2];
    const int out = side == 0 ? 0 : 2;
    for (int k = 0; k < 6; ++k) {
      const int c = kVoigt[k][0], d = kVoigt[k][1];
      double s = 0.0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) s += fr.e[i][c][0] * m[i][j] * fr.e[j][d][0];
      layers[out][k] = s;
    }
    eps[out] = ep;
  }
  for (int k = 0; k < 6; ++k) layers[1][k] = block.sigAt(k, e);
  eps[1] = block.eps_p.empty() ? 0.0 : block.eps_p[e];
}

double thickShellWaveSpeed(const domain::SolidBlock& block) {
  const materials::Moduli m = materials::moduliOf(block.law);
  const double nu = materials::poissonRatio(m);
  return std::sqrt(materials::youngModulus(m) / (block.rho0 * (1.0 - nu * nu)));
}

}  // namespace crumple::elements
