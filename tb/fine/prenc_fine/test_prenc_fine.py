# SPDX-License-Identifier: Apache-2.0
"""prenc_fine (prenc_velocity, prenc_fine_position, and with CAL = 1 prenc_cal_lookup)
against the models.

Expected values come from prenc.fine.fine.Fine (prenc.fine.velocity.Velocity,
prenc.fine.fine_position.FinePosition and prenc.cal.lookup.CalLookup), clock by clock.
The stimulus is what the core gives the block on a disc that starts at rest,
accelerates, turns, reverses smoothly and at once, wanders, stops and starts again; a
few illegal transitions (missed states) and stretches without pos_valid are mixed in.
Each run draws its stimulus; PRENC_FINE_SEED=<seed> replays the draw a failure names.
A small WINDOW makes the velocity's windows close often (tb/fine/prenc_velocity covers
its program). With CAL = 1 the disc is a printed one and the block reads its
calibration table from a file; the stimulus rewrites some of its words (a little off)
while the disc turns, some near the quarter in use.
"""

from __future__ import annotations

import os

import numpy as np
import pytest
import cocotb

from common import clock_and_check, rng, start_clock_and_reset
from prenc.cal.table import Table, read
from prenc.fine.fine import Fine
from prenc.virtual.edge_timing import true_corrections
from prenc.virtual.fine_bench import sync_stream
from prenc.virtual.printing import Printing
from prenc.virtual.trajectory import Trajectory
from runner import SIM_BUILD, SIMULATORS, run

TOPLEVEL = "prenc_fine"
N, FINE_BITS, LOOKAHEAD_HALVES, WINDOW = 6, 6, 21, 64
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
            .accelerate(-0.01, 9000)           # a long, even reversal
            .random_walk(8000, max_speed=0.03, seed=seed, knot_seconds=600)
            .accelerate(0.0, 1500)             # a stop
            .rest(3000)
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
    return {"velocity": vel.velocity & 0xFFFF_FFFF, "velocity_valid": vel.valid,
            "fine_pos": model.fine_pos, "fine_valid": model.fine_valid,
            "interpolated": model.interpolated}


@cocotb.test()
async def matches_the_models_clock_by_clock(dut):
    seed = int(os.environ.get("PRENC_FINE_SEED", rng().randrange(1 << 30)))  # replay a draw
    cal, edge_tolerance = int(dut.CAL.value), int(dut.EDGE_TOLERANCE.value)
    inputs, total = stimulus(seed, cal)
    table = read(os.environ["PRENC_CAL_FILE"], n=N).c if cal else None
    model = Fine(n=N, fine_bits=FINE_BITS, lookahead_halves=LOOKAHEAD_HALVES, window=WINDOW,
                 cal=cal, table=table, edge_tolerance=edge_tolerance)
    names = ("pos_hyb", "pos_valid", "step", "step_cw", "illegal", "cal_write", "cal_address",
             "cal_data")
    await start_clock_and_reset(dut, RESET_CLOCKS, {k: 0 for k in names})
    stops = looked_up = interpolated = outside = 0
    columns = [inputs[k].tolist() for k in names]
    for c in range(total):
        now = dict(zip(names, (col[c] for col in columns)))
        before = model.velocity.velocity
        model.clock(now["pos_hyb"], now["pos_valid"], now["step"], now["step_cw"], now["illegal"],
                    write=now["cal_write"], address=now["cal_address"],
                    data=now["cal_data"] - ((now["cal_data"] & 0x8000) << 1))
        stops += int(before != 0 and model.velocity.velocity == 0)
        looked_up += int(cal and model.lookup.ok)
        interpolated += model.interpolated
        outside += int(model.interpolated and (model.fine_pos >> FINE_BITS) != model.fine.b[1])
        await clock_and_check(dut, now, expected(model), lambda: f"seed {seed}, clock {c}")
    dut._log.info("seed %d, CAL %d, EDGE_TOLERANCE %d: %d clocks, %d stops, %d interpolated (%d "
                  "outside the quarter: the extrapolation), %d with both words of the table, %d "
                  "steps that kept their phase", seed, cal, edge_tolerance, total, stops,
                  interpolated, outside, looked_up, model.fine.kept)
    assert stops >= 2 and interpolated > total // 2 and outside > 0
    assert not cal or looked_up > 0.9 * total
    assert (model.fine.kept > 100) == bool(edge_tolerance)


@pytest.mark.parametrize("cal, edge_tolerance", [(0, 0), (1, 0), (1, 5)])
@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_fine(simulator, cal, edge_tolerance):
    parameters = {"N": N, "FINE_BITS": FINE_BITS, "LOOKAHEAD_HALVES": LOOKAHEAD_HALVES,
                  "WINDOW": WINDOW, "CAL": cal, "EDGE_TOLERANCE": edge_tolerance}
    env = {}
    if cal:
        parameters["CAL_FILE"] = env["PRENC_CAL_FILE"] = cal_file()
    run(__file__, TOPLEVEL, simulator, parameters=parameters, extra_env=env)
