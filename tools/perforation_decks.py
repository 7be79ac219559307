#!/usr/bin/env python3
"""Decks for the perforation verification (tests/verification/test_perforation.py): a rigid
blunt cylinder striking a clamped Johnson-Cook steel plate at normal incidence, a quarter
model on the symmetry planes x = 0 and y = 0, the plate eroding under
*CONTACT_ERODING_SURFACE_TO_SURFACE.

  python3 tools/perforation_decks.py OUT.k [--v0 300] [--end 0.12]

The set-up follows Børvik et al.'s blunt-projectile tests on 12 mm Weldox 460 E plates
(Int. J. Impact Eng. 27 (2002) 19; as recalled, the paper not at hand: the projectile 20 mm
across, 80 mm long, 197 g, the plate clamped at 500 mm diameter), here with the plate
clamped at 100 mm diameter (perforation by plugging is local: what the plate does beyond a
few thicknesses changes the residual velocity little; not checked here) and a coarse mesh.
Units mm, ms, kg, GPa (m/s = mm/ms, J = kN mm).
"""

from __future__ import annotations

import argparse
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from deckgen import Mesh, node_set, quarter_annulus, quarter_cylinder  # noqa: E402

# The projectile: a hardened steel cylinder 80 mm long, here rigid (*MAT_RIGID), radius mm,
# mass kg (the full projectile's). Rigid, with its rotations and lateral motion held, only its
# mass and its nose matter: the mesh is a 20 mm stub with the density that gives that mass
# (fewer segments for the contact search).
PROJECTILE = {"radius": 10.0, "length": 20.0, "mass": 0.197}
# The plate's part in contact: the elements inside this radius, mm (where the projectile can
# reach); the rest of the plate is part 3, the same material.
CONTACT_RADIUS = 14.5

# Weldox 460 E (Børvik, Hopperstad, Berstad, Langseth, Eur. J. Mech. A/Solids 20 (2001) 685,
# the Johnson-Cook fit of their perforation simulations, as recalled: check against the
# paper before relying on them; their rate term is (1 + eps_dot*)^C, *MAT_015's
# 1 + C ln eps_dot*, and they heat with 0.9 of the plastic work, Crumple with all of it), in
# mm, ms, kg, GPa, K:
# E 200 GPa, nu 0.33, A 490 MPa, B 807 MPa, n 0.73, C 0.0114 at EPSO 5e-4 /s, m 0.94,
# Tm 1800 K, Tr 293 K, cp 452 J/(kg K); fracture strain D1-D4 (D5 = 0).
WELDOX = {"rho": 7.85e-6, "E": 200.0, "nu": 0.33, "A": 0.490, "B": 0.807, "n": 0.73,
          "C": 0.0114, "m": 0.94, "Tm": 1800.0, "Tr": 293.0, "epso": 5.0e-7, "cp": 452.0,
          "D": (0.0705, 1.732, -0.54, -0.015, 0.0)}


def projectile_density() -> float:
    """The stub's density, kg/mm^3, that gives the quarter model a quarter of the projectile's
    mass (to the butterfly's chords: the test takes the mass from the run)."""
    p = PROJECTILE
    return p["mass"] / (math.pi * p["radius"] ** 2 * p["length"])


def plug_mass(thickness: float = 12.0) -> float:
    """The quarter model's plug, kg: the plate's cylinder under the projectile."""
    return WELDOX["rho"] * math.pi * PROJECTILE["radius"] ** 2 * thickness / 4.0


def _merge_coincident(m: Mesh, first: int) -> int:
    """Merges nodes from index `first` on that lie on one point (the annulus's inner ring on
    the core cylinder's rim); returns how many were merged. Node ids are renumbered."""
    keep, where, remap = [], {}, {}
    for i, p in enumerate(m.nodes, start=1):
        key = tuple(round(c, 5) for c in p) if i > first else ("own", i)
        if key in where:
            remap[i] = where[key]
            continue
        keep.append(p)
        where[key] = len(keep)
        remap[i] = len(keep)
    merged = len(m.nodes) - len(keep)
    m.nodes = keep
    m.solids = [(part, [remap[n] for n in ns]) for part, ns in m.solids]
    return merged


def _centroid_radius(m: Mesh, ns: list[int]) -> float:
    return math.hypot(sum(m.nodes[n - 1][0] for n in ns) / 8,
                      sum(m.nodes[n - 1][1] for n in ns) / 8)


def plate(m: Mesh, part: int, thickness: float, hole_radius: float, outer: list[float],
          n_core: int, n_ring: int, n_layers: int) -> None:
    """A quarter disc of hexes, z in [0, thickness]: a butterfly cylinder of radius
    hole_radius (the plug under the projectile) inside an annulus through the radii `outer`,
    2 n_core sectors over 90 degrees in both, so that their nodes meet on the rim."""
    first = len(m.nodes)
    quarter_cylinder(m, part, hole_radius, thickness, n_core, n_ring, n_layers)
    levels = [thickness * k / n_layers for k in range(n_layers + 1)]
    quarter_annulus(m, part, [hole_radius] + outer, 2 * n_core, levels)
    rim = (2 * n_core + 1) * (n_layers + 1)
    merged = _merge_coincident(m, first)
    if merged != rim:
        raise AssertionError(f"merged {merged} rim nodes, expected {rim}")


def perforation(v0: float = 300.0, end: float = 0.12, gap: float = 0.2, n_core: int = 8,
                n_ring: int = 3, n_layers: int = 12, erosion: bool = True,
                plate_radius: float = 50.0, projectile_layers: int = 16,
                refine: int = 1, sfs: float = 5.0) -> str:
    """The deck: the rigid projectile (part 1) `gap` mm above the plate (part 2, z in
    [0, 12], impact face z = 12) moving at -v0 along z. `erosion` False takes the damage out
    of the plate's law (D1 = D2 = 0: no element erodes), for the test that can fail.
    `projectile_layers`: the stub's elements along its axis (16: 1.25 mm, about the plate's
    1 mm; the penalty stiffness of its faces goes as their area squared over the element's
    volume, so deeper elements make a softer nose). `refine`: the sectors, the layers through
    the thickness, the radial divisions inside r = CONTACT_RADIUS and the projectile's
    sections and layers times this (the radii outside unchanged), for the mesh study of
    docs/validation.md. `sfs`: the contact's SFSA = SFSB, the scale on SLSFAC 0.1 K A^2 / V.
    With 1 the nose's nodes sink up to half a plate element into the plug at 500-600 m/s (the
    depth at which a node leaves a solid face) and the energy ratio drifts 1 % at 250 m/s;
    5 puts the stiffness at the stability cap of src/contact/penalty.cpp (0.1 m / dt^2, about
    0.19 K A^2 / V for these elements: so any SFS above about 2 gives the same run)."""
    t = 12.0
    m = Mesh()
    # The annulus radii: 1 mm steps out of the shear zone at r = 10, then growing to the clamp.
    inner = [11.0, 12.0, 13.0, 14.5]
    inner = [a + (b - a) * k / refine for a, b in zip([10.0] + inner, inner)
             for k in range(1, refine + 1)]
    outer = inner + [16.5, 19.0, 22.5, 27.0, 33.0, 41.0, plate_radius]
    n_core, n_ring, n_layers = refine * n_core, refine * n_ring, refine * n_layers
    projectile_layers *= refine
    plate(m, 2, t, PROJECTILE["radius"], outer, n_core, n_ring, n_layers)
    m.solids = [(3 if _centroid_radius(m, ns) > CONTACT_RADIUS else part, ns)
                for part, ns in m.solids]
    n_plate = len(m.nodes)
    first = len(m.nodes)
    quarter_cylinder(m, 1, PROJECTILE["radius"], PROJECTILE["length"], n_core, 2,
                     projectile_layers)
    m.nodes[first:] = [(x, y, z + t + gap) for x, y, z in m.nodes[first:]]
    eps = 1e-6
    plate_ids = range(1, n_plate + 1)
    on_x0 = [i for i in plate_ids if abs(m.nodes[i - 1][0]) < eps]
    on_y0 = [i for i in plate_ids if abs(m.nodes[i - 1][1]) < eps]
    rim = [i for i in plate_ids if math.hypot(*m.nodes[i - 1][:2]) > plate_radius - eps]
    rod = list(range(first + 1, len(m.nodes) + 1))
    # History nodes: the projectile's nose centre and the plate's exit-face centre.
    nose = min(rod, key=lambda i: (m.nodes[i - 1][2], math.hypot(*m.nodes[i - 1][:2])))
    back = min(plate_ids, key=lambda i: (m.nodes[i - 1][2], math.hypot(*m.nodes[i - 1][:2])))
    w = WELDOX
    d = w["D"] if erosion else (0.0, 0.0, 0.0, 0.0, 0.0)
    G = w["E"] / (2.0 * (1.0 + w["nu"]))
    K = w["E"] / (3.0 * (1.0 - 2.0 * w["nu"]))
    return f"""*KEYWORD
*TITLE
rigid blunt projectile at {v0:g} m/s on 12 mm Weldox 460 E (quarter; mm ms kg GPa)
*CONTROL_TERMINATION
{end:10.4g}
*CONTROL_HOURGLASS
$      ihq        qh
         5       0.1
*DATABASE_GLSTAT
    0.0025
*DATABASE_MATSUM
    0.0025
*DATABASE_RCFORC
   0.00005
*DATABASE_NODOUT
    0.0025
*DATABASE_HISTORY_NODE
{nose:10d}{back:10d}
*PART
projectile (rigid)
         1         1         1
*PART
plate inside r = {CONTACT_RADIUS:g} mm, in contact (Weldox 460 E, Johnson-Cook with damage)
         2         1         2         2
*PART
plate outside r = {CONTACT_RADIUS:g} mm
         3         1         2         2
*SECTION_SOLID
         1         1
*MAT_RIGID
$      mid        ro         e        pr
         1{projectile_density():10.4g}     210.0       0.3
$      cmo      con1      con2
       1.0         4         7
*MAT_JOHNSON_COOK
$      mid        ro         g         e        pr
         2{w['rho']:10.4g}{G:10.5g}{w['E']:10.5g}{w['nu']:10.4g}
$        a         b         n         c         m        tm        tr      epso
{w['A']:10.4g}{w['B']:10.4g}{w['n']:10.4g}{w['C']:10.4g}{w['m']:10.4g}{w['Tm']:10.5g}{w['Tr']:10.5g}{w['epso']:10.4g}
$       cp        pc     spall        it        d1        d2        d3        d4
{w['cp']:10.4g}     -10.0       1.0       0.0{d[0]:10.4g}{d[1]:10.4g}{d[2]:10.4g}{d[3]:10.4g}
$       d5
{d[4]:10.4g}
*EOS_LINEAR_POLYNOMIAL
$    eosid        c0        c1
         2       0.0{K:10.5g}
*CONTACT_ERODING_SURFACE_TO_SURFACE_ID
         1
$    surfa     surfb   surfatyp  surfbtyp
         2         1         3         3
$       fs        fd
       0.0       0.0
$      sfsa      sfsb
{sfs:10.4g}{sfs:10.4g}
$     isym    erosop      iadj
         0         1         0
*INITIAL_VELOCITY_NODE
""" + "".join(f"{i:10d}{0.0:10.4g}{0.0:10.4g}{-v0:10.4g}\n" for i in rod) + \
        node_set(1, on_x0, "plate on x = 0") + node_set(2, on_y0, "plate on y = 0") + \
        node_set(3, rim, "plate clamped rim") + \
        "*BOUNDARY_SPC_SET\n         1         0         1         0         0\n" + \
        "         2         0         0         1         0\n" + \
        "         3         0         1         1         1\n" + m.keyword_text() + "*END\n"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("out", type=pathlib.Path)
    ap.add_argument("--v0", type=float, default=300.0)
    ap.add_argument("--end", type=float, default=0.12)
    ap.add_argument("--no-erosion", action="store_true")
    a = ap.parse_args()
    a.out.write_text(perforation(a.v0, a.end, erosion=not a.no_erosion))


if __name__ == "__main__":
    main()
