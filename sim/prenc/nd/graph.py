# SPDX-License-Identifier: Apache-2.0
"""The de Bruijn graph of n-bit windows and the Hamming balls the searches prune with.

A window v (n bits, the oldest bit as MSB) has the two successors (v << 1 | b) mod 2^n.
A cyclic sequence of length K is a closed walk of K windows; an (n,d)-sequence is a
cycle whose windows are pairwise at distance >= d. The searches keep the windows
still allowed as one Python int used as a bit set (bit v set = window v allowed), so
that removing a window's Hamming ball of radius d-1 is a single AND.
"""

from __future__ import annotations

from itertools import combinations


class Balls:
    """Bit sets of the windows at distance < d from each window, made on demand."""

    def __init__(self, n: int, d: int):
        if not 1 <= n <= 24:
            raise ValueError(f"window length n = {n} is out of range 1..24")
        if d < 1:
            raise ValueError(f"distance d = {d} must be at least 1")
        self.n = n
        self.d = d
        self.errors = [sum(1 << i for i in bits)
                       for r in range(min(d, n + 1)) for bits in combinations(range(n), r)]
        self._cache: dict[int, int] = {}

    def __getitem__(self, v: int) -> int:
        ball = self._cache.get(v)
        if ball is None:
            ball = 0
            for e in self.errors:
                ball |= 1 << (v ^ e)
            self._cache[v] = ball
        return ball


def sequence_of_cycle(cycle: list[int], n: int) -> str:
    """The sequence whose windows are `cycle`, in order: each window's oldest bit."""
    return "".join(str(v >> (n - 1) & 1) for v in cycle)
