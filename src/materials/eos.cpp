#include "materials/eos.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "util/curve.hpp"
#include "util/error.hpp"

namespace crumple::materials {

namespace {

// EOS 1 (Theory Manual, "Equation of State Models"): the quadratic terms act in compression
// only.
EosAffine linearPolynomial(const std::array<double, 7>& c, double mu) {
  const double mu2 = mu > 0.0 ? mu * mu : 0.0;
  return {c[0] + c[1] * mu + c[2] * mu2 + c[3] * mu * mu * mu, c[4] + c[5] * mu + c[6] * mu2};
}

// EOS 4: the Hugoniot fit s(u_p) = S1 u_p + S2 (u_p / u_s)^2 + ... in compression, linear in
// expansion; the Gruneisen gamma g0 + a mu multiplies the energy.
EosAffine gruneisen(const std::array<double, 7>& c, double rho0, double mu) {
  const double C = c[0], s1 = c[1], s2 = c[2], s3 = c[3], g0 = c[4], a = c[5];
  const double rc2 = rho0 * C * C;
  const double b = g0 + a * mu;
  if (!(mu > 0.0)) return {rc2 * mu, b};
  const double m1 = mu + 1.0;
  const double den = 1.0 - (s1 - 1.0) * mu - s2 * mu * mu / m1 - s3 * mu * mu * mu / (m1 * m1);
  return {rc2 * mu * (1.0 + (1.0 - 0.5 * g0) * mu - 0.5 * a * mu * mu) / (den * den), b};
}

std::span<const double> points(const EosTable& t,
                               const std::array<double, EosTable::kMaxPoints>& y) {
  return {y.data(), static_cast<std::size_t>(t.n)};
}

// The interpolant of one column of the table at ln V, its end segments continued.
double column(const EosTable& t, const std::array<double, EosTable::kMaxPoints>& y, double ln_v) {
  const auto x = points(t, t.ln_v);
  return util::onSegment(x, points(t, y), util::segmentOf(x, ln_v), ln_v);
}

// EOS 9, and EOS 8 (`compaction`): C and T at ln V while loading; EOS 8 above the least ln V
// reached follows the line of slope K(eps_min) from C(eps_min), K held at its end values past
// the table (eos.hpp).
EosAffine tabulated(const EosTable& t, bool compaction, const EosVolume& vol) {
  const double b = t.gamma * column(t, t.t, vol.ln_v);
  if (!compaction || !(vol.ln_v > vol.ln_v_min)) return {column(t, t.c, vol.ln_v), b};
  const double e_min = vol.ln_v_min;
  const double k =
      column(t, t.k, std::clamp(e_min, t.ln_v[0], t.ln_v[static_cast<std::size_t>(t.n - 1)]));
  return {column(t, t.c, e_min) - k * (vol.ln_v - e_min), b};
}

// The stiffest bulk modulus of a table: its segments' -d(C + GAMA T E0) / d ln V (the end
// segments go on past the table), and EOS 8's unloading moduli.
double stiffestOfTable(const Eos& eos) {
  const EosTable& t = eos.table;
  double k = 0.0;
  for (std::size_t i = 1; i < static_cast<std::size_t>(t.n); ++i) {
    const double p1 = t.c[i] + t.gamma * t.t[i] * eos.e0;
    const double p0 = t.c[i - 1] + t.gamma * t.t[i - 1] * eos.e0;
    k = std::max(k, -(p1 - p0) / (t.ln_v[i] - t.ln_v[i - 1]));
    if (eos.form == Eos::Form::TabulatedCompaction) k = std::max({k, t.k[i - 1], t.k[i]});
  }
  return k;
}

}  // namespace

EosVolume eosVolume(const Eos& eos, double x, double x_min) {
  const double ln_v0 = eos.v0 == 1.0 ? 0.0 : std::log(eos.v0);
  return {eos.v0 * std::exp(x), ln_v0 + x, ln_v0 + x_min};
}

EosVolume eosVolume(double v) {
  const double ln_v = std::log(v);
  return {v, ln_v, ln_v};
}

EosAffine eosAt(const Eos& eos, double rho0, const EosVolume& vol) {
  switch (eos.form) {
    case Eos::Form::Gruneisen:
      return gruneisen(eos.c, rho0, 1.0 / vol.v - 1.0);
    case Eos::Form::TabulatedCompaction:
      return tabulated(eos.table, true, vol);
    case Eos::Form::Tabulated:
      return tabulated(eos.table, false, vol);
    case Eos::Form::LinearPolynomial:
      break;
  }
  return linearPolynomial(eos.c, 1.0 / vol.v - 1.0);
}

double eosBulkModulus(const Eos& eos, double rho0) {
  // dp/dmu at fixed E by central differences, then the isentrope's energy change
  // dE/dmu = p / (1 + mu)^2. The forms have a continuous slope through mu = 0 but a jump in
  // curvature there (terms dropped in tension), which costs the difference O(h): h is small.
  // (A table's kinks make it the mean of two segments' slopes: the stiffest segment is taken
  // below.)
  const double mu0 = 1.0 / eos.v0 - 1.0, h = 1e-7;
  auto p = [&](double mu) {
    const EosAffine f = eosAt(eos, rho0, eosVolume(1.0 / (1.0 + mu)));
    return f.a + f.b * eos.e0;
  };
  const double dpdmu = (p(mu0 + h) - p(mu0 - h)) / (2.0 * h);
  const EosAffine f0 = eosAt(eos, rho0, eosVolume(eos.v0));
  const double m1 = 1.0 + mu0;
  const double k = m1 * (dpdmu + f0.b * p(mu0) / (m1 * m1));
  return isTabulated(eos) ? std::max(k, stiffestOfTable(eos)) : k;
}

std::string_view eosKeyword(const Eos& eos) {
  switch (eos.form) {
    case Eos::Form::Gruneisen:
      return "*EOS_GRUNEISEN";
    case Eos::Form::TabulatedCompaction:
      return "*EOS_TABULATED_COMPACTION";
    case Eos::Form::Tabulated:
      return "*EOS_TABULATED";
    case Eos::Form::LinearPolynomial:
      break;
  }
  return "*EOS_LINEAR_POLYNOMIAL";
}

void checkEos(const std::string& at, const Eos& eos, double rho0) {
  if (!(eos.v0 > 0.0)) throw util::InputError(at + "V0 must be positive");
  if (eos.form == Eos::Form::Gruneisen && !(eos.c[0] > 0.0))
    throw util::InputError(at + "the sound speed C must be positive");
  if (isTabulated(eos)) {
    const EosTable& t = eos.table;
    const std::string what = at + std::string(eosKeyword(eos)) + ": ";
    if (t.n < 2 || t.n > EosTable::kMaxPoints)
      throw util::InputError(what + "the table needs 2 to 10 points");
    for (std::size_t i = 0; i < static_cast<std::size_t>(t.n); ++i) {
      if (!std::isfinite(t.ln_v[i]) || !std::isfinite(t.c[i]) || !std::isfinite(t.t[i]) ||
          !std::isfinite(t.k[i]))
        throw util::InputError(what + "the table holds a value that is not a finite number");
      if (i > 0 && !(t.ln_v[i] > t.ln_v[i - 1]))
        throw util::InputError(what + "the volumetric strains EV must decrease point by point");
      if (eos.form == Eos::Form::TabulatedCompaction && !(t.k[i] > 0.0))
        throw util::InputError(what + "the unloading bulk moduli K must be positive");
    }
  }
  if (!(eosBulkModulus(eos, rho0) > 0.0))
    throw util::InputError(at + std::string(eosKeyword(eos)) +
                           " gives no stiffness at the initial state (bulk modulus <= 0), so no "
                           "wave speed for the time step");
}

EosStep eosEnergyStep(const Eos& eos, double rho0, double pc, double e_old, double v_mid,
                      const EosVolume& vol_new, double w_dev, double p_old, double tr) {
  // E_new = E_old + V_mid [w_dev - (p_old + p_new) tr / 2] with p_new = a + b E_new.
  const EosAffine f = eosAt(eos, rho0, vol_new);
  const double known = e_old + v_mid * (w_dev - 0.5 * (p_old + f.a) * tr);
  EosStep s;
  s.e = known / (1.0 + 0.5 * v_mid * f.b * tr);
  s.p = f.a + f.b * s.e;
  if (s.p < pc) {
    // Cut off in tension: the work of the step is done at the cutoff pressure.
    s.p = pc;
    s.e = e_old + v_mid * (w_dev - 0.5 * (p_old + pc) * tr);
  }
  return s;
}

double eosPointStep(const Eos& eos, double rho0, double pc, double& ln_v, double& de0,
                    double& ln_v_min, double w_dev, double p_old, double tr) {
  const double x_old = ln_v, x_new = x_old + tr, x_min = std::min(ln_v_min, x_new);
  const EosStep st = eosEnergyStep(eos, rho0, pc, eos.e0 + de0, eos.v0 * std::exp(x_old + 0.5 * tr),
                                   eosVolume(eos, x_new, x_min), w_dev, p_old, tr);
  ln_v = x_new;
  de0 = st.e - eos.e0;
  ln_v_min = x_min;
  return st.p;
}

}  // namespace crumple::materials
