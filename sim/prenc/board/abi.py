# SPDX-License-Identifier: Apache-2.0
"""ABI (A/B quadrature with an index) and UVW (commutation), as the AS5047P's outputs:
the models of rtl/board/prenc_step_tracker.v, prenc_abi.v and prenc_uvw.v, clock for
clock (docs/interfaces/abi-uvw.md), and what those outputs mean (`abi_steps`,
`uvw_sectors`, `UVW_PATTERN`) for the testbenches.
"""

from __future__ import annotations

from dataclasses import dataclass

ABI_DECIMAL = (4000, 2000, 1600, 1200, 800, 400, 200, 100)   # ABIBIN 0, by ABIRES
ABI_BINARY = (4096, 2048, 1024, 1024, 1024, 1024, 1024, 1024)  # ABIBIN 1
ABIBIN = 1 << 5                                                  # SETTINGS1's
UVW_PATTERN = ((1, 0, 1), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 1, 1), (0, 0, 1))  # (U, V, W) by sector


def abi_steps(settings1: int, settings2: int, fixed: int = 0) -> int:
    """Steps per turn: the build's STEPS, else ABIRES with ABIBIN."""
    if fixed:
        return fixed
    table = ABI_BINARY if settings1 & ABIBIN else ABI_DECIMAL
    return table[settings2 >> 5 & 7]


def pole_pairs(settings2: int, fixed: int = 0) -> int:
    return fixed or min(7, (settings2 & 7) + 1)


def hysteresis(settings2: int, bits: int) -> int:
    """(3 - HYS) LSB of the 14-bit angle, in 2^-bits turn."""
    return (3 - (settings2 >> 3 & 3)) << (bits - 14)


def quadrature(count: int) -> tuple[int, int]:
    """(A, B) of a step count: 00, 10, 11, 01 as it goes up."""
    return (count >> 1 ^ count) & 1, count >> 1 & 1


@dataclass
class StepTracker:
    """prenc_step_tracker: the step of `bits`-bit positions in a turn of `steps` steps,
    with its registers: the settings (S, the hysteresis; a new S or the reset restarts it
    on the next clock), the edges, their remainders and the thresholds."""

    bits: int
    steps: int | None = None      # the registered S (None: the reset's clocks load it)
    hyst: int = 0
    restart: bool = True          # after the reset
    count: int = 0
    lower: int = 0
    upper: int = 0
    rem_lower: int = 0
    rem_upper: int = 0
    up_at: int = 0
    down_at: int = 0
    wait_left: int = 0
    step: bool = False
    up: bool = False

    def decide(self, position: int, valid: bool) -> tuple[bool, bool, bool]:
        """(step up, step down, caught up) on this clock, before it (combinational)."""
        turn = 1 << self.bits
        want_up = (position - self.up_at) % turn < turn // 2
        want_down = (position - self.down_at) % turn >= turn // 2
        may = valid and self.wait_left == 0
        return may and want_up, may and want_down and not want_up, valid and not want_up and not want_down

    def clock(self, position: int, valid: bool, steps: int, hyst: int, min_gap: int) -> None:
        """A clock with the settings `steps` and `hyst` at the inputs."""
        if self.steps is None:
            self.steps, self.hyst = steps, hyst
        turn = 1 << self.bits
        s = self.steps
        q, r = divmod(turn, s)
        step_up, step_down, _ = self.decide(position, valid)
        self.step, self.up = step_up or step_down, step_up
        if self.wait_left:
            self.wait_left -= 1
        if step_up:
            carry = self.rem_upper + r >= s
            above = (self.upper + q + carry) % turn
            self.count = 0 if self.count == s - 1 else self.count + 1
            self.down_at = (self.upper - self.hyst) % turn
            self.lower, self.rem_lower = self.upper, self.rem_upper
            self.upper, self.rem_upper = above, self.rem_upper + r - (s if carry else 0)
            self.up_at = above
            self.wait_left = min_gap - 1
        elif step_down:
            borrow = self.rem_lower < r
            below = (self.lower - q - borrow) % turn
            self.count = s - 1 if self.count == 0 else self.count - 1
            self.up_at = (self.lower + self.hyst) % turn
            self.upper, self.rem_upper = self.lower, self.rem_lower
            self.lower, self.rem_lower = below, self.rem_lower + (s if borrow else 0) - r
            self.down_at = below
            self.wait_left = min_gap - 1
        if self.restart:
            self.count = self.lower = self.rem_lower = self.down_at = self.wait_left = 0
            self.upper, self.rem_upper, self.up_at = q, r, q
            self.step = self.up = False
        self.restart = steps != self.steps
        self.steps, self.hyst = steps, hyst


class Abi:
    """prenc_abi, clock for clock: `clock` returns (A, B, I) after the clock."""

    def __init__(self, bits: int, steps: int = 0, min_gap: int = 8):
        self.bits, self.fixed, self.min_gap = bits, steps, min_gap
        self.tracker = StepTracker(bits)
        self.placed = False
        self.a = self.b = self.i = 0

    def clock(self, position: int, valid: bool, settings1: int, settings2: int) -> tuple[int, int, int]:
        restart = self.tracker.restart
        _, _, caught_up = self.tracker.decide(position, valid)
        count = self.tracker.count
        self.a, self.b = quadrature(count)
        self.i = int(self.placed and count == 0)
        self.placed = self.placed or caught_up
        self.tracker.clock(position, valid, abi_steps(settings1, settings2, self.fixed),
                           hysteresis(settings2, self.bits), self.min_gap)
        if restart:
            self.placed = False
            self.a = self.b = self.i = 0
        return self.a, self.b, self.i


class Uvw:
    """prenc_uvw, clock for clock: `clock` returns (U, V, W) after the clock."""

    def __init__(self, bits: int, pole_pairs: int = 0):
        self.bits, self.fixed = bits, pole_pairs
        self.tracker = StepTracker(bits)
        self.sector = 0
        self.placed = False
        self.uvw = (0, 0, 0)

    def clock(self, position: int, valid: bool, settings2: int) -> tuple[int, int, int]:
        restart = self.tracker.restart
        _, _, caught_up = self.tracker.decide(position, valid)
        if not valid:
            self.uvw = (0, 0, 0)
        elif self.placed:
            self.uvw = UVW_PATTERN[self.sector]
        if self.tracker.step:
            self.sector = (self.sector + (1 if self.tracker.up else -1)) % 6
        self.placed = self.placed or caught_up
        self.tracker.clock(position, valid, 6 * pole_pairs(settings2, self.fixed),
                           hysteresis(settings2, self.bits), 1)
        if restart:
            self.sector, self.placed, self.uvw = 0, False, (0, 0, 0)
        return self.uvw
