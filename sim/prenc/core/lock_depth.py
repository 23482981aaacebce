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
linear approximation): every p and every d, up to N = 16 (prefix sums over each
shift; `weight_counts`, the direct comparison, checks it in the tests).

Two geometries, as the reader locks (see docs/architecture.md):
- two heads, k strobes: head 1 reads s(p0 .. p0+k-1), head 2 reads
  s(p0+N-1 .. p0+N+k-2); 2k readings, 2k - N checks;
- one head, k strobes: s(p0 .. p0+k-1); k readings, k - N checks.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..codes.debruijn import Code


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
    number of p it averages over (every p unless `samples` asks for a sample)."""
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


def runs(slots: np.ndarray) -> list[tuple[int, int]]:
    """The read slots as runs of consecutive slots (first, length); a slot read by
    both heads is in two runs (two readings)."""
    out: list[tuple[int, int]] = []
    for s in slots.tolist():
        if out and out[-1][0] + out[-1][1] == s:
            out[-1] = (out[-1][0], out[-1][1] + 1)
        else:
            out.append((s, 1))
    return out


def weight_counts_exact(code: Code, slot_sets: list[np.ndarray]) -> list[np.ndarray]:
    """The same histograms over every p and d, for several reading geometries at
    once, by prefix sums: for a shift d, x(j) = [s(j) != s(j + d)], and a run of
    readings weighs a difference of the prefix sums of x. O(L^2) per geometry: all
    2^16 starts of N = 16 in a minute or two."""
    length = code.length
    seq = code.sequence.astype(np.int32)
    reach = max(int(s.max()) for s in slot_sets) + 1
    geometries = [runs(s) for s in slot_sets]
    hists = [np.zeros(len(s) + 1, dtype=np.int64) for s in slot_sets]
    twice = np.concatenate([seq, seq, seq[:reach]])
    c = np.zeros(length + reach + 1, dtype=np.int32)
    for d in range(1, length):
        np.cumsum(twice[:length + reach] ^ twice[d:d + length + reach], out=c[1:])
        for hist, geometry in zip(hists, geometries):
            w = np.zeros(length, dtype=np.int32)
            for first, count in geometry:
                w += c[first + count:first + count + length]
                w -= c[first:first + length]
            hist += np.bincount(w, minlength=len(hist))
    return hists


def p_wrong(hist: np.ndarray, starts: int, readings: int, rate: float) -> float:
    """P(a lock is wrong | it locks): wrong locks over all locks."""
    w = np.arange(len(hist))
    wrong = float((hist * rate ** w * (1 - rate) ** (readings - w)).sum()) / starts
    right = (1 - rate) ** readings
    return wrong / (wrong + right)


RATES = (0.001, 0.01, 0.03)


def make_row(n: int, heads: int, strobes: int, hist: np.ndarray, starts: int) -> DepthRow:
    readings = len(hist) - 1
    nonzero = np.flatnonzero(hist)
    return DepthRow(n, heads, strobes, readings, readings - n,
                    int(nonzero[0]) if len(nonzero) else readings + 1,
                    {r: p_wrong(hist, starts, readings, r) for r in RATES})


def depth_row(n: int, heads: int, strobes: int) -> DepthRow:
    code = Code(n)
    (hist,) = weight_counts_exact(code, [reading_slots(n, heads, strobes)])
    return make_row(n, heads, strobes, hist, code.length)


def table(ns=range(6, 17), extra=(0, 1, 2, 3, 4)) -> list[DepthRow]:
    """Two heads at k = N + e strobes, one head at k = 2N + e, for e in `extra`;
    every start p and every shift d of each disc."""
    rows = []
    for n in ns:
        code = Code(n)
        shapes = [(2, n + e) for e in extra] + [(1, 2 * n + e) for e in extra]
        hists = weight_counts_exact(code, [reading_slots(n, h, k) for h, k in shapes])
        rows += [make_row(n, h, k, hist, code.length) for (h, k), hist in zip(shapes, hists)]
    return rows


def default_depths(n: int) -> list[tuple[str, int, int]]:
    """The core's lock depths at N (prenc.core.mode_fsm's defaults): (name, heads, k)."""
    from .mode_fsm import LOCK_EXTRA, default_lock_both, default_lock_one

    both = n + default_lock_both(n) - 1
    one = n + default_lock_one(n) - 1
    return [("two heads, quiet", 2, both), ("two heads, deep", 2, both + LOCK_EXTRA),
            ("one head, quiet", 1, one), ("one head, deep", 1, one + LOCK_EXTRA)]


def defaults_table(ns=range(6, 17)) -> list[DepthRow]:
    """The four default depths of each N (every p and d)."""
    rows = []
    for n in ns:
        code = Code(n)
        shapes = [(h, k) for _, h, k in default_depths(n)]
        hists = weight_counts_exact(code, [reading_slots(n, h, k) for h, k in shapes])
        rows += [make_row(n, h, k, hist, code.length) for (h, k), hist in zip(shapes, hists)]
    return rows


HEADER = ("| N | heads | strobes k | readings | checks | lightest pattern "
          "| P wrong @0.1 % | @1 % | @3 % |\n|---|---|---|---|---|---|---|---|---|")


def markdown(rows: list[DepthRow]) -> str:
    lines = [HEADER]
    for row in rows:
        p = row.p_wrong
        lines.append(f"| {row.n} | {row.heads} | {row.strobes} | {row.readings} | {row.checks} "
                     f"| {row.min_weight} | {p[0.001]:.1e} | {p[0.01]:.1e} | {p[0.03]:.1e} |")
    return "\n".join(lines)


if __name__ == "__main__":  # pragma: no cover - the tables of docs/lock-depth.md
    import sys

    args = sys.argv[1:]
    defaults = "--defaults" in args
    ns = [int(a) for a in args if a != "--defaults"] or list(range(6, 17))
    print(markdown(defaults_table(ns) if defaults else table(ns)))
