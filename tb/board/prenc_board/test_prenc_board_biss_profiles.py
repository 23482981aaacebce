# SPDX-License-Identifier: Apache-2.0
"""prenc_board's BiSS-C profiles read as the firmware that needs them reads BiSS-C
(tb/biss_drivers.py): OnStepX's AS37_H39B_B layout (16 multi-turn + 23 single-turn
bits, the error bit 1 on an error: BISS_MT_BITS = 16, BISS_ST_BITS = 23,
BISS_ERROR_HIGH = 1), JTW_24BIT (0 + 24) and JTW_26BIT (0 + 26), and VESC's single-turn BiSS-C with
"Encoder Counts" = 22 (BISS_MT_BITS = 0, BISS_ST_BITS = 22).

The disc turns at 600 rpm from rest (N = 10 at 30 MHz). Every frame the firmware
accepts after the position is valid carries the disc's angle at the master's first
falling edge of MA: the single-turn count / 2^ST of a turn, within the fine position's
14 bits (1/16 slot, below the truth) and its own error; OnStepX accepts no frame before
the position is valid (its error bit), and every VESC frame passes its CRC.
"""

from __future__ import annotations

import cocotb
import numpy as np
import pytest
from cocotb.triggers import Timer
from cocotb.utils import get_sim_time

from biss_drivers import OnStepX, Vesc
from board_harness import drive_encoder, start_board
from common import PERIOD_NS
from prenc.virtual.encoder import Disc
from runner import rom_file, run

TOPLEVEL = "prenc_board"
N, FILTER, CLK_HZ = 10, 2, 30_000_000
SPEED = 600 / 60 * (1 << N) / CLK_HZ      # slots per clock
START, THETA0, END = 2_000, 211.6, 110_000
SETTLE = 60_000                           # lock (N + 2 slots) and the velocity
PROFILES = {
    "onstepx_as37": {"BISS_MT_BITS": 16, "BISS_ST_BITS": 23, "BISS_ERROR_HIGH": 1},
    "onstepx_jtw24": {"BISS_MT_BITS": 0, "BISS_ST_BITS": 24},
    "onstepx_jtw26": {"BISS_MT_BITS": 0, "BISS_ST_BITS": 26},
    "vesc": {"BISS_MT_BITS": 0, "BISS_ST_BITS": 22},
}


def theta_at(clocks) -> np.ndarray:
    c = np.asarray(clocks, dtype=np.float64)
    return THETA0 + SPEED * np.clip(c - START, 0, None)


def error_slots(count: int, st_bits: int, clock: float) -> float:
    length = 1 << N
    err = count / (1 << st_bits) * length - float(theta_at(np.array([clock]))[0])
    return (err + length / 2) % length - length / 2


@cocotb.test()
async def the_firmware_reads_the_disc(dut):
    st_bits = int(dut.BISS_ST_BITS.value)
    mt_bits = int(dut.BISS_MT_BITS.value)
    await start_board(dut)
    cocotb.start_soon(drive_encoder(dut, theta_at, disc=Disc(N)))
    if st_bits == 22:
        master, name = Vesc(dut, CLK_HZ, enc_res=22), "vesc"
    else:
        master = OnStepX(dut, CLK_HZ, "AS37_H39B_B" if mt_bits == 16 else f"JTW_{st_bits}BIT")
        name = "onstepx"
    errors, dropped, frames = [], [], 0
    while get_sim_time("ns") / PERIOD_NS < END:
        result = await master.read()
        frames += 1
        started = result[-1] / PERIOD_NS
        good, count = result[0], result[-2]
        if name == "vesc" and good and not result[1]:
            # VESC checks the CRC, not nE: it takes this frame, which says the position is
            # not valid (docs/guide/drives/vesc.md). The frames from the first valid one on
            # must be right.
            dropped.append(started)
            continue
        await Timer(round(25e-6 * CLK_HZ) * PERIOD_NS, unit="ns")   # BiSS-C's timeout
        if not good:
            dropped.append(started)
            continue
        err = error_slots(count, st_bits, started)
        # Never a wrong position: before the velocity settles the fine position is its
        # quarter's middle (an eighth of a slot from the truth at most).
        assert -1 / 16 - 1 / 8 <= err <= 1 / 8, (name, started, err)
        if started >= START + SETTLE:
            errors.append(err)
    e = np.array(errors)
    dut._log.info("%s, %d + %d bits: %d frames, %d after settling: error %.4f .. %.4f slot; %d dropped, "
                  "the last at clock %s", name, mt_bits, st_bits, frames, len(e), e.min(), e.max(), len(dropped),
                  round(dropped[-1]) if dropped else None)
    assert len(e) >= 20
    assert e.min() >= -1 / 16 - 1 / 64 and e.max() <= 1 / 64, (e.min(), e.max())
    if name == "onstepx":
        # The frames before the position is valid, and only those, are dropped (the error bit).
        assert dropped and max(dropped) < START + SETTLE, dropped


@pytest.mark.parametrize("profile", sorted(PROFILES))
def test_prenc_board_biss_profiles(profile):
    parameters = {"N": N, "TAPS": sum(1 << (t - 1) for t in Disc(N).taps), "FILTER": FILTER,
                  "ROM_FILE": rom_file(N), "CLK_HZ": CLK_HZ, "BAUD": 3_000_000} | PROFILES[profile]
    run(__file__, TOPLEVEL, "verilator", parameters=parameters)
