"""examples/sign_post_in_soil: the 820 kg bumper at 8.94 m/s into a steel post in soil
(tools/sign_post_deck.py), run to 20 ms (gravity settles the soil in the first 9 ms, the bumper
meets the post at 11 ms):

  - momentum: the impulse of the bumper-post contact force on the bumper equals the bumper's
    change of momentum (matsum) within 2% (rcforc written every cycle: the force is a train of
    short spikes);
  - energy: the kinetic energy the bumper lost, plus the work of gravity, is found again in the
    post and the soil (kinetic, internal, hourglass) and the contact (penalty springs and
    their damping) within 5% of it (2.5% here: 0.05% of the total energy, whose ratio stays
    within 1%);
  - the post absorbs energy (internal > 0) and so does the soil; the post turns at ground
    level: the ground point moves toward +x more than the toe does.

Run as: python3 tests/verification/test_example_sign_post.py <crumple> <source dir>
"""

import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
import clitest  # noqa: E402
from clitest import TempDirTest, crumple, describe, main  # noqa: E402

POST, SOIL, BUMPER = 1.0, 2.0, 3.0
END = 0.02


def rows(folder, name):
    with open(os.path.join(folder, name), encoding="utf-8") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def parts_at(matsum, time):
    return {r["part"]: r for r in matsum if r["time"] == time}


class SignPostExample(TempDirTest):
    def test_bookkeeping_and_the_post_turning_in_the_soil(self):
        deck = clitest.example("sign_post_in_soil", "sign_post_in_soil.k")
        out = os.path.join(self.tmp, "post.out")
        p = crumple("run", deck, "-o", out, "-q", "--endtime", END, cwd=self.tmp, timeout=600)
        self.assertEqual(p.returncode, 0, describe(p))
        matsum = rows(out, "matsum.csv")
        first, last = parts_at(matsum, matsum[0]["time"]), parts_at(matsum, matsum[-1]["time"])
        self.check_momentum(out, first, last)
        self.check_energy(out, first, last)
        self.assertGreater(last[POST]["internal"], 0.01 * self.ke_lost)
        self.assertGreater(last[SOIL]["internal"], 0.01 * self.ke_lost)
        hist = rows(out, "nodout.csv")
        end = hist[-1]["time"]
        # The last sample is written twice (at the end time): keyed by node, kept once.
        at_end = {r["node"]: r for r in hist if r["time"] == end}
        toe, ground = at_end[3.0], at_end[403.0]
        self.assertGreater(ground["dx"], 10.0)  # mm
        self.assertGreater(ground["dx"] - toe["dx"], 10.0)

    def check_momentum(self, out, first, last):
        bumper = [r for r in rows(out, "rcforc.csv") if r["contact"] == 1 and r["side"] == 1]
        impulse = sum(0.5 * (a["fx"] + b["fx"]) * (b["time"] - a["time"])
                      for a, b in zip(bumper, bumper[1:]))
        change = last[BUMPER]["x_momentum"] - first[BUMPER]["x_momentum"]
        self.assertLess(change, -1.0)  # N s: the post slowed the bumper
        self.assertAlmostEqual(impulse, change, delta=0.02 * abs(change))

    def check_energy(self, out, first, last):
        glstat = rows(out, "glstat.csv")
        ratios = [r["energy_ratio"] for r in glstat]
        self.assertLess(max(abs(r - 1.0) for r in ratios), 0.01, ratios)
        self.ke_lost = first[BUMPER]["kinetic"] - last[BUMPER]["kinetic"]
        found = sum(last[part][k] for part in (POST, SOIL)
                    for k in ("kinetic", "internal", "hourglass"))
        found += glstat[-1]["contact"]
        self.assertAlmostEqual(found, self.ke_lost + glstat[-1]["external_work"],
                               delta=0.05 * self.ke_lost)


if __name__ == "__main__":
    main()
