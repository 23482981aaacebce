# SPDX-License-Identifier: Apache-2.0
"""prenc_ssi read by an SSI controller model at 100 kHz, 500 kHz, 1 MHz and 2 MHz.

The controller (this testbench) drives ssi_clk with WIDTH + 2 pulses (+1 to see the line low) and samples
ssi_data on each falling edge after the first, as an SSI master does. Expected
values: prenc.board.ssi's frame (position at the first falling edge, Gray or binary,
error bit = not valid, and with WARN_BIT = 1 the warning bit after it) and the protocol's timing: data low after the frame, high
again one monoflop time after the last clock edge, a new latch only after it.
"""

from __future__ import annotations

import cocotb
import pytest
from cocotb.triggers import ClockCycles, FallingEdge, ReadOnly, Timer

from common import PERIOD_NS, rng, start_clock_and_reset
from prenc.board import ssi
from runner import SIMULATORS, run

TOPLEVEL = "prenc_ssi"
CLK_HZ = 48_000_000
RATES_HZ = (100_000, 500_000, 1_000_000, 2_000_000)


class Controller:
    def __init__(self, dut, rate_hz: int):
        self.dut = dut
        self.half_ps = round(CLK_HZ / rate_hz / 2 * PERIOD_NS * 1000)
        dut.ssi_clk.value = 1

    async def read(self, pulses: int, on_latch=None) -> list[int]:
        """Clock `pulses` pulses; return the data sampled at falling edges 2..pulses."""
        bits = []
        for k in range(pulses):
            self.dut.ssi_clk.value = 0
            if k == 0 and on_latch:
                on_latch()
            if k > 0:
                bits.append(int(self.dut.ssi_data.value))
            await Timer(self.half_ps, unit="ps")
            self.dut.ssi_clk.value = 1
            await Timer(self.half_ps, unit="ps")
        return bits


async def data_at(dut) -> int:
    await ReadOnly()
    value = int(dut.ssi_data.value)
    await FallingEdge(dut.clk)
    return value


@cocotb.test()
async def frames_at_every_rate_gray_and_binary(dut):
    r = rng()
    width, monoflop = int(dut.WIDTH.value), int(dut.MONOFLOP.value)
    warn_bit = int(dut.WARN_BIT.value)
    dut.position.value = 0
    dut.valid.value = 1
    dut.warn.value = 0
    dut.gray.value = 1
    dut.ssi_clk.value = 1
    await start_clock_and_reset(dut, 4)
    reads = 0
    for rate in RATES_HZ:
        ctl = Controller(dut, rate)
        for gray_code in (1, 0):
            for _ in range(6):
                position, valid, warn = r.randrange(1 << width), r.randrange(2), r.randrange(2)
                dut.gray.value = gray_code
                dut.position.value = position
                dut.valid.value = valid
                dut.warn.value = warn
                changed = {}

                def change_after_latch():
                    # The value changes 6 clocks after the first falling edge (after the
                    # synchronizer's latch): the frame must still carry the old one.
                    changed["cb"] = cocotb.start_soon(_later(dut, 6, r.randrange(1 << width)))

                bits = await ctl.read(width + 3 + warn_bit, change_after_latch)
                expected = ssi.frame_bits(position, width, bool(valid), bool(gray_code),
                                          warning=bool(warn) if warn_bit else None)
                assert bits[:-1] == expected, (rate, gray_code, position, valid, warn, bits)
                assert bits[-1] == 0, "data must be low after the last bit"
                if warn_bit:
                    got = ssi.decode_with_warning(bits[:-1], width, bool(gray_code))
                    assert got == (position, bool(valid), bool(warn))
                else:
                    assert ssi.decode(bits[:-1], width, bool(gray_code)) == (position, bool(valid))
                reads += 1
                # Monoflop: low until MONOFLOP clocks after the last edge, then high
                # (read() returns half a period after the last rising edge).
                await ClockCycles(dut.clk, monoflop - CLK_HZ // rate // 2 - 8)
                assert await data_at(dut) == 0, "data rose before the monoflop time"
                await ClockCycles(dut.clk, 16)
                assert await data_at(dut) == 1, "data did not return high after the monoflop time"
    dut._log.info("%d SSI frames read at %s Hz, Gray and binary", reads, RATES_HZ)


async def _later(dut, clocks: int, value: int) -> None:
    await ClockCycles(dut.clk, clocks)
    dut.position.value = value


@cocotb.test()
async def a_frame_cut_short_ends_at_the_monoflop_time(dut):
    width, monoflop = int(dut.WIDTH.value), int(dut.MONOFLOP.value)
    dut.position.value = (1 << width) - 1
    dut.valid.value = 1
    dut.warn.value = 0
    dut.gray.value = 0
    dut.ssi_clk.value = 1
    await start_clock_and_reset(dut, 4)
    ctl = Controller(dut, 1_000_000)
    bits = await ctl.read(4)  # three bits of a longer frame
    assert bits == [1, 1, 1]
    await ClockCycles(dut.clk, monoflop + 8)
    assert await data_at(dut) == 1
    dut.position.value = 0b1010 << (width - 4)
    bits = await ctl.read(width + 2 + int(dut.WARN_BIT.value))
    if int(dut.WARN_BIT.value):
        assert ssi.decode_with_warning(bits, width, False) == (0b1010 << (width - 4), True, False), bits
    else:
        assert ssi.decode(bits, width, False) == (0b1010 << (width - 4), True), bits


@pytest.mark.parametrize("warn_bit", [0, 1])
@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_ssi(simulator, warn_bit):
    run(__file__, TOPLEVEL, simulator,
        parameters={"WIDTH": 12, "ERROR_BIT": 1, "WARN_BIT": warn_bit, "MONOFLOP": 20 * CLK_HZ // 10**6})
