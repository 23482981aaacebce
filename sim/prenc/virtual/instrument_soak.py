# SPDX-License-Identifier: Apache-2.0
"""A soak through the whole instrument (`make soak ARGS=--instrument`): random draws of
motion, faults, sensor noise and disc printing, through the reader's model and the
fine position's and velocity's (prenc.fine.fine.Fine), wired as prenc_board wires the
RTL (which equals both clock for clock), and judged clock by clock.

A draw (`draw(seed)`), N = 10 at 30 MHz, FILTER = 2:

- motion: a start at 1,000 to 3,000 rpm, then 6 to 12 segments of 5,000 to 30,000 clocks,
  each a stop or a speed of 20 to 6,000 rpm either way (log-uniform), reached at once
  (a step of speed) or by a ramp over the segment's first half;
- the disc: ideal, or printed (edge errors up to 0.05 slot, B's phase up to 10 degrees,
  duty cycles 0.45 to 0.55, eccentricity up to 0.2 slot);
- the sensors: crossing jitter of 0 to 0.01 slot RMS on all four signals, and half the
  time the rise and fall times of an Omron EE-SX1041;
- faults, none to two of: random misreads of a head (1 pass in 1,000 to 1 in 33), a
  contaminated slot, glitches on a signal (shorter than FILTER, as the datasheet's
  "short glitches": longer ones are real transitions), bounce on every signal (FILTER
  clocks wide, as prenc.virtual.scenarios'), 1 to 3 missed quadrature states (the two
  changes on one clock or a clock apart, either way round: FILTER - 1).

What is judged, on every clock:

1. the position: no wrong valid position against the true angle (prenc.virtual.scenarios'
   judge, as every other test of the core: inside a stretch where faults hold the pins
   off the disc, any position of that stretch), or against the quarter the sensors show
   where their noise alone moved an edge (`seen_by_sensors`: a reader can only follow
   its sensors);
2. the fine position: while it is valid, within the documented bound of the core's
   quarter (docs/fine.md): in pos_hyb's quarter (of the last 8 clocks: the fine
   pipeline's delay), extended by the extrapolation, |velocity| x LOOKAHEAD_HALVES / 2
   quarters either way (the velocity of the last 8 clocks), and by the floors of the
   arithmetic (2^-FINE_BITS, and 2^-16 x LOOKAHEAD_HALVES / 2 quarter);
3. the velocity: 0 or the sign of the last step, and no more than 1.25 quarters over the
   time since the last step (docs/fine.md: the overdue quotient bounds it; half as
   long again is a stop, 0), each after the engine's latency (VELOCITY_LAG clocks):
   it never reads a stop as motion, nor a reversal with the wrong sign.

Beside the verdicts a draw reports the fine position's error against the true angle at
the clock it is read (RMS, max, in slots) while it is valid, and the velocity's error
against the true speed at steady speeds (RMS, in per cent).
"""

from __future__ import annotations

import math
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from typing import Sequence

import numpy as np

from ..codes.debruijn import Code
from ..core.reader import Reader
from ..fine.fine import Fine
from .encoder import Disc, VirtualEncoder
from .faults import Bounce, ContaminatedSlot, MissedQuadratureState, RandomGlitches, RandomMisreads
from .fine_bench import LOOKAHEAD_HALVES, V_FRAC
from .printing import Printing
from .scenarios import core_latency, judge, quarter_state, seen_by_sensors
from .sensors import CrossingJitter, EdgeDelay

N, CLK_HZ, FILTER, FINE_BITS, WINDOW = 10, 30_000_000, 2, 8, 1024
VELOCITY_LAG = 400       # clocks: the engine's window arithmetic holds a step up to ~270
OVERDUE_QUARTERS = 1.25  # docs/fine.md: the overdue bound, a quarter's width plus a quarter
RESET_CLOCKS = 4


def rpm_to_slots_per_clock(rpm: float) -> float:
    return rpm * (1 << N) / 60 / CLK_HZ


@dataclass
class Draw:
    seed: int
    theta: np.ndarray
    speed: np.ndarray          # slots per clock, the truth's derivative
    printing: Printing | None
    sensors: list
    faults: list
    label: str

    def encoder_run(self):
        """The pins: the optics' faults (misreads, a contaminated slot), then the sensors'
        noise on what the optics give, then the faults of the pins as the reader samples
        them: bounce on the sensors' edges, then a missed state (A and B seen changing on
        one clock, or a clock apart either way round), then glitches (spikes on the line,
        which no comparator bounces: bounce around a glitch's edges would make it longer
        than FILTER, a transition). A missed state takes the sensors' edges, not a
        glitch's: held back until the other signal's next edge, a glitch's end would make
        the glitch thousands of clocks long, a quarter the disc never showed. Bounce
        comes before it: FILTER clocks of bounce around the two changes could show them
        as two states of FILTER clocks each in the wrong order, two legal steps the wrong
        way, which no reader can tell from motion (docs/architecture.md)."""
        optical = [f for f in self.faults if isinstance(f, (RandomMisreads, ContaminatedSlot))]
        sampled = [f for f in self.faults if isinstance(f, MissedQuadratureState)]
        bounce = [f for f in self.faults if isinstance(f, Bounce)]
        spikes = [f for f in self.faults if f not in optical and f not in sampled and f not in bounce]
        disc = Disc(N, printing=self.printing)
        return VirtualEncoder(disc, [*optical, *self.sensors, *bounce, *sampled, *spikes]).run(self.theta, CLK_HZ)

    def sensed(self) -> tuple[np.ndarray, np.ndarray]:
        """The disc's A and B through the sensors' noise alone, without any fault."""
        run = VirtualEncoder(Disc(N, printing=self.printing), list(self.sensors)).run(self.theta, CLK_HZ)
        return run.a, run.b

    def truth(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The disc's own A, B and hybrid position at each clock, without faults or noise:
        on a printed disc its printed quarters (the position a reader of this disc must
        show), the quarter whose A and B the disc shows, nearest the angle head 1 reads."""
        disc = Disc(N, printing=self.printing)
        clean = disc.read(self.theta)
        a, b = clean["a"], clean["b"]
        if self.printing is None:
            return a, b, disc.hybrid(self.theta)
        q = quarter_state(a, b)
        seen = 4 * self.printing.seen(self.theta, disc.length, head=1) - 0.5
        h = np.round((seen - q) / 4).astype(np.int64) * 4 + q
        return a, b, h % (4 * disc.length)


def draw(seed: int) -> Draw:
    """The draw of `seed` (1 or more), reproducible."""
    rng = np.random.default_rng(seed)
    speeds, clocks, ramps = [rng.uniform(1000, 3000) * rng.choice([-1, 1])], [20_000], [False]
    for _ in range(int(rng.integers(6, 13))):
        clocks.append(int(rng.integers(5_000, 30_001)))
        if rng.random() < 0.2:
            speeds.append(0.0)
        else:
            speeds.append(float(math.exp(rng.uniform(math.log(20), math.log(6000)))) * rng.choice([-1, 1]))
        ramps.append(bool(rng.random() < 0.5))
    speed = []
    last = 0.0
    for target, length, ramp in zip(speeds, clocks, ramps):
        v = np.full(length, rpm_to_slots_per_clock(target))
        if ramp:
            half = length // 2
            v[:half] = np.linspace(last, v[0], half, endpoint=False)
        speed.append(v)
        last = v[-1]
    speed = np.concatenate(speed)
    theta = float(rng.uniform(0, 1 << N)) + np.concatenate([[0.0], np.cumsum(speed[:-1])])
    printing = None
    if rng.random() < 0.5:
        printing = Printing(edge_error=float(rng.uniform(0, 0.05)), phase_deg=float(rng.uniform(-10, 10)),
                            duty_a=float(rng.uniform(0.45, 0.55)), duty_b=float(rng.uniform(0.45, 0.55)),
                            eccentricity=float(rng.uniform(0, 0.2)), eccentricity_phase=float(rng.uniform(0, 6.28)),
                            seed=seed)
    sigma = float(rng.uniform(0, 0.01))
    sensors: list = [CrossingJitter(sigma, ("a", "b", "head1", "head2"), seed=seed)]
    if rng.random() < 0.5:
        sensors.append(EdgeDelay())
    choices = [
        lambda: RandomMisreads(int(rng.integers(1, 3)), float(rng.uniform(0.001, 0.03)), seed=seed),
        lambda: ContaminatedSlot(int(rng.integers(1, 3)), int(rng.integers(0, 1 << N))),
        lambda: RandomGlitches(str(rng.choice(["a", "b", "head1", "head2"])), int(rng.integers(1, 20)),
                               1, FILTER - 1, seed=seed),
        lambda: Bounce(("a", "b", "head1", "head2"), max(2, FILTER), seed=seed),
        lambda: MissedQuadratureState(count=int(rng.integers(1, 4)), seed=seed, skew=FILTER - 1),
    ]
    picked = rng.choice(len(choices), size=int(rng.integers(0, 3)), replace=False)
    faults = [choices[int(k)]() for k in picked]
    label = (f"{'printed' if printing else 'ideal'} disc, jitter {sigma:.4f}, "
             f"{', '.join(type(f).__name__ for f in faults) or 'no faults'}")
    return Draw(seed, theta, speed, printing, sensors, faults, label)


@dataclass
class InstrumentResult:
    seed: int
    label: str
    clocks: int
    failures: list[str] = field(default_factory=list)
    wrong: int = 0
    fine_rms: float = math.nan
    fine_max: float = math.nan
    velocity_rms: float = math.nan   # per cent, at steady speeds


def judge_position(d: Draw, enc, valid: np.ndarray, hyb: np.ndarray, mode: np.ndarray) -> tuple[int, int | None]:
    """(wrong valid clocks, the first) against the disc's own position (Draw.truth), as
    prenc.virtual.scenarios.judge does every test of the core."""
    a, b, truth = d.truth()
    seen = seen_by_sensors(truth, (a, b), d.sensed(), 1 << N)
    verdict = judge(enc, valid, hyb, mode, core_latency(FILTER), filter_len=FILTER, truth=truth, clean=(a, b),
                    seen=seen)
    return verdict.wrong, verdict.first_wrong


def run_draw(seed: int, fine_lookahead_halves: int = LOOKAHEAD_HALVES) -> InstrumentResult:
    """One draw through the instrument's models, judged. (`fine_lookahead_halves` other
    than the judge's LOOKAHEAD_HALVES builds a fine position that breaks its bound: the
    tests' proof that the judge can fail.)"""
    d = draw(seed)
    enc = d.encoder_run()
    reader = Reader(Code(N), filter_len=FILTER)
    fine = Fine(n=N, fine_bits=FINE_BITS, lookahead_halves=fine_lookahead_halves, window=WINDOW)
    total = len(d.theta)
    turn_q = 4 << N                     # quarters in a turn
    one = 1 << FINE_BITS                # a quarter in the fine position's units
    valid = np.zeros(total, dtype=bool)
    hyb = np.zeros(total, dtype=np.int64)
    mode = np.zeros(total, dtype=np.int64)
    fine_pos = np.zeros(total, dtype=np.int64)
    fine_ok = np.zeros(total, dtype=bool)
    velocity = np.zeros(total)
    failures: list[str] = []
    recent_hyb: list[tuple[int, int]] = []          # (pos_hyb, pos_valid) of the last 8 clocks
    recent_v: list[float] = []                      # the velocity of the last 8 clocks
    last_step = -10**9
    last_dir = 0
    dir_at: list[tuple[int, int]] = []              # (clock, direction) of each step
    scale = 1.0 / (1 << V_FRAC)
    for k, row in enumerate(enc.rows()):
        rst = int(k < RESET_CLOCKS)
        out = reader.clock(list(row), rst=rst)
        q = reader.quadrature
        fine.clock(out.pos_hyb, out.valid, q.step, q.step_cw, q.illegal, rst)
        valid[k], hyb[k], mode[k] = out.valid, out.pos_hyb, out.mode
        v = fine.velocity.velocity * scale if fine.velocity.valid else 0.0
        velocity[k] = v
        fine_pos[k] = fine.fine_pos
        fine_ok[k] = fine.fine_valid
        recent_hyb.append((out.pos_hyb, out.valid))
        del recent_hyb[:-8]
        if q.step and not rst:
            last_step = k
            last_dir = 1 if q.step_cw else -1
            dir_at.append((k, last_dir))
        if q.illegal and not rst:
            last_step = k
        recent_v.append(fine.velocity.velocity * scale)   # what the extrapolation takes, valid or not
        del recent_v[:-8]
        if len(failures) > 5:
            continue
        # 2. The fine position within its quarter, extended by the extrapolation.
        if fine.fine_valid and all(vv for _, vv in recent_hyb):
            # The extrapolation, and the floors on its way: the velocity to 2^-16 quarter
            # (times LOOKAHEAD_HALVES / 2), the output to 2^-FINE_BITS.
            reach = (max(abs(x) for x in recent_v) * LOOKAHEAD_HALVES / 2 * one + 1
                     + LOOKAHEAD_HALVES / 2 * one / (1 << 16) + 1e-9)
            ok = False
            for h, _ in recent_hyb:
                off = (fine.fine_pos - h * one + turn_q * one // 2) % (turn_q * one) - turn_q * one // 2
                if -reach <= off < one + reach:
                    ok = True
                    break
            if not ok:
                failures.append(f"fine position {fine.fine_pos / one:.3f} quarters outside pos_hyb "
                                f"{[h for h, _ in recent_hyb]} +- {reach / one:.3f} at clock {k}")
        # 3. The velocity's sign, and a stop.
        if v != 0.0:
            allowed = {dd for c, dd in dir_at[-64:] if c > k - VELOCITY_LAG}
            before = [dd for c, dd in dir_at[-64:] if c <= k - VELOCITY_LAG]
            if before:
                allowed.add(before[-1])
            if math.copysign(1, v) not in allowed:
                failures.append(f"velocity {v:+.3g} against the last steps' direction {sorted(allowed)} "
                                f"at clock {k}")
            waited = k - last_step - VELOCITY_LAG
            if last_step > 0 and waited > 0 and abs(v) * waited > OVERDUE_QUARTERS:
                failures.append(f"velocity {v:+.3g} quarters a clock {k - last_step} clocks after the "
                                f"last step at clock {k}: more than {OVERDUE_QUARTERS} quarters in that time")
    wrong, first_wrong = judge_position(d, enc, valid, hyb, mode)
    if wrong:
        failures.insert(0, f"wrong valid position at clock {first_wrong} ({wrong} clocks)")
    result = InstrumentResult(seed, d.label, total, failures, wrong)
    # Figures against the truth: the fine position at the clock it is read, in slots.
    fine_slots = fine_pos / one / 4
    err = (fine_slots - d.theta + (1 << N) / 2) % (1 << N) - (1 << N) / 2
    err = err[fine_ok]
    if len(err):
        result.fine_rms, result.fine_max = float(np.sqrt(np.mean(err ** 2))), float(np.max(np.abs(err)))
    # The velocity at steady speeds (the speed unchanged for 20 windows and 10 edge
    # periods: docs/fine.md's settling), in per cent.
    true_q = d.speed * 4
    steady = np.zeros(total, dtype=bool)
    same = np.concatenate([[False], np.isclose(np.diff(true_q), 0.0, atol=1e-15)])
    run = 0
    for k in range(total):
        run = run + 1 if same[k] else 0
        steady[k] = abs(true_q[k]) > 0 and run > max(20 * WINDOW, 10 / abs(true_q[k]))
    steady &= fine_ok
    if steady.any():
        rel = (velocity[steady] - true_q[steady]) / np.abs(true_q[steady]) * 100
        result.velocity_rms = float(np.sqrt(np.mean(rel ** 2)))
    return result


def soak_instrument(seeds: Sequence[int], jobs: int = 1) -> list[InstrumentResult]:
    """Every seed's draw on `jobs` processes, in seed order."""
    seeds = list(seeds)
    if jobs > 1 and len(seeds) > 1:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            return list(pool.map(run_draw, seeds))
    return [run_draw(s) for s in seeds]
