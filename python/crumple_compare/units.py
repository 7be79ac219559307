"""The consistent unit systems of LS-DYNA decks (Keyword Manual vol. I, "Consistent units"),
for axis labels and for the seconds per time unit the CFC filter needs. A deck has no units of
its own: the run records the system it was given or found (summary.json "units"), or none."""

import json
import os

from .errors import CompareError

# name: the unit of each quantity and the seconds per time unit.
SYSTEMS = {
    "kg-m-s": {"time": "s", "length": "m", "mass": "kg", "force": "N", "energy": "J",
               "stress": "Pa", "seconds": 1.0},
    "kg-mm-ms": {"time": "ms", "length": "mm", "mass": "kg", "force": "kN", "energy": "J",
                 "stress": "GPa", "seconds": 1e-3},
    "t-mm-s": {"time": "s", "length": "mm", "mass": "t", "force": "N", "energy": "mJ",
               "stress": "MPa", "seconds": 1.0},
    "g-mm-ms": {"time": "ms", "length": "mm", "mass": "g", "force": "N", "energy": "mJ",
                "stress": "MPa", "seconds": 1e-3},
    "g-cm-us": {"time": "us", "length": "cm", "mass": "g", "force": "1e7 N", "energy": "1e5 J",
                "stress": "Mbar", "seconds": 1e-6},
    "kg-mm-s": {"time": "s", "length": "mm", "mass": "kg", "force": "mN", "energy": "uJ",
                "stress": "kPa", "seconds": 1.0},
    "lbfs2/in-in-s": {"time": "s", "length": "in", "mass": "lbf s^2/in", "force": "lbf",
                      "energy": "lbf in", "stress": "psi", "seconds": 1.0},
}

# Each plotted quantity and its unit in terms of the system's units.
_QUANTITY_UNITS = {
    "time": lambda u: u["time"], "energy": lambda u: u["energy"],
    "force": lambda u: u["force"], "moment": lambda u: f"{u['force']} {u['length']}",
    "displacement": lambda u: u["length"],
    "velocity": lambda u: f"{u['length']}/{u['time']}",
    "acceleration": lambda u: f"{u['length']}/{u['time']}^2",
}


def of_run(run_dir, override=None):
    """The unit system of a run: `override` (a SYSTEMS name) if given, else what the run wrote
    in summary.json ("units": {"system": name, ...}), else None."""
    if override:
        return dict(SYSTEMS[override], name=override)
    path = os.path.join(run_dir, "summary.json")
    if not os.path.isfile(path):
        return None
    try:
        with open(path, encoding="utf-8") as f:
            recorded = json.load(f).get("units") or {}
    except (OSError, ValueError) as e:
        raise CompareError(f"unreadable summary: {e}", path) from e
    name = recorded.get("system")
    if name is None:
        return None
    if name not in SYSTEMS:
        raise CompareError(f"unknown unit system '{name}'", path)
    return dict(SYSTEMS[name], name=name)


def label(quantity, system):
    """'velocity [mm/ms]', or the bare quantity when the system is not known."""
    unit = _QUANTITY_UNITS.get(quantity)
    if system is None or unit is None:
        return quantity
    return f"{quantity} [{unit(system)}]"
