# SPDX-License-Identifier: Apache-2.0
"""What a disc's printing and mounting may be off by (`make bench` section 14; the
guide docs/guide/building-the-encoder.md quotes its table).

One imperfection at a time, on the default disc (N = 10) at 30 MHz, FILTER = 2:

- B's phase against A (electrical degrees: 90 is a whole quarter), the duty cycle of A
  and B (the share of a slot each is light), the eccentricity (slots at the tracks'
  radius: the disc turns off-centre by this much);
- the core (its clock-level model, prenc.core.reader.Reader, which the RTL equals clock
  for clock) through a turn one way and 18,000 clocks of reversals at 1/48 slot per clock:
  its share of valid clocks and its wrong valid positions, judged against the position
  the printed disc shows (prenc.virtual.instrument_soak's truth);
- the fine position (the models of rtl/fine/) over a whole turn at 3,000 rpm: its error
  against the true angle, RMS, without a table and with the table that prenc.cal.calibrate
  makes from 10 turns at 70 rpm (less the calibration's zero, as section 10).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..codes.debruijn import Code
from ..core.reader import Reader
from . import fine_bench as fb
from .cal_bench import CAL_RIPPLE, CAL_RPM, CAL_TURNS
from .edge_timing import steady_record, true_corrections
from .goals import FAST, WALK_CLOCKS, reversing
from .instrument_soak import FILTER, Draw, judge_position
from .printing import Printing
from .trajectory import Trajectory

N = fb.N
FINE_RPM = 3000.0

# (what, the printing of each row)
# (what, its value, the printing of the row), as far as prenc.virtual.printing models a
# disc (phase up to 30 degrees, duty 0.3 to 0.7, eccentricity up to 0.3 slot).
ROWS = (
    [("none (the ideal disc)", 0, Printing())]
    + [("B's phase error, degrees", p, Printing(phase_deg=p)) for p in (10, 20, 30)]
    + [("duty cycle of A and B", d, Printing(duty_a=d, duty_b=d)) for d in (0.45, 0.40, 0.35, 0.30)]
    + [("eccentricity, slots", e, Printing(eccentricity=e, eccentricity_phase=0.7)) for e in (0.1, 0.2, 0.3)]
)


@dataclass
class Tolerance:
    what: str
    value: float
    core_valid: float       # share of clocks valid
    core_wrong: int         # wrong valid clocks
    fine_raw: float         # slots RMS, no table
    fine_calibrated: float  # slots RMS, with the table


def core_row(printing: Printing, seed: int = 3) -> tuple[float, int]:
    start = float(np.random.default_rng(seed).uniform(0, 1 << N))
    t = Trajectory(clk_hz=1, start=start).constant(FAST, int((1 << N) / FAST))
    reversing(t, FAST, WALK_CLOCKS, np.random.default_rng(seed + 1))
    theta = t.theta
    speed = np.concatenate([np.diff(theta), [0.0]])
    d = Draw(seed, theta, speed, printing, [], [], "tolerance")
    enc = d.encoder_run()
    outs = Reader(Code(N), FILTER).run(enc)
    valid = np.array([o.valid for o in outs])
    hyb = np.array([o.pos_hyb for o in outs])
    mode = np.array([o.mode for o in outs])
    wrong, _ = judge_position(d, enc, valid, hyb, mode)
    return float(valid.mean()), wrong


def fine_row(printing: Printing) -> tuple[float, float]:
    from ..cal.calibrate import calibrate

    c_true = true_corrections(printing, N)
    record = steady_record(c_true, N, CAL_RPM, CAL_TURNS + 0.1, clk_hz=fb.CLK_HZ, ripple=CAL_RIPPLE[0],
                           ripple_hz=CAL_RIPPLE[1], start_edge=1234, ripple_phase=0.7)
    table = calibrate(record, CAL_TURNS).table.c
    zero = -float(c_true.mean()) / 4
    case = fb.whole_turns_case(FINE_RPM)
    sync = fb.sync_stream(case.theta, printing)
    scale = 1 << fb.FINE_BITS
    out = []
    for t, off in ((None, 0.0), (table, 4 * zero)):
        r = fb.run_fine(sync, table=t)
        out.append(fb.score(case, sync, r["fine"] / scale - off, r["velocity"]).fine[0])
    return out[0], out[1]


def rows() -> list[Tolerance]:
    out = []
    for what, value, printing in ROWS:
        valid, wrong = core_row(printing)
        raw, cal = fine_row(printing)
        out.append(Tolerance(what, value, valid, wrong, raw, cal))
    return out
