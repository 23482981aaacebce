# SPDX-License-Identifier: Apache-2.0
"""prenc.board.turns against the truth: turns across the zero crossing both ways, through
stretches without a valid position, and after missed quadrature states."""

from __future__ import annotations

import pytest

from prenc.board.turns import Turns, random_walk


@pytest.mark.parametrize("seed", range(4))
def test_turns_follow_the_truth(seed):
    pos_bits, turn_bits = 8, 6
    m = Turns(pos_bits, turn_bits)
    m.clock(0, False, 0, rst=True)
    origin = None
    crossings = 0
    last_turn = None
    for q, count, valid in random_walk(seed, 60_000, pos_bits):
        m.clock(q % (1 << pos_bits), valid, count)
        if valid and origin is None:
            origin = q >> pos_bits
        if valid:
            want = (q - (origin << pos_bits)) % (1 << (pos_bits + turn_bits))
            assert m.full == want, (q, m.full, want)
            if last_turn is not None and m.turns != last_turn:
                crossings += 1
            last_turn = m.turns
    assert crossings >= 10, crossings  # the walk crossed zero many times


def test_turns_count_down_through_zero_and_wrap():
    m = Turns(4, 3)
    m.clock(0, False, 0, rst=True)
    m.clock(2, True, 0)                      # placed: turn 0, position 2
    for p in (1, 0, 15, 14):                 # CCW through zero
        m.clock(p, True, 0)
    assert (m.turns, m.full & 15) == (7, 14)  # turn -1, modulo 2^3
    for c in range(1, 6):                    # lost: the count moves 5 quarters CW
        m.clock(0, False, c)
    m.clock(3, True, 5)                      # valid again at 3: the turn after zero
    assert (m.turns, m.full & 15) == (0, 3)


def test_bad_parameters_are_refused():
    with pytest.raises(ValueError, match="pos_bits"):
        Turns(1, 4)
    with pytest.raises(ValueError, match="turn_bits"):
        Turns(8, 0)
