# SPDX-License-Identifier: Apache-2.0
"""End-to-end scenarios for the reader, and the check against the true angle.

A scenario is a trajectory and a list of faults for a disc of N bits and a glitch
filter length: the RTL tests, the reference tests, `make demo` and the fault
campaign draw from the same list. `judge` compares a reader's outputs, clock by
clock, with the truth of the run:

    whenever valid is 1, pos_hyb (and pos_abs = pos_hyb >> 2) equals the true hybrid
    position `latency` clocks earlier

except where a fault on A or B moved the pins themselves away from the truth: there
the truth of the clocks within that many clocks is accepted too (`sync_tolerance`:
the longest stretch of such clocks, those fewer than F apart counted as one).
With a glitch filter of F clocks, the truth within F clocks is accepted as well: the
filter removes true pulses shorter than F (a reversal right at an edge) as it
removes glitches.
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
    add("glitches", "glitches on A and B shorter than the filter (none without a filter)",
        traj().constant(v, lock_clocks).random_walk(10000, **walk),
        [RandomGlitches("a", 20, 1, filter_len - 1, seed),
         RandomGlitches("b", 20, 1, filter_len - 1, seed + 1)] if filter_len >= 2 else [])
    add("missed_state", "quadrature states missed: A and B seen changing together",
        traj().constant(v, lock_clocks).random_walk(12000, **walk),
        [MissedQuadratureState(count=3, seed=seed)])
    add("bounce", "chatter on every edge of all four signals",
        traj().constant(v, lock_clocks).random_walk(10000, **walk),
        [Bounce(("a", "b", "head1", "head2"), width=max(2, filter_len), seed=seed)])
    # Not combined: bounce on A/B with a missed state. Chatter can split "A and B
    # changing together" into two legal steps in the wrong order, a miscount that no
    # quadrature decoder can see (the code check finds it at a later strobe).
    add("combined", "misreads, a contaminated slot, a dead head, missed states, head bounce",
        traj().constant(v, lock_clocks).random_walk(16000, **walk),
        [RandomMisreads(1, 0.01, seed), ContaminatedSlot(2, (p + 5) % length),
         DeadHead(1, "noise", start_clock=lock_clocks + 8000, seed=seed),
         MissedQuadratureState(count=2, seed=seed),
         Bounce(("head1", "head2"), width=max(2, filter_len), seed=seed)])
    return {s.name: s for s in out}


def must_lock(name: str) -> bool:
    """Whether every draw of the scenario must reach a valid position: start-up,
    reversals and acceleration, without faults."""
    return name.startswith(("start", "reversals", "accelerate"))


def sync_tolerance(enc: EncoderRun, filter_len: int = 0,
                   clean: tuple[np.ndarray, np.ndarray] | None = None) -> int:
    """Clocks a fault on A or B can hold the reader's view of them off the truth: the
    longest stretch from the first to the last clock where the faulted A or B differs
    from the clean one (the ideal disc's, or `clean`: the disc's own A and B), where
    clocks fewer than `filter_len` apart count as one stretch.

    A glitch filter of F clocks cannot settle between two such clocks (it needs F equal
    samples in a row), so two 1-clock glitches next to a true edge with one clean
    clock between them delay that edge by the whole stretch, not by one clock."""
    a, b = Disc.sync(enc.theta) if clean is None else clean
    differs = np.flatnonzero((enc.a != a) | (enc.b != b))
    if not len(differs):
        return 0
    # A new stretch starts where the clean clocks since the last differing one
    # number filter_len or more.
    starts = np.concatenate([[0], np.flatnonzero(np.diff(differs) - 1 >= max(filter_len, 1)) + 1])
    ends = np.concatenate([starts[1:] - 1, [len(differs) - 1]])
    return int((differs[ends] - differs[starts] + 1).max())


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
    where their noise moved an edge (`seen_by_sensors`)."""
    tol = (sync_tolerance(enc, filter_len, clean) if tolerance is None else tolerance) + filter_len
    valid = np.asarray(valid).astype(bool)
    pos_hyb = np.asarray(pos_hyb, dtype=np.int64)
    truth = enc.hybrid if truth is None else truth
    clocks = len(valid)
    idx = np.arange(clocks) - latency
    ok = np.zeros(clocks, dtype=bool)
    for d in range(-tol, tol + 1):
        j = np.clip(idx + d, 0, len(truth) - 1)
        ok |= truth[j] == pos_hyb
        if seen is not None:
            ok |= seen[j] == pos_hyb
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
