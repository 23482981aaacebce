# SPDX-License-Identifier: Apache-2.0
"""Yosys's line numbers of a Verilog source (YoWASP Yosys 0.70).

Yosys's preprocessor counts each `resetall as three lines, so after the one at the top
of every RTL file its line numbers run 2 ahead of the file's. The formal tools
(scripts/mutate.py, scripts/formal_covers.py) map between the two with these.
"""

from __future__ import annotations

from pathlib import Path


def yosys_numbers(path: Path) -> list[int]:
    """Yosys's number of each line of `path` (index 0 is the file's line 1)."""
    numbers, shift = [], 0
    for number, line in enumerate(path.read_text().splitlines(), 1):
        numbers.append(number + shift)
        if line.strip().startswith("`resetall"):
            shift += 2
    return numbers


def file_line(path: Path, yosys_line: int) -> int:
    """The line of `path` that Yosys calls `yosys_line` (itself if there is none)."""
    numbers = yosys_numbers(path)
    return numbers.index(yosys_line) + 1 if yosys_line in numbers else yosys_line
