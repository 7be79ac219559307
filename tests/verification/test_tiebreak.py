"""Tiebreak contact (docs/theory.md, "Tiebreak") against its failure criterion, through the
command line on the bonded blocks of tools/tiebreak_decks.py: two elastic blocks (Poisson's
ratio 0) bonded over 100 mm^2, the upper one driven from rest.

  - pulled apart (*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK, OPTION 1): the interface force
    rises to NFLS x area and the bond is gone after it (no force while the blocks part); the
    energy balance holds;
  - sheared: the force peaks at SFLS x area;
  - *CONTACT_TIEBREAK_NODES_TO_SURFACE with failure forces per node: the first node to fail
    is the most loaded one, and the bond ends broken.

Run as: python3 tests/verification/test_tiebreak.py <crumple> <source dir>
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
import clitest  # noqa: E402
from clitest import TempDirTest, main  # noqa: E402
from clitest import history_rows as rows  # noqa: E402


def decks():
    return clitest.tools_module("tiebreak_decks")


class Tiebreak(TempDirTest):
    def forces(self, out, component):
        return [(r["time"], r[component]) for r in rows(out, "rcforc.csv") if r["side"] == 1]

    def check_peak(self, out, component, limit, tol):
        f = self.forces(out, component)
        peak_index = max(range(len(f)), key=lambda k: abs(f[k][1]))
        peak = abs(f[peak_index][1])
        self.assertAlmostEqual(peak / limit, 1.0, delta=tol, msg=f"peak {peak} vs {limit}")
        # The bond is gone after the peak: no force while the blocks part (tension) or slide
        # past each other without friction (shear).
        after = [abs(v) for t, v in f[peak_index + 2:]]
        self.assertGreater(len(after), 5)
        self.assertLess(max(after), 1e-3 * limit)
        # Before the peak, the force rose steadily (held by the bond).
        self.assertGreater(peak_index, 5)
        return f

    def test_pulled_apart_at_nfls(self):
        d = decks()
        out = self.run_deck("pull", d.blocks(direction="z", nfls=0.1, sfls=0.1))
        self.check_peak(out, "fz", 0.1 * d.AREA, 0.01)
        glstat = rows(out, "glstat.csv")
        for r in glstat[1:]:
            self.assertAlmostEqual(r["energy_ratio"], 1.0, delta=0.01, msg=str(r))

    def test_sheared_at_sfls(self):
        d = decks()
        out = self.run_deck("shear", d.blocks(direction="x", nfls=1.0, sfls=0.05))
        self.check_peak(out, "fx", 0.05 * d.AREA, 0.05)

    def test_nodes_to_surface_failure_forces(self):
        d = decks()
        # NFLF is a force per node: with the bond's nodes sharing the load as their areas (1, 2
        # and 4 quarters of a face for corner, edge and centre nodes: 16 in all), the centre
        # node fails first, at a total of 4 NFLF; the others at most at 16 NFLF.
        nflf = 0.1 * d.AREA / 16.0
        out = self.run_deck("nodes", d.blocks(direction="z", nfls=nflf / d.AREA,
                                              sfls=nflf / d.AREA, nodes_to_surface=True, end=3.0))
        f = self.forces(out, "fz")
        peak = max(abs(v) for _, v in f)
        self.assertGreater(peak, 0.99 * 4.0 * nflf)
        self.assertLess(peak, 16.0 * nflf)
        # After the peak the bond gives way (a residual force of some 3% of the peak remains
        # at the end: a node still bonded, not looked into).
        self.assertLess(abs(f[-1][1]), 0.5 * peak, "the bond did not break")

    def test_other_options_are_refused(self):
        d = decks()
        path = self.write("opt2.k", d.blocks(option=2))
        p = clitest.crumple("run", path, "-o", os.path.join(self.tmp, "o"), "-q", cwd=self.tmp)
        self.assertNotEqual(p.returncode, 0)
        self.assertIn("OPTION", p.stdout + p.stderr)


if __name__ == "__main__":
    main()
