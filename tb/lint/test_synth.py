# SPDX-License-Identifier: Apache-2.0
"""Every top synthesizes for iCE40 with Yosys: no latches, no warnings, and
`check -assert` passes (it fails on multiple drivers, undriven nets and loops).

Tops with a ROM_FILE parameter get a generated ROM of their default N; tops with a
TABLE_FILE (the matrix-code table, "file" by default) get the n = 3 table.
"""

from __future__ import annotations

import re

import pytest

from runner import RTL, list_file, matrix_rom_file, rom_file
from yosys import synthesize

TOPS = sorted(p.stem for p in RTL.glob("*/*.f"))


def parameters_for(top: str) -> dict:
    source = list_file(top).with_suffix(".v").read_text()
    if re.search(r'parameter\s+\[71:0\]\s+TABLE\s*=\s*"file"', source):
        extra = {"CELL": 3, "TOP": 3} if "PIXEL_BITS" in source else {}
        return {"N": 3, "TABLE_FILE": matrix_rom_file(3), **extra}
    if "ROM_FILE" not in source:
        return {}
    n = int(re.search(r"parameter\s+integer\s+N\s*=\s*(\d+)", source).group(1))
    return {"ROM_FILE": rom_file(n)}


@pytest.mark.synth
@pytest.mark.parametrize("top", TOPS)
def test_synthesizes_without_latches_or_warnings(top):
    result = synthesize(top, "ice40", parameters_for(top))
    assert result.latches == 0, result.cells
    assert result.warnings == [], "\n".join(result.warnings)
    assert sum(result.cells.values()) > 0
