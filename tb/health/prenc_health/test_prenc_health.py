# SPDX-License-Identifier: Apache-2.0
"""prenc_health against its model, prenc.health.Health, clock for clock.

WARN_SLOTS = 8, WARN_BURST = 3, and 1, 1 (every correction warns). Random corrections
of the three sources, in phases: quiet travel, sparse corrections
(below one per WARN_SLOTS slots), dense ones, bursts at a stop, and resets. Every clock
the warnings equal the model's; every source both warns and stops warning.
"""

from __future__ import annotations

import cocotb
import pytest
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge

from common import rng, start_clock_and_reset
from prenc.health.health import Health
from runner import SIMULATORS, run

TOPLEVEL = "prenc_health"


@cocotb.test()
async def equals_its_model(dut):
    r = rng()
    for name in ("step", "track1_error", "track2_error", "sync_illegal"):
        getattr(dut, name).value = 0
    await start_clock_and_reset(dut, 3)
    model = Health(int(dut.WARN_SLOTS.value), int(dut.WARN_BURST.value))
    rose, fell, last = [0, 0, 0], [0, 0, 0], [0, 0, 0]
    step_p = event_p = 0.0
    for clock in range(60_000):
        if clock % 2_000 == 0:   # a new phase
            step_p = r.choice([0.0, 0.3, 1.0])
            event_p = r.choice([0.0, 0.001, 0.01, 0.05, 0.3])
        rst = int(r.random() < 0.0002)
        inputs = [int(r.random() < step_p)] + [int(r.random() < event_p) for _ in range(3)]
        for name, value in zip(("step", "track1_error", "track2_error", "sync_illegal"), inputs):
            getattr(dut, name).value = value
        dut.rst.value = rst
        model.clock(*inputs, rst=rst)
        await RisingEdge(dut.clk)
        await ReadOnly()
        got = [int(dut.warnings.value) >> k & 1 for k in range(3)]
        assert got == model.warnings, (clock, got, model.warnings, model.levels)
        assert int(dut.warning.value) == model.warning
        for k in range(3):
            rose[k] += got[k] and not last[k]
            fell[k] += last[k] and not got[k]
        last = got
        await FallingEdge(dut.clk)
    dut._log.info("warnings rose %s times, fell %s times", rose, fell)
    assert all(rose) and all(fell)


@pytest.mark.parametrize("slots, burst", [(8, 3), (1, 1)])
@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_health(simulator, slots, burst):
    run(__file__, TOPLEVEL, simulator, parameters={"WARN_SLOTS": slots, "WARN_BURST": burst})
