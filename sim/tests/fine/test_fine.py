# SPDX-License-Identifier: Apache-2.0
"""The fine blocks' models against the truth of the virtual encoder (issues 37, 58).

Expected values come from the trajectory (the true angle and speed at every clock),
from the disc's definition (a calibrated disc: its true edges, prenc.virtual.edge_timing)
and from the datasheet's sync track, never from the models themselves: the RTL is held
to the models clock by clock in tb/fine/prenc_velocity and tb/fine/prenc_fine.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from prenc.core.input_conditioner import InputConditioner
from prenc.core.quadrature import QuadratureDecoder
from prenc.fine import program
from prenc.fine.engine import Engine, Instruction, check
from prenc.fine.fine_position import OUTPUT_DELAY, V_FRAC, FinePosition
from prenc.fine.velocity import Velocity
from prenc.rtl import RTL
from prenc.virtual import fine_bench as fb
from prenc.virtual import velocity_soak as vs
from prenc.virtual.velocity_soak import calibrated_table
from prenc.virtual.edge_timing import true_corrections
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


@pytest.mark.parametrize("disc", ["ideal", "calibrated"])
@pytest.mark.parametrize("rpm", [10, 600, 6000, 10000])
def test_steady_speed_meets_the_goals(rpm, disc):
    # Goals of issues 37 and 58: fine position <= 1/256 slot RMS, velocity within 0.05 %,
    # on an ideal disc and on a printed one with its calibration table.
    theta = steady(rpm, slots=max(12.0, 40 * fb.rpm(rpm) * fb.WINDOW / fb.CLK_HZ))
    printed = disc == "calibrated"
    sync = fb.sync_stream(theta, fb.PRINTED if printed else None)
    out = fb.run_fine(sync, table=calibrated_table() if printed else None)
    zero = -true_corrections(fb.PRINTED, fb.N).mean() / 4 if printed else 0.0
    c = np.arange(len(theta) // 2, len(theta) - 1)
    err = fb.position_error(out["fine"][c] / (1 << fb.FINE_BITS), theta[c + 1]) - zero
    truth = 4 * fb.rpm(rpm) / fb.CLK_HZ
    v_err = np.abs(out["velocity"][c] - truth) / truth
    assert out["velocity_valid"][c].all() and out["interpolated"][c].all()
    assert np.sqrt(np.mean(err ** 2)) <= 1 / 256, np.sqrt(np.mean(err ** 2))
    assert np.max(np.abs(err)) < 0.25 + 0.05
    assert v_err.max() <= 0.0005, v_err.max()


@pytest.mark.parametrize("disc", ["ideal", "calibrated"])
def test_the_ramp_meets_the_goals(disc):
    # 600 -> 6,000 rpm in 4 ms (issue 37's ramp): the velocity within 1 % RMS over the
    # whole ramp, the fine position within 1/64 slot RMS; after the first 250 us of each
    # change of acceleration, within 1.5 % at every clock.
    traj = Trajectory(fb.CLK_HZ, start=100.375).constant(fb.rpm(600), 3e-3)
    start = len(traj.theta)
    theta = traj.accelerate(fb.rpm(6000), 4e-3).theta
    printed = disc == "calibrated"
    sync = fb.sync_stream(theta, fb.PRINTED if printed else None)
    out = fb.run_fine(sync, table=calibrated_table() if printed else None)
    zero = -true_corrections(fb.PRINTED, fb.N).mean() / 4 if printed else 0.0
    c = np.arange(start, len(theta) - 1)
    truth = 4 * (theta[c + 1] - theta[c])
    v_err = (out["velocity"][c] - truth) / truth
    err = fb.position_error(out["fine"][c] / (1 << fb.FINE_BITS), theta[c + 1]) - zero
    assert np.sqrt(np.mean(v_err ** 2)) <= 0.01, np.sqrt(np.mean(v_err ** 2))
    assert np.sqrt(np.mean(err ** 2)) <= 1 / 64, np.sqrt(np.mean(err ** 2))
    settled = v_err[int(fb.RAMP_SETTLE_S * fb.CLK_HZ):]
    assert np.abs(settled).max() <= 0.015, np.abs(settled).max()


def test_a_slow_acceleration_is_followed():
    # 600 -> 1200 rpm over 40 ms: an acceleration too slow for one window's test. The
    # running mean of 8 windows lags (measured -0.17 % at 600 rpm, where a window is one
    # edge period and the speed grows 0.06 % per window); a window that fails the test
    # starts a fit from the last two, which a quantized window can push up (+0.66 %
    # measured). Both stay inside the ramp's 1 % goal.
    traj = Trajectory(fb.CLK_HZ, start=100.375).constant(fb.rpm(600), 2e-3)
    start = len(traj.theta)
    theta = traj.accelerate(fb.rpm(1200), 40e-3).theta
    sync = fb.sync_stream(theta, None)
    out = fb.run_fine(sync)
    c = np.arange(start + 30_000, len(theta) - 1)
    truth = 4 * (theta[c + 1] - theta[c])
    v_err = (out["velocity"][c] - truth) / truth
    assert abs(v_err.mean()) <= 0.0025, v_err.mean()
    assert np.abs(v_err).max() <= 0.01, np.abs(v_err).max()


@pytest.mark.parametrize("before, after", fb.STEPS + ((600, -600), (3000, 100)))
def test_after_a_step_of_speed_the_velocity_is_back_within_its_bound(before, after):
    # Issue 58: after a step of speed from a steady one the velocity is back within 0.05 %
    # within 6 windows or 8 edge periods of the new speed, whichever is longer (after any
    # change of motion, 11 windows: the test of random changes below). Until then
    # it reads between the two speeds widened by the step (a step changes two windows:
    # the second change's fit extrapolates by at most the change, and a fit is integrated
    # from the third; prenc.fine.program), or 0 where the speed fell to half or less at
    # once (the overdue edge's stop).
    v0, v1 = fb.rpm(before), fb.rpm(after)
    traj = Trajectory(fb.CLK_HZ, start=100.375).constant(v0, max(3e-3, 30 / abs(v0)))
    start = len(traj.theta)
    theta = traj.constant(v1, max(4e-3, 40 / abs(v1))).theta
    sync = fb.sync_stream(theta, None)
    velocity = fb.run_fine(sync)["velocity"]
    truth = 4 * (theta[1:] - theta[:-1])
    period = fb.CLK_HZ / (4 * abs(v1))
    bound = max(6 * fb.WINDOW, 8 * period)
    k = fb.settle_clocks(velocity, truth, start)
    assert k is not None and k <= bound, (k, bound)
    lo, hi = sorted((4 * v0 / fb.CLK_HZ, 4 * v1 / fb.CLK_HZ))
    margin = (hi - lo) * 1.01
    after_step = velocity[start:]
    inside = (after_step >= lo - margin) & (after_step <= hi + margin)
    stopped = (after_step == 0) & (abs(v1) * 2 <= abs(v0))
    assert (inside | stopped).all()


@pytest.mark.parametrize("disc, seed, kinds", [("ideal", 113, {"step", "ramp"}),
                                               ("ideal", 196, {"step", "stop"}),
                                               ("ideal", 349, {"ramp", "quick"}),
                                               ("calibrated", 104, {"step", "ramp", "stop", "quick"})])
def test_the_velocity_is_never_frozen_by_random_changes_of_motion(disc, seed, kinds):
    # A property, over a random run of steps, ramps, stops, reversals and changes in
    # quick succession (prenc.virtual.velocity_soak, which `make soak ARGS=--velocity`
    # draws many of): after each, the velocity is within 0.05 % within the bound of
    # docs/fine.md, 11 windows or 8 edge periods of the new speed on the ideal disc, 18 or
    # 22 on the calibrated one (whichever is longer), and stays there until the next
    # change; until then it reads between the last speeds widened by their spread, or 0.
    # The calibrated printed disc takes longer: its test allows each edge the table's
    # residual error, so a speed off by up to that (at the end of a ramp) passes it and
    # is averaged out at 1/8 a window. The seeds are the slowest of 350 runs: 113, ideal,
    # its first ramp's end takes 9.07 windows (9.4 edge periods); 196, ideal, its second
    # step 9.90 windows (9.6 periods); 349, ideal, a ramp's end to 2,844 rpm 10.05 windows
    # (above the 10 windows the bound was until then); 104, calibrated, its second ramp's
    # end 17.05 windows.
    result = vs.run(seed, disc)
    assert not result.failures, result.failures
    assert {kind for kind, _, _ in result.settled} == kinds   # the changes the run draws


def test_the_velocity_soak_fails_a_bound_the_velocity_does_not_meet():
    # The judge can fail: the ideal run of seed 41 against 2 windows or 4 edge periods
    # (its first ramp's end takes 2.2 windows, 21 edge periods).
    theta, holds = vs.random_motion(41)
    failures, _ = vs.judge(theta, holds, vs.velocity_of(theta, "ideal"), "ideal", bounds=(2, 4))
    assert failures and failures[0].startswith("ramp"), failures


@pytest.mark.parametrize("braking_ms", [1.0, 0.0])
def test_velocity_reads_zero_within_two_edge_periods_of_a_stop(braking_ms):
    # A stop after braking evenly, and an abrupt one. The disc stops at `stopped` (as the
    # decoder sees it); the velocity must read 0 within two of the last edge periods.
    traj = Trajectory(fb.CLK_HZ, start=100.375).constant(fb.rpm(600), 3e-3)
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


@pytest.mark.parametrize("cut_ms", [1.0, 2.0, 3.0])
def test_a_dead_stop_during_a_ramp_reads_zero_and_never_more_than_the_speed_at_the_stop(cut_ms):
    # The ramp of 600 -> 6,000 rpm in 4 ms, the disc held still at once `cut_ms` into it
    # (the speed then integrates an acceleration): the velocity must not go on integrating
    # past the speed at the stop, and reads 0 within two of the last edge periods plus
    # the engine's pace (docs/fine.md: 200 clocks).
    traj = Trajectory(fb.CLK_HZ, start=100.375).constant(fb.rpm(600), 2e-3).accelerate(fb.rpm(6000), 4e-3)
    cut = int((2 + cut_ms) * 1e-3 * fb.CLK_HZ)
    theta = np.concatenate([traj.theta[:cut], np.full(int(2e-3 * fb.CLK_HZ), traj.theta[cut - 1])])
    sync = fb.sync_stream(theta, None)
    velocity = fb.run_fine(sync)["velocity"]
    edges = np.flatnonzero(sync.step)
    last, period = edges[-1], edges[-1] - edges[-2]
    at_stop = 4 * (theta[cut - 1] - theta[cut - 2])   # quarters per clock
    assert np.abs(velocity[cut:]).max() <= 1.01 * at_stop, (np.abs(velocity[cut:]).max(), at_stop)
    zero = np.flatnonzero(velocity[last:] == 0)[0] + last
    assert zero - last <= 2 * period + 200, (zero - last, period)
    assert (velocity[zero:] == 0).all()


@pytest.mark.parametrize("rpm", [100, 600, 6000])
def test_a_printed_disc_without_its_table_reads_its_speed_with_edge_tolerance(rpm):
    # The printed disc, no table: with EDGE_TOLERANCE (whole-cycle windows) the velocity
    # is within 2.5 % RMS and 5 % at every clock of the true speed; without it, not.
    theta = steady(rpm, slots=max(48.0, 60 * fb.rpm(rpm) * fb.WINDOW / fb.CLK_HZ))
    sync = fb.sync_stream(theta, fb.PRINTED)
    c = np.arange(len(theta) // 2, len(theta) - 1)
    truth = 4 * fb.rpm(rpm) / fb.CLK_HZ
    errors = {}
    for tol in (0, fb.PRINTED_EDGE_TOLERANCE):
        out = fb.run_fine(sync, edge_tolerance=tol)
        assert out["velocity_valid"][c].all()
        v_err = np.abs(out["velocity"][c] - truth) / truth
        errors[tol] = (np.sqrt(np.mean(v_err ** 2)), v_err.max())
    rms, worst = errors[fb.PRINTED_EDGE_TOLERANCE]
    assert rms <= 0.025 and worst <= 0.05, errors
    assert errors[0][1] > 0.05, errors


def test_a_noisy_sensor_reads_its_speed_with_edge_tolerance_and_a_table():
    # Crossing jitter of 0.005 slot RMS on A and B, the printed disc with its table: at
    # 6,000 rpm EDGE_TOLERANCE = 10 (twice the noise) keeps the velocity within 0.1 % at
    # every clock (the bench: 0.032 %), at least 4 times closer than without it, and the
    # fine position within 0.0025 slot RMS.
    from prenc.virtual.sensors import CrossingJitter

    theta = steady(6000, slots=max(48.0, 60 * fb.rpm(6000) * fb.WINDOW / fb.CLK_HZ))
    sync = fb.sync_stream(theta, fb.PRINTED, sensors=(CrossingJitter(sigma=0.005, seed=1),))
    c = np.arange(len(theta) // 2, len(theta) - 1)
    truth = 4 * fb.rpm(6000) / fb.CLK_HZ
    zero = -true_corrections(fb.PRINTED, fb.N).mean() / 4
    worst, rms = {}, {}
    for tol in (0, 10):
        out = fb.run_fine(sync, table=calibrated_table(), edge_tolerance=tol)
        worst[tol] = np.max(np.abs(out["velocity"][c] - truth)) / truth
        err = fb.position_error(out["fine"][c] / (1 << fb.FINE_BITS), theta[c + 1]) - zero
        rms[tol] = float(np.sqrt(np.mean(err ** 2)))
    assert worst[10] <= 0.001 and worst[0] >= 4 * worst[10], worst
    # The fine position: its phase a running mean of the edges', within issue 60's 0.0025
    # slot RMS; each edge's phase carries its noise.
    assert rms[10] <= 0.0025 < rms[0], rms


def test_a_held_speed_settles_to_the_mean_of_many_windows_through_noise():
    # The same sensor at 600 rpm held 8 ms: 16 windows without a trend weigh the running
    # mean 1/32, and over the next 6 ms the velocity is within issue 60's 0.05 % of the
    # true speed at every clock. A +-2 % ripple at 100 Hz is a trend: the weight stays
    # 1/8, and the ripple reads within 1 % RMS (at 1/32 throughout, 1.2 %).
    from prenc.virtual.sensors import CrossingJitter

    def velocity_error(traj: Trajectory, start: int) -> tuple[float, float]:
        """% RMS and max against the truth over the clocks from `start` on."""
        theta = traj.theta
        sync = fb.sync_stream(theta, fb.PRINTED, sensors=(CrossingJitter(sigma=0.005, seed=1),))
        out = fb.run_fine(sync, table=calibrated_table(), edge_tolerance=10)
        case = fb.Case("held", theta, np.arange(start, len(theta) - 1))
        return fb.score(case, sync, out["fine"] / (1 << fb.FINE_BITS), out["velocity"]).velocity

    traj = Trajectory(fb.CLK_HZ, start=100.375).constant(fb.rpm(600), 8e-3)
    start = len(traj.theta)
    assert velocity_error(traj.constant(fb.rpm(600), 6e-3), start)[1] <= 0.05
    traj = Trajectory(fb.CLK_HZ, start=100.375).constant(fb.rpm(600), 2e-3)
    start = len(traj.theta)
    assert velocity_error(traj.constant(fb.rpm(600), 10e-3, ripple=0.02, ripple_hz=100.0), start)[0] <= 1.0


def test_a_stop_on_a_printed_disc_reads_zero_with_edge_tolerance():
    # An overdue edge waits for a quarter 4 EDGE_TOLERANCE wider: the stop reads 0 within
    # 1.5 (1.25 + 4 x 0.124) = 2.62 nominal edge periods, and nothing reads 0 before it.
    traj = Trajectory(fb.CLK_HZ, start=100.375).constant(fb.rpm(600), 6e-3)
    stopped = len(traj.theta) + fb.DECODER_DELAY
    theta = traj.rest(4e-3).theta
    sync = fb.sync_stream(theta, fb.PRINTED)
    out = fb.run_fine(sync, edge_tolerance=fb.PRINTED_EDGE_TOLERANCE)
    period = fb.CLK_HZ / (4 * fb.rpm(600))
    zero = np.flatnonzero(out["velocity"] == 0)
    zero = zero[zero > 3e-3 * fb.CLK_HZ][0]
    assert 0 < zero - stopped <= 2.65 * period, ((zero - stopped) / period)
    assert (out["velocity"][zero:] == 0).all() and out["velocity_valid"][zero:].all()


def test_the_velocity_never_points_against_the_last_step():
    theta = (Trajectory(clk_hz=1, start=50.4).constant(0.01, 3000)
             .random_walk(60_000, max_speed=0.02, seed=3, knot_seconds=700).theta)
    sync = fb.sync_stream(theta, None)
    out = fb.run_fine(sync, window=128)
    direction = np.where(sync.cw == 1, 1, -1)
    last_step = np.maximum.accumulate(np.where(sync.step == 1, np.arange(len(theta)), 0))
    # The output is registered: after clock c it has the direction of the steps up to c - 1.
    before = np.concatenate([[0], last_step[:-1]])
    assert (out["velocity"][1:] * direction[before[1:]] >= 0).all()
    reversals = np.flatnonzero((sync.step == 1) & (np.diff(np.concatenate([[1], direction[last_step]])) != 0))
    assert len(reversals) > 10


def test_an_illegal_transition_drops_the_velocity():
    vel = Velocity(window=64)
    for c in range(6000):
        vel.clock(step=int(c % 20 == 0), step_cw=1)
    assert vel.valid and vel.velocity == pytest.approx((1 << V_FRAC) / 20, rel=1e-4)
    vel.clock(illegal=1)
    vel.clock()
    assert not vel.valid and vel.velocity == 0


def test_an_old_anchor_is_dropped():
    # A step, then nothing for 2^30 clocks: the window's anchor goes (the clocks wrap at
    # 2^32: a window that long would be measured wrong).
    vel = Velocity(window=64)
    vel.clock(step=1, step_cw=1)
    for _ in range(20):
        vel.clock()
    assert vel.engine.flags["ANCH"]
    vel.now += program.OLD
    for _ in range(20):
        vel.clock()
    assert not vel.engine.flags["ANCH"]


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
        rounding = 2.0 ** -20     # the product's rounding, which reach (a float) has not
        assert (off >= -reach - lsb - rounding).all() and (off < 1 + reach + rounding).all()
        assert (step_off != 0).any()   # the extrapolation does cross edges


def test_without_a_velocity_the_fraction_is_the_quarters_middle():
    fine = FinePosition(n=6, fine_bits=4, lookahead_halves=9)
    for _ in range(OUTPUT_DELAY):
        fine.clock(pos_hyb=37, pos_valid=1, step=0, step_cw=1, velocity=1 << 28, velocity_valid=0)
    assert fine.fine_pos == 37 * 16 + 8 and fine.valid and not fine.interpolated


@pytest.mark.parametrize("kwargs", [{"window": 8}, {"window": 1 << 30}, {"cal": 2}, {"edge_tolerance": -1},
                                    {"edge_tolerance": 61}])
def test_velocity_parameters_out_of_range_are_refused(kwargs):
    with pytest.raises(ValueError):
        Velocity(**kwargs)


@pytest.mark.parametrize("kwargs", [{"fine_bits": 9}, {"lookahead_halves": 256}, {"phase_filter": 2}])
def test_fine_position_parameters_out_of_range_are_refused(kwargs):
    with pytest.raises(ValueError):
        FinePosition(**kwargs)


def test_the_rtls_program_is_the_models():
    # rtl/fine/prenc_velocity_program.v is written from prenc.fine.program: up to date.
    text = (RTL / "fine" / "prenc_velocity_program.v").read_text()
    assert text == program.rom_verilog(), "run: python -m prenc.fine.program > rtl/fine/prenc_velocity_program.v"
    assert re.search(rf"assign restart = {program.PC_BITS}'d{program.RESTART};", text)


def test_a_program_that_reads_what_it_just_wrote_or_reads_where_a_jump_lands_is_refused():
    store = Instruction("STORE", 3)
    with pytest.raises(ValueError, match="reads RF\\[3\\], which instruction 0 writes"):
        check([store, Instruction("LOAD", 3)], 0)
    with pytest.raises(ValueError, match="instruction 2, where a jump goes, reads an operand"):
        check([Instruction("NOP"), Instruction("JMP", 0, 2), Instruction("ADD", 4)], 0)
    with pytest.raises(ValueError, match="must not write RF\\[0\\]"):   # QUOT adds RF[0] as 0
        check([Instruction("STORE", 0), Instruction("NOP")], 0)
    check(program.PROGRAM, program.RESTART)   # the program itself passes
    Engine(program.PROGRAM, program.constants(1024, 0), program.RESTART)
