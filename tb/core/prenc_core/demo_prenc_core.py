# SPDX-License-Identifier: Apache-2.0
"""The RTL half of `make demo` (run by scripts/demo.py, not by pytest): drive the
demo scenario onto prenc_core, switch to 12 bits on the way, save the outputs per
clock to $DEMO_OUT (.npz)."""

from __future__ import annotations

import os

import numpy as np
import cocotb
from cocotb.triggers import FallingEdge, Timer

from common import PERIOD_NS
from prenc.cli.core_demo import RESOLUTION_12_FROM, demo_run
from test_prenc_core import run_core


@cocotb.test()
async def demo(dut):
    enc, _ = demo_run()

    async def switch():
        await Timer(RESOLUTION_12_FROM * PERIOD_NS, unit="ns")
        await FallingEdge(dut.clk)
        dut.resolution.value = 1

    cocotb.start_soon(switch())
    rows = await run_core(dut, enc, resolution=0)
    valid, hyb, pabs, mode = rows.T
    position = np.where(np.arange(len(valid)) >= RESOLUTION_12_FROM + 1, hyb, pabs)
    np.savez(os.environ["DEMO_OUT"], valid=valid, pos_abs=pabs, pos_hyb=hyb, mode=mode, position=position)
