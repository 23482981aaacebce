# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/cal/prenc_cal_lookup.v: the calibration table in block RAM, and the
corrections of a quarter's two edges, one clock after the quarter is asked for.

The table (prenc.cal.table: c[x] for the 4 x 2^N edges, signed 16 bits) sits in one
memory with one read port, so that every device holds it in its plain block RAM (or
the UP5K's single-port SPRAM), loaded from the file by $readmemh or written at run
time. A quarter q needs two words, c[q] and c[q + 1]; two slots hold the last two
words read, each with the address it holds (its tag):

- each cycle, for the quarter asked (`quarter`), a slot keeps its word, takes the
  other slot's (the disc moved by one quarter: the shared edge), or is filled by the
  read; the memory reads c[q] if the lower slot needs it, else c[q + 1];
- so a move of one quarter per clock (either way) keeps both slots full, and a jump
  (the core's position set anew) takes two clocks; `ok` says both are q's;
- a write (`write`, `address`, `data`) changes the word from the next clock on; a slot
  that holds that address, or reads it in the same cycle (the read returns the old
  word), is emptied.

Outputs after the clock edge of cycle t: c_lo = c[q(t)], c_hi = c[q(t) + 1], ok.
"""

from __future__ import annotations

import numpy as np

from .table import LIMIT


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
        self.reset()

    def reset(self) -> None:
        self.lo = self.hi = 0
        self.lo_tag = self.hi_tag = 0
        self.lo_ok = self.hi_ok = 0

    @property
    def ok(self) -> int:
        return int(self.lo_ok and self.hi_ok)

    def clock(self, quarter: int, write: int = 0, address: int = 0, data: int = 0,
              rst: int = 0) -> None:
        if rst:
            if write:
                self.memory[address % self.size] = ((data + (1 << 15)) % (1 << 16)) - (1 << 15)
            self.reset()   # the memory keeps its words (and takes a write)
            return
        q = quarter % self.size
        q1 = (q + 1) % self.size
        # Where each slot's next word comes from: keep, the other slot, or the read.
        lo_keep = self.lo_ok and self.lo_tag == q
        lo_swap = not lo_keep and self.hi_ok and self.hi_tag == q
        hi_keep = self.hi_ok and self.hi_tag == q1
        hi_swap = not hi_keep and self.lo_ok and self.lo_tag == q1
        read_lo = not (lo_keep or lo_swap)
        read_addr = q if read_lo else q1
        word = self.memory[read_addr]          # read before the write: the old word
        lo = self.lo if lo_keep else self.hi if lo_swap else word
        hi = self.hi if hi_keep else self.lo if hi_swap else word
        lo_ok = 1                                     # kept, moved or read
        hi_ok = int(hi_keep or hi_swap or not read_lo)   # else read next cycle
        if write:
            a = address % self.size
            # A slot with the written address (kept, moved, or read just now) is stale.
            lo_ok = int(lo_ok and q != a)
            hi_ok = int(hi_ok and q1 != a)
            self.memory[a] = ((data + (1 << 15)) % (1 << 16)) - (1 << 15)
        self.lo, self.hi = lo, hi
        self.lo_tag, self.hi_tag = q, q1
        self.lo_ok, self.hi_ok = lo_ok, hi_ok
