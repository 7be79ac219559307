// crumple: explicit finite-element crash and impact solver.
#include <CLI/CLI.hpp>

#include "app/advise_command.hpp"
#include "app/commands.hpp"
#include "app/partition_command.hpp"
#include "app/python_tool.hpp"
#include "comm/communicator.hpp"

namespace {
int dispatch(int argc, char** argv);
}

int main(int argc, char** argv) {
  // MPI starts only under mpirun; a plain run is one serial rank.
  crumple::comm::initialize(&argc, &argv);
  const int status = dispatch(argc, argv);
  crumple::comm::finalize();
  return status;
}

namespace {
int dispatch(int argc, char** argv) {
  CLI::App app{"Crumple: parallel explicit finite-element code for crash and impact", "crumple"};
  app.set_version_flag("--version", std::string("crumple ") + CRUMPLE_VERSION);
  app.require_subcommand(1);

  crumple::app::RunOptions run;
  auto* run_cmd = app.add_subcommand("run", "Run an LS-DYNA-style keyword deck");
  run_cmd->add_option("deck", run.deck, "Keyword deck (.k)")->required()->check(CLI::ExistingFile);
  run_cmd->add_option("-o,--output", run.output_dir,
                      "Results folder (default: <deck stem>.out in the working directory)");
  run_cmd->add_option("--threads", run.threads, "OpenMP threads per rank (default: all cores)")
      ->check(CLI::PositiveNumber);
  run_cmd->add_option("--endtime", run.end_time, "End time, overriding *CONTROL_TERMINATION")
      ->check(CLI::PositiveNumber);
  run_cmd->add_flag("--strict", run.strict, "Treat unsupported keywords as errors");
  run_cmd
      ->add_option("--cycles", run.cycles, "Stop after N cycles (as *CONTROL_TERMINATION ENDCYC)")
      ->check(CLI::PositiveNumber);
  run_cmd->add_flag("--ignore-unsupported", run.ignore_unsupported,
                    "Run a deck that uses unsupported features which change the answer, leaving "
                    "them out (said in run.log and summary.json)");
  run_cmd->add_flag("--implicit-as-explicit", run.implicit_as_explicit,
                    "Run an implicit deck (*CONTROL_IMPLICIT_GENERAL IMFLAG 1) explicitly; the "
                    "answer will differ");
  run_cmd->add_flag("--overwrite", run.overwrite,
                    "Replace the results of an earlier run in the results folder");
  run_cmd->add_flag("-q,--quiet", run.quiet, "No progress line");
  run_cmd->add_option("--partition", run.partition, "Element partitioner under mpirun")
      ->check(CLI::IsMember({"metis", "rcb"}));
  run_cmd
      ->add_option("--contact-bias", run.contact_bias,
                   "Partition weight factor of elements on contact surfaces (default 1)")
      ->check(CLI::PositiveNumber);
  run_cmd->add_option("--restart", run.restart,
                      "Continue from a restart dump (a d3dump_ file, or a results folder: its "
                      "newest dump), in that dump's folder unless -o is given");
  auto* restart_deck =
      run_cmd
          ->add_option("--restart-deck", run.restart_deck,
                       "With --restart: a deck of *CONTROL_TERMINATION and *DATABASE_ changes")
          ->check(CLI::ExistingFile);
  restart_deck->needs(run_cmd->get_option("--restart"));
  run_cmd
      ->add_option("--checkpoint-every", run.checkpoint_every,
                   "Write a restart dump every SECONDS of wall time (the two newest are kept)")
      ->check(CLI::PositiveNumber);
  run_cmd
      ->add_option("--d3plot-x", run.d3plot_x,
                   "Largest d3plot family member, in 512^2 words (LS-DYNA's x=; default 7)")
      ->check(CLI::PositiveNumber);
  run_cmd
      ->add_option("--energy-band", run.energy_band,
                   "LO,HI: error termination when the energy ratio leaves [LO, HI] (checked "
                   "every 64 cycles; default: no check)")
      ->delimiter(',')
      ->expected(2);

  crumple::app::CheckOptions check;
  auto* check_cmd = app.add_subcommand(
      "check",
      "Read and validate a deck; print its contents, mass, time step and what is unsupported");
  check_cmd->add_option("deck", check.deck, "Keyword deck (.k)")
      ->required()
      ->check(CLI::ExistingFile);
  check_cmd->add_flag("--strict", check.strict, "Exit with an error if anything is unsupported");
  check_cmd->add_flag("--json", check.json, "Write the report as one JSON object");
  check_cmd->add_flag("--implicit-as-explicit", check.implicit_as_explicit,
                      "Check an implicit deck as it would run explicitly");

  std::string part_deck, part_dir, part_method = "metis";
  int part_count = 0;
  auto* part_cmd = app.add_subcommand("partition", crumple::app::kPartitionHelp);
  part_cmd->add_option("deck", part_deck, "Keyword deck (.k)")
      ->required()
      ->check(CLI::ExistingFile);
  auto* parts_opt =
      part_cmd->add_option("-n,--parts", part_count, "Number of ranks")->check(CLI::PositiveNumber);
  part_cmd->add_option("-o,--output", part_dir, "Output folder (default: <deck stem>.partition)");
  part_cmd->add_option("--partition", part_method, "Partitioner")
      ->check(CLI::IsMember({"metis", "rcb"}));
  crumple::app::AdviseOptions advise;
  bool advise_flag = false;
  auto* advise_opt = part_cmd->add_flag(
      "--advise", advise_flag,
      "Instead of one partition: time the deck's serial cycle, partition it for 1..MAX ranks and "
      "predict the time per cycle and parallel efficiency of each; advise the most ranks at 80% "
      "efficiency or more (docs/parallel.md). Under `mpirun -np 2` it measures the network too");
  part_cmd->add_option("--max", advise.max_ranks, "Most ranks to predict for (--advise)")
      ->check(CLI::Range(1, 4096))
      ->needs(advise_opt);
  part_cmd->add_option("--sample-cycles", advise.sample_cycles, "Serial cycles timed (--advise)")
      ->check(CLI::Range(1, 100000))
      ->needs(advise_opt);
  auto* from_run_opt =
      part_cmd
          ->add_option("--from-run", advise.from_run,
                       "A run of this deck on 1 rank, 1 thread: take its whole-run costs per "
                       "cycle instead of timing a sample (--advise)")
          ->check(CLI::ExistingDirectory)
          ->needs(advise_opt);
  from_run_opt->excludes("--sample-cycles");
  parts_opt->excludes(advise_opt);
  part_cmd->callback([&] {
    if (!advise_flag && part_count == 0) throw CLI::RequiredError("-n,--parts (or --advise)");
  });

  // Every argument after `compare`, `plot` or `report` goes to the Python tool, which owns those
  // options and their --help (src/app/python_tool.hpp).
  auto* compare_cmd = app.add_subcommand("compare", crumple::app::kCompareHelp);
  compare_cmd->prefix_command()->allow_extras()->set_help_flag();
  auto* plot_cmd = app.add_subcommand("plot", crumple::app::kPlotHelp);
  plot_cmd->prefix_command()->allow_extras()->set_help_flag();
  auto* report_cmd = app.add_subcommand("report", crumple::app::kReportHelp);
  report_cmd->prefix_command()->allow_extras()->set_help_flag();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (!crumple::comm::world().isRoot()) return e.get_exit_code() == 0 ? 0 : 2;
    const int code = app.exit(e);
    // CLI11 returns 0 for --help/--version; every real usage error is exit status 2.
    return code == 0 ? 0 : 2;
  }
  if (*run_cmd) return crumple::app::runCommand(run);
  // The network measurement of --advise needs every rank.
  if (*part_cmd && advise_flag) {
    advise.deck = part_deck;
    advise.out_dir = part_dir;
    advise.method = part_method;
    return crumple::app::adviseCommand(advise, stdout);
  }
  // check and partition are serial tools: under mpirun only rank 0 works.
  if (!crumple::comm::world().isRoot()) return 0;
  if (*compare_cmd)
    return crumple::app::pythonToolCommand("compare", "crumple_compare", compare_cmd->remaining());
  if (*plot_cmd)
    return crumple::app::pythonToolCommand("plot", "crumple_compare.plot", plot_cmd->remaining());
  if (*report_cmd)
    return crumple::app::pythonToolCommand("report", "crumple_compare.run_report",
                                           report_cmd->remaining());
  if (*check_cmd) return crumple::app::checkCommand(check, stdout);
  if (*part_cmd)
    return crumple::app::partitionCommand(part_deck, part_count, part_dir, part_method, stdout);
  return 2;
}
}  // namespace
