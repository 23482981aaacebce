# SPDX-License-Identifier: Apache-2.0
"""The velocity of prenc 0.11.0's default (prenc_velocity before 0.12.0: full-cycle
windows, the constant-speed test and the fit), kept as a baseline for `make bench`'s
section 9, so that the design that replaced it is measured beside it in the same run.
No RTL of it is left; prenc.virtual.fine_bench.previous_velocity runs it. Only that
configuration is kept (0.11's options QUARTER_WINDOWS, ACCEL_FIT = 0 and CAL are not).

It was the model of rtl/fine/prenc_velocity.v: velocity and acceleration from the sync track's
edge timing.

Units: quarters (quadrature states, a quarter slot) and clocks. `velocity` and `accel`
are signed fixed point with FRAC = 48 fractional bits: quarters per clock and quarters
per clock squared (docs/fine.md converts them to rpm).

The estimator, on the quadrature decoder's registered step:

- Each step crosses an edge of the sync track at a known place x in quarters (a CW
  step into quarter h crosses edge h; a CCW step into h crosses edge h + 1).
- Anchors: the step that opened the current window (A, `since_a` clocks ago) and the
  window or run before it (its quarters `prev_n` and clocks `prev_clocks`). A window
  closes at least WINDOW clocks after A on a step over an edge of A's type (x - x_A a
  multiple of 4: the same edge of A or B, so A/B phase and duty errors cancel).
- On a window's close with a window before it (n1 quarters in P1 clocks, and n2 in
  P2 before it), first the constant-speed test: if |n1 P2 - n2 P1| < |n1| + |n2|, the
  two agree within their clocks' quantization (each one's length is off by less than
  a clock), so velocity = (n1 + n2) / (P1 + P2) and accel = 0: the mean over both. If
  the test failed on the update before too, with the same sign of n1 P2 - n2 P1 (an
  acceleration that lasts, not one window's noise: a printed disc's edge errors move
  each window's mean speed by several per cent), the mean velocities fit constant
  acceleration (a parabola through the three anchors):
      v01 = n1 / P1, v12 = n2 / P2, a = 2 (v01 - v12) / (P1 + P2),
      velocity = v01 + a (P1 / 2 + FULL_CLOCKS),
  FULL_CLOCKS being how long the computation takes, so that the velocity is that of
  the cycle it is loaded in. Otherwise the mean over both, accel 0. Between updates
  the velocity integrates `accel`.
- Before the first window closes (after reset, a stop or an illegal transition): on
  each step, the mean velocity since A, accel 0.
- A reversal (a step against the last step's direction) restarts the windows; the
  velocity takes the new direction's sign at once, with the speed the last edge was
  crossed at (in a smooth reversal the disc crosses the same edge back at that speed),
  and the acceleration goes on: no means are taken while it is known, until a fit.
- Without a step the velocity never crosses 0. Integrating the acceleration to 0 holds
  it there, acceleration kept, for the reversal that should follow; a step the same
  way instead means the acceleration was wrong (it is dropped, the means restart);
  no step for 4 times as long as it took to reach 0 is a stop.
- Overdue: once the velocity predicts 1.5 quarters of travel since the last step and
  no step came,
  the disc is slower than estimated: accel becomes -3 v / E (E the clocks since the
  step), which brings the velocity to 0 at 2 predicted quarter periods, and that is a
  stop. No step for 2^TIMER_BITS - 1 clocks: a stop too. A stop reads 0 (valid).
- An illegal transition (a missed state) drops the velocity: `valid` 0 until the next
  estimate.

One serial divider (a quotient bit per clock) and one serial multiplier (a bit of the
multiplier per clock) do the arithmetic, so an update takes FULL_CLOCKS; a step that
comes while they are busy updates nothing (the window closes on a later step of the
same type).
"""

from __future__ import annotations

FRAC = 48                  # fractional bits of velocity and accel
QUOTIENT_BITS = FRAC + 1   # the divider's quotient: a velocity below 2 quarters per clock
VELOCITY_BITS = FRAC + 3   # signed, |velocity| < 4 quarters per clock (saturating)
ACCEL_BITS = FRAC + 2      # signed (saturating)
COUNT_BITS = 16            # edge positions, in quarters, modulo 2^COUNT_BITS
LEAD_LIMIT = 2 << FRAC     # the predicted travel since the last step saturates at 2 quarters
OVERDUE = 3 << (FRAC - 1)  # 1.5 quarters
DIV_CLOCKS = QUOTIENT_BITS + 2   # from a division's start cycle to its done cycle


def full_clocks(timer_bits: int) -> int:
    """Cycles from a window's closing step to the cycle the fitted velocity shows: two
    products of COUNT_BITS bits, the test, three divisions, the difference, a product of
    TIMER_BITS + 1 bits, the sum."""
    return 2 * COUNT_BITS + 3 * DIV_CLOCKS + timer_bits + 8


def saturate(value: int, bits: int) -> int:
    """Saturate to a signed value of `bits` bits (symmetric: -(2^(bits-1) - 1) at least)."""
    top = (1 << (bits - 1)) - 1
    return max(-top, min(top, value))


def _sign(value: int) -> int:
    return -1 if value < 0 else 1


class Divider:
    """0.11's prenc_divider: floor(num / den), a quotient bit per clock.
    A start in cycle k gives `done` for one cycle in cycle k + DIV_CLOCKS (it registers
    its operands, checks for saturation, then takes a bit a clock); a quotient
    that needs more than QUOTIENT_BITS bits (or den = 0) saturates to all ones; `cancel`
    drops a division under way, and one starting in the same cycle."""

    def __init__(self, quotient_bits: int = QUOTIENT_BITS) -> None:
        self.quotient_bits = quotient_bits
        self.clocks = quotient_bits + 2   # from a start's cycle to its done cycle
        self.left = 0
        self.result = 0
        self.done = 0
        self.quotient = 0

    def clock(self, start: int, num: int = 0, den: int = 0, cancel: int = 0) -> None:
        self.done = 0
        if self.left:
            self.left -= 1
            if self.left == 0:
                self.done, self.quotient = 1, self.result
        if start:
            limit = (1 << self.quotient_bits) - 1
            self.result = limit if den == 0 or num // den > limit else num // den
            self.left = self.clocks - 1
        if cancel:
            self.left = 0


class Velocity:
    """Clock-level model: `clock()` takes one cycle's inputs (the decoder's registered
    step, step_cw, illegal) and leaves the state as the RTL's registers after that
    cycle's edge."""

    (IDLE, MEAN, CROSS1, CROSS2, DECIDE, CONSTANT, FIT_V01, FIT_V12, FIT_D, FIT_A, FIT_MUL,
     FIT_LOAD, DECAY) = range(13)

    def __init__(self, window: int = 2048, timer_bits: int = 26):
        if not 12 <= timer_bits <= 32:
            raise ValueError(f"timer_bits = {timer_bits} is out of range 12..32")
        if not 16 <= window < (1 << (timer_bits - 1)):
            raise ValueError(f"window = {window} is out of range 16..2^(timer_bits-1)-1")
        self.window = window
        self.timer_bits = timer_bits
        self.timer_max = (1 << timer_bits) - 1
        self.full_clocks = full_clocks(timer_bits)
        self.reset()

    def reset(self) -> None:
        self.velocity = 0
        self.accel = 0
        self.valid = 0
        self.count = 0          # edge count in quarters, modulo 2^COUNT_BITS
        self.cw = 1             # direction of the last step
        self.step_speed = 0     # |velocity| when the last step came
        self.held = 0           # the integration reached 0: held there, accel kept
        self.zero_at = 0        # clocks from the last step to that zero
        self.moved = 0          # a step since reset, a stop or an illegal transition
        self.since_step = 0     # clocks since the last step (saturating)
        self.lead = 0           # predicted travel since the last step, FRAC bits
        self.have_a = 0         # anchor A: the step that opened the current window
        self.x_a = 0
        self.since_a = 0
        self.have_prev = 0      # the run before: its quarters and clocks
        self.prev_n = 0
        self.prev_clocks = 0
        self.n1 = 0             # the window being closed: quarters (magnitude), clocks
        self.p1 = 0
        self.n2 = 0
        self.p2 = 0
        self.state = self.IDLE
        self.sign = 1           # the direction of the windows
        self.v01 = 0
        self.cross = 0          # n1 P2, then compared with n2 P1
        self.diff = 0           # n1 P2 - n2 P1
        self.d = 0              # v01 - v12
        self.v_fit = 0          # the fitted velocity before saturation
        self.mul_left = 0
        self.multiplier = 0
        self.multiplicand = 0
        self.product = 0
        self.decaying = 0
        self.last_negative = 0  # n1 P2 - n2 P1 < 0 on the last update, and whether it failed
        self.last_fit = 0       # the constant-speed test
        self.div = Divider()

    def _multiply(self, multiplier: int, multiplicand: int, bits: int, state: int) -> None:
        self.multiplier, self.multiplicand, self.mul_left = multiplier, multiplicand, bits
        self.product, self.state = 0, state

    def clock(self, step: int = 0, step_cw: int = 0, illegal: int = 0, rst: int = 0) -> None:
        if rst:
            self.reset()
            return
        mask = (1 << COUNT_BITS) - 1
        div_done, quotient = self.div.done, self.div.quotient
        start, num, den, cancel = 0, 0, 0, 0
        idle = self.state == self.IDLE
        velocity = self.velocity
        # A step reads these as the cycle began (a hold or a stop in the same cycle does
        # not count for it, nor a decision that a reversal cancels): in the RTL they do
        # not wait for the zero-crossing test or the sequencer.
        held0, decaying0, accel0, step_speed0 = self.held, self.decaying, self.accel, self.step_speed
        last_negative0 = self.last_negative
        mul_done = self.mul_left == 0

        # Between events: the velocity integrates accel (but while held at 0); the timers run.
        v_n = velocity if self.held else saturate(velocity + self.accel, VELOCITY_BITS)
        # Without a step the velocity never crosses 0: decaying, it stops there; else it
        # is held at 0 with its acceleration, for the reversal that should come. Held for
        # 4 times as long as it took to get there, the disc has stopped.
        crossing = velocity != 0 and (v_n == 0 or (v_n < 0) != (velocity < 0))
        stop = crossing and self.decaying
        hold = crossing and not self.decaying
        stop |= self.held and self.since_step >= 4 * self.zero_at
        lead = self.lead + velocity
        lead_n = lead if abs(lead) < LEAD_LIMIT else self.lead
        since_step_n = min(self.since_step + 1, self.timer_max)
        since_a_n = min(self.since_a + 1, self.timer_max)
        timeout = self.since_step == self.timer_max

        # The serial multiplier: a bit of the multiplier a cycle, MSB first.
        if self.state in (self.CROSS1, self.CROSS2, self.FIT_MUL) and not mul_done:
            bit = (self.multiplier >> (self.mul_left - 1)) & 1
            self.product = 2 * self.product + (self.multiplicand if bit else 0)
            self.mul_left -= 1

        # The sequencer.
        state = self.state
        if state == self.MEAN and div_done:
            v_n, self.accel, self.valid = self.sign * quotient, 0, 1
            self.state = self.IDLE
        elif state == self.CROSS1 and mul_done:
            self.cross = self.product
            self._multiply(self.n2, self.p1, COUNT_BITS, self.CROSS2)
        elif state == self.CROSS2 and mul_done:
            self.diff = self.cross - self.product
            self.state = self.DECIDE
        elif state == self.DECIDE:
            diff = self.diff
            constant = -(self.n1 + self.n2) < diff < self.n1 + self.n2
            # An acceleration that lasts: the test failed twice with the same sign.
            lasting = int(diff < 0) == self.last_negative and self.last_fit
            self.last_negative, self.last_fit = int(diff < 0), int(not constant)
            if constant or not lasting:
                self.state = self.CONSTANT
                start, num, den = 1, (self.n1 + self.n2) << FRAC, self.p1 + self.p2
            else:
                start, num, den = 1, self.n1 << FRAC, self.p1
                self.state = self.FIT_V01
        elif state == self.CONSTANT and div_done:
            v_n, self.accel, self.valid = self.sign * quotient, 0, 1
            self.state = self.IDLE
        elif state == self.FIT_V01 and div_done:
            self.v01 = quotient
            start, num, den = 1, self.n2 << FRAC, self.p2
            self.state = self.FIT_V12
        elif state == self.FIT_V12 and div_done:
            self.d = self.v01 - quotient
            self.state = self.FIT_D
        elif state == self.FIT_D:
            start, num, den = 1, abs(self.d) << 1, self.p1 + self.p2
            self.sign = self.sign * _sign(self.d)    # the sign of the acceleration
            self.state = self.FIT_A
        elif state == self.FIT_A and div_done:
            accel = self.sign * quotient   # QUOTIENT_BITS < ACCEL_BITS: it always fits
            self._multiply((self.p1 >> 1) + self.full_clocks, accel, self.timer_bits + 1, self.FIT_MUL)
        elif state == self.FIT_MUL and mul_done:
            # sign: the acceleration's; the windows' direction is the last step's.
            self.v_fit = (self.v01 if self.cw else -self.v01) + self.product
            self.state = self.FIT_LOAD
        elif state == self.FIT_LOAD:
            direction = 1 if self.cw else -1
            v_n = saturate(self.v_fit, VELOCITY_BITS)
            self.accel, self.valid = self.multiplicand, 1
            if v_n * direction <= 0:   # decelerated through 0: it stops there
                v_n, self.accel = 0, 0
            self.state = self.IDLE
        elif state == self.DECAY and div_done:
            self.accel = -self.sign * quotient
            self.state = self.IDLE

        if idle and not self.decaying and not step and not illegal and velocity != 0 \
                and abs(self.lead) >= OVERDUE:
            # Overdue: decay to 0 over a third of the time since the step.
            self.sign = _sign(velocity)
            start, num, den = 1, 3 * abs(velocity), self.since_step
            self.state, self.decaying = self.DECAY, 1
        # A hold, or a stop: the decay reached 0, or no step for 2^TIMER_BITS - 1 clocks.
        # They cancel what the divider starts in this cycle.
        if stop or timeout:
            v_n, self.accel, self.valid, self.decaying, self.held = 0, 0, 1, 0, 0
            self.have_prev = self.last_fit = self.step_speed = 0
            cancel, self.state = 1, self.IDLE
        elif hold:
            v_n, self.held, self.zero_at, self.decaying = 0, 1, self.since_step, 0
            cancel, self.state = 1, self.IDLE

        # Events, which win over all the above.
        if illegal:
            v_n, self.accel, self.valid, self.decaying, self.held = 0, 0, 0, 0, 0
            self.have_a = self.have_prev = self.last_fit = self.moved = 0
            since_step_n, lead_n = 1, 0
            cancel, start, self.state = 1, 0, self.IDLE
        elif step:
            x = (self.count + 1 if step_cw else self.count) & mask   # the edge crossed
            self.count = (self.count + (1 if step_cw else -1)) & mask
            reversal = self.moved and step_cw != self.cw
            self.cw, self.moved = step_cw, 1
            since_step_n, lead_n = 1, 0
            if held0 and not reversal:   # it did not reverse: the acceleration was wrong
                self.accel, self.have_prev, self.last_fit = 0, 0, 0
            self.held = 0
            if decaying0:
                self.decaying, self.accel = 0, 0
                if self.state == self.DECAY:
                    cancel, start, self.state = 1, 0, self.IDLE
            n = abs(((x - self.x_a + (1 << (COUNT_BITS - 1))) & mask) - (1 << (COUNT_BITS - 1)))
            speed = abs(velocity)   # as the cycle began (one carry chain less in the RTL)
            if reversal:
                # The same edge crossed back at the speed it was crossed at; accel and the
                # sign memory go on (the speed's trend turns: it grows again).
                speed = step_speed0
                v_n = speed if step_cw else -speed
                self.have_prev = 0
                self.last_negative = last_negative0 ^ 1
                self.have_a, self.x_a, since_a_n = 1, x, 1
                cancel, start, self.state = 1, 0, self.IDLE
            elif not self.have_a or self.since_a == self.timer_max:
                self.have_prev = self.last_fit = 0
                self.have_a, self.x_a, since_a_n = 1, x, 1
            elif idle:
                closes = (n & 3) == 0 and self.since_a >= self.window
                self.sign = 1 if step_cw else -1
                if closes and self.have_prev:
                    self.n1, self.p1, self.n2, self.p2 = n, self.since_a, self.prev_n, self.prev_clocks
                    self._multiply(n, self.prev_clocks, COUNT_BITS, self.CROSS1)
                elif (closes or not self.have_prev) and accel0 == 0 and not held0:
                    # The mean since A, unless an acceleration is known (after a reversal):
                    # then the velocity integrates it until a fit.
                    start, num, den, cancel = 1, n << FRAC, self.since_a, 0
                    self.state = self.MEAN
                if closes:
                    self.have_prev, self.prev_n, self.prev_clocks = 1, n, self.since_a
                    self.x_a, since_a_n = x, 1
            self.step_speed = speed

        self.div.clock(start, num, den, cancel)
        self.velocity = v_n
        self.since_step, self.since_a, self.lead = since_step_n, since_a_n, lead_n
