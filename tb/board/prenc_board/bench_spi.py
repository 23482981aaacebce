# SPDX-License-Identifier: Apache-2.0
"""Benchmark for `make bench`: the AS5047P-compatible SPI's angle against the disc's true
angle at the instant the drive asked (CSn's fall), at a steady speed.

prenc_board (N = 10, 30 MHz, the ideal disc) acquires at 1,200 rpm, ramps to
$BENCH_RPM and holds it; ODrive's master (tb/as5047_drivers.py: 0xFFFF each frame,
parity and EF checked) reads frames every 5 to 15 us. For each frame taken on the steady
stretch: the error of the 14-bit angle in slots; and baselines computed from the truth
at the same instants: the coarse position (the quarter, floor(4 theta) / 4, as SSI sends
it with FINE_BITS = 0), and a perfect 14-bit angle read with the AS5047P's timing (its
register latched at the CSn rise that ended the frame before, one control cycle earlier:
ODrive's 125 us, moteus's 33 us). Writes {rpm, frames, ours: [rms, max, mean], coarse,
as5047p_8khz, as5047p_30khz} to $BENCH_OUT.
"""

from __future__ import annotations

import json
import os

import cocotb
import numpy as np
from cocotb.utils import get_sim_time

from as5047_drivers import DRIVERS
from board_harness import drive_encoder, start_board
from common import PERIOD_NS, rng
from prenc.virtual.encoder import Disc

N, CLK_HZ = 10, 30_000_000
RPM = (1 << N) / 60 / CLK_HZ        # slots per clock at 1 rpm
START, THETA0 = 2_000, 300.2
ACQUIRE, RAMP = 40_000, 20_000       # 1,200 rpm to ACQUIRE, then a ramp to the speed
SETTLE = 20_000                      # after the ramp, the velocity's windows, and
MEASURE = 150_000                    # each at least 4 edge periods of the sync track
LSB = (1 << N) / (1 << 14)


def trajectory(rpm: float):
    slow, fast = 1200 * RPM, rpm * RPM
    ramp_end = ACQUIRE + RAMP

    def angle_at(clocks) -> np.ndarray:
        c = np.asarray(clocks, dtype=np.float64)
        a = np.clip(c - START, 0, ACQUIRE - START)
        r = np.clip(c - ACQUIRE, 0, RAMP)
        f = np.clip(c - ramp_end, 0, None)
        return THETA0 + slow * a + slow * r + 0.5 * (fast - slow) / RAMP * r ** 2 + fast * f
    return angle_at


def stats(errors) -> list[float]:
    e = np.asarray(errors)
    return [float(np.sqrt(np.mean(e * e))), float(np.max(np.abs(e))), float(np.mean(e))]


def wrap(err: float) -> float:
    length = 1 << N
    return (err + length / 2) % length - length / 2


@cocotb.test()
async def spi_angle_against_the_truth(dut):
    rpm = float(os.environ["BENCH_RPM"])
    angle_at = trajectory(rpm)
    r = rng()
    await start_board(dut)
    cocotb.start_soon(drive_encoder(dut, lambda c: angle_at(c) % (1 << N), disc=Disc(N)))
    driver = DRIVERS["odrive"]
    master = driver.master(dut, CLK_HZ)
    quarter = 1 / (4 * rpm * RPM)   # clocks between edges of the sync track
    settle, measure = max(SETTLE, 4 * quarter), max(MEASURE, 4 * quarter)
    begin = ACQUIRE + RAMP + settle
    ours, coarse = [], []
    while get_sim_time("ns") / PERIOD_NS < begin + measure:
        angle, opened_ns = await driver.read(master)
        clock = opened_ns / PERIOD_NS
        truth = float(angle_at(clock))
        if clock >= begin and angle is not None:
            ours.append(wrap(angle * LSB - truth))
            coarse.append(wrap(np.floor(truth * 4) / 4 - truth))
        await master.wait_ns(r.uniform(5_000, 15_000))

    def stale(seconds: float) -> list[float]:
        """A perfect 14-bit angle, `seconds` old when the frame that carries it opens."""
        return stats([wrap(np.floor(float(angle_at(c - seconds * CLK_HZ)) / LSB) * LSB - float(angle_at(c)))
                      for c in np.linspace(begin, begin + measure, 400)])
    result = {"rpm": rpm, "frames": len(ours), "ours": stats(ours), "coarse": stats(coarse),
              "as5047p_8khz": stale(125e-6), "as5047p_30khz": stale(33.3e-6)}
    dut._log.info("%s", result)
    with open(os.environ["BENCH_OUT"], "w") as f:
        json.dump(result, f)
