#!/usr/bin/env python3
"""Decks for the contact verification problems (../shared/reference/verification.md) and the
contact benchmark. Each function returns deck text; `main` writes one to a file:

  python3 tools/contact_decks.py blocks OUT.k [--kind SURFACE_TO_SURFACE]
  python3 tools/contact_decks.py sliding OUT.k [--mu 0.3]
  python3 tools/contact_decks.py hertz OUT.k [--n 16]
  python3 tools/contact_decks.py tube OUT.k [--size 2.5] [--length 120]
  python3 tools/contact_decks.py tied OUT.k
  python3 tools/contact_decks.py cask OUT.k
  python3 tools/contact_decks.py eroding tests/data/decks/contact_eroding.k

(`eroding`: the rank determinism and restart case of eroding contact, eroding_layers with a
finer target whose lower layer erodes under the block, element by element.)

Units: SI (m, kg, s, Pa) for blocks, sliding and hertz; mm, ms, kg, GPa for the tube.
"""

from __future__ import annotations

import argparse
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from deckgen import Mesh, block, grid_solids, node_set, shell_grid  # noqa: E402


def _velocities(ids, v) -> str:
    return "".join(f"{i:10d}{v[0]:10.4g}{v[1]:10.4g}{v[2]:10.4g}\n" for i in ids)


def colliding_blocks(kind: str = "SURFACE_TO_SURFACE", n1: int = 4, n2: int = 5,
                     offset: float = 0.001, v: float = 10.0, end: float = 8e-5,
                     gap: float = 0.0005) -> str:
    """Two elastic steel cubes (10 mm, meshes n1^3 and n2^3, the second shifted sideways by
    `offset`) flying at each other at +-v along z across a gap (negative: the second starts
    inside the first)."""
    m = Mesh()
    a = sorted(block(m, 1, (0, 0, 0), (0.01, 0.01, 0.01), (n1, n1, n1)).values())
    b = sorted(block(m, 2, (offset, offset, 0.01 + gap), (0.01, 0.01, 0.01), (n2, n2, n2)).values())
    return f"""*KEYWORD
*TITLE
two elastic blocks colliding ({kind})
*CONTROL_TERMINATION
{end:10.4g}
*DATABASE_GLSTAT
   1.0e-06
*DATABASE_MATSUM
   1.0e-06
*DATABASE_RCFORC
   1.0e-06
*PART
block a
         1         1         1
block b
         2         1         1
*SECTION_SOLID
         1         1
*MAT_ELASTIC
         1    7850.0   2.0e+11       0.3
*CONTACT_{kind}_ID
         7
         1         2         3         3
*INITIAL_VELOCITY_NODE
{_velocities(a, (0, 0, v))}{_velocities(b, (0, 0, -v))}{m.keyword_text()}*END
"""


def sliding_block(mu: float = 0.3, v0: float = 1.0, g: float = 9.81, end: float = 0.5) -> str:
    """A soft elastic block (0.1 m, 4 x 4 x 2 hexes) sliding at v0 over a fixed rigid plate
    under gravity g with Coulomb friction mu: it stops after v0^2 / (2 mu g)."""
    m = Mesh()
    block(m, 1, (0.0, 0.0, 0.0), (0.1, 0.1, 0.05), (4, 4, 2))
    block(m, 2, (-0.2, -0.2, -0.05), (1.0, 0.5, 0.05), (10, 5, 1))
    blk = list(range(1, 5 * 5 * 3 + 1))  # the block's nodes come first
    return f"""*KEYWORD
*TITLE
block sliding on a rigid plate with Coulomb friction
*CONTROL_TERMINATION
{end:10.4g}
*DATABASE_GLSTAT
     0.005
*DATABASE_HISTORY_NODE
         1
*DATABASE_NODOUT
     0.001
*PART
block
         1         1         1
plate
         2         1         2
*SECTION_SOLID
         1         1
*MAT_ELASTIC
         1    1000.0     1.0e7       0.3
*MAT_RIGID
         2    1000.0     1.0e8       0.3
       1.0         7         7
*DEFINE_CURVE
         1
                 0.0                 1.0
               100.0                 1.0
*LOAD_BODY_Z
         1{g:10.4g}
*CONTACT_NODES_TO_SURFACE
         1         2         3         3
{mu:10.4g}{mu:10.4g}
*INITIAL_VELOCITY_NODE
{_velocities(blk, (v0, 0, 0))}{m.keyword_text()}*END
"""


def hertz_sphere(n: int = 16, radius: float = 0.01, E: float = 1.0e7, nu: float = 0.3,
                 rho: float = 1000.0, v: float = 1.0, end: float = 3e-3) -> str:
    """An elastic ball (a cube grid of n^3 hexes mapped radially onto the sphere) dropped at v onto a
    rigid plate (node set on the ball against the plate's top face, automatic contact)."""
    m = Mesh()
    grid = {}
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                x, y, z = (2.0 * i / n - 1.0, 2.0 * j / n - 1.0, 2.0 * k / n - 1.0)
                # Cube-to-ball map: each point moves radially, by a weight growing from the
                # centre (unchanged) to the cube surface (projected onto the sphere), so the
                # corner elements stay solid rather than flat.
                r_inf = max(abs(x), abs(y), abs(z))
                r_2 = math.sqrt(x * x + y * y + z * z)
                f = (1.0 - r_inf) + r_inf * r_inf / r_2 if r_2 > 0 else 1.0
                sx, sy, sz = f * x, f * y, f * z
                grid[i, j, k] = m.add_node(radius * sx, radius * sy, radius * (sz + 1.0) + 1e-5)
    grid_solids(m, 1, grid, (n, n, n))
    ball = list(range(1, len(m.nodes) + 1))
    half = 1.5 * radius
    block(m, 2, (-half, -half, -0.2 * radius), (2 * half, 2 * half, 0.2 * radius), (6, 6, 1))
    return f"""*KEYWORD
*TITLE
elastic ball on a rigid plate (Hertz)
*CONTROL_TERMINATION
{end:10.4g}
*DATABASE_GLSTAT
   1.0e-05
*DATABASE_RCFORC
   2.0e-06
*PART
ball
         1         1         1
plate
         2         1         2
*SECTION_SOLID
         1         1
*MAT_ELASTIC
         1{rho:10.4g}{E:10.4g}{nu:10.4g}
*MAT_RIGID
         2{rho:10.4g}{100 * E:10.4g}{nu:10.4g}
       1.0         7         7
*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE
         1         2         3         3
*INITIAL_VELOCITY_NODE
{_velocities(ball, (0, 0, -v))}{m.keyword_text()}*END
"""


def fold_half_wavelength(side: float, thickness: float) -> float:
    """H of the symmetric folding mode of a square tube (Wierzbicki & Abramowicz 1983, J. Appl.
    Mech. 50:727-734): H = 0.983 t^(1/3) C^(2/3); one fold (lobe) is 2H of the tube's length."""
    return 0.983 * thickness ** (1 / 3) * side ** (2 / 3)


def _tube_wall_offset(s: int, f: float, z: float, side: float, thickness: float, size: float,
                      trigger: float) -> float:
    """Outward offset of a wall node (side s, fraction f across it, height z above the tube's
    foot) from the perfect square. trigger = 0: a cosine dent of 1% of t over the two lowest
    rows (the old test decks). trigger > 0: a bead of depth trigger x t over one half-wavelength
    H at the foot, in the symmetric mode's pattern (two opposite walls in, two out, nothing at
    the corners), so that the first fold forms there (the usual trigger of crash boxes)."""
    if trigger <= 0.0:
        return 0.01 * thickness * math.cos(math.pi * z / (2 * size)) if z < 2 * size else 0.0
    H = fold_half_wavelength(side, thickness)
    if z > H:
        return 0.0
    sign = -1.0 if s % 2 == 0 else 1.0
    return sign * trigger * thickness * math.sin(math.pi * f) * math.sin(math.pi * z / H)


def _tube_crusher(speed: float, impact_mass, side: float, moving: list[int]) -> tuple[str, str]:
    """The crushing plate's material card and its motion: driven down at `speed` (a curve), or,
    with impact_mass (kg), a free rigid mass that starts down at `speed` carrying the tube
    (`moving`: the tube's and the plate's nodes) into the fixed plate, as a crash box on a sled
    strikes a barrier; the tube's foot is then the struck end."""
    if impact_mass is None:
        return ("""*MAT_RIGID
         3   7.85e-6     210.0       0.3
       1.0         4         7
""", f"""*BOUNDARY_PRESCRIBED_MOTION_RIGID
         3         3         0         1      -1.0
*DEFINE_CURVE
         1
                 0.0{speed:20.6g}
              1000.0{speed:20.6g}
""")
    volume = (2 * 0.8 * side) ** 2 * 4.0
    return (f"""*MAT_RIGID
         3{impact_mass / volume:10.4g}     210.0       0.3
       1.0         4         7
""", "*INITIAL_VELOCITY_NODE\n" + _velocities(moving, (0, 0, -speed)))


def tube_crush(side: float = 50.0, thickness: float = 1.5, length: float = 120.0,
               size: float = 2.5, speed: float = 10.0, end: float = 6.0,
               nip: int = 3, single: str = "AUTOMATIC_SINGLE_SURFACE", trigger: float = 0.0,
               impact_mass=None) -> str:
    """A square steel tube (side C, wall t; mm, ms, kg, GPa) standing on a fixed rigid plate and
    crushed by a rigid plate moving down at `speed` (m/s = mm/ms), with single-surface contact
    on the tube and node-to-surface contact with both plates. Nearly perfectly plastic steel
    (yield 0.3 GPa, tangent 0.05 GPa) so that the folding theories apply with sigma0 = yield.
    `trigger` and `impact_mass`: see _tube_wall_offset and _tube_crusher; with a mass, the
    plates' momenta and the tube's top corner are written (matsum, nodout)."""
    m = Mesh()
    per_side = max(2, round(side / size))
    n_axial = max(2, round(length / size))
    around = []
    for s in range(4):
        for k in range(per_side):
            f = k / per_side
            x0, y0 = [(0, 0), (side, 0), (side, side), (0, side)][s]
            x1, y1 = [(side, 0), (side, side), (0, side), (0, 0)][s]
            around.append((x0 + f * (x1 - x0) - side / 2, y0 + f * (y1 - y0) - side / 2, s, f))
    ring = len(around)
    ids = {}
    for k in range(n_axial + 1):
        for i in range(ring):
            z = length * k / n_axial
            x, y, s, f = around[i]
            # Offset along the ray from the axis (normal to the wall away from the corners).
            dent = _tube_wall_offset(s, f, z, side, thickness, size, trigger)
            r = math.hypot(x, y)
            ids[i, k] = m.add_node(x + dent * x / r, y + dent * y / r, z + 1.0)
    for k in range(n_axial):
        for i in range(ring):
            j = (i + 1) % ring
            m.add_shell(1, [ids[i, k], ids[j, k], ids[j, k + 1], ids[i, k + 1]])
    tube_nodes = len(m.nodes)
    half = 0.8 * side
    base = len(m.nodes)
    block(m, 2, (-half, -half, -4.0), (2 * half, 2 * half, 4.0), (8, 8, 1))
    block(m, 3, (-half, -half, length + 2.0), (2 * half, 2 * half, 4.0), (8, 8, 1))
    top_first = base + 9 * 9 * 2 + 1
    plate_nodes = list(range(top_first, len(m.nodes) + 1))
    moving = list(range(1, tube_nodes + 1)) + plate_nodes
    crusher, motion = _tube_crusher(speed, impact_mass, side, moving)
    histories = "" if impact_mass is None else f"""*DATABASE_MATSUM
      0.02
*DATABASE_NODOUT
      0.02
*DATABASE_HISTORY_NODE
{ids[0, n_axial]:10d}{plate_nodes[0]:10d}
"""
    return f"""*KEYWORD
*TITLE
square steel tube axial crush (single-surface contact)
*CONTROL_TERMINATION
{end:10.4g}
*CONTROL_SHELL
$    wrpang     esort     irnxx    istupd    theory       bwc     miter      proj
                                         1
*DATABASE_GLSTAT
      0.05
*DATABASE_RCFORC
      0.02
*DATABASE_BINARY_D3PLOT
       0.5
{histories}*PART
tube
         1         1         1
base plate
         2         2         2
crushing plate
         3         2         3
*SECTION_SHELL
         1         2       1.0{nip:10d}
{thickness:10.4g}{thickness:10.4g}{thickness:10.4g}{thickness:10.4g}
*SECTION_SOLID
         2         1
*MAT_PLASTIC_KINEMATIC
         1   7.85e-6     210.0       0.3       0.3      0.05       1.0
*MAT_RIGID
         2   7.85e-6     210.0       0.3
       1.0         7         7
{crusher}{motion}*CONTACT_{single}_ID
         1
         1         0         3         0
*CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID
         2
         1         2         3         3
*CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID
         3
         1         3         3         3
{m.keyword_text()}*END
"""


def tied_bar(v: float = 5.0, end: float = 1.5e-4) -> str:
    """An elastic steel bar (10 x 10 x 200 mm) in two halves meshed differently (4 x 4 and
    3 x 3 across) and joined by a tied surface-to-surface interface, striking a stonewall at
    v: a continuous bar would leave the wall at v after 2 L / c."""
    m = Mesh()
    block(m, 1, (0, 0, 0), (0.01, 0.01, 0.1), (4, 4, 20))
    first_b = len(m.nodes) + 1
    block(m, 2, (0, 0, 0.1), (0.01, 0.01, 0.1), (3, 3, 15))
    nodes = list(range(1, len(m.nodes) + 1))
    return f"""*KEYWORD
*TITLE
two-part bar joined by a tied interface striking a stonewall
*CONTROL_TERMINATION
{end:10.4g}
*DATABASE_GLSTAT
   2.0e-06
*DATABASE_RWFORC
   1.0e-06
*DATABASE_RCFORC
   2.0e-06
*DATABASE_MATSUM
   2.0e-06
*PART
lower half
         1         1         1
upper half
         2         1         1
*SECTION_SOLID
         1         1
*MAT_ELASTIC
         1    7850.0   2.0e+11       0.0
*RIGIDWALL_PLANAR
         0
       0.0       0.0       0.0       0.0       0.0       1.0
*CONTACT_TIED_SURFACE_TO_SURFACE
         2         1         3         3
*INITIAL_VELOCITY_NODE
{_velocities(nodes, (0, 0, -v))}{m.keyword_text()}*END
"""


def cask_drop(v: float = 5.0, end: float = 3.0e-4, n_theta: int = 24, refine: int = 1,
              elform: int = 1) -> str:
    """A steel cask (a tube of outer radius 0.1 m, wall 0.02 m, height 0.3 m, in hexes) with a
    lid (a disk of hexes tied to the tube's bottom face), dropped lid first at v onto a fixed
    rigid target, with two-surface symmetric penalty contact between cask and target. `refine`
    multiplies the divisions through the wall, along the height and across the lid; `elform`
    is the solids' formulation (2, fully integrated: no hourglass modes to ring)."""
    m = Mesh()
    R, wall, H, t_lid = 0.1, 0.02, 0.3, 0.02
    nr, nz = 2 * refine, 6 * refine
    ring = {}
    for k in range(nz + 1):
        for j in range(nr + 1):
            r = R - wall + wall * j / nr
            for i in range(n_theta):
                a = 2 * math.pi * i / n_theta
                ring[i, j, k] = m.add_node(r * math.cos(a), r * math.sin(a), t_lid + H * k / nz)
    for k in range(nz):
        for j in range(nr):
            for i in range(n_theta):
                i1 = (i + 1) % n_theta
                m.add_solid(1, [ring[i, j, k], ring[i, j + 1, k], ring[i1, j + 1, k], ring[i1, j, k],
                                ring[i, j, k + 1], ring[i, j + 1, k + 1], ring[i1, j + 1, k + 1],
                                ring[i1, j, k + 1]])
    # The lid: a square grid mapped onto the disk of radius R, two layers (2 x refine).
    n, layers = 8 * refine, 2 * refine
    disk = {}
    for k in range(layers + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                x, y = 2.0 * i / n - 1.0, 2.0 * j / n - 1.0
                disk[i, j, k] = m.add_node(R * x * math.sqrt(1 - y * y / 2),
                                           R * y * math.sqrt(1 - x * x / 2), t_lid * k / layers)
    grid_solids(m, 2, disk, (n, n, layers))
    cask_nodes = list(range(1, len(m.nodes) + 1))
    block(m, 3, (-0.15, -0.15, -0.0405), (0.3, 0.3, 0.04), (6, 6, 1))
    return f"""*KEYWORD
*TITLE
cask with a tied lid dropped on a rigid target (symmetric two-surface contact)
*CONTROL_TERMINATION
{end:10.4g}
*DATABASE_GLSTAT
   5.0e-06
*DATABASE_MATSUM
   5.0e-06
*DATABASE_RCFORC
   1.0e-06
*PART
cask body
         1         1         1
lid
         2         1         1
target
         3         1         2
*SECTION_SOLID
         1{elform:10d}
*MAT_ELASTIC
         1    7850.0   2.0e+11       0.3
*MAT_RIGID
         2    7850.0   2.0e+11       0.3
       1.0         7         7
*SET_PART_LIST
         1
         1         2
*CONTACT_TIED_SURFACE_TO_SURFACE_ID
         1
         1         2         3         3
*CONTACT_SURFACE_TO_SURFACE_ID
         2
         1         3         2         3
*INITIAL_VELOCITY_NODE
{_velocities(cask_nodes, (0, 0, -v))}{m.keyword_text()}*END
"""


def _shell_plate(m: Mesh, part: int, z: float) -> dict:
    """A 30 x 30 plate of 3 x 3 shells of 10 mm at height z; its node ids keyed (i, j)."""
    return shell_grid(m, part, (0.0, 0.0, z), (30.0, 30.0), (3, 3))


def pressed_plate(load: float = 100.0, end: float = 1.33e-4) -> str:
    """A 1 mm steel shell plate (3 x 3 shells of 10 mm) pressed onto an elastic block (its
    base fixed) by `load` N at each of its 16 nodes, automatic surface-to-surface contact with
    20% VDC, so that it settles; from about 80 us a column of no consequence far away (a
    near-massless 1e-4 MPa hex, squeezed at 100 m/s) makes the time step fall threefold. Units
    mm, tonne, s. A penalty stiffness capped at the current step stiffens as the step falls and
    pushes the resting plate off the block; one capped at the initial step does not."""
    m = Mesh()
    g = block(m, 1, (0.0, 0.0, 0.0), (30.0, 30.0, 10.0), (3, 3, 1))
    plate = _shell_plate(m, 2, 10.5)
    col = block(m, 3, (100.0, 0.0, 0.0), (10.0, 10.0, 14.0), (1, 1, 1))
    fixed = [g[i, j, 0] for i in range(4) for j in range(4)] + \
        [col[i, j, 0] for i in range(2) for j in range(2)]
    squeezed = [col[i, j, 1] for i in range(2) for j in range(2)]
    return f"""*KEYWORD
*TITLE
plate pressed on a block while the time step falls
*CONTROL_TERMINATION
{end}
*DATABASE_GLSTAT
1.0e-6
*DATABASE_RCFORC
1.0e-6
*PART
block
1,1,1
*PART
plate
2,2,1
*PART
squeezed column
3,1,3
*SECTION_SOLID
1,1
*SECTION_SHELL
2,2
1.0,1.0,1.0,1.0
*MAT_ELASTIC
1,7.85e-9,210000.,0.3
*MAT_ELASTIC
3,3.7e-18,1.0e-4,0.0
*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE
2,1,3,3
0.0,0.0,0.0,0.0,20.0
*DEFINE_CURVE
1
0.0,1.0
1.0,1.0
*LOAD_NODE_SET
3,3,1,{-load}
*BOUNDARY_SPC_SET
1,0,1,1,1,1,1,1
*BOUNDARY_PRESCRIBED_MOTION_SET
2,3,0,1,-1.0e5
""" + node_set(1, fixed) + node_set(2, squeezed) + node_set(3, list(plate.values())) + \
        m.keyword_text() + "*END\n"


def overlapping_stack(lower: str = "shell", overlap: float = 0.2, push: float = 0.1,
                      ignore: int = 2, local_ignore: int = 0, dtstif: float = 0.0,
                      sfs: float = 1.0) -> str:
    """A 1 mm steel shell plate (3 x 3 shells of 10 mm) that starts `overlap` deep in a fixed
    body under it (`lower`: a 1 mm shell plate of the same mesh, or a 30 x 30 x 10 mm block),
    automatic single surface contact, initial penetrations tracked (*CONTROL_CONTACT IGNORE
    `ignore`, or the contact's own card C IGNORE `local_ignore`). Every node of the upper
    plate is driven in z (mm): 0 -> -push (held from 1 to 2 ms) -> +overlap/2 (held from 3 to 4)
    -> -push (held from 5 to 6 ms). Units mm, ms, kg, GPa. Both bodies move as prescribed, so
    the contact force is a function of the position alone: LS-DYNA's tracking (LSTC FAQ
    "contact.ignore1") gives no force at the start, k x push on the first hold, none while the
    plate is lifted, and k x (push + overlap/2) on the last hold (the stored offset fell to
    overlap/2 when the plate was lifted). `dtstif` > 0: SOFT = 1 with that DTSTIF (card C) and
    SFS = SFM = `sfs`, so that the mass-based stiffness 0.5 SOFSCL m* / DTSTIF^2 governs."""
    m = Mesh()
    soft = 1 if dtstif > 0.0 else 0
    if lower == "shell":
        fixed = list(_shell_plate(m, 1, 0.0).values())
        z_top, lower_part = 1.0 - overlap, "1,2,1"
    else:
        g = block(m, 1, (0.0, 0.0, -10.0), (30.0, 30.0, 10.0), (3, 3, 1))
        fixed = sorted(g.values())
        z_top, lower_part = 0.5 - overlap, "1,1,1"
    plate = _shell_plate(m, 2, z_top)
    up = 0.5 * overlap
    return f"""*KEYWORD
*TITLE
plate starting inside a {lower}, initial penetrations tracked
*CONTROL_TERMINATION
6.0
*CONTROL_CONTACT
0.1
$ cards 2 and 3
0
0.0
{ignore}
*DATABASE_GLSTAT
0.05
*DATABASE_RCFORC
0.05
*DATABASE_BNDOUT
0.05
*PART
lower
{lower_part}
*PART
upper plate
2,2,1
*SECTION_SOLID
1,1
*SECTION_SHELL
2,2
1.0,1.0,1.0,1.0
*MAT_ELASTIC
1,7.85e-6,210.,0.3
*SET_PART_LIST
1
1,2
*CONTACT_AUTOMATIC_SINGLE_SURFACE
1,0,2
0.0,0.0,0.0,0.0,0.0
{sfs},{sfs}
{soft}
0
0,{local_ignore},0.0,{dtstif}
*DEFINE_CURVE
1
0.0,0.0
1.0,{-push}
2.0,{-push}
3.0,{up}
4.0,{up}
5.0,{-push}
6.0,{-push}
*BOUNDARY_SPC_SET
1,0,1,1,1,1,1,1
*BOUNDARY_PRESCRIBED_MOTION_SET
2,3,2,1,1.0
""" + node_set(1, fixed) + node_set(2, list(plate.values())) + m.keyword_text() + "*END\n"


def approaching_plates(kind: str = "AUTOMATIC_SINGLE_SURFACE", ssthk: int = 0,
                       optt: float = 0.0, thickness: float = 6.0, gap: float = 10.0,
                       speed: float = 1.0, end: float = 7.0) -> str:
    """Two steel shell plates (3 x 3 shells of 10 mm, `thickness` thick) with their
    mid-surfaces `gap` apart: the lower one held, the upper one driven down at `speed` (every
    node prescribed), in one contact of `kind` over both (*CONTROL_CONTACT SSTHK `ssthk`;
    `optt` > 0: *PART_CONTACT OPTT on both parts). Units mm, ms, kg, GPa. The force starts
    when the mid-surfaces come within the contact thickness, at t = (gap - thickness) / speed,
    so the force's onset measures the contact thickness the code takes: LS-DYNA limits a
    shell's to 40% of its shortest edge in single surface contacts with SSTHK 0 unless OPTT
    or SST gives one (dynasupport, "Contact thickness")."""
    m = Mesh()
    fixed = list(_shell_plate(m, 1, 0.0).values())
    plate = list(_shell_plate(m, 2, gap).values())
    single = "SINGLE_SURFACE" in kind or kind == "AUTOMATIC_GENERAL"
    surfaces = "1,0,2" if single else "1,2,3,3"
    part = "*PART_CONTACT" if optt > 0.0 else "*PART"
    extra = f"\n0.0,0.0,0.0,0.0,{optt}" if optt > 0.0 else ""
    return f"""*KEYWORD
*TITLE
plates approaching: the contact thickness of shells
*CONTROL_TERMINATION
{end}
*CONTROL_CONTACT
0.1
0,0,0,0,4.0,{ssthk}
*DATABASE_BNDOUT
0.02
{part}
lower plate
1,1,1{extra}
{part}
upper plate
2,1,1{extra}
*SECTION_SHELL
1,2
{thickness},{thickness},{thickness},{thickness}
*MAT_ELASTIC
1,7.85e-6,210.,0.3
*SET_PART_LIST
1
1,2
*CONTACT_{kind}
{surfaces}
0.0,0.0,0.0,0.0,0.0
*DEFINE_CURVE
1
0.0,{-speed}
1000.0,{-speed}
*BOUNDARY_SPC_SET
1,0,1,1,1,1,1,1
*BOUNDARY_PRESCRIBED_MOTION_SET
2,3,0,1,1.0
""" + node_set(1, fixed) + node_set(2, plate) + m.keyword_text() + "*END\n"


def edge_to_edge_plates(thickness: float = 1.0, gap: float = 5.0, speed: float = 1.0,
                        end: float = 5.0) -> str:
    """Two steel shell plates (3 x 3 shells of 10 mm, `thickness` thick) in one plane, free
    edge facing free edge `gap` apart: the left one held, the right one driven towards it at
    `speed` in their plane, one automatic single surface contact. Units mm, ms, kg, GPa. The
    contact surface wraps round a free edge with half the thickness (LS-DYNA's automatic
    contacts), so the edges meet when `gap` has closed to the thickness, at
    t = (gap - thickness) / speed; by `end` the right plate's edge nodes have come within
    0.02 mm of the left plate's edge line, into the band where their projection is clamped to
    the edge."""
    m = Mesh()
    left = list(shell_grid(m, 1, (0.0, 0.0, 0.0), (30.0, 30.0), (3, 3)).values())
    right = list(shell_grid(m, 2, (30.0 + gap, 0.0, 0.0), (30.0, 30.0), (3, 3)).values())
    return f"""*KEYWORD
*TITLE
plates in one plane meeting edge to edge
*CONTROL_TERMINATION
{end}
*DATABASE_BNDOUT
0.02
*DATABASE_GLSTAT
0.02
*PART
left plate
1,1,1
*PART
right plate
2,1,1
*SECTION_SHELL
1,2
{thickness},{thickness},{thickness},{thickness}
*MAT_ELASTIC
1,7.85e-6,210.,0.3
*SET_PART_LIST
1
1,2
*CONTACT_AUTOMATIC_SINGLE_SURFACE
1,0,2
0.0,0.0,0.0,0.0,0.0
*DEFINE_CURVE
1
0.0,{-speed}
1000.0,{-speed}
*BOUNDARY_SPC_SET
1,0,1,1,1,1,1,1
*BOUNDARY_SPC_SET
2,0,0,1,1,1,1,1
*BOUNDARY_PRESCRIBED_MOTION_SET
2,1,0,1,1.0
""" + node_set(1, left) + node_set(2, right) + m.keyword_text() + "*END\n"


def thick_sheet(n: int = 5, size: float = 2.0, optt: float = 6.4) -> str:
    """One flat steel sheet of n x n shells of `size` mm with a contact thickness (OPTT) far
    above its mesh size, alone in an automatic single surface contact, as the bolted joint's
    bolt head (6.4 mm on 2 mm shells). A node is never in contact with its own flat sheet, so
    there is no initial penetration; rounding its interior edges found hundreds."""
    m = Mesh()
    shell_grid(m, 1, (0.0, 0.0, 0.0), (n * size, n * size), (n, n))
    return f"""*KEYWORD
*TITLE
a thick flat sheet on a fine mesh
*CONTROL_TERMINATION
0.01
*CONTROL_CONTACT
0.1
$ cards 2 and 3
0
0.0
2
*PART_CONTACT
sheet
1,1,1
0.0,0.0,0.0,0.0,{optt}
*SECTION_SHELL
1,16
1.0,1.0,1.0,1.0
*MAT_ELASTIC
1,7.85e-6,210.,0.3
*CONTACT_AUTOMATIC_SINGLE_SURFACE
1,0,3
0.0,0.0,0.0,0.0,0.0
""" + m.keyword_text() + "*END\n"


def eroding_layers(kind: str = "ERODING_SURFACE_TO_SURFACE", erosop: int = 1, iadj: int = 0,
                   failtm: float = 1.0, gap: float = 3.0, speed: float = 1.0, end: float = 9.0,
                   n: int = 3, nz: int = 1, target: str = "1,2", lower_mneps: float = 0.0,
                   enmass: int | None = None) -> str:
    """A target of two 5 mm layers of steel hexes (30 x 30 mm, n x n x nz elements each,
    sharing the nodes between them; the upper layer, part 1, eroded at `failtm` by
    *MAT_ADD_EROSION FAILTM; the lower, part 2, held at its base, eroded where its minimum
    principal strain falls below `lower_mneps` if not 0) and a 10 x 10 x 5 mm block (part 3)
    `gap` above it, driven down at `speed` (every node prescribed), in contact with the
    target's parts `target` (a part set) through *CONTACT_`kind` (ERODING types: EROSOP
    `erosop`, IADJ `iadj`). Units mm, ms, kg, GPa. The upper layer is gone before the block
    reaches it; the block meets the lower layer's top, interior to the target until then, at
    t = (gap + 5) / speed when the surface follows the erosion (EROSOP 1), and never
    otherwise. `enmass`: *CONTROL_CONTACT's ENMASS, if given (the free nodes of the eroded
    layer then stay in contact)."""
    m = Mesh()
    grid = {}
    for k in range(2 * nz + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                grid[i, j, k] = m.add_node(30.0 * i / n, 30.0 * j / n, 5.0 * k / nz)
    for part, k0 in ((2, 0), (1, nz)):
        layer = {(i, j, k): grid[i, j, k0 + k]
                 for i in range(n + 1) for j in range(n + 1) for k in range(nz + 1)}
        grid_solids(m, part, layer, (n, n, nz))
    block_nodes = sorted(block(m, 3, (10.0, 10.0, 10.0 + gap), (10.0, 10.0, 5.0),
                               (2, 2, 1)).values())
    base = [grid[i, j, 0] for j in range(n + 1) for i in range(n + 1)]
    # A single surface takes the block and the target as one part set.
    single = "SINGLE_SURFACE" in kind
    surfaces = "1,0,2" if single else "3,1,3,2"
    parts = target + ",3" if single else target
    lower = "1,7.85e-6,210.,0.3"
    if lower_mneps != 0.0:
        lower += f"\n*MAT_ADD_EROSION\n1,0,0,{lower_mneps},0,0,1,1\n0,0,0,0,0,0,0,0"
    eroding = f"\n0,{erosop},{iadj}" if kind.startswith("ERODING") else ""
    control = "" if enmass is None else f"*CONTROL_CONTACT\n0.1,0,0,0,0,0,0,{enmass}\n"
    return f"""*KEYWORD
*TITLE
a block through an eroded layer onto the one below ({kind})
*CONTROL_TERMINATION
{end}
{control}*DATABASE_BNDOUT
0.02
*DATABASE_GLSTAT
0.02
*PART
upper layer (eroded at FAILTM)
1,1,2
*PART
lower layer
2,1,1
*PART
block
3,1,1
*SECTION_SOLID
1,1
*MAT_ELASTIC
{lower}
*MAT_ELASTIC
2,7.85e-6,210.,0.3
*MAT_ADD_EROSION
2,0,0,0,0,0,1,1
0,0,0,0,0,0,0,{failtm}
*SET_PART_LIST
1
{parts}
*CONTACT_{kind}
{surfaces}
0.0,0.0,0.0,0.0,0.0
1.0,1.0{eroding}
*DEFINE_CURVE
1
0.0,{-speed}
1000.0,{-speed}
*BOUNDARY_SPC_SET
1,0,1,1,1,1,1,1
*BOUNDARY_PRESCRIBED_MOTION_SET
2,3,0,1,1.0
""" + node_set(1, base) + node_set(2, block_nodes) + m.keyword_text() + "*END\n"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("problem", choices=["blocks", "sliding", "hertz", "tube", "tied", "cask", "pressed",
                             "overlap", "eroding"])
    ap.add_argument("out", type=pathlib.Path)
    ap.add_argument("--kind", default="SURFACE_TO_SURFACE")
    ap.add_argument("--mu", type=float, default=0.3)
    ap.add_argument("--n", type=int, default=16)
    ap.add_argument("--size", type=float, default=2.5)
    ap.add_argument("--length", type=float, default=120.0)
    ap.add_argument("--end", type=float, default=None)
    a = ap.parse_args()
    extra = {} if a.end is None else {"end": a.end}
    if a.problem == "blocks":
        text = colliding_blocks(a.kind, **extra)
    elif a.problem == "sliding":
        text = sliding_block(a.mu, **extra)
    elif a.problem == "hertz":
        text = hertz_sphere(a.n, **extra)
    elif a.problem == "tied":
        text = tied_bar(**extra)
    elif a.problem == "cask":
        text = cask_drop(**extra)
    elif a.problem == "pressed":
        text = pressed_plate(**extra)
    elif a.problem == "overlap":
        text = overlapping_stack()
    elif a.problem == "eroding":
        text = eroding_layers(n=5, speed=5.0, gap=0.3, failtm=0.05, lower_mneps=-0.02,
                              **(extra or {"end": 1.5}))
    else:
        text = tube_crush(size=a.size, length=a.length, **extra)
    a.out.write_text(text)


if __name__ == "__main__":
    main()
