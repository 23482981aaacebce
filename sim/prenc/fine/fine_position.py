# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/fine/prenc_fine_position.v: the verified position with the fraction of
the quarter passed, extrapolated to the instant a consumer asks.

Inputs each cycle: the core's pos_hyb and pos_valid; the quadrature decoder's
registered step and step_cw (the block delays them STEP_DELAY cycles, so that the
step meets pos_hyb, which shows it 4 cycles after the decoder); the velocity and its
valid flag (prenc_velocity, FRAC fractional bits, quarters per clock).

- travel: the velocity integrated since pos_hyb's last step (FRAC bits; it stops
  once it is 2 quarters or more, past any clamp below); or, while `offset_valid`, `offset`: a tracking filter's estimate of
  the position past the last edge crossed (prenc_tracker's, TRACKER = 2), which
  averages many edges where one edge and the velocity carry the edge's own error.
  When the filter stops tracking (an edge overdue, a stop: its velocity 0), travel
  goes on from there with the velocity.
- The fraction of the quarter: the last step crossed the quarter's lower edge (CW) or
  its upper edge (CCW); fraction = clamp(edge + travel, 0, 1 - 2^-48). So while
  pos_valid the fine position's quarter is pos_hyb's: when the next edge is late, the
  fraction holds at the quarter's end.
- Extrapolation over the pipeline: + velocity * LOOKAHEAD_HALVES / 2 (clocks from the
  pins to this block's output, and half a clock for the edge's unknown place within
  its clock). It can take the fine position past the quarter's edge by at most
  |velocity| * LOOKAHEAD_HALVES / 2 quarters: the only way it leaves the verified
  quarter. LOOKAHEAD_HALVES = 0 turns it off.
- Without a valid velocity: the fraction is the quarter's middle, nothing extrapolated,
  and `interpolated` is 0.

With a calibration table (issue 38), `c_lo` and `c_hi` are the corrections of
pos_hyb's quarter's edges: the fraction starts at the crossed edge's true place and is
clamped to the quarter's true span [c_lo, 1 + c_hi), so the fine position leaves the
verified quarter by at most the table's largest correction (plus the extrapolation).
They are 0 without a table (CAL = 0).

Three register stages, so that no two long carry chains follow each other: (A) the
fraction clamped (by its bits: it lies within 9 quarters of 0), with pos_hyb and the
flags; (B) the fraction plus the extrapolation; (C) the output. The extrapolation,
velocity x LOOKAHEAD_HALVES, comes from a registered adder tree of three levels: it
uses the velocity of three clocks before. The output is OUTPUT_DELAY = 3 clocks after
pos_hyb.

fine_pos = floor((pos_hyb + fraction) * 2^F) modulo 2^(N + 2 + F): the datasheet's
h = floor(4 theta) with F more bits, so its top N + 2 bits are the quarter. The outputs
are registered (one cycle).
"""

from __future__ import annotations

from .velocity import FRAC, LEAD_LIMIT

OFFSET_FRAC = 24   # the offset input: 2^-24 quarter
STEP_DELAY = 3     # decoder step -> the cycle before pos_hyb shows it (prenc_position: 4)
OUTPUT_DELAY = 3   # pos_hyb -> fine_pos
TREE_DELAY = 3     # velocity -> velocity x LOOKAHEAD_HALVES


class FinePosition:
    def __init__(self, n: int = 10, fine_bits: int = 8, lookahead_halves: int = 0):
        if not 0 <= fine_bits <= 8:
            raise ValueError(f"fine_bits = {fine_bits} is out of range 0..8")
        if not 0 <= lookahead_halves <= 255:
            raise ValueError(f"lookahead_halves = {lookahead_halves} is out of range 0..255")
        self.n = n
        self.fine_bits = fine_bits
        self.lookahead_halves = lookahead_halves
        self.width = n + 2 + fine_bits
        self.reset()

    def reset(self) -> None:
        self.step_d = [0] * STEP_DELAY
        self.cw_d = [1] * STEP_DELAY
        self.travel = 0
        self.cw = 1
        self.tree = [0] * TREE_DELAY                 # velocity x LOOKAHEAD_HALVES, in flight
        self.a = (0, 0, 0, 0, 1 << (FRAC - 1))       # stage A: fraction, pos_hyb, valid,
                                                     # velocity_valid, the quarter's middle
        self.b = (0, 0, 0, 0, 1 << (FRAC - 1))       # stage B: fraction + extrapolation, ...
        self.fine_pos = 0
        self.valid = 0
        self.interpolated = 0

    def clock(self, pos_hyb: int, pos_valid: int, step: int, step_cw: int, velocity: int,
              velocity_valid: int, rst: int = 0, c_lo: int = 0, c_hi: int = 0,
              offset: int = 0, offset_valid: int = 0) -> None:
        """c_lo, c_hi: with a calibration table, the corrections of pos_hyb's quarter's
        lower and upper edge (FRAC bits): the quarter really spans
        [pos_hyb + c_lo, pos_hyb + 1 + c_hi).
        offset, offset_valid: a tracking filter's position past the last edge crossed
        (2^-OFFSET_FRAC quarter), as of the step this block takes this cycle (its
        step input STEP_DELAY cycles before): travel takes it while offset_valid."""
        if rst:
            self.reset()
            return
        f = self.fine_bits
        mask = (1 << self.width) - 1
        # Stage C: the output.
        sum_b, pos_b, valid_b, vv_b, mid_b = self.b
        fraction = (sum_b if vv_b else mid_b) >> (FRAC - f)
        self.fine_pos = ((pos_b << f) + fraction) & mask
        self.valid, self.interpolated = valid_b, int(valid_b and vv_b)
        # Stage B: the fraction and the extrapolation.
        frac_a, pos_a, valid_a, vv_a, mid_a = self.a
        self.b = (frac_a + (self.tree[-1] >> 1), pos_a, valid_a, vv_a, mid_a)
        # Stage A: the fraction clamped to the quarter.
        top = (1 << FRAC) + c_hi
        edge = c_lo if self.cw else top
        frac = max(c_lo, min(top - 1, edge + self.travel))
        self.a = (frac, pos_hyb, pos_valid, velocity_valid, (c_lo + top) >> 1)
        self.tree = [velocity * self.lookahead_halves] + self.tree[:-1]
        if self.step_d[-1]:
            self.cw = self.cw_d[-1]
        if offset_valid:
            self.travel = offset << (FRAC - OFFSET_FRAC)
        elif self.step_d[-1]:
            self.travel = 0
        elif abs(self.travel) < LEAD_LIMIT:   # (the test on the register: no long path)
            self.travel += velocity
        self.step_d = [step] + self.step_d[:-1]
        self.cw_d = [step_cw] + self.cw_d[:-1]
