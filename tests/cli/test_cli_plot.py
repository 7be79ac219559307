#!/usr/bin/env python3
"""`crumple plot` end to end (docs/outputs.md): a run of examples/bar_impact drawn as PNG; the
pictures hold the run's own numbers (the energy lines are glstat.csv's columns, the wall force
is rwforc.csv's), the axes carry the unit system the run inferred (kg, mm, ms: energy in J,
force in kN), the CFC filter of node accelerations works in the run's time unit, and bad
requests exit 1 (no run, no unit system for --cfc) or 2 (usage)."""

import csv
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402
from clitest import crumple, describe  # noqa: E402

MISSING = clitest.missing_module("matplotlib", "numpy")
if not MISSING:
    import numpy as np

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def setUpModule():
    if MISSING:
        raise unittest.SkipTest(f"{sys.executable} has no {MISSING} (tools/setup.sh installs it)")
    sys.path.insert(0, os.path.join(clitest.SOURCE_DIR, "python"))


def column(path, name, where=None):
    """(time, values) of a CSV column; a time written twice (the last cycle) keeps its last row,
    as every reader of the histories does."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = [r for r in csv.DictReader(f) if not where or all(r[k] == v for k, v in
                                                                  where.items())]
    last = {float(r["time"]): float(r[name]) for r in rows}
    return np.array(list(last)), np.array(list(last.values()))


class BarImpactPlots(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls._tmp = tempfile.TemporaryDirectory(prefix="crumple_plot_")
        cls.run_dir = os.path.join(cls._tmp.name, "run")
        proc = crumple("run", clitest.example("bar_impact", "bar_impact.k"), "-o", cls.run_dir,
                       "-q", timeout=120)
        assert proc.returncode == 0, describe(proc)

    @classmethod
    def tearDownClass(cls):
        cls._tmp.cleanup()

    def figures(self, *whats, cfc=None):
        from crumple_compare import crumple_csv, plot, units
        args = plot.parse([self.run_dir, *whats] + (["--cfc", str(cfc)] if cfc else []))
        curves = crumple_csv.read_folder(self.run_dir)
        return dict(plot.draw(curves, args.what, units.of_run(self.run_dir), args))

    def test_every_picture_as_png(self):
        out = os.path.join(self._tmp.name, "pictures")
        proc = crumple("plot", self.run_dir, "--out", out, "--cfc", "600", timeout=300)
        self.assertEqual(proc.returncode, 0, describe(proc))
        names = sorted(os.listdir(out))
        self.assertIn("energies.png", names)
        self.assertIn("walls.png", names)
        self.assertIn("parts.png", names)
        self.assertTrue(any(n.startswith("node") for n in names), names)
        for name in names:
            with open(os.path.join(out, name), "rb") as f:
                self.assertEqual(f.read(8), PNG_MAGIC, name)
            self.assertGreater(os.path.getsize(os.path.join(out, name)), 10_000, name)

    def test_energy_lines_are_glstat(self):
        fig = self.figures("energies")["energies"]
        top, bottom = fig.axes
        lines = {line.get_label(): line for line in top.get_lines()}
        t, total = column(os.path.join(self.run_dir, "glstat.csv"), "total")
        np.testing.assert_array_equal(lines["total"].get_ydata(), total)
        np.testing.assert_array_equal(lines["total"].get_xdata(), t)
        self.assertEqual(top.get_ylabel(), "energy [J]")
        self.assertEqual(top.get_xlabel(), "time [ms]")
        ratio = [ln for ln in bottom.get_lines() if ln.get_label() == "total / initial"][0]
        self.assertTrue(np.all(np.abs(ratio.get_ydata() - 1.0) < 0.02))

    def test_wall_force_is_rwforc(self):
        fig = self.figures("walls")["walls"]
        (ax,) = fig.axes
        t, fn = column(os.path.join(self.run_dir, "rwforc.csv"), "fn", {"wall": "1"})
        np.testing.assert_array_equal(ax.get_lines()[0].get_ydata(), fn)
        self.assertEqual(ax.get_ylabel(), "force [kN]")

    def test_bad_requests(self):
        proc = crumple("plot", os.path.join(self._tmp.name, "nowhere"))
        self.assertEqual(proc.returncode, 1, describe(proc))
        self.assertIn("no such folder", proc.stderr)
        proc = crumple("plot", self.run_dir, "stresses")
        self.assertEqual(proc.returncode, 2, describe(proc))
        self.assertIn("unknown picture stresses", proc.stderr)
        proc = crumple("plot", self.run_dir, "--nodes", "999999", "--out", self._tmp.name)
        self.assertEqual(proc.returncode, 1, describe(proc))
        self.assertIn("no history of node 999999", proc.stderr)


class FilteredAcceleration(clitest.TempDirTest):
    def test_cfc_in_the_runs_time_unit(self):
        # A node history in ms (kg, mm, ms recorded by the run): a 10 Hz swing plus 2 kHz
        # ringing. CFC 60 (SAE J211: -0.45 dB at 60 Hz, -30 dB and more beyond 1 kHz) keeps the
        # swing and removes the ringing, if and only if the millisecond is taken as 1e-3 s.
        t = np.arange(0.0, 400.0, 0.05)  # ms
        slow = 1000.0 * np.sin(2 * np.pi * 10.0 * t * 1e-3)
        a = slow + 500.0 * np.sin(2 * np.pi * 2000.0 * t * 1e-3)
        rows = "".join(f"{ti:.6g},7,0,0,0,0,0,0,0,0,0,0,0,{ai:.9g}\n" for ti, ai in zip(t, a))
        self.write("nodout.csv", "time,node,x,y,z,dx,dy,dz,vx,vy,vz,ax,ay,az\n" + rows)
        self.write("summary.json", '{"units": {"system": "kg-mm-ms", "source": "test"}}')
        from crumple_compare import crumple_csv, plot, units
        args = plot.parse([self.tmp, "nodes", "--cfc", "60"])
        curves = crumple_csv.read_folder(self.tmp)
        fig = dict(plot.draw(curves, args.what, units.of_run(self.tmp), args))["node7"]
        acc = fig.axes[2]
        filtered = [ln for ln in acc.get_lines() if ln.get_label() == "az CFC 60"][0]
        self.assertEqual(acc.get_ylabel(), "acceleration [mm/ms^2]")
        inner = slice(len(t) // 8, -len(t) // 8)  # away from the ends' start-up
        error = filtered.get_ydata()[inner] - np.interp(filtered.get_xdata(), t, slow)[inner]
        self.assertLess(np.max(np.abs(error)), 0.03 * 1000.0)


class NoUnitsRecorded(clitest.TempDirTest):
    def test_cfc_needs_a_time_unit(self):
        with open(self.write("glstat.csv", ""), "w", encoding="utf-8") as f:
            f.write("time,kinetic,internal,total,energy_ratio\n0,1,0,1,1\n1,0.5,0.5,1,1\n")
        proc = crumple("plot", self.tmp, "--cfc", "60")
        self.assertEqual(proc.returncode, 1, describe(proc))
        self.assertIn("--cfc needs the time unit", proc.stderr)
        proc = crumple("plot", self.tmp, "--units", "t-mm-s", "--out", self.tmp)
        self.assertEqual(proc.returncode, 0, describe(proc))
        self.assertTrue(os.path.isfile(os.path.join(self.tmp, "energies.png")))


if __name__ == "__main__":
    clitest.main()
