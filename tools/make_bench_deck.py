#!/usr/bin/env python3
"""Writes a whole-run benchmark deck: an elastic-plastic steel block of NX x NY x NZ hexes
striking a stonewall, for element-cycles per second and parallel efficiency (docs/parallel.md).

usage: make_bench_deck.py OUT.k [NX NY NZ] [--cycles N] [--shells]
Default 80 x 50 x 50 = 200,000 hexes; the end time is set for about N cycles (default 200).
--shells: a clamped plastic plate of NX x NY Belytschko-Tsay shells (default 500 x 400).
"""

from __future__ import annotations

import argparse
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from deckgen import Mesh, block, shell_grid  # noqa: E402


def bench_deck(nx: int, ny: int, nz: int, cycles: int) -> str:
    h = 1.0  # mm
    mesh = Mesh()
    block(mesh, 1, (0.0, 0.0, 0.0), (nx * h, ny * h, nz * h), (nx, ny, nz))
    rho, E, nu = 7.85e-6, 210.0, 0.3
    c = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho))
    dt = 0.9 * h / (c * (0.06 + math.sqrt(1 + 0.06 ** 2)))
    end = cycles * dt
    return f"""*KEYWORD
*TITLE
benchmark: {nx} x {ny} x {nz} elastic-plastic hexes on a stonewall (mm, ms, kg, GPa)
*CONTROL_TERMINATION
{end:10.6g}
*CONTROL_HOURGLASS
         2       0.1
*DATABASE_GLSTAT
{end / 10:10.6g}
*DATABASE_BINARY_D3PLOT
{end:10.6g}
*PART
steel block
         1         1         1
*SECTION_SOLID
         1         1
*MAT_PIECEWISE_LINEAR_PLASTICITY
         1   7.85e-6     210.0       0.3      0.25       2.0
*INITIAL_VELOCITY
         0
       0.0       0.0     -50.0
*RIGIDWALL_PLANAR
         0
       0.0       0.0       0.0       0.0       0.0       1.0       0.0
{mesh.keyword_text()}*END
"""


def shell_bench_deck(nx: int, ny: int, cycles: int) -> str:
    """A clamped elastic-plastic steel plate of nx x ny Belytschko-Tsay shells (NIP 5,
    stiffness hourglass control) hit by a uniform initial velocity: bending and membrane
    plasticity at every point."""
    h = 1.0
    mesh = Mesh()
    ids = shell_grid(mesh, 1, (0.0, 0.0, 0.0), (nx * h, ny * h), (nx, ny))
    edge = [ids[i, j] for j in range(ny + 1) for i in range(nx + 1) if i in (0, nx) or j in (0, ny)]
    rho, E, nu = 7.85e-6, 210.0, 0.3
    c = math.sqrt(E / ((1 - nu * nu) * rho))
    dt = 0.9 * h / c
    end = cycles * dt
    sets = "*SET_NODE_LIST\n         1\n" + "".join(
        "".join(f"{n:10d}" for n in edge[k:k + 8]) + "\n" for k in range(0, len(edge), 8))
    return f"""*KEYWORD
*TITLE
benchmark: {nx} x {ny} elastic-plastic Belytschko-Tsay shells, NIP 5 (mm, ms, kg, GPa)
*CONTROL_TERMINATION
{end:10.6g}
*CONTROL_HOURGLASS
         4      0.05
*DATABASE_GLSTAT
{end / 10:10.6g}
*DATABASE_BINARY_D3PLOT
{end:10.6g}
*PART
steel plate
         1         1         1
*SECTION_SHELL
         1         2    0.8333         5
       1.0       1.0       1.0       1.0
*MAT_PIECEWISE_LINEAR_PLASTICITY
         1   7.85e-6     210.0       0.3      0.25       2.0
*INITIAL_VELOCITY
         0
       0.0       0.0     -50.0
{sets}*BOUNDARY_SPC_SET
         1         0         1         1         1         1         1         1
{mesh.keyword_text()}*END
"""


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("dims", nargs="*", type=int, default=[80, 50, 50])
    ap.add_argument("--cycles", type=int, default=200)
    ap.add_argument("--shells", action="store_true",
                    help="a plate of DIMS[0] x DIMS[1] shells instead (default 500 x 400)")
    a = ap.parse_args()
    if a.shells:
        nx, ny = a.dims[:2] if a.dims != [80, 50, 50] else (500, 400)
        pathlib.Path(a.out).write_text(shell_bench_deck(nx, ny, a.cycles))
        print(f"wrote {a.out}: {nx * ny} shells")
        return
    nx, ny, nz = a.dims
    pathlib.Path(a.out).write_text(bench_deck(nx, ny, nz, a.cycles))
    print(f"wrote {a.out}: {nx * ny * nz} hexes")


if __name__ == "__main__":
    main()
