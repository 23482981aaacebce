# SPDX-License-Identifier: Apache-2.0
"""The correlation decoder: the model of rtl/nd/prenc_correlator.v, in the same integers.

A line or area sensor sees a whole reading at once: for each of m tracks, n bits, p
samples per bit, each sample a B-bit intensity x[j][i][q]. The decoder centres every
sample on the fixed mid-scale, x~ = 2x - (2^B - 1) (signed; > 0 is white), and tests
K * p candidates (k, f): the reading's window starts f/p of a bit after bit k, so
sample q of bit i shows bit i + [q + f >= p] of the candidate's (n+1)-bit window
W_j(k + phi_j) on track j. Soft decision, the summed cross-correlation of the paper
in exact integers:

    score(k, f) = sum_j sum_i sum_q ( x~[j][i][q] if that bit is 1 else -x~[j][i][q] )

Centring on the fixed mid-scale (not on the reading's own mean) keeps the all-zero and
all-one windows of a de Bruijn-like sequence readable, and a contrast loss about
mid-grey scales every score alike. Testing the p sub-bit phases makes the decoder
indifferent to where the bit edges fall in the image, and gives the position to 1/p
of a bit.

Hard decision: bit i of track j reads 1 when sum_q x~[j][i][q] > 0, and
score(k, f) = the number of the m*n bits that agree with the first n bits of the
candidate's windows (the same for every f): m*n minus the Hamming distance, so the
best candidate is the nearest window and any (D-1)/2 misread bits are corrected
(D the minimum summed distance of the code).

Two passes over the candidates (k major, f minor; one candidate per clock in RTL):
the first finds the best score (the first candidate on a tie); the second finds the
best score among the candidates at least two bits away from it (cyclic distance of k
>= 2), since the neighbours k +- 1 of a true position always score well. `ambiguous`
is set when best - second < threshold.

ROM word of bit-candidate k: bit j*(n+1) + i = bit i of W_j(k + phi_j), i = 0..n
(i = 0 the window's first bit s_j(k + phi_j)); written in hex by `rom_text`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .sequence import as_bits


@dataclass(frozen=True)
class Decoded:
    position: int
    fraction: int
    score: int
    second: int
    ambiguous: bool


def rom_windows(seqs, n: int, phases=None) -> np.ndarray:
    """Expected bits per bit-candidate: shape (K, m, n+1); [k, j, i] = s_j(k + phi_j + i)."""
    seqs = [as_bits(s) for s in seqs]
    k = len(seqs[0])
    if any(len(s) != k for s in seqs):
        raise ValueError("parallel sequences must all have the same length")
    phases = [0] * len(seqs) if phases is None else list(phases)
    if len(phases) != len(seqs):
        raise ValueError("one phase per sequence")
    idx = np.arange(k)[:, None] + np.arange(n + 1)[None, :]
    return np.stack([s[(idx + ph) % k] for s, ph in zip(seqs, phases)], axis=1).astype(np.uint8)


def rom_words(windows: np.ndarray) -> list[int]:
    """The ROM word of each bit-candidate, bit j*(n+1) + i = windows[k, j, i]."""
    k, m, n1 = windows.shape
    flat = windows.reshape(k, m * n1)
    return [sum(int(b) << i for i, b in enumerate(row)) for row in flat]


def rom_text(windows: np.ndarray) -> str:
    """$readmemh text: one hex word per bit-candidate, with a comment header."""
    k, m, n1 = windows.shape
    digits = -(-(m * n1) // 4)
    lines = [f"// prenc_correlator ROM: {k} positions, {m} track(s) x {n1} bits (n+1); "
             f"bit j*{n1}+i = bit i of track j's window"]
    lines += [f"{w:0{digits}x}" for w in rom_words(windows)]
    return "\n".join(lines) + "\n"


def centred(samples: np.ndarray, sample_bits: int) -> np.ndarray:
    """x~ = 2x - (2^B - 1), signed."""
    return 2 * np.asarray(samples, dtype=np.int64) - ((1 << sample_bits) - 1)


def templates(windows: np.ndarray, p: int) -> np.ndarray:
    """+-1 expected sample signs: shape (K, p, m, n, p) for candidates (k, f)."""
    k, m, n1 = windows.shape
    n = n1 - 1
    sign = 2 * windows.astype(np.int64) - 1                          # (K, m, n+1)
    f = np.arange(p)[:, None]
    q = np.arange(p)[None, :]
    step = (f + q >= p).astype(np.int64)                             # (p_f, p_q)
    idx = np.arange(n)[None, :, None] + step[:, None, :]             # (p_f, n, p_q)
    return sign[:, :, idx].transpose(0, 2, 1, 3, 4)                 # (K, p_f, m, n, p_q)


def score_all(samples: np.ndarray, windows: np.ndarray, sample_bits: int, hard: bool = False) -> np.ndarray:
    """Scores of every candidate for readings (..., m, n, p) -> (..., K, p)."""
    x = centred(samples, sample_bits)
    p = x.shape[-1]
    if hard:
        bits = (x.sum(axis=-1) > 0).astype(np.int64)                 # (..., m, n)
        n = bits.shape[-1]
        agree = (bits[..., None, :, :] == windows[:, :, :n]).sum(axis=(-1, -2))
        return np.repeat(agree[..., None], p, axis=-1)
    return np.einsum("...jiq,kfjiq->...kf", x, templates(windows, p))


def pick(scores: np.ndarray, threshold: int) -> Decoded:
    """The two passes over one reading's (K, p) scores."""
    k_count, p = scores.shape
    flat = scores.ravel()
    c = int(np.argmax(flat))
    k, f = divmod(c, p)
    best = int(flat[c])
    dist = np.abs(np.arange(k_count) - k)
    far = np.minimum(dist, k_count - dist) >= 2
    second = int(scores[far].max()) if far.any() else best
    return Decoded(k, f, best, second, best - second < threshold)


def decode(samples: np.ndarray, windows: np.ndarray, sample_bits: int, hard: bool = False,
           threshold: int = 1) -> Decoded:
    """Decode one reading (m, n, p) against the ROM windows (K, m, n+1)."""
    return pick(score_all(samples, windows, sample_bits, hard), threshold)


def starts(samples: np.ndarray, windows: np.ndarray, sample_bits: int) -> np.ndarray:
    """Decoded window start k + f/p (in bits) of many soft readings (R, m, n, p)."""
    scores = score_all(samples, windows, sample_bits)
    r, k, p = scores.shape
    c = np.argmax(scores.reshape(r, k * p), axis=1)
    return c / p

