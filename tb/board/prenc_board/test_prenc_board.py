# SPDX-License-Identifier: Apache-2.0
"""prenc_board end to end: the real `prenc host` commands, through a pseudo-terminal,
to the board top on Verilator while the virtual encoder turns the disc.

    prenc host (subprocess, pyserial) <-> /dev/pts/N <-> this bridge <-> uart_rx/uart_tx pins

No mock: the host runs as the user runs it (`python -m prenc.cli.main host ...`), the
bytes cross a real pty, and the bridge only moves bits between the pty and the
pins at the UART's bit rate. The board runs as on the iCEBreaker (24 MHz clock,
3 Mbaud).

Expected values come from the disc, not the RTL: each answer carries SEQ, the
bridge records the clock of every answer's snapshot (prenc_host_link's
`snapshot`), and the answer must equal the true position (or count) at that clock
minus the core's latency, within +-(FILTER + 2) clocks. Checked: every kind of
`read`, `log` streaming (with a corrupted byte on the line, which must be counted
and not stop the log), `monitor`, and `plot` from the log.
"""

from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
import time

import cocotb
import numpy as np
from cocotb.triggers import Timer

from board_harness import Bridge, drive_encoder, start_board
from common import PERIOD_NS
from prenc.board import protocol
from prenc.virtual.encoder import Disc
from prenc.virtual.scenarios import core_latency
from runner import REPO, SIM_BUILD, rom_file, run

TOPLEVEL = "prenc_board"
N, FILTER, CLK_HZ, BAUD = 10, 2, 24_000_000, 3_000_000
SLOT_CLOCKS = 300          # the disc's speed: one slot per 300 clocks (4,688 rpm at 24 MHz)
START_CLOCK = 2_000        # the disc rests until here


def theta_at(clocks: np.ndarray) -> np.ndarray:
    """True angle in slots at each clock: rest, then constant speed CW."""
    moving = np.maximum(np.asarray(clocks, dtype=np.float64) - START_CLOCK, 0.0)
    return 100.4 + moving / SLOT_CLOCKS


class Truth:
    def __init__(self):
        self.disc = Disc()
        self.window = FILTER + 2
        self.latency = core_latency(FILTER)

    def clocks(self, snapshot_clock: int) -> np.ndarray:
        c = snapshot_clock - self.latency
        return np.arange(c - self.window, c + self.window + 1)

    def hybrid(self, snapshot_clock: int) -> set[int]:
        return set(self.disc.hybrid(theta_at(self.clocks(snapshot_clock))).tolist())

    def count(self, snapshot_clock: int) -> set[int]:
        q = np.floor(4 * theta_at(self.clocks(snapshot_clock))).astype(np.int64)
        q0 = int(np.floor(4 * theta_at(np.array([0])))[0])
        return set((q - q0).tolist())


async def host(bridge: Bridge, *args: str, timeout_s: float = 120.0) -> subprocess.CompletedProcess:
    """Run `prenc host ...` while the simulation keeps going; return when it exits."""
    cmd = [sys.executable, "-m", "prenc.cli.main", "host", *args]
    env = dict(os.environ, PYTHONPATH=str(REPO / "sim"))
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    t0 = time.monotonic()
    while proc.poll() is None:
        await Timer(2_000 * PERIOD_NS, unit="ns")
        if time.monotonic() - t0 > timeout_s:
            proc.kill()
            raise AssertionError(f"`{' '.join(args)}` did not finish in {timeout_s} s")
    out, err = proc.communicate()
    return subprocess.CompletedProcess(cmd, proc.returncode, out, err)


def link_args(bridge: Bridge) -> list[str]:
    return ["--port", bridge.port, "--baud", str(BAUD), "--timeout", "5"]


def check_answer(record: dict, truth: Truth, bridge: Bridge) -> None:
    clock = bridge.snapshot_of(int(record["seq"]))
    kind = record["kind"]
    assert record["valid"] in (True, 1, "1"), f"{kind} answer at clock {clock} not valid: {record}"
    assert record["mode"] == "NORMAL"
    assert record["direction"] == "cw"
    hyb = truth.hybrid(clock)
    if kind == "abs":
        assert int(record["position"]) in {h >> 2 for h in hyb}, (clock, record, sorted(hyb))
    elif kind == "hybrid":
        assert int(record["position"]) in hyb, (clock, record, sorted(hyb))
    elif kind == "incremental":
        assert int(record["count"]) in truth.count(clock), (clock, record, sorted(truth.count(clock)))
    elif kind == "tracks":
        assert int(record["track1"]) in {h >> 2 for h in hyb} and int(record["track2"]) == int(record["track1"])
        assert record["track1_valid"] in (True, 1, "1") and record["track2_valid"] in (True, 1, "1")
    elif kind == "fine":
        # The quarter, extrapolated to the answer's clock: within a quarter of the latency's.
        quarter = int(record["fine_position"]) >> int(record["fine_bits"])
        near = {(h + d) % (4 << N) for h in hyb for d in (-1, 0, 1)}
        assert quarter in near, (clock, record, sorted(hyb))
        if record["velocity_rpm"] not in (None, ""):
            true_rpm = CLK_HZ / SLOT_CLOCKS / (1 << N) * 60
            assert abs(float(record["velocity_rpm"]) - true_rpm) < 0.001 * true_rpm, (record, true_rpm)
    else:
        assert (record["version"], record["bits"]) == (protocol.VERSION, N)
        assert record["track1_errors"] == record["track2_errors"] == record["sync_errors"] == 0


@cocotb.test()
async def prenc_host_reads_the_true_position_through_a_pty(dut):
    await start_board(dut)
    cocotb.start_soon(drive_encoder(dut, theta_at))
    bridge = Bridge(dut, round(CLK_HZ / BAUD))
    truth = Truth()
    # Start-up: 3N slots of movement before the position is valid.
    await Timer((START_CLOCK + 40 * SLOT_CLOCKS) * PERIOD_NS, unit="ns")
    assert int(dut.pos_valid.value) == 1 and int(dut.mode.value) == 1

    for kind in ("abs", "hybrid", "incremental", "tracks", "status", "fine"):
        result = await host(bridge, "read", *link_args(bridge), "--kind", kind, "--json")
        assert result.returncode == 0, result.stderr
        record = json.loads(result.stdout)
        check_answer(record, truth, bridge)
        assert record["crc_errors"] == 0
        dut._log.info("prenc host read --kind %s: %s", kind, result.stdout.strip())

    out = SIM_BUILD / "prenc_board_e2e"
    out.mkdir(parents=True, exist_ok=True)
    log = out / "log.csv"
    bridge.corrupt_byte = bridge.sent + 21 + 14 * 5 + 7  # after STATUS, inside the 6th answer
    result = await host(bridge, "log", *link_args(bridge), "--out", str(log), "--kind", "hybrid",
                        "--rate", "2000", "--count", "60")
    assert result.returncode == 0, result.stderr
    progress = result.stderr.strip().splitlines()
    assert progress and "crc errors 1" in progress[-1], result.stderr
    rows = list(csv.DictReader(log.open()))
    assert len(rows) == 60
    for row in rows:
        check_answer(row, truth, bridge)
    gaps = np.diff([int(r["board_time_us"]) for r in rows])
    assert set(gaps.tolist()) <= {500, 501, 1000, 1001}, sorted(set(gaps.tolist()))  # one lost to the CRC
    assert int((gaps >= 1000).sum()) <= 1
    dut._log.info("prenc host log: %d rows, board time gaps %s us; stderr: %s", len(rows),
                  sorted(set(gaps.tolist())), result.stderr.strip().splitlines()[-1])

    result = await host(bridge, "monitor", *link_args(bridge), "--rate", "1000", "--count", "20")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.strip().splitlines()  # text mode reads each \r as a new line
    assert len(lines) == 20, lines
    last = lines[-1]
    assert "NORMAL" in last and "valid" in last and "crc 0" in last, last
    rpm = float(last.split("rpm")[0].split()[-1])
    true_rpm = CLK_HZ / SLOT_CLOCKS / (1 << N) * 60
    assert abs(rpm - true_rpm) < 0.02 * true_rpm, (rpm, true_rpm, last)
    dut._log.info("prenc host monitor: %s (true speed %.1f rpm)", last, true_rpm)

    result = await host(bridge, "plot", str(log), "--out", str(out / "log.png"))
    assert result.returncode == 0 and (out / "log.png").stat().st_size > 10_000, result.stderr
    # The fine kind: a log with the board's velocity, and its plot (a velocity panel).
    fine_log = out / "fine.csv"
    result = await host(bridge, "log", *link_args(bridge), "--out", str(fine_log), "--kind", "fine",
                        "--rate", "2000", "--count", "20")
    assert result.returncode == 0, result.stderr
    rows = list(csv.DictReader(fine_log.open()))
    assert len(rows) == 20 and all(r["velocity_valid"] == "1" for r in rows), rows[:2]
    for row in rows:
        check_answer(row, truth, bridge)
    result = await host(bridge, "plot", str(fine_log), "--out", str(out / "fine.png"))
    assert result.returncode == 0 and (out / "fine.png").stat().st_size > 10_000, result.stderr
    os.close(bridge.slave)


def test_prenc_board_host_through_pty():
    run(__file__, TOPLEVEL, "verilator",
        parameters={"N": N, "FILTER": FILTER, "ROM_FILE": rom_file(N), "CLK_HZ": CLK_HZ, "BAUD": BAUD})
