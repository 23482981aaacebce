# SPDX-License-Identifier: Apache-2.0
"""Many draws of the end-to-end scenarios through the reader model, judged as CI judges the RTL.

Each CI run draws one seed per scenario (tb/core/prenc_core, from cocotb's random seed),
so a change to the reader or to the scenarios can pass CI and fail on a later draw.
`soak` makes the draws ahead: every scenario (or those named) for each seed, the model
read through it, and the same two checks as the RTL test: no wrong valid position
(`judge`) and, where every draw must lock (`must_lock`), a valid position at all. Each
failure keeps the seed that replays it on the RTL, for instance at N = 8, FILTER = 2:

    PRENC_SCENARIO_SEED=<seed> .venv/bin/python -m pytest \
        "tb/core/prenc_core/test_prenc_core.py::test_prenc_core_verilator[8-2]"

The RTL equals the model clock for clock on every draw CI makes, so a draw the model
fails is one the RTL fails too.
"""

from __future__ import annotations

from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from functools import partial
from typing import Iterable, Sequence

from ..codes.debruijn import Code
from ..core.reader import Reader
from .scenarios import core_latency, judge_outputs, must_lock, scenarios

RESET_CLOCKS = 4  # as tb/core/prenc_core drives rst


@dataclass(frozen=True)
class SoakFailure:
    seed: int
    scenario: str
    what: str  # "wrong valid position at clock K[, M clocks in all]" or "never valid"

    def line(self, n: int, filter_len: int) -> str:
        return (f"N={n} FILTER={filter_len} {self.scenario} seed {self.seed}: {self.what} "
                f"(replay: PRENC_SCENARIO_SEED={self.seed})")


@dataclass
class SoakResult:
    n: int
    filter_len: int
    hypotheses: bool
    runs: int = 0
    failures: list[SoakFailure] = field(default_factory=list)


def check_names(n: int, filter_len: int, names: Sequence[str] | None) -> list[str]:
    """The scenarios to run: all, or the named ones (an unknown name is an error)."""
    known = list(scenarios(n, filter_len, 1))
    if not names:
        return known
    unknown = [x for x in names if x not in known]
    if unknown:
        raise ValueError(f"unknown scenario {', '.join(unknown)}; known: {', '.join(known)}")
    return list(names)


def soak_seed(n: int, filter_len: int, seed: int, names: Sequence[str], hypotheses: bool = True,
              reader_type=Reader) -> list[SoakFailure]:
    """One seed: each named scenario drawn with it, read by the model and judged."""
    if seed < 1:
        raise ValueError(f"seed {seed} must be 1 or more (0 makes the RTL test draw its own)")
    failures = []
    code = Code(n)
    for name, sc in scenarios(n, filter_len, seed).items():
        if name not in names:
            continue
        enc = sc.run(n)
        outs = reader_type(code, filter_len, hypotheses=hypotheses).run(enc, RESET_CLOCKS)
        verdict = judge_outputs(enc, outs, core_latency(filter_len), filter_len)
        if verdict.wrong:
            more = f", {verdict.wrong} clocks in all" if verdict.wrong > 1 else ""
            failures.append(SoakFailure(seed, name, f"wrong valid position at clock {verdict.first_wrong}{more}"))
        if must_lock(name) and verdict.first_valid is None:
            failures.append(SoakFailure(seed, name, "never valid"))
    return failures


def soak(n: int, filter_len: int, seeds: Iterable[int], names: Sequence[str] | None = None,
         hypotheses: bool = True, jobs: int = 1, reader_type=Reader) -> SoakResult:
    """Every seed of `seeds` through every named scenario (all by default), on `jobs`
    processes. Failures come in seed order."""
    names = check_names(n, filter_len, names)
    seeds = list(seeds)
    one_seed = partial(soak_seed, n, filter_len, names=names, hypotheses=hypotheses, reader_type=reader_type)
    if jobs > 1 and len(seeds) > 1:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            per_seed = list(pool.map(one_seed, seeds))
    else:
        per_seed = [one_seed(s) for s in seeds]
    return SoakResult(n, filter_len, hypotheses, runs=len(seeds) * len(names),
                      failures=[f for failures in per_seed for f in failures])
