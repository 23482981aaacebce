# SPDX-License-Identifier: Apache-2.0
"""Conversion ROMs of matrix codes: address = window, data = position.

The same formats as `prenc rom` (hex, bin, mif, coe, mem). Address and data are
both A = n*n bits (n*(n-1) with the parity track); the address bit order is that
of `prenc.matrix.code` (first column most significant, track 0 the MSB of a
column, the parity bit left out).
"""

from __future__ import annotations

import os

from ..codes.rom import FORMATS, format_rom, write_atomically
from .code import MatrixCode


def rom_bytes(code: MatrixCode, fmt: str = "hex") -> bytes:
    from .. import __version__

    if fmt not in FORMATS:
        raise ValueError(f"unknown format {fmt!r}; choose one of {', '.join(FORMATS)}")
    comment = (
        f"prenc {__version__} matrix-code conversion ROM: address = window, data = position\n"
        f"n={code.n} checksum={int(code.checksum)} A={code.address_bits} L={code.length}; "
        "address: first column most significant, track 0 the MSB of a column"
    )
    return format_rom(code.positions, code.address_bits, fmt, comment)


def write_matrix_rom(path: str | os.PathLike, n: int, checksum: bool = False, fmt: str = "hex") -> None:
    code = MatrixCode(n, checksum)
    write_atomically(path, lambda: rom_bytes(code, fmt))
