# SPDX-License-Identifier: Apache-2.0
"""The matrix-code reader: the integer model of rtl/matrix/prenc_matrix_reader.v.

From one frame: the darkest and brightest pixel of the tracks' rows, the edge
energy of each phase x mod cell (the sum, over those rows, of the steps
|pixel(x) - pixel(x-1)| that are a peak of their row),
the phase with the most energy (the first on a tie) as the first cell boundary,
the centre pixel of n whole cells per track from there, each compared with
(darkest + brightest) // 2, the window, its column parities and the table.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .code import MatrixCode
from .sensor import Geometry

DEFAULT_MIN_CONTRAST = 32


@dataclass(frozen=True)
class Reading:
    position: int
    phase: int
    cells: int            # n*n bits, first column most significant, track 0 first
    ok: bool
    low_contrast: bool
    uncertain: bool
    checksum_error: bool


def read_frame(frame: np.ndarray, geom: Geometry, code: MatrixCode, table: np.ndarray | None = None,
               min_contrast: int = DEFAULT_MIN_CONTRAST, ready: bool = True) -> Reading:
    """The reading the RTL gives for this frame (height x width integers)."""
    if code.n != geom.n:
        raise ValueError(f"code order {code.n} and geometry order {geom.n} differ")
    table = code.positions if table is None else table
    frame = np.asarray(frame, dtype=np.int64)
    band = frame[geom.band]
    darkest, brightest = int(band.min()), int(band.max())
    # d[:, x] = |pixel(x) - pixel(x-1)| (column 0 unused); pair x counts where it is a
    # peak of its row: >= the pair on its left, > the pair on its right. Pairs 1 and
    # width-1 lack a neighbour and never count, so an edge cut by the image border
    # cannot pull the phase with its tail.
    d = np.zeros_like(band)
    d[:, 1:] = np.abs(np.diff(band, axis=1))
    energy = [0] * geom.cell
    for x in range(2, geom.width - 1):
        peak = (d[:, x] >= d[:, x - 1]) & (d[:, x] > d[:, x + 1])
        energy[x % geom.cell] += int(d[peak, x].sum())
    phase = int(np.argmax(energy))
    contrast = brightest - darkest
    threshold = darkest + contrast // 2
    margin = contrast >> 3
    cells = 0
    uncertain = False
    for i in range(geom.n):
        x = phase + geom.cell // 2 + i * geom.cell
        for t in range(geom.n):
            v = int(frame[geom.centre_row(t), x])
            bit = v > threshold
            cells = (cells << 1) | int(bit)
            uncertain |= abs(v - threshold) <= margin
    n = geom.n
    checksum_error = False
    address = 0
    for i in range(n):
        col = (cells >> ((n - 1 - i) * n)) & ((1 << n) - 1)
        if code.checksum:
            checksum_error |= bool(bin(col).count("1") & 1)
            address = (address << (n - 1)) | (col >> 1)
        else:
            address = (address << n) | col
    low_contrast = contrast < min_contrast
    ok = ready and not low_contrast and not uncertain and not checksum_error
    return Reading(int(table[address]), phase, cells, ok, low_contrast, uncertain, checksum_error)


def latency(n: int) -> int:
    """Clocks from the frame's last pixel to out_valid (the RTL's pipeline)."""
    return n * n + 5
