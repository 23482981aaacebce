# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/fine/prenc_fine.v: prenc_velocity (or, with TRACKER = 1, prenc_tracker:
`gains`, its table's words; TRACKER = 2: `filtered` = 1 as well, the tracker's filtered
position for prenc_fine_position) and prenc_fine_position side by side, and with CAL = 1 the
calibration table (prenc.cal.lookup, rtl/cal/prenc_cal_lookup.v) between them and the
disc's true edges.

With CAL = 1 (docs/calibration.md):

- the decoder's quarter q(t) = pos_hyb(t) plus the steps pos_hyb does not show yet
  (this cycle's and the three before: pos_hyb follows the decoder by 4 clocks) goes to
  the table, which gives c[q] and c[q + 1] one clock later, registered once more (the
  block RAM's output is slow);
- so prenc_velocity takes the decoder's step, direction and illegal transition two
  clocks late, with those corrections (c_lo, c_hi);
- prenc_fine_position takes them 2 clocks later again, when pos_hyb shows that quarter;
- the corrections count only while the table has both words and pos_valid held when
  the quarter was asked (else 0: the nominal edges).
"""

from __future__ import annotations

from ..cal.decoder_quarter import DecoderQuarter
from ..cal.lookup import CalLookup
from ..cal.table import FRAC as CAL_BITS   # the table's fractional bits
from .fine_position import FinePosition
from .period import Period
from .tracker import Tracker
from .velocity import FRAC, Velocity

LATE = 2           # the decoder's step -> prenc_velocity's, with the table (its answer,
                   # registered)
OFFSET_DELAY = 2   # the tracker's offset -> prenc_fine_position's (the step it takes is
                   # STEP_DELAY = 3 clocks old; the tracker's registers, 1)
POS_DELAY = 2      # the velocity's corrections -> prenc_fine_position's (pos_hyb follows
                   # the decoder by 4 clocks)


class Fine:
    def __init__(self, n: int = 10, fine_bits: int = 8, lookahead_halves: int = 0,
                 window: int = 2048, timer_bits: int = 26, cal: int = 0, table=None,
                 quarter_windows: int = 0, accel_fit: int = 1, gains: list[int] | None = None,
                 filtered: int = 0, period: int = 0):
        if cal not in (0, 1):
            raise ValueError(f"cal = {cal} must be 0 or 1")
        if filtered not in (0, 1) or (filtered and gains is None):
            raise ValueError(f"filtered = {filtered} must be 0, or 1 with a gain table")
        if period not in (0, 1) or (period and (gains is not None or cal)):
            raise ValueError(f"period = {period} must be 0, or 1 without a gain table and CAL")
        self.filtered = filtered
        self.cal = cal
        if period:           # PERIOD = 1: prenc_period
            self.velocity = Period(timer_bits=timer_bits)
        elif gains is not None:   # TRACKER = 1 or 2: prenc_tracker with this gain table
            self.velocity = Tracker(gains, timer_bits=timer_bits, cal_bits=CAL_BITS if cal else 0)
        else:
            self.velocity = Velocity(window=window, timer_bits=timer_bits,
                                     cal_bits=CAL_BITS if cal else 0, quarter_windows=quarter_windows,
                                     accel_fit=accel_fit)
        self.fine = FinePosition(n=n, fine_bits=fine_bits, lookahead_halves=lookahead_halves)
        self.lookup = CalLookup(n, table) if cal else None
        # the tracker's offset on its way to prenc_fine_position: OFFSET_DELAY registers
        # (OFFSET_DELAY - LATE with CAL = 1)
        self.offset_d = [(0, 0)] * (OFFSET_DELAY - LATE if cal else OFFSET_DELAY)
        self.decoder_quarter = DecoderQuarter(n)
        self._reset_pipeline()

    def _offset(self, rst: int) -> None:
        """The tracker's offset, delayed to meet the step prenc_fine_position takes
        (OFFSET_DELAY: 2 clocks; 0 with CAL = 1, where the tracker is LATE already)."""
        if self.offset_d:
            now = (0, 0) if rst else self._tracker_offset()
            self.offset_d = [now] + self.offset_d[:-1]

    def _tracker_offset(self) -> tuple[int, int]:
        vel = self.velocity
        return (vel.offset, vel.offset_valid) if self.filtered else (0, 0)

    @property
    def offset_taken(self) -> tuple[int, int]:
        """The tracker's offset and its flag prenc_fine_position takes this cycle
        (TRACKER = 2; else (0, 0))."""
        return self.offset_d[-1] if self.offset_d else self._tracker_offset()

    def _reset_pipeline(self) -> None:
        self.late = [(0, 1, 0, 0)] * LATE             # step, step_cw, illegal, pos_valid, late
        self.c_reg = (0, 0)                           # the table's answer, gated, registered
        self.to_fine = [(0, 0)] * POS_DELAY           # corrections on their way

    def clock(self, pos_hyb: int, pos_valid: int, step: int, step_cw: int, illegal: int,
              rst: int = 0, write: int = 0, address: int = 0, data: int = 0) -> None:
        vel, fine = self.velocity, self.fine
        offset, offset_valid = self.offset_taken
        if not self.cal:
            fine.clock(pos_hyb, pos_valid, step, step_cw, vel.velocity, vel.valid, rst,
                       offset=offset, offset_valid=offset_valid)
            self._offset(rst)
            vel.clock(step, step_cw, illegal, rst)
            return
        look = self.lookup
        answer = (look.lo, look.hi) if look.ok and self.late[0][3] else (0, 0)
        c_lo, c_hi = self.c_reg
        shift = FRAC - CAL_BITS
        f_lo, f_hi = self.to_fine[-1]
        fine.clock(pos_hyb, pos_valid, step, step_cw, vel.velocity, vel.valid, rst,
                   c_lo=f_lo << shift, c_hi=f_hi << shift, offset=offset, offset_valid=offset_valid)
        self._offset(rst)
        late_step, late_cw, late_illegal, _ = self.late[-1]
        vel.clock(late_step, late_cw, late_illegal, rst, c_lo=c_lo, c_hi=c_hi)
        look.clock(self.decoder_quarter.quarter(pos_hyb, step, step_cw), write, address, data, rst)
        self.decoder_quarter.clock(step, step_cw, rst)
        if rst:
            self._reset_pipeline()
            return
        self.to_fine = [(c_lo, c_hi)] + self.to_fine[:-1]
        self.c_reg = answer
        self.late = [(step, step_cw, illegal, pos_valid)] + self.late[:-1]

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
