#!/usr/bin/env python3
"""Writes the example decks under examples/ (run from anywhere: paths are relative to this file).

  taylor_bar/taylor_bar.k   copper rod on a rigid wall (Kamoulakos 1990; reference/verification.md #2)
  bar_impact/bar_impact.k   elastic bar striking a stonewall (reference #1: sigma = rho c0 v0, 2L/c0)
  sign_post_in_soil/sign_post_in_soil.k   car bumper at 20 mph into a steel post in soil
                                          (tools/sign_post_deck.py)
  box_beam/box_beam.k       square steel tube crushed axially by a 60 kg mass (reference #5)
  cask_drop/cask_drop.k     steel cask with a tied lid, 9 m drop onto a rigid target
  earth_penetrator/earth_penetrator.k  rigid ogive-nosed rod at 70 m/s into a soil target of
                            tied blocks (Young, SAND97-2426)

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
import sign_post_deck  # noqa: E402
from deckgen import (Mesh, block, node_set, quarter_annulus, quarter_cylinder,  # noqa: E402
                     quarter_ogive_rod)

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
    title = "cask with a tied lid dropped on a rigid target (symmetric two-surface contact)"
    return text.replace(title, "cask with a tied lid, 9 m drop (13.29 m/s) onto a rigid target "
                        "(symmetric two-surface contact; m, kg, s, Pa)", 1)


# The earth penetrator (mm, ms, kg, GPa): a steel rod of diameter 50 mm with a 3-CRH tangent
# ogive nose and a 250 mm shank, modelled rigid (Young's equation is for penetrators that do
# not deform), into a soil target. Quarter model: symmetry on x = 0 and y = 0.
PENETRATOR = {"radius": 25.0, "shank": 250.0, "crh": 3.0, "tip_radius": 4.0}
# Target radii: a pilot hole of 8 mm on the axis (a Lagrangian mesh cannot open a hole from a
# line of nodes; the nose's blunted tip, 4 mm, enters it), fine near the path, graded outward.
TARGET_RADII = [8.0, 13.0, 19.0, 26.0, 34.0, 44.0, 56.0, 72.0, 93.0, 120.0, 155.0, 200.0, 260.0,
                330.0, 400.0]
# The target's blocks, top down: (bottom z, layers); each is meshed alone and tied to the next.
TARGET_BLOCKS = [(-400.0, 20), (-900.0, 20), (-1500.0, 20)]

# A generic stiff soil in *MAT_SOIL_AND_FOAM (RO, G, KUN, A0, A1, A2, PC; pressure against
# ln(V/V0)): density 1800 kg/m^3, shear modulus 100 MPa, yield J2 = A0 + A2 p^2: sqrt(J2) =
# 3.2 MPa at no pressure (A0 = 1e-5 GPa^2) rising as sqrt(3 J2) = 1.2 p (a friction angle of
# 30 degrees), no tension; a compaction curve of the order of the dry-sand data used with this
# law (tens of MPa at 15-25% compaction). Not calibrated to an S-number: see
# examples/earth_penetrator/README.md.
SAND = """*MAT_SOIL_AND_FOAM
$      mid        ro         g       kun        a0        a1        a2        pc
         2    1.8e-6       0.1       1.2    1.0e-5       0.0      0.48       0.0
$      vcr       ref
       0.0       0.0
$     eps1      eps2      eps3      eps4      eps5      eps6      eps7      eps8
       0.0     -0.05      -0.1     -0.15      -0.2     -0.25      -0.3
$     eps9     eps10

$       p1        p2        p3        p4        p5        p6        p7        p8
       0.0     0.002     0.006     0.014      0.03      0.06      0.12
$       p9       p10

"""


def _soil_target(m: Mesh, layer_scale: float) -> tuple[list[int], str]:
    """The target's blocks (parts 2, 3, ...), each tied to the one above by a
    *CONTACT_TIED_SURFACE_TO_SURFACE (the seed's tied slide surfaces), and its boundary
    conditions: symmetry planes, the base fixed, the outer radius held laterally."""
    top, ties, parts = 0.0, [], []
    for b, (bottom, layers) in enumerate(TARGET_BLOCKS):
        n = max(2, round(layers * layer_scale))
        quarter_annulus(m, 2 + b, TARGET_RADII, 8, [top + (bottom - top) * k / n
                                                    for k in range(n, -1, -1)])
        parts.append(2 + b)
        if b > 0:
            ties.append(f"*CONTACT_TIED_SURFACE_TO_SURFACE_ID\n{10 + b:10d}\n"
                        f"{2 + b:10d}{1 + b:10d}         3         3\n")
        top = bottom
    eps, r_out, z_base = 1e-6, TARGET_RADII[-1], TARGET_BLOCKS[-1][0]
    soil = [i + 1 for i in range(len(m.nodes))]
    on = lambda pred: [i for i in soil if pred(*m.nodes[i - 1])]  # noqa: E731
    spc = (node_set(11, on(lambda x, y, z: abs(x) < eps), "symmetry x = 0")
           + node_set(12, on(lambda x, y, z: abs(y) < eps), "symmetry y = 0")
           + node_set(13, on(lambda x, y, z: abs(z - z_base) < eps), "base")
           + node_set(14, on(lambda x, y, z: math.hypot(x, y) > r_out - eps), "outer radius")
           + "*BOUNDARY_SPC_SET\n        11         0         1         0         0\n"
           + "        12         0         0         1         0\n"
           + "        13         0         1         1         1\n"
           + "        14         0         1         1         0\n")
    return parts, "".join(ties) + spc


def earth_penetrator(v0: float = 70.0, end: float = 25.0, layer_scale: float = 1.0) -> str:
    """Units mm, ms, kg, GPa (m/s = mm/ms). The rigid penetrator (part 1) starts 1 mm above the
    target's surface (z = 0) at v0 down the axis; symmetric penalty contact between it and the
    soil blocks; its tip's depth in nodout. layer_scale scales the targets' layers (a coarser
    mesh for the test). Stiffness hourglass control (IHQ 5) on the soil: the viscous form
    took 40% of the soil's energy as hourglass work and let the penetrator through."""
    m = Mesh()
    parts, target_text = _soil_target(m, layer_scale)
    first = len(m.nodes) + 1
    quarter_ogive_rod(m, 1, n_core=2, n_ring=2, n_nose=8, n_shank=5, z_tip=1.0, **PENETRATOR)
    rod = list(range(first, len(m.nodes) + 1))
    tip = min(rod, key=lambda i: (m.nodes[i - 1][2], m.nodes[i - 1][0] + m.nodes[i - 1][1]))
    part_list = "".join(f"{p:10d}" for p in parts)
    return f"""*KEYWORD
*TITLE
earth penetrator: rigid 3-CRH ogive rod at {v0:g} m/s into tied soil blocks (mm, ms, kg, GPa)
*CONTROL_TERMINATION
{end:10.4g}
*CONTROL_HOURGLASS
$      ihq        qh
         5       0.1
*DATABASE_GLSTAT
      0.05
*DATABASE_MATSUM
      0.05
*DATABASE_NODOUT
      0.02
*DATABASE_RCFORC
      0.02
*DATABASE_BINARY_D3PLOT
       1.0
*DATABASE_HISTORY_NODE
{tip:10d}
*PART
penetrator (rigid steel)
         1         1         1
""" + "".join(f"soil block {p - 1}\n{p:10d}         1         2\n" for p in parts) + \
        f"""*SECTION_SOLID
         1         1
*MAT_RIGID
$      mid        ro         e        pr
         1   7.85e-6     210.0       0.3
$      cmo      con1      con2
       1.0         4         7
{SAND}*SET_PART_LIST
         1
{part_list}
*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID
         1
         1         1         2         3
{target_text}*INITIAL_VELOCITY_NODE
{contact_decks._velocities(rod, (0.0, 0.0, -v0))}{m.keyword_text()}*END
"""


def decks() -> dict[str, str]:
    """Every committed example deck's text keyed by its path under examples/."""
    return {"taylor_bar/taylor_bar.k": taylor_bar(), "bar_impact/bar_impact.k": bar_impact(),
            "box_beam/box_beam.k": box_beam(), "cask_drop/cask_drop.k": cask_drop(),
            "earth_penetrator/earth_penetrator.k": earth_penetrator(),
            "sign_post_in_soil/sign_post_in_soil.k": sign_post_deck.deck()}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--box-beam-refined", type=pathlib.Path, metavar="OUT.k")
    a = ap.parse_args()
    if a.box_beam_refined:
        a.box_beam_refined.write_text(box_beam(refined=True))
        return
    for rel, text in decks().items():
        path = ROOT / "examples" / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        print(f"wrote {path.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
