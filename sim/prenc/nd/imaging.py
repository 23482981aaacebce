# SPDX-License-Identifier: Apache-2.0
"""The imaging simulator of the paper's sections 5 and 6: a camera looks at a cylinder.

A cylinder (radius 55 mm, width 12 mm) carries m sequences of K bits side by side,
track j across width/m of the width, bit b of track j at angles [b, b+1) * 2 pi / K
printed black (0) or white (1); track j is written at phase phi_j (bit b shows
s_j(b + phi_j)). A camera looks at it along a radius, orthographically, with square
pixels of 1 mm (about one pixel per square millimetre of the surface near the centre
of the image). One noise coefficient c scales every imperfection:

- pose: the camera is shifted along the circumference (sigma 0.2c mm) and across it
  (sigma 0.5c mm) and rolled (sigma 1.5c degrees) without the reader knowing;
- optics: Gaussian blur of sigma 0.9c pixels after a 4 x 4 supersampled pixel area;
- dynamic range: the contrast shrinks to 1 - 0.6c of full scale (floor 0.15) about
  mid-grey;
- sensor: additive white Gaussian noise of sigma 0.15c (full scale 1), then B-bit
  quantisation.

The reader samples p points per bit along the centre line of each track at the
nominal geometry (window of n bits centred in the image, bilinear interpolation) and
decodes with `correlator`. A reading is correct when the decoded angle is within
2 pi / K of the truth, as in the paper.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .correlator import rom_windows, starts
from .sequence import as_bits

SUPERSAMPLE = 4


@dataclass(frozen=True)
class Cylinder:
    sequences: tuple[str, ...]
    phases: tuple[int, ...] = ()
    radius: float = 55.0
    width: float = 12.0

    def __post_init__(self):
        lengths = {len(s) for s in self.sequences}
        if len(lengths) != 1:
            raise ValueError("all sequences on a cylinder must have the same length")
        if self.phases and len(self.phases) != len(self.sequences):
            raise ValueError("one phase per sequence")

    @property
    def length(self) -> int:
        return len(self.sequences[0])

    @property
    def tracks(self) -> int:
        return len(self.sequences)

    @property
    def pitch(self) -> float:
        """Arc length of one bit, mm."""
        return 2 * np.pi * self.radius / self.length

    def phase_list(self) -> list[int]:
        return list(self.phases) if self.phases else [0] * self.tracks


@dataclass(frozen=True)
class Noise:
    coefficient: float = 0.0
    blur_px: float = 0.9
    awgn: float = 0.15
    contrast_loss: float = 0.6
    shift_along_mm: float = 0.2
    shift_across_mm: float = 0.5
    roll_deg: float = 1.5


@dataclass
class Camera:
    """Image geometry and the reader's sampling for a cylinder and window length n."""

    cylinder: Cylinder
    n: int
    samples_per_bit: int = 4
    sample_bits: int = 8
    pixel_mm: float = 1.0
    _bits: list = field(default_factory=list, repr=False)

    def __post_init__(self):
        half_arc = self.n * self.cylinder.pitch / 2
        chord = self.cylinder.radius * np.sin(half_arc / self.cylinder.radius)
        self.cols = int(np.ceil(2 * chord / self.pixel_mm)) + 6
        self.rows = int(np.ceil(self.cylinder.width / self.pixel_mm)) + 2
        self._bits = [as_bits(s) for s in self.cylinder.sequences]

    # -- the image --------------------------------------------------------------
    def render(self, theta: float, noise: Noise, rng: np.random.Generator) -> np.ndarray:
        """A B-bit image (rows x cols) of the cylinder turned to angle theta (radians)."""
        c = noise.coefficient
        cyl = self.cylinder
        sub = (np.arange(SUPERSAMPLE) + 0.5) / SUPERSAMPLE - 0.5
        u = ((np.arange(self.cols) - (self.cols - 1) / 2)[:, None] + sub[None, :]).ravel() * self.pixel_mm
        v = ((np.arange(self.rows) - (self.rows - 1) / 2)[:, None] + sub[None, :]).ravel() * self.pixel_mm
        uu, vv = np.meshgrid(u, v)
        roll = np.deg2rad(rng.normal(0, noise.roll_deg * c)) if c else 0.0
        du = rng.normal(0, noise.shift_along_mm * c) if c else 0.0
        dv = rng.normal(0, noise.shift_across_mm * c) if c else 0.0
        us = np.cos(roll) * uu - np.sin(roll) * vv + du
        vs = np.sin(roll) * uu + np.cos(roll) * vv + dv
        inside = np.abs(us) < cyl.radius
        phi = theta + np.arcsin(np.clip(us / cyl.radius, -1, 1))
        bit_index = np.floor(phi * cyl.length / (2 * np.pi)).astype(np.int64)
        track = np.floor((vs + cyl.width / 2) / (cyl.width / cyl.tracks)).astype(np.int64)
        on_cyl = inside & (track >= 0) & (track < cyl.tracks)
        value = np.zeros(uu.shape)
        for j, (bits, ph) in enumerate(zip(self._bits, cyl.phase_list())):
            sel = on_cyl & (track == j)
            value[sel] = bits[(bit_index[sel] + ph) % cyl.length]
        image = value.reshape(self.rows, SUPERSAMPLE, self.cols, SUPERSAMPLE).mean(axis=(1, 3))
        if c and noise.blur_px:
            image = _blur(image, noise.blur_px * c)
        contrast = max(0.15, 1 - noise.contrast_loss * c)
        image = 0.5 + (image - 0.5) * contrast
        if c and noise.awgn:
            image = image + rng.normal(0, noise.awgn * c, image.shape)
        top = (1 << self.sample_bits) - 1
        return np.clip(np.rint(image * top), 0, top).astype(np.int64)

    # -- the reader -------------------------------------------------------------
    def sample_points(self) -> tuple[np.ndarray, np.ndarray]:
        """Image coordinates (col, row) of the m x n x p samples, float pixels."""
        cyl, p = self.cylinder, self.samples_per_bit
        arc = (np.arange(self.n)[:, None] + (np.arange(p)[None, :] + 0.5) / p - self.n / 2) * cyl.pitch
        u = cyl.radius * np.sin(arc / cyl.radius)
        col = u / self.pixel_mm + (self.cols - 1) / 2
        centre = (np.arange(cyl.tracks) + 0.5) * cyl.width / cyl.tracks - cyl.width / 2
        row = centre / self.pixel_mm + (self.rows - 1) / 2
        cols = np.broadcast_to(col[None], (cyl.tracks, self.n, p))
        rows = np.broadcast_to(row[:, None, None], (cyl.tracks, self.n, p))
        return cols, rows

    def sample(self, image: np.ndarray) -> np.ndarray:
        """The reading: m x n x p B-bit samples by bilinear interpolation."""
        cols, rows = self.sample_points()
        c0 = np.clip(np.floor(cols).astype(int), 0, self.cols - 2)
        r0 = np.clip(np.floor(rows).astype(int), 0, self.rows - 2)
        fc, fr = cols - c0, rows - r0
        img = image.astype(np.float64)
        val = (img[r0, c0] * (1 - fc) * (1 - fr) + img[r0, c0 + 1] * fc * (1 - fr)
               + img[r0 + 1, c0] * (1 - fc) * fr + img[r0 + 1, c0 + 1] * fc * fr)
        return np.rint(val).astype(np.int64)

    def truth_start(self, theta: float) -> float:
        """Window start (in bits, continuous) of a reading at angle theta."""
        return theta * self.cylinder.length / (2 * np.pi) - self.n / 2

    def readings(self, thetas, noise: Noise, rng: np.random.Generator) -> np.ndarray:
        return np.stack([self.sample(self.render(t, noise, rng)) for t in thetas])


def _blur(image: np.ndarray, sigma: float) -> np.ndarray:
    radius = max(1, int(np.ceil(3 * sigma)))
    x = np.arange(-radius, radius + 1)
    kernel = np.exp(-0.5 * (x / sigma) ** 2)
    kernel /= kernel.sum()
    pad = np.pad(image, radius, mode="edge")
    rows = np.apply_along_axis(lambda r: np.convolve(r, kernel, mode="valid"), 1, pad)
    return np.apply_along_axis(lambda c: np.convolve(c, kernel, mode="valid"), 0, rows)


def correct(decoded: np.ndarray, start: np.ndarray, length: int) -> np.ndarray:
    """Within +-2 pi / K: the decoded window start within one bit of the true one."""
    diff = (decoded - start + length / 2) % length - length / 2
    return np.abs(diff) <= 1.0


@dataclass(frozen=True)
class Encoder:
    """One of the encoders of the experiment: its name, window length and cylinder."""
    name: str
    n: int
    cylinder: Cylinder


def accuracy(encoder: Encoder, noise: Noise, readings: int, rng: np.random.Generator,
             samples_per_bit: int = 4, sample_bits: int = 8) -> float:
    """Fraction of correct readings at random angles."""
    cam = Camera(encoder.cylinder, encoder.n, samples_per_bit, sample_bits)
    thetas = rng.uniform(0, 2 * np.pi, readings)
    samples = cam.readings(thetas, noise, rng)
    windows = rom_windows(encoder.cylinder.sequences, encoder.n, encoder.cylinder.phase_list())
    found = starts(samples, windows, sample_bits)
    start = np.array([cam.truth_start(t) for t in thetas])
    return float(correct(found, start, encoder.cylinder.length).mean())
