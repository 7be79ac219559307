"""`crumple partition` and the distributed run's error paths, as a user meets them.

- partition writes partition.json with the per-rank table and a VTU of the mesh coloured by
  rank that VTK reads back;
- under mpirun, bad input, and more ranks than elements, end every rank with status 1 and one
  message (printed once, by rank 0), never a hang;
- a distributed run writes one .pvtu per plot state whose pieces carry the rank field.
"""

import json
import os
import shutil
import subprocess

from clitest import TempDirTest, crumple, describe, example, main, one_brick_deck, read_vtu
import clitest

MPI_ENV = clitest.MPI_ENV


def mpirun(n, *args, cwd=None):
    exe = shutil.which("mpirun")
    return subprocess.run([exe, "--oversubscribe", "-np", str(n), clitest.CRUMPLE, *map(str, args)],
                          cwd=cwd, capture_output=True, text=True, timeout=120, env=MPI_ENV)


class Partition(TempDirTest):
    def test_partition_json_and_vtu(self):
        out = os.path.join(self.tmp, "part")
        p = crumple("partition", example("bar_impact", "bar_impact.k"), "-n", 4, "-o", out)
        self.assertEqual(p.returncode, 0, describe(p))
        with open(os.path.join(out, "partition.json"), encoding="utf-8") as f:
            j = json.load(f)
        self.assertEqual(j["parts"], 4)
        self.assertEqual(len(j["ranks"]), 4)
        self.assertEqual(sum(r["elements"] for r in j["ranks"]), 400)
        self.assertLessEqual(j["load_imbalance"], 0.03)
        self.assertGreater(j["shared_nodes_total"], 0)
        for r in j["ranks"]:
            self.assertGreater(len(r["neighbours"]), 0)
        vtu = read_vtu(os.path.join(out, "partition.vtu"), "--values")
        self.assertEqual(vtu["cells"], 400, vtu)
        ranks = vtu["cell_data"]["rank"]["values"]
        self.assertEqual(sorted(set(int(v) for v in ranks)), [0, 1, 2, 3])

    def test_partition_rcb_and_bad_count(self):
        out = os.path.join(self.tmp, "rcb")
        p = crumple("partition", example("bar_impact", "bar_impact.k"), "-n", 3, "-o", out,
                    "--partition", "rcb")
        self.assertEqual(p.returncode, 0, describe(p))
        p = crumple("partition", example("bar_impact", "bar_impact.k"), "-n", 401, "-o", out)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("400", p.stderr)


class Advise(TempDirTest):
    """`crumple partition --advise` (docs/parallel.md, "How many ranks")."""

    def advise(self, *extra, ranks=1):
        out = os.path.join(self.tmp, "advice")
        args = ("partition", example("bar_impact", "bar_impact.k"), "--advise", "--max", 8,
                "--sample-cycles", 20, "-o", out, *extra)
        p = crumple(*args) if ranks == 1 else mpirun(ranks, *args)
        self.assertEqual(p.returncode, 0, describe(p))
        with open(os.path.join(out, "advise.json"), encoding="utf-8") as f:
            return p, json.load(f)

    def test_predictions_and_the_advice(self):
        p, j = self.advise()
        preds = j["predictions"]
        self.assertEqual([q["ranks"] for q in preds], [1, 2, 3, 4, 6, 8])
        serial = j["serial_cycle"]
        self.assertEqual(serial["cycles_timed"], 20)
        one = preds[0]
        # One rank is the serial cycle, up to the rounding of sums taken in another order.
        self.assertAlmostEqual(one["efficiency"], 1.0, places=12)
        self.assertAlmostEqual(one["cycle_s"], serial["elements_s"] + serial["nodes_s"] +
                               serial["contact_split_s"] + serial["contact_replicated_s"])
        self.assertGreater(preds[1]["speedup"], 1.0)
        best = j["recommended_ranks"]
        by_ranks = {q["ranks"]: q for q in preds}
        self.assertGreaterEqual(by_ranks[best]["efficiency"], 0.8)
        for q in preds:
            if q["ranks"] > best:
                self.assertLess(q["efficiency"], 0.8)
            self.assertAlmostEqual(q["speedup"], one["cycle_s"] / q["cycle_s"])
        self.assertFalse(j["network"]["measured"])
        self.assertIn(f"advice: {best} rank", p.stdout)
        self.assertIn("not measured", p.stdout)

    def test_network_measured_under_mpirun(self):
        if shutil.which("mpirun") is None:
            self.skipTest("mpirun not found")
        p, j = self.advise(ranks=2)
        self.assertTrue(j["network"]["measured"])
        self.assertGreater(j["network"]["latency_s"], 0.0)
        self.assertLess(j["network"]["latency_s"], 1e-3)
        self.assertGreater(j["network"]["bandwidth_bytes_per_s"], 1e7)
        self.assertEqual(p.stdout.count("advice:"), 1, describe(p))

    def test_costs_from_a_serial_run(self):
        # The whole run's seconds per cycle, split as the sample splits them: the prediction
        # for one rank is the run's own cycle loop.
        run = os.path.join(self.tmp, "serial")
        deck = example("bar_impact", "bar_impact.k")
        p = crumple("run", deck, "-q", "--threads", 1, "--cycles", 40, "-o", run)
        self.assertEqual(p.returncode, 0, describe(p))
        with open(os.path.join(run, "summary.json"), encoding="utf-8") as f:
            s = json.load(f)
        p, j = self.advise_from(run)
        serial = j["serial_cycle"]
        self.assertEqual(serial["source"], "run")
        self.assertEqual(serial["cycles_timed"], s["cycles"])
        self.assertAlmostEqual(serial["elements_s"], s["timing"]["elements"] / s["cycles"])
        loop = s["wall_s"] - s["setup_s"] - s["timing"]["output"]
        self.assertAlmostEqual(j["predictions"][0]["cycle_s"], loop / s["cycles"])
        self.assertIn("of the run in", p.stdout)

    def test_costs_from_a_threaded_run_are_refused(self):
        run = os.path.join(self.tmp, "threaded")
        p = crumple("run", example("bar_impact", "bar_impact.k"), "-q", "--threads", 2,
                    "--cycles", 5, "-o", run)
        self.assertEqual(p.returncode, 0, describe(p))
        p = crumple("partition", example("bar_impact", "bar_impact.k"), "--advise",
                    "--from-run", run, "-o", os.path.join(self.tmp, "a"))
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("needs a run on 1 rank of 1 thread", p.stderr)

    def advise_from(self, run):
        out = os.path.join(self.tmp, "advice_run")
        p = crumple("partition", example("bar_impact", "bar_impact.k"), "--advise", "--max", 4,
                    "--from-run", run, "-o", out)
        self.assertEqual(p.returncode, 0, describe(p))
        with open(os.path.join(out, "advise.json"), encoding="utf-8") as f:
            return p, json.load(f)

    def test_usage(self):
        deck = example("bar_impact", "bar_impact.k")
        for args in ((), ("--max", 4), ("-n", 4, "--advise")):
            p = crumple("partition", deck, *args)
            self.assertEqual(p.returncode, 2, describe(p))


class DistributedErrors(TempDirTest):
    def setUp(self):
        super().setUp()
        if shutil.which("mpirun") is None:
            self.skipTest("mpirun not found")

    def test_more_ranks_than_elements(self):
        self.write("one.k", one_brick_deck())
        p = mpirun(2, "run", "one.k", "-q", cwd=self.tmp)
        self.assertNotEqual(p.returncode, 0, describe(p))
        self.assertEqual(p.stderr.count("crumple: error:"), 1, describe(p))
        self.assertIn("cannot split 1 element", p.stderr, describe(p))
        self.assertFalse(os.path.exists(os.path.join(self.tmp, "one.out", "summary.json")))

    def test_bad_input_one_message(self):
        text = one_brick_deck().replace("     210.0", "       abc")
        self.write("bad.k", text)
        p = mpirun(3, "run", "bad.k", "-q", cwd=self.tmp)
        self.assertNotEqual(p.returncode, 0, describe(p))
        self.assertEqual(p.stderr.count("crumple: error:"), 1, describe(p))
        self.assertIn("'abc' is not a number", p.stderr)

    def test_inverted_element_on_one_rank_stops_every_rank(self):
        # Element 300 of mixed_conditions.k turned inside out: only the rank holding it sees
        # it, yet every rank must stop before the first cycle (this hung before the check was
        # made collective), with one message naming it and no results folder.
        with open(os.path.join(clitest.SOURCE_DIR, "tests", "data", "decks", "mixed_conditions.k"),
                  encoding="utf-8") as f:
            lines = f.read().split("\n")
        k = next(i for i, line in enumerate(lines) if line.startswith("     300       1"))
        f = [lines[k][j:j + 8] for j in range(0, 80, 8)]
        lines[k] = "".join(f[:2] + f[6:10] + f[2:6])
        self.write("inverted.k", "\n".join(lines))
        for n in (2, 3):
            p = mpirun(n, "run", "inverted.k", "-q", "--threads", "1", "-o", f"out{n}", cwd=self.tmp)
            self.assertNotEqual(p.returncode, 0, describe(p))
            self.assertEqual(p.stderr.count("crumple: error:"), 1, describe(p))
            self.assertIn("solid element 300 (part 1) has zero or negative volume at cycle 0",
                          p.stderr, describe(p))
            self.assertFalse(os.path.exists(os.path.join(self.tmp, f"out{n}")))

    def test_pvtu_pieces_carry_the_rank(self):
        out = os.path.join(self.tmp, "bar")
        p = mpirun(3, "run", example("bar_impact", "bar_impact.k"), "-o", out, "-q")
        self.assertEqual(p.returncode, 0, describe(p))
        with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
            s = json.load(f)
        self.assertEqual(s["ranks"], 3)
        self.assertEqual(s["counts"]["solids"], 400)
        self.assertGreaterEqual(s["timing"]["communication"], 0.0)
        pvtus = [f for f in os.listdir(os.path.join(out, "states")) if f.endswith(".pvtu")]
        self.assertGreater(len(pvtus), 1)
        first = read_vtu(os.path.join(out, "states", sorted(pvtus)[0]), "--values")
        self.assertEqual(first["cells"], 400)
        # Every node appears in at least one piece; nodes on the cuts appear in two or three.
        self.assertGreaterEqual(first["points"], 909)
        self.assertLess(first["points"], 909 + 2 * 9 * 3)
        self.assertEqual(sorted(set(int(v) for v in first["cell_data"]["rank"]["values"])), [0, 1, 2])


if __name__ == "__main__":
    main()
