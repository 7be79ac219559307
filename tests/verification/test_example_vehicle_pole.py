"""examples/vehicle_pole: car5 (../shared/decks/car5_vehicle/main.k, the whole 0.05 s run, ~2 s)
into the rigid pole, post-processed by examples/vehicle_pole/pulse.py as a crash test reports it:

  - the rear node's (432) change of velocity equals the time integral of its sampled
    acceleration within 1% (0.17% here), and of its CFC 60 curve up to 10 ms before the end
    within 3% (1.7%: the filter keeps the area);
  - the impulse of the rigid walls on the car (pole and ground friction) equals the change of
    its momentum within 1% (0.12%);
  - the energy balance holds within 1% at the end; the CFC 60 peak is below the CFC 180 peak,
    below the unfiltered one, and above the mean deceleration of the run.

Skipped when ../shared/decks is absent. Run as:
python3 tests/verification/test_example_vehicle_pole.py <crumple> <source dir>
"""

import json
import os
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
import clitest  # noqa: E402
from clitest import TempDirTest, crumple, describe, main, shared_decks  # noqa: E402


class VehiclePoleExample(TempDirTest):
    def pulse(self):
        decks = shared_decks()
        if decks is None:
            raise unittest.SkipTest("../shared/decks is absent")
        out = os.path.join(self.tmp, "car5.out")
        p = crumple("run", os.path.join(decks, "car5_vehicle", "main.k"), "-o", out, "-q",
                    cwd=self.tmp, timeout=300)
        self.assertEqual(p.returncode, 0, describe(p))
        script = os.path.join(clitest.SOURCE_DIR, "examples", "vehicle_pole", "pulse.py")
        q = subprocess.run([sys.executable, script, out, "--json"], capture_output=True,
                           text=True, timeout=120)
        self.assertEqual(q.returncode, 0, q.stderr)
        self.assertTrue(os.path.exists(os.path.join(out, "pulse.csv")))
        return json.loads(q.stdout)

    def test_pulse_and_balances(self):
        r = self.pulse()
        dv = r["delta_v"]
        self.assertGreater(dv, 1000.0)  # the car slows by more than 1 m/s (mm/s)
        self.assertAlmostEqual(r["integral_raw"], dv, delta=0.01 * dv)
        settled = r["delta_v_settled"]
        self.assertAlmostEqual(r["integral_cfc60_settled"], settled, delta=0.03 * settled)
        change = r["momentum_change"]
        self.assertGreater(change, 0.0)  # the car moves in -x: the walls push +x
        self.assertAlmostEqual(r["wall_impulse"], change, delta=0.01 * change)
        self.assertAlmostEqual(r["energy"]["energy_ratio"], 1.0, delta=0.01)
        cfc60, cfc180, raw = (r[k][0] for k in ("peak_cfc60_g", "peak_cfc180_g", "peak_raw_g"))
        mean_g = dv / r["end_time"] / 9810.0
        self.assertLess(cfc60, cfc180)
        self.assertLess(cfc180, raw)
        self.assertGreater(cfc60, mean_g)


if __name__ == "__main__":
    main()
