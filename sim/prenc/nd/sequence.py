# SPDX-License-Identifier: Apache-2.0
"""Windows of a cyclic binary sequence and the independent minimum-distance check.

A sequence is a 1-D array (or string) of bits s(0..K-1). Its window at position i is
W(i) = (s(i), ..., s(i+n-1)) read cyclically, with s(i) as the MSB of the window's
value, the same convention as the disc's code (`prenc.codes.debruijn.window_values`).
When K < n a window wraps around more than once; the definition still holds.

`min_distance` is the check every reported sequence passes before it is printed: it
compares every pair of windows by popcount, sharing nothing with the searches and
constructions that produced the sequence.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np

_POPCOUNT8 = np.array([bin(i).count("1") for i in range(256)], dtype=np.uint8)


def as_bits(seq: str | Sequence[int] | np.ndarray) -> np.ndarray:
    """The bits of a sequence given as '0110...', a list of 0/1 or an array."""
    if isinstance(seq, str):
        if not seq or set(seq) - {"0", "1"}:
            raise ValueError(f"a sequence is a non-empty string of 0 and 1, got {seq[:40]!r}")
        return np.frombuffer(seq.encode(), dtype=np.uint8) - ord("0")
    bits = np.asarray(seq, dtype=np.uint8)
    if bits.ndim != 1 or len(bits) == 0 or bits.max() > 1:
        raise ValueError("a sequence is a non-empty 1-D array of 0 and 1")
    return bits


def to_text(seq) -> str:
    """'0110...' for a sequence of bits."""
    return "".join("1" if b else "0" for b in as_bits(seq))


def windows(seq, n: int) -> np.ndarray:
    """Window values W(i) for i = 0..K-1 (int64, s(i) as MSB)."""
    if not 1 <= n <= 62:
        raise ValueError(f"window length n = {n} is out of range 1..62")
    bits = as_bits(seq).astype(np.int64)
    k = len(bits)
    idx = (np.arange(k)[:, None] + np.arange(n)[None, :]) % k
    weights = np.int64(1) << np.arange(n - 1, -1, -1, dtype=np.int64)
    return (bits[idx] * weights).sum(axis=1)


def popcount(values: np.ndarray) -> np.ndarray:
    """Bits set in each non-negative int64 value."""
    v = np.asarray(values, dtype=np.int64).view(np.uint64)
    total = np.zeros(v.shape, dtype=np.int64)
    while np.any(v):
        total += _POPCOUNT8[(v & np.uint64(0xFF)).astype(np.intp)]
        v = v >> np.uint64(8)
    return total


def min_distance(seq, n: int) -> int:
    """The smallest Hamming distance between two of the sequence's n-windows.

    0 when two windows are equal; n + 1 (no pair to compare) for K = 1.
    """
    w = windows(seq, n)
    if len(w) < 2:
        return n + 1
    if len(np.unique(w)) < len(w):
        return 0
    if len(w) > 1 << (n - 1):
        return 1  # more distinct windows than (n-1)-bit prefixes: two differ only in their last bit
    best = n
    for i in range(len(w) - 1):
        row = popcount(w[i] ^ w[i + 1:])
        best = min(best, int(row.min()))
        if best == 0:
            break
    return best


def pairwise_distances(seq, n: int) -> np.ndarray:
    """The K x K matrix of Hamming distances between the sequence's n-windows."""
    w = windows(seq, n)
    return popcount(w[:, None] ^ w[None, :]).astype(np.int32)


def check(seq, n: int, d: int) -> int:
    """Raise ValueError unless `seq` is an (n,d)-sequence; return its minimum distance."""
    dist = min_distance(seq, n)
    if dist < d:
        raise ValueError(f"not an ({n},{d})-sequence: two of its {n}-windows differ in only {dist} bits")
    return dist
