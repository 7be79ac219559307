#include "elements/tet_nodal.hpp"

#include <cmath>
#include <cstddef>

namespace crumple::elements {

namespace {

// The volume (x2 - x1) . ((x3 - x1) x (x4 - x1)) / 6 of the tetrahedron on the first four
// corners of `conn`.
double tetVolume(const domain::NodeVector& x, const std::array<int32_t, 8>& conn) {
  const double* p[4];
  for (int a = 0; a < 4; ++a) p[a] = &x[3 * static_cast<std::size_t>(conn[std::size_t(a)])];
  double d[3][3];
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) d[k][c] = p[k + 1][c] - p[0][c];
  const double cx = d[1][1] * d[2][2] - d[1][2] * d[2][1];
  const double cy = d[1][2] * d[2][0] - d[1][0] * d[2][2];
  const double cz = d[1][0] * d[2][1] - d[1][1] * d[2][0];
  return (d[0][0] * cx + d[0][1] * cy + d[0][2] * cz) / 6.0;
}

}  // namespace

void writeNodalVolumes(const domain::SolidBlock& blk, const domain::NodeVector& x0,
                       const domain::NodeVector& x, double* slots) {
  const auto ne = static_cast<std::ptrdiff_t>(blk.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < ne; ++i) {
    const auto e = static_cast<std::size_t>(i);
    double* slot = slots + 3 * (blk.slot_offset + 8 * e);
    const bool alive = blk.active[e] != 0;
    const double v0 = alive ? 0.25 * tetVolume(x0, blk.conn[e]) : 0.0;
    const double v = alive ? 0.25 * tetVolume(x, blk.conn[e]) : 0.0;
    for (int a = 0; a < 8; ++a) {
      slot[3 * a] = a < 4 ? v0 : 0.0;
      slot[3 * a + 1] = a < 4 ? v : 0.0;
      slot[3 * a + 2] = 0.0;
    }
  }
}

void nodalVolumetricStrain(const std::vector<double>& volumes, std::vector<double>& strain) {
  const std::size_t nn = volumes.size() / 2;
  strain.resize(nn);
#pragma omp parallel for schedule(static)
  for (std::size_t n = 0; n < nn; ++n) {
    const double v0 = volumes[2 * n], v = volumes[2 * n + 1];
    // A node whose tetrahedra have all inverted keeps a finite strain; the element check
    // (negative volume) ends the run in the same pass.
    strain[n] = v0 > 0.0 && v > 0.0 ? std::log(v / v0) : 0.0;
  }
}

}  // namespace crumple::elements
