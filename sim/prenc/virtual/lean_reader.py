# SPDX-License-Identifier: Apache-2.0
"""A design study for a cheaper evidence rule (issue 15's size goal): no RTL.

The core's track words keep each head's window in count space with an index, slide
it by the disc's law and count the consistent slots beyond it (`ext_lo`, `ext_hi`),
so that reversals keep what was read. About 770 of its 1,150 logic cells are that
rule (docs/architecture.md, "What the logic pays for"). This model asks what a much
simpler rule gives up, with the same front end, the same judge (prenc.core.mode_fsm)
and the same lock depths:

- acquiring, each head keeps a plain shift register of its readings in strobe order
  (CW: the newest bit enters at the LSB; CCW: at the MSB), with no index, no slides
  by the law and no evidence counters. A reversal (a strobe that did not move) or an
  illegal transition starts the word again. Once N bits are in, each new reading
  gives a candidate offset (converted word - the slot of its first bit); `span` is
  the run of strobes whose candidates agreed with the one before. Within one
  direction each strobe reads a new slot, so the run counts distinct slots, as the
  core's span does; a re-read never adds to it.
- a raw disagreement is a run that breaks; the score and the quiet count follow the
  core's rules; a head is settled when its score is 0 and its last two candidates
  agreed (a noisy dead head never is).
- locked, a track keeps no word: each reading is compared with the disc's bit at
  count + offset (+ N - 1 for head 2), and with the bits one slot either side for
  the two hypotheses of a missed state: in hardware one ROM of s(p - 1) .. s(p + N)
  addressed by count + offset serves both heads. A hypothesis decided the other way
  moves the offset, and the tracks follow it with no realignment.

What it shows (`make bench` sections 4 and 4b; docs/architecture.md, "A cheaper
evidence rule: a design study"): the core's shares wherever acquisition runs one way,
less where reversals and faults come together (the goal "everything", the campaign),
because a reversal throws the word away; keeping the evidence across a reversal
without counting a slot twice needs what the core's track word has.
"""

from __future__ import annotations

from typing import Sequence

from ..codes.debruijn import Code
from ..core.mode_fsm import JudgeInput
from ..core.quadrature import QuadratureOutput
from ..core.reader import Reader
from ..core.track_word import SCORE_LIMIT, SCORE_UP, default_quiet, health_after_check


class LeanTrack:
    """One head: a shift register of readings while acquiring, the disc's bits when locked."""

    steady = 1  # the judge reads this track's offset as it is now: nothing to wait for

    def __init__(self, code: Code, head_offset: int, ext_max: int, score_up: int = SCORE_UP,
                 score_limit: int = SCORE_LIMIT):
        self.code, self.n, self.mask, self.length = code, code.n, code.mask, code.length
        self.seq = [int(b) for b in code.sequence]
        self.head_offset = head_offset
        self.ext_max, self.score_up, self.score_limit = ext_max, score_up, score_limit
        self.quiet_max = default_quiet(code.n)
        self.quiet = self.quiet_max
        self.word = self.fill = self.dir = self.run = 0
        self.base = 0
        self.prev = None  # the last candidate offset of this run
        self.law = self.score = 0
        self.strobe = self.checked = self.mismatch = self.mismatch_lo = self.mismatch_hi = 0
        self.raw_checked = self.raw_changed = 0

    @property
    def full(self) -> int:
        return int(not self.law and self.fill >= self.n)

    @property
    def off(self) -> int:
        return (self.code.position(self.word) - self.base) & self.mask

    @property
    def span(self) -> int:
        return min(self.run, self.ext_max) if self.full else 0

    @property
    def settled(self) -> int:
        return int(self.score == 0 and self.run >= 1)

    @property
    def is_quiet(self) -> int:
        return int(self.quiet >= self.quiet_max)

    @property
    def supported(self) -> int:
        return int(self.law and self.score < self.score_limit)

    def _restart(self) -> None:
        self.word = self.fill = self.dir = self.run = 0
        self.prev = None

    def clock(self, strobe: int, cw: int, moved: int, head: int, slot: int, illegal: int, offset: int,
              flush: int = 0, law_on: int = 0, dual: int = 0, dual_cw: int = 0, rst: int = 0) -> None:
        n = self.n
        score, quiet = health_after_check(self, dual, dual_cw)  # as the core's track word
        demote = self.law and self.score >= self.score_limit
        law = self.law
        checked = mismatch = mismatch_lo = mismatch_hi = raw_checked = raw_changed = 0
        if strobe and law:
            p = (slot + offset + self.head_offset) % self.length
            checked = 1
            mismatch = int(head != self.seq[p])
            mismatch_lo = int(head != self.seq[(p - 1) % self.length])
            mismatch_hi = int(head != self.seq[(p + 1) % self.length])
        elif strobe:
            d = 1 if cw else -1
            if not (moved and self.dir == d):
                self._restart()
                self.dir = d
            if cw:
                self.word = ((self.word << 1) | head) & self.mask
            else:
                self.word = (self.word >> 1) | (head << (n - 1))
            self.fill = min(self.fill + 1, n)
            # The slot of the word's first bit (its MSB), on this head's track.
            self.base = ((slot - n + 1) if cw else slot) + self.head_offset
            if self.fill >= n:
                cand = self.off
                if self.prev is not None:
                    # A check of an established run (its last two candidates agreed):
                    # it continues, or it breaks (a disagreement of the head).
                    if self.run >= 1:
                        raw_checked, raw_changed = int(not law_on), int(cand != self.prev)
                    self.run = self.run + 1 if cand == self.prev else 0
                self.prev = cand
        if illegal and not law:
            self._restart()
        if law_on:
            law, score = 1, 0
            self._restart()
        if flush or demote:
            law = 0
            self._restart()
        if rst:
            law, score, quiet = 0, 0, self.quiet_max
            self._restart()
            checked = mismatch = mismatch_lo = mismatch_hi = raw_checked = raw_changed = 0
        self.law, self.score, self.quiet = law, score, quiet
        self.strobe = int(strobe and not rst)
        self.checked, self.mismatch, self.mismatch_lo, self.mismatch_hi = checked, mismatch, mismatch_lo, mismatch_hi
        self.raw_checked, self.raw_changed = raw_checked, raw_changed


class LeanReader(Reader):
    """The core's model (prenc.core.reader.Reader: front end, judge, outputs) with two
    LeanTracks in place of its track words."""

    def __init__(self, code: Code, filter_len: int = 0, hypotheses: bool = True):
        super().__init__(code, filter_len, hypotheses=hypotheses)
        ext_max = max(self.fsm.lock_one, self.fsm.lock_both) - 1 + self.fsm.lock_extra
        self.tracks = [LeanTrack(code, 0, ext_max), LeanTrack(code, code.n - 1, ext_max)]
        self.t_slot = 0
        self.ahead = (0, 0, 0, (0, 0), 0, 0, 0)  # the front end's event, for the next clock

    def _core(self, quad: QuadratureOutput, heads: Sequence[int], rst: int) -> None:
        f, tracks, pos, s = self.fsm, self.tracks, self.position, self.sampler.out
        flush, law_on, _, dual, dual_cw = self._ctrl
        offset = f.offset  # the judge's offset as the tracks see it on this edge
        f.clock(self.j1, tuple(t.supported for t in tracks), tuple(t.law for t in tracks), rst=rst)
        self.j1 = JudgeInput.of_tracks(tracks, [t.off for t in tracks], self.t_illegal, self.t_illegal_cw,
                                       self.t_slot)
        if rst:
            self.j1 = JudgeInput()
        # The tracks take each event a clock after the count, as the core's track words do.
        now = (s.strobe, s.cw, s.moved, (s.head1, s.head2), pos.slot, int(pos.illegal and not rst),
               pos.illegal_cw)
        (strobe, cw, moved, heads_e, slot, illegal, illegal_cw), self.ahead = self.ahead, now
        for h, t in enumerate(tracks):
            t.clock(strobe, cw, moved, heads_e[h], slot, illegal, offset,
                    flush=flush[h], law_on=law_on[h], dual=dual, dual_cw=dual_cw, rst=rst)
        self.t_illegal, self.t_illegal_cw = int(illegal and not rst), illegal_cw
        self.t_slot = slot
        self.strobes += s.strobe and not rst
        pos.clock(quad, rst=rst)
        self.sampler.clock(heads[0], heads[1], quad.step, quad.step_cw, quad.quarter,
                           break_in=quad.illegal, rst=rst)
