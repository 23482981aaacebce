# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/core/prenc_track_word.v: one head's code word in the reader's count space.

Each head has its own N-slot window on the incremental slot count: the head's
readings at counts base .. base+N-1, with `index` = count - base the head's place
in it. A move of the count inside the window moves the index; past an end the
window slides, and the bit that enters is computed by the disc's law from the
window (forward at the top, inverse at the bottom), so a window that holds the
disc's bits keeps holding them.

- raw mode (acquiring): a strobe writes the head's reading at the index and marks
  it known; `full` (all N known) lets the converter place the window. An illegal
  quadrature transition makes every bit of a raw window unknown (the count may be
  a slot off); the window itself keeps its place.
  The evidence of a raw window is counted in distinct slots: `ext_lo` / `ext_hi`
  are the slots just below / above the window whose last reading equals the law's
  extension of the window. A window sliding over a known bit keeps it in `ext`; a
  window sliding back over such a slot takes its bit as known; a reading that
  changes the word empties `ext` (those readings agreed with the old word). A
  re-read after a reversal therefore adds nothing: dithering over a dirty slot
  cannot build a lock. `span` = ext_lo + ext_hi (saturating) once the window is full:
  the window holds the disc word of N + span consecutive readings.
- law mode (locked): the window is the disc's word, stepped by the law; a strobe
  only compares the reading with the bit at the index (`mismatch`), and with the
  bits one slot either side (`mismatch_lo`, `mismatch_hi`: the other hypothesis
  after a missed quadrature state). A health score rises by SCORE_UP on a mismatch
  and falls by one on a match; at SCORE_LIMIT the track stops supporting the
  position and returns to raw mode, to be read anew.

Word value: the window's lowest count is the MSB, as w(p) on the disc, so the
converter gives the disc slot of `base` (head 1) or of base + N - 1 (head 2).

Timing: each event is applied on the clock after the one it comes on, a clock behind
the count (the RTL registers it, with what it selects, ahead of the word); a reset
also empties the waiting event and puts the base at the head offset (the count is
reset with the track word).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..codes.debruijn import Code

SCORE_UP = 4
SCORE_LIMIT = 12


def default_quiet(n: int) -> int:
    """Checks without a disagreement after which a head counts as quiet: 4N, at most 63."""
    return min(4 * n, 63)


def health_after_check(t, dual: int, dual_cw: int) -> tuple[int, int]:
    """A head's score and quiet count after its last clock's check (the registered
    checked / mismatch / raw_checked / raw_changed of track `t`): law mode, unless the
    two hypotheses of a missed state predict different bits there, or raw mode (never
    both). A disagreement adds score_up (up to score_limit) and zeroes the quiet count;
    an agreement takes one off the score and counts towards quiet."""
    score, quiet = t.score, t.quiet
    alt = t.mismatch_lo if dual_cw else t.mismatch_hi
    scored = (t.checked and not (dual and t.mismatch != alt)) or t.raw_checked
    disagreed = t.mismatch if t.checked else t.raw_changed
    if scored:
        score = min(score + t.score_up, t.score_limit) if disagreed else max(score - 1, 0)
        quiet = 0 if disagreed else min(quiet + 1, t.quiet_max)
    return score, quiet


@dataclass
class TrackEvent:
    """One clock's input: at most one of strobe, up, down; illegal may come with up/down.
    `illegal_cw`: the way the count took at an illegal transition (two quarters CW)."""

    strobe: int = 0
    up: int = 0
    down: int = 0
    illegal: int = 0
    head: int = 0
    illegal_cw: int = 0


class TrackWord:
    def __init__(self, code: Code, head_offset: int, score_up: int = SCORE_UP,
                 score_limit: int = SCORE_LIMIT, ext_max: int | None = None, quiet_max: int | None = None,
                 event_delay: bool = True, keep: bool = True):
        self.code = code
        self.n = code.n
        self.mask = code.mask
        self.head_offset = head_offset  # 0 for head 1, N - 1 for head 2
        self.score_up, self.score_limit = score_up, score_limit
        self.ext_max = code.n + 1 if ext_max is None else ext_max
        self.ext_lo = 0
        self.ext_hi = 0
        self.primed = 0         # the window was full since the last flush: every bit read or predicted
        self.quiet_max = default_quiet(code.n) if quiet_max is None else quiet_max
        self.quiet = self.quiet_max  # agreeing checks since the head's last disagreement (saturating)
        # registers
        self.word = 0
        self.known = 0
        self.index = 0
        self.law = 0
        self.base = 0           # slot count - index + head_offset (mod 2^N)
        self.full = 0
        self.steady = 0         # the window's offset (its disc slot - base) is the last clock's: no
                                # reading changed the word, no realignment or flush moved it
        self.strobe = 0         # a strobe was handled on the last clock
        self.checked = 0        # ... in law mode: compared with the window
        self.mismatch = 0       # ... and disagreed
        self.raw_checked = 0    # ... in raw mode: a bit read or predicted before was read again
        self.raw_changed = 0    # ... and the reading changed it
        self.mismatch_lo = 0
        self.mismatch_hi = 0
        self.score = 0
        self.errors = 0
        self.addr = 0           # what the converter reads: the word after this clock
        self.realign = 0        # pending index move after a hypothesis change: 0, +1 or -1
        self.event_delay = event_delay  # False: apply each event on its own clock (not the RTL)
        self.keep = keep  # a missed state in raw mode keeps the readings right either way
                          # (HYPOTHESES = 1); else it forgets them all
        self.ahead = (TrackEvent(), 0)  # the ports' event and slot, applied on the next clock

    def bit(self, word: int, i: int) -> int:
        return (word >> (self.n - 1 - i)) & 1

    @property
    def span(self) -> int:
        """Consistent readings beyond the N of a full raw window (0 otherwise)."""
        if not self.full or self.law:
            return 0
        return min(self.ext_lo + self.ext_hi, self.ext_max)

    @property
    def settled(self) -> int:
        """No recent disagreement: the head may take part in a lock."""
        return int(self.score == 0)

    @property
    def is_quiet(self) -> int:
        """No disagreement of this head in its last quiet_max checks (or since reset)."""
        return int(self.quiet >= self.quiet_max)

    @property
    def supported(self) -> int:
        return int(self.law and self.score < self.score_limit)

    def clock(self, ev: TrackEvent, slot: int, flush: int = 0, law_on: int = 0, realign: int = 0,
              dual: int = 0, dual_cw: int = 0,
              rst: int = 0, error_max: int = 0xFFFF, clear_errors: int = 0) -> None:
        """One rising edge. `ev` and `slot` (the slot count after the event's move) are
        registered and applied on the next edge, one clock behind the count (the RTL
        registers what they select ahead of it); this edge applies the last ones.
        `realign` (+1 / -1) moves the index one slot, on the first clock without an
        event after this one."""
        if self.event_delay:  # the RTL resets the delayed event, and the base to HEAD_OFFSET
            (ev, slot), self.ahead = self.ahead, ((TrackEvent(), 0) if rst else (ev, slot))
            if rst:
                slot = 0
        n, word, known, index, law = self.n, self.word, self.known, self.index, self.law
        pending = self.realign  # the judge's pulse waits a clock in the register
        moved_off = 0  # a realignment moves the window against the count: the offset moves
        if pending and not (ev.up or ev.down or ev.strobe):
            ev = TrackEvent(up=int(pending > 0), down=int(pending < 0), illegal=ev.illegal)
            pending, moved_off = 0, 1
        pending = pending or realign
        score, quiet = health_after_check(self, dual, dual_cw)
        demote = law and self.score >= self.score_limit  # from the register: a clock after the limit
        errors = self.errors
        if self.checked and self.mismatch and errors < error_max:
            errors += 1
        if clear_errors:
            errors = 0
        mismatch = mismatch_lo = mismatch_hi = 0
        raw_checked = raw_changed = 0
        ext_lo, ext_hi, lowest = self.ext_lo, self.ext_hi, 1 << (n - 1)  # index 0 is the MSB
        rewritten = 0  # this clock's event slides the window or writes a reading
        if ev.up:
            if index == n - 1:
                rewritten = 1
                word = ((word << 1) & self.mask) | int(self.code.forward_bit(word))
                ext_lo = min(ext_lo + 1, self.ext_max) if known & lowest else 0
                known = ((known << 1) & self.mask) | int(ext_hi > 0)
                ext_hi = max(ext_hi - 1, 0)
            else:
                index += 1
        elif ev.down:
            if index == 0:
                rewritten = 1
                word = (word >> 1) | (int(self.code.inverse_bit(word)) << (n - 1))
                ext_hi = min(ext_hi + 1, self.ext_max) if known & 1 else 0
                known = (known >> 1) | (lowest if ext_lo > 0 else 0)
                ext_lo = max(ext_lo - 1, 0)
            else:
                index -= 1
        elif ev.strobe:
            if law:
                lo = self.bit(word, index - 1) if index > 0 else int(self.code.inverse_bit(word))
                hi = self.bit(word, index + 1) if index < n - 1 else int(self.code.forward_bit(word))
                mismatch = int(ev.head != self.bit(word, index))
                mismatch_lo = int(ev.head != lo)
                mismatch_hi = int(ev.head != hi)
            else:
                b = 1 << (n - 1 - index)
                changed = ev.head != self.bit(word, index)
                if changed:
                    ext_lo = ext_hi = 0  # a new word: the readings outside agreed with the old one
                    moved_off = 1
                # The bit was read or predicted: a check of the head, scored next clock
                # (a lock turning the track to law mode now starts it afresh).
                raw_checked, raw_changed = int(self.primed and not law_on), int(changed)
                word = (word & ~b & self.mask) | (b if ev.head else 0)
                known |= b
                rewritten = 1
        if law:
            ext_lo = ext_hi = 0
        primed = int(self.primed or (known == self.mask))
        if ev.illegal and not law:
            # The count may be a slot off: the other way, each reading belongs one slot
            # further along the count's way (index + 1 when the count took the CW step).
            # A bit stays known only where the bit that would take its place (index - 1
            # when CW) is known and equal to it: right whichever way the disc went
            # (docs/architecture.md); none when the same clock slides the window or
            # writes a reading. The rest are in doubt, not the window's place: it keeps
            # sliding with the count, so a lock decided on the clock before still finds
            # its word, and the judge keeps both ways open.
            if rewritten or not self.keep:
                known = 0
            elif ev.illegal_cw:
                known &= (known >> 1) & ~(word ^ (word >> 1)) & self.mask
            else:
                known &= (known << 1) & ~(word ^ (word << 1)) & self.mask
            ext_lo, ext_hi, primed = 0, 0, 0
        if law_on:
            law, score = 1, 0
        if flush or demote:  # the score stays: it is the head's record, not the window's
            known, index, law, pending, ext_lo, ext_hi, primed = 0, 0, 0, 0, 0, 0, 0
            moved_off = 1
        if rst:
            known, index, law, score, errors, pending, ext_lo, ext_hi, primed = 0, 0, 0, 0, 0, 0, 0, 0, 0
            mismatch = mismatch_lo = mismatch_hi = 0
            quiet = self.quiet_max
        self.strobe = int(ev.strobe and not rst)
        self.checked = int(ev.strobe and self.law and not rst)
        self.mismatch, self.mismatch_lo, self.mismatch_hi = mismatch, mismatch_lo, mismatch_hi
        self.raw_checked, self.raw_changed = int(raw_checked and not rst), raw_changed
        self.addr = word
        self.realign = pending
        self.word, self.known, self.index, self.law = word, known, index, law
        self.score, self.errors = score, errors
        self.ext_lo, self.ext_hi, self.primed, self.quiet = ext_lo, ext_hi, primed, quiet
        # A slide or a move keeps the offset: the law extends any word to the next
        # window of the disc, and the base follows the count.
        self.steady = int(not moved_off and not rst)
        self.full = int(known == self.mask)
        self.base = (slot - index + self.head_offset) & self.mask
