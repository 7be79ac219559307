#!/usr/bin/env python3
"""Checks `crumple partition --advise` against measured runs (docs/parallel.md, "How many
ranks"): for each deck, the predicted time per cycle at 1 and 2 ranks (one thread each) next to
the measured one of `crumple run` at 1 rank and under `mpirun -np 2`, as a markdown table.

usage: check_advice.py CRUMPLE DECK [DECK ...] [--cycles N] [--endtime T]

The measured time per cycle is the cycle loop's (wall time less set-up and output) over the
cycles run. Time it on a quiet machine: another job on the two cores makes both sides slow in
different ways. Needs mpirun for the 2-rank column and the measured network.
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


def predicted(crumple, deck, tmp, mpirun):
    out = os.path.join(tmp, "advice")
    cmd = [crumple, "partition", deck, "--advise", "--max", "2", "-o", out]
    run(([mpirun, "-np", "2"] if mpirun else []) + cmd, tmp)
    with open(os.path.join(out, "advise.json"), encoding="utf-8") as f:
        advice = json.load(f)
    return {p["ranks"]: p["cycle_s"] for p in advice["predictions"]}, advice["network"]


def measured(crumple, deck, tmp, ranks, mpirun, limits):
    out = os.path.join(tmp, f"run{ranks}")
    cmd = [crumple, "run", deck, "-q", "--threads", "1", "-o", out, "--overwrite", *limits]
    run(([mpirun, "-np", str(ranks)] if ranks > 1 else []) + cmd, tmp)
    with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
        s = json.load(f)
    loop = s["wall_s"] - s["setup_s"] - s["timing"]["output"]
    return loop / max(1, s["cycles"])


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("crumple")
    p.add_argument("decks", nargs="+")
    p.add_argument("--cycles", type=int, help="end each measured run after N cycles")
    p.add_argument("--endtime", type=float, help="end each measured run at time T")
    args = p.parse_args()
    crumple = os.path.abspath(args.crumple)
    mpirun = shutil.which("mpirun")
    limits = (["--cycles", str(args.cycles)] if args.cycles else []) + \
        (["--endtime", str(args.endtime)] if args.endtime else [])
    print("| deck | predicted 1 rank | measured | predicted 2 ranks | measured | "
          "error 1 | error 2 |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: |")
    for deck in args.decks:
        with tempfile.TemporaryDirectory(prefix="crumple_advice_") as tmp:
            deck = os.path.abspath(deck)
            pred, net = predicted(crumple, deck, tmp, mpirun)
            m1 = measured(crumple, deck, tmp, 1, mpirun, limits)
            m2 = measured(crumple, deck, tmp, 2, mpirun, limits) if mpirun else float("nan")
            print(f"| {os.path.basename(deck)} | {1e6 * pred[1]:.0f} us | {1e6 * m1:.0f} us | "
                  f"{1e6 * pred.get(2, float('nan')):.0f} us | {1e6 * m2:.0f} us | "
                  f"{100 * (pred[1] / m1 - 1):+.0f}% | "
                  f"{100 * (pred.get(2, float('nan')) / m2 - 1):+.0f}% |")
    print(f"\nnetwork: {'measured' if net['measured'] else 'assumed'}, latency "
          f"{1e6 * net['latency_s']:.2f} us, bandwidth {1e-9 * net['bandwidth_bytes_per_s']:.2f} "
          "GB/s")


if __name__ == "__main__":
    main()
