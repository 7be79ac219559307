#!/usr/bin/env python3
"""`crumple check` and short runs on real-world decks from other projects
(source-dir/../shared/decks; the tests skip with a message when that folder is absent)."""

import math
import os
import re
import sys
import unittest

sys.dont_write_bytecode = True  # keep __pycache__ out of the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402
from clitest import crumple, describe, read_summary  # noqa: E402

BLOCK = "wb_lsdyna_block/tests/testfiles/keywords/test_node_sets.k"
PROJECTILE = "projectile_plate_lstc/tests/testfiles/run/case-keywords/projectile.k"
BALL_PLATE = "ball_plate_pydyna/examples/Explicit/output/ball_plate.k"
JOINT_TRANSLATIONAL = "dynakw_joint_translational/test/full_files/joint_translational.k"
JOINT_REVOLUTE = "dynakw_joint_revolute/test/full_files/joint_revolute.k"
SPH_WALL = "lasso_sph_wall/test/test_data/sph_models/R12_2_1/sph_test.k"


def unsupported_table(stdout):
    """{keyword: reasons} from the 'keywords read but not acted on' table of check."""
    table, inside = {}, False
    for line in stdout.splitlines():
        if line.startswith("keywords read but not acted on"):
            inside = True
            continue
        if inside:
            if line.startswith("keyword ") and "reason" in line:
                continue
            m = re.match(r"^(\*\S+)\s+(\d+)\s+(\S+:\d+)\s+(.*)$", line)
            if not m:
                break
            table.setdefault(m.group(1), []).append(m.group(4).strip())
    return table


class RealDecks(clitest.TempDirTest):
    def deck(self, relative):
        root = clitest.shared_decks()
        if root is None:
            self.skipTest("../shared/decks is absent: no real-world decks to read")
        path = os.path.join(root, relative)
        if not os.path.isfile(path):
            self.skipTest(f"{path} is absent")
        return path

    def check(self, relative, status):
        p = crumple("check", self.deck(relative), cwd=self.tmp)
        self.assertEqual(p.returncode, status, describe(p))
        return p

    def initial_step(self, p):
        m = re.search(r"(?m)^initial time step: (\S+) \((solid|shell) element (\d+) \(part \d+\), TSSFAC", p.stdout)
        self.assertIsNotNone(m, describe(p))
        dt = float(m.group(1))
        self.assertTrue(math.isfinite(dt) and dt > 0.0, describe(p))
        return dt

    def short_run(self, path, end_time, name="out"):
        out = os.path.join(self.tmp, name)
        p = crumple("run", path, "--endtime", f"{end_time:.6g}", "-o", out, "-q", cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        s = read_summary(out)
        self.assertEqual(s["termination"], "normal")
        self.assertGreaterEqual(s["cycles"], 10)
        for key, value in s["energy"].items():
            self.assertTrue(math.isfinite(value), f"energy.{key} = {value}")
        return s

    def test_block_check_and_run(self):
        # *CONTROL_SOLID ESORT = 1 runs its 80 pentahedra as ELFORM 15.
        p = self.check(BLOCK, 0)
        self.assertNotIn("ESORT", p.stdout, describe(p))
        self.assertRegex(p.stdout, r"(?m)^nodes: 6724$", describe(p))
        self.assertRegex(p.stdout, r"(?m)^solid elements: 5680$", describe(p))
        table = unsupported_table(p.stdout)
        # *DATABASE_SPCFORC and _ELOUT are written (src/output/reactions.hpp, elout.hpp): not
        # in the table.
        self.assertNotIn("*DATABASE_SPCFORC", table, describe(p))
        self.assertNotIn("*DATABASE_ELOUT", table, describe(p))
        # The initial step is a pentahedron's (V / A_max is half a hexahedron's of its cell).
        self.assertRegex(p.stdout, r"initial time step: \S+ \(solid element 5601 ", describe(p))
        dt = self.initial_step(p)
        s = self.short_run(self.deck(BLOCK), 20 * dt, "out_esort1")
        self.assertEqual(s["counts"]["solids"], 5680)
        # The same deck with ESORT = 0 runs, the pentahedra as collapsed hexahedra, and says so.
        with open(self.deck(BLOCK)) as f:
            lines = f.read().split("\n")
        esort = lines.index("*CONTROL_SOLID") + 2
        self.assertEqual(lines[esort][:10], "         1")
        lines[esort] = "         0" + lines[esort][10:]
        copy = os.path.join(self.tmp, "block_esort0.k")
        with open(copy, "w") as f:
            f.write("\n".join(lines))
        p = crumple("check", copy, cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        self.assertIn("80 degenerate solid(s) (0 tetrahedra, 80 pentahedra, 0 other) run as "
                      "ELFORM 1 hexahedra", p.stdout, describe(p))
        dt = self.initial_step(p)
        # About 20 cycles: enough to see the deck's loads act, short enough to stay quick.
        s = self.short_run(copy, 20 * dt)
        self.assertEqual(s["counts"]["nodes"], 6724)
        self.assertEqual(s["counts"]["solids"], 5680)
        self.assertAlmostEqual(s["end_time"], float(f"{20 * dt:.6g}"), delta=1e-12)

    def test_projectile_check_and_run(self):
        p = self.check(PROJECTILE, 0)
        self.assertRegex(p.stdout, r"(?m)^solid elements: 5664$", describe(p))
        table = unsupported_table(p.stdout)
        self.assertIn("*CASE", table, describe(p))
        self.assertIn("load cases: Crumple runs the deck without them", table["*CASE"])
        # Its force transducer is read and written to rcforc now, so it is not in the table.
        self.assertNotIn("*CONTACT_FORCE_TRANSDUCER_PENALTY", table, describe(p))
        # Keywords inside *CASE blocks are reported as such.
        self.assertTrue(any("inside *CASE block" in r
                            for r in table.get("*INITIAL_VELOCITY_GENERATION", [])), describe(p))
        dt = self.initial_step(p)
        s = self.short_run(self.deck(PROJECTILE), 20 * dt)
        self.assertGreater(s["energy"]["total"], 0.0)

    def joint_run(self, relative):
        """The whole run, its glstat.csv and jntforc.csv rows."""
        out = os.path.join(self.tmp, "out")
        p = crumple("run", self.deck(relative), "-o", out, "-q", cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        self.assertEqual(read_summary(out)["termination"], "normal")
        tables = {}
        for name in ("glstat.csv", "jntforc.csv"):
            with open(os.path.join(out, name)) as f:
                rows = [line.strip().split(",") for line in f if line.strip()]
            tables[name] = [dict(zip(rows[0], map(float, r))) for r in rows[1:]]
        with open(os.path.join(out, "jntforc")) as f:
            self.assertIn("joint ID", f.read())
        return tables

    def test_translational_joint_deck_runs(self):
        # Two rigid shells on a translational joint along x, one of them held by an elastic
        # shell; the other starts sliding (vx = 90) and moving across the axis (vz = 300),
        # which the joint stops. The energy stays within 1e-3 of the start while the joint
        # snaps shut (it gained 2.8 % before its dampers' work was booked over the velocity
        # step, docs/theory.md "Joints"); the jntforc file holds the joint's force.
        t = self.joint_run(JOINT_TRANSLATIONAL)
        ratios = [r["energy_ratio"] for r in t["glstat.csv"]]
        self.assertLess(max(abs(r - 1.0) for r in ratios), 1e-3, ratios[:5])
        self.assertAlmostEqual(t["glstat.csv"][-1]["time"], 0.02, delta=1e-9)
        self.assertGreater(max(r["fr"] for r in t["jntforc.csv"]), 0.0)

    def test_sph_particles_on_a_stonewall_balance(self):
        # 25 plane-strain SPH particles thrown at 50 mm/ms onto a stonewall: the first column is
        # stopped at t = 0.01. The stonewall's energy is booked in the halves the half-step
        # kinetic energy takes (the sample right after the impact read 1.0499 when the whole
        # impulse's work was booked at once); the ratio stays within 1 % to the end.
        out = os.path.join(self.tmp, "sph")
        p = crumple("run", self.deck(SPH_WALL), "-o", out, "-q", "--threads", "1", cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        rows = clitest.history_rows(out, "glstat.csv")
        ratios = [r["energy_ratio"] for r in rows]
        self.assertLess(max(abs(r - 1.0) for r in ratios), 0.01, ratios)
        self.assertGreater(rows[-1]["rigidwall"], 0.5)

    def test_revolute_joint_deck_runs(self):
        # A rigid shell turned about a revolute joint by a *LOAD_RIGID_BODY moment ramped to 100
        # against a friction spring (191 per radian, slipping at 80): work and energy agree
        # within 0.5 %.
        t = self.joint_run(JOINT_REVOLUTE)
        last = t["glstat.csv"][-1]
        self.assertAlmostEqual(last["time"], 0.01, delta=1e-9)
        self.assertGreater(last["external_work"], 0.0)
        self.assertLess(abs(last["energy_ratio"] - 1.0), 0.005)
        self.assertEqual({r["joint"] for r in t["jntforc.csv"]}, {1.0})

    def test_ball_plate_check_and_run(self):
        # A rigid ball (*MAT_RIGID solids) on a plastic shell plate with an automatic single
        # surface contact: everything is read and run, --strict too, and the deck's
        # *DATABASE_GLSTAT, _MATSUM and _SLEOUT are written in LS-DYNA's layout.
        p = self.check(BALL_PLATE, 0)
        self.assertRegex(p.stdout, r"(?m)^shell elements: 256$", describe(p))
        self.assertRegex(p.stdout, r"(?m)^  part 2 \"ball\": 1512 solids, \*MAT_RIGID 2", describe(p))
        table = unsupported_table(p.stdout)
        self.assertNotIn("*CONTACT_AUTOMATIC_SINGLE_SURFACE", table, describe(p))
        self.assertEqual(table, {}, describe(p))
        dt = self.initial_step(p)
        s = self.short_run(self.deck(BALL_PLATE), 20 * dt)
        self.assertGreater(s["counts"]["shells"], 0)
        self.assertEqual(s["contact"]["interfaces"], 1)
        self.assertAlmostEqual(s["energy"]["ratio"], 1.0, delta=0.01)
        out = os.path.join(self.tmp, "strict")
        p = crumple("run", self.deck(BALL_PLATE), "-o", out, "-q", "--strict", "--cycles", "20",
                    cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        for name in ("glstat", "matsum", "sleout"):
            self.assertTrue(os.path.isfile(os.path.join(out, name)), name)


if __name__ == "__main__":
    clitest.main()
