"""Model of rtl/prenc_mode_fsm.v: the reader's modes and pos_valid.

Decided at each check (a strobe with a full word: both heads against the prediction)
and at each illegal quadrature transition; see the RTL file for the rules.
"""

from __future__ import annotations

from enum import IntEnum

from .track_monitor import TrackRun


class Mode(IntEnum):
    ACQUIRE = 0
    NORMAL = 1
    REDUCED_1 = 2  # running on track 1 only (track 2 disagreed)
    REDUCED_2 = 3  # running on track 2 only
    INCREMENTAL = 4


VALID_MODES = (Mode.NORMAL, Mode.REDUCED_1, Mode.REDUCED_2)


class ModeFsm:
    def __init__(self):
        self.mode = Mode.ACQUIRE
        self.bad1 = self.bad2 = False
        self.error_slot = 0
        self._next = None

    @property
    def valid(self) -> bool:
        return self.mode in VALID_MODES

    def next(self, illegal: bool, check: bool, m1: bool, m2: bool, slot: int, word_full: bool,
             run1: TrackRun, run2: TrackRun, hyp_ready: bool = True) -> bool:
        """Decide this clock (or event); returns flush. `commit` takes the state."""
        mode = self.mode
        bad1, bad2 = self.bad1 and word_full, self.bad2 and word_full
        only1, only2 = check and m1 and not m2, check and m2 and not m1
        error_slot = slot if (only1 or only2) else self.error_slot
        flush = False
        if check and not self.valid:
            bad1, bad2 = bad1 or m1, bad2 or m2
            if bad1 and bad2:
                flush = True
            elif hyp_ready and ((run1.run_2n and run2.run_2n) or run1.run_long):
                mode = Mode.NORMAL if run2.run_n else Mode.REDUCED_1
            elif hyp_ready and run2.run_long:
                mode = Mode.NORMAL if run1.run_n else Mode.REDUCED_2
        elif check:
            if m1 and m2:
                mode, flush = Mode.INCREMENTAL, True
            elif self.mode == Mode.NORMAL:
                if only1:
                    mode = Mode.REDUCED_2
                elif only2:
                    mode = Mode.REDUCED_1
            elif self.mode == Mode.REDUCED_1:
                if only1:
                    mode, flush = Mode.INCREMENTAL, True
                elif not m2 and slot == self.error_slot:
                    mode = Mode.NORMAL
            else:
                if only2:
                    mode, flush = Mode.INCREMENTAL, True
                elif not m1 and slot == self.error_slot:
                    mode = Mode.NORMAL
        if illegal:
            mode = Mode.ACQUIRE if mode == Mode.ACQUIRE else Mode.INCREMENTAL
            flush = False
        self._next = (mode, bad1, bad2, error_slot)
        return flush

    def commit(self) -> None:
        self.mode, self.bad1, self.bad2, self.error_slot = self._next
