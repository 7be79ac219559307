#!/usr/bin/env python3
"""Writes the dynamic-relaxation test decks (SI units):

tests/data/decks/dr_hanging_bar.k: a 1 m bar of 10 one-point hexes (E = 1e7, nu = 0,
  rho = 1000) fixed at its top face and hanging under gravity. The relaxation phase ramps
  gravity in through LCIDDR of *LOAD_BODY_Z (a SIDR = 1 curve) and relaxes to the static
  state (tip deflection rho g L^2 / (2 E)); the transient keeps gravity through LCID (a
  SIDR = 0 curve), so it starts, and stays, at rest (tests/verification/test_relaxation.cpp).
tests/data/decks/dr_rubber_sphere.k: a sphere of radius 0.1 of *MAT_MOONEY-RIVLIN_RUBBER
  Belytschko-Tsay shells inflated by *AIRBAG_SIMPLE_PRESSURE_VOLUME during the relaxation
  phase (IDRFLG = 1), then dropped at 2 m/s (*INITIAL_VELOCITY_GENERATION, given to the
  transient) on a stonewall under gravity (rank determinism, tests/CMakeLists.txt).

usage: make_dr_decks.py [OUTDIR]
"""
import math

from make_airbag_sphere import sphere_mesh
import sys


def bar(out: str) -> None:
    nz, length, side = 10, 1.0, 0.1
    lines = ["*KEYWORD", "*TITLE", "hanging bar: gravity preload by dynamic relaxation",
             "*CONTROL_TERMINATION", f"{0.05:10.4g}",
             "*CONTROL_DYNAMIC_RELAXATION",
             "$   NRCYCK     DRTOL    DRFCTR    DRTERM    TSSFDR    IRELAL     EDTTL    IDRFLG",
             f"{100:10d}{1.0e-7:10.4g}{0.99:10.4g}{0.0:10.4g}{0.0:10.4g}{0:10d}{0.0:10.4g}{0:10d}",
             "$ gravity ramp of the relaxation phase (SIDR = 1)",
             "*DEFINE_CURVE", f"{1:10d}{1:10d}", f"{0.0:20.6g}{0.0:20.6g}",
             f"{0.05:20.6g}{1.0:20.6g}", f"{100.0:20.6g}{1.0:20.6g}",
             "$ gravity of the transient (SIDR = 0)",
             "*DEFINE_CURVE", f"{2:10d}{0:10d}", f"{0.0:20.6g}{1.0:20.6g}",
             f"{100.0:20.6g}{1.0:20.6g}",
             "*LOAD_BODY_Z", f"{2:10d}{10.0:10.4g}{1:10d}",
             "*PART", "bar", f"{1:10d}{1:10d}{1:10d}",
             "*SECTION_SOLID", f"{1:10d}{1:10d}",
             "*MAT_ELASTIC", f"{1:10d}{1000.0:10.4g}{1.0e7:10.4g}{0.0:10.4g}",
             "*SET_NODE_LIST", f"{1:10d}"]
    top = [1 + i + 2 * j + 4 * nz for j in range(2) for i in range(2)]
    lines.append("".join(f"{n:10d}" for n in top))
    lines += ["*BOUNDARY_SPC_SET", f"{1:10d}{0:10d}{1:10d}{1:10d}{1:10d}{1:10d}{1:10d}{1:10d}",
              "*NODE"]
    for k in range(nz + 1):
        for j in range(2):
            for i in range(2):
                lines.append(f"{1 + i + 2 * j + 4 * k:8d}{side * i:16.9g}{side * j:16.9g}"
                             f"{length * k / nz:16.9g}")
    lines.append("*ELEMENT_SOLID")
    for k in range(nz):
        b = 4 * k
        n = [b + 1, b + 2, b + 4, b + 3, b + 5, b + 6, b + 8, b + 7]
        lines.append(f"{k + 1:8d}{1:8d}" + "".join(f"{x:8d}" for x in n))
    lines.append("*END")
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


def sphere(out: str) -> None:
    coords, shells = sphere_mesh(6, 0.1)
    lines = ["*KEYWORD", "*TITLE", "rubber sphere: inflated by dynamic relaxation, then dropped",
             "*CONTROL_TERMINATION", f"{0.02:10.4g}",
             "*CONTROL_DYNAMIC_RELAXATION",
             "$   NRCYCK     DRTOL    DRFCTR    DRTERM    TSSFDR    IRELAL     EDTTL    IDRFLG",
             f"{100:10d}{1.0e-3:10.4g}{0.995:10.4g}{0.0:10.4g}{0.0:10.4g}{0:10d}{0.0:10.4g}{1:10d}",
             "*DEFINE_CURVE", f"{1:10d}", f"{0.0:20.6g}{1.0:20.6g}", f"{1.0:20.6g}{1.0:20.6g}",
             "*LOAD_BODY_Z", f"{1:10d}{9.81:10.4g}",
             "*PART", "sphere", f"{1:10d}{1:10d}{1:10d}",
             "*SECTION_SHELL", f"{1:10d}{2:10d}", f"{0.002:10.4g}{0.002:10.4g}{0.002:10.4g}{0.002:10.4g}",
             "*MAT_MOONEY-RIVLIN_RUBBER",
             f"{1:10d}{1100.0:10.4g}{0.495:10.4g}{2.0e5:10.4g}{2.0e4:10.4g}",
             "*INITIAL_VELOCITY_GENERATION",
             f"{1:10d}{2:10d}{0.0:10.4g}{0.0:10.4g}{0.0:10.4g}{-2.0:10.4g}",
             f"{0.0:10.4g}{0.0:10.4g}{0.0:10.4g}{0.0:10.4g}{0.0:10.4g}{1.0:10.4g}",
             "*RIGIDWALL_PLANAR", f"{0:10d}",
             f"{0.0:10.4g}{0.0:10.4g}{-0.13:10.4g}{0.0:10.4g}{0.0:10.4g}{1.0:10.4g}",
             "*NODE"]
    for k, (x, y, z) in enumerate(coords, start=1):
        lines.append(f"{k:8d}{x:16.9f}{y:16.9f}{z:16.9f}")
    lines.append("*ELEMENT_SHELL")
    for k, q in enumerate(shells, start=1):
        lines.append(f"{k:8d}{1:8d}" + "".join(f"{m:8d}" for m in q))
    lines += ["*SET_PART_LIST", f"{7:10d}", f"{1:10d}",
              "*AIRBAG_SIMPLE_PRESSURE_VOLUME_ID", f"{3:10d}bag",
              "$      SID    SIDTYP      RBID      VSCA      PSCA      VINI       MWD      SPSF",
              f"{7:10d}{1:10d}{0:10d}{1.0:10.4g}{1.0:10.4g}{0.0:10.4g}{0.0:10.4g}{0.0:10.4g}",
              "$       CN      BETA      LCID    LCIDDR",
              f"{2.0e4:10.4g}{1.0:10.4g}{0:10d}{0:10d}",
              "*END"]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


def main() -> None:
    d = sys.argv[1] if len(sys.argv) > 1 else "tests/data/decks"
    bar(f"{d}/dr_hanging_bar.k")
    sphere(f"{d}/dr_rubber_sphere.k")


if __name__ == "__main__":
    main()
