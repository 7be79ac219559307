"""Decks of two bonded blocks for *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK and
*CONTACT_TIEBREAK_NODES_TO_SURFACE (docs/theory.md, "Tiebreak"), for
tests/verification/test_tiebreak.py and the rank determinism case
tests/data/decks/contact_tiebreak.k (written by `python3 tools/tiebreak_decks.py`).

mm, ms, kg, kN (GPa). Two blocks of 2 x 2 x 1 hexahedra (10 x 10 x 5 each), one on the other
with their own nodes on the plane z = 5; Poisson's ratio 0, so that the blocks stretch and shear
uniformly. The lower block's bottom is held, the upper block's top driven at a speed ramped up
from rest (z: pulled apart; x: sheared). The bond area is 100 mm^2.
"""

import os
import sys

E, RHO = 210.0, 7.85e-6
H = 5.0
AREA = 100.0


def _node(i, j, k, upper):
    # k 0, 1 in each block; the upper block's nodes are numbered from 101.
    return (101 if upper else 1) + i + 3 * j + 9 * k


def _ids(ids):
    """Node ids eight a line (the card's eight fields)."""
    return "\n".join(",".join(str(n) for n in ids[k:k + 8]) for k in range(0, len(ids), 8))


def blocks(direction="z", speed=0.1, ramp=0.05, end=1.5, nfls=0.1, sfls=0.1, dt_out=0.005,
           nodes_to_surface=False, option=1):
    nodes, solids = {}, []
    for upper in (False, True):
        z0 = H if upper else 0.0
        for k in range(2):
            for j in range(3):
                for i in range(3):
                    nodes[_node(i, j, k, upper)] = (H * i, H * j, z0 + H * k)
        for j in range(2):
            for i in range(2):
                c = [_node(i, j, 0, upper), _node(i + 1, j, 0, upper),
                     _node(i + 1, j + 1, 0, upper), _node(i, j + 1, 0, upper)]
                top = [n + 9 for n in c]
                eid = (101 if upper else 1) + i + 2 * j
                solids.append((eid, 2 if upper else 1, *c, *top))
    bottom = [_node(i, j, 0, False) for j in range(3) for i in range(3)]
    top = [_node(i, j, 1, True) for j in range(3) for i in range(3)]
    dof = {"x": 1, "z": 3}[direction]
    if nodes_to_surface:
        bond = f"""*CONTACT_TIEBREAK_NODES_TO_SURFACE_ID
1,bond
3,1,4,3
0,0,0,0,0
1,1
{nfls * AREA},{sfls * AREA},2,2
"""
    else:
        bond = f"""*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK_ID
1,bond
2,1,3,3
0,0,0,0,0
1,1
{option},{nfls},{sfls}
"""
    s = f"""*KEYWORD
*TITLE
two bonded blocks pulled apart ({direction})
*CONTROL_TERMINATION
{end}
*DATABASE_GLSTAT
{dt_out}
*DATABASE_RCFORC
{dt_out}
*DATABASE_MATSUM
{dt_out}
*PART
lower block
1,1,1
*PART
upper block
2,1,1
*SECTION_SOLID
1,1
*MAT_ELASTIC
1,{RHO},{E},0.0
*DEFINE_CURVE
1
0.0,0.0
{ramp},{speed}
1000.0,{speed}
*BOUNDARY_SPC_SET
1,0,1,1,1,0,0,0
*SET_NODE_LIST
1
{_ids(bottom)}
*SET_NODE_LIST
2
{_ids(top)}
*BOUNDARY_PRESCRIBED_MOTION_SET
2,{dof},0,1,1.0
"""
    if direction == "x":  # simple shear: the top held in y and z
        s += "*BOUNDARY_SPC_SET\n2,0,0,1,1,0,0,0\n"
    if nodes_to_surface:
        upper_bottom = [_node(i, j, 0, True) for j in range(3) for i in range(3)]
        s += f"*SET_NODE_LIST\n3\n{_ids(upper_bottom)}\n"
    s += bond
    s += "*NODE\n" + "".join(f"{n},{x},{y},{z}\n" for n, (x, y, z) in sorted(nodes.items()))
    s += "*ELEMENT_SOLID\n" + "".join(",".join(str(v) for v in e) + "\n" for e in solids)
    return s + "*END\n"


if __name__ == "__main__":
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    path = os.path.join(root, "tests", "data", "decks", "contact_tiebreak.k")
    with open(path, "w", encoding="utf-8") as f:
        # Pulled apart past the failure, the blocks then sliding back into contact is not
        # reached: short, for the rank determinism test.
        f.write(blocks(end=1.2, dt_out=0.05))
    sys.stdout.write(f"wrote {path}\n")
