"""Readers of Crumple's CSV histories (ARCHITECTURE.md Part 2, Output files), keyed as the
LS-DYNA curves they correspond to (mapping.py)."""

import csv
import os

import numpy as np

from . import mapping
from .curves import build
from .errors import CompareError


def _rows(path):
    """(header, rows of floats, line of each row); a cell that is not a number is an error
    naming its line and column."""
    with open(path, newline="", encoding="utf-8") as f:
        table = list(csv.reader(f))
    if not table:
        raise CompareError("empty file (no header row)", path, 1)
    header, rows = [h.strip() for h in table[0]], []
    for no, row in enumerate(table[1:], 2):
        if not row:
            continue
        if len(row) != len(header):
            raise CompareError(f"{len(row)} cells, the header has {len(header)}", path, no)
        try:
            rows.append([float(x) for x in row])
        except ValueError as e:
            raise CompareError(f"not a number: {e}", path, no) from e
    return header, rows


def _need(header, names, path):
    missing = [n for n in names if n not in header]
    if missing:
        raise CompareError("not a Crumple history: no column " + ", ".join(missing), path, 1)
    return {n: header.index(n) for n in header}


def _series(path, ids, quantities, key_of):
    """Series {key: (t, y)} of a CSV whose rows carry the time and the entity id columns
    `ids`; key_of(ids values, quantity) names each curve."""
    header, rows = _rows(path)
    col = _need(header, ["time", *ids], path)
    data = {}
    for row in rows:
        ident = [int(row[col[i]]) for i in ids]
        for q in quantities:
            if q in col:
                ts, ys = data.setdefault(key_of(ident, q), ([], []))
                ts.append(row[col["time"]])
                ys.append(row[col[q]])
    return data


def _rcforc(path):
    data = _series(path, ["contact", "side"], ["fx", "fy", "fz"],
                   lambda i, q: f"rcforc.contact{i[0]}.{mapping.CRUMPLE_RCFORC_SIDES[i[1]]}.{q}")
    energy = _series(path, ["contact", "side"], ["energy"],
                     lambda i, q: f"sleout.contact{i[0]}.energy" if i[1] == 1 else None)
    energy.pop(None, None)
    data.update(energy)
    if energy:  # the sum over the interfaces (each time once): sleout's total energy
        curves = build(energy, lambda k: path).values()
        times = np.unique(np.concatenate([c.t for c in curves]))
        data["sleout.total"] = (times, sum(np.interp(times, c.t, c.y) for c in curves))
    return data


_ELOUT_STRESS = ("sxx", "syy", "szz", "sxy", "syz", "szx")
_ELOUT_BEAM_POINT = {"sxx": "sigma11", "sxy": "sigma12", "szx": "sigma31", "eps_p": "eps_p"}
_ELOUT_BEAM = ("axial", "shear_s", "shear_t", "moment_s", "moment_t", "torsion", "eps_p")


def _elout_key(ident, q):
    """The key of lsdyna.read_elout for elout.csv's quantity q of (element, family, point),
    None for a column the row does not use."""
    e, family, point = ident
    if family == 0:  # solids: the plastic strain is LS-DYNA's "effsg" column
        return f"elout.solid{e}.{'effsg' if q == 'eps_p' else q}" \
            if q in _ELOUT_STRESS + ("eps_p",) else None
    if family == 1:
        return f"elout.shell{e}.ipt{point}.{q}" if q in _ELOUT_STRESS + ("eps_p",) else None
    if point == 0:
        return f"elout.beam{e}.{q}" if q in _ELOUT_BEAM else None
    return f"elout.beam{e}.ipt{point}.{_ELOUT_BEAM_POINT[q]}" if q in _ELOUT_BEAM_POINT else None


def _elout(path):
    data = _series(path, ["element", "family", "point"],
                   list(_ELOUT_STRESS) + ["eps_p", *_ELOUT_BEAM[:-1]], _elout_key)
    data.pop(None, None)
    return data


def read_folder(folder):
    """Every Crumple history in a results folder; {key: Curve}."""
    if not os.path.isdir(folder):
        raise CompareError("no such folder", folder)
    def by_id(stem, column, names):
        # One curve per id and quantity: '<stem>.<column><id>.<quantity>' (matsum.part3.internal).
        return lambda p: _series(p, [column], names, lambda i, q: f"{stem}.{column}{i[0]}.{q}")

    readers = {
        "glstat.csv": lambda p: _series(p, [], mapping.CRUMPLE_GLSTAT,
                                        lambda i, q: f"glstat.{q}"),
        "matsum.csv": by_id("matsum", "part", mapping.CRUMPLE_MATSUM),
        "nodout.csv": by_id("nodout", "node", mapping.CRUMPLE_NODOUT),
        "rwforc.csv": by_id("rwforc", "wall", mapping.CRUMPLE_RWFORC),
        "rcforc.csv": _rcforc,
        "secforc.csv": by_id("secforc", "section", mapping.CRUMPLE_SECFORC),
        "spcforc.csv": by_id("spcforc", "node", mapping.CRUMPLE_SPCFORC),
        "bndout.csv": by_id("bndout", "node", mapping.CRUMPLE_BNDOUT),
        "rbdout.csv": by_id("rbdout", "body", mapping.CRUMPLE_RBDOUT),
        "deforc.csv": by_id("deforc", "element", mapping.CRUMPLE_DEFORC),
        "elout.csv": _elout,
    }
    curves = {}
    for name, reader in readers.items():
        path = os.path.join(folder, name)
        if os.path.isfile(path):
            curves.update(build(reader(path), lambda k, p=path: p))
    if not curves:
        raise CompareError("no Crumple history (glstat.csv, matsum.csv, ...): not a results "
                           "folder of `crumple run`", folder)
    return curves
