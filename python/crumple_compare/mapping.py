"""Which Crumple column is which LS-DYNA quantity. Both readers name every curve by one key,
'<file>.<entity><id>.<quantity>' or '<file>.<quantity>':

| key | LS-DYNA (ASCII file: field) | Crumple (CSV: column) |
| --- | --- | --- |
| glstat.kinetic, .internal, .hourglass | glstat: kinetic / internal / hourglass energy | glstat.csv: kinetic, internal, hourglass |
| glstat.contact | glstat: sliding interface energy | glstat.csv: contact |
| glstat.external_work, .total, .energy_ratio | glstat: external work, total energy, total energy / initial energy | glstat.csv: external_work, total, energy_ratio |
| glstat.rigidwall, .dt, .added_mass | glstat: stonewall energy, time step, added mass | glstat.csv: rigidwall, dt, added_mass |
| matsum.partP.kinetic, .internal, .hourglass | matsum: kinen, inten, hgeng of mat.# P | matsum.csv: kinetic, internal, hourglass (part P) |
| matsum.partP.x_momentum (y, z) | matsum: x-mom (y-mom, z-mom) | matsum.csv: x_momentum (y, z) |
| rcforc.contactC.slave.fx (fy, fz) | rcforc: 'slave C ... x' (y, z) | rcforc.csv: fx (fy, fz), contact C, side 1 (SURFA) |
| rcforc.contactC.master.fx (fy, fz) | rcforc: 'master C ... x' (y, z) | rcforc.csv: side 2 (SURFB) |
| sleout.contactC.energy | sleout: slave + master energy of interface C | rcforc.csv: energy of contact C |
| sleout.total | sleout: summary 'total energy' | sum of rcforc.csv energy over the contacts |
| rwforc.wallW.fn (fx, fy, fz) | rwforc: normal force (x, y, z force) of wall W | rwforc.csv: fn (fx, fy, fz), wall W |
| nodout.nodeN.dx (dy, dz, vx .. az, x, y, z) | nodout: x-disp .. z-accl, x-coor .. z-coor | nodout.csv: the same names, node N |
| secforc.sectionS.fx (fy, fz, mx, my, mz, cx, cy, cz, area) | secforc: x-force .. z-moment, x-center .. z-center, area of section S | secforc.csv: the same names, section S |

Quantities with no counterpart on the other side (eroded energies, spring and damper energy,
rotations, contact moments) are read and listed as unmatched in the
report, never dropped silently."""

import re

GLSTAT_LABELS = {
    "kinetic energy": "kinetic", "internal energy": "internal",
    "hourglass energy": "hourglass", "sliding interface energy": "contact",
    "external work": "external_work", "total energy": "total",
    "total energy / initial energy": "energy_ratio", "time step": "dt",
    "stonewall energy": "rigidwall", "added mass": "added_mass",
    "spring and damper energy": "spring_damper", "system damping energy": "damping",
    "eroded kinetic energy": "eroded_kinetic", "eroded internal energy": "eroded_internal",
    "eroded hourglass energy": "eroded_hourglass",
    "energy ratio w/o eroded energy": "energy_ratio_wo_eroded",
    "global x velocity": "x_velocity", "global y velocity": "y_velocity",
    "global z velocity": "z_velocity",
}

MATSUM_FIELDS = {"inten": "internal", "kinen": "kinetic", "hgeng": "hourglass",
                 "x-mom": "x_momentum", "y-mom": "y_momentum", "z-mom": "z_momentum",
                 "eroded_ie": "eroded_internal", "eroded_ke": "eroded_kinetic",
                 "x-rbv": "x_rigid_velocity", "y-rbv": "y_rigid_velocity",
                 "z-rbv": "z_rigid_velocity"}

RCFORC_FIELDS = {"x": "fx", "y": "fy", "z": "fz"}

NODOUT_TRANSLATION = ["dx", "dy", "dz", "vx", "vy", "vz", "ax", "ay", "az", "x", "y", "z"]
NODOUT_ROTATION = ["rx", "ry", "rz", "rvx", "rvy", "rvz", "rax", "ray", "raz"]

# Column or label names of rwforc/secforc, as the manuals and LS-PrePost name them.
_ENTITY_COLUMNS = {
    "time": "time", "t": "time", "normal-force": "fn", "normal": "fn", "nforce": "fn",
    "x-force": "fx", "y-force": "fy", "z-force": "fz", "xforce": "fx", "yforce": "fy",
    "zforce": "fz", "x-moment": "mx", "y-moment": "my", "z-moment": "mz",
    "x-center": "cx", "y-center": "cy", "z-center": "cz", "area": "area",
    "resultant": "resultant", "total": "resultant",
}

# Crumple CSV columns and the key quantity they become.
CRUMPLE_GLSTAT = ["kinetic", "internal", "hourglass", "contact", "external_work", "total",
                  "energy_ratio", "rigidwall", "dt", "added_mass"]
CRUMPLE_MATSUM = ["kinetic", "internal", "hourglass", "x_momentum", "y_momentum", "z_momentum"]
CRUMPLE_NODOUT = NODOUT_TRANSLATION
CRUMPLE_RWFORC = ["fn", "fx", "fy", "fz"]
CRUMPLE_SECFORC = ["fx", "fy", "fz", "mx", "my", "mz", "cx", "cy", "cz", "area"]
CRUMPLE_RCFORC_SIDES = {1: "slave", 2: "master"}
CRUMPLE_SPCFORC = ["fx", "fy", "fz", "mx", "my", "mz"]
CRUMPLE_BNDOUT = ["fx", "fy", "fz", "energy"]
CRUMPLE_RBDOUT = ["x", "y", "z", "dx", "dy", "dz", "vx", "vy", "vz", "ax", "ay", "az", "rx", "ry",
                  "rz", "wx", "wy", "wz", "alphax", "alphay", "alphaz"]
CRUMPLE_DEFORC = ["force", "elongation", "fx", "fy", "fz"]


def glstat_quantity(label):
    """The key quantity of a glstat label ('sliding interface energy' -> 'contact'); a label
    not in the table keeps its words ('new thing energy' -> 'new_thing_energy')."""
    label = label.strip().lower()
    return GLSTAT_LABELS.get(label, re.sub(r"[^a-z0-9]+", "_", label).strip("_"))


def nodout_columns(header):
    if "x-disp" in header:
        return NODOUT_TRANSLATION
    if "x-rot" in header:
        return NODOUT_ROTATION
    return None


def entity_field(token, entity):
    """True when a header token names the entity id column ('wall#', 'section', 'sec#')."""
    word = token.lower().rstrip("#:")
    return word in (entity, entity[:3], "id") or word == entity + "s"


def column_name(token, entity):
    word = token.lower().rstrip(":=")
    if entity_field(word, entity):
        return "id"
    return _ENTITY_COLUMNS.get(word, re.sub(r"[^a-z0-9]+", "_", word).strip("_"))
