# SPDX-License-Identifier: Apache-2.0
"""The front end's models chained, against the truth of the virtual encoder.

The RTL of each stage is compared with its model in tb/; here the models prove
that together they read the disc right: strobes at the mid-slot crossings with the
right direction and the heads' readings, and an illegal transition flagged once.
"""

from __future__ import annotations

import numpy as np
import pytest

from prenc.core.front_end import FrontEnd
from prenc.virtual.encoder import Disc, VirtualEncoder
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
    trace = FrontEnd(filter_len).run(enc, RESET)
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


def test_illegal_transition_is_flagged_and_breaks_the_strobes():
    from prenc.virtual.faults import MissedQuadratureState

    traj = Trajectory(clk_hz=1, start=10.2).move_to(40.2, 0.1)
    enc = VirtualEncoder(Disc(10), faults=[MissedQuadratureState(index=60)]).run(traj)
    trace = FrontEnd(0).run(enc, RESET)
    assert sum(c.quad.illegal for c in trace) == 1
