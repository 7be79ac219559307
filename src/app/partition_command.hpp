// `crumple partition DECK -n N [-o DIR] [--partition metis|rcb]`: partition only, to judge a
// decomposition before running on it (ARCHITECTURE.md, Commands).
#pragma once

#include <cstdio>
#include <string>

namespace crumple::app {

// Help text for the subcommand (main.cpp wires the options).
inline constexpr const char* kPartitionHelp =
    "Partition the deck's elements over N ranks without running it. Writes partition.json "
    "(per-rank elements, weight, nodes, shared nodes, neighbours, modelled communication) and "
    "partition.vtu (the mesh coloured by rank; open it in ParaView) into DIR, default "
    "<deck stem>.partition in the working directory. Both files are overwritten if present: "
    "they are cheap to recompute. Other files in DIR are left alone.";

// Reads `deck`, partitions its elements over `parts` ranks with `method` ("metis" or "rcb"),
// writes DIR/partition.json and DIR/partition.vtu (DIR = out_dir, or <deck stem>.partition
// when empty; created if missing) and prints a per-rank table to `out`.
// Returns 0, or 1 after printing "crumple: error: ..." to stderr.
int partitionCommand(const std::string& deck, int parts, const std::string& out_dir,
                     const std::string& method, std::FILE* out);

}  // namespace crumple::app
