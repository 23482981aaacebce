# SPDX-License-Identifier: Apache-2.0
"""Benchmark probe (run by scripts/bench.py, not by pytest): maximum tracking rate.

For this build's FILTER, drive the sync pins with quadrature states that each last
exactly `dwell` clocks: 64 states CW, then 128 CCW, into prenc_core (its
conditioner and quadrature decoder). A dwell passes when the incremental count is +64
after the first leg and -64 after the second and no transition was counted illegal.
Sweeps dwell = 1 .. FILTER + 3 and writes the verdicts to $BENCH_OUT.
"""

from __future__ import annotations

import json
import os

import cocotb
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge

from common import drive_events, start_clock_and_reset

AB_OF_QUARTER = {0: (0, 1), 1: (0, 0), 2: (1, 0), 3: (1, 1)}  # datasheet


def signed(value: int, bits: int) -> int:
    return value - (1 << bits) if value >> (bits - 1) else value


async def leg(dut, start_q: int, states: int, direction: int, dwell: int) -> int:
    events = []
    for k in range(1, states + 1):
        a, b = AB_OF_QUARTER[(start_q + direction * k) % 4]
        events.append((k * dwell, a, b))
    await drive_events(dut, ["sync_a", "sync_b"], events, states * dwell + 8 + 2 * int(dut.FILTER.value))
    return (start_q + direction * states) % 4


@cocotb.test()
async def sweep_dwell(dut):
    filter_len = int(dut.FILTER.value)
    width = len(dut.incremental)
    verdicts = {}
    first = True
    for dwell in range(1, filter_len + 4):
        a, b = AB_OF_QUARTER[0]
        if first:
            await start_clock_and_reset(dut, 4, {"sync_a": a, "sync_b": b, "head1": 0, "head2": 0,
                                                 "clear_errors": 0, "resolution": 0})
            first = False
        else:
            dut.sync_a.value, dut.sync_b.value, dut.rst.value = a, b, 1
            for _ in range(6):
                await RisingEdge(dut.clk)
            await FallingEdge(dut.clk)
            dut.rst.value = 0
        q = await leg(dut, 0, 64, +1, dwell)
        await ReadOnly()
        forward = signed(int(dut.incremental.value), width)
        await FallingEdge(dut.clk)
        await leg(dut, q, 128, -1, dwell)
        await ReadOnly()
        backward = signed(int(dut.incremental.value), width)
        illegal = int(dut.sync_errors.value)
        verdicts[dwell] = {"forward": forward, "backward": backward, "illegal": illegal,
                           "ok": forward == 64 and backward == -64 and illegal == 0}
        await FallingEdge(dut.clk)
    with open(os.environ["BENCH_OUT"], "w") as f:
        json.dump({"filter": filter_len, "verdicts": verdicts}, f)
