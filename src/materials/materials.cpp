// Hypoelastic law, elastic constants and the model -> law translation (makeLaw).
// The plastic return mappings live in plastic.cpp.
#include "materials/materials.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>

#include "materials/soa.hpp"
#include "util/error.hpp"

namespace crumple::materials {

Moduli moduliFromYoung(double E, double nu) {
  // Isotropic linear elasticity: K = E / (3 (1 - 2 nu)), G = E / (2 (1 + nu)).
  return Moduli{E / (3.0 * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

namespace {
// Hypoelastic (Hooke's law on the rate of deformation): the kernel has already applied the
// Jaumann rotation, so the increment is ds = lambda tr(de) I + 2 G de with tensor shear
// components (2 G de_xy is the shear stress increment for de_xy = D_xy dt).
void elasticKernel(detail::Soa a, int n, double lam, double G2) {
  for (int i = 0; i < n; ++i) {
    const double lt = lam * (a.d0[i] + a.d1[i] + a.d2[i]);
    a.s0[i] += lt + G2 * a.d0[i];
    a.s1[i] += lt + G2 * a.d1[i];
    a.s2[i] += lt + G2 * a.d2[i];
    a.s3[i] += G2 * a.d3[i];
    a.s4[i] += G2 * a.d4[i];
    a.s5[i] += G2 * a.d5[i];
  }
}
}  // namespace

void Elastic::update(PointBatch& b) const {
  const double G2 = 2.0 * moduli.shear;
  elasticKernel(detail::soaOf(b), b.n, moduli.bulk - G2 / 3.0, G2);
}

namespace {

std::string at(const model::Material& m, const char* keyword) {
  return m.where.str() + ": " + keyword + " " + std::to_string(m.id) + ": ";
}

// E and nu must give positive K and G; the builder validates these too, but a law built
// from an unchecked Model must not silently produce negative wave speeds.
void checkElastic(const model::Material& m, const char* keyword, double E, double nu) {
  if (!(E > 0.0)) throw util::InputError(at(m, keyword) + "E must be positive");
  if (!(nu > -1.0 && nu < 0.5)) throw util::InputError(at(m, keyword) + "PR must lie in (-1, 0.5)");
}

// Ep = E Etan / (E - Etan) is singular for Etan = E and negative beyond it.
void checkTangent(const model::Material& m, const char* keyword, double E, double etan) {
  if (!(etan >= 0.0 && etan < E))
    throw util::InputError(at(m, keyword) + "ETAN must lie in [0, E)");
}

}  // namespace

Law makeLaw(const model::Material& m, const model::Model& model) {
  return std::visit(
      [&](const auto& law) -> Law {
        using T = std::decay_t<decltype(law)>;
        if constexpr (std::is_same_v<T, model::ElasticLaw>) {
          checkElastic(m, "*MAT_ELASTIC", law.E, law.nu);
          return Elastic{moduliFromYoung(law.E, law.nu)};
        } else if constexpr (std::is_same_v<T, model::PlasticKinematicLaw>) {
          const char* kw = "*MAT_PLASTIC_KINEMATIC";
          checkElastic(m, kw, law.E, law.nu);
          checkTangent(m, kw, law.E, law.etan);
          if (!(law.beta >= 0.0 && law.beta <= 1.0))
            throw util::InputError(at(m, kw) + "BETA must lie in [0, 1]");
          PlasticKinematic pk;
          pk.moduli = moduliFromYoung(law.E, law.nu);
          pk.sigy = law.sigy;
          pk.etan = law.etan;
          pk.beta = law.beta;
          pk.src = law.src;
          pk.srp = law.srp;
          pk.fs = law.fs;
          return pk;
        } else if constexpr (std::is_same_v<T, model::RigidLaw>) {
          // A rigid part computes no stress; its elastic constants serve contact stiffness.
          checkElastic(m, "*MAT_RIGID", law.E, law.nu);
          return Elastic{moduliFromYoung(law.E, law.nu)};
        } else if constexpr (std::is_same_v<T, model::SpringElasticLaw> ||
                             std::is_same_v<T, model::DamperViscousLaw> ||
                             std::is_same_v<T, model::SpringNonlinearLaw>) {
          throw util::InputError(at(m, model::materialKeyword(m.law)) +
                                 "is a spring or damper material: only discrete elements "
                                 "(*ELEMENT_DISCRETE) can use it");
        } else {
          static_assert(std::is_same_v<T, model::PiecewiseLinearLaw>,
                        "a continuum law needs its case in makeLaw");
          const char* kw = "*MAT_PIECEWISE_LINEAR_PLASTICITY";
          checkElastic(m, kw, law.E, law.nu);
          PiecewiseLinear pl;
          pl.moduli = moduliFromYoung(law.E, law.nu);
          pl.sigy = law.sigy;
          pl.etan = law.etan;
          pl.c = law.c;
          pl.p = law.p;
          pl.fail = law.fail;
          if (law.lcss != model::kNone) {
            // LCSS given: SIGY and ETAN are ignored (LS-DYNA keyword manual, MAT_024); the
            // initial yield stress is the curve's value at zero plastic strain.
            if (law.lcss < 0 || static_cast<std::size_t>(law.lcss) >= model.curves.size())
              throw util::InputError(at(m, kw) + "LCSS does not name a curve");
            const model::Curve& c = model.curves[static_cast<std::size_t>(law.lcss)];
            if (c.x.empty() || c.x.size() != c.y.size())
              throw util::InputError(at(m, kw) + "LCSS curve " + std::to_string(c.id) +
                                     " has no points");
            for (std::size_t k = 1; k < c.x.size(); ++k)
              if (!(c.x[k] >= c.x[k - 1]))
                throw util::InputError(at(m, kw) + "LCSS curve " + std::to_string(c.id) +
                                       " must have non-decreasing plastic strains");
            pl.curve_eps = c.x;
            pl.curve_sig = c.y;
            pl.sigy = c.valueExtrapolated(0.0);
          } else {
            checkTangent(m, kw, law.E, law.etan);
          }
          return pl;
        }
      },
      m.law);
}

}  // namespace crumple::materials
