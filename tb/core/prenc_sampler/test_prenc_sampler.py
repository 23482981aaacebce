# SPDX-License-Identifier: Apache-2.0
"""prenc_sampler: strobes, direction, `moved` and head readings, against the model.

Inputs come from the front-end model chain on virtual-encoder runs with random
motion, dithering across A's edge and missed quadrature states (the chain itself is
checked against the truth in sim/tests/core/test_front_end.py); the expected outputs from
prenc.core.sampler.Sampler with the same JUMP (landing readings after a missed state: the
core's sampler) and HEAD_DELAY (0: the step comes on the clock of the heads' sample, as
the core gives it from the decoder's *_next outputs; 1: the decoder's registered step).
"""

from __future__ import annotations

import pytest
import cocotb

from common import clock_and_check, rng
from prenc.core.front_end import FrontEnd
from prenc.virtual.encoder import Disc, VirtualEncoder
from prenc.virtual.faults import MissedQuadratureState
from prenc.core.sampler import Sampler
from prenc.virtual.trajectory import Trajectory
from runner import SIMULATORS, run
from cocotb.clock import Clock

TOPLEVEL = "prenc_sampler"
RESET = 4


def scenario(seed: int):
    traj = Trajectory(clk_hz=1, start=70.2).random_walk(6000, max_speed=0.2, seed=seed, knot_seconds=200)
    traj.move_to(80.3, 0.1)
    for _ in range(5):
        traj.move_to(80.5, 0.02).move_to(80.49, 0.02)  # dither on A's edge
    traj.move_to(75.2, 0.2)
    enc = VirtualEncoder(Disc(10), faults=[MissedQuadratureState(count=30, seed=seed)]).run(traj)
    return FrontEnd(0).run(enc, RESET)


@cocotb.test()
async def matches_model_through_reversals_and_breaks(dut):
    seed = rng().randrange(1 << 30)
    jump = int(dut.JUMP.value)
    head_delay = int(dut.HEAD_DELAY.value)
    trace = scenario(seed)
    model = Sampler(jump=bool(jump), head_delay=bool(head_delay))
    cocotb.start_soon(Clock(dut.clk, 10, unit="ns").start())
    strobes = landings = 0
    for k, now in enumerate(trace):
        before = trace[k - 1] if k else None
        inputs = {"rst": int(k < RESET), "head1_in": 0, "head2_in": 0, "step": 0, "step_cw": 0,
                  "quarter": 0, "break_in": 0}
        if before:
            inputs.update(step=before.quad.step, step_cw=before.quad.step_cw, quarter=before.quad.quarter,
                          break_in=before.quad.illegal)
            # The heads of the step's sample: the clock before the step (HEAD_DELAY 0), or
            # the step's clock, delayed by the sampler (HEAD_DELAY 1).
            heads = before if head_delay else trace[k - 2] if k >= 2 else None
            if heads:
                inputs.update(head1_in=heads.clean[0], head2_in=heads.clean[1])
        s = model.clock(inputs["head1_in"], inputs["head2_in"], inputs["step"], inputs["step_cw"],
                        inputs["quarter"], break_in=inputs["break_in"], rst=inputs["rst"])
        expected = {"strobe": s.strobe}
        if s.strobe and k >= RESET:
            expected.update(strobe_cw=s.cw, strobe_moved=s.moved, strobe_head1=s.head1, strobe_head2=s.head2)
            strobes += 1
            landings += s.strobe and not now.strobe.strobe  # not a mid-slot strobe
        await clock_and_check(dut, inputs, expected if k >= 1 else None, lambda: f"clock {k}, seed {seed}")
    assert strobes > 200
    if jump:
        assert landings >= 1, "no landing reading after the missed states"
    else:
        assert landings == 0


# HEAD_DELAY = 0 (the core's sampler) on Verilator only: the same logic as 1 but a mux.
CASES = [(sim, jump, 1) for sim in SIMULATORS for jump in (0, 1)] + [("verilator", jump, 0) for jump in (0, 1)]


@pytest.mark.parametrize("simulator,jump,head_delay", CASES)
def test_prenc_sampler(simulator, jump, head_delay):
    run(__file__, TOPLEVEL, simulator, parameters={"JUMP": jump, "HEAD_DELAY": head_delay})
