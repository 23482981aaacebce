# SPDX-License-Identifier: Apache-2.0
"""The board's surroundings in simulation: the virtual encoder on its pins, and a
pseudo-terminal on its UART.

Shared by the board's tests and by the virtual board (`make board-sim`):

    prenc host (pyserial) <-> /dev/pts/N <-> Bridge <-> uart_rx / uart_tx pins
    prenc.virtual.encoder.VirtualEncoder (a trajectory, faults) -> drive_encoder -> encoder pins

The bridge only moves bits between the pty and the pins at the UART's bit rate, and
records the clock of every answer's snapshot (prenc_host_link's `snapshot`).
"""

from __future__ import annotations

import fcntl
import os
import tty
from typing import Callable, Sequence

import cocotb
import numpy as np
from cocotb.triggers import RisingEdge, Timer
from cocotb.utils import get_sim_time

from common import PERIOD_NS, start_clock_and_reset
from prenc.virtual.encoder import Disc, VirtualEncoder
from uart import UartSink, UartSource

PINS = ("head1", "head2", "sync_a", "sync_b")
CHUNK = 200_000  # encoder signals are generated this many clocks at a time


async def start_board(dut, reset_clocks: int = 6) -> None:
    """Idle levels on every input of prenc_board (encoder pins 0, SSI and BiSS-C
    clocks and the UART line high, Gray selected, SPI's CSn high, SCLK low, MOSI high
    as the boards' pull-up holds it), then clock and reset."""
    for pin in PINS:
        getattr(dut, pin).value = 0
    dut.ssi_clk.value = 1
    dut.ssi_gray.value = 1
    dut.biss_ma.value = 1
    dut.spi_csn.value = 1
    dut.spi_sclk.value = 0
    dut.spi_mosi.value = 1
    dut.uart_rx.value = 1
    await start_clock_and_reset(dut, reset_clocks)


class Bridge:
    """Moves bytes between the pty's master side and the board's UART pins."""

    def __init__(self, dut, bit_clocks: int, snapshots: bool = True):
        self.dut = dut
        self.master, self.slave = os.openpty()
        tty.setraw(self.master)
        tty.setraw(self.slave)
        fcntl.fcntl(self.master, fcntl.F_SETFL, fcntl.fcntl(self.master, fcntl.F_GETFL) | os.O_NONBLOCK)
        self.port = os.ttyname(self.slave)
        self.bit_clocks = bit_clocks
        self.source = UartSource(dut.uart_rx, bit_clocks)
        self.sink = UartSink(dut.uart_tx, bit_clocks)
        self.snapshots: list[int] = []
        self.corrupt_byte: int | None = None  # index of a board byte to corrupt on the way
        self.sent = 0
        # Board bytes the pty did not take yet: a host slower than the simulation (a loaded
        # machine) must not lose bytes, as a USB-UART bridge's buffer would not. Bounded,
        # for the phases where no host reads the pty at all.
        self.backlog = bytearray()
        self.backlog_limit = 1 << 16
        cocotb.start_soon(self._to_board())
        cocotb.start_soon(self._to_host())
        if snapshots:
            cocotb.start_soon(self._snapshots())

    async def _to_board(self) -> None:
        while True:
            try:
                data = os.read(self.master, 256)
            except (BlockingIOError, OSError):
                data = b""
            self._flush()
            if data:
                await self.source.send(data)
            else:
                await Timer(10 * self.bit_clocks * PERIOD_NS, unit="ns")

    async def _to_host(self) -> None:
        while True:
            _, byte = await self.sink.queue.get()
            if self.sent == self.corrupt_byte:
                byte ^= 0x10
            self.sent += 1
            self.backlog.append(byte)
            if len(self.backlog) > self.backlog_limit:  # nobody has read the pty for long
                del self.backlog[:len(self.backlog) - self.backlog_limit]
            self._flush()

    def _flush(self) -> None:
        """Write what the pty takes of the backlog now; keep the rest for later."""
        while self.backlog:
            try:
                written = os.write(self.master, bytes(self.backlog))
            except BlockingIOError:
                return
            del self.backlog[:written]

    async def _snapshots(self) -> None:
        while True:
            await RisingEdge(self.dut.clk)
            if int(self.dut.g_host_link.u_link.snapshot.value):
                self.snapshots.append(round(get_sim_time("ns") / PERIOD_NS))

    def snapshot_of(self, seq: int) -> int:
        """The clock of the latest snapshot whose index is seq (mod 256)."""
        for index in range(len(self.snapshots) - 1, -1, -1):
            if index % 256 == seq:
                return self.snapshots[index]
        raise AssertionError(f"no snapshot for SEQ {seq}")


async def drive_encoder(dut, theta_at: Callable[[np.ndarray], np.ndarray],
                        faults: Callable[[int], Sequence[object]] = lambda chunk: (),
                        disc: Disc | None = None) -> None:
    """The virtual encoder's pins along theta_at(clock), generated CHUNK clocks at a
    time, for ever; faults(chunk_index) gives each chunk's faults. Clocks are the
    simulation's (sim time / PERIOD_NS, rounded down): the pins take the encoder's
    value of clock c during clock c, in time for the rising edge that ends it."""
    start, index = int(get_sim_time("ns") // PERIOD_NS), 0
    while True:
        enc = VirtualEncoder(disc, faults(index))
        run_ = enc.run(theta_at(np.arange(start, start + CHUNK)))
        now = start
        for clock, *values in run_.events():
            at = start + clock
            if at > now:
                await Timer((at - now) * PERIOD_NS, unit="ns")
                now = at
            for pin, value in zip(PINS, values):
                getattr(dut, pin).value = value
        await Timer((start + CHUNK - now) * PERIOD_NS, unit="ns")
        start += CHUNK
        index += 1
