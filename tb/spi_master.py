# SPDX-License-Identifier: Apache-2.0
"""An SPI master at the pins, in mode 1, for testbenches (the AS5047P's protocol is in
prenc.board.as5047; tb/as5047_drivers.py has the drives' masters built on this one).

One frame per CSn low, as a microcontroller sends it: CSn falls, `lead_ns` later SCLK
starts (idle low); MOSI changes on each rising edge; MISO is sampled `setup_ns` before
each falling edge (the slave's output delay and the master's setup time), or, for a
master that samples early (VESC's bit-banged SPI), `sample_after_rise_ns` after each
rising edge; `byte_gap_ns` of idle SCLK after each byte (a master sending bytes); half a
period after the last falling edge CSn rises and stays high `gap_ns`. Times are in ns
of the real board, whose clock is `clk_hz`; simulation time runs at common.PERIOD_NS per
design clock, so a real ns is scaled by that ratio.
"""

from __future__ import annotations

from cocotb.triggers import Timer
from cocotb.utils import get_sim_time

from common import PERIOD_NS


class SpiMaster:
    def __init__(self, dut, rate_hz: float, clk_hz: float, prefix: str = "spi_",
                 lead_ns: float = 400, setup_ns: float = 20, gap_ns: float = 400,
                 sample_after_rise_ns: float | None = None, byte_gap_ns: float = 0):
        self.csn = getattr(dut, prefix + "csn")
        self.sclk = getattr(dut, prefix + "sclk")
        self.mosi = getattr(dut, prefix + "mosi")
        self.miso = getattr(dut, prefix + "miso")
        self.ps_per_ns = clk_hz * PERIOD_NS / 1e6   # simulation ps per real ns
        self.rate_hz = rate_hz
        self.lead_ns, self.setup_ns, self.gap_ns = lead_ns, setup_ns, gap_ns
        self.sample_after_rise_ns = sample_after_rise_ns
        self.byte_gap_ns = byte_gap_ns
        self.csn.value = 1
        self.sclk.value = 0

    async def wait_ns(self, ns: float) -> None:
        ps = round(ns * self.ps_per_ns)
        if ps > 0:
            await Timer(ps, unit="ps")

    def _sample(self) -> int:
        miso = self.miso.value
        return int(miso) if miso.is_resolvable else 1

    async def frame(self, word: int, clocks: int = 16, on_open=None) -> int:
        """One frame that sends `word` (its last `clocks` bits, MSB first) and returns
        the `clocks` bits sampled on MISO. `on_open(time_ns)` is called as CSn falls,
        with the simulation time."""
        half = 0.5e9 / self.rate_hz
        early = self.sample_after_rise_ns
        self.csn.value = 0
        if on_open:
            on_open(get_sim_time("ns"))
        await self.wait_ns(self.lead_ns)
        answer = 0
        for k in range(clocks):
            self.sclk.value = 1
            self.mosi.value = (word >> (clocks - 1 - k)) & 1
            if early is None:
                await self.wait_ns(half - self.setup_ns)
                bit = self._sample()
                await self.wait_ns(self.setup_ns)
            else:
                await self.wait_ns(early)
                bit = self._sample()
                await self.wait_ns(half - early)
            answer = answer << 1 | bit
            self.sclk.value = 0
            await self.wait_ns(half)
            if self.byte_gap_ns and k % 8 == 7 and k < clocks - 1:
                await self.wait_ns(self.byte_gap_ns)
        self.csn.value = 1
        await self.wait_ns(self.gap_ns)
        return answer
