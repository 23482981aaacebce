# SPDX-License-Identifier: Apache-2.0
"""The velocity's program: what prenc_velocity's engine (prenc.fine.engine) runs.

The estimator, in the engine's words (docs/fine.md):

- A window runs from a step (its anchor) to the next step if that one is at least
  WINDOW / 2 clocks later (a slow disc: a window of one quarter, so that an
  acceleration shows at the next edge), else to the first step at least WINDOW clocks
  later: N1 (the distance between the two edges' true places, 2^-12 quarter) in P1
  clocks. Its mean speed V1 = N1 / P1 (2^-32 quarter per clock).
- With EDGE_TOLERANCE (edges off the places the velocity takes them at by up to about
  that much: a printed disc without its table, or a noisy sensor), a window is whole
  cycles: it closes at the
  first step at least 3.5 quarters from its anchor (4 quarters, so that A's and B's
  duty cycles and phase cancel) if that is at least WINDOW / 2 clocks later, else at
  the first step at least WINDOW clocks later that is whole cycles from it.
- The constant-speed test: |V1 - S| < 2 (S + 2 DELTA) / P1, S the speed as it is,
  DELTA an edge's residual error with a calibration table, and EDGE_TOLERANCE. A
  window's mean is off by less than (S + 2 DELTA) / P1 (a clock's quantization at
  each end, DELTA at each edge); twice that leaves room for the speed's own error.
  - Passed: S <- S + (V1 - S) / 2^RUN_SHIFT, acceleration 0: the speed is a running
    mean of the windows, so a steady speed reads the mean of many. With a table and
    EDGE_TOLERANCE (the edges' error is then the sensors' noise, new at every pass) the
    weight is 1/2^RUN_SHIFT_SETTLED once SETTLED windows in a row have passed without a
    trend (more than TREND in a row on one side of S: a ripple, a slow ramp). The first
    window that passes after the speed changed (a failed test) weighs 1/2: S <- (S +
    V1) / 2. S after a change is one window's mean, or two's, off by up to the test's
    bound; at 1/8 alone the speed took up to 11 windows to come within 0.05 % after a
    ramp ended (the STALE flag: a window has passed since the change).
  - Failed, but the last two windows agree with each other within the same bound: the
    speed is constant again (an acceleration ended, or the last fit was off): S <- (V1 +
    V2) / 2, acceleration 0.
  - Else the speed changed, and how depends on the windows before (UPS, DOWNS: how many
    changed the same way, up to 2). V1 and the last window's V2 are the speeds at their
    middles, (P1 + P2) / 2 clocks apart: the fit's acceleration a = 2 (V1 - V2) / (P1 +
    P2) (2^-32 quarter per clock^2), its speed V1 + a (P1 / 2 + LATENCY): P1 / 2 from
    the window's middle to its closing step, LATENCY from that step to the load, which
    the program waits for, exactly.
    - The first change: S <- V1, acceleration 0.
    - The second: the fit's speed, acceleration 0 (HOLD).
    - The third and on: the fit, and its acceleration A (per K = 64 clocks) from then
      on: the hardware makes one update due every K clocks (TICK, restarted at K / 2
      by the load, so that each update shows the speed of its K clocks' middle), and
      the program adds A to S for each (the idle loop, or between a window's divisions
      once V1 is stored), stopping at 0.
    A step of speed (at once) changes two windows at most, the one it falls in and the
    next, so it is never integrated: until the window after them agrees, the speed is
    between the two speeds widened by the second change's extrapolation: at most that
    change, so at most the step, where WINDOW >= 4 LATENCY = 1024 (P2 >= WINDOW / 2).
  - The first window after a start: S <- V1.
- Overdue: the engine divides LEVEL (the quarter's true width and a quarter, and
  four times EDGE_TOLERANCE: each of its two edges may be off by the print's
  tolerance, of which EDGE_TOLERANCE is about 0.6) by the
  clocks since the last step, whenever it has nothing else to do. The disc has turned
  less than LEVEL since that step, so its mean speed is below the quotient: the speed
  is bounded by it (acceleration 0). Half as long again without a step is a stop: 0.
  The first bound comes 1.25 edge periods after the last step, the stop 1.9 periods
  after it: a disc that stops reads 0 within two of its edge periods where these are
  long against the engine's own pace (a division and the updates between its checks:
  a dead stop reads 0 within two edge periods and 200 clocks), and one whose speed
  falls to half or less
  at once reads 0 until the first window after its next edge (the speed is below the
  bound, 0.67 of the last, all the while). A due update ends the bound's division
  (DIV abortable); its 35 steps on operands that come LEVEL_SHIFT bits up fit between
  two ticks, so a disc that stops during a ramp is bounded and then stopped.
- The output: every OUT VELOCITY shows the accumulator, which SIGN has negated unless
  the last step was CW: the velocity is 0 or has the sign of the last step.
- The first step after a start (reset, a reversal, an illegal transition, a stop) is
  the anchor of the first window.
- A step is held (its clock and its edge's place: STIME, SPOSC) from the clock it comes
  until the program is done with it (DONE); the steps in between are counted but not
  held. LTIME and LWIDTH are the last step's clock and the width of the quarter it
  entered, held or not.
"""

from __future__ import annotations

from .engine import CONDITIONS, FLAGS, OUT_KINDS, SPECIALS, Instruction

CAL_FRAC = 12          # N1, the table's corrections, LEVEL: 2^-12 quarter
V_FRAC = 32            # speeds: 2^-32 quarter per clock
A_FRAC = 32            # the acceleration: 2^-32 quarter per clock^2
LATENCY = 256          # a fitted speed shows LATENCY clocks after its closing step
RUN_SHIFT = 3          # the running mean's weight: 1/8
RUN_SHIFT_SETTLED = 5  # ... after SETTLED windows passed without a trend: 1/32
SETTLED = 16
TREND = 6              # with a table and EDGE_TOLERANCE: more in a row on one side of S
LEVEL_0 = (5 << CAL_FRAC) // 4     # an overdue edge: the quarter's width and a quarter
LEVEL_SHIFT = 17       # LEVEL (below 2^14) and the width come 17 bits up: its division 35 steps
DELTA = {0: 0, 1: 1 << (V_FRAC - 10)}   # an edge's residual error with a table: 2^-10 quarter
OLD = 1 << 30          # an anchor older than this (clocks) is dropped
K = 64                 # the speed integrates the acceleration every K clocks (A: per K clocks)

# The register file: the constants first (initial values), then the variables.
RF = ("C_ZERO", "C_WINDOW", "C_SHORT", "C_QUARTERS", "C_LEVEL0", "C_2DELTA", "C_LATENCY",
      "C_OLD", "C_ONE", "C_TWO", "C_CYCLE", "C_SETTLED", "C_TREND",
      "W_TIME", "W_POSC", "V1", "V2", "UPS", "DOWNS", "P1", "P2", "T0", "T1", "T2",
      "STOP_AT", "RUNS", "UP_LEFT", "DOWN_LEFT", "S", "A")
QUARTERS = (3 << CAL_FRAC) // 2        # below 1.5 quarters: a window of one quarter
CYCLE = (7 << CAL_FRAC) // 2           # EDGE_TOLERANCE > 0: below 3.5 quarters, no window;
                                       # then below 4.5 (C_QUARTERS 1), a whole cycle


EDGE_TOLERANCE_MAX = 60       # 1/1000 slot: S + 2 DELTA stays below 2^32


def edge_delta(edge_tolerance: int) -> int:
    """EDGE_TOLERANCE (1/1000 slot) as an edge's error, 2^-12 quarter (rounded)."""
    return (edge_tolerance * (4 << CAL_FRAC) + 500) // 1000


def constants(window: int, cal: int, edge_tolerance: int = 0) -> dict[int, int]:
    """The register file's constants. `edge_tolerance` (1/1000 slot): how far the edges
    may be off the places the velocity takes them at (the nominal ones; with a table,
    the table's: then the sensors' noise). The windows are whole cycles (C_CYCLE), the
    test allows that much more error at each edge (C_2DELTA), and an overdue edge waits
    for a quarter four times that much wider (C_LEVEL0: its two edges, each off by up to
    the print's tolerance, about 1.6 EDGE_TOLERANCE). With a table too, the running mean weighs
    1/2^RUN_SHIFT_SETTLED after C_SETTLED windows without a trend of C_TREND; else
    C_TREND is 0 and every window is a trend."""
    if not 0 <= edge_tolerance <= EDGE_TOLERANCE_MAX:
        raise ValueError(f"edge_tolerance = {edge_tolerance} is out of range 0..{EDGE_TOLERANCE_MAX}")
    edge = edge_delta(edge_tolerance)
    cycles = edge_tolerance > 0
    values = {"C_ZERO": 0, "C_WINDOW": window, "C_SHORT": window // 2,
              "C_QUARTERS": (1 << CAL_FRAC) if cycles else QUARTERS, "C_LEVEL0": (LEVEL_0 + 4 * edge) << LEVEL_SHIFT,
              "C_2DELTA": 2 * DELTA[cal] + (2 * edge << (V_FRAC - CAL_FRAC)), "C_LATENCY": LATENCY,
              "C_OLD": OLD, "C_ONE": 1, "C_TWO": 2, "C_CYCLE": CYCLE if cycles else 0,
              "C_SETTLED": SETTLED, "C_TREND": TREND if (cal and cycles) else 0}
    return {RF.index(name): value for name, value in values.items()}


# The program, as (label, op, argument, argument): an argument is an RF word, a special
# (s.NAME), a flag, an out kind, a condition, a count or a label.
WRITTEN = [
    # Nothing pending: bound the speed by an overdue edge, stop, or drop an old anchor.
    ("IDLE", "JMP", "PEND", "STEP"),
    (None, "JMP", "DUE", "UPDATE"),
    ("CHECKS", "JMP", "HAVE", "AGE"),
    (None, "JMP", "NOT_ANCH", "IDLE"),
    (None, "LOAD", "s.NOW"),
    (None, "SUB", "W_TIME"),
    (None, "SUB", "C_OLD"),
    (None, "JMP", "NEG", "IDLE"),
    (None, "FLAG", "ANCH", 0),
    (None, "JMP", "ALWAYS", "IDLE"),
    ("AGE", "LOAD", "s.NOW"),
    (None, "SUB", "s.LTIME"),
    (None, "STORE", "T1"),                 # clocks since the last step
    (None, "JMP", "NOT_BND", "BOUND"),
    (None, "SUB", "STOP_AT"),
    (None, "JMP", "NOT_NEG", "STOP"),
    ("BOUND", "LOAD", "s.LWIDTH"),         # LEVEL: the quarter's width and a quarter
    (None, "ADD", "C_LEVEL0"),
    (None, "NUM"),
    (None, "DIV", "T1", 52 - LEVEL_SHIFT, "abortable"),  # LEVEL / since, 2^-32 quarter per clock
    (None, "QUOT"),
    (None, "SUB", "S"),
    (None, "JMP", "NOT_NEG", "IDLE"),      # not overdue
    (None, "ADD", "S"),
    (None, "STORE", "S"),
    (None, "FLAG", "ACCEL", 0),
    (None, "SIGN", "C_ONE"),
    (None, "OUT", "VELOCITY"),
    (None, "JMP", "BND", "IDLE"),
    (None, "FLAG", "BND", 1),              # the first bound: a stop at 1.5 times since
    (None, "LOAD", "T1"),
    (None, "HALF", 1),
    (None, "ADD", "T1"),
    (None, "STORE", "STOP_AT"),
    (None, "JMP", "ALWAYS", "IDLE"),
    ("STOP", "LOAD", "C_ZERO"),
    (None, "OUT", "VELOCITY"),
    (None, "JMP", "ALWAYS", "RESTART"),
    # An update is due (ACCEL, every K clocks): S <- S + A, shown.
    ("UPDATE", "LOAD", "S"),
    (None, "ADD", "A"),
    (None, "JMP", "NEG", "HALT"),          # through 0 (or out of range): it stops at 0
    (None, "STORE", "S"),
    (None, "SIGN", "C_ONE"),
    (None, "OUT", "VELOCITY"),
    (None, "FLAG", "TICK", 0),
    (None, "JMP", "ALWAYS", "IDLE"),       # (and again, while K clocks are due)
    ("HALT", "LOAD", "C_ZERO"),
    (None, "STORE", "S"),
    (None, "FLAG", "ACCEL", 0),
    (None, "OUT", "VELOCITY"),
    (None, "JMP", "ALWAYS", "CHECKS"),
    # A step (held until DONE): the quarter's LEVEL, then a window's close or its anchor.
    ("STEP", "FLAG", "BND", 0),
    (None, "JMP", "NOT_ANCH", "ANCHOR"),
    (None, "LOAD", "s.STIME"),
    (None, "SUB", "W_TIME"),
    (None, "STORE", "P1"),
    (None, "SUB", "C_SHORT"),
    (None, "JMP", "NEG", "DONE"),          # shorter than WINDOW / 2: the window goes on
    (None, "LOAD", "s.SPOSC"),
    (None, "SUB", "W_POSC"),
    (None, "STORE", "T1"),                 # N1
    (None, "JMP", "NEG", "ANCHOR"),        # (a table that runs backwards: no window)
    (None, "SUB", "C_CYCLE"),              # (EDGE_TOLERANCE > 0: fewer than a cycle's
    (None, "JMP", "NEG", "DONE"),          # quarters: the window goes on)
    (None, "SUB", "C_QUARTERS"),
    (None, "JMP", "NEG", "CLOSE"),         # one quarter: it closes
    (None, "LOAD", "P1"),
    (None, "SUB", "C_WINDOW"),
    (None, "JMP", "NEG", "DONE"),          # more quarters: at WINDOW clocks
    (None, "LOAD", "C_ZERO"),
    (None, "SUB", "C_CYCLE"),
    (None, "JMP", "NOT_NEG", "CLOSE"),     # (EDGE_TOLERANCE > 0: and whole cycles:
    (None, "LOAD", "T1"),
    (None, "HALF", CAL_FRAC),
    (None, "STORE", "T0"),                 # the window's quarters A,
    (None, "HALF", 2),
    (None, "STORE", "T2"),                 # its cycles B = A / 4
    (None, "SUB", "T0"),
    (None, "ADD", "T2"),
    (None, "ADD", "T2"),
    (None, "ADD", "T2"),                   # 4 B - A
    (None, "JMP", "NEG", "DONE"),          # below 0: not whole, the window goes on)
    ("CLOSE", "LOAD", "s.STIME"),          # this step anchors the next window
    (None, "STORE", "W_TIME"),
    (None, "LOAD", "s.SPOSC"),
    (None, "STORE", "W_POSC"),
    (None, "LOAD", "T1"),
    (None, "NUM"),
    (None, "DIV", "P1", 52),               # V1 = N1 / P1
    (None, "QUOT"),
    (None, "STORE", "V1"),
    (None, "JMP", "NOT_DUE", "CLOSED"),     # an update due: taken here, where ACC is free
    (None, "LOAD", "S"),
    (None, "ADD", "A"),
    (None, "JMP", "NEG", "CLOSED"),         # (through 0: left to the idle loop)
    (None, "STORE", "S"),
    (None, "SIGN", "C_ONE"),
    (None, "OUT", "VELOCITY"),
    (None, "FLAG", "TICK", 0),
    ("CLOSED", "JMP", "NOT_HAVE", "FIRST"),
    # The test: |V1 - S| < 2 (S + 2 DELTA) / P1, as |V1 - S| / 2 < (S + 2 DELTA) / P1.
    (None, "LOAD", "S"),
    (None, "ADD", "C_2DELTA"),
    (None, "NUM"),
    (None, "DIV", "P1", 32),
    (None, "QUOT"),
    (None, "STORE", "T0"),
    (None, "LOAD", "V1"),
    (None, "SUB", "S"),
    (None, "HALF", 1),
    (None, "STORE", "T1"),                 # (V1 - S) / 2, for the running mean
    (None, "JMP", "NEG", "BELOW"),
    (None, "SUB", "T0"),
    (None, "JMP", "NOT_NEG", "AGREE"),
    # Passed. UP_LEFT, DOWN_LEFT: how many more windows in a row above (below) S are not
    # yet a trend; a window on the other side sets them to C_TREND. A trend (a ripple, a
    # slow ramp: more than C_TREND in a row) restarts RUNS, the windows passed without
    # one still to go (from C_SETTLED) before the running mean's weight is
    # 1/2^RUN_SHIFT_SETTLED instead of 1/2^RUN_SHIFT. C_TREND is 0 without a table and
    # EDGE_TOLERANCE: every window is a trend, the weight always 1/2^RUN_SHIFT.
    (None, "LOAD", "C_TREND"),             # above S
    (None, "STORE", "DOWN_LEFT"),
    (None, "LOAD", "UP_LEFT"),
    (None, "SUB", "C_ONE"),
    (None, "JMP", "NEG", "TREND"),
    (None, "STORE", "UP_LEFT"),
    (None, "JMP", "ALWAYS", "COUNT"),
    ("BELOW", "ADD", "T0"),
    (None, "JMP", "NEG", "AGREE"),
    (None, "LOAD", "C_TREND"),             # below S
    (None, "STORE", "UP_LEFT"),
    (None, "LOAD", "DOWN_LEFT"),
    (None, "SUB", "C_ONE"),
    (None, "JMP", "NEG", "TREND"),
    (None, "STORE", "DOWN_LEFT"),
    ("COUNT", "LOAD", "RUNS"),
    (None, "SUB", "C_ONE"),
    (None, "JMP", "NEG", "SETTLED"),       # (RUNS stays 0)
    ("COUNTED", "STORE", "RUNS"),
    (None, "LOAD", "T1"),                  # S + (V1 - S) / 2^RUN_SHIFT
    (None, "JMP", "NOT_STALE", "FRESH"),   # (the first since a change: S + (V1 - S) / 2)
    (None, "HALF", RUN_SHIFT - 1),
    (None, "JMP", "ALWAYS", "MEAN"),
    ("TREND", "LOAD", "C_SETTLED"),
    (None, "JMP", "ALWAYS", "COUNTED"),
    ("SETTLED", "LOAD", "T1"),             # S + (V1 - S) / 2^RUN_SHIFT_SETTLED
    (None, "HALF", RUN_SHIFT_SETTLED - 1),
    ("FRESH", "FLAG", "STALE", 1),         # (SETTLED: set already)
    ("MEAN", "ADD", "S"),
    (None, "STORE", "S"),
    (None, "FLAG", "ACCEL", 0),
    (None, "SIGN", "C_ONE"),
    (None, "OUT", "VELOCITY"),
    ("STEADY", "LOAD", "C_ZERO"),          # no run of changes
    (None, "STORE", "UPS"),
    (None, "STORE", "DOWNS"),
    (None, "JMP", "ALWAYS", "NEXT"),
    # Failed: do the last two windows agree with each other (|V1 - V2| / 2 < T0)? Then
    # the speed is constant again: S <- (V1 + V2) / 2, acceleration 0. Else the fit.
    ("AGREE", "FLAG", "STALE", 0),         # the speed changes
    (None, "LOAD", "C_SETTLED"),           # RUNS restarts
    (None, "STORE", "RUNS"),
    (None, "LOAD", "V1"),
    (None, "SUB", "V2"),
    (None, "HALF", 1),
    (None, "JMP", "NEG", "BELOW_V2"),
    (None, "SUB", "T0"),
    (None, "JMP", "NOT_NEG", "FIT"),
    (None, "JMP", "ALWAYS", "AGREED"),
    ("BELOW_V2", "ADD", "T0"),
    (None, "JMP", "NEG", "FIT"),
    ("AGREED", "LOAD", "V1"),
    (None, "ADD", "V2"),
    (None, "HALF", 1),
    (None, "STORE", "S"),
    (None, "FLAG", "ACCEL", 0),
    (None, "SIGN", "C_ONE"),
    (None, "OUT", "VELOCITY"),
    (None, "JMP", "ALWAYS", "STEADY"),
    # V1 changed from V2 (UPS, DOWNS: the windows before that changed the same way, up
    # to 2). The first change: S <- V1, acceleration 0. The second: the fit's speed, but
    # acceleration 0 (HOLD < 0). The third and on: the fit. (A step of speed changes
    # two windows at most, the one it falls in and the next: the second change of a step
    # overshoots by the fit's extrapolation alone, not its integration.)
    # The fit: a = 2 (V1 - V2) / (P1 + P2), S <- V1 + a (P1 / 2 + LATENCY).
    ("FIT", "LOAD", "P1"),
    (None, "ADD", "P2"),
    (None, "STORE", "T1"),
    (None, "LOAD", "V1"),
    (None, "SUB", "V2"),
    (None, "JMP", "NEG", "SLOWER"),
    (None, "LOAD", "C_ZERO"),
    (None, "STORE", "DOWNS"),
    (None, "LOAD", "UPS"),
    (None, "SUB", "C_ONE"),
    (None, "JMP", "NEG", "FIRST_UP"),
    (None, "SUB", "C_ONE"),
    (None, "STORE", "T2"),                 # HOLD: UPS - 2
    (None, "LOAD", "C_TWO"),
    (None, "STORE", "UPS"),
    (None, "LOAD", "V1"),
    (None, "SUB", "V2"),
    (None, "NUM"),
    (None, "DIV", "T1", 39),               # 2 |V1 - V2| K / (P1 + P2)
    (None, "QUOT"),
    (None, "STORE", "T0"),                 # the acceleration per K clocks
    (None, "HALF", 6),                     # a
    (None, "JMP", "ALWAYS", "EXTRAPOLATE"),
    ("FIRST_UP", "LOAD", "C_ONE"),
    (None, "STORE", "UPS"),
    (None, "JMP", "ALWAYS", "JUMPED"),
    ("SLOWER", "LOAD", "C_ZERO"),
    (None, "STORE", "UPS"),
    (None, "LOAD", "DOWNS"),
    (None, "SUB", "C_ONE"),
    (None, "JMP", "NEG", "FIRST_DOWN"),
    (None, "SUB", "C_ONE"),
    (None, "STORE", "T2"),                 # HOLD: DOWNS - 2
    (None, "LOAD", "C_TWO"),
    (None, "STORE", "DOWNS"),
    (None, "LOAD", "V2"),
    (None, "SUB", "V1"),
    (None, "NUM"),
    (None, "DIV", "T1", 39),
    (None, "QUOT"),
    (None, "STORE", "T0"),
    (None, "HALF", 6),
    (None, "STORE", "T1"),                 # |a|
    (None, "LOAD", "C_ZERO"),
    (None, "SUB", "T0"),
    (None, "STORE", "T0"),                 # the acceleration per K clocks, signed
    (None, "LOAD", "C_ZERO"),
    (None, "SUB", "T1"),                   # a, signed
    ("EXTRAPOLATE", "STORE", "T1"),        # (ACC: a)
    (None, "LOAD", "P1"),
    (None, "HALF", 1),
    (None, "ADD", "C_LATENCY"),
    (None, "NUM"),
    (None, "MUL", "T1", 32),               # a (P1 / 2 + LATENCY)
    (None, "ADD", "V1"),
    (None, "STORE", "T1"),                 # the speed to load
    (None, "LOAD", "T2"),                  # HOLD
    (None, "JMP", "NOT_NEG", "WAIT"),
    (None, "LOAD", "C_ZERO"),              # the second change of a run: no acceleration
    (None, "STORE", "T0"),
    # Wait for the load's clock: LATENCY after the closing step.
    ("WAIT", "LOAD", "T1"),
    (None, "JMP", "NEG", "ZERO"),          # decelerated through 0
    (None, "WAIT", LATENCY - 4),           # the output shows it LATENCY after the step
    (None, "STORE", "S"),
    (None, "SIGN", "C_ONE"),
    (None, "OUT", "VELOCITY"),
    (None, "LOAD", "T0"),
    (None, "STORE", "A"),
    (None, "FLAG", "TICK", 1),
    (None, "FLAG", "ACCEL", 1),
    (None, "JMP", "ALWAYS", "NEXT"),
    ("ZERO", "LOAD", "C_ZERO"),
    (None, "STORE", "S"),
    (None, "FLAG", "ACCEL", 0),
    (None, "OUT", "VELOCITY"),
    (None, "JMP", "ALWAYS", "NEXT"),
    ("FIRST", "LOAD", "C_SETTLED"),
    (None, "STORE", "RUNS"),
    (None, "LOAD", "C_ZERO"),
    (None, "STORE", "UPS"),
    (None, "STORE", "DOWNS"),
    (None, "FLAG", "HAVE", 1),
    ("FIRST_DOWN", "LOAD", "C_ONE"),
    (None, "STORE", "DOWNS"),
    ("JUMPED", "LOAD", "V1"),
    (None, "STORE", "S"),
    (None, "FLAG", "ACCEL", 0),
    (None, "SIGN", "C_ONE"),
    (None, "OUT", "VELOCITY"),
    ("NEXT", "LOAD", "V1"),                # the last window, for the next fit
    (None, "STORE", "V2"),
    (None, "LOAD", "P1"),
    (None, "STORE", "P2"),
    (None, "JMP", "ALWAYS", "DONE"),
    ("ANCHOR", "LOAD", "s.STIME"),
    (None, "STORE", "W_TIME"),
    (None, "LOAD", "s.SPOSC"),
    (None, "STORE", "W_POSC"),
    (None, "FLAG", "ANCH", 1),
    (None, "FLAG", "HAVE", 0),
    ("DONE", "DONE"),                      # the next step is captured from now on
    (None, "JMP", "ALWAYS", "IDLE"),
    # A restart (reset, a reversal, an illegal transition): the output is 0 already.
    ("RESTART", "STORE", "S"),             # (ACC 0)
    (None, "FLAG", "ACCEL", 0),
    (None, "FLAG", "ANCH", 0),
    (None, "FLAG", "HAVE", 0),
    (None, "FLAG", "BND", 0),
    (None, "JMP", "ALWAYS", "IDLE"),
]


def reads_operand(row) -> bool:
    op, *args = row[1:]
    return op in ("LOAD", "ADD", "SUB", "DIV", "MUL", "SIGN")


def with_landings(written) -> list[tuple]:
    """The program as written, with a NOP before each labelled instruction that reads an
    operand: an operand is fetched while the instruction before it in the program runs,
    so where a jump lands there must be one clock that reads none (prenc.fine.engine)."""
    out = []
    for row in written:
        if row[0] and reads_operand(row):
            out.append((row[0], "NOP"))
            row = (None, *row[1:])
        out.append(row)
    return out


SOURCE = with_landings(WRITTEN)


def assemble(source=SOURCE) -> list[Instruction]:
    labels = {row[0]: k for k, row in enumerate(source) if row[0]}
    program = []
    for row in source:
        _, op, *args = row
        a, n, special, abortable = 0, 0, False, "abortable" in args
        args = [x for x in args if x != "abortable"]
        if op == "HALF":
            n = args[0]
        elif op in ("LOAD", "ADD", "SUB", "STORE", "DIV", "MUL", "SIGN"):
            name = args[0]
            if name.startswith("s."):
                a, special = SPECIALS.index(name[2:]), True
            else:
                a = RF.index(name)
            if op in ("DIV", "MUL"):
                n = args[1]
        elif op == "OUT":
            a = OUT_KINDS.index(args[0])
        elif op == "FLAG":
            a, n = FLAGS.index(args[0]), args[1]
        elif op == "WAIT":
            n = args[0]
        elif op == "JMP":
            a, n = CONDITIONS.index(args[0]), labels[args[1]]
        program.append(Instruction(op, a, n, special, abortable))
    return program


PROGRAM = assemble()
RESTART = next(k for k, row in enumerate(SOURCE) if row[0] == "RESTART")

# The program as the RTL's ROM: rtl/fine/prenc_velocity_program.v, written by
# `python -m prenc.fine.program` (a test checks it is up to date). A word also holds the
# operand of the instruction after it in the program (a special's number, or the
# register file's address), which the RTL fetches while it runs.
WORD_BITS = 31   # the adder's controls 5, op 4, special 1, abortable 1, a 5, n 9, next (s 1, a 5)
PC_BITS = 9      # 512 words
ADDER_CONTROLS = {"step": ("DIV", "MUL"), "invert": ("SUB", "DIV", "SIGN"), "mul": ("MUL",),
                  "load": ("LOAD",), "quot": ("QUOT",)}


def read_address(ins: Instruction) -> int:
    """The operand the RTL fetches for `ins`: its special's number, or the register
    file's address it reads (0 if none); the RTL reads both at that number."""
    if ins.special:
        return ins.a
    r = ins.reads()
    return 0 if r is None else r


def encode(k: int, program=PROGRAM) -> int:
    from .engine import OPS

    ins = program[k]
    if not 0 <= ins.n < (1 << PC_BITS) or not 0 <= ins.a < 32:
        raise ValueError(f"{ins}: a field out of range")
    following = program[k + 1] if k + 1 < len(program) else Instruction("NOP")
    next_a = (int(following.special) << 5) | read_address(following)
    controls = sum(int(ins.op in ops) << b for b, ops in enumerate(reversed(ADDER_CONTROLS.values())))
    return (controls << 26) | (OPS.index(ins.op) << 22) | (int(ins.special) << 21) | \
        (int(ins.abortable) << 20) | (ins.a << 15) | (ins.n << 6) | next_a


def rom_verilog(program=PROGRAM, source=SOURCE) -> str:
    """The ROM module (block RAM, read on the clock), one instruction a line with its
    source as a comment."""
    lines = [
        "// SPDX-License-Identifier: Apache-2.0",
        "// prenc_velocity_program: prenc_velocity's program in block RAM, a word a clock:",
        "// {step, invert, mul, load, quot, op[3:0], special, abortable, a[4:0], n[8:0], next_s,",
        "// next_a[4:0]} (prenc.fine.engine, prenc.fine.program; docs/fine.md). step, invert,",
        "// mul, load, quot: the adder's controls, decoded here (DIV or MUL; SUB, DIV or SIGN;",
        "// MUL; LOAD; QUOT: the quotient through the adder, plus RF[0], which is 0).",
        "// next_s, next_a: the operand of the instruction after it in the program (a special",
        "// and its number, or the register file's address).",
        "//",
        "// Latency: word is the instruction at pc of the clock before (one clock).",
        "//",
        "// Written by `python -m prenc.fine.program` from sim/prenc/fine/program.py; do not edit.",
        "`resetall",
        "`timescale 1ns / 1ps",
        "`default_nettype none",
        "",
        "module prenc_velocity_program (",
        "  input  wire        clk,",
        f"  input  wire [{PC_BITS - 1}:0]  pc,",
        f"  output reg  [{WORD_BITS - 1}:0] word,      // the word at pc, a clock later",
        f"  output wire [{PC_BITS - 1}:0]  restart    // where a restart goes",
        ");",
        "",
        f"  reg [{WORD_BITS - 1}:0] rom [0:{(1 << PC_BITS) - 1}];",
        "",
        f"  assign restart = {PC_BITS}'d{RESTART};",
        "",
        "  integer i;",
        "  initial begin",
        f"    for (i = 0; i < {1 << PC_BITS}; i = i + 1) rom[i] = {WORD_BITS}'d0;",
    ]
    for k, row in enumerate(source):
        label = f"{row[0]}: " if row[0] else ""
        text = " ".join(str(x) for x in row[1:])
        lines.append(f"    rom[{k}] = {WORD_BITS}'h{encode(k, program):08x};   // {label}{text}")
    lines += [
        "  end",
        "",
        "  always @(posedge clk) begin",
        "    word <= rom[pc];",
        "  end",
        "",
        "endmodule",
        "",
        "`resetall",
        "",
    ]
    return "\n".join(lines)


if __name__ == "__main__":
    print(rom_verilog(), end="")
