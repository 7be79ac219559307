"""*CONTACT_TIED_SHELL_EDGE_TO_SURFACE (docs/theory.md, "Tied shell edges") against physics,
through the command line on the T-joint decks of tools/tied_edge_decks.py: a strip of shells
standing on a plate, its bottom edge tied to the plate, pushed sideways at its top, brought to
rest by global damping.

  - on a rigid base (every plate node held) the strip is a cantilever: its tip deflection is
    F L^3 / (3 E I) within 1.5% (the merged model: 0.997 of it) and within 1% of the model with
    the edge merged into the plate;
  - on a plate held at two edges only, the moment goes into the plate's rotations: the tip
    deflection (strip bending + plate rotation) within 1% of the merged model;
  - without the rotational tie (*CONTACT_TIED_NODES_TO_SURFACE) the edge is a hinge and the
    strip falls over: the same load moves the tip many times further;

Run as: python3 tests/verification/test_tied_edge.py <crumple> <source dir>
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
import clitest  # noqa: E402
from clitest import TempDirTest, main  # noqa: E402
from clitest import history_rows as rows  # noqa: E402


def decks():
    return clitest.tools_module("tied_edge_decks")


def tip_dy(out, node):
    """The tip's y displacement at the end, and its spread over the last quarter (at rest?)."""
    hist = [r for r in rows(out, "nodout.csv") if int(r["node"]) == node]
    tail = [r["dy"] for r in hist[-len(hist) // 4:]]
    return hist[-1]["dy"], max(tail) - min(tail)


class TiedShellEdge(TempDirTest):
    def run_tee(self, name, **kw):
        d = decks()
        out = self.run_deck(name, d.t_joint(**kw))
        dy, spread = tip_dy(out, d.tip_node())
        self.assertLess(spread, 0.002 * abs(dy), f"{name}: not at rest")
        return dy, out

    def test_cantilever_on_a_rigid_base(self):
        d = decks()
        force = 0.01
        tied, out = self.run_tee("tied", force=force)
        merged, _ = self.run_tee("merged", force=force, merged=True)
        theory = d.tip_deflection_theory(force)
        self.assertAlmostEqual(merged / theory, 1.0, delta=0.015)
        self.assertAlmostEqual(tied / merged, 1.0, delta=0.01)
        # Energy: damping takes what the load put in beyond the stored strain energy.
        glstat = rows(out, "glstat.csv")
        self.assertAlmostEqual(glstat[-1]["energy_ratio"], 1.0, delta=0.01)

    def test_negative_sst_ties_across_a_gap(self):
        # SST < 0 in a tied interface (Keyword Manual, *CONTACT card 3; abq2dyn writes -5.0):
        # nodes within |SST| of the surface are tied, whatever the thicknesses. The strip stood
        # 3 mm above the plate (more than the plate's thickness, the default tolerance) is
        # tied with SST = -5, its gap kept (_BEAM_OFFSET), and is the same cantilever: the tip
        # deflection within 1% of the strip standing on the plate. With SST = 0 nothing is
        # tied; SST < 0 in a contact that is not tied is an error.
        d = decks()
        force = 0.01
        on_plate, _ = self.run_tee("tied_on_plate", force=force)
        contact = "*CONTACT_TIED_SHELL_EDGE_TO_SURFACE_ID_BEAM_OFFSET"
        gapped, out = self.run_tee("tied_gap", force=force, gap=3.0, sst=-5.0, contact=contact)
        self.assertEqual(clitest.read_summary(out)["contact"]["tied_nodes"], 5)
        self.assertAlmostEqual(gapped / on_plate, 1.0, delta=0.01)
        loose = self.run_deck("loose", d.t_joint(gap=3.0, sst=0.0, contact=contact, end=0.5))
        self.assertEqual(clitest.read_summary(loose)["contact"]["tied_nodes"], 0)
        bad = self.write("bad.k", d.t_joint(sst=-5.0, contact="*CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID"))
        p = clitest.crumple("check", bad, cwd=self.tmp)
        self.assertNotEqual(p.returncode, 0)
        self.assertIn("SST", p.stdout + p.stderr)

    def test_moment_goes_into_a_flexible_plate(self):
        tied, _ = self.run_tee("tied_plate", support="edges")
        merged, _ = self.run_tee("merged_plate", support="edges", merged=True)
        rigid, _ = self.run_tee("merged_rigid", merged=True)
        # The plate's rotation adds to the tip deflection (1.3% with this 2 mm plate).
        self.assertGreater(merged, 1.01 * rigid)
        self.assertAlmostEqual(tied / merged, 1.0, delta=0.01)

    def test_translational_tie_alone_is_a_hinge(self):
        d = decks()
        out = self.run_deck("hinge", d.t_joint(contact="*CONTACT_TIED_NODES_TO_SURFACE_ID",
                                               end=6.0))
        hist = [r for r in rows(out, "nodout.csv") if int(r["node"]) == d.tip_node()]
        theory = d.tip_deflection_theory(0.01)
        self.assertGreater(abs(hist[-1]["dy"]), 5.0 * theory)


if __name__ == "__main__":
    main()
