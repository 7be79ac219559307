#!/usr/bin/env python3
"""Writes a synthetic vehicle-scale shell model: a boxy body-in-white of thin-walled steel
tubes and panels driven into a rigid wall at 56.3 km/h (35 mph), with single-surface contact
over the structure (issue 15's benchmark deck and issue 18's frontal_wall example).

usage: make_vehicle.py OUT.k [--scale S] [--end T] [--d3plot DT]

Units: mm, ms, kg, GPa (force kN, energy J, velocity m/s = mm/ms). The vehicle points along -x,
the wall is the plane x = 0 and the bumper starts 10 mm from it.

Structure (every part a *MAT_024 steel of its own thickness, Belytschko-Tsay shells, NIP 3,
stiffness hourglass control IHQ 4): a box-section bumper beam, two crash boxes and two front
rails (80 x 120 mm tubes, with crush triggers: rows of nodes dented inward), rails continued
under the floor as closed hats, two upper ("shotgun") rails, a firewall, a floor, rockers
(sills), A-, B- and C-pillars, a roof ring (headers and side rails) and a roof panel. The
engine is a rigid box (200 kg) held by four rail nodes (*CONSTRAINED_EXTRA_NODES_SET); the rear
of the body (floor, sills and rear panel behind x = 2600 mm) is a rigid part carrying the
rest of the 1500 kg. Parts are joined by shared nodes: every panel is an axis-aligned
rectangle between "stations" (the coordinates that bound some part), each interval between
two stations is cut into the same number of elements wherever it appears, so meeting edges
have the same nodes.

Element size is 12.5 mm x S in the crush zone (x < 1070 mm) and twice that along x behind it:
the default (S = 1) gives about 68,000 shells, S = 4 about 5,000.
The model is deterministic: the same arguments write the same bytes.
"""

from __future__ import annotations

import argparse
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from deckgen import Mesh, node_set  # noqa: E402

SPEED = 15.65  # 56.3 km/h in mm/ms
TOTAL_MASS = 1500.0  # kg
ENGINE_MASS = 200.0  # kg
RHO = 7.85e-6  # kg/mm^3

# Parts: id -> (name, thickness mm, material id). Materials 1 mild steel, 2 high-strength
# steel (rails, crash boxes, bumper, pillars), 3 rigid engine, 4 rigid rear body.
PARTS = {
    1: ("bumper beam", 2.0, 2), 2: ("crash boxes", 1.5, 1), 3: ("front rails", 2.5, 2),
    4: ("floor rails", 2.0, 2), 5: ("upper rails", 1.5, 1), 6: ("firewall", 1.0, 1),
    7: ("floor", 0.8, 1), 8: ("rockers", 1.5, 2), 9: ("pillars", 1.5, 2),
    10: ("roof rails and headers", 1.2, 1), 11: ("roof", 0.7, 1),
    12: ("engine (rigid)", 2.0, 3), 13: ("rear body (rigid)", 2.0, 4),
}
DEFORMABLE = list(range(1, 12))


class Body:
    """The station grid and the mesh: nodes keyed by their (i, j, k) grid indices, so that two
    panels meeting along a grid line share its nodes."""

    def __init__(self, size: float, stations) -> None:
        # Along x the cabin (behind the A-pillars) is meshed twice as coarsely as the crush
        # zone in front, as crash models are: elements of two sizes and aspect ratios up to 2.
        self.axes = [refine(sorted(set(s)), size, COARSE_X if a == 0 else float("inf"))
                     for a, s in enumerate(stations)]
        self.where = [{round(c, 6): i for i, c in enumerate(a)} for a in self.axes]
        self.mesh = Mesh()
        self.ids: dict[tuple[int, int, int], int] = {}
        self.part_nodes: dict[int, set[int]] = {}

    def node(self, key) -> int:
        if key not in self.ids:
            self.ids[key] = self.mesh.add_node(*(self.axes[a][key[a]] for a in range(3)))
        return self.ids[key]

    def index(self, axis: int, value: float) -> int:
        return self.where[axis][round(value, 6)]

    def nearest(self, axis: int, value: float) -> int:
        a = self.axes[axis]
        return min(range(len(a)), key=lambda i: abs(a[i] - value))

    def plate(self, part: int, axis: int, value: float, r1, r2) -> None:
        """The rectangle axis = value spanning r1 and r2 on the two other axes (in order)."""
        b, c = [x for x in range(3) if x != axis]
        k = self.index(axis, value)
        for i in range(self.index(b, r1[0]), self.index(b, r1[1])):
            for j in range(self.index(c, r2[0]), self.index(c, r2[1])):
                corners = []
                for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                    key = [0, 0, 0]
                    key[axis], key[b], key[c] = k, i + di, j + dj
                    corners.append(self.node(tuple(key)))
                self.mesh.add_shell(part, corners)
                self.part_nodes.setdefault(part, set()).update(corners)

    def tube(self, part: int, axis: int, span, r1, r2, walls=(0, 1, 2, 3)) -> None:
        """A rectangular tube along `axis` over `span` with cross-section r1 x r2 (the other
        axes in order); `walls` picks the faces (0, 1: r1 low/high; 2, 3: r2 low/high)."""
        b, c = [x for x in range(3) if x != axis]
        for w in walls:
            fixed, value = (b, r1[w]) if w < 2 else (c, r2[w - 2])
            ranges = {axis: span, b: r1, c: r2}
            other = [x for x in range(3) if x != fixed]
            self.plate(part, fixed, value, ranges[other[0]], ranges[other[1]])


def refine(stations: list[float], size, coarse_from: float = float("inf")) -> list[float]:
    """The grid coordinates: every interval between stations cut into round(length / size)
    (at least one) equal elements, twice `size` from `coarse_from` on."""
    out = [stations[0]]
    for a, b in zip(stations, stations[1:]):
        n = max(1, round((b - a) / (size if a < coarse_from else 2.0 * size)))
        out += [a + (b - a) * i / n for i in range(1, n + 1)]
    return out


def sym(lo: float, hi: float):
    """The ranges (lo, hi) and (-hi, -lo): a part and its mirror image across y = 0."""
    return ((lo, hi), (-hi, -lo))


# Stations (mm). x: bumper 10-90, crash boxes 90-290, rails 290-990, engine 350-850, firewall
# and A-pillars 990-1070, B-pillars 1800-1880, C-pillars 2520-2600, rear body 2600-3000.
# y: rockers and pillars 620-700, rails 410-490, engine -300..300. z: rockers 150-280, floor
# and rails 280-400, engine 200-600, upper rails 680-760, firewall top 900, roof rails 1120-1200.
X_ST = [10, 90, 290, 350, 850, 990, 1070, 1800, 1880, 2520, 2600, 3000]
Y_ST = [-700, -620, -490, -410, -300, 0, 300, 410, 490, 620, 700]
Z_ST = [150, 200, 280, 400, 600, 680, 760, 900, 1120, 1200]
COARSE_X = 1070  # x from which elements are twice as long


def front_structure(v: Body) -> None:
    v.tube(1, 1, (-700, 700), (10, 90), (280, 400))
    for ys in sym(410, 490):
        v.tube(2, 0, (90, 290), ys, (280, 400))
        v.tube(3, 0, (290, 990), ys, (280, 400))
        v.tube(4, 0, (990, 2600), ys, (280, 400), walls=(0, 1, 3))  # a hat on the floor
    for ys in sym(620, 700):
        v.tube(5, 0, (290, 990), ys, (680, 760))


def cabin(v: Body) -> None:
    v.plate(6, 0, 990, (-620, 620), (280, 900))
    v.plate(7, 2, 280, (990, 2600), (-620, 620))
    for ys in sym(620, 700):
        v.tube(8, 0, (990, 2600), ys, (150, 280))
        for xs, top in (((990, 1070), 1200), ((1800, 1880), 1120), ((2520, 2600), 1200)):
            v.tube(9, 2, (280, top), xs, ys)
        v.tube(10, 0, (1070, 2520), ys, (1120, 1200))
    for xs in ((990, 1070), (2520, 2600)):
        v.tube(10, 1, (-620, 620), xs, (1120, 1200))
    v.plate(11, 2, 1200, (1070, 2520), (-620, 620))


def rigid_parts(v: Body) -> None:
    v.tube(12, 0, (350, 850), (-300, 300), (200, 600))
    v.plate(12, 0, 350, (-300, 300), (200, 600))
    v.plate(12, 0, 850, (-300, 300), (200, 600))
    v.plate(13, 2, 280, (2600, 3000), (-620, 620))
    v.plate(13, 0, 3000, (-620, 620), (280, 900))
    for ys in sym(620, 700):
        v.tube(13, 0, (2600, 3000), ys, (150, 280))
    for ys in sym(410, 490):
        v.tube(13, 0, (2600, 3000), ys, (280, 400), walls=(0, 1, 3))


def add_triggers(v: Body, depth: float) -> None:
    """Crush triggers: at x = 150 (crash boxes) and x = 450 (rails) the interior nodes of the
    top and bottom walls, and at x = 200 and 600 those of the side walls, are pushed `depth`
    into the tube, so that the folds start there (alternating walls, as stamped beads do)."""
    m = v.mesh
    for ys in sym(410, 490):
        for x, axis in ((150, 2), (450, 2), (200, 1), (600, 1)):
            i = v.nearest(0, x)
            lo_hi = {1: ys, 2: (280, 400)}[axis]
            other = 3 - axis
            o_lo, o_hi = {1: ys, 2: (280, 400)}[other]
            for side, sign in ((lo_hi[0], 1.0), (lo_hi[1], -1.0)):
                s = v.index(axis, side)
                for j in range(v.index(other, o_lo) + 1, v.index(other, o_hi)):
                    key = [i, 0, 0]
                    key[axis], key[other] = s, j
                    n = v.ids[tuple(key)] - 1
                    p = list(m.nodes[n])
                    p[axis] += sign * depth
                    m.nodes[n] = tuple(p)


def build(scale: float) -> Body:
    v = Body(12.5 * scale, (X_ST, Y_ST, Z_ST))
    front_structure(v)
    cabin(v)
    rigid_parts(v)
    add_triggers(v, 3.0)
    return v


def part_areas(v: Body) -> dict[int, float]:
    areas: dict[int, float] = {}
    for part, ns in v.mesh.shells:
        p = [v.mesh.nodes[n - 1] for n in ns]
        d1 = [p[2][a] - p[0][a] for a in range(3)]
        d2 = [p[3][a] - p[1][a] for a in range(3)]
        cr = (d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0])
        areas[part] = areas.get(part, 0.0) + 0.5 * sum(c * c for c in cr) ** 0.5
    return areas


def engine_mounts(v: Body) -> list[int]:
    """The rail nodes that hold the engine: on each rail's inner wall at x = 450 and 750,
    mid-height."""
    out = []
    for y in (-410, 410):
        for x in (450, 750):
            out.append(v.ids[v.nearest(0, x), v.index(1, y), v.nearest(2, 340)])
    return out


def materials(rigid_density) -> str:
    """Mild steel (yield 0.21 GPa) and a high-strength steel (0.35 GPa), linear hardening,
    Cowper-Symonds rate factor C = 40.4 /s, P = 5 (Jones, Structural Impact, for mild steel);
    the two rigid parts have the densities that give their masses."""
    out = ["$ mild and high-strength steel: mid ro e pr sigy etan fail tdel / c p lcss lcsr vp"]
    for mid, sigy, etan in ((1, 0.21, 0.6), (2, 0.35, 0.8)):
        out += ["*MAT_PIECEWISE_LINEAR_PLASTICITY", f"{mid:10d}{RHO:10.4g}     210.0       0.3"
                f"{sigy:10.4g}{etan:10.4g}", "    0.0404       5.0"]
    for mid, ro in rigid_density:
        out += ["*MAT_RIGID", f"{mid:10d}{ro:10.4g}     210.0       0.3", "       0.0       0.0       0.0"]
    return "\n".join(out) + "\n"


def parts_text() -> str:
    out = ["*PART"]
    for pid, (name, _, mid) in PARTS.items():
        out += [name, f"{pid:10d}{pid:10d}{mid:10d}{0:10d}{1 if mid < 3 else 0:10d}"]
    out.append("$ one shell section per part: Belytschko-Tsay, NIP 3, the part's thickness")
    for pid, (_, t, _) in PARTS.items():
        out += ["*SECTION_SHELL", f"{pid:10d}         2       1.0         3", f"{t:10.4g}" * 4]
    out += ["*HOURGLASS", "         1         4      0.05"]
    return "\n".join(out) + "\n"


def part_set(set_id: int, parts: list[int]) -> str:
    out = ["*SET_PART_LIST", f"{set_id:10d}"]
    for i in range(0, len(parts), 8):
        out.append("".join(f"{p:10d}" for p in parts[i:i + 8]))
    return "\n".join(out) + "\n"


def controls(end: float, d3plot: float | None) -> str:
    dt_out = min(0.1, end / 20)
    text = f"""*CONTROL_TERMINATION
{end:10.6g}
*DATABASE_GLSTAT
{dt_out:10.4g}
*DATABASE_MATSUM
{dt_out:10.4g}
*DATABASE_RWFORC
{dt_out / 4:10.4g}
*DATABASE_NODOUT
{dt_out / 4:10.4g}
"""
    if d3plot:
        text += f"*DATABASE_BINARY_D3PLOT\n{d3plot:10.4g}\n"
    return text


def deck(scale: float, end: float, d3plot: float | None = None) -> str:
    v = build(scale)
    areas = part_areas(v)
    deformable = sum(areas[p] * PARTS[p][1] * RHO for p in DEFORMABLE)
    engine_ro = ENGINE_MASS / (areas[12] * PARTS[12][1])
    rear_ro = (TOTAL_MASS - ENGINE_MASS - deformable) / (areas[13] * PARTS[13][1])
    mounts = engine_mounts(v)
    rear = v.ids[v.nearest(0, 2800), v.index(1, 0), v.index(2, 280)]
    engine_nodes = sorted(v.part_nodes[12])
    return f"""*KEYWORD
*TITLE
synthetic vehicle into a rigid wall at 56.3 km/h, element size {12.5 * scale:g} mm (mm, ms, kg, GPa)
{controls(end, d3plot)}*DATABASE_HISTORY_NODE
{rear:10d}
{parts_text()}{materials([(3, engine_ro), (4, rear_ro)])}{part_set(1, DEFORMABLE + [12])}\
*CONTACT_AUTOMATIC_SINGLE_SURFACE_ID
         1single surface over the structure and the engine
         1         0         2         0
       0.1       0.1
*CONSTRAINED_EXTRA_NODES_SET
        12         2
*RIGIDWALL_PLANAR_ID
         1
         0         3
       0.0       0.0       0.0       1.0       0.0       0.0
*INITIAL_VELOCITY
         0
{-SPEED:10.4g}       0.0       0.0
{node_set(2, mounts, "engine mounts")}{node_set(3, engine_nodes, "engine (not held by the wall)")}\
{v.mesh.keyword_text()}*END
"""


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("out", type=pathlib.Path)
    ap.add_argument("--scale", type=float, default=1.0, help="element size 12.5 mm x SCALE")
    ap.add_argument("--end", type=float, default=80.0, help="end time, ms (default 80)")
    ap.add_argument("--d3plot", type=float, default=None, help="d3plot interval, ms")
    a = ap.parse_args()
    text = deck(a.scale, a.end, a.d3plot)
    a.out.write_text(text)
    shells = text.count("\n", text.index("*ELEMENT_SHELL"), text.index("*END")) - 1
    print(f"wrote {a.out}: {shells} shells")


if __name__ == "__main__":
    main()
