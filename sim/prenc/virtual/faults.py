# SPDX-License-Identifier: Apache-2.0
"""Faults of the datasheet as composable, seeded objects.

Each fault changes the signals of an `EncoderRun` in place through `apply(run)`;
`VirtualEncoder` applies them in the order given, so electrical effects (bounce,
glitches) listed last act on what the optics (misreads, contamination) produced.
The truth (`run.theta`) is never changed. Random faults take a `seed` and are
reproducible: the same seed gives the same signals.

Heads are numbered 1 and 2, tracks 1 and 2, sync signals "a" and "b".
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .encoder import SIGNALS, EncoderRun


def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """Maximal runs of True in mask as (start, stop) clock ranges."""
    edges = np.diff(np.concatenate([[0], mask.astype(np.int8), [0]]))
    starts = np.flatnonzero(edges == 1)
    stops = np.flatnonzero(edges == -1)
    return list(zip(starts.tolist(), stops.tolist()))


def _edges(signal: np.ndarray) -> np.ndarray:
    """Clocks c at which signal[c] != signal[c - 1]."""
    return np.flatnonzero(signal[1:] != signal[:-1]) + 1


def _head_key(head: int) -> str:
    if head not in (1, 2):
        raise ValueError(f"head must be 1 or 2, got {head!r}")
    return f"head{head}"


def _signal_key(signal: str) -> str:
    if signal not in SIGNALS:
        raise ValueError(f"signal must be one of {', '.join(SIGNALS)}, got {signal!r}")
    return signal


def _non_negative(**kwargs: int) -> None:
    for name, value in kwargs.items():
        if value < 0:
            raise ValueError(f"{name} must not be negative, got {value!r}")


def _positive(**kwargs: int) -> None:
    for name, value in kwargs.items():
        if value < 1:
            raise ValueError(f"{name} must be at least 1, got {value!r}")


def _track_position(run: EncoderRun, head: int) -> np.ndarray:
    """The track slot under a head at each clock (head 2 sits L/2 away)."""
    offset = 0 if head == 1 else run.disc.length // 2
    return (run.slot + offset) % run.disc.length


@dataclass(frozen=True)
class TransientMisread:
    """One head reads the wrong bit during one pass over one disc slot.

    A pass is a maximal run of clocks with floor(theta) mod L == slot; pass_index
    counts them from 0 in time order. Nothing happens if there is no such pass.
    """

    head: int
    slot: int
    pass_index: int = 0

    def __post_init__(self) -> None:
        _head_key(self.head)
        _non_negative(pass_index=self.pass_index)

    def apply(self, run: EncoderRun) -> None:
        key = _head_key(self.head)
        passes = _runs(run.slot == self.slot % run.disc.length)
        if self.pass_index < len(passes):
            start, stop = passes[self.pass_index]
            run.signals[key][start:stop] ^= 1


@dataclass(frozen=True)
class RandomMisreads:
    """Each pass of a head over any slot is misread with the given probability."""

    head: int
    probability: float
    seed: int = 0

    def __post_init__(self) -> None:
        _head_key(self.head)
        if not 0.0 <= self.probability <= 1.0:
            raise ValueError(f"probability must be in 0..1, got {self.probability!r}")

    def apply(self, run: EncoderRun) -> None:
        key = _head_key(self.head)
        rng = np.random.default_rng(self.seed)
        slot = run.slot
        boundaries = np.concatenate([[0], np.flatnonzero(slot[1:] != slot[:-1]) + 1, [len(slot)]])
        for start, stop in zip(boundaries[:-1].tolist(), boundaries[1:].tolist()):
            if rng.random() < self.probability:
                run.signals[key][start:stop] ^= 1


@dataclass(frozen=True)
class ContaminatedSlot:
    """A spot on one track: that track slot reads inverted on every pass."""

    track: int
    slot: int

    def __post_init__(self) -> None:
        _head_key(self.track)

    def apply(self, run: EncoderRun) -> None:
        key = _head_key(self.track)  # head h reads track h
        under = _track_position(run, self.track) == self.slot % run.disc.length
        run.signals[key][under] ^= 1


@dataclass(frozen=True)
class GrowingDirt:
    """A disc getting dirty: from `start_clock` on, every `every` clocks one more slot of
    `track` reads inverted on every pass, as a ContaminatedSlot does. The slots come in
    the order of a seeded permutation of the track, so a run cut into pieces (each
    with `start_clock` counted from its own first clock, negative once the dirt has
    begun) gets the same dirt. `spots(clock)` is how many are dirty at `clock`."""

    track: int
    every: int
    start_clock: int = 0
    seed: int = 0

    def __post_init__(self) -> None:
        _head_key(self.track)
        _positive(every=self.every)

    def spots(self, clock: int) -> int:
        return 0 if clock < self.start_clock else (clock - self.start_clock) // self.every + 1

    def apply(self, run: EncoderRun) -> None:
        key = _head_key(self.track)
        under = _track_position(run, self.track)
        length = run.disc.length
        count = min(self.spots(len(under) - 1), length)
        slots = np.random.default_rng(self.seed).permutation(length)[:count]
        since = np.full(length, len(under))          # the clock from which a slot is dirty
        since[slots] = self.start_clock + self.every * np.arange(count)
        dirty = np.arange(len(under)) >= since[under]
        run.signals[key][dirty] ^= 1


@dataclass(frozen=True)
class DeadHead:
    """A head stuck at 0, stuck at 1, or reading noise, from start_clock on (until
    stop_clock, if given: the head recovers)."""

    head: int
    mode: str = "stuck0"
    start_clock: int = 0
    seed: int = 0
    stop_clock: int | None = None

    def __post_init__(self) -> None:
        _head_key(self.head)
        _non_negative(start_clock=self.start_clock)
        if self.mode not in ("stuck0", "stuck1", "noise"):
            raise ValueError(f"mode must be stuck0, stuck1 or noise, got {self.mode!r}")

    def apply(self, run: EncoderRun) -> None:
        sig = run.signals[_head_key(self.head)]
        tail = sig[self.start_clock : self.stop_clock]
        if self.mode == "noise":
            tail[:] = np.random.default_rng(self.seed).integers(0, 2, len(tail), dtype=np.uint8)
        else:
            tail[:] = 1 if self.mode == "stuck1" else 0


@dataclass(frozen=True)
class Glitch:
    """A signal inverted for `width` clocks from `clock` on."""

    signal: str
    clock: int
    width: int = 1

    def __post_init__(self) -> None:
        _signal_key(self.signal)
        _non_negative(clock=self.clock)
        _positive(width=self.width)

    def apply(self, run: EncoderRun) -> None:
        run.signals[_signal_key(self.signal)][self.clock : self.clock + self.width] ^= 1


@dataclass(frozen=True)
class RandomGlitches:
    """Up to `count` glitches on a signal at random clocks, widths in [min_width, max_width].

    Glitches never touch: one that would start within max_width clocks of the
    previous one's end is dropped, so two short glitches cannot merge into one pulse
    as long as a filter passes (which would be a real step for any reader)."""

    signal: str
    count: int
    min_width: int = 1
    max_width: int = 1
    seed: int = 0

    def __post_init__(self) -> None:
        _signal_key(self.signal)
        _non_negative(count=self.count)
        _positive(min_width=self.min_width)
        if self.max_width < self.min_width:
            raise ValueError(f"max_width {self.max_width} < min_width {self.min_width}")

    def apply(self, run: EncoderRun) -> None:
        rng = np.random.default_rng(self.seed)
        sig = run.signals[_signal_key(self.signal)]
        starts = rng.integers(0, len(sig), self.count)
        widths = rng.integers(self.min_width, self.max_width + 1, self.count)
        last_end = None
        for start, width in sorted(zip(starts.tolist(), widths.tolist())):
            if last_end is not None and start <= last_end + self.max_width:
                continue
            sig[start : start + width] ^= 1
            last_end = start + width - 1


@dataclass(frozen=True)
class MissedQuadratureState:
    """The reader misses a quadrature state: A and B are seen changing together.

    Takes quadrature transitions whose next transition is on the other signal and
    holds the first edge back until the second, so the state between them never
    shows. `index` picks the k-th such transition; otherwise `count` are drawn
    at random with `seed`. `skip`: the clocks of first edges left alone among those
    drawn (the same draw without some of its missed states). `skew`: the two changes
    reach the pins up to that many clocks apart, in either order, drawn for each
    (two synchronizers resolve one change of both a clock apart, either way round).
    """

    index: int | None = None
    count: int = 1
    seed: int = 0
    skip: frozenset[int] = frozenset()
    skew: int = 0

    def __post_init__(self) -> None:
        _non_negative(count=self.count, skew=self.skew)
        if self.index is not None:
            _non_negative(index=self.index)

    def candidates(self, run: EncoderRun) -> list[tuple[str, int, int]]:
        """(signal, edge clock, next edge clock of the other signal) in time order."""
        edges = sorted(
            [(int(c), "a") for c in _edges(run.a)] + [(int(c), "b") for c in _edges(run.b)]
        )
        out = []
        for (c1, s1), (c2, s2) in zip(edges, edges[1:]):
            if s1 != s2 and c2 > c1:
                out.append((s1, c1, c2))
        return out

    def chosen(self, run: EncoderRun) -> list[tuple[str, int, int]]:
        """The transitions drawn (`skip` included), as candidates() gives them."""
        cands = self.candidates(run)
        if self.index is not None:
            return [cands[self.index]] if self.index < len(cands) else []
        rng = np.random.default_rng(self.seed)
        picks = rng.choice(len(cands), size=min(self.count, len(cands)), replace=False)
        return [cands[i] for i in sorted(picks.tolist())]

    def apply(self, run: EncoderRun) -> None:
        skews = np.random.default_rng([self.seed, 1])
        for signal, c1, c2 in self.chosen(run):
            d = int(skews.integers(-self.skew, self.skew + 1)) if self.skew else 0
            if c1 in self.skip:
                continue
            sig = run.signals[signal]
            # The held signal changes d clocks after the other (before it for d < 0),
            # never past its own next edge.
            later = _edges(sig)
            later = later[later > c1]
            end = max(c1, min(c2 + d, int(later[0]) if len(later) else len(sig)))
            sig[c1:end] = sig[c1 - 1]


@dataclass(frozen=True)
class Bounce:
    """Chatter around every edge of the named signals: random levels in a window of
    `width` clocks centred on the edge, clipped half-way to the neighbouring edges so
    that every settled level stays as it was."""

    signals: tuple[str, ...] = ("a", "b")
    width: int = 4
    seed: int = 0

    def __post_init__(self) -> None:
        for name in self.signals:
            _signal_key(name)
        _positive(width=self.width)

    def apply(self, run: EncoderRun) -> None:
        rng = np.random.default_rng(self.seed)
        for name in self.signals:
            sig = run.signals[_signal_key(name)]
            edges = _edges(sig)
            if not len(edges):
                continue
            bounds = np.concatenate([[0], edges, [len(sig)]])
            for i, c in enumerate(edges.tolist(), start=1):
                lo = max(c - self.width // 2, (bounds[i - 1] + c + 1) // 2)
                hi = min(c + (self.width - self.width // 2), (c + bounds[i + 1]) // 2)
                if hi > lo:
                    sig[lo:hi] = rng.integers(0, 2, hi - lo, dtype=np.uint8)
