# SPDX-License-Identifier: Apache-2.0
"""The sensors' non-repeatable errors, as composable, seeded objects beside the faults
(prenc.virtual.faults; issue 60).

A head is a photodiode or a phototransistor behind a comparator. Its crossings are not
where the disc's edges are, and not the same on each pass:

- `CrossingJitter`: each crossing moves by a Gaussian distance (slots RMS) on each
  pass: the comparator's noise.
- `Chatter`: an edge crossed slowly toggles a few more times within a few microseconds
  (too little hysteresis): most at a crawl, less as the disc speeds up.
- `EdgeDelay`: the output lags the light by a time, longer on one edge than the other
  (the phototransistor's rise and fall times): the crossing moves by speed x delay, so
  the duty cycle changes with speed.
- `DutyDrift`: the duty cycle drifts slowly (temperature): rising crossings earlier and
  falling ones later by half the drift each.

Each changes the signals of an `EncoderRun` in place through `apply(run)`, as the faults
do; `VirtualEncoder(faults=[...])` takes them in the same list (list them after the
optics' faults and before the electrical ones). The truth is never changed; the same
seed gives the same signals. Crossings keep their order: a crossing moved onto or past
the one before it stops a clock after it.

Defaults, from a cheap slotted sensor's datasheet: Omron EE-SX1041 (phototransistor,
VCC = 5 V, RL = 100 ohm): rise time 4 us typical, fall time 4 us typical; a comparator
at half the swing sees an RC-like output cross after ln 2 / ln 9 of the 10-90 % time:
about 1.3 us.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .encoder import EncoderRun
from .faults import _edges, _signal_key

RC_HALF = np.log(2) / np.log(9)   # the 50 % crossing of an RC step, in 10-90 % rise times


def _check_signals(signals: tuple[str, ...]) -> None:
    for s in signals:
        _signal_key(s)


def _speed(run: EncoderRun) -> np.ndarray:
    """|d theta / d clock| at each clock, slots per clock."""
    v = np.abs(np.diff(run.theta, prepend=run.theta[:1]))
    if len(v) > 1:
        v[0] = v[1]
    return v


def travelled(run: EncoderRun, edges: np.ndarray, slots: np.ndarray) -> np.ndarray:
    """The clocks (fractional) at which the disc has travelled `slots` from each of
    `edges` (later where positive, earlier where negative): a crossing moved along the
    disc. Where the speed changes near an edge this is where the disc really is that far
    from it, not the edge's own speed times the time (which at a step of speed would move
    a crossing by the new speed's clocks into the old speed's travel)."""
    path = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(run.theta)))])
    return np.interp(path[edges] + slots, path, np.arange(len(path), dtype=np.float64))


def move_edges(signal: np.ndarray, edges: np.ndarray, new: np.ndarray) -> np.ndarray:
    """The signal with its level changes at clocks `edges` moved to `new` (rounded, kept
    in order, one clock apart at least)."""
    if len(edges) == 0:
        return signal.copy()
    t = np.clip(np.rint(new).astype(np.int64), 1, len(signal) - 1)
    # In order, one clock apart at least: an edge pushed onto the one before it stops
    # a clock after it.
    k = np.arange(len(t))
    t = np.maximum.accumulate(t - k) + k
    if t[-1] >= len(signal):
        t = np.minimum(t, len(signal) - len(t) + k)
    out = np.empty_like(signal)
    levels = np.concatenate([[signal[0]], signal[edges]])
    bounds = np.concatenate([[0], t, [len(signal)]])
    for k, level in enumerate(levels):
        out[bounds[k]:bounds[k + 1]] = level
    return out


@dataclass
class CrossingJitter:
    """Each crossing of `signals` moves by N(0, sigma) slots of the disc's travel,
    independently on each pass."""

    sigma: float = 0.005
    signals: tuple[str, ...] = ("a", "b")
    seed: int = 0

    def __post_init__(self) -> None:
        _check_signals(self.signals)
        if self.sigma < 0:
            raise ValueError(f"sigma must not be negative, got {self.sigma!r}")

    def apply(self, run: EncoderRun) -> None:
        rng = np.random.default_rng(self.seed)
        for name in self.signals:
            sig = run.signals[name]
            edges = _edges(sig)
            shift_slots = rng.normal(0.0, self.sigma, len(edges))
            run.signals[name] = move_edges(sig, edges, travelled(run, edges, shift_slots))


@dataclass
class Chatter:
    """Crossings taken at a crawl toggle `pairs` times more (a level and back), at random
    within `window_us` after the crossing. A crossing at speed v (slots a second) chatters
    with probability exp(-v / crawl): always at a standstill, rarely above `crawl`."""

    pairs: int = 2
    window_us: float = 5.0
    crawl: float = 20.0       # slots a second
    signals: tuple[str, ...] = ("a", "b")
    seed: int = 0

    def __post_init__(self) -> None:
        _check_signals(self.signals)
        if self.pairs < 1 or self.window_us <= 0 or self.crawl <= 0:
            raise ValueError("pairs must be at least 1, window_us and crawl positive")

    def apply(self, run: EncoderRun) -> None:
        rng = np.random.default_rng(self.seed)
        speed = _speed(run) * run.clk_hz          # slots a second
        window = max(2 * self.pairs + 1, int(round(self.window_us * 1e-6 * run.clk_hz)))
        for name in self.signals:
            sig = run.signals[name].copy()
            edges = _edges(sig)
            next_edge = np.concatenate([edges[1:], [len(sig)]])
            for c, stop in zip(edges.tolist(), next_edge.tolist()):
                if rng.random() >= np.exp(-speed[c] / self.crawl):
                    continue
                room = min(window, stop - c - 1)
                if room < 2 * self.pairs + 1:
                    continue
                # 2 pairs toggles: the level flips back to the old one and returns.
                times = np.sort(rng.choice(np.arange(1, room), 2 * self.pairs, replace=False)) + c
                old = sig[c - 1]
                for k in range(0, len(times), 2):
                    sig[times[k]:times[k + 1]] = old
            run.signals[name] = sig


@dataclass
class EdgeDelay:
    """The output lags the light: rising crossings by `rise_us` x RC_HALF, falling ones by
    `fall_us` x RC_HALF (rise and fall times, 10-90 %, as datasheets give them)."""

    rise_us: float = 4.0
    fall_us: float = 4.0
    signals: tuple[str, ...] = ("a", "b", "head1", "head2")

    def __post_init__(self) -> None:
        _check_signals(self.signals)
        if self.rise_us < 0 or self.fall_us < 0:
            raise ValueError("rise_us and fall_us must not be negative")

    def apply(self, run: EncoderRun) -> None:
        rise = self.rise_us * 1e-6 * run.clk_hz * RC_HALF
        fall = self.fall_us * 1e-6 * run.clk_hz * RC_HALF
        for name in self.signals:
            sig = run.signals[name]
            edges = _edges(sig)
            rising = sig[edges] == 1
            run.signals[name] = move_edges(sig, edges, edges + np.where(rising, rise, fall))


@dataclass
class DutyDrift:
    """The duty cycle drifts by `amplitude` (a fraction of a slot) x sin(2 pi t / period):
    rising crossings come amplitude / 2 earlier, falling ones amplitude / 2 later."""

    amplitude: float = 0.02
    period_s: float = 10.0
    phase: float = 0.0
    signals: tuple[str, ...] = ("a", "b")

    def __post_init__(self) -> None:
        _check_signals(self.signals)
        if self.period_s <= 0:
            raise ValueError(f"period_s must be positive, got {self.period_s!r}")

    def drift(self, clocks: np.ndarray, clk_hz: float) -> np.ndarray:
        """The duty's change at these clocks, in slots."""
        t = clocks / clk_hz
        return self.amplitude * np.sin(2 * np.pi * t / self.period_s + self.phase)

    def apply(self, run: EncoderRun) -> None:
        for name in self.signals:
            sig = run.signals[name]
            edges = _edges(sig)
            half = self.drift(edges, run.clk_hz) / 2          # slots
            rising = sig[edges] == 1
            run.signals[name] = move_edges(sig, edges, travelled(run, edges, np.where(rising, -half, half)))
