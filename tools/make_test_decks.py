#!/usr/bin/env python3
"""Writes the decks under tests/data/decks/ used by the parallel determinism tests.

  mixed_conditions.k  every load and constraint at once on a plastic brick with erosion, under
                      a fully integrated (ELFORM 2) elastic cap:
                      SPC, follower pressure, nodal load, gravity, prescribed velocity with
                      birth/death, a moving stonewall with friction, rotating initial velocity,
                      stiffness hourglass control, mass scaling and history nodes.
  structures.k        shells (plastic BT with NIP 5, C0 triangles), solids, Hughes-Liu and
                      resultant beams, a truss, a spring and a damper in one model.
  rigid_welds.k       rigid bodies and nodal constraints across ranks: a rigid plate sharing
                      the top nodes of a plastic block, driven down and turned by
                      *BOUNDARY_PRESCRIBED_MOTION_RIGID; a spinning rigid body of two merged
                      parts (*CONSTRAINED_RIGID_BODIES) with an extra node and *PART_INERTIA
                      on one of them; a second elastic block spot welded to the first and
                      pulled off so that welds fail during the run; a generalized weld, a
                      nodal rigid body, a tied node set, a fully constrained (CMO) anvil and
                      a spherical joint between the plate's body and block B.
  contact_blocks.k, contact_tube.k, contact_tied.k, contact_cask.k
                      contact decks of tools/contact_decks.py (two-surface, single-surface
                      with rigid plates, tied).
  prism_blocks.k      the tet_blocks collision meshed in prisms (two per hex cell), ELFORM 15
                      native and sorted by ESORT
  tet13_blocks.k      the tet_blocks collision with both blocks ELFORM 13 (nodal pressure)
  tet10_bar.k         a clamped elastic-plastic bar of 10-node tetrahedra (ELFORM 16, six per
                      hex cell, two-card *ELEMENT_SOLID) whipped by a transverse initial
                      velocity: the four-point state of the quadratic tetrahedra across ranks.
  tet_blocks.k        two colliding blocks meshed in tetrahedra (six per hex cell) with
                      two-surface contact on their triangular faces: block a native ELFORM 10
                      (N5-N8 blank), block b degenerate hexahedra (N4 repeated) under ELFORM 1
                      sorted to ELFORM 10 by *CONTROL_SOLID ESORT = 1, with an elastic-plastic
                      law so that a part's history variables travel with its tetrahedra.
  erosion.k           elements deleted during the run across ranks: a steel bar (hexes,
                      *MAT_024 with *MAT_ADD_EROSION EFFEPS and MXPRES) and a strip of shells
                      (*MAT_123 with EPSMAJ, NUMINT 1, and *MAT_ADD_EROSION SIGVM at NCS 1)
                      each held at one end and pulled at the other, so that they fail
                      element by element.
  joints.k            rigid-body joints across ranks: a rigid bar swinging under gravity on a
                      revolute joint (with a *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED friction
                      spring on a *DEFINE_COORDINATE_NODE frame) from a fixed rigid frame, an
                      elastic block hanging from the bar by a spherical joint, and a rigid
                      slider on a translational joint pushed by *LOAD_RIGID_BODY.
  axisym_rod.k        an axisymmetric (*SECTION_SHELL ELFORM 15) elastic-plastic rod with a
                      conical tip stopped on its SPC'd end face, with a radial velocity
                      component, the axis held in x: 2D solids across ranks.
  eos_tabulated.k     the tabulated equations of state across ranks and restarts: a bar of a
                      crushable soil (*MAT_ELASTIC_PLASTIC_HYDRO with *EOS_TABULATED_COMPACTION)
                      backed by copper (*MAT_JOHNSON_COOK with *EOS_TABULATED and its energy
                      term) onto a stonewall: the soil compacts, unloads and reloads as the
                      waves run through it.
  tshell_plate.k      thick shells across ranks and restarts: a plastic (*MAT_024) plate of
                      *ELEMENT_TSHELL (*SECTION_TSHELL ELFORM 1, NIP 3, stiffness hourglass
                      IHQ 4) clamped on one edge and swung down about it, so that it bends
                      into a plastic hinge at the clamp.
  tshell2_plate.k     the same plate with *SECTION_TSHELL ELFORM 2 (selective reduced, 2 x 2
                      points in the plane, no hourglass control).
  jc_spall_bar.k      *MAT_JOHNSON_COOK spall across ranks and restarts: a free steel bar
                      stretched from its middle by its initial velocity; the middle yields and
                      spalls (part 1 SPALL 2 with VP 1, part 2 SPALL 3) and carries no
                      tension after, while the ends ring.
"""

from __future__ import annotations

import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from deckgen import Mesh, block, node_set, prismatize, tetrahedralize  # noqa: E402
import contact_decks  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent


def mixed_conditions(nx: int = 12, ny: int = 6, nz: int = 6) -> str:
    """Units mm, ms, kg, GPa. A 60 x 30 x 30 mm steel brick."""
    mesh = Mesh()
    g = block(mesh, 1, (0.0, 0.0, 0.02), (60.0, 30.0, 30.0), (nx, ny, nz))
    # A second part (elastic) on top, sharing the interface nodes.
    g2 = {}
    for k in range(0, 3):
        for j in range(ny + 1):
            for i in range(nx + 1):
                g2[i, j, k] = g[i, j, nz] if k == 0 else mesh.add_node(60.0 * i / nx, 30.0 * j / ny, 30.02 + 5.0 * k)
    for k in range(2):
        for j in range(ny):
            for i in range(nx):
                mesh.add_solid(2, [g2[i, j, k], g2[i + 1, j, k], g2[i + 1, j + 1, k], g2[i, j + 1, k],
                                   g2[i, j, k + 1], g2[i + 1, j, k + 1], g2[i + 1, j + 1, k + 1], g2[i, j + 1, k + 1]])
    fixed = [g[0, j, k] for j in range(ny + 1) for k in range(nz + 1)]
    driven = [g[nx, j, k] for j in range(ny + 1) for k in range(nz + 1)]
    top = [(g2[i, j, 2], g2[i + 1, j, 2], g2[i + 1, j + 1, 2], g2[i, j + 1, 2])
           for j in range(ny) for i in range(nx)]
    segs = "*SET_SEGMENT\n         1\n" + "".join(f"{a:10d}{b:10d}{c:10d}{d:10d}\n" for a, b, c, d in top)
    return f"""*KEYWORD
*TITLE
mixed conditions: every load and constraint at once (parallel determinism test)
*CONTROL_TERMINATION
      0.05
*CONTROL_TIMESTEP
$   dtinit    tssfac      isdo    tslimt     dt2ms
       0.0       0.8         0       0.0  -7.00e-4
*CONTROL_HOURGLASS
         4      0.05
*DATABASE_GLSTAT
     0.001
*DATABASE_MATSUM
     0.001
*DATABASE_NODOUT
     0.001
*DATABASE_RWFORC
     0.001
*DATABASE_BINARY_D3PLOT
      0.01
*DATABASE_HISTORY_NODE
{g[nx, ny, nz]:10d}{g[0, 0, 0]:10d}{g2[nx // 2, ny // 2, 2]:10d}
*PART
plastic brick
         1         1         1
*PART
elastic cap (fully integrated)
         2         2         2         0         1
*HOURGLASS
         1         2       0.1
*SECTION_SOLID
         1         1
*SECTION_SOLID
         2         2
*MAT_PIECEWISE_LINEAR_PLASTICITY
$      mid        ro         e        pr      sigy      etan      fail
         1   7.85e-6     210.0       0.3      0.25       2.0      0.01
*MAT_ELASTIC
         2   2.70e-6      70.0      0.33
*DEFINE_CURVE
         1
                 0.0                 0.0
                0.02                 1.0
                 1.0                 1.0
{node_set(1, fixed, "fixed end")}*BOUNDARY_SPC_SET
         1         0         1         1         1
{node_set(2, driven, "driven end")}*BOUNDARY_PRESCRIBED_MOTION_SET
$     nsid       dof       vad      lcid        sf       vid     death     birth
         2         1         0         1      20.0         0      0.04     0.002
{segs}*LOAD_SEGMENT_SET
         1         1      0.02
*LOAD_NODE_POINT
{g[nx, 0, 0]:10d}         3         1       0.5
*LOAD_BODY_Z
         1     9.81
*INITIAL_VELOCITY_GENERATION
$       id      styp     omega        vx        vy        vz
         2         2       1.0       0.0       0.0      -1.0
$       xc        yc        zc        nx        ny        nz
      30.0      15.0      35.0       0.0       0.0       1.0
*RIGIDWALL_PLANAR_MOVING
         0
       0.0       0.0       0.0       0.0       0.0       1.0       0.2
$     mass        v0
     0.005       1.0
{mesh.keyword_text()}*END
"""


def structures(nx: int = 16, ny: int = 8) -> str:
    """Units mm, ms, kg, GPa. Every structural element at once: a plastic Belytschko-Tsay plate
    (NIP 5) clamped on one edge with a C0-triangle elastic flange along another, a solid block
    under its free corner, a Hughes-Liu stiffener, resultant beams and a truss, springs and a
    damper to fixed ground nodes; driven by a prescribed edge velocity and a nodal load."""
    mesh = Mesh()
    lx, ly = 80.0, 40.0
    g = {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            g[i, j] = mesh.add_node(lx * i / nx, ly * j / ny, 0.0)
    for j in range(ny):
        for i in range(nx):
            mesh.add_shell(1, [g[i, j], g[i + 1, j], g[i + 1, j + 1], g[i, j + 1]])
    # Flange: triangles rising from the edge y = ly.
    f = {i: mesh.add_node(lx * i / nx, ly, 8.0) for i in range(nx + 1)}
    for i in range(nx):
        mesh.add_shell(2, [g[i, ny], g[i + 1, ny], f[i + 1], f[i + 1]])
        mesh.add_shell(2, [g[i, ny], f[i + 1], f[i], f[i]])
    # A 2 x 2 x 2 block of solids under the free corner (sharing the plate's nodes).
    b = {}
    for k in range(3):
        for j in range(3):
            for i in range(3):
                ii, jj = nx - 2 + i, j
                b[i, j, k] = g[ii, jj] if k == 2 else mesh.add_node(lx * ii / nx, ly * jj / ny, -5.0 + 2.5 * k)
    for k in range(2):
        for j in range(2):
            for i in range(2):
                mesh.add_solid(3, [b[i, j, k], b[i + 1, j, k], b[i + 1, j + 1, k], b[i, j + 1, k],
                                   b[i, j, k + 1], b[i + 1, j, k + 1], b[i + 1, j + 1, k + 1], b[i, j + 1, k + 1]])
    orient = mesh.add_node(0.0, -100.0, 0.0)
    # Stiffener along the middle line (Hughes-Liu), resultant beams on the edge y = 0, a truss
    # across the diagonal.
    for i in range(nx):
        mesh.add_beam(4, [g[i, ny // 2], g[i + 1, ny // 2], orient])
        mesh.add_beam(5, [g[i, 0], g[i + 1, 0], orient])
    mesh.add_beam(6, [g[0, ny], g[nx, 0], 0])
    ground = [mesh.add_node(lx, ly * j / ny, -20.0) for j in (0, ny)]
    mesh.add_discrete(7, [g[nx, 0], ground[0]])
    mesh.add_discrete(8, [g[nx, ny], ground[1]])
    fixed = [g[0, j] for j in range(ny + 1)] + [f[0]]
    driven = [g[nx, j] for j in range(ny + 1)]
    return f"""*KEYWORD
*TITLE
structures: shells, triangles, solids, beams, truss, springs (parallel determinism test)
*CONTROL_TERMINATION
       1.0
*CONTROL_SHELL
$   wrpang     esort     irnxx    istupd    theory       bwc     miter      proj
      20.0         1        -1         1         2         1         1         0
*DATABASE_GLSTAT
      0.05
*DATABASE_MATSUM
      0.05
*DATABASE_BINARY_D3PLOT
       0.5
*PART
plastic plate (BT, NIP 5)
         1         1         1
*PART
flange (C0 triangles)
         2         2         2
*PART
corner block
         3         3         2
*PART
stiffener (Hughes-Liu)
         4         4         2
*PART
edge beams (resultant)
         5         5         2
*PART
truss
         6         6         1
*PART
spring
         7         7         3
*PART
damper
         8         7         4
*SECTION_SHELL
         1         2    0.8333         5
       1.2       1.2       1.2       1.2
*SECTION_SHELL
         2         4    0.8333         3
       1.0       1.0       1.0       1.0
*SECTION_SOLID
         3         1
*SECTION_BEAM
         4         1    0.8333         2         0
       4.0       4.0       2.0       2.0
*SECTION_BEAM
         5         2    0.8333         2         0
       8.0      2.67      10.7       5.0       8.0
*SECTION_BEAM
         6         3
       3.0
*SECTION_DISCRETE
         7         0
*MAT_PIECEWISE_LINEAR_PLASTICITY
$      mid        ro         e        pr      sigy      etan
         1   7.85e-6     210.0       0.3      0.25       1.0
*MAT_ELASTIC
         2   7.85e-6     210.0       0.3
*MAT_SPRING_ELASTIC
         3       5.0
*MAT_DAMPER_VISCOUS
         4      0.02
*DEFINE_CURVE
         1
                 0.0                 0.0
                 0.2                 1.0
                10.0                 1.0
{node_set(1, fixed, "clamped edge")}*BOUNDARY_SPC_SET
         1         0         1         1         1         1         1         1
{node_set(2, driven, "driven edge")}*BOUNDARY_PRESCRIBED_MOTION_SET
$     nsid       dof       vad      lcid        sf
         2         3         0         1      -5.0
*BOUNDARY_SPC_NODE
{ground[0]:10d}         0         1         1         1         1         1         1
{ground[1]:10d}         0         1         1         1         1         1         1
{orient:10d}         0         1         1         1         1         1         1
*LOAD_NODE_POINT
{f[nx // 2]:10d}         2         1       0.2
{mesh.keyword_text()}*END
"""


def rigid_welds(nx: int = 12, ny: int = 4, nz: int = 4) -> str:
    """Units mm, ms, kg, GPa. Block A (part 1, plastic) 60 x 20 x 20 mm on a fixed rigid anvil
    (part 6, CMO); rigid plate (part 2) on its top face, sharing its nodes; block B (part 5,
    elastic) 1 mm beyond A's end face x = 60, welded to it; rigid parts 3 and 4 merged, flying
    and spinning above."""
    mesh = Mesh()
    a = block(mesh, 1, (0.0, 0.0, 0.0), (60.0, 20.0, 20.0), (nx, ny, nz))
    # Rigid plate on top of A: its bottom layer is A's top face.
    plate = {}
    for k in range(2):
        for j in range(ny + 1):
            for i in range(nx + 1):
                plate[i, j, k] = a[i, j, nz] if k == 0 else mesh.add_node(60.0 * i / nx, 20.0 * j / ny, 22.0)
    for j in range(ny):
        for i in range(nx):
            mesh.add_solid(2, [plate[i, j, 0], plate[i + 1, j, 0], plate[i + 1, j + 1, 0], plate[i, j + 1, 0],
                               plate[i, j, 1], plate[i + 1, j, 1], plate[i + 1, j + 1, 1], plate[i, j + 1, 1]])
    # Anvil under A: shares A's bottom nodes except the row y = 0, which a nodal rigid body takes.
    anvil = {}
    for k in range(2):
        for j in range(ny + 1):
            for i in range(nx + 1):
                shared = k == 1 and j > 0
                anvil[i, j, k] = a[i, j, 0] if shared else mesh.add_node(60.0 * i / nx, 20.0 * j / ny, -2.0 + 2.0 * k - (0.5 if k == 1 else 0.0))
    for j in range(ny):
        for i in range(nx):
            mesh.add_solid(6, [anvil[i, j, 0], anvil[i + 1, j, 0], anvil[i + 1, j + 1, 0], anvil[i, j + 1, 0],
                               anvil[i, j, 1], anvil[i + 1, j, 1], anvil[i + 1, j + 1, 1], anvil[i, j + 1, 1]])
    b = block(mesh, 5, (61.0, 0.0, 0.0), (20.0, 20.0, 20.0), (4, ny, nz))
    c = block(mesh, 3, (0.0, 0.0, 40.0), (20.0, 10.0, 10.0), (4, 2, 2))
    d = block(mesh, 4, (25.0, 0.0, 40.0), (10.0, 10.0, 10.0), (2, 2, 2))
    extra = mesh.add_node(40.0, 20.0, 45.0)
    # A node of the plate's body (an extra node) on B's top face, ball-jointed to B's node there.
    hinge = mesh.add_node(*mesh.nodes[b[3, 2, nz] - 1])
    # Spot welds between facing nodes of A (x = 60) and B (x = 61); the middle row is one
    # generalized weld of its nodes on both sides.
    welds = []
    general = []
    for k in range(nz + 1):
        for j in range(ny + 1):
            if k == nz // 2 and 0 < j < ny:
                general += [a[nx, j, k], b[0, j, k]]
            elif 0 < k < nz:  # the bottom row is on the anvil, the top one on the plate
                welds.append((a[nx, j, k], b[0, j, k]))
    # Strengths rising weld by weld: some fail early, some late, some hold to the end.
    weld_text = "*CONSTRAINED_SPOTWELD_ID\n" + "".join(
        f"{100 + w:10d}\n{n1:10d}{n2:10d}{0.8 + 0.4 * w:10.3g}{0.6:10.3g}{2.0:10.3g}{2.0:10.3g}\n"
        for w, (n1, n2) in enumerate(welds))
    pulled = [b[4, j, k] for j in range(ny + 1) for k in range(nz + 1)]
    nodal = [a[i, 0, 0] for i in range(0, nx + 1, 3)]
    tied = [b[2, j, nz] for j in range(ny + 1)]
    return f"""*KEYWORD
*TITLE
rigid bodies, spot welds and tied nodes across ranks (parallel determinism test)
*CONTROL_TERMINATION
      0.06
*DATABASE_GLSTAT
     0.005
*DATABASE_BINARY_D3PLOT
      0.03
*PART
plastic block A
         1         1         1
*PART
rigid plate
         2         1         2
*PART_INERTIA
flying rigid body (master)
         3         1         3
$       xc        yc        zc        tm      ircs    nodeid
      12.0       5.0      45.0    0.0125
$      ixx       ixy       ixz       iyy       iyz       izz
      0.25      0.01       0.0      0.65       0.0       0.8
$      vtx       vty       vtz       vrx       vry       vrz
       2.0       0.0       1.0       0.3       0.1       0.5
*PART
flying rigid body (merged)
         4         1         4
*PART
elastic block B
         5         1         5
*PART
anvil
         6         1         6
*SECTION_SOLID
         1         1
*MAT_PIECEWISE_LINEAR_PLASTICITY
$      mid        ro         e        pr      sigy      etan
         1   7.85e-6     210.0       0.3      0.25       2.0
*MAT_RIGID
         2   7.85e-6     210.0       0.3
*MAT_RIGID
         3   7.85e-6     210.0       0.3
*MAT_RIGID
         4   2.70e-6      70.0      0.33
*MAT_ELASTIC
         5   2.70e-6      70.0      0.33
*MAT_RIGID
         6   7.85e-6     210.0       0.3
       1.0       7.0       7.0
*DEFINE_CURVE
         1
                 0.0                 0.0
                0.01                 1.0
                 1.0                 1.0
*BOUNDARY_PRESCRIBED_MOTION_RIGID
$      pid       dof       vad      lcid        sf
         2         3         0         1      -2.0
         2         5         0         1      0.02
*CONSTRAINED_RIGID_BODIES
         3         4
*CONSTRAINED_EXTRA_NODES_NODE
         4{extra:10d}
         2{hinge:10d}
*CONSTRAINED_JOINT_SPHERICAL
{hinge:10d}{b[3, 2, nz]:10d}
{weld_text}{node_set(11, general, "generalized weld")}*CONSTRAINED_GENERALIZED_WELD_SPOT
        11
$    tfail      epsf        sn        ss         n         m
      0.04
{node_set(12, nodal, "nodal rigid body")}*CONSTRAINED_NODAL_RIGID_BODY
        70         0        12
{node_set(13, tied, "tied nodes")}*CONSTRAINED_NODE_SET
        13         3
{node_set(14, pulled, "pulled face")}*BOUNDARY_PRESCRIBED_MOTION_SET
        14         1         0         1       4.0
{mesh.keyword_text()}*END
"""


def structures_shell16() -> str:
    """The structures deck with both shell sections fully integrated (ELFORM 16): the plate's
    quadrilaterals run in the ELFORM 16 kernel, the flange's triangles as C0 triangles in a block
    of their own (parallel determinism of the fully integrated shell)."""
    text = structures()
    swaps = [("structures: shells,", "structures_shell16: ELFORM 16 shells,"),
             ("         1         2    0.8333         5", "         1        16    0.8333         5"),
             ("         2         4    0.8333         3", "         2        16    0.8333         3")]
    for old, new in swaps:
        if old not in text:
            raise SystemExit(f"structures_shell16: '{old}' not found in the structures deck")
        text = text.replace(old, new, 1)
    return text


def solid_blocks(cut, title: str, elform_a: int, n1: int, n2: int, v: float, end: float) -> str:
    """SI units. Two 10 mm steel cubes (n1^3 and n2^3 cells, each cut by `cut(mesh, part)`)
    flying at each other at +-v along z across a 0.5 mm gap, offset sideways by 1 mm; block a
    under ELFORM `elform_a`, block b degenerate hexahedra under ELFORM 1 that *CONTROL_SOLID
    ESORT = 1 sorts, with an elastic-plastic law."""
    m = Mesh()
    block(m, 1, (0, 0, 0), (0.01, 0.01, 0.01), (n1, n1, n1))
    block(m, 2, (0.001, 0.001, 0.0105), (0.01, 0.01, 0.01), (n2, n2, n2))
    cut(m, 1)
    cut(m, 2)
    a = m.node_ids(lambda x, y, z: z <= 0.0100001)
    b = m.node_ids(lambda x, y, z: z >= 0.0104)
    vel = "".join(f"{i:10d}{0:10.4g}{0:10.4g}{v:10.4g}\n" for i in a)
    vel += "".join(f"{i:10d}{0:10.4g}{0:10.4g}{-v:10.4g}\n" for i in b)
    return f"""*KEYWORD
*TITLE
{title}
*CONTROL_TERMINATION
{end:10.4g}
*CONTROL_SOLID
         1
*DATABASE_GLSTAT
   1.0e-06
*PART
block a (ELFORM {elform_a})
         1         1         1
block b (ELFORM 1, degenerate, sorted)
         2         2         2
*SECTION_SOLID
         1{elform_a:10d}
*SECTION_SOLID
         2         1
*MAT_ELASTIC
         1    7850.0   2.0e+11       0.3
*MAT_PLASTIC_KINEMATIC
         2    7850.0   2.0e+11       0.3   2.0e+08   1.0e+09       0.0
*CONTACT_SURFACE_TO_SURFACE_ID
         7
         1         2         3         3
*INITIAL_VELOCITY_NODE
{vel}{m.keyword_text()}*END
"""


def erosion(nx: int = 16, n: int = 2, v: float = 20.0, end: float = 8e-5) -> str:
    """SI units. A 40 x 5 x 5 mm bar of nx x n x n hexes and a 40 x 10 x 1 mm strip of nx x n
    shells, both along x, held at x = 0, their nodes at x = 40 mm pulled along x at a speed
    rising to v in 20 us."""
    m = Mesh()
    block(m, 1, (0, 0, 0), (0.04, 0.005, 0.005), (nx, n, n))
    grid = {}
    for j in range(n + 1):
        for i in range(nx + 1):
            grid[i, j] = m.add_node(0.04 * i / nx, 0.02 + 0.01 * j / n, 0.0)
    for j in range(n):
        for i in range(nx):
            m.add_shell(2, [grid[i, j], grid[i + 1, j], grid[i + 1, j + 1], grid[i, j + 1]])
    held = m.node_ids(lambda x, y, z: x <= 1e-9)
    kicked = m.node_ids(lambda x, y, z: x >= 0.04 - 1e-9)
    return f"""*KEYWORD
*TITLE
a bar and a strip kicked apart, eroding (*MAT_ADD_EROSION, *MAT_123)
*CONTROL_TERMINATION
{end:10.4g}
*DATABASE_GLSTAT
   1.0e-06
*PART
bar
         1         1         1
strip
         2         2         2
*SECTION_SOLID
         1         1
*SECTION_SHELL
         2         2    0.8333         5
     0.001     0.001     0.001     0.001
*MAT_PIECEWISE_LINEAR_PLASTICITY
         1    7850.0   2.0e+11       0.3   2.5e+08   1.0e+09
*MAT_ADD_EROSION
         1       0.0   5.0e+08       0.0      0.02
*MAT_MODIFIED_PIECEWISE_LINEAR_PLASTICITY
         2    7850.0   2.0e+11       0.3   2.5e+08   1.0e+09
         0         0         0         0         0       0.0      0.02         1
*MAT_ADD_EROSION
         2       0.0
       0.0       0.0   3.0e+08
*DEFINE_CURVE
         1
       0.0       0.0
   2.0e-05{v:10.4g}
       1.0{v:10.4g}
{node_set(1, held)}{node_set(2, kicked)}*BOUNDARY_SPC_SET
         1         0         1         1         1         1         1         1
*BOUNDARY_PRESCRIBED_MOTION_SET
         2         1         0         1       1.0
{m.keyword_text()}*END
"""


def tet_blocks(n1: int = 3, n2: int = 4, v: float = 10.0, end: float = 6e-5) -> str:
    """Cells of six tetrahedra: block a native ELFORM 10 (N5-N8 blank), block b N4 repeated."""
    return solid_blocks(lambda m, p: tetrahedralize(m, parts={p}, blank=p == 1),
                        "two tetrahedral blocks colliding (ELFORM 10 native and sorted by ESORT)",
                        10, n1, n2, v, end)


def tet13_blocks(n1: int = 3, n2: int = 4, v: float = 10.0, end: float = 6e-5) -> str:
    """The tet_blocks collision with both blocks nodal-pressure tetrahedra (ELFORM 13): block a
    elastic (N5-N8 blank), block b elastic-plastic (N4 repeated)."""
    text = solid_blocks(lambda m, p: tetrahedralize(m, parts={p}, blank=p == 1),
                        "two tetrahedral blocks colliding (ELFORM 13, elastic and plastic)",
                        13, n1, n2, v, end)
    text = text.replace("block b (ELFORM 1, degenerate, sorted)", "block b (ELFORM 13)", 1)
    return text.replace("*SECTION_SOLID\n         2         1\n",
                        "*SECTION_SOLID\n         2        13\n", 1)


def tet10_bar(nx: int = 8, n: int = 2, v: float = 20.0, end: float = 0.04) -> str:
    """mm, ms, kg, GPa. A 40 x 10 x 10 mm steel bar, cells of six Kuhn tetrahedra with a
    mid-side node on every edge (ELFORM 16), clamped at x = 0 (corner and mid-side nodes),
    started with v_z = v x / 40 and v_y = v x / 80."""
    from deckgen import KUHN_TETS

    lx, h = 40.0, 10.0
    nodes: list[tuple[float, float, float]] = []
    grid = {}
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(nx + 1):
                nodes.append((lx * i / nx, h * j / n, h * k / n))
                grid[i, j, k] = len(nodes)
    edges = ((0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3))
    mid: dict[tuple[int, int], int] = {}
    elements = []
    for k in range(n):
        for j in range(n):
            for i in range(nx):
                c = [grid[i, j, k], grid[i + 1, j, k], grid[i + 1, j + 1, k], grid[i, j + 1, k],
                     grid[i, j, k + 1], grid[i + 1, j, k + 1], grid[i + 1, j + 1, k + 1],
                     grid[i, j + 1, k + 1]]
                for t in KUHN_TETS:
                    corners = [c[a] for a in t]
                    mids = []
                    for a, b in edges:
                        key = (min(corners[a], corners[b]), max(corners[a], corners[b]))
                        if key not in mid:
                            pa, pb = nodes[key[0] - 1], nodes[key[1] - 1]
                            nodes.append(tuple((pa[d] + pb[d]) / 2 for d in range(3)))
                            mid[key] = len(nodes)
                        mids.append(mid[key])
                    elements.append(corners + mids)
    held = [i + 1 for i, p in enumerate(nodes) if p[0] <= 1e-9]
    lines = ["*NODE"] + [f"{i:8d}{x:16.9g}{y:16.9g}{z:16.9g}" for i, (x, y, z)
                         in enumerate(nodes, start=1)]
    lines.append("*ELEMENT_SOLID")
    for e, ns in enumerate(elements, start=1):
        lines.append(f"{e:8d}{1:8d}")
        lines.append("".join(f"{m:8d}" for m in ns))
    lines.append("*INITIAL_VELOCITY_NODE")
    for i, (x, _, _) in enumerate(nodes, start=1):
        lines.append(f"{i:10d}{0.0:10.4g}{0.5 * v * x / lx:10.4g}{v * x / lx:10.4g}")
    return f"""*KEYWORD
*TITLE
a clamped bar of 10-node tetrahedra (ELFORM 16), elastic-plastic, whipped
*CONTROL_TERMINATION
{end:10.4g}
*DATABASE_GLSTAT
    0.0005
*PART
bar (ELFORM 16)
         1         1         1
*SECTION_SOLID
         1        16
*MAT_PLASTIC_KINEMATIC
         1   7.85e-6     210.0       0.3      0.25       1.0       0.5
{node_set(1, held)}*BOUNDARY_SPC_SET
         1         0         1         1         1
""" + "\n".join(lines) + "\n*END\n"


def prism_blocks(n1: int = 3, n2: int = 4, v: float = 10.0, end: float = 6e-5) -> str:
    """Cells of two prisms: block a native ELFORM 15 (N3 = N4, N7 = N8), block b the Keyword
    Manual's pentahedron (N5 = N6, N7 = N8)."""
    return solid_blocks(lambda m, p: prismatize(m, parts={p}, manual=p == 2),
                        "two prism blocks colliding (ELFORM 15 native and sorted by ESORT)",
                        15, n1, n2, v, end)


def shearfix_blocks(n1: int = 3, n2: int = 4, v: float = 10.0, end: float = 6e-5) -> str:
    """Block a of ELFORM -1 hexahedra (the shear-corrected fully integrated form), block b of
    ELFORM 1 (parallel determinism of the ELFORM -1 kernel)."""
    text = solid_blocks(lambda m, p: None,
                        "two blocks colliding (ELFORM -1 and ELFORM 1)", -1, n1, n2, v, end)
    return text.replace("block b (ELFORM 1, degenerate, sorted)", "block b (ELFORM 1)", 1)


def joints(w0: float = 0.05, end: float = 0.5) -> str:
    """mm, ms, kg, GPa. Frame (part 1, fixed rigid), bar (part 2, rigid) hinged to it on the
    y axis and turning at w0 about it, elastic block (part 3) ball-jointed under the bar, slider
    (part 4, rigid) on a translational joint along x on top of the frame."""
    mesh = Mesh()
    frame = block(mesh, 1, (0.0, 0.0, 0.0), (20.0, 10.0, 10.0), (2, 1, 1))
    bar = block(mesh, 2, (0.0, 0.0, -30.0), (10.0, 10.0, 30.0), (2, 2, 3))
    hang = block(mesh, 3, (0.0, 0.0, -50.0), (10.0, 10.0, 20.0), (4, 4, 8))
    slider = block(mesh, 4, (0.0, 0.0, 10.0), (10.0, 10.0, 5.0), (2, 2, 1))
    moving = sorted(set(bar.values()) | set(hang.values()))
    vel = "".join(f"{n:10d}{w0 * mesh.nodes[n - 1][2]:10.5g}{0.0:10.5g}"
                  f"{-w0 * mesh.nodes[n - 1][0]:10.5g}\n" for n in moving)
    return f"""*KEYWORD
*TITLE
joints: revolute with friction spring, spherical, translational with a rigid-body load
*CONTROL_TERMINATION
{end:10.4g}
*DATABASE_GLSTAT
      0.05
*DATABASE_JNTFORC
      0.05
*PART
frame
         1         1         1
*PART
bar
         2         1         2
*PART
hanging elastic block
         3         1         3
*PART
slider
         4         1         4
*SECTION_SOLID
         1         1
*MAT_RIGID
         1   7.85e-6     210.0       0.3
       1.0       7.0       7.0
*MAT_RIGID
         2   7.85e-6     210.0       0.3
*MAT_ELASTIC
         3   7.85e-6     210.0       0.3
*MAT_RIGID
         4   7.85e-6     210.0       0.3
*DEFINE_CURVE
         1
       0.0       1.0
     100.0       1.0
*LOAD_BODY_Z
         1      0.01
*LOAD_RIGID_BODY
$      pid       dof      lcid        sf
         4         1         1    0.0005
         4         3         1    0.0003
*CONSTRAINED_JOINT_REVOLUTE
{frame[0, 0, 0]:10d}{bar[0, 0, 3]:10d}{frame[0, 1, 0]:10d}{bar[0, 2, 3]:10d}
*DEFINE_COORDINATE_NODE
         7{frame[0, 0, 0]:10d}{frame[0, 1, 0]:10d}{frame[1, 0, 0]:10d}
*CONSTRAINED_JOINT_STIFFNESS_GENERALIZED
         1         1         2         7
$   lcidph
         0
$     esph      fmph
       0.2     0.001
*CONSTRAINED_JOINT_SPHERICAL
{bar[1, 1, 0]:10d}{hang[2, 2, 4 * 2]:10d}
*CONSTRAINED_JOINT_TRANSLATIONAL
{frame[0, 0, 1]:10d}{slider[0, 0, 0]:10d}{frame[1, 0, 1]:10d}{slider[2, 0, 0]:10d}{frame[0, 1, 1]:10d}{slider[0, 2, 0]:10d}
*INITIAL_VELOCITY_NODE
{vel}{mesh.keyword_text()}*END
"""


def axisym_rod(nx: int = 6, ny: int = 30, radius: float = 5.0, length: float = 50.0,
               v: float = 200.0, end: float = 1.5e-2) -> str:
    """mm, ms, kg, GPa. A steel rod, x the radius and y the axis, its lower face tapered
    (a conical tip), moving at -v along y (with a small outward radial component) onto its end
    nodes held in y; nodes on the axis held in x."""
    def node_id(i: int, j: int) -> int:
        return 1 + i + (nx + 1) * j
    nodes, vel = [], []
    for j in range(ny + 1):
        for i in range(nx + 1):
            x = radius * i / nx
            y = length * j / ny + (0.1 * length / ny) * (i / nx) * (1 - j / ny)
            nodes.append(f"{node_id(i, j):8d}{x:16.9g}{y:16.9g}{0.0:16.9g}")
            vel.append(f"{node_id(i, j):10d}{0.05 * v * x / radius:10.5g}{-v:10.5g}{0.0:10.5g}")
    elems = [f"{1 + i + nx * j:8d}{1:8d}{node_id(i, j):8d}{node_id(i + 1, j):8d}"
             f"{node_id(i + 1, j + 1):8d}{node_id(i, j + 1):8d}"
             for j in range(ny) for i in range(nx)]
    bottom = [node_id(i, 0) for i in range(nx + 1)]
    axis = [node_id(0, j) for j in range(ny + 1)]
    spc = "".join(f"{n:10d}{0:10d}{0:10d}{1:10d}\n" for n in bottom)
    spc += "".join(f"{n:10d}{0:10d}{1:10d}{0:10d}\n" for n in axis)
    nl = "\n"
    return f"""*KEYWORD
*TITLE
axisymmetric rod impact (*SECTION_SHELL ELFORM 15)
*CONTROL_TERMINATION
{end:10.4g}
*DATABASE_GLSTAT
   1.0e-03
*PART
rod
         1         1         1
*SECTION_SHELL
         1        15
       1.0       1.0       1.0       1.0
*MAT_PLASTIC_KINEMATIC
         1   7.85e-6     210.0       0.3      0.40       1.0       0.0
*BOUNDARY_SPC_NODE
{spc}*INITIAL_VELOCITY_NODE
{nl.join(vel)}
*NODE
{nl.join(nodes)}
*ELEMENT_SHELL
{nl.join(elems)}
*END
"""


def eos_tabulated(nx: int = 12, n: int = 3, v: float = 20.0, end: float = 0.6) -> str:
    """Units mm, ms, kg, GPa. A 40 x 10 x 10 mm bar along x of nx x n x n hexes, its half at
    x < 20 mm soil (part 1), the rest copper (part 2), at v m/s onto a stonewall at x = 0. By
    0.4 ms the soil has taken most of the kinetic energy; by 0.6 ms it has given part back,
    unloading along its K."""
    m = Mesh()
    block(m, 1, (0.0, 0.0, 0.0), (40.0, 10.0, 10.0), (nx, n, n))
    m.solids = [(1 if sum(m.nodes[i - 1][0] for i in ns) / 8 < 20.0 else 2, ns)
                for _, ns in m.solids]
    return f"""*KEYWORD
*TITLE
soil backed by copper onto a stonewall (*EOS_TABULATED_COMPACTION, *EOS_TABULATED)
*CONTROL_TERMINATION
{end:10.4g}
*DATABASE_GLSTAT
     0.005
*PART
soil
         1         1         1         1
copper
         2         1         2         2
*SECTION_SOLID
         1         1
*MAT_ELASTIC_PLASTIC_HYDRO
         1    2.0e-6      0.05      0.01       0.0    -0.001
*EOS_TABULATED_COMPACTION
         1       0.0       0.0       1.0
$ EV1-EV10 (ln V), C1-C10 (GPa), T1-T10, K1-K10 (GPa)
             0.0           -0.05            -0.1            -0.2            -0.4
             0.0             0.0             0.0             0.0             0.0
             0.0            0.02            0.03            0.12             0.8
             0.0             0.0             0.0             0.0             0.0
             0.0             0.0             0.0             0.0             0.0
             0.0             0.0             0.0             0.0             0.0
             0.5             0.6             0.8             1.5             3.0
             0.0             0.0             0.0             0.0             0.0
*MAT_JOHNSON_COOK
         2   8.96e-6      46.0
      0.09     0.292      0.31     0.025      1.09    1356.0     293.0     0.001
     383.0      -1.0       1.0         0       0.0       0.0       0.0       0.0
       0.0
*EOS_TABULATED
         2       1.0       0.0       1.0
            0.05             0.0           -0.05            -0.1            -0.2
             0.0             0.0             0.0             0.0             0.0
            -7.0             0.0             7.4            15.5            35.0
             0.0             0.0             0.0             0.0             0.0
             2.0             2.0             2.0             2.0             2.0
             0.0             0.0             0.0             0.0             0.0
*INITIAL_VELOCITY
         0
{-v:10.4g}       0.0       0.0
*RIGIDWALL_PLANAR
         0
       0.0       0.0       0.0       1.0       0.0       0.0       0.0
{m.keyword_text()}*END
"""


def jc_spall_bar(nx: int = 12, n: int = 2, rate: float = 5000.0, end: float = 2.0e-5) -> str:
    """Units mm, s, tonne, MPa. A free 24 x 4 x 4 mm bar of 4340 steel (Johnson & Cook 1983)
    along x of nx x n x n hexes, stretched from its middle at `rate` /s by the initial
    velocity rate (x - 12 mm) (60 m/s at the ends): part 1 at x < 12 mm SPALL 2 with VP 1 and
    PC -1000 MPa, part 2 the rest SPALL 3 with PC -300 MPa. The middle yields, then spalls;
    the ends, unloaded by the waves from the free faces, ring."""
    m = Mesh()
    block(m, 1, (0.0, 0.0, 0.0), (24.0, 4.0, 4.0), (nx, n, n))
    m.solids = [(1 if sum(m.nodes[i - 1][0] for i in ns) / 8 < 12.0 else 2, ns)
                for _, ns in m.solids]
    velocities = "\n".join(f"{i:10d}{rate * (x - 12.0):10.1f}{0.0:10.1f}{0.0:10.1f}"
                           for i, (x, _, _) in enumerate(m.nodes, start=1))
    jc = """     792.0     510.0      0.26     0.014      1.03    1793.0     294.0       1.0"""
    return f"""*KEYWORD
*TITLE
steel bar stretched from its middle (*MAT_JOHNSON_COOK SPALL 2 with VP 1, SPALL 3)
*CONTROL_TERMINATION
{end:10.4g}
*DATABASE_GLSTAT
{end / 20:10.4g}
*PART
spall2_vp1
         1         1         1         1
spall3
         2         1         2         1
*SECTION_SOLID
         1         1
*MAT_JOHNSON_COOK
         1   7.83e-9   80000.0       0.0       0.0       0.0       1.0       0.0
{jc}
    4.77e8   -1000.0       2.0
*MAT_JOHNSON_COOK
         2   7.83e-9   80000.0       0.0       0.0       0.0       0.0       0.0
{jc}
    4.77e8    -300.0       3.0
*EOS_LINEAR_POLYNOMIAL
         1       0.0  160000.0
*INITIAL_VELOCITY_NODE
{velocities}
{m.keyword_text()}*END
"""


def tshell_plate(nx: int = 10, ny: int = 6, v: float = 40.0, end: float = 0.5,
                 elform: int = 1) -> str:
    """mm, ms, kg, GPa. A 50 x 30 x 4 mm plate of nx x ny thick shells (one through the
    thickness, N1-N4 on the bottom face z = 0), clamped at x = 0, swung down about the clamp
    at the start (z velocity -v x / 50 mm: smooth, so mostly the low modes ring). ELFORM 2
    (2 x 2 in the plane) takes the same deck; its *HOURGLASS card is read and not needed."""
    m = Mesh()
    block(m, 1, (0, 0, 0), (50.0, 30.0, 4.0), (nx, ny, 1))
    clamped = m.node_ids(lambda x, y, z: x <= 1e-9)
    velocities = "".join(f"{n + 1:10d}{0.0:10.4g}{0.0:10.4g}{-v * p[0] / 50.0:10.4g}\n"
                         for n, p in enumerate(m.nodes) if p[0] > 1e-9)
    # The mesh's 8-node elements are the thick shells.
    mesh = m.keyword_text().replace("*ELEMENT_SOLID", "*ELEMENT_TSHELL")
    return f"""*KEYWORD
*TITLE
thick shell plate: *MAT_024 *ELEMENT_TSHELL ELFORM {elform} clamped on one edge and swung down
*CONTROL_TERMINATION
{end:10.4g}
*DATABASE_GLSTAT
     0.005
*PART
plate
         1         1         1         0         1
*SECTION_TSHELL
         1{elform:10d}    0.8333         3
*MAT_PIECEWISE_LINEAR_PLASTICITY
         1   7.85e-6     210.0       0.3      0.25       1.0
*HOURGLASS
         1         4      0.05
{node_set(1, clamped)}*BOUNDARY_SPC_SET
         1         0         1         1         1
*INITIAL_VELOCITY_NODE
{velocities}{mesh}*END
"""


def main() -> None:
    out = ROOT / "tests" / "data" / "decks"
    out.mkdir(parents=True, exist_ok=True)
    (out / "mixed_conditions.k").write_text(mixed_conditions())
    (out / "structures.k").write_text(structures())
    (out / "structures_shell16.k").write_text(structures_shell16())
    (out / "rigid_welds.k").write_text(rigid_welds())
    # Contact: symmetric two-surface contact of offset blocks with unlike meshes, and the
    # square tube crushed with single-surface contact (5 mm shells, 1 ms: the first fold).
    (out / "contact_blocks.k").write_text(
        contact_decks.colliding_blocks("SURFACE_TO_SURFACE", 4, 5, 0.001))
    (out / "contact_tube.k").write_text(contact_decks.tube_crush(size=5.0, end=1.0))
    (out / "contact_tied.k").write_text(contact_decks.tied_bar(end=1.0e-4))
    (out / "contact_cask.k").write_text(contact_decks.cask_drop(end=2.0e-4))
    (out / "tet_blocks.k").write_text(tet_blocks())
    (out / "tet13_blocks.k").write_text(tet13_blocks())
    (out / "tet10_bar.k").write_text(tet10_bar())
    (out / "axisym_rod.k").write_text(axisym_rod())
    (out / "erosion.k").write_text(erosion())
    (out / "prism_blocks.k").write_text(prism_blocks())
    (out / "joints.k").write_text(joints())
    (out / "shearfix_blocks.k").write_text(shearfix_blocks())
    (out / "eos_tabulated.k").write_text(eos_tabulated())
    (out / "jc_spall_bar.k").write_text(jc_spall_bar())
    (out / "tshell_plate.k").write_text(tshell_plate())
    (out / "tshell2_plate.k").write_text(tshell_plate(elform=2))
    print("wrote tests/data/decks/mixed_conditions.k, structures.k, structures_shell16.k, "
          "rigid_welds.k, contact_blocks.k, contact_tube.k, contact_tied.k, contact_cask.k, "
          "tet_blocks.k, tet13_blocks.k, tet10_bar.k, axisym_rod.k, erosion.k, prism_blocks.k, "
          "joints.k, shearfix_blocks.k, eos_tabulated.k, jc_spall_bar.k, tshell_plate.k and "
          "tshell2_plate.k")


if __name__ == "__main__":
    main()
