// The commands whose work is done by the Python package python/crumple_compare (numpy,
// matplotlib): `crumple compare` (Crumple's histories against LS-DYNA's ASCII output of the same
// deck, docs/validation.md), `crumple plot` (a run's curves as PNG) and `crumple report` (a
// run's HTML page; both README "Using it"). This file starts the interpreter on the package's
// module for the command.
#pragma once

#include <string>
#include <vector>

namespace crumple::app {

inline constexpr const char* kCompareHelp =
    "Compare Crumple's histories with LS-DYNA's ASCII files of the same deck: peak, end value, "
    "integral and ISO/TS 18571 rating per curve, plots; `crumple compare --help` for the "
    "options (run by /usr/bin/python3 with numpy and matplotlib)";

inline constexpr const char* kPlotHelp =
    "Plot a run's histories as PNG: energies with the energy ratio, contact, wall and section "
    "forces, part energies, node histories (accelerations SAE J211 CFC filtered on request); "
    "`crumple plot --help` for the options (run by /usr/bin/python3 with numpy and matplotlib)";

inline constexpr const char* kReportHelp =
    "One self-contained HTML page of a run: model, energy balance with plot and verdict, time "
    "breakdown and parallel efficiency, warnings, partition picture, largest contact and wall "
    "forces, links to the result files; `crumple report --help` for the options";

// Runs `python3 -m <module> args...` for the command `tool` ("compare", "plot") and returns its
// exit status (0 done, 1 error, 2 usage). The interpreter is $CRUMPLE_PYTHON or
// /usr/bin/python3; the package folder is $CRUMPLE_COMPARE_DIR or the source tree's python/
// (CRUMPLE_PYTHON_DIR, set by CMake). Returns 1 after a message on stderr when either is
// missing.
int pythonToolCommand(const std::string& tool, const std::string& module,
                      const std::vector<std::string>& args);

}  // namespace crumple::app
