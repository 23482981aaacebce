# SPDX-License-Identifier: Apache-2.0
"""(n,d)-sequences of a chosen length K: a beam search with a planned closure.

The experiments need sequences of one given length (K = 170 in the paper), which the
exhaustive search finds slowly for d >= 2: closing a long cycle at exactly K windows
is the hard part. This search grows paths from every start window level by level, like
Algorithm 1, but keeps only the `width` most promising paths at each level:

1. first the paths whose closing route is still open: from the path's last window v,
   the cycle can always close in exactly n steps through the windows
   (v << t | s >> (n - t)), t = 1..n-1, back to the start s; the route is open when
   those n-1 windows are all still allowed and far enough from each other;
2. among those, the paths with the most windows still allowed (ties at random).

At K - n + 1 windows a path with an open route closes into a cycle of exactly K.
The result is a sequence, not a proof: None when the beam finds nothing.
"""

from __future__ import annotations

import random

from .exact import exact_search
from .graph import Balls, sequence_of_cycle


def _route(cur: int, start: int, allowed: int, n: int, balls: Balls) -> list[int] | None:
    mask = (1 << n) - 1
    route = []
    for t in range(1, n):
        v = ((cur << t) | (start >> (n - t))) & mask
        if not allowed >> v & 1:
            return None
        allowed &= ~balls[v]
        route.append(v)
    return route


def beam_search(n: int, d: int, length: int, width: int = 1000, seed: int = 1) -> str | None:
    """A cyclic (n,d)-sequence of exactly `length` bits, or None."""
    if length <= n + 1:
        return None
    rnd = random.Random(seed)
    balls = Balls(n, d)
    size = 1 << n
    mask = size - 1
    full = (1 << size) - 1
    # a path is (start, last window, allowed set, index of its parent in the previous level)
    levels = [[(s, s, full & ~balls[s], -1) for s in range(size)]]
    for windows_now in range(1, length - n + 1):
        grown = []
        for idx, (start, cur, allowed, _) in enumerate(levels[-1]):
            for bit in (0, 1):
                nxt = ((cur << 1) | bit) & mask
                if nxt != start and allowed >> nxt & 1:
                    rest = allowed & ~balls[nxt]
                    if windows_now + 1 + rest.bit_count() >= length:
                        grown.append((start, nxt, rest, idx))
        if not grown:
            return None
        keyed = [(_route(p[1], p[0], p[2], n, balls) is not None, p[2].bit_count() + rnd.random(), p)
                 for p in grown]
        keyed.sort(key=lambda k: (not k[0], -k[1]))
        levels.append([k[2] for k in keyed[:width]])
    for idx, (start, cur, allowed, _) in enumerate(levels[-1]):
        route = _route(cur, start, allowed, n, balls)
        if route is None:
            continue
        path = []
        level, i = len(levels) - 1, idx
        while i >= 0:
            path.append(levels[level][i][1])
            i = levels[level][i][3]
            level -= 1
        return sequence_of_cycle(path[::-1] + route, n)
    return None


def sequence_of_length(n: int, d: int, length: int, time_limit: float = 20.0) -> str | None:
    """A cyclic (n,d)-sequence of exactly `length` bits: the exact search with a target
    for d = 1 and short lengths, the beam search (a few widths and seeds) otherwise."""
    if d == 1 or length <= n + 1:
        found = exact_search(n, d, target=length, time_limit=time_limit)
        if found.sequence:
            return found.sequence
    for width, seed in ((1000, 1), (3000, 2), (10000, 3)):
        seq = beam_search(n, d, length, width, seed)
        if seq:
            return seq
    return None
