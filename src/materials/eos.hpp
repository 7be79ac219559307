// Equations of state: the pressure of a part's solids whose law leaves the volumetric response
// to the part's *EOS (*PART EOSID), as *MAT_NULL does (LS-DYNA Keyword Manual vol. II, "*EOS";
// Theory Manual, "Equation of State Models": EOS 1 Linear Polynomial, EOS 4 Gruneisen).
//
// Both forms give the pressure (positive in compression) as a function of the compression
// mu = rho / rho0 - 1 = 1 / V - 1 (V the relative volume) and of the internal energy E per
// unit reference volume, and both are affine in E: p = a(mu) + b(mu) E. That is what lets the
// law advance E and p together over a step by solving one linear equation (eos.cpp, and the
// energy update of laws/null.cpp).
//
//   Linear polynomial:  p = C0 + C1 mu + C2 mu^2 + C3 mu^3 + (C4 + C5 mu + C6 mu^2) E,
//                       the C2 and C6 terms dropped in tension (mu < 0).
//   Gruneisen, compressed (mu > 0):
//     p = rho0 C^2 mu [1 + (1 - g0/2) mu - a/2 mu^2]
//         / [1 - (S1 - 1) mu - S2 mu^2 / (mu + 1) - S3 mu^3 / (mu + 1)^2]^2 + (g0 + a mu) E
//   Gruneisen, expanded (mu <= 0):  p = rho0 C^2 mu + (g0 + a mu) E
//
// E0 and V0 are the initial energy and relative volume (V0 blank or 0: 1).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace crumple::materials {

// The deck's parameters of one equation of state (trivially copyable: stored in the Model).
struct Eos {
  enum class Form : uint8_t { LinearPolynomial = 1, Gruneisen = 4 };
  Form form = Form::LinearPolynomial;
  // Linear polynomial: C0..C6. Gruneisen: C, S1, S2, S3, GAMAO, A (c[6] unused).
  std::array<double, 7> c{};
  double e0 = 0.0;  // initial internal energy per unit reference volume
  double v0 = 1.0;  // initial relative volume
};

// p = a + b E at one relative volume.
struct EosAffine {
  double a = 0.0, b = 0.0;
};

// The equation of state at relative volume v; rho0 is the material's reference density.
EosAffine eosAt(const Eos& eos, double rho0, double v);

// The isentropic bulk modulus rho dp/drho at the initial state (V0, E0), along which
// dE = -p dV: K = (1 + mu) [dp/dmu + b p / (1 + mu)^2]. It sets the wave speed of the stable
// time step and of the hourglass and contact stiffnesses.
double eosBulkModulus(const Eos& eos, double rho0);

// The pressure and the energy per unit reference volume at the end of a step of a law whose
// solids take the part's equation of state (*MAT_NULL, *MAT_JOHNSON_COOK): E_old at the start,
// relative volumes V_mid (mid-step) and V_new, the deviatoric work w_dev = (s'_old + s'_new) / 2
// : de, the pressure p_old of the start and the volumetric strain increment tr(de).
//   E_new = E_old + V_mid [w_dev - (p_old + p_new) tr / 2],  p_new = a + b E_new
// is one linear equation in E_new, solved exactly (the time-centred energy update of the Theory
// Manual, "Equation of State Models", and of DYNA3D: Whirley & Engelmann, UCRL-MA-107254,
// 1993). Where p_new falls below the cutoff pc (<= 0) it is pc, and the work is done at pc.
struct EosStep {
  double p = 0.0, e = 0.0;
};
EosStep eosEnergyStep(const Eos& eos, double rho0, double pc, double e_old, double v_mid,
                      double v_new, double w_dev, double p_old, double tr);

// eosEnergyStep at an integration point whose history keeps ln(V / V0) (`ln_v`) and E - E0
// (`de0`), as the deviatoric laws with an equation of state do (*MAT_JOHNSON_COOK,
// *MAT_ELASTIC_PLASTIC_HYDRO): advances both over a step of volumetric strain tr and returns
// the new pressure.
double eosPointStep(const Eos& eos, double rho0, double pc, double& ln_v, double& de0, double w_dev,
                    double p_old, double tr);

// "*EOS_LINEAR_POLYNOMIAL" or "*EOS_GRUNEISEN", for messages.
std::string_view eosKeyword(const Eos& eos);

// Parameters that came through no reader (a Model built in code or received as bytes) checked
// as the readers do, and the initial state's bulk modulus required positive (a wave speed):
// util::InputError prefixed by `at`.
void checkEos(const std::string& at, const Eos& eos, double rho0);

}  // namespace crumple::materials
