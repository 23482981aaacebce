# SPDX-License-Identifier: Apache-2.0
"""prenc_biss read by a BiSS-C master at 1, 2.5, 3.3, 5 and 10 MHz (a 50 MHz design clock).

The master (this testbench, with prenc.board.biss) is written from the protocol, not from
the slave: it clocks MA, records every change of SLO, finds the Ack and the start
bit, measures the line delay there and samples each later bit that long after its
rising edge (BiSS line-delay compensation). Expected values: the data, nE and nW
given to the slave at the frame's first falling edge (changed right after it, so a
late latch would show), the CRC-6 of the protocol, SLO low after the frame and high
again TIMEOUT clocks after the last MA edge. A frame cut short, MA stopped low, and
random pulses on MA must each end at the timeout and leave the slave ready for a
good frame.
"""

from __future__ import annotations

import cocotb
import pytest
from cocotb.triggers import ClockCycles, FallingEdge, ReadOnly, Timer

from biss_master import Master
from common import PERIOD_NS, rng, start_clock_and_reset
from prenc.board import biss
from runner import SIMULATORS, run

TOPLEVEL = "prenc_biss"
CLK_HZ = 50_000_000          # the ULX3S design clock (one clock = PERIOD_NS in simulation)
RATES_HZ = (1_000_000, 2_500_000, 3_300_000, 5_000_000, 10_000_000)
MT_BITS, ST_BITS = 12, 12
TIMEOUT = 1_000              # 20 us at 50 MHz


def crc_table_entries() -> dict[int, int]:
    """The first entries of the table-driven CRC-6 of the BiSS application notes
    (tableCRC6[i] = the CRC of the six bits i), for a known-answer check."""
    table = [0x00, 0x03, 0x06, 0x05, 0x0C, 0x0F, 0x0A, 0x09, 0x18, 0x1B, 0x1E, 0x1D,
             0x14, 0x17, 0x12, 0x11, 0x30, 0x33, 0x36, 0x35, 0x3C, 0x3F, 0x3A, 0x39,
             0x28, 0x2B, 0x2E, 0x2D, 0x24, 0x27, 0x22, 0x21, 0x23, 0x20, 0x25, 0x26]
    return dict(enumerate(table))


async def slo_now(dut) -> int:
    await ReadOnly()
    value = int(dut.slo.value)
    await FallingEdge(dut.clk)
    return value


def put(dut, turns: int, position: int, error: bool, warning: bool) -> None:
    dut.data.value = (turns << ST_BITS) | position
    dut.error_n.value = 0 if error else 1
    dut.warn_n.value = 0 if warning else 1


async def start(dut) -> None:
    put(dut, 0, 0, False, False)
    dut.ma.value = 1
    await start_clock_and_reset(dut, 4)


def test_crc6_known_answers():
    for value, crc in crc_table_entries().items():
        assert biss.crc6(biss.to_bits(value, 6)) == crc, value
    # A frame's CRC check fails on any single flipped bit.
    bits = biss.frame_bits(0x5A5, 0x3C3, MT_BITS, ST_BITS, False, True)
    for i in range(1, len(bits)):
        flipped = list(bits)
        flipped[i] ^= 1
        assert not biss.decode(flipped, MT_BITS, ST_BITS).crc_ok, i


@cocotb.test()
async def frames_at_every_rate(dut):
    r = rng()
    await start(dut)
    reads = 0
    for rate in RATES_HZ:
        master = Master(dut, rate, CLK_HZ, timeout_clocks=TIMEOUT)
        for _ in range(8):
            turns, position = r.randrange(1 << MT_BITS), r.randrange(1 << ST_BITS)
            error, warning = bool(r.randrange(2)), bool(r.randrange(2))
            put(dut, turns, position, error, warning)

            def change_after_latch():
                # New values 4 clocks after the first falling edge (after the latch
                # through the synchronizer): the frame must carry the old ones.
                cocotb.start_soon(_later(dut, 4, r))

            reading, delay = await master.read(MT_BITS, ST_BITS, change_after_latch)
            assert reading == biss.Reading(turns, position, error, warning, True), (rate, reading)
            assert 2 * PERIOD_NS <= delay <= 5 * PERIOD_NS, f"line delay {delay} ns at {rate} Hz"
            # After the stop pulse SLO is low (timeout) until TIMEOUT clocks after the
            # last MA edge, then high (ready).
            assert await slo_now(dut) == 0
            await ClockCycles(dut.clk, TIMEOUT - round(master.half_ps / 1000 / PERIOD_NS) - 8)
            assert await slo_now(dut) == 0, "SLO rose before the timeout"
            await ClockCycles(dut.clk, 16)
            assert await slo_now(dut) == 1, "SLO did not return high after the timeout"
            reads += 1
    dut._log.info("%d BiSS-C frames read at %s Hz", reads, RATES_HZ)


async def _later(dut, clocks: int, r) -> None:
    await ClockCycles(dut.clk, clocks)
    put(dut, r.randrange(1 << MT_BITS), r.randrange(1 << ST_BITS), bool(r.randrange(2)),
        bool(r.randrange(2)))


async def good_frame_after(dut, master: Master, what: str) -> None:
    await ClockCycles(dut.clk, TIMEOUT + 8)
    assert await slo_now(dut) == 1, f"{what}: the slave is not idle after the timeout"
    put(dut, 0xABC, 0x123, False, False)
    reading, _ = await master.read(MT_BITS, ST_BITS)
    assert reading == biss.Reading(0xABC, 0x123, False, False, True), (what, reading)
    await ClockCycles(dut.clk, TIMEOUT + 8)


@cocotb.test()
async def cut_short_stopped_or_garbled_clocks_never_lock_the_slave_up(dut):
    r = rng()
    await start(dut)
    master = Master(dut, 2_500_000, CLK_HZ, timeout_clocks=TIMEOUT)
    # A frame cut short after a few data bits: MA stays high.
    await master.pulses(9)
    await good_frame_after(dut, master, "frame cut short")
    # MA stops low in the middle of a frame (a broken cable, or CDM held low).
    await master.pulses(6)
    dut.ma.value = 0
    await ClockCycles(dut.clk, TIMEOUT + 8)
    assert await slo_now(dut) == 1, "MA stuck low: SLO must return high after the timeout"
    dut.ma.value = 1
    await good_frame_after(dut, master, "MA stopped low")
    # Random pulses of random widths on MA.
    for _ in range(200):
        dut.ma.value = r.randrange(2)
        await Timer(r.randrange(1, 40) * PERIOD_NS * 1000 // 3, unit="ps")
    dut.ma.value = 1
    await good_frame_after(dut, master, "random pulses")
    # A frame with extra pulses after the stop: SLO stays low, then the timeout.
    put(dut, 1, 2, True, False)
    master.edges.clear()
    rises = await master.pulses(biss.clock_pulses(MT_BITS, ST_BITS) + 5)
    count = len(biss.frame_bits(0, 0, MT_BITS, ST_BITS, False, False))
    bits, _ = biss.sample(rises, list(master.edges), master.period_ns, count)
    assert biss.decode(bits, MT_BITS, ST_BITS) == biss.Reading(1, 2, True, False, True)
    assert await slo_now(dut) == 0
    await good_frame_after(dut, master, "extra pulses")


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_biss(simulator):
    run(__file__, TOPLEVEL, simulator,
        parameters={"DATA_BITS": MT_BITS + ST_BITS, "TIMEOUT": TIMEOUT})
