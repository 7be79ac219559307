// Beam end releases: the condensation of beam_release.hpp.
#include "elements/beam_release.hpp"

#include <cstddef>

namespace crumple::elements {

namespace {

// One free deformation of a 1 x 1 block (elongation or twist): the resultant R_old + k dd is
// zero after the step.
void releaseAxis(double k, double R_old, double& dd) {
  if (k > 0.0) dd = -R_old / k;
}

// The conditions of one bending plane: G_1 = 0, G_2 = 0, G_1 + G_2 = 0 (bits 1, 2, 4).
void releasePlane(int conditions, const std::array<double, 3>& k, double R1, double R2, double& d1,
                  double& d2) {
  if (conditions == 0) return;
  const double k11 = k[0], k12 = k[1], k22 = k[2];
  // Two or more conditions: both resultants zero, d = -K^-1 R_old.
  if (conditions != 1 && conditions != 2 && conditions != 4) {
    const double det = k11 * k22 - k12 * k12;
    if (!(det > 0.0)) return;
    d1 = -(k22 * R1 - k12 * R2) / det;
    d2 = -(k11 * R2 - k12 * R1) / det;
    return;
  }
  // One condition c . R = 0 with the free deformation c.
  const double c1 = conditions == 2 ? 0.0 : 1.0, c2 = conditions == 1 ? 0.0 : 1.0;
  const double kc1 = k11 * c1 + k12 * c2, kc2 = k12 * c1 + k22 * c2;
  const double ckc = c1 * kc1 + c2 * kc2;
  if (!(ckc > 0.0)) return;
  const double trial = c1 * (R1 + k11 * d1 + k12 * d2) + c2 * (R2 + k12 * d1 + k22 * d2);
  const double alpha = -trial / ckc;
  d1 += alpha * c1;
  d2 += alpha * c2;
}

// Bit `bit` of end `end` (domain::BeamSection::release: six per end).
bool has(int release, int end, int bit) {
  return (release >> (6 * end + bit) & 1) != 0;
}

}  // namespace

void applyReleases(int release, const DeformationStiffness& K, const std::array<double, 6>& R_old,
                   std::array<double, 6>& dd) {
  if (release == 0) return;
  auto either = [&](int bit) { return has(release, 0, bit) || has(release, 1, bit); };
  if (either(0)) releaseAxis(K.axial, R_old[0], dd[0]);
  if (either(3)) releaseAxis(K.torsion, R_old[1], dd[1]);
  // Plane s: G_1s, G_2s (moments about s; the shear along t); plane t likewise.
  const int plane_s =
      (has(release, 0, 4) ? 1 : 0) | (has(release, 1, 4) ? 2 : 0) | (either(2) ? 4 : 0);
  const int plane_t =
      (has(release, 0, 5) ? 1 : 0) | (has(release, 1, 5) ? 2 : 0) | (either(1) ? 4 : 0);
  releasePlane(plane_s, K.s, R_old[2], R_old[4], dd[2], dd[4]);
  releasePlane(plane_t, K.t, R_old[3], R_old[5], dd[3], dd[5]);
}

}  // namespace crumple::elements
