# SPDX-License-Identifier: Apache-2.0
"""Code word -> slot conversion: the model of rtl/core/prenc_converter.v, and the serial
method of the literature it replaces.

`Converter` is a registered ROM read: a word presented with `word_valid` on one
clock gives its slot p with `pos_valid` on the next (latency 1 clock), whatever N.

`SerialConverter` is the conversion used where no ROM is affordable: start from
the known word W(0) and step the LFSR law until the word matches, counting
clocks. Slot p takes p steps, so the worst case is L - 1 = 2^N - 1 clocks.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import NamedTuple

from ..codes.debruijn import Code

CONVERTER_LATENCY = 1


class ConverterOutput(NamedTuple):
    pos_valid: int
    pos: int | None  # None where the RTL holds whatever it last read


@dataclass
class Converter:
    """Clock-by-clock model of prenc_converter."""

    code: Code
    _valid: int = 0
    _pos: int | None = field(default=None, repr=False)

    def reset(self) -> None:
        self._valid = 0

    def clock(self, word_valid: int, word: int) -> ConverterOutput:
        """One rising clock edge; returns the registered outputs after it."""
        if word_valid:
            self._pos = self.code.position(word)
        self._valid = 1 if word_valid else 0
        return ConverterOutput(self._valid, self._pos)


@dataclass(frozen=True)
class SerialConverter:
    """Serial conversion by stepping the forward law from W(0)."""

    code: Code

    def convert(self, word: int) -> tuple[int, int]:
        """(slot, clocks spent). One clock per LFSR step."""
        w = self.code.window(0)
        steps = 0
        while w != word:
            w = self.code.step_forward(w)
            steps += 1
            if steps >= self.code.length:
                raise ValueError(f"word {word} never appears")
        return steps, steps

    def worst_case_clocks(self) -> int:
        """Slot p needs p steps from W(0): the worst is slot L - 1."""
        return self.code.length - 1
