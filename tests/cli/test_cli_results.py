#!/usr/bin/env python3
"""What `crumple run` writes (ARCHITECTURE.md Part 2, "Output files in DIR"): summary.json
keys, CSV headers, run.log, and the VTK results read back by VTK's own readers; the rules for
an existing results folder (--overwrite), the default folder, and --endtime.

The deck is examples/bar_impact: a steel bar (10 x 10 x 100 mm, 2 x 2 x 100 hexes, 909 nodes,
nu = 0) at -10 mm/ms onto a stonewall at z = 0. Contact lasts 2L/c0 = 0.0387 ms and the run
ends at 0.058 ms, after the bar has left the wall at +10 mm/ms (restitution 1)."""

import csv
import json
import math
import os
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

sys.dont_write_bytecode = True  # keep __pycache__ out of the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402
from clitest import crumple, describe, read_summary  # noqa: E402

GLSTAT = ["time", "cycle", "dt", "kinetic", "internal", "hourglass", "contact", "external_work",
          "total", "energy_ratio"]
MATSUM = ["time", "part", "kinetic", "internal", "hourglass", "x_momentum", "y_momentum",
          "z_momentum"]
NODOUT = ["time", "node", "x", "y", "z", "dx", "dy", "dz", "vx", "vy", "vz", "ax", "ay", "az"]
RWFORC = ["time", "wall", "fn", "fx", "fy", "fz"]
NODES, SOLIDS, V0 = 909, 400, 10.0


def read_csv(path):
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def pvd_files(folder):
    root = ET.parse(os.path.join(folder, "results.pvd")).getroot()
    return [d.get("file") for d in root.iter("DataSet")]


class BarImpactResults(unittest.TestCase):
    """One run of the bar impact into a fresh folder; every file in it checked."""

    @classmethod
    def setUpClass(cls):
        cls._tmp = tempfile.TemporaryDirectory(prefix="crumple_cli_")
        cls.out = os.path.join(cls._tmp.name, "results")
        cls.deck = clitest.example("bar_impact", "bar_impact.k")
        cls.proc = crumple("run", cls.deck, "-o", cls.out, "-q")

    @classmethod
    def tearDownClass(cls):
        cls._tmp.cleanup()

    def setUp(self):
        self.assertEqual(self.proc.returncode, 0, describe(self.proc))

    def test_files_present(self):
        for name in ("summary.json", "glstat.csv", "matsum.csv", "nodout.csv", "rwforc.csv",
                     "results.pvd", "run.log"):
            self.assertTrue(os.path.isfile(os.path.join(self.out, name)), f"{name} missing")

    def test_summary_keys(self):
        s = read_summary(self.out)
        for key in ("version", "deck", "ranks", "threads", "termination", "end_time", "cycles",
                    "wall_s", "element_cycles_per_s", "timing", "counts", "energy",
                    "peak_memory_bytes", "state_digest"):
            self.assertIn(key, s, f"summary.json lacks '{key}'")
        self.assertEqual(s["version"], "0.1.0")
        self.assertTrue(s["deck"].endswith("bar_impact.k"), s["deck"])
        self.assertEqual(s["ranks"], 1)
        self.assertIsInstance(s["threads"], int)
        self.assertGreaterEqual(s["threads"], 1)
        self.assertEqual(s["termination"], "normal")
        self.assertAlmostEqual(s["end_time"], 0.058002, delta=1e-12)
        self.assertIsInstance(s["cycles"], int)
        self.assertGreater(s["cycles"], 100)
        self.assertGreater(s["wall_s"], 0.0)
        self.assertGreater(s["element_cycles_per_s"], 0.0)
        # element-cycles per second = solids x cycles / time of the cycle loop, i.e. the wall
        # time less set-up (reading, partitioning, initialising: setup_s).
        self.assertGreaterEqual(s["setup_s"], 0.0)
        self.assertLess(s["setup_s"], s["wall_s"])
        self.assertAlmostEqual(s["element_cycles_per_s"],
                               SOLIDS * s["cycles"] / (s["wall_s"] - s["setup_s"]),
                               delta=1e-6 * s["element_cycles_per_s"])
        timing = s["timing"]
        for key in ("elements", "contact", "constraints", "communication", "output", "other"):
            self.assertIn(key, timing, f"summary.json timing lacks '{key}'")
            self.assertGreaterEqual(timing[key], 0.0, key)
        # Set-up and the timing rows add up to the wall time (set-up ends before the first
        # state is written, which counts as output).
        self.assertAlmostEqual(sum(timing.values()) + s["setup_s"], s["wall_s"],
                               delta=0.01 * s["wall_s"] + 1e-4,
                               msg="set-up and the timing parts do not add up to the wall time")
        # Set-up by phase, in order, adding up to setup_s.
        self.assertEqual(sorted(s["setup"]), sorted(["read", "validate", "partition",
                                                     "distribute", "initialise", "output"]))
        self.assertTrue(all(v >= 0.0 for v in s["setup"].values()), s["setup"])
        self.assertAlmostEqual(sum(s["setup"].values()), s["setup_s"], delta=1e-9,
                               msg="the set-up phases do not add up to setup_s")
        for key, value in (("nodes", NODES), ("solids", SOLIDS), ("shells", 0), ("beams", 0)):
            self.assertEqual(s["counts"].get(key), value, f"counts.{key}")
        energy = s["energy"]
        for key in ("kinetic", "internal", "hourglass", "drilling", "contact", "external_work",
                    "total", "ratio"):
            self.assertIn(key, energy, f"summary.json energy lacks '{key}'")
            self.assertTrue(math.isfinite(energy[key]), key)
        self.assertAlmostEqual(energy["ratio"], 1.0, delta=0.01)
        self.assertIsInstance(s["peak_memory_bytes"], int)
        self.assertGreater(s["peak_memory_bytes"], 0)
        self.assertRegex(s["state_digest"], r"^[0-9a-f]{64}$")

    def test_csv_headers(self):
        for name, columns in (("glstat.csv", GLSTAT), ("matsum.csv", MATSUM),
                              ("nodout.csv", NODOUT), ("rwforc.csv", RWFORC)):
            header, rows = read_csv(os.path.join(self.out, name))
            self.assertEqual(header[:len(columns)], columns, f"{name} header")
            self.assertTrue(rows, f"{name} has no data rows")
            for row in rows:
                self.assertEqual(len(row), len(header), f"{name}: ragged row {row}")
                for value in row:
                    self.assertTrue(math.isfinite(float(value)), f"{name}: {row}")

    def test_csv_contents(self):
        s = read_summary(self.out)
        header, rows = read_csv(os.path.join(self.out, "glstat.csv"))
        col = {name: header.index(name) for name in GLSTAT}
        times = [float(r[col["time"]]) for r in rows]
        self.assertEqual(times, sorted(times), "glstat.csv time goes backwards")
        self.assertEqual(times[0], 0.0)
        self.assertAlmostEqual(times[-1], s["end_time"], delta=1e-12)
        self.assertEqual(int(rows[-1][col["cycle"]]), s["cycles"])
        # At t = 0 all energy is kinetic: m v0^2 / 2 = 0.0785 x 100 / 2.
        self.assertAlmostEqual(float(rows[0][col["kinetic"]]), 0.5 * 0.0785 * V0 ** 2,
                               delta=1e-9)
        # The last glstat row is the final state of summary.json.
        self.assertAlmostEqual(float(rows[-1][col["total"]]), s["energy"]["total"],
                               delta=1e-9 * abs(s["energy"]["total"]))
        # History nodes of the deck: 1 and 901 (*DATABASE_HISTORY_NODE).
        header, rows = read_csv(os.path.join(self.out, "nodout.csv"))
        self.assertEqual({int(r[header.index("node")]) for r in rows}, {1, 901})
        # matsum: one part, momentum -m v0 along z at t = 0.
        header, rows = read_csv(os.path.join(self.out, "matsum.csv"))
        self.assertEqual({int(r[header.index("part")]) for r in rows}, {1})
        self.assertAlmostEqual(float(rows[0][header.index("z_momentum")]), -0.0785 * V0,
                               delta=1e-9)
        # rwforc: wall 1 pushes the bar up (fn > 0) while it touches.
        header, rows = read_csv(os.path.join(self.out, "rwforc.csv"))
        self.assertEqual({int(r[header.index("wall")]) for r in rows}, {1})
        self.assertGreater(max(float(r[header.index("fn")]) for r in rows), 0.0)

    def test_run_log(self):
        with open(os.path.join(self.out, "run.log"), encoding="utf-8") as f:
            log = f.read()
        self.assertIn("nodes: 909", log)
        self.assertIn("normal termination", log)
        self.assertRegex(log, r"(?m)^timing:$")
        for row in ("set-up", "elements", "contact", "constraints", "communication", "output",
                    "other", "total"):
            self.assertRegex(log, rf"(?m)^\s+{row}\s+[0-9.]+ s\s+[0-9.]+%$", f"timing row {row}")

    def test_vtk_results(self):
        data = clitest.read_vtu(self.out, "--values")
        states = data["states"]
        self.assertEqual(len(states), len(pvd_files(self.out)))
        self.assertGreaterEqual(len(states), 2)
        # d3plot every 0.0058 ms to 0.058 ms: 11 states, the first at 0, the last at the end.
        self.assertEqual(len(states), 11)
        self.assertEqual(states[0]["timestep"], 0.0)
        self.assertAlmostEqual(states[-1]["timestep"], 0.058002, delta=1e-12)
        stamps = [st["timestep"] for st in states]
        self.assertEqual(stamps, sorted(stamps))
        for st in states:
            self.assertEqual(st["points"], NODES, st["file"])
            self.assertEqual(st["cells"], SOLIDS, st["file"])
            self.assertEqual(st["cell_type_counts"], {"12": SOLIDS}, "all VTK_HEXAHEDRON")
            for name in ("displacement", "velocity", "acceleration"):
                self.assertIn(name, st["point_data"], f"{st['file']}: point field {name}")
                self.assertEqual(st["point_data"][name]["components"], 3)
                self.assertEqual(st["point_data"][name]["tuples"], NODES)
            for name in ("stress", "effective_plastic_strain", "part", "rank"):
                self.assertIn(name, st["cell_data"], f"{st['file']}: cell field {name}")
                self.assertEqual(st["cell_data"][name]["tuples"], SOLIDS)
            self.assertEqual(st["cell_data"]["stress"]["components"], 6)
            self.assertEqual(st["cell_data"]["part"]["range"], [1.0, 1.0])
            self.assertEqual(st["cell_data"]["rank"]["range"], [0.0, 0.0])
        # Physics: at t = 0 every node moves at -v0 along z; at the end the bar has rebounded
        # off the wall at +v0 (restitution 1 for an elastic bar, verification.md #1). The mesh
        # smears the unloading front over several elements and leaves a dispersive tail behind
        # it, so at 0.058 ms the last few mm of the bar still ring (node speeds down to ~4
        # mm/ms at the far end): the mean over the nodes is within 5% of v0, every node moves
        # away from the wall, and 90% of the nodes are within 10% of v0.
        first = states[0]["point_data"]["velocity"]["values"]
        self.assertEqual(first, [0.0, 0.0, -V0] * NODES)
        self.assertEqual(states[0]["point_data"]["displacement"]["values"], [0.0] * 3 * NODES)
        last = states[-1]["point_data"]["velocity"]["values"]
        vz = last[2::3]
        self.assertEqual(len(vz), NODES)
        self.assertAlmostEqual(sum(vz) / len(vz), V0, delta=0.05 * V0)
        self.assertGreater(min(vz), 0.0, "a node still moves towards the wall")
        close = sum(1 for v in vz if abs(v - V0) < 0.1 * V0)
        self.assertGreaterEqual(close, 0.9 * NODES, f"only {close} of {NODES} nodes near +v0")
        # The bar is above the wall at the end: z-displacement > -z0 everywhere, no node
        # below z = 0 (the wall is at z = 0 and the bar's bottom face starts there).
        disp = states[-1]["point_data"]["displacement"]["values"]
        self.assertGreater(min(disp[2::3]), 0.0)


class ResultsFolder(clitest.TempDirTest):
    """An existing results folder is never silently destroyed."""

    def run_bar(self, *args, cwd=None):
        return crumple("run", clitest.example("bar_impact", "bar_impact.k"), "-q", *args,
                       cwd=cwd or self.tmp)

    def test_overwrite_rules(self):
        out = os.path.join(self.tmp, "out")
        p = self.run_bar("-o", out, "--endtime", "0.02")
        self.assertEqual(p.returncode, 0, describe(p))
        with open(os.path.join(out, "summary.json"), "rb") as f:
            before = f.read()
        states_before = sorted(os.listdir(os.path.join(out, "states")))
        self.write("out/notes.txt", "mine\n")

        p = self.run_bar("-o", out, "--endtime", "0.01")
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("--overwrite", p.stderr, describe(p))
        with open(os.path.join(out, "summary.json"), "rb") as f:
            self.assertEqual(f.read(), before, "summary.json changed without --overwrite")
        self.assertEqual(sorted(os.listdir(os.path.join(out, "states"))), states_before)

        p = self.run_bar("-o", out, "--endtime", "0.01", "--overwrite")
        self.assertEqual(p.returncode, 0, describe(p))
        s = read_summary(out)
        self.assertEqual(s["termination"], "normal")
        self.assertAlmostEqual(s["end_time"], 0.01, delta=1e-12)
        # The earlier run's states are gone: the folder holds exactly the states results.pvd
        # lists; a file that is not Crumple's survives.
        listed = sorted(os.path.basename(f) for f in pvd_files(out))
        self.assertEqual(sorted(os.listdir(os.path.join(out, "states"))), listed)
        self.assertLess(len(listed), len(states_before))
        with open(os.path.join(out, "notes.txt"), encoding="utf-8") as f:
            self.assertEqual(f.read(), "mine\n")

    def test_output_path_is_a_file(self):
        path = self.write("taken", "not a folder\n")
        p = self.run_bar("-o", path, "--endtime", "0.001")
        self.assertEqual(p.returncode, 1, describe(p))
        with open(path, encoding="utf-8") as f:
            self.assertEqual(f.read(), "not a folder\n")

    def test_default_folder(self):
        beside_deck = clitest.example("bar_impact", "bar_impact.out")
        existed = os.path.exists(beside_deck)
        p = self.run_bar("--endtime", "0.005")
        self.assertEqual(p.returncode, 0, describe(p))
        out = os.path.join(self.tmp, "bar_impact.out")
        self.assertTrue(os.path.isdir(out), f"no {out}; folder has {os.listdir(self.tmp)}")
        self.assertEqual(read_summary(out)["termination"], "normal")
        self.assertAlmostEqual(read_summary(out)["end_time"], 0.005, delta=1e-12)
        self.assertEqual(os.path.exists(beside_deck), existed,
                         "results went next to the deck, not to the working directory")

    def test_endtime(self):
        p = self.run_bar("-o", "short", "--endtime", "0.01")
        self.assertEqual(p.returncode, 0, describe(p))
        s = read_summary(os.path.join(self.tmp, "short"))
        self.assertEqual(s["termination"], "normal")
        self.assertAlmostEqual(s["end_time"], 0.01, delta=1e-12)
        # The initial step is 1.74e-4: about 0.01 / 1.74e-4 = 58 cycles, far fewer than 355.
        self.assertGreater(s["cycles"], 50)
        self.assertLess(s["cycles"], 70)
        header, rows = read_csv(os.path.join(self.tmp, "short", "glstat.csv"))
        self.assertAlmostEqual(float(rows[-1][header.index("time")]), 0.01, delta=1e-12)
        with open(os.path.join(self.tmp, "short", "run.log"), encoding="utf-8") as f:
            self.assertRegex(f.read(), r"normal termination at time 0\.01\b")


if __name__ == "__main__":
    clitest.main()
