// Penalty contact (Hallquist, Goudreau & Benson 1985, "Sliding interfaces with contact-impact
// in large-scale Lagrangian computations", CMAME 51; LS-DYNA Theory Manual, "Contact-Impact
// Algorithm"): nodes of one side that penetrate a segment of the other are pushed back by a
// spring of stiffness k along the segment normal, with Coulomb friction and viscous damping,
// and the reaction goes to the segment's nodes by its shape functions.
//
// Parallel design (docs/parallel.md, "Contact"). Every contact node's position and velocity
// is gathered to every rank at a bucket sort; between sorts a rank receives, through a
// comm::Exchange, only the nodes its checks read. The checks (a node against the other side)
// are split among ranks by recursive coordinate bisection of the nodes' current positions: the
// contact partition, separate from the element partition and re-cut, with the measured cost of
// every check as its weight, when the busiest rank does more than
// ContactControls::rebalance_threshold times the mean. The forces found travel back to every
// rank as records, sorted by check index and added in that order: the same bits whatever the
// number of ranks and threads.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "comm/communicator.hpp"
#include "comm/exchange.hpp"
#include "contact/balance.hpp"
#include "contact/erosion.hpp"
#include "contact/pass.hpp"
#include "contact/penalty.hpp"
#include "contact/search.hpp"
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
  // Elements of this rank eroded in this cycle's element pass (before computeForces): those
  // the contact surfaces hold leave them at once, every rank told at a bucket sort.
  void noteErosion() { eroded_here_ = erosion_.erodedHere(); }
  // Contact energy: the energy of the penalty springs now plus what friction and damping
  // have dissipated. Every rank holds every record, so these are the same on every rank.
  double energy() const;
  std::vector<InterfaceForces> interfaceForces() const;
  // A force transducer's resultants (*CONTACT_FORCE_TRANSDUCER_PENALTY) from the other
  // interfaces' records.
  void measure(std::size_t iface, InterfaceForces& o) const;
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
  std::size_t localChecks() const { return partition_.mine().size(); }

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
    f(held_);
    f(stored_);
    f(dissipated_);
    f(cycles_since_sort_);
    f(stats_.sorts);
    f(stats_.rebalances);
    f(stats_.max_penetration_ratio);
    f(dt_stiff_);
    f(edge_pairs_);
    f(tie_moment_);
    f(tie_seg_);    // tiebreak: -1 once the bond has failed
    f(need_sort_);  // a bond failed last cycle: its node searches from the next sort on
  }
  struct Candidate;
  int32_t contactNode(int32_t model_node) const;
  // Makes pass p (its nodes from `nodes`) a tiebreak pass: tied until the bond fails.
  void makeTiebreak(Pass& p, const model::ContactSurface& nodes);
  // After the ties: the area of each node of tiebreak pass p on the bond (Pass::node_area).
  void bondAreas(Pass& p);
  // Appends a pass, numbering its checks after the others'.
  void registerPass(Pass p);
  // The checks of `nodes` against the segments of `segs`, their penalty scaled by sf (SFS or
  // SFM).
  void addPass(int32_t iface, const model::ContactSurface& nodes, const model::ContactSurface& segs,
               double sf, bool self);
  // The checks of the beam edges of `side` (*CONTACT_AUTOMATIC_GENERAL) against each other,
  // their penalty scaled by sf (docs/theory.md, "Beam edges"; src/contact/edges.cpp).
  void addEdgePass(int32_t iface, const model::ContactSurface& side, double sf);
  // The segment pairs of SOFT = 2 (src/contact/segpairs.cpp): the segments of `a` against
  // those of `b` (the same surface when `self`).
  void addSegmentPass(int32_t iface, const model::ContactSurface& a, const model::ContactSurface& b,
                      bool self);
  // Segment check `check` against segment s of its pass, if they are in contact.
  std::optional<Record> segmentPair(const Pass& p, int32_t check, std::size_t s,
                                    double dt_prev) const;
  // Segment passes before the first cycle: the pairs in contact, listed as initial
  // penetrations (kept as entry offsets).
  void listInitialSegmentOverlaps(std::size_t pass);
  // The forces of a segment pair record on the nodes of both segments.
  void applySegmentRecord(const Pass& p, const Record& r);
  // Edge passes: the reach of the buckets from the longest edge now (before a sort).
  void refreshEdgeReach();
  // The records of active edge or segment check i (an index into partition_.mine()) against
  // its candidates, appended to `out`; `tests` counts the candidates tested.
  void checkPairs(std::size_t i, double time, double dt_prev, int64_t& tests,
                  std::vector<Record>& out) const;
  // Edge check `check` against edge s of its pass, if their capsules overlap.
  std::optional<Record> edgePair(const Pass& p, int32_t check, std::size_t s, double dt_prev) const;
  // Edge passes before the first cycle: the overlapping pairs, listed as initial
  // penetrations (kept as entry offsets, the force starting from zero).
  void listInitialEdgeOverlaps(std::size_t pass);
  // f added to contact node `node` where this rank holds it.
  void addNodeForce(int32_t node, const Vec3& f);
  // A moment added to contact node `node` where this rank holds it (rotational ties).
  void addNodeMoment(int32_t node, const Vec3& m);
  // The moments of a rotational tie's record on its node and segment nodes.
  void applyTiedMoment(const Pass& p, const Record& r);
  // The largest penetration ratio of the statistics, with record r of pass p.
  void notePenetration(const Pass& p, const Record& r);
  // The forces of an edge record on the four nodes of its pair.
  void applyEdgeRecord(const Pass& p, const Record& r);
  // Every contact node from its owner (set-up, sorts); the nodes this rank reads (each cycle).
  void gatherNodes();
  void gatherNeeded();
  void gatherMasses();
  // After a sort: which nodes this rank reads, and who sends them (collective).
  void buildRoutes();
  // Re-sorts the buckets when some node may have travelled half the margin since the last
  // sort, or after BSORT cycles (collective); true if it did.
  bool sortIfDue();
  // Every rank's newly eroded elements (noteErosion) marked on every rank (collective).
  void syncErosion();
  // Whether segment s of pass p is in contact now (not eroded; erosion.hpp).
  bool live(const Pass& p, std::size_t s) const {
    return erosion_.segmentLive(std::size_t(&p - passes_.data()), s);
  }
  void sortAll();  // the buckets of every pass, and x_sorted_
  void buildCandidateLists();
  // The check partition's first cut, weighed by each check's candidates (collective).
  void cutByCandidates();
  // Owned nodes' current positions into x_owned_prev_ (sent with the next full gather).
  void recordOwnedPositions();
  // Moves a contact node before the first cycle (initial penetration, tie), on every rank.
  void moveNode(std::size_t node, const std::array<double, 3>& dx);
  void tieNodes(std::size_t pass, bool keep_offset);
  void resolveInitialPenetrations(std::size_t pass);
  // The segment a check's node penetrates among `candidates` (docs/theory.md, "Node against
  // segment"); none if none. `initial`: the check before the first cycle, which also takes
  // nodes already inside. `tests` counts the segments tested.
  std::optional<Candidate> chooseSegment(std::size_t pass, int32_t check,
                                         std::span<const int32_t> candidates, int64_t& tests,
                                         bool initial) const;
  // A check's node: its contact node, position and half shell thickness.
  struct CheckNode {
    int32_t check = 0;
    std::size_t node = 0;
    std::array<double, 3> x{};
    double half = 0.0;
  };
  // One segment against a check's node: its contact surface and rank; none if the node is not
  // in contact with it.
  std::optional<Candidate> rankSegment(const Pass& pass, const CheckNode& node, std::size_t seg,
                                       bool initial) const;
  // Whether a node at x, beyond shell segment s of pass p (projected outside it), is past an
  // edge the surface leaves exposed: a free edge, or the outside of a fold.
  bool pastExposedEdge(const Pass& p, std::size_t s, const Vec3& x) const;
  // Whether the check's node stays with the segment it was in contact with last cycle.
  bool tracks(const Pass& pass, int32_t check, std::size_t seg, const Projection& pr) const;
  // The records of this rank's checks in contact now.
  std::vector<Record> checkContacts(double time, double dt_prev);
  // The record of active check i (an index into partition_.mine()), if it is in contact;
  // adds the segments it tested to `tests`.
  std::optional<Record> checkOne(std::size_t i, double time, double dt_prev, int64_t& tests) const;
  NodeAndSegment nodeAndSegment(std::size_t node, const std::array<int32_t, 4>& seg) const;
  // Every rank's records, in check order.
  void gatherRecords(std::vector<Record> mine);
  // The records' forces into Subdomain::f, and the contact history of the next cycle.
  void applyRecords();

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
  // Rotational ties (tied shell edges, spot welds; only when some interface has them and the
  // model has rotational freedoms): angular velocities (3 per node, read as x_ and v_ are)
  // and rotary inertias (1 per node, of all).
  bool rotations_ = false;
  std::vector<double> w_, inertia_;
  std::vector<int32_t> owner_;         // rank owning each contact node
  std::vector<double> x_owned_prev_;   // owned nodes: position at the last contact pass
  std::vector<int32_t> needed_local_;  // nodes read between sorts that this rank holds
  // Between sorts, the needed nodes held elsewhere from their owners: positions and
  // velocities (2 fields of 3), in ascending contact node order on both sides.
  comm::Exchange needed_;
  std::vector<double> x_sorted_;     // positions at the last bucket sort
  std::vector<double> x_prev_;       // positions of the last cycle
  std::vector<int32_t> last_seg_;    // per check: the segment in contact last cycle, or -1
  std::vector<int32_t> in_contact_;  // checks with a record last cycle (their history is set)
  std::vector<int8_t> last_side_;    // per check: the side of that (shell) segment, or 0
  std::vector<double> entry_;        // per check: penetration at the start of the contact
  // Per check: k p^2 / 2 of its record last cycle (0: none), negative if less than the cycle
  // before (the spring unloading).
  std::vector<double> held_;
  void holdEnergy(std::size_t check, double energy);
  // Tied checks: the segment, its four weights and the normal offset of the tied point.
  std::vector<int32_t> tie_seg_;
  std::vector<std::array<double, 4>> tie_weight_;
  std::vector<double> tie_offset_;
  std::vector<double> tie_moment_;  // rotational ties: the moment of the last cycle, 3 per check
  std::vector<Pass> passes_;
  int32_t num_checks_ = 0;
  std::vector<int32_t> check_pass_;  // pass of each global check
  std::vector<int32_t> check_node_;  // contact node of each global check
  BucketSearch search_;
  CheckPartition partition_;
  std::vector<double> friction_;  // tangential force history, 3 per check
  // The step the penalty stiffness is taken at (SOFT = 1 and the stability cap): the initial
  // step, raised when the step grows, never lowered (LS-DYNA Theory Manual, "soft constraint
  // penalty"), so that a falling step does not stiffen the contacts already in force.
  double dt_stiff_ = 0.0;
  // checkContacts' scratch: segments tested per active check, records found per thread.
  std::vector<int64_t> check_tests_;
  std::vector<std::vector<Record>> thread_records_;
  bool need_sort_ = true;
  int cycles_since_sort_ = 0;
  int max_sort_interval_ = 0;  // smallest BSORT of the interfaces (0: none)

  // The history of the beam edge pairs in contact last cycle, by (check, segment) ascending:
  // friction (the elastic stick) and the entry offset a pair began with.
  struct EdgePair {
    int32_t check = 0, segment = 0;
    Vec3 friction{};
    double entry = 0.0;
    int8_t side = 0;          // segment pairs: the side of the other segment the check's is on
    double energy = 0.0;      // segment pairs: the penalty energy the pair held, k p^2 / 2
    double dissipated = 0.0;  // segment pairs: by friction and damping over its last step
  };
  std::vector<EdgePair> edge_pairs_;
  std::vector<EdgePair> last_pairs_;  // applyRecords' scratch: edge_pairs_ of the cycle before
  // The energy of the segment pairs of last cycle that are no longer in contact, booked as
  // contact energy that stays (see applyRecords).
  void bookEndedSegmentPairs();
  // The same for the node checks of last cycle with no record now (held_).
  void bookEndedNodeChecks();
  std::vector<int32_t> last_in_contact_;   // applyRecords' scratch: in_contact_ of the cycle before
  std::vector<int32_t> last_contact_seg_;  // and the segment each of them was in contact with
  const EdgePair* findEdgePair(int32_t check, int32_t segment) const;
  // A pair of pass p in contact last cycle whose edges are edges a and b of the pass or their
  // neighbours (sharing a node), the first in pair order; none if none.
  const EdgePair* continuedEdgePair(const Pass& p, std::size_t a, std::size_t b) const;

  SurfaceErosion erosion_;
  std::vector<int64_t> eroded_here_;  // noteErosion's elements, until the next sort

  std::vector<Record> records_;     // of the last cycle, in check order
  std::vector<double> stored_;      // per interface: sum of k pen^2 / 2 of the last cycle
  std::vector<double> dissipated_;  // per interface: friction and damping, accumulated
  std::vector<InitialPenetration> initial_;
  bool moved_initial_ = false;
  Statistics stats_;
};

}  // namespace crumple::contact
