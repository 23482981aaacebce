# SPDX-License-Identifier: Apache-2.0
"""A calibration run as a user makes it, without a board: `scripts/board_sim.py` (what
`make board-sim` runs) with a printed disc and the calibration table (CAL = 1, empty),
then `prenc calibrate --apply` on its pty, then `prenc host read --kind fine`.

Expected values: the disc's definition. The table must hold the printed disc's true
edges (prenc.virtual.edge_timing.true_corrections, less their mean: the table's zero),
and the fine position, read before and after, is compared with the true angle at the
answer's board time (prenc.virtual.profiles): the printed disc's errors before, a
small fraction of them after.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time

import numpy as np

from prenc.cal.table import read
from prenc.virtual.edge_timing import true_corrections
from prenc.virtual.fine_bench import PRINTED
from prenc.virtual.profiles import profile
from runner import REPO, SIM_BUILD

N, CLK_MHZ, BAUD, RPM, FINE_BITS = 6, 4, 1_000_000, 1500, 8
RESET_CLOCKS = 6.5  # the virtual board holds reset 6 clocks; time_us starts after it


def prenc(*args: str, timeout: float = 300) -> subprocess.CompletedProcess:
    env = dict(os.environ, PYTHONPATH=str(REPO / "sim"))
    out = subprocess.run([sys.executable, "-m", "prenc.cli.main", *args], capture_output=True, text=True,
                         env=env, timeout=timeout)
    assert out.returncode == 0, out.stderr
    return out


def fine_errors(port: str, count: int = 8) -> np.ndarray:
    """The fine position against the true angle at each answer's board time, in slots."""
    theta = profile("constant", RPM, N, CLK_MHZ * 1e6)
    out = []
    for _ in range(count):
        record = json.loads(prenc("host", "read", "--port", port, "--kind", "fine", "--timeout", "20",
                                  "--json").stdout)
        assert record["valid"] and record["fine_bits"] == FINE_BITS, record
        clock = RESET_CLOCKS + record["board_time_us"] * CLK_MHZ
        truth = float(theta(np.array([clock]))[0]) % (1 << N)
        err = record["fine_position"] / (4 << FINE_BITS) - truth
        out.append((err + (1 << N) / 2) % (1 << N) - (1 << N) / 2)
    return np.array(out)


def test_prenc_calibrate_on_the_virtual_board(tmp_path):
    port_file = SIM_BUILD / "virtual_board_cal.port"
    port_file.unlink(missing_ok=True)
    cmd = [sys.executable, str(REPO / "scripts" / "board_sim.py"), "--bits", str(N), "--clock-mhz", str(CLK_MHZ),
           "--baud", str(BAUD), "--rpm", str(RPM), "--fine-bits", str(FINE_BITS), "--printed", "--cal",
           "--port-file", str(port_file)]
    log_path = SIM_BUILD / "virtual_board_cal.log"
    log = log_path.open("w")
    sim = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        deadline = time.monotonic() + 600
        while not port_file.exists():
            assert sim.poll() is None, log_path.read_text()[-3000:]
            assert time.monotonic() < deadline, "the virtual board did not start in 600 s"
            time.sleep(0.2)
        port = port_file.read_text().strip()
        for _ in range(100):  # until the reader has found its position
            if json.loads(prenc("host", "read", "--port", port, "--kind", "abs", "--timeout", "20",
                                "--json").stdout)["valid"]:
                break
        before = fine_errors(port)
        table_path = tmp_path / "disc.cal"
        out = prenc("calibrate", "--port", port, "--out", str(table_path), "--turns", "10", "--apply",
                    "--timeout", "20").stdout
        assert "the board uses the table now" in out, out
        after = fine_errors(port)
    finally:
        os.killpg(sim.pid, signal.SIGTERM)
        sim.wait(timeout=30)
        log.close()
    c = true_corrections(PRINTED, N)
    table = read(table_path, n=N)
    assert np.sqrt(np.mean(((table.quarters - (c - c.mean())) / 4) ** 2)) < 1 / 256
    zero = -c.mean() / 4           # the table's zero against the shaft's (docs/calibration.md)
    print(f"fine position against the truth, slots RMS / max: before {np.sqrt(np.mean(before ** 2)):.4f} / "
          f"{np.max(np.abs(before)):.4f}, after {np.sqrt(np.mean((after - zero) ** 2)):.4f} / "
          f"{np.max(np.abs(after - zero)):.4f} (zero {zero:+.4f})")
    assert np.sqrt(np.mean(before ** 2)) > 0.05, before
    assert np.max(np.abs(after - zero)) < 1 / 64, (after, zero)
