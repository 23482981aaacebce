# SPDX-License-Identifier: Apache-2.0
"""Self-calibration against the truth (issue 38): what the table takes out of the fine
position and the velocity, and how many turns it needs.

1. Turns: a calibration run (prenc.virtual.edge_timing.steady_record: the crossings
   of a steady turn on the printed disc, with a speed ripple) through
   prenc.cal.calibrate, for 2 to 20 turns; the table's error against the disc's true
   edges (prenc.virtual.edge_timing.true_corrections, the same zero taken off), RMS and
   max, in slots.
2. Applied: the scenarios of section 9 on the printed disc, through the models of
   rtl/fine/ without and with the table (prenc.fine.fine.Fine with CAL = 1: the table
   block prenc.cal.lookup gives prenc_velocity and prenc_fine_position the corrections
   of their quarters' edges). The table is the one
   a 10-turn run at 70 rpm with a +-2 % ripple at 100 Hz gives. The position error is
   against the true angle less the calibration's zero (the mean of the disc's edge errors, which no
   calibration of one disc can see; a user sets the zero at mounting); the zero is
   printed.
"""

from __future__ import annotations

import numpy as np

from ..cal.calibrate import Result, calibrate
from . import fine_bench as fb
from .edge_timing import steady_record, true_corrections

N = fb.N
CAL_RPM = 70.0
CAL_TURNS = 10
CAL_RIPPLE = (0.02, 100.0)
TURNS = (2, 3, 5, 10, 20)
# (rpm, ripple, ripple Hz) of the turns table; 600 rpm at 100 Hz is locked to the turn.
RUNS = ((70.0, 0.0, 100.0), (70.0, 0.02, 100.0), (70.0, 0.02, 37.0), (650.0, 0.02, 100.0),
        (650.0, 0.02, 37.0), (600.0, 0.02, 100.0))


def truth() -> np.ndarray:
    """The printed disc's true corrections (quarters), before the zero is taken off."""
    return true_corrections(fb.PRINTED, N)


def table_error(result: Result, c_true: np.ndarray) -> tuple[float, float]:
    err = (result.table.quarters - (c_true - c_true.mean())) / 4
    return float(np.sqrt(np.mean(err * err))), float(np.max(np.abs(err)))


def turns_rows(c_true: np.ndarray) -> list[tuple[tuple[float, float, float], list[tuple[float, float]]]]:
    """Per run of RUNS: the table's error (slots RMS, max) after each count of TURNS."""
    rows = []
    for rpm, ripple, hz in RUNS:
        record = steady_record(c_true, N, rpm, max(TURNS) + 0.1, clk_hz=fb.CLK_HZ, ripple=ripple,
                               ripple_hz=hz, start_edge=1234, ripple_phase=0.7)
        rows.append(((rpm, ripple, hz), [table_error(calibrate(record, k), c_true) for k in TURNS]))
    return rows


def bench_table(c_true: np.ndarray) -> Result:
    record = steady_record(c_true, N, CAL_RPM, CAL_TURNS + 0.1, clk_hz=fb.CLK_HZ,
                           ripple=CAL_RIPPLE[0], ripple_hz=CAL_RIPPLE[1], start_edge=1234,
                           ripple_phase=0.7)
    return calibrate(record, CAL_TURNS)


def evaluate(case: fb.Case, table_c: np.ndarray, zero: float, sensors=(),
             edge_tolerance: int = 0) -> dict[str, fb.Row]:
    """The printed disc without and with the table (prenc_fine with CAL = 1: the table
    block prenc.cal.lookup gives prenc_velocity and prenc_fine_position the corrections
    of their quarters' edges), beside the baselines (without the table: they have none);
    `zero` (slots) is the calibration's zero against the truth, taken off the calibrated
    position's error; `sensors`: prenc.virtual.sensors' effects on A and B;
    `edge_tolerance`: the calibrated run's EDGE_TOLERANCE."""
    sync = fb.sync_stream(case.theta, fb.PRINTED, sensors=sensors)
    scale = 1 << fb.FINE_BITS
    plain = fb.run_fine(sync)
    cal = fb.run_fine(sync, table=table_c, edge_tolerance=edge_tolerance)
    rows = {"coarse": fb.score(case, sync, sync.pos_hyb.astype(np.float64), np.zeros(len(case.theta))),
            "uncalibrated": fb.score(case, sync, plain["fine"] / scale, plain["velocity"]),
            "calibrated": fb.score(case, sync, cal["fine"] / scale - 4 * zero, cal["velocity"])}
    return rows
