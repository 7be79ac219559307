"""`crumple plot RUN_DIR [WHAT ...]`: a run's histories as PNG pictures, the curves an analyst
looks at first (README, "Using it"):

| what | picture | from |
| --- | --- | --- |
| energies | kinetic, internal, hourglass, contact, stonewall, external work and total energy; below, the energy ratio in its [0.98, 1.02] band | glstat.csv |
| parts | internal energy of each part (the 12 largest by peak) | matsum.csv |
| contact | resultant force of each contact interface (SURFA side) | rcforc.csv |
| walls | normal force of each rigid wall | rwforc.csv |
| sections | resultant force and moment through each cross section | secforc.csv |
| nodes | displacement, velocity and acceleration of each history node; accelerations through the SAE J211 CFC filter with --cfc | nodout.csv |

Run as `python3 -m crumple_compare.plot ...` (the crumple command does this). Pictures go to
RUN_DIR/plots (or --out), one PNG per picture, overwritten if present: they are cheap to redraw.
"""

import argparse
import os
import sys

import numpy as np

WHATS = ("energies", "parts", "contact", "walls", "sections", "nodes")
MOST_PARTS = 12
ENERGY_BAND = (0.98, 1.02)  # the energy audit's band (src/output/energy_audit.hpp)


def parse(argv):
    from . import units
    p = argparse.ArgumentParser(
        prog="crumple plot",
        description="Plot a run's histories as PNG: energies and the energy ratio, part "
                    "energies, contact, wall and section forces, node histories.")
    p.add_argument("run_dir", help="results folder of `crumple run`")
    p.add_argument("what", nargs="*", metavar="WHAT",
                   help="pictures to draw: " + ", ".join(WHATS) + " (default: every one the "
                        "run has the history for)")
    p.add_argument("--out", help="output folder (default: RUN_DIR/plots)")
    p.add_argument("--cfc", type=float, choices=[60, 180, 600, 1000],
                   help="SAE J211 channel frequency class for the node accelerations")
    p.add_argument("--units", choices=sorted(units.SYSTEMS),
                   help="the deck's consistent unit system for the axis labels (default: the "
                        "one the run recorded in summary.json, else none)")
    p.add_argument("--nodes", type=int, nargs="+", metavar="ID", help="only these nodes")
    args = p.parse_args(argv)
    unknown = [w for w in args.what if w not in WHATS]
    if unknown:
        p.error(f"unknown picture {', '.join(unknown)} (choose from {', '.join(WHATS)})")
    args.what = list(dict.fromkeys(args.what))
    return args


def main(argv=None):
    from .command import main as command_main
    return command_main("crumple plot", parse, run, argv)


def run(args):
    from . import crumple_csv, units
    curves = crumple_csv.read_folder(args.run_dir)
    system = units.of_run(args.run_dir, args.units)
    if args.cfc and system is None:
        from .errors import CompareError
        raise CompareError("--cfc needs the time unit: give --units (the run did not record "
                           "its unit system)")
    figures = draw(curves, args.what or WHATS, system, args)
    out = args.out or os.path.join(args.run_dir, "plots")
    os.makedirs(out, exist_ok=True)
    for name, fig in figures:
        fig.savefig(os.path.join(out, name + ".png"), dpi=110)
        print(os.path.join(out, name + ".png"))
    if not figures:
        print(f"crumple plot: nothing to draw for {', '.join(args.what or WHATS)} in "
              f"{args.run_dir}", file=sys.stderr)
        return 1
    return 0


def draw(curves, whats, system, args):
    """[(file stem, Figure)] of every picture asked for whose history the run has."""
    builders = {"energies": energies, "parts": parts, "contact": contact, "walls": walls,
                "sections": sections, "nodes": nodes}
    figures = []
    for what in whats:
        figures.extend(builders[what](curves, system, args))
    return figures


def _select(curves, prefix, suffix):
    """{entity id: Curve} of keys '<prefix><id>.<suffix>' ('rwforc.wall', 'fn')."""
    out = {}
    for key, c in curves.items():
        head, _, quantity = key.rpartition(".")
        if quantity == suffix and head.startswith(prefix) and head[len(prefix):].isdigit():
            out[int(head[len(prefix):])] = c
    return dict(sorted(out.items()))


def _resultant(curves, prefix, ident, names):
    """(t, |(x, y, z)|) of the three curves '<prefix><ident>.<name>' that share one time axis."""
    parts = [curves[f"{prefix}{ident}.{n}"] for n in names]
    return parts[0].t, np.sqrt(sum(c.y ** 2 for c in parts))


def _figure(rows=1, height=3.6):
    from matplotlib.figure import Figure
    fig = Figure(figsize=(8.0, height * rows), layout="constrained")
    axes = [fig.add_subplot(rows, 1, i + 1) for i in range(rows)]
    return fig, axes


def _finish(ax, system, quantity, title=None):
    from . import units
    ax.set_xlabel(units.label("time", system))
    ax.set_ylabel(units.label(quantity, system))
    ax.grid(True, alpha=0.3)
    if title:
        ax.set_title(title)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize="small")


GLSTAT_LINES = [("kinetic", "kinetic"), ("internal", "internal"), ("hourglass", "hourglass"),
                ("contact", "contact (sliding)"), ("rigidwall", "stonewall"),
                ("external_work", "external work"), ("total", "total")]


def energies(curves, system, args):
    if "glstat.total" not in curves:
        return []
    fig, (top, bottom) = _figure(2)
    for key, label in GLSTAT_LINES:
        c = curves.get("glstat." + key)
        if c is not None and (key in ("kinetic", "internal", "total") or np.any(c.y != 0)):
            top.plot(c.t, c.y, label=label, lw=2.0 if key == "total" else 1.3)
    _finish(top, system, "energy", "Energies (glstat)")
    ratio = curves.get("glstat.energy_ratio")
    if ratio is not None:
        bottom.axhspan(*ENERGY_BAND, color="tab:green", alpha=0.12, label="audit band")
        bottom.plot(ratio.t, ratio.y, color="black", lw=1.3, label="total / initial")
        low, high = min(ENERGY_BAND[0], ratio.y.min()), max(ENERGY_BAND[1], ratio.y.max())
        bottom.set_ylim(low - 0.005, high + 0.005)
    _finish(bottom, system, "ratio", "Energy ratio")
    return [("energies", fig)]


def parts(curves, system, args):
    internal = _select(curves, "matsum.part", "internal")
    if not internal:
        return []
    largest = sorted(internal, key=lambda p: -np.max(np.abs(internal[p].y)))[:MOST_PARTS]
    fig, (ax,) = _figure()
    for p in sorted(largest):
        ax.plot(internal[p].t, internal[p].y, label=f"part {p}")
    more = len(internal) - len(largest)
    title = "Internal energy by part (matsum)" + (f", {len(largest)} largest of "
                                                   f"{len(internal)}" if more else "")
    _finish(ax, system, "energy", title)
    return [("parts", fig)]


def contact_ids(curves):
    """The contact interfaces of rcforc keys 'rcforc.contact<id>.slave.fx', ascending."""
    return sorted({int(k.split(".")[1][7:]) for k in curves
                   if k.startswith("rcforc.contact") and k.endswith(".slave.fx")})


def contact(curves, system, args):
    ids = contact_ids(curves)
    if not ids:
        return []
    fig, (ax,) = _figure()
    for c in ids:
        t, f = _resultant(curves, "rcforc.contact", f"{c}.slave", ("fx", "fy", "fz"))
        ax.plot(t, f, label=f"contact {c}")
    _finish(ax, system, "force", "Contact force, resultant on SURFA (rcforc)")
    return [("contact", fig)]


def walls(curves, system, args):
    fn = _select(curves, "rwforc.wall", "fn")
    if not fn:
        return []
    fig, (ax,) = _figure()
    for w, c in fn.items():
        ax.plot(c.t, c.y, label=f"wall {w}")
    _finish(ax, system, "force", "Rigid wall normal force (rwforc)")
    return [("walls", fig)]


def sections(curves, system, args):
    ids = sorted(_select(curves, "secforc.section", "fx"))
    if not ids:
        return []
    fig, (top, bottom) = _figure(2)
    for s in ids:
        t, f = _resultant(curves, "secforc.section", s, ("fx", "fy", "fz"))
        top.plot(t, f, label=f"section {s}")
        t, m = _resultant(curves, "secforc.section", s, ("mx", "my", "mz"))
        bottom.plot(t, m, label=f"section {s}")
    _finish(top, system, "force", "Section force, resultant (secforc)")
    _finish(bottom, system, "moment", "Section moment, resultant (secforc)")
    return [("sections", fig)]


def nodes(curves, system, args):
    ids = sorted(_select(curves, "nodout.node", "ax"))
    if args.nodes:
        missing = sorted(set(args.nodes) - set(ids))
        if missing:
            from .errors import CompareError
            raise CompareError(f"no history of node {', '.join(map(str, missing))} "
                               "(*DATABASE_HISTORY_NODE names the nodes nodout.csv holds)")
        ids = sorted(args.nodes)
    return [(f"node{n}", _node_figure(curves, n, system, args.cfc)) for n in ids]


def _node_figure(curves, n, system, cfc):
    fig, axes = _figure(3, height=2.8)
    for ax, (kind, names) in zip(axes, (("displacement", "dx dy dz"), ("velocity", "vx vy vz"),
                                        ("acceleration", "ax ay az"))):
        for name in names.split():
            c = curves[f"nodout.node{n}.{name}"]
            if kind == "acceleration" and cfc:  # the raw signal faint behind the filtered one
                t, y = _cfc(c, cfc, system)
                line, = ax.plot(t, y, label=f"{name} CFC {cfc:g}", zorder=3)
                ax.plot(c.t, c.y, lw=0.6, alpha=0.3, color=line.get_color())
            else:
                ax.plot(c.t, c.y, label=name)
        _finish(ax, system, kind, f"Node {n}: {kind}" if kind == "displacement" else None)
    return fig


def _cfc(curve, cfc, system):
    from . import signals
    step = signals.native_step(curve.t)
    t, y = signals.uniform(curve.t, curve.y, step)
    return t, signals.cfc_filter(y, step * system["seconds"], cfc)


if __name__ == "__main__":
    sys.exit(main())
