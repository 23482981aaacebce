#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A study for issue 37's "at least as good as every baseline in every row": a Kalman
filter on the sync track's edges, beside prenc_velocity and the three baselines.

    python scripts/velocity_study.py                 # both discs, every row (about 15 min)
    python scripts/velocity_study.py --disc ideal --rows "600 rpm,ramp"

Its two candidates are floating point, here to answer a design question before RTL is
written (docs/design-log.md, "A Kalman filter on the edges"); the filter's equations are
prenc.fine.tracker_gains', which computes prenc_tracker's table with them. It runs the scenarios of `make bench`'s section 9 (prenc.virtual.fine_bench:
N = 10, 30 MHz), scores every estimator the same way (the velocity's error against the
true speed at the clock it is read, RMS in per cent) and prints one Markdown table per
disc: prenc_velocity's model (ours, quarter), the two candidates below, the integer
model of prenc_tracker (tracker: the scheduled filter as the RTL has it, prenc.fine.
tracker, its table from prenc.fine.tracker_gains, and with its answer to a jump of the
innovation, which the scheduled form here does not have; `make bench` section 9 measures
it as well), and the baselines.

kalman: the state is the position (quarters), the velocity (quarters per clock) and the
acceleration. At each of the decoder's steps the position is measured as the edge
crossed (edge x at x quarters; the decoder's fixed delay does not change a velocity).
Between edges the state is predicted over the T clocks since the last one, with a white
jerk of density Q600 x (|v| / v600)^QEXP above 600 rpm and ^QEXP_LOW below (so that a
few edges at a crawl do not read as accelerations). The measurement noise is a clock's
quantization (v^2 / 12) plus the disc's edge error, SIGMA quarters RMS (0.01 for the
ideal disc, 0.15 for the bench's printed one: its edges are +-0.2 quarter, uniform).
A maneuver: when the innovations' running mean (in standard deviations) passes
MANEUVER[0], the jerk density is MANEUVER[1] times larger for the next edge.

scheduled: the same filter without a covariance at run time, the form hardware would
take: its gains come from a table by the speed (STEPS entries an octave) and the age,
the edges since the filter started (up to AGES); each edge of a maneuver halves the
age (not below AGE_FLOOR). The table is the covariance recursion run at a constant
speed.

Both give their output by prenc_velocity's rules: 0 or the sign of the last step, and,
an edge overdue by two predicted quarter periods, a linear decay to 0 at three; an
edge after that starts the filter again.
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "sim"))
from prenc.fine import tracker_gains  # noqa: E402
from prenc.fine.tracker import Tracker  # noqa: E402
from prenc.virtual import fine_bench as fb  # noqa: E402

SIGMA = tracker_gains.SIGMA             # the disc's edge error, quarters RMS
PRIOR = (0.1, 1e-2, 1e-14)              # the first edge's variances: position, velocity, accel
MANEUVER = (1.0, 1e4, 0.25)             # |innovations' mean| above [0] (in sigmas, an EMA of
                                        # weight [2]): the jerk density x [1] for the next edge
OVERDUE = (2.0, 3.0)                    # predicted quarter periods: the decay's start, 0


def stopped(velocity: float, clocks: int) -> bool:
    """An edge came after the output had decayed to 0: the filter starts again."""
    return clocks >= OVERDUE[1] / max(abs(velocity), 1e-12)


def jerk_density(v: float) -> float:
    return tracker_gains.jerk_density(v, fb.N, fb.CLK_HZ)


def shown(velocity: float, accel: float, cw: bool, clocks: int) -> np.ndarray:
    """The output for the `clocks` clocks from a step on: the state's velocity, 0 unless
    it has the sign of the step, and decaying once the next edge is overdue."""
    k = np.arange(clocks)
    v = velocity + accel * k
    v = np.where((v > 0) == cw, v, 0.0)
    quarter = 1.0 / max(abs(velocity), 1e-12)
    start, zero = OVERDUE
    return v * np.clip((zero * quarter - (k + 1)) / ((zero - start) * quarter), 0.0, 1.0)


def crossed(sync: fb.Sync) -> list[tuple[int, bool, int]]:
    """(clock, clockwise, the edge crossed) for every step: edge x is at x quarters."""
    out, count = [], 0
    for c in np.flatnonzero(sync.step):
        cw = bool(sync.cw[c])
        out.append((int(c), cw, count + 1 if cw else count))
        count += 1 if cw else -1
    return out


def kalman_velocity(sync: fb.Sync, sigma: float) -> np.ndarray:
    """The filter's velocity at every clock, quarters per clock."""
    total = len(sync.step)
    steps = crossed(sync)
    out = np.zeros(total)
    state, cov, last, bias = np.zeros(3), np.zeros((3, 3)), None, 0.0
    for i, (c, cw, x) in enumerate(steps):
        if last is None or stopped(state[1], c - last):
            state, cov = np.array([float(x), 0.0, 0.0]), np.diag(PRIOR)
        else:
            t = float(c - last)
            noise = tracker_gains.process_noise(jerk_density(state[1]), t)
            if abs(bias) > MANEUVER[0]:
                noise = noise * MANEUVER[1]
            f = tracker_gains.transition(t)
            state = f @ state
            cov, gain, spread = tracker_gains.update(cov, f, noise, state[1], sigma)
            innovation = x - state[0]
            bias += (innovation / math.sqrt(spread) - bias) * MANEUVER[2]
            state = state + gain * innovation
        end = steps[i + 1][0] if i + 1 < len(steps) else total
        out[c:end] = shown(state[1], state[2], cw, end - c)
        last = c
    return out


STEPS = 4           # the gain table's entries per octave of speed
AGES = 1024         # ... and its ages: the gains after 0..AGES-1 edges from the start
AGE_FLOOR = 4       # each edge of a maneuver halves the age, down to this
_TABLE: dict[tuple[int, float], list[tuple[np.ndarray, float]]] = {}


def table_gains(index: int, age: int, sigma: float) -> tuple[np.ndarray, float]:
    """The gains and the innovation's variance after `age` edges from the start at a
    constant speed of 2^(index / STEPS) quarters per clock: the table hardware would hold.
    Its start knows the speed to within itself (velocity variance v^2, acceleration
    variance v^4 / 100), since the first interval gave it."""
    key = (index, sigma)
    if key not in _TABLE:
        _TABLE[key] = tracker_gains.recursion(2.0 ** (index / STEPS), sigma, fb.N, fb.CLK_HZ, AGES)
    return _TABLE[key][min(age, AGES - 1)]


def scheduled_velocity(sync: fb.Sync, sigma: float) -> np.ndarray:
    """The same filter with its gains from table_gains (no covariance at run time); its
    first interval gives the speed the table is first read at."""
    total = len(sync.step)
    steps = crossed(sync)
    out = np.zeros(total)
    state, last, bias, age, previous = np.zeros(3), None, 0.0, 0, 0
    for i, (c, cw, x) in enumerate(steps):
        if last is None or stopped(state[1], c - last):
            state, age = np.array([float(x), 0.0, 0.0]), -1
        elif age < 0:
            state, age = np.array([float(x), (x - previous) / (c - last), 0.0]), 0
        else:
            state = tracker_gains.transition(float(c - last)) @ state
            if abs(bias) > MANEUVER[0]:
                age = max(min(age, AGES - 1) // 2, AGE_FLOOR)
            index = int(round(STEPS * math.log2(max(abs(state[1]), 1e-9))))
            gain, spread = table_gains(index, age, sigma)
            innovation = x - state[0]
            bias += (innovation / math.sqrt(spread) - bias) * MANEUVER[2]
            state = state + gain * innovation
            age += 1
        previous = x
        end = steps[i + 1][0] if i + 1 < len(steps) else total
        out[c:end] = shown(state[1], state[2], cw, end - c)
        last = c
    return out


def tracker_velocity(sync: fb.Sync, sigma: float) -> np.ndarray:
    """The integer model of prenc_tracker (prenc.fine.tracker), its table for this disc."""
    model = Tracker(tracker_gains.table(fb.N, fb.CLK_HZ, sigma))
    total = len(sync.step)
    out = np.zeros(total)
    step, cw = sync.step.tolist(), sync.cw.tolist()
    scale = 2.0 ** -48
    for c in range(total):
        model.clock(step[c], cw[c])
        out[c] = model.velocity * scale
    return out


COLUMNS = ("ours", "quarter", "kalman", "scheduled", "tracker", "period", "mixed", "count")
BASELINES = ("period", "mixed", "count")
CANDIDATES = ("kalman", "scheduled", "tracker")


def study(disc: str, rows: list[str] | None = None) -> list[str]:
    """The velocity's RMS error (%) of each estimator in each scenario, as Markdown; the
    last columns say whether a candidate is at least as good as every baseline (within 1 %
    of the best one; the stop: within 0.01 edge period)."""
    printing = None if disc == "ideal" else fb.PRINTED
    lines = [f"| {disc} disc | " + " | ".join(COLUMNS) + " | best baseline | " +
             " | ".join(f"{c} >= baselines" for c in CANDIDATES) + " |",
             "|---|" + "---|" * (len(COLUMNS) + 1 + len(CANDIDATES))]
    print("\n".join(lines), flush=True)
    for case in fb.cases():
        if rows and not any(case.name.startswith(r) for r in rows):
            continue
        sync = fb.sync_stream(case.theta, printing)
        velocity = {"ours": fb.run_fine(sync)["velocity"],
                    "quarter": fb.run_fine(sync, quarter_windows=1)["velocity"],
                    "kalman": kalman_velocity(sync, SIGMA[disc]),
                    "scheduled": scheduled_velocity(sync, SIGMA[disc]),
                    "tracker": tracker_velocity(sync, SIGMA[disc]),
                    "period": fb.period_velocity(sync),
                    "mixed": fb.sampled_velocity(sync, True),
                    "count": fb.sampled_velocity(sync, False)}
        scale = 1 << fb.FINE_BITS
        score = {name: fb.score(case, sync, fb.interpolate(sync, v) / scale, v) for name, v in velocity.items()}
        if case.stop_clock is not None:
            value = {n: r.zero_after for n, r in score.items()}
            best = min(value[n] for n in BASELINES)
            wins = {c: value[c] <= best + 0.01 for c in CANDIDATES}
            cells = {n: f"{v:.2f}" for n, v in value.items()}
            name = case.name + " (0 after, edge periods)"
        else:
            value = {n: r.velocity[0] for n, r in score.items()}
            best = min(value[n] for n in BASELINES)
            wins = {c: value[c] <= best * 1.01 for c in CANDIDATES}
            cells = {n: f"{v:.4f}" for n, v in value.items()}
            name = case.name.strip()
        lines.append(f"| {name} | " + " | ".join(cells[c] for c in COLUMNS) + f" | {best:.4g} | " +
                     " | ".join("yes" if wins[c] else "NO" for c in CANDIDATES) + " |")
        print(lines[-1], flush=True)
    return lines


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--disc", choices=("ideal", "printed", "both"), default="both")
    parser.add_argument("--rows", help="comma-separated beginnings of scenario names (default: all)")
    args = parser.parse_args()
    rows = args.rows.split(",") if args.rows else None
    for disc in (("ideal", "printed") if args.disc == "both" else (args.disc,)):
        print(f"\nVelocity error, % RMS (N = {fb.N}, {fb.CLK_HZ / 1e6:g} MHz; Q600 = {tracker_gains.Q600:g}, "
              f"sigma = {SIGMA[disc]} quarter)\n", flush=True)
        study(disc, rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
