#include "materials/laws/honeycomb.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "util/curve.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& Honeycomb::cards() {
  using deck::I;
  using deck::R;
  // MU's 0.05 is kept for a blank only: an explicit 0 asks for no viscous stress (as DAMP of
  // *MAT_057). MACF 0 is its default 1.
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1",
        {I("MID"), R("RO"), R("E"), R("PR"), R("SIGY"), R("VF"), R("MU", 0.05), R("BULK")}},
       {"card 2",
        {I("LCA"), I("LCB"), I("LCC"), I("LCS"), I("LCAB"), I("LCBC"), I("LCCA"), I("LCSR")}},
       {"card 3",
        {R("EAAU"), R("EBBU"), R("ECCU"), R("GABU"), R("GBCU"), R("GCAU"), R("AOPT"),
         I("MACF", 1, deck::kZeroIsDefault)}},
       {"card 4", {R("XP"), R("YP"), R("ZP"), R("A1"), R("A2"), R("A3")}},
       {"card 5", {R("D1"), R("D2"), R("D3"), R("TSEF"), R("SSEF"), R("V1"), R("V2"), R("V3")}}}};
  return spec;
}

namespace {

constexpr std::array<std::string_view, 6> kCurveFields{"LCA", "LCB", "LCC", "LCAB", "LCBC", "LCCA"};

// Card 1: E, PR, SIGY, VF, MU, BULK.
void readCard1(LawInput& in, const deck::Card& c, Honeycomb::Params& p) {
  readElastic(c, p.E, p.nu);
  p.ro = c.real("RO");
  p.sigy = c.real("SIGY");
  if (!(p.sigy > 0))
    c.fail("SIGY", "the yield stress of the fully compacted honeycomb must be positive");
  p.vf = c.real("VF");
  if (!(p.vf > 0 && p.vf < 1))
    c.fail("VF", "the relative volume at full compaction must lie in (0, 1)");
  const double bulk = c.real("BULK");
  if (bulk != 0.0 && bulk != 1.0)
    c.fail("BULK", "must be 0 (no bulk viscosity, MU) or 1 (bulk viscosity, no MU)");
  p.bulk = bulk == 1.0;
  p.mu = c.real("MU");
  if (p.mu < 0) c.fail("MU", "the viscosity coefficient must not be negative");
  if (p.bulk) {
    if (p.mu != 0.0 && !c.blank("MU"))
      in.ignore(c, "MU", "BULK = 1: the bulk viscosity replaces MU's viscous stress");
    p.mu = 0.0;
  } else if (p.mu == 0.0) {
    in.ignore(c, "MU",
              "0: no viscous stress (a blank gives LS-DYNA's default 0.05; LS-DYNA may read 0 as "
              "that default too)");
  }
}

// Card 2: the curves, with their defaults (LCB, LCC, LCS from LCA; the shears from LCS).
void readCurves(LawInput& in, const deck::Card& c, Honeycomb::Params& p) {
  for (std::string_view f : {"LCB", "LCC", "LCS", "LCAB", "LCBC", "LCCA", "LCSR"})
    if (c.integer(f) < 0) c.fail(f, "must be a curve id (0: the default)");
  const int64_t lca = c.integer("LCA");
  if (lca == 0)
    c.fail("LCA", "a curve of sigma-aa vs relative volume (or volumetric strain) is required");
  if (lca < 0) {
    in.reject(c, "LCA", "a table of curves (LCA < 0) is not supported: give a curve id");
    return;
  }
  // The field that names each component's curve: its own when given, else its default's.
  const std::string_view shear_field = c.integer("LCS") > 0 ? "LCS" : "LCA";
  for (std::size_t k = 0; k < 6; ++k) {
    std::string_view field = kCurveFields[k];
    if (c.integer(field) == 0) field = k < 3 ? "LCA" : shear_field;
    p.curve[k] = in.curveOrReject(c, field, c.integer(field));
  }
  const int64_t lcsr = c.integer("LCSR");
  p.rate_curve = lcsr > 0 ? in.curveOrReject(c, "LCSR", lcsr) : -1;
}

// Card 3: the uncompacted moduli, AOPT, MACF.
void readCard3(LawInput& in, const deck::Card& c, Honeycomb::Params& p) {
  const std::string_view e[3] = {"EAAU", "EBBU", "ECCU"}, g[3] = {"GABU", "GBCU", "GCAU"};
  for (std::size_t k = 0; k < 3; ++k) {
    p.eu[k] = c.real(e[k]);
    if (!(p.eu[k] > 0)) c.fail(e[k], "the uncompacted Young's modulus must be positive");
    p.gu[k] = c.real(g[k]);
    if (!(p.gu[k] >= 0)) c.fail(g[k], "the uncompacted shear modulus must not be negative");
  }
  const double aopt = c.real("AOPT");
  if (aopt == 0.0 || aopt == 2.0) {
    p.aopt = static_cast<int>(aopt);
  } else if (aopt == 1.0 || aopt == 3.0 || aopt == 4.0 || aopt < 0.0) {
    const std::string what = aopt == 1.0   ? "AOPT 1 (a from a point P through the element centre)"
                             : aopt == 3.0 ? "AOPT 3 (a vector V and the element normal)"
                             : aopt == 4.0 ? "AOPT 4 (cylindrical about P and V)"
                                           : "AOPT < 0 (a coordinate system id)";
    in.reject(c, "AOPT",
              what +
                  " is not supported: give AOPT 0 (axes from the element's nodes 1, 2, 4) or "
                  "2 (global vectors A and D)");
  } else {
    c.fail("AOPT", "must be 0, 1, 2, 3, 4 or a negative coordinate system id");
  }
  const int64_t macf = c.integer("MACF");
  if (macf == 0 || std::abs(macf) > 4 || macf == -1)
    c.fail("MACF", "must be 1 (no change) or +-2, +-3, +-4 (swap a-b, a-c, b-c)");
  // Without a BETA rotation (none for AOPT 0 and 2) a swap before it is the swap after it.
  p.macf = static_cast<int>(std::abs(macf));
}

double norm3(const std::array<double, 3>& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// Cards 4 and 5: A and D for AOPT 2 (unit vectors, not parallel), TSEF, SSEF.
void readCards45(LawInput& in, const deck::Card& c4, const deck::Card& c5, Honeycomb::Params& p) {
  if (c4.real("XP") != 0.0 || c4.real("YP") != 0.0 || c4.real("ZP") != 0.0)
    in.ignore(c4, "XP", "the point P belongs to AOPT 1 and 4");
  if (c5.real("V1") != 0.0 || c5.real("V2") != 0.0 || c5.real("V3") != 0.0)
    in.ignore(c5, "V1", "the vector V belongs to AOPT 3 and 4");
  p.tsef = c5.real("TSEF");
  if (p.tsef < 0) c5.fail("TSEF", "the tensile failure strain must not be negative (0: none)");
  p.ssef = c5.real("SSEF");
  if (p.ssef < 0) c5.fail("SSEF", "the shear failure strain must not be negative (0: none)");
  if (p.aopt != 2) return;
  std::array<double, 3> a{c4.real("A1"), c4.real("A2"), c4.real("A3")};
  std::array<double, 3> d{c5.real("D1"), c5.real("D2"), c5.real("D3")};
  const double na = norm3(a), nd = norm3(d);
  if (!(na > 0)) c4.fail("A1", "AOPT 2 needs a non-zero vector A (A1, A2, A3)");
  if (!(nd > 0)) c5.fail("D1", "AOPT 2 needs a non-zero vector D (D1, D2, D3)");
  for (int k = 0; k < 3; ++k) a[k] /= na, d[k] /= nd;
  const std::array<double, 3> c{a[1] * d[2] - a[2] * d[1], a[2] * d[0] - a[0] * d[2],
                                a[0] * d[1] - a[1] * d[0]};
  if (!(norm3(c) > 1e-8)) c5.fail("D1", "AOPT 2: D must not be parallel to A");
  p.a = a;
  p.d = d;
}

}  // namespace

Honeycomb::Params Honeycomb::read(LawInput& in) {
  Params p;
  readCard1(in, in.card("card 1"), p);
  readCurves(in, in.card("card 2"), p);
  readCard3(in, in.card("card 3"), p);
  const deck::Card& c4 = in.optionalCard("card 4");
  readCards45(in, c4, in.optionalCard("card 5"), p);
  return p;
}

namespace {

// A limiting curve's checks: abscissae increasing; the abscissa is the volumetric strain when
// the first one is 0 or less, else the relative volume.
Honeycomb::Curve curveOf(const std::string& at, const CurveData& c, const std::string& name,
                         bool limit) {
  if (c.x.size() < 2 || c.x.size() != c.y.size())
    throw util::InputError(at + name + " curve " + std::to_string(c.id) +
                           " needs at least two points");
  for (std::size_t k = 1; k < c.x.size(); ++k)
    if (!(c.x[k] > c.x[k - 1]))
      throw util::InputError(at + name + " curve " + std::to_string(c.id) +
                             ": the abscissae must increase");
  Honeycomb::Curve out;
  out.x.assign(c.x.begin(), c.x.end());
  out.y.assign(c.y.begin(), c.y.end());
  out.volumetric = limit && c.x.front() <= 0.0;
  return out;
}

}  // namespace

Honeycomb Honeycomb::make(const Params& p, const CurveAt& curves, const std::string& at) {
  checkModuli(at, p.E, p.nu);
  if (!(p.sigy > 0)) throw util::InputError(at + "SIGY must be positive");
  if (!(p.vf > 0 && p.vf < 1)) throw util::InputError(at + "VF must lie in (0, 1)");
  if (!(p.ro > 0)) throw util::InputError(at + "RO must be positive");
  if (p.aopt != 0 && p.aopt != 2) throw util::InputError(at + "AOPT must be 0 or 2");
  if (p.macf < 1 || p.macf > 4) throw util::InputError(at + "MACF must be 1, 2, 3 or 4");
  for (std::size_t k = 0; k < 6; ++k)
    if (p.curve[k] < 0) throw util::InputError(at + std::string(kCurveFields[k]) + ": no curve");
  Honeycomb law;
  law.young = p.E;
  const Moduli m = moduliFromYoung(p.E, p.nu);
  law.shear = m.shear;
  law.bulk_modulus = m.bulk;
  law.rho0 = p.ro;
  law.sigy = p.sigy;
  law.vf = p.vf;
  law.mu = p.mu;
  law.bulk_visc = p.bulk;
  for (std::size_t k = 0; k < 6; ++k)
    law.curve[k] = curveOf(at, curves(p.curve[k]), std::string(kCurveFields[k]), true);
  if (p.rate_curve >= 0) law.rate = curveOf(at, curves(p.rate_curve), "LCSR", false);
  law.eu = p.eu;
  law.gu = p.gu;
  law.aopt = p.aopt;
  law.macf = p.macf;
  law.a0 = p.a;
  law.d0 = p.d;
  law.tsef = p.tsef;
  law.ssef = p.ssef;
  // The wave speed and hourglass control: the compacted moduli, or the uncompacted ones where
  // those are stiffer (no stiffness the law reaches goes beyond them).
  Moduli w = m;
  w.shear = std::max({w.shear, p.gu[0], p.gu[1], p.gu[2]});
  const double stiffest = std::max({p.eu[0], p.eu[1], p.eu[2]});
  w.bulk = std::max(w.bulk, stiffest - 4.0 / 3.0 * w.shear);
  law.moduli = w;
  return law;
}

double Honeycomb::Curve::at(double v) const {
  if (x.empty()) return 1.0;
  const double t = volumetric ? 1.0 - v : v;
  return std::max(util::onSegment(x, y, util::segmentOf(x, t), t), 0.0);
}

void Honeycomb::axes(const double (&va)[3], const double (&vd)[3], double (&q)[9]) const {
  double a[3] = {va[0], va[1], va[2]};
  double c[3] = {a[1] * vd[2] - a[2] * vd[1], a[2] * vd[0] - a[0] * vd[2],
                 a[0] * vd[1] - a[1] * vd[0]};
  const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  const double nc = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  if (!(na > 0.0) || !(nc > 0.0)) {  // degenerate: the global axes
    for (int k = 0; k < 9; ++k) q[k] = k % 4 == 0 ? 1.0 : 0.0;
    return;
  }
  for (int i = 0; i < 3; ++i) a[i] /= na, c[i] /= nc;
  const double b[3] = {c[1] * a[2] - c[2] * a[1], c[2] * a[0] - c[0] * a[2],
                       c[0] * a[1] - c[1] * a[0]};
  const double* col[3] = {a, b, c};
  // MACF: swap a-b (2), a-c (3), b-c (4).
  if (macf == 2) std::swap(col[0], col[1]);
  if (macf == 3) std::swap(col[0], col[2]);
  if (macf == 4) std::swap(col[1], col[2]);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) q[3 * i + k] = col[k][i];
}

namespace {

// Voigt index of the tensor component (i, j).
constexpr int kVoigt[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};

// t' = Q^T t Q (to the axes) or Q t Q^T (back), t symmetric in Voigt order (tensor shears).
std::array<double, 6> rotate(const double (&q)[9], const std::array<double, 6>& t, bool to_axes) {
  double m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = t[std::size_t(kVoigt[i][j])];
  // r(i, k) = Q_ik (to the axes: a column k per axis) or Q_ki (back).
  auto r = [&](int i, int k) { return to_axes ? q[3 * i + k] : q[3 * k + i]; };
  double tm[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int l = 0; l < 3; ++l)
      for (int k = 0; k < 3; ++k) tm[i][l] += m[i][k] * r(k, l);
  std::array<double, 6> out{};
  const int ij[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  for (int v = 0; v < 6; ++v) {
    const int a = ij[v][0], b = ij[v][1];
    double s = 0.0;
    for (int k = 0; k < 3; ++k) s += r(k, a) * tm[k][b];
    out[std::size_t(v)] = s;
  }
  return out;
}

}  // namespace

void Honeycomb::advance(Point& pt, const std::array<double, 6>& de, double dt, double v,
                        double rho_c_l, std::array<double, 6>& viscous) const {
  const double inv_dt = dt > 0.0 ? 1.0 / dt : 0.0;
  pt.compacted = pt.compacted || v <= vf;
  auto& s = pt.s;
  if (!pt.compacted) {
    const double beta = std::clamp((1.0 - v) / (1.0 - vf), 0.0, 1.0);
    // The strain rate's scale factor: LCSR at the Euclidean norm of the deviatoric rate.
    double lambda = 1.0;
    if (!rate.x.empty()) {
      const double m = (de[0] + de[1] + de[2]) / 3.0;
      double n2 = 0.0;
      for (int k = 0; k < 3; ++k) n2 += (de[k] - m) * (de[k] - m);
      for (int k = 3; k < 6; ++k) n2 += 2.0 * de[k] * de[k];
      const double r = std::sqrt(n2) * inv_dt;
      lambda = std::max(util::onSegment(rate.x, rate.y, util::segmentOf(rate.x, r), r), 0.0);
    }
    for (std::size_t k = 0; k < 6; ++k) {
      const double modulus =
          k < 3 ? eu[k] + beta * (young - eu[k]) : gu[k - 3] + beta * (shear - gu[k - 3]);
      // Tensor shears: the engineering strain is 2 de.
      s[k] += (k < 3 ? 1.0 : 2.0) * modulus * de[k];
      const double limit = lambda * curve[k].at(v);
      if (std::abs(s[k]) > limit) s[k] = std::copysign(limit, s[k]);
      viscous[k] = rho_c_l * mu * (modulus / (k < 3 ? young : shear)) * de[k] * inv_dt;
    }
    return;
  }
  // Compacted: elastic-perfectly plastic, radial return on the deviator, elastic pressure.
  const double tr = de[0] + de[1] + de[2];
  const double p_old = -(s[0] + s[1] + s[2]) / 3.0;
  std::array<double, 6> dev{};
  for (std::size_t k = 0; k < 6; ++k)
    dev[k] = s[k] + (k < 3 ? p_old : 0.0) + 2.0 * shear * (de[k] - (k < 3 ? tr / 3.0 : 0.0));
  double j2 = 0.0;
  for (std::size_t k = 0; k < 6; ++k) j2 += (k < 3 ? 1.0 : 2.0) * dev[k] * dev[k];
  const double seff = std::sqrt(1.5 * j2);
  if (seff > sigy) {
    const double scale = sigy / seff;
    for (auto& x : dev) x *= scale;
    pt.eps_p += (seff - sigy) / (3.0 * shear);
  }
  const double p_new = p_old - bulk_modulus * tr;
  for (std::size_t k = 0; k < 6; ++k) {
    s[k] = dev[k] - (k < 3 ? p_new : 0.0);
    viscous[k] = rho_c_l * mu * (de[k] - (k < 3 ? tr / 3.0 : 0.0)) * inv_dt;
  }
}

namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<double, 9>;  // row-major

Vec3 times(const Mat3& f, const Vec3& v) {
  Vec3 out;
  for (int i = 0; i < 3; ++i)
    out[std::size_t(i)] = f[std::size_t(3 * i)] * v[0] + f[std::size_t(3 * i + 1)] * v[1] +
                          f[std::size_t(3 * i + 2)] * v[2];
  return out;
}

double det3(const Mat3& f) {
  return f[0] * (f[4] * f[8] - f[5] * f[7]) - f[1] * (f[3] * f[8] - f[5] * f[6]) +
         f[2] * (f[3] * f[7] - f[4] * f[6]);
}

Mat3 inverse(const Mat3& f, double det) {
  const double inv = 1.0 / det;
  return {(f[4] * f[8] - f[5] * f[7]) * inv, (f[2] * f[7] - f[1] * f[8]) * inv,
          (f[1] * f[5] - f[2] * f[4]) * inv, (f[5] * f[6] - f[3] * f[8]) * inv,
          (f[0] * f[8] - f[2] * f[6]) * inv, (f[2] * f[3] - f[0] * f[5]) * inv,
          (f[3] * f[7] - f[4] * f[6]) * inv, (f[1] * f[6] - f[0] * f[7]) * inv,
          (f[0] * f[4] - f[1] * f[3]) * inv};
}

}  // namespace

void Honeycomb::axesNow(const double (&f)[9], const double* const (&edge)[6], int l,
                        double (&q)[9]) const {
  double va[3], vd[3];
  if (aopt == 2) {
    // A and D carried by F.
    const Mat3 fm = std::to_array(f);
    const Vec3 a = times(fm, a0), d = times(fm, d0);
    for (int i = 0; i < 3; ++i) va[i] = a[std::size_t(i)], vd[i] = d[std::size_t(i)];
  } else {
    // The element's current edges 1-2 and 1-4.
    for (int i = 0; i < 3; ++i) va[i] = edge[i][l], vd[i] = edge[3 + i][l];
  }
  axes(va, vd, q);
}

bool Honeycomb::strainFails(const double (&f)[9], const double (&q)[9], double det) const {
  const Mat3 fm = std::to_array(f);
  // The vectors that gave the axes at the start: A and D, or F^-1 of the current edges (the
  // current a and the a-d plane's normal c suffice: they span the same plane as the edges).
  double va[3], vd[3];
  if (aopt == 2) {
    for (int i = 0; i < 3; ++i) va[i] = a0[std::size_t(i)], vd[i] = d0[std::size_t(i)];
  } else {
    const Mat3 g = inverse(fm, det);
    // Undo MACF to find a and b as the axes were built, then carry them back.
    Vec3 axis[3];
    for (int k = 0; k < 3; ++k) axis[k] = {q[k], q[3 + k], q[6 + k]};
    if (macf == 2) std::swap(axis[0], axis[1]);
    if (macf == 3) std::swap(axis[0], axis[2]);
    if (macf == 4) std::swap(axis[1], axis[2]);
    const Vec3 ra = times(g, axis[0]), rb = times(g, axis[1]);
    for (int i = 0; i < 3; ++i) va[i] = ra[std::size_t(i)], vd[i] = rb[std::size_t(i)];
  }
  double q0[9];
  axes(va, vd, q0);
  // Each starting axis carried by F: its stretch, and the cosine of the angle between two.
  Vec3 fa[3];
  double len[3];
  for (int k = 0; k < 3; ++k) {
    fa[k] = times(fm, {q0[k], q0[3 + k], q0[6 + k]});
    len[k] = std::sqrt(fa[k][0] * fa[k][0] + fa[k][1] * fa[k][1] + fa[k][2] * fa[k][2]);
    if (tsef > 0.0 && len[k] - 1.0 >= tsef) return true;
  }
  for (int k = 0; k < 3 && ssef > 0.0; ++k) {
    const int j = (k + 1) % 3;
    const double dot = fa[k][0] * fa[j][0] + fa[k][1] * fa[j][1] + fa[k][2] * fa[j][2];
    if (std::abs(dot) >= ssef * len[k] * len[j]) return true;
  }
  return false;
}

void Honeycomb::update(PointBatch& p) const {
  const double m_compacted = bulk_modulus + 4.0 / 3.0 * shear;
  const double m_wave = std::max(moduli.bulk + 4.0 / 3.0 * moduli.shear, m_compacted);
  // A linear viscosity of ratio zeta shortens the stable step to L / c (sqrt(1 + zeta^2) -
  // zeta): the wave modulus that gives that step (the ratio of mu rho c L D is at most mu).
  const double amp = mu + std::sqrt(1.0 + mu * mu);
  for (int l = 0; l < p.n; ++l) {
    double f[9];
    for (int k = 0; k < 9; ++k) f[k] = p.F[k][l];
    const double det = det3(std::to_array(f));
    double q[9];
    axesNow(f, p.edge, l, q);
    // The point's state on the axes.
    Point pt;
    for (std::size_t k = 0; k < 6; ++k) pt.s[k] = p.h[k][l];
    pt.compacted = p.h[6][l] != 0.0;
    pt.eps_p = p.eps_p[l];
    std::array<double, 6> de_global{};
    for (std::size_t k = 0; k < 6; ++k) de_global[k] = p.de[k][l];
    // rho c L with rho = rho0 / V and rho c^2 the compacted wave modulus.
    const double rho = det > 0.0 ? rho0 / det : rho0;
    const double rho_c_l = std::sqrt(rho * m_compacted) * p.length[l];
    std::array<double, 6> visc{}, total{};
    advance(pt, rotate(q, de_global, true), p.dt, det, rho_c_l, visc);
    for (std::size_t k = 0; k < 6; ++k) {
      p.h[k][l] = pt.s[k];
      total[k] = pt.s[k] + visc[k];
    }
    p.h[6][l] = pt.compacted ? 1.0 : 0.0;
    p.eps_p[l] = pt.eps_p;
    const std::array<double, 6> s = rotate(q, total, false);
    for (std::size_t k = 0; k < 6; ++k) p.s[k][l] = s[k];
    if (p.modulus) p.modulus[l] = mu > 0.0 ? m_wave * amp * amp : m_wave;
    if ((tsef > 0.0 || ssef > 0.0) && det > 0.0 && strainFails(f, q, det)) p.failed[l] = 1;
  }
}

}  // namespace crumple::materials
