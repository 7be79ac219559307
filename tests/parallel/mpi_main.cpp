// The main of the unit tests that run under mpirun (ctest's parallel.exchange_*): every rank
// runs every test (and prints, so that a failure on any rank is seen), and the run fails when a
// test fails on any rank.
#include <gtest/gtest.h>

#include <cstdio>

#include "comm/communicator.hpp"

int main(int argc, char** argv) {
  crumple::comm::initialize(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  auto& world = crumple::comm::world();
  // Said in the log: a run that did not start MPI would pass as serial runs.
  if (world.isRoot()) std::printf("%d ranks\n", world.size());
  const bool failed = world.anyAll(RUN_ALL_TESTS() != 0);
  crumple::comm::finalize();
  return failed ? 1 : 0;
}
