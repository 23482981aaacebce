# SPDX-License-Identifier: Apache-2.0
"""The warning before a failure, measured (`make bench` section 13): the reader's model
(prenc.core.reader.Reader, which prenc_core equals clock for clock) with prenc_health's
(prenc.health.Health) fed by its corrections, on the virtual encoder, judged against
the truth.

    result = run_case(Case("dirt on track 1", faults=lambda: [GrowingDirt(1, 4000, 50_000)]))
    result.first_warning, result.spots_at(result.first_warning), result.first_reduced

A case turns the disc at a steady speed (30,000 rpm at N = 10 and 30 MHz by default:
58.6 clocks a slot, so a turn takes 60,000 clocks). Growing dirt adds a spot every
`every` clocks; what a case reports is when the warning first rises, when the reader
first drops a track (a reduced mode), when it first loses the position, and the wrong
valid positions (always 0: the warning changes nothing in the position).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Sequence

import numpy as np

from ..codes.debruijn import Code
from ..core.reader import Reader
from ..health.health import Health
from .encoder import Disc, VirtualEncoder
from .faults import GrowingDirt
from .scenarios import core_latency, judge

N, CLK_HZ, RPM, FILTER = 10, 30_000_000, 30_000, 2


@dataclass
class Case:
    name: str
    faults: Callable[[], Sequence[object]]
    turns: float = 6.0
    rpm: float = RPM
    n: int = N

    @property
    def slots_per_clock(self) -> float:
        return self.rpm * (1 << self.n) / 60 / CLK_HZ


@dataclass
class Result:
    case: Case
    clocks: int
    corrections: tuple[int, int, int]          # head 1, head 2, sync (illegal transitions)
    first_warning: int | None
    first_reduced: int | None
    first_lost: int | None                     # the position valid, then not
    wrong: int
    dirt: list[GrowingDirt] = field(default_factory=list)

    def spots_at(self, clock: int | None) -> str:
        """Dirty slots of each growing dirt at `clock` ("-" for none)."""
        if clock is None or not self.dirt:
            return "-"
        return " + ".join(str(min(d.spots(clock), 1 << self.case.n)) for d in self.dirt)

    def turns_at(self, clock: int | None) -> str:
        if clock is None:
            return "-"
        return f"{clock * self.case.slots_per_clock / (1 << self.case.n):.2f}"


def run_case(case: Case, health: Health | None = None) -> Result:
    """The reader and the warning through the case, clock by clock."""
    health = health or Health()
    clocks = int(case.turns * (1 << case.n) / case.slots_per_clock)
    theta = 7.3 + np.arange(clocks) * case.slots_per_clock
    faults = list(case.faults())
    run = VirtualEncoder(Disc(case.n), faults).run(theta)
    reader = Reader(Code(case.n), filter_len=FILTER)
    corrections = [0, 0, 0]
    first_warning = first_reduced = first_lost = None
    valid = np.zeros(clocks, dtype=bool)
    hyb = np.zeros(clocks, dtype=np.int64)
    mode = np.zeros(clocks, dtype=np.int64)
    was_valid = False
    for k, row in enumerate(run.rows()):
        rst = int(k < 4)
        out = reader.clock(list(row), rst=rst)
        q = reader.quadrature
        errors = [int(t.checked and t.mismatch) for t in reader.tracks]
        events = (errors[0], errors[1], q.illegal)
        health.clock(q.step, *events, rst=rst)
        for s in range(3):
            corrections[s] += events[s]
        if health.warning and first_warning is None:
            first_warning = k
        if out.mode in (2, 3) and first_reduced is None:
            first_reduced = k
        if was_valid and not out.valid and first_lost is None:
            first_lost = k
        was_valid = was_valid or bool(out.valid)
        valid[k], hyb[k], mode[k] = out.valid, out.pos_hyb, out.mode
    verdict = judge(run, valid, hyb, mode, core_latency(FILTER), filter_len=FILTER)
    dirt = [f for f in faults if isinstance(f, GrowingDirt)]
    return Result(case, clocks, tuple(corrections), first_warning, first_reduced, first_lost,
                  verdict.wrong, dirt)
