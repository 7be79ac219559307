"""Perforation of an eroding plate (issues 13 and 15), through the command line on decks from
tools/perforation_decks.py.

The problem: a rigid blunt cylinder (radius 10 mm, 197 g) strikes a 12 mm steel plate
(Weldox 460 E, *MAT_JOHNSON_COOK with the Johnson-Cook fracture strain, the element eroding
at damage 1, *EOS_LINEAR_POLYNOMIAL C1 = K) at normal incidence, clamped at r = 50 mm; a
quarter model (SPCs on x = 0 and y = 0, the projectile's lateral motion and rotations held by
*MAT_RIGID CON1 4, CON2 7), *CONTACT_ERODING_SURFACE_TO_SURFACE (EROSOP 1, SFSA = SFSB = 5:
the penalty at its stability cap) between the projectile and the plate's inner part. Units
mm, ms, kg, GPa: m/s = mm/ms, J = kN mm.

Reference. Recht and Ipson (J. Appl. Mech. 30 (1963) 384) balance energy and momentum over
the perforation: above the ballistic limit v_bl the residual velocity is
    v_r = a (v_i^p - v_bl^p)^(1/p),
with p = 2 and a = m_p / (m_p + m_plug) for a plug carried away at the projectile's speed;
Lambert and Jonas's form lets a and p free, as Børvik et al. fit their tests of 12 mm
Weldox 460 E plates struck by 20 mm blunt projectiles (Int. J. Impact Eng. 27 (2002) 19;
ballistic limit about 185 m/s, quoted from memory of the paper). The test checks the model
against the relation, not the relation's constants against the experiment: the mesh, 1 mm
in the shear zone, is far too coarse for the shear band a plug forms in and overestimates
v_bl (twice finer, the residual velocity at 300 m/s rises from 103 to 192 m/s; too slow
for the suite). It checks:

  - 250 m/s does not perforate (nothing erodes; the projectile rebounds) and 300, 350, 400,
    500, 600 m/s do, each leaving at a steady velocity;
  - a, p, v_bl through the residual velocities at 300, 400 and 600 m/s put v_bl between
    250 and 300 m/s, and predict the residual velocities at 350 and 500 m/s within
    PREDICTION_TOLERANCE of the impact velocity;
  - from 350 to 600 m/s the residual velocities follow p = 2 (within 2 % of v_i) with a
    between m_p / (m_p + m_plug) (m_plug the plate's cylinder under the projectile) and 1;
  - energy: the ratio within [0.98, 1.02] at every glstat sample of every run, with the
    eroded elements' internal energy kept in the internal energy (as Crumple books it); that
    energy is more than 2 % of the initial energy in every perforating run, so a run that
    lost it would leave the band;
  - momentum: the projectile's change of momentum (matsum) equals the impulse of the
    contact force on it (rcforc, side 2, written every cycle, trapezoid) within 0.5 %.

Doubtful (docs/validation.md): the limit of this mesh, 250-300 m/s, is 35-60 % above the
measured one. The contact's compliance moves the residual velocities by 2-6 % (SFS 1
against 5) and, near the limit, by much more: at SFS 1, 86, 130, 99 m/s at 300 m/s for
10, 2.5, 1.25 mm deep nose elements (the penalty goes as face area squared over element
volume), against 1 % at 400 m/s and less at 500.

Figures (docs/validation.md, "Perforation") from `python3 tests/verification/
test_perforation.py build/release/crumple .`; about 130 s on one core, 85 of them the
500 and 600 m/s runs.

Run as: python3 tests/verification/test_perforation.py <crumple> <source dir>
"""

import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
import clitest  # noqa: E402
from clitest import crumple, describe, main, read_summary  # noqa: E402
from clitest import history_rows as rows  # noqa: E402

BELOW = 250.0  # m/s: does not perforate
FIT = (300.0, 400.0, 600.0)  # m/s: the runs a, p, v_bl are fitted to
PREDICTED = (350.0, 500.0)  # m/s: the runs they predict
PREDICTION_TOLERANCE = 0.02  # of the impact velocity


def end_time(v0):
    """ms: the plate's thickness and more at the residual velocity, and the plug gone."""
    return round(30.0 / v0 + 0.02, 4)


def recht_ipson(points):
    """a, p, v_bl of v_r = a (v_i^p - v_bl^p)^(1/p) through three (v_i, v_r) points: for a
    given p the first two fix A = a^p and B = v_bl^p; p is the root of the third's residual,
    by bisection on [1, 8]."""
    (v1, r1), (v2, r2), (v3, r3) = points

    def constants(p):
        A = (r1 ** p - r2 ** p) / (v1 ** p - v2 ** p)
        return A, v1 ** p - r1 ** p / A

    def residual(p):
        A, B = constants(p)
        return A * (v3 ** p - B) - r3 ** p

    lo, hi = 1.0, 8.0
    if residual(lo) * residual(hi) > 0.0:
        raise AssertionError(f"no p in [1, 8] through {points}")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if residual(lo) * residual(mid) <= 0.0:
            hi = mid
        else:
            lo = mid
    p = 0.5 * (lo + hi)
    A, B = constants(p)
    return A ** (1.0 / p), p, B ** (1.0 / p)


def residual_velocity(a, p, v_bl, v_i):
    return a * max(v_i ** p - v_bl ** p, 0.0) ** (1.0 / p)


class PerforationVerification(unittest.TestCase):
    runs = {}  # impact velocity -> results folder

    @classmethod
    def setUpClass(cls):
        cls._tmp = tempfile.TemporaryDirectory(prefix="crumple_perf_")
        decks = clitest.tools_module("perforation_decks")
        for v0 in (BELOW, *FIT, *PREDICTED):
            path = os.path.join(cls._tmp.name, f"v{v0:g}.k")
            with open(path, "w", encoding="utf-8") as f:
                f.write(decks.perforation(v0, end_time(v0)))
            out = os.path.join(cls._tmp.name, f"v{v0:g}.out")
            p = crumple("run", path, "-o", out, "-q", "--threads", "1", timeout=300)
            if p.returncode != 0:
                raise AssertionError(describe(p))
            cls.runs[v0] = out

    @classmethod
    def tearDownClass(cls):
        cls._tmp.cleanup()

    def projectile(self, v0):
        """The projectile's (time, velocity along -z) from matsum (part 1, the rigid body's
        momentum over its mass) and its mass."""
        m = [r for r in rows(self.runs[v0], "matsum.csv") if r["part"] == 1.0]
        mass = -m[0]["z_momentum"] / v0
        return [(r["time"], -r["z_momentum"] / mass) for r in m], mass

    def residual(self, v0, steady=True):
        v = self.projectile(v0)[0]
        # Steady: the contact has let go (the last two samples agree to 0.2 %).
        if steady:
            self.assertAlmostEqual(v[-1][1], v[-2][1], delta=0.002 * v0, msg=(v0, v[-4:]))
        return v[-1][1]

    def test_below_the_limit_the_projectile_rebounds(self):
        self.assertEqual(read_summary(self.runs[BELOW])["eroded_elements"], 0)
        # Still pushed back by the plate's spring-back at the end (not steady).
        self.assertLess(self.residual(BELOW, steady=False), 0.0)

    def test_recht_ipson_fit_predicts_the_other_runs(self):
        points = [(v, self.residual(v)) for v in FIT]
        for v, r in points:
            self.assertGreater(r, 0.0, (v, r))
        a, p, v_bl = recht_ipson(points)
        print(f"\nRecht-Ipson through {[(v, round(r, 1)) for v, r in points]}: "
              f"a = {a:.3f}, p = {p:.2f}, v_bl = {v_bl:.1f} m/s")
        self.assertGreater(v_bl, BELOW)
        self.assertLess(v_bl, FIT[0])
        for v in PREDICTED:
            measured, predicted = self.residual(v), residual_velocity(a, p, v_bl, v)
            print(f"  {v:g} m/s: residual {measured:.1f} m/s, predicted {predicted:.1f} m/s "
                  f"({(measured - predicted) / v:+.1%} of v_i)")
            self.assertAlmostEqual(measured, predicted, delta=PREDICTION_TOLERANCE * v)

    def test_away_from_the_limit_p_is_2_and_a_is_bounded_by_the_plug(self):
        # Recht and Ipson's constants for a plug that leaves with the projectile: p = 2,
        # a = m_p / (m_p + m_plug). Away from the limit (350-600 m/s) v_r^2 is linear in
        # v_i^2 with slope a^2, and a lies between the whole plug carried (m_plug the plate's
        # cylinder under the projectile, the quarter model's quarter) and none (a = 1): at 500
        # and 600 m/s much of the plug erodes.
        decks = clitest.tools_module("perforation_decks")
        pts = [(v, self.residual(v)) for v in sorted((*FIT, *PREDICTED)) if v >= 350.0]
        m_p = self.projectile(pts[0][0])[1]
        m_plug = decks.plug_mass()
        x = [v * v for v, _ in pts]
        y = [r * r for _, r in pts]
        mx, my = sum(x) / len(x), sum(y) / len(y)
        slope = (sum((a - mx) * (b - my) for a, b in zip(x, y)) /
                 sum((a - mx) ** 2 for a in x))
        a, v_bl = slope ** 0.5, (mx - my / slope) ** 0.5
        print(f"\np = 2 through {[(v, round(r, 1)) for v, r in pts]}: a = {a:.4f}, "
              f"v_bl = {v_bl:.1f} m/s; m_p / (m_p + m_plug) = {m_p / (m_p + m_plug):.4f}")
        self.assertGreater(a, m_p / (m_p + m_plug))
        self.assertLess(a, 1.0)
        for v, r in pts:
            self.assertAlmostEqual(r, residual_velocity(a, 2.0, v_bl, v), delta=0.02 * v)

    def test_energy_balance_with_the_eroded_energy(self):
        for v0, out in sorted(self.runs.items()):
            with self.subTest(v0=v0):
                ratios = [r["energy_ratio"] for r in rows(out, "glstat.csv")]
                s = read_summary(out)
                e0 = rows(out, "glstat.csv")[0]["total"]
                print(f"\n{v0:g} m/s: energy ratio {min(ratios):.4f}-{max(ratios):.4f}, "
                      f"{s['eroded_elements']} eroded, their internal energy "
                      f"{s['eroded_internal_energy'] / e0:.1%} of the initial, "
                      f"{s['wall_s']:.1f} s")
                self.assertGreaterEqual(min(ratios), 0.98)
                self.assertLessEqual(max(ratios), 1.02)
                if v0 > BELOW:
                    self.assertGreater(s["eroded_elements"], 0)
                    self.assertGreater(s["eroded_internal_energy"], 0.02 * e0)

    def test_momentum_change_is_the_contact_impulse(self):
        for v0, out in sorted(self.runs.items()):
            with self.subTest(v0=v0):
                v, mass = self.projectile(v0)
                change = mass * (v0 - v[-1][1])  # along +z: the plate pushes the projectile up
                f = [(r["time"], r["fz"]) for r in rows(out, "rcforc.csv") if r["side"] == 2.0]
                impulse = sum(0.5 * (f[i][1] + f[i + 1][1]) * (f[i + 1][0] - f[i][0])
                              for i in range(len(f) - 1))
                print(f"\n{v0:g} m/s: contact impulse / momentum change {impulse / change:.5f}")
                self.assertAlmostEqual(impulse / change, 1.0, delta=0.005)


if __name__ == "__main__":
    main()
