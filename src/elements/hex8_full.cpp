// The fully integrated hexahedron (*SECTION_SOLID ELFORM 2): 2 x 2 x 2 Gauss points, each
// with its own stress and material history, and the volumetric strain rate taken from the
// element mean (selective-reduced integration in its B-bar form: Hughes, "Generalization of
// selective integration procedures to anisotropic and nonlinear media", IJNME 15 (1980)
// 1413-1418). The mean is the exact volume-averaged dilatation of Flanagan & Belytschko, so
// the element does not lock in near-incompressible plastic flow; it needs no hourglass control.
// The same kernel runs the two-point pentahedron (ELFORM 15) with its own rule (PrismRule).
#include <cmath>
#include <memory>

#include "elements/hex8.hpp"
#include "elements/hex8_kernel.hpp"

namespace crumple::elements {

namespace {

using detail::BatchScratch;
using detail::LaneArray;

// 1/sqrt(3) to double precision (std::sqrt is not constexpr here).
constexpr double kGauss = 0.57735026918962576451;

// The corners' natural coordinates (xi, eta, zeta); Gauss point q sits at kCorner[q] / sqrt(3).
constexpr int kCorner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                               {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

// Derivatives of the trilinear shape functions at the Gauss points: kShape[q][a][i] =
// dN_a / dxi_i at xi = kCorner[q] / sqrt(3).
struct HexDerivatives {
  double d[8][8][3];
  constexpr HexDerivatives() : d{} {
    constexpr const auto& n = kCorner;
    constexpr double g = kGauss;
    for (int q = 0; q < 8; ++q)
      for (int a = 0; a < 8; ++a) {
        const double xi = n[q][0] * g, eta = n[q][1] * g, zeta = n[q][2] * g;
        d[q][a][0] = n[a][0] * (1 + n[a][1] * eta) * (1 + n[a][2] * zeta) / 8;
        d[q][a][1] = (1 + n[a][0] * xi) * n[a][1] * (1 + n[a][2] * zeta) / 8;
        d[q][a][2] = (1 + n[a][0] * xi) * (1 + n[a][1] * eta) * n[a][2] / 8;
      }
  }
};

// The 6-node pentahedron (ELFORM 15) in the canonical slots N1 N2 N3 N4 N5 N5 N6 N6
// (model/solid_shape.hpp): triangle (N1 N5 N2) at t = -1, (N4 N6 N3) at t = +1, with
// N_a = L_i(r, s) (1 -+ t) / 2, L = (1 - r - s, r, s). Two points on the axis through the
// triangles' centroids, r = s = 1/3, t = -+1/sqrt(3), each of weight 1/2 (the triangle's area
// in r, s times the Gauss weight 1): the "2 point pentahedron" of the Keyword Manual
// (*SECTION_SOLID ELFORM 15). The repeated slots 5 and 7 get no derivative.
struct PrismDerivatives {
  double d[2][8][3];
  constexpr PrismDerivatives() : d{} {
    // Slot of prism node (bottom b0 b1 b2, top t0 t1 t2), and the node's dL/dr, dL/ds.
    constexpr int slot[6] = {0, 4, 1, 3, 6, 2};
    constexpr double dl[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
    for (int q = 0; q < 2; ++q) {
      const double t = q == 0 ? -kGauss : kGauss;
      for (int k = 0; k < 6; ++k) {
        const int i = k % 3;
        const double side = k < 3 ? -1.0 : 1.0;
        const double ft = (1 + side * t) / 2;
        d[q][slot[k]][0] = dl[i][0] * ft;
        d[q][slot[k]][1] = dl[i][1] * ft;
        d[q][slot[k]][2] = side / 3.0 / 2.0;  // L_i = 1/3 at the centroid
      }
    }
  }
};

// An integration rule of the multi-point kernel: its points, their weight in the natural
// coordinates, and the shape-function derivatives there.
// kShearFix: the transverse shear correction of ELFORM -1 and -2 (shearCorrection below).
struct HexRule {
  static constexpr int kPoints = 8;
  static constexpr double kWeight = 1.0;
  static constexpr HexDerivatives kShape{};
  static constexpr bool kShearFix = false;
};
struct HexShearRule : HexRule {
  static constexpr bool kShearFix = true;
};
struct PrismRule {
  static constexpr int kPoints = 2;
  static constexpr double kWeight = 0.5;
  static constexpr PrismDerivatives kShape{};
  static constexpr bool kShearFix = false;
};

// Gradients dN_a/dx_j of the 8 slots' shape functions at point q on geometry x, and the
// point's volume weight det(J) times the rule's weight.
template <class Rule>
void gradientsAt(int q, const NodalBatch& x, NodalBatch& grad, LaneArray& det) {
  detail::isoparametricGradients<8>(Rule::kShape.d[q], Rule::kWeight, x, grad, det);
}

// ---- ELFORM -1, -2: the transverse shear correction ------------------------------------------
// In natural coordinates the velocity derivative along xi_j carries, from each hourglass pattern
// h_ij = xi_i xi_j (i != j, corner values kCorner[a][i] kCorner[a][j]), the term
// q_ij xi_i / 8, q_ij = sum_a v_a h_ij,a. Its component along g_i (the natural direction i)
// is the bending mode "v_i = xi_i xi_j": its strain along i, xi_j times it, is the bending strain
// the element needs; its derivative along xi_j, xi_i times it, is a transverse shear that a
// bent beam does not have, and at the Gauss points (xi_i = +-1/sqrt 3) it stiffens bending by
// a factor of order (aspect ratio)^2 (shear locking). Here that term is taken out of every
// dv/dxi_j before the strain rate:
//   dv/dxi_j' = dv/dxi_j - sum_{i != j} g_i (r_i . q~_ij) xi_i,
// with g_i = dx/dxi_i and r_i = d xi_i / dx of the centre (the element's affine part), and
// q~_ij = sum_a v_a gamma_ij,a on the Flanagan-Belytschko vectors gamma = (h - (h . x_c) b_c /
// V) / 8 (Flanagan & Belytschko, IJNME 17 (1981) 679-706), which vanish on every linear
// velocity field: the uniform strain of the patch test is untouched and exact. The
// other hourglass terms (twist v_i = xi_j xi_k, and xi eta zeta) keep their strains, so no
// mode loses all its stiffness. For a rectangular brick this is the removal of the
// "parasitic shear" of the bilinear element, which makes its pure bending exact (the result
// of Wilson's incompatible modes on a rectangle: Cook, Malkus, Plesha & Witt, "Concepts and
// Applications of FEA", 4th ed., 6.13). The internal forces are the transpose of the corrected
// rate (work conjugate). As in Taylor's correction of incompatible modes (Taylor, Beresford &
// Wilson, IJNME 10 (1976) 1211-1219), the correction at point q is taken on the centre's map,
// g_i (x) r_j scaled by det J_0 / det J_q, so that it integrates to zero over any element:
// a uniform stress then gives no correction forces, and the patch test holds on distorted
// meshes in forces as well as in strains. It is the idea of LS-DYNA's -1 and -2 (Keyword Manual
// *SECTION_SOLID; T. Borrvall, "A heuristic attempt to reduce transverse shear locking in
// fully integrated hexahedra with poor aspect ratio", 7th European LS-DYNA Conference, 2009:
// Jacobian terms of the spurious shear modes cancelled); LS-DYNA's exact expressions are not
// public, so answers may differ from LS-DYNA's by a few per cent on coarse meshes.
constexpr int kPair[3][2] = {{0, 1}, {1, 2}, {2, 0}};

// The correction's geometry on one configuration: the pairs' gamma vectors, g_i, r_i.
struct ShearGeometry {
  double gam[3][8][kBatch];
  double g[3][3][kBatch];  // g[i][c] = dx_c / dxi_i at the centre
  double r[3][3][kBatch];  // r[i][c] = (G^-1)[i][c] = d xi_i / dx_c, G[c][i] = g[i][c]
  double det0[kBatch];     // det G
};

// The inverse of m (cofactors over the determinant; zero for a singular m); returns det m.
inline double invert3(const double (&m)[3][3], double (&out)[3][3]) {
  const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  const double r = det != 0.0 ? 1.0 / det : 0.0;
  out[0][0] = c00 * r;
  out[1][0] = c01 * r;
  out[2][0] = c02 * r;
  out[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * r;
  out[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * r;
  out[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * r;
  out[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * r;
  out[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * r;
  out[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * r;
  return det;
}

// On geometry x with volume gradient b and volume vol.
inline void shearGeometry(const NodalBatch& x, const NodalBatch& b, const LaneArray& vol,
                          ShearGeometry& sg) {
  for (int l = 0; l < kBatch; ++l) {
    double G[3][3], Gi[3][3];
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) {
        double s = 0.0;
        for (int a = 0; a < 8; ++a) s += kCorner[a][i] * x[c][a][l];
        sg.g[i][c][l] = G[c][i] = s / 8.0;
      }
    sg.det0[l] = invert3(G, Gi);
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) sg.r[i][c][l] = Gi[i][c];
    const double rv = vol[l] != 0.0 ? 1.0 / vol[l] : 0.0;
    for (int p = 0; p < 3; ++p) {
      const int i = kPair[p][0], j = kPair[p][1];
      double hx[3] = {0.0, 0.0, 0.0};
      for (int c = 0; c < 3; ++c)
        for (int a = 0; a < 8; ++a) hx[c] += kCorner[a][i] * kCorner[a][j] * x[c][a][l];
      for (int a = 0; a < 8; ++a)
        sg.gam[p][a][l] = (kCorner[a][i] * kCorner[a][j] -
                           rv * (hx[0] * b[0][a][l] + hx[1] * b[1][a][l] + hx[2] * b[2][a][l])) /
                          8.0;
    }
  }
}

// amp[p][k] = r_i . q~_ij for pair p, i = kPair[p][k]: the bending modes' amplitudes.
using ShearAmplitudes = double[3][2][kBatch];
inline void shearAmplitudes(const ShearGeometry& sg, const NodalBatch& v, ShearAmplitudes& amp) {
  for (int p = 0; p < 3; ++p)
    for (int k = 0; k < 2; ++k) {
      const int i = kPair[p][k];
      for (int l = 0; l < kBatch; ++l) {
        double s = 0.0;
        for (int a = 0; a < 8; ++a)
          s += (sg.r[i][0][l] * v[0][a][l] + sg.r[i][1][l] * v[1][a][l] +
                sg.r[i][2][l] * v[2][a][l]) *
               sg.gam[p][a][l];
        amp[p][k][l] = s;
      }
    }
}

// L += -(det J_0 / det J_q) sum xi_i amp_ij g_i (x) r_j at point q (weight det_q), lane l.
inline void addShearRate(const ShearGeometry& sg, const ShearAmplitudes& amp, int q, double det_q,
                         int l, double (&L)[3][3]) {
  const double scale = det_q != 0.0 ? sg.det0[l] / det_q : 0.0;
  for (int p = 0; p < 3; ++p)
    for (int k = 0; k < 2; ++k) {
      const int i = kPair[p][k], j = kPair[p][1 - k];
      const double c = -kCorner[q][i] * kGauss * amp[p][k][l] * scale;
      for (int m = 0; m < 3; ++m)
        for (int n = 0; n < 3; ++n) L[m][n] += c * sg.g[i][m][l] * sg.r[j][n][l];
    }
}

// The work conjugates of the amplitudes, summed over the points: coef[p][k] += det J_0 xi_i
// (g_i . S r_j), S the point's deviatoric stress (sym[6]: xx yy zz xy yz zx).
inline void addShearWork(const ShearGeometry& sg, int q, int l, const double (&S)[6],
                         ShearAmplitudes& coef) {
  const double M[3][3] = {{S[0], S[3], S[5]}, {S[3], S[1], S[4]}, {S[5], S[4], S[2]}};
  for (int p = 0; p < 3; ++p)
    for (int k = 0; k < 2; ++k) {
      const int i = kPair[p][k], j = kPair[p][1 - k];
      double s = 0.0;
      for (int m = 0; m < 3; ++m)
        for (int n = 0; n < 3; ++n) s += sg.g[i][m][l] * M[m][n] * sg.r[j][n][l];
      coef[p][k][l] += sg.det0[l] * kCorner[q][i] * kGauss * s;
    }
}

// f_a += sum coef_ij gamma_ij,a r_i: the transpose of the rate correction.
inline void addShearForces(const ShearGeometry& sg, const ShearAmplitudes& coef, NodalBatch& f) {
  for (int p = 0; p < 3; ++p)
    for (int k = 0; k < 2; ++k) {
      const int i = kPair[p][k];
      for (int a = 0; a < 8; ++a)
        for (int c = 0; c < 3; ++c)
          for (int l = 0; l < kBatch; ++l)
            f[c][a][l] += coef[p][k][l] * sg.gam[p][a][l] * sg.r[i][c][l];
    }
}

// Sums over the eight Gauss points of one batch: the internal energy, any failed point, the
// element-level mean stress and plastic strain.
struct FullPointSums {
  LaneArray de_int, eps_mean;
  uint8_t any_failed[kBatch] = {};
  double sig_mean[6][kBatch] = {};
};

// The current geometry: volume, characteristic length, wave speed for the step, bulk viscosity.
struct FullGeometry {
  LaneArray vol, len, c_dt, qbv;
};

// The mid-step geometry x - dt/2 v and the element mean dilatation rate from its exact volume
// gradient.
inline void meanDilatation(double dt, BatchScratch& w, LaneArray& vol_mid, LaneArray& trace_mean) {
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 8; ++a)
      for (int l = 0; l < kBatch; ++l) w.xm[c][a][l] = w.x[c][a][l] - 0.5 * dt * w.v[c][a][l];
  volumeGradient(w.xm, w.b);
  detail::volumeOf(w.xm, w.b, vol_mid);
  for (int l = 0; l < kBatch; ++l) {
    double s = 0.0;
    for (int c = 0; c < 3; ++c)
      for (int a = 0; a < 8; ++a) s += w.v[c][a][l] * w.b[c][a][l];
    trace_mean[l] = s / vol_mid[l];
  }
}

// The Jaumann rotation of one point's stress (and back stress) and its B-bar strain increment:
// the point's own deviatoric rate, the element's mean dilatation.
// The correction's state for the rates (at the mid-step geometry) of ELFORM -1, -2.
struct ShearRates {
  ShearGeometry sg;
  ShearAmplitudes amp;
};

// With kFix (ELFORM -1, -2) the velocity gradient of point q takes the shear correction of sr.
template <class Law, bool kFix>
inline void pointRates(double dt, const NodalBatch& grad, const LaneArray& trace_mean,
                       BatchScratch& w, int q, const LaneArray& det, const ShearRates* sr) {
  for (int l = 0; l < kBatch; ++l) {
    double L[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double s = 0.0;
        for (int a = 0; a < 8; ++a) s += w.v[i][a][l] * grad[j][a][l];
        L[i][j] = s;
      }
    if constexpr (kFix) addShearRate(sr->sg, sr->amp, q, det[l], l, L);
    const double wxy = 0.5 * (L[0][1] - L[1][0]) * dt;
    const double wyz = 0.5 * (L[1][2] - L[2][1]) * dt;
    const double wzx = 0.5 * (L[2][0] - L[0][2]) * dt;
    detail::rotateJaumann(w.s, l, wxy, wyz, wzx);
    if constexpr (Law::kKinematic) detail::rotateJaumann(w.alpha, l, wxy, wyz, wzx);
    const double shift = (trace_mean[l] - (L[0][0] + L[1][1] + L[2][2])) / 3.0;
    w.de[0][l] = (L[0][0] + shift) * dt;
    w.de[1][l] = (L[1][1] + shift) * dt;
    w.de[2][l] = (L[2][2] + shift) * dt;
    w.de[3][l] = 0.5 * (L[0][1] + L[1][0]) * dt;
    w.de[4][l] = 0.5 * (L[1][2] + L[2][1]) * dt;
    w.de[5][l] = 0.5 * (L[2][0] + L[0][2]) * dt;
  }
}

// Stress update at each Gauss point (loaded from and stored to the point records), summed
// into the element-level view.
template <class Law, class Rule>
inline void gaussPointStresses(const Law& law, domain::SolidBlock& blk, std::size_t first,
                               double dt, const LaneArray& trace_mean, BatchScratch& w,
                               NodalBatch& grad, FullPointSums& sums, const ShearRates* sr) {
  const std::size_t padded = blk.paddedSize();
  for (int l = 0; l < kBatch; ++l) sums.de_int[l] = sums.eps_mean[l] = 0.0;
  constexpr double share = 1.0 / Rule::kPoints;
  for (int q = 0; q < Rule::kPoints; ++q) {
    LaneArray det;
    gradientsAt<Rule>(q, w.xm, grad, det);
    const std::size_t at = static_cast<std::size_t>(q) * padded + first;
    for (int k = 0; k < 6; ++k)
      for (int l = 0; l < kBatch; ++l) w.s[k][l] = blk.sig_ip[k][at + l];
    if constexpr (Law::kPlastic)
      for (int l = 0; l < kBatch; ++l) w.eps_p[l] = blk.eps_p_ip[at + l];
    if constexpr (Law::kKinematic)
      for (int k = 0; k < 6; ++k)
        for (int l = 0; l < kBatch; ++l) w.alpha[k][l] = blk.alpha_ip[k][at + l];
    constexpr int H = materials::historyOf<Law>();
    for (int k = 0; k < H; ++k)
      for (int l = 0; l < kBatch; ++l)
        w.hist[k][l] = blk.hist_ip[std::size_t(q * H + k) * padded + first + l];
    pointRates<Law, Rule::kShearFix>(dt, grad, trace_mean, w, q, det, sr);
    detail::updateMaterial(law, w, dt);
    for (int l = 0; l < kBatch; ++l) {
      sums.de_int[l] += detail::stressWork(w, l) * det[l];
      sums.any_failed[l] |= w.failed[l];
    }
    for (int k = 0; k < 6; ++k)
      for (int l = 0; l < kBatch; ++l) {
        blk.sig_ip[k][at + l] = w.s[k][l];
        sums.sig_mean[k][l] += share * w.s[k][l];
      }
    if constexpr (Law::kPlastic)
      for (int l = 0; l < kBatch; ++l) {
        blk.eps_p_ip[at + l] = w.eps_p[l];
        sums.eps_mean[l] += share * w.eps_p[l];
      }
    if constexpr (Law::kKinematic)
      for (int k = 0; k < 6; ++k)
        for (int l = 0; l < kBatch; ++l) blk.alpha_ip[k][at + l] = w.alpha[k][l];
    for (int k = 0; k < H; ++k)
      for (int l = 0; l < kBatch; ++l)
        blk.hist_ip[std::size_t(q * H + k) * padded + first + l] = w.hist[k][l];
  }
}

// Geometry at x(n): volume, exact volume gradient, characteristic length, bulk viscosity (its
// work taken from de_int).
inline void fullGeometry(domain::SolidBlock& blk, std::size_t first, double lam2mu, double dt,
                         const BulkViscosity& bv, const LaneArray& trace_mean,
                         const LaneArray& vol_mid, BatchScratch& w, FullGeometry& g,
                         LaneArray& de_int) {
  volumeGradient(w.x, w.b);
  LaneArray area, rho, c;
  detail::volumeOf(w.x, w.b, g.vol);
  detail::maxFaceArea(w.x, area);
  for (int l = 0; l < kBatch; ++l) {
    const std::size_t e = first + static_cast<std::size_t>(l);
    const double v_safe = g.vol[l] > 0.0 ? g.vol[l] : 1.0;
    rho[l] = blk.rho0 * blk.vol0[e] / v_safe;
    c[l] = std::sqrt(lam2mu / rho[l]);
    g.c_dt[l] = blk.mass_scale.empty() ? c[l] : c[l] / std::sqrt(blk.mass_scale[e]);
    g.len[l] = v_safe / area[l];
    g.qbv[l] =
        trace_mean[l] < 0.0
            ? rho[l] * g.len[l] *
                  (bv.q1 * g.len[l] * trace_mean[l] * trace_mean[l] - bv.q2 * c[l] * trace_mean[l])
            : 0.0;
    de_int[l] += detail::bulkViscosityWork(blk, first, l, g.qbv[l], trace_mean[l], dt) * vol_mid[l];
  }
}

// Forces: deviatoric stress at each point on its own gradients; the mean pressure (plus bulk
// viscosity) on the exact volume gradient, which the Gauss sum of det(J) grad N reproduces
// exactly.
// ELFORM -1, -2 add the transpose of the shear correction (on the geometry at x(n)).
template <class Rule>
inline void fullForces(const domain::SolidBlock& blk, std::size_t first, const FullGeometry& g,
                       BatchScratch& w, NodalBatch& grad, ShearGeometry* sg) {
  const std::size_t padded = blk.paddedSize();
  for (int c3 = 0; c3 < 3; ++c3)
    for (int a = 0; a < 8; ++a)
      for (int l = 0; l < kBatch; ++l) w.f[c3][a][l] = 0.0;
  LaneArray pbar;
  for (int l = 0; l < kBatch; ++l) pbar[l] = 0.0;
  ShearAmplitudes coef = {};
  if constexpr (Rule::kShearFix) shearGeometry(w.x, w.b, g.vol, *sg);
  for (int q = 0; q < Rule::kPoints; ++q) {
    LaneArray det;
    gradientsAt<Rule>(q, w.x, grad, det);
    const std::size_t at = static_cast<std::size_t>(q) * padded + first;
    for (int l = 0; l < kBatch; ++l) {
      const double s0 = blk.sig_ip[0][at + l], s1 = blk.sig_ip[1][at + l],
                   s2 = blk.sig_ip[2][at + l];
      const double mean = (s0 + s1 + s2) / 3.0;
      pbar[l] += mean * det[l];
      const double dxx = (s0 - mean) * det[l], dyy = (s1 - mean) * det[l],
                   dzz = (s2 - mean) * det[l];
      const double sxy = blk.sig_ip[3][at + l] * det[l], syz = blk.sig_ip[4][at + l] * det[l],
                   szx = blk.sig_ip[5][at + l] * det[l];
      for (int a = 0; a < 8; ++a) {
        const double gx = grad[0][a][l], gy = grad[1][a][l], gz = grad[2][a][l];
        w.f[0][a][l] -= dxx * gx + sxy * gy + szx * gz;
        w.f[1][a][l] -= sxy * gx + dyy * gy + syz * gz;
        w.f[2][a][l] -= szx * gx + syz * gy + dzz * gz;
      }
      if constexpr (Rule::kShearFix) {
        const double S[6] = {s0 - mean,
                             s1 - mean,
                             s2 - mean,
                             blk.sig_ip[3][at + l],
                             blk.sig_ip[4][at + l],
                             blk.sig_ip[5][at + l]};
        addShearWork(*sg, q, l, S, coef);
      }
    }
  }
  if constexpr (Rule::kShearFix) addShearForces(*sg, coef, w.f);
  for (int l = 0; l < kBatch; ++l) {
    // pbar holds the volume integral of the mean normal stress; per unit volume:
    const double mean_stress = pbar[l] / (g.vol[l] != 0.0 ? g.vol[l] : 1.0) - g.qbv[l];
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i) w.f[i][a][l] -= mean_stress * w.b[i][a][l];
  }
}

// Stores the element-level view (mean stress, mean plastic strain) for output and sums, then
// the slots, erosion and stable step.
template <class Law>
inline void storeFullBatch(domain::SolidBlock& blk, std::size_t first, int n,
                           const BulkViscosity& bv, const LaneArray& trace_mean,
                           const FullPointSums& sums, const FullGeometry& g, const BatchScratch& w,
                           double* slots, BlockStatus& st) {
  for (int l = 0; l < n; ++l) {
    const std::size_t e = first + static_cast<std::size_t>(l);
    double* slot = slots + 3 * (blk.slot_offset + 8 * e);
    if (!blk.active[e]) {
      std::fill(slot, slot + 24, 0.0);
      continue;
    }
    for (int k = 0; k < 6; ++k) blk.sigAt(k, e) = sums.sig_mean[k][l];
    if constexpr (Law::kPlastic) blk.eps_p[e] = sums.eps_mean[l];
    blk.vol[e] = g.vol[l];
    blk.e_int[e] += sums.de_int[l];
    // Eroded when any Gauss point reaches the failure strain (a documented choice).
    detail::finishElement(blk, e, l, w.f, g.vol[l], sums.any_failed[l] != 0, g.len[l], g.c_dt[l],
                          trace_mean[l], bv, slot, st);
  }
}

template <class Law, class Rule>
BlockStatus fullBlockForces(const Law& law, domain::SolidBlock& blk, const domain::NodeVector& x,
                            const domain::NodeVector& v, double dt, const BulkViscosity& bv,
                            double* slots, std::size_t range_first, std::size_t range_last) {
  const std::size_t nbatch =
      range_last > range_first ? (range_last - range_first + kBatch - 1) / kBatch : 0;
  const double lam2mu = law.moduli.bulk + 4.0 / 3.0 * law.moduli.shear;
  std::vector<BlockStatus> status(nbatch);

#pragma omp parallel
  {
    BatchScratch w;
    NodalBatch grad;
    // ELFORM -1, -2 only: the shear correction's scratch (on the heap: it is large).
    auto sr = Rule::kShearFix ? std::make_unique<ShearRates>() : nullptr;
#pragma omp for schedule(static)
    for (std::size_t ib = 0; ib < nbatch; ++ib) {
      const std::size_t first = range_first + ib * kBatch;
      const int n = static_cast<int>(std::min<std::size_t>(kBatch, range_last - first));
      detail::gatherNodal(blk, first, n, x, w.x);
      detail::gatherNodal(blk, first, n, v, w.v);
      LaneArray vol_mid, trace_mean;
      meanDilatation(dt, w, vol_mid, trace_mean);
      if constexpr (Rule::kShearFix) {
        shearGeometry(w.xm, w.b, vol_mid, sr->sg);
        shearAmplitudes(sr->sg, w.v, sr->amp);
      }
      FullPointSums sums;
      gaussPointStresses<Law, Rule>(law, blk, first, dt, trace_mean, w, grad, sums, sr.get());
      FullGeometry g;
      fullGeometry(blk, first, lam2mu, dt, bv, trace_mean, vol_mid, w, g, sums.de_int);
      fullForces<Rule>(blk, first, g, w, grad, sr ? &sr->sg : nullptr);
      storeFullBatch<Law>(blk, first, n, bv, trace_mean, sums, g, w, slots, status[ib]);
    }
  }
  return detail::mergeStatus(status);
}

}  // namespace

BlockStatus computeFullSolidForces(domain::SolidBlock& block, const domain::NodeVector& x,
                                   const domain::NodeVector& v, double dt, const BulkViscosity& bv,
                                   double* slots, std::size_t first, std::size_t last) {
  return std::visit(
      [&](const auto& law) -> BlockStatus {
        using Law = std::decay_t<decltype(law)>;
        // Laws of the deformation gradient are refused for these formulations when the model is
        // built (model/build_mesh.cpp, finishParts): no Gauss point here computes F.
        if constexpr (materials::SolidLaw<Law> && !materials::needsDeformationGradient<Law>())
          return block.elform == 15
                     ? fullBlockForces<Law, PrismRule>(law, block, x, v, dt, bv, slots, first, last)
                 : block.elform == 2
                     ? fullBlockForces<Law, HexRule>(law, block, x, v, dt, bv, slots, first, last)
                     : fullBlockForces<Law, HexShearRule>(law, block, x, v, dt, bv, slots, first,
                                                          last);
        else
          materials::noUpdateFor(materials::Family::Solid);
      },
      block.law);
}

}  // namespace crumple::elements
