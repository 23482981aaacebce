# SPDX-License-Identifier: Apache-2.0
"""`prenc disc template`: the heads' places follow the datasheet, the slit is checked, and
the sync pair may sit whole slots from head 1 with the reader's outputs unchanged."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from prenc.cli import disc_template
from prenc.cli.disc import dual_disc
from prenc.cli.disc_template import to_svg
from prenc.codes.debruijn import Code
from prenc.core.reader import Reader
from prenc.virtual.encoder import Disc, EncoderRun, VirtualEncoder
from prenc.virtual.goals import FAST, WALK_CLOCKS, reversing
from prenc.virtual.scenarios import core_latency, judge
from prenc.virtual.trajectory import Trajectory


def template(bits: int, outer: float = 30.0, ring_b: bool = True, **kw):
    return disc_template.template(dual_disc(bits, outer=outer, ring_b=ring_b), bits, **kw)


def test_the_heads_sit_where_the_datasheet_puts_them():
    tp = template(10)
    heads = {h.name: h for h in tp.heads}
    assert heads["head 1"].angle_deg == 0 and heads["head 1"].ring.name == "track1"
    assert heads["head 2"].angle_deg == 180 and heads["head 2"].ring.name == "track2"
    assert heads["sync A"].ring.name == "sync_a" and heads["sync B"].ring.name == "sync_b"
    x, y = heads["head 2"].xy()
    assert abs(x) < 1e-9 and y == pytest.approx(-heads["head 2"].radius)
    # The default slit: a quarter of the narrowest slot (the innermost ring's inner edge).
    innermost = min(r.r_in for r in tp.rings)
    assert tp.slit == pytest.approx(2 * math.pi * innermost / 1024 / 4)


def test_without_ring_b_the_b_head_reads_a_a_quarter_slot_behind():
    """B(theta) = A(theta - 1/4) (the datasheet's A and B): B's head reads ring A (k + 1/4)
    slots counter-clockwise of A's, at least the sensors' width away."""
    tp = template(8, outer=20.0, ring_b=False, sensor_width=4.0)
    heads = {h.name: h for h in tp.heads}
    slots = (heads["sync A"].angle_deg - heads["sync B"].angle_deg) / (360 / 256)
    assert slots % 1 == pytest.approx(0.25)
    assert heads["sync B"].ring.name == "sync_a"
    (xa, ya), (xb, yb) = heads["sync A"].xy(), heads["sync B"].xy()
    assert math.hypot(xa - xb, ya - yb) >= 4.0 * 0.99
    # ... and the disc agrees: ring A read there is B.
    theta = np.linspace(0, 5, 2001)
    a_there, _ = Disc(8).sync(theta - slots)
    _, b = Disc(8).sync(theta)
    assert np.array_equal(a_there, b)


def test_a_slit_too_wide_for_the_sync_track_is_an_error():
    with pytest.raises(ValueError, match="under half the narrowest slot"):
        template(10, slit=0.1)


def test_the_svg_is_at_scale_and_names_every_head():
    svg = to_svg(template(10))
    assert re.search(r'width="[\d.]+mm"', svg)
    for name in ("head 1", "head 2", "sync A", "sync B"):
        assert name in svg


@pytest.mark.parametrize("offset", [1, 7, 64])
def test_the_sync_pair_may_sit_whole_slots_from_head_1(offset):
    """The core's outputs with A and B read `offset` slots clockwise of head 1 equal those
    with A and B beside it, and are right (a turn one way, then reversals)."""
    t = Trajectory(clk_hz=1, start=300.3).constant(FAST, int(1024 / FAST) // 4)
    reversing(t, FAST, WALK_CLOCKS // 3, np.random.default_rng(4))
    beside = VirtualEncoder(Disc(10)).run(t.theta)
    a, b = Disc(10).sync(t.theta + offset)
    moved = EncoderRun(beside.disc, beside.clk_hz, beside.theta, {**beside.signals, "a": a, "b": b})
    out_beside = Reader(Code(10), 2).run(beside)
    out_moved = Reader(Code(10), 2).run(moved)
    assert [(o.valid, o.pos_hyb, o.mode) for o in out_moved] == [(o.valid, o.pos_hyb, o.mode) for o in out_beside]
    verdict = judge(beside, np.array([o.valid for o in out_moved]), np.array([o.pos_hyb for o in out_moved]),
                    np.array([o.mode for o in out_moved]), core_latency(2), filter_len=2)
    assert verdict.wrong == 0 and verdict.availability > 0.9


def test_the_disc_and_its_slit_masks_on_one_sheet():
    disc = dual_disc(10)
    tp = disc_template.template(disc, 10)
    from prenc.cli.disc import to_svg as disc_svg

    sheet = disc_template.beside(disc_svg(disc), to_svg(tp), gap=10.0)
    widths = [float(re.search(r'<svg[^>]*width="([\d.]+)mm"', s).group(1)) for s in (disc_svg(disc), to_svg(tp))]
    assert float(re.search(r'<svg[^>]*width="([\d.]+)mm"', sheet).group(1)) == pytest.approx(sum(widths) + 10.0)
    assert 'id="track1"' in sheet and "prenc head template" in sheet
    assert sheet.count('<rect width="100%"') == 1   # one white background, under both
