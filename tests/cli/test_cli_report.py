#!/usr/bin/env python3
"""`crumple report` end to end: the page of a two-rank run of examples/bar_impact renders in a
real headless browser (Debian's chromium) with every picture decoded; its verdict, largest
wall force and parallel efficiency are the run's own numbers; every link resolves; bad input
exits 1."""

import csv
import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402
from clitest import crumple, describe  # noqa: E402

MISSING = clitest.missing_module("matplotlib", "numpy")

MPI_ENV = clitest.MPI_ENV


def browser():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def setUpModule():
    if MISSING:
        raise unittest.SkipTest(f"{sys.executable} has no {MISSING} (tools/setup.sh installs it)")


class BarImpactReport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls._tmp = tempfile.TemporaryDirectory(prefix="crumple_report_")
        tmp = cls._tmp.name
        deck = clitest.example("bar_impact", "bar_impact.k")
        cls.serial = os.path.join(tmp, "serial")
        proc = crumple("run", deck, "-o", cls.serial, "-q", "--threads", "1", timeout=120)
        assert proc.returncode == 0, describe(proc)
        cls.run_dir = os.path.join(tmp, "two")
        mpirun = shutil.which("mpirun")
        if mpirun:
            proc = subprocess.run([mpirun, "--oversubscribe", "-np", "2", clitest.CRUMPLE, "run",
                                   deck, "-o", cls.run_dir, "-q", "--threads", "1"],
                                  capture_output=True, text=True, timeout=120, env=MPI_ENV)
        else:
            proc = crumple("run", deck, "-o", cls.run_dir, "-q", timeout=120)
        assert proc.returncode == 0, describe(proc)
        proc = crumple("report", cls.run_dir, "--baseline", cls.serial, timeout=300)
        assert proc.returncode == 0, describe(proc)
        cls.page_path = os.path.join(cls.run_dir, "report.html")
        with open(cls.page_path, encoding="utf-8") as f:
            cls.page = f.read()
        with open(os.path.join(cls.run_dir, "summary.json"), encoding="utf-8") as f:
            cls.summary = json.load(f)

    @classmethod
    def tearDownClass(cls):
        cls._tmp.cleanup()

    def test_renders_in_a_real_browser_with_every_picture(self):
        exe = browser()
        if exe is None:
            self.skipTest("no chromium (tools/setup.sh installs it)")
        profile = os.path.join(self._tmp.name, "profile")
        proc = subprocess.run([exe, "--headless", "--no-sandbox", "--disable-gpu",
                               f"--user-data-dir={profile}", "--virtual-time-budget=10000",
                               "--dump-dom", "file://" + self.page_path],
                              capture_output=True, text=True, timeout=120)
        body = re.search(r"<body[^>]*>", proc.stdout)
        self.assertIsNotNone(body, describe(proc))
        shown = re.search(r'data-images="(\d+)"', body.group(0))
        loaded = re.search(r'data-images-loaded="(\d+)"', body.group(0))
        self.assertIsNotNone(shown, body.group(0))
        # energies, partition, wall force
        self.assertGreaterEqual(int(shown.group(1)), 3, body.group(0))
        self.assertEqual(loaded.group(1), shown.group(1), body.group(0))
        for heading in ("Model", "Energy balance", "Time", "Warnings", "Partition",
                        "Largest forces", "Result files"):
            self.assertIn(f"<h2>{heading}</h2>", proc.stdout)

    def test_verdict_is_the_audit(self):
        audit = self.summary["energy_audit"]
        self.assertEqual(audit["samples_outside"], 0)
        self.assertIn(f"stayed in [0.98, 1.02] over {audit['samples']} samples", self.page)

    def test_largest_wall_force_is_rwforc(self):
        with open(os.path.join(self.run_dir, "rwforc.csv"), newline="", encoding="utf-8") as f:
            fn = [float(r["fn"]) for r in csv.DictReader(f) if r["wall"] == "1"]
        peak = max(fn, key=abs)
        self.assertIn(f"<td>wall 1 (normal)</td><td>", self.page)
        self.assertIn(f"<td>{peak:.6g}</td>", self.page)

    def test_parallel_efficiency_against_the_baseline(self):
        with open(os.path.join(self.serial, "summary.json"), encoding="utf-8") as f:
            base = json.load(f)
        ranks = self.summary["ranks"]
        per_cycle = self.summary["wall_s"] / self.summary["cycles"]
        expected = base["wall_s"] / base["cycles"] / (ranks * per_cycle)
        self.assertIn(f"against the 1-rank run: {100 * expected:.0f}%", self.page)

    def test_links_resolve(self):
        hrefs = re.findall(r'href="([^"]+)"', self.page)
        self.assertIn("summary.json", hrefs)
        for href in hrefs:
            path = os.path.join(self.run_dir, html.unescape(href))
            self.assertTrue(os.path.isfile(path), href)

    def test_bad_input(self):
        proc = crumple("report", os.path.join(self._tmp.name, "nowhere"))
        self.assertEqual(proc.returncode, 1, describe(proc))
        self.assertIn("no summary.json", proc.stderr)
        if self.summary["ranks"] > 1:
            proc = crumple("report", self.serial, "--baseline", self.run_dir,
                           "--out", os.path.join(self._tmp.name, "x.html"))
            self.assertEqual(proc.returncode, 1, describe(proc))
            self.assertIn("baseline must be a 1-rank run", proc.stderr)


if __name__ == "__main__":
    clitest.main()
