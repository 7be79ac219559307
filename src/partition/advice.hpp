// How many ranks to use: the wall time per cycle predicted for P ranks from the deck's own
// serial cycle (measured), its partition for P ranks, and the machine's message latency and
// bandwidth (docs/parallel.md, "How many ranks"). The seed set out to "provide guidelines to
// the analyst for selecting an optimal number of processors"; this is that guideline, made
// from the model rather than from a rule of thumb.
#pragma once

#include <vector>

#include "partition/partition.hpp"

namespace crumple::partition {

// One serial cycle of the deck, split by how each part of it scales with the ranks.
struct CycleCosts {
  double elements_s = 0;            // element kernels and force gather: by element weight
  double nodes_s = 0;               // constraints, time integration, the rest: by node count
  double contact_split_s = 0;       // contact checks and forces: divided among the ranks
  double contact_replicated_s = 0;  // bucket sorts, boxes, records: every rank repeats them
  double total() const { return elements_s + nodes_s + contact_split_s + contact_replicated_s; }
};

struct Network {
  double latency_s = 2e-6;             // per message
  double bandwidth_bytes_per_s = 5e9;  // per link
  bool measured = false;               // false: CommModel's defaults
};

// The contact checks of the busiest rank of each cycle relative to the mean, and the exchanges
// a contact cycle makes (positions, travel maximum, records), each a collective of about
// log2(P) messages deep (docs/parallel.md, "Contact"). The re-cuts hold each rank's sum of
// checks under 1.25 times the mean, but which rank is busiest changes from cycle to cycle and
// each cycle waits at its records for that cycle's busiest: measured at 2 ranks as (checks +
// the wait at the contact exchanges) over the mean checks (summary.json timing_by_rank), 1.2 to
// 1.6 on the contact examples (docs/parallel.md, "How many ranks").
inline constexpr double kContactImbalance = 1.4;
inline constexpr int kContactExchanges = 3;

struct Prediction {
  int ranks = 1;
  int64_t max_elements = 0;  // on the heaviest rank
  double imbalance = 0;      // max weight / mean weight - 1
  int max_neighbours = 0;
  double elements_s = 0, nodes_s = 0, contact_s = 0, comm_s = 0;  // per cycle, slowest rank
  double cycle_s = 0;
  double speedup = 1, efficiency = 1;
  double comm_share = 0;  // messages (element exchange, step minimum, contact) / cycle
};

// The cycle on P = s.parts ranks of one thread each. The slowest rank's element and node work
// (from the partition's weights and node counts), the contact checks divided with
// kContactImbalance and the repeated contact work whole, the element exchange from computeStats
// with the network's speed, the time-step minimum (ceil(log2 P) latencies) and the contact
// exchanges; the parts are added (no overlap).
Prediction predict(const Stats& s, const CycleCosts& serial, const Network& net, bool has_contact);

// The largest rank count whose efficiency is at least `min_efficiency` (predictions in
// ascending ranks; 1 when none is).
int recommend(const std::vector<Prediction>& p, double min_efficiency = 0.8);

// The rank counts worth predicting up to `max_ranks`: 1, 2, 3, 4, 6, 8, 12, 16, 24, 32, ...
std::vector<int> candidateRanks(int max_ranks);

}  // namespace crumple::partition
