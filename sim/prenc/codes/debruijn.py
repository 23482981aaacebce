# SPDX-License-Identifier: Apache-2.0
"""The disc's code: an LFSR sequence completed to a de Bruijn sequence.

Definitions follow the disc datasheet (shared/encoder-disc.md):

- s is the maximal-length sequence from the seed 1, 0, ..., 0 with one extra 0
  inserted into its single run of N-1 zeros, giving period L = 2^N in which every
  N-bit word appears exactly once.
- W(p) = (s(p), ..., s(p+N-1)); its value w(p) has s(p) as MSB, so w(0) = 2^(N-1),
  w(1) = 0, w(2) = 1.
- forward law:  s(p+N) = XOR_{t in T} s(p+N-t) XOR [s(p+1..p+N-1) all zero]
- inverse law:  s(p-1) = s(p+N-1) XOR_{t in T, t<N} s(p+N-1-t) XOR [s(p..p+N-2) all zero]

In a window value w = w(p), s(p+i) is bit N-1-i. So tap t of the forward law reads
bit t-1 of w, and the inverse law reads bit 0 (s(p+N-1)) and bit t for t < N.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import Iterable

import numpy as np

from .lfsr import check_bits, check_taps, msequence


def debruijn_sequence(n: int, taps: Iterable[int] | None = None) -> np.ndarray:
    """The de Bruijn sequence s(0 .. 2^N - 1) of the datasheet (uint8, read-only).

    The m-sequence from the seed 1, 0, ..., 0 starts with its run of N-1 zeros at
    positions 1..N-1 (an m-sequence has exactly one such run and none longer), so
    the extra 0 goes right after it, at position N. W(0) stays 1 0 ... 0.
    """
    m = msequence(n, taps)
    seq = np.concatenate([m[:n], np.zeros(1, dtype=np.uint8), m[n:]])
    seq.setflags(write=False)
    return seq


def window_values(seq: np.ndarray, n: int) -> np.ndarray:
    """w(p) for every p of a cyclic sequence, as uint32 (uint64 above 32 bits)."""
    length = len(seq)
    dtype = np.uint32 if n <= 32 else np.uint64
    ext = np.concatenate([seq, seq[: n - 1]]).astype(dtype)
    w = np.zeros(length, dtype=dtype)
    for i in range(n):
        w <<= dtype(1)
        w |= ext[i : i + length]
    return w


def forward_bit(word, n: int, taps: Iterable[int]):
    """s(p+N) from w(p) by the forward law; works on ints and numpy arrays."""
    bit = 0
    for t in taps:
        bit = bit ^ ((word >> (t - 1)) & 1)
    low_mask = (1 << (n - 1)) - 1
    return bit ^ ((word & low_mask) == 0) * 1


def inverse_bit(word, n: int, taps: Iterable[int]):
    """s(p-1) from w(p) by the inverse law; works on ints and numpy arrays."""
    bit = word & 1
    for t in taps:
        if t != n:
            bit = bit ^ ((word >> t) & 1)
    return bit ^ ((word >> 1) == 0) * 1


def step_forward(word, n: int, taps: Iterable[int]):
    """w(p+1) from w(p): shift left, the forward-law bit enters as LSB."""
    mask = (1 << n) - 1
    return ((word << 1) & mask) | forward_bit(word, n, taps)


def step_inverse(word, n: int, taps: Iterable[int]):
    """w(p-1) from w(p): shift right, the inverse-law bit enters as MSB."""
    return (word >> 1) | (inverse_bit(word, n, taps) << (n - 1))


@dataclass(frozen=True)
class Code:
    """The disc code for N and a feedback set: sequence, windows and laws.

    >>> c = Code(10)
    >>> c.window(0), c.window(1), c.window(2)
    (512, 0, 1)
    """

    n: int = 10
    taps: tuple[int, ...] | None = None
    _taps: tuple[int, ...] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "n", check_bits(self.n))
        object.__setattr__(self, "_taps", check_taps(self.n, self.taps))
        object.__setattr__(self, "taps", self._taps)

    @property
    def length(self) -> int:
        """L = 2^N slots."""
        return 1 << self.n

    @property
    def mask(self) -> int:
        return (1 << self.n) - 1

    @cached_property
    def sequence(self) -> np.ndarray:
        """s(0 .. L-1)."""
        return debruijn_sequence(self.n, self.taps)

    @cached_property
    def windows(self) -> np.ndarray:
        """w(p) for p = 0 .. L-1."""
        w = window_values(self.sequence, self.n)
        w.setflags(write=False)
        return w

    @cached_property
    def positions(self) -> np.ndarray:
        """The inverse of `windows`: positions[w(p)] = p (the conversion ROM)."""
        pos = np.empty(self.length, dtype=self.windows.dtype)
        pos[self.windows] = np.arange(self.length, dtype=self.windows.dtype)
        pos.setflags(write=False)
        return pos

    def bit(self, p: int) -> int:
        """s(p), index taken mod L."""
        return int(self.sequence[p % self.length])

    def window(self, p: int) -> int:
        """w(p), index taken mod L."""
        return int(self.windows[p % self.length])

    def position(self, word: int) -> int:
        """p such that w(p) = word."""
        if not 0 <= word <= self.mask:
            raise ValueError(f"word {word} does not fit in N = {self.n} bits")
        return int(self.positions[word])

    def forward_bit(self, word):
        return forward_bit(word, self.n, self.taps)

    def inverse_bit(self, word):
        return inverse_bit(word, self.n, self.taps)

    def step_forward(self, word):
        return step_forward(word, self.n, self.taps)

    def step_inverse(self, word):
        return step_inverse(word, self.n, self.taps)
