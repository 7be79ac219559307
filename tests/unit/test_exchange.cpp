// comm::Exchange and the typed gathers at any rank count: serially in the unit tests (a rank's
// messages to itself are copies), and the same tests under mpirun (tests/parallel/mpi_main.cpp,
// ctest's parallel.exchange_*). Values encode where they come from, so a value unpacked in the
// wrong place, from the wrong peer or field, shows.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <stdexcept>
#include <vector>

#include "comm/communicator.hpp"
#include "comm/exchange.hpp"

namespace {

using crumple::comm::Communicator;
using crumple::comm::Exchange;

Communicator& world() {
  return crumple::comm::world();
}

constexpr std::size_t kEntries = 6;
constexpr int kComponents = 3;
constexpr double kUntouched = -1.0;

// Component c of entry i of field f on rank r.
double value(int r, int f, int32_t i, int c) {
  return 1000.0 * r + 100.0 * f + 10.0 * i + c;
}

std::vector<double> field(int f) {
  std::vector<double> out(kComponents * kEntries);
  for (std::size_t i = 0; i < kEntries; ++i)
    for (int c = 0; c < kComponents; ++c)
      out[kComponents * i + std::size_t(c)] = value(world().rank(), f, int32_t(i), c);
  return out;
}

// Each rank sends entries {3, 0, 2} (not ascending) to the next rank and receives the previous
// rank's into its entries {1, 4, 5}; serially both neighbours are the rank itself.
const std::vector<int32_t> kSent = {3, 0, 2};
const std::vector<int32_t> kFilled = {1, 4, 5};

Exchange ring(int fields) {
  const int n = world().size(), r = world().rank();
  std::map<int, Exchange::Peer> peers;
  peers[(r + 1) % n].send = kSent;
  peers[(r + n - 1) % n].recv = kFilled;
  std::vector<Exchange::Peer> list;
  for (auto& [rank, p] : peers) {
    p.rank = rank;
    list.push_back(std::move(p));
  }
  return Exchange(world(), std::move(list), kComponents, fields);
}

// The received entries hold the previous rank's sent ones; the others are untouched.
void expectFromPrevious(const std::vector<double>& got, int f) {
  const int prev = (world().rank() + world().size() - 1) % world().size();
  for (std::size_t i = 0; i < kEntries; ++i)
    for (int c = 0; c < kComponents; ++c) {
      double want = kUntouched;
      for (std::size_t k = 0; k < kFilled.size(); ++k)
        if (kFilled[k] == int32_t(i)) want = value(prev, f, kSent[k], c);
      EXPECT_EQ(got[kComponents * i + std::size_t(c)], want) << "entry " << i << " field " << f;
    }
}

TEST(Exchange, RingOfTwoFieldsUnpacksEachEntryWhereThePlanSays) {
  Exchange ex = ring(2);
  const auto x = field(0), v = field(1);
  std::vector<double> x_in(x.size(), kUntouched), v_in(v.size(), kUntouched);
  ex.begin({x, v});
  ex.end({x_in, v_in});
  expectFromPrevious(x_in, 0);
  expectFromPrevious(v_in, 1);
  // The plan is kept: a second round gives the same.
  std::fill(x_in.begin(), x_in.end(), kUntouched);
  ex.begin({x, v});
  ex.end({x_in, v_in});
  expectFromPrevious(x_in, 0);
}

TEST(Exchange, ValuesArePackedAtBegin) {
  // Work between begin and end may overwrite what was sent (the solver's interior elements).
  Exchange ex = ring(1);
  auto x = field(0);
  std::vector<double> got(x.size(), kUntouched);
  ex.begin({x});
  std::fill(x.begin(), x.end(), 0.0);
  ex.end({got});
  expectFromPrevious(got, 0);
}

TEST(Exchange, TwoExchangesInFlightAtOnce) {
  Exchange a = ring(1), b = ring(1);
  const auto x = field(0), y = field(1);
  std::vector<double> x_in(x.size(), kUntouched), y_in(y.size(), kUntouched);
  a.begin({x});
  b.begin({y});
  b.end({y_in});
  a.end({x_in});
  expectFromPrevious(x_in, 0);
  expectFromPrevious(y_in, 1);
}

TEST(Exchange, OneWayFromRankZero) {
  // Contact nodes travel one way: rank 0 sends entry 2 to every rank (itself too), no rank
  // sends back.
  const int r = world().rank();
  std::vector<Exchange::Peer> peers;
  if (r == 0)
    for (int q = 0; q < world().size(); ++q) peers.push_back({q, {2}, {}});
  if (r == 0)
    peers[0].recv = {0};
  else
    peers.push_back({0, {}, {0}});
  Exchange ex(world(), std::move(peers), kComponents);
  const auto x = field(0);
  std::vector<double> got(x.size(), kUntouched);
  ex.begin({x});
  ex.end({got});
  for (int c = 0; c < kComponents; ++c) EXPECT_EQ(got[std::size_t(c)], value(0, 0, 2, c));
  EXPECT_EQ(got[kComponents], kUntouched);
}

TEST(Exchange, WithoutPeersDoesNothing) {
  Exchange none;
  Exchange dropped(world(), {{world().rank(), {}, {}}}, kComponents);
  EXPECT_TRUE(none.empty());
  EXPECT_TRUE(dropped.empty());
  std::vector<double> x(3, kUntouched);
  none.begin({x});
  none.end({x});
  EXPECT_EQ(x, std::vector<double>(3, kUntouched));
}

TEST(Exchange, RefusesAPlanOrUseThatCannotWork) {
  const int r = world().rank();
  EXPECT_THROW(Exchange(world(), {{world().size(), {0}, {}}}, kComponents), std::invalid_argument);
  EXPECT_THROW(Exchange(world(), {{-1, {}, {0}}}, kComponents), std::invalid_argument);
  EXPECT_THROW(Exchange(world(), {{r, {0, 1}, {0}}}, kComponents), std::invalid_argument);
  Exchange self(world(), {{r, {0}, {1}}}, kComponents, 2);
  std::vector<double> x(6, 0.0);
  EXPECT_THROW(self.begin({x}), std::logic_error);
  EXPECT_THROW(self.end({x, x}), std::logic_error);
  self.begin({x, x});
  EXPECT_THROW(self.begin({x, x}), std::logic_error);
  self.end({x, x});
}

// Ids beside values, as the contact sends them: the ids stay integers, exact beyond 2^53.
struct Tagged {
  int32_t rank = 0;
  int32_t index = 0;
  int64_t id = 0;
  double value = 0.0;
};

TEST(Communicator, AllGatherOfStructsInRankOrder) {
  const int r = world().rank();
  constexpr int64_t kBig = (int64_t(1) << 53) + 1;  // not a double
  std::vector<Tagged> mine;
  for (int32_t k = 0; k <= r; ++k) mine.push_back({r, k, kBig + r, 0.5 * k});
  const auto all = world().allGather(mine);
  std::size_t at = 0;
  for (int q = 0; q < world().size(); ++q)
    for (int32_t k = 0; k <= q; ++k, ++at) {
      ASSERT_LT(at, all.size());
      EXPECT_EQ(all[at].rank, q);
      EXPECT_EQ(all[at].index, k);
      EXPECT_EQ(all[at].id, kBig + q);
      EXPECT_EQ(all[at].value, 0.5 * k);
    }
  EXPECT_EQ(at, all.size());
  EXPECT_TRUE(world().allGather(std::vector<Tagged>{}).empty());
}

}  // namespace
