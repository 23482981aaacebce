# SPDX-License-Identifier: Apache-2.0
"""`make equiv` (scripts/equiv.py) proves a behaviour-preserving rewrite and rejects a
changed circuit: the quadrature decoder at HEAD against HEAD's own text rewritten two
ways, and the whole core (`--whole`, with its ROM) against itself and a mutant. Only
HEAD's files are used, so the test does not depend on the working tree.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

from runner import REPO, SIM_BUILD

sys.path.insert(0, str(REPO / "scripts"))
import equiv  # noqa: E402

MODULE = "prenc_quadrature"
STEP = "count_reg + {{(COUNT_WIDTH - 1){delta[1]}}, 1'b1}"  # one adder: +1 or -1


def head_source(module: str = MODULE) -> str:
    return subprocess.run(["git", "show", f"HEAD:rtl/core/{module}.v"], cwd=REPO, check=True,
                          capture_output=True, text=True).stdout


def run(tmp_name: str, text: str, module: str = MODULE, depth: int = 3,
        whole: bool = False) -> tuple[bool, str]:
    out = SIM_BUILD / "equiv" / tmp_name
    out.mkdir(parents=True, exist_ok=True)
    source = out / f"{module}_edit.v"
    source.write_text(text)
    return equiv.check(module, "HEAD", source, {}, depth, out, whole=whole)


@pytest.mark.synth
def test_a_rewrite_of_the_count_is_proven_equivalent():
    text = head_source()
    assert STEP in text
    proven, summary = run("rewrite", text.replace(STEP, "(delta[1] ? count_reg - 1'b1 : count_reg + 1'b1)"))
    assert proven, summary


@pytest.mark.synth
def test_a_count_that_steps_the_wrong_way_is_not():
    text = head_source()
    proven, summary = run("mutant", text.replace(STEP, "count_reg - {{(COUNT_WIDTH - 1){delta[1]}}, 1'b1}"))
    assert not proven
    assert "count_reg" in summary and "NOT proven" in summary


@pytest.mark.synth
def test_a_changed_port_list_is_an_error():
    text = head_source().replace("output wire", "output wire [0:0] extra_port,\n  output wire", 1)
    with pytest.raises(equiv.FlowError, match="ports differ"):
        run("ports", text)


@pytest.mark.synth
def test_the_whole_core_with_its_rom_is_proven_equal_to_itself():
    """prenc_core reads its ROM at elaboration: equiv.py writes the default disc's table
    and compares the whole hierarchy, the submodules too taken at the base revision."""
    proven, summary = run("core-same", head_source("prenc_core"), "prenc_core", 2, whole=True)
    assert proven, summary
    assert (SIM_BUILD / "equiv" / "core-same" / "prenc_rom_n10.hex").is_file()


@pytest.mark.synth
def test_a_core_that_adds_the_window_base_is_not():
    text = head_source("prenc_core")
    assert "conv1_j - base1_j" in text
    proven, summary = run("core-mutant", text.replace("conv1_j - base1_j", "conv1_j + base1_j", 1),
                          "prenc_core", 2, whole=True)
    assert not proven
    assert "off1_j_reg" in summary and "NOT proven" in summary
