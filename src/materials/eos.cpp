#include "materials/eos.hpp"

#include <cmath>

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

}  // namespace

EosAffine eosAt(const Eos& eos, double rho0, double v) {
  const double mu = 1.0 / v - 1.0;
  return eos.form == Eos::Form::Gruneisen ? gruneisen(eos.c, rho0, mu)
                                          : linearPolynomial(eos.c, mu);
}

double eosBulkModulus(const Eos& eos, double rho0) {
  // dp/dmu at fixed E by central differences, then the isentrope's energy change
  // dE/dmu = p / (1 + mu)^2. Both forms have a continuous slope through mu = 0 but a jump in
  // curvature there (terms dropped in tension), which costs the difference O(h): h is small.
  const double mu0 = 1.0 / eos.v0 - 1.0, h = 1e-7;
  auto p = [&](double mu) {
    const EosAffine f = eosAt(eos, rho0, 1.0 / (1.0 + mu));
    return f.a + f.b * eos.e0;
  };
  const double dpdmu = (p(mu0 + h) - p(mu0 - h)) / (2.0 * h);
  const EosAffine f0 = eosAt(eos, rho0, eos.v0);
  const double m1 = 1.0 + mu0;
  return m1 * (dpdmu + f0.b * p(mu0) / (m1 * m1));
}

std::string_view eosKeyword(const Eos& eos) {
  return eos.form == Eos::Form::Gruneisen ? "*EOS_GRUNEISEN" : "*EOS_LINEAR_POLYNOMIAL";
}

void checkEos(const std::string& at, const Eos& eos, double rho0) {
  if (!(eos.v0 > 0.0)) throw util::InputError(at + "V0 must be positive");
  if (eos.form == Eos::Form::Gruneisen && !(eos.c[0] > 0.0))
    throw util::InputError(at + "the sound speed C must be positive");
  if (!(eosBulkModulus(eos, rho0) > 0.0))
    throw util::InputError(at + std::string(eosKeyword(eos)) +
                           " gives no stiffness at the initial state (bulk modulus <= 0), so no "
                           "wave speed for the time step");
}

EosStep eosEnergyStep(const Eos& eos, double rho0, double pc, double e_old, double v_mid,
                      double v_new, double w_dev, double p_old, double tr) {
  // E_new = E_old + V_mid [w_dev - (p_old + p_new) tr / 2] with p_new = a + b E_new.
  const EosAffine f = eosAt(eos, rho0, v_new);
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

double eosPointStep(const Eos& eos, double rho0, double pc, double& ln_v, double& de0, double w_dev,
                    double p_old, double tr) {
  const double x_old = ln_v, x_new = x_old + tr;
  const EosStep st = eosEnergyStep(eos, rho0, pc, eos.e0 + de0, eos.v0 * std::exp(x_old + 0.5 * tr),
                                   eos.v0 * std::exp(x_new), w_dev, p_old, tr);
  ln_v = x_new;
  de0 = st.e - eos.e0;
  return st.p;
}

}  // namespace crumple::materials
