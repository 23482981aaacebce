# SPDX-License-Identifier: Apache-2.0
"""The fault campaign of the reference reader: millions of strobes, seeded.

Events are made straight from a random walk of the disc in quarter steps, without
a clock, so the reference (`prenc.core.reader.Reader`) runs at full Python speed. Each
segment starts the reader from reset at a random angle, picks a random mix of the
datasheet's faults and walks with random reversals (also at mid-slot):

- misreads: each head reading wrong with a probability (a transient misread);
- contaminated cells: slots of a track that read wrong on every pass;
- a dead head for a stretch: stuck at 0, at 1, or noise;
- missed quadrature states: two steps seen as one illegal transition;
- glitches: a step and its undoing, with the heads of the current slot (not
  judged between the two: the pins are a quarter off there, for any reader).

After every event the reader's output is compared with the truth: whenever it
says valid, pos_hyb must equal the true hybrid position. `campaign(...)` returns
the counts; `make bench` prints them.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass, field

import numpy as np

from ..codes.debruijn import Code
from ..core.mode_fsm import Mode
from ..core.position import DECISION_DELAY
from ..core.quadrature import QuadratureOutput
from ..core.reader import Reader


@dataclass
class CampaignResult:
    n: int
    seed: int
    segments: int = 0
    events: int = 0
    strobes: int = 0
    valid_events: int = 0
    wrong_valid: int = 0
    mode_events: dict = field(default_factory=lambda: {m.name: 0 for m in Mode})
    faults: dict = field(default_factory=lambda: {k: 0 for k in (
        "misreads", "contaminated_reads", "dead_head_reads", "missed_states", "glitches")})

    @property
    def availability(self) -> float:
        return self.valid_events / max(1, self.events)


def run_segment(code: Code, rng: np.random.Generator, strobes: int, result: CampaignResult,
                reader_type=Reader) -> None:
    n, length = code.n, code.length
    seq = code.sequence.astype(np.int64)
    h = int(rng.integers(0, 4 * length))  # true hybrid position
    reader = reader_type(code)
    last_cw = 1
    truth: deque = deque([None] * DECISION_DELAY, maxlen=DECISION_DELAY + 1)
    # Fault mix of this segment.
    p_misread = float(rng.choice([0.0, 1e-3, 1e-2, 3e-2]))
    contaminated = [set(rng.integers(0, length, int(rng.integers(0, 3))).tolist()) for _ in range(2)]
    dead = None
    if rng.random() < 0.4:
        dead = (int(rng.integers(1, 3)), str(rng.choice(["stuck0", "stuck1", "noise"])),
                int(rng.integers(0, 4 * strobes)), int(rng.integers(0, 4 * strobes)))
    p_missed = float(rng.choice([0.0, 1e-4, 1e-3, 1e-2]))
    p_glitch = float(rng.choice([0.0, 1e-3, 1e-2]))
    p_idle = float(rng.choice([0.0, 0.2, 0.5]))
    direction = 1 if rng.random() < 0.5 else -1
    p_reverse = float(rng.choice([0.01, 0.05, 0.2]))
    k = 0

    def heads(h_now: int) -> tuple[int, int]:
        p = (h_now >> 2) % length
        bits = [int(seq[p]), int(seq[(p + n - 1) % length])]
        for t in (0, 1):
            if p in contaminated[t]:
                bits[t] ^= 1
                result.faults["contaminated_reads"] += 1
            if p_misread and rng.random() < p_misread:
                bits[t] ^= 1
                result.faults["misreads"] += 1
        if dead is not None and dead[2] <= k < dead[2] + dead[3]:
            t = dead[0] - 1
            bits[t] = 0 if dead[1] == "stuck0" else 1 if dead[1] == "stuck1" else int(rng.integers(0, 2))
            result.faults["dead_head_reads"] += 1
        return bits[0], bits[1]

    def emit(step: int, cw: int, illegal: int, judged: bool = True, rst: int = 0) -> None:
        # The heads as the pins show them on a step or an illegal transition (the core
        # reads them where a missed state landed); between events nothing reads them.
        h1, h2 = heads(h) if (step or illegal) else (0, 0)
        q = QuadratureOutput(h % 4, step, cw, illegal, 0, 0)
        out = reader.clock_decoded(q, h1, h2, rst=rst)
        truth.append(h % (4 * length) if judged else None)
        expected = truth[0]
        result.events += 1
        result.mode_events[Mode(out.mode).name] += 1
        if out.valid and expected is not None:
            result.valid_events += 1
            if out.pos_hyb != expected:
                result.wrong_valid += 1

    for _ in range(4):
        emit(0, 1, 0, judged=False, rst=1)
    while reader.strobes < strobes:
        k += 1
        if p_idle and rng.random() < p_idle:
            emit(0, last_cw, 0)
            continue
        if rng.random() < p_reverse:
            direction = -direction
        if p_missed and rng.random() < p_missed:
            h += 2 * direction
            result.faults["missed_states"] += 1
            emit(0, last_cw, 1)
            continue
        if p_glitch and rng.random() < p_glitch:
            result.faults["glitches"] += 1
            g = 1 if rng.random() < 0.5 else -1
            h += g
            emit(1, int(g > 0), 0, judged=False)  # the pins are a quarter off: not judged
            h -= g
            last_cw = int(g < 0)
            emit(1, last_cw, 0, judged=False)
        h += direction
        last_cw = int(direction > 0)
        emit(1, last_cw, 0)
    for _ in range(DECISION_DELAY + 1):
        emit(0, last_cw, 0)
    result.strobes += reader.strobes
    result.segments += 1


def campaign(n: int = 10, strobes: int = 1_000_000, segment_strobes: int = 20_000, seed: int = 1,
             reader_type=Reader) -> CampaignResult:
    code = Code(n)
    rng = np.random.default_rng(seed)
    result = CampaignResult(n, seed)
    while result.strobes < strobes:
        run_segment(code, rng, min(segment_strobes, strobes - result.strobes), result, reader_type)
    return result
