# SPDX-License-Identifier: Apache-2.0
"""prenc_board's ABI and UVW outputs read as a drive reads them, while the virtual
encoder turns: 1,200 rpm, a stop, a reversal, then a ramp to 30,000 rpm (2 M steps a
second) for two turns and more.

A quadrature counter (a drive's timer in encoder mode) counts A and B from power-up; at
every edge of A, B, I, U, V or W, and at random instants between, it is compared with
the disc's true angle at that instant (prenc.virtual's trajectory): once the position is
valid and the outputs have stepped to it, the count equals floor(angle x 4000) (ABIRES
0: 4000 steps), the shorter way round from power-up (N = 10 at 30 MHz; SPI_SETTINGS2 =
0x03: 4 pole pairs, HYS 0, the hysteresis 3 LSB of 14 bits): within one step at a steady
speed, within two while the disc speeds up from a stop. There the fine position knows
little more than its quarter (0.98 step; up to 0.72 step behind the truth seen), and
the hysteresis (0.73 step) adds to it after a reversal. The index
is high only where the count is 0 modulo 4000, and comes once per turn as the disc
passes the zero. U, V, W are 000 until the position is valid, then always the Hall
pattern of the true electrical angle (4 x the angle) within one sector. Edges of A
and B are at least ABI_EDGE_NS (250 ns, 8 clocks) apart, and never illegal.
"""

from __future__ import annotations

import cocotb
import numpy as np
from cocotb.triggers import Edge, First, Timer
from cocotb.utils import get_sim_time

from board_harness import drive_encoder, start_board
from common import PERIOD_NS, rng
from prenc.board import abi as spec
from prenc.virtual.encoder import Disc
from runner import rom_file, run

TOPLEVEL = "prenc_board"
N, FILTER, CLK_HZ = 10, 2, 30_000_000
STEPS, PAIRS, MIN_GAP = 4000, 4, 8
RPM = (1 << N) / 60 / CLK_HZ       # slots per clock at 1 rpm
START, THETA0 = 2_000, 1000.3      # near the zero: the first turn passes it soon
SEGMENTS = [  # (until clock, speed in rpm at the end; linear between)
    (40_000, 1200), (50_000, 1200), (60_000, 0), (70_000, 0), (80_000, -600), (95_000, -600),
    (105_000, 0), (135_000, 30_000), (260_000, 30_000),
]
SETTLE = 35_000
STEADY = 3_000                     # clocks into a constant-speed segment: steady from there


def steady(clock: float) -> bool:
    """Whether the disc has turned at one speed for STEADY clocks at `clock`."""
    start, speed = START, 1200
    for until, end_speed in SEGMENTS:
        if clock < until:
            return end_speed == speed and clock >= start + STEADY
        start, speed = until, end_speed
    return False


def angle_at(clocks) -> np.ndarray:
    """The disc's angle in slots, not wrapped."""
    c = np.asarray(clocks, dtype=np.float64)
    t = [START] + [s[0] for s in SEGMENTS]
    v = [1200 * RPM] + [s[1] * RPM for s in SEGMENTS]
    theta = np.full_like(c, THETA0)
    for k in range(len(SEGMENTS)):
        a, b = t[k], t[k + 1]
        span = np.clip(c - a, 0, b - a)
        theta += v[k] * span + 0.5 * (v[k + 1] - v[k]) / (b - a) * span ** 2
    return theta


def theta_at(clocks) -> np.ndarray:
    return angle_at(clocks) % (1 << N)


def now() -> float:
    return get_sim_time("ns") / PERIOD_NS


def off_by(count: int, clock: float) -> int:
    truth = int(float(theta_at(np.array([clock]))[0]) / (1 << N) * STEPS)
    return (count - truth + STEPS // 2) % STEPS - STEPS // 2


@cocotb.test()
async def abi_and_uvw_follow_the_disc(dut):
    r = rng()
    await start_board(dut)
    cocotb.start_soon(drive_encoder(dut, theta_at, disc=Disc(N)))
    states = {(0, 0): 0, (1, 0): 1, (1, 1): 2, (0, 1): 3}
    count, state, last_edge, indexes, checked, sectors_checked = 0, 0, -10**9, [], 0, 0
    steady_checked = 0
    end = SEGMENTS[-1][0]
    while now() < end:
        await First(Edge(dut.abi_a), Edge(dut.abi_b), Edge(dut.abi_i), Edge(dut.uvw_u), Edge(dut.uvw_v),
                    Edge(dut.uvw_w), Timer(r.randrange(200, 3000) * PERIOD_NS, unit="ns"))
        await Timer(1, unit="ps")
        clock = now()
        a, b, i = int(dut.abi_a.value), int(dut.abi_b.value), int(dut.abi_i.value)
        new = states[(a, b)]
        delta = (new - state) % 4
        assert delta != 2, f"illegal A/B transition at clock {clock}"
        if delta:
            assert clock - last_edge >= MIN_GAP - 0.01, (clock, last_edge)
            last_edge = clock
            count += 1 if delta == 1 else -1
            state = new
        uvw = (int(dut.uvw_u.value), int(dut.uvw_v.value), int(dut.uvw_w.value))
        if clock < START + 20_000:
            assert uvw == (0, 0, 0) or clock > START + 10_000, (clock, uvw)
        if i:
            assert count % STEPS == 0, (clock, count)
            if not indexes or clock - indexes[-1] > 1000:
                indexes.append(clock)
        if clock >= START + SETTLE:
            limit = 1 if steady(clock) else 2
            assert abs(off_by(count, clock)) <= limit, (clock, count % STEPS, off_by(count, clock))
            checked += 1
            steady_checked += steady(clock)
            electrical = float(theta_at(np.array([clock]))[0]) / (1 << N) * PAIRS * 6 % 6
            near = {spec.UVW_PATTERN[(int(electrical) + d) % 6] for d in (-1, 0, 1)}
            assert uvw in near, (clock, uvw, electrical)
            sectors_checked += 1
    dut._log.info("ABI: %d checks (%d at a steady speed), count %d, indexes at %s; UVW: %d checks",
                  checked, steady_checked, count, [round(c) for c in indexes], sectors_checked)
    assert checked > 100 and steady_checked > 100 and sectors_checked > 100
    # One index per pass of the zero: the disc's crossings of it after settling.
    turns = np.floor(angle_at(np.arange(START + SETTLE, end, 20)) / (1 << N))
    crossings = int(np.count_nonzero(np.diff(turns)))
    seen = [c for c in indexes if c >= START + SETTLE + 100]
    assert crossings >= 2 and len(seen) == crossings, (crossings, indexes)


def test_prenc_board_abi():
    parameters = {"N": N, "TAPS": sum(1 << (t - 1) for t in Disc(N).taps), "FILTER": FILTER,
                  "ROM_FILE": rom_file(N), "CLK_HZ": CLK_HZ, "BAUD": 3_000_000, "SPI_SETTINGS2": 0x03}
    run(__file__, TOPLEVEL, "verilator", parameters=parameters)
