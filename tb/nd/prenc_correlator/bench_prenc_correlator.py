# SPDX-License-Identifier: Apache-2.0
"""Benchmark probe (run by scripts/bench.py, not by pytest): measure, don't assert.

Decodes back-to-back readings of the experiment's two-parallel-(10,2) cylinder (the
case file of $PRENC_CORRELATOR_CASE) and writes to $BENCH_OUT the clocks from the
start clock to done, and from one start to the next (start raised again on done).
"""

from __future__ import annotations

import json
import os

import cocotb

from test_prenc_correlator import TB


@cocotb.test()
async def measure(dut):
    tb = TB(dut)
    await tb.reset()
    latencies, agree = [], 0
    total = 0
    for reading in tb.case["readings"]:
        got, clocks = await tb.read(reading, False, 1)
        latencies.append(clocks)
        total += clocks + 1  # the start clock
        agree += got == tb.expected(reading, False, 1)
    with open(os.environ["BENCH_OUT"], "w") as f:
        json.dump({"latency": max(latencies), "clocks_per_reading": total / len(latencies),
                   "readings": len(latencies), "agree_with_model": agree}, f)
