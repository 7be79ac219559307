"""Decks of a T-joint for *CONTACT_TIED_SHELL_EDGE_TO_SURFACE (docs/theory.md, "Tied shell
edges"), for tests/verification/test_tied_edge.py and the rank determinism case
tests/data/decks/contact_tied_edge.k (written by `python3 tools/tied_edge_decks.py`).

mm, ms, kg, kN (GPa). A plate of shells in the x-y plane (z = 0, 40 x 40, 2 mm thick) and a
strip of shells standing on it in the x-z plane (y = 0, 20 wide, 50 tall, 1 mm thick, Poisson's
ratio 0 so that beam theory is exact for it). The strip's top edge is pushed sideways (y) by a
force ramped up and held; *DAMPING_GLOBAL brings it to rest. The strip's bottom edge is either
tied to the plate (its own nodes, on the plate's nodes) or merged with it (the plate's nodes):
without the rotational tie the edge is a hinge and the strip falls over.
"""

import os
import sys

E, RHO = 210.0, 7.85e-6
T_PLATE, T_STRIP = 2.0, 1.0
WIDTH, HEIGHT = 20.0, 50.0  # the strip
H = 5.0  # element size
PLATE_N = 8  # elements along each side of the plate (40 mm)
STRIP_NX, STRIP_NZ = 4, 10


def tip_deflection_theory(force):
    """Cantilever tip deflection F L^3 / (3 E I), I = w t^3 / 12 (shear deflection < 0.1%)."""
    inertia = WIDTH * T_STRIP**3 / 12.0
    return force * HEIGHT**3 / (3.0 * E * inertia)


def _plate_node(i, j):
    return 1 + i + (PLATE_N + 1) * j


def _strip_node(i, k, merged):
    # The bottom row (k = 0) is the plate's row y = 0 when merged.
    if k == 0 and merged:
        return _plate_node(2 + i, PLATE_N // 2)
    return 1001 + i + (STRIP_NX + 1) * k


def tip_node():
    return _strip_node(STRIP_NX // 2, STRIP_NZ, False)


def t_joint(merged=False, support="clamped", force=0.01, ramp=6.0, end=20.0, damping=1.0,
            contact="*CONTACT_TIED_SHELL_EDGE_TO_SURFACE_ID", dt_out=0.5, gap=0.0, sst=None):
    """support: "clamped" (every plate node held: a rigid base) or "edges" (the plate held at
    y = +-20 only, so that it bends under the strip's moment). `gap`: the strip stands that far
    above the plate; `sst`: the contact's card 3 SST if given (negative: a tie distance)."""
    nodes = {}
    for j in range(PLATE_N + 1):
        for i in range(PLATE_N + 1):
            nodes[_plate_node(i, j)] = (H * i, H * j - 20.0, 0.0)
    for k in range(STRIP_NZ + 1):
        for i in range(STRIP_NX + 1):
            nodes[_strip_node(i, k, merged)] = (10.0 + H * i, 0.0, H * k + gap)
    shells = []
    for j in range(PLATE_N):
        for i in range(PLATE_N):
            shells.append((1 + i + PLATE_N * j, 1, _plate_node(i, j), _plate_node(i + 1, j),
                           _plate_node(i + 1, j + 1), _plate_node(i, j + 1)))
    for k in range(STRIP_NZ):
        for i in range(STRIP_NX):
            shells.append((101 + i + STRIP_NX * k, 2, _strip_node(i, k, merged),
                           _strip_node(i + 1, k, merged), _strip_node(i + 1, k + 1, merged),
                           _strip_node(i, k + 1, merged)))
    if support == "clamped":
        held = sorted(_plate_node(i, j) for j in range(PLATE_N + 1) for i in range(PLATE_N + 1))
    else:
        held = sorted(_plate_node(i, j) for j in (0, PLATE_N) for i in range(PLATE_N + 1))
    top = [_strip_node(i, STRIP_NZ, merged) for i in range(STRIP_NX + 1)]
    edge = [_strip_node(i, 0, merged) for i in range(STRIP_NX + 1)]
    # The tip force shared as a consistent load along the top edge (ends take half).
    share = [0.5 if i in (0, STRIP_NX) else 1.0 for i in range(STRIP_NX + 1)]
    per = force / sum(share)

    def node_list(sid, ids):
        # Eight ids a line (the card's eight fields).
        rows = "".join(",".join(str(n) for n in ids[k:k + 8]) + "\n" for k in range(0, len(ids), 8))
        return f"*SET_NODE_LIST\n{sid}\n{rows}"

    s = f"""*KEYWORD
*TITLE
T-joint: a strip's edge {'merged with' if merged else 'tied to'} a plate, pushed at its top
*CONTROL_TERMINATION
{end}
*DATABASE_GLSTAT
{dt_out}
*DATABASE_NODOUT
{dt_out}
*DATABASE_RCFORC
{dt_out}
*DATABASE_HISTORY_NODE
{tip_node()}
*PART
plate
1,1,1
*PART
strip
2,2,2
*SECTION_SHELL
1,2,0.8333,2
{T_PLATE},{T_PLATE},{T_PLATE},{T_PLATE}
*SECTION_SHELL
2,2,0.8333,2
{T_STRIP},{T_STRIP},{T_STRIP},{T_STRIP}
*MAT_ELASTIC
1,{RHO},{E},0.3
*MAT_ELASTIC
2,{RHO},{E},0.0
*DAMPING_GLOBAL
0,{damping}
*DEFINE_CURVE
1
0.0,0.0
{ramp},1.0
1000.0,1.0
*BOUNDARY_SPC_SET
1,0,1,1,1,1,1,1
"""
    s += node_list(1, held)
    for i, n in enumerate(top):
        s += f"*LOAD_NODE_POINT\n{n},2,1,{per * share[i]}\n"
    if not merged:
        s += node_list(2, edge)
        s += f"{contact}\n1,tee\n2,1,4,3\n"
        if sst is not None:
            s += f"0.0\n1.0,1.0,{sst},0.0\n"
    s += "*NODE\n" + "".join(f"{n},{x},{y},{z}\n" for n, (x, y, z) in sorted(nodes.items()))
    s += "*ELEMENT_SHELL\n" + "".join(",".join(str(v) for v in e) + "\n" for e in shells)
    return s + "*END\n"


if __name__ == "__main__":
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    path = os.path.join(root, "tests", "data", "decks", "contact_tied_edge.k")
    with open(path, "w", encoding="utf-8") as f:
        # The flexible plate, to the end of the ramp: the moment goes into the plate's rotations.
        f.write(t_joint(support="edges", end=3.0, dt_out=0.25))
    sys.stdout.write(f"wrote {path}\n")
