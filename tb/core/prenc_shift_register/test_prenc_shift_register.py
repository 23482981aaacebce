# SPDX-License-Identifier: Apache-2.0
"""prenc_shift_register: the word, its known bits and their count, against the model.

Inputs are the sampler outputs of the datapath model chain on virtual-encoder runs
(random motion, reversals, missed states that flush the word).
"""

from __future__ import annotations

import pytest
import cocotb
from cocotb.clock import Clock

from common import clock_and_check, rng, to_int_x_as_zero
from prenc.core.datapath import Datapath
from prenc.codes.debruijn import Code
from prenc.virtual.encoder import Disc, VirtualEncoder
from prenc.virtual.faults import MissedQuadratureState
from prenc.virtual.trajectory import Trajectory
from runner import SIMULATORS, run

TOPLEVEL = "prenc_shift_register"
RESET = 4


@cocotb.test()
async def matches_model_through_reversals_and_flushes(dut):
    n = len(dut.word)
    seed = rng().randrange(1 << 30)
    traj = Trajectory(clk_hz=1, start=5.6).random_walk(8000, max_speed=0.2, seed=seed, knot_seconds=150)
    enc = VirtualEncoder(Disc(n), faults=[MissedQuadratureState(count=4, seed=seed)]).run(traj)
    trace = Datapath(Code(n), 0).run(enc, RESET)
    cocotb.start_soon(Clock(dut.clk, 10, unit="ns").start())
    fulls = 0
    for k, now in enumerate(trace):
        inputs = {"rst": int(k < RESET), "flush": 0, "strobe": 0, "strobe_cw": 0, "strobe_moved": 0,
                  "strobe_head1": 0, "strobe_head2": 0}
        if k:
            s, q = trace[k - 1].strobe, trace[k - 1].quad
            inputs.update(flush=q.illegal, strobe=s.strobe, strobe_cw=s.cw, strobe_moved=s.moved,
                          strobe_head1=s.head1, strobe_head2=s.head2)
        w = now.word
        await clock_and_check(dut, inputs, {"known": w.known, "count": w.count, "full": w.full},
                              lambda: f"clock {k}, seed {seed}")
        got_word = to_int_x_as_zero(dut.word.value) & w.known  # unknown bits: don't care
        assert got_word == w.word & w.known, f"clock {k}, seed {seed}: word {got_word:#x}, model {w.word & w.known:#x}"
        fulls += w.full
    assert fulls > 1000


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("n", [2, 4, 10])
def test_prenc_shift_register(simulator, n):
    run(__file__, TOPLEVEL, simulator, parameters={"N": n})
