#!/usr/bin/env python3
"""Numerical failure ends a run with exit status 1, termination "error" in summary.json, a
message naming the element, its part, the cycle and the time, and the last state written
(ARCHITECTURE.md Part 2, "Errors")."""

import csv
import os
import re
import sys
import xml.etree.ElementTree as ET

sys.dont_write_bytecode = True  # keep __pycache__ out of the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402
from clitest import crumple, describe, read_summary  # noqa: E402


def collapsing_block(element_id=42, part_id=3):
    """A unit cube of steel, bottom face held, top face driven down 5 mm in 0.1 ms: the element
    turns inside out after about 1 mm / (50 mm/ms) = 0.02 ms. Plot states every 0.01 ms."""
    nodes = [(1, 0, 0, 0), (2, 1, 0, 0), (3, 1, 1, 0), (4, 0, 1, 0),
             (5, 0, 0, 1), (6, 1, 0, 1), (7, 1, 1, 1), (8, 0, 1, 1)]
    s = "*KEYWORD\n*TITLE\ncollapse\n*CONTROL_TERMINATION\n       1.0\n"
    s += "*DATABASE_BINARY_D3PLOT\n      0.01\n*DATABASE_GLSTAT\n     0.001\n"
    s += f"*PART\nblock\n{part_id:10d}         1         1\n*SECTION_SOLID\n         1         1\n"
    s += "*MAT_ELASTIC\n         1  7.85e-06     210.0       0.3\n*NODE\n"
    s += "".join(f"{n:8d}{x:16.6f}{y:16.6f}{z:16.6f}\n" for n, x, y, z in nodes)
    s += "*ELEMENT_SOLID\n" + "".join(
        f"{v:8d}" for v in (element_id, part_id, 1, 2, 3, 4, 5, 6, 7, 8)) + "\n"
    s += "*SET_NODE_LIST\n         1\n         1         2         3         4\n"
    s += "*SET_NODE_LIST\n         2\n         5         6         7         8\n"
    s += "*BOUNDARY_SPC_SET\n         1         0         1         1         1\n"
    s += "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n"
    s += "                 0.1                -5.0\n"
    s += "*BOUNDARY_PRESCRIBED_MOTION_SET\n         2         3         2         1       1.0\n"
    return s + "*END\n"


class ErrorTermination(clitest.TempDirTest):
    def test_inverted_element(self):
        self.write("collapse.k", collapsing_block())
        out = os.path.join(self.tmp, "out")
        p = crumple("run", "collapse.k", "-o", out, "-q", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("element 42", p.stderr, describe(p))
        self.assertIn("part 3", p.stderr, describe(p))
        m = re.search(r"cycle (\d+), time (\S+)", p.stderr)
        self.assertIsNotNone(m, "the message names the cycle and time" + describe(p))
        cycle, time = int(m.group(1)), float(m.group(2))

        s = read_summary(out)
        self.assertEqual(s["termination"], "error")
        self.assertIn("element 42", s.get("message", ""), "summary.json keeps the message")
        self.assertEqual(s["cycles"], cycle)
        # The top face reaches the bottom one (1 mm at 50 mm/ms) at 0.02 ms; the element
        # fails at or before that, well before the end time 1.0.
        self.assertGreater(time, 0.0)
        self.assertLessEqual(time, 0.0201)
        # The message prints 6 significant digits.
        self.assertAlmostEqual(s["end_time"], time, delta=1e-5 * time)

        # The last state was written: results.pvd lists the states up to the failure, the last
        # one at the failure time, and VTK reads them.
        root = ET.parse(os.path.join(out, "results.pvd")).getroot()
        stamps = [float(d.get("timestep")) for d in root.iter("DataSet")]
        self.assertGreaterEqual(len(stamps), 1)
        self.assertEqual(stamps[-1], s["end_time"])
        data = clitest.read_vtu(out)
        self.assertEqual(len(data["states"]), len(stamps))
        self.assertEqual(data["states"][-1]["cells"], 1)
        self.assertEqual(data["states"][-1]["points"], 8)
        # The top face has moved down in the last state.
        disp = data["states"][-1]["point_data"]["displacement"]["range"]
        self.assertLess(disp[0], -0.5)

        with open(os.path.join(out, "run.log"), encoding="utf-8") as f:
            log = f.read()
        self.assertIn("error termination", log)
        self.assertIn("element 42", log)
        with open(os.path.join(out, "glstat.csv"), newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        self.assertGreater(len(rows), 2, "glstat.csv has the history up to the failure")

    def test_error_results_need_overwrite_too(self):
        # A failed run's folder holds results as well: a rerun must not destroy them silently.
        self.write("collapse.k", collapsing_block())
        p = crumple("run", "collapse.k", "-o", "out", "-q", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        p = crumple("run", "collapse.k", "-o", "out", "-q", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("--overwrite", p.stderr, describe(p))


if __name__ == "__main__":
    clitest.main()
