# SPDX-License-Identifier: Apache-2.0
"""prenc_uvw (with prenc_step_tracker) against its model, prenc.board.abi.Uvw, clock for
clock, and against the electrical angle.

The position (B = 16) moves as in tb/board/prenc_abi (speeds both ways, stops,
reversals, dropouts of `valid`); UVWPP and HYS change now and then (with POLE_PAIRS = 7,
UVWPP is ignored). Every clock U, V
and W equal the model's; they are 000 while the position is not valid, and whenever
the sectors have caught up with the position they are the Hall pattern of the
electrical angle P x position (prenc.board.abi.UVW_PATTERN), within one sector of it for
the hysteresis; they never take 111, and a change of pattern is one sector (one signal
toggles).
"""

from __future__ import annotations

import cocotb
import pytest
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge

from common import rng, start_clock_and_reset
from prenc.board import abi as spec
from runner import SIMULATORS, run
from test_prenc_abi import BITS, TURN, motion

TOPLEVEL = "prenc_uvw"


@cocotb.test()
async def equals_its_model_and_the_electrical_angle(dut):
    r = rng()
    settings2 = 0x03 << 0   # 4 pole pairs, HYS 0
    dut.position.value = 0
    dut.valid.value = 0
    dut.settings2.value = settings2
    await start_clock_and_reset(dut, 3)
    fixed = int(dut.POLE_PAIRS.value)   # 0: UVWPP chooses
    model = spec.Uvw(BITS, fixed)
    checked, last, changed = 0, (0, 0, 0), -10
    seen = [0, 0]   # the positions 2 clocks and 1 before: caught_up is of the first
    for clock, (position, valid) in enumerate(motion(r, 60_000)):
        if r.random() < 0.0002:
            settings2 = r.randrange(256)
            changed = clock   # the new P counts 2 clocks later
        dut.position.value = position
        dut.valid.value = int(valid)
        dut.settings2.value = settings2
        pairs = spec.pole_pairs(settings2, fixed)
        _, _, caught_up = model.tracker.decide()   # of the position 2 clocks before
        expected = model.clock(position, valid, settings2)
        await RisingEdge(dut.clk)
        await ReadOnly()
        got = (int(dut.u.value), int(dut.v.value), int(dut.w.value))
        assert got == expected, (clock, got, expected)
        assert got != (1, 1, 1)
        if not valid:
            assert got == (0, 0, 0)
        if got != (0, 0, 0) and last != (0, 0, 0):
            assert sum(x != y for x, y in zip(got, last)) <= 1, (clock, last, got)
        if caught_up and model.placed and got != (0, 0, 0) and clock > changed + 3:
            sector = seen[0] * 6 * pairs // TURN % 6
            near = {spec.UVW_PATTERN[(sector + d) % 6] for d in (-1, 0, 1)}
            assert got in near, (clock, got, sector)
            checked += 1
        last = got
        seen = [seen[1], position]
        await FallingEdge(dut.clk)
    assert checked > 2_000, checked
    dut._log.info("%d clocks checked against the electrical angle", checked)


@pytest.mark.parametrize("pole_pairs", [0, 7])
@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_uvw(simulator, pole_pairs):
    run(__file__, TOPLEVEL, simulator, parameters={"B": BITS, "POLE_PAIRS": pole_pairs})
