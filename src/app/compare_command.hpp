// `crumple compare --lsdyna DIR --crumple RUN_DIR [...]`: Crumple's histories against
// LS-DYNA's ASCII output of the same deck (docs/validation.md). The work is done by the Python
// package python/crumple_compare (numpy, matplotlib); this command starts it.
#pragma once

#include <string>
#include <vector>

namespace crumple::app {

inline constexpr const char* kCompareHelp =
    "Compare Crumple's histories with LS-DYNA's ASCII files of the same deck: peak, end value, "
    "integral and ISO/TS 18571 rating per curve, plots; `crumple compare --help` for the "
    "options (run by /usr/bin/python3 with numpy and matplotlib)";

// Runs `python3 -m crumple_compare args...` and returns its exit status (0 done, 1 error, 2
// usage). The interpreter is $CRUMPLE_PYTHON or /usr/bin/python3; the package folder is
// $CRUMPLE_COMPARE_DIR or the source tree's python/ (CRUMPLE_PYTHON_DIR, set by CMake).
// Returns 1 after a message on stderr when either is missing.
int compareCommand(const std::vector<std::string>& args);

}  // namespace crumple::app
