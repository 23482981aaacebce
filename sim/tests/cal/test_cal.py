# SPDX-License-Identifier: Apache-2.0
"""Self-calibration (issue 38): the table's file format and its refusals, the
calibration from a run's crossings against the disc's true edges and its refusals,
and the fine blocks' models with a table.

Expected values come from the disc's definition (prenc.virtual.printing, through
prenc.virtual.edge_timing.true_corrections, itself checked here against the clock-level
sync track), never from the code under test."""

from __future__ import annotations

import numpy as np
import pytest

from prenc.cal.calibrate import CalibrationError, Record, calibrate
from prenc.cal.table import FRAC, Table, TableError, parse, read
from prenc.fine.fine import VEL_DELAY
from prenc.fine.fine_position import FinePosition
from prenc.fine.fine_position import CAL_FRAC, V_FRAC
from prenc.virtual import cal_bench as cb
from prenc.virtual import fine_bench as fb
from prenc.virtual.edge_timing import steady_record, true_corrections
from prenc.virtual.printing import Printing
from prenc.virtual.trajectory import Trajectory

N = 6
PRINTED = Printing(edge_error=0.05, phase_deg=10, duty_a=0.45, duty_b=0.55, eccentricity=0.2, seed=5)


@pytest.fixture(scope="module")
def c_true() -> np.ndarray:
    return true_corrections(PRINTED, N)


# -- the virtual disc's edges --------------------------------------------------------

@pytest.mark.parametrize("direction", [1, -1])
def test_true_corrections_are_where_the_sync_track_changes(direction):
    """Every quadrature change of the clock-level sync track (Printing.sync) happens
    between the two clocks whose true angles bracket the edge's (x + c[x]) / 4."""
    n = 8
    c = true_corrections(PRINTED, n)
    theta = Trajectory(30e6, start=10.3).constant(direction * 3000 / 60 * (1 << n), 4e-3).theta
    a, b = PRINTED.sync(theta, 1 << n)
    q = (a.astype(np.int64) << 1) | (1 - (a ^ b))
    changes = np.flatnonzero(q[1:] != q[:-1]) + 1
    assert len(changes) > 100
    quarters = 4 << n
    for k in changes:
        lo, hi = sorted((4 * theta[k - 1], 4 * theta[k]))
        xs = np.arange(int(np.floor(lo)) - 3, int(np.ceil(hi)) + 4)
        at = xs + c[xs % quarters]
        assert np.sum((at >= lo - 1e-9) & (at <= hi + 1e-9)) == 1


def test_an_ideal_disc_needs_no_correction():
    assert not np.any(true_corrections(None, N))
    assert np.allclose(true_corrections(Printing(), N), 0, atol=1e-9)


# -- the file format ------------------------------------------------------------------

def test_table_file_round_trip(tmp_path, c_true):
    table = Table.from_quarters(N, c_true - c_true.mean())
    path = table.write(tmp_path / "disc.cal")
    again = read(path, n=N)
    assert np.array_equal(again.c, table.c)
    assert np.allclose(again.quarters, c_true - c_true.mean(), atol=2.0 ** -FRAC)
    lines = path.read_text().splitlines()
    assert lines[0] == "// prenc calibration table 1" and len(lines) == 5 + (4 << N)
    # $readmemh's words: 4 hex digits each, negative corrections in two's complement.
    assert all(len(w) == 4 for w in lines[5:])


def _text(n=N) -> str:
    return Table.from_quarters(n, np.linspace(-1, 1, 4 << n)).text()


@pytest.mark.parametrize("mangle, message", [
    (lambda t: t.replace("// n 6", "// n 7", 1), "N = 7, the reader has N = 6"),
    (lambda t: t.rsplit("\n", 2)[0] + "\n", "corrections, N = 6 needs"),
    (lambda t: t[:-2] + ("0" if t[-2] != "0" else "1") + "\n", "corrupt"),
    (lambda t: t.replace("// crc32", "// crc33"), "should be '// crc32"),
    (lambda t: "hello\n" + t, "not a prenc calibration table"),
    (lambda t: t.replace("// frac 12", "// frac 8"), "'frac' is 8"),
])
def test_a_bad_table_is_refused(mangle, message):
    with pytest.raises(TableError, match=message):
        parse(mangle(_text()), n=N)


def test_a_table_for_another_disc_or_no_file_is_refused(tmp_path):
    with pytest.raises(TableError, match="N = 6, the reader has N = 10"):
        parse(_text(), n=10)
    with pytest.raises(TableError, match="no such file"):
        read(tmp_path / "missing.cal")
    bad = _text().splitlines()
    bad[5 + 7] = "12x4"
    with pytest.raises(TableError, match="not hex"):
        parse("\n".join(bad))
    with pytest.raises(TableError, match="beyond the format"):
        Table(N, np.full(4 << N, 1 << 15))


# -- calibration ------------------------------------------------------------------------

@pytest.mark.parametrize("rpm, ripple, hz, direction, goal", [
    (70, 0.0, 100, 1, 1e-4),
    (70, 0.02, 100, 1, 1 / 512),
    (650, 0.02, 37, 1, 1 / 128),
    (200, 0.02, 100, -1, 1 / 128),
])
def test_calibration_finds_the_true_edges(c_true, rpm, ripple, hz, direction, goal):
    record = steady_record(c_true, N, rpm, 10.5, ripple=ripple, ripple_hz=hz, start_edge=77,
                           direction=direction, ripple_phase=1.1)
    result = calibrate(record, 10)
    assert result.direction == direction
    err = (result.table.quarters - (c_true - c_true.mean())) / 4
    assert np.sqrt(np.mean(err ** 2)) <= goal
    h = result.harmonics
    # The disc's printing, read back (N = 6: each edge type's mean holds the random
    # errors of 64 edges, so the phase is within a few degrees).
    assert abs(h["eccentricity"] - 0.2) < 0.01 and abs(h["phase_deg"] - 10) < 3
    assert abs(h["duty_a"] - 0.45) < 0.015 and abs(h["duty_b"] - 0.55) < 0.015


def _record(c_true, **kw) -> Record:
    return steady_record(c_true, N, 100, 10.5, start_edge=3, **kw)


def test_calibration_refuses_a_run_unfit_for_it(c_true):
    good = _record(c_true)
    with pytest.raises(CalibrationError, match="turn the disc longer"):
        calibrate(good, 11)
    edges = good.edges.copy()
    edges[500:] = (edges[500:] + 1) % (4 << N)          # a missed state
    with pytest.raises(CalibrationError, match="reversed or a state was missed"):
        calibrate(Record(N, edges, good.clocks), 10)
    back = good.edges.copy()
    back[600:] = (back[599] - np.arange(1, len(back) - 599)) % (4 << N)   # a reversal
    with pytest.raises(CalibrationError, match="reversed"):
        calibrate(Record(N, back, good.clocks), 10)
    clocks = good.clocks.copy()
    clocks[900:] += 40 * int(np.mean(np.diff(clocks)))  # a stop
    with pytest.raises(CalibrationError, match="nearly stopped"):
        calibrate(Record(N, good.edges, clocks), 10)
    with pytest.raises(CalibrationError, match="steadier"):
        calibrate(_record(c_true, ripple=0.5, ripple_hz=0.2), 10)
    with pytest.raises(CalibrationError, match="not of a disc of N = 5"):
        calibrate(Record(5, good.edges, good.clocks), 10)
    noisy = good.clocks + np.random.default_rng(1).integers(-34000, 34000, len(good.clocks))
    with pytest.raises(CalibrationError, match="see the edges"):
        calibrate(Record(N, good.edges, np.sort(noisy)), 10)


# -- the fine blocks with a table -----------------------------------------------------

def _case(rpm_value: float) -> fb.Case:
    v = fb.rpm(rpm_value)
    theta = Trajectory(fb.CLK_HZ, start=100.375).constant(v, 6e-3).theta
    return fb.Case(f"{rpm_value} rpm", theta, np.arange(int(3e-3 * fb.CLK_HZ), len(theta) - 1))


def test_a_zero_table_reads_as_no_table():
    """The same fine position within an LSB and velocity within 2 x 10^-4 of itself: with
    a table the fine position takes pos_hyb CAL_DELAY clocks later and extrapolates over
    them (fine_bench.run_fine, as the board), the velocity takes the step VEL_DELAY
    clocks later, and the constant-speed test allows for an edge's residual error."""
    case = _case(600)
    sync = fb.sync_stream(case.theta, None)
    plain = fb.run_fine(sync)
    zero = fb.run_fine(sync, table=np.zeros(4 << fb.N, dtype=np.int64))
    m = case.measure
    assert np.max(np.abs(plain["fine"][m] - zero["fine"][m])) <= 1
    assert np.max(np.abs(plain["velocity"][m - VEL_DELAY] - zero["velocity"][m])
                  / np.abs(plain["velocity"][m])) < 2e-4


def test_the_calibrated_fine_position_meets_the_goals_on_a_printed_disc():
    c10 = cb.truth()
    table = Table.from_quarters(fb.N, c10 - c10.mean())
    zero = -float(c10.mean()) / 4
    rows = cb.evaluate(_case(1000), table.c, zero)
    assert rows["uncalibrated"].fine[0] > 0.05
    assert rows["calibrated"].fine[0] <= 1 / 128 and rows["calibrated"].fine[1] <= 1 / 64
    assert rows["calibrated"].velocity[1] <= 0.1


def test_the_fraction_stays_in_the_calibrated_quarter():
    """With the velocity too high, the fraction holds at the quarter's true end
    (1 + c_hi); too low (CCW, from the upper edge), at its true start (c_lo)."""
    f = FinePosition(n=fb.N, fine_bits=8, lookahead_halves=0)
    c_lo, c_hi = -(1 << CAL_FRAC) // 4, (1 << CAL_FRAC) // 8
    f.clock(40, 1, 1, 1, 0, 1, c_lo=c_lo, c_hi=c_hi)
    for _ in range(50):
        f.clock(40, 1, 0, 1, 1 << (V_FRAC - 3), 1, c_lo=c_lo, c_hi=c_hi)
    assert f.fine_pos == (40 << 8) + ((1 << 8) + (1 << 8) // 8) - 1
    f.clock(40, 1, 1, 0, 0, 1, c_lo=c_lo, c_hi=c_hi)
    for _ in range(50):
        f.clock(40, 1, 0, 0, -(1 << (V_FRAC - 3)), 1, c_lo=c_lo, c_hi=c_hi)
    assert f.fine_pos == (40 << 8) - (1 << 8) // 4
