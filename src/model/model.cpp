#include "model/model.hpp"

#include <algorithm>

namespace crumple::model {

namespace {
// Index of the segment [x[i], x[i+1]] that holds t, for x ascending with at least 2 points.
std::size_t segmentOf(const std::vector<double>& x, double t) {
  auto it = std::upper_bound(x.begin(), x.end(), t);
  std::size_t i = it == x.begin() ? 0 : static_cast<std::size_t>(it - x.begin()) - 1;
  return std::min(i, x.size() - 2);
}
double interpolate(const std::vector<double>& x, const std::vector<double>& y, std::size_t i,
                   double t) {
  const double dx = x[i + 1] - x[i];
  if (dx <= 0.0) return y[i + 1];
  return y[i] + (y[i + 1] - y[i]) * (t - x[i]) / dx;
}
}  // namespace

double Curve::value(double t) const {
  if (x.empty()) return 0.0;
  if (x.size() == 1 || t <= x.front()) return y.front();
  if (t >= x.back()) return y.back();
  return interpolate(x, y, segmentOf(x, t), t);
}

double Curve::valueExtrapolated(double t) const {
  if (x.empty()) return 0.0;
  if (x.size() == 1) return y.front();
  return interpolate(x, y, segmentOf(x, t), t);
}

namespace {
int32_t find(const std::unordered_map<int64_t, int32_t>& m, int64_t id) {
  auto it = m.find(id);
  return it == m.end() ? kNone : it->second;
}
template <class Ids>
void fill(std::unordered_map<int64_t, int32_t>& m, const Ids& ids) {
  m.clear();
  m.reserve(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) m.emplace(ids[i], static_cast<int32_t>(i));
}
}  // namespace

int32_t Model::nodeIndex(int64_t id) const {
  return find(node_index_, id);
}
int32_t Model::partIndex(int64_t id) const {
  return find(part_index_, id);
}
int32_t Model::curveIndex(int64_t id) const {
  return find(curve_index_, id);
}

void Model::releaseMesh() {
  nodes = Nodes{};
  solids = Solids{};
  node_sets.clear();
  part_sets.clear();
  segment_sets.clear();
  std::vector<Vec3>().swap(initial_velocity);
  std::unordered_map<int64_t, int32_t>().swap(node_index_);
}

void Model::finalize() {
  fill(node_index_, nodes.id);
  std::vector<int64_t> ids;
  for (const auto& p : parts) ids.push_back(p.id);
  fill(part_index_, ids);
  ids.clear();
  for (const auto& c : curves) ids.push_back(c.id);
  fill(curve_index_, ids);
}

}  // namespace crumple::model
