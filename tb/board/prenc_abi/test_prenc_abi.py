# SPDX-License-Identifier: Apache-2.0
"""prenc_abi (with prenc_step_tracker) against its model, prenc.board.abi.Abi, clock for
clock, and against the definition of its outputs.

A position (B = 16) moves as a disc does: steady speeds both ways, stops, reversals,
bursts faster than MIN_GAP lets the outputs follow, dropouts of `valid` after which it
reappears elsewhere; the settings change now and then (ABIRES, ABIBIN, HYS). Every clock
A, B and I equal the model's. A quadrature counter reads A and B from reset, as a drive
does: whenever the outputs have caught up, it equals the step the position is in
(floor(position x S / 2^B), modulo S, within one step for the hysteresis), and I is high
exactly when it is 0 (mod S); it never sees two steps in one clock, nor an illegal
transition, and steps are MIN_GAP clocks apart at least.
"""

from __future__ import annotations

import cocotb
import pytest
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge

from common import rng, start_clock_and_reset
from prenc.board import abi as spec
from runner import SIMULATORS, run

TOPLEVEL = "prenc_abi"
BITS, MIN_GAP = 16, 3
TURN = 1 << BITS


def motion(r, clocks: int):
    """(position, valid) per clock."""
    pos, speed, valid = TURN - 1500.0, 2.0, False   # it passes the zero in the first 1,000 clocks
    for k in range(clocks):
        if k > 3_000 and r.random() < 0.002:
            speed = r.choice((0.0, r.uniform(-40, 40), r.uniform(-400, 400), -speed))
        if k > 3_000 and r.random() < 0.0005:
            valid = not valid
            if not valid:
                pos = r.randrange(TURN)   # it comes back elsewhere
        if k == 300:
            valid = True
        pos = (pos + speed) % TURN
        yield int(pos), valid


class Counter:
    """A drive's quadrature counter on A and B."""

    STATES = {(0, 0): 0, (1, 0): 1, (1, 1): 2, (0, 1): 3}

    def __init__(self):
        self.count, self.state, self.last_step = 0, 0, -10**9

    def see(self, a: int, b: int, clock: int) -> int:
        state = self.STATES[(a, b)]
        delta = (state - self.state) % 4
        assert delta != 2, f"illegal transition at clock {clock}"
        if delta:
            assert clock - self.last_step >= MIN_GAP, f"steps {clock - self.last_step} clocks apart at {clock}"
            self.last_step = clock
            self.count += 1 if delta == 1 else -1
        self.state = state
        return delta


@cocotb.test()
async def equals_its_model_and_its_definition(dut):
    r = rng()
    settings1, settings2 = 0x01, 0x00
    dut.position.value = 0
    dut.valid.value = 0
    dut.settings1.value = settings1
    dut.settings2.value = settings2
    await start_clock_and_reset(dut, 3)
    model, counter = spec.Abi(BITS, min_gap=MIN_GAP), Counter()
    checked = indexes = 0
    recount = 0   # a new resolution restarts the outputs at 00: the drive starts counting again
    seen = [0, 0]   # the positions 2 clocks and 1 before: caught_up is of the first
    for clock, (position, valid) in enumerate(motion(r, 60_000)):
        if r.random() < 0.0002:
            old = spec.abi_steps(settings1, settings2)
            settings1 = r.choice((0x01, 0x01 | spec.ABIBIN))
            settings2 = r.randrange(256)
            if spec.abi_steps(settings1, settings2) != old:
                recount = 2
        dut.position.value = position
        dut.valid.value = int(valid)
        dut.settings1.value = settings1
        dut.settings2.value = settings2
        _, _, caught_up = model.tracker.decide()   # of the position 2 clocks before
        expected = model.clock(position, valid, settings1, settings2)
        await RisingEdge(dut.clk)
        await ReadOnly()
        got = (int(dut.a.value), int(dut.b.value), int(dut.i.value))
        assert got == expected, (clock, got, expected)
        if recount:
            recount -= 1
            if recount == 0:
                assert got == (0, 0, 0), (clock, got)
                counter = Counter()
            seen = [seen[1], position]
            await FallingEdge(dut.clk)
            continue
        counter.see(got[0], got[1], clock)
        steps = spec.abi_steps(settings1, settings2)
        if caught_up and model.placed and model.tracker.wait_left == 0:
            truth = seen[0] * steps // TURN
            off = (counter.count - truth + steps // 2) % steps - steps // 2
            assert abs(off) <= 1, (clock, counter.count % steps, truth)
            checked += 1
            indexes += got[2]
        if got[2]:
            assert counter.count % steps == 0, (clock, counter.count)
        seen = [seen[1], position]
        await FallingEdge(dut.clk)
    assert checked > 2_000 and indexes > 0, (checked, indexes)
    dut._log.info("%d clocks checked against the position, %d with the index", checked, indexes)


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_abi(simulator):
    run(__file__, TOPLEVEL, simulator, parameters={"B": BITS, "MIN_GAP": MIN_GAP})
