# SPDX-License-Identifier: Apache-2.0
"""Speed profiles of endless length: the disc angle as a function of the clock.

A Trajectory (prenc.virtual.trajectory) is built segment by segment and has an end; the
virtual board (`make board-sim`) runs until it is stopped, so it takes the angle
from a function of the absolute clock, evaluated a chunk at a time:

    theta_at = profile("reversals", rpm=600, n=10, clk_hz=24e6)
    theta = theta_at(np.arange(0, 200_000))        # slots, unwrapped

- constant:  turns one way at `rpm` (negative: CCW), after `rest_s` at rest;
- reversals: back and forth at `rpm`, reversing every `period_s` seconds;
- sine:      theta0 + amplitude * sin(2 pi t / period): the speed peaks at `rpm`.
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

PROFILES = ("constant", "reversals", "sine")


def profile(name: str, rpm: float, n: int, clk_hz: float, theta0: float = 100.4,
            rest_s: float = 50e-6, period_s: float = 5e-3) -> Callable[[np.ndarray], np.ndarray]:
    """theta_at(clocks) -> slots for the named profile."""
    if name not in PROFILES:
        raise ValueError(f"unknown profile {name!r}; choose one of {', '.join(PROFILES)}")
    if clk_hz <= 0 or period_s <= 0 or rest_s < 0:
        raise ValueError("clk_hz and period_s must be > 0, rest_s >= 0")
    per_clock = rpm / 60.0 * (1 << n) / clk_hz  # slots per clock
    rest = rest_s * clk_hz
    period = period_s * clk_hz

    def constant(clocks):
        t = np.maximum(np.asarray(clocks, dtype=np.float64) - rest, 0.0)
        return theta0 + per_clock * t

    def reversals(clocks):
        t = np.maximum(np.asarray(clocks, dtype=np.float64) - rest, 0.0)
        phase = np.mod(t, 2 * period)
        return theta0 + per_clock * np.where(phase < period, phase, 2 * period - phase)

    def sine(clocks):
        t = np.maximum(np.asarray(clocks, dtype=np.float64) - rest, 0.0)
        amplitude = per_clock * period / (2 * math.pi)
        return theta0 + amplitude * np.sin(2 * math.pi * t / period)

    return {"constant": constant, "reversals": reversals, "sine": sine}[name]
