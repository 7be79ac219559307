// The 10-node tetrahedron (*SECTION_SOLID ELFORM 16): see tet10.hpp for the formulation, the
// mass lumping and the stable step. The kernel follows the fully integrated hexahedron
// (hex8_full.cpp) point for point: batches of kBatch elements, each point's state loaded,
// rotated, updated by the law and stored back, the forces summed over the points.
#include "elements/tet10.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "elements/hex8_kernel.hpp"

namespace crumple::elements {

namespace {

using detail::BatchScratch;
using detail::LaneArray;

constexpr int kNodes = 10;
constexpr int kPoints = domain::Tet10Block::kPoints;
// Coordinates or velocities of a batch's ten nodes: v[component][node][lane].
using Nodal10 = double[3][kNodes][kBatch];

// The corners of the six edges whose mid-side nodes are N5..N10 (0-based).
constexpr int kEdge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

// The 4-point rule: point q at L_q = a, the other volume coordinates b; weight 1/24 (the
// reference tetrahedron's volume 1/6 over four points).
constexpr double kA = 0.58541019662496845446;  // (5 + 3 sqrt 5) / 20
constexpr double kB = 0.13819660112501051518;  // (5 - sqrt 5) / 20
constexpr double kWeight = 1.0 / 24.0;

// dN_a / dxi_i at the points, natural coordinates xi_i = L_{i+1} (L_1 = 1 - xi_1 - xi_2 -
// xi_3): dN/dxi_i = dN/dL_{i+1} - dN/dL_1.
struct Tet10Derivatives {
  double d[kPoints][kNodes][3];
  constexpr Tet10Derivatives() : d{} {
    for (int q = 0; q < kPoints; ++q) {
      double L[4] = {kB, kB, kB, kB};
      L[q] = kA;
      double dl[kNodes][4] = {};  // dN_a / dL_m
      for (int k = 0; k < 4; ++k) dl[k][k] = 4.0 * L[k] - 1.0;
      for (int e = 0; e < 6; ++e) {
        const int i = kEdge[e][0], j = kEdge[e][1];
        dl[4 + e][i] = 4.0 * L[j];
        dl[4 + e][j] = 4.0 * L[i];
      }
      for (int a = 0; a < kNodes; ++a)
        for (int i = 0; i < 3; ++i) d[q][a][i] = dl[a][i + 1] - dl[a][0];
    }
  }
};
constexpr Tet10Derivatives kShape{};

// Gradients dN_a/dx_j at point q on geometry x, and the point's volume weight det(J) / 24.
void gradientsAt(int q, const Nodal10& x, Nodal10& grad, LaneArray& det) {
  detail::isoparametricGradients<kNodes>(kShape.d[q], kWeight, x, grad, det);
}

// The smallest altitude of the corner tetrahedron at lane l: its volume over the largest
// |dV/dx_a| (a third of the largest face area), as the 4-node tetrahedron's length
// (hex8_kernel.hpp, tetLengthArea).
double cornerAltitude(const Nodal10& x, int l) {
  double d[3][3];
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) d[k][c] = x[c][k + 1][l] - x[c][0][l];
  const auto cross = [](const double* u, const double* v, double* out) {
    out[0] = u[1] * v[2] - u[2] * v[1];
    out[1] = u[2] * v[0] - u[0] * v[2];
    out[2] = u[0] * v[1] - u[1] * v[0];
  };
  double g[4][3];  // 6 dV/dx_a
  cross(d[1], d[2], g[1]);
  cross(d[2], d[0], g[2]);
  cross(d[0], d[1], g[3]);
  for (int c = 0; c < 3; ++c) g[0][c] = -(g[1][c] + g[2][c] + g[3][c]);
  const double vol6 = d[0][0] * g[1][0] + d[0][1] * g[1][1] + d[0][2] * g[1][2];
  double m = 0.0;
  for (const auto& ga : g) m = std::max(m, ga[0] * ga[0] + ga[1] * ga[1] + ga[2] * ga[2]);
  return m > 0.0 ? vol6 / std::sqrt(m) : 0.0;
}

void gather10(const domain::Tet10Block& b, std::size_t first, int n, const domain::NodeVector& src,
              Nodal10& out) {
  for (int l = 0; l < kBatch; ++l) {
    const auto& conn = b.conn[detail::laneElement(first, n, l)];
    for (int a = 0; a < kNodes; ++a) {
      const double* p = &src[3 * static_cast<std::size_t>(conn[std::size_t(a)])];
      out[0][a][l] = p[0];
      out[1][a][l] = p[1];
      out[2][a][l] = p[2];
    }
  }
}

struct Scratch10 {
  Nodal10 x, v, xm, f;
  Nodal10 grad[kPoints];  // at x(n), kept from the volume to the forces
  LaneArray det[kPoints];
};

// The law at each point (state loaded from and stored to the point records), from its rate
// of deformation at the mid-step geometry; the sums the element needs.
struct PointSums {
  LaneArray de_int{}, vol_mid{}, trace{}, eps_mean{};
  double sig_mean[6][kBatch] = {};
  uint8_t any_failed[kBatch] = {};
  bool inverted[kBatch] = {};
};

template <class Law>
void pointStresses(const Law& law, domain::Tet10Block& blk, std::size_t first, double dt,
                   Scratch10& t, BatchScratch& w, PointSums& sums) {
  const std::size_t padded = blk.paddedSize();
  constexpr int H = materials::historyOf<Law>();
  for (int q = 0; q < kPoints; ++q) {
    LaneArray det;
    gradientsAt(q, t.xm, t.f, det);  // t.f holds the mid-step gradients here
    const auto& grad = t.f;
    const std::size_t at = static_cast<std::size_t>(q) * padded + first;
    for (int k = 0; k < 6; ++k)
      for (int l = 0; l < kBatch; ++l) w.s[k][l] = blk.sig_ip[k][at + l];
    if constexpr (Law::kPlastic)
      for (int l = 0; l < kBatch; ++l) w.eps_p[l] = blk.eps_p_ip[at + l];
    if constexpr (Law::kKinematic)
      for (int k = 0; k < 6; ++k)
        for (int l = 0; l < kBatch; ++l) w.alpha[k][l] = blk.alpha_ip[k][at + l];
    for (int k = 0; k < H; ++k)
      for (int l = 0; l < kBatch; ++l)
        w.hist[k][l] = blk.hist_ip[std::size_t(q * H + k) * padded + first + l];
    for (int l = 0; l < kBatch; ++l) {
      double L[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double s = 0.0;
          for (int a = 0; a < kNodes; ++a) s += t.v[i][a][l] * grad[j][a][l];
          L[i][j] = s;
        }
      const double wxy = 0.5 * (L[0][1] - L[1][0]) * dt;
      const double wyz = 0.5 * (L[1][2] - L[2][1]) * dt;
      const double wzx = 0.5 * (L[2][0] - L[0][2]) * dt;
      detail::rotateJaumann(w.s, l, wxy, wyz, wzx);
      if constexpr (Law::kKinematic) detail::rotateJaumann(w.alpha, l, wxy, wyz, wzx);
      w.de[0][l] = L[0][0] * dt;
      w.de[1][l] = L[1][1] * dt;
      w.de[2][l] = L[2][2] * dt;
      w.de[3][l] = 0.5 * (L[0][1] + L[1][0]) * dt;
      w.de[4][l] = 0.5 * (L[1][2] + L[2][1]) * dt;
      w.de[5][l] = 0.5 * (L[2][0] + L[0][2]) * dt;
      sums.trace[l] += (L[0][0] + L[1][1] + L[2][2]) * det[l];
      sums.vol_mid[l] += det[l];
    }
    detail::updateMaterial(law, w, dt);
    for (int l = 0; l < kBatch; ++l) {
      sums.de_int[l] += detail::stressWork(w, l) * det[l];
      sums.any_failed[l] |= w.failed[l];
    }
    for (int k = 0; k < 6; ++k)
      for (int l = 0; l < kBatch; ++l) {
        blk.sig_ip[k][at + l] = w.s[k][l];
        sums.sig_mean[k][l] += 0.25 * w.s[k][l];
      }
    if constexpr (Law::kPlastic)
      for (int l = 0; l < kBatch; ++l) {
        blk.eps_p_ip[at + l] = w.eps_p[l];
        sums.eps_mean[l] += 0.25 * w.eps_p[l];
      }
    if constexpr (Law::kKinematic)
      for (int k = 0; k < 6; ++k)
        for (int l = 0; l < kBatch; ++l) blk.alpha_ip[k][at + l] = w.alpha[k][l];
    for (int k = 0; k < H; ++k)
      for (int l = 0; l < kBatch; ++l)
        blk.hist_ip[std::size_t(q * H + k) * padded + first + l] = w.hist[k][l];
  }
  // The element's mean rate of dilatation (for the bulk viscosity).
  for (int l = 0; l < kBatch; ++l)
    sums.trace[l] = sums.vol_mid[l] != 0.0 ? sums.trace[l] / sums.vol_mid[l] : 0.0;
}

// Forces at x(n): f_a = -sum_q w_q det J_q (sigma_q - q_bv I) grad N_a, after the volume,
// the characteristic length and the bulk viscosity q (its trapezoidal work into de_int).
struct Geometry {
  LaneArray vol, len, c_dt, qbv;
};

void forcesAt(domain::Tet10Block& blk, std::size_t first, double lam2mu, double dt,
              const BulkViscosity& bv, Scratch10& t, PointSums& sums, Geometry& g) {
  const std::size_t padded = blk.paddedSize();
  for (int l = 0; l < kBatch; ++l) g.vol[l] = 0.0;
  for (int q = 0; q < kPoints; ++q) {
    gradientsAt(q, t.x, t.grad[q], t.det[q]);
    for (int l = 0; l < kBatch; ++l) {
      g.vol[l] += t.det[q][l];
      sums.inverted[l] = sums.inverted[l] || !(t.det[q][l] > 0.0);
    }
  }
  for (int l = 0; l < kBatch; ++l) {
    const std::size_t e = first + static_cast<std::size_t>(l);
    const double v_safe = g.vol[l] > 0.0 ? g.vol[l] : 1.0;
    const double rho = blk.rho0 * blk.vol0[e] / v_safe;
    const double c = std::sqrt(lam2mu / rho);
    g.c_dt[l] = blk.mass_scale.empty() ? c : c / std::sqrt(blk.mass_scale[e]);
    g.len[l] = kTet10LengthFactor * cornerAltitude(t.x, l);
    const double tr = sums.trace[l];
    g.qbv[l] = tr < 0.0 ? rho * g.len[l] * (bv.q1 * g.len[l] * tr * tr - bv.q2 * c * tr) : 0.0;
    // Trapezoidal work of q (hex8_kernel.hpp, bulkViscosityWork).
    double& q_old = blk.q_bulk[e];
    sums.de_int[l] += -0.5 * (q_old + g.qbv[l]) * tr * dt * sums.vol_mid[l];
    q_old = g.qbv[l];
  }
  for (int c3 = 0; c3 < 3; ++c3)
    for (int a = 0; a < kNodes; ++a)
      for (int l = 0; l < kBatch; ++l) t.f[c3][a][l] = 0.0;
  for (int q = 0; q < kPoints; ++q) {
    const std::size_t at = static_cast<std::size_t>(q) * padded + first;
    const auto& grad = t.grad[q];
    for (int l = 0; l < kBatch; ++l) {
      const double d = t.det[q][l];
      const double sxx = (blk.sig_ip[0][at + l] - g.qbv[l]) * d;
      const double syy = (blk.sig_ip[1][at + l] - g.qbv[l]) * d;
      const double szz = (blk.sig_ip[2][at + l] - g.qbv[l]) * d;
      const double sxy = blk.sig_ip[3][at + l] * d, syz = blk.sig_ip[4][at + l] * d,
                   szx = blk.sig_ip[5][at + l] * d;
      for (int a = 0; a < kNodes; ++a) {
        const double gx = grad[0][a][l], gy = grad[1][a][l], gz = grad[2][a][l];
        t.f[0][a][l] -= sxx * gx + sxy * gy + szx * gz;
        t.f[1][a][l] -= sxy * gx + syy * gy + syz * gz;
        t.f[2][a][l] -= szx * gx + syz * gy + szz * gz;
      }
    }
  }
}

// The element-level view, the energy, then erosion, the slots and the stable step.
template <class Law>
void storeBatch(domain::Tet10Block& blk, std::size_t first, int n, const BulkViscosity& bv,
                const PointSums& sums, const Geometry& g, const Scratch10& t, double* slots,
                BlockStatus& st) {
  for (int l = 0; l < n; ++l) {
    const std::size_t e = first + static_cast<std::size_t>(l);
    double* slot = slots + 3 * (blk.slot_offset + kNodes * e);
    if (!blk.active[e]) {
      std::fill(slot, slot + 3 * kNodes, 0.0);
      continue;
    }
    for (int k = 0; k < 6; ++k) blk.sigAt(k, e) = sums.sig_mean[k][l];
    if constexpr (Law::kPlastic) blk.eps_p[e] = sums.eps_mean[l];
    blk.vol[e] = g.vol[l];
    blk.e_int[e] += sums.de_int[l];
    if (sums.inverted[l] && (st.bad_elem < 0 || blk.elem[e] < st.bad_elem))
      st.bad_elem = blk.elem[e];
    const double dte = solidTimeStep(g.len[l], g.c_dt[l], sums.trace[l], bv);
    // Eroded when any point fails (as the fully integrated hexahedron), or below the floor.
    if (sums.any_failed[l] || dte < blk.erode_dt) {
      blk.active[e] = 0;
      if (sums.any_failed[l]) blk.failed[e] = 1;
      for (int k = 0; k < 6; ++k) blk.sigAt(k, e) = 0.0;
      std::fill(slot, slot + 3 * kNodes, 0.0);
      ++st.eroded;
      continue;
    }
    for (int a = 0; a < kNodes; ++a)
      for (int i = 0; i < 3; ++i) slot[3 * a + i] = t.f[i][a][l];
    st.observeStep(dte, blk.elem[e]);
  }
}

template <class Law>
BlockStatus blockForces(const Law& law, domain::Tet10Block& blk, const domain::NodeVector& x,
                        const domain::NodeVector& v, double dt, const BulkViscosity& bv,
                        double* slots, std::size_t range_first, std::size_t range_last) {
  const std::size_t nbatch =
      range_last > range_first ? (range_last - range_first + kBatch - 1) / kBatch : 0;
  const double lam2mu = law.moduli.bulk + 4.0 / 3.0 * law.moduli.shear;
  std::vector<BlockStatus> status(nbatch);
#pragma omp parallel
  {
    auto t = std::make_unique<Scratch10>();
    auto w = std::make_unique<BatchScratch>();
#pragma omp for schedule(static)
    for (std::size_t ib = 0; ib < nbatch; ++ib) {
      const std::size_t first = range_first + ib * kBatch;
      const int n = static_cast<int>(std::min<std::size_t>(kBatch, range_last - first));
      gather10(blk, first, n, x, t->x);
      gather10(blk, first, n, v, t->v);
      for (int c = 0; c < 3; ++c)
        for (int a = 0; a < kNodes; ++a)
          for (int l = 0; l < kBatch; ++l)
            t->xm[c][a][l] = t->x[c][a][l] - 0.5 * dt * t->v[c][a][l];
      PointSums sums;
      pointStresses(law, blk, first, dt, *t, *w, sums);
      Geometry g;
      forcesAt(blk, first, lam2mu, dt, bv, *t, sums, g);
      storeBatch<Law>(blk, first, n, bv, sums, g, *t, slots, status[ib]);
    }
  }
  return detail::mergeStatus(status);
}

}  // namespace

void resizeTet10Block(domain::Tet10Block& b) {
  const std::size_t padded = b.paddedSize();
  const std::size_t points = std::size_t(kPoints) * padded;
  const bool plastic = materials::isPlastic(b.law);
  const bool kinematic = materials::isKinematic(b.law);
  b.history = materials::historyCount(b.law);
  b.sig.assign(6 * padded, 0.0);
  b.eps_p.assign(plastic ? padded : 0, 0.0);
  for (auto& s : b.sig_ip) s.assign(points, 0.0);
  for (auto& s : b.alpha_ip) s.assign(kinematic ? points : 0, 0.0);
  b.eps_p_ip.assign(plastic ? points : 0, 0.0);
  b.hist_ip.assign(std::size_t(b.history) * points, 0.0);
  b.q_bulk.assign(padded, 0.0);
  // Padding lanes get a unit volume so that densities stay finite there.
  b.vol0.assign(padded, 1.0);
  b.vol.assign(padded, 1.0);
  b.e_int.assign(padded, 0.0);
  b.active.assign(padded, 1);
  b.failed.assign(padded, 0);
}

BlockStatus initializeTet10(domain::Tet10Block& blk, const domain::NodeVector& x0, double* slots,
                            std::vector<double>& element_dt, const BulkViscosity& bv) {
  BlockStatus st;
  element_dt.assign(blk.size(), 0.0);
  const materials::Moduli mod = materials::moduliOf(blk.law);
  const double lam2mu = mod.bulk + 4.0 / 3.0 * mod.shear;
  const double c = blk.rho0 > 0.0 ? std::sqrt(lam2mu / blk.rho0) : 0.0;
  auto t = std::make_unique<Scratch10>();
  for (std::size_t first = 0; first < blk.size(); first += kBatch) {
    const int n = static_cast<int>(std::min<std::size_t>(kBatch, blk.size() - first));
    gather10(blk, first, n, x0, t->x);
    LaneArray vol = {};
    bool inverted[kBatch] = {};
    for (int q = 0; q < kPoints; ++q) {
      gradientsAt(q, t->x, t->grad[q], t->det[q]);
      for (int l = 0; l < kBatch; ++l) {
        vol[l] += t->det[q][l];
        inverted[l] = inverted[l] || !(t->det[q][l] > 0.0);
      }
    }
    for (int l = 0; l < n; ++l) {
      const std::size_t e = first + static_cast<std::size_t>(l);
      if (inverted[l] && (st.bad_elem < 0 || blk.elem[e] < st.bad_elem)) st.bad_elem = blk.elem[e];
      blk.vol0[e] = blk.vol[e] = vol[l];
      double* slot = slots + 3 * (blk.slot_offset + kNodes * e);
      for (int a = 0; a < kNodes; ++a) {
        slot[3 * a] = blk.rho0 * vol[l] * tet10MassShare(a);
        slot[3 * a + 1] = slot[3 * a + 2] = 0.0;
      }
      const double len = kTet10LengthFactor * cornerAltitude(t->x, l);
      element_dt[e] = c > 0.0 ? solidTimeStep(len, c, 0.0, bv) : 0.0;
      if (element_dt[e] > 0.0) st.observeStep(element_dt[e], blk.elem[e]);
    }
  }
  return st;
}

BlockStatus computeTet10Forces(domain::Tet10Block& block, const domain::NodeVector& x,
                               const domain::NodeVector& v, double dt, const BulkViscosity& bv,
                               double* slots, std::size_t first, std::size_t last) {
  return std::visit(
      [&](const auto& law) -> BlockStatus {
        using Law = std::decay_t<decltype(law)>;
        // Laws of the deformation gradient are refused for ELFORM 16 when the model is built
        // (model/build_mesh.cpp, finishParts): no point here computes F.
        if constexpr (materials::SolidLaw<Law> && !materials::needsDeformationGradient<Law>())
          return blockForces(law, block, x, v, dt, bv, slots, first, last);
        else
          materials::noUpdateFor(materials::Family::Solid);
      },
      block.law);
}

}  // namespace crumple::elements
