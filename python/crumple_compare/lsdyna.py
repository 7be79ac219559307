"""Readers of LS-DYNA's ASCII output files (glstat, matsum, nodout, rcforc, rwforc, secforc,
sleout, spcforc, bndout, rbdout, deforc, elout), in the layouts LS-DYNA R13 writes them (the samples are the bolted-joint results in
../shared/decks/bolted_joint_lsdyna/Bolt_B_Explicit). Each reader returns {key: Curve} with
the keys of mapping.py. rwforc and secforc have no sample here: their readers take both a
table (a header row of names, then rows of numbers) and labelled values ('x-force= 1.0E+00'),
as the LS-DYNA Keyword Manual's *DATABASE_OPTION describes their content; see
docs/validation.md for what is doubtful.

Numbers are Fortran E fields that may touch ('2.74E-05-7.90E+00'): they are split by the
regex, not by white space."""

import os
import re

from . import mapping
from .curves import build
from .errors import CompareError

NUM = r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?"
_NUM_RE = re.compile(NUM)
_DOTTED = re.compile(r"^\s*(\S.*?)\s*\.{2,}\s*(" + NUM + r")\s*$")
_PAIR = re.compile(r"([A-Za-z][A-Za-z0-9_\-#\.]*)\s*=?\s*(" + NUM + r")(?![\w.])")
_PAIR_EQ = re.compile(r"([A-Za-z][A-Za-z0-9_\-#\.]*)\s*=\s*(" + NUM + r")")
FILES = ("glstat", "matsum", "nodout", "rcforc", "rwforc", "secforc", "sleout", "spcforc",
         "bndout", "rbdout", "deforc", "elout")


_ID_ROW = re.compile(r"^\s*(\d+)(?=[\s+-])(.*)$")


def numbers(text):
    return [float(x) for x in _NUM_RE.findall(text)]


def id_row(line):
    """(id, numbers) of a row that starts with an integer id, which the first number may touch
    when it is negative ('  1100002-4.08233E-11 ...'); None for any other line."""
    m = _ID_ROW.match(line)
    return (m.group(1), numbers(m.group(2))) if m else None


def _lines(path):
    """The lines of a file, with LS-DYNA's banner (the title line and the 'ls-dyna ... date'
    line, whose version numbers are no data) blanked so that line numbers stay right."""
    try:
        with open(path, encoding="latin-1") as f:
            lines = f.read().splitlines()
    except OSError as e:
        raise CompareError(f"cannot read: {e.strerror}", path) from e
    for i, line in enumerate(lines[:3]):
        if "ls-dyna" in line.lower():
            lines[: i + 1] = [""] * (i + 1)
    return lines


class _Series:
    """Samples gathered per key, and the line of each key's first sample."""

    def __init__(self, path):
        self.path, self.data, self.first = path, {}, {}

    def add(self, key, t, y, line):
        ts, ys = self.data.setdefault(key, ([], []))
        ts.append(t)
        ys.append(y)
        self.first.setdefault(key, line)

    def curves(self):
        return build(self.data, lambda k: f"{self.path}:{self.first[k]}")


def read_glstat(path):
    """Blocks of 'label....... value' lines, each block opened by 'time......'."""
    out, t, seen = _Series(path), None, False
    for no, line in enumerate(_lines(path), 1):
        m = _DOTTED.match(line)
        if not m:
            continue
        label = " ".join(m.group(1).replace(".", " ").split())
        value = float(m.group(2))
        if label == "time":
            t, seen = value, True
            continue
        if t is None:
            raise CompareError(f"'{label}' before the first 'time....' line", path, no)
        out.add("glstat." + mapping.glstat_quantity(label), t, value, no)
    if not seen:
        raise CompareError("not an LS-DYNA glstat file: no 'time......' line", path)
    return out.curves()


def read_matsum(path):
    """' time = T' then per part ' mat.#= ID inten= ... kinen= ...' and continuation lines."""
    out, t, part, seen = _Series(path), None, None, False
    for no, line in enumerate(_lines(path), 1):
        for name, value in _PAIR_EQ.findall(line):
            name = name.lower()
            if name == "time":
                t, part, seen = float(value), None, True
            elif name in ("mat.#", "part", "part#", "mat#"):
                part = int(float(value))
            elif part is None or t is None:
                raise CompareError(f"'{name}=' outside a part block", path, no)
            else:
                key = f"matsum.part{part}.{mapping.MATSUM_FIELDS.get(name, name)}"
                out.add(key, t, float(value), no)
    if not seen:
        raise CompareError("not an LS-DYNA matsum file: no 'time =' line", path)
    return out.curves()


_NODOUT_TIME = re.compile(r"at time\s*(" + NUM + r")")


def read_nodout(path):
    """Blocks '... at time T', a header 'nodal point x-disp ...' (or 'x-rot ...'), then one
    row per node: the id and the header's numbers."""
    out, t, columns, seen = _Series(path), None, None, False
    for no, line in enumerate(_lines(path), 1):
        m = _NODOUT_TIME.search(line)
        if m:
            t, columns, seen = float(m.group(1)), None, True
            continue
        if "nodal point" in line:
            columns = mapping.nodout_columns(line)
            if columns is None:
                raise CompareError("unknown nodout column header: " + line.strip(), path, no)
            continue
        if columns is None or not line.strip() or "{" in line:
            continue
        row = id_row(line)
        if row is None:
            continue
        head, values = row
        if len(values) != len(columns):
            raise CompareError(f"node {head}: {len(values)} numbers, the header has "
                               f"{len(columns)}", path, no)
        for name, value in zip(columns, values):
            out.add(f"nodout.node{head}.{name}", t, value, no)
    if not seen:
        raise CompareError("not an LS-DYNA nodout file: no 'at time' line", path)
    return out.curves()


_RCFORC = re.compile(r"^\s*(slave|master)\s+(\d+)\s+time\s+(" + NUM + r")(.*)$")


def read_rcforc(path):
    """Rows '  slave  ID time T  x FX  y FY  z FZ mass M  mx .. my .. mz ..' (and master);
    single-surface interfaces print a note instead ('resultants are undefined')."""
    out = _Series(path)
    for no, line in enumerate(_lines(path), 1):
        m = _RCFORC.match(line)
        if not m:
            continue
        side, cid, t = m.group(1), m.group(2), float(m.group(3))
        for name, value in re.findall(r"([a-z]+)\s+(" + NUM + r")", m.group(4)):
            key = f"rcforc.contact{cid}.{side}.{mapping.RCFORC_FIELDS.get(name, name)}"
            out.add(key, t, float(value), no)
    return out.curves()


_SLEOUT_TIME = re.compile(r"interface energy file, time\s*=\s*(" + NUM + r")")
_SLEOUT_SUMMARY = {"total slave side": "total_slave", "total mastr side": "total_master",
                   "total master side": "total_master", "total energy": "total",
                   "friction energy": "friction"}


def read_sleout(path):
    """Blocks 'contact interface energy file, time= T', rows 'ID slave master [frictional]',
    and the summary lines ('total energy    = E')."""
    out, t = _Series(path), None
    for no, line in enumerate(_lines(path), 1):
        m = _SLEOUT_TIME.search(line)
        if m:
            t = float(m.group(1))
            continue
        if t is None:
            continue
        text = line.replace("summary", "").strip()
        label = text.split("=")[0].strip() if "=" in text else None
        if label in _SLEOUT_SUMMARY:
            out.add("sleout." + _SLEOUT_SUMMARY[label], t, numbers(text.split("=")[1])[0], no)
            continue
        row = id_row(line)
        if row is not None and "cycle" not in line:
            ident, values = row
            if len(values) < 2:
                raise CompareError(f"interface {ident}: expected slave and master energies",
                                   path, no)
            base = f"sleout.contact{ident}."
            out.add(base + "slave", t, values[0], no)
            out.add(base + "master", t, values[1], no)
            out.add(base + "energy", t, values[0] + values[1], no)
            if len(values) > 2:
                out.add(base + "friction", t, values[2], no)
    if t is None:
        raise CompareError("not an LS-DYNA sleout file: no 'interface energy file, time=' line",
                           path)
    return out.curves()


def _entity_rows(path, entity):
    """The rows of rwforc/secforc as (line, time, id, {name: value}). A row is either a table
    row under a header of names (one of them the entity, e.g. 'wall#', maybe 'time') or a
    group of labelled values ('section# 1 time 1.0E-03', 'x-force= ...') that an entity label
    opens. A 'time = T' line sets the time of rows that do not carry one."""
    rows, header, t = [], None, None
    for no, line in enumerate(_lines(path), 1):
        tokens = line.split()
        if not tokens or "{" in line:
            continue
        if not _NUM_RE.search(line) and any(mapping.entity_field(x, entity) for x in tokens):
            header = [mapping.column_name(x, entity) for x in tokens]
            continue
        if header and all(_NUM_RE.fullmatch(x) for x in tokens):
            cols = header if len(tokens) == len(header) else [h for h in header if h != "time"]
            if len(tokens) != len(cols) or (cols is not header and t is None):
                raise CompareError(f"{len(tokens)} numbers under a header of {len(header)} "
                                   "names", path, no)
            values = dict(zip(cols, map(float, tokens)))
            rows.append([no, values.pop("time", t), int(values.pop("id")), values])
            continue
        for name, value in _PAIR.findall(line):
            field = mapping.column_name(name, entity)
            if field == "time":
                t = float(value)
                # The time of a row opened on this line ('section# 1 time T') or still open.
                if rows and (rows[-1][1] is None or rows[-1][0] == no):
                    rows[-1][1] = t
            elif field == "id":
                rows.append([no, t, int(float(value)), {}])
            elif rows:
                rows[-1][3][field] = float(value)
    return rows


def _read_entity_file(path, kind, entity):
    out = _Series(path)
    for no, t, ident, values in _entity_rows(path, entity):
        if t is None:
            raise CompareError(f"{entity} {ident} has no time", path, no)
        for name, value in values.items():
            out.add(f"{kind}.{entity}{ident}.{name}", t, value, no)
    return out.curves()


def read_rwforc(path):
    return _read_entity_file(path, "rwforc", "wall")


def read_secforc(path):
    return _read_entity_file(path, "secforc", "section")


def _timed_lines(path, time_re):
    """(line number, line, time) of the lines after the first block title that `time_re`
    matches (its group 1 is the time); a title itself is yielded with line None."""
    t = None
    for no, line in enumerate(_lines(path), 1):
        m = time_re.search(line)
        if m:
            t = float(m.group(1))
            yield no, None, t
        elif t is not None:
            yield no, line, t


_SPC_TIME = re.compile(r"output at time\s*=\s*(" + NUM + r")")
_SPC_ROW = re.compile(r"^\s*node=\s*(\d+)\s+local x,y,z (forces|moments)\s*=\s*(.*?)\s+setid")


def read_spcforc(path):
    """Blocks 'output at time = T'; rows ' node= ID local x,y,z forces = FX FY FZ   setid S'
    (and 'moments='); the 'force resultants =' (and 'moment resultants=') line."""
    out = _Series(path)
    for no, line, t in _timed_lines(path, _SPC_TIME):
        m = _SPC_ROW.match(line or "")
        what = None
        if m:
            what, values, base = m.group(2), numbers(m.group(3)), f"spcforc.node{m.group(1)}."
        elif "resultants" in (line or ""):
            what = "forces" if "force" in line else "moments"
            values, base = numbers(line.split("=", 1)[1]), "spcforc.total."
        if what is None:
            continue
        if len(values) != 3:
            raise CompareError("an spcforc row without three numbers", path, no)
        for axis, value in zip("xyz", values):
            out.add(base + ("f" if what == "forces" else "m") + axis, t, value, no)
    return out.curves()


_BND_TIME = re.compile(r"o u t p u t\s+t=\s*(" + NUM + r")")
_BND_FIELDS = {"xforce": "fx", "yforce": "fy", "zforce": "fz", "energy": "energy",
               "xmoment": "mx", "ymoment": "my", "zmoment": "mz", "xtotal": "fx",
               "ytotal": "fy", "ztotal": "fz", "etotal": "energy"}


def read_bndout(path):
    """Blocks 'n o d a l   f o r c e/e n e r g y    o u t p u t  t= T'; rows ' nd# ID
    xforce= .. yforce= .. zforce= .. energy= .. setid = .. xmoment= ..' and the totals line."""
    out = _Series(path)
    for no, line, t in _timed_lines(path, _BND_TIME):
        row = re.match(r"^\s*nd#\s*(\d+)", line or "")
        if not row and "xtotal" not in (line or ""):
            continue
        base = f"bndout.node{row.group(1)}." if row else "bndout.total."
        for name, value in _PAIR_EQ.findall(line):
            if name in _BND_FIELDS:
                out.add(base + _BND_FIELDS[name], t, float(value), no)
    return out.curves()


_RBD_TIME = re.compile(r"r i g i d   b o d y   m o t i o n.*time=\s*(" + NUM + r")")
_RBD_ROWS = {"coordinates:": ("x", "y", "z"),
             "displacements:": ("dx", "dy", "dz", "rx", "ry", "rz"),
             "velocities:": ("vx", "vy", "vz", "wx", "wy", "wz"),
             "accelerations:": ("ax", "ay", "az", "alphax", "alphay", "alphaz")}


def read_rbdout(path):
    """Blocks 'r i g i d   b o d y   m o t i o n   a t  cycle= N   time= T'; per body
    ' rigid body ID' (or ' nodal rigid body ID'), its global 'coordinates:', 'displacements:',
    'velocities:', 'accelerations:' rows (translations then rotations), the principal
    directions and the same rows in them (read as '.local.' keys)."""
    out, body, local = _Series(path), None, False
    for no, line, t in _timed_lines(path, _RBD_TIME):
        if line is None:
            body = None
            continue
        m = re.match(r"^\s*(?:nodal )?rigid body\s+(\d+)\s*$", line)
        if m:
            body, local = m.group(1), False
            continue
        if "output in principal" in line:
            local = True
            continue
        label = line.split(":")[0].strip() + ":" if ":" in line else None
        if body is None or label not in _RBD_ROWS:
            continue
        values, names = numbers(line.split(":", 1)[1]), _RBD_ROWS[label]
        if len(values) != len(names):
            raise CompareError(f"rigid body {body}: {len(values)} numbers in '{label}'", path, no)
        base = f"rbdout.body{body}." + ("local." if local else "")
        for name, value in zip(names, values):
            out.add(base + name, t, value, no)
    return out.curves()


_DEF_TIME = re.compile(r"a t   t i m e\s*(" + NUM + r")")
_DEF_FIELDS = {"x-force": "fx", "y-force": "fy", "z-force": "fz", "resultant": "force",
               "length": "elongation"}


def read_deforc(path):
    """Blocks 'd i s c r e t e   e l e m e n t   f o r c e s   a t   t i m e T'; per element
    ' element# ID  x-force= ..  y-force= ..  z-force= ..' and 'resultant= ..  change in
    length= ..'."""
    out, element = _Series(path), None
    for no, line, t in _timed_lines(path, _DEF_TIME):
        if line is None:
            element = None
            continue
        m = re.match(r"^\s*element#\s*(\d+)", line)
        if m:
            element = m.group(1)
        if element is None or "=" not in line:
            continue
        for name, value in _PAIR_EQ.findall(line):
            if name in _DEF_FIELDS:
                out.add(f"deforc.element{element}.{_DEF_FIELDS[name]}", t, float(value), no)
    return out.curves()


_ELO_TIME = re.compile(r"f o r   t i m e  s t e p\s*\d+\s*\(\s*at time\s*(" + NUM + r")")
_ELO_SOLID = ("sxx", "syy", "szz", "sxy", "syz", "szx", "effsg", "yield")
_ELO_BEAM = ("axial", "shear_s", "shear_t", "moment_s", "moment_t", "torsion", "eps_p")
_ELO_BEAM_POINT = ("sigma11", "sigma12", "sigma31", "eps_p")


def _elout_line(out, state, line, t, no):
    """One line of an elout block; `state` holds the block's kind and the current element."""
    if "ipt-shl" in line or re.match(r"^\s*ipt\s+stress", line):
        state.update(kind="shell" if "ipt-shl" in line else "solid", element=None)
        return
    m = re.match(r"^\s*beam/truss # =\s*(\d+)", line)
    element = re.match(r"^\s*(\d+)-\s*(\d+)\s*$", line)
    if m or element:
        state["element"] = (m or element).group(1)
        return
    kind, e = state.get("kind"), state.get("element")
    if e is None:
        return
    solid = re.match(r"^\s*1 [a-z]+ ", line) if kind == "solid" else None
    shell = re.match(r"^\s*(\d+)-\s*\d+ [a-z]+ ", line) if kind == "shell" else None
    point = re.match(r"^\s*(\d+)\s{11}", line) if kind == "beam" else None
    if solid:
        names, base, rest = _ELO_SOLID, f"elout.solid{e}.", line[solid.end():]
    elif shell:
        names, base = _ELO_SOLID[:6] + ("eps_p",), f"elout.shell{e}.ipt{shell.group(1)}."
        rest = line[shell.end():]
    elif kind == "beam" and line.startswith(" " * 11) and "sigma" not in line and numbers(line):
        names, base, rest = _ELO_BEAM, f"elout.beam{e}.", line
    elif point:
        names, base = _ELO_BEAM_POINT, f"elout.beam{e}.ipt{point.group(1)}."
        rest = line[point.end():]
    else:
        return
    values = numbers(rest)
    if len(values) != len(names):
        raise CompareError(f"elout {kind} {e}: {len(values)} numbers, {len(names)} expected",
                           state["path"], no)
    for name, value in zip(names, values):
        out.add(base + name, t, value, no)


def read_elout(path):
    """Blocks 'e l e m e n t   s t r e s s   c a l c u l a t i o n s   f o r   t i m e  s t e p
    N ( at time T )' (solids: ' ID- MAT' then '       1 state  sxx .. szx effsg yield';
    shells: per point ' IPT- IOP state  sxx .. szx plastic-strain') and 'r e s u l t a n t s
    a n d   s t r e s s e s ...' (beams: ' beam/truss # = ID', the resultants row axial,
    shear-s, shear-t, moment-s, moment-t, torsion, pl eps, then the integration points'
    sigma 11, 12, 31 and plastic strain)."""
    out, state, t = _Series(path), {"path": path}, None
    for no, line in enumerate(_lines(path), 1):
        m = _ELO_TIME.search(line)
        if m:
            t = float(m.group(1))
            state.update(kind="beam" if "r e s u l t a n t s" in line else None, element=None)
        elif t is not None:
            _elout_line(out, state, line, t, no)
    return out.curves()


READERS = {"glstat": read_glstat, "matsum": read_matsum, "nodout": read_nodout,
           "rcforc": read_rcforc, "rwforc": read_rwforc, "secforc": read_secforc,
           "sleout": read_sleout, "spcforc": read_spcforc, "bndout": read_bndout,
           "rbdout": read_rbdout, "deforc": read_deforc, "elout": read_elout}


def read_folder(folder):
    """Every LS-DYNA ASCII file of FILES present in `folder`; {key: Curve}."""
    if not os.path.isdir(folder):
        raise CompareError("no such folder", folder)
    curves, found = {}, []
    for name in FILES:
        path = os.path.join(folder, name)
        if os.path.isfile(path):
            found.append(name)
            curves.update(READERS[name](path))
    if not found:
        binout = [f for f in os.listdir(folder) if f.startswith("binout")]
        hint = (" (binout is not read: ask LS-DYNA for ASCII files, *DATABASE_GLSTAT etc. with "
                "BINARY = 1 or 3)") if binout else ""
        raise CompareError("no LS-DYNA ASCII file (" + ", ".join(FILES) + ")" + hint, folder)
    return curves
