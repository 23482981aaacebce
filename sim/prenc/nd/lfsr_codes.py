# SPDX-License-Identifier: Apache-2.0
"""Long (n,d)-sequences at once from maximal-length LFSR sequences.

The m-sequence of a primitive polynomial of degree k < n has period 2^k - 1, and its
n-windows are exactly the non-zero codewords of a linear [n, k] code (each window is
fixed by its first k bits, and the sum of two windows is a window, shifted). So the
windows are all distinct and the distance between two of them is the weight of a
third: the minimum pairwise distance is the minimum window weight, computed in
O(K) instead of O(K^2). Searching every primitive polynomial of each degree k gives,
for every n and d, the longest such sequence: length 2^k - 1 for the largest k whose
best polynomial has minimum window weight >= d.

For d = 1 the de Bruijn sequence of the disc's code (length 2^n) is better still.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ..codes.debruijn import debruijn_sequence
from ..codes.lfsr import is_primitive, msequence, polynomial
from .sequence import to_text


@dataclass(frozen=True)
class Construction:
    n: int
    d: int
    length: int
    taps: tuple[int, ...]
    sequence: str
    method: str


def primitive_taps(k: int) -> list[tuple[int, ...]]:
    """Every feedback set of degree k whose polynomial is primitive, in a fixed order."""
    found = []
    for middle in range(1 << (k - 1)):
        poly = (1 << k) | 1 | (middle << 1)
        if poly.bit_count() % 2 == 0 and k > 1:  # divisible by x + 1
            continue
        if is_primitive(poly):
            taps = (k,) + tuple(k - i for i in range(k - 1, 0, -1) if poly >> i & 1)
            assert polynomial(taps) == poly
            found.append(taps)
    return found


def min_window_weight(seq: np.ndarray, n: int) -> int:
    """The smallest weight of an n-window of a cyclic sequence (sliding sum)."""
    length = len(seq)
    ext = np.tile(seq, n // length + 2)[: length + n].astype(np.int32)
    cum = np.concatenate([[0], np.cumsum(ext)])
    return int((cum[n:n + length] - cum[:length]).min())


@lru_cache(maxsize=None)
def _best_by_degree(k: int, max_n: int) -> dict[int, tuple[int, tuple[int, ...]]]:
    """For each n in k+1..max_n: (best minimum window weight, its taps) over degree k."""
    best: dict[int, tuple[int, tuple[int, ...]]] = {}
    for taps in primitive_taps(k):
        seq = msequence(k, taps)
        for n in range(k + 1, max_n + 1):
            weight = min_window_weight(seq, n)
            if weight > best.get(n, (-1,))[0]:
                best[n] = (weight, taps)
    return best


def best_lfsr(n: int, d: int, max_n: int | None = None) -> Construction | None:
    """The longest m-sequence (degree k < n, every primitive polynomial) whose n-windows
    have pairwise distance >= d; for d = 1 the de Bruijn sequence of length 2^n."""
    if d <= 1:
        seq = debruijn_sequence(n) if n >= 2 else np.array([0, 1], dtype=np.uint8)
        return Construction(n, d, len(seq), (), to_text(seq), "de Bruijn (disc code)")
    max_n = max(n, max_n or n)
    for k in range(n - 1, 1, -1):
        weight, taps = _best_by_degree(k, max_n).get(n, (-1, ()))
        if weight >= d:
            seq = msequence(k, taps)
            return Construction(n, d, len(seq), taps, to_text(seq),
                                f"m-sequence taps {','.join(map(str, taps))} (degree {k})")
    return None
