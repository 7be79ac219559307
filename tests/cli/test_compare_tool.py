#!/usr/bin/env python3
"""The crumple_compare package (python/crumple_compare, docs/validation.md) without the
command: LS-DYNA ASCII readers on the bolted joint's R13 files (when ../shared is present) and
on hand-made files (tests/data/compare), the SAE J211 CFC filter against its analytic response
and J211's corridor, and the ISO/TS 18571 ratings on curves with answers derived by hand."""

import math
import os
import sys
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402

try:
    import numpy as np
except ImportError:  # the tests below are skipped, said why
    np = None


def setUpModule():
    if np is None:
        raise unittest.SkipTest(f"{sys.executable} has no numpy (tools/setup.sh installs it)")
    sys.path.insert(0, os.path.join(clitest.SOURCE_DIR, "python"))


def data(*parts):
    return os.path.join(clitest.SOURCE_DIR, "tests", "data", "compare", *parts)


def at(curve, t):
    return float(np.interp(t, curve.t, curve.y))


class BoltedJointFiles(unittest.TestCase):
    """LS-DYNA R13's own files; the values are read off the files by eye."""

    @classmethod
    def setUpClass(cls):
        decks = clitest.shared_decks()
        folder = decks and os.path.join(decks, "bolted_joint_lsdyna", "Bolt_B_Explicit")
        if not folder or not os.path.isdir(folder):
            raise unittest.SkipTest("../shared/decks/bolted_joint_lsdyna is not present")
        from crumple_compare import lsdyna
        cls.c = lsdyna.read_folder(folder)

    def test_glstat(self):
        c = self.c
        self.assertEqual(len(c["glstat.kinetic"].t), 1001)
        self.assertAlmostEqual(at(c["glstat.kinetic"], 4.87301e-3), 9.93442e-6, delta=1e-11)
        self.assertAlmostEqual(c["glstat.internal"].y[1], 1.36945e-5, delta=1e-11)
        self.assertEqual(c["glstat.contact"].y[-1], 22.9217)  # sliding interface energy
        self.assertEqual(c["glstat.external_work"].y[-1], 23.2649)
        self.assertEqual(c["glstat.energy_ratio"].y[-1], 3.41802)
        self.assertEqual(c["glstat.dt"].y[0], 2.11870e-4)
        self.assertEqual(c["glstat.total"].t[-1], 4.99989)

    def test_matsum_parts(self):
        parts = {k.split(".")[1] for k in self.c if k.startswith("matsum.")}
        self.assertEqual(parts, {f"part{p}" for p in (10, 20, 100, 110, 120, 101, 310)})
        self.assertEqual(self.c["matsum.part100.internal"].y[-1], 34.151)
        self.assertEqual(self.c["matsum.part10.x_momentum"].y[-1], 0.0823)

    def test_nodout_touching_numbers(self):
        # ' 1100002 ... 2.74317E-05-7.90000E+00 ...': the y coordinate touches the x one.
        self.assertEqual(self.c["nodout.node1100002.y"].y[0], -7.9)
        self.assertEqual(self.c["nodout.node1100002.x"].y[0], 2.74317e-5)
        self.assertAlmostEqual(at(self.c["nodout.node1100002.vy"], 4.8730101e-3), 3.25501e-2)
        self.assertAlmostEqual(at(self.c["nodout.node1200000.ay"], 9.9578902e-3), -1.16459e1)
        self.assertIn("nodout.node1200000.rz", self.c)  # the rotation block

    def test_rcforc_and_sleout(self):
        c = self.c
        self.assertAlmostEqual(at(c["rcforc.contact2.slave.fy"], 1.99490), -19.1012)
        self.assertNotIn("rcforc.contact10001.slave.fx", c)  # single surface: undefined
        self.assertEqual(c["sleout.contact10001.slave"].y[-1], 22.22)
        self.assertAlmostEqual(c["sleout.contact10013.energy"].y[-1], 0.6972)
        self.assertEqual(c["sleout.total"].y[-1], 22.92167)
        self.assertEqual(c["sleout.friction"].y[-1], 23.77826)


class HandMadeFiles(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        from crumple_compare import crumple_csv, lsdyna
        cls.lsdyna, cls.crumple_csv = lsdyna, crumple_csv
        cls.c = lsdyna.read_folder(data("lsdyna"))

    def test_every_file(self):
        c = self.c
        self.assertEqual(list(c["glstat.kinetic"].y), [100.0, 60.0])
        self.assertEqual(c["glstat.hourglass"].y[-1], 1.0)
        self.assertEqual(list(c["matsum.part7.z_momentum"].y), [-1.0, -0.75])
        self.assertEqual(c["nodout.node12.dx"].y[-1], -1e-3)  # touches the id
        self.assertEqual(c["nodout.node12.ax"].y[-1], 1e4)
        self.assertEqual(c["rcforc.contact3.master.fx"].y[-1], -1500.0)
        self.assertEqual(c["sleout.contact3.energy"].y[-1], 4.0)
        self.assertEqual(c["sleout.contact3.friction"].y[-1], 0.5)
        self.assertEqual(list(c["rwforc.wall1.fn"].y), [0.0, 500.0])
        self.assertEqual(list(c["rwforc.wall1.fz"].t), [0.0, 1e-4])
        self.assertEqual(c["secforc.section5.fy"].y[-1], -10.0)
        self.assertEqual(c["secforc.section5.mz"].y[-1], 3.0)
        self.assertEqual(c["secforc.section5.area"].t[-1], 1e-4)

    def test_rwforc_blocks(self):
        c = self.lsdyna.read_rwforc(data("rwforc_blocks", "rwforc"))
        self.assertEqual(list(c["rwforc.wall2.fn"].t), [1e-4, 2e-4])
        self.assertEqual(list(c["rwforc.wall2.fy"].y), [700.0, 800.0])

    def test_errors_name_file_and_line(self):
        from crumple_compare.errors import CompareError
        cases = [(lambda: self.lsdyna.read_nodout(data("bad", "nodout")), "nodout:7: node 12"),
                 (lambda: self.lsdyna.read_glstat(data("notglstat", "glstat")),
                  "glstat: not an LS-DYNA glstat file"),
                 (lambda: self.crumple_csv.read_folder(data("crumple_bad")),
                  "matsum.csv:3: not a number"),
                 (lambda: self.lsdyna.read_folder(data("crumple")), "no LS-DYNA ASCII file")]
        for call, message in cases:
            with self.assertRaises(CompareError) as e:
                call()
            self.assertIn(message, str(e.exception))

    def test_crumple_columns_map_to_lsdyna_keys(self):
        cru = self.crumple_csv.read_folder(data("crumple"))
        for key in ("glstat.kinetic", "glstat.internal", "glstat.hourglass", "glstat.total",
                    "matsum.part7.kinetic", "matsum.part7.z_momentum"):
            self.assertEqual(list(cru[key].y), list(self.c[key].y), key)


class CfcFilter(unittest.TestCase):
    """SAE J211-1 Appendix C filter: gain 1 at DC, the analytic response of a double pass of
    the prewarped 2-pole Butterworth, J211's corridor, no phase."""

    @classmethod
    def setUpClass(cls):
        from crumple_compare import signals
        cls.s = signals

    def gain(self, cfc, f, fs=20000.0):
        t = np.arange(0, 0.5, 1 / fs)
        y = self.s.cfc_filter(np.sin(2 * math.pi * f * t), 1 / fs, cfc)
        mid = slice(len(t) // 4, 3 * len(t) // 4)  # away from the ends
        return np.max(np.abs(y[mid]))

    def test_dc_gain_is_one(self):
        for cfc in self.s.CFC_CLASSES:
            y = self.s.cfc_filter(np.full(500, 3.5), 1e-4, cfc)
            np.testing.assert_allclose(y, 3.5, rtol=1e-12)
            line = np.linspace(-1, 2, 500)  # and a straight line passes unchanged
            np.testing.assert_allclose(self.s.cfc_filter(line, 1e-4, cfc), line, atol=1e-9)

    def test_response_and_j211_corridor(self):
        fs = 20000.0
        for cfc in self.s.CFC_CLASSES:
            wa = math.tan(math.pi * self.s.CFC_DESIGN_FACTOR * cfc / fs)
            for ratio in (0.5, 1.0, 1.65, 3.0, 6.0):
                f = ratio * cfc
                expected = 1 / (1 + (math.tan(math.pi * f / fs) / wa) ** 4)
                self.assertAlmostEqual(self.gain(cfc, f), expected, delta=2e-3,
                                       msg=f"CFC {cfc}, f = {f}")
            db = lambda f: 20 * math.log10(self.gain(cfc, f))  # noqa: E731
            self.assertTrue(-1.0 <= db(cfc) <= 0.5, db(cfc))           # F_H
            self.assertTrue(-4.0 <= db(1.65 * cfc) <= 0.5, db(1.65 * cfc))  # F_N
            # Beyond F_N the corridor's upper edge falls 9 dB per octave.
            self.assertLess(db(6 * cfc), 0.5 - 9 * math.log2(6 / 1.65))

    def test_phaseless(self):
        t = np.arange(1001) * 1e-4
        pulse = np.exp(-((t - 0.05) / 0.004) ** 2)
        y = self.s.cfc_filter(pulse, 1e-4, 60)
        np.testing.assert_allclose(y[:501], y[500:][::-1], atol=1e-9)  # symmetric about 0.05
        self.assertEqual(int(np.argmax(y)), 500)
        self.assertLess(y.max(), 0.99)  # and it did filter

    def test_refuses_coarse_sampling(self):
        from crumple_compare.errors import CompareError
        with self.assertRaises(CompareError):
            self.s.cfc_filter(np.zeros(100), 1e-3, 1000)


class Iso18571(unittest.TestCase):
    """Ratings with answers derived by hand (docs/validation.md)."""

    @classmethod
    def setUpClass(cls):
        from crumple_compare import iso18571
        cls.iso = iso18571
        cls.t = np.linspace(0.0, 1.0, 1001)
        cls.dt = cls.t[1]
        cls.pulse = lambda self, c=0.4, w=0.05: np.exp(-((self.t - c) / w) ** 2)

    def test_identical_curves_score_one(self):
        for y in (self.pulse(), np.sin(7 * self.t), self.t ** 2):
            r = self.iso.rate(y, y.copy(), self.dt)
            self.assertEqual((r["R"], r["corridor"], r["phase"], r["magnitude"], r["slope"]),
                             (1.0, 1.0, 1.0, 1.0, 1.0))
            self.assertEqual(r["grade"], "excellent")

    def test_corridor_of_scaled_ramp(self):
        # T = t, C = s t on [0, 1]: |C - T| = (s - 1) t against the inner 0.05 and outer 0.5.
        # s = 1.2: 1 up to t = 0.25, then ((0.5 - 0.2 t) / 0.45)^2: Z = 0.25 + 19/36 = 7/9.
        # s = 1.5: 1 up to t = 0.1, then ((1 - t) / 0.9)^2: Z = 0.1 + 0.3 = 0.4.
        self.assertAlmostEqual(self.iso.corridor(self.t, 1.2 * self.t), 7 / 9, delta=2e-4)
        self.assertAlmostEqual(self.iso.corridor(self.t, 1.5 * self.t), 0.4, delta=2e-4)
        self.assertEqual(self.iso.corridor(self.t, 3.0 * self.t + 1), 0.0)

    def test_phase_of_shifted_pulse(self):
        # A pulse k samples late: the best shift is k, EP = (0.2 N - k) / (0.2 N); after the
        # shift the curves are the same, so magnitude and slope are 1.
        n = len(self.t)
        for k in (0, 10, 50, 150, -80):
            c = self.pulse(c=0.4 + k * self.dt)
            r = self.iso.rate(self.pulse(), c, self.dt)
            self.assertAlmostEqual(r["lag"], k * self.dt, delta=1e-12)
            self.assertAlmostEqual(r["phase"], max(0.0, (0.2 * n - abs(k)) / (0.2 * n)), 12)
            self.assertAlmostEqual(r["magnitude"], 1.0, 9)
            self.assertAlmostEqual(r["slope"], 1.0, 9)
        self.assertEqual(self.iso.phase(201, n), 0.0)  # beyond 0.2 N = 200.2 samples

    def test_magnitude_of_offset_and_slope_of_ramp(self):
        # Constant 1 against 1.2: no warping helps, eps = 0.2, EM = (0.5 - 0.2) / 0.5 = 0.6.
        self.assertAlmostEqual(self.iso.magnitude(np.ones(200), np.full(200, 1.2)), 0.6, 12)
        # Ramps of slope 1 and 1.5: eps = 0.5, ES = (2 - 0.5) / 2 = 0.75.
        self.assertAlmostEqual(self.iso.slope(self.t, 1.5 * self.t, self.dt), 0.75, 12)

    def test_total_is_the_weighted_sum(self):
        r = self.iso.rate(self.pulse(), 1.3 * self.pulse(c=0.42), self.dt)
        self.assertAlmostEqual(r["R"], 0.4 * r["corridor"] + 0.2 * (r["phase"] + r["magnitude"]
                                                                   + r["slope"]), 14)

    def test_monotone_degradation(self):
        scaled = [self.iso.rate(self.pulse(), s * self.pulse(), self.dt)["R"]
                  for s in (1.0, 1.1, 1.25, 1.5, 2.0, 3.0)]
        shifted = [self.iso.rate(self.pulse(), self.pulse(c=0.4 + d), self.dt)["R"]
                   for d in (0.0, 0.01, 0.03, 0.06, 0.1)]
        for seq in (scaled, shifted):
            self.assertTrue(all(a > b for a, b in zip(seq, seq[1:])), seq)
        self.assertEqual([self.iso.grade(x) for x in (0.95, 0.9, 0.6, 0.5)],
                         ["excellent", "good", "fair", "poor"])


if __name__ == "__main__":
    clitest.main()
