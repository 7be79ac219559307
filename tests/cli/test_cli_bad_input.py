#!/usr/bin/env python3
"""Bad input and a bad environment end cleanly (issue 6, "Bad input and environment").

Every deck of tests/data/malformed (with tests/data/malformed/expected.json) goes through
`crumple check` and `crumple run`: exit status 1, one 'crumple: error:' message holding the
expected fragments (file:line and what is wrong), no traceback, abort or sanitizer report, and
the run leaves no results folder behind. A deck with a 2 GB line (a sparse file: 2 GB apparent,
a few KiB on disk) must be refused quickly and without holding the line in memory. Results
folders that cannot be written (below a regular file, which fails even for root; or read-only,
skipped as root) and a missing include fail before the first cycle with nothing left behind."""

import json
import os
import resource
import shutil
import stat
import time

import clitest
from clitest import TempDirTest, crumple, describe, main

BAD_SIGNS = ["Traceback", "Sanitizer", "runtime error", "terminate called", "Aborted",
             "core dumped", "what():"]


def malformed_dir():
    return os.path.join(clitest.SOURCE_DIR, "tests", "data", "malformed")


def write_long_line_deck(path, size=2 * 1024**3):
    """A deck whose third line is `size` bytes long, as a sparse file: the first MiB is real
    text (a title of 'x'), the rest a hole that reads as NUL bytes; no line end anywhere."""
    with open(path, "wb") as f:
        f.write(b"*KEYWORD\n*TITLE\n")
        f.write(b"x" * (1 << 20))
        f.truncate(size)


class BadInput(TempDirTest):
    def setUp(self):
        super().setUp()
        with open(os.path.join(malformed_dir(), "expected.json"), encoding="utf-8") as f:
            self.expected = {k: v for k, v in json.load(f).items() if not k.startswith("_")}
        # The decks are copied next to each other so that messages name them by bare file name
        # (and includes find their partners).
        self.decks = os.path.join(self.tmp, "decks")
        shutil.copytree(malformed_dir(), self.decks)
        write_long_line_deck(os.path.join(self.decks, "long_line.k"))

    def check_failure(self, p, name, fragments):
        self.assertEqual(p.returncode, 1, f"{name}: {describe(p)}")
        self.assertIn("crumple: error:", p.stderr, f"{name}: {describe(p)}")
        for bad in BAD_SIGNS:
            self.assertNotIn(bad, p.stderr, f"{name}: {describe(p)}")
        for fragment in fragments:
            self.assertIn(fragment, p.stderr, f"{name}: expected {fragment!r}{describe(p)}")

    def test_every_malformed_deck_fails_cleanly(self):
        handled = 0
        for key, fragments in sorted(self.expected.items()):
            name = key.split(":", 1)[-1]
            with self.subTest(deck=name):
                started = time.monotonic()
                p = crumple("check", name, cwd=self.decks)
                self.check_failure(p, name, fragments)
                out = os.path.join(self.tmp, "out_" + name)
                p = crumple("run", name, "-o", out, "-q", cwd=self.decks)
                self.check_failure(p, name, fragments)
                self.assertFalse(os.path.exists(out), f"{name}: the failed run left {out}")
                self.assertLess(time.monotonic() - started, 20, name)
                handled += 1
        print(f"malformed decks handled cleanly: {handled} of {len(self.expected)}")
        self.assertEqual(handled, len(self.expected))

    def test_long_line_is_refused_without_reading_it(self):
        path = os.path.join(self.decks, "long_line.k")
        self.assertEqual(os.path.getsize(path), 2 * 1024**3)
        started = time.monotonic()
        p = crumple("check", path)
        elapsed = time.monotonic() - started
        self.check_failure(p, "long_line.k", ["long_line.k:3:", "line longer than"])
        self.assertLess(elapsed, 10, "the reader read on instead of stopping at the cap")
        # The largest child so far (kilobytes on Linux): far below the 2 GB of the line.
        peak_mib = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
        self.assertLess(peak_mib, 512, f"peak memory of a child {peak_mib:.0f} MiB")

    def test_every_malformed_deck_is_listed(self):
        # A deck added to the folder without an expected message would silently go untested.
        listed = {k.split(":", 1)[-1] for k in self.expected}
        on_disk = {f for f in os.listdir(malformed_dir()) if f.endswith(".k")}
        # include_cycle_b.k is reached through include_cycle_a.k.
        self.assertEqual(on_disk - listed, {"include_cycle_b.k"})


class BadEnvironment(TempDirTest):
    def deck(self):
        return self.write("brick.k", clitest.one_brick_deck(end_time=0.001))

    def test_results_folder_below_a_regular_file(self):
        # Fails for every user, root included: a regular file cannot hold a folder.
        deck = self.deck()
        blocker = self.write("blocker", "not a folder\n")
        p = crumple("run", deck, "-o", os.path.join(blocker, "sub"), "-q")
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("crumple: error:", p.stderr)
        self.assertIn("cannot create results folder", p.stderr, describe(p))
        self.assertIn(os.path.join(blocker, "sub"), p.stderr)
        with open(blocker, encoding="utf-8") as f:
            self.assertEqual(f.read(), "not a folder\n")

    def test_read_only_results_folder(self):
        if os.geteuid() == 0:
            self.skipTest("running as root: a read-only mode does not stop root from writing")
        deck = self.deck()
        out = os.path.join(self.tmp, "ro")
        os.mkdir(out)
        os.chmod(out, stat.S_IRUSR | stat.S_IXUSR)
        try:
            p = crumple("run", deck, "-o", out, "-q")
            self.assertEqual(p.returncode, 1, describe(p))
            self.assertIn("cannot write to results folder", p.stderr, describe(p))
            self.assertEqual(os.listdir(out), [])
        finally:
            os.chmod(out, stat.S_IRWXU)

    def test_missing_include_leaves_nothing(self):
        deck = self.write("inc.k", clitest.one_brick_deck(extra="*INCLUDE\nnowhere/mesh.k\n"))
        out = os.path.join(self.tmp, "out")
        p = crumple("run", deck, "-o", out, "-q")
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("inc.k:14: *INCLUDE: cannot open 'nowhere/mesh.k'", p.stderr, describe(p))
        self.assertFalse(os.path.exists(out))

    def test_failure_before_first_state_removes_what_the_run_created(self):
        # A results folder in which the first plot state cannot be written: the states
        # subfolder is taken by a regular file. The run fails before its first cycle and removes
        # the files it created, keeping the folder (it existed) and what was there before.
        deck = self.deck()
        out = os.path.join(self.tmp, "out")
        os.mkdir(out)
        self.write(os.path.join("out", "states"), "mine\n")
        self.write(os.path.join("out", "notes.txt"), "mine too\n")
        p = crumple("run", deck, "-o", out, "-q")
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("crumple: error", p.stderr)
        self.assertEqual(sorted(os.listdir(out)), ["notes.txt", "states"], describe(p))


if __name__ == "__main__":
    main()
