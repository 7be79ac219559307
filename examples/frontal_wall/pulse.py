#!/usr/bin/env python3
"""The figures of a frontal_wall run (README.md): wall impulse against the vehicle's momentum
change, energy ratio, dynamic crush and the rear node's deceleration, CFC 60 filtered as
SAE J211 asks for vehicle structure accelerations; optionally the crash pulse as a PNG.

usage: pulse.py RUNDIR [--png FILE]

Units of the deck: mm, ms, kg, GPa (force kN, impulse kN ms = kg m/s).
"""

from __future__ import annotations

import argparse
import csv
import json
import pathlib
import sys

G = 9.81e-3  # standard gravity in mm/ms^2


def rows(path: pathlib.Path) -> list[dict]:
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def wall_impulse(run: pathlib.Path) -> float:
    """The x impulse of the wall on the vehicle (trapezoidal over rwforc.csv's samples)."""
    r = rows(run / "rwforc.csv")
    t = [float(x["time"]) for x in r]
    f = [float(x["fx"]) for x in r]
    return sum(0.5 * (f[i] + f[i + 1]) * (t[i + 1] - t[i]) for i in range(len(t) - 1))


def momentum_change(run: pathlib.Path) -> tuple[float, float]:
    """(initial, final) x momentum of the whole vehicle: matsum.csv summed over the parts at
    its first and last time (a time written twice counts once)."""
    per_time: dict[float, dict[str, float]] = {}
    for x in rows(run / "matsum.csv"):
        per_time.setdefault(float(x["time"]), {}).setdefault(x["part"], float(x["x_momentum"]))
    times = sorted(per_time)
    return sum(per_time[times[0]].values()), sum(per_time[times[-1]].values())


def rear_node(run: pathlib.Path):
    """Time, x displacement, x velocity and x acceleration of the history node."""
    r = rows(run / "nodout.csv")
    return tuple([float(x[k]) for x in r] for k in ("time", "dx", "vx", "ax"))


def figures(run: pathlib.Path) -> dict:
    import numpy as np
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "python"))
    from crumple_compare.signals import cfc_filter, uniform
    s = json.loads((run / "summary.json").read_text())
    p0, p1 = momentum_change(run)
    t, dx, vx, ax = (np.array(c) for c in rear_node(run))
    step = float(np.median(np.diff(t)))
    grid, a = uniform(t, ax, step)
    a60 = cfc_filter(a, step * 1e-3, 60)  # the filter takes seconds
    stop = int(np.argmax(vx >= 0.0)) if (vx >= 0.0).any() else len(t) - 1
    return {"impulse": wall_impulse(run), "momentum_change": p1 - p0, "initial_momentum": p0,
            "energy_ratio": s["energy"]["ratio"], "energy_audit": s["energy_audit"],
            "hourglass_share": s["energy"]["hourglass"] / max(s["energy"]["internal"], 1e-30),
            "stop_time": float(t[stop]), "dynamic_crush": float(-dx.min()),
            "peak_deceleration_g_cfc60": float(a60.max() / G), "grid": grid, "a60": a60}


def plot(run: pathlib.Path, f: dict, png: pathlib.Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from crumple_compare.signals import cfc_filter, uniform
    r = rows(run / "rwforc.csv")
    t, fx = [float(x["time"]) for x in r], [float(x["fx"]) for x in r]
    step = (t[-1] - t[0]) / (len(t) - 1)
    grid, f60 = uniform(t, fx, step)
    f60 = cfc_filter(f60, step * 1e-3, 60)
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    top.plot(t, fx, lw=0.4, color="0.7", label="as sampled")
    top.plot(grid, f60, label="CFC 60")
    # The first contact of the bumper's face is a one-cycle spike of several MN: clipped.
    top.set_ylim(min(0.0, f60.min()), 2.0 * f60.max())
    top.legend()
    top.set_ylabel("wall force fx [kN]")
    bottom.plot(f["grid"], f["a60"] / G)
    bottom.set_ylabel("rear deceleration, CFC 60 [g]")
    bottom.set_xlabel("time [ms]")
    top.set_title("synthetic vehicle into a rigid wall at 56.3 km/h")
    fig.tight_layout()
    fig.savefig(png, dpi=90)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("run", type=pathlib.Path)
    ap.add_argument("--png", type=pathlib.Path)
    a = ap.parse_args()
    f = figures(a.run)
    print(f"wall impulse            {f['impulse']:10.1f} kg m/s")
    print(f"momentum change         {f['momentum_change']:10.1f} kg m/s "
          f"(ratio {f['impulse'] / f['momentum_change']:.4f}; initial {f['initial_momentum']:.1f})")
    print(f"energy ratio            {f['energy_ratio']:10.4f} (audit min {f['energy_audit']['min_ratio']:.4f}"
          f", max {f['energy_audit']['max_ratio']:.4f})")
    print(f"hourglass / internal    {f['hourglass_share']:10.3f}")
    print(f"rear node stops at      {f['stop_time']:10.2f} ms after a crush of {f['dynamic_crush']:.0f} mm")
    print(f"peak deceleration       {f['peak_deceleration_g_cfc60']:10.1f} g (CFC 60)")
    if a.png:
        plot(a.run, f, a.png)
        print(f"wrote {a.png}")


if __name__ == "__main__":
    main()
