# SPDX-License-Identifier: Apache-2.0
"""What SAT runs settled for entries of Table 1, too slow to redo in a table, or too
close to its time limit to be redone the same on every machine.

`prenc nd table` recomputes every entry within its time limit; for the entries below it
also takes what is recorded here:

- a proven upper bound: the SAT back end (`prenc.nd.sat`) answered UNSAT to "is there
  an (n,d)-sequence of length at least K?", so K - 1 bounds every (n,d)-sequence;
- the command that reproduces it and what it cost.

A sequence longer than the table's constructions, found by a search, is recorded here
too, and re-checked by `prenc.nd.sequence.check` before the table prints it. `docs/nd-sequences.md` gives every instance tried.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Record:
    n: int
    d: int
    upper: int | None  # proven: no (n,d)-sequence is longer
    upper_how: str
    sequence: str | None = None  # a sequence longer than the table's constructions


RECORDS: dict[tuple[int, int], Record] = {
    # (8,2) = 63 and (10,3) = 62: the exhaustive search proves them too, but in 12 s and
    # 5 to 9 s, close to the table's 20 s limit on a busy machine (which once printed
    # (8,2) as a lower bound); the proofs make the table read the same on any machine.
    (8, 2): Record(8, 2, 63, "SAT: no sequence of length >= 64 (prenc nd search --n 8 --d 2 "
                   "--method sat --at-least 64: UNSAT in 4.2 s on one core, PySAT 1.9.dev24, CaDiCaL 1.9.5)"),
    # (10,3): the construction gives 40; the exhaustive search found this 62 in 5.3 s.
    (10, 3): Record(10, 3, 62, "SAT: no sequence of length >= 63 (prenc nd search --n 10 --d 3 "
                    "--method sat --at-least 63: UNSAT in 36.5 s on one core, PySAT 1.9.dev24, "
                    "CaDiCaL 1.9.5)",
                    "00000010001101101011001111000101111110111001001010011000011101"),
    # (9,2) = 127: the m-sequences of degree 7 are maximal.
    (9, 2): Record(9, 2, 127, "SAT: no sequence of length >= 128 (prenc nd search --n 9 --d 2 "
                   "--method sat --at-least 128 --time-limit 3600: UNSAT in 272 s on one core, PySAT 1.9.dev24, "
                   "CaDiCaL 1.9.5)"),
    # (10,2): 255 <= K <= 384; "at least 256" is still open (docs/nd-sequences.md).
    (10, 2): Record(10, 2, 384, "SAT: no sequence of length >= 385 (prenc nd search --n 10 --d 2 "
                    "--method sat --at-least 385 --time-limit 600: UNSAT in 186 s on one core, "
                    "PySAT 1.9.dev24, CaDiCaL 1.9.5)"),
}
