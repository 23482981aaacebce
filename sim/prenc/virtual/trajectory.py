# SPDX-License-Identifier: Apache-2.0
"""Disc trajectories sampled on the reader's clock.

A trajectory is the true disc angle theta (in slots, unwrapped: it may leave
0..L and counts whole turns) at every clock tick k = 0, 1, 2, ... of a clock of
`clk_hz`. It is built from segments, each starting where the last one ended:

    traj = (Trajectory(clk_hz=50e6, start=100.25)
            .rest(1e-6)
            .constant(speed=2e5, seconds=20e-6)      # slots per second
            .accelerate(to_speed=-1e5, seconds=30e-6)  # reverses on the way
            .move_to(200.5, speed=1e5)                 # exact arrival at a tick
            .random_walk(seconds=1e-3, max_speed=3e5, seed=7))
    theta = traj.theta                                 # numpy float64, one per tick

With clk_hz=1, seconds are clock ticks and speeds are slots per tick.

`move_to` lands exactly on its target at its last tick, so a reversal can be put
exactly on a sampling instant (theta = p + 0.5, where A changes).
"""

from __future__ import annotations

import math

import numpy as np


def rpm_to_slots_per_second(rpm: float, slots_per_turn: int) -> float:
    return rpm / 60.0 * slots_per_turn


class Trajectory:
    """A sequence of motion segments sampled once per clock tick."""

    def __init__(self, clk_hz: float, start: float = 0.0):
        if not clk_hz > 0:
            raise ValueError(f"clk_hz must be positive, got {clk_hz!r}")
        self.clk_hz = float(clk_hz)
        self._chunks: list[np.ndarray] = [np.array([float(start)])]
        self._speed = 0.0  # slots per second at the end of the last segment

    # -- state -------------------------------------------------------------------
    @property
    def theta(self) -> np.ndarray:
        """Angle at every tick so far (tick 0 is the start angle)."""
        if len(self._chunks) > 1:
            self._chunks = [np.concatenate(self._chunks)]
        return self._chunks[0]

    @property
    def end(self) -> float:
        return float(self._chunks[-1][-1])

    @property
    def speed(self) -> float:
        """Speed at the end, in slots per second."""
        return self._speed

    def __len__(self) -> int:
        return sum(len(c) for c in self._chunks)

    def _ticks(self, seconds: float) -> int:
        if seconds < 0:
            raise ValueError(f"a duration must not be negative, got {seconds!r}")
        return int(round(seconds * self.clk_hz))

    def _append(self, samples: np.ndarray, end_speed: float) -> "Trajectory":
        if len(samples):
            self._chunks.append(np.asarray(samples, dtype=np.float64))
        self._speed = float(end_speed)
        return self

    # -- segments ----------------------------------------------------------------
    def rest(self, seconds: float) -> "Trajectory":
        """Stand still."""
        return self._append(np.full(self._ticks(seconds), self.end), 0.0)

    def constant(self, speed: float, seconds: float, ripple: float = 0.0,
                 ripple_hz: float = 0.0) -> "Trajectory":
        """Turn at `speed` slots/s (negative: counter-clockwise). With `ripple`, the
        speed is speed * (1 + ripple * sin(2 pi ripple_hz t)) (t from the segment's
        start): ripple = 0.02 is a +-2 % speed ripple."""
        if ripple and not ripple_hz > 0:
            raise ValueError(f"a speed ripple needs ripple_hz > 0, got {ripple_hz!r}")
        t = np.arange(1, self._ticks(seconds) + 1) / self.clk_hz
        theta = self.end + speed * t
        end_speed = speed
        if ripple:
            w = 2 * math.pi * ripple_hz
            theta += speed * ripple * (1 - np.cos(w * t)) / w
            end_speed = speed * (1 + ripple * math.sin(w * t[-1])) if len(t) else speed
        return self._append(theta, end_speed)

    def accelerate(self, to_speed: float, seconds: float) -> "Trajectory":
        """Change speed linearly from the current speed to `to_speed`."""
        n = self._ticks(seconds)
        if n == 0:
            return self._append(np.empty(0), to_speed)
        v0 = self._speed
        k = np.arange(1, n + 1) / self.clk_hz
        a = (to_speed - v0) / (n / self.clk_hz)
        return self._append(self.end + v0 * k + 0.5 * a * k * k, to_speed)

    def move_to(self, target: float, speed: float) -> "Trajectory":
        """Move at |speed| to `target` and stop there; the last tick is exactly target."""
        speed = abs(float(speed))
        if speed == 0:
            raise ValueError("move_to needs a non-zero speed")
        start = self.end
        distance = target - start
        n = max(1, math.ceil(abs(distance) * self.clk_hz / speed))
        samples = np.linspace(start, target, n + 1)[1:]
        samples[-1] = target
        return self._append(samples, 0.0)

    def random_walk(
        self,
        seconds: float,
        max_speed: float,
        seed: int,
        knot_seconds: float | None = None,
    ) -> "Trajectory":
        """Smooth random motion with reversals: speed is piecewise linear between
        random knots, uniform in [-max_speed, max_speed], every `knot_seconds`
        (default: a twentieth of the segment)."""
        n = self._ticks(seconds)
        if n == 0:
            return self
        rng = np.random.default_rng(seed)
        knot_ticks = max(2, self._ticks(knot_seconds) if knot_seconds else n // 20)
        knots = math.ceil(n / knot_ticks) + 1
        knot_speed = rng.uniform(-max_speed, max_speed, knots)
        knot_speed[0] = self._speed
        k = np.arange(1, n + 1)
        speed = np.interp(k, np.arange(knots) * knot_ticks, knot_speed)
        theta = self.end + np.cumsum(speed) / self.clk_hz
        return self._append(theta, speed[-1])
