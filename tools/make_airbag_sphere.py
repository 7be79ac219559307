#!/usr/bin/env python3
"""Writes tests/data/decks/airbag_sphere.k: a closed sphere of radius 1 (a cube projected on
it, N x N quadrilateral shells per cube face, right-hand normals outward) of elastic shells,
inflated by *AIRBAG_SIMPLE_PRESSURE_VOLUME with mass weighted damping. SI units.
The verification test (tests/verification/test_airbag.cpp) reads it, and runs a copy
without damping for the energy balance.

usage: make_airbag_sphere.py [OUT]
"""
import math
import sys

N = 6
R = 1.0


def sphere_mesh(n: int, radius: float):
    """A cube of n x n quads per face projected onto a sphere: node coordinates and outward
    quads (1-based node ids)."""
    ids: dict[tuple[int, int, int], int] = {}
    coords: list[tuple[float, float, float]] = []

    def node(p: tuple[int, int, int]) -> int:
        if p not in ids:
            ids[p] = len(coords) + 1
            x, y, z = (2.0 * c / n - 1.0 for c in p)
            r = math.sqrt(x * x + y * y + z * z)
            coords.append((radius * x / r, radius * y / r, radius * z / r))
        return ids[p]

    shells = []
    # Each cube face: the axis it is normal to, its side, and two in-plane axes (u, v) with
    # u x v along the outward normal.
    for axis in range(3):
        u, v = (axis + 1) % 3, (axis + 2) % 3
        for side in (0, n):
            for i in range(n):
                for j in range(n):
                    quad = []
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        p = [0, 0, 0]
                        p[axis], p[u], p[v] = side, i + di, j + dj
                        quad.append(node(tuple(p)))
                    if side == 0:
                        quad = [quad[0], quad[3], quad[2], quad[1]]
                    shells.append(quad)
    return coords, shells


def main() -> None:
    out = sys.argv[1] if len(sys.argv) > 1 else "tests/data/decks/airbag_sphere.k"
    coords, shells = sphere_mesh(N, R)
    lines = ["*KEYWORD", "*TITLE", "airbag sphere: elastic shells inflated by a pressure-volume bag",
             "*CONTROL_TERMINATION", f"{0.1:10.4g}",
             "*PART", "sphere", f"{1:10d}{1:10d}{1:10d}",
             "*SECTION_SHELL", f"{1:10d}{2:10d}", f"{0.01:10.4g}{0.01:10.4g}{0.01:10.4g}{0.01:10.4g}",
             "*MAT_ELASTIC", f"{1:10d}{1000.0:10.4g}{2.0e8:10.4g}{0.3:10.4g}",
             "*NODE"]
    for k, (x, y, z) in enumerate(coords, start=1):
        lines.append(f"{k:8d}{x:16.9f}{y:16.9f}{z:16.9f}")
    lines.append("*ELEMENT_SHELL")
    for k, q in enumerate(shells, start=1):
        lines.append(f"{k:8d}{1:8d}" + "".join(f"{n:8d}" for n in q))
    lines += ["*SET_PART_LIST", f"{7:10d}", f"{1:10d}",
              "*AIRBAG_SIMPLE_PRESSURE_VOLUME_ID", f"{3:10d}bag",
              "$      SID    SIDTYP      RBID      VSCA      PSCA      VINI       MWD      SPSF",
              f"{7:10d}{1:10d}{0:10d}{1.0:10.4g}{1.0:10.4g}{0.0:10.4g}{756.0:10.4g}{0.0:10.4g}",
              "$       CN      BETA      LCID    LCIDDR",
              f"{3.0e4:10.4g}{1.0:10.4g}{0:10d}{0:10d}",
              "*END"]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
