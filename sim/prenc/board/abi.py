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


def hysteresis(settings2: int) -> int:
    """(3 - HYS) LSB of the 14-bit angle, in 2^-16 turn."""
    return (3 - (settings2 >> 3 & 3)) << 2


def quadrature(count: int) -> tuple[int, int]:
    """(A, B) of a step count: 00, 10, 11, 01 as it goes up."""
    return (count >> 1 ^ count) & 1, count >> 1 & 1


def step_of(p16: int, steps: int) -> int:
    """The step a 16-bit position is in: floor(p S / 2^16)."""
    return p16 * steps >> 16


@dataclass
class StepTracker:
    """prenc_step_tracker: the step of `bits`-bit positions (taken at their top 16 bits)
    in a turn of `steps` steps, with its registers: the settings (S, the hysteresis; a
    new S or the reset restarts it on the next clock), the thresholds' steps of the clock
    before (k_up, k_down, with `valid`), the directions those wanted against the count
    (want_up, want_down, with `valid` again), the count and the last step's direction."""

    bits: int
    steps: int | None = None      # the registered S (None: the reset's clocks load it)
    hyst: int = 0
    restart: bool = True          # after the reset
    count: int = 0
    last: int = 0                 # +1 the last step was up, -1 down, 0 none since a restart
    k_up: int = 0
    k_down: int = 0
    valid: bool = False           # the registered valid, of k_up and k_down's position
    want_up: bool = False
    want_down: bool = False
    valid2: bool = False          # valid, registered again: of want_up and want_down
    wait_left: int = 0
    step: bool = False
    up: bool = False

    def p16(self, position: int) -> int:
        return position >> (self.bits - 16) if self.bits >= 16 else position << (16 - self.bits)

    def decide(self) -> tuple[bool, bool, bool]:
        """(step up, step down, caught up) on this clock, from the registers."""
        may = self.valid2 and self.wait_left == 0
        return (may and self.want_up, may and self.want_down and not self.want_up,
                self.valid2 and not self.want_up and not self.want_down)

    def clock(self, position: int, valid: bool, steps: int, hyst: int, min_gap: int) -> None:
        """A clock with the settings `steps` and `hyst` at the inputs."""
        if self.steps is None:
            self.steps, self.hyst = steps, hyst
        s = self.steps
        step_up, step_down, _ = self.decide()
        d, e = self.k_up - self.count, self.count - self.k_down   # the shorter way round
        self.want_up = 0 < 2 * d < s or 2 * d < -s
        self.want_down = 0 < 2 * e <= s or 2 * e <= -s
        self.valid2 = self.valid
        p = self.p16(position)
        self.k_up = step_of((p - (self.hyst if self.last < 0 else 0)) % (1 << 16), s)
        self.k_down = step_of((p + (self.hyst if self.last > 0 else 0)) % (1 << 16), s)
        self.valid = valid
        self.step, self.up = step_up or step_down, step_up
        if self.wait_left:
            self.wait_left -= 1
        if step_up or step_down:
            self.count = (self.count + (1 if step_up else -1)) % s
            self.last = 1 if step_up else -1
            self.wait_left = max(min_gap, 3) - 1
        if self.restart:
            self.count = self.last = self.wait_left = 0
            self.valid = self.valid2 = False   # the stages' steps are of the old S and direction
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
        _, _, caught_up = self.tracker.decide()
        count = self.tracker.count
        self.a, self.b = quadrature(count)
        self.i = int(self.placed and count == 0)
        self.placed = self.placed or caught_up
        self.tracker.clock(position, valid, abi_steps(settings1, settings2, self.fixed),
                           hysteresis(settings2), self.min_gap)
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
        _, _, caught_up = self.tracker.decide()
        if not valid:
            self.uvw = (0, 0, 0)
        elif self.placed:
            self.uvw = UVW_PATTERN[self.sector]
        if self.tracker.step:
            self.sector = (self.sector + (1 if self.tracker.up else -1)) % 6
        self.placed = self.placed or caught_up
        self.tracker.clock(position, valid, 6 * pole_pairs(settings2, self.fixed),
                           hysteresis(settings2), 1)
        if restart:
            self.sector, self.placed, self.uvw = 0, False, (0, 0, 0)
        return self.uvw
