# SPDX-License-Identifier: Apache-2.0
"""Maximal-length LFSR sequences over GF(2).

A feedback set T (the "taps") defines the recurrence of the disc datasheet:

    s(k) = XOR over t in T of s(k - t)

The largest tap is the register length N. The recurrence's characteristic
polynomial is P(x) = x^N + sum over t in T, t < N, of x^(N - t) + 1, so the
default disc T = [10, 3] has P(x) = x^10 + x^7 + 1. The sequence has the
maximal period 2^N - 1 exactly when P is primitive, which `is_primitive`
decides by computing the multiplicative order of x modulo P.

Polynomials are Python ints: bit i is the coefficient of x^i.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Iterable, Iterator, Sequence

import numpy as np

MIN_BITS = 2
MAX_BITS = 32

# Default feedback set for each N: the primitive trinomial [N, t] with the smallest t
# where one exists, otherwise the first primitive pentanomial in `find_default_taps`
# order (N has no primitive trinomial for N = 8, 12, 13, 14, 16, 19, 24, 26, 27, 30, 32).
# Found by `find_default_taps`; every entry is proven primitive by the test suite,
# which recomputes the order of x, so nothing here is taken on trust.
DEFAULT_TAPS: dict[int, tuple[int, ...]] = {
    2: (2, 1),
    3: (3, 1),
    4: (4, 1),
    5: (5, 2),
    6: (6, 1),
    7: (7, 1),
    8: (8, 7, 2, 1),
    9: (9, 4),
    10: (10, 3),
    11: (11, 2),
    12: (12, 8, 2, 1),
    13: (13, 5, 2, 1),
    14: (14, 12, 2, 1),
    15: (15, 1),
    16: (16, 12, 3, 1),
    17: (17, 3),
    18: (18, 7),
    19: (19, 5, 2, 1),
    20: (20, 3),
    21: (21, 2),
    22: (22, 1),
    23: (23, 5),
    24: (24, 7, 2, 1),
    25: (25, 3),
    26: (26, 6, 2, 1),
    27: (27, 5, 2, 1),
    28: (28, 3),
    29: (29, 2),
    30: (30, 23, 2, 1),
    31: (31, 3),
    32: (32, 22, 2, 1),
}


class TapsError(ValueError):
    """A feedback set that does not give a maximal-length sequence."""


def check_bits(n: int, lo: int = MIN_BITS, hi: int = MAX_BITS) -> int:
    """Return n if it is an int in lo..hi, else raise ValueError naming the range."""
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)):
        raise ValueError(f"N must be an integer, got {n!r}")
    if not lo <= int(n) <= hi:
        raise ValueError(f"N = {n} is out of range {lo}..{hi}")
    return int(n)


def polynomial(taps: Sequence[int]) -> int:
    """Characteristic polynomial of the recurrence with feedback set `taps`."""
    n = max(taps)
    poly = (1 << n) | 1
    for t in taps:
        if t != n:
            poly ^= 1 << (n - t)
    return poly


def poly_str(poly: int) -> str:
    """Human-readable polynomial, highest power first: 'x^10 + x^7 + 1'."""
    terms = []
    for i in range(poly.bit_length() - 1, -1, -1):
        if poly >> i & 1:
            terms.append("1" if i == 0 else "x" if i == 1 else f"x^{i}")
    return " + ".join(terms) if terms else "0"


def _mulmod(a: int, b: int, poly: int, n: int) -> int:
    """a * b mod poly over GF(2); a and b have degree < n."""
    result = 0
    top = 1 << n
    while b:
        if b & 1:
            result ^= a
        b >>= 1
        a <<= 1
        if a & top:
            a ^= poly
    return result


def _powmod_x(e: int, poly: int, n: int) -> int:
    """x^e mod poly over GF(2)."""
    result = 1
    base = 2 if n > 1 else 2 ^ poly  # x reduced mod poly
    while e:
        if e & 1:
            result = _mulmod(result, base, poly, n)
        base = _mulmod(base, base, poly, n)
        e >>= 1
    return result


def prime_factors(m: int) -> list[int]:
    """Distinct prime factors of m by trial division (m < 2^32 here: fast)."""
    factors = []
    d = 2
    while d * d <= m:
        if m % d == 0:
            factors.append(d)
            while m % d == 0:
                m //= d
        d += 1 if d == 2 else 2
    if m > 1:
        factors.append(m)
    return factors


def order_of_x(poly: int) -> int:
    """Multiplicative order of x modulo poly, for poly with constant term 1.

    Computed as the smallest divisor d of 2^n - 1 with x^d = 1 if such a divisor
    exists; returns 0 when x^(2^n - 1) != 1 (poly is then not even square-free
    irreducible), so callers can compare the result with 2^n - 1.
    """
    n = poly.bit_length() - 1
    if n < 1 or not poly & 1:
        return 0
    period = (1 << n) - 1
    if _powmod_x(period, poly, n) != 1:
        return 0
    order = period
    for q in prime_factors(period):
        while order % q == 0 and _powmod_x(order // q, poly, n) == 1:
            order //= q
    return order


def is_primitive(poly: int) -> bool:
    """True when poly (degree n) is primitive: x has order 2^n - 1 modulo poly."""
    n = poly.bit_length() - 1
    return n >= 1 and order_of_x(poly) == (1 << n) - 1


def normalize_taps(taps: Iterable[int]) -> tuple[int, ...]:
    """Sorted (largest first), de-duplicated, validated feedback set."""
    try:
        values = sorted({int(t) for t in taps}, reverse=True)
    except (TypeError, ValueError):
        raise TapsError(f"taps must be integers, got {taps!r}") from None
    if not values:
        raise TapsError("taps must not be empty")
    if values[-1] < 1:
        raise TapsError(f"taps must be positive, got {values}")
    return tuple(values)


def check_taps(n: int, taps: Iterable[int] | None = None) -> tuple[int, ...]:
    """Validated feedback set for an N-bit LFSR; the default one when taps is None.

    Raises TapsError when the set's largest tap is not N or the characteristic
    polynomial is not primitive (the sequence would not visit every state).
    """
    n = check_bits(n)
    if taps is None:
        return DEFAULT_TAPS[n]
    values = normalize_taps(taps)
    if values[0] != n:
        raise TapsError(f"taps {list(values)}: the largest tap must equal N = {n}")
    if len(values) < 2:
        raise TapsError(f"taps {list(values)}: need at least two taps")
    poly = polynomial(values)
    if not is_primitive(poly):
        raise TapsError(
            f"taps {list(values)} are not primitive: {poly_str(poly)} has x of order "
            f"{order_of_x(poly)}, not {2**n - 1}; the sequence would not be maximal-length"
        )
    return values


def taps_mask(taps: Iterable[int]) -> int:
    """The RTL's TAPS parameter: bit t-1 set for each tap t."""
    mask = 0
    for t in taps:
        mask |= 1 << (t - 1)
    return mask


def find_default_taps(n: int) -> tuple[int, ...]:
    """Search rule behind DEFAULT_TAPS (kept so the table can be regenerated)."""
    for t in range(1, n):
        if is_primitive(polynomial((n, t))):
            return (n, t)
    # No primitive trinomial: the smallest pentanomial, then heptanomial.
    for k in (3, 5):
        best = _smallest_taps(n, k)
        if best:
            return best
    raise TapsError(f"no primitive trinomial, pentanomial or heptanomial for N = {n}")


def _smallest_taps(n: int, k: int) -> tuple[int, ...] | None:
    """Smallest (as a sorted-ascending tuple) set of k taps below n that is primitive."""
    from itertools import combinations

    for combo in combinations(range(1, n), k):
        taps = (n,) + tuple(sorted(combo, reverse=True))
        if is_primitive(polynomial(taps)):
            return taps
    return None


@lru_cache(maxsize=16)
def _msequence_cached(n: int, taps: tuple[int, ...]) -> np.ndarray:
    seq = _msequence(n, taps)
    seq.setflags(write=False)
    return seq


def msequence(n: int, taps: Iterable[int] | None = None) -> np.ndarray:
    """The maximal-length sequence s(0 .. 2^N - 2) from the seed 1, 0, ..., 0.

    Returns a read-only uint8 array. Built with numpy in O(2^N) work: the
    sequence is annihilated by P(x), hence by P(x)^(2^j) = P(x^(2^j)), so
    s(k) = XOR over t of s(k - t * 2^j) also holds, which fills blocks of
    min(T) * 2^j elements at once instead of one bit per Python step.
    """
    n = check_bits(n)
    return _msequence_cached(n, check_taps(n, taps))


def _msequence(n: int, taps: tuple[int, ...]) -> np.ndarray:
    length = (1 << n) - 1
    seq = np.zeros(length, dtype=np.uint8)
    seq[0] = 1
    tmax, tmin = max(taps), min(taps)
    filled = n
    while filled < length:
        j = 0
        while (tmax << (j + 1)) <= filled:
            j += 1
        block = min(tmin << j, length - filled)
        acc = np.zeros(block, dtype=np.uint8)
        for t in taps:
            start = filled - (t << j)
            acc ^= seq[start : start + block]
        seq[filled : filled + block] = acc
        filled += block
    return seq


class Lfsr:
    """A Fibonacci LFSR stepped one bit at a time (any N in 2..32).

    `state` holds the last N bits as a window value, s(k - N) in the MSB, matching
    the datasheet's window values. Iterating yields the sequence from s(0).
    """

    def __init__(self, n: int, taps: Iterable[int] | None = None, seed: int | None = None):
        self.n = check_bits(n)
        self.taps = check_taps(self.n, taps)
        self.mask = (1 << self.n) - 1
        self.state = (1 << (self.n - 1)) if seed is None else int(seed) & self.mask
        if self.state == 0:
            raise ValueError("an LFSR seed must not be all zeros")

    def next_bit(self) -> int:
        """Advance one step and return the new bit s(k)."""
        bit = 0
        for t in self.taps:
            bit ^= (self.state >> (t - 1)) & 1
        self.state = ((self.state << 1) & self.mask) | bit
        return bit

    def __iter__(self) -> Iterator[int]:
        # The seed bits come first, then the recurrence.
        for i in range(self.n - 1, -1, -1):
            yield (self.state >> i) & 1
        while True:
            yield self.next_bit()
