# SPDX-License-Identifier: Apache-2.0
"""Exact search for long (n,d)-sequences: depth-first, one canonical rotation.

Every cyclic sequence has a smallest window s. The search tries s = 0, 1, 2, ... and
from each grows the cycle depth-first through windows larger than s only, so each
cycle is met from one rotation instead of K. The windows still allowed form a bit
set: entering a window removes its Hamming ball of radius d-1, so the pairwise
distance test of a new window is one bit lookup. Bounds:

- a branch dies when its length plus the number of windows still allowed cannot
  beat the best cycle found (or reach the target length);
- the outer loop ends when fewer than best+1 windows are larger than s;
- the search stops at once when the best reaches a proven upper bound
  (`prenc.nd.bounds`).

Seeded with a construction's length (`lower`), the search only has to rule out
longer cycles. When it runs to the end the best length is proven maximal
(`exact=True`); when the time limit stops it first, the best found is a lower bound.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

from .graph import Balls, sequence_of_cycle


@dataclass(frozen=True)
class SearchResult:
    n: int
    d: int
    length: int
    sequence: str | None
    exact: bool
    nodes: int
    seconds: float
    method: str

    def as_dict(self) -> dict:
        return {"n": self.n, "d": self.d, "length": self.length, "exact": self.exact,
                "sequence": self.sequence, "method": self.method, "nodes": self.nodes,
                "seconds": round(self.seconds, 6)}


_CHECK_EVERY = 1 << 13


def exact_search(n: int, d: int, *, lower: int = 0, lower_sequence: str | None = None,
                 upper: int | None = None, time_limit: float | None = None,
                 target: int | None = None) -> SearchResult:
    """The longest (n,d)-sequence, or with `target` the first one of exactly that length.

    lower / lower_sequence: a known sequence to beat (the result keeps it when the
    search finds nothing longer). upper: a proven bound that ends the search when
    reached. time_limit in seconds: on expiry the best so far is returned with
    exact=False.
    """
    balls = Balls(n, d)
    size = 1 << n
    mask = size - 1
    full = (1 << size) - 1
    best, best_seq = lower, lower_sequence
    if target is not None and not 1 <= target <= size:
        raise ValueError(f"target length {target} is out of range 1..{size}")
    deadline = None if time_limit is None else time.perf_counter() + time_limit
    start = time.perf_counter()
    nodes = 0
    stopped = False
    done = upper is not None and best >= upper

    for s in range(size):
        if done or stopped:
            break
        if target is None and size - s <= best:
            break
        if target is not None and size - s < target:
            break
        allowed = ((full >> (s + 1)) << (s + 1)) & ~balls[s]
        path = [s]
        stack = [[s, allowed, 0]]
        nodes += 1
        while stack:
            frame = stack[-1]
            cur, allowed, bit = frame
            if bit == 2:
                stack.pop()
                path.pop()
                continue
            frame[2] = bit + 1
            nxt = ((cur << 1) | bit) & mask
            length = len(path)
            if nxt == s:
                if target is not None:
                    if length == target:
                        return SearchResult(n, d, length, sequence_of_cycle(path, n), True, nodes,
                                            time.perf_counter() - start, "exact-dfs(target)")
                elif length > best:
                    best, best_seq = length, sequence_of_cycle(path, n)
                    if upper is not None and best >= upper:
                        done = True
                        break
                continue
            if not allowed >> nxt & 1:
                continue
            rest = allowed & ~balls[nxt]
            if target is not None:
                left = target - length - 1  # windows still to add after nxt
                if left < 0 or length + 1 + rest.bit_count() < target:
                    continue
                if left < n - 1 and (nxt & ((1 << (n - left - 1)) - 1)) != s >> (left + 1):
                    continue  # the last n windows before s are forced: nxt is not on that route
            elif length + 1 + rest.bit_count() <= best:
                continue
            nodes += 1
            if nodes % _CHECK_EVERY == 0 and deadline is not None and time.perf_counter() > deadline:
                stopped = True
                break
            path.append(nxt)
            stack.append([nxt, rest, 0])

    seconds = time.perf_counter() - start
    if target is not None:
        return SearchResult(n, d, 0, None, not stopped, nodes, seconds, "exact-dfs(target)")
    return SearchResult(n, d, best, best_seq, not stopped, nodes, seconds, "exact-dfs")
