# SPDX-License-Identifier: Apache-2.0
"""prenc_quadrature: steps, direction, illegal transitions and the step count.

Expected values: the model clock by clock (with faults), and the truth of the
virtual encoder (the count over a million clocks of random motion).
"""

from __future__ import annotations

import numpy as np
import pytest
import cocotb
from cocotb.triggers import ReadOnly, RisingEdge

from common import clock_and_check, drive_events, rng, start_clock_and_reset
from prenc.virtual.encoder import VirtualEncoder
from prenc.virtual.faults import Glitch, MissedQuadratureState, RandomGlitches
from prenc.core.quadrature import QuadratureDecoder
from prenc.virtual.trajectory import Trajectory
from runner import SIMULATORS, run

TOPLEVEL = "prenc_quadrature"
RESET_CLOCKS = 3
OUTPUTS = ("quarter", "step", "step_cw", "illegal", "illegal_count", "count")
NEXT = ("quarter", "step", "step_cw", "illegal")  # also given as <name>_next before the edge


def widths(dut) -> tuple[int, int]:
    return int(dut.COUNT_WIDTH.value), int(dut.ERROR_WIDTH.value)


@cocotb.test()
async def a_million_clocks_of_random_motion_count_exactly(dut):
    """Clean A/B: the count is 4 x the true travel (in quarters), nothing is illegal."""
    count_width, _ = widths(dut)
    seed = rng().randrange(1 << 30)
    clocks = 1_000_000
    traj = Trajectory(clk_hz=1, start=300.6).random_walk(clocks - 1, max_speed=0.06, seed=seed,
                                                           knot_seconds=5000)
    run_ = VirtualEncoder().run(traj)
    events = [(c, a, b) for c, _, _, a, b in run_.events()]
    await start_clock_and_reset(dut, RESET_CLOCKS, {"a": events[0][1], "b": events[0][2], "clear_errors": 0})
    await drive_events(dut, ["a", "b"], events[1:], clocks + 4)
    await RisingEdge(dut.clk)
    await ReadOnly()
    quarters = np.floor(4 * traj.theta).astype(np.int64)
    travel = int(quarters[-1] - quarters[0])
    mask = (1 << count_width) - 1
    assert int(dut.illegal_count.value) == 0, f"seed {seed}"
    assert int(dut.count.value) == travel & mask, (
        f"seed {seed}: count {int(dut.count.value)}, true travel {travel} quarters "
        f"({len(events)} events, {np.abs(np.diff(quarters)).sum()} transitions)"
    )
    assert np.abs(np.diff(quarters)).max() == 1  # never faster than one state per clock


@cocotb.test()
async def matches_model_with_missed_states_glitches_and_clears(dut):
    count_width, error_width = widths(dut)
    r = rng()
    seed = r.randrange(1 << 30)
    traj = Trajectory(clk_hz=1, start=20.1).random_walk(5999, max_speed=0.2, seed=seed, knot_seconds=300)
    faults = [MissedQuadratureState(count=12, seed=seed), RandomGlitches("a", 10, 1, 2, seed=seed + 1),
              RandomGlitches("b", 10, 1, 2, seed=seed + 2), Glitch("a", 100, 1), Glitch("b", 100, 1)]
    enc = VirtualEncoder(faults=faults).run(traj)
    clears = {r.randrange(len(traj)) for _ in range(6)}
    model = QuadratureDecoder(count_width, error_width)
    for _ in range(RESET_CLOCKS):
        model.clock(int(enc.a[0]), int(enc.b[0]), rst=1)
    await start_clock_and_reset(dut, RESET_CLOCKS, {"a": int(enc.a[0]), "b": int(enc.b[0]), "clear_errors": 0})
    illegal_seen = 0
    for k in range(len(traj)):
        a, b, clear = int(enc.a[k]), int(enc.b[k]), int(k in clears)
        out = model.clock(a, b, clear)
        illegal_seen += out.illegal
        for name, value in {"a": a, "b": b, "clear_errors": clear}.items():
            getattr(dut, name).value = value
        await ReadOnly()  # before the edge: the *_next outputs are what it will register
        nxt = {name: int(getattr(dut, f"{name}_next").value) for name in NEXT}
        assert nxt == {name: getattr(out, name) for name in NEXT}, f"clock {k}, seed {seed}: {nxt}"
        await clock_and_check(dut, {}, out._asdict(), lambda: f"clock {k}, seed {seed}")
    assert illegal_seen >= 12  # every missed state (and A/B glitching together) was flagged


@cocotb.test()
async def missed_state_is_flagged_never_counted_and_saturates(dut):
    """q0 -> q2 directly: illegal, no step, count unchanged; the counter saturates."""
    _, error_width = widths(dut)
    await start_clock_and_reset(dut, RESET_CLOCKS, {"a": 0, "b": 1, "clear_errors": 0})  # q0
    jumps = [(1, 0), (0, 1)] * 4  # q0 <-> q2, eight illegal transitions
    for k, (a, b) in enumerate(jumps):
        expected = {"illegal": 1, "step": 0, "count": 0,
                    "illegal_count": min(k + 1, (1 << error_width) - 1)}
        await clock_and_check(dut, {"a": a, "b": b}, expected, lambda: f"jump {k}")
    await clock_and_check(dut, {"clear_errors": 1}, {"illegal_count": 0, "illegal": 0})
    # one legal CW step q0 -> q1 counts +1 and says CW
    await clock_and_check(dut, {"a": 0, "b": 0, "clear_errors": 0},
                          {"step": 1, "step_cw": 1, "count": 1, "quarter": 1, "illegal": 0})


PARAMETER_SETS = [{"COUNT_WIDTH": 32, "ERROR_WIDTH": 16}, {"COUNT_WIDTH": 8, "ERROR_WIDTH": 2}]


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("params", PARAMETER_SETS, ids=lambda p: f"count{p['COUNT_WIDTH']}-err{p['ERROR_WIDTH']}")
def test_prenc_quadrature(simulator, params):
    run(__file__, TOPLEVEL, simulator, parameters=params)
