# SPDX-License-Identifier: Apache-2.0
"""From the edge timing of a few steady turns to the calibration table.

The record: every edge of the sync track that the disc crossed, in order, with the
clock it was crossed on (`Record`). Over K whole turns the edges' intervals add up to
exactly one turn each (the closure of a turn), so with the mean speed of the record,
the time of each crossing gives the angle of its edge, up to the speed's ripple:

    d[i] = dir x (K x 4L x (t[i] - t[0]) / (t[K 4L] - t[0]) - i)   quarters

is c[x_i] - c[x_0] plus what the speed's ripple moved the disc by at t[i]. An edge is
crossed once a turn, so averaging its K values takes the ripple out, except ripple
locked to the turn (a cogging motor's, say: nothing a single head can tell from the
disc). A plain average leaves the ripple's leakage from the record's ends; the record
is weighted by a Hann window instead (sin^2 over the K turns), which takes a
sinusoidal ripple that is not locked out to about 1/K^3 where the plain average
leaves 1/K. `make bench` (section 10) gives the turns it needs.

Then the table's zero: the corrections' mean is taken off (see prenc.cal.table).

Checks, each refusing the run with a message that says what to do:
- the record holds at least `turns` whole turns, in one direction, each edge the one
  after the edge before (no reversal, no missed state);
- no stop: no interval is longer than 8 times the record's mean interval, and the
  turns' durations agree within 25 % (a roughly steady speed);
- plausible: every correction within +-2 slots (the file's range);
- the turns agree: each turn sees the same edges. Each turn's deviation, less its
  running mean over SMOOTH edges (which takes out a ripple slower than that), is
  within `agree` slots RMS of the turns' mean: a larger spread means a disc slipping
  on its hub, edges read with noise, or a speed changing within a few slots. The
  spread is reported.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .table import FRAC, LIMIT, Table, entries

AGREE_SLOTS = 1 / 16   # each turn's edges within this of the turns' mean (RMS), slots
SMOOTH = 64            # edges: the running mean that takes the ripple out of one turn
STEADY = 1.25          # the longest turn over the shortest
STOP = 8.0             # an interval this many times the mean is a stop


class CalibrationError(ValueError):
    """The run cannot give a table: the message says why and what to do."""


@dataclass
class Record:
    """Consecutive crossings of the sync track's edges: `edges[i]` (edge index, 0 to
    4 x 2^n - 1) crossed on clock `clocks[i]`."""

    n: int
    edges: np.ndarray
    clocks: np.ndarray

    def __post_init__(self) -> None:
        self.edges = np.asarray(self.edges, dtype=np.int64)
        self.clocks = np.asarray(self.clocks, dtype=np.int64)
        if self.edges.shape != self.clocks.shape or self.edges.ndim != 1:
            raise CalibrationError("a record needs as many clocks as edges")


@dataclass
class Result:
    table: Table
    turns: int
    direction: int            # +1 clockwise, -1 counter-clockwise
    clocks_per_turn: float    # the record's mean
    turn_rms: float           # slots: the turns' edges against their mean (RMS)
    turn_spread: float        # the longest turn over the shortest
    harmonics: dict = field(default_factory=dict)   # what the table says of the disc

    def summary(self, clk_hz: float | None = None) -> str:
        h = self.harmonics
        speed = (f", {60 * clk_hz / self.clocks_per_turn:.1f} rpm" if clk_hz else "")
        return (f"{self.turns} turns {'CW' if self.direction > 0 else 'CCW'}{speed}; "
                f"the turns {100 * (self.turn_spread - 1):.2f} % apart in time and "
                f"see the edges {self.turn_rms:.5f} slot RMS apart\n"
                f"corrections: {h['rms']:.4f} slot RMS, {h['max']:.4f} max; eccentricity "
                f"{h['eccentricity']:.4f} slot; B against A {h['phase_deg']:+.2f} deg; "
                f"duty A {100 * h['duty_a']:.2f} %, B {100 * h['duty_b']:.2f} %; "
                f"edges {h['edges_rms']:.4f} slot RMS")


def _deviation(clocks: np.ndarray, turns: int, quarters: int, direction: int) -> np.ndarray:
    """d[i] for i = 0 .. turns x quarters - 1 (see the module's doc)."""
    t = clocks[: turns * quarters + 1].astype(np.float64) - float(clocks[0])
    theta = turns * quarters * t / t[-1]
    return direction * (theta[:-1] - np.arange(turns * quarters))


def _fold(d: np.ndarray, turns: int, quarters: int) -> np.ndarray:
    """The Hann-weighted mean of each edge over the turns (index i mod quarters)."""
    s = (np.arange(turns * quarters) + 0.5) / (turns * quarters)
    w = np.sin(np.pi * s) ** 2
    est = (w * d).reshape(turns, quarters).sum(0) / w.reshape(turns, quarters).sum(0)
    return est - est.mean()


def describe(n: int, c: np.ndarray) -> dict:
    """What corrections (quarters, by edge) say of the disc, in slots and degrees."""
    q = entries(n)
    x = np.arange(q)
    once = np.exp(-2j * np.pi * x / q)
    ecc = 2 * abs(np.sum(c * once)) / q / 4
    by_type = [float(np.mean(c[t::4])) for t in range(4)]   # edge x mod 4: 0 A fall, 1 B fall, 2 A rise, 3 B rise
    a_centre = (by_type[2] + by_type[0]) / 2
    b_centre = (by_type[3] + by_type[1]) / 2
    residual = c - np.real(2 * np.sum(c * once) / q * np.conj(once)) \
        - np.array(by_type)[x % 4]
    return {"rms": float(np.sqrt(np.mean(c * c)) / 4), "max": float(np.max(np.abs(c)) / 4),
            "eccentricity": float(ecc), "phase_deg": float((b_centre - a_centre) / 4 * 360),
            "duty_a": 0.5 + (by_type[0] - by_type[2]) / 4,
            "duty_b": 0.5 + (by_type[1] - by_type[3]) / 4,
            "edges_rms": float(np.sqrt(np.mean(residual ** 2)) / 4)}


def calibrate(record: Record, turns: int = 10, agree: float = AGREE_SLOTS) -> Result:
    """The table from `turns` whole turns of the record (its first ones), checked."""
    n, edges, clocks = record.n, record.edges, record.clocks
    quarters = entries(n)
    if turns < 2:
        raise CalibrationError(f"turns = {turns}: a calibration needs at least 2 turns")
    need = turns * quarters + 1
    if len(edges) < need:
        raise CalibrationError(f"the record holds {max(len(edges) - 1, 0) / quarters:.2f} turns, "
                               f"{turns} are asked for: turn the disc longer")
    edges, clocks = edges[:need], clocks[:need]
    if np.any((edges < 0) | (edges >= quarters)):
        raise CalibrationError(f"an edge index is outside 0..{quarters - 1}: "
                               f"the record is not of a disc of N = {n}")
    step = (edges[1:] - edges[:-1]) % quarters
    direction = 1 if step[0] == 1 else -1
    if np.any(step != (1 if direction > 0 else quarters - 1)):
        i = int(np.flatnonzero(step != step[0])[0]) + 1
        raise CalibrationError(f"crossing {i} (edge {edges[i]}) does not follow edge {edges[i - 1]}: "
                               "the disc reversed or a state was missed; turn it one way, steadily")
    interval = np.diff(clocks)
    if np.any(interval <= 0):
        raise CalibrationError("the record's clocks do not increase: it is corrupt")
    mean = (clocks[-1] - clocks[0]) / (need - 1)
    if np.max(interval) > STOP * mean:
        i = int(np.argmax(interval)) + 1
        raise CalibrationError(f"the disc nearly stopped at crossing {i} (an interval of "
                               f"{interval.max() / mean:.1f} x the mean): turn it steadily")
    durations = clocks[quarters::quarters] - clocks[:-1:quarters][:turns]
    spread = float(durations.max() / durations.min())
    if spread > STEADY:
        raise CalibrationError(f"the turns took from {durations.min()} to {durations.max()} clocks "
                               f"({100 * (spread - 1):.0f} % apart): turn the disc at a steadier speed")
    d = _deviation(clocks, turns, quarters, direction)
    est = _fold(d, turns, quarters)
    # Edge x_i is at index i mod quarters of the fold: rotate so that est[x] is edge x.
    x = edges[: quarters]
    c = np.zeros(quarters)
    c[x] = est
    c -= c.mean()
    if np.max(np.abs(c)) * (1 << FRAC) > LIMIT:
        raise CalibrationError(f"a correction of {np.max(np.abs(c)) / 4:.2f} slots is beyond the "
                               "table's +-2 slots: is this the disc the reader was built for?")
    kernel = np.ones(SMOOTH) / SMOOTH
    fast = d - np.convolve(np.pad(d, SMOOTH // 2, mode="edge"), kernel, mode="same")[
        SMOOTH // 2: SMOOTH // 2 + len(d)]
    single = fast.reshape(turns, quarters)[:, SMOOTH:-SMOOTH]
    single = single - single.mean(axis=0)
    turn_rms = float(np.sqrt(np.mean(single ** 2)) / 4)
    if turn_rms > agree:
        raise CalibrationError(f"the turns see the edges {turn_rms:.4f} slot RMS apart (at most "
                               f"{agree:.4f}): the disc slipped, the edges are read with noise, or "
                               "the speed was not steady; turn it steadily and try again")
    table = Table.from_quarters(n, c)
    return Result(table, turns, direction, float(np.mean(durations)), turn_rms, spread,
                  describe(n, table.quarters))
