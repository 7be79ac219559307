#!/usr/bin/env python3
"""Checks `crumple partition --advise` against measured runs (docs/parallel.md, "How many
ranks"): for each deck, the predicted time per cycle at 1 and 2 ranks (one thread each) next to
the measured one of `crumple run` at 1 rank and under `mpirun -np 2`, as a markdown table.

usage: check_advice.py CRUMPLE DECK [DECK ...] [--cycles N] [--endtime T] [--runs DIR]

Two predictions per deck: from a timed sample of the first cycles (`--advise`), and from the
measured serial run's whole-run costs (`--advise --from-run`), which leaves only the scaling
model to check at 2 ranks. The measured time per cycle is the cycle loop's (wall time less
set-up and output) over the cycles run. With --runs DIR the runs are kept in DIR/NAME.1 and
DIR/NAME.2 and, when already there, used instead of running again. Time it on a quiet
machine: another job on the two cores makes both sides slow in different ways. Needs mpirun for the 2-rank column and the measured network.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

ENV = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="PASSIVE",
           OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")


def run(cmd, cwd):
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, env=ENV, timeout=3600)
    if proc.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed:\n{proc.stdout}\n{proc.stderr}")
    return proc


def predicted(crumple, deck, tmp, mpirun, from_run=None):
    out = os.path.join(tmp, "advice")
    cmd = [crumple, "partition", deck, "--advise", "--max", "2", "-o", out]
    if from_run:
        cmd += ["--from-run", from_run]
    run(([mpirun, "-np", "2"] if mpirun else []) + cmd, tmp)
    with open(os.path.join(out, "advise.json"), encoding="utf-8") as f:
        advice = json.load(f)
    return {p["ranks"]: p["cycle_s"] for p in advice["predictions"]}, advice["network"]


def measured(crumple, deck, runs, ranks, mpirun, limits):
    """The loop's seconds per cycle of the run on `ranks` ranks, and its folder."""
    out = os.path.join(runs, f"{os.path.splitext(os.path.basename(deck))[0]}.{ranks}")
    summary = os.path.join(out, "summary.json")
    if not os.path.exists(summary):
        cmd = [crumple, "run", deck, "-q", "--threads", "1", "-o", out, "--overwrite", *limits]
        run(([mpirun, "-np", str(ranks)] if ranks > 1 else []) + cmd, runs)
    with open(summary, encoding="utf-8") as f:
        s = json.load(f)
    loop = s["wall_s"] - s["setup_s"] - s["timing"]["output"]
    return loop / max(1, s["cycles"]), out


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("crumple")
    p.add_argument("decks", nargs="+")
    p.add_argument("--cycles", type=int, help="end each measured run after N cycles")
    p.add_argument("--endtime", type=float, help="end each measured run at time T")
    p.add_argument("--runs", help="keep the measured runs here (and reuse those already here)")
    args = p.parse_args()
    crumple = os.path.abspath(args.crumple)
    mpirun = shutil.which("mpirun")
    limits = (["--cycles", str(args.cycles)] if args.cycles else []) + \
        (["--endtime", str(args.endtime)] if args.endtime else [])
    print("| deck | measured 1 rank | sample: 1 rank | measured 2 ranks | sample: 2 ranks | "
          "from the run: 2 ranks |")
    print("| --- | ---: | ---: | ---: | ---: | ---: |")
    nan = float("nan")
    for deck in args.decks:
        with tempfile.TemporaryDirectory(prefix="crumple_advice_") as tmp:
            runs = os.path.abspath(args.runs) if args.runs else tmp
            os.makedirs(runs, exist_ok=True)
            deck = os.path.abspath(deck)
            pred, net = predicted(crumple, deck, tmp, mpirun)
            m1, run1 = measured(crumple, deck, runs, 1, mpirun, limits)
            m2 = measured(crumple, deck, runs, 2, mpirun, limits)[0] if mpirun else nan
            from_run = predicted(crumple, deck, tmp, mpirun, run1)[0]

            def cell(p, m):
                return f"{1e6 * p:.0f} us ({100 * (p / m - 1):+.0f}%)"
            print(f"| {os.path.basename(deck)} | {1e6 * m1:.0f} us | {cell(pred[1], m1)} | "
                  f"{1e6 * m2:.0f} us | {cell(pred.get(2, nan), m2)} | "
                  f"{cell(from_run.get(2, nan), m2)} |")
    print(f"\nnetwork: {'measured' if net['measured'] else 'assumed'}, latency "
          f"{1e6 * net['latency_s']:.2f} us, bandwidth {1e-9 * net['bandwidth_bytes_per_s']:.2f} "
          "GB/s")


if __name__ == "__main__":
    main()
