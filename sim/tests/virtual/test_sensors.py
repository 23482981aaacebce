# SPDX-License-Identifier: Apache-2.0
"""prenc.virtual.sensors against their definitions: the jitter's measured distribution,
chatter's count of toggles, the rise and fall times' shift of each crossing, the duty
cycle's drift; seeded, the truth unchanged, crossings kept in order."""

from __future__ import annotations

import numpy as np
import pytest

from prenc.virtual.encoder import Disc, VirtualEncoder
from prenc.virtual.sensors import RC_HALF, Chatter, CrossingJitter, DutyDrift, EdgeDelay, move_edges

CLK_HZ = 30e6
N = 6


def steady(clocks_per_slot: float, clocks: int, start: float = 3.1) -> np.ndarray:
    return start + np.arange(clocks) / clocks_per_slot


def edges(signal: np.ndarray) -> np.ndarray:
    return np.flatnonzero(signal[1:] != signal[:-1]) + 1


def run_with(theta, *effects, clk_hz=CLK_HZ):
    return VirtualEncoder(Disc(N), list(effects)).run(theta, clk_hz=clk_hz)


def test_jitter_moves_each_crossing_by_its_gaussian_in_slots():
    theta = steady(4000.0, 400_000)               # a crossing of A or B every 2,000 clocks
    clean, noisy = run_with(theta), run_with(theta, CrossingJitter(sigma=0.005, seed=3))
    for s in ("a", "b"):
        e0, e1 = edges(clean.signals[s]), edges(noisy.signals[s])
        assert len(e0) == len(e1) > 150
        shift_slots = (e1 - e0) / 4000.0
        assert abs(np.std(shift_slots) - 0.005) < 0.0008, np.std(shift_slots)
        assert abs(np.mean(shift_slots)) < 0.0015
    np.testing.assert_array_equal(noisy.theta, clean.theta)
    np.testing.assert_array_equal(noisy.head1, clean.head1)   # only A and B by default
    again = run_with(theta, CrossingJitter(sigma=0.005, seed=3))
    np.testing.assert_array_equal(again.a, noisy.a)


def test_jitter_moves_a_crossing_by_slots_of_travel_where_the_speed_steps():
    # Steps of speed at once, fast (1,000 clocks a slot) and slow (20,000), 0.37 slot each:
    # a crossing's jitter is in slots of the disc's travel, so no crossing moves further
    # along the disc than about its Gaussian allows (5 sigma), whichever side of a step it
    # falls on. (Taken as the edge's speed times the time, a crossing just after a step
    # moved by the slow speed's clocks into the fast travel: 0.4 slot for 0.02.)
    parts, start = [], 3.1
    for k in range(200):
        clocks_per_slot = 1000.0 if k % 2 == 0 else 20000.0
        n = int(0.37 * clocks_per_slot)
        parts.append(start + np.arange(n) / clocks_per_slot)
        start = parts[-1][-1] + 1 / clocks_per_slot
    theta = np.concatenate(parts)
    sigma = 0.02
    clean, noisy = run_with(theta), run_with(theta, CrossingJitter(sigma=sigma, seed=5))
    for s in ("a", "b"):
        e0, e1 = edges(clean.signals[s]), edges(noisy.signals[s])
        assert len(e0) == len(e1) > 100
        moved = np.abs(theta[e1] - theta[e0])
        assert moved.max() < 5 * sigma, moved.max()


def test_chatter_adds_its_toggles_at_a_crawl_and_none_at_speed():
    slow_clock = 2e6                                     # a slower clock keeps the arrays short
    crawl = steady(slow_clock / 2.0, 4_000_000, start=3.05)   # 2 slots a second: 8 crossings of A
    chatter = Chatter(pairs=2, window_us=5.0, crawl=20.0, seed=1)
    clean, noisy = run_with(crawl, clk_hz=slow_clock), run_with(crawl, chatter, clk_hz=slow_clock)
    for s in ("a", "b"):
        n0 = len(edges(clean.signals[s]))
        assert n0 >= 3
        extra = len(edges(noisy.signals[s])) - n0
        # exp(-2 / 20) = 0.90 of the crossings chatter, each with 4 more toggles.
        assert extra % 4 == 0 and extra >= 4 * (n0 - 2), (n0, extra)
        # within 5 us (10 clocks) after a clean crossing
        for e in edges(noisy.signals[s]):
            assert np.min(np.abs(e - edges(clean.signals[s]))) <= 10
    fast = steady(300.0, 200_000)                    # 100,000 slots a second
    assert len(edges(run_with(fast, Chatter(seed=1)).a)) == len(edges(run_with(fast).a))


def test_rise_and_fall_times_delay_each_crossing_by_their_half_swing_time():
    theta = steady(3000.0, 300_000)
    clean, late = run_with(theta), run_with(theta, EdgeDelay(rise_us=4.0, fall_us=10.0))
    for s in ("a", "b", "head1", "head2"):
        e0, e1 = edges(clean.signals[s]), edges(late.signals[s])
        rising = clean.signals[s][e0] == 1
        np.testing.assert_array_equal(e1[rising] - e0[rising], round(4e-6 * CLK_HZ * RC_HALF))
        np.testing.assert_array_equal(e1[~rising] - e0[~rising], round(10e-6 * CLK_HZ * RC_HALF))


def test_duty_drift_widens_the_high_half_by_its_amplitude():
    theta = steady(4000.0, 200_000)
    drift = DutyDrift(amplitude=0.04, period_s=1e9, phase=np.pi / 2)   # constant: +0.04 slot
    clean, drifted = run_with(theta), run_with(theta, drift)
    e0, e1 = edges(clean.a), edges(drifted.a)
    rising = clean.a[e0] == 1
    np.testing.assert_allclose((e1 - e0)[rising] / 4000.0, -0.02, atol=0.0003)
    np.testing.assert_allclose((e1 - e0)[~rising] / 4000.0, 0.02, atol=0.0003)


def test_moved_crossings_keep_their_order():
    sig = np.array([0, 0, 1, 1, 0, 0, 1, 1, 0, 0], dtype=np.int8)
    e = edges(sig)
    out = move_edges(sig, e, np.array([5, 1, 7, 9]))   # the first past the second
    np.testing.assert_array_equal(edges(out), [5, 6, 7, 9])
    assert out[0] == 0


@pytest.mark.parametrize("bad", [lambda: CrossingJitter(sigma=-1), lambda: CrossingJitter(signals=("z",)),
                                 lambda: Chatter(pairs=0), lambda: EdgeDelay(rise_us=-1),
                                 lambda: DutyDrift(period_s=0)])
def test_bad_parameters_are_named(bad):
    with pytest.raises(ValueError):
        bad()
