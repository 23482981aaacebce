# SPDX-License-Identifier: Apache-2.0
"""prenc.virtual.soak: many draws of the scenarios through the model, with the RTL test's
two checks. A soak that cannot fail is worse than none, so each check is shown to fire
on a reader that breaks it."""

from __future__ import annotations

import dataclasses

import pytest

from prenc.core.reader import Reader
from prenc.virtual.scenarios import scenarios
from prenc.virtual.soak import soak, soak_seed

N = 6
NAMES = ["start_at_rest_cw", "glitches", "missed_state"]


class OneSlotAhead(Reader):
    """Outputs the position one slot (4 quarters) ahead of the model's."""

    def clock(self, *args, **kwargs):
        out = super().clock(*args, **kwargs)
        return dataclasses.replace(out, pos_hyb=(out.pos_hyb + 4) % (4 << N))


class NeverValid(Reader):
    def clock(self, *args, **kwargs):
        return dataclasses.replace(super().clock(*args, **kwargs), valid=0)


def test_the_model_passes_its_draws():
    result = soak(N, 2, [1, 2], NAMES, jobs=2)  # the process pool too
    assert (result.runs, result.failures) == (6, [])


def test_a_wrong_position_fails_every_draw_with_its_seed():
    result = soak(N, 2, [3, 4], NAMES, reader_type=OneSlotAhead)
    assert [(f.seed, f.scenario) for f in result.failures] == [(s, x) for s in (3, 4) for x in NAMES]
    assert all(f.what.startswith("wrong valid position at clock") for f in result.failures)
    assert "PRENC_SCENARIO_SEED=3" in result.failures[0].line(N, 2)


def test_never_valid_fails_only_where_every_draw_must_lock():
    failures = soak_seed(N, 0, 5, NAMES, reader_type=NeverValid)
    assert [(f.scenario, f.what) for f in failures] == [("start_at_rest_cw", "never valid")]


def test_bad_requests_name_what_is_wrong():
    with pytest.raises(ValueError, match="unknown scenario nope"):
        soak(N, 0, [1], ["glitches", "nope"])
    with pytest.raises(ValueError, match="seed 0 must be 1 or more"):
        soak(N, 0, [0], ["glitches"])


@pytest.mark.parametrize("filter_len", [4, 8])
def test_the_model_passes_every_scenario_at_larger_filters(filter_len):
    """CI's RTL tests run FILTER 0 and 2; the scenarios' fault speeds depend on FILTER, so
    every scenario is drawn here at FILTER 4 and 8 too, at N = 10, through the model (the
    RTL equals it). At FILTER 8 seeds 1, 4 and 7 failed the bounce scenario before its
    speed left FILTER clean clocks of each state (0.20.1)."""
    result = soak(10, filter_len, [1, 4, 7], None, jobs=2)
    assert result.runs == 3 * len(scenarios(10, filter_len)) and result.failures == []
