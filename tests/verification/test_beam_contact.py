"""Beam-to-beam contact of *CONTACT_AUTOMATIC_GENERAL (beams as capsules; docs/theory.md,
"Beam edges") against physics, through the command line on decks from
tools/beam_contact_decks.py:

  - two crossing beams, one held, the other driven into it: the contact force is
    k x penetration with k = SLSFAC x SSF x K x D (the slope dF/dz is -k to 1e-6), none while
    the axes are further apart than the sum of the radii, equal and opposite on the two beams;
  - two crossing beams colliding freely (middles over each other, so each moves as a body):
    the elastic collision of equal masses, the struck beam leaves with the striker's speed,
    kinetic energy back to 0.5%, momentum to round-off, the contact energy at the deepest
    point half the kinetic energy;
  - a beam driven along a parallel one, the capsules overlapping: the force k x overlap, shared
    between the long beam's nodes as 1 - s and s, s the middle of the overlap (accelerations of
    its nodes), and none once the short beam is past the end.

Run as: python3 tests/verification/test_beam_contact.py <crumple> <source dir>
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
import clitest  # noqa: E402
from clitest import TempDirTest, main  # noqa: E402
from clitest import history_rows as rows  # noqa: E402


def decks():
    return clitest.tools_module("beam_contact_decks")


class BeamContactVerification(TempDirTest):
    def test_crossing_beams_force_is_stiffness_times_penetration(self):
        b = decks()
        v, gap = 1.0, 0.002
        out = self.run_deck("push", b.crossing(gap, v_b=v, pushed=True, end=4e-3, dt_out=1e-4))
        k = b.stiffness(0.01)
        dt = rows(out, "glstat.csv")[1]["dt"]
        z = {r["time"]: r["z"] for r in rows(out, "nodout.csv") if r["node"] == 3}
        force = {}
        for r in rows(out, "rcforc.csv"):
            force.setdefault(r["time"], {})[int(r["side"])] = r
        touching = []
        for t in sorted(force):
            a, s = force[t][1], force[t][2]
            # Equal and opposite, along the line between the axes (z) only.
            self.assertEqual(a["fz"], -s["fz"])
            self.assertAlmostEqual(a["fx"], 0.0, delta=1e-9 * abs(a["fz"]) + 1e-12)
            if z[t] > b.D + 2.0 * v * dt:
                self.assertEqual(a["fz"], 0.0, f"a force at t = {t}, axes {z[t]} apart > {b.D}")
            elif a["fz"] != 0.0:
                touching.append((z[t], abs(a["fz"])))
        self.assertGreater(len(touching), 10, "the beams never met")
        # The last sample is at the end time, after a shortened step: left out.
        touching = touching[:-1]
        for (z1, f1), (z2, f2) in zip(touching, touching[1:]):
            self.assertAlmostEqual((f2 - f1) / (z1 - z2), k, delta=1e-6 * k)
        # nodout's position is one step of travel ahead of the one the force was found at.
        for zi, fi in touching:
            self.assertAlmostEqual(fi / k, b.D - zi - v * dt, delta=1e-9 * b.D)

    def test_colliding_beams_bounce_back_elastically(self):
        b = decks()
        v = 10.0
        out = self.run_deck("bounce", b.crossing(0.0005, v_b=v))
        glstat = rows(out, "glstat.csv")
        ke0 = glstat[0]["kinetic"]
        ratios = [r["energy_ratio"] for r in glstat]
        self.assertLess(max(abs(r - 1.0) for r in ratios), 0.005, ratios)
        self.assertAlmostEqual(glstat[-1]["kinetic"] / ke0, 1.0, delta=0.005)
        self.assertLess(glstat[-1]["contact"], 1e-6 * ke0, "still in contact at the end")
        # Equal masses meeting: at the deepest point both move at v / 2, half the kinetic
        # energy is in the spring (sampled every 5 us of a 430 us contact: within 2%).
        peak = max(r["contact"] for r in glstat)
        self.assertAlmostEqual(peak / (0.5 * ke0), 1.0, delta=0.02)
        matsum = rows(out, "matsum.csv")
        last = matsum[-1]["time"]
        p0 = sum(r["z_momentum"] for r in matsum if r["time"] == 0.0)
        end = {int(r["part"]): r["z_momentum"] for r in matsum if r["time"] == last}
        self.assertAlmostEqual(end[1] + end[2], p0, delta=1e-12 * abs(p0))
        mv = b.beam_mass(0.1) * v
        self.assertAlmostEqual(end[1], -mv, delta=0.005 * mv)  # the struck beam takes it all
        self.assertAlmostEqual(end[2], 0.0, delta=0.005 * mv)

    def test_parallel_beam_force_shared_by_the_middle_of_the_overlap(self):
        b = decks()
        overlap, u, length_a = 0.002, 10.0, 0.2
        out = self.run_deck("slide", b.parallel_sliding(overlap, u, end=0.045))
        k = b.stiffness(0.001)
        half_mass = 0.5 * b.beam_mass(length_a, rho=b.RHO * 1e8)
        by_time = {}
        for r in rows(out, "nodout.csv"):
            by_time.setdefault(r["time"], {})[int(r["node"])] = r
        contact = {r["time"]: r for r in rows(out, "rcforc.csv") if r["side"] == 1}
        # The capsules' ends meet when the short beam's end is sqrt(D^2 - z^2) from the long
        # beam's end, z the distance of the axes.
        z = b.D - overlap
        reach = (b.D ** 2 - z ** 2) ** 0.5
        shared = past = 0
        for t, n in by_time.items():
            x3, x4 = n[3]["x"], n[4]["x"]
            f0, f1 = -half_mass * n[1]["az"], -half_mass * n[2]["az"]
            if x4 < -reach - 0.001 or x3 > length_a + reach + 0.001:
                fc = contact[t]
                self.assertEqual((fc["fx"], fc["fz"]), (0.0, 0.0), f"a force apart at {x3}")
                past += x3 > length_a
            elif 0.005 < x4 and x3 < length_a - 0.005:
                s = 0.5 * (max(x3, 0.0) + min(x4, length_a)) / length_a
                self.assertAlmostEqual(f0 + f1, k * overlap, delta=1e-4 * k * overlap)
                # Within one step's travel of the short beam (u dt / L ~ 1e-3).
                self.assertAlmostEqual(f1 / (f0 + f1), s, delta=0.002)
                shared += 1
        self.assertGreater(shared, 100)
        self.assertGreater(past, 5, "the short beam never went past the end")


if __name__ == "__main__":
    main()
