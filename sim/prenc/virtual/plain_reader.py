# SPDX-License-Identifier: Apache-2.0
"""The plain verifying reader: the baseline that `make bench` sets beside the core.

What a straightforward absolute-encoder reader does, with the same front end as the
core (prenc.core.reader.Reader: conditioner, quadrature decoder, sampler, count):

- acquire: both heads' words fill (N strobes each), then both must convert to one
  offset at N + 1 further strobes in a row (2N + 1 strobes in all) before the
  position is valid;
- locked: every strobe, each head's reading must equal the disc's bit at count +
  offset; any disagreement, and any illegal quadrature transition, drops
  everything (words emptied, position invalid) and acquisition starts again.

It never corrects anything, so it is never wrong for long, and rarely available
under faults. It is a model for comparison only; there is no RTL of it.
"""

from __future__ import annotations

from typing import Sequence

from ..codes.debruijn import Code
from .encoder import EncoderRun
from ..core.input_conditioner import InputConditioner
from ..core.position import DECISION_DELAY, Position
from ..core.quadrature import QuadratureDecoder
from ..core.reader import ReaderOutput
from ..core.sampler import Sampler
from ..core.track_word import TrackEvent, TrackWord


class PlainReader:
    def __init__(self, code: Code, filter_len: int = 0, verify: int | None = None):
        self.code = code
        self.n = code.n
        self.mask = code.mask
        self.seq = [int(b) for b in code.sequence]
        self.verify = code.n + 1 if verify is None else verify
        self.conditioner = InputConditioner(4, filter_len)
        self.quadrature = QuadratureDecoder()
        self.sampler = Sampler(head_delay=False)  # the core's front end, at its latency
        self.position = Position(code.n)
        # Each event on its own clock, as the plain reader has always taken them.
        self.tracks = [TrackWord(code, 0, event_delay=False),
                       TrackWord(code, code.n - 1, event_delay=False)]
        self.clean = [0, 0, 0, 1]
        self.locked = 0
        self.offset = 0
        self.cand = None
        self.run_len = 0
        self.valid_d = [0] * DECISION_DELAY

    def _drop(self) -> None:
        self.locked, self.cand, self.run_len = 0, None, 0
        for t in self.tracks:
            t.known, t.ext_lo, t.ext_hi, t.full = 0, 0, 0, 0

    def clock(self, raw: Sequence[int], rst: int = 0) -> ReaderOutput:
        heads = self.clean
        quad = self.quadrature.clock(heads[2], heads[3], rst=rst)
        pos, s = self.position, self.sampler.out
        for h, t in enumerate(self.tracks):
            t.clock(TrackEvent(strobe=s.strobe, up=pos.up, down=pos.down, illegal=pos.illegal,
                               head=s.head1 if h == 0 else s.head2), pos.slot, rst=rst)
        if rst:
            self._drop()
        elif pos.illegal:
            self._drop()
        elif s.strobe and self.locked:
            p = (pos.slot + self.offset) & self.mask
            if s.head1 != self.seq[p] or s.head2 != self.seq[(p + self.n - 1) & self.mask]:
                self._drop()
        elif s.strobe and all(t.full for t in self.tracks):
            offs = [(self.code.position(t.word) - t.base) & self.mask for t in self.tracks]
            if offs[0] != offs[1]:
                self.cand, self.run_len = None, 0
            elif offs[0] == self.cand:
                self.run_len += s.moved
            else:
                self.cand, self.run_len = offs[0], 1
            if self.cand is not None and self.run_len >= self.verify + 1:
                self.locked, self.offset = 1, self.cand
        self.valid_d = [self.locked] + self.valid_d[:-1]
        pos.clock(quad, rst=rst)
        self.sampler.clock(heads[0], heads[1], quad.step, quad.step_cw, quad.quarter,
                           break_in=quad.illegal, rst=rst)
        self.clean = self.conditioner.clock(list(raw), rst=rst)
        p = (pos.slot_d[-1] + self.offset) & self.mask
        valid = self.valid_d[-1]
        return ReaderOutput(valid, p, 4 * p + pos.quarter_d[-1], 1 if valid else 0, 0)

    def run(self, enc: EncoderRun, reset_clocks: int = 4) -> list[ReaderOutput]:
        rows = enc.rows()
        return [self.clock(list(r), rst=int(k < reset_clocks)) for k, r in enumerate(rows)]
