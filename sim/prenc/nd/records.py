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


RECORDS: dict[tuple[int, int], Record] = {}
