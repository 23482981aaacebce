# SPDX-License-Identifier: Apache-2.0
"""prenc_velocity (its engine, its program, the registers around them) against the
model prenc.fine.velocity.Velocity, clock by clock.

The stimulus is what the quadrature decoder gives the block on a disc that starts at
rest, accelerates, turns, reverses smoothly and at once, wanders, stops, crawls and
starts again; a few illegal transitions are mixed in, outside the crawl, which is held
long enough for the running mean to settle (every draw runs the settled weight: 200
draws of the model checked). With CAL = 1 the disc is a
printed one and the corrections of each quarter's edges come with its steps, as
prenc_fine gives them from the calibration table; with EDGE_TOLERANCE and CAL = 0 the
disc is the same printed one, without its table. A small WINDOW makes the windows
close often. The test counts the instructions the program ran, and requires every
one of them but the drop of an old anchor (2^30 clocks; sim/tests/fine has it) and the
test for whole cycles, which the run with EDGE_TOLERANCE requires.
Each run draws its stimulus; PRENC_VELOCITY_SEED=<seed> replays a draw.
"""

from __future__ import annotations

import os

import numpy as np
import pytest
import cocotb

from common import clock_and_check, rng, start_clock_and_reset
from prenc.fine.program import PROGRAM, SOURCE
from prenc.fine.velocity import Velocity
from prenc.virtual.edge_timing import true_corrections
from prenc.virtual.fine_bench import POSITION_DELAY, sync_stream
from prenc.virtual.printing import Printing
from prenc.virtual.trajectory import Trajectory
from runner import SIMULATORS, run

TOPLEVEL = "prenc_velocity"
N, WINDOW = 6, 64
RESET_CLOCKS = 3
PRINTED = Printing(edge_error=0.03, phase_deg=5, duty_a=0.47, duty_b=0.53, eccentricity=0.05,
                   seed=38)
# The drop of an old anchor (2^30 clocks without a step): FLAG ANCH 0, JMP IDLE.
OLD_ANCHOR = [k for k, row in enumerate(SOURCE) if row[1:] == ("FLAG", "ANCH", 0)][0]
NEVER = (OLD_ANCHOR, OLD_ANCHOR + 1)
# The test for whole cycles, which only EDGE_TOLERANCE > 0 runs.
_FIRST = next(k for k, row in enumerate(SOURCE) if row[1:] == ("JMP", "NOT_NEG", "CLOSE")) + 1
WHOLE_CYCLES = tuple(range(_FIRST, next(k for k, row in enumerate(SOURCE) if row[0] == "CLOSE")))
# The running mean's settled weight and its trend counts, which only CAL = 1 with
# EDGE_TOLERANCE > 0 runs (C_TREND > 0).
_LABEL = {row[0]: k for k, row in enumerate(SOURCE) if row[0]}
SETTLING = tuple(sorted(
    [k for k, row in enumerate(SOURCE)
     if row[1:] in (("STORE", "UP_LEFT"), ("STORE", "DOWN_LEFT"), ("JMP", "ALWAYS", "COUNT"))]
    + list(range(_LABEL["COUNT"], _LABEL["COUNTED"])) + list(range(_LABEL["SETTLED"], _LABEL["MEAN"]))))


def stimulus(seed: int, cal: int, printed: bool) -> dict[str, np.ndarray]:
    """The decoder's outputs and the corrections, clock by clock (clk_hz = 1)."""
    r = np.random.default_rng(seed)
    traj = (Trajectory(clk_hz=1, start=10.4)
            .rest(300)
            .accelerate(0.01, 1000)            # an even stop, before any illegal transition:
            .accelerate(0.0, 2500)             # fits below 0
            .rest(400)
            .accelerate(0.02, 3000)            # a ramp from rest
            .constant(0.02, 3000)
            .accelerate(0.0, 200)              # another hard stop
            .rest(800)
            .accelerate(0.02, 800)
            .accelerate(-0.015, 4000)          # a smooth reversal
            .constant(-0.015, 2000)
            .constant(0.01, 2500)              # a reversal at once
            .constant(0.01, 2000)              # steps up, then a slow acceleration:
            .constant(0.02, 600)               # windows that agree, a speed that does
            .accelerate(0.021, 3000)           # not (the fit before was off)
            .constant(0.012, 600)
            .accelerate(0.0125, 3000)
            .random_walk(8000, max_speed=0.03, seed=seed, knot_seconds=600)
            .accelerate(0.0, 1500)             # a stop
            .rest(3000)
            .constant(0.01, 1500)              # an abrupt stop: overdue, bounded, stopped
            .rest(2000))
    crawl = (len(traj), len(traj.constant(-0.004, 8000)))   # a crawl held long enough
    traj = (traj.rest(600)                     # to settle (no illegal transition in it);
            .constant(-0.004, 1000)            # stopped at once
            .accelerate(-0.03, 3000))
    sync = sync_stream(traj.theta, PRINTED if printed else None, n=N)
    total = len(traj.theta)
    illegal = np.zeros(total, dtype=np.int8)
    clocks = np.concatenate([np.arange(5000, crawl[0]), np.arange(crawl[1], total - 10)])
    for c in r.choice(clocks, size=4, replace=False):
        illegal[c] = 1
    step = np.where(illegal == 1, 0, sync.step)
    # The decoder's quarter after each step: pos_hyb, POSITION_DELAY clocks later.
    quarter = np.concatenate([sync.pos_hyb[POSITION_DELAY:], np.full(POSITION_DELAY, sync.pos_hyb[-1])])
    c_lo = np.zeros(total, dtype=np.int64)
    c_hi = np.zeros(total, dtype=np.int64)
    if cal:
        c = np.round((true_corrections(PRINTED, N) - true_corrections(PRINTED, N).mean()) * 4096)
        c = c.astype(np.int64)
        c_lo, c_hi = c[quarter % len(c)], c[(quarter + 1) % len(c)]
    return {"step": step, "step_cw": sync.cw, "illegal": illegal, "c_lo": c_lo & 0xFFFF,
            "c_hi": c_hi & 0xFFFF, "c_lo_signed": c_lo, "c_hi_signed": c_hi}


@cocotb.test()
async def matches_the_model_clock_by_clock(dut):
    seed = int(os.environ.get("PRENC_VELOCITY_SEED", rng().randrange(1 << 30)))
    cal, edge_tolerance = int(dut.CAL.value), int(dut.EDGE_TOLERANCE.value)
    inputs = stimulus(seed, cal, printed=bool(cal or edge_tolerance))
    total = len(inputs["step"])
    model = Velocity(window=WINDOW, cal=cal, edge_tolerance=edge_tolerance)
    names = ("step", "step_cw", "illegal", "c_lo", "c_hi")
    await start_clock_and_reset(dut, RESET_CLOCKS, {k: 0 for k in names})
    ran = [0] * len(PROGRAM)
    columns = [inputs[k].tolist() for k in names]
    lo_s, hi_s = inputs["c_lo_signed"].tolist(), inputs["c_hi_signed"].tolist()
    for c in range(total):
        now = dict(zip(names, (col[c] for col in columns)))
        ran[model.engine.pc] += 1
        model.clock(now["step"], now["step_cw"], now["illegal"], 0, lo_s[c], hi_s[c])
        expected = {"velocity": model.velocity & 0xFFFF_FFFF, "valid": model.valid}
        await clock_and_check(dut, now, expected, lambda: f"seed {seed}, clock {c}")
    if edge_tolerance:   # the rest of the program: the runs without EDGE_TOLERANCE
        missing = [k for k in WHOLE_CYCLES + (SETTLING if cal else ()) if ran[k] == 0]
    else:
        missing = [k for k, n in enumerate(ran) if n == 0 and k not in NEVER + WHOLE_CYCLES + SETTLING]
    dut._log.info("seed %d, CAL %d, EDGE_TOLERANCE %d: %d clocks; instructions never run: %s",
                  seed, cal, edge_tolerance, total,
                  [(k, SOURCE[k]) for k in missing])
    assert not missing


@pytest.mark.parametrize("cal, edge_tolerance", [(0, 0), (1, 0), (0, 31), (1, 5)])
@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_velocity(simulator, cal, edge_tolerance):
    run(__file__, TOPLEVEL, simulator, parameters={"WINDOW": WINDOW, "CAL": cal,
                                                   "EDGE_TOLERANCE": edge_tolerance})
