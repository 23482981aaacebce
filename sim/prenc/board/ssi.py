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


def frame_bits(position: int, width: int, valid: bool, gray_code: bool, error_bit: bool = True,
               warning: bool | None = None) -> list[int]:
    """The bits on the data line, first to last; with `warning` (not None) the warning
    bit after the error bit (prenc_ssi's WARN_BIT = 1)."""
    if warning is not None and not error_bit:
        raise ValueError("a warning bit needs the error bit")
    if not 0 <= position < 1 << width:
        raise ValueError(f"position {position} does not fit in {width} bits")
    coded = gray(position) if gray_code else position
    bits = [(coded >> (width - 1 - i)) & 1 for i in range(width)]
    return bits + ([0 if valid else 1] if error_bit else []) + ([] if warning is None else [int(warning)])


def decode(bits: list[int], width: int, gray_code: bool, error_bit: bool = True) -> tuple[int, bool]:
    """(position, valid) from the bits a controller sampled."""
    if len(bits) != width + (1 if error_bit else 0):
        raise ValueError(f"{len(bits)} bits for a {width}-bit frame{' with error bit' if error_bit else ''}")
    coded = 0
    for bit in bits[:width]:
        coded = coded << 1 | bit
    position = from_gray(coded) if gray_code else coded
    return position, (bits[width] == 0) if error_bit else True


def decode_with_warning(bits: list[int], width: int, gray_code: bool) -> tuple[int, bool, bool]:
    """(position, valid, warning) from a frame with the error and the warning bit."""
    if len(bits) != width + 2:
        raise ValueError(f"{len(bits)} bits for a {width}-bit frame with error and warning bits")
    position, valid = decode(bits[:-1], width, gray_code)
    return position, valid, bits[-1] == 1
