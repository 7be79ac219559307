#!/usr/bin/env python3
"""The compatibility matrix over the real-world decks (source-dir/../shared/decks; the tests
skip with a message when that folder is absent): tools/compatibility.py is run once into a
temporary folder and its raw results are checked.

Fails when a deck crashes or hangs crumple, when a deck listed in
tests/data/compatibility_expected.json no longer reads, when a deck that reads fails its short
run, or when docs/compatibility.md is not what the script writes now (only compared when the
binary has `check --json`; an older binary writes a different page)."""

import difflib
import json
import os
import subprocess
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # keep __pycache__ out of the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402

# The whole matrix takes seconds per deck at most; a deck that hangs costs the script's own
# 120 s timeout. Stay under ctest's 600 s for the cli label.
SCRIPT_TIMEOUT = 540

_MATRIX = {}  # the one run of the script, shared by the tests


def matrix():
    """Runs tools/compatibility.py once (default cycles, one job) and returns
    {"raw": parsed --json output, "page": the Markdown it wrote}; skips without the corpus."""
    decks = clitest.shared_decks()
    if decks is None:
        raise unittest.SkipTest("../shared/decks is absent: no real-world decks to assess")
    if not _MATRIX:
        with tempfile.TemporaryDirectory(prefix="crumple_cli_") as tmp:
            page, raw = os.path.join(tmp, "compatibility.md"), os.path.join(tmp, "results.json")
            script = os.path.join(clitest.SOURCE_DIR, "tools", "compatibility.py")
            proc = subprocess.run([sys.executable, script, "--crumple", clitest.CRUMPLE,
                                   "--decks", decks, "--out", page, "--json", raw, "--jobs", "1"],
                                  capture_output=True, text=True, timeout=SCRIPT_TIMEOUT)
            if proc.returncode != 0:
                raise AssertionError(f"tools/compatibility.py failed:{clitest.describe(proc)}")
            with open(raw, encoding="utf-8") as f:
                _MATRIX["raw"] = json.load(f)
            with open(page, encoding="utf-8") as f:
                _MATRIX["page"] = f.read()
    return _MATRIX


def records():
    return {r["deck"]: r for r in matrix()["raw"]["results"]}


def expected_reads():
    path = os.path.join(clitest.SOURCE_DIR, "tests", "data", "compatibility_expected.json")
    with open(path, encoding="utf-8") as f:
        return json.load(f)["reads"]


def outcome(record):
    """'check crash', 'run hang', ... or the check status, for failure messages."""
    run = record["run"]
    check = record["check"]
    if check["status"] in ("crash", "hang") or run is None:
        return f"check {check['status']} {check.get('detail', '')}".rstrip()
    return f"run {run['end']}: {run.get('message', '')}"


class Compatibility(unittest.TestCase):
    def test_no_deck_crashes_or_hangs(self):
        bad = {name: outcome(r) for name, r in records().items()
               if r["check"]["status"] in ("crash", "hang")
               or (r["run"] and r["run"]["end"] in ("crash", "hang"))}
        self.assertEqual(bad, {}, "crumple crashed or hung on these decks")

    def test_expected_decks_still_read(self):
        found = records()
        lost = {name: (found[name]["check"]["status"] if name in found else "not in the corpus")
                for name in expected_reads()
                if name not in found or found[name]["check"]["status"] != "ok"}
        self.assertEqual(lost, {}, "decks in tests/data/compatibility_expected.json no longer read")
        new = sorted(n for n, r in found.items()
                     if r["check"]["status"] == "ok" and n not in expected_reads())
        if new:  # not a failure: the lead adds them to the expectations when they are meant to
            print(f"note: these decks read but are not in compatibility_expected.json: {new}")

    def test_decks_that_read_also_run(self):
        failed = {name: outcome(r) for name, r in records().items()
                  if r["check"]["status"] == "ok" and r["run"]["end"] != "runs"}
        self.assertEqual(failed, {}, "decks that read but fail their short run")

    def test_committed_page_is_current(self):
        m = matrix()
        if not m["raw"]["check_json"]:
            self.skipTest("this crumple has no `check --json`: its page would differ by design")
        path = os.path.join(clitest.SOURCE_DIR, "docs", "compatibility.md")
        with open(path, encoding="utf-8") as f:
            committed = f.read()
        if committed != m["page"]:
            diff = "".join(list(difflib.unified_diff(
                committed.splitlines(True), m["page"].splitlines(True),
                "docs/compatibility.md", "tools/compatibility.py now"))[:80])
            self.fail("docs/compatibility.md is out of date; regenerate it with "
                      "`python3 tools/compatibility.py --crumple <crumple>`:\n" + diff)


if __name__ == "__main__":
    clitest.main()
