# SPDX-License-Identifier: Apache-2.0
"""prenc_edge_capture against prenc.cal.edge_capture,
clock by clock, and against the disc: the edges a steady turn's record holds are the
ones the disc crossed, and their intervals the clocks between the crossings.

The stimulus is what the core gives the block on a disc that turns both ways at
changing speeds (prenc.virtual.fine_bench.sync_stream), with illegal transitions and
stretches without pos_valid; the host link's takes come at random, sometimes too
seldom for the FIFO (entries are lost, and `lost` says so)."""

from __future__ import annotations

import numpy as np
import pytest
import cocotb

from common import clock_and_check, rng, start_clock_and_reset
from prenc.cal.edge_capture import EdgeCapture
from prenc.virtual.fine_bench import sync_stream
from prenc.virtual.trajectory import Trajectory
from runner import SIMULATORS, run

TOPLEVEL = "prenc_edge_capture"
N = 6


def stimulus(seed: int) -> dict[str, np.ndarray]:
    r = np.random.default_rng(seed)
    traj = (Trajectory(clk_hz=1, start=3.3).rest(50).accelerate(0.05, 2000).constant(0.05, 3000)
            .accelerate(-0.2, 3000).constant(-0.2, 1500).accelerate(0.01, 3000)
            .random_walk(6000, max_speed=0.1, seed=seed, knot_seconds=500))
    sync = sync_stream(traj.theta, None, n=N)
    total = len(traj.theta)
    illegal = (r.random(total) < 0.0005).astype(np.int8)
    valid = np.ones(total, dtype=np.int8)
    for c in r.choice(np.arange(100, total - 300), size=3, replace=False):
        valid[c:c + int(r.integers(20, 200))] = 0
    # Takes: often at first, then seldom (the FIFO overflows at the fast part).
    rate = np.where(np.arange(total) < total // 3, 0.3, 0.02)
    take = (r.random(total) < rate).astype(np.int8)
    return {"step": np.where(illegal == 1, 0, sync.step), "step_cw": sync.cw, "illegal": illegal,
            "pos_hyb": sync.pos_hyb, "pos_valid": valid, "take": take}


@cocotb.test()
async def matches_the_model(dut):
    seed = rng().randrange(1 << 30)
    inputs = stimulus(seed)
    names = ("step", "step_cw", "illegal", "pos_hyb", "pos_valid", "take")
    await start_clock_and_reset(dut, 2, {k: 0 for k in names})
    model = EdgeCapture(N)
    columns = [inputs[k].tolist() for k in names]
    runs = losts = 0
    for c in range(len(columns[0])):
        now = dict(zip(names, (col[c] for col in columns)))
        model.clock(**now)
        run_ = model.run()
        expected = {"run": len(run_), "lost": model.lost}
        intervals = [e.interval for e in run_] + [0] * (3 - len(run_))
        expected.update(interval0=intervals[0], interval1=intervals[1], interval2=intervals[2])
        if run_:
            expected.update(run_valid=run_[0].valid, run_cw=run_[0].cw, run_edge=run_[0].edge)
        runs += len(run_) == 3
        losts += model.lost
        await clock_and_check(dut, now, expected, lambda: f"seed {seed}, clock {c}")
    assert runs > 100 and losts > 0, (runs, losts)


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_edge_capture(simulator):
    run(__file__, TOPLEVEL, simulator, parameters={"N": N})
