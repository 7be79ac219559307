#!/usr/bin/env python3
"""Writes the example decks under examples/ (run from anywhere: paths are relative to this file).

  taylor_bar/taylor_bar.k   copper rod on a rigid wall (Kamoulakos 1990; reference/verification.md #2)
  bar_impact/bar_impact.k   elastic bar striking a stonewall (reference #1: sigma = rho c0 v0, 2L/c0)
  box_beam/box_beam.k       square steel tube crushed axially by a 60 kg mass (reference #5)
  cask_drop/cask_drop.k     steel cask with a tied lid, 9 m drop onto a rigid target

  python3 tools/make_examples.py                          writes them all
  python3 tools/make_examples.py --box-beam-refined OUT.k the box beam at 2x the mesh in each
                                                          direction (not committed: 6400 shells)
"""

from __future__ import annotations

import argparse
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import contact_decks  # noqa: E402
from deckgen import Mesh, block, node_set, quarter_cylinder  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent


def taylor_bar(n_core: int = 6, n_ring: int = 4, n_axial: int = 60) -> str:
    """Units: mm, ms, kg, kN, GPa. Quarter model with symmetry on x = 0 and y = 0; the rod
    moves in -z onto a frictionless stonewall at z = 0."""
    mesh = Mesh()
    quarter_cylinder(mesh, 1, radius=3.2, length=32.4, n_core=n_core, n_ring=n_ring, n_axial=n_axial)
    eps = 1e-9
    sym_x = mesh.node_ids(lambda x, y, z: abs(x) < eps)
    sym_y = mesh.node_ids(lambda x, y, z: abs(y) < eps)
    axis_top = mesh.node_ids(lambda x, y, z: abs(x) < eps and abs(y) < eps and abs(z - 32.4) < eps)
    axis_bottom = mesh.node_ids(lambda x, y, z: abs(x) < eps and abs(y) < eps and abs(z) < eps)
    return f"""*KEYWORD
*TITLE
Taylor bar: copper rod, 227 m/s onto a rigid wall (units mm, ms, kg, GPa)
$ Kamoulakos (1990); expected final length ~21.47 mm, footprint radius ~7.1 mm at 80 us.
*CONTROL_TERMINATION
$   endtim
      0.08
*CONTROL_TIMESTEP
$   dtinit    tssfac
       0.0       0.9
*CONTROL_HOURGLASS
$      ihq        qh
         2       0.1
*CONTROL_ENERGY
$     hgen      rwen
         2         2
*DATABASE_GLSTAT
    0.0008
*DATABASE_MATSUM
    0.0008
*DATABASE_NODOUT
    0.0008
*DATABASE_RWFORC
    0.0008
*DATABASE_BINARY_D3PLOT
     0.004
*DATABASE_HISTORY_NODE
{axis_top[0]:10d}{axis_bottom[0]:10d}
*PART
copper rod
$      pid     secid       mid
         1         1         1
*SECTION_SOLID
$    secid    elform
         1         1
*MAT_PIECEWISE_LINEAR_PLASTICITY
$      mid        ro         e        pr      sigy      etan
         1   8.93e-6     117.0      0.35       0.4       0.1
*INITIAL_VELOCITY
$     nsid
         0
$       vx        vy        vz
       0.0       0.0    -227.0
*RIGIDWALL_PLANAR
$     nsid
         0
$       xt        yt        zt        xh        yh        zh      fric
       0.0       0.0       0.0       0.0       0.0       1.0       0.0
{node_set(1, sym_x, "symmetry x = 0")}*BOUNDARY_SPC_SET
$     nsid       cid      dofx      dofy      dofz
         1         0         1         0         0
{node_set(2, sym_y, "symmetry y = 0")}*BOUNDARY_SPC_SET
         2         0         0         1         0
{mesh.keyword_text()}*END
"""


def bar_impact(n_cross: int = 2, n_long: int = 100) -> str:
    """Elastic steel bar, 100 mm long, 10 mm square, at 10 m/s onto a stonewall, laterally
    free (uniaxial stress). Poisson's ratio 0 so the 1D answers hold exactly: c0 = sqrt(E/rho),
    wall stress rho c0 v0, contact time 2L/c0, rebound at v0. Units mm, ms, kg, GPa."""
    mesh = Mesh()
    block(mesh, 1, (0.0, 0.0, 0.0), (10.0, 10.0, 100.0), (n_cross, n_cross, n_long))
    rho, E, v0, L = 7.85e-6, 210.0, 10.0, 100.0
    c0 = math.sqrt(E / rho)
    t_contact = 2 * L / c0
    end = 1.5 * t_contact
    tip = mesh.node_ids(lambda x, y, z: abs(z) < 1e-9)
    top = mesh.node_ids(lambda x, y, z: abs(z - L) < 1e-9)
    return f"""*KEYWORD
*TITLE
Elastic bar on a stonewall (units mm, ms, kg, GPa): sigma = rho c0 v0, contact 2L/c0
*CONTROL_TERMINATION
{end:10.6f}
*CONTROL_TIMESTEP
       0.0       0.9
*DATABASE_GLSTAT
{end / 400:10.7f}
*DATABASE_NODOUT
{end / 400:10.7f}
*DATABASE_RWFORC
{end / 400:10.7f}
*DATABASE_BINARY_D3PLOT
{end / 10:10.7f}
*DATABASE_HISTORY_NODE
{tip[0]:10d}{top[0]:10d}
*PART
steel bar
         1         1         1
*SECTION_SOLID
         1         1
*MAT_ELASTIC
$      mid        ro         e        pr
         1  {rho:8.3g}     {E:5.1f}       0.0
*INITIAL_VELOCITY
         0
       0.0       0.0     {-v0:5.1f}
*RIGIDWALL_PLANAR
         0
       0.0       0.0       0.0       0.0       0.0       1.0       0.0
{mesh.keyword_text()}*END
"""


# The box beam: DYNA3D's box-beam buckling problem in the form of Abramowicz & Jones's drop
# tests (Int. J. Impact Eng. 2(2):179-208, 1984): a square mild-steel tube, side C = 50 mm,
# wall t = 1.5 mm (C/t = 33, their tubes had 30.25 and 32.18), 200 mm long.
BOX_BEAM = {"side": 50.0, "thickness": 1.5, "length": 200.0, "speed": 10.0, "impact_mass": 60.0,
            "trigger": 0.1}


def box_beam(refined: bool = False, end: float = 25.0) -> str:
    """Units mm, ms, kg, GPa (kN, J). The tube rides on a 60 kg rigid mass at 10 m/s (3000 J)
    into a fixed rigid plate, with a bead trigger (10% of t) at its struck foot and automatic
    single-surface contact; shells of 5 mm (2.5 mm refined, 2x in each direction)."""
    text = contact_decks.tube_crush(size=2.5 if refined else 5.0, end=end, **BOX_BEAM)
    return text.replace("square steel tube axial crush (single-surface contact)",
                        "DYNA3D box beam: square steel tube, 60 kg at 10 m/s onto a rigid plate "
                        "(mm, ms, kg, GPa)", 1)


def cask_drop(end: float = 4.0e-4) -> str:
    """Units m, kg, s, Pa (SI, as the contact test decks). An elastic steel cask (outer radius
    0.1 m, wall 0.02 m, 0.32 m tall with its lid, 31.6 kg) dropped lid first from 9 m (the
    regulatory drop height for transport packages, IAEA SSR-6: v = sqrt(2 g h) = 13.29 m/s) onto
    a fixed rigid target; lid tied to the body, symmetric two-surface penalty contact with the
    target; fully integrated hexes (ELFORM 2), twice the test deck's divisions."""
    v = math.sqrt(2 * 9.81 * 9.0)
    text = contact_decks.cask_drop(v, end=end, n_theta=48, refine=2, elform=2)
    return text.replace("cask with a tied lid dropped on a rigid target (symmetric two-surface contact)",
                        "cask with a tied lid, 9 m drop (13.29 m/s) onto a rigid target "
                        "(symmetric two-surface contact; m, kg, s, Pa)", 1)


def example_decks() -> dict[str, str]:
    """Every committed example deck by its path under examples/."""
    return {"taylor_bar/taylor_bar.k": taylor_bar(), "bar_impact/bar_impact.k": bar_impact(),
            "box_beam/box_beam.k": box_beam(), "cask_drop/cask_drop.k": cask_drop()}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--box-beam-refined", type=pathlib.Path, metavar="OUT.k")
    a = ap.parse_args()
    if a.box_beam_refined:
        a.box_beam_refined.write_text(box_beam(refined=True))
        return
    for rel, text in example_decks().items():
        path = ROOT / "examples" / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        print(f"wrote {path.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
