# SPDX-License-Identifier: Apache-2.0
"""The virtual board: prenc_board on Verilator, the virtual encoder on its pins and
its UART on a pseudo-terminal, so that `prenc host` works without a board.

Started by `make board-sim` (scripts/board_sim.py), which passes the settings in the
environment variable PRENC_BOARD_SIM (JSON):

    n, clk_hz, baud        the board's parameters
    profile, rpm           the speed profile (prenc.virtual.profiles)
    misreads, dead_head, missed_states, seed   faults (prenc.virtual.faults); misreads and
                           missed states are drawn anew for each chunk of encoder
                           signal (board_harness.CHUNK clocks)
    seconds                board time to simulate (0: until stopped)
    printed                a printed disc (prenc.virtual.fine_bench.PRINTED), not the ideal one
    port_file              where to write the pty's name (for scripts and tests)

It prints the pty's name, then every few seconds how fast it simulates against
real time. This is a cocotb test module, not a test: pytest does not collect it.
"""

from __future__ import annotations

import json
import os
import time
from pathlib import Path

import cocotb
from cocotb.triggers import Timer
from cocotb.utils import get_sim_time

from board_harness import Bridge, drive_encoder, start_board
from common import PERIOD_NS
from prenc.virtual.encoder import Disc
from prenc.virtual.faults import DeadHead, MissedQuadratureState, RandomMisreads
from prenc.virtual.fine_bench import PRINTED
from prenc.virtual.profiles import profile

REPORT_S = 5.0  # wall-clock seconds between speed reports


def faults_of(cfg: dict):
    seed = int(cfg.get("seed", 1))

    def faults(chunk: int) -> list:
        out = []
        if cfg.get("misreads"):
            out += [RandomMisreads(head=h, probability=float(cfg["misreads"]), seed=seed * 1000 + chunk * 2 + h)
                    for h in (1, 2)]
        if cfg.get("dead_head"):
            out.append(DeadHead(head=int(cfg["dead_head"]), mode="stuck0"))
        if cfg.get("missed_states"):
            out.append(MissedQuadratureState(count=int(cfg["missed_states"]), seed=seed * 1000 + chunk))
        return out

    return faults


@cocotb.test()
async def virtual_board(dut):
    cfg = json.loads(os.environ["PRENC_BOARD_SIM"])
    n, clk_hz, baud = int(cfg["n"]), float(cfg["clk_hz"]), int(cfg["baud"])
    await start_board(dut)
    theta_at = profile(cfg["profile"], float(cfg["rpm"]), n, clk_hz)
    disc = Disc(n, printing=PRINTED if cfg.get("printed") else None)
    cocotb.start_soon(drive_encoder(dut, theta_at, faults_of(cfg), disc))
    bridge = Bridge(dut, round(clk_hz / baud), snapshots=False)
    if cfg.get("port_file"):
        Path(cfg["port_file"]).write_text(bridge.port + "\n")
    first = faults_of(cfg)(0)
    described = ", faults: " + ", ".join(type(f).__name__ for f in first) if first else ""
    printed = ", a printed disc" if cfg.get("printed") else ""
    print(f"virtual board: prenc_board, N = {n}, {clk_hz / 1e6:g} MHz, {cfg['profile']} at "
          f"{float(cfg['rpm']):g} rpm{printed}{described}", flush=True)
    print(f"virtual board: UART on {bridge.port}   try: prenc host monitor --port {bridge.port} --rate 1000",
          flush=True)
    end_clocks = float(cfg.get("seconds", 0)) * clk_hz  # 0: until stopped
    step = 20_000  # clocks between looks at the wall clock
    t0, clock0 = time.monotonic(), get_sim_time("ns") / PERIOD_NS
    last = t0
    while not end_clocks or get_sim_time("ns") / PERIOD_NS - clock0 < end_clocks:
        await Timer(step * PERIOD_NS, unit="ns")
        now = time.monotonic()
        if now - last >= REPORT_S:
            board_s = (get_sim_time("ns") / PERIOD_NS - clock0) / clk_hz
            print(f"virtual board: {board_s * 1e3:.1f} ms of board time in {now - t0:.1f} s: "
                  f"{(now - t0) / board_s:.0f} x slower than real time", flush=True)
            last = now
