# SPDX-License-Identifier: Apache-2.0
"""prenc.virtual.health_bench (`make bench` section 13) on short runs: a clean disc with
sensor noise never warns; a disc getting dirty warns, before the reader drops the track,
and no position is ever wrong."""

from __future__ import annotations

from prenc.virtual.faults import GrowingDirt
from prenc.virtual.health_bench import Case, run_case
from prenc.virtual.sensors import CrossingJitter


def test_a_clean_disc_with_noise_never_warns():
    r = run_case(Case("clean", lambda: [CrossingJitter(0.01, ("a", "b", "head1", "head2"), seed=2)], turns=1.5))
    assert r.first_warning is None and r.corrections == (0, 0, 0) and r.wrong == 0


def test_a_disc_getting_dirty_warns_before_a_track_is_dropped():
    r = run_case(Case("dirt", lambda: [GrowingDirt(1, 4_000, 30_000, seed=1)], turns=3))
    assert r.first_warning is not None and r.wrong == 0
    assert r.first_reduced is None or r.first_warning < r.first_reduced
    assert r.spots_at(r.first_warning) == str(GrowingDirt(1, 4_000, 30_000).spots(r.first_warning))
