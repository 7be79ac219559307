// Penalty contact (Hallquist, Goudreau & Benson 1985, "Sliding interfaces with contact-impact
// in large-scale Lagrangian computations", CMAME 51; LS-DYNA Theory Manual, "Contact-Impact
// Algorithm"): nodes of one side that penetrate a segment of the other are pushed back by a
// spring of stiffness k along the segment normal, with Coulomb friction and viscous damping,
// and the reaction goes to the segment's nodes by its shape functions.
//
// Parallel design (docs/parallel.md, "Contact"). Every contact node's position and velocity
// is gathered to every rank each cycle (7 doubles per node). The checks (a node against the
// other side) are split among ranks by recursive coordinate bisection of the nodes' current
// positions: the contact partition, separate from the element partition and re-cut, with the
// measured cost of every check as its weight, when the busiest rank does more than
// ContactControls::rebalance_threshold times the mean. The forces found travel back to every
// rank as records, sorted by check index and added in that order: the same bits whatever the
// number of ranks and threads.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "comm/communicator.hpp"
#include "domain/subdomain.hpp"
#include "model/model.hpp"

namespace crumple::contact {

// Per interface, for rcforc.csv: the force on the nodes of each side, and the energy.
struct InterfaceForces {
  int64_t id = 0;
  std::array<double, 3> side_a{}, side_b{};
  double energy = 0.0;  // penalty energy stored now + energy dissipated by friction/damping
  int64_t pairs = 0;    // nodes in contact
};

struct InitialPenetration {
  int64_t interface_id = 0;
  int64_t node_id = 0;
  double depth = 0.0;
};

struct Statistics {
  // Seconds of this rank in computeForces: the checks (divided among ranks), the work every
  // rank repeats (sort, boxes, records), and the two gathers (positions, records).
  double search_s = 0.0, replicated_s = 0.0, exchange_s = 0.0;
  int64_t records = 0;  // contact records summed over cycles
  int64_t cycles = 0;
  int64_t checks = 0;                  // node-against-surface checks of the whole model
  int64_t sorts = 0;                   // bucket re-sorts
  int64_t rebalances = 0;              // contact partition re-cuts after the initial one
  int64_t tests = 0;                   // node-segment tests on this rank since the start
  int64_t tied_nodes = 0;              // nodes of tied interfaces that found their segment
  double max_penetration_ratio = 0.0;  // largest penetration / (segment size or thickness)
};

class Contact {
 public:
  Contact(const model::Model& model, domain::Subdomain& sd, comm::Communicator& comm);
  ~Contact();
  Contact(const Contact&) = delete;
  Contact& operator=(const Contact&) = delete;

  bool empty() const { return passes_.empty(); }

  // After the masses are known and before rigid bodies are built: the first bucket sort, the
  // contact partition, and the initial penetrations (moved out, or remembered, by IGNORE).
  void initialize(double dt0);
  // Contact forces at t(n) from x(n) and v(n-1/2), added to Subdomain::f (collective).
  void computeForces(double time, double dt_prev);
  // Contact energy: the energy of the penalty springs now plus what friction and damping
  // have dissipated. Every rank holds every record, so these are the same on every rank.
  double energy() const;
  std::vector<InterfaceForces> interfaceForces() const;
  const std::vector<InitialPenetration>& initialPenetrations() const { return initial_; }
  bool movedInitialPenetrations() const { return moved_initial_; }
  const Statistics& statistics() const { return stats_; }
  // Restart (docs/reliability.md): the state is the same on every rank (replicated), so one
  // copy is dumped (saveState is collective and returns the bytes on rank 0) and every rank
  // loads it. Positions at the last bucket sort come along so
  // that the buckets and candidate lists are rebuilt as they were: the continued run gives
  // the same bits.
  std::vector<char> saveState() const;
  void loadState(const std::vector<char>& bytes);

  // Checks this rank computes now (the contact partition).
  std::size_t localChecks() const { return my_checks_.size(); }

 private:
  // Every piece of state a restart needs besides the positions of the last pass, in dump
  // order: one list for saveState and loadState.
  template <class F>
  void history(F&& f) {
    f(x_sorted_);
    f(friction_);
    f(last_seg_);
    f(last_side_);
    f(entry_);
    f(stored_);
    f(dissipated_);
    f(cycles_since_sort_);
    f(stats_.sorts);
    f(stats_.rebalances);
    f(stats_.max_penetration_ratio);
  }
  struct Pass;  // one side's nodes against the other side's segments
  struct Candidate;
  // Every contact node from its owner (set-up, sorts); the nodes this rank reads (each cycle).
  void gatherNodes();
  void gatherNeeded();
  // After a sort: which nodes this rank reads, and who sends them (collective).
  void buildRoutes();
  void sortAll();  // every pass's buckets, the margin and x_sorted_
  double reachOf(const Pass& pass) const;
  void sortBuckets(Pass& pass);
  void updateBoxes(Pass& pass, bool needed_only);
  // Looks for the segment a check penetrates; false if none.
  std::array<double, 3> segmentNormal(const std::array<int32_t, 4>& seg) const;
  // Segments a check may meet before the next sort (appended to `out`).
  void collectCandidates(const Pass& pass, int32_t check, double margin,
                         std::vector<int32_t>& out) const;
  void buildCandidateLists();
  // Owned nodes' current positions into x_owned_prev_ (sent with the next full gather).
  void recordOwnedPositions();
  // Moves a contact node before the first cycle (initial penetration, tie), on every rank.
  void moveNode(std::size_t node, const std::array<double, 3>& dx);
  void tieNodes(const Pass& pass, bool keep_offset);
  void tiedForce(const Pass& pass, int32_t check, double dt_prev,
                 std::vector<double>& records) const;
  // The segment the check's node penetrates among `candidates`; false if none. `initial`: the
  // check before the first cycle, which also takes nodes already inside.
  bool search(const Pass& pass, int32_t check, const int32_t* candidates, std::size_t count,
              Candidate& best, int64_t& tests, bool initial) const;
  void partitionChecks(const std::vector<double>& weight);
  void maybeRebalance();

  const model::Model& model_;
  domain::Subdomain& sd_;
  comm::Communicator& comm_;

  // Contact nodes: every node of any interface, in ascending model index ("cn" numbering).
  std::vector<int32_t> cn_model_;
  std::vector<int32_t> cn_local_;  // local index on this rank, or -1
  std::vector<uint8_t> cn_owned_;
  // Positions and velocities (3 per node) of the nodes this rank reads, all of them after a
  // sort; masses (1 per node) of all.
  std::vector<double> x_, v_, mass_;
  std::vector<int32_t> owner_;         // rank owning each contact node
  std::vector<double> x_owned_prev_;   // owned nodes: position at the last contact pass
  std::vector<int32_t> needed_local_;  // nodes read between sorts that this rank holds
  struct Route {
    int peer = 0;
    std::vector<int32_t> nodes;  // ascending contact node indices
    std::vector<double> buffer;  // 6 per node: x, v
  };
  std::vector<Route> send_routes_, recv_routes_;
  std::vector<double> x_sorted_;     // positions at the last bucket sort
  std::vector<double> x_prev_;       // positions of the last cycle
  std::vector<int32_t> last_seg_;    // per check: the segment in contact last cycle, or -1
  std::vector<int32_t> in_contact_;  // checks with a record last cycle (their history is set)
  std::vector<int8_t> last_side_;    // per check: the side of that (shell) segment, or 0
  std::vector<double> entry_;        // per check: penetration at the start of the contact
  // Tied checks: the segment, its four weights and the normal offset of the tied point.
  std::vector<int32_t> tie_seg_;
  std::vector<double> tie_weight_, tie_offset_;
  std::vector<Pass> passes_;
  int32_t num_checks_ = 0;
  std::vector<int32_t> check_pass_;           // pass of each global check
  std::vector<int32_t> my_checks_;            // ascending
  std::vector<int32_t> cand_ptr_, cand_seg_;  // candidate segments of each of my checks (CSR)
  std::vector<int32_t> active_;               // indices into my_checks_ with candidates (or a tie)
  std::vector<double> friction_;              // tangential force history, 3 per check
  std::vector<double> initial_gap_;           // IGNORE 1/2: initial penetration per check
  std::vector<double> check_cost_;  // tests per check since the last balance (this rank's)
  int64_t tests_since_balance_ = 0;
  double dt0_ = 0.0;
  double sort_margin_ = 0.0;
  bool need_sort_ = true;
  int cycles_since_sort_ = 0;
  int max_sort_interval_ = 0;  // smallest BSORT of the interfaces (0: none)

  // Records of the last cycle, sorted by check: see kRecord in contact.cpp.
  std::vector<double> records_;
  std::vector<double> stored_;      // per interface: sum of k pen^2 / 2 of the last cycle
  std::vector<double> dissipated_;  // per interface: friction and damping, accumulated
  std::vector<InitialPenetration> initial_;
  bool moved_initial_ = false;
  Statistics stats_;
};

}  // namespace crumple::contact
