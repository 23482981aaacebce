# SPDX-License-Identifier: Apache-2.0
"""SSI, the synchronous serial interface of absolute encoders: the controller's side.

The model of what rtl/board/prenc_ssi.v sends, used by its testbench and documentation:
a frame is the position, MSB first, Gray-coded or binary, then an error bit
(1 = the position is not valid).
"""

from __future__ import annotations


def gray(value: int) -> int:
    return value ^ (value >> 1)


def from_gray(code: int) -> int:
    value = 0
    while code:
        value ^= code
        code >>= 1
    return value


def frame_bits(position: int, width: int, valid: bool, gray_code: bool, error_bit: bool = True) -> list[int]:
    """The bits on the data line, first to last."""
    if not 0 <= position < 1 << width:
        raise ValueError(f"position {position} does not fit in {width} bits")
    coded = gray(position) if gray_code else position
    bits = [(coded >> (width - 1 - i)) & 1 for i in range(width)]
    return bits + ([0 if valid else 1] if error_bit else [])


def decode(bits: list[int], width: int, gray_code: bool, error_bit: bool = True) -> tuple[int, bool]:
    """(position, valid) from the bits a controller sampled."""
    if len(bits) != width + (1 if error_bit else 0):
        raise ValueError(f"{len(bits)} bits for a {width}-bit frame{' with error bit' if error_bit else ''}")
    coded = 0
    for bit in bits[:width]:
        coded = coded << 1 | bit
    position = from_gray(coded) if gray_code else coded
    return position, (bits[width] == 0) if error_bit else True
