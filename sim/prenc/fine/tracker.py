# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/fine/prenc_tracker.v: velocity and acceleration from the sync track's
edges by a tracking filter whose gains come from a table (prenc.fine.tracker_gains).

Units: quarters and clocks. The state is integer fixed point:

    pos   the predicted position minus the last edge crossed, 2^-40 quarter (+-8)
    vel   quarters per clock, 2^-40                                         (+-2)
    acc   quarters per clock^2, 2^-60

Every clock the state moves: pos += vel, vel += acc >> 20. On a step of the decoder
(edge x crossed; the last edge crossed was x - 1, x + 1 or, after a reversal, x
itself: d = x - x_last is +1, -1 or 0; with a calibration table, cal_bits = 12, the
edges are at their true places: d = x + c(x) - x_last - c(x_last), the corrections in
2^-12 quarter from the table, as prenc_velocity takes them):

- the innovation e = d - (pos + vel), the measured edge less the predicted position,
  in 2^-20 quarter (saturated to +-4 quarters); pos is referred to the new edge
  (pos + vel - d);
- the gains: a word of the table, at the column of |vel| of the clock before (2 an
  octave; its leading one is a register) and the bin of the filter's age (the updates
  since it started). A maneuver halves the age first, not below AGE_FLOOR: the
  innovations' running mean (weight 1/4, in their standard deviations, the table's gz)
  above 1. A jump sets it to AGE_FLOOR: the last update's innovation above 4 standard
  deviations (a change of acceleration, as where a ramp starts); the filter then
  chases: its age holds, not counting this update, while the running mean stays above
  1/2;
- the table's word takes two clocks (the block RAM's read, registered once more); one
  serial multiplier per gain, a mantissa bit a clock (12 clocks), then one shifter for
  all four, a gain a clock (its output registered);
- the corrections land APPLY = 32 clocks after the step, as if they had at the step
  and the state had moved since: acc += g2 e, vel += g1 e + 32 (g2 e >> 20),
  pos += g0 e + 32 g1 e + 512 (g2 e >> 20) (32 32 / 2 for 32 31 / 2: shifts, no
  multiplier).
  A step while an update is under way is referred (pos) but measures nothing.

The start: the first step (after reset, a stop or an illegal transition) is an anchor;
the second one gives the velocity, one quarter over the clocks between them (a serial
division, prenc_divider), LOAD = 64 clocks after the step, the position moved on by as
many clocks (a shift); the filter starts at age 0 then. Steps before that are referred
(pos -= d, so that the position is right when the velocity loads); a reversal makes the
step the anchor again.

The output (`velocity`, a clock after the state): the state's velocity, 0 unless it has
the sign of the last step; once the predicted position is 2 quarters past the last edge
(an edge overdue), it decays linearly: a level starting at the velocity shown falls by
about v^2 a clock (a power of two from the leading one p of |vel| of the clock before,
2^(2p - 38) in 2^-40: v^2 to 4 v^2), which reaches 0 within 2.25 to 3 predicted quarter
periods after the edge; there, or after no step for 2^TIMER_BITS - 1 clocks, the disc
has stopped: the velocity reads 0 (valid) and the next step is an anchor. An illegal
transition drops the velocity (`valid` 0) until the next estimate. So do LOST = 3
measured updates in a row whose innovation is a quarter or more (the filter has lost the
edges: a gain table for a smaller edge error than the disc's can leave it in a wrong
state, docs/fine.md), until as many in a row come closer. `offset` is the
filtered position past the last edge crossed (pos's top bits), valid while the filter
tracks the way the disc last stepped, no edge is overdue, the edges are not lost and it
measured the last two steps: prenc_fine's TRACKER = 2 makes it the fine position between
edges. With a calibration
table the first velocity is the quarter's true width over the clocks (its correction
clamped to +-1/2 quarter).
"""

from __future__ import annotations

from ..cal.table import FRAC as CAL_BITS   # the calibration's corrections: 2^-12 quarter
from . import tracker_gains as tg
from .fine_position import OFFSET_FRAC   # the offset output: pos's top bits, 2^-24 quarter
from .velocity import DIV_CLOCKS, FRAC, Divider, saturate

POS_BITS = 44              # pos: signed, 2^-40 quarter (+-8 quarters)
CORR_BITS = 46             # the position's and the velocity's corrections, 2^-40
VEL_BITS = 42              # vel: signed, 2^-40 quarter per clock
ACC_BITS = 52              # acc: signed, 2^-60 quarter per clock^2
STATE_FRAC = 40
OFFSET_BITS = POS_BITS - (STATE_FRAC - OFFSET_FRAC)
ACC_SHIFT = 20             # acc's extra fractional bits
E_BITS = 23                # the innovation: signed, 2^-20 quarter
RESULT_BITS = 52           # a correction from the shifter
BIAS_BITS = 16             # the innovations' running mean: signed, 2^-8 sigma
AGE_FLOOR = 4
FIRST_DC = 1 << (CAL_BITS - 1)   # the first velocity's correction: +-1/2 quarter at most
APPLY = 32                 # clocks from the step to the corrections
LOAD = 64                  # clocks from the second step to the first velocity
assert DIV_CLOCKS < LOAD   # the division is done by then
MANEUVER = 1 << 8          # |bias| above 1 sigma: the age halves
JUMP = 4 << 8              # the last update's |z| above 4 sigma: the age drops to AGE_FLOOR
CHASE = 1 << 7             # after a jump, the age holds while |bias| is above 1/2 sigma
FAR = 1 << tg.INNOVATION_FRAC   # an innovation of a quarter or more (e >= 1 or e < -1)
LOST = 3                   # updates in a row that far off: the edges are lost (`valid` 0);
                           # as many closer ones in a row: found again

# The sequence after a step (seq): the table's word (read, then registered once more:
# a block RAM's output is slow), 12 multiplier clocks, 4 shifts (a gain a clock, the
# shifter's output registered), each used the clock after its shift.
S_READ, S_WORD, S_MUL = 1, 2, 3
S_SHIFT = S_MUL + 12
S_ACC, S_VEL, S_POS, S_BIAS = S_SHIFT + 1, S_SHIFT + 2, S_SHIFT + 3, S_SHIFT + 4
SHIFTED = (2, 1, 0, 3)     # the gain shifted at S_SHIFT, S_SHIFT + 1, ...


def clamp(value: int, bits: int) -> int:
    """Saturated to a signed value of `bits` bits (two's complement: -2^(bits-1) at least)."""
    return max(-(1 << (bits - 1)), min((1 << (bits - 1)) - 1, value))


def wrap(value: int, bits: int) -> int:
    """The low `bits` bits as a signed number (what a register of that width keeps)."""
    value &= (1 << bits) - 1
    return value - (1 << bits) if value >> (bits - 1) else value


def shifter(value: int, s: int) -> int:
    """(value << PRE_SHIFT) >> s, arithmetic, kept to RESULT_BITS."""
    return wrap((value << tg.PRE_SHIFT) >> s, RESULT_BITS)


class Tracker:
    """Clock-level model: `clock()` takes one cycle's inputs (the decoder's registered
    step, step_cw, illegal) and leaves the state as the RTL's registers after that
    cycle's edge."""

    NONE, ANCHOR, DIVIDE, TRACK = range(4)

    def __init__(self, words: list[int], timer_bits: int = 26, cal_bits: int = 0):
        if len(words) != tg.COLUMNS * tg.BINS:
            raise ValueError(f"the gain table has {len(words)} words, not {tg.COLUMNS * tg.BINS}")
        if not 12 <= timer_bits <= 32:
            raise ValueError(f"timer_bits = {timer_bits} is out of range 12..32")
        if cal_bits not in (0, CAL_BITS):
            raise ValueError(f"cal_bits = {cal_bits} must be 0 or {CAL_BITS}")
        self.words = words
        self.cal_bits = cal_bits
        self.timer_bits = timer_bits
        self.timer_max = (1 << timer_bits) - 1
        self.reset()

    def reset(self) -> None:
        self.phase = self.NONE
        self.estimate = 0       # a velocity was estimated (the first one loaded, no illegal
                                # transition since): `valid` unless the edges are lost
        self.measured = 0       # the last two steps were measured (each an update; or the
        self.measured_last = 0  # filter started after them): `offset` follows the edges
        self.lost = 0           # the edges are lost: LOST updates in a row far off
        self.lock_count = 0     # ... counted (and as many close ones to find them again)
        self.velocity = 0       # the output: quarters per clock, FRAC (48) fractional bits
        self.cw = 1             # the last step's direction
        self.c_last = 0         # the correction of the last edge crossed (CAL = 1)
        self.since = 0          # clocks since the last step (saturating)
        self.pos = 0
        self.vel = 0
        self.acc = 0
        self.age = 0
        self.bias = 0
        self.jump = 0
        self.chase = 0
        self.seq = 0
        self.e = 0
        self.address = 0
        self.read = 0           # the block RAM's read register
        self.word = 0
        self.product = [0, 0, 0, 0]
        self.shifted = 0        # the shifter's output, registered
        self.acc_corr = 0
        self.vel_corr = 0
        self.pos_corr = 0
        self.negative = 0       # the first velocity's sign
        self.dividing = 0       # clocks since the division started (7 bits, wrapping)
        self.class_speed = 0    # |vel| of the clock before: its leading one and the bit
                                # below it are registers (the table's column, the slope)
        self.decaying = 0
        self.level = 0
        self.slope = 0
        self.div = Divider()

    def field(self, i: int) -> tuple[int, int]:
        """Gain i of the word read: (mantissa, shift)."""
        f = (self.word >> (i * tg.FIELD_BITS)) & ((1 << tg.FIELD_BITS) - 1)
        return f & ((1 << tg.MANTISSA_BITS) - 1), f >> tg.MANTISSA_BITS

    def shown(self) -> int:
        """The velocity the output shows next (from the registers as the cycle began)."""
        if self.phase != self.TRACK:
            return 0
        same = self.vel > 0 if self.cw else self.vel < 0
        magnitude = abs(self.vel) if same else 0
        if self.decaying:
            magnitude = min(magnitude, self.level)
        return magnitude if self.cw else -magnitude

    @property
    def valid(self) -> int:
        """The velocity is an estimate: estimated, and the edges not lost."""
        return int(self.estimate and not self.lost)

    @property
    def offset(self) -> int:
        """The filtered position: the predicted position minus the last edge crossed, in
        2^-OFFSET_FRAC quarter (pos's top OFFSET_BITS bits), for prenc_fine_position."""
        return self.pos >> (STATE_FRAC - OFFSET_FRAC)

    @property
    def offset_valid(self) -> int:
        """The filter tracks and moves the way the disc last stepped, no edge overdue,
        the edges not lost, and it measured the last two steps (above about 13,700 rpm
        at N = 10 and 30 MHz it measures some steps only: its position is then not
        taken): `offset` is its estimate (from the registers, as `offset` is)."""
        same = self.vel > 0 if self.cw else self.vel < 0
        return int(self.phase == self.TRACK and not self.decaying and same and not self.lost
                   and self.measured)

    @property
    def accel(self) -> int:
        """The acceleration output: quarters per clock^2, FRAC (48) fractional bits."""
        return self.acc >> (STATE_FRAC + ACC_SHIFT - FRAC)

    def clock(self, step: int = 0, step_cw: int = 0, illegal: int = 0, rst: int = 0,
              c_lo: int = 0, c_hi: int = 0) -> None:
        """c_lo, c_hi: with a calibration table (cal_bits = 12), the corrections of the
        edges of the quarter the decoder is in (after this cycle's step), in 2^-12
        quarter: a clockwise step crossed its lower edge (c_lo), a counter-clockwise one
        its upper edge (c_hi)."""
        if not self.cal_bits:
            c_lo = c_hi = 0
        step_c = c_lo if step_cw else c_hi
        if rst:
            self.reset()
            return
        quotient = self.div.quotient
        vel = self.vel
        start = cancel = 0
        num = 1 << FRAC         # the first velocity: a quarter over the clocks
        shown = self.shown()
        seq, phase = self.seq, self.phase

        # Every clock: the state moves; the timer runs.
        pos_n = self.pos + self.vel
        vel_n = self.vel + (self.acc >> ACC_SHIFT)
        acc_n = self.acc
        since_n = min(self.since + 1, self.timer_max)
        dividing_n = (self.dividing + 1) & 127
        seq_n = seq + 1 if seq else 0

        # The update's sequence.
        if seq == S_READ:
            self.read = self.words[self.address]
        elif seq == S_WORD:
            self.word = self.read
        elif S_MUL <= seq < S_SHIFT:
            bit = tg.MANTISSA_BITS - 1 - (seq - S_MUL)
            for i in range(4):
                m, _ = self.field(i)
                self.product[i] = 2 * self.product[i] + (self.e if (m >> bit) & 1 else 0)
        shifted = self.shifted
        if S_SHIFT <= seq < S_SHIFT + 4:
            i = SHIFTED[seq - S_SHIFT]
            self.shifted = shifter(self.product[i], self.field(i)[1])
        if seq == S_ACC:
            self.acc_corr = shifted
        elif seq == S_VEL:
            self.vel_corr = wrap(shifted + (self.acc_corr >> (ACC_SHIFT - 5)), CORR_BITS)
            self.pos_corr = wrap((shifted << 5) + (self.acc_corr >> (ACC_SHIFT - 9)), CORR_BITS)
        elif seq == S_POS:
            self.pos_corr = wrap(self.pos_corr + shifted, CORR_BITS)
        elif seq == S_BIAS:
            z = clamp(shifted, BIAS_BITS)
            self.bias += (z - self.bias) >> 2
            self.jump = int(abs(z) > JUMP)
        if seq == APPLY:
            pos_n += self.pos_corr
            vel_n += self.vel_corr
            acc_n += self.acc_corr
            seq_n = 0

        # The first velocity, from the division (done DIV_CLOCKS after the step), LOAD
        # clocks after the step.
        if phase == self.DIVIDE and self.dividing == LOAD:
            v = quotient >> (FRAC - STATE_FRAC)
            vel_n = -v if self.negative else v
            pos_n, acc_n = self.pos + vel_n * LOAD, 0
            self.phase, self.estimate, self.age, self.bias, self.jump, self.chase = self.TRACK, 1, 0, 0, 0, 0
            self.measured = self.measured_last = 1

        # An overdue edge: the output decays to 0, a stop.
        stop = self.since == self.timer_max and phase != self.NONE
        if self.decaying:
            if self.level <= self.slope:
                stop = 1
            self.level -= self.slope
        elif phase == self.TRACK and seq == 0 and not step and not illegal \
                and (self.pos if self.cw else -self.pos) >= 2 << STATE_FRAC:
            self.decaying, self.level = 1, abs(shown)
            lead = max(self.class_speed.bit_length() - 1, 0)
            self.slope = 1 << (2 * lead - 38) if lead >= 19 else 1

        if stop:
            self.phase, self.decaying, self.level = self.NONE, 0, 0
            pos_n = vel_n = acc_n = 0
            seq_n, cancel = 0, 1

        # Events, which win over all the above.
        if illegal:
            self.phase, self.estimate, self.decaying, self.level = self.NONE, 0, 0, 0
            pos_n = vel_n = acc_n = 0
            seq_n, cancel, since_n = 0, 1, 1
        elif step:
            reversal = step_cw != self.cw
            d = 0 if reversal else (1 if step_cw else -1)
            dc = step_c - self.c_last
            moved = (d << STATE_FRAC) + (dc << (STATE_FRAC - CAL_BITS))
            self.cw, since_n, self.c_last = step_cw, 1, step_c
            self.decaying, self.level = 0, 0
            if phase == self.TRACK and not stop:
                predicted = self.pos + self.vel
                pos_n = pos_n - moved
                self.measured = int(seq == 0 and self.measured_last)
                self.measured_last = int(seq == 0)
                if seq == 0:
                    e = (moved - predicted) >> (STATE_FRAC - tg.INNOVATION_FRAC)
                    self.e = clamp(e, E_BITS)
                    far = self.e >= FAR or self.e < -FAR
                    if far != bool(self.lost):
                        self.lock_count += 1
                        if self.lock_count == LOST:
                            self.lost, self.lock_count = int(far), 0
                    else:
                        self.lock_count = 0
                    age = self.age
                    if self.jump:
                        age = AGE_FLOOR
                    elif abs(self.bias) > MANEUVER:
                        age = max(age >> 1, AGE_FLOOR)
                    self.address = tg.column(self.class_speed) * tg.BINS + tg.age_bin(age)
                    self.chase = int(self.jump or (self.chase and abs(self.bias) > CHASE))
                    self.age = age if self.chase else min(age + 1, tg.AGE_MAX)
                    self.product = [0, 0, 0, 0]
                    seq_n = S_READ
            elif phase == self.ANCHOR and not reversal and not stop:
                start, self.negative, dividing_n = 1, int(not step_cw), 1
                # ... the quarter's true width with a table (its correction within +-1/2)
                num += max(-FIRST_DC, min(FIRST_DC - 1, dc)) << (FRAC - CAL_BITS)
                self.phase = self.DIVIDE
                pos_n = vel_n = acc_n = 0
            elif phase == self.DIVIDE and not reversal and not stop:
                pos_n = pos_n - moved   # referred, as the velocity is not known yet
            else:   # an anchor: the first step, a reversal, a stop
                self.phase = self.ANCHOR
                pos_n = vel_n = acc_n = 0
                seq_n, cancel = 0, 1

        self.div.clock(start, num, self.since, cancel)
        self.velocity = shown << (FRAC - STATE_FRAC)
        self.pos = clamp(pos_n, POS_BITS)
        self.vel = saturate(vel_n, VEL_BITS)
        self.acc = clamp(acc_n, ACC_BITS)
        self.since, self.seq, self.dividing = since_n, seq_n, dividing_n
        self.class_speed = abs(vel)
