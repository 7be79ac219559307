// The crumple subcommands, callable from main() and from tests.
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace crumple::app {

struct RunOptions {
  std::string deck;
  std::string output_dir;           // empty: <deck stem>.out next to the working directory
  int threads = 0;                  // 0: OpenMP default
  std::optional<double> end_time;   // overrides *CONTROL_TERMINATION ENDTIM
  bool strict = false;              // unsupported keywords are errors
  bool overwrite = false;           // replace results of an earlier run in the folder
  bool quiet = false;               // no progress line
  std::string partition = "metis";  // element partitioner for distributed runs: metis or rcb
  double contact_bias = 1.0;        // weight factor of elements on contact surfaces
  // Restart (docs/reliability.md): a dump file, or a results folder whose newest dump is
  // taken; the run continues in the dump's folder (or -o) from the dumped state.
  std::string restart;
  std::string restart_deck;         // *CONTROL_TERMINATION / *DATABASE_ changes at restart
  double checkpoint_every = 0.0;    // wall seconds between dumps; 0: none
  std::vector<double> energy_band;  // --energy-band LO,HI: error when the energy ratio leaves it
  double d3plot_x = 0.0;            // --d3plot-x: d3plot family member size / 512^2 words; 0: 7
  int64_t cycles = 0;               // --cycles N: stop after N cycles (as ENDCYC); 0: no limit
  // Run a deck that uses unsupported features which change the answer, leaving them out.
  bool ignore_unsupported = false;
  bool implicit_as_explicit = false;  // run an implicit deck explicitly
};

// Exit status: 0 normal termination, 1 error termination (ARCHITECTURE.md, Commands).
int runCommand(const RunOptions& opt);

struct CheckOptions {
  std::string deck;
  bool strict = false;
  bool json = false;  // the report as one JSON object on stdout
  bool implicit_as_explicit = false;
};
int checkCommand(const CheckOptions& opt, std::FILE* out);

}  // namespace crumple::app
