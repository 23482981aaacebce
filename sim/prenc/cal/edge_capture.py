# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/cal/prenc_edge_capture.v: the sync track's edges as the disc crosses
them, with the clocks between them, for a calibration run over the host link.

Each decoder step crosses an edge (clockwise into quarter q: edge q; counter-clockwise:
edge q + 1). pos_hyb follows the step by POS_LAG clocks, so the step, its direction and
an illegal transition are taken POS_LAG clocks late, when pos_hyb is q. One clock after
that, an entry (pos_valid, cw, edge, interval) goes into a FIFO of DEPTH entries,
interval the clocks since the step before (saturating at 65535), with a bit that says
whether it continues the entry pushed before it (the next edge the same way, both with
pos_valid). The head is offered as a run: it and the entries that continue it, up to 3; `take` removes it.
`lost`: an entry found the FIFO full, or an illegal transition came (a clock before),
since the last take."""

from __future__ import annotations

from dataclasses import dataclass

DEPTH = 4
POS_LAG = 4   # clocks from the core's step to its pos_hyb
SATURATED = 0xFFFF


@dataclass(frozen=True)
class Entry:
    valid: int
    cw: int
    edge: int
    interval: int
    continues: int = 0


class EdgeCapture:
    def __init__(self, n: int):
        self.size = 4 << n
        self.reset()

    def reset(self) -> None:
        self.since = SATURATED
        self.stage = (0, 0, 0, 0, 0, 0)    # step, cw, pos_valid, illegal, quarter, interval
        self.fifo: list[Entry] = []
        self.lost = 0
        self.last = (0, 0, 0)              # the last entry pushed: edge, cw, valid
        self.late = [(0, 0, 0)] * POS_LAG  # step, cw, illegal of the clocks before, newest first

    def run(self) -> list[Entry]:
        """The run at the head (what the outputs show)."""
        out = self.fifo[:1]
        for e in self.fifo[1:3]:
            if not e.continues:
                break
            out.append(e)
        return out

    def clock(self, step: int, step_cw: int, illegal: int, pos_hyb: int, pos_valid: int,
              take: int = 0, rst: int = 0) -> None:
        if rst:
            self.reset()
            return
        # Stage 2: the FIFO, from the step registered a clock ago.
        s_step, s_cw, s_valid, s_illegal, s_quarter, s_interval = self.stage
        taken = len(self.run()) if take else 0
        fifo = self.fifo[taken:]
        full = len(fifo) == DEPTH
        if s_step and not full:
            edge = (s_quarter if s_cw else s_quarter + 1) % self.size
            last_edge, last_cw, last_valid = self.last
            following = (last_edge + (1 if last_cw else -1)) % self.size
            continues = int(bool(s_valid and last_valid and s_cw == last_cw and edge == following))
            fifo.append(Entry(s_valid, s_cw, edge, s_interval, continues))
            self.last = (edge, s_cw, s_valid)
        self.lost = int((self.lost and not take) or s_illegal or (s_step and full))
        self.fifo = fifo
        # Stage 1: the step of POS_LAG clocks ago, with this cycle's pos_hyb.
        l_step, l_cw, l_illegal = self.late[-1]
        interval = SATURATED if self.since == SATURATED else self.since + 1
        self.stage = (l_step, l_cw, int(pos_valid), l_illegal, pos_hyb % self.size, interval)
        self.since = 0 if l_step else min(self.since + 1, SATURATED)
        self.late = [(int(step), int(step_cw), int(illegal))] + self.late[:-1]
