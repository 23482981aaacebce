# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/fine/prenc_fine.v: prenc_velocity and prenc_fine_position side by side,
and with CAL = 1 the calibration table (prenc.cal.lookup, rtl/cal/prenc_cal_lookup.v)
between them and the disc's true edges.

With CAL = 1 (docs/calibration.md, docs/fine.md's timing diagram):

- the table is asked for pos_hyb's quarter; its pair (c[q], c[q + 1]) comes
  READ_DELAY = 3 clocks later and is registered, gated: 0 (the nominal edges) unless
  the pair is the quarter of pos_hyb 3 clocks before and pos_valid held then;
- so prenc_fine_position takes pos_hyb, pos_valid and the decoder's step CAL_DELAY = 4
  clocks late, and prenc_velocity the decoder's step, direction and illegal transition
  VEL_DELAY = 8 clocks late (pos_hyb follows the decoder by POS_LAG = 4), each with
  the corrections of its quarter.
"""

from __future__ import annotations

from ..cal.lookup import READ_DELAY, CalLookup
from .fine_position import FinePosition
from .velocity import Velocity

POS_LAG = 4                        # the decoder's step -> pos_hyb (prenc_core)
CAL_DELAY = READ_DELAY + 1         # pos_hyb -> its corrections, registered
VEL_DELAY = POS_LAG + CAL_DELAY    # the decoder's step -> its quarter's corrections


class Fine:
    def __init__(self, n: int = 10, fine_bits: int = 8, lookahead_halves: int = 0,
                 window: int = 1024, cal: int = 0, table=None, edge_tolerance: int = 0):
        if cal not in (0, 1):
            raise ValueError(f"cal = {cal} must be 0 or 1")
        self.cal = cal
        self.velocity = Velocity(window=window, cal=cal, edge_tolerance=edge_tolerance)
        self.fine = FinePosition(n=n, fine_bits=fine_bits, lookahead_halves=lookahead_halves,
                                 phase_filter=int(edge_tolerance > 0))
        self.lookup = CalLookup(n, table) if cal else None
        self._reset_pipeline()

    def _reset_pipeline(self) -> None:
        self.pos_d = [(0, 0)] * CAL_DELAY              # pos_hyb, pos_valid, late
        self.step_d = [(0, 1, 0)] * VEL_DELAY          # step, step_cw, illegal, late
        self.c_reg = (0, 0)                            # the pair, gated, registered

    def clock(self, pos_hyb: int, pos_valid: int, step: int, step_cw: int, illegal: int,
              rst: int = 0, write: int = 0, address: int = 0, data: int = 0) -> None:
        vel, fine = self.velocity, self.fine
        if not self.cal:
            fine.clock(pos_hyb, pos_valid, step, step_cw, vel.velocity, vel.valid, rst)
            vel.clock(step, step_cw, illegal, rst)
            return
        look = self.lookup
        c_lo, c_hi = self.c_reg
        f_pos, f_valid = self.pos_d[CAL_DELAY - 1]
        f_step, f_cw, _ = self.step_d[CAL_DELAY - 1]
        fine.clock(f_pos, f_valid, f_step, f_cw, vel.velocity, vel.valid, rst, c_lo=c_lo, c_hi=c_hi)
        v_step, v_cw, v_illegal = self.step_d[VEL_DELAY - 1]
        vel.clock(v_step, v_cw, v_illegal, rst, c_lo=c_lo, c_hi=c_hi)
        pos_3, valid_3 = self.pos_d[CAL_DELAY - 2]
        used = look.ok and look.quarter == pos_3 and valid_3
        self.c_reg = (look.lo, look.hi) if used and not rst else (0, 0)
        look.clock(pos_hyb, write, address, data, rst)
        if rst:
            self.pos_d = [(0, 0)] * CAL_DELAY
            self.step_d = [(0, 1, 0)] * VEL_DELAY
            return
        self.pos_d = [(pos_hyb, pos_valid)] + self.pos_d[:-1]
        self.step_d = [(step, step_cw, illegal)] + self.step_d[:-1]

    # What the RTL's outputs show after the clock edge.
    @property
    def fine_pos(self) -> int:
        return self.fine.fine_pos

    @property
    def fine_valid(self) -> int:
        return self.fine.valid

    @property
    def interpolated(self) -> int:
        return self.fine.interpolated
