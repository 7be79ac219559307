#!/usr/bin/env python3
"""`crumple check` reports every problem of a deck in one pass (input errors, features that
change the answer, what is read and not used), as text and as JSON; `crumple run` refuses a
deck whose skipped features change the answer unless told otherwise; `--cycles N` stops a run
after N cycles (issue "Real decks first")."""

import json
import os
import sys
import unittest

sys.dont_write_bytecode = True  # keep __pycache__ out of the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402
from clitest import crumple, describe, one_brick_deck, read_summary  # noqa: E402

# Three independent mistakes: a bad number, an element naming a node that does not exist,
# and a load naming a curve that does not exist. A compiler-like check lists all three.
THREE_ERRORS = one_brick_deck(extra=(
    "*MAT_ELASTIC\n         2   7.85e-6       abc       0.3\n"
    "*LOAD_NODE_POINT\n         1         1        77       1.0\n")).replace(
        "*END\n", "*ELEMENT_SOLID\n       2       1       1       2       3       4       5"
                  "       6       7      99\n*END\n")

# An implicit deck (IMFLAG 1) and an answer-changing keyword Crumple does not have.
IMPLICIT = one_brick_deck(extra="*CONTROL_IMPLICIT_GENERAL\n         1     0.001\n")
UNSUPPORTED = one_brick_deck(extra="*DAMPING_FREQUENCY_RANGE\n      0.05       1.0      30.0\n")


class CheckReport(clitest.TempDirTest):
    def line_of(self, text, needle):
        return text.splitlines().index(needle) + 1

    def test_every_input_error_in_one_pass(self):
        self.write("three.k", THREE_ERRORS)
        p = crumple("check", "three.k", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        lines = THREE_ERRORS.splitlines()
        bad_number = lines.index("         2   7.85e-6       abc       0.3") + 1
        bad_curve = lines.index("         1         1        77       1.0") + 1
        bad_node = len(lines) - 1  # the second element, just before *END
        expected = [f"three.k:{bad_number}: *MAT_ELASTIC card 1 field 3 (E): 'abc' is not a number",
                    f"three.k:{bad_node}: *ELEMENT_SOLID card 1 field 10 (N8): node 99 is not "
                    "defined",
                    f"three.k:{bad_curve}: *LOAD_NODE_POINT card 1 field 3 (LCID): curve 77 is "
                    "not defined"]
        self.assertIn("input errors: 3", p.stdout, describe(p))
        for e in expected:
            self.assertIn(e, p.stdout, describe(p))
            self.assertIn("crumple: error: " + e, p.stderr, describe(p))
        self.assertIn("the deck has 3 input error(s)", p.stderr, describe(p))

        j = crumple("check", "three.k", "--json", cwd=self.tmp)
        self.assertEqual(j.returncode, 1, describe(j))
        report = json.loads(j.stdout)
        self.assertEqual(report["status"], "error")
        self.assertEqual(sorted(e["message"] for e in report["errors"]), sorted(expected))
        self.assertEqual(sorted(e["where"] for e in report["errors"]),
                         sorted(f"three.k:{n}" for n in (bad_number, bad_node, bad_curve)))

    def test_json_of_a_deck_that_reads(self):
        self.write("ok.k", one_brick_deck())
        p = crumple("check", "ok.k", "--json", cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        report = json.loads(p.stdout)
        self.assertEqual(report["status"], "ok")
        self.assertEqual(report["errors"], [])
        self.assertEqual(report["counts"]["solids"], 1)
        self.assertEqual(report["counts"]["nodes"], 8)
        self.assertGreater(report["initial_dt"], 0.0)
        self.assertAlmostEqual(report["end_time"], 0.01)

    def test_tetrahedra_counted_per_part(self):
        # tet_blocks.k: part 1 native ELFORM 10, part 2 degenerate hexahedra sorted by ESORT.
        deck = os.path.join(clitest.SOURCE_DIR, "tests", "data", "decks", "tet_blocks.k")
        p = crumple("check", deck, cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        self.assertRegex(p.stdout, r"(?m)^  part 1 .*: 162 solids, .*, 162 as ELFORM 10 tetrahedra$",
                         describe(p))
        self.assertRegex(p.stdout, r"(?m)^  part 2 .*: 384 solids, .*, 384 as ELFORM 10 tetrahedra$",
                         describe(p))
        self.assertNotIn("degenerate solid", p.stdout, describe(p))

    def test_pentahedra_counted_per_part(self):
        # prism_blocks.k: part 1 native ELFORM 15, part 2 degenerate hexahedra sorted by ESORT.
        deck = os.path.join(clitest.SOURCE_DIR, "tests", "data", "decks", "prism_blocks.k")
        p = crumple("check", deck, cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        self.assertRegex(p.stdout, r"(?m)^  part 1 .*: 54 solids, .*, 54 as ELFORM 15 pentahedra$",
                         describe(p))
        self.assertRegex(p.stdout,
                         r"(?m)^  part 2 .*: 128 solids, .*, 128 as ELFORM 15 pentahedra$",
                         describe(p))
        self.assertNotIn("degenerate solid", p.stdout, describe(p))

    def test_implicit_deck_refused_unless_run_explicitly_on_request(self):
        self.write("imp.k", IMPLICIT)
        p = crumple("check", "imp.k", "--json", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        report = json.loads(p.stdout)
        self.assertEqual(report["status"], "refused")
        changing = [u for u in report["unsupported"] if u["changes_answer"]]
        self.assertEqual([u["feature"] for u in changing], ["implicit analysis"])
        out = os.path.join(self.tmp, "out")
        p = crumple("run", "imp.k", "-o", out, "-q", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("IMFLAG 1 asks for an implicit analysis", p.stderr, describe(p))
        self.assertIn("--implicit-as-explicit", p.stderr, describe(p))
        self.assertFalse(os.path.exists(out))
        p = crumple("run", "imp.k", "-o", out, "-q", "--implicit-as-explicit", "--cycles", "3",
                    cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        with open(os.path.join(out, "run.log"), encoding="utf-8") as f:
            self.assertIn("run explicitly (--implicit-as-explicit)", f.read())

    def test_answer_changing_keyword_refused_and_ignored_on_request(self):
        self.write("damp.k", UNSUPPORTED)
        p = crumple("check", "damp.k", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("not supported, and leaving it out would change the answer:\n"
                      "  *DAMPING_FREQUENCY_RANGE (1x", p.stdout, describe(p))
        out = os.path.join(self.tmp, "out")
        p = crumple("run", "damp.k", "-o", out, "-q", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("*DAMPING_FREQUENCY_RANGE", p.stderr, describe(p))
        p = crumple("run", "damp.k", "-o", out, "-q", "--ignore-unsupported", "--cycles", "4",
                    cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        s = read_summary(out)
        self.assertEqual(s["ignored_unsupported"], ["*DAMPING_FREQUENCY_RANGE"])
        self.assertEqual(s["cycles"], 4)

    def test_cycles_stops_a_run_after_n_cycles(self):
        self.write("brick.k", one_brick_deck(end_time=1.0))
        out = os.path.join(self.tmp, "out")
        p = crumple("run", "brick.k", "-o", out, "-q", "--cycles", "7", cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        s = read_summary(out)
        self.assertEqual(s["termination"], "normal")
        self.assertEqual(s["cycles"], 7)
        self.assertLess(s["end_time"], 1.0)
        self.assertNotIn("ignored_unsupported", s)


if __name__ == "__main__":
    clitest.main()
