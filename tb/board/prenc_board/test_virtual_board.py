# SPDX-License-Identifier: Apache-2.0
"""The virtual board as a user starts it: `scripts/board_sim.py` (what `make board-sim`
runs) in its own process, and `prenc host read` on the pty it prints.

Each answer carries the board's time in microseconds since reset; the virtual
board's disc turns at a known speed (prenc.virtual.profiles), so the answer must equal the
true position at that time, less the core's latency, within the microsecond's
resolution. The virtual board also reports how fast it simulates.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

from prenc.virtual.encoder import Disc
from prenc.virtual.profiles import profile
from prenc.virtual.scenarios import core_latency
from runner import REPO, SIM_BUILD

N, CLK_MHZ, FILTER, RPM = 10, 30, 2, 600  # CLK_MHZ: board_sim.py's default, the iCEBreaker's clock
RESET_CLOCKS = 6.5  # the virtual board holds reset 6 clocks; time_us starts after it


def host(port: str, *args: str) -> dict:
    cmd = [sys.executable, "-m", "prenc.cli.main", "host", "read", "--port", port, "--timeout", "20",
           "--json", *args]
    env = dict(os.environ, PYTHONPATH=str(REPO / "sim"))
    out = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=120)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def truth(record: dict) -> set[int]:
    """True hybrid positions over the clocks that the answer's time_us can mean."""
    theta = profile("constant", RPM, N, CLK_MHZ * 1e6)
    first = RESET_CLOCKS + int(record["board_time_us"]) * CLK_MHZ - core_latency(FILTER) - 1
    clocks = np.arange(int(first) - FILTER - 2, int(first) + CLK_MHZ + FILTER + 3)
    return set(Disc(N).hybrid(theta(clocks)).tolist())


def test_prenc_host_reads_the_virtual_board():
    port_file = SIM_BUILD / "virtual_board.port"
    port_file.unlink(missing_ok=True)
    cmd = [sys.executable, str(REPO / "scripts" / "board_sim.py"), "--clock-mhz", str(CLK_MHZ), "--rpm", str(RPM),
           "--seconds", "0", "--port-file", str(port_file)]
    log = (SIM_BUILD / "virtual_board.log").open("w")
    sim = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        deadline = time.monotonic() + 300
        while not port_file.exists():
            assert sim.poll() is None, (SIM_BUILD / "virtual_board.log").read_text()[-3000:]
            assert time.monotonic() < deadline, "the virtual board did not start in 300 s"
            time.sleep(0.2)
        port = port_file.read_text().strip()
        for _ in range(100):  # until the reader has found its position
            if host(port, "--kind", "abs")["valid"]:
                break
        else:
            raise AssertionError("the virtual board's position never became valid")
        for kind in ("hybrid", "abs", "hybrid", "tracks", "hybrid"):
            record = host(port, "--kind", kind)
            assert record["valid"] and record["mode"] == "NORMAL" and record["direction"] == "cw", record
            hybrid = truth(record)
            if kind == "hybrid":
                assert record["position"] in hybrid, (record, sorted(hybrid))
            elif kind == "abs":
                assert record["position"] in {h >> 2 for h in hybrid}, (record, sorted(hybrid))
            else:
                assert record["track1"] in {h >> 2 for h in hybrid}, (record, sorted(hybrid))
        time.sleep(5.5)  # one speed report
    finally:
        os.killpg(sim.pid, signal.SIGTERM)
        sim.wait(timeout=30)
        log.close()
    text = (SIM_BUILD / "virtual_board.log").read_text()
    assert f"UART on {port}" in text
    assert "x slower than real time" in text, text[-2000:]


def test_board_sim_builds_the_board_with_edge_tolerance():
    # `make board-sim ARGS="--printed --edge-tolerance 31"`: the option reaches prenc_board's
    # parameter; a value out of range is refused before anything is built.
    sys.path.insert(0, str(REPO / "scripts"))
    import board_sim

    args = board_sim.parse(["--printed", "--edge-tolerance", "31"])
    assert board_sim.board_parameters(args, 30_000_000)["EDGE_TOLERANCE"] == 31
    assert "EDGE_TOLERANCE" not in board_sim.board_parameters(board_sim.parse([]), 30_000_000)
    with pytest.raises(SystemExit):
        board_sim.parse(["--edge-tolerance", "61"])
