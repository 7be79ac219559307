"""The examples under examples/ (issue 18) against their expected results, through the command
line, on the committed decks (shortened where the whole run is too long for the suite):

  - every committed deck is what tools/make_examples.py writes;
  - box_beam: the mean crush force of the tube (its plastic work over the crush distance) lies
    between 0.8 x Wierzbicki-Abramowicz and 1.2 x Abramowicz-Jones, the folds do not pass
    through each other, energy is conserved;
  - cask_drop: the impulse of the target's contact force equals the cask's change of
    momentum, energy within 2%, the peak deceleration between the mean over the impact and the
    plane-wave bound rho c A v / M;
  - earth_penetrator: the depth travelled per speed lost follows Young's penetration equation
    (remaining depth proportional to V - 30.5 m/s) with the S-number the whole run gives.

Run as: python3 tests/verification/test_examples.py <crumple> <source dir>
"""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
import clitest  # noqa: E402
from clitest import TempDirTest, crumple, describe, main, read_summary  # noqa: E402
from clitest import history_rows as rows  # noqa: E402


class ExampleVerification(TempDirTest):
    def run_example(self, name, *args, timeout=600):
        deck = clitest.example(name, name + ".k")
        out = os.path.join(self.tmp, name + ".out")
        p = crumple("run", deck, "-o", out, "-q", *args, cwd=self.tmp, timeout=timeout)
        self.assertEqual(p.returncode, 0, describe(p))
        return out

    def test_box_beam_mean_crush_force_in_the_folding_band(self):
        # The first 6.5 ms of the example (about 55 mm of crush, two and a half folds): the
        # tube's plastic work (internal + hourglass of part 1) over the mass's travel since it
        # met the tube (1 mm gap) is the mean crush force. C = 50, t = 1.5, sigma0 = 0.3 GPa.
        C, t, sigma0 = 50.0, 1.5, 0.3
        out = self.run_example("box_beam", "--endtime", "6.5")
        tube = [r for r in rows(out, "matsum.csv") if r["part"] == 1]
        work = tube[-1]["internal"] + tube[-1]["hourglass"]
        mass_node = max(r["node"] for r in rows(out, "nodout.csv"))
        travel = -[r for r in rows(out, "nodout.csv") if r["node"] == mass_node][-1]["dz"] - 1.0
        self.assertGreater(travel, 40.0)  # it did crush
        mean = work / travel
        wa = 9.56 * sigma0 * t ** (5 / 3) * C ** (1 / 3)  # 20.8 kN
        aj = 13.06 * sigma0 * t ** (5 / 3) * C ** (1 / 3)  # 28.4 kN
        self.assertGreater(mean, 0.8 * wa)
        self.assertLess(mean, 1.2 * aj)
        s = read_summary(out)
        self.assertLess(s["contact"]["max_penetration_ratio"], 0.3)
        ratios = [r["energy_ratio"] for r in rows(out, "glstat.csv")]
        self.assertLess(max(abs(r - 1.0) for r in ratios), 0.02, ratios)

    def test_cask_drop_impulse_energy_and_peak_deceleration(self):
        out = self.run_example("cask_drop")
        target = [r for r in rows(out, "rcforc.csv") if r["contact"] == 2 and r["side"] == 2]
        impulse = sum(0.5 * (a["fz"] + b["fz"]) * (b["time"] - a["time"])
                      for a, b in zip(target, target[1:]))
        matsum = [r for r in rows(out, "matsum.csv") if r["part"] in (1, 2)]
        p0 = sum(r["z_momentum"] for r in matsum if r["time"] == matsum[0]["time"])
        p1 = sum(r["z_momentum"] for r in matsum if r["time"] == matsum[-1]["time"])
        self.assertAlmostEqual(-impulse, p1 - p0, delta=0.01 * abs(p1 - p0))
        self.assertGreater(p1, 0.5 * abs(p0))  # it bounced
        ratios = [r["energy_ratio"] for r in rows(out, "glstat.csv")]
        self.assertLess(max(abs(r - 1.0) for r in ratios), 0.02, ratios)
        # Peak deceleration of the cask's centre of mass (contact force / mass) between the mean
        # over the impact and the plane-wave bound: the whole lid face striking at once,
        # F = rho c_p A v with c_p the dilatational speed (uniaxial strain).
        rho, E, nu, R, v = 7850.0, 2.0e11, 0.3, 0.1, math.sqrt(2 * 9.81 * 9.0)
        mass = abs(p0) / v
        self.assertAlmostEqual(mass, rho * math.pi * (R * R * 0.02 + (R * R - 0.08 ** 2) * 0.3),
                               delta=0.01 * mass)  # the 31.6 kg of the README
        peak = max(abs(r["fz"]) for r in target) / mass
        on = [r["time"] for r in target if r["fz"] != 0.0]
        mean = abs(p1 - p0) / (on[-1] - on[0]) / mass
        c_p = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho))
        bound = rho * c_p * math.pi * R * R * v / mass
        self.assertGreater(peak, mean)
        self.assertLess(peak, bound)

    def test_earth_penetrator_follows_young(self):
        # Young's equation (SAND97-2426, 1997; soil, V >= 61 m/s, SI form): the depth still to
        # go from speed V is D = 1.8e-5 S N (m/A)^0.7 (V - 30.5) K_s metres (m kg, A m^2,
        # V m/s; K_s = 0.27 m^0.4 for m < 27 kg; N = 0.18 sqrt(CRH - 0.25) + 0.56 for an
        # ogive). So the depth travelled between two times is 1.8e-5 S N (m/A)^0.7 K_s times
        # the speed lost. The first 7 ms (70 -> 47 m/s, through the first tie at 400 mm) in
        # two halves must give the same S within 10% (a constant force would put them 21%
        # apart, a force ~ V^2 18%; Crumple: 4%), each within Young's own scatter (20%) of the
        # S = 10.6 of the whole 25 ms run (706.7 mm; examples/earth_penetrator/README.md).
        S_WHOLE_RUN, v0, radius, crh = 10.6, 70.0, 0.025, 3.0
        out = self.run_example("earth_penetrator", "--endtime", "7")
        rod = [r for r in rows(out, "matsum.csv") if r["part"] == 1]
        mass = 4.0 * abs(rod[0]["z_momentum"]) / v0  # the whole rod, four quarters
        area = math.pi * radius ** 2
        nose = 0.18 * math.sqrt(crh - 0.25) + 0.56
        k = 1.8e-5 * nose * (mass / area) ** 0.7 * 0.27 * mass ** 0.4  # m per (m/s) per unit S
        tip = rows(out, "nodout.csv")

        def at(t):
            return min(tip, key=lambda r: abs(r["time"] - t))

        s = []
        for a, b in ((0.0, 3.5), (3.5, 7.0)):
            depth = (at(a)["z"] - at(b)["z"]) / 1000.0
            s.append(depth / (k * (at(b)["vz"] - at(a)["vz"])))
        self.assertLess(at(7.0)["z"], -400.0)  # past the first tied interface
        self.assertAlmostEqual(s[0] / s[1], 1.0, delta=0.1, msg=s)
        for value in s:
            self.assertAlmostEqual(value, S_WHOLE_RUN, delta=0.2 * S_WHOLE_RUN, msg=s)
        ratios = [r["energy_ratio"] for r in rows(out, "glstat.csv")]
        self.assertLess(max(abs(r - 1.0) for r in ratios), 0.02, ratios)


if __name__ == "__main__":
    main()
