# SPDX-License-Identifier: Apache-2.0
"""The reader's datapath models chained: pins -> conditioner -> quadrature -> sampler
-> shift register -> predictor, clock by clock.

Testbenches of one RTL module use this chain to make that module's inputs from a
virtual-encoder run (the models are proven equal to their RTL one by one), and the
model tests use it to check the chain against the truth.
"""

from __future__ import annotations

from typing import TYPE_CHECKING
from dataclasses import dataclass, field

from ..codes.debruijn import Code
from .input_conditioner import InputConditioner
from .predictor import Prediction, Predictor, expected_heads
from .quadrature import QuadratureDecoder, QuadratureOutput
from .sampler import Sampler, Strobe
from .shift_register import ShiftRegister, Word

if TYPE_CHECKING:  # the virtual encoder feeds the model; the model does not need it
    from ..virtual.encoder import EncoderRun


@dataclass
class DatapathClock:
    """Every stage's outputs after one rising edge."""

    clean: list[int]  # head1, head2, a, b after the conditioner
    quad: QuadratureOutput
    strobe: Strobe
    word: Word
    prediction: Prediction


@dataclass
class Datapath:
    code: Code
    filter_len: int = 0
    conditioner: InputConditioner = field(init=False)
    quadrature: QuadratureDecoder = field(init=False)
    sampler: Sampler = field(init=False)
    shift_register: ShiftRegister = field(init=False)
    predictor: Predictor = field(init=False)
    _clean: list[int] = field(default_factory=lambda: [0, 0, 0, 1], init=False, repr=False)

    def __post_init__(self) -> None:
        self.conditioner = InputConditioner(4, self.filter_len)
        self.quadrature = QuadratureDecoder()
        self.sampler = Sampler()
        self.shift_register = ShiftRegister(self.code.n)
        self.predictor = Predictor(self.code)

    def clock(self, raw: list[int], rst: int = 0, flush: int = 0) -> DatapathClock:
        """One clock; each stage sees the registered outputs of the one before it
        as they were before this edge, as in the RTL. Once the word is full it
        advances by the law (the predicted bits), not by the readings."""
        quad_before = self.quadrature.output()
        strobe_before = self.sampler.out
        word_before = self.shift_register.output()
        clean_before = self._clean
        prediction = self.predictor.clock(*strobe_before, word=word_before.word, full=word_before.full, rst=rst)
        s = strobe_before
        if word_before.full:
            e1, e2 = expected_heads(self.code, word_before.word, s.cw, s.moved)
            s = s._replace(head1=e1, head2=e2)
        word = self.shift_register.clock(*s, flush=int(quad_before.illegal or flush), rst=rst)
        strobe = self.sampler.clock(clean_before[0], clean_before[1], quad_before.step,
                                    quad_before.step_cw, quad_before.quarter,
                                    break_in=quad_before.illegal, rst=rst)
        quad = self.quadrature.clock(clean_before[2], clean_before[3], rst=rst)
        self._clean = self.conditioner.clock(raw, rst=rst)
        return DatapathClock(list(self._clean), quad, strobe, word, prediction)

    def run(self, enc: EncoderRun, reset_clocks: int = 4) -> list[DatapathClock]:
        """The chain over a whole run; rst is high for the first reset_clocks clocks."""
        rows = enc.rows()
        return [self.clock(list(row), rst=int(k < reset_clocks)) for k, row in enumerate(rows)]
