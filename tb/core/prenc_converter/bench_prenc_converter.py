# SPDX-License-Identifier: Apache-2.0
"""Benchmark probe (run by scripts/bench.py, not by pytest): measure, don't assert.

Presents the word of the last slot, W(L-1), the serial converter's worst case, and
counts clocks until pos_valid; writes the count and the slot read to $BENCH_OUT.
"""

from __future__ import annotations

import json
import os

import cocotb
from cocotb.clock import Clock
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge

from prenc.codes.debruijn import Code


@cocotb.test()
async def measure_latency(dut):
    n = len(dut.word)
    code = Code(n)
    cocotb.start_soon(Clock(dut.clk, 10, unit="ns").start())
    dut.rst.value = 1
    dut.word_valid.value = 0
    dut.word.value = 0
    await RisingEdge(dut.clk)
    await FallingEdge(dut.clk)
    dut.rst.value = 0
    dut.word_valid.value = 1
    dut.word.value = code.window(code.length - 1)
    clocks = 0
    while clocks < 1 << (n + 1):
        await RisingEdge(dut.clk)
        clocks += 1
        await ReadOnly()
        if int(dut.pos_valid.value):
            break
    result = {"n": n, "clocks": clocks, "pos": dut.pos.value.to_unsigned(), "expected": code.length - 1}
    with open(os.environ["BENCH_OUT"], "w") as f:
        json.dump(result, f)
