#!/usr/bin/env python3
"""The crash pulse of car5 into the pole, as a crash test reports it (examples/vehicle_pole).

    python3 examples/vehicle_pole/pulse.py RUNDIR [--node 432] [--json]

reads RUNDIR's nodout.csv, rwforc.csv, matsum.csv and glstat.csv (a `crumple run` of
../shared/decks/car5_vehicle/main.k, units mm, s, tonne, N) and

  - filters the x acceleration of the rear node (432, on the roof 2.9 m behind the front; node
    167 is on the crushing front), taken as the mean of each output interval from its velocity,
    with the SAE J211-1 CFC 60 and CFC 180 filters (python/crumple_compare/signals.py),
    reports the peaks in g and writes RUNDIR/pulse.csv (time, interval mean, CFC 180, CFC 60
    in g; velocity in m/s);
  - checks the node's change of velocity against the time integral of its acceleration (raw
    and filtered: the filter keeps the area);
  - checks the impulse of the rigid walls (the pole, wall 2, and the ground's friction, wall 1)
    against the change of the vehicle's x momentum (matsum);
  - gives the energy balance at the end (glstat).
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "python"))
from crumple_compare.signals import cfc_filter  # noqa: E402

G = 9810.0  # mm/s^2


def rows(folder: str, name: str) -> list[dict]:
    """A CSV's rows as floats, a sample written twice (the last one) kept once."""
    with open(os.path.join(folder, name), encoding="utf-8") as f:
        out, seen = [], set()
        for r in csv.DictReader(f):
            row = {k: float(v) for k, v in r.items()}
            key = tuple(row.values())
            if key not in seen:
                seen.add(key)
                out.append(row)
        return out


def integral(t, y) -> float:
    return float(np.trapz(y, t))


def node_pulse(folder: str, node: int) -> dict:
    """The node's x velocity and acceleration on a uniform grid: `raw`, the nodal acceleration
    as sampled; `mean`, the mean acceleration of each output interval (the difference of the
    velocities: a sample of the nodal acceleration, which rings at the element frequencies, is
    aliased when there are many cycles per output interval; the mean is not); and `mean`
    through the CFC 180 and CFC 60 filters."""
    hist = [r for r in rows(folder, "nodout.csv") if r["node"] == node]
    t = np.array([r["time"] for r in hist])
    v = np.array([r["vx"] for r in hist])
    dt = float(np.median(np.diff(t)))
    grid = np.linspace(t[0], t[-1], int(round((t[-1] - t[0]) / dt)) + 1)
    mid = 0.5 * (t[1:] + t[:-1])
    mean = np.interp(grid, mid, np.diff(v) / np.diff(t))
    return {"t": grid, "v": np.interp(grid, t, v), "t_raw": t,
            "raw": np.array([r["ax"] for r in hist]), "mean": mean,
            "cfc180": cfc_filter(mean, dt, 180), "cfc60": cfc_filter(mean, dt, 60)}


def wall_impulse(folder: str) -> float:
    """Time integral of the walls' x force on the vehicle, summed over the walls."""
    total = 0.0
    forces = rows(folder, "rwforc.csv")
    for wall in sorted({r["wall"] for r in forces}):
        w = [r for r in forces if r["wall"] == wall]
        total += integral([r["time"] for r in w], [r["fx"] for r in w])
    return total


def momentum_change(folder: str) -> float:
    m = rows(folder, "matsum.csv")
    first, last = m[0]["time"], m[-1]["time"]
    return (sum(r["x_momentum"] for r in m if r["time"] == last)
            - sum(r["x_momentum"] for r in m if r["time"] == first))


def write_csv(folder: str, p: dict) -> None:
    with open(os.path.join(folder, "pulse.csv"), "w", encoding="utf-8") as f:
        f.write("time,mean_g,cfc180_g,cfc60_g,vx_m_per_s\n")
        for row in zip(p["t"], p["mean"] / G, p["cfc180"] / G, p["cfc60"] / G, p["v"] / 1000):
            f.write(",".join(f"{x:.9g}" for x in row) + "\n")


def peak(t, a) -> tuple[float, float]:
    """Largest deceleration (the car moves in -x: deceleration is +x) in g and its time."""
    i = int(np.argmax(a))
    return float(a[i] / G), float(t[i])


def filtered_area(p: dict, settle: float = 0.01) -> tuple[float, float]:
    """(integral of the CFC 60 curve, change of velocity) over [0, end - settle]: the filter
    keeps the area, but its last ~8 ms (1 / (2.0775 x 60 Hz)) lean on the end's point
    reflection (signals.cfc_filter) and so on the last sample of a noisy signal."""
    keep = p["t"] <= p["t"][-1] - settle
    return integral(p["t"][keep], p["cfc60"][keep]), float(p["v"][keep][-1] - p["v"][0])


def report(folder: str, node: int) -> dict:
    p = node_pulse(folder, node)
    write_csv(folder, p)
    g = rows(folder, "glstat.csv")[-1]
    area, dv = filtered_area(p)
    return {
        "node": node, "end_time": float(p["t"][-1]),
        "peak_raw_g": peak(p["t_raw"], p["raw"]), "peak_mean_g": peak(p["t"], p["mean"]),
        "peak_cfc180_g": peak(p["t"], p["cfc180"]),
        "peak_cfc60_g": peak(p["t"], p["cfc60"]),
        "delta_v": float(p["v"][-1] - p["v"][0]),
        "integral_raw": integral(p["t_raw"], p["raw"]),
        "integral_cfc60_settled": area, "delta_v_settled": dv,
        "wall_impulse": wall_impulse(folder), "momentum_change": momentum_change(folder),
        "energy": {k: g[k] for k in ("kinetic", "internal", "hourglass", "contact", "rigidwall",
                                     "total", "energy_ratio") if k in g},
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("rundir")
    ap.add_argument("--node", type=int, default=432)
    ap.add_argument("--json", action="store_true", help="print the figures as JSON")
    args = ap.parse_args()
    r = report(args.rundir, args.node)
    if args.json:
        print(json.dumps(r, indent=1))
        return
    print(f"node {r['node']}, 0 to {r['end_time']:.4g} s (pulse.csv written in {args.rundir})")
    for k in ("raw", "mean", "cfc180", "cfc60"):
        value, at = r[f"peak_{k}_g"]
        print(f"  peak deceleration {k:>6}: {value:7.2f} g at {1000 * at:6.2f} ms")
    print(f"  change of velocity {r['delta_v'] / 1000:.4f} m/s; integral of the acceleration "
          f"{r['integral_raw'] / 1000:.4f} m/s; to 10 ms before the end: change "
          f"{r['delta_v_settled'] / 1000:.4f}, integral of the CFC 60 curve "
          f"{r['integral_cfc60_settled'] / 1000:.4f} m/s")
    print(f"  impulse of the walls {r['wall_impulse']:.6g} N s; change of the vehicle's momentum "
          f"{r['momentum_change']:.6g} N s")
    e = r["energy"]
    print("  energy at the end (N mm): " + ", ".join(f"{k} {v:.4g}" for k, v in e.items()))


if __name__ == "__main__":
    main()
