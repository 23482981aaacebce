# SPDX-License-Identifier: Apache-2.0
"""The paper's Algorithm 1: breadth-first growth of paths in the de Bruijn graph.

Kept as the baseline the exact search is measured against (`make bench`). Every
window starts a path; at each level every path is extended by each successor whose
distance to every window already on the path is at least d (tested pair by pair, by
popcount); a successor equal to the path's first window closes a cycle, whose length
is recorded. The levels run until no path can grow, so the longest cycle recorded is
the maximum. Nothing is pruned by length and each cycle is grown from all K of its
rotations, so the number of paths grows exponentially: `max_paths` stops a run that
would exhaust memory (the result is then not exact).
"""

from __future__ import annotations

import time

from .exact import SearchResult
from .graph import sequence_of_cycle


def algorithm1(n: int, d: int, *, max_paths: int = 2_000_000, time_limit: float | None = None) -> SearchResult:
    if d < 1:
        raise ValueError(f"distance d = {d} must be at least 1")
    mask = (1 << n) - 1
    start = time.perf_counter()
    deadline = None if time_limit is None else start + time_limit
    paths: list[tuple[int, ...]] = [(v,) for v in range(1 << n)]
    nodes = len(paths)
    best, best_cycle = 0, None
    complete = True
    while paths:
        grown: list[tuple[int, ...]] = []
        for path in paths:
            last = path[-1]
            for bit in (0, 1):
                nxt = ((last << 1) | bit) & mask
                if nxt == path[0]:
                    if len(path) > best:
                        best, best_cycle = len(path), path
                    continue
                if all((nxt ^ w).bit_count() >= d for w in path):
                    grown.append(path + (nxt,))
        nodes += len(grown)
        paths = grown
        if len(paths) > max_paths or (deadline is not None and time.perf_counter() > deadline):
            complete = False
            break
    sequence = sequence_of_cycle(list(best_cycle), n) if best_cycle else None
    return SearchResult(n, d, best, sequence, complete, nodes, time.perf_counter() - start, "algorithm1")
