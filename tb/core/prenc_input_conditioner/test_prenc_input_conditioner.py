# SPDX-License-Identifier: Apache-2.0
"""prenc_input_conditioner: synchronizer + glitch filter, against its model and its rule.

Inputs are the virtual encoder's four signals on a random walk, with bounce and
glitches of every length from 1 to FILTER + 2 clocks on every input. With PAIRED = 1
(the core's), A and B are one state: changes of the two fewer than FILTER clocks apart
come out together, in either order.
"""

from __future__ import annotations

import numpy as np
import pytest
import cocotb

from common import clock_and_check, rng, start_clock_and_reset
from prenc.virtual.encoder import SIGNALS, VirtualEncoder
from prenc.virtual.faults import Bounce, RandomGlitches
from prenc.core.input_conditioner import InputConditioner
from prenc.virtual.trajectory import Trajectory
from runner import SIMULATORS, run

TOPLEVEL = "prenc_input_conditioner"
RESET_CLOCKS = 3


def pack(bits) -> int:
    """in_raw[0] = head1, [1] = head2, [2] = A, [3] = B."""
    return sum(int(b) << i for i, b in enumerate(bits))


def noisy_inputs(filter_len: int, clocks: int, seed: int) -> np.ndarray:
    traj = Trajectory(clk_hz=1, start=50.3).random_walk(clocks - 1, max_speed=0.05, seed=seed)
    faults = [Bounce(SIGNALS, width=4, seed=seed)]
    for i, name in enumerate(SIGNALS):
        for width in range(1, filter_len + 3):
            faults.append(RandomGlitches(name, count=4, min_width=width, max_width=width, seed=seed + 97 * i + width))
    enc = VirtualEncoder(faults=faults).run(traj)
    return np.stack([enc.signals[s] for s in SIGNALS], axis=1)


@cocotb.test()
async def matches_model_on_noisy_encoder_signals(dut):
    filter_len = int(dut.FILTER.value)
    seed = rng().randrange(1 << 30)
    raw = noisy_inputs(filter_len, 6000, seed)
    model = InputConditioner(4, filter_len, paired=bool(int(dut.PAIRED.value)))
    for _ in range(RESET_CLOCKS):
        model.clock(raw[0], rst=1)
    await start_clock_and_reset(dut, RESET_CLOCKS, {"in_raw": pack(raw[0])})
    for k, row in enumerate(raw.tolist()):
        expected = pack(model.clock(row))
        await clock_and_check(dut, {"in_raw": pack(row)}, {"in_clean": expected},
                              lambda: f"clock {k}, seed {seed}")


@cocotb.test()
async def glitches_shorter_than_filter_never_pass(dut):
    """From the rule itself: a pulse of g clocks passes iff g >= FILTER (any g with no
    filter), unchanged in width, after 2 + FILTER clocks."""
    filter_len = int(dut.FILTER.value)
    await start_clock_and_reset(dut, RESET_CLOCKS, {"in_raw": 0b0101})
    for bit in range(4):
        for g in range(1, filter_len + 3):
            idle = 0b0101
            trace = []
            stimulus = [idle ^ (1 << bit)] * g + [idle] * (filter_len + 6)
            for value in stimulus:
                await clock_and_check(dut, {"in_raw": value}, None)
                trace.append((int(dut.in_clean.value) >> bit) & 1)
            level = (idle >> bit) & 1
            changed = [k for k, v in enumerate(trace) if v != level]
            if g < filter_len:
                assert changed == [], f"bit {bit}: a {g}-clock glitch passed FILTER={filter_len}"
            else:
                start = 2 + filter_len - 1  # trace[k] is the output after edge k + 1
                assert changed == list(range(start, start + g)), (
                    f"bit {bit}, {g}-clock pulse: output differed at clocks {changed}"
                )


@cocotb.test()
async def a_and_b_closer_than_filter_come_out_together(dut):
    """From the rule itself, with PAIRED = 1: from (A, B) = (0, 0), A rises and B rises
    d clocks later (or B first): for d < FILTER both output bits change on one clock,
    never through (1, 0) or (0, 1); for d >= FILTER one at a time, in the inputs' order,
    d clocks apart. Without PAIRED each bit passes alone."""
    filter_len = int(dut.FILTER.value)
    paired = int(dut.PAIRED.value)
    heads = 0b0101 & 0b0011
    await start_clock_and_reset(dut, RESET_CLOCKS, {"in_raw": heads})
    for first in (2, 3):                            # A first, then B first
        for d in range(0, filter_len + 3):
            states = []
            stimulus = ([heads | 1 << first] * d + [heads | 0b1100] * (filter_len + 6) +
                        [heads] * (filter_len + 6))
            for value in stimulus:
                await clock_and_check(dut, {"in_raw": value}, None)
                states.append(int(dut.in_clean.value) >> 2)
            rising = states[:d + filter_len + 6]
            changes = [s for s, t in zip(rising, rising[1:]) if s != t]
            seen = [s for s in dict.fromkeys(rising)]   # the states shown, in order
            if paired and d < filter_len:
                assert seen == [0, 3], f"FILTER={filter_len}, d={d}: the pair showed {seen}"
            elif d >= max(filter_len, 1):
                assert seen == [0, 1 << (first - 2), 3], f"FILTER={filter_len}, d={d}: {seen}"
            assert len(changes) <= 2


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("filter_len, paired", [(0, 0), (1, 0), (2, 0), (4, 0), (8, 0),
                                                (0, 1), (2, 1), (4, 1)])
def test_prenc_input_conditioner(simulator, filter_len, paired):
    run(__file__, TOPLEVEL, simulator, parameters={"WIDTH": 4, "FILTER": filter_len, "PAIRED": paired})


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("params, stop", [
    ({"FILTER": -1}, "prenc_input_conditioner_parameter_FILTER_out_of_range_0_to_65535"),
    ({"FILTER": 70000}, "prenc_input_conditioner_parameter_FILTER_out_of_range_0_to_65535"),
    ({"PAIRED": 2}, "prenc_input_conditioner_parameter_PAIRED_must_be_0_or_1"),
    ({"WIDTH": 1, "PAIRED": 1}, "prenc_input_conditioner_parameter_PAIRED_needs_WIDTH_2"),
])
def test_illegal_parameters_stop_elaboration(simulator, params, stop, capfd):
    with pytest.raises((SystemExit, RuntimeError)):
        run(__file__, TOPLEVEL, simulator, parameters=params)
    out = capfd.readouterr()
    assert stop in out.out + out.err
