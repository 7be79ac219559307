"""The example decks committed under examples/ are exactly what tools/make_examples.py writes
(a generator changed without regenerating, or a deck edited by hand, fails here).

Run as: python3 tests/cli/test_cli_examples_generated.py <crumple> <source dir>
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import clitest  # noqa: E402
from clitest import TempDirTest, main  # noqa: E402


class ExamplesGenerated(TempDirTest):
    def test_committed_decks_equal_the_generator(self):
        sys.path.insert(0, os.path.join(clitest.SOURCE_DIR, "tools"))
        import make_examples  # noqa: E402
        for rel, text in make_examples.decks().items():
            with self.subTest(deck=rel):
                with open(clitest.example(*rel.split("/")), encoding="utf-8") as f:
                    self.assertTrue(f.read() == text,
                                    f"examples/{rel} differs from tools/make_examples.py's "
                                    "output: run python3 tools/make_examples.py")


if __name__ == "__main__":
    main()
