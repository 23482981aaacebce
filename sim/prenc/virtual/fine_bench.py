# SPDX-License-Identifier: Apache-2.0
"""Fine position and velocity against the truth, beside baselines (issues 37, 58).

A scenario is a trajectory (the shaft's angle at every clock) and a disc, ideal or
printed (prenc.virtual.printing). From its sync track this module makes what the
fine blocks see from the core:

- the quadrature decoder's registered step (and direction), from A and B through the
  input conditioner (2 + FILTER clocks, clean signals) and the decoder (1 clock);
- pos_hyb, 4 clocks after the decoder (prenc_position), counted from the sync track,
  and pos_valid = 1: the core is taken as locked, so that what is measured is the
  fine blocks alone (the core's promise has its own tests and goals).

Then it runs the model of rtl/fine/ (prenc.fine.fine.Fine: prenc_velocity and
prenc_fine_position) clock by clock ("ours"), beside the velocity of 0.11.0's default
("0.11", prenc.virtual.previous_velocity) and three velocity estimators that users pick
instead, each of these with the same interpolation and extrapolation for its fine
position:

- period: the time between the last two same-type edges (a full cycle), bounded
  by the time since the last edge (the dVRK firmware's running period);
- mixed:  every SAMPLE_CLOCKS, the edges counted since the last sample over the time
  between the last edge before each sample (Petrella and Tursini's mixed method, as
  SimpleFOC uses it); no edge: bounded by the time since the last edge;
- count:  every SAMPLE_CLOCKS, the edges counted over SAMPLE_CLOCKS (differencing the
  count at a fixed rate).

Errors are against the true angle at the clock the output is read (the instant a
consumer asks), in slots: RMS and max over the measured clocks; velocity errors in
per cent of the true speed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..fine.fine import CAL_DELAY, Fine
from ..fine.fine_position import OUTPUT_DELAY, STEP_DELAY
from ..fine.velocity import V_FRAC
from .encoder import Disc
from .printing import Printing
from .trajectory import Trajectory

CLK_HZ = 30e6
N = 10
FILTER = 2
FINE_BITS = 8
WINDOW = 1024                 # prenc_velocity's at 30 MHz (34 us)
SAMPLE_CLOCKS = 3000          # the baselines' sampling period: 100 us at 30 MHz (10 kHz)
DECODER_DELAY = 2 + FILTER + 1  # pins -> the decoder's registered step
POSITION_DELAY = 4              # decoder -> pos_hyb
# Clocks from the pins to the fine output (and the half clock of an edge's unknown place).
LOOKAHEAD_HALVES = 2 * (DECODER_DELAY + POSITION_DELAY + OUTPUT_DELAY) + 1

PRINTED = Printing(edge_error=0.05, phase_deg=10, duty_a=0.45, duty_b=0.55, eccentricity=0.2, seed=7)
PRINTED_EDGE_TOLERANCE = 31   # EDGE_TOLERANCE (1/1000 slot) for PRINTED without its table


def rpm(value: float) -> float:
    """Slots per second at `value` rpm (N = 10)."""
    return value / 60.0 * (1 << N)


@dataclass
class Sync:
    """What the fine blocks get from the core, clock by clock."""

    step: np.ndarray       # the decoder's registered step
    cw: np.ndarray         # its direction
    pos_hyb: np.ndarray    # the core's pos_hyb (pos_valid = 1)


def sync_stream(theta: np.ndarray, printing: Printing | None, n: int = N, sensors=()) -> Sync:
    """The decoder's steps and pos_hyb for a run of the sync track: clean, or through the
    sensors' effects (prenc.virtual.sensors, applied to A and B in order)."""
    disc = Disc(n, printing=printing)
    if printing is None:
        a, b = disc.sync(theta)
    else:
        a, b = printing.sync(theta, disc.length)
    if sensors:
        from .encoder import EncoderRun

        run = EncoderRun(disc, CLK_HZ, theta, {"head1": a, "head2": a, "a": a.copy(), "b": b.copy()})
        for effect in sensors:
            effect.apply(run)
        a, b = run.a, run.b
    q = (a.astype(np.int64) << 1) | (1 - (a ^ b))
    delta = (q[1:] - q[:-1]) & 3
    if np.any(delta == 2):
        raise ValueError("the trajectory is too fast for the clock: a quadrature state was missed")
    move = np.zeros(len(theta), dtype=np.int64)
    move[1:] = np.where(delta == 1, 1, np.where(delta == 3, -1, 0))
    step = np.zeros(len(theta), dtype=np.int8)
    cw = np.ones(len(theta), dtype=np.int8)
    d = DECODER_DELAY
    step[d:] = (move[:-d] != 0)
    cw[d:] = (move[:-d] >= 0)
    # pos_hyb: the sync track's hybrid position, counted from the first sample: the
    # quarter whose state A and B show, the one nearest the angle seen (on a printed
    # disc the edges are off their places: within a few hundredths of a slot of a slot's
    # end, A and B may show the next slot's first quarter or the last one's).
    seen0 = theta[0] if printing is None else printing.seen(theta[:1], disc.length)[0]
    quarter0 = int(math.floor(4 * seen0))
    h0 = quarter0 + (int(q[0]) - quarter0 + 2) % 4 - 2
    h = h0 + np.cumsum(move)
    pos = np.full(len(theta), h0, dtype=np.int64)
    pos[d + POSITION_DELAY:] = h[:-(d + POSITION_DELAY)]
    return Sync(step, cw, pos % (4 << n))


def run_fine(sync: Sync, fine_bits: int = FINE_BITS, lookahead_halves: int = LOOKAHEAD_HALVES,
             n: int = N, window: int = WINDOW, table=None, edge_tolerance: int = 0) -> dict[str, np.ndarray]:
    """The model of prenc_fine (prenc_velocity and prenc_fine_position; with `table`, a
    calibration table's corrections, CAL = 1; `edge_tolerance`, EDGE_TOLERANCE),
    clock by clock."""
    cal = int(table is not None)
    # With a table the fine position is CAL_DELAY clocks later: the board extrapolates
    # over them too (prenc_board's LOOKAHEAD_HALVES).
    fine = Fine(n=n, fine_bits=fine_bits, lookahead_halves=lookahead_halves + 2 * CAL_DELAY * cal,
                window=window, cal=cal, table=table, edge_tolerance=edge_tolerance)
    vel = fine.velocity
    total = len(sync.step)
    v_out = np.zeros(total)
    v_valid = np.zeros(total, dtype=np.int8)
    fine_pos = np.zeros(total, dtype=np.int64)
    interpolated = np.zeros(total, dtype=np.int8)
    fine_valid = np.zeros(total, dtype=np.int8)
    step, cw, pos = sync.step.tolist(), sync.cw.tolist(), sync.pos_hyb.tolist()
    scale = 1.0 / (1 << V_FRAC)
    for c in range(total):
        fine.clock(pos[c], 1, step[c], cw[c], 0)
        v_out[c] = vel.velocity * scale
        v_valid[c] = vel.valid
        fine_pos[c] = fine.fine_pos
        interpolated[c] = fine.fine.interpolated
        fine_valid[c] = fine.fine_valid
    return {"velocity": v_out, "velocity_valid": v_valid, "fine": fine_pos, "interpolated": interpolated,
            "fine_valid": fine_valid}


# -- baselines --------------------------------------------------------------------

def _edges(sync: Sync) -> tuple[np.ndarray, np.ndarray]:
    clocks = np.flatnonzero(sync.step)
    direction = np.where(sync.cw[clocks] == 1, 1, -1)
    return clocks, direction


def period_velocity(sync: Sync) -> np.ndarray:
    """Quarters per clock: 4 / (time between same-type edges), bounded by 1 / (time
    since the last edge); 1 / (last interval) before four edges or after a reversal."""
    total = len(sync.step)
    clocks, direction = _edges(sync)
    latched = np.zeros(total)
    last_edge = np.full(total, -1, dtype=np.int64)
    for i, c in enumerate(clocks):
        if i >= 4 and np.all(direction[i - 4:i + 1] == direction[i]):
            v = 4.0 / (c - clocks[i - 4])
        elif i >= 1:
            v = 1.0 / (c - clocks[i - 1])
        else:
            v = 0.0
        latched[c:] = direction[i] * v
        last_edge[c:] = c
    since = np.arange(total) - last_edge
    bound = np.where(last_edge >= 0, 1.0 / np.maximum(since, 1), 0.0)
    return np.sign(latched) * np.minimum(np.abs(latched), bound)


def sampled_velocity(sync: Sync, mixed: bool, sample: int = SAMPLE_CLOCKS) -> np.ndarray:
    """Every `sample` clocks: edges counted over the time between the last edges before
    the two samples (mixed) or over the sampling period (count)."""
    total = len(sync.step)
    signed = np.where(sync.step == 1, np.where(sync.cw == 1, 1, -1), 0)
    count = np.cumsum(signed)
    edge_clock = np.maximum.accumulate(np.where(sync.step == 1, np.arange(total), -1))
    out = np.zeros(total)
    v, prev = 0.0, 0
    for s in range(sample, total, sample):
        dn = count[s] - count[prev]
        if not mixed:
            v = dn / sample
        elif dn != 0:
            v = dn / max(edge_clock[s] - edge_clock[prev], 1)
        elif edge_clock[s] >= 0:
            v = math.copysign(min(abs(v), 1.0 / max(s - edge_clock[s], 1)), v)
        out[s:] = v
        prev = s
    return out


def interpolate(sync: Sync, velocity: np.ndarray, fine_bits: int = FINE_BITS,
                lookahead_halves: int = LOOKAHEAD_HALVES, n: int = N) -> np.ndarray:
    """The same fraction and extrapolation as prenc_fine_position, in floating point,
    for a baseline's velocity (quarters per clock)."""
    total = len(sync.step)
    aligned = np.zeros(total, dtype=np.int8)   # the step as pos_hyb shows it
    aligned_cw = np.ones(total, dtype=np.int8)
    d = STEP_DELAY + 1
    aligned[d:] = sync.step[:-d]
    aligned_cw[d:] = sync.cw[:-d]
    last = np.maximum.accumulate(np.where(aligned == 1, np.arange(total), 0))
    moved = np.concatenate([[0.0], np.cumsum(velocity)[:-1]])   # travel integrates the velocity
    travel = moved - moved[last]
    edge = np.where(aligned_cw[last] == 1, 0.0, 1.0)
    frac = np.clip(edge + travel, 0.0, 1.0 - 2.0 ** -48) + np.concatenate([[0.0], velocity[:-1]]) * lookahead_halves / 2
    out = np.floor((sync.pos_hyb + frac) * (1 << fine_bits))   # truncated, as the RTL
    # ... and OUTPUT_DELAY - 1 clocks later (prenc_fine_position's stages A to C).
    d = OUTPUT_DELAY - 1
    return np.concatenate([np.full(d, out[0]), out[:-d]]) if d else out


# -- scoring ----------------------------------------------------------------------

def position_error(quarters: np.ndarray, theta: np.ndarray, n: int = N) -> np.ndarray:
    """(position in quarters) - truth, in slots, wrapped to +- half a turn."""
    length = 1 << n
    err = quarters / 4.0 - theta
    return (err + length / 2) % length - length / 2


def stats(err: np.ndarray) -> tuple[float, float]:
    return float(np.sqrt(np.mean(err * err))), float(np.max(np.abs(err)))


# -- the scenarios of issue 37 ------------------------------------------------------

STEADY_RPM = (1, 10, 100, 600, 1000, 6000, 10000)
RAMP_SETTLE_S = 250e-6     # the ramp's rows without the first 250 us after each change of
                           # acceleration (two windows at 600 rpm): what no causal
                           # estimator can know yet


@dataclass
class Case:
    """A scenario: the angle at every clock and the clocks it is measured over."""

    name: str
    theta: np.ndarray
    measure: np.ndarray            # clock indices c (the output after clock c, against theta[c + 1])
    speed_norm: float | None = None  # velocity errors in % of this speed (quarters per clock);
                                     # None: of the true speed at each clock
    stop_clock: int | None = None    # the stop scenario: where the disc stops


def _traj(start: float = 100.375) -> Trajectory:
    return Trajectory(CLK_HZ, start=start)


def cases() -> list[Case]:
    """Every scenario of `make bench`'s section 9 (N = 10, 30 MHz)."""
    out: list[Case] = []
    for r in STEADY_RPM:
        v = rpm(r)
        warm = max(6.0, 24 * v * WINDOW / CLK_HZ)        # slots: the running mean settled
        measured = max(1.0 if r == 1 else 2.0, v * 30_000 / CLK_HZ)
        theta = _traj().constant(v, (warm + measured) / v).theta
        start = int(warm / v * CLK_HZ)
        out.append(Case(f"{r} rpm", theta, np.arange(start, len(theta) - 1)))
    for r in (600, 6000):
        traj = _traj().constant(rpm(r), 2e-3)
        start = len(traj.theta)
        theta = traj.constant(rpm(r), 20e-3, ripple=0.02, ripple_hz=100.0).theta
        out.append(Case(f"{r} rpm, +-2 % ripple at 100 Hz", theta, np.arange(start, len(theta) - 1)))
    traj = _traj().constant(rpm(600), 2e-3)
    t0 = len(traj.theta)
    traj.accelerate(rpm(6000), 4e-3)
    t1 = len(traj.theta)
    theta = traj.constant(rpm(6000), 1e-3).theta
    settle = int(RAMP_SETTLE_S * CLK_HZ)
    out.append(Case("ramp 600 -> 6000 rpm in 4 ms", theta, np.arange(t0, t1)))
    out.append(Case("  the same, settled", theta, np.concatenate([np.arange(t0 + settle, t1),
                                                                   np.arange(t1 + settle, len(theta) - 1)])))
    traj = _traj().constant(rpm(600), 2e-3)
    t0 = len(traj.theta)
    theta = traj.accelerate(-rpm(600), 2e-3).constant(-rpm(600), 1e-3).theta
    out.append(Case("reversal 600 -> -600 rpm in 2 ms", theta, np.arange(t0, len(theta) - 1),
                    speed_norm=4 * rpm(600) / CLK_HZ))
    traj = _traj().constant(rpm(600), 2e-3)
    t0 = len(traj.theta)
    traj.accelerate(0.0, 1e-3)
    stop = len(traj.theta)
    theta = traj.rest(3e-3).theta
    out.append(Case("stop from 600 rpm in 1 ms", theta, np.arange(t0, len(theta) - 1),
                    speed_norm=4 * rpm(600) / CLK_HZ, stop_clock=stop + DECODER_DELAY))
    return out


@dataclass
class Row:
    """One estimator's errors in one case: position in slots, velocity in per cent."""

    fine: tuple[float, float]
    velocity: tuple[float, float]
    zero_after: float | None = None   # the stop: edge periods from the stop to a 0 reading


def score(case: Case, sync: Sync, fine_quarters: np.ndarray, velocity: np.ndarray) -> Row:
    c = case.measure
    err = position_error(fine_quarters[c], case.theta[c + 1])
    truth = 4 * (case.theta[c + 1] - case.theta[c])
    norm = np.abs(truth) if case.speed_norm is None else case.speed_norm
    v_err = (velocity[c] - truth) / norm * 100
    zero_after = None
    if case.stop_clock is not None:
        edges = np.flatnonzero(sync.step)
        period = edges[-1] - edges[-2]
        zeros = np.flatnonzero(velocity[case.stop_clock:] == 0)
        zero_after = float(zeros[0] / period) if len(zeros) else math.inf
    return Row(stats(err), stats(v_err), zero_after)


BASELINES = ("0.11", "period", "mixed", "count")


def previous_velocity(sync: Sync) -> np.ndarray:
    """0.11.0's default velocity (full-cycle windows of 2048 clocks, the fit), quarters per
    clock, clock by clock."""
    from .previous_velocity import FRAC, Velocity

    vel = Velocity(window=2048)
    out = np.zeros(len(sync.step))
    for c, (step, cw) in enumerate(zip(sync.step.tolist(), sync.cw.tolist())):
        vel.clock(step, cw)
        out[c] = vel.velocity / (1 << FRAC)
    return out


def baseline_velocities(sync: Sync) -> dict[str, np.ndarray]:
    return {"0.11": previous_velocity(sync), "period": period_velocity(sync),
            "mixed": sampled_velocity(sync, True), "count": sampled_velocity(sync, False)}


def evaluate(case: Case, printing: Printing | None, table=None, sensors=()) -> dict[str, Row]:
    """The coarse position, ours (with `table`, a calibration table's corrections: CAL =
    1) and the baselines in one case (through the sensors' effects, if any)."""
    sync = sync_stream(case.theta, printing, sensors=sensors)
    ours = run_fine(sync, table=table)
    scale = 1 << FINE_BITS
    rows = {"coarse": score(case, sync, sync.pos_hyb.astype(np.float64), np.zeros(len(case.theta))),
            "ours": score(case, sync, ours["fine"] / scale, ours["velocity"])}
    for name, velocity in baseline_velocities(sync).items():
        rows[name] = score(case, sync, interpolate(sync, velocity) / scale, velocity)
    return rows


def evaluate_ours(case: Case, printing: Printing | None, edge_tolerance: int = 0) -> Row:
    """Ours alone in one case, with EDGE_TOLERANCE (no table)."""
    sync = sync_stream(case.theta, printing)
    ours = run_fine(sync, edge_tolerance=edge_tolerance)
    return score(case, sync, ours["fine"] / (1 << FINE_BITS), ours["velocity"])


def whole_turns_case(rpm_value: float, turns: int = 1) -> Case:
    """A steady speed over whole turns, after the velocity has settled: the printed disc's
    eccentricity is once a turn, and a short arc would flatter or hurt an estimator."""
    v = rpm(rpm_value)
    warm = max(6.0, 24 * v * WINDOW / CLK_HZ)
    theta = _traj().constant(v, (warm + turns * (1 << N)) / v).theta
    start = int(warm / v * CLK_HZ)
    return Case(f"{rpm_value} rpm, {turns} turn{'s' if turns > 1 else ''}", theta, np.arange(start, len(theta) - 1))


STEPS = ((600, 6000), (6000, 600), (10, 10000), (10000, 10))


def settle_clocks(velocity: np.ndarray, truth: np.ndarray, start: int, within: float = 0.0005) -> int | None:
    """Clocks from `start` until the velocity is within `within` of the truth and stays so
    to the end (None: it never does)."""
    err = np.abs(velocity[start:-1] - truth[start:]) > within * np.abs(truth[start:])
    bad = np.flatnonzero(err)
    if len(bad) == 0:
        return 0
    return None if bad[-1] >= len(err) - 1 else int(bad[-1] + 1)


def step_rows() -> list[tuple[str, list[str]]]:
    """For each step of speed (at once) in STEPS: the clocks until each estimator's
    velocity is within 0.05 % and stays, and in edge periods of the new speed."""
    out = []
    for before, after in STEPS:
        v0, v1 = rpm(before), rpm(after)
        traj = _traj().constant(v0, max(3e-3, 30 / v0))
        start = len(traj.theta)
        theta = traj.constant(v1, max(4e-3, 40 / v1)).theta
        sync = sync_stream(theta, None)
        truth = 4 * (theta[1:] - theta[:-1])
        edges = np.flatnonzero(sync.step)
        period = float(np.median(np.diff(edges[edges > start])))
        velocities = {"ours": run_fine(sync)["velocity"], **baseline_velocities(sync)}
        cells = []
        for name, velocity in velocities.items():
            k = settle_clocks(velocity, truth, start)
            cells.append("never" if k is None else f"{k} ({k / period:.1f})")
        out.append((f"{before} -> {after} rpm", cells))
    return out
