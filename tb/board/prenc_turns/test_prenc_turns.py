# SPDX-License-Identifier: Apache-2.0
"""prenc_turns: the multi-turn position, clock by clock against the model
(prenc.board.turns), and against the truth of a random walk that crosses zero both ways,
loses the position in stretches and misses quadrature states."""

from __future__ import annotations

import cocotb
import pytest

from common import clock_and_check, rng, start_clock_and_reset
from prenc.board.turns import Turns, random_walk
from runner import SIMULATORS, run

TOPLEVEL = "prenc_turns"


@cocotb.test()
async def turns_follow_the_model_and_the_truth(dut):
    pos_bits, turn_bits = int(dut.POS_BITS.value), int(dut.TURN_BITS.value)
    model = Turns(pos_bits, turn_bits)
    model.clock(0, False, 0, rst=True)
    await start_clock_and_reset(dut, 3, {"position": 0, "valid": 0, "count": 0})
    origin, crossings, last = None, 0, None
    mask = (1 << pos_bits) - 1
    for t, (q, count, valid) in enumerate(random_walk(rng().randrange(1 << 30), 40_000, pos_bits)):
        model.clock(q & mask, valid, count)
        await clock_and_check(dut, {"position": q & mask, "valid": int(valid), "count": count & mask},
                              {"full": model.full, "turns": model.turns, "placed": int(model.placed)},
                              lambda: f"clock {t}")
        if valid:
            origin = (q >> pos_bits) if origin is None else origin
            assert model.full == (q - (origin << pos_bits)) % (1 << (pos_bits + turn_bits)), t
            crossings += last is not None and model.turns != last
            last = model.turns
    assert crossings >= 8, crossings
    dut._log.info("40,000 clocks, %d zero crossings while valid", crossings)


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_turns(simulator):
    run(__file__, TOPLEVEL, simulator, parameters={"POS_BITS": 8, "TURN_BITS": 5})
