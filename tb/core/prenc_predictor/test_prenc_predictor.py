# SPDX-License-Identifier: Apache-2.0
"""prenc_predictor: exhaustive over every word, both directions, both kinds of strobe
and every pair of head readings, against the model, for several N and feedback sets.
"""

from __future__ import annotations

import os

import pytest
import cocotb
from cocotb.clock import Clock

from common import clock_and_check, rng
from prenc.codes.debruijn import Code
from prenc.core.predictor import Predictor, taps_mask
from runner import SIMULATORS, run

TOPLEVEL = "prenc_predictor"

# (cw, moved): CW to a new slot, CCW to a new slot, a reversal strobe either way
KINDS = [(1, 1), (0, 1), (1, 0), (0, 0)]


@cocotb.test()
async def every_word_every_direction_every_reading(dut):
    n = len(dut.word)
    taps = tuple(int(t) for t in os.environ["PRENC_TAPS"].split(","))
    code = Code(n, taps)
    model = Predictor(code)
    r = rng()
    cocotb.start_soon(Clock(dut.clk, 10, unit="ns").start())
    idle = {"strobe": 0, "strobe_cw": 0, "strobe_moved": 0, "strobe_head1": 0, "strobe_head2": 0,
            "word": 0, "full": 0}
    await clock_and_check(dut, dict(idle, rst=1), None)
    model.clock(0, 0, 0, 0, 0, 0, 0, rst=1)
    mismatches = [0, 0]
    for word in range(1 << n):
        for cw, moved in KINDS:
            for h1, h2 in ((0, 0), (0, 1), (1, 0), (1, 1)):
                full = int(r.random() < 0.9)
                inputs = dict(idle, rst=0, strobe=1, strobe_cw=cw, strobe_moved=moved,
                              strobe_head1=h1, strobe_head2=h2, word=word, full=full)
                exp = model.clock(1, cw, moved, h1, h2, word, full)
                mismatches[0] += exp.mismatch1
                mismatches[1] += exp.mismatch2
                await clock_and_check(dut, inputs, exp._asdict(),
                                      lambda: f"word {word:#x} cw={cw} moved={moved} heads={h1}{h2}")
    assert min(mismatches) > 0
    # idle: no check, no mismatch, predictions held
    await clock_and_check(dut, dict(idle, rst=0), {"check": 0, "mismatch1": 0, "mismatch2": 0,
                                                   "expect1": exp.expect1, "expect2": exp.expect2})


CODES = [(4, (4, 1)), (7, (7, 3)), (7, (7, 1)), (10, (10, 3)), (10, (10, 7))]


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("n, taps", CODES, ids=lambda v: str(v) if isinstance(v, int) else ",".join(map(str, v)))
def test_prenc_predictor(simulator, n, taps):
    Code(n, taps)  # the feedback set must be primitive
    run(__file__, TOPLEVEL, simulator, parameters={"N": n, "TAPS": taps_mask(taps)},
        extra_env={"PRENC_TAPS": ",".join(map(str, taps))})


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_taps_without_bit_n_minus_1_stop_elaboration(simulator, capfd):
    with pytest.raises((SystemExit, RuntimeError)):
        run(__file__, TOPLEVEL, simulator, parameters={"N": 10, "TAPS": 0x104})
    out = capfd.readouterr()
    assert "prenc_predictor_parameter_TAPS_not_a_feedback_set_for_N" in out.out + out.err
