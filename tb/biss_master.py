# SPDX-License-Identifier: Apache-2.0
"""A BiSS-C master at the pins, for testbenches (the protocol is in prenc.board.biss).

It clocks MA at a chosen rate, asynchronous to the design clock, records every
change of SLO, and decodes the frame as a master with line-delay compensation
does: it finds the Ack and the start bit, measures how long after its rising edge
the start bit came, and samples every later bit that long after its own rising
edge, half a period in. Rates are in Hz of a design clock of `clk_hz`; simulation
time runs at common.PERIOD_NS per design clock.
"""

from __future__ import annotations

import cocotb
from cocotb.triggers import Edge, Timer
from cocotb.utils import get_sim_time

from common import PERIOD_NS
from prenc.board import biss


class Master:
    def __init__(self, dut, rate_hz: float, clk_hz: float, ma: str = "ma", slo: str = "slo",
                 timeout_clocks: int | None = None):
        self.ma = getattr(dut, ma)
        self.slo = getattr(dut, slo)
        self.clk_hz = clk_hz
        self.half_ps = round(clk_hz / rate_hz / 2 * PERIOD_NS * 1000)
        self.period_ns = 2 * self.half_ps / 1000
        self.timeout_clocks = timeout_clocks if timeout_clocks is not None else round(20e-6 * clk_hz)
        self.edges: list[tuple[float, int]] = []
        self.ma.value = 1
        cocotb.start_soon(self._watch())

    async def _watch(self) -> None:
        while True:
            await Edge(self.slo)
            self.edges.append((get_sim_time("ns"), int(self.slo.value)))

    async def pulses(self, count: int, on_start=None) -> list[float]:
        """`count` MA pulses (a falling, then a rising edge); MA is left high. Returns
        the times of the rising edges."""
        rises = []
        for k in range(count):
            self.ma.value = 0
            if k == 0 and on_start:
                on_start()
            await Timer(self.half_ps, unit="ps")
            self.ma.value = 1
            rises.append(get_sim_time("ns"))
            await Timer(self.half_ps, unit="ps")
        return rises

    async def read(self, mt_bits: int, st_bits: int, on_start=None) -> tuple[biss.Reading, float]:
        """One frame: the reading and the measured line delay in ns."""
        self.edges.clear()
        count = len(biss.frame_bits(0, 0, mt_bits, st_bits, False, False))
        rises = await self.pulses(biss.clock_pulses(mt_bits, st_bits), on_start)
        bits, delay = biss.sample(rises, list(self.edges), self.period_ns, count)
        return biss.decode(bits, mt_bits, st_bits), delay

    def timeout_ns(self, margin_clocks: int = 16) -> float:
        """How long after a frame the slave is ready again (its timeout and a margin)."""
        return (self.timeout_clocks + margin_clocks) * PERIOD_NS
