"""Decks of segment-based contact (SOFT = 2) for tests/verification/test_segment_contact.py and
the rank determinism case tests/data/decks/contact_soft2.k (written by
`python3 tools/segment_contact_decks.py`).

Steel, SI units. The penalty stiffness of a segment pair is
k = 0.5 x SLSFAC x SFS x m1 m2 / (m1 + m2) / dt^2 (docs/theory.md, "Segment-based contact"),
m1 and m2 the nodal masses interpolated at the two contact points, dt the initial step.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from beam_contact_decks import _header  # noqa: E402  (the same output requests)

E, NU, RHO = 2.0e11, 0.3, 7850.0
SLSFAC = 0.1


def pair_stiffness(m1, m2, dt, sfs=1.0):
    return 0.5 * SLSFAC * sfs * m1 * m2 / (m1 + m2) / (dt * dt)


def _contact(soft=2, fs=0.0, fd=0.0, vdc=0.0):
    # Single surface over every part (SSTYP 5, SSID 0); card A: SOFT.
    return f"""*CONTACT_AUTOMATIC_SINGLE_SURFACE_ID
1
0,0,5,0
{fs},{fd},0,0,{vdc}
1,1
{soft}
"""


class Mesh:
    def __init__(self):
        self.nodes, self.solids, self.shells = {}, [], []

    def node(self, x, y, z):
        nid = len(self.nodes) + 1
        self.nodes[nid] = (x, y, z)
        return nid

    def block(self, part, x0, y0, z0, a, n=1):
        """A cube of side a, n x n x n hexahedra, corner at (x0, y0, z0); its node ids."""
        h = a / n
        ids = {}
        for k in range(n + 1):
            for j in range(n + 1):
                for i in range(n + 1):
                    ids[i, j, k] = self.node(x0 + i * h, y0 + j * h, z0 + k * h)
        for k in range(n):
            for j in range(n):
                for i in range(n):
                    c = [ids[i, j, k], ids[i + 1, j, k], ids[i + 1, j + 1, k], ids[i, j + 1, k],
                         ids[i, j, k + 1], ids[i + 1, j, k + 1], ids[i + 1, j + 1, k + 1],
                         ids[i, j + 1, k + 1]]
                    self.solids.append((part, c))
        return sorted(ids.values())

    def sheet(self, part, origin, u, v, nu=1, nv=1):
        """A flat sheet origin + s u + t v, s, t in [0, 1], nu x nv quads; its node ids."""
        ids = {}
        for j in range(nv + 1):
            for i in range(nu + 1):
                ids[i, j] = self.node(*[o + i / nu * a + j / nv * b for o, a, b in zip(origin, u, v)])
        for j in range(nv):
            for i in range(nu):
                self.shells.append((part, [ids[i, j], ids[i + 1, j], ids[i + 1, j + 1],
                                           ids[i, j + 1]]))
        return sorted(ids.values())

    def text(self):
        out = "*NODE\n" + "".join(f"{n},{x!r},{y!r},{z!r}\n" for n, (x, y, z) in self.nodes.items())
        if self.solids:
            out += "*ELEMENT_SOLID\n" + "".join(
                f"{e},{p}," + ",".join(map(str, c)) + "\n"
                for e, (p, c) in enumerate(self.solids, 1))
        if self.shells:
            out += "*ELEMENT_SHELL\n" + "".join(
                f"{e},{p}," + ",".join(map(str, c)) + "\n"
                for e, (p, c) in enumerate(self.shells, len(self.solids) + 1))
        return out


def _solid_parts(pids):
    out = "*SECTION_SOLID\n1,1\n"
    for p in pids:
        out += f"*PART\nblock {p}\n{p},1,{p}\n*MAT_ELASTIC\n{p},{RHO},{E},{NU}\n"
    return out


def _shell_parts(pids, t):
    out = f"*SECTION_SHELL\n2,2,0.8333,2\n{t},{t},{t},{t}\n"
    for p in pids:
        out += f"*PART\nsheet {p}\n{p},2,{p}\n*MAT_ELASTIC\n{p},{RHO},{E},{NU}\n"
    return out


def _prescribed(nodes, dof, curve):
    return "*BOUNDARY_PRESCRIBED_MOTION_NODE\n" + "".join(
        f"{n},{dof},0,{curve},1.0\n" for n in nodes)


def _curve(cid, v):
    return f"*DEFINE_CURVE\n{cid}\n0.0,{v}\n1.0,{v}\n"


def _spc(nodes):
    return "*BOUNDARY_SPC_NODE\n" + "".join(f"{n},0,1,1,1,1,1,1\n" for n in nodes)


A = 0.01  # block side


def pressed_blocks(gap, v, end, dt_out=1e-6, soft=2):
    """Block 1 (one hexahedron, side A) held; block 2 over it, gap above, driven down at v as a
    body (every node prescribed). Node 9 (a bottom corner of block 2) in nodout."""
    m = Mesh()
    lower = m.block(1, 0.0, 0.0, 0.0, A)
    upper = m.block(2, 0.0, 0.0, A + gap, A)
    text = _header("a block pressed on a block", end, dt_out, f"*DATABASE_HISTORY_NODE\n{upper[0]}\n")
    text += _solid_parts([1, 2]) + _contact(soft) + m.text() + _spc(lower)
    text += _prescribed(upper, 3, 1) + _curve(1, -v)
    for d in (1, 2):
        text += _prescribed(upper, d, 2)
    return text + _curve(2, 0.0) + "*END\n"


def colliding_blocks(gap, v, end, dt_out=2e-6, n=2):
    """Two free cubes of side A (n^3 hexahedra each), block 2 gap over block 1, flying down
    at v onto it."""
    m = Mesh()
    m.block(1, 0.0, 0.0, 0.0, A, n)
    upper = m.block(2, 0.0, 0.0, A + gap, A, n)
    text = _header("a block hitting a block", end, dt_out)
    text += _solid_parts([1, 2]) + _contact() + m.text()
    text += "*INITIAL_VELOCITY_NODE\n" + "".join(f"{i},0,0,{-v}\n" for i in upper)
    return text + "*END\n"


L, T = 0.1, 0.002  # sheet edge length and thickness


def crossing_edges(gap, v, end, dt_out=1e-6, soft=2):
    """Sheet 1 in the plane y = 0, x in [-L/2, L/2], z in [0, L], one quad, held; sheet 2 in
    the plane x = 0, y in [-L/2, L/2], z in [-L, 0] + h + gap (its top edge along y, gap over
    the contact thickness h = T above sheet 1's bottom edge... below: sheet 2's top edge is
    under sheet 1's bottom edge), driven up at v. The edges cross at x = y = 0 where neither
    has a node: node-to-segment contact sees nothing."""
    m = Mesh()
    held = m.sheet(1, (-0.5 * L, 0.0, 0.0), (L, 0.0, 0.0), (0.0, 0.0, L))
    top = -T - gap
    moved = m.sheet(2, (0.0, -0.5 * L, top - L), (0.0, L, 0.0), (0.0, 0.0, L))
    text = _header("a sheet's edge crossing another's", end, dt_out,
                   f"*DATABASE_HISTORY_NODE\n{moved[-1]}\n")
    text += _shell_parts([1, 2], T) + _contact(soft) + m.text() + _spc(held)
    text += _prescribed(moved, 3, 1) + _curve(1, v)
    for d in (1, 2):
        text += _prescribed(moved, d, 2)
    return text + _curve(2, 0.0) + "*END\n"


def determinism(end=2.5e-4, dt_out=2e-5):
    """A 4 x 4 sheet turned about x and y falling with friction and damping onto a plate of
    6 x 6 shells resting on two 2 x 2 x 2 blocks, a third block falling onto it too: many
    pairs of every kind (shell-shell face and edge, shell-solid, solid-solid), for the rank
    determinism test."""
    m = Mesh()
    m.block(1, 0.0, 0.0, 0.0, 0.02, 2)
    m.block(1, 0.04, 0.04, 0.0, 0.02, 2)
    plate = m.sheet(2, (0.0, 0.0, 0.021), (0.06, 0.0, 0.0), (0.0, 0.06, 0.0), 6, 6)
    c, s = 0.98, 0.2
    falling = m.sheet(3, (0.01, 0.01, 0.03), (0.04 * c, 0.0, 0.04 * s), (0.0, 0.04 * c, 0.04 * s),
                      4, 4)
    block = m.block(4, 0.044, 0.0, 0.024, 0.008, 2)
    text = _header("sheets and blocks falling on each other", end, dt_out)
    text += "*SECTION_SOLID\n1,1\n"
    for p in (1, 4):
        text += f"*PART\nblock {p}\n{p},1,{p}\n*MAT_ELASTIC\n{p},{RHO},{E},{NU}\n"
    text += f"*SECTION_SHELL\n2,2,0.8333,2\n{T},{T},{T},{T}\n"
    for p in (2, 3):
        text += f"*PART\nsheet {p}\n{p},2,{p}\n*MAT_ELASTIC\n{p},{RHO},{E / 100},{NU}\n"
    text += _contact(2, 0.3, 0.2, 10.0) + m.text()
    text += "*INITIAL_VELOCITY_NODE\n" + "".join(f"{i},1,0.5,-20\n" for i in falling + block)
    return text + "*END\n"


if __name__ == "__main__":
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    path = os.path.join(root, "tests", "data", "decks", "contact_soft2.k")
    with open(path, "w", encoding="utf-8") as f:
        f.write(determinism())
    sys.stdout.write(f"wrote {path}\n")
