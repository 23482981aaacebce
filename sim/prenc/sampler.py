"""Model of rtl/prenc_sampler.v: mid-slot strobes with direction and head readings.

A strobe is a CW step into q = 2 (A rose) or a CCW step into q = 1 (A fell). The
heads are taken as they were at the input sample where A changed (delayed one
clock to line up with the decoder's step). `moved` is false when the strobe's
direction differs from the last one's: the disc crossed the same mid-slot point back.
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
    def __init__(self):
        self.head1_d = self.head2_d = 0
        self.out = Strobe(0, 0, 0, 0, 0)
        self.have_last = 0
        self.last_cw = 0

    def clock(self, head1_in: int, head2_in: int, step: int, step_cw: int, quarter: int,
              break_in: int = 0, rst: int = 0) -> Strobe:
        mid_slot = step and (quarter == 2 if step_cw else quarter == 1)
        out = self.out._replace(strobe=0)
        if mid_slot:
            moved = int((not self.have_last) or step_cw == self.last_cw)
            out = Strobe(1, step_cw, moved, self.head1_d, self.head2_d)
            self.have_last, self.last_cw = 1, step_cw
        if break_in:
            self.have_last = 0
        if rst:
            out = out._replace(strobe=0)
            self.have_last = 0
        self.head1_d, self.head2_d = head1_in, head2_in
        self.out = out
        return out
