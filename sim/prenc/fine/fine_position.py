# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/fine/prenc_fine_position.v: the verified position with the fraction of
the quarter passed, extrapolated to the instant a consumer asks.

Inputs each cycle: the core's pos_hyb and pos_valid; the quadrature decoder's
registered step and step_cw (delayed STEP_DELAY cycles, so that the step meets pos_hyb,
which shows it 4 cycles after the decoder); the velocity and its valid flag
(prenc_velocity: quarters per clock, V_FRAC = 32 fractional bits).

- travel: the velocity integrated since pos_hyb's last step (Q2.32; it stops once it is
  2 quarters or more, past any clamp below). It starts at 0: the fraction starts at the
  crossed edge. With PHASE_FILTER (prenc_fine: EDGE_TOLERANCE > 0, edges that are off
  their places), after a step in the same direction as the last it starts at 3/4 of
  where the travel said the disc is against the crossed edge (edge + travel + velocity
  - the crossed edge, unclamped; 0 if that is half a quarter or more): the phase is a
  running mean of the edges' (1/4 of each new edge), so an edge's own error or noise
  moves it a quarter as much.
- The fraction of the quarter: the last step crossed the quarter's lower edge (CW) or
  its upper edge (CCW); fraction = clamp(edge + travel) to the quarter, [0, 1) or, with
  a calibration table, its true span [c_lo, 1 + c_hi). So while pos_valid the fine
  position's quarter is pos_hyb's (the table's span with CAL): when the next edge is
  late, the fraction holds at the quarter's end. It is kept to FRAC = 16 bits.
- The extrapolation over the pipeline: + velocity x LOOKAHEAD_HALVES / 2 (the clocks
  from the pins to this block's output, and half a clock for the edge's unknown place
  within its clock), from the velocity to 2^-16 (its registered product is the velocity
  of the clock before). It is the only way the fine position leaves the verified
  quarter, by at most |velocity| x LOOKAHEAD_HALVES / 2 quarters. LOOKAHEAD_HALVES = 0
  turns it off.
- Without a valid velocity: the fraction is the quarter's middle, nothing extrapolated,
  and `interpolated` is 0.

fine_pos = floor((pos_hyb + fraction) x 2^F) modulo 2^(N + 2 + F): the datasheet's
h = floor(4 theta) with F more bits, so its top N + 2 bits are the quarter.

Three register stages, so that no two long carry chains follow each other: (A) the
fraction clamped, with pos_hyb and the flags; (B) the fraction plus the extrapolation;
(C) the output, OUTPUT_DELAY = 3 clocks after pos_hyb.
"""

from __future__ import annotations

V_FRAC = 32        # the velocity and travel: 2^-32 quarter (per clock)
FRAC = 16          # the fraction and the extrapolation: 2^-16 quarter
CAL_FRAC = 12      # the table's corrections: 2^-12 quarter
STEP_DELAY = 3     # decoder step -> the cycle before pos_hyb shows it (prenc_position: 4)
OUTPUT_DELAY = 3   # pos_hyb -> fine_pos
TRAVEL_LIMIT = 2 << V_FRAC   # travel stops once it is 2 quarters
PHASE_SHIFT = 2              # PHASE_FILTER: the phase keeps 1 - 2^-2 of its difference
PHASE_LIMIT = 1 << (V_FRAC - 1)   # ... while that is below half a quarter


class FinePosition:
    def __init__(self, n: int = 10, fine_bits: int = 8, lookahead_halves: int = 0,
                 phase_filter: int = 0):
        if not 0 <= fine_bits <= 8:
            raise ValueError(f"fine_bits = {fine_bits} is out of range 0..8")
        if not 0 <= lookahead_halves <= 255:
            raise ValueError(f"lookahead_halves = {lookahead_halves} is out of range 0..255")
        if phase_filter not in (0, 1):
            raise ValueError(f"phase_filter = {phase_filter} must be 0 or 1")
        self.phase_filter = phase_filter
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
        self.ext = 0                          # velocity x LOOKAHEAD_HALVES, 2^-16 (registered)
        self.a = (0, 0, 0, 0, 1 << (FRAC - 1))   # stage A: fraction, pos_hyb, valid,
                                                 # velocity_valid, the quarter's middle
        self.b = (0, 0, 0, 0, 1 << (FRAC - 1))   # stage B: fraction + extrapolation, ...
        self.fine_pos = 0
        self.valid = 0
        self.interpolated = 0
        self.kept = 0                         # steps whose phase was kept (PHASE_FILTER)

    def clock(self, pos_hyb: int, pos_valid: int, step: int, step_cw: int, velocity: int,
              velocity_valid: int, rst: int = 0, c_lo: int = 0, c_hi: int = 0) -> None:
        """c_lo, c_hi: with a calibration table, the corrections of pos_hyb's quarter's
        lower and upper edge (2^-12 quarter): it spans [pos_hyb + c_lo, pos_hyb + 1 + c_hi)."""
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
        self.b = (frac_a + (self.ext >> 1), pos_a, valid_a, vv_a, mid_a)
        # Stage A: the fraction clamped to the quarter, to 2^-16.
        lo = c_lo << (FRAC - CAL_FRAC)
        hi = (1 << FRAC) + (c_hi << (FRAC - CAL_FRAC))
        edge = lo if self.cw else hi
        frac = max(lo, min(hi - 1, edge + (self.travel >> (V_FRAC - FRAC))))
        self.a = (frac, pos_hyb, pos_valid, velocity_valid, (lo + hi) >> 1)
        self.ext = (velocity >> (V_FRAC - FRAC)) * self.lookahead_halves
        if self.step_d[-1]:
            # The phase against the crossed edge (the travel as it would be this clock).
            e = ((edge - (hi if self.cw else lo)) << (V_FRAC - FRAC)) + self.travel + velocity
            keep = (self.phase_filter and self.cw_d[-1] == self.cw and velocity_valid
                    and abs(e) < PHASE_LIMIT)
            self.travel = e - (e >> PHASE_SHIFT) if keep else 0
            self.kept += int(keep)
            self.cw = self.cw_d[-1]
        elif abs(self.travel) < TRAVEL_LIMIT:   # (the test on the register: no long path)
            self.travel += velocity
        self.step_d = [step] + self.step_d[:-1]
        self.cw_d = [step_cw] + self.cw_d[:-1]
