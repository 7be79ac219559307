"""Contact through the command line: initial penetrations listed by `check` and moved out by
`run` (and said so), contact types Crumple does not run reported and refused by --strict,
bad contact cards named by file:line and field, and the contact partition bias.
"""

import os
import shutil
import subprocess
import sys

import clitest
from clitest import TempDirTest, crumple, describe, main, read_summary


def decks():
    sys.path.insert(0, os.path.join(clitest.SOURCE_DIR, "tools"))
    import contact_decks  # noqa: E402
    return contact_decks


def overlapping_blocks():
    """The colliding blocks with the second block moved 0.2 mm into the first."""
    text = decks().colliding_blocks("SURFACE_TO_SURFACE", 4, 5, 0.001)
    sys.path.insert(0, os.path.join(clitest.SOURCE_DIR, "tools"))
    from deckgen import Mesh, block  # noqa: E402
    m = Mesh()
    block(m, 1, (0, 0, 0), (0.01, 0.01, 0.01), (4, 4, 4))
    block(m, 2, (0.001, 0.001, 0.0098), (0.01, 0.01, 0.01), (5, 5, 5))
    return text[:text.index("*NODE")] + m.keyword_text() + "*END\n"


class Contact(TempDirTest):
    def test_initial_penetrations_listed_and_moved_out(self):
        deck = self.write("pen.k", overlapping_blocks())
        p = crumple("check", deck, cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        self.assertRegex(p.stdout, r"initial penetrations: \d+ \(moved back onto the surface",
                         describe(p))
        self.assertIn("contact 7 node", p.stdout, describe(p))
        out = os.path.join(self.tmp, "out")
        p = crumple("run", deck, "-o", out, "-q", "--endtime", "2e-6", cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        self.assertIn("initial contact penetration(s) moved back onto the surface", p.stderr)
        s = read_summary(out)
        listed = int(p.stderr.split("note: ")[1].split()[0])
        self.assertEqual(s["contact"]["initial_penetrations"], listed)
        self.assertGreater(listed, 0)
        with open(os.path.join(out, "run.log"), encoding="utf-8") as f:
            self.assertIn(f"initial penetrations: {listed} (moved back", f.read())

    def test_unsupported_contact_type_refused_unless_ignored(self):
        """A contact left out changes the answer: check and run refuse the deck and name it;
        --ignore-unsupported runs without it and says so in run.log and summary.json."""
        text = decks().colliding_blocks().replace("*CONTACT_SURFACE_TO_SURFACE_ID",
                                                  "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR_ID")
        deck = self.write("mortar.k", text)
        p = crumple("check", deck, cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("leaving it out would change the answer", p.stdout, describe(p))
        self.assertIn("*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR_ID", p.stdout, describe(p))
        out = os.path.join(self.tmp, "o")
        p = crumple("run", deck, "-o", out, "-q", cwd=self.tmp)
        self.assertEqual(p.returncode, 1, describe(p))
        self.assertIn("*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR_ID", p.stderr, describe(p))
        self.assertIn("--ignore-unsupported", p.stderr, describe(p))
        self.assertFalse(os.path.exists(out), "a refused deck writes nothing")
        p = crumple("run", deck, "--ignore-unsupported", "-o", out, "-q", "--cycles", "5",
                    cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        s = read_summary(out)
        self.assertEqual(s["cycles"], 5)
        self.assertEqual(s["ignored_unsupported"], ["*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR_ID"])
        with open(os.path.join(out, "run.log"), encoding="utf-8") as f:
            self.assertIn("--ignore-unsupported: this run leaves out", f.read())

    def test_optional_cards_b_to_d_reported_and_later_lines_named(self):
        text = decks().colliding_blocks().replace(
            "         1         2         3         3\n",
            "         1         2         3         3\n\n\n\n       0.5\n         1\n         1\n"
            "         9\n", 1)
        deck = self.write("cards.k", text)
        p = crumple("check", deck, cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        for fragment in ("PENMAX: value 0.5", "IGAP: value 1", "Q2TRI: value 1",
                         "cards E and after: not read"):
            self.assertIn(fragment, p.stdout, describe(p))

    def test_bad_contact_cards_name_file_line_and_field(self):
        base = decks().colliding_blocks()
        cases = [
            # (replace this, with that, expected message fragment)
            ("         1         2         3         3\n",
             "         1         2         1         3\n", "SSTYP): surface type 1 is not supported"),
            ("         1         2         3         3\n",
             "         1        99         3         3\n", "MSID): part 99"),
        ]
        for old, new, expected in cases:
            with self.subTest(expected=expected):
                deck = self.write("bad.k", base.replace(old, new, 1))
                p = crumple("check", deck, cwd=self.tmp)
                self.assertEqual(p.returncode, 1, describe(p))
                self.assertIn("bad.k:", p.stderr, describe(p))
                self.assertIn("*CONTACT_SURFACE_TO_SURFACE_ID card 1", p.stderr, describe(p))
                self.assertIn(expected, p.stderr, describe(p))

    def test_contact_bias_changes_the_partition_not_the_result(self):
        if not shutil.which("mpirun"):
            self.skipTest("no mpirun")
        deck = os.path.join(clitest.SOURCE_DIR, "tests", "data", "decks", "contact_blocks.k")
        serial = os.path.join(self.tmp, "serial")
        p = crumple("run", deck, "-o", serial, "-q", "--threads", 1, cwd=self.tmp)
        self.assertEqual(p.returncode, 0, describe(p))
        env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE", OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        # Open MPI's own allocations are reported as leaks by the sanitizer build.
        env["ASAN_OPTIONS"] = (env.get("ASAN_OPTIONS", "") + ":detect_leaks=0").lstrip(":")
        biased = os.path.join(self.tmp, "biased")
        q = subprocess.run(["mpirun", "--oversubscribe", "-np", "2", clitest.CRUMPLE, "run", deck,
                            "-o", biased, "-q", "--threads", "1", "--contact-bias", "3"],
                           capture_output=True, text=True, timeout=120, env=env)
        self.assertEqual(q.returncode, 0, q.stderr)
        self.assertEqual(read_summary(serial)["state_digest"], read_summary(biased)["state_digest"])


if __name__ == "__main__":
    main()
