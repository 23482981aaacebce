# SPDX-License-Identifier: Apache-2.0
"""prenc_fine_position alone against its model, at every width the block allows.

Expected values come from prenc.fine.fine_position.FinePosition, clock by clock. The
stimulus is drawn at random rather than from a disc, so that every input takes values
a disc rarely gives: corrections of a quarter's edges over the table's whole range
(+-8 quarters, the quarter kept wider than nothing: the formal proof's assumption),
velocities up to the port's range, steps either way, stretches without a valid
velocity or position. tb/fine/prenc_fine runs the block inside prenc_fine on a disc.

N goes to both ends of its range with FINE_BITS = 8: the fine position is then up to
34 bits, wider than the block's fraction and extrapolation, which must reach it
sign-extended (a quarter whose middle is below its own start, with a table, is a
negative fraction).
Each run draws its stimulus; PRENC_FINE_SEED=<seed> replays the draw a failure names.
"""

from __future__ import annotations

import os

import numpy as np
import pytest
import cocotb

from common import clock_and_check, rng, start_clock_and_reset
from prenc.fine.fine_position import OUTPUT_DELAY, FinePosition
from runner import SIMULATORS, run

TOPLEVEL = "prenc_fine_position"
FINE_BITS, LOOKAHEAD_HALVES = 8, 255
CLOCKS = 6000
RESET_CLOCKS = 3


def stimulus(seed: int, n: int) -> dict[str, np.ndarray]:
    r = np.random.default_rng(seed)
    quarters = 4 << n
    # pos_hyb walks a quarter at a time, sometimes jumps; steps come at random.
    moves = r.choice([-1, 0, 0, 0, 1], size=CLOCKS)
    jumps = r.random(CLOCKS) < 0.002
    moves[jumps] = r.integers(0, quarters, size=int(jumps.sum()))
    pos_hyb = (int(r.integers(0, quarters)) + np.cumsum(moves)) % quarters
    step = (r.random(CLOCKS) < 0.05).astype(np.int64)
    step_cw = (r.random(CLOCKS) < 0.6).astype(np.int64)
    # The velocity holds for a while, then changes: mostly a disc's (below 1/16 quarter
    # a clock), sometimes anywhere in the port's range.
    velocity = np.zeros(CLOCKS, dtype=np.int64)
    c = 0
    while c < CLOCKS:
        length = int(r.integers(1, 400))
        if r.random() < 0.2:
            v = int(r.integers(-(1 << 31), 1 << 31))
        else:
            v = int(r.integers(-(1 << 28), 1 << 28))
        velocity[c:c + length] = v
        c += length
    # The corrections (2^-12 quarter, 16 bits): small, or anywhere with c_hi + 1 > c_lo.
    c_lo = np.where(r.random(CLOCKS) < 0.5, r.integers(-800, 800, size=CLOCKS),
                    r.integers(-(1 << 15) + 1, 1 << 15, size=CLOCKS))
    c_hi = np.array([int(r.integers(max(lo - 4095, -(1 << 15) + 1), 1 << 15)) for lo in c_lo])
    low = r.random(CLOCKS) < 0.5
    c_hi[low] = np.maximum(c_lo[low] - 4095, -(1 << 15) + 1) + r.integers(0, 1600, size=int(low.sum()))
    c_hi = np.minimum(c_hi, (1 << 15) - 1)
    velocity_valid = np.ones(CLOCKS, dtype=np.int64)
    pos_valid = np.ones(CLOCKS, dtype=np.int64)
    for flag in (velocity_valid, pos_valid):
        for start in r.choice(np.arange(CLOCKS), size=8, replace=False):
            flag[start:start + int(r.integers(20, 300))] = 0
    return {"pos_hyb": pos_hyb, "pos_valid": pos_valid, "step": step, "step_cw": step_cw,
            "velocity": velocity, "velocity_valid": velocity_valid, "c_lo": c_lo, "c_hi": c_hi}


@cocotb.test()
async def matches_the_model_clock_by_clock(dut):
    seed = int(os.environ.get("PRENC_FINE_SEED", rng().randrange(1 << 30)))  # replay a draw
    n, cal = int(dut.N.value), int(dut.CAL.value)
    inputs = stimulus(seed, n)
    model = FinePosition(n=n, fine_bits=FINE_BITS, lookahead_halves=LOOKAHEAD_HALVES)
    names = ("pos_hyb", "pos_valid", "step", "step_cw", "velocity", "velocity_valid", "c_lo", "c_hi")
    await start_clock_and_reset(dut, RESET_CLOCKS, {k: 0 for k in names})
    columns = [inputs[k].tolist() for k in names]
    outside = 0   # clocks whose fine position is not in the quarter of OUTPUT_DELAY before
    for c in range(CLOCKS):
        now = dict(zip(names, (col[c] for col in columns)))
        model.clock(now["pos_hyb"], now["pos_valid"], now["step"], now["step_cw"], now["velocity"],
                    now["velocity_valid"], c_lo=now["c_lo"] if cal else 0,
                    c_hi=now["c_hi"] if cal else 0)
        outside += int(c >= OUTPUT_DELAY and model.valid
                       and (model.fine_pos >> FINE_BITS) != columns[0][c - OUTPUT_DELAY])
        pins = {k: v & 0xFFFF_FFFF if k == "velocity" else v & 0xFFFF if k.startswith("c_") else v
                for k, v in now.items()}
        await clock_and_check(dut, pins, {"fine_pos": model.fine_pos, "fine_valid": model.valid,
                                          "interpolated": model.interpolated},
                              lambda: f"seed {seed}, N {n}, clock {c}")
    dut._log.info("seed %d, N %d, CAL %d: %d clocks, %d outside the quarter", seed, n, cal,
                  CLOCKS, outside)
    assert outside > CLOCKS // 10


@pytest.mark.parametrize("n, cal", [(6, 1), (16, 1), (24, 1), (24, 0)])
@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_fine_position(simulator, n, cal):
    run(__file__, TOPLEVEL, simulator,
        parameters={"N": n, "FINE_BITS": FINE_BITS, "LOOKAHEAD_HALVES": LOOKAHEAD_HALVES,
                    "CAL": cal})
