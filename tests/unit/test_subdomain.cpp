// The distributed subdomain without MPI: several ranks' subdomains built in one process, the
// exchange done by hand. Nodal sums over local and ghost slots must equal the serial sums bit
// for bit, which is the property the parallel determinism of the solver rests on.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "brick_model.hpp"
#include "domain/subdomain.hpp"
#include "gather.hpp"
#include "model/model.hpp"

namespace {

using namespace crumple;

// nx x ny x nz brick of unit hexes with one elastic part.
model::Model brick(int nx, int ny, int nz) {
  return crumple::testing::brickModel(nx, ny, nz);
}

// An arbitrary, non-round value for each (element, corner, component).
double cornerValue(int32_t elem, int corner, int c) {
  return std::sin(1.37 * elem + 0.71 * corner + 0.29 * c) * 1e3 / (1.0 + elem);
}

void fillSlots(domain::Subdomain& sd) {
  for (const auto& b : sd.solid_blocks)
    for (std::size_t k = 0; k < b.size(); ++k)
      for (int a = 0; a < 8; ++a)
        for (int c = 0; c < 3; ++c)
          sd.slots[3 * (b.slot_offset + 8 * k + a) + c] = cornerValue(b.elem[k], a, c);
}

class SubdomainRanks : public ::testing::TestWithParam<int> {};

TEST_P(SubdomainRanks, GhostExchangeReproducesSerialSumsBitForBit) {
  const int ranks = GetParam();
  const auto m = brick(5, 3, 2);
  // A deliberately irregular element -> rank map (not contiguous in id order).
  std::vector<int32_t> elem_rank(m.solids.size());
  for (std::size_t e = 0; e < elem_rank.size(); ++e)
    elem_rank[e] = int32_t((e * 7 + e / 3) % ranks);

  auto serial = domain::buildSerialSubdomain(m);
  fillSlots(serial);
  const auto f_serial = crumple::testing::gatheredForces(serial);

  std::vector<domain::Subdomain> sds;
  for (int r = 0; r < ranks; ++r) {
    sds.push_back(domain::buildSubdomain(m, elem_rank, r, ranks));
    fillSlots(sds.back());
  }
  // The exchange: rank r's send list to q lands, in order, in q's ghost range from r.
  for (int r = 0; r < ranks; ++r)
    for (const auto& p : sds[std::size_t(r)].peers) {
      const auto& q = sds[std::size_t(p.rank)];
      const auto it =
          std::find_if(q.peers.begin(), q.peers.end(), [&](const auto& x) { return x.rank == r; });
      ASSERT_NE(it, q.peers.end()) << "peer lists must be symmetric";
      ASSERT_EQ(it->recv_count, p.send_slots.size());
      for (std::size_t k = 0; k < p.send_slots.size(); ++k)
        for (int c = 0; c < 3; ++c)
          sds[std::size_t(p.rank)].slots[3 * (it->recv_first + k) + c] =
              sds[std::size_t(r)].slots[3 * std::size_t(p.send_slots[k]) + c];
    }
  std::map<int32_t, int> owners;
  for (const auto& sd : sds) {
    const auto f = crumple::testing::gatheredForces(sd);
    for (std::size_t n = 0; n < sd.numNodes(); ++n) {
      const auto g = static_cast<std::size_t>(sd.node_model[n]);
      for (int c = 0; c < 3; ++c) EXPECT_EQ(f[3 * n + c], f_serial[3 * g + c]) << "node " << g;
      owners[sd.node_model[n]] += sd.node_owned[n];
    }
  }
  ASSERT_EQ(owners.size(), m.nodes.size());
  for (const auto& [node, count] : owners) EXPECT_EQ(count, 1) << "node " << node << " owners";
}

INSTANTIATE_TEST_SUITE_P(TwoToFive, SubdomainRanks, ::testing::Values(2, 3, 4, 5));

TEST(Subdomain, ElementIdsAndCounts) {
  const auto m = brick(3, 1, 1);
  std::vector<int32_t> elem_rank = {0, 0, 1};
  const auto sd1 = domain::buildSubdomain(m, elem_rank, 1, 2);
  EXPECT_EQ(sd1.global_solids, 3);
  EXPECT_EQ(sd1.global_nodes, 16);
  EXPECT_EQ(sd1.num_elements, 1u);
  EXPECT_EQ(sd1.elementId(2), 3);
  EXPECT_EQ(sd1.elementId(0), 0);  // not held here
  EXPECT_EQ(sd1.numNodes(), 8u);
  // The 4 nodes of the shared face are owned by rank 0.
  int owned = 0;
  for (auto o : sd1.node_owned) owned += o;
  EXPECT_EQ(owned, 4);
}

}  // namespace
