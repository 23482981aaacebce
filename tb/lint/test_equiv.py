# SPDX-License-Identifier: Apache-2.0
"""`make equiv` (scripts/equiv.py) proves a behaviour-preserving rewrite and rejects a
changed circuit: the quadrature decoder at HEAD against HEAD's own text rewritten two
ways. Only HEAD's files are used, so the test does not depend on the working tree.
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


def head_source() -> str:
    return subprocess.run(["git", "show", f"HEAD:rtl/core/{MODULE}.v"], cwd=REPO, check=True,
                          capture_output=True, text=True).stdout


def run(tmp_name: str, text: str) -> tuple[bool, str]:
    out = SIM_BUILD / "equiv" / tmp_name
    out.mkdir(parents=True, exist_ok=True)
    source = out / f"{MODULE}_edit.v"
    source.write_text(text)
    return equiv.check(MODULE, "HEAD", source, {}, 3, out)


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


def core_source() -> str:
    return subprocess.run(["git", "show", "HEAD:rtl/core/prenc_core.v"], cwd=REPO, check=True,
                          capture_output=True, text=True).stdout


@pytest.mark.synth
def test_the_whole_core_with_its_rom_is_proven_equal_to_itself():
    """prenc_core reads its ROM at elaboration: equiv.py writes the default disc's table
    and compares the whole hierarchy, the submodules too taken at the base revision."""
    out = SIM_BUILD / "equiv" / "core-same"
    out.mkdir(parents=True, exist_ok=True)
    source = out / "prenc_core_edit.v"
    source.write_text(core_source())
    proven, summary = equiv.check("prenc_core", "HEAD", source, {}, 2, out, whole=True)
    assert proven, summary
    assert (out / "prenc_rom_n10.hex").is_file()


@pytest.mark.synth
def test_a_core_that_adds_the_window_base_is_not():
    text = core_source()
    assert "conv1_j - base1_j" in text
    out = SIM_BUILD / "equiv" / "core-mutant"
    out.mkdir(parents=True, exist_ok=True)
    source = out / "prenc_core_edit.v"
    source.write_text(text.replace("conv1_j - base1_j", "conv1_j + base1_j", 1))
    proven, summary = equiv.check("prenc_core", "HEAD", source, {}, 2, out, whole=True)
    assert not proven
    assert "off1_j_reg" in summary and "NOT proven" in summary
