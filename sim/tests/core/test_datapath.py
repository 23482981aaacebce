# SPDX-License-Identifier: Apache-2.0
"""The datapath models chained, against the truth of the virtual encoder.

The RTL of each stage is compared with its model in tb/; here the models prove
that together they read the disc right: strobes at the mid-slot crossings with the
right direction, the word W(p) whenever it is full, no mismatch on a clean disc,
and the first mismatch on the track that erred.
"""

from __future__ import annotations

import numpy as np
import pytest

from prenc.core.datapath import Datapath
from prenc.codes.debruijn import Code
from prenc.virtual.encoder import Disc, VirtualEncoder
from prenc.virtual.faults import ContaminatedSlot
from prenc.virtual.trajectory import Trajectory

RESET = 4  # the chain needs rst for >= 4 clocks (see rtl/core/prenc_quadrature.v)


def dithering_walk(seed: int, filter_len: int = 0, clocks: int = 20000) -> Trajectory:
    """Random motion, then dithering back and forth across mid-slot 40.5 and slot edge
    42. Every quadrature state lasts at least max(1, filter_len) clocks, so a filter of
    that length passes it all and the truth stays comparable."""
    dwell = max(1, filter_len)
    speed = 0.15 if filter_len == 0 else 0.24 / (filter_len + 1)
    traj = Trajectory(clk_hz=1, start=30.7).random_walk(clocks, max_speed=speed, seed=seed, knot_seconds=400)
    def touch(target: float, v: float) -> None:  # arrive, and stay `dwell` clocks in all
        traj.move_to(target, v).rest(dwell - 1)

    traj.rest(dwell)  # the walk may have just entered a state: let it last
    touch(40.3, speed)
    for k in range(6):
        touch(40.5, speed / 2)  # A's edge, exactly
        touch(40.45 + 0.01 * k, speed / 2)
    for target in (42.02, 41.97, 42.3, 38.2):  # across the slot edge at 42 and back
        touch(target, speed)
    return traj


def strobes(trace):
    return [(k, c) for k, c in enumerate(trace) if c.strobe.strobe]


@pytest.mark.parametrize("filter_len", [0, 2])
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_strobes_are_the_mid_slot_crossings(filter_len, seed):
    enc = VirtualEncoder(Disc(10)).run(dithering_walk(seed, filter_len))
    trace = Datapath(Code(10), filter_len).run(enc, RESET)
    # raw[c] is sampled at edge c; trace[k] holds the outputs after edge k: the
    # synchronizer shows it after edge c + 1, the decoder c + 2, the sampler c + 3.
    lag = 3 + filter_len
    theta = enc.theta
    # Truth: every clock c at which theta crosses a mid-slot point p + 0.5.
    half = np.floor(theta - 0.5)
    crossings = [(c, bool(half[c] > half[c - 1])) for c in range(1, len(theta)) if half[c] != half[c - 1]]
    got = [(k - lag, bool(s.strobe.cw)) for k, s in strobes(trace)]
    assert got == [(c, cw) for c, cw in crossings if c + lag < len(theta)]
    prev_slot = None
    for k, s in strobes(trace):
        c = k - lag
        slot = int(enc.slot[c])
        assert (s.strobe.head1, s.strobe.head2) == (int(enc.head1[c]), int(enc.head2[c]))
        if prev_slot is not None:
            assert s.strobe.moved == int(slot != prev_slot)
        prev_slot = slot


@pytest.mark.parametrize("seed", [4, 5, 6])
def test_full_word_is_always_the_true_window_and_nothing_mismatches(seed):
    code = Code(10)
    enc = VirtualEncoder(Disc(10)).run(dithering_walk(seed))
    trace = Datapath(code, 0).run(enc, RESET)
    lag = 3
    fulls = checks = 0
    for k, s in strobes(trace):
        after = trace[k + 1].word if k + 1 < len(trace) else None
        if after is not None and after.full:
            assert after.word == code.window(int(enc.slot[k - lag])), f"clock {k}"
            fulls += 1
        assert after is None or after.count == bin(after.known).count("1")
    for c in trace:
        assert not (c.prediction.mismatch1 or c.prediction.mismatch2)
        checks += c.prediction.check
    assert fulls > 100 and checks > 100


@pytest.mark.parametrize("track", [1, 2])
def test_first_mismatch_is_on_the_contaminated_track(track):
    code = Code(10)
    L = code.length
    traj = Trajectory(clk_hz=1, start=100.2).move_to(140.2, 0.1).move_to(110.4, 0.1)
    disc_slot = 125  # contaminate the track cell under head `track` at disc slot 125
    track_slot = (disc_slot + (0 if track == 1 else L // 2)) % L
    enc = VirtualEncoder(Disc(10), faults=[ContaminatedSlot(track, track_slot)]).run(traj)
    trace = Datapath(code, 0).run(enc, RESET)
    first = next(c.prediction for c in trace if c.prediction.mismatch1 or c.prediction.mismatch2)
    assert (first.mismatch1, first.mismatch2) == ((1, 0) if track == 1 else (0, 1))


def test_illegal_transition_flushes_the_word():
    code = Code(10)
    from prenc.virtual.faults import MissedQuadratureState

    traj = Trajectory(clk_hz=1, start=10.2).move_to(40.2, 0.1)
    enc = VirtualEncoder(Disc(10), faults=[MissedQuadratureState(index=60)]).run(traj)
    trace = Datapath(code, 0).run(enc, RESET)
    illegal_at = next(k for k, c in enumerate(trace) if c.quad.illegal)
    assert trace[illegal_at + 1].word.count == 0
    assert any(c.word.full for c in trace[:illegal_at])
