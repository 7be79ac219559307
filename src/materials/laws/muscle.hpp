// *MAT_MUSCLE (*MAT_156): the Hill-type muscle of LS-DYNA's human body models, for trusses
// (*SECTION_BEAM ELFORM 3) only (LS-DYNA Keyword Manual vol. II, *MAT_MUSCLE). Three elements
// act in parallel on the truss; with the stretch lambda = l / l_orig (l_orig = l0 / SNO, l0
// the initial length of the element) and the strain rate eps_dot = (dl / dt) / l_orig
// (positive when the muscle lengthens), the stress is
//   sigma = PIS a(t) f_l(lambda) f_v(eps_dot / (SRM f_r(lambda)))   contractile element
//         + PIS f_p(lambda)                                          parallel elastic element
//         + DMP eps_dot                                              damping element
// and the force sigma A (A the section's area, constant). a = ALM (< 0: curve |ALM| of time,
// else the constant), f_r = SFR, f_l = SVS, f_v = SVR (< 0: curve |value| of its argument,
// else 1), f_p = SSP (< 0: curve of lambda; 0: the exponential
// (exp(CER (lambda - 1) / SSM) - 1) / (exp(CER) - 1) for lambda > 1, 0 below; > 0: none).
// The nodal masses take the density RO / SNO, so that the mass is RO A l_orig. The curves of
// lambda and of the strain rate go on past their ends with their end slopes (util/curve.hpp);
// the activation, a curve of time, holds its end values, as a load curve. The
// formulation and the stable step are in docs/theory.md ("Muscles").
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "materials/law.hpp"
#include "materials/uniaxial.hpp"

namespace crumple::materials {

// A factor of the muscle law: a curve, or a constant where the deck gives no curve.
struct MuscleFactor {
  std::vector<double> x, y;  // empty: the constant
  double constant = 1.0;
  // Value and slope at t (the slope of a constant is 0).
  void at(double t, double& value, double& slope) const;
};

// The stress of a muscle point and the tangents the stable step needs.
struct MuscleResponse {
  double stress = 0.0;
  double modulus = 0.0;    // |d sigma / d lambda| (active and passive elements)
  double viscosity = 0.0;  // |d sigma / d eps_dot| (active element and DMP)
};

struct Muscle {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_MUSCLE", "*MAT_156"};
  static constexpr Cost kCost = Cost::Elastic;
  static constexpr bool kPlastic = false;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  // The Keyword Manual's element: trusses.
  static constexpr BeamOnly kBeamOnly{3, "trusses (*SECTION_BEAM ELFORM 3)"};

  struct Params {
    using Law = Muscle;
    double sno = 1, srm = 0, pis = 0, ssm = 0, cer = 0, dmp = 0;
    double alm = 0;  // the activation when constant (alm_curve < 0)
    // Model curve indices; -1: the constant (alm; 1 for sfr, svs, svr).
    int32_t alm_curve = -1, sfr = -1, svs = -1, svr = -1, ssp = -1;
    bool exponential = false;  // SSP = 0: the exponential parallel element; else none / curve
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static Muscle make(const Params& p, const CurveAt& curves, const std::string& at);

  // Nominal moduli (E = PIS, nu = 0) for whatever asks a law for its stiffness (beam contact);
  // the stable step uses the tangents of response().
  Moduli moduli;
  double sno = 1, srm = 0, pis = 0, ssm = 0, cer = 0, dmp = 0;
  bool exponential = false;
  MuscleFactor activation, rate_scale, length, velocity, passive;

  // The stress at stretch lambda and strain rate eps_dot at time t; the tangents with the
  // largest activation from t on (activationAhead), for the stable step.
  MuscleResponse response(double lambda, double eps_dot, double t) const;
  // The largest activation of the points of the ALM curve after t (the constant ALM).
  double activationAhead(double t) const;
  // The density of the nodal masses: RO / SNO.
  double massDensity(double ro) const { return ro / sno; }
  FibreLaw fibre() const;
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return 0.0; }
};

// The stable step of a muscle truss (docs/theory.md, "Muscles"): nodes of mass rho A L0 / 2,
// stiffness A M / l_orig and viscous coefficient A eta / l_orig between them, so with
// Lr^2 = L0 l_orig, omega^2 = 4 M / (rho Lr^2) and q = 2 eta / (rho Lr^2),
//   dt = 2 / (sqrt(omega^2 + q^2) + q)
// (the central difference limit with viscous damping, Belytschko, Liu & Moran 2000,
// sec. 6.3.3); infinite when M = eta = 0.
double muscleStep(const MuscleResponse& r, double rho, double L0, double l_orig);

}  // namespace crumple::materials
