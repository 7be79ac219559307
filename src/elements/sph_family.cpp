#include "elements/sph_family.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "elements/sph.hpp"
#include "util/error.hpp"

namespace crumple::elements {

namespace {

using util::Vec3;

// The particles' positions or velocities from the nodal arrays.
std::vector<Vec3> particleVectors(const domain::SphBlock& b, const domain::NodeVector& xv) {
  std::vector<Vec3> out(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) {
    const auto n = 3 * static_cast<std::size_t>(b.node[i]);
    out[i] = {xv[n], xv[n + 1], xv[n + 2]};
  }
  return out;
}

double soundSpeed(const domain::SphBlock& b, std::size_t i) {
  const auto& m = materials::moduliOf(b.groups[std::size_t(b.group[i])].law);
  return std::sqrt((m.bulk + 4.0 / 3.0 * m.shear) / b.rho[i]);
}

void keepStep(SphStatus& st, double dt, std::size_t i) {
  if (dt < st.dt_min) {
    st.dt_min = dt;
    st.dt_particle = static_cast<int64_t>(i);
  }
}

// Jaumann rotation of a Voigt stress (tensor shear) over dt by W = skew(L):
// sig += dt (W sig - sig W).
void rotateStress(std::array<double, 6>& s, const std::array<double, 9>& L, double dt) {
  const double S[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  double W[3][3];
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c)
      W[a][c] = 0.5 * (L[std::size_t(3 * a + c)] - L[std::size_t(3 * c + a)]);
  auto rate = [&](int a, int c) {
    double r = 0.0;
    for (int k = 0; k < 3; ++k) r += W[a][k] * S[k][c] - S[a][k] * W[k][c];
    return r;
  };
  static constexpr int kA[6] = {0, 1, 2, 0, 1, 2}, kC[6] = {0, 1, 2, 1, 2, 0};
  std::array<double, 6> out{};
  for (int k = 0; k < 6; ++k) out[std::size_t(k)] = s[std::size_t(k)] + dt * rate(kA[k], kC[k]);
  s = out;
}

// The law's update of one particle with the strain increment de; returns the stress work per
// unit volume, (sig_old + sig) / 2 : de.
double updateStress(domain::SphBlock& b, std::size_t i, const std::array<double, 6>& de,
                    double dt) {
  double s[6], d[6], eps = b.eps_p[i], alpha[6], hist[materials::kMaxHistory];
  const std::array<double, 6> s_old = b.sig[i];
  for (int k = 0; k < 6; ++k) {
    s[k] = s_old[std::size_t(k)];
    d[k] = de[std::size_t(k)];
    alpha[k] = b.alpha_back[i][std::size_t(k)];
  }
  for (int k = 0; k < materials::kMaxHistory; ++k) hist[k] = b.hist[i][std::size_t(k)];
  uint8_t failed = 0;
  materials::PointBatch pb;
  pb.n = 1;
  pb.dt = dt;
  for (int k = 0; k < 6; ++k) {
    pb.s[k] = &s[k];
    pb.de[k] = &d[k];
    pb.alpha[k] = &alpha[k];
  }
  pb.eps_p = &eps;
  for (int k = 0; k < materials::kMaxHistory; ++k) pb.h[k] = &hist[k];
  pb.failed = &failed;
  std::visit(
      [&](const auto& law) {
        if constexpr (materials::SolidLaw<std::decay_t<decltype(law)>>)
          law.update(pb);
        else
          materials::noUpdateFor(materials::Family::Solid);
      },
      b.groups[std::size_t(b.group[i])].law);
  double work = 0.0;
  for (int k = 0; k < 6; ++k) {
    work += (k < 3 ? 0.5 : 1.0) * (s_old[std::size_t(k)] + s[k]) * d[k];
    b.sig[i][std::size_t(k)] = s[k];
    b.alpha_back[i][std::size_t(k)] = alpha[k];
  }
  for (int k = 0; k < materials::kMaxHistory; ++k) b.hist[i][std::size_t(k)] = hist[k];
  b.eps_p[i] = eps;
  return work;
}

// Steps 3 and 4 of the pass for particle i.
void advanceParticle(domain::SphBlock& b, std::size_t i, double drho,
                     const std::array<double, 9>& L, double dt) {
  const auto& g = b.groups[std::size_t(b.group[i])];
  b.rho[i] += dt * drho;
  if (!(b.rho[i] > 0.0))
    throw util::NumericalError("SPH particle at node index " + std::to_string(b.node[i]) +
                               " (part " + std::to_string(g.part_id) +
                               "): its density fell to zero or below");
  // The particle's volume m / rho ~ h^d: dh/dt = h div(v) / d.
  const double div = L[0] + L[4] + L[8];
  b.h[i] = std::clamp(b.h[i] * (1.0 + dt * div / b.dim), g.hmin * g.h0, g.hmax * g.h0);
  rotateStress(b.sig[i], L, dt);
  std::array<double, 6> de{};
  de[0] = L[0] * dt;
  de[1] = L[4] * dt;
  de[2] = L[8] * dt;
  de[3] = 0.5 * (L[1] + L[3]) * dt;  // xy
  de[4] = 0.5 * (L[5] + L[7]) * dt;  // yz
  de[5] = 0.5 * (L[6] + L[2]) * dt;  // zx
  b.e_int[i] += b.mass[i] / b.rho[i] * updateStress(b, i, de, dt);
  b.c[i] = soundSpeed(b, i);
}

}  // namespace

SphStatus initializeSph(domain::SphBlock& b, const domain::NodeVector& x) {
  const std::size_t n = b.size();
  b.rho.resize(n);
  b.h.resize(n);
  b.c.resize(n);
  b.e_int.assign(n, 0.0);
  b.eps_p.assign(n, 0.0);
  b.sig.assign(n, std::array<double, 6>{});
  b.alpha_back.assign(n, std::array<double, 6>{});
  b.hist.assign(n, std::array<double, materials::kMaxHistory>{});
  const std::vector<Vec3> xs = particleVectors(b, x);
  for (std::size_t ig = 0; ig < b.groups.size(); ++ig) {
    auto& g = b.groups[ig];
    std::vector<Vec3> members;
    for (std::size_t i = 0; i < n; ++i)
      if (std::size_t(b.group[i]) == ig) members.push_back(xs[i]);
    if (g.sphini > 0.0) {
      g.h0 = g.sphini;
    } else {
      if (members.size() < 2)
        throw util::InputError("*SECTION_SPH of part " + std::to_string(g.part_id) +
                               ": one particle has no neighbour to set the smoothing length "
                               "from (give SPHINI)");
      g.h0 = sph::initialSmoothingLength(members, g.cslh);
    }
  }
  SphStatus st;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& g = b.groups[std::size_t(b.group[i])];
    b.rho[i] = g.rho0;
    b.h[i] = g.h0;
    b.c[i] = soundSpeed(b, i);
    keepStep(st, b.h[i] / b.c[i], i);
  }
  return st;
}

SphStatus computeSphForces(domain::SphBlock& b, const domain::NodeVector& x,
                           const domain::NodeVector& v, double dt, domain::NodeVector& f) {
  SphStatus st;
  const std::size_t n = b.size();
  if (n == 0) return st;
  const std::vector<Vec3> xs = particleVectors(b, x), vs = particleVectors(b, v);
  const auto pairs = sph::neighbourPairs(xs, b.h);
  sph::Particles p;
  p.dim = b.dim;
  p.x = xs;
  p.v = vs;
  p.mass = b.mass;
  p.rho = b.rho;
  p.h = b.h;
  p.sig = b.sig;
  p.c = b.c;
  p.alpha = b.alpha;
  p.beta = b.beta;
  std::vector<double> drho;
  std::vector<std::array<double, 9>> grad_v;
  sph::computeRates(p, pairs, drho, grad_v);
  for (std::size_t i = 0; i < n; ++i) advanceParticle(b, i, drho[i], grad_v[i], dt);
  // The forces at x(n) from the stress at t(n); spans still view the updated arrays. The
  // pairs are those of the pass's start: h changed by a fraction dt div(v) / 3 at most.
  std::vector<Vec3> force;
  std::vector<double> heat;
  sph::computeForces(p, pairs, force, &heat);
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = 3 * static_cast<std::size_t>(b.node[i]);
    for (int c = 0; c < 3; ++c) f[k + std::size_t(c)] += force[i][std::size_t(c)];
    b.e_int[i] += dt * heat[i];
    keepStep(st, b.h[i] / (b.c[i] + util::norm(vs[i])), i);
  }
  return st;
}

}  // namespace crumple::elements
