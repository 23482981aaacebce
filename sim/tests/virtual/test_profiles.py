# SPDX-License-Identifier: Apache-2.0
"""prenc.virtual.profiles: endless speed profiles as functions of the clock."""

from __future__ import annotations

import numpy as np
import pytest

from prenc.virtual.profiles import profile


def test_constant_turns_at_the_given_speed_after_its_rest():
    theta = profile("constant", rpm=600, n=10, clk_hz=1e6, theta0=5.0, rest_s=1e-3)
    clocks = np.array([0, 1000, 2000, 61_000])
    assert theta(clocks).tolist() == pytest.approx([5.0, 5.0, 5.0 + 10.24, 5.0 + 60 * 10.24])


def test_reversals_go_back_and_forth_and_chunks_join():
    theta = profile("reversals", rpm=60, n=6, clk_hz=1e4, theta0=0.0, rest_s=0, period_s=1.0)
    t = theta(np.arange(0, 40_000))
    assert t.max() == pytest.approx(64.0, abs=1e-2) and t.min() == pytest.approx(0.0)
    speed = np.diff(t)
    assert (speed > 0).any() and (speed < 0).any()
    assert np.abs(speed).max() == pytest.approx(64 / 1e4)
    # The same function of the clock, whichever chunk asks.
    assert theta(np.arange(12_345, 12_400)).tolist() == t[12_345:12_400].tolist()


def test_sine_peaks_at_the_given_speed():
    theta = profile("sine", rpm=120, n=10, clk_hz=1e5, period_s=0.01, rest_s=0)
    speed = np.diff(theta(np.arange(0, 10_000)))
    assert np.abs(speed).max() == pytest.approx(2 * 1024 / 1e5, rel=1e-3)


def test_bad_profile_is_refused():
    with pytest.raises(ValueError, match="unknown profile"):
        profile("zigzag", 1, 10, 1e6)
