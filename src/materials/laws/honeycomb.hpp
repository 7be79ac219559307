// *MAT_HONEYCOMB (026): LS-DYNA's orthotropic crushable honeycomb (Keyword Manual vol. II,
// *MAT_HONEYCOMB; Theory Manual, "Material Model 26: Honeycomb"). Solids only, as in LS-DYNA
// (one-point ELFORM 1, 10: the law needs the deformation gradient and the element's nodes).
//
// Before full compaction the six stress components on the material axes a, b, c are uncoupled:
// each is elastic with a modulus interpolated between the uncompacted one and the compacted
// material's, E_ij = E_iju + beta (E - E_iju) (G for the shears, G = E / (2 (1 + PR))),
// beta = max(min((1 - V) / (1 - VF), 1), 0) with V the relative volume, and each is limited in
// magnitude by its load curve (LCA, LCB, LCC, LCAB, LCBC, LCCA; LCB, LCC and LCS default to LCA,
// the shear curves to LCS) times the LCSR factor of the deviatoric strain rate's Euclidean norm.
// A curve's abscissa is the relative volume V, or the volumetric strain 1 - V when its first
// abscissa is 0 or less (Keyword Manual, the remarks of *MAT_026); curves go on past their ends
// with their end slopes and never limit below zero. Once V reaches VF the point is compacted for
// good: elastic-perfectly plastic and isotropic with E, PR and SIGY (radial return), its stress
// carried over. MU adds the viscous stress mu rho c L D (rho c^2 the compacted wave modulus,
// L the element's length), on the uncompacted axes scaled by E_ij / E (G_ij / G), deviatoric
// once compacted; it is not stored and the stable step allows for it (kWaveModulus).
//
// The stress is kept on the material axes (history h[0..5]), which follow the material: the
// axes given at the start (AOPT 2: A and D; AOPT 0: the element's edges 1-2 and 1-4) carried by
// F, a along F A, c normal to F A and F D, b = c x a (for AOPT 0 these are the element's
// current edges). MACF 2, 3, 4 swap a-b, a-c, b-c. TSEF, SSEF erode the element at a tensile
// strain of an axis (stretch - 1) or a shear strain between two axes (the cosine of their angle)
// of the axes given at the start. BULK 1: the bulk viscosity of *CONTROL_BULK_VISCOSITY and no
// MU; BULK 0: no bulk viscosity. Refused: AOPT 1, 3, 4 and < 0; a table for LCA.
// docs/theory.md, "Honeycomb".
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "materials/law.hpp"

namespace crumple::materials {

struct Honeycomb {
  static constexpr std::array<std::string_view, 2> kKeywords{"*MAT_HONEYCOMB", "*MAT_026"};
  static constexpr Cost kCost = Cost::Plastic;
  static constexpr bool kPlastic = true;  // the compacted material's plastic strain
  static constexpr bool kKinematic = false;
  static constexpr bool kDensity = true;
  static constexpr bool kDeformationGradient = true;
  static constexpr bool kElementGeometry = true;
  // h[0..5]: the stress on the material axes (aa bb cc ab bc ca); h[6]: 1 once compacted.
  static constexpr int kHistory = 7;
  static constexpr bool kWaveModulus = true;  // raised for MU's viscous stress

  // The six stress components in Voigt order on the material axes.
  enum Component { kAA, kBB, kCC, kAB, kBC, kCA };

  struct Params {
    using Law = Honeycomb;
    double E = 0, nu = 0;  // the compacted material's (and the contact stiffness's)
    double ro = 0;         // RO: the viscous stress's density
    double sigy = 0, vf = 0;
    double mu = 0;      // MU (0 with BULK 1)
    bool bulk = false;  // BULK 1: *CONTROL_BULK_VISCOSITY's bulk viscosity
    std::array<int32_t, 6> curve{-1, -1, -1, -1, -1, -1};  // model curve indices (Voigt order)
    int32_t rate_curve = -1;                               // LCSR, -1 for none
    std::array<double, 3> eu{}, gu{};                      // EAAU EBBU ECCU, GABU GBCU GCAU
    int aopt = 2;                                          // 0 (element nodes) or 2 (vectors A, D)
    int macf = 1;                                  // 1 none, 2 swap a-b, 3 swap a-c, 4 swap b-c
    std::array<double, 3> a{1, 0, 0}, d{0, 1, 0};  // AOPT 2, unit vectors
    double tsef = 0, ssef = 0;                     // 0: no failure
  };
  static const deck::KeywordSpec& cards();
  static Params read(LawInput& in);
  static Honeycomb make(const Params& p, const CurveAt& curves, const std::string& at);

  // A limiting curve and its abscissa: relative volume V, or volumetric strain 1 - V.
  struct Curve {
    std::vector<double> x, y;
    bool volumetric = false;
    double at(double v) const;  // the limit at relative volume v, >= 0
  };

  Moduli moduli;  // from E, PR, raised to the uncompacted moduli if those are stiffer
  double young = 0, shear = 0, bulk_modulus = 0, rho0 = 0, sigy = 0, vf = 0, mu = 0;
  bool bulk_visc = false;
  std::array<Curve, 6> curve;
  Curve rate;  // LCSR (empty: factor 1); abscissa the strain rate
  std::array<double, 3> eu{}, gu{};
  int aopt = 2, macf = 1;
  std::array<double, 3> a0{1, 0, 0}, d0{0, 1, 0};
  double tsef = 0, ssef = 0;

  void update(PointBatch& p) const;
  bool bulkViscosity() const { return bulk_visc; }
  double failureStrain() const { return 0.0; }
  double deletionStep() const { return 0.0; }

  // One point's state for update() and the tests: the stress on the material axes (in/out),
  // the compaction flag, the plastic strain; the strain increment on the material axes, dt, the
  // relative volume and rho c L of the viscous stress; out the viscous stress on the axes.
  struct Point {
    std::array<double, 6> s{};
    bool compacted = false;
    double eps_p = 0;
  };
  void advance(Point& pt, const std::array<double, 6>& de, double dt, double v, double rho_c_l,
               std::array<double, 6>& viscous) const;
  // The material axes (columns of q, q[3 i + k] = component i of axis k) from the vectors that
  // define a and the a-d plane, MACF applied.
  void axes(const double (&va)[3], const double (&vd)[3], double (&q)[9]) const;
  // The axes now of point l: AOPT 2 from F A and F D, AOPT 0 from the element's edges.
  void axesNow(const double (&f)[9], const double* const (&edge)[6], int l, double (&q)[9]) const;
  // TSEF, SSEF: whether an axis as given at the start is stretched by TSEF, or two of them
  // sheared by SSEF, at F (q: the axes now; det = det F > 0).
  bool strainFails(const double (&f)[9], const double (&q)[9], double det) const;
};

}  // namespace crumple::materials
