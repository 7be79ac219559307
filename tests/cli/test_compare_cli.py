#!/usr/bin/env python3
"""`crumple compare` end to end (docs/validation.md): a Crumple run of examples/bar_impact
against itself written in LS-DYNA's ASCII layouts scores 1 on every curve, with a table, JSON
and one PNG per curve; a curve changed by 10 % scores less and only that one; --cfc filters
the accelerations; the bolted joint's LS-DYNA files are read by the command; bad input exits
with status 1 (missing folder, bad file: file and line named) or 2 (usage)."""

import json
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402
from clitest import crumple, describe  # noqa: E402

MISSING = clitest.missing_module("matplotlib", "numpy")


def setUpModule():
    if MISSING:
        raise unittest.SkipTest(f"{sys.executable} has no {MISSING} (tools/setup.sh installs it)")
    sys.path.insert(0, os.path.join(clitest.SOURCE_DIR, "python"))


class BarImpactAgainstItself(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        from crumple_compare import crumple_csv, lsdyna_write
        cls._tmp = tempfile.TemporaryDirectory(prefix="crumple_compare_")
        cls.tmp = cls._tmp.name
        cls.run_dir = os.path.join(cls.tmp, "run")
        proc = crumple("run", clitest.example("bar_impact", "bar_impact.k"), "-o", cls.run_dir,
                       "-q", timeout=120)
        assert proc.returncode == 0, describe(proc)
        cls.curves = crumple_csv.read_folder(cls.run_dir)
        cls.same = os.path.join(cls.tmp, "lsdyna_same")
        lsdyna_write.write_folder(cls.curves, cls.same, digits=10)

    @classmethod
    def tearDownClass(cls):
        cls._tmp.cleanup()

    def compare(self, *args):
        proc = crumple("compare", *args, timeout=300)
        self.assertEqual(proc.returncode, 0, describe(proc))
        return proc

    def load(self, out):
        with open(os.path.join(out, "compare.json"), encoding="utf-8") as f:
            return {row["key"]: row for row in json.load(f)["curves"]}

    def test_itself_scores_one_with_table_and_plots(self):
        out = os.path.join(self.tmp, "same")
        self.compare("--lsdyna", self.same, "--crumple", self.run_dir, "--out", out)
        rows = self.load(out)
        for key in ("glstat.kinetic", "glstat.internal", "rwforc.wall1.fn", "nodout.node1.vz"):
            self.assertIn(key, rows)
        for key, row in rows.items():
            self.assertGreater(row["iso"]["R"], 0.9999, key)
            self.assertEqual(row["iso"]["lag"], 0.0, key)
            self.assertAlmostEqual(row["lsdyna"]["peak"], row["crumple"]["peak"],
                                   delta=1e-9 * (1 + abs(row["crumple"]["peak"])))
            with open(os.path.join(out, "plots", key + ".png"), "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        with open(os.path.join(out, "compare.md"), encoding="utf-8") as f:
            table = f.read()
        self.assertIn("| glstat.kinetic |", table)
        kinetic = rows["glstat.kinetic"]["crumple"]
        self.assertAlmostEqual(kinetic["end"], float(self.curves["glstat.kinetic"].y[-1]))

    def test_changed_curve_scores_less(self):
        from crumple_compare import lsdyna_write
        changed = dict(self.curves)
        k = changed["glstat.kinetic"]
        changed["glstat.kinetic"] = type(k)(k.key, k.t, 1.1 * k.y, k.source)
        folder = os.path.join(self.tmp, "lsdyna_changed")
        lsdyna_write.write_folder(changed, folder, digits=10)
        out = os.path.join(self.tmp, "changed")
        self.compare("--lsdyna", folder, "--crumple", self.run_dir, "--out", out, "--no-plots",
                     "--curves", "glstat.*")
        rows = self.load(out)
        self.assertTrue(all(k.startswith("glstat.") for k in rows))
        self.assertLess(rows["glstat.kinetic"]["iso"]["R"], 0.99)
        # LS-DYNA's integral is the reference's: 10 % larger.
        a, b = rows["glstat.kinetic"]["lsdyna"], rows["glstat.kinetic"]["crumple"]
        self.assertAlmostEqual(a["integral"], 1.1 * b["integral"], delta=1e-6 * abs(a["integral"]))
        self.assertGreater(rows["glstat.internal"]["iso"]["R"], 0.9999)

    def test_cfc_filters_accelerations_only(self):
        out = os.path.join(self.tmp, "cfc")
        # The deck is in mm and ms; the positional form (RUN_DIR LSDYNA_DIR) of the command.
        self.compare(self.run_dir, self.same, "--out", out, "--no-plots", "--cfc", "1000",
                     "--time-unit", "ms", "--curves", "nodout.node1.*")
        rows = self.load(out)
        self.assertEqual(rows["nodout.node1.az"]["cfc"], 1000)
        self.assertIsNone(rows["nodout.node1.vz"]["cfc"])
        self.assertGreater(rows["nodout.node1.az"]["iso"]["R"], 0.999)  # both filtered alike

    def test_bolted_joint_files(self):
        decks = clitest.shared_decks()
        folder = decks and os.path.join(decks, "bolted_joint_lsdyna", "Bolt_B_Explicit")
        if not folder or not os.path.isdir(folder):
            self.skipTest("../shared/decks/bolted_joint_lsdyna is not present")
        out = os.path.join(self.tmp, "bolted")
        proc = self.compare("--lsdyna", folder, "--crumple", self.run_dir, "--out", out,
                            "--no-plots", "--curves", "glstat.*")
        self.assertIn("only in LS-DYNA", proc.stdout)
        with open(os.path.join(out, "compare.json"), encoding="utf-8") as f:
            result = json.load(f)
        self.assertIn("glstat.eroded_kinetic", result["unmatched"]["lsdyna"])
        self.assertIn("glstat.kinetic", [r["key"] for r in result["curves"]])


class BadInput(clitest.TempDirTest):
    def data(self, name):
        return os.path.join(clitest.SOURCE_DIR, "tests", "data", "compare", name)

    def test_errors(self):
        cases = [
            (["--lsdyna", self.data("lsdyna"), "--crumple", os.path.join(self.tmp, "none")], 1,
             "none: no such folder"),
            (["--lsdyna", self.data("bad"), "--crumple", self.data("crumple")], 1,
             "nodout:7: node 12"),
            (["--lsdyna", self.data("lsdyna"), "--crumple", self.data("crumple_bad")], 1,
             "matsum.csv:3: not a number"),
            (["--lsdyna", self.data("lsdyna")], 2, "--crumple is required"),
            (["--lsdyna", self.data("lsdyna"), "--crumple", self.data("crumple"), "--cfc", "60"],
             2, "--cfc needs --time-unit"),
            (["--lsdyna", self.data("lsdyna"), "--crumple", self.data("crumple"), "--curves",
              "secforc.*"], 1, "no curve in common"),
        ]
        for args, status, message in cases:
            proc = crumple("compare", *args, "--out", self.tmp)
            self.assertEqual(proc.returncode, status, describe(proc))
            self.assertIn(message, proc.stderr, describe(proc))

    def test_missing_interpreter(self):
        env = dict(os.environ, CRUMPLE_PYTHON=os.path.join(self.tmp, "python3"))
        import subprocess
        proc = subprocess.run([clitest.CRUMPLE, "compare", "--help"], capture_output=True,
                              text=True, env=env, timeout=30)
        self.assertEqual(proc.returncode, 1)
        self.assertIn("no Python interpreter at", proc.stderr)

    def test_hand_made_files(self):
        proc = crumple("compare", "--lsdyna", self.data("lsdyna"), "--crumple",
                       self.data("crumple"), "--out", self.tmp)
        self.assertEqual(proc.returncode, 0, describe(proc))
        with open(os.path.join(self.tmp, "compare.json"), encoding="utf-8") as f:
            rows = {r["key"]: r for r in json.load(f)["curves"]}
        self.assertEqual(rows["glstat.kinetic"]["iso"]["R"], 1.0)
        self.assertEqual(rows["matsum.part7.z_momentum"]["lsdyna"]["integral"], -0.0000875)


if __name__ == "__main__":
    clitest.main()
