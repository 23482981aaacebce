# SPDX-License-Identifier: Apache-2.0
"""LFSR sequences and feedback sets: primitivity is computed, never assumed."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from prenc.codes.lfsr import (
    DEFAULT_TAPS,
    MAX_BITS,
    MIN_BITS,
    Lfsr,
    TapsError,
    check_taps,
    find_default_taps,
    is_primitive,
    msequence,
    order_of_x,
    polynomial,
    poly_str,
    prime_factors,
)


def brute_force_period(taps: tuple[int, ...]) -> int:
    """Period of the LFSR state from the seed 1 0 ... 0, by stepping."""
    n = max(taps)
    mask = (1 << n) - 1
    start = state = 1 << (n - 1)
    for k in range(1, 1 << n):
        bit = 0
        for t in taps:
            bit ^= (state >> (t - 1)) & 1
        state = ((state << 1) & mask) | bit
        if state == start:
            return k
    return 0


def test_polynomial_of_the_default_disc():
    assert polynomial((10, 3)) == (1 << 10) | (1 << 7) | 1
    assert poly_str(polynomial((10, 3))) == "x^10 + x^7 + 1"


@pytest.mark.parametrize("n", range(MIN_BITS, MAX_BITS + 1))
def test_every_default_feedback_set_is_primitive(n):
    """The order of x modulo P(x) is 2^N - 1, computed here for every default set."""
    taps = DEFAULT_TAPS[n]
    assert max(taps) == n
    assert order_of_x(polynomial(taps)) == 2**n - 1


def test_default_table_is_what_the_search_rule_finds():
    for n in range(MIN_BITS, MAX_BITS + 1):
        assert find_default_taps(n) == DEFAULT_TAPS[n], n


def test_default_for_ten_bits_is_the_datasheet_disc():
    assert DEFAULT_TAPS[10] == (10, 3)


@pytest.mark.parametrize("n", range(2, 15))
def test_order_agrees_with_brute_force_for_all_trinomials(n):
    """is_primitive against stepping the register, for every trinomial of small N."""
    for t in range(1, n):
        taps = (n, t)
        assert is_primitive(polynomial(taps)) == (brute_force_period(taps) == 2**n - 1), taps


@pytest.mark.parametrize(
    "taps",
    [
        (8, 4),  # x^8 + x^4 + 1 = (x^2 + x + 1)^4: reducible
        (10, 5),
        (16, 8),
        (4, 2),
        (6, 3),
        (32, 16),
        (12, 3),  # x^12 + x^9 + 1: no trinomial of degree 12 is primitive
    ],
)
def test_non_primitive_taps_are_refused_with_a_clear_error(taps):
    with pytest.raises(TapsError, match="not primitive"):
        check_taps(max(taps), taps)


def test_reducible_but_full_order_candidates_are_told_apart():
    # x^6 + x^3 + 1 is irreducible but not primitive: x has order 9, not 63.
    assert order_of_x(polynomial((6, 3))) == 9
    assert not is_primitive(polynomial((6, 3)))


def test_taps_must_start_with_n():
    with pytest.raises(TapsError, match="largest tap must equal N"):
        check_taps(10, (9, 4))
    with pytest.raises(TapsError, match="at least two"):
        check_taps(10, (10,))
    with pytest.raises(ValueError, match="out of range"):
        check_taps(33, None)


def test_prime_factors():
    assert prime_factors(2**32 - 1) == [3, 5, 17, 257, 65537]
    assert prime_factors(1023) == [3, 11, 31]
    assert prime_factors(2**31 - 1) == [2**31 - 1]


@pytest.mark.parametrize("n", range(MIN_BITS, 17))
def test_msequence_is_maximal_and_matches_the_stepped_register(n):
    seq = msequence(n)
    assert len(seq) == 2**n - 1
    assert list(seq[:n]) == [1] + [0] * (n - 1)
    stepped = np.fromiter(
        (bit for _, bit in zip(range(len(seq)), iter(Lfsr(n)))), dtype=np.uint8, count=len(seq)
    )
    assert np.array_equal(seq, stepped)
    # Maximal length: 2^(N-1) ones, and every nonzero N-bit state exactly once.
    assert int(seq.sum()) == 2 ** (n - 1)


@settings(max_examples=40, deadline=None)
@given(st.integers(min_value=3, max_value=14).flatmap(
    lambda n: st.tuples(st.just(n), st.sets(st.integers(1, n - 1), min_size=1, max_size=4))
))
def test_fast_sequence_equals_the_recurrence_for_any_primitive_set(case):
    """The block-doubling generator against the plain recurrence, for random sets."""
    n, lower = case
    taps = (n,) + tuple(sorted(lower, reverse=True))
    if not is_primitive(polynomial(taps)):
        with pytest.raises(TapsError):
            msequence(n, taps)
        return
    seq = msequence(n, taps)
    ref = [1] + [0] * (n - 1)
    for k in range(n, 2**n - 1):
        bit = 0
        for t in taps:
            bit ^= ref[k - t]
        ref.append(bit)
    assert seq.tolist() == ref
