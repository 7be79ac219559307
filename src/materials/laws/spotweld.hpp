// *MAT_SPOTWELD (100): the weld material of spot-weld beams (*SECTION_BEAM ELFORM 9) and of
// solid (hexahedral) welds, elastic-plastic with linear isotropic hardening,
// sigma_y = SIGY + EH eps_p (LS-DYNA Keyword Manual vol. II, *MAT_SPOTWELD; Theory Manual,
// material model 100). Failure, the element deleted:
//   - by the effective plastic strain EFAIL at an integration point (beams: a point of the
//     section; solids: the element's point, von Mises plasticity of the 3-D stress);
//   - beams only, by the force resultants at mid-length when any of NRR .. MTT is given:
//       (max(N_rr, 0) / NRR)^2 + (N_rs / NRS)^2 + (N_rt / NRT)^2
//     + (M_rr / MRR)^2 + (M_ss / MSS)^2 + (M_tt / MTT)^2 >= 1,
//     a term left out where its limit is zero (compression does not fail the weld);
//   - beams only, at the time TFAIL when it is positive.
// Solid welds with TFAIL or NRR .. MTT (the resultants of a hexahedral weld or its cluster),
// the mass-scaling step DT, the filter NF and card 3 (the OPT failure models) are refused by
// name (model/build_mesh.cpp for what needs the part's section).
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "materials/law.hpp"
#include "materials/return_mapping.hpp"
#include "materials/uniaxial.hpp"

namespace crumple::materials {

struct Spotweld {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_SPOTWELD", "*MAT_100"};
  static constexpr Cost kCost = Cost::Plastic;
  static constexpr bool kPlastic = true;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  static constexpr BeamOnly kBeamOnly{9, "spot-weld beams (*SECTION_BEAM ELFORM 9)", true};

  struct Params {
    using Law = Spotweld;
    double E = 0, nu = 0, sigy = 0, eh = 0;
    double tfail = 0, efail = 0;                                  // 0: no failure by time / strain
    double nrr = 0, nrs = 0, nrt = 0, mrr = 0, mss = 0, mtt = 0;  // 0: term left out
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static Spotweld make(const Params& p, const CurveAt& curves, const std::string& at);

  Moduli moduli;
  double sigy = 0, eh = 0, efail = 0;
  ResultantFailure weld;
  // What a solid weld of these parameters would need that solids do not have (TFAIL, a
  // resultant limit), or empty.
  static std::string solidRefusal(const Params& p);
  void update(PointBatch& b) const;
  FibreLaw fibre() const;
  double failureStrain() const { return efail; }
  double deletionStep() const { return 0.0; }
};

}  // namespace crumple::materials
