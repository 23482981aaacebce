# SPDX-License-Identifier: Apache-2.0
"""prenc_tracker's gain table (prenc.fine.tracker_gains): its indexing, its encoding
against the Kalman recursion it holds, and `prenc gains`."""

from __future__ import annotations

import math

import pytest

from prenc.cli.main import main
from prenc.fine import tracker_gains as tg


def test_every_age_has_a_bin_and_a_bin_holds_an_age_of_its_own():
    bins = [tg.age_bin(a) for a in range(tg.AGE_MAX + 1)]
    assert bins == sorted(bins) and set(bins) == set(range(tg.BINS))
    for b in range(tg.BINS):
        assert tg.age_bin(tg.bin_age(b)) == b


def test_the_column_is_two_an_octave_and_clamped():
    for col in range(1, tg.COLUMNS - 1):
        v = tg.column_speed(col)
        assert tg.column(int(v * 2 ** 40)) == col
    assert tg.column(0) == 0 and tg.column(1) == 0
    assert tg.column((1 << 41) - 1) == tg.COLUMNS - 1


@pytest.mark.parametrize("gain, unit", [(1.0, 40), (3.7e-7, 40), (1.2e-9, 40), (6.9e-6, 60), (0.95, 8)])
def test_a_field_holds_its_gain_within_the_mantissa(gain, unit):
    field = tg.encode(gain, unit)
    assert field >> tg.FIELD_BITS == 0
    assert math.isclose(tg.decode(field, unit), gain, rel_tol=2 ** -tg.MANTISSA_BITS)


def test_the_table_holds_the_recursion_it_is_computed_from():
    n, clk, sigma = 10, 30e6, tg.SIGMA["printed"]
    words = tg.table(n, clk, sigma)
    assert len(words) == tg.COLUMNS * tg.BINS and all(w >> tg.WORD_BITS == 0 for w in words)
    col, b = 20, 30
    gain, spread = tg.recursion(tg.column_speed(col), sigma, n, clk)[tg.bin_age(b)]
    word = words[col * tg.BINS + b]
    fields = [(word >> (i * tg.FIELD_BITS)) & ((1 << tg.FIELD_BITS) - 1) for i in range(4)]
    expected = (gain[0], gain[1], gain[2], 1 / math.sqrt(spread))
    for field, unit, g in zip(fields, tg.UNITS, expected):
        assert math.isclose(tg.decode(field, unit), g, rel_tol=2 ** -tg.MANTISSA_BITS)


def test_prenc_gains_writes_the_table_and_rejects_bad_arguments(tmp_path, capsys):
    out = tmp_path / "gains.hex"
    assert main(["gains", "--bits", "10", "--clock", "30e6", "--disc", "printed", "-o", str(out)]) == 0
    assert tg.read(out) == tg.table(10, 30e6, tg.SIGMA["printed"])
    bad = tmp_path / "bad.hex"
    assert main(["gains", "--bits", "30", "--clock", "30e6", "-o", str(bad)]) == 1
    assert main(["gains", "--bits", "10", "--clock", "0", "-o", str(bad)]) == 1
    assert main(["gains", "--bits", "10", "--clock", "30e6", "--sigma", "-1", "-o", str(bad)]) == 1
    assert not bad.exists()
    assert capsys.readouterr().err.count("prenc gains: error:") == 3
