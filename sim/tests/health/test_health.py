# SPDX-License-Identifier: Apache-2.0
"""prenc.health.Health against its definition: a source warns when its corrections come
more often than one per WARN_SLOTS slots of travel, or WARN_BURST at once, and stops
warning once its level has drained, WARN_SLOTS x WARN_BURST slots after the last."""

from __future__ import annotations

import pytest

from prenc.health.health import Health

SLOTS, BURST = 16, 4


def travel(health: Health, quarters: int, every: int | None = None, source: int = 0) -> int | None:
    """Move `quarters` quarter steps with a correction of `source` every `every`
    quarters; the quarter at which the source first warns (None: never)."""
    first = None
    for q in range(quarters):
        event = [0, 0, 0]
        if every and q % every == every - 1:
            event[source] = 1
        health.clock(1, *event)
        if health.warnings[source] and first is None:
            first = q
    return first


@pytest.mark.parametrize("source", [0, 1, 2])
def test_one_correction_per_warn_slots_never_warns(source):
    h = Health(SLOTS, BURST)
    assert travel(h, 100_000, every=4 * SLOTS, source=source) is None
    assert h.levels[source] <= 4 * SLOTS


@pytest.mark.parametrize("source", [0, 1, 2])
def test_corrections_more_often_warn_when_the_bucket_is_full(source):
    h = Health(SLOTS, BURST)
    every = 2 * SLOTS                      # twice the rate: +4S every 2S quarters, net +2S
    first = travel(h, 100_000, every=every, source=source)
    # The level after k corrections is 4S k - (k every - 1) ... the limit 4 S B.
    k = next(k for k in range(1, 10_000) if 4 * SLOTS * k - (k - 1) * every >= 4 * SLOTS * BURST)
    assert first == k * every - 1
    assert h.warning and h.warnings == [int(i == source) for i in range(3)]


def test_a_burst_warns_at_once_and_drains_after_slots_times_burst():
    h = Health(SLOTS, BURST)
    for k in range(BURST):
        h.clock(0, 1, 0, 0)
        assert h.warnings[0] == (k == BURST - 1)
    for _ in range(100):                    # standing still: nothing drains
        h.clock(0, 0, 0, 0)
    assert h.warnings[0] == 1
    quarters = 0
    while h.warnings[0]:
        h.clock(1, 0, 0, 0)
        quarters += 1
    assert quarters == 4 * SLOTS * BURST


def test_reset_clears_everything():
    h = Health(SLOTS, BURST)
    for _ in range(BURST):
        h.clock(0, 1, 1, 1)
    assert h.warnings == [1, 1, 1]
    h.clock(0, 1, 1, 1, rst=1)
    assert h.warnings == [0, 0, 0] and h.levels == [0, 0, 0]


@pytest.mark.parametrize("slots, burst", [(0, 8), (4097, 8), (128, 0), (128, 65)])
def test_illegal_parameters(slots, burst):
    with pytest.raises(ValueError, match="WARN_SLOTS" if slots in (0, 4097) else "WARN_BURST"):
        Health(slots, burst)
