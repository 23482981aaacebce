# SPDX-License-Identifier: Apache-2.0
"""The register map is described once (rtl/bus/prenc_wb.rdl): the committed C header,
register map page are what scripts/regmap.py generates from it,
the RTL's addresses are the RDL's, and the C header compiles with the example."""

from __future__ import annotations

import re
import subprocess
import sys

from runner import REPO

sys.path.insert(0, str(REPO / "scripts"))
import regmap  # noqa: E402


def test_the_generated_files_are_up_to_date():
    root = regmap.compile_rdl()
    for path, text in regmap.outputs(root).items():
        assert path.read_text() == text, f"{path.relative_to(REPO)} is stale: run scripts/regmap.py"


def test_the_rtl_addresses_are_the_rdl_s():
    source = (REPO / "rtl" / "bus" / "prenc_wb.v").read_text()
    rtl = {m.group(1): int(m.group(2), 16)
           for m in re.finditer(r"localparam \[4:0\] A_(\w+)\s*=\s*5'h([0-9A-Fa-f]+);", source)}
    registers = regmap.registers(regmap.compile_rdl())
    rdl = {reg["name"]: reg["offset"] // 4 for reg in registers}
    assert rtl == rdl
    ids = {m.group(1): int(m.group(2).replace("_", ""), 16)
           for m in re.finditer(r"localparam \[31:0\] (ID|VERSION)\s*=\s*32'h([0-9A-Fa-f_]+);", source)}
    resets = {reg["name"]: sum((f["reset"] or 0) << f["lsb"] for f in reg["fields"])
              for reg in registers}
    assert ids == {"ID": resets["ID"], "VERSION": resets["VERSION"]}


def test_the_c_header_compiles_with_the_example(tmp_path):
    proc = subprocess.run(["gcc", "-std=c11", "-Wall", "-Wextra", "-Werror", "-Wno-unused-function",
                           "-I", str(REPO / "sw"), "-c", str(REPO / "sw" / "prenc_wb_example.c"),
                           "-o", str(tmp_path / "example.o")], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
