# SPDX-License-Identifier: Apache-2.0
"""prenc_period's model (prenc_fine's PERIOD = 1, the small FPGA's velocity) against the
truth of the virtual encoder.

Expected values come from the trajectory (the true speed and angle at every clock) and
the ideal disc's definition (a quarter is a quarter), never from the model itself: the
RTL is held to the model clock by clock in tb/fine/prenc_fine.
"""

from __future__ import annotations

import numpy as np
import pytest

from prenc.fine.period import Period
from prenc.fine.velocity import FRAC
from prenc.virtual import fine_bench as fb
from prenc.virtual.trajectory import Trajectory


def run(theta: np.ndarray, illegal_at: int | None = None) -> tuple[np.ndarray, np.ndarray, fb.Sync]:
    """prenc_period's velocity (quarters per clock) and valid flag on the ideal disc."""
    sync = fb.sync_stream(theta, None)
    period = Period()
    v = np.zeros(len(theta))
    valid = np.zeros(len(theta), dtype=np.int8)
    for c, (step, cw) in enumerate(zip(sync.step.tolist(), sync.cw.tolist())):
        illegal = int(c == illegal_at)
        period.clock(0 if illegal else step, cw, illegal)
        v[c] = period.velocity / (1 << FRAC)
        valid[c] = period.valid
    return v, valid, sync


@pytest.mark.parametrize("rpm", [10, 600, 6000])
def test_a_steady_speed_reads_within_0_05_percent(rpm):
    # A full sync cycle's period on an ideal disc: exact but for the clock's quantization
    # (at 10 rpm a cycle is 176,000 clocks) and the divider's 2^-32.
    speed = fb.rpm(rpm)
    theta = Trajectory(fb.CLK_HZ, start=100.375).constant(speed, 12 / speed).theta
    v, valid, _ = run(theta)
    c = np.arange(len(theta) // 2, len(theta) - 1)
    truth = 4 * (theta[c + 1] - theta[c])
    err = (v[c] - truth) / truth * 100
    assert valid[c].all()
    assert np.max(np.abs(err)) <= 0.05, np.max(np.abs(err))


@pytest.mark.parametrize("instant", [True, False])
def test_a_reversal_shows_the_new_sign_a_clock_after_its_step(instant):
    # At once (600 to -600 rpm between two clocks): the last speed with the new sign, on
    # the clock after the step's (the output register); through 0 in 2 ms: the disc stops first
    # (no step for four intervals), and the first step the other way is an anchor.
    traj = Trajectory(fb.CLK_HZ, start=100.375).constant(fb.rpm(600), 1e-3)
    if instant:
        traj.constant(-fb.rpm(600), 1e-3)
    else:
        traj.accelerate(-fb.rpm(600), 2e-3).constant(-fb.rpm(600), 1e-3)
    v, valid, sync = run(traj.theta)
    steps = np.flatnonzero(sync.step)
    turns = [s for a, s in zip(steps, steps[1:]) if sync.cw[s] != sync.cw[a]]
    assert len(turns) == 1
    t = turns[0]
    # (v[c]: the output after clock c's edge, the step's clock t included)
    assert (v[t + 1:] <= 0).all() and (v[:t + 1] >= 0).all()
    assert (v[t] > 0 and v[t + 1] < 0) if instant else v[t] == 0
    assert valid[t:].all()


def test_a_stop_reads_0_within_two_edge_periods_and_never_above_the_bound():
    # The disc stops from 600 rpm in 1 ms. After the last edge the magnitude is never more
    # than 1.5 quarters over the clocks since it (the widest quarter a disc may print) once
    # the interval it came from has passed, and it reads 0 within two of the last edge
    # periods of the stop.
    traj = Trajectory(fb.CLK_HZ, start=100.375).constant(fb.rpm(600), 2e-3)
    stop = len(traj.accelerate(0.0, 1e-3).theta)
    theta = traj.rest(3e-3).theta
    v, valid, sync = run(theta)
    edges = np.flatnonzero(sync.step)
    last, before = edges[-1], edges[-2]
    after = np.arange(last + 1, len(theta))
    since = after - last
    # the bound lags by up to two divisions (35 clocks each) and the registers
    late = since > 1.5 * (last - before) + 80
    assert (np.abs(v[after][late]) <= 1.5 / (since[late] - 80) + 1e-12).all()
    zero = np.flatnonzero(v[stop + fb.DECODER_DELAY:] == 0)
    assert len(zero) and zero[0] <= 2 * (last - before), (zero[:1], last - before)
    assert valid[-1] == 1 and v[-1] == 0


def test_an_illegal_transition_drops_the_velocity_until_two_steps_later():
    speed = fb.rpm(600)
    theta = Trajectory(fb.CLK_HZ, start=100.375).constant(speed, 12 / speed).theta
    at = len(theta) // 2
    v, valid, sync = run(theta, illegal_at=at)
    assert valid[at - 1] == 1 and valid[at] == 0 and v[at + 1] == 0
    steps = np.flatnonzero(sync.step[at + 1:]) + at + 1
    # the first step after it is an anchor; the second gives 1 / interval, 35 + 3 clocks on
    assert not valid[at:steps[1] + 1].any()
    shown = steps[1] + 40
    assert valid[shown] == 1
    truth = 4 * (theta[shown + 1] - theta[shown])
    assert abs(v[shown] - truth) / truth < 0.01
