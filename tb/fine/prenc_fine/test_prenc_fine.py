# SPDX-License-Identifier: Apache-2.0
"""prenc_fine (prenc_velocity, prenc_divider, prenc_fine_position, and with CAL = 1
prenc_cal_lookup) against the models.

Expected values come from prenc.fine.fine.Fine (prenc.fine.velocity.Velocity,
prenc.fine.fine_position.FinePosition and prenc.cal.lookup.CalLookup), clock by clock. The stimulus is what the core
gives the block on a disc that starts at rest, accelerates, turns, reverses smoothly
and at once, wanders, stops longer than the velocity's time-out and starts again; a
few illegal transitions (missed states) and stretches without pos_valid are mixed in.
Each run draws its stimulus; PRENC_FINE_SEED=<seed> replays the draw a failure names.
A small WINDOW and TIMER_BITS make every step of the sequencer (the mean, the
constant-speed test, the fit, the decay after an overdue edge, the hold at zero
speed before a reversal, the stop, the time-out) happen in a short run; the test
counts them. With CAL = 1 the disc is a printed one and the block reads its calibration
table from a file; the stimulus rewrites some of its words (a little off) while the
disc turns, some near the quarter in use. With QUARTER_WINDOWS = 1 the windows close on
any edge, and the test counts the decisions: a window joining a run, a fit, a fit at a
single large failure and a first small failure (the window's own mean). With
ACCEL_FIT = 0 (no fit, the small FPGA's velocity) every close loads the mean over two
windows: the sequencer's states without the multiplier run, and nothing is held. With
TRACKER = 1 the velocity is prenc_tracker's (prenc.fine.tracker.Tracker, its gain table
for N = 6 at 100 kHz, as in tb/fine/prenc_tracker), and the test counts its updates and
stops instead; with CAL = 1 as well, the steps whose edge the table moves by another
correction than the last edge's (the tracker's measured distance is not a whole quarter).
With TRACKER = 2 the fine position between edges is the tracker's filtered position
(its offset, delayed to meet the step prenc_fine_position takes: 2 clocks, none with
CAL = 1), and the test counts the clocks it is taken. With PERIOD = 1 the velocity is
prenc_period's (prenc.fine.period.Period), and the test counts its divisions for a step
and for a bound (overdue), its stops after four intervals without a step and its
reversals.
"""

from __future__ import annotations

import os

import numpy as np
import pytest
import cocotb

from common import clock_and_check, rng, start_clock_and_reset
from prenc.cal.table import Table, read
from prenc.fine import tracker_gains
from prenc.fine.fine import Fine
from prenc.fine.velocity import ACCEL_BITS, VELOCITY_BITS
from prenc.virtual.edge_timing import true_corrections
from prenc.virtual.fine_bench import sync_stream
from prenc.virtual.printing import Printing
from prenc.virtual.trajectory import Trajectory
from runner import SIM_BUILD, SIMULATORS, gains_file, run

TOPLEVEL = "prenc_fine"
N, FINE_BITS, LOOKAHEAD_HALVES, WINDOW, TIMER_BITS = 6, 6, 21, 96, 12
RESET_CLOCKS = 3
PRINTED = Printing(edge_error=0.03, phase_deg=5, duty_a=0.47, duty_b=0.53, eccentricity=0.05,
                   seed=38)


def cal_table() -> Table:
    """The printed disc's table, as a perfect calibration would find it."""
    c = true_corrections(PRINTED, N)
    return Table.from_quarters(N, c - c.mean())


def cal_file() -> str:
    """The table's file, where builds that name it are reused."""
    return str(cal_table().write(SIM_BUILD / "roms" / f"prenc_cal_n{N}_printed.hex"))


def stimulus(seed: int, cal: int) -> tuple[dict[str, np.ndarray], int]:
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
            .rest(600)                         # stopped at once
            .constant(-0.004, 1000)
            .accelerate(-0.03, 3000))
    theta = traj.theta
    sync = sync_stream(theta, PRINTED if cal else None, n=N)
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
    # With CAL: words of the table rewritten a little off while the disc turns, near the
    # quarter in use half of the time (so that a slot is emptied).
    write = np.zeros(total, dtype=np.int8)
    address = np.zeros(total, dtype=np.int64)
    data = np.zeros(total, dtype=np.int64)
    if cal:
        table = cal_table().c
        for c in r.choice(np.arange(100, total - 10), size=400, replace=False):
            near = int(sync.pos_hyb[c]) + int(r.integers(-2, 3))
            write[c] = 1
            address[c] = (near if r.random() < 0.5 else int(r.integers(0, 4 << N))) % (4 << N)
            data[c] = (int(table[address[c]]) + int(r.integers(-20, 21))) & 0xFFFF
    return {"pos_hyb": sync.pos_hyb, "pos_valid": valid, "step": step, "step_cw": sync.cw,
            "illegal": illegal, "cal_write": write, "cal_address": address, "cal_data": data}, total


def expected(model: Fine) -> dict[str, int]:
    """The block's outputs after this clock, from the model (as the port widths hold them)."""
    vel = model.velocity
    return {"velocity": vel.velocity & ((1 << VELOCITY_BITS) - 1),
            "accel": vel.accel & ((1 << ACCEL_BITS) - 1),
            "velocity_valid": vel.valid, "fine_pos": model.fine_pos,
            "fine_valid": model.fine_valid, "interpolated": model.interpolated}


@cocotb.test()
async def matches_the_models_clock_by_clock(dut):
    seed = int(os.environ.get("PRENC_FINE_SEED", rng().randrange(1 << 30)))  # replay a draw
    cal = int(dut.CAL.value)
    quarter = int(dut.QUARTER_WINDOWS.value)
    fit = int(dut.ACCEL_FIT.value)
    tracker = int(dut.TRACKER.value)
    period = int(dut.PERIOD.value)
    inputs, total = stimulus(seed, cal)
    table = read(os.environ["PRENC_CAL_FILE"], n=N).c if cal else None
    gains = tracker_gains.read(os.environ["PRENC_GAIN_FILE"]) if tracker else None
    model = Fine(n=N, fine_bits=FINE_BITS, lookahead_halves=LOOKAHEAD_HALVES, window=WINDOW,
                 timer_bits=TIMER_BITS, cal=cal, table=table, quarter_windows=quarter,
                 accel_fit=fit, gains=gains, filtered=int(tracker == 2), period=period)
    vel = model.velocity
    if period:
        await period_matches(dut, model, inputs, total, seed)
        return
    if tracker:
        await tracker_matches(dut, model, inputs, total, seed, cal, tracker)
        return
    names = ("pos_hyb", "pos_valid", "step", "step_cw", "illegal", "cal_write", "cal_address",
             "cal_data")
    await start_clock_and_reset(dut, RESET_CLOCKS, {k: 0 for k in names})
    all_states = range(vel.SUMS + 1)   # the sequencer's, IDLE .. SUMS
    seen = {state: 0 for state in all_states}
    stops = holds = looked_up = 0
    decisions = {"run": 0, "fit": 0, "fit at once": 0, "one failure": 0}
    columns = [inputs[k].tolist() for k in names]
    for c in range(total):
        now = dict(zip(names, (col[c] for col in columns)))
        before = vel.velocity
        deciding, last_fit, run_before = vel.state == vel.DECIDE, vel.last_fit, vel.prev_clocks
        model.clock(now["pos_hyb"], now["pos_valid"], now["step"], now["step_cw"], now["illegal"],
                    write=now["cal_write"], address=now["cal_address"],
                    data=now["cal_data"] - ((now["cal_data"] & 0x8000) << 1))
        seen[vel.state] += 1
        if deciding and vel.state == vel.FIT_V01:
            decisions["fit" if last_fit else "fit at once"] += 1
        elif deciding and vel.prev_clocks != run_before:
            decisions["run"] += 1
        elif deciding and vel.last_fit and not last_fit:
            decisions["one failure"] += 1
        stops += int(before != 0 and vel.velocity == 0)
        holds += vel.held
        looked_up += int(cal and model.lookup.ok)
        await clock_and_check(dut, now, expected(model), lambda: f"seed {seed}, clock {c}")
    dut._log.info("seed %d, CAL %d, QUARTER_WINDOWS %d, ACCEL_FIT %d: %d clocks, cycles per "
                  "sequencer state %s, %d stops, %d clocks held, %d with both words of the table, "
                  "decisions %s", seed, cal, quarter, fit, total, seen, stops, holds, looked_up, decisions)
    states = ([vel.IDLE, vel.MEAN, vel.SUMS, vel.DECIDE, vel.CONSTANT, vel.DECAY] if not fit
              else [s for s in all_states if s != vel.SUMS])
    assert all(seen[s] > 0 for s in states), seen   # every state of the sequencer ran
    assert all(seen[s] == 0 for s in all_states if s not in states), seen
    assert stops >= 2 and (holds > 0) == bool(fit)
    assert not cal or looked_up > 0.9 * total
    assert (decisions["fit"] > 0) == bool(fit)
    assert not quarter or min(decisions.values()) > 0, decisions


async def tracker_matches(dut, model: Fine, inputs, total: int, seed: int, cal: int,
                          tracker: int) -> None:
    """TRACKER = 1 or 2: the outputs against the model, clock by clock; prenc_tracker's
    updates and stops counted, and with TRACKER = 2 the clocks the fine position takes
    the tracker's offset."""
    names = ("pos_hyb", "pos_valid", "step", "step_cw", "illegal", "cal_write", "cal_address",
             "cal_data")
    await start_clock_and_reset(dut, RESET_CLOCKS, {k: 0 for k in names})
    vel = model.velocity
    updates = stops = interpolated = corrected = filtered = 0
    columns = [inputs[k].tolist() for k in names]
    for c in range(total):
        now = dict(zip(names, (col[c] for col in columns)))
        seq, phase, c_last = vel.seq, vel.phase, vel.c_last
        filtered += model.offset_taken[1]
        model.clock(now["pos_hyb"], now["pos_valid"], now["step"], now["step_cw"], now["illegal"],
                    write=now["cal_write"], address=now["cal_address"],
                    data=now["cal_data"] - ((now["cal_data"] & 0x8000) << 1))
        updates += int(seq == 0 and vel.seq == 1)
        stops += int(phase == vel.TRACK and vel.phase == vel.NONE)
        corrected += int(vel.c_last != c_last)
        interpolated += model.interpolated
        await clock_and_check(dut, now, expected(model), lambda: f"seed {seed}, clock {c}")
    dut._log.info("seed %d, CAL %d, TRACKER %d: %d clocks, %d updates, %d stops, %d interpolated, "
                  "%d steps corrected, %d clocks filtered", seed, cal, tracker, total, updates, stops,
                  interpolated, corrected, filtered)
    assert updates > 200 and stops >= 2 and interpolated > total // 2
    assert (filtered > total // 4) if tracker == 2 else filtered == 0
    assert (corrected > updates // 2) if cal else corrected == 0


async def period_matches(dut, model: Fine, inputs, total: int, seed: int) -> None:
    """PERIOD = 1: the outputs against the model, clock by clock; prenc_period's
    divisions (for a step, for a bound), stops and reversals counted."""
    names = ("pos_hyb", "pos_valid", "step", "step_cw", "illegal", "cal_write", "cal_address",
             "cal_data")
    await start_clock_and_reset(dut, RESET_CLOCKS, {k: 0 for k in names})
    vel = model.velocity
    divisions = bounds = bounded = stops = reversals = full = interpolated = 0
    columns = [inputs[k].tolist() for k in names]
    for c in range(total):
        now = dict(zip(names, (col[c] for col in columns)))
        busy, moved, timed, cw = vel.busy, vel.moved, vel.timed, vel.cw
        model.clock(now["pos_hyb"], now["pos_valid"], now["step"], now["step_cw"], now["illegal"])
        started = not busy and vel.busy
        divisions += int(started and not vel.bounding)
        bounds += int(started and vel.bounding)
        full += int(started and not vel.bounding and vel.run == 4)
        stops += int(moved and timed and not vel.moved and not now["illegal"])
        reversals += int(now["step"] and moved and now["step_cw"] != cw)
        bounded += int(vel.valid and 0 < vel.bound < vel.speed)   # the bound is shown
        interpolated += model.interpolated
        await clock_and_check(dut, now, expected(model), lambda: f"seed {seed}, clock {c}")
    dut._log.info("seed %d, PERIOD 1: %d clocks, %d divisions for a step (%d of a full cycle), "
                  "%d for a bound, %d clocks bounded, %d stops, %d reversals, %d interpolated", seed, total,
                  divisions, full, bounds, bounded, stops, reversals, interpolated)
    assert divisions > 200 and full > 100 and bounds > 5 and bounded > 20 and stops >= 2 and reversals >= 2
    assert interpolated > total // 2


@pytest.mark.parametrize("cal, quarter, fit, tracker, period", [
    (0, 0, 1, 0, 0), (1, 0, 1, 0, 0), (0, 1, 1, 0, 0), (1, 1, 1, 0, 0), (0, 0, 0, 0, 0), (1, 0, 0, 0, 0),
    (0, 0, 1, 1, 0), (1, 0, 1, 1, 0), (0, 0, 1, 2, 0), (1, 0, 1, 2, 0), (0, 0, 1, 0, 1)])
@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_fine(simulator, cal, quarter, fit, tracker, period):
    parameters = {"N": N, "FINE_BITS": FINE_BITS, "LOOKAHEAD_HALVES": LOOKAHEAD_HALVES,
                  "WINDOW": WINDOW, "TIMER_BITS": TIMER_BITS, "CAL": cal,
                  "QUARTER_WINDOWS": quarter, "ACCEL_FIT": fit, "TRACKER": tracker, "PERIOD": period}
    env = {}
    if cal:
        parameters["CAL_FILE"] = env["PRENC_CAL_FILE"] = cal_file()
    if tracker:
        parameters["GAIN_FILE"] = env["PRENC_GAIN_FILE"] = str(gains_file(N, 1e5))
    run(__file__, TOPLEVEL, simulator, parameters=parameters, extra_env=env)
