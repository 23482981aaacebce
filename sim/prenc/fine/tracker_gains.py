# SPDX-License-Identifier: Apache-2.0
"""The gain table of rtl/fine/prenc_tracker.v (prenc.fine.tracker): a Kalman filter's
gains, computed here once for a disc and a clock, looked up by the tracker at run time.

The filter (docs/design-log.md, "A Kalman filter on the edges"): the state is the
position (quarters), the velocity (quarters per clock) and the acceleration; each of
the decoder's steps measures the position of the edge crossed. Between edges a white
jerk of density Q600 (|v| / v600)^QEXP drives the state (QEXP_LOW below 600 rpm, so that
a crawl's few edges do not read as accelerations); a measurement is off by a clock's
quantization (v^2 / 12) and the disc's edge error, `sigma` quarters RMS. The gains
depend on the speed and on the edges since the filter started (its age); the table
holds them for COLUMNS speeds (2 an octave, from 2^(P_LOW - 40) quarters per clock) and
BINS ages (0..15, then 4 bins an octave up to 1023), each the covariance recursion run
at that speed (scripts/velocity_study.py's `scheduled` filter, at these bins).

A word holds four gains, each as a 12-bit mantissa m and a 6-bit shift s: the tracker
multiplies the innovation e (2^-20 quarter) by m, then takes (e m 2^24) >> s, which is
in the unit of what it corrects:

    g0  position (2^-40 quarter)          g1  velocity (2^-40 quarter per clock)
    g2  acceleration (2^-60 q per clock^2) gz  1 / the innovation's standard deviation
                                              (2^-8, for the maneuver detector)

Word = {gz, g2, g1, g0}, each {s[5:0], m[11:0]}: 72 bits, as 18 hex digits a line, the
line col * BINS + bin ($readmemh).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

Q600 = 1e-23                 # jerk density at 600 rpm, quarters^2 / clock^5
QEXP = 2.0                   # ... growing as |v|^QEXP above 600 rpm
QEXP_LOW = 5.0               # ... and as |v|^QEXP_LOW below
PRIOR_POSITION = 0.1         # the position variance at the start, quarters^2
SIGMA = {"ideal": 0.01, "printed": 0.15}   # the disc's edge error, quarters RMS

COLUMNS = 32                 # speeds: 2 an octave from 2^(P_LOW - 40) quarters per clock
P_LOW = 19
BINS = 40                    # ages: 0..15, then 4 bins an octave (16..1023)
AGE_MAX = 1023
MANTISSA_BITS = 12
SHIFT_BITS = 6
FIELD_BITS = MANTISSA_BITS + SHIFT_BITS
WORD_BITS = 4 * FIELD_BITS
INNOVATION_FRAC = 20         # the innovation's fractional bits
PRE_SHIFT = 24               # the product's left shift before the table's right shift
UNITS = (40, 40, 60, 8)      # fractional bits of what each gain corrects: g0, g1, g2, gz


def age_bin(age: int) -> int:
    """The table's bin of an age (0..AGE_MAX): 0..15 as themselves, then 4 an octave."""
    if age < 16:
        return age
    octave = age.bit_length() - 1            # 4..9
    return 16 + 4 * (octave - 4) + ((age >> (octave - 2)) & 3)


def bin_age(b: int) -> int:
    """The age whose gains a bin holds: its own, or the middle of its quarter octave."""
    if b < 16:
        return b
    octave, j = 4 + (b - 16) // 4, (b - 16) % 4
    first = (1 << octave) + j * (1 << (octave - 2))
    return first + (1 << (octave - 2)) // 2


def column(speed: int) -> int:
    """The table's column of |velocity| (2^-40 quarter per clock): 2 an octave, by its
    leading one and the bit below it, clamped to 0..COLUMNS - 1."""
    if speed <= 0:
        return 0
    p = speed.bit_length() - 1
    half = (speed >> (p - 1)) & 1 if p > 0 else 0
    return max(0, min(COLUMNS - 1, 2 * (p - P_LOW) + half))


def column_speed(col: int) -> float:
    """The speed a column's gains are computed at, quarters per clock."""
    p, half = P_LOW + col // 2, col % 2
    return 2.0 ** (p - 40) * (1.25 if half == 0 else 1.75)


def v600(n: int, clk_hz: float) -> float:
    """600 rpm in quarters per clock."""
    return 4 * 600 / 60 * (1 << n) / clk_hz


def jerk_density(v: float, n: int, clk_hz: float) -> float:
    ratio = abs(v / v600(n, clk_hz))
    return Q600 * ratio ** (QEXP if ratio >= 1 else QEXP_LOW)


def transition(t: float) -> np.ndarray:
    """Position, velocity and acceleration over t clocks."""
    return np.array([[1.0, t, t * t / 2], [0.0, 1.0, t], [0.0, 0.0, 1.0]])


def process_noise(q: float, t: float) -> np.ndarray:
    """A white jerk of density q over t clocks."""
    return q * np.array([[t ** 5 / 20, t ** 4 / 8, t ** 3 / 6],
                         [t ** 4 / 8, t ** 3 / 3, t ** 2 / 2],
                         [t ** 3 / 6, t ** 2 / 2, t]])


def update(cov: np.ndarray, f: np.ndarray, noise: np.ndarray, v: float,
           sigma: float) -> tuple[np.ndarray, np.ndarray, float]:
    """One edge of the covariance: predicted over f (with the process noise), then
    measured at velocity v. Returns the new covariance, the gains and the innovation's
    variance."""
    cov = f @ cov @ f.T + noise
    spread = cov[0, 0] + v * v / 12 + sigma ** 2
    gain = cov[:, 0] / spread
    return cov - np.outer(gain, cov[0, :]), gain, spread


def recursion(v: float, sigma: float, n: int, clk_hz: float, ages: int = AGE_MAX + 1):
    """The gains (g0, g1, g2) and the innovation's variance after each age 0..ages-1,
    at a constant speed v (quarters per clock). The start knows the speed to within
    itself (velocity variance v^2, acceleration variance v^4 / 100): the first
    interval gave it."""
    t = 1.0 / v
    f, noise = transition(t), process_noise(jerk_density(v, n, clk_hz), t)
    cov = np.diag([PRIOR_POSITION, v * v, (v * v) ** 2 * 1e-2])
    rows = []
    for _ in range(ages):
        cov, gain, spread = update(cov, f, noise, v, sigma)
        rows.append((gain, spread))
    return rows


def encode(gain: float, unit: int) -> int:
    """{s, m}: the field whose (e m 2^PRE_SHIFT) >> s is gain x e (e in 2^-20) in 2^-unit."""
    if gain <= 0:
        return (1 << SHIFT_BITS) - 1 << MANTISSA_BITS   # m = 0: no correction
    x = MANTISSA_BITS - 1 - math.floor(math.log2(gain))
    m = round(gain * 2.0 ** x)
    if m >= 1 << MANTISSA_BITS:
        m, x = m >> 1, x - 1
    s = x + INNOVATION_FRAC + PRE_SHIFT - unit
    if s < 0:
        raise ValueError(f"gain {gain:g} is too large for the table (unit 2^-{unit})")
    if s >= 1 << SHIFT_BITS:
        return (1 << SHIFT_BITS) - 1 << MANTISSA_BITS   # too small to count
    return s << MANTISSA_BITS | m


def decode(field: int, unit: int) -> float:
    """The gain a field stands for (the inverse of encode, within its rounding)."""
    m, s = field & ((1 << MANTISSA_BITS) - 1), field >> MANTISSA_BITS
    return m * 2.0 ** (INNOVATION_FRAC + PRE_SHIFT - unit - s)


def table(n: int = 10, clk_hz: float = 30e6, sigma: float = SIGMA["ideal"]) -> list[int]:
    """The table's words, line col * BINS + bin."""
    if not 2 <= n <= 24:
        raise ValueError(f"n = {n} is out of range 2..24")
    if clk_hz <= 0:
        raise ValueError(f"clk_hz = {clk_hz} must be positive")
    if sigma < 0:
        raise ValueError(f"sigma = {sigma} must not be negative")
    words = []
    for col in range(COLUMNS):
        rows = recursion(column_speed(col), sigma, n, clk_hz)
        for b in range(BINS):
            gain, spread = rows[bin_age(b)]
            gains = (gain[0], gain[1], gain[2], 1.0 / math.sqrt(spread))
            word = 0
            for i, (g, unit) in enumerate(zip(gains, UNITS)):
                word |= encode(float(g), unit) << (i * FIELD_BITS)
            words.append(word)
    return words


def render(n: int = 10, clk_hz: float = 30e6, sigma: float = SIGMA["ideal"]) -> bytes:
    """The table as a $readmemh file's text."""
    digits = (WORD_BITS + 3) // 4
    return "".join(f"{w:0{digits}x}\n" for w in table(n, clk_hz, sigma)).encode()


def write(path: str | Path, n: int = 10, clk_hz: float = 30e6, sigma: float = SIGMA["ideal"]) -> None:
    """The table as a $readmemh file, written whole (a temporary file renamed into
    place: a simulation reading it meanwhile sees the old file or the new one)."""
    from ..codes.rom import write_atomically

    write_atomically(path, lambda: render(n, clk_hz, sigma))


def read(path: str | Path) -> list[int]:
    """A table file's words; a missing file, a bad line or a wrong size is an error."""
    lines = [ln.strip() for ln in Path(path).read_text().splitlines()]
    lines = [ln for ln in lines if ln and not ln.startswith("//")]
    if len(lines) != COLUMNS * BINS:
        raise ValueError(f"{path}: {len(lines)} words, the tracker's gain table has {COLUMNS * BINS}")
    words = []
    for k, ln in enumerate(lines):
        try:
            w = int(ln, 16)
        except ValueError:
            raise ValueError(f"{path}: word {k} ({ln!r}) is not hexadecimal") from None
        if w >> WORD_BITS:
            raise ValueError(f"{path}: word {k} has more than {WORD_BITS} bits")
        words.append(w)
    return words
