#!/usr/bin/env python3
"""Results are bitwise identical for any number of threads (ARCHITECTURE.md, "Determinism is a
design rule"): the state_digest of summary.json (SHA-256 of the final x and v) must not depend
on --threads. Also checks that the digest is what it claims to be: it changes when the state
does, and a repeated run reproduces it."""

import hashlib
import os
import struct
import sys

sys.dont_write_bytecode = True  # keep __pycache__ out of the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402
from clitest import crumple, describe, read_summary  # noqa: E402


class ThreadCountIndependence(clitest.TempDirTest):
    def run_deck(self, deck, threads, *extra):
        out = os.path.join(self.tmp, f"{os.path.basename(deck)}.{threads}.{len(os.listdir(self.tmp))}")
        p = crumple("run", deck, "-o", out, "--threads", threads, "-q", *extra)
        self.assertEqual(p.returncode, 0, describe(p))
        s = read_summary(out)
        self.assertEqual(s["termination"], "normal")
        self.assertEqual(s["threads"], threads, "summary.json threads is not what was asked")
        self.assertRegex(s["state_digest"], r"^[0-9a-f]{64}$")
        return s

    def assertSameRun(self, a, b, what):
        self.assertEqual(a["cycles"], b["cycles"], f"{what}: cycle counts differ")
        self.assertEqual(a["end_time"], b["end_time"], f"{what}: end times differ")
        self.assertEqual(a["state_digest"], b["state_digest"],
                         f"{what}: final state differs between 1 and 2 threads")
        # Diagnostics are summed in a fixed order too.
        self.assertEqual(a["energy"], b["energy"], f"{what}: energies differ")

    def test_bar_impact(self):
        deck = clitest.example("bar_impact", "bar_impact.k")
        one, two = self.run_deck(deck, 1), self.run_deck(deck, 2)
        self.assertSameRun(one, two, "bar impact")
        # The same run again reproduces the digest; a different end time changes it.
        self.assertEqual(self.run_deck(deck, 1)["state_digest"], one["state_digest"])
        shorter = self.run_deck(deck, 1, "--endtime", "0.05")
        self.assertNotEqual(shorter["state_digest"], one["state_digest"])

    def test_taylor_bar(self):
        # Elastic-plastic, with a stonewall; shortened to 10 us (about 320 cycles) to stay quick.
        deck = clitest.example("taylor_bar", "taylor_bar.k")
        one = self.run_deck(deck, 1, "--endtime", "0.01")
        two = self.run_deck(deck, 2, "--endtime", "0.01")
        self.assertAlmostEqual(one["end_time"], 0.01, delta=1e-12)
        self.assertGreater(one["energy"]["internal"], 0.0, "the bar should be deforming by now")
        self.assertSameRun(one, two, "Taylor bar")

    def test_tube_crush_contact(self):
        # Single-surface contact on a folding tube: the contact checks run on the threads too
        # (more than 128 active checks), and the records are put in check order.
        sys.path.insert(0, os.path.join(clitest.SOURCE_DIR, "tools"))
        import contact_decks  # noqa: E402
        deck = self.write("tube.k", contact_decks.tube_crush(size=5.0, length=60.0, end=1.0))
        one, two = self.run_deck(deck, 1), self.run_deck(deck, 2)
        self.assertGreater(one["contact"]["records_per_cycle"], 1.0)
        self.assertSameRun(one, two, "1 vs 2 threads")


class DigestDefinition(clitest.TempDirTest):
    """state_digest = SHA-256 of the final x then v, little-endian float64, nodes in ascending
    global id (ARCHITECTURE.md, summary.json). A brick at rest keeps x = x0 and v = 0 exactly,
    so the digest can be computed here; the nodes are listed in descending id order, with ids
    that are not contiguous, to check the ordering."""

    def test_digest_of_a_brick_at_rest(self):
        coords = {10 * (1 + i + 2 * j + 4 * k): (1.5 * i, 2.0 * j, 0.25 * k)
                  for k in range(2) for j in range(2) for i in range(2)}
        deck = "*KEYWORD\n*CONTROL_TERMINATION\n     0.001\n*PART\nblock\n"
        deck += "         1         1         1\n*SECTION_SOLID\n         1         1\n"
        deck += "*MAT_ELASTIC\n         1   7.85e-6     210.0       0.3\n*NODE\n"
        for nid in sorted(coords, reverse=True):
            deck += f"{nid:8d}" + "".join(f"{c:16.6f}" for c in coords[nid]) + "\n"
        deck += "*ELEMENT_SOLID\n" + "".join(
            f"{v:8d}" for v in (1, 1, 10, 20, 40, 30, 50, 60, 80, 70)) + "\n*END\n"
        self.write("rest.k", deck)
        p = crumple("run", "rest.k", "-o", "out", "-q", cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        s = read_summary(os.path.join(self.tmp, "out"))
        self.assertGreater(s["cycles"], 0)
        x = [c for nid in sorted(coords) for c in coords[nid]]
        expected = hashlib.sha256(struct.pack(f"<{len(x)}d", *x) +
                                  struct.pack(f"<{len(x)}d", *([0.0] * len(x)))).hexdigest()
        self.assertEqual(s["state_digest"], expected)


if __name__ == "__main__":
    clitest.main()
