"""Restart dumps, sense switches and signals, as a user meets them (docs/reliability.md).

- restart equality: a run with *DATABASE_BINARY_D3DUMP is restarted from its mid-run dump in a
  copy of its results folder; state_digest and every history file must come out byte for byte
  those of the uninterrupted run (bar impact, Taylor bar, shells/beams/springs, rigid bodies
  and welds, loads and constraints, the tabulated equations of state, Johnson-Cook spall,
  laminated shells with failed plies);
- across rank counts (dump at 2 ranks, restart at 1 and 3): state_digest and nodout.csv
  bitwise; glstat.csv time, cycle and dt bitwise and the energies to rounding (their sums over
  ranks are added in another grouping at another rank count, as in uninterrupted runs);
- a restart deck extends the end time and changes an interval; other keywords are refused;
- corrupted, truncated and foreign dumps, and a folder of another run, end with status 1 and
  a message, touching nothing;
- DIR/stop with sw1, sw2, sw3; SIGTERM (143), SIGINT (130), SIGUSR1 (dump and go on);
  --checkpoint-every keeps the two newest dumps and changes no result.
"""

import csv
import os
import shutil
import signal
import subprocess
import time

import clitest
from clitest import TempDirTest, crumple, describe, example, main, read_summary

MPI_ENV = clitest.MPI_ENV
HISTORIES = ("glstat.csv", "matsum.csv", "nodout.csv", "rwforc.csv", "rcforc.csv", "results.pvd")


def data_deck(name):
    return os.path.join(clitest.SOURCE_DIR, "tests", "data", "decks", name)


def mpirun(n, *args):
    exe = shutil.which("mpirun")
    return subprocess.run([exe, "--oversubscribe", "-np", str(n), clitest.CRUMPLE,
                           *map(str, args)], capture_output=True, text=True, timeout=120,
                          env=MPI_ENV)


def dumps(folder):
    return sorted(f for f in os.listdir(folder) if f.startswith("d3dump_"))


def read(path):
    with open(path, "rb") as f:
        return f.read()


class RestartCase(TempDirTest):
    def with_dumps(self, deck, cycles):
        """A deck that includes `deck` and asks for a dump every `cycles` cycles."""
        return self.write(f"dump{cycles}.k", f"*KEYWORD\n*INCLUDE\n{deck}\n"
                          f"*DATABASE_BINARY_D3DUMP\n{cycles:10d}\n*END\n")

    def run_ok(self, *args, runner=None):
        p = (runner or crumple)(*args)
        self.assertEqual(p.returncode, 0, describe(p))
        return p

    def assert_same_results(self, ref, other, files=HISTORIES):
        for name in files:
            if os.path.exists(os.path.join(ref, name)):
                self.assertEqual(read(os.path.join(ref, name)), read(os.path.join(other, name)),
                                 f"{name} differs between {ref} and {other}")
        self.assertEqual(read_summary(ref)["state_digest"], read_summary(other)["state_digest"])
        self.assertEqual(read_summary(ref)["cycles"], read_summary(other)["cycles"])


class RestartEquality(RestartCase):
    # (deck, extra arguments, dump interval in cycles: the first kept dump is mid-run)
    @staticmethod
    def cases():
        return [
            (example("bar_impact", "bar_impact.k"), [], 200),
            (example("taylor_bar", "taylor_bar.k"), ["--endtime", "0.008"], 150),
            (data_deck("structures.k"), ["--endtime", "0.3"], 500),
            (data_deck("rigid_welds.k"), [], 50),
            (data_deck("mixed_conditions.k"), [], 40),
            (data_deck("contact_tube.k"), ["--endtime", "0.5"], 700),
            (data_deck("contact_blocks.k"), [], 150),
            (data_deck("contact_tied_edge.k"), [], 2500),
            (data_deck("contact_tiebreak.k"), [], 1100),
            (data_deck("contact_eroding.k"), [], 1200),
            (data_deck("tet_blocks.k"), [], 150),
            (data_deck("tet13_blocks.k"), [], 150),
            (data_deck("tet10_bar.k"), [], 200),
            (data_deck("prism_blocks.k"), [], 300),
            (data_deck("axisym_rod.k"), [], 80),
            (data_deck("erosion.k"), ["--endtime", "2.5e-5"], 40),
            (data_deck("eos_tabulated.k"), [], 700),
            (data_deck("honeycomb_barrier.k"), [], 5000),
            # Spalled by cycle 40: the spall flag (law history) must come back from the dump.
            (data_deck("jc_spall_bar.k"), [], 40),
            # Plies failed by the dump: the failure flags (shell law history) come back.
            (data_deck("composite_plate.k"), [], 900),
            (data_deck("tshell_plate.k"), [], 400),
            (data_deck("tshell2_plate.k"), [], 400),
            # *MAT_024 VP = 1 on hexes, shells and beams, plastic by the dump.
            (data_deck("vp1_mixed.k"), [], 150),
        ]

    def test_restart_from_mid_run_dump_is_bitwise(self):
        for deck, extra, cycles in self.cases():
            with self.subTest(deck=os.path.basename(deck)):
                wrapped = self.with_dumps(deck, cycles)
                full = os.path.join(self.tmp, "full_" + os.path.basename(deck))
                self.run_ok("run", wrapped, "-q", "-o", full, "--threads", 1, *extra)
                kept = dumps(full)
                # The cycle dump and the end-of-run dump.
                self.assertEqual(len(kept), 2, kept)
                self.assertEqual(int(kept[0][7:]), cycles)
                self.assertLess(cycles, read_summary(full)["cycles"])
                again = full + "_restarted"
                shutil.copytree(full, again)
                self.run_ok("run", wrapped, "-q", "--threads", 2, *extra, "--restart",
                            os.path.join(again, kept[0]))
                self.assert_same_results(full, again)
                with open(os.path.join(again, "run.log"), encoding="utf-8") as f:
                    self.assertIn(f"restart from {os.path.join(again, kept[0])} at cycle {cycles}",
                                  f.read())


class RestartIntoANewFolder(RestartCase):
    def snapshot(self, folder):
        out = {}
        for root, _, files in os.walk(folder):
            for name in files:
                path = os.path.join(root, name)
                out[os.path.relpath(path, folder)] = read(path)
        return out

    def test_continues_in_the_new_folder_and_leaves_the_dumped_run(self):
        # `--restart DUMP -o NEWDIR`: the histories so far are copied into NEWDIR and
        # continued there, to the uninterrupted run's bytes; the dumped run's folder keeps
        # every byte (no cut-back, no new rows, no removed dump).
        wrapped = self.with_dumps(example("bar_impact", "bar_impact.k"), 200)
        full = os.path.join(self.tmp, "full")
        self.run_ok("run", wrapped, "-q", "-o", full, "--threads", 1)
        mid = os.path.join(self.tmp, "mid")
        shutil.copytree(full, mid)
        for name in ("summary.json",):  # as a run stopped at the dump would leave it
            os.remove(os.path.join(mid, name))
        before = self.snapshot(mid)
        new = os.path.join(self.tmp, "continued")
        self.run_ok("run", wrapped, "-q", "--threads", 2, "--restart",
                    os.path.join(mid, dumps(mid)[0]), "-o", new)
        self.assert_same_results(full, new, files=HISTORIES + ("d3plot", "d3plot01"))
        self.assertEqual(self.snapshot(mid), before)
        self.assertEqual(dumps(new), dumps(full)[1:])  # only the continuation's own dump
        # -o naming a folder with other results is checked as before: refused, untouched.
        other = os.path.join(self.tmp, "other")
        self.run_ok("run", example("bar_impact", "bar_impact.k"), "-q", "-o", other,
                    "--endtime", "0.001")
        kept = self.snapshot(other)
        p = crumple("run", wrapped, "-q", "--restart", os.path.join(mid, dumps(mid)[0]), "-o",
                    other)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertEqual(self.snapshot(other), kept)


class RestartAcrossRanks(RestartCase):
    def setUp(self):
        super().setUp()
        if not shutil.which("mpirun"):
            self.skipTest("no mpirun")

    def glstat(self, folder):
        with open(os.path.join(folder, "glstat.csv"), encoding="utf-8") as f:
            return list(csv.DictReader(f))

    def test_dump_at_two_ranks_restarts_at_one_two_and_three(self):
        for deck, extra, cycles in [(data_deck("structures.k"), ["--endtime", "0.2"], 300),
                                    (data_deck("rigid_welds.k"), [], 50)]:
            wrapped = self.with_dumps(deck, cycles)
            full = os.path.join(self.tmp, "np2_" + os.path.basename(deck))
            self.run_ok("run", wrapped, "-q", "-o", full, "--threads", 1, *extra,
                        runner=lambda *a: mpirun(2, *a))
            first = dumps(full)[0]
            self.assertEqual(int(first[7:]), cycles)
            for n in (1, 2, 3):
                with self.subTest(deck=os.path.basename(deck), ranks=n):
                    again = f"{full}_to{n}"
                    shutil.copytree(full, again)
                    self.run_ok("run", wrapped, "-q", "--threads", 1, *extra, "--restart",
                                os.path.join(again, first), runner=lambda *a: mpirun(n, *a))
                    if n == 2:  # the dump's partition is reused: everything bitwise
                        self.assert_same_results(full, again)
                        continue
                    self.assert_same_results(full, again, files=("nodout.csv",))
                    ref, got = self.glstat(full), self.glstat(again)
                    self.assertEqual(len(ref), len(got))
                    for a, b in zip(ref, got):
                        for key in ("time", "cycle", "dt", "added_mass"):
                            self.assertEqual(a[key], b[key], (key, a, b))
                        for key in ("kinetic", "internal", "hourglass", "external_work", "total"):
                            x, y = float(a[key]), float(b[key])
                            self.assertLessEqual(abs(x - y), 1e-12 * max(abs(x), 1.0), (key, a, b))


class RestartDeckAndErrors(RestartCase):
    def setUp(self):
        super().setUp()
        self.deck = self.with_dumps(example("bar_impact", "bar_impact.k"), 200)
        self.full = os.path.join(self.tmp, "full")
        self.run_ok("run", self.deck, "-q", "-o", self.full, "--endtime", "0.03")

    def test_restart_deck_extends_the_run_and_changes_an_interval(self):
        end_dump = os.path.join(self.full, dumps(self.full)[-1])
        changes = self.write("changes.k", "*KEYWORD\n*CONTROL_TERMINATION\n      0.05\n"
                             "*DATABASE_GLSTAT\n     0.005\n*END\n")
        before = read_summary(self.full)
        p = self.run_ok("run", self.deck, "-q", "--restart", end_dump, "--restart-deck", changes)
        after = read_summary(self.full)
        self.assertAlmostEqual(after["end_time"], 0.05, places=12)
        self.assertGreater(after["cycles"], before["cycles"])
        with open(os.path.join(self.full, "glstat.csv"), encoding="utf-8") as f:
            times = [float(r["time"]) for r in csv.DictReader(f)]
        later = [t for t in times if t > 0.03 + 1e-9]
        self.assertGreaterEqual(len(later), 4, times)
        for a, b in zip(later, later[1:-1]):  # the last row is the end state
            self.assertAlmostEqual(b - a, 0.005, delta=0.0005, msg=times)
        self.assertEqual(p.stderr, "")

    def test_restart_deck_refuses_other_keywords(self):
        changes = self.write("changes.k", "*KEYWORD\n*CONTROL_TERMINATION\n      0.05\n"
                             "*CHANGE_VELOCITY\n         1\n*END\n")
        before = read(os.path.join(self.full, "glstat.csv"))
        p = crumple("run", self.deck, "--restart", self.full, "--restart-deck", changes)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("changes.k:4: *CHANGE_VELOCITY is not supported in a restart deck", p.stderr)
        self.assertEqual(before, read(os.path.join(self.full, "glstat.csv")))

    def test_corrupted_truncated_and_foreign_dumps(self):
        good = os.path.join(self.full, dumps(self.full)[0])
        data = read(good)
        flipped = self.write("flipped", "")
        with open(flipped, "wb") as f:
            f.write(data[:len(data) // 2] + bytes([data[len(data) // 2] ^ 1]) +
                    data[len(data) // 2 + 1:])
        cut = self.write("cut", "")
        with open(cut, "wb") as f:
            f.write(data[:-100])
        deck_as_dump = self.deck
        for path, message in [(flipped, "corrupted restart dump (checksum mismatch)"),
                              (cut, "truncated or padded restart dump"),
                              (deck_as_dump, "not a Crumple restart dump")]:
            with self.subTest(path=os.path.basename(path)):
                p = crumple("run", self.deck, "-q", "-o", self.full, "--restart", path)
                self.assertEqual(p.returncode, 1, describe(p))
                self.assertIn(f"{path}: {message}", p.stderr)
        # A dump of another deck.
        p = crumple("run", data_deck("rigid_welds.k"), "-q", "--restart", good)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("does not belong to this deck", p.stderr)

    def test_folder_of_another_run_is_left_untouched(self):
        other = os.path.join(self.tmp, "other")
        self.run_ok("run", self.deck, "-q", "-o", other, "--endtime", "0.02")
        before = {f: read(os.path.join(other, f)) for f in os.listdir(other)
                  if os.path.isfile(os.path.join(other, f))}
        p = crumple("run", self.deck, "-q", "-o", other, "--restart",
                    os.path.join(self.full, dumps(self.full)[0]))
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("does not hold the run the dump was written by", p.stderr)
        after = {f: read(os.path.join(other, f)) for f in os.listdir(other)
                 if os.path.isfile(os.path.join(other, f))}
        self.assertEqual(before, after)

    def test_new_run_refuses_a_folder_with_dumps_and_overwrite_removes_them(self):
        p = crumple("run", self.deck, "-q", "-o", self.full)
        self.assertEqual(p.returncode, 1, describe(p))
        self.run_ok("run", example("bar_impact", "bar_impact.k"), "-q", "-o", self.full,
                    "--overwrite", "--endtime", "0.01")
        self.assertEqual(dumps(self.full), [])


class SenseSwitchesAndSignals(RestartCase):
    TAYLOR = ["--endtime", "0.02", "--threads", "1"]

    def test_sw1_stops_with_a_dump_and_the_restart_completes_the_run(self):
        deck = example("bar_impact", "bar_impact.k")
        full = os.path.join(self.tmp, "full")
        self.run_ok("run", deck, "-q", "-o", full)
        stopped = os.path.join(self.tmp, "stopped")
        os.makedirs(stopped)
        self.write("stopped/stop", "sw1\n")
        self.run_ok("run", deck, "-q", "-o", stopped)
        s = read_summary(stopped)
        self.assertEqual(s["termination"], "signal")
        self.assertIn("sw1", s["message"])
        self.assertLess(s["cycles"], read_summary(full)["cycles"])
        self.assertFalse(os.path.exists(os.path.join(stopped, "stop")))
        self.assertEqual(len(dumps(stopped)), 1)
        self.run_ok("run", deck, "-q", "--restart", stopped)
        self.assert_same_results(full, stopped)

    def test_checkpoint_every_keeps_two_dumps_and_changes_nothing(self):
        deck = example("bar_impact", "bar_impact.k")
        plain, timed = os.path.join(self.tmp, "plain"), os.path.join(self.tmp, "timed")
        self.run_ok("run", deck, "-q", "-o", plain)
        # A dump whenever 0.1 ms of wall time has passed: nearly every cycle.
        self.run_ok("run", deck, "-q", "-o", timed, "--checkpoint-every", "0.0001")
        self.assertEqual(len(dumps(timed)), 2)
        with open(os.path.join(timed, "run.log"), encoding="utf-8") as f:
            self.assertGreater(f.read().count("(--checkpoint-every)"), 2)
        self.assert_same_results(plain, timed)

    def test_sw2_prints_status_and_sw3_dumps_and_goes_on(self):
        deck = example("bar_impact", "bar_impact.k")
        # d3kil is LS-DYNA's name for the file; an unknown word is reported and removed.
        for word, name, dumped in (("sw2", "stop", 0), ("sw3", "d3kil", 1), ("sw9", "stop", 0)):
            with self.subTest(word=word):
                out = os.path.join(self.tmp, word)
                os.makedirs(out)
                self.write(f"{word}/{name}", word)
                p = self.run_ok("run", deck, "-q", "-o", out)
                self.assertEqual(read_summary(out)["termination"], "normal")
                self.assertEqual(len(dumps(out)), dumped)
                self.assertFalse(os.path.exists(os.path.join(out, name)))
                if word == "sw9":
                    self.assertIn("'sw9' is not a sense switch", p.stderr)
                if word == "sw2":
                    self.assertIn("sw2: cycle ", p.stdout)

    def interrupt(self, sig, out):
        """Starts the Taylor bar, sends `sig` once it has written history rows."""
        proc = subprocess.Popen([clitest.CRUMPLE, "run", example("taylor_bar", "taylor_bar.k"),
                                 "-q", "-o", out, *self.TAYLOR], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, env=clitest._ENV)
        glstat = os.path.join(out, "glstat.csv")
        deadline = time.time() + 30
        while time.time() < deadline and proc.poll() is None:
            if os.path.exists(glstat) and read(glstat).count(b"\n") >= 3:
                break
            time.sleep(0.01)
        proc.send_signal(sig)
        _, err = proc.communicate(timeout=60)
        return proc.returncode, err

    def test_sigterm_and_sigint_dump_and_exit_143_and_130(self):
        full = os.path.join(self.tmp, "full")
        self.run_ok("run", example("taylor_bar", "taylor_bar.k"), "-q", "-o", full, *self.TAYLOR)
        for sig, status in ((signal.SIGTERM, 143), (signal.SIGINT, 130)):
            with self.subTest(signal=sig.name):
                out = os.path.join(self.tmp, sig.name)
                code, err = self.interrupt(sig, out)
                if code == 0:
                    self.skipTest("the run ended before the signal arrived (machine too fast)")
                self.assertEqual(code, status, err)
                s = read_summary(out)
                self.assertEqual(s["termination"], "signal")
                self.assertIn(sig.name, s["message"])
                self.assertEqual(len(dumps(out)), 1)
                self.run_ok("run", example("taylor_bar", "taylor_bar.k"), "-q", *self.TAYLOR,
                            "--restart", out)
                self.assert_same_results(full, out)

    def test_sigusr1_dumps_and_goes_on(self):
        out = os.path.join(self.tmp, "usr1")
        code, err = self.interrupt(signal.SIGUSR1, out)
        self.assertEqual(code, 0, err)
        self.assertEqual(read_summary(out)["termination"], "normal")
        # The SIGUSR1 dump (if the run was still going) and none other: no dumps requested.
        self.assertLessEqual(len(dumps(out)), 1)
        with open(os.path.join(out, "run.log"), encoding="utf-8") as f:
            log = f.read()
        if dumps(out):
            self.assertIn("(SIGUSR1)", log)


if __name__ == "__main__":
    main()
