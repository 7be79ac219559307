"""The d3plot family (src/output/d3plot.hpp) read back by an independent reader, VTK's
vtkLSDynaReader (Debian python3-vtk9, the reader ParaView uses), against the VTU states of the
same run and against the layout of d3plot files written by LS-DYNA itself
(/work/shared/reference/d3plot-samples, when present):

- solids, shells (quads and C0 triangles), beams (Hughes-Liu, resultant, truss) and springs:
  point and cell counts, part titles, node and element ids, current coordinates,
  displacements, velocities, accelerations, solid stresses and plastic strain, shell stresses
  at the mid, inner and outer surface, thickness, spring forces: the VTU values to float
  precision, at every state; the state times are the VTU times;
- the global variables (kinetic, internal, total energy) are glstat's at the last state;
- an element eroded by failure is deleted in the d3plot (VTK drops it, as the VTU does);
- a family split at a small size limit (--d3plot-x) reads as the same states;
- a restarted run continues the family: byte for byte the uninterrupted run's files;
- under mpirun at 2 ranks the family is byte for byte the serial one, but for the global
  variables (energy sums whose last bits depend on the rank count, as glstat's): to rounding;
- the control words have the meanings of LS-DYNA's own files (word by word where the model
  agrees), the NARBS size formula, titles after the first EOF marker, states from d3plot01 on,
  every member ends with the EOF marker padded to 512-word blocks.
Physics: a cantilever of resultant beams under an end load P: shear P, moment P (L - x) at
mid-element, axial force and torque 0; a plate pulled in-plane: membrane force sigma t.
"""

import csv
import os
import shutil
import struct
import subprocess

import clitest
from clitest import TempDirTest, crumple, describe, main, read_summary

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:  # the tests skip (clitest counts them as neither passed nor failed)
    vtk = None

SAMPLES = "/work/shared/reference/d3plot-samples"
EOF_MARKER = -999999.0
MPI_ENV = clitest.MPI_ENV


def data_deck(name):
    return os.path.join(clitest.SOURCE_DIR, "tests", "data", "decks", name)


def family(folder):
    """The d3plot family members of a folder, in order."""
    names = [f for f in os.listdir(folder) if f == "d3plot" or
             (f.startswith("d3plot") and f[6:].isdigit())]
    return sorted(names, key=lambda f: int(f[6:] or 0))


def read_bytes(path):
    with open(path, "rb") as f:
        return f.read()


def words(path):
    data = read_bytes(path)
    n = len(data) // 4
    return struct.unpack(f"<{n}i", data), struct.unpack(f"<{n}f", data)


def part_titles(deck):
    """{title: part id} of the *PART cards of a deck (title line, then PID in columns 1-10)."""
    with open(deck, encoding="utf-8") as f:
        lines = [l.rstrip("\n") for l in f if not l.startswith("$")]
    out = {}
    for k, line in enumerate(lines):
        name = line.strip().upper()
        if name.startswith("*PART"):
            # A plain *PART may hold several parts: title and card pairs up to the next
            # keyword; an option (_INERTIA, ...) adds cards after the first pair.
            while k + 2 < len(lines) and not lines[k + 1].startswith("*"):
                out[lines[k + 1].strip()] = int(lines[k + 2][:10])
                k += 2
                if name != "*PART":
                    break
    return out


def family_class(cell):
    """solid, shell or line, by VTK cell type (a d3plot triangle is a quad with n3 = n4)."""
    return {vtk.VTK_QUAD: "shell", vtk.VTK_TRIANGLE: "shell",
            vtk.VTK_LINE: "line"}.get(cell.GetCellType(), "solid")


def array(data, name):
    a = data.GetArray(name)
    return None if a is None else vtk_to_numpy(a)


def vtu_states(folder):
    """(time, path) of every state in results.pvd."""
    import xml.etree.ElementTree as ET
    root = ET.parse(os.path.join(folder, "results.pvd")).getroot()
    return [(float(d.get("timestep")), os.path.join(folder, d.get("file")))
            for d in root.iter("DataSet")]


def read_vtu_cells(path):
    """Per node id: coordinates, displacement, velocity, acceleration; per (class, part,
    element id): the cell arrays."""
    r = vtk.vtkXMLUnstructuredGridReader() if path.endswith(".vtu") else \
        vtk.vtkXMLPUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    ug = r.GetOutput()
    pd, cd = ug.GetPointData(), ug.GetCellData()
    pts = vtk_to_numpy(ug.GetPoints().GetData())
    nodes = {}
    ids = array(pd, "node_id")
    for k, nid in enumerate(ids):
        nodes[int(nid)] = {"x": pts[k], "u": array(pd, "displacement")[k],
                           "v": array(pd, "velocity")[k], "a": array(pd, "acceleration")[k]}
    cells = {}
    names = ("stress", "stress_top", "stress_bottom", "effective_plastic_strain",
             "effective_plastic_strain_top", "effective_plastic_strain_bottom", "thickness",
             "axial_force")
    for c in range(ug.GetNumberOfCells()):
        cell = ug.GetCell(c)
        key = (family_class(cell), int(array(cd, "part")[c]),
               int(array(cd, "element_id")[c]))
        cells[key] = {n: array(cd, n)[c] for n in names}
        cells[key]["nodes"] = {int(ids[cell.GetPointId(k)])
                               for k in range(cell.GetNumberOfPoints())}
    return nodes, cells


def read_d3plot(folder, titles, step=-1):
    """The d3plot at state `step` through vtkLSDynaReader: times, nodes and cells keyed as
    read_vtu_cells; fails on any error VTK reports."""
    errors = []

    def note(obj, event):
        errors.append(event)

    r = vtk.vtkLSDynaReader()
    r.AddObserver("ErrorEvent", note)
    r.AddObserver("WarningEvent", note)
    r.SetDatabaseDirectory(folder)
    r.UpdateInformation()
    times = [r.GetTimeValue(k) for k in range(r.GetNumberOfTimeSteps())]
    r.SetTimeStep(step % len(times))
    nodes, cells, counts = {}, {}, {}
    # Nodes with every cell kept (removing the deleted ones renumbers a part's points), cells
    # with the deleted ones removed.
    r.SetRemoveDeletedCells(0)
    r.Update()
    mb = r.GetOutput()
    for b in range(mb.GetNumberOfBlocks()):
        ug = mb.GetBlock(b)
        if ug is None:
            continue
        pd = ug.GetPointData()
        pts = vtk_to_numpy(ug.GetPoints().GetData())
        # By block and point: VTK 9.1 garbles the node ids of 4-byte files (its UserID point
        # array), so nodes are matched by their initial coordinates (node_ids below).
        for k in range(len(pts)):
            nodes[(b, k)] = {"x": pts[k], "v": array(pd, "Velocity")[k],
                             "a": array(pd, "Acceleration")[k]}
    r.SetRemoveDeletedCells(1)
    r.Update()
    mb = r.GetOutput()
    for b in range(mb.GetNumberOfBlocks()):
        ug = mb.GetBlock(b)
        title = mb.GetMetaData(b).Get(vtk.vtkCompositeDataSet.NAME())
        if ug is None:
            continue
        part = titles[title]
        cd = ug.GetCellData()
        for c in range(ug.GetNumberOfCells()):
            cls = family_class(ug.GetCell(c))
            counts[cls] = counts.get(cls, 0) + 1
            cells[(cls, part, int(array(cd, "UserIds")[c]))] = {
                n: array(cd, n)[c] for n in ("Stress", "StressInnerSurf", "StressOuterSurf",
                                             "EffPlastStrn", "EffPlastStrnInnerSurf",
                                             "EffPlastStrnOuterSurf", "Thickness",
                                             "AxialForce", "ShearResultant",
                                             "BendingResultant", "TorsionResultant",
                                             "NormalResultant")
                if cd.GetArray(n) is not None}
    return {"times": times, "nodes": nodes, "cells": cells, "counts": counts,
            "parts": [r.GetPartArrayName(k) for k in range(r.GetNumberOfPartArrays())],
            "errors": errors}


def node_ids(d3_first, vtu_first_nodes):
    """Node id of every (block, point) of the d3plot, from the initial coordinates (the
    first state of both files); None for coincident nodes (tied interfaces, welds), which
    the coordinates cannot tell apart."""
    by_x, seen = {}, set()
    for nid, v in vtu_first_nodes.items():
        key = tuple(f32(float(c)) for c in v["x"])
        by_x[key] = None if key in by_x else nid
    return {k: by_x[tuple(float(c) for c in v["x"])] for k, v in d3_first["nodes"].items()}


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


class D3plotCase(TempDirTest):
    def setUp(self):
        super().setUp()
        if vtk is None:
            self.skipTest("no Python with the vtk module (python3-vtk9)")

    def run_ok(self, *args, runner=None):
        p = (runner or crumple)(*args)
        self.assertEqual(p.returncode, 0, describe(p))
        return p

    def assertClose(self, a, b, scale, what, rel=2e-7):
        """a (float32 from the d3plot) equals b (float64 from the VTU) to float precision."""
        for x, y in zip(list(a) if hasattr(a, "__len__") else [a],
                        list(b) if hasattr(b, "__len__") else [b]):
            self.assertLessEqual(abs(float(x) - float(y)), rel * (abs(float(y)) + scale),
                                 f"{what}: d3plot {a} vs VTU {b}")

    def compare_with_vtu(self, folder, deck, thick_parts=()):
        titles = part_titles(deck)
        states = vtu_states(folder)
        d3 = read_d3plot(folder, titles, 0)
        self.assertEqual(d3["errors"], [])
        self.assertEqual(sorted(d3["parts"]), sorted(titles))
        self.assertEqual(len(d3["times"]), len(states))
        for t3, (t, _) in zip(d3["times"], states):
            self.assertEqual(t3, f32(t))
        ids = node_ids(d3, read_vtu_cells(states[0][1])[0])
        self.assertGreaterEqual(sum(v is not None for v in ids.values()), 0.9 * len(ids))
        x0 = {ids[k]: v["x"] for k, v in d3["nodes"].items() if ids[k] is not None}
        for step in (0, len(states) - 1):
            d3 = read_d3plot(folder, titles, step)
            self.assertEqual(d3["errors"], [])
            d3["nodes"] = {ids[k]: v for k, v in d3["nodes"].items() if ids[k] is not None}
            nodes, cells = read_vtu_cells(states[step][1])
            self.compare_state(d3, nodes, cells, x0, thick_parts)
        return d3, nodes, cells

    def compare_state(self, d3, nodes, cells, x0, thick_parts=()):
        size = max(abs(float(c)) for v in nodes.values() for c in v["x"]) or 1.0
        # The d3plot's parts show the nodes of their elements (not, e.g., beam orientation
        # nodes): every node of a VTU cell, and no other node than the VTU's.
        used = set().union(*(c["nodes"] for c in cells.values())) if cells else set()
        self.assertLessEqual(used & set(x0), set(d3["nodes"]))
        self.assertLessEqual(set(d3["nodes"]), set(nodes))
        for nid, got in d3["nodes"].items():
            v = nodes[nid]
            self.assertClose(got["x"], v["x"], size, f"node {nid} coordinates")
            self.assertClose(got["x"] - x0[nid], v["u"], size, f"node {nid} displacement",
                             rel=4e-7)
            vmax = max(abs(float(c)) for c in v["v"]) + 1e-30
            self.assertClose(got["v"], v["v"], vmax, f"node {nid} velocity")
            self.assertClose(got["a"], v["a"], max(abs(float(c)) for c in v["a"]),
                             f"node {nid} acceleration")
        self.assertEqual(set(d3["cells"]), set(cells))
        for key, c in cells.items():
            got = d3["cells"][key]
            smax = max(abs(float(s)) for s in c["stress"]) + 1e-30
            if key[0] == "solid":
                self.assertClose(got["Stress"], c["stress"], smax, f"{key} stress")
                # VTK 9.1 reads a thick shell's plastic strain from another word (ThickShells).
                if key[1] not in thick_parts:
                    self.assertClose(got["EffPlastStrn"], c["effective_plastic_strain"], 0, key)
            elif key[0] == "shell":
                for d3name, vtuname in (("Stress", "stress"), ("StressInnerSurf", "stress_bottom"),
                                        ("StressOuterSurf", "stress_top")):
                    self.assertClose(got[d3name], c[vtuname], smax, f"{key} {d3name}")
                self.assertClose(got["EffPlastStrnOuterSurf"], c["effective_plastic_strain_top"],
                                 0, key)
                self.assertClose(got["Thickness"], c["thickness"], 0, f"{key} thickness")
            elif c["axial_force"] != 0.0:
                self.assertClose(got["AxialForce"], c["axial_force"], 0, f"{key} spring force")


class Structures(D3plotCase):
    """Solids, shells, triangles, beams of three formulations, springs and dampers."""

    def test_same_as_vtu_and_glstat(self):
        deck = data_deck("structures.k")
        out = os.path.join(self.tmp, "out")
        self.run_ok("run", deck, "-o", out, "-q")
        d3, nodes, cells = self.compare_with_vtu(out, deck)
        s = read_summary(out)
        self.assertEqual(d3["counts"]["solid"], s["counts"]["solids"])
        self.assertEqual(d3["counts"]["shell"], s["counts"]["shells"])
        self.assertEqual(d3["counts"]["line"], s["counts"]["beams"] + s["counts"]["discretes"])
        # Global variables of the last state: glstat's kinetic, internal and total energy.
        header = Header(os.path.join(out, "d3plot"))
        last = header.states(out)[-1]
        with open(os.path.join(out, "glstat.csv"), encoding="utf-8") as f:
            row = list(csv.DictReader(f))[-1]
        self.assertEqual(last[0], f32(float(row["time"])))
        for k, name in enumerate(("kinetic", "internal", "total")):
            self.assertEqual(last[1 + k], f32(float(row[name])), name)
        # Part masses add up to the model's physical mass.
        nmmat = header.w[51]
        masses = last[7 + 5 * nmmat: 7 + 6 * nmmat]
        self.assertAlmostEqual(sum(masses) / s["mass"]["physical"], 1.0, delta=1e-6)

    def test_family_split_reads_the_same(self):
        deck = data_deck("structures.k")
        one, split = os.path.join(self.tmp, "one"), os.path.join(self.tmp, "split")
        self.run_ok("run", deck, "-o", one, "-q")
        # 0.01 x 512^2 words: a few states per member.
        self.run_ok("run", deck, "-o", split, "-q", "--d3plot-x", "0.01")
        self.assertGreater(len(family(split)), 2, family(split))
        titles = part_titles(deck)
        a, b = read_d3plot(one, titles), read_d3plot(split, titles)
        self.assertEqual((a["errors"], b["errors"]), ([], []))
        self.assertEqual(a["times"], b["times"])
        for k in a["nodes"]:
            self.assertEqual(list(a["nodes"][k]["x"]), list(b["nodes"][k]["x"]))
        # The states are the same words, only spread over more members.
        self.assertEqual(Header(os.path.join(one, "d3plot")).states(one),
                         Header(os.path.join(split, "d3plot")).states(split))


def driven_set(set_id, nodes, dof, end, value):
    """Node set `set_id` displaced along `dof` from 0 to `value` over [0, end] (curve 1)."""
    s = f"*SET_NODE_LIST\n{set_id:10d}\n" + "".join(f"{n:10d}" for n in nodes) + "\n"
    s += "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n"
    s += f"{end:20.6g}{value:20.6g}\n"
    return s + f"*BOUNDARY_PRESCRIBED_MOTION_SET\n{set_id:10d}{dof:10d}         2         1       1.0\n"


def eroding_column():
    """Two unit cubes stacked along z: the lower elastic (part 1), the upper (part 2) of a
    plastic steel failing at 5% plastic strain; the bottom held, the top pulled up 5 mm in
    0.1 ms. The upper cube fails and erodes; the lower stays."""
    nodes = [(i + 1 + 4 * layer, x, y, float(layer)) for layer in range(3)
             for i, (x, y) in enumerate(((0, 0), (1, 0), (1, 1), (0, 1)))]
    s = "*KEYWORD\n*TITLE\neroding column\n*CONTROL_TERMINATION\n     0.005\n"
    s += "*DATABASE_BINARY_D3PLOT\n    0.0005\n"
    s += "*PART\nelastic base\n         1         1         1\n"
    s += "*PART\nfailing top\n         2         1         2\n*SECTION_SOLID\n         1         1\n"
    s += "*MAT_ELASTIC\n         1  7.85e-06     210.0       0.3\n"
    s += ("*MAT_PLASTIC_KINEMATIC\n         2  7.85e-06     210.0       0.3      0.25"
          "       1.0       0.0\n       0.0       0.0      0.05       0.0\n*NODE\n")
    s += "".join(f"{n:8d}{x:16.6f}{y:16.6f}{z:16.6f}\n" for n, x, y, z in nodes)
    s += "*ELEMENT_SOLID\n"
    s += "".join(f"{v:8d}" for v in (11, 1, 1, 2, 3, 4, 5, 6, 7, 8)) + "\n"
    s += "".join(f"{v:8d}" for v in (12, 2, 5, 6, 7, 8, 9, 10, 11, 12)) + "\n"
    s += "*SET_NODE_LIST\n         1\n         1         2         3         4\n"
    s += "*BOUNDARY_SPC_SET\n         1         0         1         1         1\n"
    return s + driven_set(2, (9, 10, 11, 12), 3, 0.1, 5.0) + "*END\n"


class SuiteDecks(D3plotCase):
    """Every test deck that asks for a d3plot: VTK opens it and reads the VTU's values."""

    def test_decks(self):
        cases = [(data_deck("mixed_conditions.k"), ()),
                 (data_deck("structures_shell16.k"), ()),
                 (data_deck("rigid_welds.k"), ("--cycles", 100)),
                 (data_deck("contact_tube.k"), ("--cycles", 100)),
                 (clitest.example("bar_impact", "bar_impact.k"), ("--cycles", 100)),
                 (clitest.example("taylor_bar", "taylor_bar.k"), ("--cycles", 100))]
        for deck, extra in cases:
            with self.subTest(deck=os.path.basename(deck)):
                out = os.path.join(self.tmp, os.path.basename(deck))
                self.run_ok("run", deck, "-o", out, "-q", *extra)
                self.compare_with_vtu(out, deck)


class QuadraticTetrahedra(D3plotCase):
    """10-node tetrahedra (ELFORM 16) in the d3plot as their corner tetrahedra with the mean
    stress of their points: VTK reads the VTU's cells, nodes and values (the VTU draws them
    the same way)."""

    def test_tet10_bar(self):
        with open(data_deck("tet10_bar.k"), encoding="utf-8") as f:
            text = f.read()
        deck = self.write("tet10_bar.k", text.replace(
            "*KEYWORD\n", "*KEYWORD\n*DATABASE_BINARY_D3PLOT\n     0.004\n", 1))
        out = os.path.join(self.tmp, "out")
        self.run_ok("run", deck, "-o", out, "-q")
        d3, _, cells = self.compare_with_vtu(out, deck)
        self.assertEqual(d3["counts"]["solid"], read_summary(out)["counts"]["solids"])
        # Plastic by the end: the stresses compared above are not all zero.
        self.assertGreater(max(float(c["effective_plastic_strain"]) for c in cells.values()), 0)


class ThickShells(D3plotCase):
    """Thick shells (*ELEMENT_TSHELL, ELFORM 1 and 2) in the d3plot's own thick-shell section
    (NELT, 9 words each; state records of NV3DT = 3 layers x (6 stresses + plastic strain),
    mid, inner, outer, as the shells' and as lasso-python reads them): VTK reads them as its
    thick-shell cells (hexahedra) with the VTU's nodes and mid stress (the solver's
    through-thickness mean). VTK 9.1 reads the layers' words in another order (the three
    stresses, then the three plastic strains), so the plastic strains and the surface layers
    are checked in the words themselves: the mid layer's plastic strain is the VTU's, and the
    plate swung down about its clamp bends: at the clamp the inner and outer sigma_xx are large
    and of opposite signs."""

    def test_tshell_plates(self):
        for name in ("tshell_plate.k", "tshell2_plate.k"):
            with self.subTest(deck=name), open(data_deck(name), encoding="utf-8") as f:
                deck = self.write(name, f.read().replace(
                    "*KEYWORD\n", "*KEYWORD\n*DATABASE_BINARY_D3PLOT\n      0.05\n", 1))
                out = os.path.join(self.tmp, name + ".out")
                self.run_ok("run", deck, "-o", out, "-q", "--endtime", "0.2")
                h = Header(os.path.join(out, "d3plot"))
                self.assertEqual((h.nel8, h.nelt, h.nv3dt), (0, 60, 21))
                self.assertEqual(h.w[41], 1, "NUMMATT")
                d3, _, cells = self.compare_with_vtu(out, deck, thick_parts={1})
                self.assertEqual(d3["counts"]["solid"], 60)
                # Element 1 (the first thick shell) at the clamp, x from 0 to 5 mm.
                state = h.states(out)[-1]
                at = 1 + h.nglbv + 9 * h.numnp + h.nel8 * h.nv3d
                mid, inner, outer = (state[at + 7 * k: at + 7 * k + 7] for k in range(3))
                vtu = cells[("solid", 1, 1)]
                self.assertClose(mid[:6], vtu["stress"], max(abs(v) for v in mid), "mid")
                self.assertClose(mid[6], vtu["effective_plastic_strain"], 0, "mid eps_p")
                self.assertGreater(min(abs(inner[0]), abs(outer[0])), 0.1, (inner, outer))
                self.assertLess(inner[0] * outer[0], 0.0, (inner, outer))
                self.assertGreater(min(inner[6], outer[6]), 0.0, "the surfaces yield")


class Extent(D3plotCase):
    """*DATABASE_EXTENT_BINARY: the shell switches honoured, the rest reported."""

    def test_shell_flags(self):
        # MAXINT 5, SIGFLG 2 (no shell stresses), EPSFLG 1, RLTFLG 2 (no resultants), ENGFLG 1.
        deck = self.write("extent.k", "*KEYWORD\n*INCLUDE\n" + data_deck("structures.k") +
                          "\n*DATABASE_EXTENT_BINARY\n         0         0         5         0"
                          "         2         1         2         1\n*END\n")
        out = os.path.join(self.tmp, "out")
        self.run_ok("run", deck, "-o", out, "-q")
        h = Header(os.path.join(out, "d3plot"))
        self.assertEqual(h.w[43:47], (999, 1000, 999, 1000))
        self.assertEqual(h.nv2d, 3 * 1 + 4)
        d3 = read_d3plot(out, part_titles(data_deck("structures.k")))
        self.assertEqual(d3["errors"], [])
        shell = next(c for k, c in d3["cells"].items() if k[0] == "shell")
        self.assertNotIn("Stress", shell)
        self.assertIn("EffPlastStrn", shell)
        self.assertIn("Thickness", shell)
        self.assertIn("Stress", next(c for k, c in d3["cells"].items() if k[0] == "solid"))
        with open(os.path.join(out, "run.log"), encoding="utf-8") as f:
            log = f.read()
        self.assertIn("MAXINT", log)  # written as 3: reported as read but not honoured
        self.assertNotIn("SIGFLG", log)


class Erosion(D3plotCase):
    def test_eroded_element_is_deleted(self):
        deck = self.write("column.k", eroding_column())
        out = os.path.join(self.tmp, "out")
        self.run_ok("run", deck, "-o", out, "-q")
        self.assertEqual(read_summary(out)["eroded_elements"], 1)
        titles = part_titles(deck)
        first, last = read_d3plot(out, titles, 0), read_d3plot(out, titles)
        self.assertEqual(sorted(first["cells"]), [("solid", 1, 11), ("solid", 2, 12)])
        self.assertEqual(sorted(last["cells"]), [("solid", 1, 11)])
        # The deletion flags themselves: 1, 1 at the start, 1, 0 at the end.
        h = Header(os.path.join(out, "d3plot"))
        states = h.states(out)
        self.assertEqual(states[0][-2:], (1.0, 1.0))
        self.assertEqual(states[-1][-2:], (1.0, 0.0))
        self.compare_with_vtu(out, deck)


def cantilever(load):
    """Ten resultant beams (ELFORM 2) of 10 mm along x, 10 x 10 mm steel, clamped at x = 0,
    orientation node on +y (s = y, t = z); an end load `load` (kN) along +z ramped over 50 ms.
    The first bending mode, omega = 1.875^2 sqrt(E I / (rho A L^4)) = 5.2 rad/ms, makes that
    quasi-static: the ramp leaves a dynamic error of about 1 / (omega T) = 0.4%. Small
    deflection: the tip moves P L^3 / (3 E I) = 0.19 mm for 0.1 kN."""
    s = "*KEYWORD\n*TITLE\ncantilever\n*CONTROL_TERMINATION\n      50.0\n"
    s += "*DATABASE_BINARY_D3PLOT\n      12.5\n*PART\nbeam\n         1         1         1\n"
    s += "*SECTION_BEAM\n         1         2    0.8333         2         0\n"
    s += "     100.0     833.3     833.3    1406.0     83.33\n"
    s += "*MAT_ELASTIC\n         1   7.85e-6     210.0       0.3\n*NODE\n"
    s += "".join(f"{i + 1:8d}{10.0 * i:16.6f}{0.0:16.6f}{0.0:16.6f}\n" for i in range(11))
    s += f"{99:8d}{0.0:16.6f}{100.0:16.6f}{0.0:16.6f}\n*ELEMENT_BEAM\n"
    s += "".join(f"{e:8d}{1:8d}{e:8d}{e + 1:8d}{99:8d}\n" for e in range(1, 11))
    s += "*BOUNDARY_SPC_NODE\n         1         0         1         1         1         1"
    s += "         1         1\n        99         0         1         1         1         1"
    s += "         1         1\n"
    s += "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n"
    s += "                50.0                 1.0\n"
    s += f"*LOAD_NODE_POINT\n        11         3         1{load:10.4g}\n"
    return s + "*END\n"


def pulled_plate():
    """A 40 x 20 mm plate of 4 x 2 Belytschko-Tsay shells, 1 mm thick, NIP 3, elastic steel,
    in the xy plane (z held): the x = 0 edge held along x (node 1 also along y), the x = 40
    edge pulled 0.02 mm along x in 1 ms. A membrane state: the stress is the same at every
    point through the thickness."""
    s = "*KEYWORD\n*TITLE\npulled plate\n*CONTROL_TERMINATION\n       1.0\n"
    s += "*DATABASE_BINARY_D3PLOT\n      0.25\n*PART\nplate\n         1         1         1\n"
    s += "*SECTION_SHELL\n         1         2    0.8333         3\n"
    s += "       1.0       1.0       1.0       1.0\n"
    s += "*MAT_ELASTIC\n         1   7.85e-6     210.0       0.3\n*NODE\n"
    s += "".join(f"{1 + i + 5 * j:8d}{10.0 * i:16.6f}{10.0 * j:16.6f}{0.0:16.6f}\n"
                 for j in range(3) for i in range(5))
    s += "*ELEMENT_SHELL\n"
    s += "".join(f"{1 + i + 4 * j:8d}{1:8d}{1 + i + 5 * j:8d}{2 + i + 5 * j:8d}"
                 f"{7 + i + 5 * j:8d}{6 + i + 5 * j:8d}\n" for j in range(2) for i in range(4))
    s += "*BOUNDARY_SPC_NODE\n"
    for n in range(1, 16):
        dofs = (1 if n == 1 or n % 5 == 1 else 0, 1 if n == 1 else 0, 1, 1, 1, 0)
        s += f"{n:10d}{0:10d}" + "".join(f"{d:10d}" for d in dofs) + "\n"
    return s + driven_set(1, (5, 10, 15), 1, 1.0, 0.02) + "*END\n"


class Resultants(D3plotCase):
    """The beam and shell resultants against statics."""

    def test_cantilever_shear_and_moment(self):
        load, length = 0.1, 100.0
        deck = self.write("cantilever.k", cantilever(load))
        out = os.path.join(self.tmp, "out")
        self.run_ok("run", deck, "-o", out, "-q")
        d3 = read_d3plot(out, part_titles(deck))
        self.assertEqual(d3["errors"], [])
        self.assertEqual(d3["times"][-1], 50.0)
        shear_t, moment_s = [], []
        for e in range(1, 11):
            c = d3["cells"][("line", 1, e)]
            x_mid = 10.0 * e - 5.0
            # Statics of the cantilever: shear P along t everywhere, bending about s of
            # P (L - x); no axial force, no shear along s, no bending about t, no torque.
            self.assertAlmostEqual(abs(c["ShearResultant"][1]), load, delta=0.01 * load)
            self.assertAlmostEqual(abs(c["BendingResultant"][0]), load * (length - x_mid),
                                   delta=0.01 * load * length)
            for v in (c["AxialForce"], c["ShearResultant"][0], c["BendingResultant"][1],
                      c["TorsionResultant"]):
                self.assertLess(abs(float(v)), 0.01 * load, e)
            shear_t.append(float(c["ShearResultant"][1]))
            moment_s.append(float(c["BendingResultant"][0]))
        # One sign along the whole beam (Crumple's convention, docs/theory.md "d3plot").
        self.assertTrue(all(v > 0 for v in shear_t) or all(v < 0 for v in shear_t), shear_t)
        self.assertTrue(all(v > 0 for v in moment_s) or all(v < 0 for v in moment_s), moment_s)

    def test_plate_membrane_forces(self):
        deck = self.write("plate.k", pulled_plate())
        out = os.path.join(self.tmp, "out")
        self.run_ok("run", deck, "-o", out, "-q")
        h = Header(os.path.join(out, "d3plot"))
        last = h.states(out)[-1]
        # The shell records follow the globals, the nodes, the solids and the beams.
        at = 1 + h.nglbv + 9 * h.numnp + h.nv3d * h.nel8 + h.nv1d * h.nel2
        self.assertEqual(h.nv2d, 33)
        stretched = 0
        for e in range(h.nel4):
            r = last[at + 33 * e: at + 33 * (e + 1)]
            mid, inner, outer = r[0:6], r[7:13], r[14:20]
            m, q, n, thick = r[21:24], r[24:26], r[26:29], r[29]
            self.assertEqual(mid, inner)  # a membrane: every layer alike
            self.assertEqual(mid, outer)
            # N = sigma t (the plate's local axes are the global x, y), M = Q = 0.
            for k, c in ((0, 0), (1, 1), (2, 3)):
                # (to 1e-5 of N: the corotational frame turns by ~1e-6 from the global axes)
                self.assertAlmostEqual(n[k], mid[c] * thick, delta=1e-5 * abs(mid[0]) * thick)
            for v in m:
                self.assertLess(abs(v), 1e-6 * abs(n[0]) * thick)
            for v in q:
                self.assertLess(abs(v), 1e-6 * abs(n[0]))
            # Pulled 0.02 / 40 along x: sigma_xx about E eps = 0.105 GPa, to the ringing.
            stretched += abs(mid[0] / (210.0 * 0.02 / 40.0) - 1.0) < 0.1
        self.assertGreaterEqual(stretched, h.nel4 // 2)


class RestartAndRanks(D3plotCase):
    def test_restart_continues_the_family(self):
        deck = self.write("dump.k", "*KEYWORD\n*INCLUDE\n" + data_deck("structures.k") +
                          "\n*DATABASE_BINARY_D3DUMP\n       400\n*END\n")
        full = os.path.join(self.tmp, "full")
        self.run_ok("run", deck, "-o", full, "-q", "--d3plot-x", "0.01")
        dumps = sorted(f for f in os.listdir(full) if f.startswith("d3dump_"))
        self.assertTrue(dumps)
        again = os.path.join(self.tmp, "again")
        shutil.copytree(full, again)
        self.run_ok("run", deck, "-q", "--d3plot-x", "0.01", "--restart",
                    os.path.join(again, dumps[0]))
        self.assertEqual(family(again), family(full))
        for name in family(full):
            self.assertEqual(read_bytes(os.path.join(again, name)),
                             read_bytes(os.path.join(full, name)), name)

    def test_restart_deck_starts_a_family(self):
        # A run without *DATABASE_BINARY_D3PLOT, restarted with it: a new family, from the
        # restart on, that VTK reads.
        deck = self.write("brick.k", clitest.one_brick_deck(end_time=0.01).replace(
            "*END\n", "*DATABASE_BINARY_D3DUMP\n        50\n*END\n"))
        out = os.path.join(self.tmp, "out")
        self.run_ok("run", deck, "-o", out, "-q")
        self.assertEqual(family(out), [])
        dumps = sorted(f for f in os.listdir(out) if f.startswith("d3dump_"))
        changes = self.write("changes.k", "*KEYWORD\n*DATABASE_BINARY_D3PLOT\n     0.002\n*END\n")
        self.run_ok("run", deck, "-q", "--restart", os.path.join(out, dumps[0]),
                    "--restart-deck", changes)
        self.assertEqual(family(out), ["d3plot", "d3plot01"])
        d3 = read_d3plot(out, {"block": 1})
        self.assertEqual(d3["errors"], [])
        self.assertGreater(d3["times"][0], 0.0)  # the first state is the restart's
        self.assertEqual(d3["times"][-1], f32(read_summary(out)["end_time"]))
        self.assertEqual(sorted(d3["cells"]), [("solid", 1, 1)])

    def test_two_ranks_write_the_serial_states(self):
        mpirun = shutil.which("mpirun")
        if mpirun is None:
            self.skipTest("mpirun not found")
        # Structures of every family; mixed_conditions erodes elements (deletion flags).
        for deck in (data_deck("structures.k"), data_deck("mixed_conditions.k")):
            serial = os.path.join(self.tmp, "serial_" + os.path.basename(deck))
            par = os.path.join(self.tmp, "par_" + os.path.basename(deck))
            self.run_ok("run", deck, "-o", serial, "-q", "--threads", "1")
            p = subprocess.run([mpirun, "--oversubscribe", "-np", "2", clitest.CRUMPLE, "run",
                                deck, "-o", par, "-q", "--threads", "1"], capture_output=True,
                               text=True, timeout=120, env=MPI_ENV)
            self.assertEqual(p.returncode, 0, describe(p))
            self.assertEqual(family(par), family(serial))
            self.assertEqual(read_bytes(os.path.join(par, "d3plot")),
                             read_bytes(os.path.join(serial, "d3plot")))
            # Every state word bitwise, but for the global variables: they are glstat's and
            # matsum's energies, summed per rank and then over ranks, whose last bits depend
            # on the rank count as glstat.csv's do (docs/reliability.md): to float rounding.
            h = Header(os.path.join(serial, "d3plot"))
            a, b = h.states(serial), h.states(par)
            self.assertEqual(len(a), len(b))
            for sa, sb in zip(a, b):
                self.assertEqual(sa[0], sb[0])
                self.assertEqual(sa[1 + h.nglbv:], sb[1 + h.nglbv:])
                # (relative to the largest: a velocity that sums to ~0 is rounding noise)
                scale = max(abs(x) for x in sa[1:1 + h.nglbv])
                for x, y in zip(sa[1:1 + h.nglbv], sb[1:1 + h.nglbv]):
                    self.assertLessEqual(abs(x - y), 1e-6 * max(abs(x), 1e-6 * scale), (x, y))


class Header:
    """The control words of a d3plot and the word layout that follows from them."""

    def __init__(self, path):
        self.path = path
        self.w, self.f = words(path)
        w = self.w
        self.numnp, self.nglbv, self.nel8, self.nel2, self.nel4 = w[16], w[18], w[23], w[28], w[31]
        self.nv3d, self.nv1d, self.nv2d, self.narbs = w[27], w[30], w[33], w[39]
        self.nelt, self.nv3dt = w[40], w[42]
        self.it, self.iu, self.iv, self.ia = w[19:23]
        maxint = w[36]
        self.mdlopt = 2 if maxint < -10000 else (1 if maxint < 0 else 0)
        self.geometry = 64 + 3 * self.numnp + 9 * (self.nel8 + self.nelt) + 6 * self.nel2 + \
            5 * self.nel4

    def state_words(self):
        n = 1 + self.nglbv + self.numnp * (self.it + 3 * (self.iu + self.iv + self.ia))
        n += self.nel8 * self.nv3d + self.nel2 * self.nv1d + self.nel4 * self.nv2d
        n += self.nelt * self.nv3dt
        if self.mdlopt == 2:
            n += self.nel8 + self.nel2 + self.nel4 + self.nelt
        return n + (self.numnp if self.mdlopt == 1 else 0)

    def states(self, folder):
        """Every state of the family as a tuple of floats."""
        size, out = self.state_words(), []
        for name in family(folder)[1:]:
            _, f = words(os.path.join(folder, name))
            at = 0
            while f[at] != EOF_MARKER:
                out.append(f[at:at + size])
                at += size
        return out


class Layout(D3plotCase):
    """Crumple's words against LS-DYNA's: the same meaning in the same place."""

    def check_layout(self, folder):
        h = Header(os.path.join(folder, "d3plot"))
        w, f = h.w, h.f
        self.assertEqual(f[14], 960.0, "version word: IEEE single precision")
        self.assertEqual((w[11], w[15], w[17]), (1, 4, 6), "file type, NDIM, ICODE")
        self.assertIn(w[43], (999, 1000))
        # NARBS: 10 words (16 when NSORT < 0), the node and element ids, 3 words per material.
        nsort = w[h.geometry]
        nmmat = w[51]
        self.assertEqual(h.narbs, (16 if nsort < 0 else 10) + h.numnp + h.nel8 + h.nel2 +
                         h.nel4 + w[40] + 3 * nmmat)
        # After the ids: the EOF marker, the part titles (90001), the header title (90000).
        at = h.geometry + h.narbs
        self.assertEqual(f[at], EOF_MARKER)
        self.assertEqual((w[at + 1], w[at + 2]), (90001, nmmat))
        self.assertEqual(w[at + 3 + 19 * nmmat], 90000)
        self.assertEqual(f[at + 4 + 19 * nmmat + 18], EOF_MARKER)
        # Every member ends with the EOF marker and zero padding to whole 512-word blocks;
        # the states start in d3plot01 and fill each member whole.
        for name in family(folder):
            ww, ff = words(os.path.join(folder, name))
            self.assertEqual(len(ww) % 512, 0, name)
            last = max(k for k, v in enumerate(ww) if v != 0)
            self.assertEqual(ff[last], EOF_MARKER, name)
            if name != "d3plot":
                self.assertEqual(last % h.state_words(), 0, name)
        return h

    def test_lsdyna_samples(self):
        if not os.path.isdir(SAMPLES):
            self.skipTest(SAMPLES + " not present")
        for sample in ("d3plot_node_temperature", "d3plot_beamip"):
            with self.subTest(sample=sample):
                self.check_layout(os.path.join(SAMPLES, sample))

    def test_crumple_files(self):
        out = os.path.join(self.tmp, "out")
        self.run_ok("run", data_deck("structures.k"), "-o", out, "-q")
        h = self.check_layout(out)
        w = h.w
        nmmat = w[51]
        self.assertEqual(nmmat, w[24] + w[29] + w[32], "NUMMAT8 + NUMMAT2 + NUMMAT4")
        self.assertEqual(h.nglbv, 6 + 7 * nmmat, "the beamip sample's 13 = 6 + 7 x 1")
        self.assertEqual(w[36], -10003, "MAXINT 3 with element deletion, as the beamip sample")
        self.assertEqual((h.nv3d, h.nv1d), (7, 6))
        self.assertEqual(h.nv2d, 3 * 7 + 8 + 4)
        if os.path.isdir(SAMPLES):
            beamip = Header(os.path.join(SAMPLES, "d3plot_beamip", "d3plot"))
            self.assertEqual((w[11], w[14], w[15], w[17], w[36]),
                             (beamip.w[11], beamip.w[14], beamip.w[15], beamip.w[17],
                              beamip.w[36]))


if __name__ == "__main__":
    main()
