# SPDX-License-Identifier: Apache-2.0
"""cocotb helpers shared by the testbenches: clock, reset, clocked drive-and-check.

Timing convention of every testbench: inputs change just after a falling edge,
outputs are read in the ReadOnly phase after the next rising edge, and a model's
`clock(inputs)` returns what the registers hold after that edge.
"""

from __future__ import annotations

import random
from typing import Callable, Mapping, Sequence

import cocotb
from cocotb.clock import Clock
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge, Timer

PERIOD_NS = 10


def rng() -> random.Random:
    """A generator seeded from COCOTB_RANDOM_SEED (cocotb prints it on failure)."""
    return random.Random(cocotb.RANDOM_SEED)


async def start_clock_and_reset(dut, reset_clocks: int = 3, inputs: Mapping[str, int] | None = None) -> None:
    """Start clk, hold rst for reset_clocks rising edges with inputs set; return after
    the falling edge where rst goes low."""
    for name, value in (inputs or {}).items():
        getattr(dut, name).value = value
    dut.rst.value = 1
    cocotb.start_soon(Clock(dut.clk, PERIOD_NS, unit="ns").start())
    for _ in range(reset_clocks):
        await RisingEdge(dut.clk)
    await FallingEdge(dut.clk)
    dut.rst.value = 0


async def clock_and_check(dut, inputs: Mapping[str, int], expected: Mapping[str, int] | None,
                          context: Callable[[], str] = lambda: "") -> None:
    """Drive inputs, take one rising edge, compare outputs with `expected`, return at
    the following falling edge."""
    for name, value in inputs.items():
        getattr(dut, name).value = value
    await RisingEdge(dut.clk)
    await ReadOnly()
    if expected:
        got = {name: int(getattr(dut, name).value) for name in expected}
        if got != dict(expected):
            diff = {k: (got[k], v) for k, v in expected.items() if got[k] != v}
            raise AssertionError(f"{context()} (got, expected): {diff}")
    await FallingEdge(dut.clk)


async def drive_events(dut, pins: Sequence[str], events, clocks_total: int) -> None:
    """Drive an event stream [(clock, v0, v1, ...)] onto `pins`, one value per pin,
    changing them just after the falling edge that ends clock `clock - 1`. Waits with
    Timer between events, so long quiet stretches cost no Python per clock.
    Starts and ends at a falling edge."""
    now = 0
    for clock, *values in events:
        if clock > now:
            await Timer((clock - now) * PERIOD_NS, unit="ns")
            now = clock
        for pin, value in zip(pins, values):
            getattr(dut, pin).value = value
    if clocks_total > now:
        await Timer((clocks_total - now) * PERIOD_NS, unit="ns")


def to_int_x_as_zero(value) -> int:
    """An RTL value as an int, with X/Z bits as 0: for bits the test masks out."""
    return int("".join(c if c in "01" else "0" for c in str(value)), 2)
