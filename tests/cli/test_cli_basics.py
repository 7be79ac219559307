#!/usr/bin/env python3
"""The crumple command line: version, help, usage errors (exit 2), input errors with
file:line messages (exit 1), --strict, and what `crumple check` prints
(ARCHITECTURE.md Part 2, "Commands" and "Errors")."""

import os
import re
import sys

sys.dont_write_bytecode = True  # keep __pycache__ out of the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402
from clitest import crumple, describe, one_brick_deck  # noqa: E402


class VersionAndHelp(clitest.TempDirTest):
    def test_version(self):
        p = crumple("--version")
        self.assertEqual(p.returncode, 0, describe(p))
        self.assertEqual(p.stdout.strip(), "crumple 0.1.0", describe(p))

    def test_help(self):
        p = crumple("--help")
        self.assertEqual(p.returncode, 0, describe(p))
        for word in ("Usage", "run", "check"):
            self.assertIn(word, p.stdout, describe(p))

    def test_subcommand_help(self):
        for cmd in ("run", "check"):
            p = crumple(cmd, "--help")
            self.assertEqual(p.returncode, 0, describe(p))
            self.assertIn("deck", p.stdout, describe(p))
        p = crumple("run", "--help")
        for option in ("--output", "--threads", "--endtime", "--strict", "--overwrite"):
            self.assertIn(option, p.stdout, describe(p))


class UsageErrors(clitest.TempDirTest):
    """Usage errors exit 2 and point at --help; they never create results."""

    def assertUsageError(self, *args):
        before = sorted(os.listdir(self.tmp))
        p = crumple(*args, cwd=self.tmp)
        self.assertEqual(p.returncode, 2, describe(p))
        self.assertTrue(p.stderr.strip(), "a usage error must say what is wrong" + describe(p))
        self.assertIn("--help", p.stderr, describe(p))
        self.assertEqual(sorted(os.listdir(self.tmp)), before,
                         "a usage error created files" + describe(p))
        return p

    def test_no_subcommand(self):
        p = self.assertUsageError()
        self.assertIn("subcommand", p.stderr.lower(), describe(p))

    def test_unknown_subcommand(self):
        self.assertUsageError("frobnicate")

    def test_unknown_option(self):
        self.write("ok.k", one_brick_deck())
        p = self.assertUsageError("run", "--no-such-option", "ok.k")
        self.assertIn("--no-such-option", p.stderr, describe(p))
        p = self.assertUsageError("check", "ok.k", "--no-such-option")
        self.assertIn("--no-such-option", p.stderr, describe(p))
        self.assertUsageError("--no-such-option")

    def test_missing_deck_file(self):
        for cmd in ("run", "check"):
            p = self.assertUsageError(cmd, "no_such_deck.k")
            self.assertIn("no_such_deck.k", p.stderr, describe(p))

    def test_missing_deck_argument(self):
        self.assertUsageError("run")
        self.assertUsageError("check")

    def test_bad_option_values(self):
        deck = os.path.join(clitest.SOURCE_DIR, "examples", "bar_impact", "bar_impact.k")
        self.assertUsageError("run", deck, "--threads", "0")
        self.assertUsageError("run", deck, "--threads", "two")
        self.assertUsageError("run", deck, "--endtime", "-1")


class InputErrors(clitest.TempDirTest):
    """Input errors exit 1 and name file:line, keyword, card and field."""

    def test_malformed_number(self):
        deck = self.write("bad.k", "*KEYWORD\n*MAT_ELASTIC\n$      mid        ro         e"
                          "        pr\n         1  7.85e-06       abc       0.3\n*END\n")
        for cmd in ("run", "check"):
            p = crumple(cmd, "bad.k", cwd=self.tmp)
            self.assertEqual(p.returncode, 1, describe(p))
            self.assertIn("bad.k:4: *MAT_ELASTIC card 1 field 3 (E): 'abc' is not a number",
                          p.stderr, describe(p))
        # An absolute deck path is named as given.
        p = crumple("run", deck, cwd=self.tmp)
        self.assertIn(f"{deck}:4: *MAT_ELASTIC card 1 field 3 (E): 'abc' is not a number",
                      p.stderr, describe(p))
        self.assertEqual(sorted(os.listdir(self.tmp)), ["bad.k"],
                         "an input error must not create a results folder")

    def test_undefined_material(self):
        text = one_brick_deck(material_id=7)
        self.write("undef.k", text)
        part_line = text.splitlines().index("block") + 2  # the PID SECID MID card
        p = crumple("run", "undef.k", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn(f"undef.k:{part_line}: *PART", p.stderr, describe(p))
        self.assertIn("MID", p.stderr, describe(p))
        self.assertIn("material 7 is not defined", p.stderr, describe(p))

    def test_missing_include(self):
        text = one_brick_deck().replace("*END\n", "*INCLUDE\nmissing_part.k\n*END\n")
        self.write("inc.k", text)
        include_line = text.splitlines().index("*INCLUDE") + 1
        p = crumple("run", "inc.k", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn(f"inc.k:{include_line}: *INCLUDE", p.stderr, describe(p))
        self.assertIn("missing_part.k", p.stderr, describe(p))

    def test_include_error_names_the_included_file(self):
        self.write("sub.k", "*MAT_ELASTIC\n         2   7.85e-6       xyz       0.3\n")
        self.write("main.k", one_brick_deck().replace("*END\n", "*INCLUDE\nsub.k\n*END\n"))
        p = crumple("check", "main.k", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertRegex(p.stderr, r"sub\.k:2: \*MAT_ELASTIC card 1 field 3 \(E\): 'xyz' is not "
                         r"a number", describe(p))

    def test_no_end_time(self):
        text = one_brick_deck()
        lines = text.splitlines(keepends=True)
        k = lines.index("*CONTROL_TERMINATION\n")
        text = "".join(lines[:k] + lines[k + 2:])
        self.assertNotIn("*CONTROL_TERMINATION", text)
        self.write("noend.k", text)
        p = crumple("run", "noend.k", "-q", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("--endtime", p.stderr, describe(p))
        p = crumple("run", "noend.k", "-q", "--endtime", "0.001", cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))


class Strict(clitest.TempDirTest):
    def setUp(self):
        super().setUp()
        text = one_brick_deck().replace("*END\n", "*DATABASE_SSSTAT\n      0.01\n*END\n")
        self.write("unsup.k", text)
        self.unsup_line = text.splitlines().index("*DATABASE_SSSTAT") + 1

    def test_run_without_strict_warns_and_runs(self):
        p = crumple("run", "unsup.k", "-q", "-o", "out", cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        self.assertIn("*DATABASE_SSSTAT", p.stderr, describe(p))
        with open(os.path.join(self.tmp, "out", "run.log"), encoding="utf-8") as f:
            self.assertIn("*DATABASE_SSSTAT", f.read())

    def test_run_strict_refuses(self):
        p = crumple("run", "unsup.k", "--strict", "-q", "-o", "out", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("--strict", p.stderr, describe(p))
        self.assertIn("*DATABASE_SSSTAT", p.stderr, describe(p))
        self.assertIn(f"unsup.k:{self.unsup_line}", p.stderr, describe(p))
        self.assertFalse(os.path.exists(os.path.join(self.tmp, "out", "summary.json")))

    def test_check_strict_refuses(self):
        p = crumple("check", "unsup.k", "--strict", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("*DATABASE_SSSTAT", p.stdout, describe(p))
        self.assertIn("--strict", p.stderr, describe(p))

    def test_strict_accepts_a_clean_deck(self):
        self.write("clean.k", one_brick_deck())
        for args in (("check", "clean.k", "--strict"),
                     ("run", "clean.k", "--strict", "-q", "-o", "clean")):
            p = crumple(*args, cwd=self.tmp)
            self.assertEqual(p.returncode, 0, describe(p))


class Check(clitest.TempDirTest):
    def test_check_bar_impact(self):
        p = crumple("check", clitest.example("bar_impact", "bar_impact.k"), cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        out = p.stdout
        self.assertRegex(out, r"(?m)^nodes: 909$", describe(p))
        self.assertRegex(out, r"(?m)^solid elements: 400$", describe(p))
        self.assertRegex(out, r"(?m)^\s+part 1 .*400 solids, \*MAT_ELASTIC 1", describe(p))
        # 10 x 10 x 100 mm of steel at 7.85e-6 kg/mm^3.
        m = re.search(r"(?m)^total mass: (\S+)$", out)
        self.assertIsNotNone(m, describe(p))
        self.assertAlmostEqual(float(m.group(1)), 0.0785, delta=1e-9)
        # Initial step: TSSFAC 0.9 x L / (c (Q2 + sqrt(1 + Q2^2))) with the default linear bulk
        # viscosity Q2 = 0.06 (docs/theory.md); the bar is 10 x 10 x 100 mm in 2 x 2 x 100 hexes
        # (5 x 5 x 1 mm, nu = 0): L = V / largest face = 1 mm, c = sqrt(E / rho).
        m = re.search(r"(?m)^initial time step: (\S+) \(solid element (\d+) \(part \d+\), TSSFAC 0\.9\)$", out)
        self.assertIsNotNone(m, describe(p))
        c = (210.0 / 7.85e-6) ** 0.5
        q = 0.06 + (1 + 0.06 ** 2) ** 0.5
        self.assertAlmostEqual(float(m.group(1)), 0.9 * 1.0 / (c * q), delta=1e-4 * 0.9 / c)
        self.assertTrue(1 <= int(m.group(2)) <= 400)
        self.assertIn("everything in the deck is supported", out, describe(p))
        self.assertEqual(os.listdir(self.tmp), [], "check must not write results")

    def test_check_lists_unsupported_keywords(self):
        text = one_brick_deck().replace(
            "*END\n", "*DATABASE_SSSTAT\n      0.01\n*DATABASE_BINARY_D3THDT\n      0.01\n"
            "*CONTROL_PARALLEL\n         1\n*END\n")
        self.write("unsup.k", text)
        lines = text.splitlines()
        p = crumple("check", "unsup.k", cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        self.assertRegex(p.stdout, r"(?m)^nodes: 8$")
        self.assertRegex(p.stdout, r"(?m)^solid elements: 1$")
        self.assertRegex(p.stdout, r"(?m)^total mass: 7\.85e-0?6$", describe(p))
        self.assertRegex(p.stdout, r"(?m)^initial time step: \S+ \(solid element 1 \(part \d+\), TSSFAC 0\.9\)$")
        for keyword, reason in (("*DATABASE_SSSTAT", "output not written yet"),
                                ("*DATABASE_BINARY_D3THDT", "output not written yet"),
                                ("*CONTROL_PARALLEL", "MPP/SMP")):
            line = lines.index(keyword) + 1
            self.assertRegex(p.stdout, rf"(?m)^{re.escape(keyword)}\s+1\s+unsup\.k:{line}\s+.*"
                             rf"{re.escape(reason)}", describe(p))

    def test_check_controlling_element(self):
        # Two cubes, the second one half the size: it controls the step.
        text = one_brick_deck().replace("*END\n", "")
        text += "*NODE\n" + "".join(
            f"{n:8d}{x:16.6f}{y:16.6f}{z:16.6f}\n"
            for n, x, y, z in [(11, 5, 0, 0), (12, 5.5, 0, 0), (13, 5.5, 0.5, 0), (14, 5, 0.5, 0),
                               (15, 5, 0, 0.5), (16, 5.5, 0, 0.5), (17, 5.5, 0.5, 0.5),
                               (18, 5, 0.5, 0.5)])
        text += "*ELEMENT_SOLID\n" + "".join(
            f"{v:8d}" for v in (77, 1, 11, 12, 13, 14, 15, 16, 17, 18)) + "\n*END\n"
        self.write("two.k", text)
        p = crumple("check", "two.k", cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        self.assertRegex(p.stdout, r"(?m)^solid elements: 2$", describe(p))
        m = re.search(r"(?m)^initial time step: (\S+) \(solid element 77 ", p.stdout)
        self.assertIsNotNone(m, "the smaller element 77 controls the step" + describe(p))
        # Cube of side h: L = h; c = sqrt((K + 4G/3) / rho) with E = 210, nu = 0.3; the linear
        # bulk viscosity Q2 = 0.06 enters the step; and both cubes share no node with another
        # element, so their breathing mode limits them: factor sqrt((K + 4G/3) / 3K).
        E, nu, rho = 210.0, 0.3, 7.85e-6
        c = (E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho)) ** 0.5
        q = 0.06 + (1 + 0.06 ** 2) ** 0.5
        breathing = ((1 - nu) / (1 + nu)) ** 0.5  # = sqrt((K + 4G/3) / 3K)
        expected = 0.9 * 0.5 * breathing / (c * q)
        self.assertAlmostEqual(float(m.group(1)), expected, delta=1e-5 * expected)


if __name__ == "__main__":
    clitest.main()
