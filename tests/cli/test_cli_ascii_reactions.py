#!/usr/bin/env python3
"""LS-DYNA's spcforc, bndout, rbdout and deforc (src/output/reactions.hpp) and their CSVs:

- python/crumple_compare/lsdyna.py reads every file and finds the CSVs' numbers;
- physics: a bar clamped at one end under an end load P (static after a slow ramp): the SPC
  forces sum to -P; a plate pulled by a prescribed displacement: the SPCs and the prescribed
  motion balance, their force is sigma t W, and the motion's work is the integral of
  force x velocity and the plate's strain energy; a cantilever of beams: the clamp's moment is
  P L; a rigid block under a constant force F: V = F t / m, d = F t^2 / (2 m), a = F / m; a
  spring with a mass hung on it, loaded slowly: force = k x elongation = the load;
- layout: bndout's banner, block title and one row against LS-DYNA R13's (bolted joint);
- the files are the same bytes at 1, 2 and 3 ranks, and a restart continues them.
"""

import os
import shutil
import subprocess
import sys
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402
from clitest import describe, main  # noqa: E402
import test_cli_ascii  # noqa: E402
from test_cli_ascii import Case, MPI_ENV, bar, mask, read_csv  # noqa: E402
import test_cli_d3plot  # noqa: E402

try:
    import numpy as np
except ImportError:
    np = None


def setUpModule():
    test_cli_ascii.setUpModule()


def with_keywords(deck, text):
    return deck.replace("*PART\n", text + "*PART\n", 1)


def rigid_block(force=2.0):
    """A free 10 mm steel cube of *MAT_RIGID (m = 7.85e-3 kg) pushed along +x by `force` kN,
    a quarter at each corner of its x = 10 face: no moment about the centre (symmetry). 1 ms;
    *DATABASE_RBDOUT."""
    nodes = [(1 + i + 2 * j + 4 * k, 10.0 * i, 10.0 * j, 10.0 * k)
             for k in range(2) for j in range(2) for i in range(2)]
    s = "*KEYWORD\n*TITLE\nrigid block\n*CONTROL_TERMINATION\n       1.0\n"
    s += "*DATABASE_RBDOUT\n       0.1\n*DATABASE_GLSTAT\n       0.1\n"
    s += "*PART\nblock\n         1         1         1\n*SECTION_SOLID\n         1         1\n"
    s += "*MAT_RIGID\n         1   7.85e-6     210.0       0.3\n       0.0       0.0       0.0\n"
    s += "*NODE\n" + "".join(f"{n:8d}{x:16.6f}{y:16.6f}{z:16.6f}\n" for n, x, y, z in nodes)
    s += "*ELEMENT_SOLID\n       1       1       1       2       4       3       5       6"
    s += "       8       7\n"
    s += "*DEFINE_CURVE\n         1\n                 0.0                 1.0\n"
    s += "                10.0                 1.0\n*LOAD_NODE_POINT\n"
    s += "".join(f"{n:10d}         1         1{force / 4:10.6g}\n" for n in (2, 4, 6, 8))
    return s + "*END\n"


def hung_spring(load=0.5, k=5.0):
    """A linear spring (k = `k` kN/mm) from a fixed node 1 to node 2 (10 mm along x) carrying
    a 0.01 kg point mass, loaded along +x by `load` kN ramped over 5 ms then held to 6 ms
    (period 2 pi sqrt(m / k) = 0.28 ms: quasi-static); *DATABASE_DEFORC."""
    s = "*KEYWORD\n*TITLE\nhung spring\n*CONTROL_TERMINATION\n       6.0\n"
    s += "*DATABASE_DEFORC\n       0.1\n"
    s += "*PART\nspring\n         1         1         1\n*SECTION_DISCRETE\n         1         0\n"
    s += f"*MAT_SPRING_ELASTIC\n         1{k:10.6g}\n*NODE\n"
    s += "       1             0.0             0.0             0.0\n"
    s += "       2            10.0             0.0             0.0\n"
    s += "*ELEMENT_DISCRETE\n       7       1       1       2\n"
    s += "*ELEMENT_MASS\n       1       2      0.01\n"
    s += "*BOUNDARY_SPC_NODE\n         1         0         1         1         1\n"
    s += "         2         0         0         1         1\n"
    s += "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n"
    s += "                 5.0                 1.0\n                10.0                 1.0\n"
    s += f"*LOAD_NODE_POINT\n         2         1         1{load:10.6g}\n"
    return s + "*END\n"


def last_rows(rows, key):
    """The rows of the last time, by `key`."""
    t = rows[-1]["time"]
    return {int(r[key]): r for r in rows if r["time"] == t}


class Physics(Case):
    def test_bar_spc_forces_balance_the_load(self):
        load = 10.0
        out = self.run_deck("bar.k", bar(load, "*DATABASE_SPCFORC\n      0.05\n"))
        rows = read_csv(os.path.join(out, "spcforc.csv"))
        # The nine clamped nodes of the x = 0 face, every sample.
        self.assertEqual(len({int(r["node"]) for r in rows}), 9)
        for t in sorted({r["time"] for r in rows if r["time"] >= 2.5}):
            at = [r for r in rows if r["time"] == t]
            fx = sum(r["fx"] for r in at)
            # Statics: the clamp holds the bar against the end load.
            self.assertAlmostEqual(fx, -load, delta=0.02 * load)
            self.assertLess(abs(sum(r["fy"] for r in at)), 1e-6 * load)
            self.assertLess(abs(sum(r["fz"] for r in at)), 1e-6 * load)
        t_mid = min((r["time"] for r in rows), key=lambda t: abs(t - 1.0))
        mid = [r for r in rows if r["time"] == t_mid]
        self.assertAlmostEqual(sum(r["fx"] for r in mid), -0.5 * load, delta=0.02 * load)

    def test_plate_prescribed_motion_force_and_work(self):
        # test_cli_d3plot's plate pulled 0.02 mm at x = 40 in 1 ms: sigma t W = E u / L t W
        # = 2.1 kN, held by the SPCs of the x = 0 edge.
        deck = with_keywords(test_cli_d3plot.pulled_plate(),
                             "*DATABASE_SPCFORC\n      0.01\n*DATABASE_BNDOUT\n      0.01\n"
                             "*DATABASE_GLSTAT\n      0.01\n")
        out = self.run_deck("plate.k", deck)
        force = 210.0 * 0.02 / 40.0 * 20.0 * 1.0
        bnd = read_csv(os.path.join(out, "bndout.csv"))
        spc = read_csv(os.path.join(out, "spcforc.csv"))
        self.assertEqual(set(last_rows(bnd, "node")), {5, 10, 15})
        pull = sum(r["fx"] for r in last_rows(bnd, "node").values())
        hold = sum(r["fx"] for r in last_rows(spc, "node").values())
        self.assertAlmostEqual(pull, force, delta=0.03 * force)
        self.assertAlmostEqual(hold, -pull, delta=0.03 * force)
        # The work of the motion: the integral of force x velocity (the edge moves at
        # 0.02 mm/ms; trapezoids over the samples), and the strain energy F u / 2.
        times = sorted({r["time"] for r in bnd})
        f = np.array([sum(r["fx"] for r in bnd if r["time"] == t) for t in times])
        e = np.array([sum(r["energy"] for r in bnd if r["time"] == t) for t in times])
        integral = np.concatenate([[0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(times))])
        integral *= 0.02
        self.assertAlmostEqual(e[-1], 0.5 * force * 0.02, delta=0.05 * 0.5 * force * 0.02)
        np.testing.assert_allclose(e, integral, atol=0.03 * e[-1])
        glstat = read_csv(os.path.join(out, "glstat.csv"))
        self.assertAlmostEqual(e[-1], glstat[-1]["internal"] + glstat[-1]["kinetic"],
                               delta=0.02 * e[-1])

    def test_cantilever_clamp_moment(self):
        load, length = 0.1, 100.0
        deck = with_keywords(test_cli_d3plot.cantilever(load), "*DATABASE_SPCFORC\n       5.0\n")
        out = self.run_deck("cantilever.k", deck)
        clamp = last_rows(read_csv(os.path.join(out, "spcforc.csv")), "node")[1]
        # Statics about node 1: the clamp's force -P z and moment +P L about y.
        self.assertAlmostEqual(clamp["fz"], -load, delta=0.01 * load)
        self.assertAlmostEqual(clamp["my"], load * length, delta=0.01 * load * length)
        for key in ("fx", "fy", "mx", "mz"):
            self.assertLess(abs(clamp[key]), 1e-3 * load * length, key)

    def test_rigid_body_under_constant_force(self):
        force, mass = 2.0, 7.85e-6 * 1000.0
        out = self.run_deck("rigid.k", rigid_block(force))
        rows = read_csv(os.path.join(out, "rbdout.csv"))
        self.assertEqual({int(r["body"]) for r in rows}, {1})
        late = [r for r in rows if r["time"] > 0.0]
        self.assertGreater(len(late), 5)
        dt = {g["time"]: g["dt"] for g in read_csv(os.path.join(out, "glstat.csv"))}
        for r in late:
            t = r["time"]
            # Central differences: V(n+1/2) = F t(n+1/2) / m exactly for a constant force, the
            # centre written at t(n+1) = t(n+1/2) + dt(n+1/2) / 2; x to O(dt).
            v = force * (t - 0.5 * dt[t]) / mass
            self.assertAlmostEqual(r["vx"], v, delta=1e-9 * v)
            self.assertAlmostEqual(r["dx"], 0.5 * force * t * t / mass,
                                   delta=2e-3 * force * t * t / mass + 1e-3)
            self.assertAlmostEqual(r["ax"], force / mass, delta=1e-6 * force / mass)
            self.assertAlmostEqual(r["x"], 5.0 + r["dx"], places=9)
            for key in ("vy", "vz", "wx", "wy", "wz", "ay", "az"):
                self.assertLess(abs(r[key]), 1e-9 * force / mass, key)

    def test_spring_force_is_k_times_elongation(self):
        load, k = 0.5, 5.0
        out = self.run_deck("spring.k", hung_spring(load, k))
        rows = read_csv(os.path.join(out, "deforc.csv"))
        self.assertEqual({int(r["element"]) for r in rows}, {7})
        for r in rows:
            self.assertAlmostEqual(r["force"], k * r["elongation"], delta=1e-9 + 1e-6 * load)
        last = rows[-1]
        self.assertAlmostEqual(last["force"], load, delta=0.02 * load)
        # The spring pulls node 2 back towards node 1: -F along x.
        self.assertAlmostEqual(last["fx"], -last["force"], delta=1e-6 * load)


class FilesAndReader(Case):
    def assertSameAsCsv(self, out, prefix, at_least):
        from crumple_compare import crumple_csv, lsdyna
        theirs = lsdyna.read_folder(out)
        ours = crumple_csv.read_folder(out)
        keys = [k for k in ours if k.startswith(prefix)]
        self.assertGreaterEqual(len(keys), at_least, sorted(ours))
        for key in keys:
            self.assertIn(key, theirs)
            c, d = ours[key], theirs[key]
            np.testing.assert_allclose(d.t, c.t, rtol=6e-5, err_msg=key)
            scale = max(np.max(np.abs(c.y)), 1e-30)
            np.testing.assert_allclose(d.y, c.y, rtol=6e-5, atol=1e-4 * scale, err_msg=key)
        return theirs

    def test_every_file_reads_back(self):
        deck = with_keywords(test_cli_d3plot.pulled_plate(),
                             "*DATABASE_SPCFORC\n      0.05\n*DATABASE_BNDOUT\n      0.05\n")
        out = self.run_deck("plate.k", deck)
        theirs = self.assertSameAsCsv(out, "spcforc.", 15 * 6)
        self.assertSameAsCsv(out, "bndout.", 3 * 4)
        # The resultant line: the sum of the node rows.
        total = theirs["spcforc.total.fx"].y
        nodes = sum(theirs[f"spcforc.node{n}.fx"].y for n in range(1, 16))
        np.testing.assert_allclose(total, nodes, atol=1e-3 * np.max(np.abs(total)))
        out = self.run_deck("rigid.k", rigid_block())
        theirs = self.assertSameAsCsv(out, "rbdout.", 21)
        # The local rows are the global ones in the principal axes (any orthonormal frame for
        # a cube): the same length.
        local = np.hypot(np.hypot(theirs["rbdout.body1.local.vx"].y,
                                  theirs["rbdout.body1.local.vy"].y),
                         theirs["rbdout.body1.local.vz"].y)
        np.testing.assert_allclose(local, np.abs(theirs["rbdout.body1.vx"].y), rtol=1e-3)
        out = self.run_deck("spring.k", hung_spring())
        self.assertSameAsCsv(out, "deforc.", 5)

    def test_only_with_the_keyword(self):
        out = self.run_deck("plate.k", test_cli_d3plot.pulled_plate())
        for name in ("spcforc", "bndout", "spcforc.csv", "bndout.csv", "rbdout", "deforc"):
            self.assertFalse(os.path.exists(os.path.join(out, name)), name)


class Layout(Case):
    @classmethod
    def setUpClass(cls):
        cls.dyna = test_cli_ascii.lsdyna_folder()
        if cls.dyna is None:
            raise unittest.SkipTest("../shared/decks/bolted_joint_lsdyna is not present")

    def lines(self, folder, name):
        with open(os.path.join(folder, name), encoding="latin-1") as f:
            return f.read().splitlines()

    def test_bndout_and_rbdout(self):
        deck = with_keywords(test_cli_d3plot.pulled_plate(), "*DATABASE_BNDOUT\n      0.05\n")
        out = self.run_deck("plate.k", deck)
        ours, theirs = self.lines(out, "bndout"), self.lines(self.dyna, "bndout")
        layout = test_cli_ascii.Layout("banner")
        layout.banner(ours, theirs)
        # A blank, the title with the time, a blank, the 'velocity boundary condition' line, a
        # blank, the first node row; then the totals line after the last row.
        for k in range(2, 8):
            self.assertEqual(mask(ours[k]), mask(theirs[k]), f"bndout line {k + 1}")
        a = next(i for i, l in enumerate(ours) if "xtotal" in l)
        b = next(i for i, l in enumerate(theirs) if "xtotal" in l)
        self.assertEqual(mask(ours[a]), mask(theirs[b]))
        self.assertEqual(mask(ours[a + 2]), mask(theirs[b + 2]))  # the next block's title
        # rbdout: LS-DYNA's sample holds only the banner (its deck has no rigid body).
        out = self.run_deck("rigid.k", rigid_block())
        layout.banner(self.lines(out, "rbdout"), self.lines(self.dyna, "rbdout"))


    def test_reader_on_lsdyna_bndout(self):
        from crumple_compare import lsdyna
        c = lsdyna.read_bndout(os.path.join(self.dyna, "bndout"))
        nodes = [k for k in c if k.endswith(".fx") and ".node" in k]
        self.assertEqual(len(nodes), 17)  # the prescribed set's nodes
        self.assertEqual(len(c["bndout.total.fx"].t), 1001)
        # The totals line is the sum of the rows (to the four digits printed).
        total = sum(c[k].y for k in nodes)
        np.testing.assert_allclose(c["bndout.total.fx"].y, total,
                                   atol=1e-3 * np.max(np.abs(total)))
        self.assertEqual(lsdyna.read_rbdout(os.path.join(self.dyna, "rbdout")), {})


class Parallel(Case):
    def test_same_bytes_at_1_2_3_ranks(self):
        exe = shutil.which("mpirun")
        if exe is None:
            self.skipTest("mpirun not found")
        deck = self.write("plate.k", with_keywords(
            test_cli_d3plot.pulled_plate(),
            "*DATABASE_SPCFORC\n      0.05\n*DATABASE_BNDOUT\n      0.05\n"))
        rigid = os.path.join(clitest.SOURCE_DIR, "tests", "data", "decks", "rigid_welds.k")
        with open(rigid, encoding="utf-8") as f:
            rigid = self.write("rigid.k", f.read().replace(
                "*DATABASE_GLSTAT\n", "*DATABASE_RBDOUT\n     0.005\n*DATABASE_GLSTAT\n", 1))
        for path, names in ((deck, ("spcforc", "spcforc.csv", "bndout", "bndout.csv")),
                            (rigid, ("rbdout", "rbdout.csv"))):
            data = []
            for n in (1, 2, 3):
                out = os.path.join(self.tmp, f"{os.path.basename(path)}{n}")
                p = subprocess.run([exe, "--oversubscribe", "-np", str(n), clitest.CRUMPLE, "run",
                                    path, "-o", out, "-q", "--threads", "1"],
                                   capture_output=True, text=True, timeout=300, env=MPI_ENV)
                self.assertEqual(p.returncode, 0, describe(p))
                data.append([open(os.path.join(out, x), "rb").read() for x in names])
            self.assertEqual(data[0], data[1], path)
            self.assertEqual(data[0], data[2], path)


class Restart(Case):
    def test_restart_continues_the_files(self):
        self.assertRestartContinues(
            with_keywords(test_cli_d3plot.pulled_plate(),
                          "*DATABASE_SPCFORC\n      0.05\n*DATABASE_BNDOUT\n      0.05\n"
                          "*DATABASE_BINARY_D3DUMP\n     150.0\n"),
            ("spcforc", "spcforc.csv", "bndout", "bndout.csv"), cycles=400)


if __name__ == "__main__":
    main()
