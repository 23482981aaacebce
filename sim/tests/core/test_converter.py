# SPDX-License-Identifier: Apache-2.0
"""The converter models: parallel (one clock) and serial (LFSR stepping)."""

from __future__ import annotations

import pytest

from prenc.core.converter import CONVERTER_LATENCY, Converter, SerialConverter
from prenc.codes.debruijn import Code


@pytest.mark.parametrize("n", [4, 6, 10])
def test_serial_and_parallel_agree_and_serial_worst_case_is_l_minus_1(n):
    code = Code(n)
    serial = SerialConverter(code)
    parallel = Converter(code)
    worst = 0
    for p in range(code.length):
        word = code.window(p)
        slot, clocks = serial.convert(word)
        out = parallel.clock(1, word)
        assert slot == p == out.pos and out.pos_valid == 1
        worst = max(worst, clocks)
    assert worst == serial.worst_case_clocks() == 2**n - 1
    assert CONVERTER_LATENCY == 1


def test_parallel_model_holds_its_output_while_idle():
    code = Code(6)
    conv = Converter(code)
    assert conv.clock(0, 0).pos_valid == 0
    out = conv.clock(1, code.window(17))
    assert out == (1, 17)
    assert conv.clock(0, code.window(3)) == (0, 17)
    conv.reset()
    assert conv.clock(0, 0).pos_valid == 0


def test_position_of_a_word_that_does_not_fit():
    with pytest.raises(ValueError, match="does not fit"):
        Code(4).position(16)
