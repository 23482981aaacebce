# SPDX-License-Identifier: Apache-2.0
"""Table 1 of the paper, recomputed and extended: the longest (n,d)-sequences.

For each n and d the entry starts from the best construction (`lfsr_codes`: the
de Bruijn sequence for d = 1, the best m-sequence otherwise), then the exact search
(`exact`) is seeded with it and looks for anything longer within a time limit:

- it ends with the construction's length or a longer one it found, and when it runs
  to the end, or the length meets the upper bound of `bounds`, the entry is proven
  maximal (`exact: true`);
- when the time limit stops it, the entry is a lower bound (`exact: false`): it says
  so (the time limit ran out), and the upper bound says how far the truth can be;
- for the entries that SAT runs settled (`records`), a recorded sequence longer than
  the construction and a recorded bound tighter than `bounds` are taken. An entry whose
  recorded bound its sequence meets is proven whatever the time limit, so the table
  reads the same on a busy machine.

Every sequence is checked by `sequence.min_distance`, an independent pairwise
computation, before it is put in the table. JSON shape:
{"<n>": {"<d>": {"length": L, "exact": bool, "sequence": "0110...", ...}}}.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

from .bounds import upper_bound
from .exact import exact_search
from .lfsr_codes import best_lfsr
from .records import RECORDS
from .sequence import check

# The two open entries the paper reports as lower bounds (the issue quotes them).
PAPER_OPEN = {(9, 2): 100, (10, 2): 188}


@dataclass(frozen=True)
class Entry:
    n: int
    d: int
    length: int
    exact: bool
    sequence: str
    method: str
    min_distance: int
    upper: int
    upper_reason: str
    nodes: int
    seconds: float

    def as_dict(self, with_sequence: bool = True) -> dict:
        out = {"length": self.length, "exact": self.exact}
        if with_sequence:
            out["sequence"] = self.sequence
        out.update({"min_distance": self.min_distance, "method": self.method,
                    "upper_bound": self.upper, "upper_bound_reason": self.upper_reason,
                    "search_nodes": self.nodes, "seconds": round(self.seconds, 3)})
        return out


def entry(n: int, d: int, time_limit: float | None = 10.0, max_n: int | None = None) -> Entry:
    """The best (n,d)-sequence the construction and a time-limited exact search give."""
    start = time.perf_counter()
    upper, reason = upper_bound(n, d)
    built = best_lfsr(n, d, max_n)
    lower, lower_seq, method = (built.length, built.sequence, built.method) if built else (0, None, "")
    record = RECORDS.get((n, d))
    if record and record.sequence and len(record.sequence) > lower:
        check(record.sequence, n, d)
        lower, lower_seq, method = len(record.sequence), record.sequence, "recorded SAT run"
    if record and record.upper is not None and record.upper < upper:
        upper, reason = record.upper, record.upper_how
    result = exact_search(n, d, lower=lower, lower_sequence=lower_seq, upper=upper,
                          time_limit=time_limit)
    if result.sequence is None:
        raise AssertionError(f"no ({n},{d})-sequence found at all")
    if result.length > lower:
        method = "exact search"
    exact = result.exact or result.length >= upper
    distance = check(result.sequence, n, d)
    if len(result.sequence) != result.length:
        raise AssertionError("sequence length does not match the reported length")
    return Entry(n, d, result.length, exact, result.sequence, method, distance, upper, reason,
                 result.nodes, time.perf_counter() - start)


def build_table(max_n: int, min_n: int = 3, ds=(1, 2, 3, 4), time_limit: float | None = 10.0,
                progress=None) -> dict[int, dict[int, Entry]]:
    if not 3 <= min_n <= max_n <= 16:
        raise ValueError(f"the table covers n = 3..16, got {min_n}..{max_n}")
    table: dict[int, dict[int, Entry]] = {}
    for n in range(min_n, max_n + 1):
        table[n] = {}
        for d in ds:
            table[n][d] = entry(n, d, time_limit, max_n)
            if progress:
                progress(table[n][d])
    return table


def to_json(table, with_sequence: bool = True) -> dict:
    return {str(n): {str(d): e.as_dict(with_sequence) for d, e in row.items()} for n, row in table.items()}


def to_markdown(table) -> str:
    """The table as Markdown: L for proven maxima, >= L (<= U) for lower bounds (the
    exact search's time limit ran out; a line under the table says so).

    "by SAT" marks a bound that a recorded SAT run proved (`records`).
    """
    ds = sorted(next(iter(table.values())).keys())
    lines = ["| n | " + " | ".join(f"d = {d}" for d in ds) + " |",
             "|---|" + "---|" * len(ds)]
    for n, row in table.items():
        cells = []
        for d in ds:
            e = row[d]
            by_sat = " by SAT" if e.upper_reason.startswith("SAT") else ""
            if e.exact:
                cell = f"{e.length}" + (f" (proven{by_sat})" if by_sat else "")
            else:
                cell = f">= {e.length} (<= {e.upper}{by_sat})"
            if (n, d) in PAPER_OPEN:
                cell += f" [paper: >= {PAPER_OPEN[(n, d)]}]"
            cells.append(cell)
        lines.append(f"| {n} | " + " | ".join(cells) + " |")
    if any(not e.exact for row in table.values() for e in row.values()):
        lines += ["", "`>= L`: the exact search's time limit ran out; L is a lower bound."]
    return "\n".join(lines)
