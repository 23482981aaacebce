# SPDX-License-Identifier: Apache-2.0
"""UART at the pins, for testbenches: send bytes onto an input, receive from an output.

Bit times are in clocks of the testbench clock (common.PERIOD_NS), as the RTL
counts them; `bit_clocks` may be fractional, to send with a baud rate error.
The sink samples each bit in its middle, as a real receiver does, and keeps the
clock at which each byte's start bit began (for matching answers to snapshots).
"""

from __future__ import annotations

import cocotb
from cocotb.queue import Queue
from cocotb.triggers import FallingEdge, Timer

from common import PERIOD_NS


def _wait(clocks: float):
    return Timer(round(clocks * PERIOD_NS * 1000), unit="ps")


class UartSource:
    def __init__(self, pin, bit_clocks: float):
        self.pin = pin
        self.bit_clocks = bit_clocks
        pin.value = 1

    async def send(self, data: bytes, gap_bits: float = 0.0, break_stop: bool = False) -> None:
        """Send bytes (8N1); `break_stop` sends a low stop bit (a framing error)."""
        for byte in bytes(data):
            bits = [0] + [(byte >> i) & 1 for i in range(8)] + [0 if break_stop else 1]
            for bit in bits:
                self.pin.value = bit
                await _wait(self.bit_clocks)
            self.pin.value = 1
            if gap_bits:
                await _wait(gap_bits * self.bit_clocks)


class UartSink:
    """Decodes every byte on `pin` into `queue` as (start_time_ps, byte); counts framing errors."""

    def __init__(self, pin, bit_clocks: float):
        self.pin = pin
        self.bit_clocks = bit_clocks
        self.queue: Queue = Queue()
        self.framing_errors = 0
        self.count = 0
        self._task = cocotb.start_soon(self._run())

    async def _run(self) -> None:
        from cocotb.utils import get_sim_time

        while True:
            await FallingEdge(self.pin)
            start = get_sim_time("ps")
            await _wait(self.bit_clocks / 2)
            if int(self.pin.value) != 0:
                continue  # a glitch, not a start bit
            value = 0
            for i in range(8):
                await _wait(self.bit_clocks)
                value |= int(self.pin.value) << i
            await _wait(self.bit_clocks)
            if int(self.pin.value) != 1:
                self.framing_errors += 1
                continue
            self.count += 1
            self.queue.put_nowait((start, value))
