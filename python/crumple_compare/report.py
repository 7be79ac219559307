"""The comparison of matched curves and what is written of it: compare.json, compare.md and
one PNG per curve (both codes on the left, their difference in the ISO corridors right)."""

import fnmatch
import json
import os

import numpy as np

from . import iso18571, signals
from .errors import CompareError

ACCELERATIONS = ("ax", "ay", "az")


def select(lsdyna, crumple, patterns):
    """The keys both sides have (matching one of `patterns`, fnmatch globs, if any), and the
    keys only one side has."""
    def wanted(k):
        return not patterns or any(fnmatch.fnmatchcase(k, p) for p in patterns)
    both = sorted(k for k in lsdyna if k in crumple and wanted(k))
    only_l = sorted(k for k in lsdyna if k not in crumple and wanted(k))
    only_c = sorted(k for k in crumple if k not in lsdyna and wanted(k))
    if not both:
        raise CompareError("no curve in common" + (" matching " + " ".join(patterns)
                                                   if patterns else ""))
    return both, only_l, only_c


def _filtered(curve, cfc, seconds):
    """The curve on a uniform grid of its own interval, through the CFC filter."""
    step = signals.native_step(curve.t)
    if step <= 0.0:
        return curve.t, curve.y
    t, y = signals.uniform(curve.t, curve.y, step)
    try:
        return t, signals.cfc_filter(y, step * seconds, cfc)
    except CompareError as e:
        raise CompareError(f"{curve.key}: {e}", curve.source) from e


def compare_one(a, b, opts):
    """One row of the table: LS-DYNA curve `a` (the reference) against Crumple's `b`."""
    cfc = opts["cfc"] if opts["cfc"] and (opts["filter_all"] or
                                          a.key.rsplit(".", 1)[-1] in ACCELERATIONS) else None
    (ta, ya), (tb, yb) = (a.t, a.y), (b.t, b.y)
    if cfc:
        (ta, ya), (tb, yb) = _filtered(a, cfc, opts["seconds"]), _filtered(b, cfc, opts["seconds"])
    row = {"key": a.key, "cfc": cfc, "lsdyna_source": a.source, "crumple_source": b.source}
    grid = signals.common_grid(ta, tb, opts["max_points"])
    if grid is None:
        row["note"] = "the two curves do not overlap in time"
        return row, None
    t0, t1 = float(grid[0]), float(grid[-1])
    ra, rb = np.interp(grid, ta, ya), np.interp(grid, tb, yb)
    row.update({"window": [t0, t1], "points": len(grid),
                "lsdyna": signals.figures(ta, ya, t0, t1),
                "crumple": signals.figures(tb, yb, t0, t1),
                "iso": iso18571.rate(ra, rb, grid[1] - grid[0])})
    return row, (ta, ya, tb, yb, grid, ra, rb)


def plot(path, row, data):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ta, ya, tb, yb, grid, ra, rb = data
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
    left.plot(ta, ya, label="LS-DYNA", color="black")
    left.plot(tb, yb, label="Crumple", color="tab:red", linestyle="--")
    left.set_xlim(grid[0], grid[-1])
    left.set_xlabel("time")
    left.set_title(row["key"] + (f" (CFC {row['cfc']:g})" if row["cfc"] else ""))
    left.legend()
    norm = float(np.max(np.abs(ra)))
    p = iso18571.DEFAULTS
    for width, shade in ((p["b0"], 0.12), (p["a0"], 0.25)):
        right.fill_between(grid, -width * norm, width * norm, color="tab:green", alpha=shade,
                           linewidth=0)
    right.plot(grid, rb - ra, color="tab:red")
    right.set_xlabel("time")
    iso = row["iso"]
    right.set_title(f"Crumple - LS-DYNA; ISO R = {iso['R']:.3f} ({iso['grade']}): "
                    f"Z {iso['corridor']:.2f} P {iso['phase']:.2f} M {iso['magnitude']:.2f} "
                    f"S {iso['slope']:.2f}", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def _g(x):
    return f"{x:.4g}"


def markdown(result):
    lines = ["# Crumple against LS-DYNA", "",
             f"LS-DYNA: `{result['lsdyna_dir']}`; Crumple: `{result['crumple_dir']}`; "
             + (f"CFC {result['cfc']:g} on " + ("every curve" if result["filter_all"]
                                                else "accelerations") if result["cfc"]
                else "no filter") + ".", "",
             "ISO/TS 18571 rating R = 0.4 Z + 0.2 P + 0.2 M + 0.2 S (corridor, phase, "
             "magnitude, slope); LS-DYNA is the reference. Lag: Crumple later by.", "",
             "| curve | peak LS-DYNA (t) | peak Crumple (t) | end LS-DYNA | end Crumple "
             "| integral LS-DYNA | integral Crumple | R | Z | P | M | S | lag | grade |",
             "|" + " --- |" * 14]
    for row in result["curves"]:
        if "iso" not in row:
            lines.append(f"| {row['key']} | {row['note']} |" + " |" * 12)
            continue
        a, b, s = row["lsdyna"], row["crumple"], row["iso"]
        lines.append(
            f"| {row['key']} | {_g(a['peak'])} ({_g(a['peak_time'])}) | {_g(b['peak'])} "
            f"({_g(b['peak_time'])}) | {_g(a['end'])} | {_g(b['end'])} | {_g(a['integral'])} "
            f"| {_g(b['integral'])} | {s['R']:.3f} | {s['corridor']:.3f} | {s['phase']:.3f} "
            f"| {s['magnitude']:.3f} | {s['slope']:.3f} | {_g(s['lag'])} | {s['grade']} |")
    for side in ("lsdyna", "crumple"):
        keys = result["unmatched"][side]
        if keys:
            name = "LS-DYNA" if side == "lsdyna" else "Crumple"
            lines += ["", f"Only in {name} ({len(keys)}): " + ", ".join(keys)]
    return "\n".join(lines) + "\n"


def write(out, result, plots):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "compare.json"), "w", encoding="utf-8") as f:
        json.dump(result, f, indent=1)
    with open(os.path.join(out, "compare.md"), "w", encoding="utf-8") as f:
        f.write(markdown(result))
    if plots:
        os.makedirs(os.path.join(out, "plots"), exist_ok=True)
        for row, data in plots:
            plot(os.path.join(out, "plots", row["key"] + ".png"), row, data)
