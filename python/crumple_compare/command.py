"""What every command of the package does around its work: usage errors exit 2, a missing
numpy or matplotlib and a CompareError (bad input, named by file and line) exit 1 with one
line on stderr."""

import sys

USAGE_ERROR, ERROR = 2, 1


def main(prog, parse, run, argv):
    try:
        args = parse(sys.argv[1:] if argv is None else argv)
    except SystemExit as e:
        return USAGE_ERROR if e.code else 0
    try:
        import numpy  # noqa: F401
        import matplotlib
        matplotlib.use("Agg")  # files only, never a window
    except ImportError as e:
        print(f"{prog}: {sys.executable} lacks {e.name} (Debian: apt-get install "
              "python3-numpy python3-matplotlib)", file=sys.stderr)
        return ERROR
    from .errors import CompareError
    try:
        return run(args)
    except CompareError as e:
        print(f"{prog}: error: {e}", file=sys.stderr)
        return ERROR
