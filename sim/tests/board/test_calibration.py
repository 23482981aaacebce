# SPDX-License-Identifier: Apache-2.0
"""prenc calibrate's host side: EDGES answers, as the board's capture block (its model,
prenc.cal.edge_capture) makes them from a printed disc's steady turn, strung into a
record that calibrates to the disc's true edges; breaks in the record; and the
command's refusals. The whole run on the RTL board is tb/board/prenc_board's
test_calibrate_virtual_board."""

from __future__ import annotations

import numpy as np
import pytest

from prenc.board.calibration import RecordBuilder, collect
from prenc.board.host import HostError
from prenc.board.protocol import Answer, Kind
from prenc.cal.calibrate import calibrate
from prenc.cal.edge_capture import EdgeCapture
from prenc.virtual.edge_timing import true_corrections
from prenc.virtual.fine_bench import sync_stream
from prenc.virtual.printing import Printing
from prenc.virtual.trajectory import Trajectory

N = 6
PRINTED = Printing(edge_error=0.05, phase_deg=10, duty_a=0.45, duty_b=0.55, eccentricity=0.2, seed=4)


def edges_answers(turns: float, take_every: int, clocks_per_slot: float = 400.0,
                  direction: int = 1) -> list[Answer]:
    """The EDGES answers of a steady turn, one every `take_every` clocks."""
    theta = Trajectory(clk_hz=1, start=7.3).constant(direction / clocks_per_slot,
                                                     turns * (1 << N) * clocks_per_slot).theta
    sync = sync_stream(theta, PRINTED, n=N)
    capture = EdgeCapture(N)
    out = []
    for c, (step, cw, pos) in enumerate(zip(sync.step.tolist(), sync.cw.tolist(), sync.pos_hyb.tolist())):
        take = int(c % take_every == 0)
        if take:
            run = capture.run()
            head = run[0] if run else None
            out.append(Answer(Kind.EDGES, True, 1, 1, True, len(out) % 256, c, {
                "lost": bool(capture.lost), "cw": bool(head.cw) if head else False,
                "pos_valid": bool(head.valid) if head else False, "run": len(run),
                "edge": head.edge if head else 0, "intervals": [e.interval for e in run]}))
        capture.clock(step, cw, 0, pos, 1, take=take)
    return out


def test_a_record_from_the_capture_calibrates_to_the_true_edges():
    record = collect(edges_answers(10.6, take_every=60), N, 10)
    c = true_corrections(PRINTED, N)
    err = (calibrate(record, 10).table.quarters - (c - c.mean())) / 4
    assert np.sqrt(np.mean(err ** 2)) < 1 / 512


def test_the_record_starts_anew_where_the_board_lost_edges():
    answers = edges_answers(4.5, take_every=60)
    lost = answers[len(answers) // 3]
    answers[len(answers) // 3] = Answer(lost.kind, True, 1, 1, True, lost.seq, lost.time_us,
                                        dict(lost.values, lost=True))
    builder = RecordBuilder(N, 2 * (4 << N) + 1)
    done = any(builder.feed(a) for a in answers)
    assert done and builder.breaks["lost"] == 1
    record = builder.record()
    assert np.all(np.diff(record.edges) % (4 << N) == 1)


def test_too_fast_for_the_link_says_so():
    with pytest.raises(HostError, match=r"breaks: \d+ lost"):
        collect(edges_answers(2.5, take_every=2000), N, 2)
