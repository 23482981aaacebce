# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/fine/prenc_velocity.v: the velocity from windows of the sync track's
edges (docs/fine.md). The estimator is the program of prenc.fine.program, run by the
engine of prenc.fine.engine; around them, the registers the RTL keeps every clock:

- NOW, a clock count (32 bits, wrapping); COUNT, the steps (20 bits, wrapping).
- A step is held for the program (pend) unless one is held already: its clock STIME
  and its edge's place SPOSC (COUNT 2^12 plus the crossed edge's correction, signed by
  the direction: along the motion, in 2^-12 quarter). Every step, held or not: its
  clock LTIME and LWIDTH, the width of the quarter it entered less one (c_hi - c_lo,
  2^-12 quarter, clamped to -1/2 .. 3/4).
- The output: the velocity, 2^-32 quarter per clock, signed, as the program shows it
  (OUT: the speed it keeps in its register file, with the sign of the last step, SIGN;
  and its acceleration, added once for every K = 64 clocks that TICK makes due), and
  `valid`.
- A reversal (a step against the last) or an illegal transition restarts the program
  (the velocity 0; an illegal transition also drops `valid` and the step held; a
  reversal holds its step: the anchor of the first window after it).

Units: quarters and clocks; `velocity` is signed with V_FRAC = 32 fractional bits.
"""

from __future__ import annotations

from .engine import Engine, WORD_MASK
from .program import K, LEVEL_SHIFT, PROGRAM, RESTART, V_FRAC, constants

COUNT_BITS = 20
AGE_MAX = 511                         # the held step's age, saturating (9 bits)
WIDTH_LO, WIDTH_HI = -(1 << 11), 3 << 10   # the quarter's width less one, clamped (2^-12)
VELOCITY_BITS = 32                     # the output: signed


class Velocity:
    """Clock-level model: `clock()` takes one cycle's inputs and leaves the state as
    the RTL's registers after that cycle's edge."""

    def __init__(self, window: int = 512, cal: int = 0, edge_tolerance: int = 0):
        if not 16 <= window < (1 << 30):
            raise ValueError(f"window = {window} is out of range 16..2^30-1")
        if cal not in (0, 1):
            raise ValueError(f"cal = {cal} must be 0 or 1")
        self.window = window
        self.cal = cal
        self.edge_tolerance = edge_tolerance
        self.engine = Engine(PROGRAM, constants(window, cal, edge_tolerance), RESTART)
        self.reset()

    def reset(self) -> None:
        self.engine.reset()
        self.engine.restart(RESTART)
        self.now = 0
        self.count = 0
        self.stime = self.sposc = self.ltime = self.lwidth = 0
        self.pend = 0
        self.cw = 1
        self.moved = 0
        self.valid = 0
        self.tick = K
        self.due = 0
        self.velocity = 0

    def clock(self, step: int = 0, step_cw: int = 0, illegal: int = 0, rst: int = 0,
              c_lo: int = 0, c_hi: int = 0) -> None:
        """c_lo, c_hi: with a calibration table (cal = 1), the corrections of the edges
        of the quarter the decoder is in after this cycle's step, 2^-12 quarter: a CW
        step crossed its lower edge, a CCW one its upper edge."""
        if rst:
            self.reset()
            return
        if not self.cal:
            c_lo = c_hi = 0
        specials = {"NOW": self.now, "STIME": self.stime, "SPOSC": self.sposc,
                    "LTIME": self.ltime, "LWIDTH": self.lwidth << LEVEL_SHIFT}
        effects = self.engine.step(specials, self.pend, min((self.now - self.stime) & WORD_MASK, AGE_MAX),
                                   self.cw, self.due)
        # The tick: every K clocks one more update is due (up to 7); FLAG TICK 0 takes
        # one, FLAG TICK 1 restarts it (K / 2 to go: the speed shown is each K clocks'
        # middle one).
        self.tick -= 1
        due = self.due
        if self.tick == 0:
            self.tick, due = K, min(due + 1, 7)
        t = effects.get("tick")
        if t == 0:
            due = max(due - 1, 0)
        elif t == 1:
            self.tick, due = K // 2, 0
        self.due = due
        out = effects.get("out")
        if out is not None:
            _, acc = out
            self.velocity = acc - (1 << 32) if acc >> 31 else acc
            self.valid = 1
        if effects.get("done"):
            self.pend = 0
        # The steps.
        reversal = step and self.moved and step_cw != self.cw
        if step:
            crossed = c_lo if step_cw else c_hi
            self.count = (self.count + 1) & ((1 << COUNT_BITS) - 1)
            if not self.pend or reversal:
                self.stime = self.now
                self.sposc = ((self.count << 12) + (crossed if step_cw else -crossed)) & WORD_MASK
                self.pend = 1
            self.ltime = self.now
            self.lwidth = max(WIDTH_LO, min(WIDTH_HI, c_hi - c_lo))
            self.cw, self.moved = step_cw, 1
        if illegal or reversal:
            self.velocity = 0
            self.engine.restart(RESTART)
            if illegal:
                self.valid = self.pend = self.moved = 0
        self.now = (self.now + 1) & WORD_MASK
