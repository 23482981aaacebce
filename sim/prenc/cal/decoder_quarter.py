# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/cal/prenc_decoder_quarter.v: the quarter the quadrature decoder is in,
in the core's position count.

pos_hyb follows the decoder's step by 4 clocks, so the quarter the decoder entered with
this cycle's step is pos_hyb plus this cycle's step and the three before (+1
clockwise, -1 counter-clockwise)."""

from __future__ import annotations


class DecoderQuarter:
    def __init__(self, n: int):
        self.size = 4 << n
        self.reset()

    def reset(self) -> None:
        self.moved = [0, 0, 0]   # the steps of the 3 cycles before

    def quarter(self, pos_hyb: int, step: int, step_cw: int) -> int:
        """This cycle's output (combinational)."""
        return (pos_hyb + _moved(step, step_cw) + sum(self.moved)) % self.size

    def clock(self, step: int, step_cw: int, rst: int = 0) -> None:
        if rst:
            self.reset()
            return
        self.moved = [_moved(step, step_cw)] + self.moved[:-1]


def _moved(step: int, step_cw: int) -> int:
    return (1 if step_cw else -1) if step else 0
