# SPDX-License-Identifier: Apache-2.0
"""The instrument soak (prenc.virtual.instrument_soak, `make soak ARGS=--instrument`):
the draws CI can afford pass every check; the draws are reproducible; and the checks
can fail: a fine position built with more extrapolation than its bound allows is caught."""

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
