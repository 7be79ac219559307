// *MAT_NULL (009): a material without deviatoric strength (LS-DYNA Keyword Manual vol. II,
// *MAT_NULL; Theory Manual, "Material Model 9: Null Material").
//
// Solids: the pressure comes from the part's equation of state (*PART EOSID, materials/eos.hpp),
// which the Keyword Manual requires for solids (a solid part without one is refused). The
// deviatoric stress is the viscous stress s' = 2 MU e_dot' (e_dot' the deviatoric strain
// rate), so the total stress is s' - p I. The pressure is cut off at PC (<= 0; blank: the
// material carries no tension). The element erodes when its relative volume V exceeds TEROD
// (expansion) or falls below CEROD (compression), each when non-zero.
//
// The internal energy E per unit reference volume that the EOS reads is advanced with the work
// of the step, the same midpoint work the elements book as internal energy:
//   E_new = E_old + V_mid [ (s'_old + s'_new) / 2 : de - (p_old + p_new) / 2 tr(de) ],
// and since p_new = a + b E_new (eos.hpp) this is one linear equation in E_new, solved exactly
// (the time-centred energy update, implicit in p, of LS-DYNA's Theory Manual, "Equation of
// State Models", and of DYNA3D: Whirley & Engelmann, UCRL-MA-107254, 1993; after Wilkins,
// "Calculation of elastic-plastic flow", Methods in Computational Physics 3, 1964).
// History (kHistory = kEosHistory, eos.hpp): h[0] = ln(V / V0) integrated from the volumetric
// strain increments (d ln V = tr D dt), h[1] = E - E0, h[2] = the least ln(V / V0) reached
// (EOS 8's unloading); all start at zero.
//
// Shells and beams: bypassed in the element processing, as in LS-DYNA ("null shells" and
// "null beams" carry contact only): their elements give mass and inertia to their nodes and
// compute no force and no time step; YM and PR set the contact stiffness of their segments.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "materials/eos.hpp"
#include "materials/law.hpp"

namespace crumple::materials {

struct MatNull {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_NULL", "*MAT_009"};
  static constexpr Cost kCost = Cost::Elastic;
  static constexpr bool kPlastic = false;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  static constexpr int kHistory = kEosHistory;  // ln(V / V0), E - E0, least ln(V / V0)
  // Its solids take the part's equation of state (required); law.hpp.
  static constexpr bool kEos = true;
  // Its shells and beams are bypassed: mass only (law.hpp).
  static constexpr bool kMassOnlyStructures = true;

  struct Params {
    using Law = MatNull;
    double rho = 0, pc = 0, mu = 0, terod = 0, cerod = 0;
    double E = 0, nu = 0;  // YM, PR: the contact stiffness of null shells and beams
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  // `eos`: the part's equation of state (solids); none for shells and beams.
  static MatNull make(const Params& p, const CurveAt& curves, const std::string& at,
                      const Eos* eos = nullptr);

  Moduli moduli;  // K: the EOS's bulk modulus at the initial state (solids), else from YM, PR
  double rho0 = 0, pc = 0, mu = 0, terod = 0, cerod = 0;
  Eos eos;
  void update(PointBatch& b) const;
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return 0.0; }
};

}  // namespace crumple::materials
