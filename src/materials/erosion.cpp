#include "materials/erosion.hpp"

#include <algorithm>
#include <cmath>

namespace crumple::materials {

namespace {

constexpr uint32_t bit(Criterion c) {
  return 1U << static_cast<int>(c);
}

constexpr uint32_t kStrainCriteria =
    bit(Criterion::MinPrincipalStrain) | bit(Criterion::EffectiveStrain) |
    bit(Criterion::VolumetricStrain) | bit(Criterion::MaxPrincipalStrain) |
    bit(Criterion::ShearStrain) | bit(Criterion::Thinning) | bit(Criterion::MajorStrain);
constexpr uint32_t kShellOnly = bit(Criterion::Thinning) | bit(Criterion::MajorStrain);
constexpr uint32_t kPrincipalStrain = bit(Criterion::MinPrincipalStrain) |
                                      bit(Criterion::MaxPrincipalStrain) |
                                      bit(Criterion::ShearStrain);

// sqrt(3/2 d:d) of the deviator d of t (tensor shear components counted twice).
double deviatoricNorm(const Voigt& t) {
  const double m = (t[0] + t[1] + t[2]) / 3.0;
  const double a = t[0] - m, b = t[1] - m, c = t[2] - m;
  return std::sqrt(1.5 * (a * a + b * b + c * c + 2.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5])));
}

// The *MAT_ADD_EROSION criteria that hold (Keyword Manual vol. II, *MAT_ADD_EROSION, cards 1-2).
int criteriaMet(const Erosion& er, const Voigt& s, const Voigt& e, double time) {
  auto on = [&](Criterion c) { return er.has(c); };
  auto lim = [&](Criterion c) { return er.at(c); };
  int met = 0;
  const double p = -(s[0] + s[1] + s[2]) / 3.0;
  if (on(Criterion::MaxPressure) && p >= lim(Criterion::MaxPressure)) ++met;
  if (on(Criterion::MinPressure) && p <= lim(Criterion::MinPressure)) ++met;
  if (on(Criterion::MaxPrincipalStress) &&
      principalOf(s).value[2] >= lim(Criterion::MaxPrincipalStress))
    ++met;
  if (on(Criterion::VonMises) && deviatoricNorm(s) >= lim(Criterion::VonMises)) ++met;
  // Effective strain sqrt(2/3 e':e') = (2/3) sqrt(3/2 e':e').
  if (on(Criterion::EffectiveStrain) &&
      2.0 / 3.0 * deviatoricNorm(e) >= lim(Criterion::EffectiveStrain))
    ++met;
  if (on(Criterion::VolumetricStrain)) {
    const double v = e[0] + e[1] + e[2], l = lim(Criterion::VolumetricStrain);
    if (l > 0.0 ? v >= l : v <= l) ++met;
  }
  if (er.active & kPrincipalStrain) {
    const auto ev = principalOf(e).value;  // ascending
    if (on(Criterion::MinPrincipalStrain) && ev[0] <= lim(Criterion::MinPrincipalStrain)) ++met;
    if (on(Criterion::MaxPrincipalStrain) && ev[2] >= lim(Criterion::MaxPrincipalStrain)) ++met;
    if (on(Criterion::ShearStrain) && 0.5 * (ev[2] - ev[0]) >= lim(Criterion::ShearStrain)) ++met;
  }
  if (on(Criterion::FailureTime) && time >= lim(Criterion::FailureTime)) ++met;
  return met;
}

// The shell criteria of *MAT_123, each enough on its own (Keyword Manual vol. II,
// *MAT_MODIFIED_PIECEWISE_LINEAR_PLASTICITY, EPSTHIN and EPSMAJ).
bool shellCriterionHolds(const Erosion& er, const Voigt& e) {
  if (er.has(Criterion::Thinning) && -e[2] >= er.at(Criterion::Thinning)) return true;
  if (er.has(Criterion::MajorStrain)) {
    const double m = 0.5 * (e[0] + e[1]), r = std::hypot(0.5 * (e[0] - e[1]), e[3]);
    if (m + r >= er.at(Criterion::MajorStrain)) return true;
  }
  return false;
}

}  // namespace

bool Erosion::needsStrain() const {
  return (active & kStrainCriteria) != 0;
}

Erosion Erosion::forSolids() const {
  Erosion s = *this;
  s.active &= ~kShellOnly;
  return s;
}

bool pointFails(const Erosion& er, const Voigt& s, const Voigt& e, double time) {
  if (shellCriterionHolds(er, e)) return true;
  const uint32_t added = er.active & ~kShellOnly;
  return added != 0 && criteriaMet(er, s, e, time) >= std::max(1, er.ncs);
}

}  // namespace crumple::materials
