# SPDX-License-Identifier: Apache-2.0
"""The paper's experiment (its figure 5): six encoders on a cylinder against image noise.

All sequences have K = 170 bits. Single tracks: a (10,1)-, an (8,1)- and a
(10,2)-sequence; parallel tracks (phased by equation 1, `phasing.best_phasing`): two
and three copies of the (8,1)-sequence, and two of the (10,2)-sequence. For each noise
coefficient the simulator images the cylinder at random angles, decodes each image
with the correlation decoder and counts the readings within 2 pi / K of the truth.
Everything is seeded: the same command gives the same figures.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .beam import sequence_of_length
from .imaging import Cylinder, Encoder, Noise, accuracy
from .phasing import best_phasing

LENGTH = 170
NOISE_LEVELS = (0.0, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.5)


def _sequence(n: int, d: int, length: int) -> str:
    seq = sequence_of_length(n, d, length)
    if seq is None:
        raise RuntimeError(f"no ({n},{d})-sequence of length {length} found")
    return seq


def encoders(length: int = LENGTH) -> list[Encoder]:
    s10_1 = _sequence(10, 1, length)
    s8_1 = _sequence(8, 1, length)
    s10_2 = _sequence(10, 2, length)
    two8 = best_phasing([s8_1] * 2, 8)
    three8 = best_phasing([s8_1] * 3, 8)
    two10 = best_phasing([s10_2] * 2, 10)
    return [
        Encoder("single (10,1)", 10, Cylinder((s10_1,))),
        Encoder("single (8,1)", 8, Cylinder((s8_1,))),
        Encoder("single (10,2)", 10, Cylinder((s10_2,))),
        Encoder("two parallel (8,1)", 8, Cylinder((s8_1,) * 2, two8.phases)),
        Encoder("three parallel (8,1)", 8, Cylinder((s8_1,) * 3, three8.phases)),
        Encoder("two parallel (10,2)", 10, Cylinder((s10_2,) * 2, two10.phases)),
    ]


@dataclass(frozen=True)
class Result:
    levels: tuple[float, ...]
    readings: int
    names: tuple[str, ...]
    correct: dict  # name -> list of fractions, one per level

    def mean(self, name: str) -> float:
        return float(np.mean(self.correct[name]))

    def as_dict(self) -> dict:
        return {"noise_levels": list(self.levels), "readings_per_level": self.readings,
                "percent_correct": {k: [round(100 * v, 1) for v in vals] for k, vals in self.correct.items()}}


def run(readings: int = 400, levels=NOISE_LEVELS, seed: int = 5, length: int = LENGTH,
        progress=None) -> Result:
    encs = encoders(length)
    correct = {}
    for i, enc in enumerate(encs):
        rng = np.random.default_rng([seed, i])
        correct[enc.name] = [accuracy(enc, Noise(c), readings, rng) for c in levels]
        if progress:
            progress(enc.name, correct[enc.name])
    return Result(tuple(levels), readings, tuple(e.name for e in encs), correct)


def conclusions(result: Result) -> dict[str, bool]:
    """The paper's conclusions, judged on the mean percentage over the noise levels."""
    m = result.mean
    singles = ["single (10,1)", "single (8,1)", "single (10,2)"]
    multi = ["two parallel (8,1)", "three parallel (8,1)", "two parallel (10,2)"]
    return {
        "multi-sequence encoders beat every single-sequence one":
            min(m(x) for x in multi) > max(m(x) for x in singles),
        "(10,2) beats (10,1) and (8,1)": m("single (10,2)") > max(m("single (10,1)"), m("single (8,1)")),
        "two parallel (10,2) is the best": m("two parallel (10,2)") == max(m(x) for x in result.names),
    }


def plot(result: Result, path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4.2), dpi=120)
    for name in result.names:
        ax.plot(result.levels, [100 * v for v in result.correct[name]], marker="o", ms=3, label=name)
    ax.set_xlabel("noise coefficient c (blur, AWGN, contrast loss, pose noise)")
    ax.set_ylabel("readings within 2\u03c0/K [%]")
    ax.set_title(f"Correlation decoding on a simulated cylinder, K = 170, {result.readings} readings per point")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
