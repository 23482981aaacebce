# SPDX-License-Identifier: Apache-2.0
"""`make demo`: the reader core on a virtual encoder, told as a story.

The scenario (N = 10, FILTER = 2) shows start-up, both resolutions, a reversal, a
one-time misread, a contaminated track, a dead head and its recovery. The RTL core
runs it (scripts/demo.py, through cocotb on Verilator) and leaves its outputs per
clock in a .npz file; this module tells what happened, compares every valid
position with the truth, runs the same scenario through a reader without
protection (the ROM of the raw word at each strobe, no prediction, no verification)
and plots the story.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..codes.debruijn import Code
from ..virtual.encoder import EncoderRun, Disc, VirtualEncoder
from ..virtual.faults import ContaminatedSlot, DeadHead, TransientMisread
from ..core.mode_fsm import Mode
from ..core.reader import Step, events_from_run
from ..virtual.scenarios import core_latency, judge, max_speed
from ..virtual.trajectory import Trajectory

N = 10
FILTER = 2
START = 300.3
RESOLUTION_12_FROM = 3000  # clock at which the demo switches `resolution` to 12 bits


def demo_run() -> tuple[EncoderRun, list[tuple[int, str]]]:
    """The scenario and its chapters (clock, what happens)."""
    v = max_speed(FILTER)
    t = Trajectory(clk_hz=1, start=START)
    chapters = []

    def chapter(what: str) -> None:
        chapters.append((len(t), what))

    chapter("rest, then start-up CW")
    t.rest(200).move_to(START + 40.5, v)
    chapter("reversal exactly at a sampling instant, CCW")
    t.move_to(START + 20.2, v)
    chapter("CW over a one-time misread of head 2 (slot +45)")
    t.move_to(START + 60.7, v)
    chapter("CCW back over slot +45: it reads right now")
    t.move_to(START + 30.1, v)
    chapter("CW over a spot on track 1 (slot +75)")
    t.move_to(START + 90.7, v)
    chapter("CCW back over the spot: wrong again")
    t.move_to(START + 60.1, v)
    dead_from = len(t)
    chapter("head 1 dies (stuck at 0)")
    t.move_to(START + 110.6, v).move_to(START + 85.2, v)
    dead_to = len(t)
    chapter("head 1 recovers")
    t.move_to(START + 120.4, v).rest(300)
    faults = [TransientMisread(2, int(START) + 45, 0),
              ContaminatedSlot(1, int(START) + 75),
              DeadHead(1, "stuck0", start_clock=dead_from, stop_clock=dead_to)]
    chapters.append((RESOLUTION_12_FROM, "resolution switched from 10 to 12 bits"))
    chapters.sort()
    return VirtualEncoder(Disc(N), faults).run(t), chapters


def unprotected(enc: EncoderRun, filter_len: int = FILTER) -> tuple[int, int]:
    """A reader without protection: at each strobe, the ROM of the word formed from
    the raw leading-head readings, output as the position. Returns (strobes with a
    full word, of which wrong)."""
    code = Code(enc.disc.n)
    n, mask, msb = code.n, (1 << code.n) - 1, 1 << (code.n - 1)
    word = known = 0  # the raw word from the leading head, and which of its bits were read
    have_last, last_cw = False, 0
    out = wrong = 0
    for ev in events_from_run(enc, filter_len):
        if not isinstance(ev, Step):  # an illegal transition: start the word again
            known, have_last = 0, False
            continue
        if ev.quarter != (2 if ev.cw else 1):
            continue
        moved = not have_last or ev.cw == last_cw
        have_last, last_cw = True, ev.cw
        if moved and ev.cw:  # to the next slot: shift left, head 2 enters as the LSB
            word, known = ((word << 1) & mask) | ev.head2, ((known << 1) & mask) | 1
        elif moved:  # to the previous slot: shift right, head 1 enters as the MSB
            word, known = (word >> 1) | (ev.head1 << (n - 1)), (known >> 1) | msb
        elif ev.cw and not known & 1:  # back over the same mid-slot point: fill that end
            word, known = (word & ~1) | ev.head2, known | 1
        elif not ev.cw and not known & msb:
            word, known = (word & ~msb) | (ev.head1 << (n - 1)), known | msb
        if known == mask:
            out += 1
            truth = int(enc.slot[ev.clock - 2 - filter_len])
            wrong += code.position(word) != truth
    return out, wrong


def tell(trace_path: str | Path, out_dir: str | Path) -> int:
    """Print the summary and write the plot; returns the wrong valid clocks."""
    out = Path(out_dir)
    enc, chapters = demo_run()
    t = np.load(trace_path)
    valid, pos_abs, pos_hyb, mode, position = (t[k] for k in ("valid", "pos_abs", "pos_hyb", "mode", "position"))
    lat = core_latency(FILTER)
    verdict = judge(enc, valid, pos_hyb, mode, lat, filter_len=FILTER)
    n_out, n_wrong = unprotected(enc)
    print(f"prenc demo: the RTL core (prenc_core, N={N}, FILTER={FILTER}) on a virtual encoder, "
          f"{len(enc):,} clocks")
    print("  what happens:")
    for c, what in chapters:
        print(f"    clock {c:>6}  {what}")
    print("  what the core did:")
    changes = np.flatnonzero(np.diff(mode)) + 1
    for c in [0] + changes.tolist():
        print(f"    clock {c:>6}  mode {Mode(int(mode[c])).name:<12} pos_valid {int(valid[c])}  "
              f"pos_abs {int(pos_abs[c]):>4}  position {int(position[c]):>5}")
    print(f"  start-up: first valid at clock {verdict.first_valid} "
          f"(both heads agree over N + 1 slots each, from clock 0 at rest)")
    print(f"  protected core: {verdict.wrong} wrong valid clocks; availability {verdict.availability:.1%}; "
          + ", ".join(f"{k} {v:.0%}" for k, v in verdict.modes.items() if v))
    print(f"  without protection: {n_wrong} wrong positions output in {n_out} strobes")
    plot(enc, valid, pos_hyb, mode, lat, chapters, out / "demo.png", n_wrong)
    print(f"  plot: {out / 'demo.png'}")
    return verdict.wrong


def plot(enc, valid, pos_hyb, mode, lat, chapters, path: Path, unprotected_wrong: int) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    clocks = np.arange(len(valid))
    truth = enc.hybrid[np.clip(clocks - lat, 0, None)]
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(11, 6.5), sharex=True, height_ratios=[3, 1.3])
    ax1.plot(clocks, truth / 4, color="0.6", lw=3, label="true position (slots)")
    shown = np.where(valid.astype(bool), pos_hyb / 4, np.nan)
    ax1.plot(clocks, shown, color="tab:blue", lw=1.2, label="reported pos_hyb / 4 while pos_valid")
    for c, what in chapters:
        ax1.axvline(c, color="0.85", lw=0.8)
        ax1.text(c, truth.max() / 4 + 2, what, rotation=90, fontsize=7, va="top", ha="right")
    ax1.set_ylabel("slot")
    ax1.legend(loc="lower right", fontsize=8)
    ax1.set_title(f"prenc_core (RTL, Verilator): valid positions all true; an unprotected reader "
                  f"output {unprotected_wrong} wrong ones", fontsize=10)
    ax2.step(clocks, mode, where="post", color="tab:orange", label="mode")
    ax2.step(clocks, valid * 0.8 - 1.2, where="post", color="tab:green", label="pos_valid")
    ax2.set_yticks([-1.2, -0.4, 0, 1, 2, 3, 4], ["valid 0", "valid 1", "ACQUIRE", "NORMAL",
                                                 "REDUCED_1", "REDUCED_2", "INCREMENTAL"], fontsize=7)
    ax2.set_xlabel("clock")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
