#include "partition/advice.hpp"

#include <algorithm>
#include <cmath>

namespace crumple::partition {

namespace {

// Messages deep of a collective over P ranks (a tree or recursive doubling).
double collectiveDepth(int ranks) {
  return ranks > 1 ? std::ceil(std::log2(double(ranks))) : 0;
}

}  // namespace

Prediction predict(const Stats& s, const CycleCosts& serial, const Network& net, bool has_contact) {
  Prediction p;
  p.ranks = s.parts;
  p.imbalance = s.load_imbalance;
  double total_weight = 0, max_weight = 0;
  int64_t max_nodes = 0;
  for (const auto& r : s.ranks) {
    total_weight += r.weight;
    if (r.weight > max_weight) {
      max_weight = r.weight;
      p.max_elements = r.elements;
    }
    max_nodes = std::max(max_nodes, r.nodes);
    p.max_neighbours = std::max(p.max_neighbours, int(r.neighbours.size()));
    p.comm_s = std::max(p.comm_s, r.comm_s);  // computeStats took the network's speed
  }
  p.elements_s = total_weight > 0 ? serial.elements_s * max_weight / total_weight : 0;
  p.nodes_s = s.nodes > 0 ? serial.nodes_s * double(max_nodes) / double(s.nodes) : 0;
  const double depth = collectiveDepth(s.parts);
  const double contact_messages = has_contact ? kContactExchanges * depth * net.latency_s : 0;
  const double split = s.parts > 1 ? kContactImbalance / s.parts : 1.0;
  p.contact_s = serial.contact_split_s * std::min(1.0, split) + serial.contact_replicated_s;
  p.comm_s += depth * net.latency_s + contact_messages;
  p.cycle_s = p.elements_s + p.nodes_s + p.contact_s + p.comm_s;
  p.speedup = p.cycle_s > 0 ? serial.total() / p.cycle_s : 1;
  p.efficiency = p.speedup / s.parts;
  p.comm_share = p.cycle_s > 0 ? p.comm_s / p.cycle_s : 0;
  return p;
}

int recommend(const std::vector<Prediction>& p, double min_efficiency) {
  int best = 1;
  for (const auto& q : p)
    if (q.efficiency >= min_efficiency) best = std::max(best, q.ranks);
  return best;
}

std::vector<int> candidateRanks(int max_ranks) {
  std::vector<int> out;
  for (int base = 1; base <= max_ranks; base *= 2) {
    out.push_back(base);
    if (base >= 2 && base + base / 2 <= max_ranks) out.push_back(base + base / 2);
  }
  if (out.back() != max_ranks) out.push_back(max_ranks);
  return out;
}

}  // namespace crumple::partition
