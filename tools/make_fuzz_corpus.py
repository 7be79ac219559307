#!/usr/bin/env python3
"""Writes the seed corpus of the deck fuzzer (tests/fuzz/corpus) from real decks.

Each seed is a slice of one deck small enough for the fuzzer to mutate quickly (at most
MAX_BYTES): every keyword is kept with its first few data lines, element lists are cut to their
first records, and *NODE keeps only the nodes those records name, so that most seeds still
build a model and the fuzzer reaches the builder's later phases, not only the reader.

Usage: tools/make_fuzz_corpus.py [--shared DIR]   (re-run after changing the sources below)
"""

import argparse
import hashlib
import os
import re

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "tests", "fuzz", "corpus")
MAX_BYTES = 12000
KEEP_LINES = 8       # data lines kept per keyword
KEEP_ELEMENTS = 6    # data lines kept per element keyword
KEEP_NODES = 80

SOURCES = ["examples/bar_impact/bar_impact.k", "examples/taylor_bar/taylor_bar.k",
           "tests/data/decks/mixed_conditions.k", "tests/data/decks/rigid_welds.k",
           "tests/data/decks/structures.k"]
SHARED = ["projectile_plate_lstc/tests/testfiles/run/case-keywords/projectile.k",
          "projectile_plate_lstc/tests/testfiles/run/case-keywords/elem.k",
          "ball_plate_pydyna/examples/Explicit/output/ball_plate.k",
          "wb_lsdyna_block/tests/testfiles/keywords/test_node_sets.k"]


def blocks(lines):
    """(keyword line, data lines) in order; lines before the first keyword form a header."""
    out, current = [], None
    for line in lines:
        if line.startswith("*"):
            current = (line, [])
            out.append(current)
        elif current is not None:
            current[1].append(line)
    return out


def integers(line):
    found = set()
    for tok in re.split(r"[\s,]+", line):
        if re.fullmatch(r"[+-]?\d+", tok):
            found.add(int(tok))
    for k in range(0, len(line), 8):  # runs of digits with no blank between fields
        tok = line[k:k + 8].strip()
        if re.fullmatch(r"\d+", tok):
            found.add(int(tok))
    return found


def node_id(line):
    tok = line.split(",")[0] if "," in line else line[:8]
    tok = tok.strip()
    return int(tok) if re.fullmatch(r"\d+", tok) else None


def slice_deck(text):
    data = [b for b in blocks(text.split("\n"))]
    referenced = set()
    kept = []
    for kw, lines in data:
        name = kw.split()[0].upper() if kw.split() else kw
        if name.startswith("*NODE"):
            kept.append((kw, lines, "node"))
            continue
        body = [l for l in lines if not l.lstrip().startswith("$")][:KEEP_ELEMENTS if name.startswith("*ELEMENT") else KEEP_LINES]
        if name.startswith("*ELEMENT"):
            for l in body:
                referenced |= integers(l)
        # Keep one comment line per keyword: comments are part of what the reader skips.
        comments = [l for l in lines[:2] if l.lstrip().startswith("$")][:1]
        kept.append((kw, comments + body, "other"))
    out = []
    for kw, lines, kind in kept:
        if kind == "node":
            lines = [l for l in lines if node_id(l) in referenced][:KEEP_NODES]
        out.append(kw)
        out.extend(lines)
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--shared", default=os.path.join(ROOT, "..", "shared", "decks"))
    args = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    paths = [os.path.join(ROOT, p) for p in SOURCES]
    paths += [os.path.join(args.shared, p) for p in SHARED if os.path.exists(os.path.join(args.shared, p))]
    seeds = []
    for path in paths:
        with open(path, encoding="utf-8", errors="replace") as f:
            seeds.append((path, slice_deck(f.read()).encode()[:MAX_BYTES]))
    # The malformed decks of the CLI test, as they are (small, and each one a way to fail).
    malformed = os.path.join(ROOT, "tests", "data", "malformed")
    for name in sorted(os.listdir(malformed)):
        if name.endswith(".k"):
            with open(os.path.join(malformed, name), "rb") as f:
                seeds.append((name, f.read()[:MAX_BYTES]))
    for path, seed in seeds:
        if not seed:
            continue  # libFuzzer tries the empty input by itself
        name = os.path.splitext(os.path.basename(path))[0]
        with open(os.path.join(OUT, f"{name}-{hashlib.sha1(seed).hexdigest()[:8]}.k"), "wb") as f:
            f.write(seed)


if __name__ == "__main__":
    main()
