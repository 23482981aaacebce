# SPDX-License-Identifier: Apache-2.0
"""Benchmark probe (run by scripts/bench.py, not by pytest): the RTL fault campaign.

Seeded segments of a random walk with a random mix of the datasheet's faults
(misreads, contaminated cells, a dead head, missed quadrature states, bounce on
the heads) drive prenc_core until $BENCH_STROBES strobes have been made; each
segment is judged against the true angle (prenc.virtual.scenarios.judge). Writes the
counts to $BENCH_OUT.
"""

from __future__ import annotations

import json
import os

import numpy as np
import cocotb

from prenc.virtual.encoder import Disc, VirtualEncoder
from prenc.virtual.faults import Bounce, ContaminatedSlot, DeadHead, MissedQuadratureState, RandomMisreads
from prenc.core.reader import Reader
from prenc.codes.debruijn import Code
from prenc.virtual.scenarios import core_latency, judge, max_speed
from prenc.virtual.trajectory import Trajectory
from test_prenc_core import RESET, run_core


@cocotb.test()
async def campaign(dut):
    n, filter_len = len(dut.pos_abs), int(dut.FILTER.value)
    target = int(os.environ.get("BENCH_STROBES", "100000"))
    seed = int(os.environ.get("BENCH_SEED", "1"))
    rng = np.random.default_rng(seed)
    totals = {"n": n, "filter": filter_len, "seed": seed, "segments": 0, "clocks": 0, "strobes": 0,
              "valid_clocks": 0, "wrong_valid_clocks": 0}
    v = max_speed(filter_len)
    while totals["strobes"] < target:
        s = int(rng.integers(1 << 30))
        clocks = 60_000
        start = float(rng.uniform(0, 1 << n))
        traj = Trajectory(clk_hz=1, start=start).random_walk(clocks, max_speed=v, seed=s,
                                                             knot_seconds=int(rng.integers(50, 400)))
        faults = [RandomMisreads(1, float(rng.choice([0, 1e-3, 1e-2])), s),
                  RandomMisreads(2, float(rng.choice([0, 1e-3, 1e-2])), s + 1),
                  ContaminatedSlot(int(rng.integers(1, 3)), int(rng.integers(0, 1 << n))),
                  MissedQuadratureState(count=int(rng.integers(0, 4)), seed=s),
                  Bounce(("head1", "head2"), width=2, seed=s)]
        if rng.random() < 0.5:
            faults.append(DeadHead(int(rng.integers(1, 3)), str(rng.choice(["stuck0", "stuck1", "noise"])),
                                   start_clock=int(rng.integers(0, clocks)), seed=s))
        enc = VirtualEncoder(Disc(n), faults).run(traj)
        rows = await run_core(dut, enc, start_clock=totals["segments"] == 0)
        valid, hyb, _pabs, mode = rows.T
        verdict = judge(enc, valid, hyb, mode, core_latency(filter_len), filter_len=filter_len)
        reader = Reader(Code(n), filter_len)
        reader.run(enc, RESET)
        totals["segments"] += 1
        totals["clocks"] += len(enc)
        totals["strobes"] += reader.strobes
        totals["valid_clocks"] += int(valid.sum())
        totals["wrong_valid_clocks"] += verdict.wrong
        dut._log.info("segment %d: %d strobes so far, %s", totals["segments"], totals["strobes"], verdict.line())
    with open(os.environ["BENCH_OUT"], "w") as f:
        json.dump(totals, f)
