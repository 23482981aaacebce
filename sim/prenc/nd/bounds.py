# SPDX-License-Identifier: Apache-2.0
"""Sound upper bounds on the length K of an (n,d)-sequence.

The K windows of an (n,d)-sequence are K distinct words of length n with pairwise
distance >= d: a binary code. So K <= A(n,d), the largest size of such a code, and
every upper bound on A(n,d) bounds K:

- d = 1: K <= 2^n (met by de Bruijn sequences);
- d = 2: K <= 2^(n-1): two words that differ only in the last bit are at distance 1,
  so the (n-1)-bit prefixes of the windows are all distinct;
- odd d = 2t+1: the sphere-packing (Hamming) bound, K <= 2^n / sum_{i<=t} C(n, i);
- even d: A(n,d) = A(n-1,d-1) (puncture one coordinate), then the bound for d-1;
- when 2d > n, Plotkin's bound: A(n,d) <= 2 floor(d / (2d - n)) for even d, and
  A(n,d) = A(n+1,d+1) for odd d.

The smallest of these that applies is returned with its name. These bounds ignore
that the windows overlap, so they are far above the lengths reached for d >= 2;
exact values come from the exhaustive search.
"""

from __future__ import annotations

from math import comb


def _plotkin_even(n: int, d: int) -> int | None:
    if 2 * d > n:
        return 2 * (d // (2 * d - n))
    if 2 * d == n:
        return 4 * d
    return None


def upper_bound(n: int, d: int) -> tuple[int, str]:
    """(bound, name of the argument) for the length of an (n,d)-sequence."""
    if d <= 1:
        return 1 << n, "2^n windows"
    if d > n:
        return 1, "no two n-bit words differ in more than n bits"
    if d == 2:
        candidates = [((1 << (n - 1)), "distinct (n-1)-bit prefixes")]
    else:
        m, e = (n, d) if d % 2 else (n - 1, d - 1)
        t = (e - 1) // 2
        ball = sum(comb(m, i) for i in range(t + 1))
        candidates = [((1 << m) // ball, "sphere-packing (Hamming)")]
    even_n, even_d = (n, d) if d % 2 == 0 else (n + 1, d + 1)
    plotkin = _plotkin_even(even_n, even_d)
    if plotkin is not None:
        candidates.append((plotkin, "Plotkin"))
    return min(candidates)
