# SPDX-License-Identifier: Apache-2.0
"""Where a printed disc's edges really are, and when a steady turn crosses them.

For calibration (issue 38) runs of many turns: computed edge by edge, not clock by
clock (ten turns at 70 rpm are 2.6 x 10^8 clocks at 30 MHz, 41,000 edges).

- `true_corrections(printing, n)`: c[x] in quarters, the shaft's true angle at the
  crossing of edge x is (x + c[x]) / 4 slots: what a perfect calibration would find
  (before its zero is taken off). Edge x is the one a clockwise step into quarter x
  crosses (prenc.cal.table); on the disc of prenc.virtual.printing, edge 4p + 1 is B's
  fall near p + 0.25, 4p + 2 A's rise, 4p + 3 B's rise and 4p + 4 A's fall near p + 1,
  seen through the eccentricity.
- `steady_record(...)`: the crossings of `turns` turns and more at a steady speed with
  a sinusoidal speed ripple (as Trajectory.constant makes it), each on the first clock
  at or after the crossing: a prenc.cal.Record.
"""

from __future__ import annotations

import math

import numpy as np

from ..cal.calibrate import Record
from .printing import Printing


def true_corrections(printing: Printing | None, n: int) -> np.ndarray:
    """c[x] (quarters) for the 4 x 2^n edges; zeros on an ideal disc."""
    length = 1 << n
    quarters = 4 * length
    if printing is None:
        return np.zeros(quarters)
    e = printing.edges(length)
    p = np.arange(length)
    seen = np.zeros(quarters)              # the edge's place on the disc, in slots
    seen[4 * p + 1] = p - 1 + e["b_fall"][(p - 1) % length]
    seen[4 * p + 2] = p + e["a_rise"]
    seen[4 * p + 3] = p + e["b_rise"]
    seen[(4 * p + 4) % quarters] = np.where(p == length - 1, -1.0, p) + e["a_fall"]
    # The shaft's angle theta that the head sees there: theta + ecc sin(2 pi theta / L + phi) = seen.
    theta = seen.copy()
    k = 2 * math.pi / length
    for _ in range(40):
        arg = k * theta + printing.eccentricity_phase
        theta -= (theta + printing.eccentricity * np.sin(arg) - seen) / \
            (1 + printing.eccentricity * k * np.cos(arg))
    return 4 * theta - np.arange(quarters)


def steady_record(corrections: np.ndarray, n: int, rpm: float, turns: float,
                  clk_hz: float = 30e6, ripple: float = 0.0, ripple_hz: float = 100.0,
                  start_edge: int = 0, direction: int = 1, ripple_phase: float = 0.0) -> Record:
    """Crossings of `turns` turns (and one edge) from just before `start_edge`, at
    `rpm` (the mean speed) with a speed ripple: speed x (1 + ripple sin(w t + phase))."""
    quarters = 4 << n
    v = abs(rpm) / 60.0 * quarters / clk_hz        # quarters per clock
    count = int(round(turns * quarters)) + 1
    i = np.arange(count)
    x = (start_edge + direction * i) % quarters
    # The angle travelled from the start (quarters, positive) at each crossing.
    unwrapped = start_edge + direction * i
    angle = direction * (unwrapped + corrections[x] - (start_edge + corrections[start_edge])) + 0.5
    w = 2 * math.pi * ripple_hz / clk_hz
    amp = v * ripple / w if ripple else 0.0

    def travelled(t):
        return v * t + amp * (np.cos(ripple_phase) - np.cos(w * t + ripple_phase))

    t = angle / v
    for _ in range(30):
        t -= (travelled(t) - angle) / (v * (1 + ripple * np.sin(w * t + ripple_phase)))
    return Record(n, x, np.ceil(t).astype(np.int64))
