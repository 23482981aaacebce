# SPDX-License-Identifier: Apache-2.0
"""What long SAT runs settled for the open entries of Table 1, too slow to redo in a table.

`prenc nd table` recomputes every entry within its time limit; for (9,2) and (10,2) it
also takes what is recorded here:

- a proven upper bound: the SAT back end (`prenc.nd.sat`) answered UNSAT to "is there
  an (n,d)-sequence of length at least K?", so K - 1 bounds every (n,d)-sequence;
- the command that reproduces it and what it cost.

A longer sequence found by a run would be recorded here too, and re-checked by
`prenc.nd.sequence.check` before the table prints it; so far none is longer than the
m-sequences the table builds itself. `docs/nd-sequences.md` gives every instance tried.
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
    # (9,2) = 127: the m-sequences of degree 7 are maximal.
    (9, 2): Record(9, 2, 127, "SAT: no sequence of length >= 128 (prenc nd search --n 9 --d 2 "
                   "--method sat --at-least 128 --time-limit 3600: UNSAT in 272 s on one core, PySAT 1.9.dev24, "
                   "CaDiCaL 1.9.5)"),
    # (10,2): 255 <= K <= 384; "at least 256" is still open (docs/nd-sequences.md).
    (10, 2): Record(10, 2, 384, "SAT: no sequence of length >= 385 (prenc nd search --n 10 --d 2 "
                    "--method sat --at-least 385 --time-limit 600: UNSAT in 186 s on one core, "
                    "PySAT 1.9.dev24, CaDiCaL 1.9.5)"),
}
