#!/usr/bin/env python3
"""Energy balance of the corpus decks that run: each deck to its own end time (or a budget).

  python3 tools/energy_sweep.py [--crumple PATH] [--decks DIR] [--budget 300] [--json FILE]
                                [--only NAME ...] [--paths DECK.k ...]

Issue 16 asks the energy ratio to stay within [0.98, 1.02] for the whole run on every explicit
deck of ../shared/decks that runs. tools/compatibility.py runs 20 cycles of each; this runs
each deck that reads (`crumple check` exit 0) to its end time, serially with one thread, and
stops a run that is still going after --budget seconds with SIGINT (Crumple then ends the run
cleanly and writes glstat.csv and summary.json up to that point). From glstat.csv it reports
the smallest and largest energy ratio over the run, where the ratio first left the band, the
hourglass and drilling energy as shares of the internal energy at the last sample, and how far
the run got (time reached over the deck's end time). The table it prints (Markdown) goes to
docs/validation.md; --json keeps the raw figures. Python 3 standard library only.
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compatibility  # noqa: E402  (the corpus listing and the crumple binary defaults)

BAND = (0.98, 1.02)


def read_glstat(out: str) -> list:
    try:
        with open(os.path.join(out, "glstat.csv"), encoding="utf-8") as f:
            return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    except (OSError, ValueError):
        return []


def figures(rows: list, summary: dict, end_time: float) -> dict:
    """Ratio range, first time out of the band, end-of-run shares, progress."""
    ratios = [r["energy_ratio"] for r in rows]
    outside = [r["time"] for r in rows if not BAND[0] <= r["energy_ratio"] <= BAND[1]]
    last = rows[-1]
    internal = last.get("internal", 0.0)
    share = (lambda key: last.get(key, 0.0) / internal if internal > 0 else None)
    return {"samples": len(rows), "min_ratio": min(ratios), "max_ratio": max(ratios),
            "first_outside": outside[0] if outside else None,
            "hourglass_share": share("hourglass"), "drilling_share": share("drilling"),
            "time": last["time"], "end_time": end_time, "cycles": int(last["cycle"]),
            "termination": summary.get("termination")}


def run_one(deck: dict, crumple: str, budget: float, end_time: float) -> dict:
    """The deck to its end time, or stopped by SIGINT after `budget` seconds."""
    path = os.path.join(deck["folder"], deck["main_deck"])
    with tempfile.TemporaryDirectory(prefix="crumple_sweep_") as tmp:
        out = os.path.join(tmp, "out")
        start = time.monotonic()
        proc = subprocess.Popen([crumple, "run", path, "-o", out, "-q", "--threads", "1"],
                                cwd=tmp, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                text=True, errors="replace", env=compatibility.ENV)
        stopped = False
        try:
            _, err = proc.communicate(timeout=budget)
        except subprocess.TimeoutExpired:
            stopped = True
            proc.send_signal(signal.SIGINT)
            _, err = proc.communicate()
        seconds = round(time.monotonic() - start, 1)
        summary = compatibility.read_summary(out) or {}
        rows = read_glstat(out)
    record = {"deck": deck["deck"], "seconds": seconds, "stopped": stopped,
              "returncode": proc.returncode}
    if not rows:
        record["error"] = (err or "").strip().splitlines()[-1:] or ["no glstat.csv"]
        return record
    record.update(figures(rows, summary, end_time))
    return record


def deck_end_time(deck: dict, crumple: str):
    """The deck's termination time from `crumple check --json`, or None when it does not read."""
    path = os.path.join(deck["folder"], deck["main_deck"])
    p = subprocess.run([crumple, "check", path, "--json"], capture_output=True, text=True,
                       errors="replace", env=compatibility.ENV, timeout=600)
    if p.returncode != 0:
        return None
    return (compatibility.parse_json_object(p.stdout) or {}).get("end_time") or 0.0


def pct(x) -> str:
    return "" if x is None else f"{100 * x:.2f} %"


def table(records: list) -> str:
    lines = ["| deck | reached (of end time) | cycles | energy ratio min - max | first outside "
             "[0.98, 1.02] | hourglass / internal | drilling / internal |",
             "|---|---:|---:|---|---|---:|---:|"]
    for r in records:
        if "error" in r:
            lines.append(f"| {r['deck']} | run failed: {' '.join(r['error'])} | | | | | |")
            continue
        reached = f"{r['time']:.4g} of {r['end_time']:.4g}" + (" (stopped)" if r["stopped"] else "")
        first = "" if r["first_outside"] is None else f"t = {r['first_outside']:.4g}"
        lines.append(f"| {r['deck']} | {reached} | {r['cycles']} | "
                     f"{r['min_ratio']:.4f} - {r['max_ratio']:.4f} | {first} | "
                     f"{pct(r['hourglass_share'])} | {pct(r['drilling_share'])} |")
    return "\n".join(lines) + "\n"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--crumple", default=compatibility.DEFAULT_CRUMPLE)
    ap.add_argument("--decks", default=compatibility.DEFAULT_DECKS)
    ap.add_argument("--budget", type=float, default=300.0, help="seconds per deck")
    ap.add_argument("--json", help="write the raw figures here")
    ap.add_argument("--only", nargs="*", help="deck folder names")
    ap.add_argument("--paths", nargs="*", help="deck files to run instead of the corpus (the "
                    "project's verification and example decks)")
    opts = ap.parse_args()
    records = []
    decks = compatibility.list_decks(opts.decks) if not opts.paths else [
        {"deck": os.path.relpath(p, compatibility.ROOT), "folder": os.path.dirname(os.path.abspath(p)),
         "main_deck": os.path.basename(p)} for p in opts.paths]
    for deck in decks:
        if opts.only and deck["deck"] not in opts.only:
            continue
        end_time = deck_end_time(deck, opts.crumple) if deck["main_deck"] else None
        if end_time is None:
            continue
        record = run_one(deck, opts.crumple, opts.budget, end_time)
        print(json.dumps(record), file=sys.stderr, flush=True)
        records.append(record)
    if opts.json:
        with open(opts.json, "w", encoding="utf-8") as f:
            json.dump(records, f, indent=1)
    sys.stdout.write(table(records))
    return 0


if __name__ == "__main__":
    sys.exit(main())
