# SPDX-License-Identifier: Apache-2.0
"""The instrument soak (prenc.virtual.instrument_soak, `make soak ARGS=--instrument`):
the draws CI can afford pass every check; the draws are reproducible; and the checks
can fail: a fine position built with more extrapolation than its bound allows is caught,
and so is a count a slot off at speed."""

from __future__ import annotations

import numpy as np

from prenc.virtual.instrument_soak import LOOKAHEAD_HALVES, draw, run_draw


def test_the_draws_ci_affords_pass():
    # A missed state with glitches; a printed disc with bounce; glitches and bounce on B
    # (bounce once made a glitch 3 clocks long: a transition, not a glitch); a missed
    # state that once held a glitch's end back 6,548 clocks (a quarter the disc never
    # showed); two passes of one B edge, each with its own noise, the second 118 clocks
    # late (the sensors' quarter, accepted).
    for seed in (1, 4, 5107, 5509, 5552):
        result = run_draw(seed)
        assert result.failures == [], (seed, result.label, result.failures[:3])
        assert result.wrong == 0 and result.fine_rms < 0.3


def test_a_draw_is_reproducible():
    a, b = draw(7), draw(7)
    assert np.array_equal(a.theta, b.theta) and a.label == b.label
    assert draw(8).label != a.label or not np.array_equal(draw(8).theta, a.theta)


def test_a_fine_position_beyond_its_bound_fails():
    result = run_draw(3, fine_lookahead_halves=LOOKAHEAD_HALVES + 60)
    assert any("fine position" in f for f in result.failures), result.failures[:3]


def test_a_slot_error_at_speed_is_caught():
    """Seed 4 with its missed states applied before its bounce (which can then show the
    two changes a clock or two apart in the wrong order), read with A and B filtered one
    by one: the count goes a slot behind at 5,480 rpm, and the position's judge sees it.
    (Its tolerance was once the run's longest fault stretch, 1,180 clocks here, 3.7
    slots at that speed, and it passed this draw.)"""
    from prenc.codes.debruijn import Code
    from prenc.core.input_conditioner import InputConditioner
    from prenc.core.reader import Reader
    from prenc.virtual.encoder import Disc, VirtualEncoder
    from prenc.virtual.faults import Bounce, MissedQuadratureState
    from prenc.virtual.instrument_soak import CLK_HZ, FILTER, N, judge_position

    d = draw(4)
    missed = [f for f in d.faults if isinstance(f, MissedQuadratureState)]
    bounce = [f for f in d.faults if isinstance(f, Bounce)]
    assert missed and bounce and len(d.faults) == 2
    enc = VirtualEncoder(Disc(N, printing=d.printing), [*d.sensors, *missed, *bounce]).run(d.theta, CLK_HZ)
    reader = Reader(Code(N), FILTER)
    reader.conditioner = InputConditioner(4, FILTER)
    outs = reader.run(enc)
    wrong, _ = judge_position(d, enc, np.array([o.valid for o in outs]).astype(bool),
                              np.array([o.pos_hyb for o in outs]), np.array([o.mode for o in outs]))
    assert wrong > 1000
