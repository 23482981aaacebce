# SPDX-License-Identifier: Apache-2.0
"""Parallel (n,d)-sequences: the phasing that maximises the summed distance.

m sequences of the same length K written side by side (tracks of a cylinder or a
disc) are read together: at position k the reader sees the n-window of sequence j at
position k + phi_j. The summed distance matrix of the paper's equation 1 is

    D_phi(k, l) = sum over j of dist(W_j(k + phi_j), W_j(l + phi_j))

and the reading tells positions apart by at least min_{k != l} D_phi(k, l) bits. The
phasing keeps phi_1 = 0 and tries every other phase exhaustively; it maximises that
minimum and breaks ties by the smallest standard deviation of the pairwise values
(so that no pair sits much closer than the rest). A reading with minimum summed
distance D detects D - 1 misread bits and corrects floor((D - 1) / 2).

`dual_track` applies this to the project's own disc: one de Bruijn sequence on two
tracks, the second shifted by D slots.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..codes.debruijn import debruijn_sequence
from ..virtual.encoder import default_shift
from .sequence import as_bits, pairwise_distances


@dataclass(frozen=True)
class Phasing:
    phases: tuple[int, ...]
    min_distance: int
    std: float
    pairs_at_min: int

    @property
    def detects(self) -> int:
        return self.min_distance - 1

    @property
    def corrects(self) -> int:
        return max(0, (self.min_distance - 1) // 2)

    def as_dict(self) -> dict:
        return {"phases": list(self.phases), "min_summed_distance": self.min_distance,
                "std": round(self.std, 4), "pairs_at_min": self.pairs_at_min,
                "detects": self.detects, "corrects": self.corrects}


def _rolled(dist: np.ndarray, phase: int) -> np.ndarray:
    """dist(k + phase, l + phase) as a matrix over (k, l)."""
    return np.roll(dist, -phase, axis=(0, 1))


def summed_matrix(seqs, n: int, phases) -> np.ndarray:
    """D_phi of equation 1 for sequences `seqs` at `phases`."""
    total = None
    for seq, phase in zip(seqs, phases):
        part = _rolled(pairwise_distances(seq, n), phase)
        total = part if total is None else total + part
    return total


def evaluate(summed: np.ndarray, phases) -> Phasing:
    k = len(summed)
    upper = summed[np.triu_indices(k, 1)]
    low = int(upper.min())
    return Phasing(tuple(int(p) for p in phases), low, float(upper.std()), int((upper == low).sum()))


def best_phasing(seqs, n: int) -> Phasing:
    """The phasing of equation 1 (exhaustive over phi_2..phi_m; phi_1 = 0)."""
    seqs = [as_bits(s) for s in seqs]
    k = len(seqs[0])
    if any(len(s) != k for s in seqs):
        raise ValueError("parallel sequences must all have the same length")
    if not 1 <= len(seqs) <= 4:
        raise ValueError(f"1..4 parallel sequences are supported, got {len(seqs)}")
    dists = [pairwise_distances(s, n).astype(np.int16) for s in seqs]
    off = ~np.eye(k, dtype=bool)
    iu = np.triu_indices(k, 1)

    best_key, best_phases = None, (0,) * len(seqs)

    def consider(total: np.ndarray, phases: tuple[int, ...]) -> None:
        nonlocal best_key, best_phases
        values = total[iu]
        key = (int(values.min()), -float(values.std()))
        if best_key is None or key > best_key:
            best_key, best_phases = key, phases

    def grow(total: np.ndarray, phases: tuple[int, ...]) -> None:
        j = len(phases)
        if j == len(seqs):
            consider(total, phases)
            return
        if j == len(seqs) - 1:
            # last sequence: all its phases at once, vectorised; keep only the
            # phases whose minimum ties the best before computing deviations
            stack = np.stack([_rolled(dists[j], p) for p in range(k)])
            totals = stack + total[None]
            mins = np.where(off[None], totals, np.int16(32767)).min(axis=(1, 2))
            top = int(mins.max())
            if best_key is not None and top < best_key[0]:
                return
            for p in np.flatnonzero(mins == top):
                consider(totals[p], phases + (int(p),))
            return
        for p in range(k):
            grow(total + _rolled(dists[j], p), phases + (p,))

    grow(dists[0].copy(), (0,))
    return evaluate(summed_matrix(seqs, n, best_phases), best_phases)


@dataclass(frozen=True)
class DualTrack:
    n: int
    length: int
    track_shift: int
    head_offset: int
    at_line_sensor: Phasing
    at_heads: Phasing
    best: Phasing
    best_offsets: tuple[int, ...]
    by_offset: np.ndarray

    def as_dict(self) -> dict:
        return {"n": self.n, "length": self.length, "track_shift": self.track_shift,
                "head_offset": self.head_offset,
                "line_sensor_at_track_shift": self.at_line_sensor.as_dict(),
                "two_heads_180_degrees": self.at_heads.as_dict(),
                "best": self.best.as_dict(),
                "best_offsets": list(self.best_offsets),
                "best_track_shifts_line_sensor": list(self.best_offsets),
                "best_track_shifts_two_heads": sorted((e - self.length // 2) % self.length
                                                      for e in self.best_offsets),
                "offsets_by_min_distance": {str(v): int((self.by_offset == v).sum())
                                 for v in np.unique(self.by_offset)}}


def dual_track(n: int = 10, taps=None, shift: int | None = None) -> DualTrack:
    """The project's disc: minimum summed distance of its two-track reading for every shift.

    Track 2 carries s(x + D). A line sensor across both tracks at one angle reads the
    windows at p and p + D; the project's two heads, 180 degrees apart, read them at
    p and p + D + L/2 (for the default D that is p + N - 1: the two windows share one
    bit). Both are evaluated, and every offset E from 1 to L-1, to find the best.
    """
    seq = debruijn_sequence(n, taps)
    length = len(seq)
    shift = default_shift(n) if shift is None else shift
    if not 0 <= shift < length:
        raise ValueError(f"track shift D = {shift} is out of range 0..{length - 1}")
    dist = pairwise_distances(seq, n).astype(np.int8)
    off = ~np.eye(length, dtype=bool)
    by_offset = np.zeros(length, dtype=np.int32)
    big = np.int8(127)
    for e in range(length):
        total = dist + _rolled(dist, e)
        by_offset[e] = int(np.where(off, total, big).min())
    top = int(by_offset.max())
    candidates = [int(e) for e in np.flatnonzero(by_offset == top)]
    scored = [evaluate(dist.astype(np.int16) + _rolled(dist, e), (0, e)) for e in candidates]
    best = max(scored, key=lambda ph: (ph.min_distance, -ph.std))
    half = length // 2
    head_offset = (shift + half) % length
    return DualTrack(
        n, length, shift, head_offset,
        evaluate(dist.astype(np.int16) + _rolled(dist, shift), (0, shift)),
        evaluate(dist.astype(np.int16) + _rolled(dist, head_offset), (0, head_offset)),
        best, tuple(candidates), by_offset)
