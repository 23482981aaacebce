# SPDX-License-Identifier: Apache-2.0
"""The virtual encoder: disc, two heads and the sync track, sampled on a clock.

Geometry (shared/encoder-disc.md): track 1 carries s(x) at slot x, track 2 carries
s(x + D mod L). Head 1 reads track 1 at the disc angle theta; head 2, mounted L/2
slots away, reads track 2 at theta + L/2, so for the default D = 2^(N-1) + N - 1
it sees s(p + N - 1). The sync track gives A = 1 for frac(theta) in [0.5, 1) and
B = 1 for frac(theta) in [0.75, 1) or [0, 0.25).

    disc = Disc(n=10)
    run = VirtualEncoder(disc, faults=[Glitch("a", clock=500, width=2)]).run(traj)
    for ev in run.events():      # (clock, head1, head2, a, b) at every change
        ...
    run.slot[k], run.quarter[k], run.hybrid[k]   # the truth at clock k

Signals are 1 for a light (transparent) cell, as on the datasheet.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable, NamedTuple, Sequence

import numpy as np

from ..codes.debruijn import Code
from .printing import Printing
from .trajectory import Trajectory

SIGNALS = ("head1", "head2", "a", "b")


def default_shift(n: int) -> int:
    """D = 2^(N-1) + N - 1: head 2 then reads the last bit of W(p)."""
    return (1 << (n - 1)) + n - 1


@dataclass(frozen=True)
class Disc:
    """An encoder disc: the code on two tracks and the quadrature sync track.

    `printing` gives a printed disc's imperfections (prenc.virtual.printing); without
    it the disc is the datasheet's ideal one. `heads`, `sync` and `hybrid` are always
    the ideal geometry; `read` is what the heads and the sync track of this disc see.
    """

    n: int = 10
    taps: tuple[int, ...] | None = None
    shift: int | None = None
    printing: Printing | None = None
    code: Code = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        code = Code(self.n, self.taps)
        object.__setattr__(self, "code", code)
        object.__setattr__(self, "taps", code.taps)
        shift = default_shift(code.n) if self.shift is None else int(self.shift)
        if not 0 <= shift < code.length:
            raise ValueError(f"track shift D = {shift} is out of range 0..{code.length - 1}")
        object.__setattr__(self, "shift", shift)

    @property
    def length(self) -> int:
        return self.code.length

    @property
    def track1(self) -> np.ndarray:
        return self.code.sequence

    @property
    def track2(self) -> np.ndarray:
        return np.roll(self.code.sequence, -self.shift)

    def slot(self, theta):
        """p = floor(theta) mod L."""
        return np.floor(theta).astype(np.int64) % self.length

    @staticmethod
    def quarter(theta):
        """q = floor(4 frac(theta)), 0..3."""
        frac = np.asarray(theta) - np.floor(theta)
        return np.minimum((frac * 4).astype(np.int64), 3)

    def hybrid(self, theta):
        """h = 4p + q, N+2 bits."""
        return 4 * self.slot(theta) + self.quarter(theta)

    def heads(self, theta) -> tuple[np.ndarray, np.ndarray]:
        """What head 1 and head 2 see at angle theta (uint8 arrays)."""
        p = self.slot(theta)
        seq = self.code.sequence
        head1 = seq[p]
        head2 = seq[(p + self.length // 2 + self.shift) % self.length]
        return head1, head2

    def read(self, theta) -> dict[str, np.ndarray]:
        """The four signals of this disc at the shaft angle theta, in SIGNALS order."""
        if self.printing is None:
            head1, head2 = self.heads(theta)
            a, b = self.sync(theta)
        else:
            head1, _ = self.heads(self.printing.seen(theta, self.length, head=1))
            _, head2 = self.heads(self.printing.seen(theta, self.length, head=2))
            a, b = self.printing.sync(theta, self.length)
        return {"head1": np.array(head1, dtype=np.uint8), "head2": np.array(head2, dtype=np.uint8),
                "a": a, "b": b}

    @classmethod
    def sync(cls, theta) -> tuple[np.ndarray, np.ndarray]:
        """A and B of the quadrature sync track at angle theta (uint8 arrays)."""
        q = cls.quarter(theta)
        a = (q >= 2).astype(np.uint8)
        b = ((q == 3) | (q == 0)).astype(np.uint8)
        return a, b


class Event(NamedTuple):
    """The four input levels from `clock` on, until the next event."""

    clock: int
    head1: int
    head2: int
    a: int
    b: int


@dataclass
class EncoderRun:
    """Signals seen by the reader at each clock tick, with the truth beside them."""

    disc: Disc
    clk_hz: float
    theta: np.ndarray
    signals: dict[str, np.ndarray]

    def __len__(self) -> int:
        return len(self.theta)

    @property
    def head1(self) -> np.ndarray:
        return self.signals["head1"]

    @property
    def head2(self) -> np.ndarray:
        return self.signals["head2"]

    @property
    def a(self) -> np.ndarray:
        return self.signals["a"]

    @property
    def b(self) -> np.ndarray:
        return self.signals["b"]

    @property
    def slot(self) -> np.ndarray:
        return self.disc.slot(self.theta)

    @property
    def quarter(self) -> np.ndarray:
        return self.disc.quarter(self.theta)

    @property
    def hybrid(self) -> np.ndarray:
        return self.disc.hybrid(self.theta)

    def change_clocks(self) -> np.ndarray:
        """Clock 0 and every clock at which at least one signal changes."""
        stacked = np.stack([self.signals[s] for s in SIGNALS])
        changed = np.any(stacked[:, 1:] != stacked[:, :-1], axis=0)
        return np.concatenate([[0], np.flatnonzero(changed) + 1])

    def rows(self) -> list[tuple[int, int, int, int]]:
        """(head1, head2, a, b) at every clock: the reader's pins, in SIGNALS order."""
        return list(zip(*(self.signals[s].tolist() for s in SIGNALS)))

    def events(self) -> list[Event]:
        """The timed event stream that a testbench drives onto the reader's pins."""
        clocks = self.change_clocks()
        cols = [self.signals[s][clocks].tolist() for s in SIGNALS]
        return [Event(int(c), *vals) for c, *vals in zip(clocks.tolist(), *cols)]


class VirtualEncoder:
    """A disc read by two heads and a sync track, with faults applied in order."""

    def __init__(self, disc: Disc | None = None, faults: Sequence["object"] = ()):
        self.disc = disc if disc is not None else Disc()
        self.faults = list(faults)

    def clean(self, theta: np.ndarray) -> dict[str, np.ndarray]:
        return self.disc.read(theta)

    def run(self, trajectory: Trajectory | Iterable[float], clk_hz: float | None = None) -> EncoderRun:
        """Sample the encoder along a trajectory, one sample per clock tick."""
        if isinstance(trajectory, Trajectory):
            theta = trajectory.theta
            clk_hz = trajectory.clk_hz
        else:
            theta = np.asarray(trajectory, dtype=np.float64)
            clk_hz = 1.0 if clk_hz is None else clk_hz
        run = EncoderRun(self.disc, float(clk_hz), theta, self.clean(theta))
        for fault in self.faults:
            fault.apply(run)
        return run
