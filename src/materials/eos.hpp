// Equations of state: the pressure of a part's solids whose law leaves the volumetric response
// to the part's *EOS (*PART EOSID), as *MAT_NULL does (LS-DYNA Keyword Manual vol. II, "*EOS";
// Theory Manual, "Equation of State Models": EOS 1 Linear Polynomial, EOS 4 Gruneisen, EOS 8
// Tabulated Compaction, EOS 9 Tabulated).
//
// Every form gives the pressure (positive in compression) as a function of the relative volume
// V (mu = rho / rho0 - 1 = 1 / V - 1, eps_V = ln V) and of the internal energy E per unit
// reference volume, and every form is affine in E: p = a(V) + b(V) E. That is what lets the
// law advance E and p together over a step by solving one linear equation (eos.cpp, and the
// energy update of laws/null.cpp).
//
//   Linear polynomial:  p = C0 + C1 mu + C2 mu^2 + C3 mu^3 + (C4 + C5 mu + C6 mu^2) E,
//                       the C2 and C6 terms dropped in tension (mu < 0).
//   Gruneisen, compressed (mu > 0):
//     p = rho0 C^2 mu [1 + (1 - g0/2) mu - a/2 mu^2]
//         / [1 - (S1 - 1) mu - S2 mu^2 / (mu + 1) - S3 mu^3 / (mu + 1)^2]^2 + (g0 + a mu) E
//   Gruneisen, expanded (mu <= 0):  p = rho0 C^2 mu + (g0 + a mu) E
//   Tabulated (EOS 9):  p = C(eps_V) + GAMA T(eps_V) E, nonlinear elastic
//   Tabulated compaction (EOS 8):  the same while loading (eps_V at or below the least eps_V
//     reached, eps_min); above it, unloading and reloading on the straight line of slope
//     K(eps_min) from the point of largest compression:
//       p = C(eps_min) - K(eps_min) (eps_V - eps_min) + GAMA T(eps_V) E
// C, T and K are the piecewise-linear interpolants of the deck's 2 to 10 points (EV_i, C_i,
// T_i, K_i), EV_i = ln V strictly decreasing (the manual's order, negative in compression).
// Past the table's ends C and T go on along their end segments (the manual: "LS-DYNA will
// extrapolate to find the coefficients C and T"); K, of which the manual says nothing there,
// keeps its end values, so that the unloading stiffness stays within the table's and the
// stable step computed from it holds.
//
// E0 and V0 are the initial energy and relative volume (V0 blank or 0: 1).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace crumple::materials {

// The state a point of a law with an equation of state keeps: its first kEosHistory history
// variables, all starting at zero:
//   h[0] = ln(V / V0)          integrated from the volumetric strain increments tr(de)
//   h[1] = E - E0
//   h[2] = the least ln(V / V0) reached (the largest compression: EOS 8 unloads from there)
inline constexpr int kEosHistory = 3;

// The points of a tabulated form (EOS 8, 9), stored with ln V ascending (the deck's order
// reversed): n in [2, 10].
struct EosTable {
  static constexpr int kMaxPoints = 10;
  int32_t n = 0;
  double gamma = 0.0;                                    // GAMA
  std::array<double, kMaxPoints> ln_v{}, c{}, t{}, k{};  // k: EOS 8's unloading bulk modulus
};

// The deck's parameters of one equation of state (trivially copyable: stored in the Model).
struct Eos {
  enum class Form : uint8_t {
    LinearPolynomial = 1,
    Gruneisen = 4,
    TabulatedCompaction = 8,
    Tabulated = 9
  };
  Form form = Form::LinearPolynomial;
  // Linear polynomial: C0..C6. Gruneisen: C, S1, S2, S3, GAMAO, A (c[6] unused). Unused by the
  // tabulated forms.
  std::array<double, 7> c{};
  EosTable table;   // the tabulated forms
  double e0 = 0.0;  // initial internal energy per unit reference volume
  double v0 = 1.0;  // initial relative volume
};

// Whether the form is one of the tabulated ones (EOS 8, 9).
inline bool isTabulated(const Eos& eos) {
  return eos.form == Eos::Form::TabulatedCompaction || eos.form == Eos::Form::Tabulated;
}

// p = a + b E at one state.
struct EosAffine {
  double a = 0.0, b = 0.0;
};

// Where a point is on its equation of state: the relative volume V, ln V and the least ln V
// it has reached (only EOS 8 reads it).
struct EosVolume {
  double v = 1.0, ln_v = 0.0, ln_v_min = 0.0;
};
// The volume of a point whose history holds x = ln(V / V0) and x_min, its least value.
EosVolume eosVolume(const Eos& eos, double x, double x_min);
// A volume on the loading path (ln_v_min = ln V).
EosVolume eosVolume(double v);

// The equation of state at one state; rho0 is the material's reference density.
EosAffine eosAt(const Eos& eos, double rho0, const EosVolume& vol);

// The bulk modulus for the wave speed of the stable time step and of the hourglass and contact
// stiffnesses: the isentropic rho dp/drho at the initial state (V0, E0), along which
// dE = -p dV: K = (1 + mu) [dp/dmu + b p / (1 + mu)^2]; for the tabulated forms the stiffest
// of that, of the table's segments -d(C + GAMA T E0) / d eps_V, and (EOS 8) of its unloading
// moduli K_i, as *MAT_SOIL_AND_FOAM takes the stiffest of its curve and KUN.
double eosBulkModulus(const Eos& eos, double rho0);

// The pressure and the energy per unit reference volume at the end of a step of a law whose
// solids take the part's equation of state (*MAT_NULL, *MAT_JOHNSON_COOK): E_old at the start,
// the relative volume V_mid at mid-step and the volume at the end, the deviatoric work
// w_dev = (s'_old + s'_new) / 2 : de, the pressure p_old of the start and the volumetric strain
// increment tr(de).
//   E_new = E_old + V_mid [w_dev - (p_old + p_new) tr / 2],  p_new = a + b E_new
// is one linear equation in E_new, solved exactly (the time-centred energy update of the Theory
// Manual, "Equation of State Models", and of DYNA3D: Whirley & Engelmann, UCRL-MA-107254,
// 1993). Where p_new falls below the cutoff pc (<= 0) it is pc, and the work is done at pc.
struct EosStep {
  double p = 0.0, e = 0.0;
};
EosStep eosEnergyStep(const Eos& eos, double rho0, double pc, double e_old, double v_mid,
                      const EosVolume& vol_new, double w_dev, double p_old, double tr);

// eosEnergyStep at an integration point whose history keeps the EOS's state (kEosHistory:
// `ln_v` = ln(V / V0), `de0` = E - E0, `ln_v_min` its least ln(V / V0)), as every law with an
// equation of state does (*MAT_NULL, *MAT_JOHNSON_COOK, *MAT_ELASTIC_PLASTIC_HYDRO): advances
// them over a step of volumetric strain tr and returns the new pressure.
double eosPointStep(const Eos& eos, double rho0, double pc, double& ln_v, double& de0,
                    double& ln_v_min, double w_dev, double p_old, double tr);

// "*EOS_LINEAR_POLYNOMIAL", "*EOS_GRUNEISEN", "*EOS_TABULATED_COMPACTION" or "*EOS_TABULATED",
// for messages.
std::string_view eosKeyword(const Eos& eos);

// Parameters that came through no reader (a Model built in code or received as bytes) checked
// as the readers do (a tabulated form: 2 to 10 points, ln V strictly increasing as stored,
// EOS 8's K_i positive), and the bulk modulus required positive (a wave speed):
// util::InputError prefixed by `at`.
void checkEos(const std::string& at, const Eos& eos, double rho0);

}  // namespace crumple::materials
