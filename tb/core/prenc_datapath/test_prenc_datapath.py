# SPDX-License-Identifier: Apache-2.0
"""prenc_datapath: the five stages wired together, against the model chain clock by
clock (with faults) and against the truth of the virtual encoder."""

from __future__ import annotations

import numpy as np
import pytest
import cocotb
from cocotb.clock import Clock
from cocotb.triggers import ReadOnly, RisingEdge

from common import clock_and_check, drive_events, rng, start_clock_and_reset, to_int_x_as_zero
from prenc.core.datapath import Datapath
from prenc.codes.debruijn import Code
from prenc.virtual.encoder import SIGNALS, Disc, VirtualEncoder
from prenc.virtual.faults import Bounce, ContaminatedSlot, MissedQuadratureState, RandomGlitches, TransientMisread
from prenc.core.predictor import taps_mask
from prenc.virtual.trajectory import Trajectory
from runner import SIMULATORS, run

TOPLEVEL = "prenc_datapath"
RESET = 4
PINS = ("head1", "head2", "sync_a", "sync_b")


def outputs(c) -> dict:
    """The model chain's registered outputs, named as the RTL's ports."""
    return {
        "quarter": c.quad.quarter, "step": c.quad.step, "step_cw": c.quad.step_cw,
        "illegal": c.quad.illegal, "illegal_count": c.quad.illegal_count, "step_count": c.quad.count,
        "strobe": c.strobe.strobe, "word_known": c.word.known, "word_count": c.word.count,
        "word_full": c.word.full, "check": c.prediction.check, "mismatch1": c.prediction.mismatch1,
        "mismatch2": c.prediction.mismatch2,
    }


@cocotb.test()
async def matches_model_chain_with_every_fault(dut):
    n, filter_len = len(dut.word), int(dut.FILTER.value)
    seed = rng().randrange(1 << 30)
    traj = Trajectory(clk_hz=1, start=200.4).random_walk(8000, max_speed=0.25 / (filter_len + 2), seed=seed,
                                                          knot_seconds=300)
    faults = [TransientMisread(2, 205), ContaminatedSlot(1, 198), MissedQuadratureState(count=2, seed=seed),
              RandomGlitches("a", 5, 1, filter_len + 1, seed=seed), Bounce(SIGNALS, width=3, seed=seed)]
    enc = VirtualEncoder(Disc(n), faults=faults).run(traj)
    trace = Datapath(Code(n), filter_len).run(enc, RESET)
    cocotb.start_soon(Clock(dut.clk, 10, unit="ns").start())
    dut.clear_errors.value = 0
    dut.flush.value = 0
    for k, c in enumerate(trace):
        raw = {pin: int(enc.signals[s][k]) for pin, s in zip(PINS, SIGNALS)}
        await clock_and_check(dut, dict(raw, rst=int(k < RESET)), outputs(c) if k >= RESET else None,
                              lambda: f"clock {k}, seed {seed}")
        if k >= RESET:
            got = to_int_x_as_zero(dut.word.value) & c.word.known
            assert got == c.word.word & c.word.known, f"clock {k}, seed {seed}: word"


@cocotb.test()
async def reads_the_true_window_and_counts_the_true_travel(dut):
    n, filter_len = len(dut.word), int(dut.FILTER.value)
    code = Code(n)
    seed = rng().randrange(1 << 30)
    clocks = 200_000
    traj = Trajectory(clk_hz=1, start=17.3).random_walk(clocks, max_speed=0.2 / (filter_len + 1), seed=seed,
                                                         knot_seconds=2000)
    enc = VirtualEncoder(Disc(n)).run(traj)
    events = enc.events()
    await start_clock_and_reset(dut, RESET, dict(zip(PINS, events[0][1:]), clear_errors=0, flush=0))
    checked = 0

    async def no_mismatch_on_a_clean_disc():
        nonlocal checked
        while True:
            await RisingEdge(dut.clk)
            await ReadOnly()
            assert not (int(dut.mismatch1.value) or int(dut.mismatch2.value)), f"seed {seed}: mismatch"
            checked += int(dut.check.value)

    watcher = cocotb.start_soon(no_mismatch_on_a_clean_disc())
    await drive_events(dut, PINS, events[1:], clocks + 10)
    watcher.cancel()
    await RisingEdge(dut.clk)
    await ReadOnly()
    quarters = np.floor(4 * traj.theta).astype(np.int64)
    assert int(dut.illegal_count.value) == 0
    assert int(dut.step_count.value) == int(quarters[-1] - quarters[0]) & 0xFFFFFFFF
    assert int(dut.word_full.value) == 1
    # The word is W(p) of the slot p of the last mid-slot crossing (the current slot
    # may be one further on until the next crossing: the quadrature covers that).
    half = np.floor(traj.theta - 0.5)
    last_crossing = int(np.flatnonzero(half[1:] != half[:-1])[-1]) + 1
    p = int(np.floor(traj.theta[last_crossing])) % code.length
    assert int(dut.word.value) == code.window(p), f"seed {seed}: word is not W({p})"
    assert checked > 1000


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("filter_len", [0, 2])
def test_prenc_datapath(simulator, filter_len):
    run(__file__, TOPLEVEL, simulator, parameters={"N": 10, "TAPS": taps_mask((10, 3)), "FILTER": filter_len})
