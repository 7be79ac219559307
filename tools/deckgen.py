"""Small generators of LS-DYNA-style keyword decks for Crumple's examples and tests.

Standard library only. Meshes are hexahedra in LS-DYNA node order (1-4 one face, 5-8 the
opposite face, right-handed). Every function returns deck text; nothing here runs a solver.
"""

from __future__ import annotations

import math


class Mesh:
    """Nodes and 8-node solids with 1-based ids."""

    def __init__(self) -> None:
        self.nodes: list[tuple[float, float, float]] = []
        self.solids: list[tuple[int, list[int]]] = []  # (part id, 8 node ids)
        self.shells: list[tuple[int, list[int]]] = []  # (part id, 4 node ids; n3 == n4 triangle)
        self.beams: list[tuple[int, list[int]]] = []  # (part id, [n1, n2, orientation node])
        self.discretes: list[tuple[int, list[int]]] = []  # (part id, [n1, n2])

    def add_shell(self, part: int, nodes: list[int]) -> int:
        self.shells.append((part, nodes))
        return len(self.shells)

    def add_beam(self, part: int, nodes: list[int]) -> int:
        self.beams.append((part, nodes))
        return len(self.beams)

    def add_discrete(self, part: int, nodes: list[int]) -> int:
        self.discretes.append((part, nodes))
        return len(self.discretes)

    def add_node(self, x: float, y: float, z: float) -> int:
        self.nodes.append((x, y, z))
        return len(self.nodes)

    def add_solid(self, part: int, nodes: list[int]) -> int:
        self.solids.append((part, nodes))
        return len(self.solids)

    def node_ids(self, pred) -> list[int]:
        return [i + 1 for i, p in enumerate(self.nodes) if pred(*p)]

    def keyword_text(self) -> str:
        out = ["*NODE"]
        for i, (x, y, z) in enumerate(self.nodes, start=1):
            out.append(f"{i:8d}{x:16.9g}{y:16.9g}{z:16.9g}{0:8d}{0:8d}")
        if self.solids:
            out.append("*ELEMENT_SOLID")
            for e, (part, ns) in enumerate(self.solids, start=1):
                out.append(f"{e:8d}{part:8d}" + "".join(f"{n:8d}" for n in ns))
        for keyword, elements in (("*ELEMENT_SHELL", self.shells), ("*ELEMENT_BEAM", self.beams),
                                  ("*ELEMENT_DISCRETE", self.discretes)):
            if elements:
                out.append(keyword)
                for e, (part, ns) in enumerate(elements, start=1):
                    out.append(f"{e:8d}{part:8d}" + "".join(f"{n:8d}" for n in ns))
        return "\n".join(out) + "\n"


def block(mesh: Mesh, part: int, origin, size, divisions) -> dict:
    """A structured brick of nx*ny*nz hexes; returns the grid of node ids keyed (i, j, k)."""
    (x0, y0, z0), (lx, ly, lz), (nx, ny, nz) = origin, size, divisions
    grid = {}
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                grid[i, j, k] = mesh.add_node(x0 + lx * i / nx, y0 + ly * j / ny, z0 + lz * k / nz)
    grid_solids(mesh, part, grid, divisions)
    return grid


def shell_grid(mesh: Mesh, part: int, origin, size, divisions) -> dict:
    """A flat structured plate of nx*ny quadrilateral shells in the plane z = origin z;
    returns the grid of node ids keyed (i, j), i along x fastest."""
    (x0, y0, z0), (lx, ly), (nx, ny) = origin, size, divisions
    grid = {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            grid[i, j] = mesh.add_node(x0 + lx * i / nx, y0 + ly * j / ny, z0)
    for j in range(ny):
        for i in range(nx):
            mesh.add_shell(part, [grid[i, j], grid[i + 1, j], grid[i + 1, j + 1], grid[i, j + 1]])
    return grid


def grid_solids(mesh: Mesh, part: int, grid: dict, divisions) -> None:
    """The nx*ny*nz hexes of a structured grid of node ids keyed (i, j, k), k slowest."""
    nx, ny, nz = divisions
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                mesh.add_solid(part, [grid[i, j, k], grid[i + 1, j, k], grid[i + 1, j + 1, k],
                                      grid[i, j + 1, k], grid[i, j, k + 1], grid[i + 1, j, k + 1],
                                      grid[i + 1, j + 1, k + 1], grid[i, j + 1, k + 1]])


# The six tetrahedra of a hexahedron around its diagonal 1-7 (Kuhn's split, 0-based corners),
# each positive for a positive hexahedron. Every hex of a structured grid cut the same way
# gives a conforming mesh: the face diagonals of neighbours coincide.
KUHN_TETS = ((0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6))


def tetrahedralize(mesh: Mesh, parts=None, blank: bool = False) -> None:
    """Cuts the hexahedra of `parts` (all when None) into six tetrahedra each, written as
    LS-DYNA's degenerate hexahedron N1 N2 N3 N4 N4 N4 N4 N4, or with N5-N8 blank (0) when
    `blank` (the form for *SECTION_SOLID ELFORM 10)."""
    solids = []
    for part, ns in mesh.solids:
        if parts is not None and part not in parts:
            solids.append((part, ns))
            continue
        for t in KUHN_TETS:
            tet = [ns[a] for a in t]
            solids.append((part, tet + ([0] * 4 if blank else [tet[3]] * 4)))
    mesh.solids = solids


def prismatize(mesh: Mesh, parts=None, manual: bool = False) -> None:
    """Cuts the hexahedra of `parts` (all when None) along the bottom diagonal N1-N3 into two
    prisms each (triangles N1 N2 N3 and N1 N3 N4 below the ones above them), written as
    N1 N2 N3 N3 N5 N6 N7 N7, or in the Keyword Manual's form N1 N2 N3 N4 N5 N5 N6 N6 (triangles
    N1 N5 N2 and N4 N6 N3) when `manual`."""
    solids = []
    for part, ns in mesh.solids:
        if parts is not None and part not in parts:
            solids.append((part, ns))
            continue
        for a, b, c in ((0, 1, 2), (0, 2, 3)):
            lo, hi = [ns[a], ns[b], ns[c]], [ns[a + 4], ns[b + 4], ns[c + 4]]
            if manual:
                solids.append((part, [lo[0], lo[2], hi[2], hi[0], lo[1], lo[1], hi[1], hi[1]]))
            else:
                solids.append((part, lo + [lo[2]] + hi + [hi[2]]))
    mesh.solids = solids


def quarter_cylinder(mesh: Mesh, part: int, radius: float, length: float, n_core: int,
                     n_ring: int, n_axial: int) -> None:
    """A quarter cylinder (x >= 0, y >= 0, 0 <= z <= length) as a butterfly (O-grid) mesh:
    a square core of n_core x n_core cells and a ring of n_ring layers out to the circle."""
    core = 0.55 * radius

    def section_point(a: int, b: int, r: int):
        """Point of the cross-section: a, b index the core square (0..n_core); r = ring layer.
        For r > 0 the point lies on the ray from the core edge to the circle."""
        if r == 0:
            return core * a / n_core, core * b / n_core
        # Ring points: boundary of the core (a == n_core or b == n_core) blended to the arc.
        if a == n_core:
            t = b / n_core  # along the core's right edge, angle 0 .. 45 deg
            inner = (core, core * t)
            ang = 0.25 * math.pi * t
        else:
            t = a / n_core  # along the core's top edge, angle 90 .. 45 deg
            inner = (core * t, core)
            ang = 0.5 * math.pi - 0.25 * math.pi * t
        outer = (radius * math.cos(ang), radius * math.sin(ang))
        s = r / n_ring
        return inner[0] + s * (outer[0] - inner[0]), inner[1] + s * (outer[1] - inner[1])

    # Cross-section node table: core nodes (a, b, 0) and ring nodes along the core boundary.
    section = {}
    for a in range(n_core + 1):
        for b in range(n_core + 1):
            section[a, b, 0] = section_point(a, b, 0)
    boundary = [(n_core, b) for b in range(n_core + 1)] + [(a, n_core) for a in range(n_core - 1, -1, -1)]
    for (a, b) in boundary:
        for r in range(1, n_ring + 1):
            section[a, b, r] = section_point(a, b, r)
    # Quads of the cross-section (counter-clockwise seen from +z).
    quads = []
    for a in range(n_core):
        for b in range(n_core):
            quads.append([(a, b, 0), (a + 1, b, 0), (a + 1, b + 1, 0), (a, b + 1, 0)])
    for s in range(len(boundary) - 1):
        p, q = boundary[s], boundary[s + 1]
        for r in range(n_ring):
            quads.append([(p[0], p[1], r), (p[0], p[1], r + 1), (q[0], q[1], r + 1), (q[0], q[1], r)])
    ids = {}
    for k in range(n_axial + 1):
        z = length * k / n_axial
        for key, (x, y) in section.items():
            ids[key, k] = mesh.add_node(x, y, z)
    for k in range(n_axial):
        for q in quads:
            mesh.add_solid(part, [ids[c, k] for c in q] + [ids[c, k + 1] for c in q])


def node_set(set_id: int, nodes: list[int], title: str = "") -> str:
    out = ["*SET_NODE_LIST_TITLE", title or f"set {set_id}", f"{set_id:10d}"]
    for i in range(0, len(nodes), 8):
        out.append("".join(f"{n:10d}" for n in nodes[i:i + 8]))
    return "\n".join(out) + "\n"


def quarter_annulus(mesh: Mesh, part: int, radii: list[float], n_theta: int,
                    z_levels: list[float]) -> dict:
    """A quarter annular cylinder (x >= 0, y >= 0) of hexes: nodes at the given radii (inner
    first; a pilot hole when radii[0] > 0), n_theta sectors over 90 degrees and the given z
    levels (ascending). Returns the node ids keyed (i radius, j angle, k level)."""
    grid = {}
    for k, z in enumerate(z_levels):
        for j in range(n_theta + 1):
            a = 0.5 * math.pi * j / n_theta
            for i, r in enumerate(radii):
                grid[i, j, k] = mesh.add_node(r * math.cos(a), r * math.sin(a), z)
    grid_solids(mesh, part, grid, (len(radii) - 1, n_theta, len(z_levels) - 1))
    return grid


def ogive_radius(u: float, radius: float, crh: float) -> float:
    """Radius of a tangent ogive nose (caliber radius head crh: ogive radius crh x diameter) at
    the distance u behind its tip; the nose is radius x sqrt(4 crh - 1) long."""
    s = crh * 2.0 * radius
    length = radius * math.sqrt(4.0 * crh - 1.0)
    w = length - u  # distance ahead of the shoulder
    return math.sqrt(max(s * s - w * w, 0.0)) - (s - radius) if w > 0.0 else radius


def quarter_ogive_rod(mesh: Mesh, part: int, radius: float, shank: float, crh: float,
                      tip_radius: float, n_core: int, n_ring: int, n_nose: int, n_shank: int,
                      z_tip: float) -> None:
    """A quarter rod (x >= 0, y >= 0) along +z from its tip at z_tip: a tangent-ogive nose
    (blunted to tip_radius) then a cylindrical shank; the butterfly mesh of quarter_cylinder
    with each section scaled to the nose's radius there."""
    nose = radius * math.sqrt(4.0 * crh - 1.0)
    first = len(mesh.nodes)
    quarter_cylinder(mesh, part, radius, nose + shank, n_core, n_ring, n_nose + n_shank)
    # quarter_cylinder spaces its sections evenly; respace them so the nose has n_nose of them.
    dz = (nose + shank) / (n_nose + n_shank)
    for i in range(first, len(mesh.nodes)):
        x, y, z = mesh.nodes[i]
        k = round(z / dz)
        u = nose * k / n_nose if k <= n_nose else nose + shank * (k - n_nose) / n_shank
        f = max(ogive_radius(u, radius, crh), tip_radius) / radius
        mesh.nodes[i] = (f * x, f * y, z_tip + u)
