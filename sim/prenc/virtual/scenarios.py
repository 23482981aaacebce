# SPDX-License-Identifier: Apache-2.0
"""End-to-end scenarios for the reader, and the check against the true angle.

A scenario is a trajectory and a list of faults for a disc of N bits and a glitch
filter length: the RTL tests, the reference tests, `make demo` and the fault
campaign draw from the same list. `judge` compares a reader's outputs, clock by
clock, with the truth of the run:

    whenever valid is 1, pos_hyb (and pos_abs = pos_hyb >> 2) equals the true hybrid
    position `latency` clocks earlier

except where a fault on A or B moved the pins themselves away from the truth: at a
clock inside such a stretch (`sync_stretches`: the clocks where the faulted A or B
differ from the clean ones, those fewer than F apart counted as one), the truth of
any clock of that stretch or of the clock either side is accepted too, and nowhere
else: a fault can hold the pins back or push them on for as long as it lasts, not
longer. With a glitch filter
of F clocks, the truth within F clocks is accepted as well: the filter removes true
pulses shorter than F (a reversal right at an edge) as it removes glitches.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Sequence

import numpy as np

from .encoder import EncoderRun, Disc, VirtualEncoder
from .faults import (Bounce, ContaminatedSlot, DeadHead, MissedQuadratureState, RandomGlitches,
                     RandomMisreads, TransientMisread)
from ..core.mode_fsm import Mode
from ..core.reader import LATENCY
from .trajectory import Trajectory


def core_latency(filter_len: int) -> int:
    """Clocks from the pins to prenc_core's pos_abs, pos_hyb and pos_valid."""
    return LATENCY + filter_len


def max_speed(filter_len: int) -> float:
    """Slots per clock the scenarios stay under: 0.2 / (FILTER + 2), so each
    quadrature state lasts more than the filter needs."""
    return 0.2 / (filter_len + 2)


def glitch_speed(filter_len: int) -> float:
    """Slots per clock the scenarios with glitches stay under: max_speed, and each
    quadrature state at least 3 FILTER clocks long (1 / (12 FILTER) slots a clock).
    A glitch shorter than FILTER then leaves at least FILTER clocks of the state on one
    side of it, which the filter shows. Faster, glitches can hide a state (the filter
    shows A and B as one state) or delay one signal's edge past the other's, and a
    reader counts wrong (docs/architecture.md)."""
    return min(max_speed(filter_len), 1 / (12 * filter_len)) if filter_len else max_speed(filter_len)


def fault_speed(filter_len: int, width: int) -> float:
    """Slots per clock the scenarios stay under when a fault holds the pins off the disc
    for up to `width` clocks at an edge (bounce, a missed state's skew): max_speed, and
    each quadrature state 1.25 (width + FILTER) clocks long, so that FILTER clean clocks
    of it are left for the filter, which shows A and B as one state. Faster, the filter
    can miss the state, and chatter can show the neighbours in the wrong order: a
    reader counts wrong (docs/architecture.md)."""
    return min(max_speed(filter_len), 0.2 / max(width + filter_len, 1))


@dataclass
class Scenario:
    name: str
    what: str
    trajectory: Trajectory
    faults: list = field(default_factory=list)

    def run(self, n: int) -> EncoderRun:
        return VirtualEncoder(Disc(n), self.faults).run(self.trajectory)


def scenarios(n: int, filter_len: int, seed: int = 1) -> dict[str, Scenario]:
    """Every scenario, named. Each lasts at most ~30,000 clocks at N=10."""
    rng = np.random.default_rng(seed)
    v = max_speed(filter_len)
    length = 1 << n
    start = float(rng.uniform(0, length))
    lock = 4 * n + 4                       # slots of travel that surely verify
    lock_clocks = int(lock / v) + 200
    walk = dict(max_speed=v, seed=seed, knot_seconds=int(8 / v))

    def traj(s: float = start) -> Trajectory:
        return Trajectory(clk_hz=1, start=s)

    out: list[Scenario] = []

    def add(name: str, what: str, t: Trajectory, faults: Sequence = ()) -> None:
        out.append(Scenario(name, what, t, list(faults)))

    add("start_at_rest_cw", "rest, then CW: start-up needs 3N-1 slots",
        traj().rest(300).constant(v, lock_clocks).rest(100).constant(-v, 2000))
    add("start_moving_ccw", "moving CCW from the first clock",
        traj().constant(-v, lock_clocks + 2000))
    add("reversals", "random walk with reversals, also at mid-slot",
        traj().constant(v, lock_clocks).random_walk(12000, **walk))
    add("reversal_at_strobe", "reversals exactly at the sampling instant",
        traj().constant(v, lock_clocks).move_to(start + lock + 0.5, v).move_to(start + lock - 3.2, v)
        .move_to(start + lock + 0.5, v).move_to(start + lock + 0.5 - 6, v))
    add("accelerate", "from rest to full speed and back, both directions",
        traj().accelerate(v, 4000).constant(v, 1000).accelerate(-v, 8000).accelerate(0, 4000))
    # Faults, each after start-up; the disc moves back and forth over them.
    here = start + lock + 2
    back_and_forth = lambda t: t.move_to(here - 8, v).move_to(here + 8, v).move_to(here - 8, v)
    p = int(np.floor(here)) % length
    add("transient_misread", "one misread on each head, one pass",
        back_and_forth(traj().constant(v, lock_clocks)),
        [TransientMisread(1, (p + 3) % length, 0), TransientMisread(2, (p - 2) % length, 1)])
    add("random_misreads", "2 % of the passes misread on each head",
        traj().constant(v, lock_clocks).random_walk(12000, **walk),
        [RandomMisreads(1, 0.02, seed), RandomMisreads(2, 0.02, seed + 1)])
    add("contaminated_track1", "a spot on track 1: wrong on every pass",
        back_and_forth(traj().constant(v, lock_clocks)), [ContaminatedSlot(1, (p + 2) % length)])
    add("contaminated_track2", "a spot on track 2: wrong on every pass",
        back_and_forth(traj().constant(v, lock_clocks)),
        [ContaminatedSlot(2, (p + n - 1 + length // 2 - 3) % length)])
    for head, mode in ((1, "stuck0"), (2, "stuck1"), (1, "noise")):
        add(f"dead_head{head}_{mode}", f"head {head} {mode} after start-up",
            traj().constant(v, lock_clocks).random_walk(10000, **walk),
            [DeadHead(head, mode, start_clock=lock_clocks, seed=seed)])
    def slower_walk(speed: float, clocks: int) -> Trajectory:
        """The start-up and random walk of the others, under a lower speed limit."""
        return traj().constant(speed, int(lock / speed) + 200).random_walk(
            clocks, **dict(walk, max_speed=speed, knot_seconds=int(8 / speed)))

    # Glitches shorter than FILTER at a speed where each state lasts 3 FILTER clocks
    # (glitch_speed): one glitch leaves FILTER clocks of a state on a side of it.
    add("glitches", "glitches on A and B shorter than the filter (none without a filter)",
        slower_walk(glitch_speed(filter_len), 10000),
        [RandomGlitches("a", 20, 1, filter_len - 1, seed),
         RandomGlitches("b", 20, 1, filter_len - 1, seed + 1)] if filter_len >= 2 else [])
    # A missed state's two changes reach the pins together or up to FILTER - 1 clocks
    # apart in either order (the synchronizers, bounce): the filter keeps A and B as one
    # state, so the reader sees them together either way. Bounce is FILTER clocks wide.
    # Both hold the pins off the disc around an edge, so these scenarios move at
    # fault_speed: the state after the fault still lasts FILTER clocks.
    skew = max(filter_len - 1, 0)
    width = max(2, filter_len)

    add("missed_state", "quadrature states missed: A and B seen changing together "
        "(or fewer than FILTER clocks apart, either way round)",
        slower_walk(fault_speed(filter_len, skew), 12000),
        [MissedQuadratureState(count=3, seed=seed, skew=skew)])
    add("bounce", "chatter on every edge of all four signals",
        slower_walk(fault_speed(filter_len, width), 10000),
        [Bounce(("a", "b", "head1", "head2"), width=width, seed=seed)])
    # Not combined: bounce of FILTER clocks on A/B with a missed state. Chatter that
    # long can split "A and B changing together" into two states, each FILTER clocks
    # long, in the wrong order: two legal steps the wrong way, a slot off, which no
    # quadrature decoder can see (the code check finds it at later strobes). FILTER
    # must outlast the chatter (docs/architecture.md).
    add("combined", "misreads, a contaminated slot, a dead head, missed states, head bounce",
        slower_walk(fault_speed(filter_len, skew), 16000),
        [RandomMisreads(1, 0.01, seed), ContaminatedSlot(2, (p + 5) % length),
         DeadHead(1, "noise", start_clock=lock_clocks + 8000, seed=seed),
         MissedQuadratureState(count=2, seed=seed, skew=skew),
         Bounce(("head1", "head2"), width=width, seed=seed)])
    return {s.name: s for s in out}


def must_lock(name: str) -> bool:
    """Whether every draw of the scenario must reach a valid position: start-up,
    reversals and acceleration, without faults."""
    return name.startswith(("start", "reversals", "accelerate"))


def sync_stretches(enc: EncoderRun, filter_len: int = 0,
                   clean: tuple[np.ndarray, np.ndarray] | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The stretches where a fault on A or B holds the pins off the truth: (first clocks,
    last clocks), each stretch from the first to the last clock where the faulted A or B
    differs from the clean one (the ideal disc's, or `clean`: the disc's own A and B),
    where clocks fewer than `filter_len` apart count as one stretch.

    A glitch filter of F clocks cannot settle between two such clocks (it needs F equal
    samples in a row), so two 1-clock glitches next to a true edge with one clean
    clock between them delay that edge by the whole stretch, not by one clock. For the
    same reason a state of the pins shorter than F clocks is in a stretch, fault or not:
    the filter, which keeps A and B as one state, never shows it and holds the state
    before it (A and B changing a clock apart, a reversal right at an edge)."""
    a, b = Disc.sync(enc.theta) if clean is None else clean
    changes = np.flatnonzero((enc.a[1:] != enc.a[:-1]) | (enc.b[1:] != enc.b[:-1])) + 1
    bounds = np.concatenate([[0], changes, [len(enc.a)]])
    short = np.repeat(np.diff(bounds) < filter_len, np.diff(bounds))
    differs = np.flatnonzero((enc.a != a) | (enc.b != b) | short)
    if not len(differs):
        return differs, differs
    # A new stretch starts where the clean clocks since the last differing one
    # number filter_len or more.
    starts = np.concatenate([[0], np.flatnonzero(np.diff(differs) - 1 >= max(filter_len, 1)) + 1])
    ends = np.concatenate([starts[1:] - 1, [len(differs) - 1]])
    return differs[starts], differs[ends]


def sync_tolerance(enc: EncoderRun, filter_len: int = 0,
                   clean: tuple[np.ndarray, np.ndarray] | None = None) -> int:
    """The longest of the `sync_stretches`, in clocks (0 without any)."""
    first, last = sync_stretches(enc, filter_len, clean)
    return int((last - first + 1).max()) if len(first) else 0


@dataclass
class Verdict:
    clocks: int
    wrong: int                 # clocks with valid = 1 and a wrong position
    first_wrong: int | None
    availability: float       # share of clocks with valid = 1 after the first valid
    first_valid: int | None
    modes: dict[str, float]   # share of clocks in each mode

    def line(self) -> str:
        modes = " ".join(f"{k}={v:.0%}" for k, v in self.modes.items() if v)
        start = "never" if self.first_valid is None else f"clock {self.first_valid}"
        return (f"wrong valid {self.wrong}, first valid {start}, "
                f"availability {self.availability:.1%}, {modes}")


def judge(enc: EncoderRun, valid: np.ndarray, pos_hyb: np.ndarray, mode: np.ndarray,
          latency: int, tolerance: int | None = None, filter_len: int = 0,
          truth: np.ndarray | None = None, clean: tuple[np.ndarray, np.ndarray] | None = None,
          seen: np.ndarray | None = None) -> Verdict:
    """Compare per-clock outputs (index = clock) with the truth of the run: the ideal
    disc's hybrid position, or `truth` with the disc's own clean A and B (`clean`: a
    printed disc's quarters are its printed edges). `seen`: a second position accepted
    as well, clock for clock, within the same tolerance: the quarter the sensors show
    where their noise moved an edge (`seen_by_sensors`). `tolerance`: clocks of the
    truth accepted around every clock instead of the faults' own stretches (the tests'
    handle on the judge)."""
    valid = np.asarray(valid).astype(bool)
    pos_hyb = np.asarray(pos_hyb, dtype=np.int64)
    truth = enc.hybrid if truth is None else truth
    clocks = len(valid)
    idx = np.arange(clocks) - latency
    ok = np.zeros(clocks, dtype=bool)
    tol = filter_len + (0 if tolerance is None else tolerance)
    for d in range(-tol, tol + 1):
        j = np.clip(idx + d, 0, len(truth) - 1)
        ok |= truth[j] == pos_hyb
        if seen is not None:
            ok |= seen[j] == pos_hyb
    if tolerance is None:
        # Inside a stretch of faulted pins (widened by the filter), any position the
        # truth or the sensors took during that stretch or on the clocks either side of
        # it (what a fault holds the pins at, or pushes them on to).
        for first, last in zip(*sync_stretches(enc, filter_len, clean)):
            lo = max(int(first) - 1 - filter_len, 0)
            hi = min(int(last) + 1 + filter_len, len(truth) - 1)
            shown = np.unique(truth[lo:hi + 1])
            if seen is not None:
                shown = np.union1d(shown, seen[lo:hi + 1])
            k = slice(max(lo + latency, 0), max(min(hi + latency + 1, clocks), 0))
            ok[k] |= np.isin(pos_hyb[k], shown)
    bad = valid & ~ok & (idx >= 0)
    wrong = int(bad.sum())
    first_valid = int(np.argmax(valid)) if valid.any() else None
    after = valid[first_valid:] if first_valid is not None else valid[:0]
    modes = {m.name: float(np.mean(np.asarray(mode) == int(m))) for m in Mode}
    return Verdict(clocks, wrong, int(np.argmax(bad)) if wrong else None,
                   float(after.mean()) if len(after) else 0.0, first_valid, modes)


def quarter_state(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The quarter of a slot (0 to 3) that A and B show: (0, 1), (0, 0), (1, 0), (1, 1)."""
    return np.select([(a == 0) & (b == 1), (a == 0) & (b == 0), (a == 1) & (b == 0)], [0, 1, 2], 3)


def seen_by_sensors(truth: np.ndarray, clean: tuple[np.ndarray, np.ndarray],
                    sensed: tuple[np.ndarray, np.ndarray], length: int) -> np.ndarray:
    """The position the sensors show, clock for clock: `truth` moved by the quarters that
    the sensors' A and B (`sensed`: the disc's signals through the sensors' noise alone,
    no fault) differ from the disc's own (`clean`), -1, 0 or +1. A reader can only follow
    its sensors: where a crossing's noise moves an edge, the quarter it shows until the
    edge comes is the sensors', not a fault of the reader. (Two passes of one edge, each
    with its own noise, can move the quarter's end further than any one stretch of the
    signals' difference, which is what `sync_tolerance` measures.)"""
    delta = (quarter_state(*sensed) - quarter_state(*clean)) % 4
    delta = np.where(delta == 3, -1, np.where(delta == 1, 1, 0))
    return (truth + delta) % (4 * length)


def judge_outputs(enc: EncoderRun, outs: Sequence, latency: int, filter_len: int = 0) -> Verdict:
    """`judge` for a model's outputs, one per clock, each with .valid, .pos_hyb and .mode."""
    return judge(enc, np.array([o.valid for o in outs]), np.array([o.pos_hyb for o in outs]),
                 np.array([o.mode for o in outs]), latency, filter_len=filter_len)
