# SPDX-License-Identifier: Apache-2.0
"""The disc code: de Bruijn completion, indexing, windows and next-bit laws."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from prenc.codes.debruijn import Code
from prenc.codes.lfsr import DEFAULT_TAPS, MIN_BITS, is_primitive, polynomial

SMALL_N = range(MIN_BITS, 17)


def codes_with_any_primitive_taps():
    """Hypothesis strategy: a Code for N in 3..14 with a random primitive feedback set."""

    def build(n_and_lower):
        n, lower = n_and_lower
        return (n,) + tuple(sorted(lower, reverse=True))

    taps = st.integers(min_value=3, max_value=14).flatmap(
        lambda n: st.tuples(st.just(n), st.sets(st.integers(1, n - 1), min_size=1, max_size=4))
    ).map(build).filter(lambda t: is_primitive(polynomial(t)))
    return taps.map(lambda t: Code(max(t), t))


def test_datasheet_values_for_the_default_disc():
    code = Code(10, (10, 3))
    assert code.length == 1024
    assert code.window(0) == 512 and code.window(1) == 0 and code.window(2) == 1
    assert code.sequence[:12].tolist() == [1] + [0] * 10 + [1]
    # forward law as printed: s(p+10) = s(p) ^ s(p+7) ^ [s(p+1..p+9) all zero]
    s = code.sequence.astype(int)
    L = code.length
    for p in range(L):
        corr = int(all(s[(p + i) % L] == 0 for i in range(1, 10)))
        assert s[(p + 10) % L] == s[p] ^ s[(p + 7) % L] ^ corr
        corr = int(all(s[(p + i) % L] == 0 for i in range(0, 9)))
        assert s[(p - 1) % L] == s[(p + 9) % L] ^ s[(p + 6) % L] ^ corr


@pytest.mark.parametrize("n", SMALL_N)
def test_every_window_appears_exactly_once(n):
    code = Code(n)
    assert np.array_equal(np.sort(code.windows), np.arange(2**n))


@pytest.mark.parametrize("n", SMALL_N)
def test_laws_agree_with_the_sequence_everywhere(n):
    code = Code(n)
    w = code.windows.astype(np.int64)
    s = code.sequence.astype(np.int64)
    assert np.array_equal(code.forward_bit(w), np.roll(s, -n))
    assert np.array_equal(code.inverse_bit(w), np.roll(s, 1))
    assert np.array_equal(code.step_forward(w), np.roll(w, -1))
    assert np.array_equal(code.step_inverse(w), np.roll(w, 1))


@pytest.mark.parametrize("n", SMALL_N)
def test_inverse_undoes_forward_on_every_word(n):
    code = Code(n)
    words = np.arange(2**n, dtype=np.int64)
    assert np.array_equal(code.step_inverse(code.step_forward(words)), words)
    assert np.array_equal(code.step_forward(code.step_inverse(words)), words)


@pytest.mark.parametrize("n", SMALL_N)
def test_position_table_is_a_bijection_inverse_to_windows(n):
    code = Code(n)
    assert np.array_equal(np.sort(code.positions), np.arange(2**n))
    assert np.array_equal(code.positions[code.windows], np.arange(2**n))


@settings(max_examples=30, deadline=None)
@given(codes_with_any_primitive_taps())
def test_properties_hold_for_any_primitive_feedback_set(code):
    n = code.n
    w = code.windows.astype(np.int64)
    assert code.window(0) == 1 << (n - 1) and code.window(1) == 0 and code.window(2) == 1
    assert len(np.unique(w)) == 2**n
    assert np.array_equal(code.step_forward(w), np.roll(w, -1))
    assert np.array_equal(code.step_inverse(w), np.roll(w, 1))
    assert np.array_equal(code.positions[w], np.arange(2**n))


@settings(max_examples=200, deadline=None)
@given(st.integers(0, 2**10 - 1))
def test_scalar_and_vector_laws_agree(word):
    code = Code(10)
    vec = np.array([word], dtype=np.int64)
    assert code.step_forward(word) == int(code.step_forward(vec)[0])
    assert code.step_inverse(word) == int(code.step_inverse(vec)[0])


@pytest.mark.parametrize("n", [20, 24])
def test_large_codes_are_de_bruijn(n):
    code = Code(n)
    assert code.taps == DEFAULT_TAPS[n]
    counts = np.bincount(code.windows, minlength=2**n)
    assert counts.min() == 1 and counts.max() == 1
