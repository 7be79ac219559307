#!/usr/bin/env python3
"""Regression decks: runs each deck of tests/regression/expected.json and compares the run's
summary (cycles, time step, energies, added mass, eroded elements) with the stored values,
each with its own tolerance. Catches a change of the physics that no analytic test notices.

When a change of results is intended, regenerate the file and say why in the commit:
    python3 tests/regression/check_regression.py CRUMPLE SOURCE_DIR --update

usage: check_regression.py CRUMPLE SOURCE_DIR [--update]
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile

# Relative tolerances. Bits are not compared (compiler and library versions may round
# differently); these catch any change of substance.
TOLERANCES = {
    "cycles": 0.0,
    "initial_dt": 1e-9,
    "kinetic": 1e-6,
    "internal": 1e-6,
    "hourglass": 1e-5,
    "drilling": 1e-5,
    "external_work": 1e-6,
    "rigidwall": 1e-5,
    "total": 1e-6,
    "added_mass": 1e-9,
    "eroded_elements": 0.0,
}


def summarise(crumple: str, source: str, case: dict, tmp: str) -> dict:
    out = os.path.join(tmp, case["name"])
    cmd = [crumple, "run", os.path.join(source, case["deck"]), "-o", out, "-q", "--threads", "1"]
    cmd += case.get("args", [])
    env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=600, env=env)
    if proc.returncode != 0:
        raise SystemExit(f"{case['name']}: run failed ({proc.returncode}): {proc.stderr}")
    with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
        s = json.load(f)
    e = s["energy"]
    return {"cycles": s["cycles"], "initial_dt": s["initial_dt"], "kinetic": e["kinetic"],
            "internal": e["internal"], "hourglass": e["hourglass"], "drilling": e["drilling"],
            "external_work": e["external_work"], "rigidwall": e["rigidwall"], "total": e["total"],
            "added_mass": s["mass"]["added"], "eroded_elements": s["eroded_elements"]}


def main() -> int:
    crumple, source = sys.argv[1], sys.argv[2]
    update = "--update" in sys.argv[3:]
    path = os.path.join(source, "tests", "regression", "expected.json")
    with open(path, encoding="utf-8") as f:
        expected = json.load(f)
    passed = failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for case in expected["cases"]:
            got = summarise(crumple, source, case, tmp)
            if update:
                case["values"] = got
                continue
            for key, tol in TOLERANCES.items():
                want = case["values"][key]
                scale = max(abs(want), 1e-30)
                ok = abs(got[key] - want) <= tol * scale
                passed += ok
                failed += not ok
                if not ok:
                    print(f"{case['name']}: {key} = {got[key]!r}, expected {want!r} "
                          f"(relative tolerance {tol})")
            print(f"{case['name']}: checked")
    if update:
        with open(path, "w", encoding="utf-8") as f:
            json.dump(expected, f, indent=2)
            f.write("\n")
        print(f"updated {path}")
        return 0
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
