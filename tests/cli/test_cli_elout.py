#!/usr/bin/env python3
"""elout (*DATABASE_ELOUT with *DATABASE_HISTORY_SOLID, _SHELL, _BEAM and their _SET forms;
src/output/elout.hpp) and cross sections defined by sets (*DATABASE_CROSS_SECTION_SET;
src/output/sections.hpp):

- physics: test_cli_ascii's bar under an axial end load P: elout's stress sigma_xx = P / A of
  the history solids (named directly and through a *SET_SOLID), the other components near 0;
  a cut given by the nodes at x = 50 and the solid set of the column before them carries P, the
  same numbers as the plane cut through that column; the cantilever of beams pulled along its
  axis: the axial resultant is the load; under a tip load the set cut (node 6, beam 5) has the
  shear P and the moment P (L - 50) of the plane cut; a shell strip bent by a tip load:
  sigma_xx at every point through the thickness is -6 M / (b t^2) zeta;
- lsdyna.py reads the elout file and finds elout.csv's numbers (to the digits printed); it
  reads LS-DYNA R13's own elout of the bolted joint;
- layout: a Hughes-Liu beam's block against LS-DYNA R13's elout line by line (numbers masked);
- the same bytes at 1, 2 and 3 ranks; a restarted run continues elout as the uninterrupted run
  wrote it.
"""

import os
import sys
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402
from clitest import main  # noqa: E402
from test_cli_ascii import Case, bar, cantilever, lsdyna_folder, mask, read_csv  # noqa: E402

try:
    import numpy as np
except ImportError:
    np = None


def setUpModule():
    if np is None:
        raise unittest.SkipTest(f"{sys.executable} has no numpy (tools/setup.sh installs it)")
    sys.path.insert(0, os.path.join(clitest.SOURCE_DIR, "python"))


def cards(*ids):
    return "".join(f"{i:10d}" for i in ids) + "\n"


# The bar's nodes at x = 50 (test_cli_ascii.bar's numbering) and its solids between x = 40
# and 50 (the column the plane cut at x = 45 goes through).
CUT_NODES = [1 + 5 + 11 * (j + 3 * k) for k in range(3) for j in range(3)]
COLUMN = [5, 15, 25, 35]


def bar_with_elout(extra=""):
    s = "*DATABASE_ELOUT\n      0.05\n*DATABASE_HISTORY_SOLID\n" + cards(5, 25)
    s += "*SET_SOLID_TITLE\ncolumn\n        10\n" + cards(*COLUMN)
    s += "*DATABASE_HISTORY_SOLID_SET\n        10\n"
    s += "*SET_NODE_LIST\n        20\n" + cards(*CUT_NODES[:8]) + cards(CUT_NODES[8])
    s += "*DATABASE_CROSS_SECTION_SET_ID\n        11set cut\n" + cards(20, 10)
    return bar(extra=s + extra)


def shell_strip(load):
    """A cantilever strip of 8 x 1 fully integrated shells (ELFORM 16), 80 x 10 mm, 4 mm thick,
    NIP 5 (Gauss), elastic steel, clamped at x = 0, a tip load `load` (kN) along +z on its two
    x = 80 nodes ramped over 50 ms. The first bending mode, 1.875^2 sqrt(E t^2 / (12 rho)) /
    L^2 = 3.3 rad/ms, makes the ramp quasi-static (dynamic error about 1 / (omega T) = 0.6%);
    the tip deflects P L^3 / (3 E I) = 0.61 mm for 0.04 kN (I = b t^3 / 12)."""
    s = "*KEYWORD\n*TITLE\nshell strip\n*CONTROL_TERMINATION\n      50.0\n"
    s += "*DATABASE_ELOUT\n      12.5\n*DATABASE_HISTORY_SHELL_ID\n         3element three\n"
    s += "*PART\nstrip\n         1         1         1\n"
    s += "*SECTION_SHELL\n         1        16    0.8333         5\n"
    s += "       4.0       4.0       4.0       4.0\n"
    s += "*MAT_ELASTIC\n         1   7.85e-6     210.0       0.3\n*NODE\n"
    s += "".join(f"{1 + i + 9 * j:8d}{10.0 * i:16.6f}{10.0 * j:16.6f}{0.0:16.6f}\n"
                 for j in range(2) for i in range(9))
    s += "*ELEMENT_SHELL\n" + "".join(f"{1 + i:8d}{1:8d}{1 + i:8d}{2 + i:8d}{11 + i:8d}"
                                      f"{10 + i:8d}\n" for i in range(8))
    s += "*BOUNDARY_SPC_NODE\n" + "".join(f"{n:10d}{0:10d}" + "         1" * 6 + "\n"
                                          for n in (1, 10))
    s += "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n"
    s += "                50.0                 1.0\n"
    s += "*LOAD_NODE_POINT\n" + "".join(f"{n:10d}         3         1{load / 2:10.4g}\n"
                                        for n in (9, 18))
    return s + "*END\n"


def tshell_strip(load):
    """A strip of 8 x 1 thick shells (*SECTION_TSHELL ELFORM 2, NIP 3), 80 x 10 x 4 mm,
    elastic steel with nu = 0, clamped at x = 0 and pulled along x by `load` (kN) spread over
    its four x = 80 nodes, ramped over 50 ms. *SET_TSHELL 10 holds elements 4 and 5 (x = 30 to
    50), which elout lists (*DATABASE_HISTORY_TSHELL_SET) and which a cut at the x = 50 nodes
    takes (*DATABASE_CROSS_SECTION_SET TSID)."""
    node = lambda i, j, k: 1 + i + 9 * (j + 2 * k)  # noqa: E731
    s = "*KEYWORD\n*TITLE\nthick shell strip\n*CONTROL_TERMINATION\n      50.0\n"
    s += "*DATABASE_ELOUT\n      12.5\n*DATABASE_SECFORC\n      12.5\n"
    s += "*SET_TSHELL_LIST\n        10\n" + cards(4, 5)
    s += "*DATABASE_HISTORY_TSHELL_SET\n        10\n"
    s += "*SET_NODE_LIST\n        20\n" + cards(*[node(5, j, k) for k in (0, 1) for j in (0, 1)])
    s += "*DATABASE_CROSS_SECTION_SET\n        20         0         0         0        10\n"
    s += "*PART\nstrip\n         1         1         1\n"
    s += "*SECTION_TSHELL\n         1         2    0.8333         3\n"
    s += "*MAT_ELASTIC\n         1   7.85e-6     210.0       0.0\n*NODE\n"
    s += "".join(f"{node(i, j, k):8d}{10.0 * i:16.6f}{10.0 * j:16.6f}{4.0 * k:16.6f}\n"
                 for k in range(2) for j in range(2) for i in range(9))
    s += "*ELEMENT_TSHELL\n" + "".join(
        f"{1 + i:8d}{1:8d}" + "".join(f"{node(a, b, k):8d}" for k in (0, 1)
                                      for a, b in ((i, 0), (i + 1, 0), (i + 1, 1), (i, 1)))
        + "\n" for i in range(8))
    s += "*BOUNDARY_SPC_NODE\n" + "".join(f"{node(0, j, k):10d}{0:10d}" + "         1" * 6 +
                                          "\n" for k in (0, 1) for j in (0, 1))
    s += "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n"
    s += "                50.0                 1.0\n"
    s += "*LOAD_NODE_POINT\n" + "".join(f"{node(8, j, k):10d}         1         1{load / 4:10.4g}\n"
                                        for k in (0, 1) for j in (0, 1))
    return s + "*END\n"


def hughes_liu(cantilever_deck):
    """The cantilever with Hughes-Liu beams (ELFORM 1) of the same 10 x 10 mm section, 2 x 2
    Gauss points (QR 2), as the bolted joint's spot weld beam has four."""
    old = "*SECTION_BEAM\n         1         2    0.8333         2         0\n"
    old += "     100.0     833.3     833.3    1406.0     83.33\n"
    new = "*SECTION_BEAM\n         1         1    0.8333         2         0\n"
    new += "      10.0      10.0      10.0      10.0\n"
    assert old in cantilever_deck
    return cantilever_deck.replace(old, new)


def elout_rows(out, family):
    return [r for r in read_csv(os.path.join(out, "elout.csv")) if r["family"] == family]


class EloutPhysics(Case):
    def test_bar_stress_and_set_cut(self):
        load, area = 10.0, 100.0
        out = self.run_deck("bar.k", bar_with_elout())
        rows = elout_rows(out, 0)
        self.assertEqual(sorted({int(r["element"]) for r in rows}), COLUMN)
        late = [r for r in rows if r["time"] >= 2.5]
        self.assertGreater(len(late), 20)
        for r in late:
            # Uniaxial stress P / A = 0.1 GPa along the bar, tension positive.
            self.assertAlmostEqual(r["sxx"], load / area, delta=0.02 * load / area)
            for key in ("syy", "szz", "sxy", "syz", "szx", "eps_p"):
                self.assertLess(abs(r[key]), 0.01 * load / area, key)
        sections = read_csv(os.path.join(out, "secforc.csv"))
        by_id = {}
        for r in sections:
            by_id.setdefault(int(r["section"]), []).append(r)
        self.assertEqual(sorted(by_id), [7, 11])
        for plane, cut in zip(by_id[7], by_id[11]):
            # The same elements on the same nodes as the plane cut: the same sums.
            for key in ("time", "fx", "fy", "fz", "mx", "my", "mz", "cx", "cy", "cz", "area"):
                self.assertEqual(plane[key], cut[key], key)
        last = by_id[11][-1]
        self.assertAlmostEqual(last["fx"], load, delta=0.02 * load)
        self.assertEqual(last["area"], area)

    def test_beam_axial_resultant(self):
        load = 0.1
        deck = cantilever(load).replace("        11         3         1",
                                        "        11         1         1")
        deck = deck.replace("*PART\n", "*DATABASE_ELOUT\n       5.0\n*DATABASE_HISTORY_BEAM\n"
                            "         3\n*PART\n", 1)
        out = self.run_deck("pulled.k", deck)
        last = elout_rows(out, 2)[-1]
        self.assertEqual((last["time"], last["element"], last["point"]), (50.0, 3.0, 0.0))
        self.assertAlmostEqual(last["axial"], load, delta=0.01 * load)
        for key in ("shear_s", "shear_t", "moment_s", "moment_t", "torsion"):
            self.assertLess(abs(last[key]), 1e-3 * load, key)

    def test_beam_set_cut_moment(self):
        load, length = 0.1, 100.0
        extra = "*SET_NODE_LIST\n        30\n         6\n*SET_BEAM_LIST\n        31\n         5\n"
        extra += "*DATABASE_CROSS_SECTION_SET\n        30         0        31\n"
        out = self.run_deck("cantilever.k", cantilever(load).replace("*PART\n", extra + "*PART\n"))
        rows = read_csv(os.path.join(out, "secforc.csv"))
        plane = [r for r in rows if r["section"] == 1.0][-1]
        cut = [r for r in rows if r["section"] == 2.0][-1]
        for key in ("fx", "fy", "fz", "mx", "my", "mz", "area"):
            self.assertEqual(plane[key], cut[key], key)
        # Moment = force x arm: the tip load P about node 6 at x = 50.
        self.assertAlmostEqual(cut["fz"], load, delta=0.01 * load)
        self.assertAlmostEqual(cut["my"], -load * (length - 50.0), delta=0.01 * load * length)

    def test_shell_bending_through_thickness(self):
        load, b, t = 0.04, 10.0, 4.0
        out = self.run_deck("strip.k", shell_strip(load))
        rows = [r for r in elout_rows(out, 1) if r["time"] == 50.0]
        self.assertEqual([int(r["point"]) for r in rows], [1, 2, 3, 4, 5])
        # Element 3 spans x = 20..30: M = P (L - 25) at its centre; sigma_xx = -6 M / (b t^2)
        # zeta (the load bends the strip concave up: the bottom, zeta < 0, in tension).
        surface = 6.0 * load * (80.0 - 25.0) / (b * t * t)
        zeta = [-0.9061798459, -0.5384693101, 0.0, 0.5384693101, 0.9061798459]
        for r, z in zip(rows, zeta):
            self.assertAlmostEqual(r["sxx"], -surface * z, delta=0.02 * surface, msg=z)
            self.assertLess(abs(r["szz"]), 1e-3 * surface)


    def test_tshell_set_history_and_cut(self):
        load, area = 4.0, 40.0
        out = self.run_deck("tshell_strip.k", tshell_strip(load))
        # The thick shells of *SET_TSHELL 10, listed with the solids (family 0): sigma_xx = P / A.
        rows = elout_rows(out, 0)
        self.assertEqual(sorted({int(r["element"]) for r in rows}), [4, 5])
        for r in [r for r in rows if r["time"] == 50.0]:
            self.assertAlmostEqual(r["sxx"], load / area, delta=0.01 * load / area)
        cut = read_csv(os.path.join(out, "secforc.csv"))[-1]
        self.assertEqual(cut["time"], 50.0)
        self.assertAlmostEqual(cut["fx"], load, delta=0.01 * load)
        self.assertLess(abs(cut["fz"]), 1e-3 * load)


class EloutFiles(Case):
    def test_every_curve_of_the_csv_in_the_ascii_file(self):
        # crumple_csv keys elout.csv as lsdyna.py keys elout: every curve of a solid, shell
        # and Hughes-Liu beam history read from both agrees to the digits printed.
        deck = hughes_liu(cantilever(0.1)).replace(
            "*PART\n", "*DATABASE_ELOUT\n      25.0\n*DATABASE_HISTORY_BEAM\n         1\n*PART\n")
        # The beam resultants have four significant digits (E11.3).
        for name, text, at_least, rtol in (("bar.k", bar_with_elout(), 4 * 7, 6e-5),
                                           ("strip.k", shell_strip(0.04), 5 * 7, 6e-5),
                                           ("hl.k", deck, 7 + 4 * 4, 6e-4)):
            out = self.run_deck(name, text)
            theirs = self.assertReaderAgrees(out, at_least, rtol)
            self.assertTrue(any(k.startswith("elout.") for k in theirs))

    def test_reader_agrees_with_csv(self):
        from crumple_compare import lsdyna
        out = self.run_deck("bar.k", bar_with_elout())
        curves = lsdyna.read_elout(os.path.join(out, "elout"))
        rows = elout_rows(out, 0)
        for e in COLUMN:
            mine = [r for r in rows if r["element"] == e]
            for key in ("sxx", "syy", "szz", "sxy", "syz", "szx"):
                c = curves[f"elout.solid{e}.{key}"]
                np.testing.assert_allclose(c.t, [r["time"] for r in mine], rtol=6e-5)
                scale = max(abs(r[key]) for r in mine) or 1.0
                np.testing.assert_allclose(c.y, [r[key] for r in mine], rtol=6e-4,
                                           atol=1e-4 * scale, err_msg=key)
        # Shells and beams too: every point of the strip and the Hughes-Liu beam's points.
        out = self.run_deck("strip.k", shell_strip(0.04))
        curves = lsdyna.read_elout(os.path.join(out, "elout"))
        self.assertEqual(len(curves["elout.shell3.ipt5.sxx"].t), 5)
        last = elout_rows(out, 1)[-1]
        self.assertAlmostEqual(curves["elout.shell3.ipt5.sxx"].y[-1], last["sxx"],
                               delta=1e-4 * abs(last["sxx"]))
        deck = hughes_liu(cantilever(0.1)).replace(
            "*PART\n", "*DATABASE_ELOUT\n      25.0\n*DATABASE_HISTORY_BEAM\n         1\n*PART\n")
        out = self.run_deck("hl.k", deck)
        curves = lsdyna.read_elout(os.path.join(out, "elout"))
        self.assertIn("elout.beam1.ipt4.sigma11", curves)
        self.assertAlmostEqual(curves["elout.beam1.shear_t"].y[-1], 0.1, delta=0.002)

    def test_lsdyna_r13_sample_read_and_beam_layout(self):
        from crumple_compare import lsdyna
        dyna = lsdyna_folder()
        if dyna is None:
            self.skipTest("../shared/decks/bolted_joint_lsdyna is not present")
        theirs = lsdyna.read_elout(os.path.join(dyna, "elout"))
        self.assertEqual(len(theirs["elout.beam1000000.axial"].t), 1001)
        self.assertIn("elout.beam1000000.ipt4.sigma31", theirs)
        deck = hughes_liu(cantilever(0.1)).replace(
            "*PART\n", "*DATABASE_ELOUT\n      25.0\n*DATABASE_HISTORY_BEAM\n         1\n*PART\n")
        out = self.run_deck("hl.k", deck)
        with open(os.path.join(out, "elout"), encoding="latin-1") as f:
            ours = f.read().splitlines()
        with open(os.path.join(dyna, "elout"), encoding="latin-1") as f:
            ref = f.read().splitlines()
        self.assertEqual(len(ours[0]), len(ref[0]))
        self.assertEqual(ours[1][:20], ref[1][:20])
        # The first block: title, beam line, resultants, the four points; and the next title.
        for k in range(2, 22):
            self.assertEqual(mask(ours[k]), mask(ref[k]), f"line {k + 1}:\n{ours[k]!r}\n{ref[k]!r}")


class EloutRanksAndRestart(Case):
    def test_same_bytes_at_1_2_3_ranks(self):
        self.assertSameBytesAtRanks(bar_with_elout(),
                                    ("elout", "elout.csv", "secforc", "secforc.csv"))

    def test_restart_continues_elout(self):
        self.assertRestartContinues(bar_with_elout("*DATABASE_BINARY_D3DUMP\n     400.0\n"),
                                    ("elout", "elout.csv", "secforc.csv"))


if __name__ == "__main__":
    main()
