# SPDX-License-Identifier: Apache-2.0
"""Model of rtl/core/prenc_predictor.v: what each head must read at a strobe.

From the word W(p) before the strobe and its direction:
  CW to p+1:   head 2 = forward law of W(p) = s(p+N),  head 1 = s(p+1)
  CCW to p-1:  head 1 = inverse law of W(p) = s(p-1), head 2 = s(p+N-2)
  same slot:   head 1 = s(p), head 2 = s(p+N-1)
A head that reads otherwise is flagged; checks need a full word.
"""

from __future__ import annotations

from typing import NamedTuple

from ..codes.debruijn import Code


def taps_mask(taps) -> int:
    """The RTL's TAPS parameter: bit t-1 set for each tap t."""
    mask = 0
    for t in taps:
        mask |= 1 << (t - 1)
    return mask


class Prediction(NamedTuple):
    check: int
    expect1: int
    expect2: int
    mismatch1: int
    mismatch2: int


def expected_heads(code: Code, word: int, cw: int, moved: int) -> tuple[int, int]:
    """(head 1, head 2) that a correct disc shows at the strobe."""
    n = code.n
    if not moved:
        return (word >> (n - 1)) & 1, word & 1
    if cw:
        return (word >> (n - 2)) & 1, int(code.forward_bit(word))
    return int(code.inverse_bit(word)), (word >> 1) & 1


class Predictor:
    def __init__(self, code: Code):
        self.code = code
        self.out = Prediction(0, 0, 0, 0, 0)

    def clock(self, strobe: int, cw: int, moved: int, head1: int, head2: int,
              word: int, full: int, rst: int = 0) -> Prediction:
        e1, e2 = expected_heads(self.code, word, cw, moved)
        check = int(bool(strobe and full))
        expect1, expect2 = (e1, e2) if strobe else (self.out.expect1, self.out.expect2)
        out = Prediction(check, expect1, expect2, int(check and head1 != e1), int(check and head2 != e2))
        if rst:
            out = out._replace(check=0, mismatch1=0, mismatch2=0)
        self.out = out
        return out
