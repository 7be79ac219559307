// *MAT_ENHANCED_COMPOSITE_DAMAGE (054 / 055): an orthotropic elastic layer of a laminated shell
// with the failure criteria of Chang & Chang (1987), "A progressive damage model for laminated
// composites containing stress concentrations", J. Compos. Mater. 21:834-855, as LS-DYNA gives
// them (Keyword Manual vol. II, *MAT_054-055; Theory Manual, material models 22 and 54-55):
// CRIT 54 the Chang-Chang matrix criteria, CRIT 55 the Tsai-Wu matrix criterion (Tsai & Wu
// 1971). Shells only (plane stress, kLayered: each point turned by MANGLE plus its layer angle
// B_i of *SECTION_SHELL ICOMP 1, from the element's first axis, side 1-2: AOPT 0; or from the
// vector A projected on the element (AOPT 2, no MANGLE) or V x normal (AOPT 3), fixed in the
// element frame from the initial geometry).
//
// In the material axes a, b (hypoelastic, in the corotational element frame turned by the
// point's angle theta): s += Q de with
//   Q11 = Ea / D, Q22 = Eb / D, Q12 = nu_ba Ea / D, D = 1 - nu_ab nu_ba, nu_ab = nu_ba Ea / Eb,
//   s_ab += 2 Gab de_ab (tensor shear); transverse shear Gca (c-a), Gbc (b-c) through the
//   element (transverseShear).
// After the update each criterion is checked on the stress (strengths positive):
//   fibre tension     (s_aa > 0)  (s_aa / Xt)^2 + beta (s_ab / Sc)^2 >= 1
//   fibre compression (s_aa < 0)  (s_aa / Xc)^2 >= 1
//   matrix, CRIT 54   (s_bb >= 0) (s_bb / Yt)^2 + (s_ab / Sc)^2 >= 1
//                     (s_bb < 0)  (s_bb / 2Sc)^2 + ((Yc / 2Sc)^2 - 1) s_bb / Yc + (s_ab / Sc)^2 >=
//                     1
//   matrix, CRIT 55   s_bb^2 / (Yc Yt) + (s_ab / Sc)^2 + (Yc - Yt) s_bb / (Yc Yt) >= 1
// and a mode once reached stays (history): fibre tension Ea = Eb = Gab = nu = 0 (the point
// carries nothing: failed); fibre compression Ea = nu = 0 (s_aa dropped); matrix (either)
// Eb = Gab = nu = 0 (s_bb, s_ab dropped). After matrix compression the fibre strengths become
// Xc = YCFAC Yc and, with FBRT > 0, Xt = FBRT Xt.
// Residual strength (SLIMT1, SLIMC1, SLIMT2, SLIMC2, SLIMS, *MAT_054 only; the manual defines
// them as the lower stress limit a mode keeps once past its maximum, as *MAT_058): a failed mode
// with a factor > 0 keeps its modulus and its stress is held within the factor times the strength
// (elastic-perfectly plastic), instead of dropping to zero.
// Layer failure (Keyword Manual, *MAT_054 remarks: a layer fails by one of these rules; the
// element is deleted when all its layers have failed): DFAILT = 0, the fibre tension
// criterion; DFAILT > 0, the total fibre strain above DFAILT or below DFAILC, the matrix strain
// beyond DFAILM, the tensor shear strain beyond DFAILS; EFS > 0, the effective strain above EFS.
// The total strains are accumulated per point in the ply axes (history). The element also
// erodes when its time step falls below TFAIL (0 < TFAIL <= 0.1).
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "materials/law.hpp"
#include "materials/plane_stress.hpp"

namespace crumple::materials {

struct EnhancedComposite {
  static constexpr std::array<std::string_view, 3> kKeywords{"*MAT_ENHANCED_COMPOSITE_DAMAGE",
                                                             "*MAT_054", "*MAT_055"};
  static constexpr Cost kCost = Cost::Elastic;
  static constexpr bool kPlastic = false;
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  static constexpr bool kLayered = true;
  static constexpr bool kPointFailure = true;
  // h[0..3]: 1 once failed in fibre tension, fibre compression, matrix tension, matrix
  // compression (else 0); h[4..6]: the total strain in the ply axes e_aa, e_bb, e_ab (tensor
  // shear); h[7]: 1 once the layer has failed by a strain limit (DFAILT, DFAILC, DFAILM, DFAILS,
  // EFS).
  static constexpr int kHistory = 8;

  // The layer's strain limits (0 = none; DFAILC < 0) and the residual-strength factors.
  struct Limits {
    double dfailm = 0, dfails = 0, dfailt = 0, dfailc = 0, efs = 0;
    double slimt1 = 0, slimc1 = 0, slimt2 = 0, slimc2 = 0, slims = 0;
  };
  struct Params {
    using Law = EnhancedComposite;
    double ea = 0, eb = 0, ec = 0, prba = 0, prca = 0, prcb = 0;
    double gab = 0, gbc = 0, gca = 0;
    double mangle = 0;  // degrees
    int aopt = 0;       // 0: side 1-2; 2: A projected on the shell; 3: V x normal
    std::array<double, 3> a{}, v{};
    double xc = 0, xt = 0, yc = 0, yt = 0, sc = 0;
    double beta = 0, fbrt = 0, ycfac = 2.0;
    double tfail = 0;  // element deletion below this time step (0 = none)
    int crit = 54;
    Limits lim;
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static EnhancedComposite make(const Params& p, const CurveAt& curves, const std::string& at);

  Moduli moduli;  // for the element: wave speed (the stiffer axis), hourglass and drilling
  double q11 = 0, q22 = 0, q12 = 0, g2 = 0;  // intact Q (g2 = 2 Gab, tensor shear)
  double ea = 0, eb = 0;                     // the moduli left after matrix / fibre failure
  double zz_a = 0, zz_b = 0;  // thickness strain per stress: -nu_ca / Ec, -nu_cb / Ec
  double gbc = 0, gca = 0;
  double mangle = 0;  // radians
  int aopt = 0;
  std::array<double, 3> a{}, v{};
  double xc = 0, xt = 0, yc = 0, yt = 0, sc = 0, beta = 0, fbrt = 0, ycfac = 2.0;
  bool tsai_wu = false;
  double tfail = 0;
  Limits lim;
  void updatePlaneStress(PlaneStressPoints& b) const;
  // Transverse shear moduli in the element frame of a layer at `ply` (radians): g[0] xz-xz,
  // g[1] yz-yz, g[2] the coupling.
  void transverseShear(double ply, double g[3]) const;
  // Whether the a axis comes from a vector (AOPT 2, 3) rather than the element's side 1-2; then
  // axisAngle(e) is the angle of that axis about the normal e[2] from e[0] in an element frame
  // e (rows: e1, e2, normal), taken once from the initial geometry (NaN when the vector gives no
  // direction in the element's plane).
  bool elementAxes() const { return aopt != 0; }
  double axisAngle(const double e[3][3]) const;
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return tfail; }
};

}  // namespace crumple::materials
