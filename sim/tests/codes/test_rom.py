# SPDX-License-Identifier: Apache-2.0
"""`prenc rom` / `prenc tracks`: tables, vendor formats and bad input."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from prenc.cli.main import main
from prenc.codes.debruijn import Code
from prenc.codes.rom import FORMATS

PRENC = [sys.executable, "-m", "prenc.cli.main"]


def prenc(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(PRENC + list(args), capture_output=True, text=True, timeout=120)


def parse(path: Path, fmt: str) -> list[int]:
    """Read a table back with each vendor format's rules, independent of the writer."""
    text = path.read_text()
    if fmt == "hex":
        return [int(line, 16) for line in text.split()]
    if fmt == "bin":
        return [int(line, 2) for line in text.split()]
    if fmt == "mif":
        head, _, body = text.partition("CONTENT BEGIN")
        depth = int(re.search(r"DEPTH\s*=\s*(\d+);", head).group(1))
        assert re.search(r"ADDRESS_RADIX\s*=\s*HEX;", head) and re.search(r"DATA_RADIX\s*=\s*HEX;", head)
        assert body.rstrip().endswith("END;")
        table = [None] * depth
        for addr, data in re.findall(r"([0-9a-fA-F]+)\s*:\s*([0-9a-fA-F]+);", body):
            table[int(addr, 16)] = int(data, 16)
        return table
    if fmt == "coe":
        joined = " ".join(text.split("memory_initialization_vector=")[1].split())
        assert "memory_initialization_radix=16;" in text and joined.endswith(";")
        return [int(v, 16) for v in joined.rstrip(";").split(",")]
    if fmt == "mem":
        lines = text.splitlines()
        assert lines[:6] == ["#Format=Hex", f"#Depth={len(lines) - 6}", lines[2], "#AddrRadix=3", "#DataRadix=3", "#Data"]
        return [int(l, 16) for l in lines[6:]]
    raise AssertionError(fmt)


def test_default_hex_table_is_the_datasheet_table(tmp_path):
    out = tmp_path / "rom.hex"
    result = prenc("rom", "--bits", "10", "--taps", "10,3", "--format", "hex", "-o", str(out))
    assert result.returncode == 0, result.stderr
    lines = out.read_text().splitlines()
    assert len(lines) == 1024
    assert all(re.fullmatch(r"[0-9a-f]{3}", l) for l in lines)
    assert int(lines[512], 16) == 0  # address 0b1000000000 is W(0)
    assert int(lines[0], 16) == 1
    assert int(lines[1], 16) == 2


@pytest.mark.parametrize("fmt", FORMATS)
@pytest.mark.parametrize("n", [2, 4, 10, 12, 16])
def test_every_format_holds_the_model_table(tmp_path, fmt, n):
    out = tmp_path / f"rom.{fmt}"
    assert main(["rom", "--bits", str(n), "--format", fmt, "-o", str(out)]) == 0
    table = parse(out, fmt)
    assert table == Code(n).positions.tolist()


def test_tracks_are_the_two_code_tracks(tmp_path):
    out = tmp_path / "tracks.txt"
    assert main(["tracks", "--bits", "10", "-o", str(out)]) == 0
    t1, t2 = out.read_text().split()
    code = Code(10)
    s = "".join(map(str, code.sequence.tolist()))
    assert t1 == s
    d = 2**9 + 9
    assert t2 == s[d:] + s[:d]
    csv = tmp_path / "tracks.csv"
    assert main(["tracks", "--bits", "4", "--format", "csv", "-o", str(csv)]) == 0
    rows = csv.read_text().splitlines()
    assert rows[0] == "slot,track1,track2" and len(rows) == 17


@pytest.mark.parametrize(
    "args, message",
    [
        (["rom", "--format", "srec"], "invalid choice"),
        (["rom", "--bits", "1"], "out of range 2..24"),
        (["rom", "--bits", "25"], "out of range 2..24"),
        (["rom", "--bits", "ten"], "N must be an integer"),
        (["rom", "--bits", "10", "--taps", "10,5"], "not primitive"),
        (["rom", "--bits", "10", "--taps", "9,4"], "largest tap must equal N"),
        (["rom", "--bits", "10", "--taps", "10,x"], "taps must be integers"),
        (["rom", "--bits", "17", "--format", "mem"], "at most 65536 words"),
        (["rom", "-o", "/nonexistent-folder/rom.hex"], "no such folder"),
    ],
)
def test_bad_input_gives_one_clear_line_and_no_file(tmp_path, args, message):
    out = tmp_path / "out.hex"
    if "-o" not in args:
        args = args + ["-o", str(out)]
    result = prenc(*args)
    assert result.returncode != 0
    assert result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert message in lines[0]
    assert lines[0].startswith("prenc")
    assert not out.exists()
    assert list(tmp_path.iterdir()) == []


def test_output_into_a_folder_path_is_an_error(tmp_path):
    result = prenc("rom", "-o", str(tmp_path))
    assert result.returncode == 1
    assert "is a folder" in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_a_failed_run_keeps_an_existing_table(tmp_path):
    out = tmp_path / "rom.hex"
    assert main(["rom", "--bits", "4", "-o", str(out)]) == 0
    before = out.read_bytes()
    result = prenc("rom", "--bits", "17", "--format", "mem", "-o", str(out))
    assert result.returncode == 1
    assert out.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["rom.hex"]


def test_taps_command_checks_a_set():
    ok = prenc("taps", "--bits", "10")
    assert ok.returncode == 0 and "x^10 + x^7 + 1" in ok.stdout
    assert "TAPS = 32'h00000204" in ok.stdout  # bits 9 and 2: taps 10 and 3
    bad = prenc("taps", "--bits", "8", "--taps", "8,4")
    assert bad.returncode == 1 and "not primitive" in bad.stderr
