# SPDX-License-Identifier: Apache-2.0
"""A soak of the velocity's bound after a change of motion (`make soak ARGS=--velocity`):
random runs of changes through the model of rtl/fine/ (prenc.fine.fine.Fine, which the
RTL equals clock for clock), judged against the truth and docs/fine.md's bound.

A run (`random_motion(seed)`), N = 10 at 30 MHz: a start at 31 to 10,000 rpm either way,
then 4 to 7 changes, each followed by a held speed: a step; a ramp of 0.3 to 5 ms; a
stop of 1 to 4 ms, then a step; or a change during the recovery from another (a speed
held 0.05 to 1.5 ms, then another). Every speed is 31 to 10,000 rpm (log-uniform),
either way: a reversal where the sign changes. A hold lasts 30 slots or 3 ms, whichever
is longer, times 1 to 1.5.

The disc (`DISCS`): ideal, or the bench's printed disc with the table a perfect
calibration makes (prenc.virtual.fine_bench.PRINTED, CAL = 1).

What is judged, for each hold (`judge`):

1. from `BOUNDS[disc]` windows or edge periods of the new speed after the hold's first
   clock, whichever is longer, to the hold's end: the velocity within 0.05 % of the true
   speed (docs/fine.md: the bound after any change of motion);
2. from the change's first clock to then: the velocity between the last four speeds
   widened by their spread, or 0 (it never reads a speed that the motion did not have).

Beside the verdict a run reports, for each hold, the clocks until the velocity is
within 0.05 % and stays, in windows and in edge periods of the new speed.
"""

from __future__ import annotations

from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from typing import Sequence

import numpy as np

from ..cal.table import Table
from . import fine_bench as fb
from .edge_timing import true_corrections
from .trajectory import Trajectory

DISCS = ("ideal", "calibrated")
BOUNDS = {"ideal": (11, 8), "calibrated": (18, 22)}   # (windows, edge periods): docs/fine.md
WITHIN = 0.0005                                      # 0.05 %


@dataclass
class Hold:
    kind: str            # step, ramp, stop, quick
    begin: int           # the change's first clock
    start: int           # the hold's first clock
    end: int             # the clock after its last
    speed: float         # slots per second
    recent: list[float]  # the last four speeds, this one's included


@dataclass
class VelocityResult:
    seed: int
    disc: str
    clocks: int
    failures: list[str] = field(default_factory=list)
    settled: list[tuple[str, float | None, float | None]] = field(default_factory=list)
    # (kind, windows, edge periods) until within 0.05 % for each hold; None: never


def random_motion(seed: int) -> tuple[np.ndarray, list[Hold]]:
    """The angle of run `seed` (1 or more) at every clock, and its holds; reproducible."""
    r = np.random.default_rng(seed)

    def speed() -> float:
        return fb.rpm(float(r.choice([1, -1]) * 10 ** r.uniform(1.5, 4)))

    traj = Trajectory(fb.CLK_HZ, start=100.375 + r.uniform(0, 50))
    v = speed()
    traj.constant(v, max(3e-3, 30 / abs(v)))
    holds, recent = [], [v]
    for _ in range(int(r.integers(4, 8))):
        kind = str(r.choice(["step", "ramp", "stop", "quick"]))
        begin = len(traj.theta)
        if kind == "stop":
            traj.rest(float(r.uniform(1e-3, 4e-3)))
            recent.append(0.0)
        v = speed()
        if kind == "quick":
            traj.constant(v, float(r.uniform(0.05e-3, 1.5e-3)))
            recent.append(v)
            v = speed()
        if kind == "ramp":
            traj.accelerate(v, float(r.uniform(0.3e-3, 5e-3)))
        start = len(traj.theta)
        traj.constant(v, max(3e-3, 30 / abs(v)) * r.uniform(1.0, 1.5))
        recent.append(v)
        holds.append(Hold(kind, begin, start, len(traj.theta), v, recent[-4:]))
    return traj.theta, holds


def calibrated_table() -> np.ndarray:
    """The bench's printed disc's table as a perfect calibration makes it (its zero taken
    off)."""
    c = true_corrections(fb.PRINTED, fb.N)
    return Table.from_quarters(fb.N, c - c.mean()).c


def velocity_of(theta: np.ndarray, disc: str) -> np.ndarray:
    """The velocity (quarters per clock) of the model of rtl/fine/ on `disc`, clock by
    clock."""
    if disc == "ideal":
        return fb.run_fine(fb.sync_stream(theta, None))["velocity"]
    if disc == "calibrated":
        return fb.run_fine(fb.sync_stream(theta, fb.PRINTED), table=calibrated_table())["velocity"]
    raise ValueError(f"disc must be one of {DISCS}, got {disc!r}")


def judge(theta: np.ndarray, holds: Sequence[Hold], velocity: np.ndarray, disc: str,
          bounds: tuple[float, float] | None = None) -> tuple[list[str], list]:
    """The failures of a run against the bound (`bounds`: windows, edge periods; default
    BOUNDS[disc]), and for each hold the clocks until within 0.05 % in windows and edge
    periods."""
    windows, periods = bounds or BOUNDS[disc]
    truth = 4 * (theta[1:] - theta[:-1])          # quarters per clock
    failures, settled = [], []
    for h in holds:
        period = fb.CLK_HZ / (4 * abs(h.speed))   # clocks per quarter
        bound = int(max(windows * fb.WINDOW, periods * period))
        at = fb.settle_clocks(velocity[:h.end], truth[:h.end - 1], h.start, WITHIN)
        settled.append((h.kind, None if at is None else at / fb.WINDOW, None if at is None else at / period))
        rpm = h.speed * 60 / (1 << fb.N)
        if h.start + bound >= h.end - 1:
            failures.append(f"{h.kind} to {rpm:.0f} rpm: the hold is shorter than the bound")
            continue
        seen = slice(h.start + bound, h.end - 1)
        err = np.abs(velocity[seen] - truth[seen]) / np.abs(truth[seen])
        if err.max() > WITHIN:
            failures.append(f"{h.kind} to {rpm:.0f} rpm at clock {h.start}: {100 * err.max():.3f} % "
                            f"after {windows} windows or {periods} edge periods ({bound} clocks); "
                            f"within 0.05 % after {at} clocks")
        quarters = [4 * x / fb.CLK_HZ for x in h.recent]
        lo, hi = min(quarters), max(quarters)
        margin = (hi - lo) * 1.01
        before = velocity[h.begin:h.start + bound]
        inside = ((before >= lo - margin) & (before <= hi + margin)) | (before == 0)
        if not inside.all():
            k = int(np.argmin(inside))
            failures.append(f"{h.kind} to {rpm:.0f} rpm: {before[k]:.4g} quarters a clock at clock "
                            f"{h.begin + k}, outside the last speeds widened by their spread")
    return failures, settled


def run(seed: int, disc: str = "ideal") -> VelocityResult:
    """Run `seed` on `disc`, judged."""
    theta, holds = random_motion(seed)
    failures, settled = judge(theta, holds, velocity_of(theta, disc), disc)
    return VelocityResult(seed, disc, len(theta), failures, settled)


def _run(args: tuple[int, str]) -> VelocityResult:
    return run(*args)


def soak_velocity(seeds: Sequence[int], discs: Sequence[str] = DISCS, jobs: int = 1) -> list[VelocityResult]:
    """Every seed on every disc, on `jobs` processes, in seed order."""
    work = [(s, d) for s in seeds for d in discs]
    if jobs > 1 and len(work) > 1:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            return list(pool.map(_run, work))
    return [_run(w) for w in work]
