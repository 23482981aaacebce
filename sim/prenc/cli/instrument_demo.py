# SPDX-License-Identifier: Apache-2.0
"""`make demo`, second part: the instrument (the fine position and the velocity) on a
printed disc, before and after calibration.

The models of rtl/fine/ (prenc.fine.fine.Fine, which the RTL equals clock for clock in
tb/fine/prenc_fine) read the sync track of the bench's printed disc (edges off by up to
0.05 slot, B 10 degrees late, duties 45 / 55 %, 0.2 slot of eccentricity;
prenc.virtual.fine_bench.PRINTED), N = 10 at 30 MHz, through a motion of five chapters:
a start, one whole turn at 600 rpm, a ramp to 6,000 rpm in 4 ms and back, a reversal
and a stop. The core is taken as locked (its own story is the first part).

Twice: without a table (CAL = 0, EDGE_TOLERANCE = 31: what a printed disc without its
table is built with, docs/fine.md), then with the table that `prenc calibrate` computes
(prenc.cal.calibrate, the same code) from the crossings of a 10-turn run at 70 rpm, as
the board's edge capture records them (prenc.virtual.edge_timing.steady_record: no
board is simulated here; tb/board/prenc_board/test_calibrate_virtual_board.py runs the
command itself against the virtual board). Every output is compared with the true angle
and speed at the clock it is read. The calibrated position's error is taken against the
truth less the calibration's zero: the mean of the disc's edge errors, which no
calibration of one disc can see; a user sets the zero at mounting (ZPOS, the host tool).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..virtual import cal_bench, fine_bench as fb
from ..virtual.trajectory import Trajectory

START = 100.375       # slots: where the shaft starts


@dataclass
class Chapter:
    name: str
    label: str       # its short name in the picture
    start: int       # clocks
    end: int


def motion() -> tuple[np.ndarray, list[Chapter]]:
    """The shaft's angle (slots) at every clock, and the chapters of the story."""
    t = Trajectory(fb.CLK_HZ, start=START)
    chapters: list[Chapter] = []
    r600, r6000 = fb.rpm(600), fb.rpm(6000)

    def chapter(name: str, label: str, *moves) -> None:
        begin = len(t)
        for move, args in moves:
            getattr(t, move)(*args)
        chapters.append(Chapter(name, label, begin, len(t) - 1))

    chapter("start: rest, then up to 600 rpm in 2 ms", "start", ("rest", (0.5e-3,)), ("accelerate", (r600, 2e-3)))
    chapter("one turn at 600 rpm", "one turn", ("constant", (r600, 100e-3)))
    chapter("ramp to 6,000 rpm in 4 ms, and back", "ramp", ("accelerate", (r6000, 4e-3)),
            ("constant", (r6000, 2e-3)), ("accelerate", (r600, 4e-3)), ("constant", (r600, 1e-3)))
    chapter("reversal: 600 to -600 rpm in 2 ms", "reversal", ("accelerate", (-r600, 2e-3)),
            ("constant", (-r600, 1e-3)))
    chapter("stop in 1 ms, at rest", "stop", ("accelerate", (0.0, 1e-3)), ("rest", (2e-3,)))
    return t.theta, chapters


@dataclass
class Result:
    theta: np.ndarray
    chapters: list[Chapter]
    rpm_true: np.ndarray          # the true speed over each clock
    quarter_err: np.ndarray       # slots: the quarter alone (pos_hyb)
    err: dict[str, np.ndarray]    # slots: the fine position, "uncalibrated" and "calibrated"
                                  # (NaN while it is not valid)
    rpm: dict[str, np.ndarray]    # the velocity output, in rpm
    table_rms: float              # the table against the disc's true edges, slots RMS
    zero: float                   # the calibration's zero against the shaft's, slots


def run() -> Result:
    theta, chapters = motion()
    c_true = cal_bench.truth()
    table = cal_bench.bench_table(c_true)          # prenc calibrate's computation, 10 turns at 70 rpm
    zero = -float(c_true.mean()) / 4
    sync = fb.sync_stream(theta, fb.PRINTED)
    scale = 1 << fb.FINE_BITS
    to_rpm = fb.CLK_HZ * 60 / (4 << fb.N)           # quarters per clock -> rpm
    # The output after clock c is read against theta[c + 1], as the bench does.
    truth = theta[1:]
    out_err, out_rpm = {}, {}
    for name, t, tol in (("uncalibrated", None, fb.PRINTED_EDGE_TOLERANCE), ("calibrated", table.table.c, 0)):
        r = fb.run_fine(sync, table=t, edge_tolerance=tol)
        fine = r["fine"][:-1] / scale - (4 * zero if t is not None else 0.0)
        # Until the fine position is valid (its pipeline's first clocks) it is not read: NaN.
        out_err[name] = np.where(r["fine_valid"][:-1] == 1, fb.position_error(fine, truth), np.nan)
        out_rpm[name] = r["velocity"][:-1] * to_rpm
    return Result(theta, chapters, (theta[1:] - theta[:-1]) * 4 * to_rpm,
                  fb.position_error(sync.pos_hyb[:-1].astype(np.float64), truth), out_err, out_rpm,
                  cal_bench.table_error(table, c_true)[0], zero)


def rms_max(x: np.ndarray) -> tuple[float, float]:
    """RMS and largest magnitude, over the clocks read (not NaN)."""
    return float(np.sqrt(np.nanmean(x * x))), float(np.nanmax(np.abs(x)))


def figures(r: Result) -> list[str]:
    """The table printed beside the picture: per chapter, the position error (slots) of the
    quarter alone and of the fine position without and with the table, and the velocity
    error (rpm), RMS / max."""
    lines = [f"  {'chapter':<40} {'quarter alone':>15} {'fine, no table':>16} {'fine, table':>16} "
             f"{'speed, no table':>17} {'speed, table':>15}",
             f"  {'':<40} {'slots RMS/max':>15} {'slots RMS/max':>16} {'slots RMS/max':>16} "
             f"{'rpm RMS/max':>17} {'rpm RMS/max':>15}"]
    for ch in r.chapters:
        s = slice(ch.start, ch.end)
        cells = [rms_max(r.quarter_err[s]), rms_max(r.err["uncalibrated"][s]), rms_max(r.err["calibrated"][s])]
        speed = [rms_max(r.rpm[k][s] - r.rpm_true[s]) for k in ("uncalibrated", "calibrated")]
        lines.append(f"  {ch.name:<40} " + " ".join(f"{a:>8.4f}/{b:.3f}" for a, b in cells)
                     + " " + " ".join(f"{a:>9.2f}/{b:<6.1f}" for a, b in speed))
    return lines


def tell(out_dir: str | Path) -> Result:
    """Run the instrument's story, print its figures and plot it (instrument.png)."""
    out = Path(out_dir)
    r = run()
    print(f"\nprenc demo, part 2: the fine position and the velocity (the models of rtl/fine/, N = {fb.N}, "
          f"{fb.CLK_HZ / 1e6:.0f} MHz, FINE_BITS = {fb.FINE_BITS})")
    print("  on a printed disc (edges +-0.05 slot, B 10 degrees late, duty 45/55 %, eccentricity 0.2 slot),")
    print(f"  before calibration (EDGE_TOLERANCE = {fb.PRINTED_EDGE_TOLERANCE}) and after: prenc calibrate's "
          f"computation on a 10-turn run at 70 rpm, the table {r.table_rms:.5f} slot RMS from the disc's true edges")
    for line in figures(r):
        print(line)
    path = out / "instrument.png"
    plot(r, path)
    print(f"  plot: {path}")
    return r


def _envelope(x: np.ndarray, y: np.ndarray, bins: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per bin of x: the bin's middle, y's minimum and maximum (a line of millions of
    points drawn as the band it fills)."""
    edges = np.linspace(0, len(x), bins + 1).astype(np.int64)
    edges = np.unique(edges)
    lo = np.fmin.reduceat(y, edges[:-1])
    hi = np.fmax.reduceat(y, edges[:-1])
    mid = x[(edges[:-1] + edges[1:] - 1) // 2]
    return mid, lo, hi


def plot(r: Result, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    turn = r.chapters[1]
    ms = np.arange(len(r.rpm_true)) / fb.CLK_HZ * 1e3
    # Two columns: the whole turn at 600 rpm (where eccentricity shows), and the motion
    # around it (the start, the ramp, the reversal, the stop) on a 1 ms scale.
    parts = [("one turn at 600 rpm", np.arange(turn.start, turn.end)),
             ("start, ramp, reversal, stop", np.concatenate([np.arange(0, turn.start),
                                                             np.arange(turn.end, len(ms))]))]
    fig, axes = plt.subplots(3, 2, figsize=(12, 8), sharey="row", width_ratios=[1, 1.6])
    colours = {"quarter": "0.7", "uncalibrated": "tab:orange", "calibrated": "tab:blue"}
    for col, (title, idx) in enumerate(parts):
        ax_v, ax_p, ax_e = axes[:, col]
        # The second column's clocks skip the turn: plot against a time with the turn cut out.
        x = ms[idx] - (ms[turn.end] - ms[turn.start] if col == 1 else 0) * (idx >= turn.end)
        bins = 1500
        mid, lo, hi = _envelope(x, r.rpm_true[idx], bins)
        ax_v.plot(mid, (lo + hi) / 2, color="0.3", lw=2.5, label="true speed")
        names = {"uncalibrated": f"no table (EDGE_TOLERANCE = {fb.PRINTED_EDGE_TOLERANCE})",
                 "calibrated": "with the table"}
        for name in ("uncalibrated", "calibrated"):
            mid, lo, hi = _envelope(x, r.rpm[name][idx], bins)
            ax_v.fill_between(mid, lo, hi, color=colours[name], alpha=0.6, lw=0.6,
                              label=f"velocity, {names[name]}")
        # The errors: the largest |error| in each of the bins, on log axes (the table's
        # thousandths and the raw disc's tenths in one picture).
        mid, _, worst = _envelope(x, np.abs(r.quarter_err[idx]), bins)
        ax_p.plot(mid, worst, color=colours["quarter"], lw=1, label="the quarter alone")
        for name in ("uncalibrated", "calibrated"):
            which = names[name]
            mid, _, worst = _envelope(x, np.abs(r.err[name][idx]), bins)
            ax_p.plot(mid, worst, color=colours[name], lw=1, label=f"fine position, {which}")
            mid, _, worst = _envelope(x, np.abs(r.rpm[name][idx] - r.rpm_true[idx]), bins)
            ax_e.plot(mid, worst, color=colours[name], lw=1, label=which)
        ax_v.set_title(title, fontsize=10)
        ax_e.set_xlabel("time, ms" + (" (the turn at 600 rpm cut out)" if col == 1 else ""))
        if col == 1:
            for ch in r.chapters:
                if ch is turn:
                    continue
                x0 = ms[ch.start] - (ms[turn.end] - ms[turn.start] if ch.start >= turn.end else 0)
                for ax in (ax_v, ax_p, ax_e):
                    ax.axvline(x0, color="0.85", lw=0.8, zorder=0)
                ax_v.text(x0 + 0.1, 6900, ch.label, fontsize=8, va="top")
    axes[0, 0].set_ylabel("speed, rpm")
    axes[1, 0].set_ylabel("|position error|, slots")
    axes[2, 0].set_ylabel("|velocity error|, rpm")
    axes[1, 0].set_yscale("log")
    axes[1, 0].set_ylim(1e-4, 1)
    axes[2, 0].set_yscale("log")
    axes[2, 0].set_ylim(1e-2, 2e3)
    axes[0, 1].legend(loc="center right", fontsize=7)
    axes[1, 1].legend(loc="lower right", fontsize=7)
    axes[2, 1].legend(loc="lower right", fontsize=7)
    cal = rms_max(r.err["calibrated"][turn.start:turn.end])
    raw = rms_max(r.err["uncalibrated"][turn.start:turn.end])
    fig.suptitle(f"prenc_fine on a printed disc (the models of rtl/fine/, N = {fb.N}, 30 MHz): over a turn at "
                 f"600 rpm the fine position is\n{raw[0]:.3f} slot RMS from the truth without a table, "
                 f"{cal[0]:.4f} with the table of prenc calibrate (10 turns at 70 rpm)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
