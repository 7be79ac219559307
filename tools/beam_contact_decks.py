"""Decks of beam-to-beam contact (*CONTACT_AUTOMATIC_GENERAL, beams as capsules) for
tests/verification/test_beam_contact.py and the rank determinism case
tests/data/decks/contact_beams.k (written by `python3 tools/beam_contact_decks.py`).

Steel beams, SI units, one Hughes-Liu element (ELFORM 1) of solid circular section (CST 1,
outer diameter D) each unless said otherwise. The penalty stiffness of a pair is
SLSFAC x SSF x K x D (K the bulk modulus), SSF set so that it stays under the stability cap.
"""

import os
import sys

E, NU, RHO = 2.0e11, 0.3, 7850.0
D = 0.01  # section diameter (the contact diameter unless OPTT says otherwise)
SLSFAC = 0.1


def bulk_modulus():
    return E / (3.0 * (1.0 - 2.0 * NU))


def stiffness(ssf, d=D):
    """The penalty stiffness of a pair of beams of diameter d (docs/theory.md, "Beam edges")."""
    return SLSFAC * ssf * bulk_modulus() * d


def beam_mass(length, rho=RHO, d=D):
    return rho * 3.141592653589793 * d * d / 4.0 * length


def _header(title, end, dt_out, extra=""):
    return f"""*KEYWORD
*TITLE
{title}
*CONTROL_TERMINATION
{end}
*DATABASE_GLSTAT
{dt_out}
*DATABASE_MATSUM
{dt_out}
*DATABASE_RCFORC
{dt_out}
*DATABASE_NODOUT
{dt_out}
{extra}"""


def _part(pid, ssf, rho=RHO, optt=0.0, title=None):
    return f"""*PART_CONTACT
{title or f'beam {pid}'}
{pid},1,{pid}
0,0,0,0,{optt},0,{ssf}
*MAT_ELASTIC
{pid},{rho},{E},{NU}
"""


def _section():
    return f"""*SECTION_BEAM
1,1,0.8333,2,1
{D},{D},0,0
"""


def _contact(fs=0.0, fd=0.0, soft=0, vdc=0.0):
    return f"""*CONTACT_AUTOMATIC_GENERAL_ID
1
0,0,5,0
{fs},{fd},0,0,{vdc}
1,1
{soft}
"""


def _nodes(nodes):
    return "*NODE\n" + "".join(f"{n},{x},{y},{z}\n" for n, (x, y, z) in nodes.items())


def _beams(beams):
    # eid, pid, n1, n2, orientation node
    return "*ELEMENT_BEAM\n" + "".join(f"{e},{p},{a},{b},{o}\n" for e, p, a, b, o in beams)


def crossing(gap, length=0.1, v_b=0.0, pushed=False, ssf=0.01, end=7e-4, dt_out=5e-6):
    """Beam A along x through the origin, beam B along y at height z = D + gap over it, their
    middles over each other. pushed: A held (all freedoms), B driven down at v_b; otherwise
    both free, B flying down at v_b."""
    h = D + gap
    half = 0.5 * length
    nodes = {1: (-half, 0.0, 0.0), 2: (half, 0.0, 0.0), 3: (0.0, -half, h), 4: (0.0, half, h),
             5: (0.0, 1.0, 0.0), 6: (1.0, 0.0, h)}
    text = _header("two crossing beams", end, dt_out, "*DATABASE_HISTORY_NODE\n1,3\n")
    text += _part(1, ssf) + _part(2, ssf) + _section() + _contact()
    text += _nodes(nodes) + _beams([(1, 1, 1, 2, 5), (2, 2, 3, 4, 6)])
    if pushed:
        text += "*BOUNDARY_SPC_NODE\n1,0,1,1,1,1,1,1\n2,0,1,1,1,1,1,1\n"
        text += "*BOUNDARY_PRESCRIBED_MOTION_NODE\n3,3,0,1,-1.0\n4,3,0,1,-1.0\n"
        text += f"*DEFINE_CURVE\n1\n0.0,{v_b}\n1.0,{v_b}\n"
    else:
        text += f"*INITIAL_VELOCITY_NODE\n3,0,0,{-v_b}\n4,0,0,{-v_b}\n"
    return text + "*END\n"


def parallel_sliding(overlap, u, length_a=0.2, length_b=0.1, start=-0.03, ssf=0.001,
                     rho_a=RHO * 1e8, end=0.03, dt_out=2e-4):
    """Beam A along x from 0 to length_a, free but so heavy that it stays put; beam B parallel
    to it at z = D - overlap (the capsules overlap by `overlap` where they lie side by side),
    from x = start - length_b to start, driven along +x at u (y and z held by prescribed zero
    velocity). Nodes 1, 2 of A in nodout: their accelerations are the shares of the force."""
    z = D - overlap
    nodes = {1: (0.0, 0.0, 0.0), 2: (length_a, 0.0, 0.0), 3: (start - length_b, 0.0, z),
             4: (start, 0.0, z), 5: (0.0, 1.0, 0.0), 6: (0.0, 1.0, z)}
    text = _header("a beam sliding along another", end, dt_out, "*DATABASE_HISTORY_NODE\n1,2,3,4\n")
    text += _part(1, ssf, rho=rho_a) + _part(2, ssf) + _section() + _contact()
    text += _nodes(nodes) + _beams([(1, 1, 1, 2, 5), (2, 2, 3, 4, 6)])
    text += "*BOUNDARY_PRESCRIBED_MOTION_NODE\n"
    for n in (3, 4):
        text += f"{n},1,0,1,1.0\n{n},2,0,2,1.0\n{n},3,0,2,1.0\n"
    text += f"*DEFINE_CURVE\n1\n0.0,{u}\n1.0,{u}\n*DEFINE_CURVE\n2\n0.0,0.0\n1.0,0.0\n"
    return text + "*END\n"


def beam_grids(n=10, end=1e-3, dt_out=1e-4):
    """Two layers of sticks: n beams along x and, 1.1 D over them, n along y (4 elements
    each); above them the same turned 45 degrees, falling at 20 m/s (and drifting sideways)
    onto the first, with friction, SOFT = 1 and damping: many pairs, crossing and sliding,
    for the rank determinism test."""
    nodes, beams = {}, []
    nid, eid = [0], [0]

    def node(x, y, z):
        nid[0] += 1
        nodes[nid[0]] = (x, y, z)
        return nid[0]

    orient = node(0.0, 0.0, 10.0)

    def line(p0, p1, part, segments=4):
        ids = [node(*[a + (b - a) * k / segments for a, b in zip(p0, p1)])
               for k in range(segments + 1)]
        for a, b in zip(ids, ids[1:]):
            eid[0] += 1
            beams.append((eid[0], part, a, b, orient))

    half, pitch, r2 = 0.05, 0.1 / (n - 1), 0.5 ** 0.5
    offsets = [k * pitch - half for k in range(n)]
    for c in offsets:
        line((-half, c, 0.0), (half, c, 0.0), 1)
    for c in offsets:
        line((c, -half, 1.1 * D), (c, half, 1.1 * D), 1)
    lower = nid[0]
    for z, (ax, ay) in ((2.5 * D, (r2, r2)), (3.6 * D, (r2, -r2))):
        for c in offsets:
            ox, oy = -ay * c, ax * c  # across the line
            line((ox - ax * half, oy - ay * half, z), (ox + ax * half, oy + ay * half, z), 2)
    text = _header("two layers of sticks falling on two others", end, dt_out)
    text += _part(1, 0.01) + _part(2, 0.01) + _section() + _contact(0.3, 0.2, 1, 10.0)
    text += _nodes(nodes) + _beams(beams)
    text += "*INITIAL_VELOCITY_NODE\n" + "".join(
        f"{i},0.5,0,-20\n" for i in range(lower + 1, nid[0] + 1))
    text += f"*BOUNDARY_SPC_NODE\n{orient},0,1,1,1,1,1,1\n"
    return text + "*END\n"


if __name__ == "__main__":
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    path = os.path.join(root, "tests", "data", "decks", "contact_beams.k")
    with open(path, "w", encoding="utf-8") as f:
        f.write(beam_grids())
    sys.stdout.write(f"wrote {path}\n")
