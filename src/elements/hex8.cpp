#include "elements/hex8.hpp"

#include "elements/hex8_kernel.hpp"
#include "elements/tshell.hpp"
#include "materials/erosion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace crumple::elements {

namespace {

using detail::BatchScratch;
using detail::gatherNodal;
using detail::hourglassForces;
using detail::LaneArray;
using detail::laneElement;
using detail::maxFaceArea;
using detail::rotateJaumann;
using detail::SolidGeometry;
using detail::SolidParams;
using detail::SolidSpin;
using detail::volumeOf;

// Node permutation of FB 1981 (Appendix): the formula for node 1 gives node a's gradient
// when nodes are renumbered by row a. Zero-based.
constexpr int kPerm[8][8] = {{0, 1, 2, 3, 4, 5, 6, 7}, {1, 2, 3, 0, 5, 6, 7, 4},
                             {2, 3, 0, 1, 6, 7, 4, 5}, {3, 0, 1, 2, 7, 4, 5, 6},
                             {4, 7, 6, 5, 0, 3, 2, 1}, {5, 4, 7, 6, 1, 0, 3, 2},
                             {6, 5, 4, 7, 2, 1, 0, 3}, {7, 6, 5, 4, 3, 2, 1, 0}};

// dV/dx of node A, component C, from the other two components (Y, Z) = (C+1, C+2) mod 3:
// FB 1981 eq. 79 for every lane, all indices known at compile time.
template <int A, int C>
inline void gradientOfNodeComponent(const NodalBatch& x, NodalBatch& b) {
  constexpr int p1 = kPerm[A][1], p2 = kPerm[A][2], p3 = kPerm[A][3], p4 = kPerm[A][4],
                p5 = kPerm[A][5], p7 = kPerm[A][7];
  constexpr double twelfth = 1.0 / 12.0;
  const auto& y = x[(C + 1) % 3];
  const auto& z = x[(C + 2) % 3];
  for (int l = 0; l < kBatch; ++l) {
    b[C][A][l] = twelfth * (y[p1][l] * ((z[p5][l] - z[p2][l]) - (z[p3][l] - z[p4][l])) +
                            y[p2][l] * (z[p1][l] - z[p3][l]) +
                            y[p3][l] * ((z[p2][l] - z[p7][l]) - (z[p4][l] - z[p1][l])) +
                            y[p4][l] * ((z[p7][l] - z[p5][l]) - (z[p1][l] - z[p3][l])) +
                            y[p5][l] * (z[p4][l] - z[p1][l]) + y[p7][l] * (z[p3][l] - z[p4][l]));
  }
}

template <int A>
inline void gradientOfNode(const NodalBatch& x, NodalBatch& b) {
  gradientOfNodeComponent<A, 0>(x, b);
  gradientOfNodeComponent<A, 1>(x, b);
  gradientOfNodeComponent<A, 2>(x, b);
}

template <std::size_t... A>
inline void gradientOfAll(const NodalBatch& x, NodalBatch& b, std::index_sequence<A...>) {
  (gradientOfNode<int(A)>(x, b), ...);
}

// The two shapes of the one-point kernel: the volume gradient B = dV/dx and the area A with
// characteristic length L = V / A. The hexahedron: FB 1981 and its largest face; the
// tetrahedron (ELFORM 10): hex8_kernel.hpp, its minimum altitude.
struct HexShape {
  static constexpr bool kHourglass = true;
  static constexpr bool kNodalPressure = false;
  static void gradient(const NodalBatch& x, NodalBatch& b) {
    gradientOfAll(x, b, std::make_index_sequence<8>{});
  }
  static void lengthArea(const NodalBatch& x, const NodalBatch&, LaneArray& area) {
    maxFaceArea(x, area);
  }
};
struct TetShape {
  static constexpr bool kHourglass = false;  // a linear element has no hourglass modes
  static constexpr bool kNodalPressure = false;
  static void gradient(const NodalBatch& x, NodalBatch& b) { detail::tetVolumeGradient(x, b); }
  static void lengthArea(const NodalBatch&, const NodalBatch& b, LaneArray& area) {
    detail::tetLengthArea(b, area);
  }
};

// The nodal-pressure tetrahedron (ELFORM 13, tet_nodal.hpp): the tetrahedron's kinematics,
// with the volumetric strain from its nodes.
struct NodalTetShape : TetShape {
  static constexpr bool kNodalPressure = true;
};

// ELFORM 13: the step's change of the element's nodal-mean volumetric strain (tet_nodal.hpp),
// e_e = (e_1 + e_2 + e_3 + e_4) / 4 from the nodal strains at x(n), against the last pass's;
// the new value is kept for a live element.
inline void nodalVolumetricStep(domain::SolidBlock& blk, std::size_t first, int n,
                                const double* nodal_ev, LaneArray& step) {
  for (int l = 0; l < kBatch; ++l) {
    const auto& conn = blk.conn[laneElement(first, n, l)];
    const double ev =
        0.25 * (nodal_ev[conn[0]] + nodal_ev[conn[1]] + nodal_ev[conn[2]] + nodal_ev[conn[3]]);
    double& kept = blk.ev_nodal[first + static_cast<std::size_t>(l)];
    step[l] = ev - kept;
    if (blk.active[first + static_cast<std::size_t>(l)]) kept = ev;
  }
}

// Kinematics of one batch at the mid-step geometry x(n-1/2) = x(n) - dt/2 v(n-1/2): the
// volume and the velocity gradient L = dv_i/dx_j.
struct SolidRates {
  LaneArray vol_mid;
  double L[3][3][kBatch];
};

template <class Shape>
inline void midStepGradient(const SolidParams& p, BatchScratch& w, SolidRates& r) {
  const double dt = p.dt;
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 8; ++a)
      for (int l = 0; l < kBatch; ++l) w.xm[c][a][l] = w.x[c][a][l] - 0.5 * dt * w.v[c][a][l];
  Shape::gradient(w.xm, w.b);
  volumeOf(w.xm, w.b, r.vol_mid);
  LaneArray inv_vol_mid;
  for (int l = 0; l < kBatch; ++l) inv_vol_mid[l] = 1.0 / r.vol_mid[l];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int l = 0; l < kBatch; ++l) {
        double s = 0.0;
        for (int a = 0; a < 8; ++a) s += w.v[i][a][l] * w.b[j][a][l];
        r.L[i][j][l] = s * inv_vol_mid[l];
      }
}

// For laws that declare kElementGeometry: the edges from node 1 at x(n) and the characteristic
// length V / A at the mid-step geometry (w.b holds the gradient at x(n-1/2) here).
template <class Shape>
inline void elementGeometry(BatchScratch& w, const SolidRates& r) {
  detail::nodeEdges(w);
  LaneArray area;
  Shape::lengthArea(w.xm, w.b, area);
  for (int l = 0; l < kBatch; ++l) w.length[l] = r.vol_mid[l] / area[l];
}

// Stress: load the batch's records, the Jaumann rotation, then the material law.
// `ev_step` (ELFORM 13, else null): the volumetric strain increment the law receives in place
// of the element's own tr(de): de' = de + (ev_step - tr de) I / 3, the deviatoric part
// unchanged. A rate law splits through it: its deviatoric update sees the element's deviatoric
// strain, its pressure (elastic K tr de', or the EOS's relative volume integrated from
// tr de') the nodes' mean volume change. The work and the erosion strain keep the element's
// own de, the strain rate the forces sigma . B do work on (docs/theory.md).
template <class Law>
inline void updateStress(const Law& law, const SolidParams& p, const domain::SolidBlock& blk,
                         std::size_t first, const double* sig_batch, const double* alpha_batch,
                         BatchScratch& w, const SolidRates& r, SolidSpin& sp,
                         const LaneArray* ev_step) {
  const double dt = p.dt;
  const auto& L = r.L;
  for (int k = 0; k < 6; ++k)
    for (int l = 0; l < kBatch; ++l) w.s[k][l] = sig_batch[k * kBatch + l];
  if constexpr (Law::kPlastic)
    for (int l = 0; l < kBatch; ++l) w.eps_p[l] = blk.eps_p[first + l];
  if constexpr (Law::kKinematic)
    for (int k = 0; k < 6; ++k)
      for (int l = 0; l < kBatch; ++l) w.alpha[k][l] = alpha_batch[k * kBatch + l];
  constexpr int H = materials::historyOf<Law>();
  const double* hist_batch = H > 0 ? blk.hist.data() + first * H : nullptr;
  for (int k = 0; k < H; ++k)
    for (int l = 0; l < kBatch; ++l) w.hist[k][l] = hist_batch[k * kBatch + l];
  for (int l = 0; l < kBatch; ++l) {
    const double wxy = sp.spin_xy[l] = 0.5 * (L[0][1][l] - L[1][0][l]) * dt;
    const double wyz = sp.spin_yz[l] = 0.5 * (L[1][2][l] - L[2][1][l]) * dt;
    const double wzx = sp.spin_zx[l] = 0.5 * (L[2][0][l] - L[0][2][l]) * dt;
    rotateJaumann(w.s, l, wxy, wyz, wzx);
    // The back stress is a tensor in the same frame: it rotates with the stress.
    if constexpr (Law::kKinematic) rotateJaumann(w.alpha, l, wxy, wyz, wzx);
    w.de[0][l] = L[0][0][l] * dt;
    w.de[1][l] = L[1][1][l] * dt;
    w.de[2][l] = L[2][2][l] * dt;
    w.de[3][l] = 0.5 * (L[0][1][l] + L[1][0][l]) * dt;
    w.de[4][l] = 0.5 * (L[1][2][l] + L[2][1][l]) * dt;
    w.de[5][l] = 0.5 * (L[2][0][l] + L[0][2][l]) * dt;
    sp.trace_d[l] = L[0][0][l] + L[1][1][l] + L[2][2][l];
  }
  if constexpr (materials::needsDeformationGradient<Law>())
    detail::deformationGradient(blk, first, w);
  if (!ev_step) {
    detail::updateMaterial(law, w, dt);
    return;
  }
  double own[3][kBatch];
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < kBatch; ++l) own[k][l] = w.de[k][l];
  for (int l = 0; l < kBatch; ++l) {
    const double shift = ((*ev_step)[l] - (w.de[0][l] + w.de[1][l] + w.de[2][l])) / 3.0;
    for (int k = 0; k < 3; ++k) w.de[k][l] += shift;
  }
  detail::updateMaterial(law, w, dt);
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < kBatch; ++l) w.de[k][l] = own[k][l];
}

// The block's erosion criteria (materials/erosion.hpp) at the batch's points after the law:
// the stored total strain turned with the stress and advanced by de, and a point that meets
// them flagged failed, so that finishElement deletes its element as it deletes one the law
// failed.
inline void erodeSolidPoints(domain::SolidBlock& blk, std::size_t first, BatchScratch& w,
                             const SolidSpin& sp) {
  double e[6][kBatch] = {};
  if (!blk.strain.empty()) {
    double* strain_batch = blk.strain.data() + first * 6;
    for (int k = 0; k < 6; ++k)
      for (int l = 0; l < kBatch; ++l) e[k][l] = strain_batch[k * kBatch + l];
    for (int l = 0; l < kBatch; ++l)
      rotateJaumann(e, l, sp.spin_xy[l], sp.spin_yz[l], sp.spin_zx[l]);
    for (int k = 0; k < 6; ++k)
      for (int l = 0; l < kBatch; ++l) strain_batch[k * kBatch + l] = e[k][l] += w.de[k][l];
  }
  for (int l = 0; l < kBatch; ++l) {
    const materials::Voigt s{w.s[0][l], w.s[1][l], w.s[2][l], w.s[3][l], w.s[4][l], w.s[5][l]};
    const materials::Voigt eps{e[0][l], e[1][l], e[2][l], e[3][l], e[4][l], e[5][l]};
    if (materials::pointFails(blk.erosion, s, eps, blk.time)) w.failed[l] = 1;
  }
}

// A failing element (the law's flag or the erosion criteria) is deleted at the end of this
// pass and gives its nodes no force in it (finishElement): its stress and bulk viscosity are
// zero in the pass, so that its internal energy books only the old half of the step's
// trapezoid, the work its last applied force did (docs/theory.md, "Energy balance"), as the
// shells' failed points do.
inline void dropFailedStress(BatchScratch& w, SolidGeometry& g) {
  for (int l = 0; l < kBatch; ++l) {
    const double keep = w.failed[l] ? 0.0 : 1.0;
    for (int k = 0; k < 6; ++k) w.s[k][l] *= keep;
    g.q[l] *= keep;
  }
}

// Geometry at x(n): volume, volume gradient, characteristic length, bulk viscosity. The wave
// speed is that of lambda + 2 mu, or of the point's wave modulus when the law reports a larger
// one (`modulus`, null otherwise: law.hpp, kWaveModulus).
template <class Shape>
inline void currentGeometry(const SolidParams& p, const domain::SolidBlock& blk, std::size_t first,
                            const BulkViscosity& bv, BatchScratch& w, const SolidSpin& sp,
                            const double* modulus, SolidGeometry& g) {
  Shape::gradient(w.x, w.b);
  volumeOf(w.x, w.b, g.vol);
  Shape::lengthArea(w.x, w.b, g.area);
  for (int l = 0; l < kBatch; ++l) {
    const std::size_t e = first + static_cast<std::size_t>(l);
    const double v_safe = g.vol[l] > 0.0 ? g.vol[l] : 1.0;
    g.rho[l] = blk.rho0 * blk.vol0[e] / v_safe;
    const double m = modulus ? std::max(p.lam2mu, modulus[l]) : p.lam2mu;
    g.c[l] = std::sqrt(m / g.rho[l]);
    // Mass scaling slows the element's waves: c / sqrt(scale) enters the stable step only.
    g.c_dt[l] = blk.mass_scale.empty() ? g.c[l] : g.c[l] / std::sqrt(blk.mass_scale[e]);
    g.len[l] = v_safe / g.area[l];
    // Bulk viscosity (von Neumann-Richtmyer quadratic + Landshoff linear), compression only;
    // LS-DYNA Theory Manual "Bulk viscosity".
    const double td = sp.trace_d[l];
    g.q[l] =
        td < 0.0 ? g.rho[l] * g.len[l] * (bv.q1 * g.len[l] * td * td - bv.q2 * g.c[l] * td) : 0.0;
    // V^(2/3) for the viscous hourglass coefficient only (cbrt is not cheap).
    g.cbrt_vol[l] = p.stiffness_hg ? 0.0 : std::cbrt(v_safe);
  }
}

// Internal energy (midpoint rule on the stress power, plus bulk viscosity work, trapezoidal
// on q) and the stress divergence f_a = -(sigma - q I) . B_a.
inline void stressDivergence(const SolidParams& p, domain::SolidBlock& blk, std::size_t first,
                             BatchScratch& w, const SolidRates& r, const SolidSpin& sp,
                             const SolidGeometry& g, LaneArray& de_int) {
  for (int l = 0; l < kBatch; ++l) {
    de_int[l] = (detail::stressWork(w, l) +
                 detail::bulkViscosityWork(blk, first, l, g.q[l], sp.trace_d[l], p.dt)) *
                r.vol_mid[l];
  }
  for (int a = 0; a < 8; ++a)
    for (int l = 0; l < kBatch; ++l) {
      const double sxx = w.s[0][l] - g.q[l], syy = w.s[1][l] - g.q[l], szz = w.s[2][l] - g.q[l];
      const double sxy = w.s[3][l], syz = w.s[4][l], szx = w.s[5][l];
      const double bx = w.b[0][a][l], by = w.b[1][a][l], bz = w.b[2][a][l];
      w.f[0][a][l] = -(sxx * bx + sxy * by + szx * bz);
      w.f[1][a][l] = -(sxy * bx + syy * by + syz * bz);
      w.f[2][a][l] = -(szx * bx + syz * by + szz * bz);
    }
}

// Stores the state (whole batch, contiguous), then per element: forces and stable step.
template <class Law>
inline void storeSolidBatch(domain::SolidBlock& blk, std::size_t first, int n, double* sig_batch,
                            double* alpha_batch, const BatchScratch& w, const SolidSpin& sp,
                            const SolidGeometry& g, const LaneArray& de_int, const LaneArray& de_hg,
                            const BulkViscosity& bv, double* slots, BlockStatus& st) {
  const uint8_t* alive = &blk.active[first];
  for (int k = 0; k < 6; ++k)
    for (int l = 0; l < kBatch; ++l) sig_batch[k * kBatch + l] = alive[l] ? w.s[k][l] : 0.0;
  if constexpr (Law::kPlastic)
    for (int l = 0; l < kBatch; ++l)
      blk.eps_p[first + l] = alive[l] ? w.eps_p[l] : blk.eps_p[first + l];
  if constexpr (Law::kKinematic)
    for (int k = 0; k < 6; ++k)
      for (int l = 0; l < kBatch; ++l) alpha_batch[k * kBatch + l] = w.alpha[k][l];
  constexpr int H = materials::historyOf<Law>();
  double* hist_batch = H > 0 ? blk.hist.data() + first * H : nullptr;
  for (int k = 0; k < H; ++k)
    for (int l = 0; l < kBatch; ++l)
      hist_batch[k * kBatch + l] = alive[l] ? w.hist[k][l] : hist_batch[k * kBatch + l];
  for (int l = 0; l < kBatch; ++l) {
    blk.vol[first + l] = g.vol[l];
    blk.e_int[first + l] += alive[l] ? de_int[l] : 0.0;
    blk.e_hg[first + l] += alive[l] ? de_hg[l] : 0.0;
  }
  for (int l = 0; l < n; ++l) {
    const std::size_t e = first + static_cast<std::size_t>(l);
    double* slot = slots + 3 * (blk.slot_offset + 8 * e);
    if (!blk.active[e]) {
      std::fill(slot, slot + 24, 0.0);
      continue;
    }
    detail::finishElement(blk, e, l, w.f, g.vol[l], w.failed[l] != 0, g.len[l], g.c_dt[l],
                          sp.trace_d[l], bv, slot, st);
  }
}

// One portable binary, three instruction sets: GCC compiles this kernel (with everything it
// calls inlined: flatten) for AVX-512, for AVX2 and for the x86-64 baseline, and picks one at
// load time from the CPU. The clones do the same IEEE operations in the same order (no FMA
// contraction, no fast-math), so they give the same bits; tested on the example decks
// (docs/performance.md).
template <class Law, class Shape>
[[gnu::flatten, gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]] BlockStatus
solidBlockForces(const Law& law, domain::SolidBlock& blk, const domain::NodeVector& x,
                 const domain::NodeVector& v, double dt, const BulkViscosity& bv, double* slots,
                 std::size_t range_first, std::size_t range_last, const double* nodal_ev) {
  const std::size_t ne = range_last;
  const std::size_t batch0 = range_first / kBatch;
  const std::size_t nbatch =
      range_last > range_first ? (range_last - range_first + kBatch - 1) / kBatch : 0;
  SolidParams p;
  p.dt = dt;
  p.lam2mu = law.moduli.bulk + 4.0 / 3.0 * law.moduli.shear;
  p.qm = Shape::kHourglass ? blk.hourglass.qm : 0.0;
  p.stiffness_hg = blk.hourglass.ihq >= 4;
  p.projected_hg = blk.hourglass.ihq >= 2;
  std::vector<BlockStatus> status(nbatch);

#pragma omp parallel
  {
    BatchScratch w;
#pragma omp for schedule(static)
    for (std::size_t ib = 0; ib < nbatch; ++ib) {
      const std::size_t first = (batch0 + ib) * kBatch;
      const int n = static_cast<int>(std::min<std::size_t>(kBatch, ne - first));
      gatherNodal(blk, first, n, x, w.x);
      gatherNodal(blk, first, n, v, w.v);
      // This batch's records of stress and back stress (batch-blocked storage).
      double* sig_batch = blk.sig.data() + first * 6;
      double* alpha_batch = Law::kKinematic ? blk.alpha.data() + first * 6 : nullptr;
      SolidRates r;
      midStepGradient<Shape>(p, w, r);
      if constexpr (materials::needsElementGeometry<Law>()) elementGeometry<Shape>(w, r);
      SolidSpin sp;
      LaneArray ev_step;
      if constexpr (Shape::kNodalPressure) nodalVolumetricStep(blk, first, n, nodal_ev, ev_step);
      updateStress(law, p, blk, first, sig_batch, alpha_batch, w, r, sp,
                   Shape::kNodalPressure ? &ev_step : nullptr);
      if (blk.erosion.any()) erodeSolidPoints(blk, first, w, sp);
      SolidGeometry g;
      currentGeometry<Shape>(p, blk, first, bv, w, sp,
                             materials::reportsWaveModulus<Law>() ? w.modulus : nullptr, g);
      dropFailedStress(w, g);
      LaneArray de_int, de_hg;
      stressDivergence(p, blk, first, w, r, sp, g, de_int);
      for (int l = 0; l < kBatch; ++l) de_hg[l] = 0.0;
      if (p.qm > 0.0) hourglassForces(p, blk, first, w, sp, g, de_hg);
      storeSolidBatch<Law>(blk, first, n, sig_batch, alpha_batch, w, sp, g, de_int, de_hg, bv,
                           slots, status[ib]);
    }
  }

  return detail::mergeStatus(status);
}

}  // namespace

void volumeGradient(const NodalBatch& x, NodalBatch& b) {
  gradientOfAll(x, b, std::make_index_sequence<8>{});
}

double solidTimeStep(double length, double wave_speed, double trace_d, const BulkViscosity& bv) {
  // LS-DYNA applies Q in compression only. Switching it on and off with the sign of tr(D)
  // modulates the step in phase with a vibrating element and pumps energy into it (a small
  // free element with the default Q1, Q2 collapses within a few hundred cycles; see
  // docs/theory.md). Q is continuous in tr(D) here: the step is at most 6% shorter.
  const double qv = bv.q2 * wave_speed + bv.q1 * length * std::abs(trace_d);
  return length / (qv + std::sqrt(qv * qv + wave_speed * wave_speed));
}

void markIsolatedElements(domain::SolidBlock& blk, const domain::GatherPlan& plan) {
  blk.dt_scale.clear();
  // A thick shell's step is the plate's (tshell.hpp), not the breathing brick's.
  if (blk.thickShell()) return;
  const materials::Moduli mod = materials::moduliOf(blk.law);
  // A free tetrahedron's highest mode (lumped mass) has 2 / omega between 0.5 and 0.87 of
  // its minimum altitude over c: 0.51 for the regular one at nu = 0.49, 0.50 in the limit,
  // never lower over 3000 random shapes at nu = 0.4999 (docs/theory.md). In a mesh the
  // shared nodes' mass lowers it to within the altitude rule (tests/unit/test_tet4.cpp).
  const double factor =
      model::isTetrahedron(blk.elform)
          ? 0.5
          : std::min(1.0, std::sqrt((mod.bulk + 4.0 / 3.0 * mod.shear) / (3.0 * mod.bulk)));
  for (std::size_t e = 0; e < blk.size(); ++e) {
    bool isolated = true;
    for (int a = 0; a < 8 && isolated; ++a) {
      const auto n = static_cast<std::size_t>(blk.conn[e][a]);
      const int own =
          static_cast<int>(std::count(blk.conn[e].begin(), blk.conn[e].end(), blk.conn[e][a]));
      isolated = plan.ptr[n + 1] - plan.ptr[n] == own;
    }
    if (isolated && factor < 1.0) {
      if (blk.dt_scale.empty()) blk.dt_scale.assign(blk.paddedSize(), 1.0);
      blk.dt_scale[e] = factor;
    }
  }
}

BlockStatus computeSolidForces(domain::SolidBlock& block, const domain::NodeVector& x,
                               const domain::NodeVector& v, double dt, const BulkViscosity& bv,
                               double* slots, std::size_t first, std::size_t last,
                               const double* nodal_ev) {
  // Batches never straddle the range: unconditional vector stores of state would otherwise
  // write elements outside it.
  if (first % kBatch != 0 || (last % kBatch != 0 && last != block.size()) || last > block.size())
    throw std::logic_error("computeSolidForces: range not aligned to batches");
  if (block.elform == 13 && (!nodal_ev || block.ev_nodal.size() != block.paddedSize()))
    throw std::logic_error("computeSolidForces: ELFORM 13 without nodal volumetric strains");
  return std::visit(
      [&](const auto& law) -> BlockStatus {
        using Law = std::decay_t<decltype(law)>;
        // A law may switch the bulk viscosity off for its elements (*MAT_057 BVFLAG 0).
        [[maybe_unused]] const BulkViscosity q =
            materials::takesBulkViscosity(law) ? bv : BulkViscosity{0.0, 0.0};
        if constexpr (!materials::SolidLaw<Law>)
          materials::noUpdateFor(materials::Family::Solid);
        else if (block.elform == 13)
          return solidBlockForces<Law, NodalTetShape>(law, block, x, v, dt, q, slots, first, last,
                                                      nodal_ev);
        else if (block.elform == 10)
          return solidBlockForces<Law, TetShape>(law, block, x, v, dt, q, slots, first, last,
                                                 nullptr);
        else
          return solidBlockForces<Law, HexShape>(law, block, x, v, dt, q, slots, first, last,
                                                 nullptr);
      },
      block.law);
}

BlockStatus initializeSolids(domain::SolidBlock& blk, const domain::NodeVector& x0, double* slots,
                             std::vector<double>& element_dt, const BulkViscosity& bv) {
  const materials::Moduli mod = materials::moduliOf(blk.law);
  // Thick shells: the plate wave speed over the smaller of the thickness and the in-plane
  // length, no bulk viscosity (tshell.hpp).
  const bool tshell = blk.thickShell();
  if (tshell) setThickShellRule(blk);
  const double c =
      tshell ? thickShellWaveSpeed(blk) : std::sqrt((mod.bulk + 4.0 / 3.0 * mod.shear) / blk.rho0);
  const BulkViscosity bv_step = tshell ? BulkViscosity{0.0, 0.0} : bv;
  BlockStatus st;
  NodalBatch xb, bb;
  const bool tet = model::isTetrahedron(blk.elform);
  // The corners that carry mass: a tetrahedron's N1-N4, a pentahedron's six distinct nodes
  // (N1 N2 N3 N4 N5 N5 N6 N6: slots 5 and 7 repeat 4 and 6), a hexahedron's eight.
  const bool prism = blk.elform == 15;
  const int corners = tet ? 4 : (prism ? 6 : 8);
  auto carries = [&](int a) { return tet ? a < 4 : !(prism && (a == 5 || a == 7)); };
  const std::size_t ne = blk.size();
  element_dt.assign(ne, 0.0);
  const bool gradients = materials::needsDeformationGradient(blk.law);
  if (gradients) blk.grad0.assign(blk.paddedSize() * 24, 0.0);
  for (std::size_t first = 0; first < ne; first += kBatch) {
    const int n = static_cast<int>(std::min<std::size_t>(kBatch, ne - first));
    gatherNodal(blk, first, n, x0, xb);
    LaneArray vol, area;
    if (tet) {
      TetShape::gradient(xb, bb);
      volumeOf(xb, bb, vol);
      TetShape::lengthArea(xb, bb, area);
    } else {
      volumeGradient(xb, bb);
      volumeOf(xb, bb, vol);
      maxFaceArea(xb, area);
    }
    LaneArray length;
    if (tshell) thickShellLengths(xb, length);
    for (int l = 0; l < kBatch; ++l) length[l] = tshell ? length[l] : vol[l] / area[l];
    if (gradients) detail::storeInitialGradient(blk, first, bb, vol);
    for (int l = 0; l < n; ++l) {
      const std::size_t e = first + static_cast<std::size_t>(l);
      blk.vol0[e] = blk.vol[e] = vol[l];
      if (vol[l] <= 0.0) {
        if (st.bad_elem < 0) st.bad_elem = blk.elem[e];
        continue;
      }
      // A quarter of the tetrahedron's mass at each of its nodes, a sixth of the
      // pentahedron's (the repeated corners get none), an eighth of the hexahedron's at each
      // corner. The pentahedron's length is the hexahedron's V / A_max over its five faces
      // (the collapsed face has no area).
      const double corner_mass = blk.rho0 * vol[l] / corners;
      double* slot = slots + 3 * (blk.slot_offset + 8 * e);
      for (int a = 0; a < 8; ++a) {
        slot[3 * a] = carries(a) ? corner_mass : 0.0;
        slot[3 * a + 1] = slot[3 * a + 2] = 0.0;
      }
      double dte = solidTimeStep(length[l], c, 0.0, bv_step);
      if (!blk.dt_scale.empty()) dte *= blk.dt_scale[e];
      element_dt[e] = dte;
      st.observeStep(dte, blk.elem[e]);
    }
  }
  return st;
}

}  // namespace crumple::elements
