#!/usr/bin/env python3
"""Reads Crumple's VTK output with VTK's own XML readers and prints a JSON summary.

    read_vtu.py FILE [--values] [--volumes]

FILE is a .vtu, a .pvtu, a .pvd collection, or a results folder (its results.pvd is read).
A .vtu/.pvtu gives one summary; a .pvd or folder gives {"file", "states": [summary, ...]}
with each state's "timestep". A summary holds the point and cell counts, the VTK cell type of
every cell and a count per type, and per point/cell array its data type, components, first
tuple and range; --values adds every array's values (flattened), --volumes each cell's volume
(vtkCellSizeFilter; a wrongly ordered cell shows up as a negative volume).

Any error VTK reports makes the script fail (exit 1): a file VTK reads only with complaints
is broken. Exit 77 means no Python reachable from here can import vtk (callers skip).
"""

import argparse
import json
import os
import sys
import xml.etree.ElementTree as ET

SKIP = 77


try:
    import vtk
except ImportError:
    vtk = None


def reexec_with_vtk_or_skip():
    """Re-runs this script under a system Python that has vtk when the current interpreter
    (often a pyenv or virtualenv one) lacks the Debian python3-vtk9 bindings."""
    if not os.environ.get("CRUMPLE_READ_VTU_REEXEC"):
        for candidate in ("/usr/bin/python3", "/usr/local/bin/python3"):
            if os.path.exists(candidate) and os.path.realpath(candidate) != os.path.realpath(
                    sys.executable):
                env = dict(os.environ, CRUMPLE_READ_VTU_REEXEC="1")
                os.execve(candidate, [candidate, os.path.abspath(__file__)] + sys.argv[1:], env)
    sys.stderr.write("read_vtu.py: no Python with the vtk module (python3-vtk9) was found\n")
    sys.exit(SKIP)


class ErrorCollector:
    """Turns VTK error and warning events into a list instead of text on stderr."""

    def __init__(self):
        self.messages = []

        @vtk.calldata_type(vtk.VTK_STRING)
        def collect(caller, event, text):
            self.messages.append(f"{event}: {str(text).strip()}")

        self.callback = collect

    def watch(self, obj):
        obj.AddObserver("ErrorEvent", self.callback)
        obj.AddObserver("WarningEvent", self.callback)


def read_grid(path):
    ext = os.path.splitext(path)[1].lower()
    if ext == ".vtu":
        reader = vtk.vtkXMLUnstructuredGridReader()
    elif ext == ".pvtu":
        reader = vtk.vtkXMLPUnstructuredGridReader()
    else:
        raise SystemExit(f"read_vtu.py: '{path}' is not a .vtu, .pvtu or .pvd file")
    if not os.path.isfile(path):
        raise SystemExit(f"read_vtu.py: '{path}' does not exist")
    errors = ErrorCollector()
    errors.watch(reader)
    # Errors of the piece readers inside a .pvtu reader are reported through the output window.
    window = vtk.vtkOutputWindow.GetInstance()
    window_errors = ErrorCollector()
    window_errors.watch(window)
    reader.SetFileName(path)
    reader.Update()
    window.RemoveAllObservers()
    problems = errors.messages + window_errors.messages
    if problems:
        raise SystemExit(f"read_vtu.py: VTK could not read '{path}' cleanly: {problems}")
    return reader.GetOutput()


def array_summary(array, want_values):
    n = array.GetNumberOfTuples()
    c = array.GetNumberOfComponents()
    summary = {
        "type": array.GetDataTypeAsString(),
        "components": c,
        "tuples": n,
        "first": list(array.GetTuple(0)) if n > 0 else [],
        "range": [min(array.GetRange(k)[0] for k in range(c)),
                  max(array.GetRange(k)[1] for k in range(c))] if n > 0 else [],
    }
    if want_values:
        summary["values"] = [array.GetComponent(i, k) for i in range(n) for k in range(c)]
    return summary


def grid_summary(grid, want_values, want_volumes):
    types = [grid.GetCellType(i) for i in range(grid.GetNumberOfCells())]
    counts = {}
    for t in types:
        counts[str(t)] = counts.get(str(t), 0) + 1
    summary = {
        "points": grid.GetNumberOfPoints(),
        "cells": grid.GetNumberOfCells(),
        "cell_types": types,
        "cell_type_counts": counts,
        "point_data": {},
        "cell_data": {},
    }
    for key, data in (("point_data", grid.GetPointData()), ("cell_data", grid.GetCellData())):
        for i in range(data.GetNumberOfArrays()):
            array = data.GetAbstractArray(i)
            summary[key][array.GetName()] = array_summary(array, want_values)
    if want_volumes:
        sizes = vtk.vtkCellSizeFilter()
        sizes.SetInputData(grid)
        sizes.ComputeVertexCountOff()
        sizes.ComputeLengthOff()
        sizes.ComputeAreaOff()
        sizes.Update()
        volume = sizes.GetOutput().GetCellData().GetArray("Volume")
        summary["volumes"] = [volume.GetValue(i) for i in range(volume.GetNumberOfTuples())]
    return summary


def read_pvd(path, want_values, want_volumes):
    root = ET.parse(path).getroot()
    if root.get("type") != "Collection":
        raise SystemExit(f"read_vtu.py: '{path}' is not a VTK Collection file")
    folder = os.path.dirname(os.path.abspath(path))
    states = []
    for dataset in root.iter("DataSet"):
        file = dataset.get("file")
        summary = grid_summary(read_grid(os.path.join(folder, file)), want_values, want_volumes)
        summary = {"timestep": float(dataset.get("timestep")), "file": file, **summary}
        states.append(summary)
    return {"file": path, "states": states}


def summarize(path, want_values=False, want_volumes=False):
    if os.path.isdir(path):
        path = os.path.join(path, "results.pvd")
    if path.lower().endswith(".pvd"):
        return read_pvd(path, want_values, want_volumes)
    return {"file": path, **grid_summary(read_grid(path), want_values, want_volumes)}


def main():
    if vtk is None:
        reexec_with_vtk_or_skip()
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file", help=".vtu, .pvtu, .pvd or a results folder")
    parser.add_argument("--values", action="store_true", help="print every array value")
    parser.add_argument("--volumes", action="store_true", help="print every cell volume")
    args = parser.parse_args()
    json.dump(summarize(args.file, args.values, args.volumes), sys.stdout, indent=1)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
