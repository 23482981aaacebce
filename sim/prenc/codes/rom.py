# SPDX-License-Identifier: Apache-2.0
"""Conversion ROM tables and disc track patterns, in the formats FPGA tools load.

The conversion ROM maps a code word to its slot: address w(p), data p. Both are N
bits wide and the table has L = 2^N words.

Formats (one file each, text, data of address k on the k-th data line):
- hex: Verilog `$readmemh`, one hex word per line, no header.
- bin: Verilog `$readmemb`, one binary word per line, no header.
- mif: Intel/Altera Memory Initialization File (Quartus).
- coe: Xilinx coefficient file (Vivado Block Memory Generator).
- mem: Lattice memory initialization file (Diamond / Radiant); the format
  itself allows at most 65536 words, so N <= 16.

Formatting is vectorised with numpy so that N = 24 (16 Mi words) takes seconds.
Files are written to a temporary file beside the target and renamed into place, so
a failed run never leaves a partial table behind.
"""

from __future__ import annotations

import os
import sys
import tempfile
from pathlib import Path
from typing import Callable

import numpy as np

from .debruijn import Code
from .lfsr import check_bits

ROM_MIN_BITS = 2
# 2^24 words of 24 bits are 48 MiB: beyond the block RAM of any FPGA; a table
# larger than this is a mistake rather than a use case.
ROM_MAX_BITS = 24
LATTICE_MEM_MAX_DEPTH = 65536

FORMATS = ("hex", "bin", "mif", "coe", "mem")
TRACK_FORMATS = ("txt", "csv")

_HEX_DIGITS = np.frombuffer(b"0123456789abcdef", dtype=np.uint8)


def write_rom(path: str | os.PathLike, n: int, taps=None, fmt: str = "hex") -> None:
    """Write the conversion ROM of the code (n, taps) to path in format fmt."""
    from .. import __version__

    if fmt not in FORMATS:
        raise ValueError(f"unknown format {fmt!r}; choose one of {', '.join(FORMATS)}")
    code = Code(check_bits(n, ROM_MIN_BITS, ROM_MAX_BITS), taps)
    comment = (
        f"prenc {__version__} conversion ROM: address w(p), data p\n"
        f"N={code.n} taps={','.join(map(str, code.taps))} L={code.length}"
    )
    table = code.positions
    write_atomically(path, lambda: format_rom(table, code.n, fmt, comment))


def _digits(values: np.ndarray, bits_per_digit: int, width: int) -> np.ndarray:
    """ASCII digits of `values` in radix 2^bits_per_digit, zero-padded: (len, width)."""
    out = np.empty((len(values), width), dtype=np.uint8)
    mask = (1 << bits_per_digit) - 1
    v = values.astype(np.uint32)
    for col in range(width):
        shift = bits_per_digit * (width - 1 - col)
        out[:, col] = _HEX_DIGITS[(v >> np.uint32(shift)) & np.uint32(mask)]
    return out


def _rows(*columns) -> bytes:
    """Join per-row columns (byte strings or (len, k) digit arrays) into text."""
    rows = next(len(c) for c in columns if isinstance(c, np.ndarray))
    parts = []
    for c in columns:
        if isinstance(c, np.ndarray):
            parts.append(c)
        else:
            lit = np.frombuffer(c, dtype=np.uint8)
            parts.append(np.broadcast_to(lit, (rows, len(lit))))
    return np.concatenate(parts, axis=1).tobytes()


def _hex_width(bits: int) -> int:
    return (bits + 3) // 4


def format_rom(table: np.ndarray, n: int, fmt: str, comment: str = "") -> bytes:
    """Render a table of 2^n words of n bits in one of FORMATS."""
    depth = len(table)
    hw = _hex_width(n)
    addresses = np.arange(depth, dtype=np.uint32)
    if fmt == "hex":
        return _rows(_digits(table, 4, hw), b"\n")
    if fmt == "bin":
        return _rows(_digits(table, 1, n), b"\n")
    if fmt == "mif":
        head = "".join(f"-- {line}\n" for line in comment.splitlines())
        head += (
            f"WIDTH={n};\nDEPTH={depth};\n\nADDRESS_RADIX=HEX;\nDATA_RADIX=HEX;\n\n"
            "CONTENT BEGIN\n"
        )
        body = _rows(b"  ", _digits(addresses, 4, _hex_width(n)), b" : ", _digits(table, 4, hw), b";\n")
        return head.encode() + body + b"END;\n"
    if fmt == "coe":
        head = "".join(f"; {line}\n" for line in comment.splitlines())
        head += "memory_initialization_radix=16;\nmemory_initialization_vector=\n"
        body = _rows(_digits(table, 4, hw), b",\n")
        return head.encode() + body[:-2] + b";\n"
    if fmt == "mem":
        if depth > LATTICE_MEM_MAX_DEPTH:
            raise ValueError(
                f"the Lattice .mem format holds at most {LATTICE_MEM_MAX_DEPTH} words "
                f"(N <= 16); N = {n} needs {depth}"
            )
        # The header must not carry comments (Lattice's rule), so none are written.
        head = f"#Format=Hex\n#Depth={depth}\n#Width={n}\n#AddrRadix=3\n#DataRadix=3\n#Data\n"
        return head.encode() + _rows(_digits(table, 4, hw), b"\n")
    raise ValueError(f"unknown format {fmt!r}; choose one of {', '.join(FORMATS)}")


def format_tracks(code: Code, shift: int, fmt: str) -> bytes:
    """Track 1 carries s(x) at slot x, track 2 carries s(x + D mod L)."""
    track1 = code.sequence
    track2 = np.roll(code.sequence, -shift)
    if fmt == "txt":
        return b"".join([(track1 + 48).tobytes(), b"\n", (track2 + 48).tobytes(), b"\n"])
    if fmt == "csv":
        rows = (f"{x},{a},{b}\n" for x, (a, b) in enumerate(zip(track1.tolist(), track2.tolist())))
        return ("slot,track1,track2\n" + "".join(rows)).encode()
    raise ValueError(f"unknown track format {fmt!r}; choose one of {', '.join(TRACK_FORMATS)}")


def write_atomically(path: str | os.PathLike, render: Callable[[], bytes]) -> None:
    """Write render()'s bytes to path, or to stdout for '-', never leaving a partial file.

    The target's folder is checked before rendering, so an unwritable path fails
    fast; the data goes to a temporary file in that folder and is renamed into place.
    """
    if str(path) == "-":
        sys.stdout.buffer.write(render())
        sys.stdout.buffer.flush()
        return
    target = Path(path)
    folder = target.parent if str(target.parent) else Path(".")
    if target.is_dir():
        raise OSError(f"{target}: is a folder, not a file")
    if not folder.is_dir():
        raise OSError(f"{folder}: no such folder")
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(render())
        os.chmod(tmp, 0o644)
        os.replace(tmp, target)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise
