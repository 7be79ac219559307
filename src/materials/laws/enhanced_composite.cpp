#include "materials/laws/enhanced_composite.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "util/error.hpp"

namespace crumple::materials {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// The history flags (EnhancedComposite::kHistory).
enum Mode : int {
  kFibreTension = 0,
  kFibreCompression = 1,
  kMatrixTension = 2,
  kMatrixCompression = 3
};

// Fields that change the answer and that Crumple does not honour: refused when not zero.
void rejectNonZero(LawInput& in, const deck::Card& c, std::initializer_list<std::string_view> f,
                   const std::string& why) {
  for (const auto name : f)
    if (c.real(name) != 0.0) in.reject(c, name, why);
}

// Reads each field into its member; each must be positive (else an error naming it).
void readPositive(const deck::Card& c,
                  std::initializer_list<std::pair<std::string_view, double*>> fields,
                  const char* why) {
  for (const auto& [name, to] : fields) {
    *to = c.real(name);
    if (!(*to > 0)) c.fail(name, why);
  }
}

// AOPT (shells): 0 the element's side 1-2, 2 the vector A projected on the element, 3 V x the
// normal; MANGLE (AOPT 0, 3) and the section's angles turn the axes about the normal. Reads
// cards 3 and 4; gives card 4 (its DFAILM, DFAILS are read with the failure cards).
const deck::Card& readAxes(LawInput& in, const deck::Card& c2, EnhancedComposite::Params& p) {
  const double aopt = c2.real("AOPT");
  const deck::Card& c3 = in.card("card 3");
  const deck::Card& c4 = in.card("card 4");
  p.mangle = c3.real("MANGLE");
  if (aopt != 0.0 && aopt != 2.0 && aopt != 3.0) {
    in.reject(c2, "AOPT",
              "only AOPT 0 (the element's side 1-2), 2 (vector A) and 3 (V x the normal) are "
              "supported");
    return c4;
  }
  p.aopt = static_cast<int>(aopt);
  const bool two = p.aopt == 2;
  const deck::Card& c = two ? c3 : c4;
  auto& vec = two ? p.a : p.v;
  for (int k = 0; k < 3; ++k)
    vec[std::size_t(k)] = c.real(std::string(two ? "A" : "V") + std::to_string(k + 1));
  if (p.aopt != 0 && vec[0] == 0 && vec[1] == 0 && vec[2] == 0)
    c.fail(two ? "A1" : "V1", "AOPT " + std::to_string(p.aopt) + " needs a non-zero vector");
  if (two && p.mangle != 0) in.ignore(c3, "MANGLE", "MANGLE applies to AOPT 0 and 3 only");
  return c4;
}

const deck::Card& readElasticCards(LawInput& in, EnhancedComposite::Params& p) {
  const deck::Card& c = in.card("card 1");
  readPositive(c, {{"EA", &p.ea}, {"EB", &p.eb}}, "must be positive");
  p.ec = c.real("EC");
  p.prba = c.real("PRBA");
  p.prca = c.real("PRCA");
  p.prcb = c.real("PRCB");
  if (!(p.ec >= 0)) c.fail("EC", "must not be negative");
  if (!(p.prba >= 0)) c.fail("PRBA", "must not be negative");
  if (!(p.prba * p.prba * p.ea / p.eb < 1.0))
    c.fail("PRBA", "nu_ab nu_ba = PRBA^2 EA / EB must be below 1 (positive definite)");
  const deck::Card& c2 = in.card("card 2");
  readPositive(c2, {{"GAB", &p.gab}, {"GBC", &p.gbc}, {"GCA", &p.gca}},
               "must be positive (the shells' transverse shear uses GBC, GCA)");
  rejectNonZero(in, c2, {"2WAY"}, "the two-way fibre option is not supported");
  return readAxes(in, c2, p);
}

// Fields LS-DYNA does not use in this setting: noted as ignored and dropped.
void ignoreNonZero(LawInput& in, const deck::Card& c,
                   std::initializer_list<std::pair<std::string_view, double*>> fields,
                   const std::string& why) {
  for (const auto& [name, v] : fields)
    if (*v != 0.0) {
      in.ignore(c, name, why);
      *v = 0.0;
    }
}

// The layer's strain limits (Keyword Manual vol. II, *MAT_054-055, cards 4 and 5): DFAILT the
// fibre tension strain, DFAILC the fibre compression strain (negative, required with DFAILT >
// 0), DFAILM the matrix strain in tension or compression and DFAILS the tensor shear strain
// (both positive, acting only when DFAILT > 0), EFS the effective strain; the manual restricts
// all of them to MAT_054, so they are noted as ignored with CRIT 55. EFS < 0 (the manual's
// full-tensor effective strain) is refused.
void readStrainLimits(LawInput& in, const deck::Card& c4, const deck::Card& c5,
                      EnhancedComposite::Params& p) {
  auto& l = p.lim;
  l.dfailm = c4.real("DFAILM");
  l.dfails = c4.real("DFAILS");
  l.dfailt = c5.real("DFAILT");
  l.dfailc = c5.real("DFAILC");
  l.efs = c5.real("EFS");
  if (!(l.dfailt >= 0)) c5.fail("DFAILT", "must not be negative (0: no fibre strain limit)");
  if (!(l.dfailm >= 0)) c4.fail("DFAILM", "must not be negative (a strain magnitude)");
  if (!(l.dfails >= 0)) c4.fail("DFAILS", "must not be negative (a strain magnitude)");
  if (l.efs < 0)
    in.reject(c5, "EFS",
              "EFS < 0 (the effective strain of the full strain tensor) is not supported; EFS > "
              "0 (volume preserving) is");
  if (p.crit == 55) {
    const std::string why = "the strain limits are *MAT_054 only (CRIT 54)";
    ignoreNonZero(in, c4, {{"DFAILM", &l.dfailm}, {"DFAILS", &l.dfails}}, why);
    ignoreNonZero(in, c5, {{"DFAILT", &l.dfailt}, {"DFAILC", &l.dfailc}, {"EFS", &l.efs}}, why);
    return;
  }
  if (l.dfailt > 0 && !(l.dfailc < 0)) c5.fail("DFAILC", "must be negative when DFAILT > 0");
  if (l.dfailt == 0) {
    const std::string why = "acts only with DFAILT > 0";
    ignoreNonZero(in, c4, {{"DFAILM", &l.dfailm}, {"DFAILS", &l.dfails}}, why);
    ignoreNonZero(in, c5, {{"DFAILC", &l.dfailc}}, why);
  }
}

void readFailureCards(LawInput& in, const deck::Card& c4, EnhancedComposite::Params& p) {
  const deck::Card& c5 = in.card("card 5");
  // TFAIL in (0, 0.1]: an element whose step falls below it is deleted (as *MAT_024 TDEL).
  p.tfail = std::max(c5.real("TFAIL"), 0.0);
  if (p.tfail > 0.1)
    in.reject(c5, "TFAIL",
              "TFAIL > 0.1 (deletion by the ratio of the element's step to its first) is not "
              "supported; TFAIL <= 0.1 (an absolute step) is");
  rejectNonZero(in, c5, {"ALPH"}, "the nonlinear shear term (ALPH) is not supported");
  const double soft = c5.real("SOFT");
  if (soft != 0.0 && soft != 1.0)
    in.reject(c5, "SOFT", "crashfront softening (SOFT other than 1) is not supported");
  p.fbrt = c5.real("FBRT");
  if (!(p.fbrt >= 0 && p.fbrt <= 1)) c5.fail("FBRT", "must lie in [0, 1]");
  p.ycfac = c5.real("YCFAC");
  if (!(p.ycfac > 0)) c5.fail("YCFAC", "must be positive");
  const deck::Card& c6 = in.card("card 6");
  readPositive(c6, {{"XC", &p.xc}, {"XT", &p.xt}, {"YC", &p.yc}, {"YT", &p.yt}, {"SC", &p.sc}},
               "the strength must be positive");
  const double crit = c6.real("CRIT");
  if (crit != 54.0 && crit != 55.0) c6.fail("CRIT", "must be 54 (Chang-Chang) or 55 (Tsai-Wu)");
  p.crit = static_cast<int>(crit);
  p.beta = c6.real("BETA");
  if (!(p.beta >= 0 && p.beta <= 1)) c6.fail("BETA", "must lie in [0, 1]");
  readStrainLimits(in, c4, c5, p);
}

// Card 8: the residual-strength factors SLIMT1, SLIMC1 (fibre), SLIMT2, SLIMC2 (matrix), SLIMS
// (shear), each in [0, 1] ("MAT_054 only": noted as ignored with CRIT 55).
void readResidualStrengths(LawInput& in, EnhancedComposite::Params& p) {
  auto& l = p.lim;
  const deck::Card& c8 = in.optionalCard("card 8");
  const std::initializer_list<std::pair<std::string_view, double*>> slim{{"SLIMT1", &l.slimt1},
                                                                         {"SLIMC1", &l.slimc1},
                                                                         {"SLIMT2", &l.slimt2},
                                                                         {"SLIMC2", &l.slimc2},
                                                                         {"SLIMS", &l.slims}};
  for (const auto& [name, to] : slim) {
    *to = c8.real(name);
    if (!(*to >= 0 && *to <= 1)) c8.fail(name, "must lie in [0, 1]");
  }
  if (p.crit == 55) ignoreNonZero(in, c8, slim, "the residual strengths are *MAT_054 only");
  rejectNonZero(in, c8, {"NCYRED"}, "the cycle reduction of the residual stress is not supported");
}

void readOptionalCards(LawInput& in, EnhancedComposite::Params& p) {
  const deck::Card& c7 = in.optionalCard("card 7");
  rejectNonZero(in, c7, {"EPSF", "EPSR"}, "transverse shear damage is not supported");
  readResidualStrengths(in, p);
  const deck::Card& c9 = in.optionalCard("card 9");
  rejectNonZero(in, c9, {"LCXC", "LCXT", "LCYC", "LCYT", "LCSC"},
                "rate-dependent strengths (curves) are not supported");
}

// One point's stress (material axes) after the step and its flags: the criteria, then the
// stresses of the failed modes.
struct PointState {
  double aa, bb, ab;
  double f[4];
};

}  // namespace

const deck::KeywordSpec& EnhancedComposite::cards() {
  using deck::I;
  using deck::kZeroIsDefault;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("EA"), R("EB"), R("EC"), R("PRBA"), R("PRCA"), R("PRCB")}},
       {"card 2", {R("GAB"), R("GBC"), R("GCA"), R("KF"), R("AOPT"), R("2WAY"), R("TI")}},
       {"card 3", {R("XP"), R("YP"), R("ZP"), R("A1"), R("A2"), R("A3"), R("MANGLE")}},
       {"card 4", {R("V1"), R("V2"), R("V3"), R("D1"), R("D2"), R("D3"), R("DFAILM"), R("DFAILS")}},
       {"card 5",
        {R("TFAIL"), R("ALPH"), R("SOFT", 1.0, kZeroIsDefault), R("FBRT"),
         R("YCFAC", 2.0, kZeroIsDefault), R("DFAILT"), R("DFAILC"), R("EFS")}},
       {"card 6",
        {R("XC"), R("XT"), R("YC"), R("YT"), R("SC"), R("CRIT", 54.0, kZeroIsDefault), R("BETA")}},
       {"card 7", {R("PFL"), R("EPSF"), R("EPSR"), R("TSMD"), R("SOFT2")}},
       {"card 8",
        {R("SLIMT1"), R("SLIMC1"), R("SLIMT2"), R("SLIMC2"), R("SLIMS"), R("NCYRED"), R("SOFTG")}},
       {"card 9", {R("LCXC"), R("LCXT"), R("LCYC"), R("LCYT"), R("LCSC"), R("DT")}}}};
  return spec;
}

EnhancedComposite::Params EnhancedComposite::read(LawInput& in) {
  Params p;
  const deck::Card& c4 = readElasticCards(in, p);
  readFailureCards(in, c4, p);
  readOptionalCards(in, p);
  return p;
}

EnhancedComposite EnhancedComposite::make(const Params& p, const CurveAt&, const std::string& at) {
  const double nu_ab = p.prba * p.ea / p.eb;
  const double d = 1.0 - nu_ab * p.prba;
  if (!(p.ea > 0 && p.eb > 0 && p.gab > 0 && p.gbc > 0 && p.gca > 0 && d > 0))
    throw util::InputError(at + "EA, EB, GAB, GBC, GCA must be positive and PRBA^2 EA / EB < 1");
  if (!(p.xc > 0 && p.xt > 0 && p.yc > 0 && p.yt > 0 && p.sc > 0))
    throw util::InputError(at + "the strengths XC, XT, YC, YT, SC must be positive");
  EnhancedComposite law;
  // The element's wave speed sqrt(E / (rho (1 - nu^2))) is then that of the stiffer axis,
  // max(Q11, Q22) / rho.
  law.moduli = moduliFromYoung(std::max(p.ea, p.eb), std::sqrt(nu_ab * p.prba));
  law.q11 = p.ea / d;
  law.q22 = p.eb / d;
  law.q12 = p.prba * p.ea / d;
  law.g2 = 2.0 * p.gab;
  law.ea = p.ea;
  law.eb = p.eb;
  law.zz_a = p.ec > 0 ? -p.prca / p.ec : 0.0;
  law.zz_b = p.ec > 0 ? -p.prcb / p.ec : 0.0;
  law.gbc = p.gbc;
  law.gca = p.gca;
  law.mangle = p.aopt == 2 ? 0.0 : p.mangle * kDegree;
  law.aopt = p.aopt;
  law.a = p.a;
  law.v = p.v;
  if (law.aopt != 0 && law.aopt != 2 && law.aopt != 3)
    throw util::InputError(at + "AOPT must be 0, 2 or 3");
  law.xc = p.xc;
  law.xt = p.xt;
  law.yc = p.yc;
  law.yt = p.yt;
  law.sc = p.sc;
  law.beta = p.beta;
  law.fbrt = p.fbrt;
  law.ycfac = p.ycfac;
  law.tfail = p.tfail;
  law.tsai_wu = p.crit == 55;
  law.lim = p.lim;
  return law;
}

double EnhancedComposite::axisAngle(const double e[3][3]) const {
  double d[3];
  if (aopt == 2) {  // A projected on the element's plane
    const double an = a[0] * e[2][0] + a[1] * e[2][1] + a[2] * e[2][2];
    for (int k = 0; k < 3; ++k) d[k] = a[std::size_t(k)] - an * e[2][k];
  } else {  // V x the normal
    d[0] = v[1] * e[2][2] - v[2] * e[2][1];
    d[1] = v[2] * e[2][0] - v[0] * e[2][2];
    d[2] = v[0] * e[2][1] - v[1] * e[2][0];
  }
  const double x = d[0] * e[0][0] + d[1] * e[0][1] + d[2] * e[0][2];
  const double y = d[0] * e[1][0] + d[1] * e[1][1] + d[2] * e[1][2];
  const double vec =
      aopt == 2 ? a[0] * a[0] + a[1] * a[1] + a[2] * a[2] : v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  if (!(x * x + y * y > 1e-12 * vec)) return std::numeric_limits<double>::quiet_NaN();
  return std::atan2(y, x);
}

void EnhancedComposite::transverseShear(double ply, double g[3]) const {
  const double c = std::cos(mangle + ply), s = std::sin(mangle + ply);
  g[0] = c * c * gca + s * s * gbc;
  g[1] = s * s * gca + c * c * gbc;
  g[2] = c * s * (gca - gbc);
}

namespace {

// The fibre strengths in force: after matrix compression Xc = YCFAC Yc and, with FBRT > 0,
// Xt = FBRT Xt (Keyword Manual, *MAT_054: FBRT, YCFAC).
double fibreTensionStrength(const EnhancedComposite& m, const double f[4]) {
  return f[kMatrixCompression] != 0 && m.fbrt > 0 ? m.fbrt * m.xt : m.xt;
}
double fibreCompressionStrength(const EnhancedComposite& m, const double f[4]) {
  return f[kMatrixCompression] != 0 ? m.ycfac * m.yc : m.xc;
}

// Whether the residual strengths hold a failed fibre, matrix or shear stress (SLIM > 0).
bool holdsFibre(const EnhancedComposite& m) {
  return m.lim.slimt1 > 0 || m.lim.slimc1 > 0;
}
bool holdsMatrix(const EnhancedComposite& m) {
  return m.lim.slimt2 > 0 || m.lim.slimc2 > 0;
}

// The modes the criteria newly reach.
struct NewModes {
  bool ft = false, fc = false, matrix = false;
};

// The criteria of the modes not yet reached, on the stress after the step; sets their flags.
NewModes checkCriteria(const EnhancedComposite& m, PointState& p) {
  const double ab = p.ab / m.sc;
  const bool matrix = p.f[kMatrixTension] != 0 || p.f[kMatrixCompression] != 0;
  const double xt = fibreTensionStrength(m, p.f), xc = fibreCompressionStrength(m, p.f);
  bool ft = false, fc = false, mt = false, mc = false;
  if (p.aa > 0) ft = (p.aa / xt) * (p.aa / xt) + m.beta * ab * ab >= 1.0;
  if (p.aa < 0) fc = (p.aa / xc) * (p.aa / xc) >= 1.0;
  if (!matrix) {
    const double bb = p.bb;
    double e;
    if (m.tsai_wu)
      e = bb * bb / (m.yc * m.yt) + ab * ab + (m.yc - m.yt) * bb / (m.yc * m.yt);
    else if (bb >= 0)
      e = (bb / m.yt) * (bb / m.yt) + ab * ab;
    else
      e = (bb / (2.0 * m.sc)) * (bb / (2.0 * m.sc)) +
          ((m.yc / (2.0 * m.sc)) * (m.yc / (2.0 * m.sc)) - 1.0) * bb / m.yc + ab * ab;
    mt = e >= 1.0 && bb >= 0;
    mc = e >= 1.0 && bb < 0;
  }
  if (ft) p.f[kFibreTension] = 1.0;
  if (fc) p.f[kFibreCompression] = 1.0;
  if (mt) p.f[kMatrixTension] = 1.0;
  if (mc) p.f[kMatrixCompression] = 1.0;
  return {ft, fc, mt || mc};
}

// The stresses of the failed modes: held between -SLIMC x strength and SLIMT x strength where
// a residual factor is set (*MAT_054's SLIMT1 ... SLIMS: the stress a mode keeps once past its
// maximum, as in *MAT_058; an elastic-perfectly plastic plateau), else dropped when the
// mode is reached (its modulus is then zero). Fibre tension drops the matrix and the shear too
// (Eb = Gab = 0, the manual's degradation).
void failedModeStresses(const EnhancedComposite& m, PointState& p, const NewModes& n) {
  const bool ft = p.f[kFibreTension] != 0, fibre = ft || p.f[kFibreCompression] != 0;
  const bool matrix = p.f[kMatrixTension] != 0 || p.f[kMatrixCompression] != 0;
  if (fibre && holdsFibre(m))
    p.aa = std::clamp(p.aa, -m.lim.slimc1 * fibreCompressionStrength(m, p.f),
                      m.lim.slimt1 * fibreTensionStrength(m, p.f));
  else if (n.fc || ft)
    p.aa = 0.0;
  if (ft) {
    p.bb = p.ab = 0.0;
    return;
  }
  if (matrix && holdsMatrix(m))
    p.bb = std::clamp(p.bb, -m.lim.slimc2 * m.yc, m.lim.slimt2 * m.yt);
  else if (n.matrix)
    p.bb = 0.0;
  if (matrix && m.lim.slims > 0)
    p.ab = std::clamp(p.ab, -m.lim.slims * m.sc, m.lim.slims * m.sc);
  else if (n.matrix)
    p.ab = 0.0;
}

// Whether the layer's total strain (ply axes; e_ab tensor shear) has reached a limit (Keyword
// Manual, *MAT_054 remarks): with DFAILT > 0 the fibre strain above DFAILT or below DFAILC, the
// matrix strain beyond DFAILM in tension or compression, the tensor shear strain beyond DFAILS;
// with EFS > 0 the effective strain above EFS. The effective strain is the volume-preserving one
// of the manual's EFS > 0, e_zz = -(e_aa + e_bb): sqrt(2/3 e_ij e_ij) = sqrt(4/3 (e_aa^2 + e_bb^2
// + e_aa e_bb + e_ab^2)), an invariant of the in-plane strain.
bool reachesStrainLimit(const EnhancedComposite::Limits& l, const double e[3]) {
  if (l.dfailt > 0 && (e[0] > l.dfailt || e[0] < l.dfailc)) return true;
  if (l.dfailm > 0 && std::abs(e[1]) > l.dfailm) return true;
  if (l.dfails > 0 && std::abs(e[2]) > l.dfails) return true;
  if (l.efs > 0) {
    const double q = e[0] * e[0] + e[1] * e[1] + e[0] * e[1] + e[2] * e[2];
    if (std::sqrt(4.0 / 3.0 * q) > l.efs) return true;
  }
  return false;
}

// The ply's stiffness with the moduli its failed modes leave (tensor shear: s_ab += g de_ab): a
// failed mode with a residual strength keeps its own modulus (no Poisson coupling).
struct Stiffness {
  double k11, k22, k12, g;
};

Stiffness stiffnessOf(const EnhancedComposite& m, const double f[4]) {
  const bool fibre = f[kFibreCompression] != 0 || f[kFibreTension] != 0;
  const bool matrix = f[kMatrixTension] != 0 || f[kMatrixCompression] != 0;
  const double k11 = fibre ? (holdsFibre(m) ? m.ea : 0.0) : (matrix ? m.ea : m.q11);
  const double k22 = matrix ? (holdsMatrix(m) ? m.eb : 0.0) : (fibre ? m.eb : m.q22);
  return {k11, k22, fibre || matrix ? 0.0 : m.q12, matrix && !(m.lim.slims > 0) ? 0.0 : m.g2};
}

}  // namespace

void EnhancedComposite::updatePlaneStress(PlaneStressPoints& b) const {
  constexpr int kStrain = 4, kLayerFailed = 7;
  for (int i = 0; i < b.n; ++i) {
    const double th = mangle + (b.ply != nullptr ? b.ply[i] : 0.0);
    const double c = std::cos(th), s = std::sin(th), cc = c * c, ss = s * s, cs = c * s;
    PointState p;
    for (int k = 0; k < 4; ++k) p.f[k] = b.h[k][i];
    const double sx = b.s[0][i], sy = b.s[1][i], sxy = b.s[2][i];
    const double dx = b.de[0][i], dy = b.de[1][i], dxy = b.de[2][i];
    // To the material axes (tensor shear), Hooke's law with the moduli the modes left.
    const double daa = cc * dx + ss * dy + 2.0 * cs * dxy;
    const double dbb = ss * dx + cc * dy - 2.0 * cs * dxy;
    const double dab = cs * (dy - dx) + (cc - ss) * dxy;
    const Stiffness k = stiffnessOf(*this, p.f);
    const double aa0 = cc * sx + ss * sy + 2.0 * cs * sxy;
    const double bb0 = ss * sx + cc * sy - 2.0 * cs * sxy;
    p.aa = aa0 + k.k11 * daa + k.k12 * dbb;
    p.bb = bb0 + k.k12 * daa + k.k22 * dbb;
    p.ab = cs * (sy - sx) + (cc - ss) * sxy + k.g * dab;
    NewModes n;
    if (p.f[kFibreTension] == 0) n = checkCriteria(*this, p);
    failedModeStresses(*this, p, n);
    // The total strain in the ply axes (the axes are fixed in the corotational frame, so the
    // increments add up) and the layer's strain limits.
    const double e[3] = {b.h[kStrain][i] + daa, b.h[kStrain + 1][i] + dbb,
                         b.h[kStrain + 2][i] + dab};
    const bool layer_failed = b.h[kLayerFailed][i] != 0 || reachesStrainLimit(lim, e);
    if (layer_failed) p.aa = p.bb = p.ab = 0.0;
    b.de_zz[i] = zz_a * (p.aa - aa0) + zz_b * (p.bb - bb0);
    b.s[0][i] = cc * p.aa + ss * p.bb - 2.0 * cs * p.ab;
    b.s[1][i] = ss * p.aa + cc * p.bb + 2.0 * cs * p.ab;
    b.s[2][i] = cs * (p.aa - p.bb) + (cc - ss) * p.ab;
    for (int k2 = 0; k2 < 4; ++k2) b.h[k2][i] = p.f[k2];
    for (int k2 = 0; k2 < 3; ++k2) b.h[kStrain + k2][i] = e[k2];
    b.h[kLayerFailed][i] = layer_failed ? 1.0 : 0.0;
    // The layer fails (Keyword Manual, *MAT_054 remarks) in fibre tension when DFAILT = 0, by
    // the strain limits otherwise; the element is deleted when all its layers have failed.
    const bool fails = layer_failed || (lim.dfailt == 0 && p.f[kFibreTension] != 0);
    if (b.failed != nullptr) b.failed[i] = fails ? 1 : 0;
  }
}

}  // namespace crumple::materials
