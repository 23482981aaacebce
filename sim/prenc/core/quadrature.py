# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/core/prenc_quadrature.v: quarter index, steps, illegal transitions.

q = {A, A xnor B}: (A,B) = (0,1), (0,0), (1,0), (1,1) give q = 0, 1, 2, 3
(datasheet). A change of q by +1 (mod 4) is a CW step, by -1 a CCW step, by 2 an
illegal transition (A and B changed together), which is counted, never stepped.
"""

from __future__ import annotations

from typing import NamedTuple


def quarter_of(a: int, b: int) -> int:
    return (a << 1) | (1 - (a ^ b))


class QuadratureOutput(NamedTuple):
    quarter: int
    step: int
    step_cw: int
    illegal: int
    illegal_count: int
    count: int  # two's complement in count_width bits, as the RTL shows it


class QuadratureDecoder:
    def __init__(self, count_width: int = 32, error_width: int = 16):
        if not 2 <= count_width <= 64:
            raise ValueError(f"count_width = {count_width} is out of range 2..64")
        if not 1 <= error_width <= 32:
            raise ValueError(f"error_width = {error_width} is out of range 1..32")
        self.count_mask = (1 << count_width) - 1
        self.error_max = (1 << error_width) - 1
        self.quarter = 0
        self.step = 0
        self.step_cw = 1
        self.illegal = 0
        self.illegal_count = 0
        self.count = 0

    def output(self) -> QuadratureOutput:
        return QuadratureOutput(self.quarter, self.step, self.step_cw, self.illegal,
                                self.illegal_count, self.count & self.count_mask)

    def clock(self, a: int, b: int, clear_errors: int = 0, rst: int = 0) -> QuadratureOutput:
        q_in = quarter_of(a, b)
        delta = (q_in - self.quarter) & 3
        self.quarter = q_in
        self.step = self.illegal = 0
        if rst:
            self.step_cw, self.illegal_count, self.count = 1, 0, 0
            return self.output()
        if delta == 1:
            self.step, self.step_cw, self.count = 1, 1, self.count + 1
        elif delta == 3:
            self.step, self.step_cw, self.count = 1, 0, self.count - 1
        elif delta == 2:
            self.illegal = 1
            self.illegal_count = min(self.illegal_count + 1, self.error_max)
        if clear_errors:
            self.illegal_count = 0
        return self.output()
