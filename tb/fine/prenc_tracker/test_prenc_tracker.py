# SPDX-License-Identifier: Apache-2.0
"""prenc_tracker (with prenc_divider) against its model, prenc.fine.tracker.Tracker,
clock by clock.

The gain table is prenc.fine.tracker_gains's for N = 6 at 100 kHz (600 rpm is 0.0256
quarter per clock), so that the stimulus's speeds cross most of the table's columns.
The stimulus is what the core gives the block on a disc that starts at rest, turns
steadily long enough for the filter's age to reach the table's last bins, changes
speed at once (a maneuver: a jump of the innovation sets the age back and the filter
chases; the innovations' mean halves the age), turns faster than an update takes (steps
that only refer the position: `offset_valid` 0), reverses smoothly and at once (after
which the filter loses the edges, `valid` 0, and finds them again), wanders, stops (an edge
overdue: the decay to 0) and rests, with a lone step in the rest (an anchor and no
second step: the time-out); a few illegal transitions
(missed states) are mixed in, one in the fast stretch (the start again at speed: steps
during the first velocity's division). Each run draws its stimulus; PRENC_TRACKER_SEED=<seed>
replays the draw a failure names. The test counts what it must have exercised.
"""

from __future__ import annotations

import os

import numpy as np
import pytest
import cocotb

from common import clock_and_check, rng, start_clock_and_reset
from prenc.fine import tracker_gains
from prenc.fine.tracker import OFFSET_BITS, Tracker
from prenc.virtual.fine_bench import sync_stream
from prenc.virtual.trajectory import Trajectory
from runner import SIM_BUILD, SIMULATORS, gains_file, run

TOPLEVEL = "prenc_tracker"
N, CLK_HZ, TIMER_BITS = 6, 1e5, 12
RESET_CLOCKS = 3
FAST_ILLEGAL = 25_300          # in the fast stretch (0.06 slot per clock)
# In the rest, after the stop (by the decay, or at the latest by the time-out): an anchor,
# then the time-out.
LONE_STEP = 42_800 + (1 << TIMER_BITS) + 500
REST = (LONE_STEP - 42_800) + (1 << TIMER_BITS) + 1000


def stimulus(seed: int) -> tuple[dict[str, np.ndarray], int]:
    """The core's outputs to the block, clock by clock (clk_hz = 1: slots per clock)."""
    r = np.random.default_rng(seed)
    traj = (Trajectory(clk_hz=1, start=10.4)
            .rest(300)
            .accelerate(0.0075, 2000)          # from rest
            .constant(0.0075, 18000)           # 540 edges: the last bins of the age
            .constant(0.012, 3000)             # a speed change at once: a maneuver
            .accelerate(0.06, 1500)            # faster than an update: steps that only refer
            .constant(0.06, 1000)
            .accelerate(-0.004, 6000)          # a smooth reversal
            .constant(0.004, 3000)             # a reversal at once
            .random_walk(6000, max_speed=0.02, seed=seed, knot_seconds=600)
            .constant(0.002, 2000)
            .rest(REST)                        # a stop (an overdue edge); a lone step (below)
            .constant(-0.001, 6000))           # a crawl
    sync = sync_stream(traj.theta, None, n=N)
    total = len(traj.theta)
    illegal = np.zeros(total, dtype=np.int8)
    for c in r.choice(np.r_[30_000:40_000, LONE_STEP + 5000:total - 10], size=3,
                      replace=False):
        illegal[c] = 1
    illegal[FAST_ILLEGAL] = 1   # the start again at speed: steps during the first division
    step = np.where(illegal == 1, 0, sync.step)
    assert not sync.step[LONE_STEP - 500:LONE_STEP + (1 << TIMER_BITS) + 1].any()
    step[LONE_STEP] = 1
    return {"step": step, "step_cw": sync.cw, "illegal": illegal}, total


@cocotb.test()
async def matches_the_model_clock_by_clock(dut):
    seed = int(os.environ.get("PRENC_TRACKER_SEED", rng().randrange(1 << 30)))  # replay a draw
    inputs, total = stimulus(seed)
    model = Tracker(tracker_gains.read(os.environ["PRENC_GAIN_FILE"]), timer_bits=TIMER_BITS)
    names = ("step", "step_cw", "illegal")
    await start_clock_and_reset(dut, RESET_CLOCKS, {k: 0 for k in names})
    seen = {"updates": 0, "referred only": 0, "maneuvers": 0, "jumps": 0, "chases": 0,
            "decays": 0, "stops": 0,
            "time-outs": 0, "first velocities": 0, "steps while dividing": 0,
            "edges lost": 0, "edges found again": 0, "clocks offset_valid": 0}
    columns, bins = set(), set()
    data = [inputs[k].tolist() for k in names]
    for c in range(total):
        now = dict(zip(names, (col[c] for col in data)))
        before = (model.phase, model.seq, model.decaying, model.bias, model.since, model.jump,
                  model.chase)
        lost = model.lost
        model.clock(now["step"], now["step_cw"], now["illegal"])
        phase, seq, decaying, bias, since, jump, chase = before
        if now["step"] and phase == model.TRACK:
            if seq == 0 and model.seq:
                seen["updates"] += 1
                columns.add(model.address // tracker_gains.BINS)
                bins.add(model.address % tracker_gains.BINS)
                seen["maneuvers"] += int(abs(bias) > 256 and not jump)
                seen["jumps"] += jump
                seen["chases"] += int(chase and not jump and model.chase)   # the age held
            elif seq:
                seen["referred only"] += 1
        seen["steps while dividing"] += int(now["step"] and phase == model.DIVIDE
                                            and model.phase != model.ANCHOR)
        seen["decays"] += int(model.decaying and not decaying)
        seen["stops"] += int(phase == model.TRACK and model.phase == model.NONE and not now["illegal"])
        seen["time-outs"] += int(since == model.timer_max and phase != model.NONE)
        seen["first velocities"] += int(phase == model.DIVIDE and model.phase == model.TRACK)
        seen["edges lost"] += int(model.lost and not lost)
        seen["edges found again"] += int(lost and not model.lost)
        seen["clocks offset_valid"] += model.offset_valid
        expected = {"velocity": model.velocity & ((1 << 51) - 1),
                    "accel": model.accel & ((1 << 50) - 1), "valid": model.valid,
                    "offset": model.offset & ((1 << OFFSET_BITS) - 1), "offset_valid": model.offset_valid}
        await clock_and_check(dut, now, expected, lambda: f"seed {seed}, clock {c}")
    dut._log.info("seed %d: %d clocks, %s, columns %s, age bins %s", seed, total, seen,
                  sorted(columns), sorted(bins))
    assert all(v > 0 for v in seen.values()), seen
    assert max(bins) >= 36 and len(columns) >= 5, (sorted(columns), sorted(bins))


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_tracker(simulator):
    path = str(gains_file(N, 1e5))
    run(__file__, TOPLEVEL, simulator, parameters={"TIMER_BITS": TIMER_BITS, "GAIN_FILE": path},
        extra_env={"PRENC_GAIN_FILE": path})


def bad_gain_file(case: str) -> str:
    """A gain table that is missing, or one word short."""
    path = SIM_BUILD / "roms" / f"prenc_tracker_gains_{case}.hex"
    path.parent.mkdir(parents=True, exist_ok=True)
    if case == "missing":
        path.unlink(missing_ok=True)
    else:
        path.write_text("".join(gains_file(N, CLK_HZ).read_text().splitlines(keepends=True)[:-1]))
    return str(path)


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("case, message", [("missing", "cannot be opened"),
                                           ("short", "1 of 1280 words missing")])
def test_a_bad_gain_file_stops_the_simulation(simulator, case, message, capfd):
    path = bad_gain_file(case)
    with pytest.raises(SystemExit):
        run(__file__, TOPLEVEL, simulator, parameters={"TIMER_BITS": TIMER_BITS, "GAIN_FILE": path},
            extra_env={"PRENC_GAIN_FILE": str(gains_file(N, CLK_HZ))})
    text = "".join(capfd.readouterr())
    assert f'GAIN_FILE "{path}"' in text and message in text


def test_the_model_rejects_a_bad_gain_file(tmp_path):
    short = tmp_path / "short.hex"
    short.write_text("0\n" * (tracker_gains.COLUMNS * tracker_gains.BINS - 1))
    with pytest.raises(ValueError, match="1279 words"):
        tracker_gains.read(short)
    wide = tmp_path / "wide.hex"
    wide.write_text("1" + "0" * 18 + "\n" + "0\n" * (tracker_gains.COLUMNS * tracker_gains.BINS - 1))
    with pytest.raises(ValueError, match="more than 72 bits"):
        tracker_gains.read(wide)
    with pytest.raises(ValueError, match="not 1280"):
        Tracker([0] * 10)
