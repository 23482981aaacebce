# SPDX-License-Identifier: Apache-2.0
"""The lean-rule design study (prenc.virtual.lean_reader, no RTL): it keeps the promise
that a valid position is never wrong, and it equals the core where acquisition runs one
way (the two rules differ only in how a raw word survives a reversal)."""

from __future__ import annotations

import pytest

from prenc.codes.debruijn import Code
from prenc.core.reader import LATENCY, Reader
from prenc.virtual.campaign import campaign
from prenc.virtual.goals import goals, measure
from prenc.virtual.lean_reader import LeanReader
from prenc.virtual.scenarios import judge_outputs, scenarios


@pytest.mark.parametrize("n", [6, 10])
def test_scenarios_never_wrong(n):
    for name, sc in scenarios(n, 0, 11).items():
        enc = sc.run(n)
        verdict = judge_outputs(enc, LeanReader(Code(n)).run(enc), LATENCY)
        assert verdict.wrong == 0, f"{name}: wrong valid at clock {verdict.first_wrong}"


def test_campaign_small_is_never_wrong():
    r = campaign(6, 20_000, 5_000, seed=4, reader_type=LeanReader)
    assert r.wrong_valid == 0
    assert r.strobes >= 20_000 and r.availability > 0.3


def test_equals_the_core_where_acquisition_runs_one_way():
    """Clean, one direction: both rules place the first position after the same
    strobes and keep it, so their outputs are the same on every clock."""
    n = 10
    g = {x.name: x for x in goals(n)}["clean_one_way"]
    enc = g.run(n)
    core = [(o.valid, o.pos_hyb) for o in Reader(Code(n)).run(enc)]
    lean = [(o.valid, o.pos_hyb) for o in LeanReader(Code(n)).run(enc)]
    assert core == lean
    assert measure(g, LeanReader(Code(n)), n, 0, enc).meets(g)
