#include "constraints/airbag.hpp"

#include <algorithm>
#include <cmath>

#include "util/error.hpp"

namespace crumple::constraints {

namespace {

void crossInto(const double* a, const double* b, double* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// The patch x(xi, eta) = a + b xi + c eta + d xi eta through x1..x4 at the corners
// (-1,-1), (1,-1), (1,1), (-1,1): b, c, d (a is the corner mean).
struct Patch {
  double b[3], c[3], d[3], mean[3];
};
Patch patchOf(const std::array<const double*, 4>& x) {
  Patch p{};
  for (int k = 0; k < 3; ++k) {
    p.b[k] = 0.25 * (-x[0][k] + x[1][k] + x[2][k] - x[3][k]);
    p.c[k] = 0.25 * (-x[0][k] - x[1][k] + x[2][k] + x[3][k]);
    p.d[k] = 0.25 * (x[0][k] - x[1][k] + x[2][k] - x[3][k]);
    p.mean[k] = 0.25 * (x[0][k] + x[1][k] + x[2][k] + x[3][k]);
  }
  return p;
}

// A = (x3 - x1) x (x4 - x2) / 2 = 4 b x c: the integral of n dA over the patch.
void areaVector(const std::array<const double*, 4>& x, double* area) {
  const double d1[3] = {x[2][0] - x[0][0], x[2][1] - x[0][1], x[2][2] - x[0][2]};
  const double d2[3] = {x[3][0] - x[1][0], x[3][1] - x[1][1], x[3][2] - x[1][2]};
  crossInto(d1, d2, area);
  for (int k = 0; k < 3; ++k) area[k] *= 0.5;
}

}  // namespace

double segmentVolume(const std::array<const double*, 4>& x) {
  // The flux of x / 3 through the patch: (1/3) integral(x . (x_xi x x_eta)) over [-1, 1]^2 =
  // (4/3) a . (b x c) = (1/3) a . A (the other terms integrate to zero); a triangle (x3 = x4)
  // is flat, where x . n is constant, so the corner mean serves as well.
  const Patch p = patchOf(x);
  double area[3];
  areaVector(x, area);
  return (p.mean[0] * area[0] + p.mean[1] * area[1] + p.mean[2] * area[2]) / 3.0;
}

void segmentPressureForces(const std::array<const double*, 4>& x, double q, double out[12]) {
  double area[3];
  areaVector(x, area);
  if (x[2] == x[3]) {  // a triangle: integral(N_i n dA) = A / 3 at each corner
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) out[3 * i + k] = q * area[k] / 3.0;
    for (int k = 0; k < 3; ++k) out[9 + k] = 0.0;
    return;
  }
  // integral(N_i (b x c + xi b x d + eta d x c)) = b x c + (xi_i b x d + eta_i d x c) / 3.
  const Patch p = patchOf(x);
  double bd[3], dc[3];
  crossInto(p.b, p.d, bd);
  crossInto(p.d, p.c, dc);
  static constexpr double kXi[4] = {-1, 1, 1, -1}, kEta[4] = {-1, -1, 1, 1};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k)
      out[3 * i + k] = q * (0.25 * area[k] + (kXi[i] * bd[k] + kEta[i] * dc[k]) / 3.0);
}

Airbags::Airbags(const model::Model& m, const domain::Subdomain& sd) : model_(&m) {
  for (const auto& def : m.airbags) {
    Bag bag;
    bag.def = &def;
    if (def.cn_curve != model::kNone) bag.cn_curve = &m.curves[std::size_t(def.cn_curve)];
    if (def.pv_curve != model::kNone) bag.pv_curve = &m.curves[std::size_t(def.pv_curve)];
    if (def.cn_dr_curve != model::kNone) bag.cn_dr_curve = &m.curves[std::size_t(def.cn_dr_curve)];
    for (std::size_t s = def.first; s < def.first + def.count; ++s)
      for (int32_t n : m.pressure_loads[s].nodes)
        if (const int32_t l = sd.localNode(n); l != model::kNone) bag.nodes.push_back(l);
    std::sort(bag.nodes.begin(), bag.nodes.end());
    bag.nodes.erase(std::unique(bag.nodes.begin(), bag.nodes.end()), bag.nodes.end());
    bags_.push_back(std::move(bag));
  }
  for (int32_t s : sd.pressure_segments) {
    const auto& load = m.pressure_loads[std::size_t(s)];
    if (load.airbag == model::kNone) continue;
    Segment seg{s, {}};
    for (int k = 0; k < 4; ++k)
      seg.nodes[std::size_t(k)] = sd.localNode(load.nodes[std::size_t(k)]);
    segments_.push_back(seg);
  }
}

std::vector<double> Airbags::volumes(const domain::NodeVector& x,
                                     const comm::Communicator& comm) const {
  // This rank's shares, then every rank's, added in ascending segment order.
  std::vector<Share> mine;
  mine.reserve(segments_.size());
  for (const Segment& s : segments_) {
    std::array<const double*, 4> corner{};
    for (std::size_t k = 0; k < 4; ++k) corner[k] = &x[3 * std::size_t(s.nodes[k])];
    mine.push_back({s.index, segmentVolume(corner)});
  }
  auto all = comm.allGather(mine);
  std::sort(all.begin(), all.end(),
            [](const Share& a, const Share& b) { return a.segment < b.segment; });
  std::vector<double> v(bags_.size(), 0.0);
  for (const Share& s : all)
    v[std::size_t(model_->pressure_loads[std::size_t(s.segment)].airbag)] += s.volume;
  return v;
}

void Airbags::update(double t, const domain::Subdomain& sd, const comm::Communicator& comm) {
  if (!initialised_) {
    const auto v0 = volumes(sd.x0, comm);
    for (std::size_t b = 0; b < bags_.size(); ++b) {
      // Segments numbered against the outward normal enclose a negative volume: the bag is
      // the same, its pressure pushes along -n.
      bags_[b].sign = v0[b] < 0.0 ? -1.0 : 1.0;
      bags_[b].initial = std::abs(v0[b]);
      if (!(bags_[b].initial > 0.0))
        throw util::InputError("*AIRBAG_SIMPLE_PRESSURE_VOLUME " +
                               std::to_string(bags_[b].def->id) +
                               ": the surface encloses no volume (is it closed?)");
    }
    initialised_ = true;
  }
  const auto v = volumes(sd.x, comm);
  for (std::size_t b = 0; b < bags_.size(); ++b) {
    Bag& bag = bags_[b];
    const model::Airbag& d = *bag.def;
    bag.volume = bag.sign * v[b];
    // V / V0 of the volumes scaled by VSCA (VINI = 0): VSCA cancels.
    const double relative = bag.volume / bag.initial;
    if (bag.pv_curve) {
      bag.pressure = d.psca * bag.pv_curve->value(relative);
    } else {
      const double cn = phase_ == model::Phase::Relaxation && bag.cn_dr_curve
                            ? bag.cn_dr_curve->value(t)
                        : bag.cn_curve ? model::loadFactor(bag.cn_curve, t, phase_)
                                       : d.cn;
      bag.pressure = relative > 0.0 ? d.psca * d.beta * cn / relative : 0.0;
    }
    bag.q = bag.sign * bag.pressure;
  }
}

void Airbags::addDampingForces(domain::Subdomain& sd, const comm::Communicator& comm) const {
  // The bag's mass-weighted mean velocity from its owned nodes on every rank, in node id order.
  struct NodeMomentum {
    int64_t id;
    int32_t bag;
    double m, p[3];
  };
  std::vector<NodeMomentum> mine;
  for (std::size_t b = 0; b < bags_.size(); ++b) {
    if (bags_[b].def->mwd == 0.0) continue;
    for (int32_t n : bags_[b].nodes) {
      if (!sd.node_owned[std::size_t(n)]) continue;
      const double m = sd.mass[std::size_t(n)];
      const double* v = &sd.v[3 * std::size_t(n)];
      mine.push_back({sd.node_id[std::size_t(n)], int32_t(b), m, {m * v[0], m * v[1], m * v[2]}});
    }
  }
  auto all = comm.allGather(mine);
  std::sort(all.begin(), all.end(), [](const NodeMomentum& a, const NodeMomentum& b) {
    return a.bag != b.bag ? a.bag < b.bag : a.id < b.id;
  });
  std::vector<std::array<double, 4>> sum(bags_.size(), {0.0, 0.0, 0.0, 0.0});
  for (const auto& e : all) {
    auto& s = sum[std::size_t(e.bag)];
    for (std::size_t k = 0; k < 3; ++k) s[k] += e.p[k];
    s[3] += e.m;
  }
  for (std::size_t b = 0; b < bags_.size(); ++b) {
    const double D = bags_[b].def->mwd;
    if (D == 0.0 || !(sum[b][3] > 0.0)) continue;
    for (int32_t n : bags_[b].nodes) {
      const std::size_t i = 3 * std::size_t(n);
      for (std::size_t k = 0; k < 3; ++k)
        sd.f_ext[i + k] -= D * sd.mass[std::size_t(n)] * (sd.v[i + k] - sum[b][k] / sum[b][3]);
    }
  }
}

}  // namespace crumple::constraints
