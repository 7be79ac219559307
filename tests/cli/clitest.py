"""Shared helpers for the command-line tests in tests/cli/test_*.py (Python 3 stdlib only).

Every script is run by ctest as

    python3 tests/cli/test_NAME.py <path-to-crumple> <source-dir>

`main()` takes those two positional arguments off sys.argv, runs the script's unittest cases,
prints 'N passed, N failed' and exits non-zero on any failure or error. Skipped tests count as
neither (they are listed with their reason).
"""

import csv
import importlib
import json
import os
import subprocess
import sys
import tempfile
import unittest

CRUMPLE = None  # absolute path of the crumple executable
SOURCE_DIR = None  # absolute path of the source tree (holds examples/, tests/)

# The 2-thread runs share the machine with builds and benchmarks; a passive wait policy keeps
# an OpenMP barrier from spinning against a busy core. It does not change any result.
_ENV = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")

# A one-run budget well under the per-script 60 s aim; a hung run fails instead of stalling.
RUN_TIMEOUT = 50


def crumple(*args, cwd=None, timeout=RUN_TIMEOUT):
    """Runs crumple with `args`; returns the CompletedProcess (text stdout/stderr)."""
    return subprocess.run([CRUMPLE, *map(str, args)], cwd=cwd, capture_output=True, text=True,
                          timeout=timeout, env=_ENV)


def describe(proc):
    """The exit status and both streams of a finished run, for assertion messages."""
    return (f"\n  command: {' '.join(proc.args)}\n  exit status: {proc.returncode}"
            f"\n  stdout: {proc.stdout.strip()[:2000]!r}\n  stderr: {proc.stderr.strip()[:2000]!r}")


def tools_module(name):
    """The module `name` of the source tree's tools/ (the deck generators)."""
    sys.path.insert(0, os.path.join(SOURCE_DIR, "tools"))
    return importlib.import_module(name)


def history_rows(folder, name):
    """A CSV history of a results folder (glstat.csv, matsum.csv, ...) as rows of floats. A row
    repeating the time of an earlier one for the same part/node/contact/side (the final sample
    when the end time is also an output time is written twice) is dropped, so that sums over
    the rows of one time count each part once."""
    with open(os.path.join(folder, name), encoding="utf-8") as f:
        out, seen = [], set()
        for r in csv.DictReader(f):
            r = {k: float(v) for k, v in r.items()}
            key = tuple(v for k, v in r.items() if k in ("time", "part", "node", "contact", "side"))
            if key not in seen:
                seen.add(key)
                out.append(r)
        return out


def read_summary(folder):
    with open(os.path.join(folder, "summary.json"), encoding="utf-8") as f:
        return json.load(f)


def read_vtu(folder, *flags):
    """Reads a results folder with VTK's own readers (tests/tools/read_vtu.py); returns the
    parsed JSON, or raises unittest.SkipTest when no Python with vtk is available (exit 77)."""
    script = os.path.join(SOURCE_DIR, "tests", "tools", "read_vtu.py")
    proc = subprocess.run(["/usr/bin/python3" if os.path.exists("/usr/bin/python3")
                           else sys.executable, script, folder, *flags],
                          capture_output=True, text=True, timeout=120)
    if proc.returncode == 77:
        raise unittest.SkipTest("no Python with the vtk module: " + proc.stderr.strip())
    if proc.returncode != 0:
        raise AssertionError(f"read_vtu.py failed on {folder}:{describe(proc)}")
    return json.loads(proc.stdout)


# The environment of `mpirun` in the tests: root allowed, oversubscription, passive OpenMP waits.
MPI_ENV = dict(os.environ, OMP_WAIT_POLICY="PASSIVE", OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
# Open MPI's components leave allocations LeakSanitizer cannot attribute (no frame of ours);
# address and undefined-behaviour checks stay on.
MPI_ENV["ASAN_OPTIONS"] = (MPI_ENV.get("ASAN_OPTIONS", "") + ":detect_leaks=0").lstrip(":")


def missing_module(*names):
    """The first of the Python modules `names` this interpreter lacks, or None."""
    import importlib
    for name in names:
        try:
            importlib.import_module(name)
        except ImportError:
            return name
    return None


def example(*parts):
    return os.path.join(SOURCE_DIR, "examples", *parts)


def shared_decks():
    """source-dir/../shared/decks (the real-world decks), or None when absent."""
    path = os.path.normpath(os.path.join(SOURCE_DIR, "..", "shared", "decks"))
    return path if os.path.isdir(path) else None


class TempDirTest(unittest.TestCase):
    """A test case with a fresh temporary folder self.tmp, removed afterwards."""

    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="crumple_cli_")
        self.tmp = self._tmp.name

    def tearDown(self):
        self._tmp.cleanup()

    def write(self, name, text):
        path = os.path.join(self.tmp, name)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        return path

    def run_deck(self, name, text):
        """Runs the deck `text` as NAME.k in self.tmp (quietly); asserts it ends normally and
        returns its results folder NAME.out."""
        path = self.write(name + ".k", text)
        out = os.path.join(self.tmp, name + ".out")
        p = crumple("run", path, "-o", out, "-q", cwd=self.tmp, timeout=600)
        self.assertEqual(p.returncode, 0, describe(p))
        return out


def one_brick_deck(title="one brick", material_id=1, extra="", end_time=0.01):
    """A unit cube of one hex (element 1, part 1, nodes 1-8), steel in mm/ms/kg/GPa."""
    nodes = [(1, 0, 0, 0), (2, 1, 0, 0), (3, 1, 1, 0), (4, 0, 1, 0),
             (5, 0, 0, 1), (6, 1, 0, 1), (7, 1, 1, 1), (8, 0, 1, 1)]
    s = f"*KEYWORD\n*TITLE\n{title}\n*CONTROL_TERMINATION\n{end_time:10.4g}\n"
    s += f"*PART\nblock\n         1         1{material_id:10d}\n"
    s += "*SECTION_SOLID\n         1         1\n"
    s += "*MAT_ELASTIC\n$      mid        ro         e        pr\n"
    s += "         1   7.85e-6     210.0       0.3\n"
    s += extra
    s += "*NODE\n" + "".join(f"{n:8d}{x:16.6f}{y:16.6f}{z:16.6f}\n" for n, x, y, z in nodes)
    s += "*ELEMENT_SOLID\n" + "".join(f"{v:8d}" for v in (1, 1, 1, 2, 3, 4, 5, 6, 7, 8)) + "\n"
    return s + "*END\n"


def main():
    global CRUMPLE, SOURCE_DIR
    if len(sys.argv) < 3:
        sys.stderr.write(f"usage: {sys.argv[0]} <path-to-crumple> <source-dir> [unittest args]\n")
        sys.exit(2)
    CRUMPLE = os.path.abspath(sys.argv[1])
    SOURCE_DIR = os.path.abspath(sys.argv[2])
    del sys.argv[1:3]
    if not os.access(CRUMPLE, os.X_OK):
        sys.stderr.write(f"{CRUMPLE} is not an executable\n")
        sys.exit(1)
    program = unittest.main(module="__main__", exit=False, verbosity=2)
    result = program.result
    failed = len(result.failures) + len(result.errors) + len(result.unexpectedSuccesses)
    skipped = len(result.skipped)
    passed = result.testsRun - failed - skipped
    print(f"{passed} passed, {failed} failed" + (f", {skipped} skipped" if skipped else ""))
    sys.exit(1 if failed or result.testsRun == 0 else 0)
