# SPDX-License-Identifier: Apache-2.0
"""prenc_fine (prenc_velocity, prenc_divider, prenc_fine_position) against the models.

Expected values come from prenc.fine.velocity.Velocity and
prenc.fine.fine_position.FinePosition, clock by clock. The stimulus is what the core
gives the block on a disc that starts at rest, accelerates, turns, reverses smoothly
and at once, wanders, stops longer than the velocity's time-out and starts again; a
few illegal transitions (missed states) and stretches without pos_valid are mixed in.
Each run draws its stimulus; PRENC_FINE_SEED=<seed> replays the draw a failure names.
A small WINDOW and TIMER_BITS make every step of the sequencer (the mean, the
constant-speed test, the fit, the decay after an overdue edge, the hold at zero
speed before a reversal, the stop, the time-out) happen in a short run; the test
counts them.
"""

from __future__ import annotations

import os

import numpy as np
import pytest
import cocotb

from common import clock_and_check, rng, start_clock_and_reset
from prenc.fine.fine_position import FinePosition
from prenc.fine.velocity import ACCEL_BITS, VELOCITY_BITS, Velocity
from prenc.virtual.fine_bench import sync_stream
from prenc.virtual.trajectory import Trajectory
from runner import SIMULATORS, run

TOPLEVEL = "prenc_fine"
N, FINE_BITS, LOOKAHEAD_HALVES, WINDOW, TIMER_BITS = 6, 6, 21, 96, 12
RESET_CLOCKS = 3


def stimulus(seed: int) -> tuple[dict[str, np.ndarray], int]:
    """The core's outputs to the block, clock by clock (clk_hz = 1: slots per clock)."""
    r = np.random.default_rng(seed)
    traj = (Trajectory(clk_hz=1, start=10.4)
            .rest(300)
            .accelerate(0.02, 3000)            # a ramp from rest
            .constant(0.02, 3000)
            .accelerate(-0.015, 4000)          # a smooth reversal
            .constant(-0.015, 2000)
            .constant(0.01, 2500)              # a reversal at once
            .accelerate(-0.01, 9000)           # a long, even reversal: fitted, held at 0
            .random_walk(8000, max_speed=0.03, seed=seed, knot_seconds=600)
            .accelerate(0.0, 1500)             # a stop, longer than the time-out
            .rest((1 << TIMER_BITS) + 500)
            .constant(-0.004, 6000)            # a crawl
            .accelerate(-0.03, 3000))
    theta = traj.theta
    sync = sync_stream(theta, None, n=N)
    total = len(theta)
    illegal = np.zeros(total, dtype=np.int8)
    even_reversal = (14_800, 24_000)   # kept free of them, so that a fit is held at 0 there
    outside = np.r_[2000:even_reversal[0], even_reversal[1]:total - 10]
    for c in r.choice(outside, size=4, replace=False):
        illegal[c] = 1
    step = np.where(illegal == 1, 0, sync.step)
    valid = np.ones(total, dtype=np.int8)
    for c in r.choice(np.arange(1000, total - 600), size=3, replace=False):
        valid[c:c + int(r.integers(50, 500))] = 0
    return {"pos_hyb": sync.pos_hyb, "pos_valid": valid, "step": step, "step_cw": sync.cw,
            "illegal": illegal}, total


@cocotb.test()
async def matches_the_models_clock_by_clock(dut):
    seed = int(os.environ.get("PRENC_FINE_SEED", rng().randrange(1 << 30)))  # replay a draw
    inputs, total = stimulus(seed)
    vel = Velocity(window=WINDOW, timer_bits=TIMER_BITS)
    fine = FinePosition(n=N, fine_bits=FINE_BITS, lookahead_halves=LOOKAHEAD_HALVES)
    names = ("pos_hyb", "pos_valid", "step", "step_cw", "illegal")
    await start_clock_and_reset(dut, RESET_CLOCKS, {k: 0 for k in names})
    seen = {state: 0 for state in range(13)}
    stops = holds = 0
    columns = [inputs[k].tolist() for k in names]
    for c in range(total):
        now = dict(zip(names, (col[c] for col in columns)))
        fine.clock(now["pos_hyb"], now["pos_valid"], now["step"], now["step_cw"], vel.velocity, vel.valid)
        before = vel.velocity
        vel.clock(now["step"], now["step_cw"], now["illegal"])
        seen[vel.state] += 1
        stops += int(before != 0 and vel.velocity == 0)
        holds += vel.held
        expected = {"velocity": vel.velocity & ((1 << VELOCITY_BITS) - 1),
                    "accel": vel.accel & ((1 << ACCEL_BITS) - 1),
                    "velocity_valid": vel.valid, "fine_pos": fine.fine_pos, "fine_valid": fine.valid,
                    "interpolated": fine.interpolated}
        await clock_and_check(dut, now, expected, lambda: f"seed {seed}, clock {c}")
    dut._log.info("seed %d: %d clocks, cycles per sequencer state %s, %d stops, %d clocks held",
                  seed, total, seen, stops, holds)
    assert all(seen[s] > 0 for s in range(13)), seen   # every state of the sequencer ran
    assert stops >= 2 and holds > 0


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_fine(simulator):
    run(__file__, TOPLEVEL, simulator,
        parameters={"N": N, "FINE_BITS": FINE_BITS, "LOOKAHEAD_HALVES": LOOKAHEAD_HALVES,
                    "WINDOW": WINDOW, "TIMER_BITS": TIMER_BITS})
