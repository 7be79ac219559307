"""A named time history, as both readers return it."""

from dataclasses import dataclass, field

import numpy as np


@dataclass
class Curve:
    """One quantity over time. `key` is the name shared by both codes (see mapping.py), e.g.
    'glstat.kinetic', 'matsum.part10.internal', 'rcforc.contact2.slave.fx',
    'nodout.node1100002.ax'; `source` is the file (and line of the first sample)."""

    key: str
    t: np.ndarray
    y: np.ndarray
    source: str = ""
    label: str = ""
    extra: dict = field(default_factory=dict)


def build(series, source_of):
    """Curves from {key: ([t...], [y...])}; `source_of(key)` names where each came from.
    Samples at a repeated time keep the last value (a restart or a second block at one time)."""
    out = {}
    for key, (ts, ys) in series.items():
        t = np.asarray(ts, dtype=float)
        y = np.asarray(ys, dtype=float)
        order = np.argsort(t, kind="stable")
        t, y = t[order], y[order]
        keep = np.ones(len(t), dtype=bool)
        keep[:-1] = t[1:] != t[:-1]
        out[key] = Curve(key, t[keep], y[keep], source_of(key))
    return out
