"""Model of rtl/prenc_track_monitor.v: how far one track's readings confirm the word.

The interval [lo, hi] of consecutive slots (incremental slot count, modulo 2^N) at
which every reading of the track agreed since its last disagreement. A re-read
inside it changes nothing, a new neighbouring slot extends it, a disagreement or
`clear` empties it. N agreeing slots are a whole code word read by this track;
`run_long` slots (at least 2N) survive one misread among them. Slots where this
track's head fed the word (`feed`, the hull of them) are no evidence: checks there
neither start nor lengthen the interval.
"""

from __future__ import annotations

from typing import NamedTuple


def default_run_long(n: int) -> int:
    """The RTL's default RUN_LONG: 4N, or 2^N when that is less."""
    return min(4 * n, 1 << n)


class TrackRun(NamedTuple):
    run_n: bool
    run_long: bool
    run_2n: bool = False


class TrackMonitor:
    def __init__(self, n: int, run_long: int | None = None):
        run_long = default_run_long(n) if run_long is None else run_long
        if not 2 <= n <= 24:
            raise ValueError(f"N = {n} is out of range 2..24")
        if not 2 * n <= run_long <= 1 << n:
            raise ValueError(f"RUN_LONG = {run_long} is out of range 2N..2^N")
        self.n, self.run_long = n, run_long
        self.mask = (1 << n) - 1
        self.lo = self.hi = 0
        self.nonempty = False
        self.run_n = False
        self.errors = 0
        self._next = (0, 0, False)
        self.fed_lo = self.fed_hi = 0
        self.fed = False

    def _inside(self, slot: int, lo: int, hi: int) -> bool:
        return ((slot - lo) & self.mask) <= ((hi - lo) & self.mask)

    def feed(self, slot: int, word_empty: bool) -> None:
        """This track's head fed the word at `slot` (registered, as `fill`)."""
        if word_empty or not self.fed:
            self.fed_lo = self.fed_hi = slot
            self.fed = True
        elif not self._inside(slot, self.fed_lo, self.fed_hi):
            if ((self.fed_lo - slot) & self.mask) < ((slot - self.fed_hi) & self.mask):
                self.fed_lo = slot
            else:
                self.fed_hi = slot

    def span(self, lo: int, hi: int) -> int:
        return ((hi - lo) & self.mask) + 1

    def next(self, clear: bool, check: bool, mismatch: bool, slot: int) -> TrackRun:
        """The state this check leads to (combinational); `commit` takes it."""
        lo, hi, nonempty = self.lo, self.hi, self.nonempty
        if check and mismatch:
            nonempty = False
        elif check and self.fed and self._inside(slot, self.fed_lo, self.fed_hi):
            pass
        elif check:
            if not nonempty:
                lo = hi = slot
                nonempty = True
            elif self._inside(slot, lo, hi):
                pass
            elif slot == (hi + 1) & self.mask:
                hi = slot
            elif slot == (lo - 1) & self.mask:
                lo = slot
            else:
                lo = hi = slot
        if clear:
            nonempty = False
        self._next = (lo, hi, nonempty)
        span = self.span(lo, hi)
        self._errors_next = self.errors + int(check and mismatch)
        return TrackRun(nonempty and span >= self.n, nonempty and span >= self.run_long,
                        nonempty and span >= min(2 * self.n, 1 << self.n))

    def commit(self) -> None:
        self.lo, self.hi, self.nonempty = self._next
        self.run_n = self.nonempty and self.span(self.lo, self.hi) >= self.n
        self.errors = self._errors_next
