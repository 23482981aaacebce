# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/core/prenc_position.v: the slot count, the reader's events, and the output.

From the quadrature decoder's registered step (clock t) it registers, on t+1, the
slot count and the event the rest of the core sees on that clock: `up` (a CW step
into q = 0), `down` (a CCW step into q = 3) or `illegal`. An illegal transition
(A and B together) moved the disc two quarters; the count takes the pair of steps
in the last legal direction (it moves a slot when that crosses a boundary) and the
judge keeps the other way open. The count and quarter are also delayed four more
clocks, to meet the judge's decision: pos_abs = count + offset at one latency.
"""

from __future__ import annotations

from .quadrature import QuadratureOutput

DECISION_DELAY = 4  # clocks from the event registers to the judge's registers


class Position:
    def __init__(self, n: int):
        self.n = n
        self.mask = (1 << n) - 1
        self.slot = 0
        self.quarter = 0
        self.up = self.down = self.illegal = self.illegal_cw = 0
        self.slot_d = [0] * DECISION_DELAY
        self.quarter_d = [0] * DECISION_DELAY

    def clock(self, q: QuadratureOutput, rst: int = 0) -> None:
        up = int((q.step and q.step_cw and q.quarter == 0) or (q.illegal and q.step_cw and q.quarter <= 1))
        down = int((q.step and not q.step_cw and q.quarter == 3)
                   or (q.illegal and not q.step_cw and q.quarter >= 2))
        self.slot_d = [self.slot] + self.slot_d[:-1]
        self.quarter_d = [self.quarter] + self.quarter_d[:-1]
        self.slot = (self.slot + up - down) & self.mask
        self.quarter = q.quarter
        self.up, self.down, self.illegal, self.illegal_cw = up, down, int(q.illegal), int(q.step_cw)
        if rst:
            self.slot, self.quarter = 0, 0
            self.up = self.down = self.illegal = 0
            self.slot_d = [0] * DECISION_DELAY
            self.quarter_d = [0] * DECISION_DELAY
