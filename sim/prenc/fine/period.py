# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/fine/prenc_period.v: velocity from the period of the sync track's last
cycle, for a small FPGA (prenc_fine's PERIOD = 1; the dVRK firmware's method, and the
bench's "period" baseline, in integers).

- A step is an interval (the clocks since the step before). After four intervals the
  same way, the velocity is 4 / (their sum); before that (after a reversal, the start)
  1 / (the last interval). The division (32 fractional bits, DIV_CLOCKS = 35) starts
  2 clocks after the step; a step that comes while it runs is taken when it is done.
- The sign is the last step's (a clock after it: the output is registered).
- Overdue (no step for 1.5 times the interval the velocity came from): the magnitude is
  at most 1.5 quarters (a printed disc's widest quarter) over the clocks since the last
  step, divided again whenever the divider is free. No step for 4 times that interval,
  or for 2^TIMER_BITS - 1 clocks: a stop, 0 (valid). The thresholds are compared a
  clock ahead (registers).
- The first step after reset, a stop or an illegal transition is an anchor; an illegal
  transition drops the velocity (valid 0).

`clock()` takes one cycle's inputs and leaves the state as the RTL's registers after
that cycle's edge.
"""

from __future__ import annotations

from .velocity import FRAC, Divider

FP = 32                    # the quotient's fractional bits
QUOTIENT_BITS = FP + 1
DIV_CLOCKS = QUOTIENT_BITS + 2
NO_BOUND = (1 << QUOTIENT_BITS) - 1


class Period:
    def __init__(self, timer_bits: int = 26):
        if not 12 <= timer_bits <= 32:
            raise ValueError(f"timer_bits = {timer_bits} is out of range 12..32")
        self.timer_bits = timer_bits
        self.timer_max = (1 << timer_bits) - 1
        self.reset()

    def reset(self) -> None:
        self.div = Divider(QUOTIENT_BITS)   # its reset
        self.moved = 0
        self.cw = 1
        self.since = 0
        self.q = [0, 0, 0, 0]       # the last four intervals, newest first
        self.run = 0
        self.change = 0
        self.period = 0
        self.summing = 0
        self.want = 0
        self.busy = 0
        self.bounding = 0
        self.interval = 0
        self.late = 0
        self.timed = 0
        self.past_late = 0          # since > late, compared the clock before
        self.past_stop = 0          # since > 4 interval, likewise
        self.speed = 0
        self.bound = NO_BOUND
        self.valid = 0
        self.shown = 0
        self.out = 0                # the signed output register (2^-FRAC)

    @property
    def velocity(self) -> int:
        """Quarters per clock, 2^-FRAC (the RTL's output register)."""
        return self.out

    @property
    def accel(self) -> int:
        return 0

    def clock(self, step: int, step_cw: int, illegal: int, rst: int = 0, c_lo: int = 0, c_hi: int = 0) -> None:
        """One cycle (c_lo and c_hi: unused, prenc_velocity's calling convention)."""
        if rst:
            self.reset()
            return
        div = self.div
        # This cycle's wires, from the registers.
        busy, bounding, since = self.busy, self.bounding, self.since
        moved, cw, run, q, period = self.moved, self.cw, self.run, self.q, self.period
        full = run == 4
        start_step = self.want and not busy
        overdue = moved and self.timed and self.past_late
        start_bound = not self.want and not busy and overdue and not step
        stop = moved and (since == self.timer_max or (self.timed and self.past_stop))
        cancel = illegal or stop or (step and busy and bounding)
        if start_step:
            num, den = (4 << FP, period) if full else (1 << FP, q[0])
        else:
            num, den = 3 << (FP - 1), since   # 1.5 quarters: a bound
        done, quotient = div.done, div.quotient
        shown = min(self.bound, self.speed)

        # The registers' next values, in the RTL's order (later ones win).
        if since != self.timer_max:
            self.since = since + 1
        ahead = not step and not start_step   # the thresholds, a clock ahead
        self.past_late = int(ahead and since >= self.late)
        self.past_stop = int(ahead and since >= self.interval << 2)
        summing, self.summing = self.summing, 0
        if summing:
            self.period = period + self.change
            self.want = 1
        if start_step:
            self.want = 0
            self.busy = 1
            self.bounding = 0
            self.interval = period >> 2 if full else q[0]
            self.late = self.interval + (self.interval >> 1)
        elif start_bound:
            self.busy = 1
            self.bounding = 1
        if done and busy:   # (a division cancelled may still say done)
            self.busy = 0
            if bounding:
                self.bound = quotient
            else:
                self.speed = quotient
                self.valid = 1
                self.timed = 1
        magnitude = self.shown << (FRAC - FP)
        self.out = magnitude if cw else -magnitude
        self.shown = shown

        # Events, which win over all the above.
        if illegal or stop:
            self.moved = 0
            self.timed = 0
            self.run = 0
            self.want = 0
            self.busy = 0
            self.speed = 0
            self.bound = NO_BOUND
            self.shown = 0
            self.q = [0, 0, 0, 0]
            self.period = 0
            self.summing = 0
            self.valid = 0 if illegal else 1
            if illegal:
                self.since = 1
        elif step:
            self.moved = 1
            self.cw = step_cw
            self.since = 1
            self.bound = NO_BOUND
            if busy and bounding:   # cancelled
                self.busy = 0
            if moved:   # an interval (else the step is an anchor)
                self.run = 0 if step_cw != cw else 4 if full else run + 1
                self.q = [since] + q[:3]
                self.change = since - q[3]
                self.summing = 1
        div.clock(start_step or start_bound, num, den, cancel)
