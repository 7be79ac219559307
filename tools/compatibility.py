#!/usr/bin/env python3
"""Compatibility matrix: what Crumple does with each real LS-DYNA deck in ../shared/decks.

  python3 tools/compatibility.py [--crumple PATH] [--decks DIR] [--out docs/compatibility.md]
                                 [--json FILE] [--cycles 20] [--jobs 1] [--timeout 120]

For every deck folder (its SOURCE.txt names the main deck) it runs `crumple check DECK --json`
and, when the check exits 0, a short `crumple run DECK --cycles N` in a temporary folder. It
writes a generated Markdown page (a summary line, one row per deck, and the missing features
ordered by how many decks need them) and, with --json, the raw results.

Why: the corpus is the closest thing we have to users' decks; the page says which of them
Crumple reads and runs today and which missing feature would unlock the most decks next. The
page has no timestamps or absolute paths so that tests/cli/test_cli_compatibility.py can
check that the committed docs/compatibility.md is what this script writes now.

A binary without `check --json` or `run --cycles` is still handled: the check is judged from
its exit status and first error line, and the short run uses --endtime (N + 1/2) initial steps.
Python 3 standard library only.
"""

from __future__ import annotations

import argparse
import concurrent.futures
import json
import math
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_CRUMPLE = os.path.join(ROOT, "build", "release", "crumple")
DEFAULT_DECKS = os.path.normpath(os.path.join(ROOT, "..", "shared", "decks"))
DEFAULT_OUT = os.path.join(ROOT, "docs", "compatibility.md")
DEFAULT_CYCLES = 20
DEFAULT_TIMEOUT = 120  # seconds per crumple call; longer is reported as a hang
MAX_FEATURES_SHOWN = 3  # per deck in the table; the rest is counted as "+k more"
MAX_MESSAGE = 160  # characters of an error message shown in the table

# Passive OpenMP waiting: with other work on two cores, spinning threads turn short runs
# into long ones. It changes timing only, never results.
ENV = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")

# Check outcomes in the order the summary line lists them.
CHECK_OUTCOMES = ("ok", "refused", "error", "crash", "hang")
OUTCOME_WORDS = {"ok": "read", "refused": "refused", "error": "error",
                 "crash": "crashed", "hang": "hung"}


# ---------------------------------------------------------------------------------------------
# The corpus


def read_source_txt(folder: str) -> dict:
    """'key: value' lines of a deck folder's SOURCE.txt (first occurrence wins), because that
    file, not the folder layout, says which file is the main deck."""
    fields = {}
    with open(os.path.join(folder, "SOURCE.txt"), encoding="utf-8", errors="replace") as f:
        for line in f:
            m = re.match(r"^([A-Za-z ]+):\s*(.*?)\s*$", line)
            if m and m.group(1) not in fields:
                fields[m.group(1)] = m.group(2)
    return fields


def corpus_table_statuses(decks_dir: str) -> dict:
    """{deck: status} from CORPUS.md's table; used only where a SOURCE.txt has no status line,
    so the page still says what the corpus expects of a deck."""
    path = os.path.join(decks_dir, "CORPUS.md")
    if not os.path.isfile(path):
        return {}
    statuses = {}
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
            if len(cells) >= 3 and re.fullmatch(r"[a-z0-9_]+", cells[0]):
                statuses[cells[0]] = cells[2]
    return statuses


def is_complete_explicit(status: str) -> bool:
    """The corpus marks decks that should run in an explicit solver 'complete, explicit'
    (some with a coupled-thermal note); the summary counts how many of those Crumple reads."""
    return status.startswith("complete, explicit")


def list_decks(decks_dir: str) -> list:
    """Every folder with a SOURCE.txt naming a main deck, sorted by name for a stable page."""
    table = corpus_table_statuses(decks_dir)
    decks = []
    for name in sorted(os.listdir(decks_dir)):
        folder = os.path.join(decks_dir, name)
        if not os.path.isfile(os.path.join(folder, "SOURCE.txt")):
            continue
        fields = read_source_txt(folder)
        status = fields.get("status") or table.get(name, "")
        decks.append({"deck": name, "folder": folder, "main_deck": fields.get("main deck", ""),
                      "corpus_status": status, "complete_explicit": is_complete_explicit(status)})
    return decks


# ---------------------------------------------------------------------------------------------
# Running crumple


def call(command: list, cwd: str, timeout: float) -> dict:
    """Runs a command and classifies how it ended: 'done' (any exit status), 'crash' (killed
    by a signal) or 'hang' (still running after `timeout` s), so one bad deck cannot stop
    the whole matrix."""
    start = time.monotonic()
    try:
        p = subprocess.run(command, cwd=cwd, capture_output=True, text=True, errors="replace",
                           timeout=timeout, env=ENV)
    except subprocess.TimeoutExpired:
        return {"end": "hang", "returncode": None, "stdout": "", "stderr": "",
                "seconds": round(time.monotonic() - start, 2)}
    end = "crash" if p.returncode < 0 else "done"
    return {"end": end, "returncode": p.returncode, "stdout": p.stdout, "stderr": p.stderr,
            "seconds": round(time.monotonic() - start, 2)}


def signal_name(returncode: int) -> str:
    try:
        return signal.Signals(-returncode).name
    except (ValueError, TypeError):
        return f"signal {-returncode}"


def supports(crumple: str, subcommand: str, option: str) -> bool:
    """Whether `crumple SUBCOMMAND --help` lists `option`: lets the script work with a binary
    from before --json / --cycles instead of reporting every deck as an error."""
    p = call([crumple, subcommand, "--help"], cwd=ROOT, timeout=30)
    return p["end"] == "done" and re.search(re.escape(option) + r"\b", p["stdout"]) is not None


def relative(text: str, deck: dict, decks_dir: str) -> str:
    """Paths inside messages made relative to the deck folder (or the corpus), so the page does
    not depend on where the corpus lives."""
    for base in (deck["folder"], decks_dir):
        text = re.sub(re.escape(base.rstrip("/")) + r"/+", "", text)
    return text


def first_error_line(stderr: str) -> str:
    """The line that says why crumple stopped: the first 'error' line, else the first line
    (warnings such as 'fields read but not honoured' may come before it)."""
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    for pattern in (r"^crumple:\s*error:", r"\berror:"):  # '(an error if ...)' is a warning
        for line in lines:
            if re.search(pattern, line, re.IGNORECASE):
                return re.sub(r"^crumple:\s*error:\s*", "", line)
    return lines[0] if lines else ""


# ---------------------------------------------------------------------------------------------
# crumple check


def parse_json_object(stdout: str):
    """The JSON object crumple check printed, or None when there is none (old binary, crash)."""
    text = stdout.strip()
    if "{" not in text:
        return None
    try:
        value = json.loads(text[text.index("{"):text.rindex("}") + 1])
    except ValueError:
        return None
    return value if isinstance(value, dict) and "status" in value else None


def fallback_error(line: str) -> dict:
    """An errors entry built from a text error line ('file:line: message'), with the feature
    named by the 'cannot run yet' wording ('uses *MAT_X', '*KEYWORD: option _Y is not
    supported') so that the missing-features table is useful even without --json."""
    line = re.sub(r"^this deck cannot run yet:\s*", "", line)
    m = re.match(r"^(.*?:\d+):\s*(.*)$", line)
    where, message = (m.group(1), m.group(2)) if m else ("", line)
    feature = re.search(r"uses (\*[A-Za-z0-9_-]+(?: ELFORM=-?\d+)?)", message)
    if feature is None:
        feature = re.search(r"(\*[A-Za-z0-9_-]+): option \S+ is not supported", message)
    return {"where": where, "message": message, "feature": feature.group(1) if feature else None}


def fallback_check(proc: dict, line: str) -> dict:
    """A check result without JSON: the exit status decides ok / not ok, and a 'cannot run
    yet' error (features Crumple lacks) counts as refused rather than a deck error."""
    if proc["returncode"] == 0:
        status, errors = "ok", []
    else:
        status = "refused" if "cannot run yet" in line else "error"
        errors = [fallback_error(line)] if line else [
            {"where": "", "message": f"exit status {proc['returncode']}", "feature": None}]
    dt = re.search(r"(?m)^initial time step: (\S+)", proc["stdout"])
    end = re.search(r"(?m)^end time: (\S+)", proc["stdout"])
    return {"status": status, "errors": errors, "unsupported": [], "ignored": [], "counts": {},
            "initial_dt": float(dt.group(1)) if dt else None,
            "end_time": float(end.group(1)) if end else None}


def check_deck(deck: dict, opts) -> dict:
    """`crumple check` on one deck: the JSON report (paths made relative) plus how the process
    ended; 'crash' or 'hang' replace the status when the process did not finish cleanly."""
    path = os.path.join(deck["folder"], deck["main_deck"])
    args = [opts.crumple, "check", path] + (["--json"] if opts.has_json else [])
    with tempfile.TemporaryDirectory(prefix="crumple_compat_") as tmp:
        proc = call(args, cwd=tmp, timeout=opts.timeout)
    line = relative(first_error_line(proc["stderr"]), deck, opts.decks)
    result = {"returncode": proc["returncode"], "seconds": proc["seconds"], "json": False,
              "stderr_line": line}
    if proc["end"] != "done":
        detail = (signal_name(proc["returncode"]) if proc["end"] == "crash"
                  else f"no end after {opts.timeout:g} s")
        result.update(status=proc["end"], errors=[], unsupported=[], detail=detail)
        return result
    report = parse_json_object(proc["stdout"]) if opts.has_json else None
    if report is not None:
        report = json.loads(relative(json.dumps(report), deck, opts.decks))
        result["json"] = True
    else:
        report = fallback_check(proc, line)
    result.update(report)
    return result


def normalised_feature(name: str) -> str:
    """'*MAT_X_TITLE' and '*MAT_X' are the same missing feature for the ranking."""
    return re.sub(r"_TITLE\b", "", name.strip())


def features_of(check: dict) -> list:
    """Missing features that change the answer, in report order and without repeats:
    unsupported entries with changes_answer (their feature: the keyword, or the definition a
    part uses, such as *MAT_JOHNSON_COOK), then the features named by errors."""
    names = [u.get("feature") or u.get("keyword", "") for u in check.get("unsupported") or []
             if u.get("changes_answer")]
    names += [e.get("feature") for e in check.get("errors") or [] if e.get("feature")]
    seen = []
    for name in map(normalised_feature, filter(None, names)):
        if name not in seen:
            seen.append(name)
    return seen


# ---------------------------------------------------------------------------------------------
# Short run


def run_arguments(deck: dict, check: dict, opts, out: str):
    """The `crumple run` command line for N cycles, or None when it cannot be built (an old
    binary without --cycles needs the initial time step to turn N cycles into an end time)."""
    args = [opts.crumple, "run", os.path.join(deck["folder"], deck["main_deck"]),
            "-o", out, "-q", "--threads", str(opts.threads)]
    if opts.has_cycles:
        return args + ["--cycles", str(opts.cycles)]
    dt = check.get("initial_dt")
    if not dt or not math.isfinite(dt) or dt <= 0:
        return None
    return args + ["--endtime", f"{(opts.cycles + 0.5) * dt:.6g}"]


def judge_summary(summary: dict, cycles: int) -> tuple:
    """(ran, message, cycles run) from summary.json: a run counts when it terminated normally
    with finite energies; fewer than N cycles is fine when the deck's end time came first."""
    done = summary.get("cycles")
    if summary.get("termination") != "normal":
        return False, f"termination: {summary.get('termination')}", done
    for key, value in sorted((summary.get("energy") or {}).items()):
        if not isinstance(value, (int, float)) or not math.isfinite(value):
            return False, f"energy.{key} = {value}", done
    if not isinstance(done, int) or done < 1:
        return False, f"cycles = {done}", done
    return True, "" if done >= cycles else f"end time reached after {done} cycles", done


def read_summary(out: str):
    try:
        with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def run_deck(deck: dict, check: dict, opts) -> dict:
    """A short run of a deck that reads, in a temporary folder: does it take N cycles without
    NaN or inf? 'end' is runs / fails / crash / hang."""
    with tempfile.TemporaryDirectory(prefix="crumple_compat_") as tmp:
        out = os.path.join(tmp, "out")
        args = run_arguments(deck, check, opts, out)
        if args is None:
            return {"end": "fails", "message": "no initial time step to set a short end time",
                    "cycles": None, "seconds": 0.0}
        proc = call(args, cwd=tmp, timeout=opts.timeout)
        summary = read_summary(out) if proc["end"] == "done" else None
    result = {"end": proc["end"], "cycles": None, "seconds": proc["seconds"], "message": "",
              "returncode": proc["returncode"]}
    if proc["end"] == "crash":
        result["message"] = signal_name(proc["returncode"])
    elif proc["end"] == "hang":
        result["message"] = f"no end after {opts.timeout:g} s"
    elif proc["returncode"] != 0 or summary is None:
        line = relative(first_error_line(proc["stderr"]), deck, opts.decks)
        result.update(end="fails", message=line or f"exit status {proc['returncode']}, "
                      f"summary.json {'missing' if summary is None else 'written'}")
    else:
        ran, message, cycles = judge_summary(summary, opts.cycles)
        result.update(end="runs" if ran else "fails", message=message, cycles=cycles)
    return result


# ---------------------------------------------------------------------------------------------
# One deck


def assess(deck: dict, opts) -> dict:
    """Check, then (if it reads) a short run; the record both the page and --json use."""
    check = check_deck(deck, opts)
    run = run_deck(deck, check, opts) if check["status"] == "ok" else None
    record = {k: deck[k] for k in ("deck", "main_deck", "corpus_status", "complete_explicit")}
    record.update(check=check, run=run, features=features_of(check))
    return record


def assess_all(decks: list, opts) -> list:
    """All decks, `opts.jobs` at a time, in name order whatever order they finish in."""
    def one(numbered):
        i, deck = numbered
        record = assess(deck, opts)
        print(f"[{i}/{len(decks)}] {deck['deck']}: {result_label(record)}", file=sys.stderr,
              flush=True)
        return record
    with concurrent.futures.ThreadPoolExecutor(max_workers=opts.jobs) as pool:
        return list(pool.map(one, enumerate(decks, 1)))


# ---------------------------------------------------------------------------------------------
# The Markdown page


def cell(text: str) -> str:
    """Text safe inside a Markdown table cell."""
    return text.replace("|", "\\|").replace("\n", " ")


def code(text: str, limit: int = MAX_MESSAGE) -> str:
    """A code span (so '*KEYWORD' is not read as emphasis), cut to `limit` characters."""
    text = " ".join(text.split()).replace("`", "'")
    if len(text) > limit:
        text = text[:limit - 1].rstrip() + "…"
    return "`" + cell(text) + "`"


def result_label(record: dict) -> str:
    """One word or phrase per deck: runs / reads, run fails / refused / error / crash / hang."""
    check, run = record["check"], record["run"]
    if check["status"] in ("crash", "hang"):
        return f"check {check['status']} ({check['detail']})"
    if check["status"] != "ok":
        return check["status"]
    if run["end"] == "runs":
        return "runs"
    return {"fails": "reads, run fails", "crash": "reads, run crash",
            "hang": "reads, run hang"}[run["end"]]


def first_error(check: dict) -> str:
    errors = check.get("errors") or []
    if not errors:
        return check.get("stderr_line", "")
    e = errors[0]
    where, message = e.get("where") or "", e.get("message", "")
    # Crumple's messages already start with their file:line; do not name the place twice.
    return f"{where}: {message}" if where and not message.startswith(where) else message


def blocker(record: dict) -> str:
    """What stops the deck: its first few missing features, else its first error, else why
    the short run failed; empty when it runs."""
    check, run = record["check"], record["run"]
    if record["features"] and check["status"] != "ok":
        shown = ", ".join(code(f) for f in record["features"][:MAX_FEATURES_SHOWN])
        more = len(record["features"]) - MAX_FEATURES_SHOWN
        return shown + (f" (+{more} more)" if more > 0 else "")
    if check["status"] != "ok":
        message = first_error(check)
        return code(message) if message else ""
    return code(run["message"]) if run["message"] else ""


def cycles_cell(record: dict) -> str:
    run = record["run"]
    return str(run["cycles"]) if run and run.get("cycles") is not None else ""


def short_status(status: str) -> str:
    """The corpus status up to its first ':' (the rest explains why), at most 50 characters."""
    head = status.split(":")[0].strip()
    return head if len(head) <= 50 else head[:49].rstrip() + "…"


def tally(records: list, cycles: int) -> str:
    """'N read (K run C cycles), N refused, ...' for a group of decks; the five check outcomes
    add up to the group's size."""
    counts = {k: 0 for k in CHECK_OUTCOMES}
    for r in records:
        counts[r["check"]["status"] if r["check"]["status"] in counts else "error"] += 1
    runs = sum(1 for r in records if r["run"] and r["run"]["end"] == "runs")
    words = [f"{counts[k]} {OUTCOME_WORDS[k]}" for k in CHECK_OUTCOMES]
    words[0] += f" ({runs} run {cycles} cycles)"
    return ", ".join(words)


def summary_line(records: list, cycles: int) -> str:
    explicit = [r for r in records if r["complete_explicit"]]
    return (f"**{len(records)} decks:** {tally(records, cycles)}. "
            f"**Of the {len(explicit)} the corpus calls complete explicit:** "
            f"{tally(explicit, cycles)}.")


def deck_table(records: list) -> list:
    lines = ["| deck | corpus status | result | cycles | what blocks it |",
             "|---|---|---|---|---|"]
    for r in records:
        lines.append(f"| {r['deck']} | {cell(short_status(r['corpus_status']))} | "
                     f"{result_label(r)} | {cycles_cell(r)} | {blocker(r)} |")
    return lines


def missing_features(records: list) -> list:
    """[(feature, [decks])], most needed first (then by name, for a stable order)."""
    needed = {}
    for r in records:
        for feature in r["features"]:
            needed.setdefault(feature, []).append(r["deck"])
    return sorted(needed.items(), key=lambda item: (-len(item[1]), item[0]))


def feature_table(records: list) -> list:
    rows = missing_features(records)
    if not rows:
        return ["No deck names a missing feature."]
    lines = ["| feature | decks | which |", "|---|---|---|"]
    for feature, decks in rows:
        lines.append(f"| {code(feature)} | {len(decks)} | {', '.join(decks)} |")
    return lines


def command_line(opts) -> str:
    """The command that regenerates the page (only options that change its content)."""
    return f"python3 tools/compatibility.py --cycles {opts.cycles}"


def render(records: list, opts) -> str:
    """The whole page. No dates, durations or absolute paths: the same binary and corpus give
    the same bytes, which the CLI test relies on."""
    source = ("`crumple check DECK --json`" if opts.has_json else
              "`crumple check DECK` (no --json in this binary: judged from the exit status "
              "and the first error line)")
    run = (f"`crumple run DECK --cycles {opts.cycles}`" if opts.has_cycles else
           f"`crumple run DECK --endtime` {opts.cycles} + 1/2 initial time steps "
           "(no --cycles in this binary)")
    lines = [
        "# Compatibility with real LS-DYNA decks",
        "",
        "<!-- Generated by tools/compatibility.py; do not edit. "
        f"Regenerate: {command_line(opts)} -->",
        "",
        f"Generated by `{command_line(opts)}` (do not edit by hand) from the decks in "
        "`../shared/decks` (see its CORPUS.md): " + source + " on each main deck, then, "
        "for the decks that read, " + run + " in a temporary folder.",
        "",
        summary_line(records, opts.cycles),
        "",
        "Results: **runs** = reads and runs the cycles with finite energies; **refused** = "
        "reads but uses features that change the answer and that Crumple lacks; **error** = "
        "a format or reference error; **crash** / **hang** = killed by a signal / no end "
        f"within {opts.timeout:g} s. Corpus status comes from each folder's SOURCE.txt.",
        "",
        "## Decks",
        "",
        *deck_table(records),
        "",
        "## Missing features, most needed first",
        "",
        "From `unsupported` entries that change the answer and the features named by errors.",
        "",
        *feature_table(records),
        "",
    ]
    return "\n".join(lines)


# ---------------------------------------------------------------------------------------------
# Command line


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--crumple", default=DEFAULT_CRUMPLE, help="crumple executable")
    p.add_argument("--decks", default=DEFAULT_DECKS, help="corpus folder (one folder per deck)")
    p.add_argument("--out", default=DEFAULT_OUT, help="Markdown page to write")
    p.add_argument("--json", dest="json_out", help="also write the raw results to this file")
    p.add_argument("--cycles", type=int, default=DEFAULT_CYCLES, help="cycles of the short run")
    p.add_argument("--jobs", type=int, default=1, help="decks assessed at the same time")
    p.add_argument("--timeout", type=float, default=DEFAULT_TIMEOUT,
                   help="seconds per crumple call before it counts as a hang")
    opts = p.parse_args(argv)
    if opts.cycles < 1 or opts.jobs < 1:
        p.error("--cycles and --jobs must be at least 1")
    opts.crumple = os.path.abspath(opts.crumple)
    opts.decks = os.path.abspath(opts.decks)
    if not os.access(opts.crumple, os.X_OK):
        p.error(f"{opts.crumple} is not an executable")
    if not os.path.isdir(opts.decks):
        p.error(f"{opts.decks} is not a folder")
    return opts


def main(argv=None) -> int:
    opts = parse_args(argv)
    opts.has_json = supports(opts.crumple, "check", "--json")
    opts.has_cycles = supports(opts.crumple, "run", "--cycles")
    opts.threads = max(1, (os.cpu_count() or 1) // opts.jobs)  # no oversubscription with --jobs
    start = time.monotonic()
    records = assess_all(list_decks(opts.decks), opts)
    os.makedirs(os.path.dirname(os.path.abspath(opts.out)), exist_ok=True)
    with open(opts.out, "w", encoding="utf-8") as f:
        f.write(render(records, opts))
    if opts.json_out:
        raw = {"crumple": opts.crumple, "decks": opts.decks, "cycles": opts.cycles,
               "check_json": opts.has_json, "run_cycles": opts.has_cycles,
               "summary": summary_line(records, opts.cycles), "results": records}
        with open(opts.json_out, "w", encoding="utf-8") as f:
            json.dump(raw, f, indent=1)
            f.write("\n")
    print(f"{summary_line(records, opts.cycles)}\nwrote {opts.out} "
          f"({time.monotonic() - start:.1f} s)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
