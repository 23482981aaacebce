# SPDX-License-Identifier: Apache-2.0
"""An image sensor looking at a matrix-code disc: the test images of the reader.

The sensor sees a small patch of the n tracks (the paper's prototype: 15 x 15
pixels). Along x the code moves: pixel x shows the disc at theta + x / cell cells,
where theta is the angle of the image's left edge, in cells. Across the rows the
tracks are fixed: track t covers rows top + t*cell .. top + (t+1)*cell (plus a
radial misalignment). Outside the tracks the disc is dark.

The image is rendered on a grid `supersample` times finer than the pixels, blurred
by a Gaussian (the optics), averaged over each pixel (its area), then given
Gaussian noise and quantised to `pixel_bits`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .code import MatrixCode, check_order


@dataclass(frozen=True)
class Geometry:
    """Where the cells fall on the sensor: the reader's parameters N, CELL, WIDTH,
    HEIGHT, TOP and PIXEL_BITS."""

    n: int
    cell: int = 3
    width: int = 15
    height: int = 15
    top: int = 1
    pixel_bits: int = 8

    def __post_init__(self) -> None:
        check_order(self.n)
        if not 3 <= self.cell <= 16:
            raise ValueError(f"cell = {self.cell} pixels is out of range 3..16")
        if not (self.n + 1) * self.cell <= self.width <= 64:
            raise ValueError(f"width = {self.width} is out of range (n+1)*cell = "
                             f"{(self.n + 1) * self.cell}..64")
        if not 0 <= self.top <= 255 or not self.top + self.n * self.cell <= self.height <= 255:
            raise ValueError(f"height = {self.height} and top = {self.top} must hold the "
                             f"{self.n * self.cell} rows of the tracks (height <= 255)")
        if not 4 <= self.pixel_bits <= 12:
            raise ValueError(f"pixel_bits = {self.pixel_bits} is out of range 4..12")

    def centre_row(self, track: int) -> int:
        return self.top + track * self.cell + self.cell // 2

    @property
    def band(self) -> slice:
        return slice(self.top, self.top + self.n * self.cell)

    def parameters(self) -> dict:
        """The reader's RTL parameters for this geometry."""
        return {"N": self.n, "CELL": self.cell, "WIDTH": self.width, "HEIGHT": self.height,
                "TOP": self.top, "PIXEL_BITS": self.pixel_bits}


def default_geometry(n: int) -> Geometry:
    """A 15 x 15 sensor: cells of 5 pixels for n = 2, 3 pixels for n = 3 and 4."""
    check_order(n)
    if n == 2:
        return Geometry(2, cell=5, top=2)
    if n == 3:
        return Geometry(3, cell=3, top=3)
    return Geometry(4, cell=3, top=1)


@dataclass(frozen=True)
class Optics:
    blur: float = 0.5       # Gaussian sigma of the optics, pixels
    noise: float = 3.0      # sigma of the additive noise, grey levels
    dark: float = 40.0      # grey level of an opaque cell
    bright: float = 200.0   # grey level of a light cell
    radial: float = 0.0     # radial misalignment of the tracks, pixels (down)


def truth(theta: float, geom: Geometry, length: int) -> tuple[int, int]:
    """The reading a correct reader gives for an image at angle theta: the position
    of the first whole cell and the pixel where it starts, with the left edge
    rounded to the nearest pixel."""
    fine = round(theta * geom.cell)
    position = -((-fine) // geom.cell)
    return position % length, position * geom.cell - fine


def _blur(image: np.ndarray, sigma: float) -> np.ndarray:
    if sigma <= 0:
        return image
    radius = max(1, int(math.ceil(3 * sigma)))
    k = np.exp(-0.5 * (np.arange(-radius, radius + 1) / sigma) ** 2)
    k /= k.sum()
    out = np.apply_along_axis(lambda r: np.convolve(r, k, mode="same"), 1, image)
    return np.apply_along_axis(lambda c: np.convolve(c, k, mode="same"), 0, out)


def render(code: MatrixCode, theta: float, geom: Geometry, optics: Optics = Optics(),
           rng: np.random.Generator | None = None, flip: tuple[int, int] | None = None,
           supersample: int = 8) -> np.ndarray:
    """The image (height x width, integers) of the code at angle theta (cells).

    flip = (track, position) prints that one cell inverted (a defect on the disc)."""
    s = supersample
    margin = max(1, int(math.ceil(3 * optics.blur)) + 1)  # pixels rendered beyond each side
    ys = (np.arange(-margin * s, (geom.height + margin) * s) + 0.5) / s
    xs = (np.arange(-margin * s, (geom.width + margin) * s) + 0.5) / s
    cells = code.cells()
    if flip is not None:
        cells = cells.copy()
        t, p = flip
        cells[t, p % code.length] ^= 1
    col = np.floor(theta + xs / geom.cell).astype(np.int64) % code.length
    v = (ys - geom.top - optics.radial) / geom.cell
    track = np.floor(v).astype(np.int64)
    inside = (v >= 0) & (track < geom.n)
    lit = np.zeros((len(ys), len(xs)), dtype=bool)
    lit[inside, :] = cells[track[inside]][:, col].astype(bool)
    fine = np.where(lit, optics.bright, optics.dark).astype(float)
    fine = _blur(fine, optics.blur * s)
    fine = fine[margin * s:(margin + geom.height) * s, margin * s:(margin + geom.width) * s]
    pixels = fine.reshape(geom.height, s, geom.width, s).mean(axis=(1, 3))
    if optics.noise > 0:
        rng = rng if rng is not None else np.random.default_rng(0)
        pixels = pixels + rng.normal(0.0, optics.noise, pixels.shape)
    top = (1 << geom.pixel_bits) - 1
    return np.clip(np.rint(pixels), 0, top).astype(np.int64)
