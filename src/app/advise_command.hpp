// `crumple partition DECK --advise [--max N]`: how many ranks to run the deck on
// (docs/parallel.md, "How many ranks"). Under `mpirun -np 2` the message latency and bandwidth
// are measured by a ping-pong; alone, the defaults of partition::CommModel stand in and the
// report says so.
#pragma once

#include <cstdio>
#include <string>

namespace crumple::app {

struct AdviseOptions {
  std::string deck;
  std::string out_dir;  // advise.json goes here (default <deck stem>.partition)
  std::string method = "metis";
  int max_ranks = 64;
  int sample_cycles = 100;  // serial cycles timed, after kWarmUpCycles
  std::string from_run;     // a serial run's folder: its whole-run costs instead of a sample
};

// Every rank calls it (the ping-pong is collective); rank 0 reads the deck, times its serial
// cycle, partitions it for each candidate rank count, prints the table and the advice to `out`
// and writes advise.json. Returns 0, or 1 after "crumple: error: ..." on stderr.
int adviseCommand(const AdviseOptions& opt, std::FILE* out);

}  // namespace crumple::app
