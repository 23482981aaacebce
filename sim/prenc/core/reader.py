# SPDX-License-Identifier: Apache-2.0
"""The reader core, clock by clock: the model that prenc_core must equal.

    reader = Reader(Code(10), filter_len=2)
    out = reader.clock([head1, head2, a, b], rst)   # outputs after the rising edge
    out.valid, out.pos_abs, out.pos_hyb, out.mode, out.dual

The stages, each the model of one RTL module, registered as in the RTL:

    pins -> InputConditioner -> QuadratureDecoder, and on the same edge
                                Sampler (strobes, heads) and Position (count, events)
         -> TrackWord x2 (one head each; raw or law mode; each event a clock after
            the count) -> converter (the ROM)
         -> J1 registers (offset of each track's window) -> ModeFsm (the judge)
         -> pos_abs = count (delayed) + offset, pos_valid, mode

The sampler and the position take the decoder's step on the decoder's own edge (its
next values, as prenc_quadrature's *_next outputs give them to the RTL's).
`clock_decoded` enters there, for the fault campaign. The judge gets each track's offset
of this clock (prenc_core with CONV_REG = 0), or with `conv_reg` the clock before's
(CONV_REG = 1), and decides the same either way: it reads an offset only while the
track is steady (the same offset as on the clock before).
`hypotheses` is HYPOTHESES; `keep` (default: as `hypotheses`) is the track words' KEEP,
which the core sets to HYPOTHESES: False empties the windows at a missed state while
acquiring, for the bench's and the tests' comparisons.
Latency: outputs show the pins LATENCY + FILTER clocks earlier.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple, Sequence, TYPE_CHECKING

from ..codes.debruijn import Code
from .input_conditioner import InputConditioner
from .mode_fsm import DUAL_SPAN, DUAL_VOTES, JudgeInput, Mode, ModeFsm
from .position import Position
from .quadrature import QuadratureDecoder, QuadratureOutput
from .sampler import Sampler
from .track_word import SCORE_LIMIT, SCORE_UP, TrackEvent, TrackWord

if TYPE_CHECKING:  # the virtual encoder feeds the model; the model does not need it
    from ..virtual.encoder import EncoderRun

LATENCY = 6  # clocks from a pin to pos_abs / pos_valid, plus FILTER


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


@dataclass
class ReaderOutput:
    valid: int
    pos_abs: int
    pos_hyb: int
    mode: int
    dual: int


class Reader:
    def __init__(self, code: Code, filter_len: int = 0, lock_both: int | None = None,
                 lock_one: int | None = None, dual_votes: int = DUAL_VOTES,
                 dual_span: int = DUAL_SPAN, score_up: int = SCORE_UP, score_limit: int = SCORE_LIMIT,
                 hypotheses: bool = True, conv_reg: bool = False, keep: bool | None = None):
        self.code = code
        self.n = code.n
        self.mask = code.mask
        self.conditioner = InputConditioner(4, filter_len, paired=True)
        self.quadrature = QuadratureDecoder()
        # The landing reading serves the hypotheses; the step comes with the heads' sample.
        self.sampler = Sampler(jump=hypotheses, head_delay=False)
        self.position = Position(code.n)
        self.fsm = ModeFsm(code.n, lock_both=lock_both, lock_one=lock_one, dual_votes=dual_votes,
                           dual_span=dual_span, hypotheses=hypotheses)
        ext_max = max(self.fsm.lock_one, self.fsm.lock_both) - 1 + self.fsm.lock_extra
        keep = hypotheses if keep is None else keep
        self.tracks = [TrackWord(code, 0, score_up, score_limit, ext_max, keep=keep),
                       TrackWord(code, code.n - 1, score_up, score_limit, ext_max, keep=keep)]
        self.j1 = JudgeInput()
        self.conv_reg = conv_reg  # CONV_REG = 1: the judge gets the offsets of the clock before
        self.off_before = [0, 0]
        self.t_illegal = self.t_illegal_cw = 0
        self.e_illegal = self.e_illegal_cw = 0
        self.clean = [0, 0, 0, 1]
        self.strobes = 0

    def output(self) -> ReaderOutput:
        pos = (self.position.slot_d[-1] + self.fsm.offset) & self.mask
        return ReaderOutput(int(self.fsm.valid), pos, 4 * pos + self.position.quarter_d[-1],
                            int(self.fsm.mode), self.fsm.dual)

    def _core(self, quad: QuadratureOutput, heads: Sequence[int], rst: int) -> None:
        """Everything after the quadrature decoder, for one rising edge: `quad` is what the
        decoder registers at this edge, `heads` the heads of the same input sample."""
        tracks, pos, s = self.tracks, self.position, self.sampler.out
        self.fsm.clock(self.j1, tuple(t.supported for t in tracks), tuple(t.law for t in tracks), rst=rst)
        off = [(self.code.position(t.word) - t.base) & self.mask for t in tracks]
        if self.conv_reg:
            off, self.off_before = self.off_before, off
        self.j1 = JudgeInput.of_tracks(tracks, off, self.t_illegal, self.t_illegal_cw,
                                       (tracks[0].base + tracks[0].index) & self.mask)
        if rst:
            self.j1 = JudgeInput()
        flush, law_on, realign, dual, dual_cw = self._ctrl
        for h, t in enumerate(tracks):
            ev = TrackEvent(strobe=s.strobe, up=pos.up, down=pos.down, illegal=pos.illegal,
                            head=s.head1 if h == 0 else s.head2, illegal_cw=pos.illegal_cw)
            t.clock(ev, pos.slot, flush=flush[h], law_on=law_on[h], realign=realign,
                    dual=dual, dual_cw=dual_cw, rst=rst)
        # The track words apply each event a clock after the count: so do its flags.
        self.t_illegal, self.t_illegal_cw = int(self.e_illegal and not rst), self.e_illegal_cw
        self.e_illegal, self.e_illegal_cw = int(pos.illegal and not rst), pos.illegal_cw
        self.strobes += s.strobe and not rst
        pos.clock(quad, rst=rst)
        self.sampler.clock(heads[0], heads[1], quad.step, quad.step_cw, quad.quarter,
                           break_in=quad.illegal, rst=rst)

    def _latch_ctrl(self) -> None:
        """The judge's registered outputs, as the tracks see them on this edge."""
        f = self.fsm
        self._ctrl = (list(f.flush), list(f.law_on), f.realign, f.dual, f.dual_cw)

    def clock(self, raw: Sequence[int], rst: int = 0) -> ReaderOutput:
        clean_before = self.clean
        self._latch_ctrl()
        quad = self.quadrature.clock(clean_before[2], clean_before[3], rst=rst)
        self._core(quad, clean_before, rst)
        self.clean = self.conditioner.clock(list(raw), rst=rst)
        return self.output()

    def clock_decoded(self, quad: QuadratureOutput, head1: int, head2: int, rst: int = 0) -> ReaderOutput:
        """One edge with `quad` as what the decoder registers and the heads read with it."""
        self._latch_ctrl()
        self._core(quad, (head1, head2), rst)
        return self.output()

    def run(self, enc: EncoderRun, reset_clocks: int = 4, tail: int = 0) -> list[ReaderOutput]:
        rows = enc.rows()
        rows += rows[-1:] * tail
        return [self.clock(list(r), rst=int(k < reset_clocks)) for k, r in enumerate(rows)]


def events_from_run(enc: EncoderRun, filter_len: int = 0, reset_clocks: int = 4,
                    tail: int = 0) -> list[Step | Illegal]:
    """What the RTL's conditioner and quadrature decoder make of a run, as events.

    Each step carries the heads as the sampler takes them (the conditioned heads the
    decoder's step was made from) and the clock of the decoder's output. `tail`
    more clocks hold the last input levels."""
    cond = InputConditioner(4, filter_len, paired=True)
    quad = QuadratureDecoder()
    clean_before = [0, 0, 0, 1]
    events: list[Step | Illegal] = []
    rows = enc.rows()
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
