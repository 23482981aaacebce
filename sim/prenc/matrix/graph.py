# SPDX-License-Identifier: Apache-2.0
"""The paper's graph G (Definition 3) and its Hamiltonian cycles.

The vertices of G are the 2^(n*n) binary n x n matrices. There is an arc from A to B
when B is A moved on by one column: columns 2..n of A are columns 1..n-1 of B. A
Hamiltonian cycle of G visits every window once and returns: it is a matrix code,
the sequence of the columns it adds. G is the de Bruijn graph of order n over the
2^n column symbols, so its Hamiltonian cycles are exactly the de Bruijn sequences
of that order (counted by the closed formula below, from the BEST theorem).

Vertices are numbered here by the window address of `prenc.matrix.code` (columns in
order, first column most significant, track 0 the MSB of a column).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

from .code import check_order


def successors(v: int, n: int) -> range | list[int]:
    """The 2^n windows that follow window v: drop its first column, add one."""
    k = 1 << n
    base = (v << n) & ((1 << (n * n)) - 1)
    return [base | c for c in range(k)]


def adjacency(n: int) -> list[list[int]]:
    """Adjacency matrix of G (row A, column B: 1 when A -> B), address order."""
    size = 1 << (n * n)
    rows = [[0] * size for _ in range(size)]
    for v in range(size):
        for w in successors(v, n):
            rows[v][w] = 1
    return rows


def debruijn_count(k: int, n: int) -> int:
    """Number of de Bruijn sequences of order n over k symbols (cycles counted
    once, not per rotation): (k!)^(k^(n-1)) / k^n."""
    return math.factorial(k) ** (k ** (n - 1)) // k ** n


def matrix_code_count(n: int) -> int:
    """Number of Hamiltonian cycles of G, i.e. of n-track matrix codes."""
    return debruijn_count(1 << n, n)


def count_hamiltonian_cycles(n: int) -> int:
    """Count the Hamiltonian cycles of G by enumerating them: a depth-first search
    from window 0 over bit sets, pruning a branch when an unvisited window has lost
    every unvisited predecessor. Practical for n = 2 (16 vertices)."""
    check_order(n)
    if n > 2:
        raise ValueError("enumerating the Hamiltonian cycles is practical for n = 2 only")
    size = 1 << (n * n)
    succ = [successors(v, n) for v in range(size)]
    pred_mask = [0] * size
    for v in range(size):
        for w in succ[v]:
            pred_mask[w] |= 1 << v
    full = (1 << size) - 1
    start = 0
    count = 0
    stack = [(start, 1 << start)]
    while stack:
        v, visited = stack.pop()
        if visited == full:
            if start in succ[v]:
                count += 1
            continue
        for w in succ[v]:
            if visited >> w & 1:
                continue
            nv = visited | (1 << w)
            # every window still to visit needs a predecessor that is w or unvisited
            ok = True
            open_mask = (full & ~nv) | (1 << w)
            rest = full & ~nv
            u = rest
            while u:
                low = u & -u
                x = low.bit_length() - 1
                if not pred_mask[x] & open_mask:
                    ok = False
                    break
                u ^= low
            if ok:
                stack.append((w, nv))
    return count


@dataclass
class SearchResult:
    cycle: list[int] | None  # the windows in order, starting at window 0
    nodes: int
    seconds: float


ORDERS = ("warnsdorff", "lexicographic")


def hamiltonian_cycle(n: int, order: str = "warnsdorff", time_limit: float = 60.0) -> SearchResult:
    """Find one Hamiltonian cycle of G from window 0 by backtracking search. A
    generic graph search: it knows nothing of Lyndon words, so it cross-checks the
    FKM construction.

    order "warnsdorff" tries the successor with the fewest onward choices first
    (the largest on a tie);
    "lexicographic" tries the smallest first, so the first cycle found is the
    lexicographically least, whose columns must be exactly the FKM sequence."""
    if order not in ORDERS:
        raise ValueError(f"unknown search order {order!r}; choose one of {', '.join(ORDERS)}")
    check_order(n)
    size = 1 << (n * n)
    succ = [successors(v, n) for v in range(size)]
    pred_count = [0] * size
    for v in range(size):
        for w in succ[v]:
            pred_count[w] += 1
    visited = [False] * size
    start = 0
    visited[start] = True
    path = [start]
    # per depth: the candidate list still to try
    todo: list[list[int]] = []
    t0 = time.perf_counter()
    nodes = 0

    def ordered(v: int) -> list[int]:
        cand = [w for w in succ[v] if not visited[w]]
        if order == "lexicographic":
            return cand[::-1]
        # popped from the end: fewest onward choices first, the largest window on a
        # tie (so that it does not retrace the lexicographic search)
        cand.sort(key=lambda w: (sum(1 for x in succ[w] if not visited[x]), -w), reverse=True)
        return cand

    todo.append(ordered(start))
    while todo:
        if time.perf_counter() - t0 > time_limit:
            return SearchResult(None, nodes, time.perf_counter() - t0)
        if len(path) == size:
            if start in succ[path[-1]]:
                return SearchResult(list(path), nodes, time.perf_counter() - t0)
        cand = todo[-1]
        if not cand or len(path) == size:
            todo.pop()
            visited[path.pop()] = False
            continue
        w = cand.pop()
        nodes += 1
        visited[w] = True
        path.append(w)
        todo.append(ordered(w))
    return SearchResult(None, nodes, time.perf_counter() - t0)


def columns_of_cycle(cycle: list[int], n: int) -> list[int]:
    """The column sequence of a Hamiltonian cycle: the last column of each window,
    rotated so that position p's window is cycle[p]."""
    mask = (1 << n) - 1
    last = [v & mask for v in cycle]
    # window cycle[p] ends with column p+n-1: rotate right by n-1
    size = len(cycle)
    return [last[(p - (n - 1)) % size] for p in range(size)]
