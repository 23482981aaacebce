# SPDX-License-Identifier: Apache-2.0
"""How deep the reader must verify before it places a position: the arithmetic.

A lock reads k strobes of one-directional travel and accepts the offset they
convert to when every window agrees. It is wrong exactly when the misreads turn
the true readings into the readings of another place on the disc: for a true slot
p and a wrong shift d, every reading at disc slot j that differs between s(j) and
s(j + d) must be misread, and every other one read right. So for each p and d the
error pattern is fixed, and its weight w(p, d) gives

    P(lock wrong) = mean over p of  sum over d != 0 of  r^w (1 - r)^(R - w)

for R readings at misread rate r (each reading flips independently). This module
enumerates those patterns on the disc itself (the de Bruijn sequence, not a
linear approximation): every p and d for N <= 12, a sample of p (every d) above.

Two geometries, as the reader locks (see docs/architecture.md):
- two heads, k strobes: head 1 reads s(p0 .. p0+k-1), head 2 reads
  s(p0+N-1 .. p0+N+k-2); 2k readings, 2k - N checks;
- one head, k strobes: s(p0 .. p0+k-1); k readings, k - N checks.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .debruijn import Code


@dataclass(frozen=True)
class DepthRow:
    n: int
    heads: int       # 1 or 2
    strobes: int     # k
    readings: int
    checks: int
    min_weight: int  # lightest undetectable error pattern
    p_wrong: dict    # misread rate -> probability that a lock is wrong


def reading_slots(n: int, heads: int, strobes: int) -> np.ndarray:
    """Disc slots (relative to p0) read by a lock of `strobes` one-way strobes."""
    first = np.arange(strobes)
    if heads == 1:
        return first
    return np.concatenate([first, first + n - 1])


def weight_counts(code: Code, slots: np.ndarray, samples: int | None = None,
                  seed: int = 1) -> tuple[np.ndarray, int]:
    """Histogram over (p, d != 0) of the undetectable patterns' weights, and the
    number of p it averages over."""
    length = code.length
    seq = code.sequence.astype(np.uint8)
    if samples is None or samples >= length:
        starts = np.arange(length)
    else:
        starts = np.random.default_rng(seed).choice(length, samples, replace=False)
    hist = np.zeros(len(slots) + 1, dtype=np.int64)
    d = np.arange(1, length)
    for p0 in starts:
        j = (p0 + slots) % length                      # the read slots
        true = seq[j]                                  # (R,)
        other = seq[(j[None, :] + d[:, None]) % length]  # (L-1, R)
        w = (other != true[None, :]).sum(axis=1)
        hist += np.bincount(w, minlength=len(slots) + 1)
    return hist, len(starts)


def p_wrong(hist: np.ndarray, starts: int, readings: int, rate: float) -> float:
    """P(a lock is wrong | it locks): wrong locks over all locks."""
    w = np.arange(len(hist))
    wrong = float((hist * rate ** w * (1 - rate) ** (readings - w)).sum()) / starts
    right = (1 - rate) ** readings
    return wrong / (wrong + right)


RATES = (0.001, 0.01, 0.03)


def depth_row(n: int, heads: int, strobes: int, samples: int | None = None) -> DepthRow:
    code = Code(n)
    slots = reading_slots(n, heads, strobes)
    if samples is None and n > 12:
        samples = 64
    hist, starts = weight_counts(code, slots, samples)
    readings = len(slots)
    nonzero = np.flatnonzero(hist)
    return DepthRow(n, heads, strobes, readings, readings - n,
                    int(nonzero[0]) if len(nonzero) else readings + 1,
                    {r: p_wrong(hist, starts, readings, r) for r in RATES})


def table(ns=range(6, 17), extra=(0, 1, 2, 3, 4)) -> list[DepthRow]:
    """Two heads at k = N + e strobes, one head at k = 2N + e, for e in `extra`."""
    rows = []
    for n in ns:
        for e in extra:
            rows.append(depth_row(n, 2, n + e))
        for e in extra:
            rows.append(depth_row(n, 1, 2 * n + e))
    return rows


if __name__ == "__main__":  # pragma: no cover - a table for docs/architecture.md
    import sys

    ns = [int(a) for a in sys.argv[1:]] or list(range(6, 17))
    print("| N | heads | strobes k | readings | checks | lightest pattern | P wrong @0.1 % | @1 % | @3 % |")
    print("|---|---|---|---|---|---|---|---|---|")
    for row in table(ns):
        p = row.p_wrong
        print(f"| {row.n} | {row.heads} | {row.strobes} | {row.readings} | {row.checks} | {row.min_weight} "
              f"| {p[0.001]:.1e} | {p[0.01]:.1e} | {p[0.03]:.1e} |")
