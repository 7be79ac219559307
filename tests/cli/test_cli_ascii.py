#!/usr/bin/env python3
"""LS-DYNA's ASCII history files (src/output/ascii.hpp) and section forces
(src/output/sections.hpp):

- the files a deck asks for (*DATABASE_GLSTAT, _MATSUM, _NODOUT, _RCFORC, _RWFORC, _SLEOUT,
  _SECFORC) are written beside the CSVs, and only those;
- python/crumple_compare/lsdyna.py reads them and finds the CSVs' numbers (to the five
  significant digits LS-DYNA prints);
- their layout is LS-DYNA R13's: the banner, legend and one block of glstat, matsum, nodout,
  rcforc and sleout compared line by line with the bolted joint's files
  (../shared/decks/bolted_joint_lsdyna, when present): the same text where numbers are
  masked, every number ending in the same column;
- physics: a bar under an axial end load P (static after a slow ramp): section force P along
  the normal, no moment, area 100 mm^2, centroid on the cut nodes; cuts bounded by a circle
  and a rectangle; a shell plate pulled in-plane: sigma t W through t W; a cantilever of beams under
  a tip load P: shear P and moment P (L - x) about the cut nodes, of the signs the
  positive-side-on-negative-side convention gives;
- the section files are the same bytes at 1, 2 and 3 ranks, and a restarted run continues
  them as the uninterrupted run wrote them.
"""

import os
import re
import shutil
import subprocess
import sys
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402
from clitest import TempDirTest, crumple, describe, main  # noqa: E402
import test_cli_d3plot  # noqa: E402  (its cantilever deck)

try:
    import numpy as np
except ImportError:
    np = None

MPI_ENV = dict(os.environ, OMP_WAIT_POLICY="PASSIVE", OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
MPI_ENV["ASAN_OPTIONS"] = (MPI_ENV.get("ASAN_OPTIONS", "") + ":detect_leaks=0").lstrip(":")
NUM = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")


def setUpModule():
    if np is None:
        raise unittest.SkipTest(f"{sys.executable} has no numpy (tools/setup.sh installs it)")
    sys.path.insert(0, os.path.join(clitest.SOURCE_DIR, "python"))


def lsdyna_folder():
    decks = clitest.shared_decks()
    folder = decks and os.path.join(decks, "bolted_joint_lsdyna", "Bolt_B_Explicit")
    return folder if folder and os.path.isdir(folder) else None


def bar(load=10.0, extra=""):
    """A steel bar of 10 x 2 x 2 hexahedra, 100 x 10 x 10 mm along x (mm, ms, kg, kN),
    clamped at x = 0; the x = 100 face carries `load` kN along +x, nine equal nodal loads
    ramped over 2 ms and then held to 3 ms. The first axial mode (period 4 L / c = 0.077 ms)
    follows the ramp quasi-statically (dynamic error about 1 / (omega T) = 0.6%). A cross
    section at x = 45 (normal +x) cuts the fifth column of elements."""
    nodes, elems = [], []
    nid = lambda i, j, k: 1 + i + 11 * (j + 3 * k)  # noqa: E731
    for k in range(3):
        for j in range(3):
            for i in range(11):
                nodes.append((nid(i, j, k), 10.0 * i, 5.0 * j, 5.0 * k))
    e = 1
    for k in range(2):
        for j in range(2):
            for i in range(10):
                elems.append((e, nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k),
                              nid(i, j + 1, k), nid(i, j, k + 1), nid(i + 1, j, k + 1),
                              nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)))
                e += 1
    s = "*KEYWORD\n*TITLE\naxial bar\n*CONTROL_TERMINATION\n       3.0\n"
    s += "*DATABASE_GLSTAT\n      0.05\n*DATABASE_MATSUM\n      0.05\n"
    s += "*DATABASE_NODOUT\n      0.05\n*DATABASE_HISTORY_NODE\n        11        33\n"
    s += "*DATABASE_SECFORC\n      0.05\n"
    s += "*DATABASE_CROSS_SECTION_PLANE_ID\n         7mid-span cut\n"
    s += "         0      45.0       0.0       0.0      46.0       0.0       0.0\n"
    s += "       0.0       0.0       0.0\n"
    s += extra
    s += "*PART\nbar\n         1         1         1\n*SECTION_SOLID\n         1         2\n"
    s += "*MAT_ELASTIC\n         1   7.85e-6     210.0       0.3\n*NODE\n"
    s += "".join(f"{n:8d}{x:16.6f}{y:16.6f}{z:16.6f}\n" for n, x, y, z in nodes)
    s += "*ELEMENT_SOLID\n" + "".join("".join(f"{v:8d}" for v in (el[0], 1) + el[1:]) + "\n"
                                      for el in elems)
    s += "*BOUNDARY_SPC_NODE\n" + "".join(
        f"{nid(0, j, k):10d}         0         1         1         1         1         1"
        "         1\n" for k in range(3) for j in range(3))
    s += "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n"
    s += "                 2.0                 1.0\n                10.0                 1.0\n"
    s += "*LOAD_NODE_POINT\n" + "".join(f"{nid(10, j, k):10d}         1         1{load / 9:10.6g}\n"
                                        for k in range(3) for j in range(3))
    return s + "*END\n"


def cantilever(load=0.1):
    """test_cli_d3plot's cantilever of ten resultant beams, 100 mm along x, A = 100, clamped
    at x = 0, tip load `load` along +z ramped over 50 ms (quasi-static), with a cross section
    at x = 45 (normal +x) that cuts element 5; its positive-side node is node 6 at x = 50."""
    section = "*DATABASE_SECFORC\n       5.0\n*DATABASE_CROSS_SECTION_PLANE\n"
    section += "         0      45.0       0.0       0.0      46.0       0.0       0.0\n"
    return test_cli_d3plot.cantilever(load).replace("*PART\n", section + "*PART\n", 1)


def contact_blocks_with_sleout():
    """tests/data/decks/contact_blocks.k (two blocks colliding, surface-to-surface contact,
    *DATABASE_GLSTAT, _MATSUM, _RCFORC) with a *DATABASE_SLEOUT at the rcforc interval."""
    deck = os.path.join(clitest.SOURCE_DIR, "tests", "data", "decks", "contact_blocks.k")
    with open(deck, encoding="utf-8") as f:
        lines = f.read().splitlines(keepends=True)
    k = next(i for i, l in enumerate(lines) if l.startswith("*DATABASE_RCFORC"))
    return "".join(lines[:k] + ["*DATABASE_SLEOUT\n", lines[k + 1]] + lines[k:])


def read_bytes(path):
    with open(path, "rb") as f:
        return f.read()


def read_csv(path):
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    names = lines[0].split(",")
    return [dict(zip(names, map(float, line.split(",")))) for line in lines[1:]]


class Case(TempDirTest):
    def run_ok(self, *args):
        p = crumple(*args, timeout=300)
        self.assertEqual(p.returncode, 0, describe(p))
        return p

    def run_deck(self, name, text, *extra):
        deck = self.write(name, text)
        out = os.path.join(self.tmp, name + ".out")
        self.run_ok("run", deck, "-o", out, "-q", "--threads", "1", *extra)
        return out

    def assertReaderAgrees(self, out, at_least, rtol=6e-5):
        """Every curve lsdyna.py reads from the ASCII files that the CSVs also hold: the same
        times and values, to the five significant digits LS-DYNA prints (`rtol`: fewer, as
        elout's beam resultants E11.3)."""
        from crumple_compare import crumple_csv, lsdyna
        theirs = lsdyna.read_folder(out)
        ours = crumple_csv.read_folder(out)
        compared = 0
        for key, c in ours.items():
            if key not in theirs:
                continue
            d = theirs[key]
            self.assertEqual(len(d.t), len(c.t), key)
            np.testing.assert_allclose(d.t, c.t, rtol=6e-5, atol=0, err_msg=key)
            scale = max(np.max(np.abs(c.y)), 1e-30)
            # Five significant digits, and LS-DYNA's E13.4 in matsum.
            np.testing.assert_allclose(d.y, c.y, rtol=rtol, atol=1e-4 * scale, err_msg=key)
            compared += 1
        self.assertGreaterEqual(compared, at_least, sorted(theirs))
        return theirs

    def assertSameBytesAtRanks(self, text, names):
        """The files `names` of the deck `text` run on 1, 2 and 3 ranks are the same bytes."""
        exe = shutil.which("mpirun")
        if exe is None:
            self.skipTest("mpirun not found")
        deck = self.write("deck.k", text)
        outs = []
        for n in (1, 2, 3):
            out = os.path.join(self.tmp, f"out{n}")
            p = subprocess.run([exe, "--oversubscribe", "-np", str(n), clitest.CRUMPLE, "run",
                                deck, "-o", out, "-q", "--threads", "1"], capture_output=True,
                               text=True, timeout=300, env=MPI_ENV)
            self.assertEqual(p.returncode, 0, describe(p))
            outs.append(out)
        for name in names:
            data = [read_bytes(os.path.join(o, name)) for o in outs]
            self.assertEqual(data[0], data[1], name)
            self.assertEqual(data[0], data[2], name)

    def assertRestartContinues(self, text, names, cycles=900):
        """A run of `text` (which asks for dumps) stopped after `cycles` cycles and restarted
        from its last dump writes the files `names` as the uninterrupted run."""
        deck = self.write("deck.k", text)
        full = os.path.join(self.tmp, "full")
        self.run_ok("run", deck, "-o", full, "-q")
        part = os.path.join(self.tmp, "part")
        self.run_ok("run", deck, "-o", part, "-q", "--cycles", str(cycles))
        dumps = sorted(f for f in os.listdir(part) if f.startswith("d3dump_"))
        self.assertTrue(dumps, os.listdir(part))
        self.run_ok("run", deck, "-o", part, "-q", "--restart", os.path.join(part, dumps[-1]))
        for name in names:
            self.assertEqual(read_bytes(os.path.join(full, name)),
                             read_bytes(os.path.join(part, name)), name)


class SectionPhysics(Case):
    def test_bar_axial_force(self):
        load = 10.0
        out = self.run_deck("bar.k", bar(load))
        rows = read_csv(os.path.join(out, "secforc.csv"))
        self.assertEqual({r["section"] for r in rows}, {7.0})
        self.assertEqual(rows[0]["time"], 0.0)
        self.assertEqual(rows[0]["fx"], 0.0)  # before the first cycle: no forces yet
        late = [r for r in rows if r["time"] >= 2.5]
        self.assertGreater(len(late), 5)
        for r in late:
            # Statics: the cut carries the end load, tension positive along the normal.
            self.assertAlmostEqual(r["fx"], load, delta=0.02 * load)
            self.assertLess(abs(r["fy"]) + abs(r["fz"]), 1e-6 * load)
            # Symmetric about the bar's axis: no moment about the centroid of the cut nodes.
            self.assertLess(max(abs(r["mx"]), abs(r["my"]), abs(r["mz"])), 1e-6 * load * 10.0)
            self.assertAlmostEqual(r["area"], 100.0, places=9)
            # The cut nodes at x = 50 have moved by P x / (E A) = 0.0238 mm.
            self.assertAlmostEqual(r["cx"], 50.0 + load * 50.0 / (210.0 * 100.0), delta=0.001)
            self.assertAlmostEqual(r["cy"], 5.0, places=6)
            self.assertAlmostEqual(r["cz"], 5.0, places=6)
        # Mid-ramp (t = 1 ms, load/2): still the applied load, to the small dynamic error.
        mid = min(rows, key=lambda r: abs(r["time"] - 1.0))
        self.assertAlmostEqual(mid["fx"], 0.5 * load, delta=0.02 * load)
        # `crumple plot RUN sections` draws the section's resultant force from secforc.csv.
        p = self.run_ok("plot", out, "sections", "--out", os.path.join(self.tmp, "pictures"))
        self.assertTrue(os.path.isfile(os.path.join(self.tmp, "pictures", "sections.png")),
                        describe(p))

    def test_bounded_cuts(self):
        # Tail at (45, 0, 0): a circle of radius 4 takes the one element column whose centre
        # (y, z) = (2.5, 2.5) lies within it; a rectangle LENL = 5 along y by LENM = 10 along
        # z = n x l takes the two columns at y = 2.5.
        extra = "*DATABASE_CROSS_SECTION_PLANE_ID\n         8circle\n"
        extra += "         0      45.0       0.0       0.0      46.0       0.0       0.0       4.0\n"
        extra += "*DATABASE_CROSS_SECTION_PLANE_ID\n         9rectangle\n"
        extra += "         0      45.0       0.0       0.0      46.0       0.0       0.0\n"
        extra += "      45.0       1.0       0.0       5.0      10.0\n"
        out = self.run_deck("bar.k", bar(extra=extra))
        rows = read_csv(os.path.join(out, "secforc.csv"))
        last = {int(r["section"]): r for r in rows}
        self.assertEqual(last[8]["area"], 25.0)
        self.assertEqual(last[9]["area"], 50.0)
        self.assertAlmostEqual(last[8]["cy"], 2.5, delta=0.01)  # nodes at y, z in {0, 5}
        # The halves carry half the load (symmetry about y = 5).
        self.assertAlmostEqual(last[9]["fx"], 0.5 * last[7]["fx"], delta=1e-6 * last[7]["fx"])
        self.assertGreater(last[8]["fx"], 0.0)

    def test_beam_cantilever_moment(self):
        load, length, x_cut_nodes = 0.1, 100.0, 50.0
        out = self.run_deck("cantilever.k", cantilever(load))
        last = read_csv(os.path.join(out, "secforc.csv"))[-1]
        self.assertEqual(last["time"], 50.0)
        # The positive side (x > 45) pulls the negative side with the load it carries, +P z,
        # and bends it with the load's moment about the cut node: (L - 50) x^ x P z^ = -P (L -
        # 50) y^.
        self.assertAlmostEqual(last["fz"], load, delta=0.01 * load)
        self.assertAlmostEqual(last["my"], -load * (length - x_cut_nodes),
                               delta=0.01 * load * length)
        for key in ("fx", "fy", "mx", "mz"):
            self.assertLess(abs(last[key]), 0.01 * load, key)
        self.assertEqual(last["area"], 100.0)
        self.assertAlmostEqual(last["cx"], 50.0, delta=0.01)


    def test_shell_plate_membrane_force(self):
        # test_cli_d3plot's plate of 4 x 2 shells, 40 x 20 x 1 mm, free to contract in y, its
        # x = 40 edge pulled 0.02 mm in 1 ms (quasi-static: the axial period is 0.03 ms).
        # Uniaxial stress E u / L = 0.105 GPa; a cut at x = 15 carries sigma t W = 2.1 kN
        # through 20 mm x 1 mm.
        section = "*DATABASE_SECFORC\n      0.05\n*DATABASE_CROSS_SECTION_PLANE\n"
        section += "         0      15.0       0.0       0.0      16.0       0.0       0.0\n"
        deck = test_cli_d3plot.pulled_plate().replace("*PART\n", section + "*PART\n", 1)
        out = self.run_deck("plate.k", deck)
        last = read_csv(os.path.join(out, "secforc.csv"))[-1]
        self.assertEqual(last["time"], 1.0)
        force = 210.0 * 0.02 / 40.0 * 20.0 * 1.0
        self.assertAlmostEqual(last["fx"], force, delta=0.02 * force)
        self.assertLess(max(abs(last["fy"]), abs(last["fz"])), 0.01 * force)
        self.assertLess(max(abs(last[k]) for k in ("mx", "my", "mz")), 0.01 * force * 20.0)
        self.assertAlmostEqual(last["area"], 20.0, places=9)
        # The plate contracts towards y = 0 (node 1 held in y): the cut's middle node at
        # 10 (1 - nu u / L).
        self.assertAlmostEqual(last["cy"], 10.0 * (1.0 - 0.3 * 0.02 / 40.0), delta=1e-4)


class FilesAndReader(Case):
    def test_walls_nodes_and_energies(self):
        # The loads-and-constraints deck: a moving rigid wall (rwforc, the glstat stonewall
        # line), history nodes, two parts.
        deck = os.path.join(clitest.SOURCE_DIR, "tests", "data", "decks", "mixed_conditions.k")
        out = os.path.join(self.tmp, "mixed")
        self.run_ok("run", deck, "-o", out, "-q")
        for name in ("glstat", "matsum", "nodout", "rwforc"):
            self.assertTrue(os.path.isfile(os.path.join(out, name)), name)
        theirs = self.assertReaderAgrees(out, 30)
        self.assertTrue(any(k.startswith("rwforc.wall") for k in theirs), sorted(theirs))
        self.assertIn("glstat.rigidwall", theirs)

    def test_only_requested_files_and_reader_agrees_with_csv(self):
        from crumple_compare import lsdyna
        out = self.run_deck("bar.k", bar())
        for name in ("glstat", "matsum", "nodout", "secforc"):
            self.assertTrue(os.path.isfile(os.path.join(out, name)), name)
        for name in ("rcforc", "rwforc", "sleout"):
            self.assertFalse(os.path.exists(os.path.join(out, name)), name)
        self.assertReaderAgrees(out, 20)
        # secforc: the labelled values against secforc.csv.
        theirs = lsdyna.read_folder(out)
        rows = read_csv(os.path.join(out, "secforc.csv"))
        # The final sample repeats the last regular one (both files hold it twice).
        rows = [r for i, r in enumerate(rows) if i + 1 == len(rows) or rows[i + 1]["time"] != r["time"]]
        fx = theirs["secforc.section7.fx"]
        self.assertEqual(len(fx.t), len(rows))
        np.testing.assert_allclose(fx.y, [r["fx"] for r in rows], rtol=1e-4, atol=1e-6)
        area = theirs["secforc.section7.area"]
        self.assertAlmostEqual(float(area.y[-1]), 100.0, places=3)

    def test_contact_and_wall_files(self):
        from crumple_compare import crumple_csv, lsdyna
        out = self.run_deck("contact.k", contact_blocks_with_sleout())
        theirs = {**lsdyna.read_rcforc(os.path.join(out, "rcforc")),
                  **lsdyna.read_sleout(os.path.join(out, "sleout"))}
        ours = crumple_csv.read_folder(out)
        keys = [k for k in ours if k.startswith(("rcforc.", "sleout."))]
        self.assertGreaterEqual(len(keys), 7, sorted(ours))
        for key in keys:
            c, d = ours[key], theirs[key]
            scale = max(np.max(np.abs(c.y)), 1e-30)
            self.assertGreater(scale, 1e-20, key)  # the blocks do touch
            np.testing.assert_allclose(d.t, c.t, rtol=6e-5, err_msg=key)
            np.testing.assert_allclose(d.y, c.y, rtol=6e-5, atol=1e-4 * scale, err_msg=key)


def mask(line):
    """The text of a line with its numbers (and the blanks that right-align them) masked, and
    the column each number ends in."""
    ends = [m.end() for m in NUM.finditer(line)]
    return re.sub(" *" + NUM.pattern, "#", line), ends


class Layout(Case):
    """Our files against LS-DYNA R13's, line by line where the content is alike."""

    @classmethod
    def setUpClass(cls):
        cls.dyna = lsdyna_folder()
        if cls.dyna is None:
            raise unittest.SkipTest("../shared/decks/bolted_joint_lsdyna is not present")

    def lines(self, folder, name):
        with open(os.path.join(folder, name), encoding="latin-1") as f:
            return f.read().splitlines()

    def assertSameLayout(self, ours, theirs, what):
        a, b = mask(ours), mask(theirs)
        self.assertEqual(a, b, f"{what}:\n ours:   {ours!r}\n LS-DYNA: {theirs!r}")

    def banner(self, ours, theirs):
        self.assertEqual(len(ours[0]), len(theirs[0]))
        self.assertTrue(ours[0].startswith(" ") and theirs[0].startswith(" "))
        self.assertEqual(ours[1][:20], theirs[1][:20])
        self.assertTrue(ours[1][20:].startswith("ls-dyna"))

    def legend(self, ours, theirs, name):
        """The legend block: same framing lines, ids ending in column 9, titles from the same
        column, lines of the same length."""
        a0, b0 = ours.index("{BEGIN LEGEND}"), theirs.index("{BEGIN LEGEND}")
        self.assertEqual(ours[:a0], [l for l in ours[:a0]])
        self.assertEqual(ours[a0 + 1], theirs[b0 + 1])
        self.assertEqual(len(ours[a0 + 2]), len(theirs[b0 + 2]), name)
        self.assertEqual(mask(ours[a0 + 2])[1][0], mask(theirs[b0 + 2])[1][0], name)
        a1, b1 = ours.index("{END LEGEND}"), theirs.index("{END LEGEND}")
        return a1, b1

    def test_glstat_matsum_nodout(self):
        out = self.run_deck("bar.k", bar())
        ours, theirs = self.lines(out, "glstat"), self.lines(self.dyna, "glstat")
        self.banner(ours, theirs)
        # Two blank lines, the 'dt of cycle' line, a blank, the 19 labelled lines.
        for k in range(2, 25):
            self.assertSameLayout(ours[k], theirs[k], f"glstat line {k + 1}")
        self.assertSameLayout(ours[27], theirs[27], "glstat second block")
        ours, theirs = self.lines(out, "matsum"), self.lines(self.dyna, "matsum")
        self.banner(ours, theirs)
        a1, b1 = self.legend(ours, theirs, "matsum")
        # From the legend's end: blanks, ' time =', one part's four lines and the blanks after.
        for k in range(0, 10):
            self.assertSameLayout(ours[a1 + k], theirs[b1 + k], f"matsum line {a1 + k + 1}")
        ours, theirs = self.lines(out, "nodout"), self.lines(self.dyna, "nodout")
        self.banner(ours, theirs)
        a1, b1 = self.legend(ours, theirs, "nodout")
        # blanks, the title line, a blank, the column header, two node rows, blanks, next title.
        for k in range(0, 9):
            self.assertSameLayout(ours[a1 + k], theirs[b1 + k], f"nodout line {a1 + k + 1}")
        self.assertEqual(ours[a1 + 11], theirs[b1 + 11][:0] + ours[a1 + 11])

    def test_rcforc_sleout(self):
        out = self.run_deck("contact.k", contact_blocks_with_sleout())
        ours, theirs = self.lines(out, "rcforc"), self.lines(self.dyna, "rcforc")
        self.banner(ours, theirs)
        a1, b1 = self.legend(ours, theirs, "rcforc")
        self.assertSameLayout(ours[a1 + 1], theirs[b1 + 1], "rcforc blank")
        slave = next(l for l in theirs if l.startswith("  slave"))
        master = next(l for l in theirs if l.startswith("  master"))
        self.assertSameLayout(ours[a1 + 2], slave, "rcforc slave row")
        self.assertSameLayout(ours[a1 + 3], master, "rcforc master row")
        ours, theirs = self.lines(out, "sleout"), self.lines(self.dyna, "sleout")
        self.banner(ours, theirs)
        a1, b1 = self.legend(ours, theirs, "sleout")
        for k in range(0, 9):
            self.assertSameLayout(ours[a1 + k], theirs[b1 + k], f"sleout line {a1 + k + 1}")
        # After the one interface's row: the blank and the summary (LS-DYNA's has three rows).
        for k in range(0, 7):
            self.assertSameLayout(ours[a1 + 8 + k], theirs[b1 + 10 + k], f"sleout summary {k}")

    def test_secforc_banner(self):
        # LS-DYNA's sample secforc holds only the banner (its deck has no cross section).
        out = self.run_deck("bar.k", bar())
        self.banner(self.lines(out, "secforc"), self.lines(self.dyna, "secforc"))


class Parallel(Case):
    def test_section_files_same_bytes_at_1_2_3_ranks(self):
        self.assertSameBytesAtRanks(bar(), ("secforc.csv", "secforc", "nodout", "nodout.csv"))


class Restart(Case):
    def test_restart_continues_ascii_files(self):
        self.assertRestartContinues(bar(extra="*DATABASE_BINARY_D3DUMP\n     400.0\n"),
                                    ("glstat", "matsum", "nodout", "secforc", "secforc.csv"))


if __name__ == "__main__":
    main()
