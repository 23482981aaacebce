# SPDX-License-Identifier: Apache-2.0
"""prenc_as5047 against its model (prenc.board.as5047) and the AS5047P datasheet, read
by an SPI master in mode 1 (tb/spi_master.py) on a 30 MHz clock.

- Random traffic: reads of every register, writes of the writable ones, frames with
  bad parity, 8, 15, 17 or 24 clocks, unknown addresses, while the angle and its
  validity change between frames; every answer equals the model's, at 1, 5 and 10 MHz
  on a 30 MHz clock and 10.6 and 16 MHz on 50 MHz (TIMINGS), the master sampling MISO
  20 ns before each falling edge, at random phases of SCLK to the clock.
- The datasheet's definitions, written out here: a read is answered in the next frame
  with even parity and EF 0; an error frame sets its ERRFL bit and EF until ERRFL is
  read; a zero written through ZPOSM/ZPOSL makes the angle read 0 there; DIR turns it
  around; while the position is not valid the angle frames carry EF and the last valid
  angle, and DIAAGC's COF is set.
"""

from __future__ import annotations

import pytest
from cocotb.triggers import ClockCycles, Timer

import cocotb
from common import PERIOD_NS, rng, start_clock_and_reset
from prenc.board import as5047 as spec
from runner import SIMULATORS, run
from spi_master import SpiMaster

TOPLEVEL = "prenc_as5047"
CLK_HZ = 30_000_000


async def start(dut, angle: int = 0, valid: int = 1) -> None:
    dut.angle.value = angle
    dut.valid.value = valid
    dut.warning.value = 0
    dut.csn.value = 1
    dut.sclk.value = 0
    dut.mosi.value = 0
    await start_clock_and_reset(dut, 4)
    await ClockCycles(dut.clk, 4)


class Bench:
    """The DUT, its model and a master; inputs change only while CSn is high."""

    def __init__(self, dut, rate_hz: float):
        self.dut = dut
        self.model = spec.As5047()
        self.master = SpiMaster(dut, rate_hz, CLK_HZ, prefix="")
        self.raw, self.valid, self.warning = 0, True, False

    async def set_angle(self, raw: int, valid: bool, warning: bool = False) -> None:
        # The slave decodes the last frame 2 to 3 clocks after CSn rose (a write of the
        # zero changes the held angle on the clock after): wait for it.
        await ClockCycles(self.dut.clk, 4)
        self.model.follow(self.raw, self.valid)
        self.raw, self.valid, self.warning = raw, valid, warning
        self.dut.angle.value = raw
        self.dut.valid.value = int(valid)
        self.dut.warning.value = int(warning)
        await ClockCycles(self.dut.clk, 2)
        self.model.follow(raw, valid)

    async def frame(self, word: int, clocks: int = 16) -> tuple[int, int]:
        """(the DUT's answer, the model's)."""
        expected = self.model.open(self.raw, self.valid, self.warning)
        got = await self.master.frame(word, clocks)
        if clocks > 16:   # after the answer, zeros
            expected <<= clocks - 16
        else:
            expected >>= 16 - clocks
        self.model.shut(word & ((1 << clocks) - 1), clocks)
        return got, expected


# (board clock, SCLK, CSn falling to SCLK's first rising edge, CSn high) in Hz and real ns:
# the iCEBreaker's 30 MHz at 1, 5 and 10 MHz, the last at the shortest times
# docs/interfaces/as5047.md allows; the ULX3S's 50 MHz at moteus's 10.6 MHz and at 16 MHz.
TIMINGS = ((30e6, 1e6, 400, 400), (30e6, 5e6, 400, 400), (30e6, 10e6, 155 - 50, 100),
           (50e6, 170e6 / 16, 200, 200), (50e6, 16e6, 100 - 31, 60))
ADDRESSES = spec.READABLE + (0x0002, 0x0004, 0x1234, 0x3FFB)


@cocotb.test()
async def random_traffic_equals_the_model(dut):
    r = rng()
    await start(dut)
    frames = 0
    bench = Bench(dut, 1_000_000)
    for clk_hz, rate, lead_ns, gap_ns in TIMINGS:
        bench.master = SpiMaster(dut, rate, clk_hz, prefix="", lead_ns=lead_ns, gap_ns=gap_ns)
        history = []
        for _ in range(150):
            await Timer(r.randrange(1, 1000 * PERIOD_NS), unit="ps")   # SCLK's phase
            if r.random() < 0.2:
                await bench.set_angle(r.randrange(1 << 14), r.random() < 0.8, r.random() < 0.3)
            kind = r.random()
            clocks = 16
            if kind < 0.45:
                word = spec.read_command(r.choice(ADDRESSES))
            elif kind < 0.65:
                word = spec.write_command(r.choice(spec.WRITABLE + (spec.ANGLECOM, 0x0005)))
            elif kind < 0.8:
                word = spec.data_frame(r.randrange(1 << 14))
            elif kind < 0.9:
                word = spec.read_command(r.choice(ADDRESSES)) ^ (1 << r.randrange(16))
            else:
                word = r.randrange(1 << 24)
                clocks = r.choice((8, 15, 17, 24))
            got, expected = await bench.frame(word, clocks)
            history.append((hex(word), clocks, hex(got), hex(expected)))
            assert got == expected, (clk_hz, rate, history[-6:])
            frames += 1
    dut._log.info("%d frames equal to the model's", frames)


@cocotb.test()
async def the_datasheets_frames(dut):
    angle = 0x1ABC
    await start(dut, angle)
    m = SpiMaster(dut, 10_000_000, CLK_HZ, prefix="")

    async def read(address: int) -> spec.Answer:
        await m.frame(spec.read_command(address))
        return spec.Answer(await m.frame(spec.read_command(spec.NOP)))

    a = await read(spec.ANGLECOM)
    assert (a.parity_ok, a.error, a.data) == (True, False, angle)
    assert (await read(spec.ANGLEUNC)).data == angle
    assert (await read(spec.SETTINGS1)).data == 0x01
    diag = await read(spec.DIAAGC)
    assert diag.data & spec.LF and not diag.data & spec.COF

    # A command with bad parity: not executed, PARERR, EF until ERRFL is read.
    await m.frame(spec.read_command(spec.ANGLECOM) ^ 0x8000)
    a = spec.Answer(await m.frame(spec.read_command(spec.ERRFL)))
    assert a.error and a.parity_ok
    e = spec.Answer(await m.frame(spec.read_command(spec.NOP)))
    assert e.data == spec.PARERR and e.error
    assert not spec.Answer(await m.frame(spec.read_command(spec.NOP))).error
    # Fifteen clocks: FRERR. An unknown address: INVCOMM.
    await m.frame(spec.read_command(spec.ANGLECOM) >> 1, clocks=15)
    assert (await read(spec.ERRFL)).data == spec.FRERR
    await m.frame(spec.read_command(0x0005))
    assert (await read(spec.ERRFL)).data == spec.INVCOMM

    # The zero: ZPOSM = bits 13:6, ZPOSL bits 5:0; the angle there reads 0.
    for address, value in ((spec.ZPOSM, angle >> 6), (spec.ZPOSL, angle & 0x3F)):
        await m.frame(spec.write_command(address))
        old = spec.Answer(await m.frame(spec.data_frame(value)))
        assert old.data == 0 and not old.error
        assert (await read(address)).data == value
    assert (await read(spec.ANGLECOM)).data == 0
    dut.angle.value = angle + 5
    await ClockCycles(dut.clk, 2)
    assert (await read(spec.ANGLECOM)).data == 5
    # DIR: the angle counts the other way.
    await m.frame(spec.write_command(spec.SETTINGS1))
    await m.frame(spec.data_frame(0x01 | spec.DIR))
    assert (await read(spec.ANGLECOM)).data == (-1 - (angle + 5) - angle) % (1 << 14)   # the one's complement

    # Not valid: EF and the last valid angle; COF; LF stays.
    held = (await read(spec.ANGLECOM)).data
    dut.valid.value = 0
    dut.angle.value = 0x0123
    await ClockCycles(dut.clk, 2)
    a = await read(spec.ANGLECOM)
    assert (a.parity_ok, a.error, a.data) == (True, True, held)
    diag = await read(spec.DIAAGC)
    assert diag.data & spec.COF and diag.data & spec.LF and not diag.error
    dut.valid.value = 1
    await ClockCycles(dut.clk, 2)
    a = await read(spec.ANGLECOM)
    assert not a.error and a.data == (-1 - 0x0123 - angle) % (1 << 14)


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_as5047(simulator):
    run(__file__, TOPLEVEL, simulator)
