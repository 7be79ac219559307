#!/usr/bin/env python3
"""Classical lamination theory (Jones, Mechanics of Composite Materials, 2nd ed., 1999, ch. 2
and 4): the A, B, D matrices of a laminate from its plies, independently of Crumple, for the
composite verification tests (tests/verification/test_composite.cpp).

Each ply: E1, E2 (fibre and transverse moduli), nu21 (the minor Poisson ratio, LS-DYNA's
PRBA: nu21 / E2 = nu12 / E1), G12, its angle theta (degrees, fibre from the x axis about z)
and thickness. Q is the reduced stiffness in the ply axes, Qbar = T^-1 Q R T R^-1 turned to
x, y (engineering shear), and
  A = sum Qbar_k (z_k+1 - z_k),  B = sum Qbar_k (z_k+1^2 - z_k^2) / 2,
  D = sum Qbar_k (z_k+1^3 - z_k^3) / 3,
with "D (midpoint)" the one-point-per-ply value sum Qbar_k t_k zbar_k^2 that a shell with one
integration point per ply integrates.

python3 tools/clt.py prints the numbers the tests use.
"""

import math


def reduced_stiffness(e1, e2, nu21, g12):
    nu12 = nu21 * e1 / e2
    d = 1.0 - nu12 * nu21
    return [[e1 / d, nu21 * e1 / d, 0.0], [nu21 * e1 / d, e2 / d, 0.0], [0.0, 0.0, g12]]


def turned(q, theta_deg):
    """Qbar of a ply at theta (Jones eq. 2.85)."""
    t = math.radians(theta_deg)
    c, s = math.cos(t), math.sin(t)
    q11, q12, q22, q66 = q[0][0], q[0][1], q[1][1], q[2][2]
    c2, s2, c4, s4 = c * c, s * s, c ** 4, s ** 4
    b11 = q11 * c4 + 2 * (q12 + 2 * q66) * s2 * c2 + q22 * s4
    b12 = (q11 + q22 - 4 * q66) * s2 * c2 + q12 * (s4 + c4)
    b22 = q11 * s4 + 2 * (q12 + 2 * q66) * s2 * c2 + q22 * c4
    b16 = (q11 - q12 - 2 * q66) * s * c ** 3 + (q12 - q22 + 2 * q66) * s ** 3 * c
    b26 = (q11 - q12 - 2 * q66) * s ** 3 * c + (q12 - q22 + 2 * q66) * s * c ** 3
    b66 = (q11 + q22 - 2 * q12 - 2 * q66) * s2 * c2 + q66 * (s4 + c4)
    return [[b11, b12, b16], [b12, b22, b26], [b16, b26, b66]]


def laminate(q, angles, thicknesses):
    h = sum(thicknesses)
    z = -h / 2
    a = [[0.0] * 3 for _ in range(3)]
    b = [[0.0] * 3 for _ in range(3)]
    d = [[0.0] * 3 for _ in range(3)]
    dmid = [[0.0] * 3 for _ in range(3)]
    for theta, t in zip(angles, thicknesses):  # plies from the bottom (z = -h / 2) up
        qb = turned(q, theta)
        z1, zm = z + t, z + t / 2
        for i in range(3):
            for j in range(3):
                a[i][j] += qb[i][j] * t
                b[i][j] += qb[i][j] * (z1 * z1 - z * z) / 2
                d[i][j] += qb[i][j] * (z1 ** 3 - z ** 3) / 3
                dmid[i][j] += qb[i][j] * t * zm * zm
        z = z1
    return a, b, d, dmid


def inverse3(m):
    (a, b, c), (d, e, f), (g, h, i) = m
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return [[(e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det],
            [(f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det],
            [(d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det]]


def show(name, m):
    print(f"{name}:")
    for row in m:
        print("  " + "  ".join(f"{v:.10g}" for v in row))


def main():
    # The tests' ply (GPa, mm): a carbon/epoxy (T300/5208-like) lamina.
    q = reduced_stiffness(181.0, 10.3, 0.016, 7.17)
    show("Q", q)
    for name, angles in [("[0/45/-45/90]s", [0, 45, -45, 90, 90, -45, 45, 0]),
                         ("[0/0/90/90]s", [0, 0, 90, 90, 90, 90, 0, 0]),
                         ("[30]", [30])]:
        n = len(angles)
        a, _, d, dmid = laminate(q, angles, [1.0 / n] * n)
        print(f"--- {name}, h = 1")
        show("A", a)
        show("D", d)
        show("D (midpoint)", dmid)
        ai = inverse3(a)
        print(f"  uniaxial N_x / eps_x = 1 / a11 = {1 / ai[0][0]:.10g}; eps_y / eps_x = "
              f"{ai[0][1] / ai[0][0]:.10g}; gamma_xy / eps_x = {ai[0][2] / ai[0][0]:.10g}")
        if n > 1:
            di, dmi = inverse3(d), inverse3(dmid)
            print(f"  strip bending 1 / d11 = {1 / di[0][0]:.10g} (midpoint "
                  f"{1 / dmi[0][0]:.10g})")


if __name__ == "__main__":
    main()
