"""Bad input never crashes the reader: `crumple check` on mutated copies of the example decks
(fields replaced by garbage, lines cut, duplicated or dropped, keywords misspelt) must end with
exit status 0 or 1 and, for 1, a 'crumple: error:' message; never a signal, a sanitizer report
or a hang. A fixed seed makes every run test the same mutations."""

import os
import random
import subprocess

from clitest import TempDirTest, crumple, describe, example, main

GARBAGE = ["abc", "1e999", "-1", "0", "", "&nope", "1.2.3", "9999999999", "nan", "*", ",,,", "1e-400",
           "2147483648", "-0", "+", "$", "1" * 40]


def mutate(lines, rng):
    lines = list(lines)
    for _ in range(rng.randint(1, 4)):
        i = rng.randrange(len(lines))
        kind = rng.randrange(6)
        line = lines[i]
        if kind == 0 and len(line) >= 10:  # replace one 10-character field
            f = rng.randrange(len(line) // 10)
            lines[i] = line[:10 * f] + rng.choice(GARBAGE).rjust(10)[:10] + line[10 * f + 10:]
        elif kind == 1:  # cut the line
            lines[i] = line[:rng.randrange(len(line) + 1)]
        elif kind == 2:  # drop it
            del lines[i]
        elif kind == 3:  # duplicate it
            lines.insert(i, line)
        elif kind == 4 and line.startswith("*"):  # misspell a keyword
            lines[i] = line[:-1] + "X"
        else:  # free-format garbage
            lines[i] = ",".join(rng.choice(GARBAGE) for _ in range(rng.randint(1, 8)))
    return lines


class Fuzz(TempDirTest):
    def test_mutated_decks_fail_cleanly(self):
        rng = random.Random(20261121)
        sources = [example("bar_impact", "bar_impact.k"),
                   os.path.join(os.path.dirname(example()), "tests", "data", "decks", "mixed_conditions.k")]
        decks = []
        for src in sources:
            with open(src, encoding="utf-8") as f:
                lines = f.read().split("\n")
            # Keep the mutations near the keyword cards, where the reader's logic is.
            head = [k for k, l in enumerate(lines) if not l.startswith(" ") or k < 80]
            for n in range(60):
                mutated = mutate(lines, rng) if n % 2 else mutate([lines[k] for k in head] + lines[len(head):], rng)
                decks.append(self.write(f"fuzz_{len(decks)}.k", "\n".join(mutated)))
        outcomes = {0: 0, 1: 0}
        for path in decks:
            try:
                p = crumple("check", path, timeout=30)
            except subprocess.TimeoutExpired:
                self.fail(f"{path}: check hung")
            self.assertIn(p.returncode, (0, 1), f"{path}: {describe(p)}")
            self.assertNotIn("Sanitizer", p.stderr, f"{path}: {describe(p)}")
            self.assertNotIn("runtime error", p.stderr, f"{path}: {describe(p)}")
            if p.returncode == 1:
                self.assertIn("crumple: error:", p.stderr, f"{path}: {describe(p)}")
            outcomes[p.returncode] += 1
        # Both outcomes occur: the mutations reach errors and harmless places alike.
        self.assertGreater(outcomes[1], 10, outcomes)
        self.assertGreater(outcomes[0], 0, outcomes)


if __name__ == "__main__":
    main()
