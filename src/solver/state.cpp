// The solver's part of a restart dump (docs/reliability.md, "Restart"). Everything is keyed
// by global ids: nodes by model node index, elements by global element index. Each rank sends
// what it owns to rank 0, which writes it in global order; on restart every rank takes from
// the same bytes what its subdomain holds, whatever the number of ranks either time.
#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <limits>

#include "solver/solver.hpp"
#include "util/archive.hpp"
#include "util/error.hpp"

namespace crumple::solver {

namespace {

// Every per-element value of a block that the run changes, element e, in a fixed order; f is
// called with a reference to each (double or byte). Values set by initialize() from the
// initial geometry (vol0, area0, length0, mass and step scaling) are recomputed on restart and
// not visited. Padding lanes are never read back (blocks.hpp), so they are not visited either.
template <class B, class F>
void visitSolid(B& b, std::size_t e, F&& f) {
  for (int k = 0; k < 6; ++k) f(b.sig[b.blocked(6, k, e)]);
  if (!b.eps_p.empty()) f(b.eps_p[e]);
  if (!b.alpha.empty())
    for (int k = 0; k < 6; ++k) f(b.alpha[b.blocked(6, k, e)]);
  if (!b.hgq.empty())
    for (int c = 0; c < 12; ++c) f(b.hgq[b.blocked(12, c, e)]);
  f(b.q_bulk[e]);
  if (!b.hist.empty())
    for (int k = 0; k < b.history; ++k) f(b.hist[b.blocked(b.history, k, e)]);
  f(b.vol[e]);
  f(b.e_int[e]);
  f(b.e_hg[e]);
  f(b.active[e]);
  f(b.failed[e]);
  const std::size_t padded = b.paddedSize();
  auto points = [&](auto& v) {
    if (!v.empty())
      for (std::size_t q = 0; q < std::size_t(b.points); ++q) f(v[q * padded + e]);
  };
  for (auto& s : b.sig_ip) points(s);
  for (auto& s : b.alpha_ip) points(s);
  points(b.eps_p_ip);
  for (std::size_t q = 0; q < std::size_t(b.points * b.history) && !b.hist_ip.empty(); ++q)
    f(b.hist_ip[q * padded + e]);
  if (!b.strain.empty())
    for (int k = 0; k < 6; ++k) f(b.strain[b.blocked(6, k, e)]);
  if (!b.ev_nodal.empty()) f(b.ev_nodal[e]);
}

template <class B, class F>
void visitTet10(B& b, std::size_t e, F&& f) {
  for (int k = 0; k < 6; ++k) f(b.sig[domain::SolidBlock::blocked(6, k, e)]);
  if (!b.eps_p.empty()) f(b.eps_p[e]);
  f(b.q_bulk[e]);
  f(b.vol[e]);
  f(b.e_int[e]);
  f(b.active[e]);
  f(b.failed[e]);
  const std::size_t padded = b.paddedSize();
  constexpr auto kPoints = std::size_t(domain::Tet10Block::kPoints);
  auto points = [&](auto& v) {
    if (!v.empty())
      for (std::size_t q = 0; q < kPoints; ++q) f(v[q * padded + e]);
  };
  for (auto& s : b.sig_ip) points(s);
  for (auto& s : b.alpha_ip) points(s);
  points(b.eps_p_ip);
  for (std::size_t q = 0; q < kPoints * std::size_t(b.history) && !b.hist_ip.empty(); ++q)
    f(b.hist_ip[q * padded + e]);
}

template <class B, class F>
void visitShell(B& b, std::size_t e, F&& f) {
  f(b.thick[e]);
  f(b.e_int[e]);
  f(b.e_hg[e]);
  f(b.e_drill[e]);
  f(b.active[e]);
  f(b.failed[e]);
  for (int k = 0; k < b.sigFields(); ++k) f(b.sig[b.blocked(b.sigFields(), k, e)]);
  if (!b.eps_p.empty())
    for (int k = 0; k < b.epsFields(); ++k) f(b.eps_p[b.blocked(b.epsFields(), k, e)]);
  if (!b.alpha.empty())
    for (int k = 0; k < b.alphaFields(); ++k) f(b.alpha[b.blocked(b.alphaFields(), k, e)]);
  if (!b.hgq.empty())
    for (int k = 0; k < 5; ++k) f(b.hgq[b.blocked(5, k, e)]);
  for (int k = 0; k < 4; ++k) f(b.drill[b.blocked(4, k, e)]);
  if (!b.erosion_state.empty())
    for (int k = 0; k < b.erosionFields(); ++k)
      f(b.erosion_state[b.blocked(b.erosionFields(), k, e)]);
  if (!b.hist.empty())
    for (int k = 0; k < b.histFields(); ++k) f(b.hist[b.blocked(b.histFields(), k, e)]);
}

template <class B, class F>
void visitBeam(B& b, std::size_t e, F&& f) {
  f(b.e_int[e]);
  if (!b.e_damp.empty()) f(b.e_damp[e]);
  if (!b.damping_resultant.empty())
    for (auto& v : b.damping_resultant[e]) f(v);
  f(b.active[e]);
  if (!b.triad.empty())
    for (auto& v : b.triad[e]) f(v);
  if (!b.deformation.empty())
    for (auto& v : b.deformation[e]) f(v);
  for (auto& v : b.resultant[e]) f(v);
  const auto np = static_cast<std::size_t>(b.points);
  for (std::size_t i = 0; i < np && !b.point.empty(); ++i) {
    auto& p = b.point[e * np + i];
    f(p.sig);
    f(p.tau_s);
    f(p.tau_t);
    f(p.eps_p);
    f(p.alpha);
    f(p.alpha_s);
    f(p.alpha_t);
  }
}

template <class B, class F>
void visitDiscrete(B& b, std::size_t e, F&& f) {
  f(b.e_int[e]);
  f(b.force[e]);
  f(b.elongation[e]);
}

// Calls f(block, e, global index, visitor) for every element held here.
template <class SD, class F>
void forEachElement(SD& sd, F&& f) {
  for (auto& b : sd.solid_blocks)
    for (std::size_t e = 0; e < b.size(); ++e)
      f(sd.globalElement(model::Family::Solid, b.elem[e]), [&](auto&& g) { visitSolid(b, e, g); });
  for (auto& b : sd.tet10_blocks)
    for (std::size_t e = 0; e < b.size(); ++e)
      f(sd.globalElement(model::Family::Solid, b.elem[e]), [&](auto&& g) { visitTet10(b, e, g); });
  for (auto& b : sd.shell_blocks)
    for (std::size_t e = 0; e < b.size(); ++e)
      f(sd.globalElement(model::Family::Shell, b.elem[e]), [&](auto&& g) { visitShell(b, e, g); });
  for (auto& b : sd.beam_blocks)
    for (std::size_t e = 0; e < b.size(); ++e)
      f(sd.globalElement(model::Family::Beam, b.elem[e]), [&](auto&& g) { visitBeam(b, e, g); });
  for (auto& b : sd.discrete_blocks)
    for (std::size_t e = 0; e < b.size(); ++e)
      f(sd.globalElement(model::Family::Discrete, b.elem[e]),
        [&](auto&& g) { visitDiscrete(b, e, g); });
}

template <class T>
void put(std::vector<char>& out, const T& v) {
  util::appendValue(out, v);
}

template <class T>
T peek(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;
}

// Values per node record: x, v, a, v(n-1/2), mass; then w, w(n-1/2) with rotations.
std::size_t nodeFields(bool rotations) {
  return rotations ? 19 : 13;
}

[[noreturn]] void mismatch(const std::string& what) {
  throw util::InputError("the restart dump does not belong to this deck: " + what);
}

// The dumps do not hold the SPH particles' state (density, smoothing length, stress).
[[noreturn]] void refuseSphRestart() {
  throw util::InputError(
      "restart dumps (*DATABASE_BINARY_D3DUMP, --restart) of a deck with SPH particles "
      "(*SECTION_SPH) are not supported yet");
}

}  // namespace

std::vector<char> Solver::saveState(StateSection which) const {
  // Every rank has the same model: all refuse together.
  if (!model_.sph_sections.empty()) refuseSphRestart();
  switch (which) {
    case StateSection::Scalars: {
      // Per-rank accumulators are kept per rank: restarted at the same number of ranks each
      // continues its own partial sum, so the energy sums stay bitwise those of the
      // uninterrupted run (at another count rank 0 takes the total, docs/reliability.md).
      const auto partials =
          comm_.allGather(std::vector<double>{external_work_, rigidwall_energy_, work_ahead_,
                                              damping_work_, damping_ahead_, rigidwall_ahead_});
      const long long eroded = comm_.sumAll(eroded_);
      if (!comm_.isRoot()) return {};
      util::ArchiveWriter w;
      w.put<int32_t>(comm_.size());
      w.put(time_);
      w.put(cycle_);
      w.put(dt_);
      w.put(dt_next_);
      w.put(dt_elem_);
      w.put(dt_initial_);
      w.put(initial_energy_);
      w.put<int64_t>(eroded);
      w.put(partials);
      w.put<uint8_t>(v_old_.size() == sd_.v.size() ? 1 : 0);
      w.put<uint8_t>(sd_.rotations && w_old_.size() == sd_.w.size() ? 1 : 0);
      return std::move(w.bytes());
    }
    case StateSection::Nodes: {
      const std::size_t k = nodeFields(sd_.rotations);
      std::vector<char> mine;
      mine.reserve(sd_.numNodes() * (sizeof(int64_t) + k * sizeof(double)));
      for (std::size_t n = 0; n < sd_.numNodes(); ++n) {
        if (!sd_.node_owned[n]) continue;
        put<int64_t>(mine, sd_.node_model[n]);
        auto three = [&](const std::vector<double>& a) {
          for (int c = 0; c < 3; ++c)
            put(mine, a.empty() ? 0.0 : a[3 * n + static_cast<std::size_t>(c)]);
        };
        three(sd_.x);
        three(sd_.v);
        three(sd_.a);
        three(v_old_);
        put(mine, sd_.mass[n]);
        if (sd_.rotations) {
          three(sd_.w);
          three(w_old_);
        }
      }
      const auto all = comm_.gatherToRoot(mine);
      if (!comm_.isRoot()) return {};
      const auto nodes = static_cast<std::size_t>(sd_.global_nodes);
      const std::size_t rec = sizeof(int64_t) + k * sizeof(double);
      std::vector<double> table(nodes * k, 0.0);
      std::vector<uint8_t> seen(nodes, 0);
      for (std::size_t off = 0; off + rec <= all.size(); off += rec) {
        const auto idx = static_cast<std::size_t>(peek<int64_t>(all.data() + off));
        if (idx >= nodes || seen[idx])
          throw std::logic_error("restart: node owned twice or out of range");
        seen[idx] = 1;
        std::memcpy(&table[idx * k], all.data() + off + sizeof(int64_t), k * sizeof(double));
      }
      if (std::count(seen.begin(), seen.end(), 0) != 0)
        throw std::logic_error("restart: a node is owned by no rank");
      util::ArchiveWriter w;
      w.put<int64_t>(sd_.global_nodes);
      w.put<uint8_t>(sd_.rotations ? 1 : 0);
      w.put(table);
      return std::move(w.bytes());
    }
    case StateSection::Elements: {
      std::vector<char> mine;
      // Room for a hex with plastic strain and hourglass resistances, so that the common case
      // fills one buffer without growing it (each growth copies everything so far).
      mine.reserve(sd_.num_elements * 256);
      forEachElement(sd_, [&](int64_t g, auto&& visit) {
        put(mine, g);
        const std::size_t at = mine.size();
        put<uint32_t>(mine, 0);
        const std::size_t start = mine.size();
        visit([&](const auto& v) { put(mine, v); });
        const auto len = static_cast<uint32_t>(mine.size() - start);
        std::memcpy(mine.data() + at, &len, sizeof(len));
      });
      const auto all = comm_.gatherToRoot(mine);
      if (!comm_.isRoot()) return {};
      // Global element g's bytes are payload[offset[g], offset[g + 1]).
      const auto ne = static_cast<std::size_t>(sd_.global_elements);
      std::vector<std::pair<std::size_t, uint32_t>> where(
          ne, {0, std::numeric_limits<uint32_t>::max()});
      for (std::size_t off = 0; off < all.size();) {
        const auto g = static_cast<std::size_t>(peek<int64_t>(all.data() + off));
        const auto len = peek<uint32_t>(all.data() + off + 8);
        if (g >= ne || where[g].second != std::numeric_limits<uint32_t>::max())
          throw std::logic_error("restart: element held twice or out of range");
        where[g] = {off + 12, len};
        off += 12 + len;
      }
      std::vector<uint64_t> offset(ne + 1, 0);
      for (std::size_t g = 0; g < ne; ++g) {
        if (where[g].second == std::numeric_limits<uint32_t>::max())
          throw std::logic_error("restart: an element is held by no rank");
        offset[g + 1] = offset[g] + where[g].second;
      }
      std::vector<char> payload(offset[ne]);
      for (std::size_t g = 0; g < ne; ++g)
        if (where[g].second > 0)
          std::memcpy(payload.data() + offset[g], all.data() + where[g].first, where[g].second);
      util::ArchiveWriter w;
      w.put<int64_t>(sd_.global_elements);
      w.put(offset);
      w.put(payload);
      return std::move(w.bytes());
    }
    case StateSection::Constraints: {
      // Rigid bodies and walls hold the same state on every rank: rank 0's copy is the state;
      // the prescribed motions' work is gathered from the ranks that own the nodes.
      const auto motion_work = comm_.allGather(boundary_.ownedMotionWork(sd_));
      if (!comm_.isRoot()) return {};
      util::ArchiveWriter w;
      w.put<uint8_t>(rigid_ ? 1 : 0);
      if (rigid_) rigid_->saveState(w);
      boundary_.saveState(w, motion_work);
      return std::move(w.bytes());
    }
  }
  return {};
}

void Solver::loadState(StateSection which, const std::vector<char>& bytes) {
  if (!model_.sph_sections.empty()) refuseSphRestart();
  util::ArchiveReader r(bytes);
  switch (which) {
    case StateSection::Scalars: {
      int32_t ranks = 0;
      int64_t eroded = 0;
      double dt_initial = 0.0, initial_energy = 0.0;
      std::vector<double> partials;
      uint8_t stepped = 0, spun = 0;
      r.get(ranks);
      r.get(time_);
      r.get(cycle_);
      r.get(dt_);
      r.get(dt_next_);
      r.get(dt_elem_);
      r.get(dt_initial);
      r.get(initial_energy);
      r.get(eroded);
      r.get(partials);
      r.get(stepped);
      r.get(spun);
      if (dt_initial != dt_initial_)
        mismatch(fmt::format("its initial time step {:.17g} differs from this deck's {:.17g}",
                             dt_initial, dt_initial_));
      // Six accumulators per rank (two in dumps written before the work ahead was kept, three
      // before the damping work was, five before the stonewall energy ahead was).
      const auto per_rank = static_cast<std::size_t>(ranks) == 0
                                ? std::size_t{0}
                                : partials.size() / static_cast<std::size_t>(ranks);
      if ((per_rank < 2 || per_rank > 6 || per_rank == 4) ||
          partials.size() != per_rank * std::size_t(ranks))
        throw util::InputError("restart dump: the solver section is inconsistent");
      initial_energy_ = initial_energy;
      auto partial = [&](int k, std::size_t i) {
        return i < per_rank ? partials[per_rank * static_cast<std::size_t>(k) + i] : 0.0;
      };
      if (ranks == comm_.size()) {
        external_work_ = partial(comm_.rank(), 0);
        rigidwall_energy_ = partial(comm_.rank(), 1);
        work_ahead_ = partial(comm_.rank(), 2);
        damping_work_ = partial(comm_.rank(), 3);
        damping_ahead_ = partial(comm_.rank(), 4);
        rigidwall_ahead_ = partial(comm_.rank(), 5);
      } else {
        // Summed in rank order from zero, as Communicator::sumOrdered adds them.
        double sums[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        for (int k = 0; k < ranks; ++k)
          for (std::size_t i = 0; i < 6; ++i) sums[i] += partial(k, i);
        const bool root = comm_.isRoot();
        external_work_ = root ? sums[0] : 0.0;
        rigidwall_energy_ = root ? sums[1] : 0.0;
        work_ahead_ = root ? sums[2] : 0.0;
        damping_work_ = root ? sums[3] : 0.0;
        damping_ahead_ = root ? sums[4] : 0.0;
        rigidwall_ahead_ = root ? sums[5] : 0.0;
      }
      eroded_ = comm_.isRoot() ? eroded : 0;
      if (stepped) v_old_.assign(sd_.v.size(), 0.0);
      if (spun) w_old_.assign(sd_.w.size(), 0.0);
      break;
    }
    case StateSection::Nodes: {
      int64_t nodes = 0;
      uint8_t rotations = 0;
      std::vector<double> table;
      r.get(nodes);
      r.get(rotations);
      r.get(table);
      const std::size_t k = nodeFields(sd_.rotations);
      if (nodes != sd_.global_nodes || (rotations != 0) != sd_.rotations ||
          table.size() != static_cast<std::size_t>(nodes) * k)
        mismatch(fmt::format("it holds {} nodes, the deck {}", nodes, sd_.global_nodes));
      constexpr int64_t kNone = std::numeric_limits<int64_t>::max();
      int64_t bad = kNone;
      for (std::size_t n = 0; n < sd_.numNodes(); ++n) {
        const double* rec = &table[static_cast<std::size_t>(sd_.node_model[n]) * k];
        auto three = [&](std::vector<double>& a, int at) {
          if (a.empty()) return;
          for (int c = 0; c < 3; ++c) a[3 * n + static_cast<std::size_t>(c)] = rec[at + c];
        };
        three(sd_.x, 0);
        three(sd_.v, 3);
        three(sd_.a, 6);
        three(v_old_, 9);
        // The masses were recomputed by initialize(): the same deck gives the same bits.
        if (rec[12] != sd_.mass[n]) bad = std::min(bad, sd_.node_id[n]);
        if (sd_.rotations) {
          three(sd_.w, 13);
          three(w_old_, 16);
        }
      }
      const int64_t bad_id = comm_.minAll(bad);
      if (bad_id != kNone) mismatch(fmt::format("the mass of node {} differs", bad_id));
      break;
    }
    case StateSection::Elements: {
      int64_t ne = 0;
      std::vector<uint64_t> offset;
      std::vector<char> payload;
      r.get(ne);
      r.get(offset);
      r.get(payload);
      if (ne != sd_.global_elements || offset.size() != static_cast<std::size_t>(ne) + 1 ||
          offset.back() != payload.size())
        mismatch(fmt::format("it holds {} elements, the deck {}", ne, sd_.global_elements));
      constexpr int64_t kNone = std::numeric_limits<int64_t>::max();
      int64_t bad = kNone;
      forEachElement(sd_, [&](int64_t g, auto&& visit) {
        const auto gi = static_cast<std::size_t>(g);
        const char* p = payload.data() + offset[gi];
        const char* end = payload.data() + offset[gi + 1];
        bool fits = true;
        visit([&](auto& v) {
          if (static_cast<std::size_t>(end - p) < sizeof(v)) {
            fits = false;
            return;
          }
          std::memcpy(&v, p, sizeof(v));
          p += sizeof(v);
        });
        // Another material, section or formulation stores another amount of state.
        if (!fits || p != end) bad = std::min(bad, int64_t(g));
      });
      const int64_t bad_g = comm_.minAll(bad);
      if (bad_g != kNone)
        mismatch(fmt::format("the state of {} differs in size", elementLabel(bad_g)));
      break;
    }
    case StateSection::Constraints: {
      uint8_t has_rigid = 0;
      r.get(has_rigid);
      if ((has_rigid != 0) != (rigid_ != nullptr))
        mismatch("rigid bodies in one and not in the other");
      if (rigid_) rigid_->loadState(r);
      boundary_.loadState(r, sd_);
      break;
    }
  }
  if (!r.atEnd()) throw util::InputError("restart dump: a solver section has trailing bytes");
}

}  // namespace crumple::solver
