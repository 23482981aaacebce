# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/core/prenc_sampler.v: mid-slot strobes with direction and head readings.

A strobe is a CW step into q = 2 (A rose) or a CCW step into q = 1 (A fell). The
heads are taken as they were at the input sample where A changed: with `head_delay`
(HEAD_DELAY = 1) the step is the decoder's registered one and the heads are delayed
one clock to line up with it; without (the core's sampler, HEAD_DELAY = 0) the step
is the decoder's next value, on the same clock as the heads' sample. `moved` is
false when the strobe's direction differs from the last one's: the disc crossed the
same mid-slot point back.

With `jump` (the core's sampler, JUMP = 1), an illegal transition whose quarter after
is 1 or 2 also gives a landing reading: the heads at that sample, strobed one clock
later unless a step or another illegal transition comes in between.
"""

from __future__ import annotations

from typing import NamedTuple


class Strobe(NamedTuple):
    strobe: int
    cw: int
    moved: int
    head1: int
    head2: int


class Sampler:
    def __init__(self, jump: bool = False, head_delay: bool = True):
        self.jump = jump
        self.head_delay = head_delay
        self.head1_d = self.head2_d = 0
        self.out = Strobe(0, 0, 0, 0, 0)
        self.have_last = 0
        self.last_cw = 0
        self.pending = 0          # a landing reading waiting for a quiet clock
        self.pending_heads = (0, 0)
        self.pending_cw = 0

    def clock(self, head1_in: int, head2_in: int, step: int, step_cw: int, quarter: int,
              break_in: int = 0, rst: int = 0) -> Strobe:
        mid_slot = step and (quarter == 2 if step_cw else quarter == 1)
        heads = (self.head1_d, self.head2_d) if self.head_delay else (head1_in, head2_in)
        out = self.out._replace(strobe=0)
        if mid_slot:
            moved = int((not self.have_last) or step_cw == self.last_cw)
            out = Strobe(1, step_cw, moved, *heads)
            self.have_last, self.last_cw = 1, step_cw
        elif self.pending and not (step or break_in):
            out = Strobe(1, self.pending_cw, 1, *self.pending_heads)
        pending = int(self.jump and break_in and quarter in (1, 2))
        if pending:
            self.pending_heads, self.pending_cw = heads, step_cw
        if break_in:
            self.have_last = 0
        if rst:
            out = out._replace(strobe=0)
            self.have_last = 0
            pending = 0
        self.pending = pending
        self.head1_d, self.head2_d = head1_in, head2_in
        self.out = out
        return out
