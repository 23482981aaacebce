# SPDX-License-Identifier: Apache-2.0
"""The reader core's front end, its models chained: pins -> conditioner -> quadrature ->
sampler, clock by clock, as prenc_core wires prenc_input_conditioner, prenc_quadrature
and prenc_sampler.

Testbenches of one RTL module use this chain to make that module's inputs from a
virtual-encoder run (the models are proven equal to their RTL one by one), and the
model tests use it to check the chain against the truth.
"""

from __future__ import annotations

from typing import TYPE_CHECKING
from dataclasses import dataclass, field

from .input_conditioner import InputConditioner
from .quadrature import QuadratureDecoder, QuadratureOutput
from .sampler import Sampler, Strobe

if TYPE_CHECKING:  # the virtual encoder feeds the model; the model does not need it
    from ..virtual.encoder import EncoderRun


@dataclass
class FrontEndClock:
    """Every stage's outputs after one rising edge."""

    clean: list[int]  # head1, head2, a, b after the conditioner
    quad: QuadratureOutput
    strobe: Strobe


@dataclass
class FrontEnd:
    filter_len: int = 0
    conditioner: InputConditioner = field(init=False)
    quadrature: QuadratureDecoder = field(init=False)
    sampler: Sampler = field(init=False)
    _clean: list[int] = field(default_factory=lambda: [0, 0, 0, 1], init=False, repr=False)

    def __post_init__(self) -> None:
        self.conditioner = InputConditioner(4, self.filter_len, paired=True)
        self.quadrature = QuadratureDecoder()
        self.sampler = Sampler()

    def clock(self, raw: list[int], rst: int = 0) -> FrontEndClock:
        """One clock; each stage sees the registered outputs of the one before it
        as they were before this edge, as in the RTL."""
        quad_before = self.quadrature.output()
        clean_before = self._clean
        strobe = self.sampler.clock(clean_before[0], clean_before[1], quad_before.step,
                                    quad_before.step_cw, quad_before.quarter,
                                    break_in=quad_before.illegal, rst=rst)
        quad = self.quadrature.clock(clean_before[2], clean_before[3], rst=rst)
        self._clean = self.conditioner.clock(raw, rst=rst)
        return FrontEndClock(list(self._clean), quad, strobe)

    def run(self, enc: EncoderRun, reset_clocks: int = 4) -> list[FrontEndClock]:
        """The chain over a whole run; rst is high for the first reset_clocks clocks."""
        rows = enc.rows()
        return [self.clock(list(row), rst=int(k < reset_clocks)) for k, row in enumerate(rows)]
