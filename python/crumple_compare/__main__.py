"""`crumple compare`: Crumple's histories against LS-DYNA's ASCII files of the same deck.
Run as `python3 -m crumple_compare ...` (the crumple command does this); docs/validation.md."""

import argparse
import os
import sys

TIME_UNITS = {"s": 1.0, "ms": 1e-3, "us": 1e-6}


def parse(argv):
    p = argparse.ArgumentParser(
        prog="crumple compare",
        description="Compare Crumple's histories with LS-DYNA's ASCII output of the same deck: "
                    "peaks, ends, integrals and the ISO/TS 18571 rating per curve, with plots.")
    p.add_argument("run_dir", nargs="?", help="Crumple results folder (as --crumple)")
    p.add_argument("lsdyna_dir", nargs="?", help="LS-DYNA output folder (as --lsdyna)")
    p.add_argument("--lsdyna", help="folder of LS-DYNA's ASCII files (glstat, matsum, nodout, "
                                    "rcforc, rwforc, secforc, sleout)")
    p.add_argument("--crumple", help="results folder of `crumple run` (glstat.csv, ...)")
    p.add_argument("--out", help="output folder (default: <crumple folder>/compare)")
    p.add_argument("--cfc", type=float, choices=[60, 180, 600, 1000],
                   help="SAE J211 channel frequency class filter for accelerations")
    p.add_argument("--filter-all", action="store_true", help="with --cfc: filter every curve")
    p.add_argument("--time-unit", choices=sorted(TIME_UNITS),
                   help="the deck's time unit (needed by --cfc, which is in Hz)")
    p.add_argument("--curves", nargs="+", metavar="PATTERN",
                   help="only curves whose key matches a pattern (glob: 'glstat.*', "
                        "'nodout.node12.a?')")
    p.add_argument("--max-points", type=int, default=2000,
                   help="most common time points per curve for the ISO rating (default 2000)")
    p.add_argument("--no-plots", action="store_true", help="table only")
    p.add_argument("--list", action="store_true", help="list the curve keys of both sides")
    args = p.parse_args(argv)
    args.crumple = _one(p, args.crumple, args.run_dir, "--crumple")
    args.lsdyna = _one(p, args.lsdyna, args.lsdyna_dir, "--lsdyna")
    if args.cfc and not args.time_unit:
        p.error("--cfc needs --time-unit (s, ms or us): the CFC is in Hz, the deck's time unit "
                "is not known")
    if args.filter_all and not args.cfc:
        p.error("--filter-all needs --cfc")
    if args.max_points < 16 or args.max_points > 3000:
        p.error("--max-points must be in 16..3000")
    return args


def _one(p, option, positional, name):
    if option and positional:
        p.error(f"{name} given twice (as an option and as an argument)")
    if not (option or positional):
        p.error(f"{name} is required")
    return option or positional


def main(argv=None):
    from .command import main as command_main
    return command_main("crumple compare", parse, run, argv)


def run(args):
    from . import crumple_csv, lsdyna, report
    lsd, cru = lsdyna.read_folder(args.lsdyna), crumple_csv.read_folder(args.crumple)
    if args.list:
        for name, side in (("LS-DYNA", lsd), ("Crumple", cru)):
            print(f"{name} ({len(side)}):")
            for k in sorted(side):
                print("  " + k)
        return 0
    both, only_l, only_c = report.select(lsd, cru, args.curves)
    opts = {"cfc": args.cfc, "filter_all": args.filter_all, "max_points": args.max_points,
            "seconds": TIME_UNITS.get(args.time_unit, 1.0)}
    rows, plots = [], []
    for key in both:
        row, data = report.compare_one(lsd[key], cru[key], opts)
        rows.append(row)
        if data is not None and not args.no_plots:
            plots.append((row, data))
    out = args.out or os.path.join(args.crumple, "compare")
    result = {"lsdyna_dir": os.path.abspath(args.lsdyna),
              "crumple_dir": os.path.abspath(args.crumple), "cfc": args.cfc,
              "filter_all": args.filter_all, "time_unit": args.time_unit,
              "iso_parameters": report.iso18571.DEFAULTS, "curves": rows,
              "unmatched": {"lsdyna": only_l, "crumple": only_c}}
    report.write(out, result, plots)
    rated = [r for r in rows if "iso" in r]
    mean = sum(r["iso"]["R"] for r in rated) / len(rated) if rated else float("nan")
    print(f"crumple compare: {len(rows)} curves ({len(rated)} rated, mean ISO R {mean:.3f}); "
          f"{len(only_l)} only in LS-DYNA, {len(only_c)} only in Crumple; "
          f"{os.path.join(out, 'compare.md')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
