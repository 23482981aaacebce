# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/board/prenc_turns.v: a multi-turn position from the single-turn one and
the incremental count.

`full` = turns * 2^POS_BITS + position, turn 0 at the first valid position after
reset. While valid it moves by the shortest way to each new position (so turns
accumulate across the zero crossing); while not valid it moves with the incremental
count; when the position is valid again it takes the turn nearest to where the
count brought it.
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Iterator


@dataclass
class Turns:
    pos_bits: int = 12
    turn_bits: int = 12

    def __post_init__(self) -> None:
        if not 2 <= self.pos_bits <= 30:
            raise ValueError(f"pos_bits {self.pos_bits} out of range 2..30")
        if not 1 <= self.turn_bits <= 32:
            raise ValueError(f"turn_bits {self.turn_bits} out of range 1..32")
        self.full = 0
        self.placed = False
        self.count_prev = 0

    @property
    def width(self) -> int:
        return self.pos_bits + self.turn_bits

    @property
    def turns(self) -> int:
        return self.full >> self.pos_bits

    def _signed(self, value: int) -> int:
        value &= (1 << self.pos_bits) - 1
        return value - (1 << self.pos_bits) if value >> (self.pos_bits - 1) else value

    def clock(self, position: int, valid: bool, count: int, rst: bool = False) -> None:
        """One clock; `count` is the incremental count (its low pos_bits are used)."""
        mask = (1 << self.width) - 1
        pos_mask = (1 << self.pos_bits) - 1
        count &= pos_mask
        if rst:
            self.full, self.placed, self.count_prev = 0, False, count
            return
        if valid and not self.placed:
            self.full, self.placed = position & pos_mask, True
        elif valid:
            self.full = (self.full + self._signed(position - self.full)) & mask
        else:
            self.full = (self.full + self._signed(count - self.count_prev)) & mask
        self.count_prev = count


def random_walk(seed: int, clocks: int, pos_bits: int) -> Iterator[tuple[int, int, bool]]:
    """A stimulus for the tests: each clock's true unwrapped position in quarters (at
    most one step a clock, reversing now and then), the incremental count (which
    misses the two quarters of a missed quadrature state, one clock in a thousand),
    and the valid flag (lost and found in stretches)."""
    r = random.Random(seed)
    q, count, valid, way = 3 * (1 << pos_bits) + 5, 0, False, 1
    for t in range(clocks):
        if r.random() < 0.002:
            way = -way
        jump = 2 * way if r.random() < 0.001 else 0
        step = way if (r.random() < 0.7 and not jump) else 0
        q += step + jump
        count += step
        if t > 50 and r.random() < 0.0015:
            valid = not valid
        yield q, count, valid
