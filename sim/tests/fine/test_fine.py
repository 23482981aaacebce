# SPDX-License-Identifier: Apache-2.0
"""The fine blocks' models against the truth of the virtual encoder (issue 37).

Expected values come from the trajectory (the true angle and speed at every clock)
and from the datasheet's sync track, never from the models themselves: the RTL is
held to the models clock by clock in tb/fine/prenc_fine.
"""

from __future__ import annotations

import numpy as np
import pytest

from prenc.core.input_conditioner import InputConditioner
from prenc.core.quadrature import QuadratureDecoder
from prenc.fine.fine_position import OUTPUT_DELAY, FinePosition
from prenc.fine.velocity import FRAC, Velocity
from prenc.virtual import fine_bench as fb
from prenc.virtual.encoder import Disc
from prenc.virtual.trajectory import Trajectory


def steady(rpm: float, slots: float) -> np.ndarray:
    return Trajectory(fb.CLK_HZ, start=100.375).constant(fb.rpm(rpm), slots / fb.rpm(rpm)).theta


def test_the_sync_stream_is_the_decoders_output_clock_by_clock():
    theta = Trajectory(clk_hz=1, start=20.4).constant(0.03, 600).accelerate(-0.03, 900).theta
    sync = fb.sync_stream(theta, None)
    a, b = Disc.sync(theta)
    cond, dec = InputConditioner(4, fb.FILTER), QuadratureDecoder()
    for _ in range(4):   # reset on the first pins, as the core
        clean = cond.clock([0, 0, a[0], b[0]], rst=1)
        dec.clock(clean[2], clean[3], rst=1)
    clean = cond.clock([0, 0, a[0], b[0]])
    for c in range(1, len(theta) - 1):
        # As the core: the decoder registers at edge c what the conditioner had before it.
        q = dec.clock(clean[2], clean[3])
        clean = cond.clock([0, 0, a[c], b[c]])
        # The decoder's registers after edge c are its outputs during cycle c + 1.
        assert q.step == sync.step[c + 1], c
        if q.step:
            assert q.step_cw == sync.cw[c + 1], c
    # pos_hyb counts the steps from the first pins' hybrid position, 4 clocks after them.
    steps = np.where(sync.step == 1, np.where(sync.cw == 1, 1, -1), 0)
    h0 = int(np.floor(4 * theta[0]))
    assert np.array_equal(sync.pos_hyb[4:], (h0 + np.cumsum(steps)[:-4]) % (4 << fb.N))


@pytest.mark.parametrize("quarter_windows", [0, 1])
@pytest.mark.parametrize("rpm", [10, 600, 6000, 10000])
def test_steady_speed_meets_the_goals_on_an_ideal_disc(rpm, quarter_windows):
    # Goals of issue 37: fine position <= 1/256 slot RMS, velocity within 0.05 %.
    theta = steady(rpm, slots=max(12.0, 30 * fb.rpm(rpm) * fb.WINDOW / fb.CLK_HZ))
    sync = fb.sync_stream(theta, None)
    out = fb.run_fine(sync, quarter_windows=quarter_windows)
    c = np.arange(len(theta) // 2, len(theta) - 1)
    err = fb.position_error(out["fine"][c] / (1 << fb.FINE_BITS), theta[c + 1])
    truth = 4 * fb.rpm(rpm) / fb.CLK_HZ
    v_err = np.abs(out["velocity"][c] - truth) / truth
    assert out["velocity_valid"][c].all() and out["interpolated"][c].all()
    assert np.sqrt(np.mean(err ** 2)) <= 1 / 256, np.sqrt(np.mean(err ** 2))
    assert np.max(np.abs(err)) < 0.25
    assert v_err.max() <= 0.0005, v_err.max()


def test_constant_acceleration_is_followed_without_lag():
    # 600 -> 1200 rpm over 40 ms: after the first windows the fit has no bias (FULL_CLOCKS
    # puts the velocity on the cycle it shows); what is left is the clocks' quantization.
    traj = Trajectory(fb.CLK_HZ, start=100.375).constant(fb.rpm(600), 2e-3)
    start = len(traj.theta)
    theta = traj.accelerate(fb.rpm(1200), 40e-3).theta
    sync = fb.sync_stream(theta, None)
    out = fb.run_fine(sync)
    c = np.arange(start + 30_000, len(theta) - 1)
    truth = 4 * (theta[c + 1] - theta[c])
    v_err = (out["velocity"][c] - truth) / truth
    assert abs(v_err.mean()) <= 0.0001, v_err.mean()
    assert np.sqrt(np.mean(v_err ** 2)) <= 0.001, np.sqrt(np.mean(v_err ** 2))


def test_quarter_windows_follow_a_ramp_from_its_first_quarters():
    # 600 -> 6,000 rpm in 4 ms on an ideal disc (issue 37's ramp): with quarter windows
    # the velocity is within 1 % RMS over the whole ramp, and within 1 % at every clock
    # from 250 us after the jerk; full-cycle windows see the jerk only a slot or two later.
    traj = Trajectory(fb.CLK_HZ, start=100.375).constant(fb.rpm(600), 2e-3)
    start = len(traj.theta)
    theta = traj.accelerate(fb.rpm(6000), 4e-3).theta
    sync = fb.sync_stream(theta, None)
    c = np.arange(start, len(theta) - 1)
    truth = 4 * (theta[c + 1] - theta[c])
    rms = {}
    for quarter_windows in (0, 1):
        out = fb.run_fine(sync, quarter_windows=quarter_windows)
        v_err = (out["velocity"][c] - truth) / truth
        rms[quarter_windows] = np.sqrt(np.mean(v_err ** 2))
        if quarter_windows:
            settled = v_err[int(fb.RAMP_SETTLE_S * fb.CLK_HZ):]
            assert np.abs(settled).max() <= 0.01, np.abs(settled).max()
    assert rms[1] <= 0.01 < rms[0], rms


@pytest.mark.parametrize("braking_ms", [1.0, 0.0])
def test_velocity_reads_zero_within_two_edge_periods_of_a_stop(braking_ms):
    # A stop after braking evenly, and an abrupt one. The disc stops at `stopped` (as the
    # decoder sees it); the velocity must read 0 within two of the last edge periods.
    traj = Trajectory(fb.CLK_HZ, start=100.375).constant(fb.rpm(600), 2e-3)
    traj.accelerate(0.0, braking_ms * 1e-3)
    stopped = len(traj.theta) + fb.DECODER_DELAY
    theta = traj.rest(4e-3).theta
    sync = fb.sync_stream(theta, None)
    out = fb.run_fine(sync)
    edges = np.flatnonzero(sync.step)
    period = edges[-1] - edges[-2]
    zero = np.flatnonzero(out["velocity"][edges[-1]:] == 0)[0] + edges[-1]
    assert zero - stopped <= 2 * period, (zero - stopped, period)
    assert (out["velocity"][zero:] == 0).all() and out["velocity_valid"][zero:].all()


@pytest.mark.parametrize("quarter_windows", [0, 1])
def test_the_velocity_never_points_against_the_last_step(quarter_windows):
    theta = (Trajectory(clk_hz=1, start=50.4).constant(0.01, 3000)
             .random_walk(60_000, max_speed=0.02, seed=3, knot_seconds=700).theta)
    sync = fb.sync_stream(theta, None)
    out = fb.run_fine(sync, window=128, quarter_windows=quarter_windows)
    direction = np.where(sync.cw == 1, 1, -1)
    last_step = np.maximum.accumulate(np.where(sync.step == 1, np.arange(len(theta)), 0))
    # run_fine records the registers after each clock: the step of clock c is in them.
    assert (out["velocity"] * direction[last_step] >= 0).all()
    reversals = np.flatnonzero((sync.step == 1) & (np.diff(np.concatenate([[1], direction[last_step]])) != 0))
    assert len(reversals) > 10
    # Right after a reversal the velocity has the new direction's sign, or reads 0.
    for c in reversals:
        assert out["velocity"][c] * direction[c] >= 0


def test_an_illegal_transition_drops_the_velocity():
    vel = Velocity(window=64, timer_bits=12)
    for c in range(4000):
        vel.clock(step=int(c % 20 == 0), step_cw=1)
    assert vel.valid and vel.velocity == pytest.approx((1 << FRAC) / 20, rel=1e-6)
    vel.clock(illegal=1)
    assert not vel.valid and vel.velocity == 0


@pytest.mark.parametrize("lookahead", [0, 21])
def test_the_fine_position_keeps_the_verified_quarter_but_for_the_extrapolation(lookahead):
    theta = (Trajectory(clk_hz=1, start=50.4).constant(0.02, 2000)
             .random_walk(30_000, max_speed=0.03, seed=5, knot_seconds=500).theta)
    sync = fb.sync_stream(theta, None)
    fine_bits = 6
    out = fb.run_fine(sync, window=128, fine_bits=fine_bits, lookahead_halves=lookahead)
    quarters = 4 << fb.N
    # fine_pos after clock c comes from pos_hyb of clock c - (OUTPUT_DELAY - 1).
    d = OUTPUT_DELAY - 1
    pos_hyb = np.concatenate([np.full(d, sync.pos_hyb[0]), sync.pos_hyb[:-d]])
    quarter = out["fine"] >> fine_bits
    step_off = (quarter - pos_hyb + quarters // 2) % quarters - quarters // 2
    step_off[:OUTPUT_DELAY] = 0   # the stages fill after reset
    if lookahead == 0:
        assert (step_off == 0).all()
    else:
        # The extrapolation uses a velocity a few clocks old: the largest of the last eight.
        speed = np.abs(out["velocity"])
        recent = np.max([np.concatenate([np.zeros(k), speed[:len(speed) - k]]) for k in range(8)], axis=0)
        reach = recent * lookahead / 2
        frac = (out["fine"] % (1 << fine_bits)) / (1 << fine_bits)
        position = quarter + frac
        off = (position - pos_hyb + quarters / 2) % quarters - quarters / 2
        off[:OUTPUT_DELAY] = 0.5
        lsb = 2.0 ** -fine_bits   # truncated to F bits
        assert (off >= -reach - lsb).all() and (off < 1 + reach).all()
        assert (step_off != 0).any()   # the extrapolation does cross edges


def test_without_a_velocity_the_fraction_is_the_quarters_middle():
    fine = FinePosition(n=6, fine_bits=4, lookahead_halves=9)
    for _ in range(OUTPUT_DELAY):
        fine.clock(pos_hyb=37, pos_valid=1, step=0, step_cw=1, velocity=1 << 40, velocity_valid=0)
    assert fine.fine_pos == 37 * 16 + 8 and fine.valid and not fine.interpolated


@pytest.mark.parametrize("kwargs", [{"window": 8}, {"timer_bits": 40}, {"window": 1 << 20, "timer_bits": 16}])
def test_velocity_parameters_out_of_range_are_refused(kwargs):
    with pytest.raises(ValueError):
        Velocity(**kwargs)


@pytest.mark.parametrize("kwargs", [{"fine_bits": 9}, {"lookahead_halves": 256}])
def test_fine_position_parameters_out_of_range_are_refused(kwargs):
    with pytest.raises(ValueError):
        FinePosition(**kwargs)
