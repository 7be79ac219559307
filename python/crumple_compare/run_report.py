"""`crumple report RUN_DIR [--out FILE] [--baseline RUN1_DIR]`: one self-contained HTML page
of a run (README, "Using it"): the model summary, the energy balance with its plot and verdict,
the time breakdown and parallel efficiency, the warnings, the partition picture, the largest
contact and wall forces, and links to the result files. Pictures are embedded (data URIs), so
the page can be mailed; the links are relative to the page, written into RUN_DIR by default.

Run as `python3 -m crumple_compare.run_report ...` (the crumple command does this)."""

import argparse
import base64
import html
import io
import json
import os
import sys

import numpy as np

TIMING_ROWS = ("elements", "contact", "constraints", "communication", "output", "other")


def parse(argv):
    p = argparse.ArgumentParser(
        prog="crumple report",
        description="One self-contained HTML page of a run: model, energy balance and verdict, "
                    "time breakdown, warnings, partition, largest forces, result files.")
    p.add_argument("run_dir", help="results folder of `crumple run`")
    p.add_argument("--out", help="the page (default: RUN_DIR/report.html)")
    p.add_argument("--baseline", metavar="RUN1_DIR",
                   help="a 1-rank run of the same deck: the parallel efficiency is measured "
                        "against it")
    return p.parse_args(argv)


def main(argv=None):
    from .command import main as command_main
    return command_main("crumple report", parse, run, argv)


def run(args):
    from . import crumple_csv, units
    from .errors import CompareError
    summary = _summary(args.run_dir)
    curves = crumple_csv.read_folder(args.run_dir)
    system = units.of_run(args.run_dir)
    baseline = _summary(args.baseline) if args.baseline else None
    if baseline is not None and baseline.get("ranks", 1) != 1:
        raise CompareError("the baseline must be a 1-rank run", args.baseline)
    out = args.out or os.path.join(args.run_dir, "report.html")
    page = render(args.run_dir, os.path.dirname(os.path.abspath(out)), summary, curves, system,
                  baseline)
    with open(out, "w", encoding="utf-8") as f:
        f.write(page)
    print(out)
    return 0


def _summary(folder):
    from .errors import CompareError
    path = os.path.join(folder, "summary.json")
    if not os.path.isfile(path):
        raise CompareError("no summary.json: not a results folder of `crumple run`", folder)
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except ValueError as e:
        raise CompareError(f"unreadable: {e}", path) from e


def render(run_dir, page_dir, summary, curves, system, baseline):
    log = _read(os.path.join(run_dir, "run.log"))
    sections = [
        _model(summary, log), _energy(summary, curves, system), _timing(summary, baseline),
        _warnings(log), _partition(run_dir, summary), _forces(curves, system),
        _files(run_dir, page_dir)]
    title = html.escape(f"Crumple run: {os.path.basename(os.path.abspath(run_dir))}")
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{title}"
            f"</title><style>{STYLE}</style></head>\n<body>\n<h1>{title}</h1>\n"
            + "\n".join(sections) + f"\n<script>{IMAGE_CHECK}</script>\n</body></html>\n")


STYLE = ("body{font-family:sans-serif;max-width:60em;margin:1em auto;color:#222}"
         "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 8px;"
         "text-align:right}th{background:#eee}pre{background:#f6f6f6;padding:6px;"
         "overflow-x:auto;font-size:85%}img{max-width:100%}.bad{color:#b00}.good{color:#070}")
# Marks on <body> how many pictures the browser decoded: the test reads them back from a real
# headless browser (tests/cli/test_cli_report.py).
IMAGE_CHECK = ("window.addEventListener('load',function(){var i=document.images,n=0;"
               "for(var k=0;k<i.length;k++){if(i[k].complete&&i[k].naturalWidth>0)n++;}"
               "document.body.setAttribute('data-images',i.length);"
               "document.body.setAttribute('data-images-loaded',n);});")


def _read(path):
    if not os.path.isfile(path):
        return ""
    with open(path, encoding="utf-8", errors="replace") as f:
        return f.read()


def _table(header, rows):
    head = "".join(f"<th>{html.escape(str(h))}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in r) + "</tr>"
                   for r in rows)
    return f"<table><tr>{head}</tr>{body}</table>"


def _png(fig):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=90)
    data = base64.b64encode(buf.getvalue()).decode("ascii")
    return f'<img alt="plot" src="data:image/png;base64,{data}">'


def _model(summary, log):
    counts = summary.get("counts", {})
    units = summary.get("units") or {}
    rows = [("deck", summary.get("deck", "")), ("termination", summary.get("termination", "")),
            ("end time", summary.get("end_time", "")), ("cycles", summary.get("cycles", "")),
            ("nodes", counts.get("nodes", "")),
            ("elements", ", ".join(f"{v} {k}" for k, v in counts.items() if k != "nodes" and v)),
            ("mass", summary.get("mass", {}).get("physical", "")),
            ("added mass", summary.get("mass", {}).get("added", "")),
            ("initial time step", summary.get("initial_dt", "")),
            ("units", f"{units.get('system') or 'not known'} ({units.get('source', '')})"),
            ("ranks x threads", f"{summary.get('ranks', 1)} x {summary.get('threads', 1)}"),
            ("state digest", summary.get("state_digest", ""))]
    start = log.find("deck:")
    end = log.find("\ntiming:")
    described = log[start:end] if start >= 0 else ""
    return ("<h2>Model</h2>" + _table(["", ""], rows) +
            (f"<pre>{html.escape(described)}</pre>" if described else ""))


def _energy(summary, curves, system):
    from . import plot
    audit = summary.get("energy_audit", {})
    outside = audit.get("samples_outside", 0)
    band = audit.get("band", plot.ENERGY_BAND)
    if outside:
        verdict = (f'<p class="bad">The energy ratio left [{band[0]}, {band[1]}] at time '
                   f'{audit.get("first_outside_time")}: {outside} of {audit.get("samples")} '
                   f'samples outside (range {audit.get("min_ratio"):.4f} to '
                   f'{audit.get("max_ratio"):.4f}); run.log lists each with the term that '
                   'moved most.</p>')
    else:
        verdict = (f'<p class="good">The energy ratio stayed in [{band[0]}, {band[1]}] over '
                   f'{audit.get("samples", 0)} samples (range {audit.get("min_ratio", 1):.4f} '
                   f'to {audit.get("max_ratio", 1):.4f}).</p>')
    e = summary.get("energy", {})
    rows = [(k, f"{v:.6g}") for k, v in e.items()]
    figures = plot.energies(curves, system, None)
    pictures = "".join(_png(fig) for _, fig in figures)
    return "<h2>Energy balance</h2>" + verdict + pictures + _table(["at the end", ""], rows)


def _timing(summary, baseline):
    timing = summary.get("timing", {})
    wall = summary.get("wall_s", 0.0) or sum(timing.values())
    rows = [(k, f"{timing.get(k, 0.0):.3f}", f"{100 * timing.get(k, 0.0) / wall:.1f}%")
            for k in TIMING_ROWS if wall > 0]
    text = (f"<p>Wall time {wall:.3f} s, set-up {summary.get('setup_s', 0.0):.3f} s; "
            f"{summary.get('element_cycles_per_s', 0.0):.3g} element-cycles per second on "
            f"{summary.get('ranks', 1)} rank(s) x {summary.get('threads', 1)} thread(s).</p>")
    return ("<h2>Time</h2>" + text + _table(["part of the cycle", "s", "share"], rows) +
            _efficiency(summary, baseline))


def _efficiency(summary, baseline):
    ranks = summary.get("ranks", 1)
    if baseline is None:
        return ("<p>Parallel efficiency: give <code>--baseline</code> a 1-rank run of the same "
                "deck to measure it; <code>crumple partition DECK --advise</code> predicts "
                "it.</p>" if ranks > 1 else "")
    per_cycle = summary["wall_s"] / max(1, summary["cycles"])
    base = baseline["wall_s"] / max(1, baseline["cycles"])
    efficiency = base / (ranks * per_cycle)
    return (f"<p>Parallel efficiency against the 1-rank run: {100 * efficiency:.0f}% "
            f"(speed-up {base / per_cycle:.2f} on {ranks} ranks, wall time per cycle).</p>")


def _warnings(log):
    head = log[:log.find("deck:")] if "deck:" in log else ""
    lines = head.splitlines()[1:]  # after the version line
    audit = [ln for ln in log.splitlines()
             if ln.startswith(("energy audit", "warning")) or "energy ratio left" in ln]
    body = "\n".join(lines + ([""] if lines and audit else []) + audit)
    return "<h2>Warnings</h2>" + (f"<pre>{html.escape(body)}</pre>" if body.strip()
                                  else "<p>None.</p>")


def _partition(run_dir, summary):
    ranks = summary.get("ranks", 1)
    cells = _cell_centres(run_dir)
    if cells is None:
        return ("<h2>Partition</h2><p>No plot state to draw it from (VTK's Python bindings, "
                "python3-vtk9, read the states).</p>")
    from .plot import _figure
    centres, rank = cells
    fig, _ = _figure()
    fig.clear()
    ax = fig.add_subplot(projection="3d")
    step = max(1, len(rank) // 20000)
    ax.scatter(centres[::step, 0], centres[::step, 1], centres[::step, 2], c=rank[::step],
               cmap="tab20", s=2, vmin=0, vmax=max(1, ranks - 1))
    ax.set_title(f"Elements by rank ({ranks} rank{'s' if ranks > 1 else ''})")
    return "<h2>Partition</h2>" + _png(fig)


def _cell_centres(run_dir):
    """(cell centres, rank per cell) of the first plot state, or None."""
    states = os.path.join(run_dir, "states")
    names = sorted(n for n in os.listdir(states)) if os.path.isdir(states) else []
    names = [n for n in names if n.endswith((".pvtu", ".vtu"))]
    pvtu = [n for n in names if n.endswith(".pvtu")]
    first = (pvtu or names or [None])[0]
    if first is None:
        return None
    try:
        from vtkmodules.util.numpy_support import vtk_to_numpy
        from vtkmodules.vtkFiltersCore import vtkCellCenters
        from vtkmodules.vtkIOXML import (vtkXMLPUnstructuredGridReader,
                                         vtkXMLUnstructuredGridReader)
    except ImportError:
        return None
    reader = vtkXMLPUnstructuredGridReader() if first.endswith(".pvtu") \
        else vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(states, first))
    reader.Update()
    grid = reader.GetOutput()
    rank = grid.GetCellData().GetArray("rank")
    centres = vtkCellCenters()
    centres.SetInputData(grid)
    centres.Update()
    points = vtk_to_numpy(centres.GetOutput().GetPoints().GetData())
    ranks = vtk_to_numpy(rank) if rank is not None else np.zeros(len(points))
    return points, ranks


def _forces(curves, system):
    from . import plot
    rows = []
    for key, c in sorted(curves.items()):
        if key.startswith("rwforc.wall") and key.endswith(".fn"):
            rows.append((f"wall {key.split('.')[1][4:]} (normal)", *_peak(c.t, c.y)))
    for cid in plot.contact_ids(curves):
        t, f = plot._resultant(curves, "rcforc.contact", f"{cid}.slave", ("fx", "fy", "fz"))
        rows.append((f"contact {cid} (resultant on SURFA)", *_peak(t, f)))
    rows.sort(key=lambda r: -abs(r[3]))
    figures = plot.contact(curves, system, None) + plot.walls(curves, system, None)
    if not rows:
        return "<h2>Largest forces</h2><p>No contact or rigid wall in this run.</p>"
    table = _table(["force", "peak time", "peak", "|peak|"],
                   [(n, f"{t:.6g}", f"{v:.6g}", f"{abs(v):.6g}") for n, t, v, _ in rows])
    return "<h2>Largest forces</h2>" + table + "".join(_png(f) for _, f in figures)


def _peak(t, y):
    k = int(np.argmax(np.abs(y)))
    return float(t[k]), float(y[k]), float(abs(y[k]))


def _files(run_dir, page_dir):
    rows = []
    for name in sorted(os.listdir(run_dir)):
        path = os.path.join(run_dir, name)
        if os.path.isfile(path) and name != "report.html":
            href = html.escape(os.path.relpath(path, page_dir))
            rows.append(f'<li><a href="{href}">{html.escape(name)}</a> '
                        f'({os.path.getsize(path):,} bytes)</li>')
    return "<h2>Result files</h2><ul>" + "".join(rows) + "</ul>"


if __name__ == "__main__":
    sys.exit(main())
