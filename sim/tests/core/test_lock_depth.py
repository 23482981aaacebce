# SPDX-License-Identifier: Apache-2.0
"""The lock-depth arithmetic (prenc.core.lock_depth): undetectable misread patterns of a
lock after k strobes, enumerated on the disc itself."""

from __future__ import annotations

from prenc.codes.debruijn import Code
from prenc.core.lock_depth import depth_row, reading_slots, weight_counts


def test_reading_slots_follow_the_geometry():
    assert reading_slots(10, 1, 3).tolist() == [0, 1, 2]
    assert reading_slots(10, 2, 2).tolist() == [0, 1, 9, 10]


def test_every_wrong_shift_is_counted_once_per_start():
    code = Code(6)
    hist, starts = weight_counts(code, reading_slots(6, 2, 6))
    assert starts == 64 and hist.sum() == 64 * 63


def test_weight_matches_brute_force():
    """The lightest undetectable pattern, recomputed by comparing readings directly."""
    code = Code(6)
    seq = code.sequence
    slots = reading_slots(6, 2, 7)
    best = min(int(sum(seq[(p + s) % 64] != seq[(p + d + s) % 64] for s in slots))
               for p in range(64) for d in range(1, 64))
    assert depth_row(6, 2, 7).min_weight == best


def test_deeper_locks_are_safer():
    for n in (6, 8, 10):
        rows = [depth_row(n, 2, n + e).p_wrong[0.03] for e in range(4)]
        assert all(b <= a for a, b in zip(rows, rows[1:])), rows
    assert depth_row(10, 2, 11).p_wrong[0.03] < depth_row(10, 2, 10).p_wrong[0.03]
    row = depth_row(12, 1, 25)
    assert row.p_wrong[0.001] < row.p_wrong[0.01] < row.p_wrong[0.03]


def test_prefix_sums_equal_the_direct_comparison():
    """The exact enumeration used for the table (every p and d, by prefix sums)
    against the direct comparison of readings, for both geometries and overlaps."""
    from prenc.core.lock_depth import weight_counts_exact

    for n in (5, 6, 8):
        code = Code(n)
        sets = [reading_slots(n, 2, n + e) for e in (0, 2, 4)] + \
               [reading_slots(n, 1, 2 * n + e) for e in (0, 3)]
        for slots, hist in zip(sets, weight_counts_exact(code, sets)):
            direct, starts = weight_counts(code, slots)
            assert starts == code.length
            assert hist.tolist() == direct.tolist()
