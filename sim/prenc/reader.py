"""The whole reader at the level of events: the reference the RTL core must agree with.

Events are what the quadrature decoder makes of the sync track, each legal step
with the two head readings taken with it, and illegal transitions:

    reader = Reader(Code(10))
    for ev in events:                  # Step(cw, quarter, head1, head2) or Illegal()
        out = reader.event(ev)         # ReaderState after it
        out.valid, out.pos_abs, out.pos_hyb, out.mode

It keeps no clock: one event is one step of the disc as the decoder saw it. It
mirrors prenc_core's stages (sampler rule, shift register, predictor, converter,
position count, track monitors, mode state machine) with the ROM replaced by the
code's own position lookup. `events_from_run` makes the event stream from a
virtual-encoder run through the conditioner and quadrature models, as the RTL
sees it; `prenc.campaign` makes events straight from a trajectory of quarters.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Iterable, NamedTuple

from .debruijn import Code
from .encoder import SIGNALS, EncoderRun
from .input_conditioner import InputConditioner
from .mode_fsm import Mode, ModeFsm
from .predictor import expected_heads
from .quadrature import QuadratureDecoder
from .shift_register import ShiftRegister
from .track_monitor import TrackMonitor, TrackRun


class Step(NamedTuple):
    """A legal quadrature step into `quarter`, with the heads read with it."""

    cw: int
    quarter: int
    head1: int
    head2: int
    clock: int = -1  # the RTL clock of the decoder's step, where known


class Illegal(NamedTuple):
    """A and B changed together: the decoder cannot tell the direction."""

    quarter: int
    clock: int = -1


class Check(NamedTuple):
    """One strobe with a full word: the heads against the prediction, and after it."""

    slot: int           # incremental slot count of the strobe
    mismatch1: int
    mismatch2: int
    mode: Mode
    valid: bool
    pos_abs: int


@dataclass
class ReaderState:
    mode: Mode
    valid: bool
    pos_abs: int
    pos_hyb: int
    incremental: int  # quadrature steps, signed


class Reader:
    def __init__(self, code: Code, run_long: int | None = None, quarter: int = 0):
        self.code = code
        self.n, self.length = code.n, code.length
        self.mask = self.length - 1
        self.word = ShiftRegister(code.n)
        self.track1 = TrackMonitor(code.n, run_long)
        self.track2 = TrackMonitor(code.n, run_long)
        self.fsm = ModeFsm()
        self.slot = 0           # incremental slot count, modulo 2^N
        self.quarter = quarter
        self.offset = 0         # disc slot minus slot count, from the converter
        self.incremental = 0
        self.have_last = False  # sampler: a strobe since reset or the last break
        self.last_cw = 0
        self.checks: list[Check] = []
        self.strobes = 0
        self._clock = -1        # clock of the step being handled, where known
        self._check_clock = -2  # clock of the step of the last check

    # -- outputs
    @property
    def pos_abs(self) -> int:
        return (self.slot + self.offset) & self.mask

    def state(self) -> ReaderState:
        return ReaderState(self.fsm.mode, self.fsm.valid, self.pos_abs,
                           4 * self.pos_abs + self.quarter, self.incremental)

    # -- events
    def event(self, ev: Step | Illegal) -> ReaderState:
        if isinstance(ev, Illegal):
            self._illegal(ev.quarter)
            if self.checks and ev.clock >= 0 and self._check_clock == ev.clock - 1:
                # The RTL decides a strobe's check one clock after the step, on the
                # same clock as this illegal transition: it shows both together.
                self.checks[-1] = self.checks[-1]._replace(mode=self.fsm.mode, valid=self.fsm.valid,
                                                           pos_abs=self.pos_abs)
        else:
            self._clock = ev.clock
            self._step(ev)
        return self.state()

    def run(self, events: Iterable[Step | Illegal]) -> list[ReaderState]:
        return [self.event(ev) for ev in events]

    def _restart(self) -> None:
        """The word is empty: tracks and bad marks start over."""
        self.word.clock(0, 0, 0, 0, 0, flush=1)
        for track in (self.track1, self.track2):
            track.next(True, False, False, 0)
            track.commit()
        self.fsm.bad1 = self.fsm.bad2 = False

    def _illegal(self, quarter: int) -> None:
        self.quarter = quarter
        self.have_last = False
        none = TrackRun(False, False, False)
        self.fsm.next(True, False, False, False, self.slot, True, none, none)
        self.fsm.commit()
        self._restart()

    def _step(self, ev: Step) -> None:
        self.incremental += 1 if ev.cw else -1
        self.quarter = ev.quarter
        if ev.cw and ev.quarter == 0:
            self.slot = (self.slot + 1) & self.mask
        elif not ev.cw and ev.quarter == 3:
            self.slot = (self.slot - 1) & self.mask
        if ev.quarter == (2 if ev.cw else 1):
            self._strobe(ev.cw, ev.head1, ev.head2)

    def _strobe(self, cw: int, head1: int, head2: int) -> None:
        self.strobes += 1
        moved = int(not self.have_last or cw == self.last_cw)
        self.have_last, self.last_cw = True, cw
        before = self.word.output()
        flush = False
        if before.full:
            e1, e2 = expected_heads(self.code, before.word, cw, moved)
            m1, m2 = int(head1 != e1), int(head2 != e2)
            run1 = self.track1.next(False, True, bool(m1), self.slot)
            run2 = self.track2.next(False, True, bool(m2), self.slot)
            flush = self.fsm.next(False, True, bool(m1), bool(m2), self.slot, True, run1, run2)
            self.track1.commit()
            self.track2.commit()
            self.fsm.commit()
            head1, head2 = e1, e2  # a full word advances by the law
        else:
            (self.track2 if cw else self.track1).feed(self.slot, before.count == 0)
        after = self.word.clock(1, cw, moved, head1, head2)
        if flush:
            self._restart()
        elif after.full and not before.full:
            self.offset = (self.code.position(after.word) - self.slot) & self.mask
        if before.full:
            self.checks.append(Check(self.slot, m1, m2, self.fsm.mode, self.fsm.valid, self.pos_abs))
            self._check_clock = self._clock


def events_from_run(enc: EncoderRun, filter_len: int = 0, reset_clocks: int = 4,
                    tail: int = 0) -> list[Step | Illegal]:
    """What the RTL's conditioner and quadrature decoder make of a run, as events.

    Each step carries the heads as the sampler takes them (the conditioned heads the
    decoder's step was made from) and the clock of the decoder's output. `tail`
    more clocks hold the last input levels."""
    cond = InputConditioner(4, filter_len)
    quad = QuadratureDecoder()
    clean_before = [0, 0, 0, 1]
    events: list[Step | Illegal] = []
    rows = list(zip(*(enc.signals[s].tolist() for s in SIGNALS)))
    rows += rows[-1:] * tail
    for k, raw in enumerate(rows):
        rst = int(k < reset_clocks)
        q = quad.clock(clean_before[2], clean_before[3], rst=rst)
        heads_now = (clean_before[0], clean_before[1])
        clean_before = cond.clock(list(raw), rst=rst)
        if not rst:
            if q.step:
                events.append(Step(q.step_cw, q.quarter, heads_now[0], heads_now[1], k))
            elif q.illegal:
                events.append(Illegal(q.quarter, k))
    return events
