# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/core/prenc_input_conditioner.v: two-flop synchronizer, then glitch filter.

Clock-accurate: `clock()` takes the inputs before a rising edge and returns the
outputs after it. A new level reaches the output only after the synchronized input
has shown it on `filter_len` consecutive clocks; filter_len = 0 is no filter.
With `paired`, the top two inputs (the quadrature pair A, B) are filtered as one
two-bit state: a new (A, B) reaches the output only after the inputs showed that
state on `filter_len` consecutive clocks, so A and B changing fewer than
`filter_len` clocks apart, in either order, reach the output together.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np


class InputConditioner:
    def __init__(self, width: int = 4, filter_len: int = 2, paired: bool = False):
        if width < 1:
            raise ValueError(f"width must be at least 1, got {width}")
        if paired and width < 2:
            raise ValueError(f"paired needs a width of at least 2, got {width}")
        if not 0 <= filter_len <= 65535:
            raise ValueError(f"filter_len = {filter_len} is out of range 0..65535")
        self.width = width
        self.filter_len = filter_len
        self.sync_q1 = [0] * width
        self.sync_q2 = [0] * width
        self.level = [0] * width
        self.count = [0] * width
        self.paired = paired
        self.pair_prev = (0, 0)    # the synchronized pair one clock earlier
        self.pair_count = 0

    def latency(self) -> int:
        """Clocks from a clean input edge to the output edge."""
        return 2 + self.filter_len

    def clock(self, raw: Sequence[int], rst: int = 0) -> list[int]:
        s2 = self.sync_q2
        if self.filter_len:
            last = self.filter_len - 1
            single = self.width - 2 if self.paired else self.width
            for i in range(single):
                if rst:
                    self.count[i], self.level[i] = 0, s2[i]
                elif s2[i] == self.level[i]:
                    self.count[i] = 0
                elif self.count[i] == last:
                    self.count[i], self.level[i] = 0, s2[i]
                else:
                    self.count[i] += 1
            if self.paired:
                pair, level = tuple(s2[-2:]), tuple(self.level[-2:])
                # Clocks the pair has shown this state before this one (0: a new state).
                seen = self.pair_count if pair == self.pair_prev else 0
                if rst:
                    self.pair_count, self.level[-2:] = 0, list(pair)
                elif pair == level:
                    self.pair_count = 0
                elif seen == last:
                    self.pair_count, self.level[-2:] = 0, list(pair)
                else:
                    self.pair_count = seen + 1
                self.pair_prev = pair
        self.sync_q2 = self.sync_q1
        self.sync_q1 = [int(v) & 1 for v in raw]
        return list(self.sync_q2) if self.filter_len == 0 else list(self.level)

    def run(self, raw: np.ndarray, reset_clocks: int = 0) -> np.ndarray:
        """Outputs for a (clocks, width) array of inputs, rst high for the first clocks."""
        out = np.empty_like(raw)
        for k, row in enumerate(raw.tolist()):
            out[k] = self.clock(row, rst=int(k < reset_clocks))
        return out
