"""The sign-post-in-soil example deck (examples/sign_post_in_soil; issue 18).

A rigid bumper of an 820 kg vehicle (the NCHRP Report 350 small car, 820C) at 20 mph
(8.94 m/s) strikes a steel C-channel sign post standing 1.2 m out of a soil block in which it is
embedded 1.0 m. Units: mm, s, tonne, N, MPa (those of roadside-safety LS-DYNA decks).

  post    shells (Belytschko-Tsay), *MAT_PIECEWISE_LINEAR_PLASTICITY; a plain C channel of
          3 lb/ft (web 60 mm, flanges 40 mm, 4 mm wall: 560 mm2, 4.4 kg/m), web toward the car,
          ASTM A499 grade 60 rail steel (yield 414 MPa = 60 ksi, the grade's minimum)
  soil    hexahedra, *MAT_SOIL_AND_FOAM, the moduli, density and strength of FHWA-HRT-04-095
          (Lewis 2004, "Manual for LS-DYNA Soil Material Model 147"), default material: the
          NCHRP Report 350 "strong soil" (compacted AASHTO M147 grade B gravel): K 465.4 MPa,
          G 186.2 MPa, rho 2350 kg/m3, peak friction angle 1.1 rad, cohesion 6.2 kPa. The
          Mohr-Coulomb strength becomes *MAT_005's J2 = a0 + a1 p + a2 p^2 through the
          Drucker-Prager cone that passes through the Mohr-Coulomb corners in triaxial
          compression: sqrt(J2) = k + alpha p, alpha = 2 sin(phi) / (sqrt(3) (3 - sin(phi))),
          k = 6 c cos(phi) / (sqrt(3) (3 - sin(phi))). Bulk behaviour linear at K (no compaction
          curve in that source: VCR 0 with a straight loading line of slope KUN = K), no tension.
  bumper  a rigid shell plate 600 mm wide, 300 mm high, centred 500 mm above ground, of the
          car's mass (its density), on a straight line (y, z and rotations held: a bogie)

Contacts: bumper to post and post to soil, *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE. The soil has
a hole of the post's outer outline (the channel's open side is a void, not soil), so the post's
shells start touching it; the far faces of the block are held normal to themselves and its
bottom fixed. Gravity is needed: the soil's strength is mostly friction, and without the
overburden a weightless soil lets the post turn through it as a rigid lever (tried: the post,
thrown ahead of the bumper, never bent).
"""

from __future__ import annotations

import math

from deckgen import Mesh, node_set

# Post section (mid-surface; x along the impact, y across, z up), mm.
WEB, FLANGE, WALL = 60.0, 40.0, 4.0
ABOVE, EMBED, ROW = 1200.0, 1000.0, 20.0
# Hole in the soil: the post's outer outline (the outer faces of web and flanges, the flange
# tips and the toe half a wall short of the soil: shells touch at their mid-surface +- WALL/2).
HOLE_X = (-WALL / 2, FLANGE + WALL / 2)
HOLE_Y = (-(WEB + WALL) / 2, (WEB + WALL) / 2)
# Soil block (mm) and materials (MPa, t/mm3).
SOIL_X, SOIL_Y, SOIL_DEPTH = (-400.0, 450.0), 350.0, 1250.0
STEEL = {"rho": 7.85e-9, "E": 2.0e5, "nu": 0.3, "sigy": 414.0, "etan": 1000.0}
SOIL = {"rho": 2.35e-9, "K": 465.4, "G": 186.2, "phi": 1.1, "c": 6.2e-3}
# Impactor: mass (t), speed (mm/s), bumper centre height and size (mm).
MASS, SPEED, IMPACT_Z, BUMPER_W, BUMPER_H, BUMPER_T = 0.82, 8940.0, 500.0, 600.0, 300.0, 10.0
# Gravity (mm/s^2) rises over RAMP (s), one period 4 H / c of the soil column's first mode, so
# that the column settles without ringing; the bumper starts GAP (mm) short of the post and
# meets it just after.
GRAVITY, RAMP, GAP = 9810.0, 0.009, 100.0


def drucker_prager(phi: float, c: float) -> tuple[float, float, float]:
    """(a0, a1, a2) of *MAT_005's J2 = a0 + a1 p + a2 p^2 for the Drucker-Prager cone through
    the compression corners of Mohr-Coulomb (friction angle phi, cohesion c)."""
    s = math.sin(phi)
    denom = math.sqrt(3.0) * (3.0 - s)
    alpha, k = 2.0 * s / denom, 6.0 * c * math.cos(phi) / denom
    return k * k, 2.0 * k * alpha, alpha * alpha


def plastic_moment() -> float:
    """Fully plastic moment (N mm) of the C channel bent by a push along x (thin wall: the
    plastic neutral axis, parallel to the web, halves the area)."""
    web, flange = WEB * WALL, 2 * FLANGE * WALL
    xp = (flange - web) / 2 / (2 * WALL) if flange > web else 0.0  # from the web
    z = web * xp + 2 * WALL * (xp * xp / 2 + (FLANGE - xp) ** 2 / 2)
    return STEEL["sigy"] * z


def graded(length: float, first: float, largest: float, growth: float = 1.3) -> list[float]:
    """Cell sizes from `first` growing by `growth` up to `largest`, scaled to sum to `length`."""
    sizes, total = [], 0.0
    while total < length - 0.5 * min(largest, first * growth ** len(sizes)):
        h = min(largest, first * growth ** len(sizes))
        sizes.append(h)
        total += h
    return [h * length / total for h in sizes]


def march(start: float, end: float, first: float, largest: float,
          growth: float = 1.3) -> list[float]:
    """Coordinates from start to end (exactly) in graded cells, first ones at start."""
    sign = 1.0 if end > start else -1.0
    points = [start]
    for h in graded(abs(end - start), first, largest, growth):
        points.append(points[-1] + sign * h)
    points[-1] = end
    return points


def axis(lo: float, hole: tuple[float, float], hi: float, n_hole: int, first: float,
         largest: float) -> list[float]:
    """Grid coordinates from lo to hi: n_hole cells across the hole, graded cells outside."""
    inside = [hole[0] + (hole[1] - hole[0]) * i / n_hole for i in range(1, n_hole)]
    return (march(hole[0], lo, first, largest)[::-1] + inside
            + march(hole[1], hi, first, largest))


def soil(mesh: Mesh, part: int) -> dict:
    """The soil block with the post's hole (cells inside the outline, above the post's toe,
    left out); returns the node grid keyed (i, j, k) and the axes."""
    xs = axis(SOIL_X[0], HOLE_X, SOIL_X[1], 2, 30.0, 200.0)
    ys = axis(-SOIL_Y, HOLE_Y, SOIL_Y, 2, 30.0, 200.0)
    zs = [-SOIL_DEPTH] + march(0.0, -EMBED - WALL / 2, 30.0, 160.0, 1.35)[::-1]
    grid = {}
    for k, z in enumerate(zs):
        for j, y in enumerate(ys):
            for i, x in enumerate(xs):
                grid[i, j, k] = mesh.add_node(x, y, z)

    def in_hole(i: int, j: int, k: int) -> bool:
        cx, cy, cz = (xs[i] + xs[i + 1]) / 2, (ys[j] + ys[j + 1]) / 2, (zs[k] + zs[k + 1]) / 2
        return HOLE_X[0] < cx < HOLE_X[1] and HOLE_Y[0] < cy < HOLE_Y[1] and cz > -EMBED - WALL / 2

    for k in range(len(zs) - 1):
        for j in range(len(ys) - 1):
            for i in range(len(xs) - 1):
                if not in_hole(i, j, k):
                    mesh.add_solid(part, [grid[i, j, k], grid[i + 1, j, k], grid[i + 1, j + 1, k],
                                          grid[i, j + 1, k], grid[i, j, k + 1],
                                          grid[i + 1, j, k + 1], grid[i + 1, j + 1, k + 1],
                                          grid[i, j + 1, k + 1]])
    return {"grid": grid, "xs": xs, "ys": ys, "zs": zs}


def post(mesh: Mesh, part: int) -> dict:
    """The C channel: flange tip (40, -30) round the web to (40, 30), rows of ROW along z;
    returns the node ids keyed (point around the section, row)."""
    half = WEB / 2
    section = [(FLANGE * (1 - i / 2), -half) for i in range(2)]
    section += [(0.0, -half + WEB * i / 3) for i in range(3)]
    section += [(FLANGE * i / 2, half) for i in range(3)]
    rows = round((ABOVE + EMBED) / ROW)
    ids = {}
    for r in range(rows + 1):
        for s, (x, y) in enumerate(section):
            ids[s, r] = mesh.add_node(x, y, -EMBED + r * ROW)
    for r in range(rows):
        for s in range(len(section) - 1):
            mesh.add_shell(part, [ids[s, r], ids[s + 1, r], ids[s + 1, r + 1], ids[s, r + 1]])
    return ids


def bumper(mesh: Mesh, part: int) -> float:
    """The rigid bumper plate in the plane x = x0 (GAP short of the web's face, half its own
    thickness further); returns x0."""
    x0 = HOLE_X[0] - GAP - BUMPER_T / 2
    ny, nz = 12, 6
    ids = {}
    for k in range(nz + 1):
        for j in range(ny + 1):
            ids[j, k] = mesh.add_node(x0, -BUMPER_W / 2 + BUMPER_W * j / ny,
                                      IMPACT_Z - BUMPER_H / 2 + BUMPER_H * k / nz)
    for k in range(nz):
        for j in range(ny):
            mesh.add_shell(part, [ids[j, k], ids[j + 1, k], ids[j + 1, k + 1], ids[j, k + 1]])
    return x0


def history_nodes(ids: dict) -> list[int]:
    """The web's corner with the -y flange (section point 2) at the toe, 500 mm down, ground,
    bumper height and top."""
    return [ids[2, round((EMBED + z) / ROW)] for z in (-EMBED, -500.0, 0.0, IMPACT_Z, ABOVE)]


def boundary_sets(mesh: Mesh, s: dict) -> str:
    """Node sets 1-3 with their SPCs: the bottom fixed, the x faces held in x, the y faces in
    y (a rigid container: what reaches the far faces is reflected, not absorbed)."""
    xs, ys = s["xs"], s["ys"]
    nodes = s["grid"]
    bottom = sorted(n for (i, j, k), n in nodes.items() if k == 0)
    x_faces = sorted(n for (i, j, k), n in nodes.items() if k > 0 and i in (0, len(xs) - 1))
    y_faces = sorted(n for (i, j, k), n in nodes.items()
                     if k > 0 and j in (0, len(ys) - 1) and 0 < i < len(xs) - 1)
    return (node_set(1, bottom, "soil bottom") + node_set(2, x_faces, "soil faces normal to x")
            + node_set(3, y_faces, "soil faces normal to y") + """*BOUNDARY_SPC_SET
$     nsid       cid      dofx      dofy      dofz     dofrx     dofry     dofrz
         1         0         1         1         1
         2         0         1         0         0
         3         0         0         1         0
""")


def deck(end: float = 0.05) -> str:
    mesh = Mesh()
    ids = post(mesh, 1)
    s = soil(mesh, 2)
    first_bumper = len(mesh.nodes) + 1
    x0 = bumper(mesh, 3)
    a0, a1, a2 = drucker_prager(SOIL["phi"], SOIL["c"])
    density = MASS / (BUMPER_W * BUMPER_H * BUMPER_T)
    bumper_nodes = list(range(first_bumper, len(mesh.nodes) + 1))
    history = "".join(f"{n:10d}" for n in history_nodes(ids))
    k = SOIL["K"]
    return f"""*KEYWORD
*TITLE
Bumper of an 820 kg car at 20 mph into a 3 lb/ft steel sign post in soil (mm, s, t, N, MPa)
$ Generated by tools/make_examples.py (tools/sign_post_deck.py); see README.md beside it.
$ Plastic moment of the post {plastic_moment():.4g} N mm; over the {IMPACT_Z:.0f} mm lever
$ from the bumper to the ground a force of {plastic_moment() / IMPACT_Z:.4g} N.
*CONTROL_TERMINATION
$   endtim
{end:10.4g}
*CONTROL_TIMESTEP
$   dtinit    tssfac
       0.0       0.9
*CONTROL_ENERGY
$     hgen      rwen
         2         2
*DATABASE_GLSTAT
    2.0e-4
*DATABASE_MATSUM
    2.0e-4
*DATABASE_RCFORC
$ every cycle: the bumper's force is a train of spikes a few cycles long (the post
$ rattling on the rigid plate), which sparser samples alias (impulse off by half at 0.1 ms)
    1.0e-6
*DATABASE_NODOUT
    1.0e-4
*DATABASE_BINARY_D3PLOT
     0.005
*DATABASE_HISTORY_NODE
$ the web's middle line at the toe, 500 mm down, ground, bumper height, top; the bumper
{history}
{first_bumper:10d}
*PART
sign post (3 lb/ft C channel)
$      pid     secid       mid
         1         1         1
*PART
soil (NCHRP 350 strong soil)
         2         2         2
*PART
bumper (rigid, the car's mass: its density makes the 10 mm plate weigh {1000 * MASS:.0f} kg)
         3         3         3
*SECTION_SHELL
$    secid    elform      shrf       nip
         1         2       1.0         5
{WALL:10.4g}{WALL:10.4g}{WALL:10.4g}{WALL:10.4g}
*SECTION_SOLID
$ fully integrated: the post's nodes press the soil's faces at points, and one-point hexes
$ put as much energy into hourglass control as into the soil (ELFORM 1: 71 of 147 J at 10 ms)
$    secid    elform
         2         2
*SECTION_SHELL
         3         2       1.0         2
{BUMPER_T:10.4g}{BUMPER_T:10.4g}{BUMPER_T:10.4g}{BUMPER_T:10.4g}
*MAT_PIECEWISE_LINEAR_PLASTICITY
$      mid        ro         e        pr      sigy      etan
         1{STEEL["rho"]:10.4g}{STEEL["E"]:10.4g}{STEEL["nu"]:10.4g}{STEEL["sigy"]:10.4g}{STEEL["etan"]:10.4g}
*MAT_SOIL_AND_FOAM
$      mid        ro         g       kun        a0        a1        a2        pc
         2{SOIL["rho"]:10.4g}{SOIL["G"]:10.4g}{k:10.4g}{a0:10.4g}{a1:10.4g}{a2:10.4g}       0.0
$      vcr       ref
       0.0       0.0
$     eps1      eps2
       0.0      -0.1

$       p1        p2
       0.0{0.1 * k:10.4g}

*MAT_RIGID
$      mid        ro         e        pr         n    couple         m     alias
         3{density:10.4g}{STEEL["E"]:10.4g}{STEEL["nu"]:10.4g}
$      cmo      con1      con2: y and z translations and all rotations held (a bogie on a
$ straight line)
       1.0         5         7
*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID
$      cid heading
         1bumper to post
$     ssid      msid     sstyp     mstyp
         3         1         3         3
$ VDC 100 (critical damping of the normal spring): a plastic impact, as of a crushable bumper;
$ undamped, the rigid plate throws the 9.7 kg post ahead of it at twice its speed
$       fs        fd        dc        vc       vdc
       0.0       0.0       0.0       0.0     100.0
*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID
         2post to soil
         1         2         3         3
       0.0       0.0
*LOAD_BODY_Z
$     lcid        sf
         1{GRAVITY:10.4g}
*DEFINE_CURVE
         1
                 0.0                 0.0
{RAMP:20.6g}                 1.0
                 1.0                 1.0
*INITIAL_VELOCITY
$     nsid
         4
$       vx        vy        vz
{SPEED:10.4g}       0.0       0.0
{node_set(4, bumper_nodes, "bumper")}{boundary_sets(mesh, s)}{mesh.keyword_text()}*END
"""
