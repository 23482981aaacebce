# SPDX-License-Identifier: Apache-2.0
"""prenc_board's BiSS-C output, read by a BiSS-C master while the disc turns.

The disc (N = 6, 64 slots) rests, turns 3.5 times CW, then 6 times CCW, so the
multi-turn count goes up across the zero crossing and down below turn 0; head 2
sticks at 0 for the last four turns, which puts the core in a reduced mode (nW). A master
(prenc.board.biss, written from the protocol) reads frame after frame at 5 MHz and 1 MHz
(6 and 30 clocks of the iCEBreaker's 30 MHz design clock). Every frame must carry, with a good
CRC, what the board had on the clock before its latch (the frame's first falling
edge): the pair {turns, position} of prenc_turns' register (the fine position, here
FINE_BITS = 0: the quarter, extrapolated to the master's request), nE = its valid,
nW = not a reduced mode. Every valid frame must also match the truth of the virtual
encoder: the position that of the master's first falling edge (or, before the
velocity is known, of the core's latency before it), and the turns counted from the
turn of the first valid position.
"""

from __future__ import annotations

import cocotb
import numpy as np
from cocotb.triggers import ReadOnly, RisingEdge, Timer
from cocotb.utils import get_sim_time

from biss_master import Master
from board_harness import drive_encoder, start_board
from common import PERIOD_NS
from prenc.board import biss
from prenc.virtual.encoder import Disc
from prenc.virtual.faults import DeadHead
from prenc.virtual.scenarios import core_latency
from runner import rom_file, run

TOPLEVEL = "prenc_board"
N, FILTER, CLK_HZ = 6, 2, 30_000_000  # the iCEBreaker's design clock
MT_BITS, ST_BITS = 12, N + 2
TURN = 1 << N
SLOT_CLOCKS = 24
START_CLOCK = 1_000
THETA0 = 10.4
CW_CLOCKS = int(3.5 * TURN * SLOT_CLOCKS)
CCW_CLOCKS = 6 * TURN * SLOT_CLOCKS
RATES_HZ = (5_000_000, 1_000_000)


def theta_at(clocks: np.ndarray) -> np.ndarray:
    c = np.asarray(clocks, dtype=np.float64) - START_CLOCK
    cw = np.clip(c, 0, CW_CLOCKS)
    ccw = np.clip(c - CW_CLOCKS, 0, CCW_CLOCKS)
    return THETA0 + (cw - ccw) / SLOT_CLOCKS


class Board:
    """What the board had on each clock, and the clocks of the BiSS latches."""

    def __init__(self, dut):
        self.dut = dut
        self.latches: list[tuple[int, dict]] = []
        self.first_valid: int | None = None
        cocotb.start_soon(self._watch())

    async def _watch(self) -> None:
        dut, before = self.dut, None
        while True:
            await RisingEdge(dut.clk)
            await ReadOnly()
            clock = round(get_sim_time("ns") / PERIOD_NS)
            if int(dut.u_biss.latch.value) and before is not None:
                self.latches.append((clock - 1, before))
            valid = int(dut.u_core.pos_valid.value)
            if valid and self.first_valid is None:
                self.first_valid = clock
            # prenc_turns keeps the fine position at the SPI's 14 bits at least (FULL_BITS);
            # BiSS-C sends its top ST_BITS.
            pair, full_bits = int(dut.u_turns.full.value), len(dut.full_held)
            before = {"turns": pair >> full_bits,
                      "position": (pair & ((1 << full_bits) - 1)) >> (full_bits - ST_BITS),
                      "valid": int(dut.fine_valid_d.value), "mode": int(dut.u_core.mode.value)}


@cocotb.test()
async def biss_frames_carry_the_core_and_the_turns_of_the_disc(dut):
    await start_board(dut)
    dead = DeadHead(head=2, mode="stuck0", start_clock=START_CLOCK + CW_CLOCKS + CCW_CLOCKS // 3)
    cocotb.start_soon(drive_encoder(dut, theta_at, lambda chunk: [dead] if chunk == 0 else [], Disc(N)))
    board = Board(dut)
    masters = [Master(dut, rate, CLK_HZ, ma="biss_ma", slo="biss_slo") for rate in RATES_HZ]
    disc, latency = Disc(N), core_latency(FILTER)
    frames, valid_frames, warned, turns_seen = 0, 0, 0, set()
    end = START_CLOCK + CW_CLOCKS + CCW_CLOCKS
    while round(get_sim_time("ns") / PERIOD_NS) < end:
        master = masters[frames % len(masters)]
        asked = []
        reading, _ = await master.read(mt_bits=MT_BITS, st_bits=ST_BITS,
                                       on_start=lambda: asked.append(get_sim_time("ns") / PERIOD_NS))
        clock, had = board.latches[-1]
        assert reading.crc_ok, (clock, reading)
        assert reading == biss.Reading(had["turns"], had["position"], not had["valid"],
                                       had["mode"] in (2, 3), True), (clock, reading, had)
        if had["valid"]:
            request = int(asked[0])
            truth = theta_at(np.arange(request - latency - FILTER - 2, request + 3))
            hybrid = set(disc.hybrid(truth).tolist())
            assert reading.position in hybrid, (clock, reading, sorted(hybrid))
            turn0 = int(np.floor(theta_at(np.array([board.first_valid - latency]))[0] / TURN))
            turns = {int(np.floor(t / TURN)) - turn0 for t in truth}
            assert reading.turns in {t % (1 << MT_BITS) for t in turns}, (clock, reading, turns)
            turns_seen.add(reading.turns)
            valid_frames += 1
            warned += reading.warning
        frames += 1
        await Timer(master.timeout_ns(), unit="ns")
    dut._log.info("%d BiSS-C frames, %d valid, %d of them with the warning; turns seen %s",
                  frames, valid_frames, warned, sorted(turns_seen))
    assert valid_frames >= frames - 3, (frames, valid_frames)
    assert warned >= 3 and valid_frames - warned >= 5, (valid_frames, warned)
    assert {1, 2, 3} <= turns_seen, sorted(turns_seen)
    assert {(1 << MT_BITS) - 1, (1 << MT_BITS) - 2} <= turns_seen, sorted(turns_seen)  # turns -1, -2


def test_prenc_board_biss():
    run(__file__, TOPLEVEL, "verilator",
        parameters={"N": N, "TAPS": sum(1 << (t - 1) for t in Disc(N).taps), "FILTER": FILTER, "ROM_FILE": rom_file(N), "CLK_HZ": CLK_HZ,
                    "BAUD": 3_000_000, "BISS_MT_BITS": MT_BITS, "BISS_HYBRID": 1})
