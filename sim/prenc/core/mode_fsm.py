# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/core/prenc_mode_fsm.v: the judge of the offset, the modes and pos_valid.

The position is the slot count plus an offset; this machine decides the offset and
whether it is proven. It sees, one clock after the track words, each strobe with
both tracks' conversions (offset = converted slot - window base), their law-mode
comparisons, and each illegal quadrature transition:

- ACQUIRE / INCREMENTAL (no offset): each raw track reports its window's offset
  and its span, the consistent readings beyond the window's N (distinct slots:
  see prenc.core.track_word) and whether it is settled (no recent disagreement of
  its head), and whether the head is quiet (no disagreement in its last 4N
  checks, or since reset). A lock from heads that are not quiet needs
  LOCK_EXTRA more slots: misreads come in bunches of time, and a lock after
  N + 1 slots is wrong at a rate that only a quiet head makes rare enough
  (docs/architecture.md). Both tracks full and settled on one offset with spans >= LOCK_BOTH - 1
  (N + LOCK_BOTH - 1 slots each), or one track with span >= LOCK_ONE - 1 while
  the other is not settled on another offset, lock:
  that offset, and those tracks turn to law mode. A track's offset counts only
  while it is steady (the same as on the clock before: no reading changed its
  word, no realignment or flush moved it), and a full, settled track that is not
  steady blocks any lock on that clock: so the RTL may give the judge the offsets
  of the clock before (prenc_core's CONV_REG) without changing a decision.
- locked: the mode follows which law-mode tracks still support the offset
  (NORMAL both, REDUCED_1 / REDUCED_2 one); a raw track whose steady window
  converts to the offset rejoins. No track left: the offset is dropped (INCREMENTAL).
- an illegal transition while locked with both tracks supporting: the count took
  the step the last direction makes likely; the other hypothesis is one slot the
  other way. Both stay open (`dual`, pos_valid 0). A reading at a slot not yet
  visited since the transition, where the two hypotheses predict different bits,
  is a vote. A hypothesis wins with DUAL_VOTES votes, at least one from each head,
  and none for the other; votes for both, a track losing support, a second
  illegal transition or DUAL_SPAN slots of travel without a decision drop the
  offset. With one track supporting, an illegal transition drops it at once (a
  lone head that may be the one failing cannot choose between hypotheses).
  With `hypotheses` off (HYPOTHESES = 0) every illegal transition drops a held offset.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import IntEnum


class Mode(IntEnum):
    ACQUIRE = 0
    NORMAL = 1
    REDUCED_1 = 2  # only track 1 supports the offset
    REDUCED_2 = 3  # only track 2
    INCREMENTAL = 4


VALID_MODES = (Mode.NORMAL, Mode.REDUCED_1, Mode.REDUCED_2)


def default_lock_both(n: int) -> int:
    """Per track, N + LOCK_BOTH - 1 slots: N + 1 from N = 8 on; small discs go one
    deeper (their dirty cells are a larger share of the disc; docs/architecture.md)."""
    return 3 if n < 8 else 2


def default_lock_one(n: int) -> int:
    return n + 5 if n < 8 else n + 2


LOCK_EXTRA = 3
DUAL_VOTES = 3
DUAL_SPAN = 12


@dataclass
class JudgeInput:
    """The J1 registers: one strobe or illegal transition with both tracks' views."""

    strobe: int = 0
    illegal: int = 0
    illegal_cw: int = 0
    slot: int = 0
    full: tuple = (0, 0)
    steady: tuple = (0, 0)
    off: tuple = (0, 0)
    span: tuple = (0, 0)
    settled: tuple = (0, 0)
    quiet: tuple = (0, 0)
    checked: tuple = (0, 0)
    mismatch: tuple = (0, 0)
    mismatch_lo: tuple = (0, 0)
    mismatch_hi: tuple = (0, 0)

    @classmethod
    def of_tracks(cls, tracks, off: tuple, illegal: int, illegal_cw: int, slot: int) -> "JudgeInput":
        """The J1 registers from both tracks' registered outputs and their offsets."""
        return cls(strobe=tracks[0].strobe, illegal=illegal, illegal_cw=illegal_cw, slot=slot,
                   full=tuple(t.full for t in tracks), steady=tuple(t.steady for t in tracks), off=tuple(off),
                   span=tuple(t.span for t in tracks),
                   settled=tuple(t.settled for t in tracks), quiet=tuple(t.is_quiet for t in tracks),
                   checked=tuple(t.checked for t in tracks), mismatch=tuple(t.mismatch for t in tracks),
                   mismatch_lo=tuple(t.mismatch_lo for t in tracks),
                   mismatch_hi=tuple(t.mismatch_hi for t in tracks))


@dataclass
class ModeFsm:
    n: int
    lock_both: int | None = None
    lock_one: int | None = None
    lock_extra: int = LOCK_EXTRA
    dual_votes: int = DUAL_VOTES
    dual_span: int = DUAL_SPAN
    hypotheses: bool = True
    mode: Mode = Mode.ACQUIRE
    offset: int = 0
    dual: int = 0
    dual_cw: int = 0
    anchor: int = 0
    lo: int = 1
    hi: int = 0
    votes: list = field(default_factory=lambda: [0, 0])        # for keeping / for the other way
    voted: list = field(default_factory=lambda: [0, 0, 0, 0])  # keep by head 1, 2; other by head 1, 2
    flush: list = field(default_factory=lambda: [0, 0])   # registered pulses to the tracks
    law_on: list = field(default_factory=lambda: [0, 0])
    realign: int = 0  # registered pulse to the tracks: +1 / -1 index after the other hypothesis won

    def __post_init__(self) -> None:
        if self.lock_both is None:
            self.lock_both = default_lock_both(self.n)
        if self.lock_one is None:
            self.lock_one = default_lock_one(self.n)
        self.mask = (1 << self.n) - 1

    @property
    def valid(self) -> bool:
        return self.mode in VALID_MODES and not self.dual

    def clock(self, j: JudgeInput, supported: tuple, law: tuple, rst: int = 0) -> None:
        """One rising edge; `supported` and `law` are the tracks' current flags."""
        mode, offset, dual, dual_cw = self.mode, self.offset, self.dual, self.dual_cw
        anchor, lo, hi, votes, voted = self.anchor, self.lo, self.hi, list(self.votes), list(self.voted)
        flush, law_on, realign = [0, 0], [0, 0], 0
        sup = [int((supported[h] and not self.flush[h]) or self.law_on[h]) for h in (0, 1)]
        lawish = [int((law[h] and not self.flush[h]) or self.law_on[h]) for h in (0, 1)]
        locked = mode in VALID_MODES or dual
        locked_now = False
        drop = False
        if j.illegal:
            if self.hypotheses and mode in VALID_MODES and not dual and sup[0] and sup[1]:
                dual, dual_cw, mode = 1, j.illegal_cw, Mode.INCREMENTAL
                anchor, lo, hi, votes, voted = j.slot, 1, 0, [0, 0], [0, 0, 0, 0]
            elif locked:
                drop = True
        elif j.strobe and not locked:
            # A track's offset counts only while steady (the same word's on the last clock
            # too); a settled track whose word just changed blocks any lock on this clock.
            ready = [j.full[h] and j.settled[h] and j.steady[h] for h in (0, 1)]
            blocked = any(j.full[h] and j.settled[h] and not j.steady[h] for h in (0, 1))
            both_extra = 0 if (j.quiet[0] and j.quiet[1]) else self.lock_extra
            one_extra = [0 if j.quiet[h] else self.lock_extra for h in (0, 1)]
            if blocked:
                pass
            elif (ready[0] and ready[1] and j.off[0] == j.off[1]
                    and min(j.span) >= self.lock_both - 1 + both_extra):
                offset, law_on, mode, locked_now = j.off[0], [1, 1], Mode.NORMAL, True
            # One head alone, unless the other is settled on another offset: two
            # settled heads that disagree leave the offset unproven.
            elif (ready[0] and j.span[0] >= self.lock_one - 1 + one_extra[0]
                  and not (ready[1] and j.off[1] != j.off[0])):
                offset, law_on, mode, locked_now = j.off[0], [1, 0], Mode.REDUCED_1, True
            elif (ready[1] and j.span[1] >= self.lock_one - 1 + one_extra[1]
                  and not (ready[0] and j.off[0] != j.off[1])):
                offset, law_on, mode, locked_now = j.off[1], [0, 1], Mode.REDUCED_2, True
        elif j.strobe and not dual:
            for h in (0, 1):
                if j.full[h] and j.steady[h] and not lawish[h] and j.off[h] == offset:
                    law_on[h] = 1
        elif j.strobe:
            rel = (j.slot - anchor) & self.mask
            if rel >= 1 << (self.n - 1):
                rel -= 1 << self.n
            if abs(rel) > self.dual_span:
                drop = True
            elif rel < lo or rel > hi:
                lo, hi = min(lo, rel), max(hi, rel)
                for h in (0, 1):
                    alt = j.mismatch_lo[h] if dual_cw else j.mismatch_hi[h]
                    if j.checked[h] and j.mismatch[h] != alt:
                        way = j.mismatch[h]  # 0: the reading is the kept hypothesis's bit
                        votes[way] = min(votes[way] + 1, self.dual_votes)
                        voted[2 * way + h] = 1
                if votes[0] and votes[1]:
                    drop = True
                elif votes[0] >= self.dual_votes and voted[0] and voted[1]:
                    dual, mode = 0, Mode.NORMAL  # kept: the modes below follow support
                elif votes[1] >= self.dual_votes and voted[2] and voted[3]:
                    # The other way: the count is one slot off; the offset takes it.
                    dual, mode = 0, Mode.NORMAL
                    offset += -1 if dual_cw else 1
                    realign = -1 if dual_cw else 1
        # Modes from support, every clock, while the offset stands.
        if drop:
            flush, dual, mode = [1, 1], 0, Mode.INCREMENTAL
        elif dual:
            if not (sup[0] and sup[1]):
                flush, dual, mode = [1, 1], 0, Mode.INCREMENTAL
        elif mode in VALID_MODES and not locked_now:
            s = [sup[h] or law_on[h] for h in (0, 1)]
            if s[0] and s[1]:
                mode = Mode.NORMAL
            elif s[0]:
                mode = Mode.REDUCED_1
            elif s[1]:
                mode = Mode.REDUCED_2
            else:
                flush, mode = [1, 1], Mode.INCREMENTAL
        if rst:
            mode, offset, dual, dual_cw = Mode.ACQUIRE, 0, 0, 0
            anchor, lo, hi, votes, voted = 0, 1, 0, [0, 0], [0, 0, 0, 0]
            flush, law_on, realign = [0, 0], [0, 0], 0
        self.realign = realign
        self.mode, self.offset, self.dual, self.dual_cw = mode, offset & self.mask, dual, dual_cw
        self.anchor, self.lo, self.hi, self.votes, self.voted = anchor, lo, hi, votes, voted
        self.flush, self.law_on = flush, law_on
