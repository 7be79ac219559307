"""Curves written back in LS-DYNA's ASCII layouts (those lsdyna.py reads: R13's glstat,
matsum, nodout, rcforc, sleout, and a rwforc table). Used to test the comparison end to end
(a Crumple run against itself as LS-DYNA files) and to make small LS-DYNA-format files.

    python3 -m crumple_compare.lsdyna_write RUN_DIR OUT_DIR   # a Crumple run as LS-DYNA files
"""

import os
import re
import sys

import numpy as np

from . import mapping

BANNER = " crumple_compare.lsdyna_write\n                    ls-dyna (layout of R13 ASCII files)\n\n"
_GLSTAT_LABELS = {v: k for k, v in mapping.GLSTAT_LABELS.items()}
_MATSUM_NAMES = {v: k for k, v in mapping.MATSUM_FIELDS.items()}


DIGITS = [5]  # digits after the point of every number (LS-DYNA writes 5); write_folder sets it


def _e(x):
    return f"{x:{DIGITS[0] + 7}.{DIGITS[0]}E}"


def _groups(curves, prefix, pattern):
    """{entity id: {quantity: Curve}} of the keys 'prefix<id>.<quantity>'."""
    out = {}
    for key, c in curves.items():
        m = re.fullmatch(re.escape(prefix) + pattern, key)
        if m:
            out.setdefault(int(m.group(1)), {})[m.group(2)] = c
    return dict(sorted(out.items()))


def _times(groups):
    return np.unique(np.concatenate([c.t for g in groups.values() for c in g.values()]))


def _at(c, t):
    return float(np.interp(t, c.t, c.y))


def glstat(curves):
    own = {k.split(".", 1)[1]: c for k, c in curves.items() if k.startswith("glstat.")}
    if not own:
        return None
    text = BANNER
    for t in _times({0: own}):
        text += "\n dt of cycle       0 is controlled by solid 1 of part 1\n\n"
        text += f" {'time':.<31}{_e(t)}\n"
        for q, c in own.items():
            text += f" {_GLSTAT_LABELS.get(q, q.replace('_', ' ')):.<31}{_e(_at(c, t))}\n"
    return text


def matsum(curves):
    parts = _groups(curves, "matsum.part", r"(\d+)\.(\w+)")
    if not parts:
        return None
    text = BANNER
    for t in _times(parts):
        text += f"\n time = {_e(t)}\n"
        for pid, qs in parts.items():
            pairs = [f"{_MATSUM_NAMES.get(q, q)}={_e(_at(c, t))}" for q, c in qs.items()]
            text += f" mat.#={pid:5d}     " + "     ".join(pairs) + "\n\n"
    return text


def nodout(curves):
    nodes = _groups(curves, "nodout.node", r"(\d+)\.(\w+)")
    if not nodes:
        return None
    text = BANNER
    header = " nodal point  x-disp     y-disp      z-disp      x-vel       y-vel       z-vel  " \
             "    x-accl      y-accl      z-accl      x-coor      y-coor      z-coor\n"
    for step, t in enumerate(_times(nodes), 1):
        text += (f"\n\n n o d a l   p r i n t   o u t   f o r   t i m e  s t e p{step:8d}"
                 f"   ( at time {t:.7E} )\n\n" + header)
        for nid, qs in nodes.items():
            values = [_at(qs[q], t) if q in qs else 0.0 for q in mapping.NODOUT_TRANSLATION]
            text += f"{nid:9d}" + "".join(_e(v) for v in values) + "\n"
    return text


def rcforc(curves):
    sides = _groups(curves, "rcforc.contact", r"(\d+)\.((?:slave|master)\.f[xyz])")
    if not sides:
        return None
    text, times = BANNER, _times(sides)
    for t in times:
        for cid, qs in sides.items():
            for side in ("slave", "master"):
                f = [_at(qs[f"{side}.f{d}"], t) if f"{side}.f{d}" in qs else 0.0 for d in "xyz"]
                text += (f"  {side:<6}{cid:10d} time {_e(t)[1:]}  x {_e(f[0])}  y {_e(f[1])}"
                         f"  z {_e(f[2])}\n")
    return text


def sleout(curves):
    energy = _groups(curves, "sleout.contact", r"(\d+)\.(energy)")
    if not energy:
        return None
    text = BANNER
    for step, t in enumerate(_times(energy), 1):
        text += (f"\n contact interface energy file, time= {t:.7E}\n"
                 f"    #             slave       master       cycle={step:14d}    frictional\n\n")
        total = 0.0
        for cid, qs in energy.items():
            e = _at(qs["energy"], t)
            total += e
            text += f"{cid:10d}{_e(e)}{_e(0.0)}\n"
        text += (f"\n summary   total slave side= {total:.7E}\n           total mastr side= "
                 f"{0.0:.7E}\n           total energy    = {total:.7E}\n")
    return text


def rwforc(curves):
    walls = _groups(curves, "rwforc.wall", r"(\d+)\.(\w+)")
    if not walls:
        return None
    text = BANNER + "\n    time       wall#   normal-force    x-force      y-force      z-force\n"
    for t in _times(walls):
        for wid, qs in walls.items():
            values = [_at(qs[q], t) if q in qs else 0.0 for q in ("fn", "fx", "fy", "fz")]
            text += f"{_e(t)}{wid:6d}" + "".join(" " + _e(v) for v in values) + "\n"
    return text


WRITERS = {"glstat": glstat, "matsum": matsum, "nodout": nodout, "rcforc": rcforc,
           "sleout": sleout, "rwforc": rwforc}


def write_folder(curves, folder, digits=5):
    """The files of WRITERS that `curves` fill, in `folder`; numbers with `digits` digits after
    the point (more than LS-DYNA's 5 keep a comparison of a run with itself exact)."""
    DIGITS[0] = digits
    os.makedirs(folder, exist_ok=True)
    written = []
    for name, writer in WRITERS.items():
        text = writer(curves)
        if text is not None:
            with open(os.path.join(folder, name), "w", encoding="latin-1") as f:
                f.write(text)
            written.append(name)
    return written


if __name__ == "__main__":
    from . import crumple_csv
    print(" ".join(write_folder(crumple_csv.read_folder(sys.argv[1]), sys.argv[2])))
