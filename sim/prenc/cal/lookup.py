# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/cal/prenc_cal_lookup.v: the calibration table in block RAM, and the
corrections of a quarter's two edges.

The table (prenc.cal.table: c[x] for the 4 x 2^N edges, signed 16 bits) sits in one
memory with one read port, so that every device holds it in its plain block RAM,
loaded from the file by $readmemh or written at run time. A quarter q needs two words,
c[q] and c[q + 1]:

- when the pair on the outputs is not the quarter asked's (or there is none), a read
  starts: c[q] asked of the memory (IDLE), c[q] comes and c[q + 1] is asked (READ_LO),
  c[q + 1] comes (READ_HI): the pair (lo, hi) and its quarter change together;
- a quarter that changes during a read is read after it;
- a write (`write`, `address`, `data`) changes the word from the next clock on; it
  empties the pair (ok 0) and spoils a read under way (its pair is not loaded).

Outputs after the clock edge: lo = c[quarter], hi = c[quarter + 1], ok.
"""

from __future__ import annotations

import numpy as np

from .table import LIMIT

IDLE, READ_LO, READ_HI = 0, 1, 2
READ_DELAY = 3     # a quarter asked from clock t on: its pair from t + 3 (no read under way)


def _signed16(value: int) -> int:
    return ((value + (1 << 15)) % (1 << 16)) - (1 << 15)


class CalLookup:
    def __init__(self, n: int, table=None):
        self.n = n
        self.size = 4 << n
        self.memory = [0] * self.size
        if table is not None:
            words = np.asarray(table, dtype=np.int64)
            if words.shape != (self.size,) or np.max(np.abs(words)) > LIMIT + 1:
                raise ValueError(f"a table for n = {n} has {self.size} words of 16 bits")
            self.memory = [int(w) for w in words]
        self.word = 0
        self.asked = 0
        self.lo_word = 0
        self.dirty = 0
        self.lo = self.hi = self.quarter = 0
        self.reset()

    def reset(self) -> None:
        self.state = IDLE
        self.ok = 0

    def clock(self, quarter: int, write: int = 0, address: int = 0, data: int = 0,
              rst: int = 0) -> None:
        q = quarter % self.size
        read_addr = (self.asked + 1) % self.size if self.state == READ_LO else q
        word = self.memory[read_addr]            # the word before this clock's write
        if write:
            self.memory[address % self.size] = _signed16(data)
        if self.state == IDLE:
            if not self.ok or q != self.quarter:
                self.asked, self.dirty, self.state = q, 0, READ_LO
        elif self.state == READ_LO:
            self.lo_word, self.state = self.word, READ_HI
        else:
            if not self.dirty:
                self.lo, self.hi, self.quarter, self.ok = self.lo_word, self.word, self.asked, 1
            self.state = IDLE
        if write:
            self.dirty, self.ok = 1, 0
        self.word = word
        if rst:
            self.reset()
