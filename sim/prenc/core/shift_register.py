# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/core/prenc_shift_register.v: the main code word from the leading head.

CW to a new slot: shift left, head 2 enters as LSB; CCW: shift right, head 1 enters
as MSB; a strobe at the same slot fills that end if unknown. `known` marks bits
read since reset or the last flush, `count` is how many.
"""

from __future__ import annotations

from typing import NamedTuple


class Word(NamedTuple):
    word: int
    known: int
    count: int
    full: int


class ShiftRegister:
    def __init__(self, n: int = 10):
        if not 2 <= n <= 24:
            raise ValueError(f"N = {n} is out of range 2..24")
        self.n = n
        self.mask = (1 << n) - 1
        self.msb = 1 << (n - 1)
        self.word = 0
        self.known = 0
        self.count = 0

    def output(self) -> Word:
        return Word(self.word, self.known, self.count, int(self.count == self.n))

    def clock(self, strobe: int, cw: int, moved: int, head1: int, head2: int,
              flush: int = 0, rst: int = 0) -> Word:
        if strobe:
            if moved and cw:
                self.count += 1 - (self.known >> (self.n - 1))
                self.word = ((self.word << 1) & self.mask) | head2
                self.known = ((self.known << 1) & self.mask) | 1
            elif moved:
                self.count += 1 - (self.known & 1)
                self.word = (self.word >> 1) | (head1 << (self.n - 1))
                self.known = (self.known >> 1) | self.msb
            elif cw and not self.known & 1:
                self.word = (self.word & ~1) | head2
                self.known |= 1
                self.count += 1
            elif not cw and not self.known & self.msb:
                self.word = (self.word & ~self.msb & self.mask) | (head1 << (self.n - 1))
                self.known |= self.msb
                self.count += 1
        if rst or flush:
            self.known = self.count = 0
        return self.output()
