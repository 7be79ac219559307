// *MAT_ELASTIC_PLASTIC_HYDRO (010): von Mises plasticity with isotropic hardening whose
// pressure comes from the part's equation of state (LS-DYNA Keyword Manual vol. II,
// *MAT_ELASTIC_PLASTIC_HYDRO; Theory Manual, "Material Model 10: Elastic-Plastic-Hydrodynamic").
// Solids only.
//
// Yield stress (Keyword Manual, remarks): with no EPS/ES table, the bilinear
//   sigma_y = SIG0 + EH eps_p        (EH the plastic hardening modulus, beta = 1: isotropic);
// with the table EPS1-16 / ES1-16 (at least two points), the piecewise-linear curve of ES
// against the effective plastic strain, extrapolated past its ends (SIG0 and EH not used).
// The deviator is returned radially to the surface (return_mapping.hpp, exact for the linear
// and piecewise-linear curves). The pressure is the EOS's with the time-centred energy update
// of *MAT_NULL (eos.hpp, eosEnergyStep) and is held at PC where it would fall below it
// (PC <= 0; PC = 0 means no cutoff, -infinity, as the manual says). FS > 0: the point fails
// (the element erodes) when the effective plastic strain reaches FS.
// History (kHistory = kEosHistory): h[0..2] = ln(V / V0), E - E0 and the least ln(V / V0) (the
// EOS's state, eos.hpp, as *MAT_NULL).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "materials/eos.hpp"
#include "materials/law.hpp"

namespace crumple::materials {

struct ElasticPlasticHydro {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_ELASTIC_PLASTIC_HYDRO",
                                                             "*MAT_010"};
  static constexpr Cost kCost = Cost::Plastic;
  static constexpr bool kPlastic = true;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  static constexpr int kHistory = kEosHistory;  // ln(V / V0), E - E0, least ln(V / V0)
  static constexpr bool kEos = true;            // its solids take the part's equation of state

  struct Params {
    using Law = ElasticPlasticHydro;
    double rho = 0, G = 0, sig0 = 0, eh = 0;
    double pc = 0;       // pressure cutoff (<= 0); 0 = none
    double fs = 0;       // effective plastic strain at failure; 0 = none
    int32_t curve = -1;  // model curve index of the EPS/ES table; -1 = bilinear
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  // `eos`: the part's equation of state (required).
  static ElasticPlasticHydro make(const Params& p, const CurveAt& curves, const std::string& at,
                                  const Eos* eos = nullptr);

  Moduli moduli;  // K: the EOS's bulk modulus at the initial state; G
  Params par;
  Eos eos;
  std::vector<double> curve_eps, curve_sig;  // the EPS/ES table; empty: bilinear
  void update(PointBatch& b) const;
  double failureStrain() const { return par.fs; }
  double deletionStep() const { return 0.0; }
  // The yield stress at an effective plastic strain and its slope.
  void flow(double eps_p, double& y, double& h) const;
  // The pressure cutoff as eosEnergyStep takes it (PC = 0: -infinity).
  double cutoff() const;
};

}  // namespace crumple::materials
