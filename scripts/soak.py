#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""`make soak`: many random draws of the end-to-end scenarios through the reader model.

    python scripts/soak.py                                    # N = 8, FILTER = 2, seeds 1..100
    python scripts/soak.py --bits 10 --filter 0 --seeds 1000..1500
    python scripts/soak.py --bits 8 --filter 2 --seeds 809969825 --scenario glitches
    python scripts/soak.py --no-hypotheses --bits 10 --filter 0
    python scripts/soak.py --instrument --seeds 1..50           # the whole instrument
    python scripts/soak.py --velocity --seeds 1..40             # the velocity's bound

With --instrument each seed is one draw of motion, faults, sensor noise and disc
printing through the reader, the fine position and the velocity (N = 10, FILTER = 2;
prenc.virtual.instrument_soak), judged on every clock: no wrong valid position, the
fine position within its documented bound of the core's quarter, the velocity 0 or of
the last step's sign and never motion at a stop. About 6 s a draw on one core.

With --velocity each seed is one random run of changes of motion (steps, ramps, stops,
reversals, changes in quick succession) through the velocity's model, on the ideal disc
and on the calibrated printed disc (prenc.virtual.velocity_soak), judged against the
bound of docs/fine.md: back within 0.05 % within 11 windows or 8 edge periods of the new
speed (18 or 22 calibrated), and between the last speeds until then. About 12 s a run on
one core.

CI draws one seed per scenario on every run, so a change can pass CI and fail on a
later draw. Run this before pushing a change to the reader, the judge or the
scenarios: each failure prints its scenario, seed and the RTL test's replay
variable, and the exit status is 1 if any draw failed (2 for a malformed command
line). Checks as tb/core/prenc_core: no wrong valid position, and a valid position in
every draw of the scenarios without faults. About 3 s per seed at N = 8 on one core.
"""

from __future__ import annotations

import argparse
import os
import re
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "sim"))
from prenc.virtual.soak import soak  # noqa: E402


def seed_list(text: str) -> list[int]:
    """'A..B' (A to B inclusive) or 'S,S,...'; every seed 1 or more, none twice."""
    m = re.fullmatch(r"\s*(\d+)\s*\.\.\s*(\d+)\s*", text)
    if m:
        lo, hi = int(m.group(1)), int(m.group(2))
        if lo > hi:
            raise argparse.ArgumentTypeError(f"seed range {text!r} is empty ({lo} > {hi})")
        seeds = list(range(lo, hi + 1))
    else:
        try:
            seeds = [int(x) for x in text.split(",")]
        except ValueError:
            raise argparse.ArgumentTypeError(f"seeds {text!r}: expected A..B or S,S,... of integers") from None
    if min(seeds) < 1:
        raise argparse.ArgumentTypeError(f"seeds {text!r}: every seed must be 1 or more")
    if len(set(seeds)) != len(seeds):
        raise argparse.ArgumentTypeError(f"seeds {text!r}: a seed is given twice")
    return seeds


def instrument(seeds: list[int], jobs: int) -> int:
    """The instrument soak: a line per draw, a summary; 1 if any draw failed."""
    import math

    from prenc.virtual.instrument_soak import soak_instrument

    start = time.monotonic()
    results = soak_instrument(seeds, jobs)
    failed = 0
    for r in results:
        verdict = "ok" if not r.failures else "FAILED: " + "; ".join(r.failures[:3])
        vel = "-" if math.isnan(r.velocity_rms) else f"{r.velocity_rms:.2f} %"
        fine = ("never valid (the core never locked)" if math.isnan(r.fine_rms)
                else f"{r.fine_rms:.4f} / {r.fine_max:.3f} slot (RMS / max)")
        print(f"seed {r.seed}: {r.label}; {r.clocks} clocks; fine position {fine}, "
              f"velocity at steady speeds {vel} RMS: {verdict}")
        failed += bool(r.failures)
    print(f"instrument soak: {len(results)} draws, {failed} failed, {time.monotonic() - start:.0f} s")
    return 1 if failed else 0


def velocity(seeds: list[int], jobs: int) -> int:
    """The velocity soak: a line per run, a summary; 1 if any run failed."""
    from prenc.virtual.velocity_soak import BOUNDS, soak_velocity

    start = time.monotonic()
    results = soak_velocity(seeds, jobs=jobs)
    failed = 0
    worst: dict[str, float] = {}
    for r in results:
        windows, periods = BOUNDS[r.disc]
        # Each hold's settling against its bound (1: at the bound).
        used = max((min(w / windows, p / periods) for _, w, p in r.settled if w is not None), default=0.0)
        worst[r.disc] = max(worst.get(r.disc, 0.0), used)
        verdict = "ok" if not r.failures else "FAILED: " + "; ".join(r.failures[:3])
        print(f"seed {r.seed}, {r.disc} disc: {r.clocks} clocks, {len(r.settled)} changes, "
              f"at most {used:.2f} of the bound: {verdict}")
        failed += bool(r.failures)
    shares = ", ".join(f"{disc} {share:.2f}" for disc, share in worst.items())
    print(f"velocity soak: {len(results)} runs, {failed} failed, the most of its bound a change took: "
          f"{shares}, {time.monotonic() - start:.0f} s")
    return 1 if failed else 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bits", type=int, default=8, metavar="N", help="code word length, 4..16 (default 8)")
    parser.add_argument("--filter", type=int, default=2, metavar="F", help="glitch filter length (default 2)")
    parser.add_argument("--seeds", type=seed_list, default=seed_list("1..100"), metavar="A..B|S,S,...",
                        help="scenario seeds (default 1..100)")
    parser.add_argument("--scenario", action="append", default=None, metavar="NAME",
                        help="only this scenario (repeatable; default every one)")
    parser.add_argument("--no-hypotheses", action="store_true", help="the reader built with HYPOTHESES = 0")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="processes (default: every core)")
    parser.add_argument("--instrument", action="store_true",
                        help="draws through the whole instrument (N = 10, FILTER = 2; --bits, --filter, "
                             "--scenario and --no-hypotheses do not apply)")
    parser.add_argument("--velocity", action="store_true",
                        help="random runs of changes of motion through the velocity's model, judged against "
                             "its bound (N = 10; --bits, --filter, --scenario and --no-hypotheses do not apply)")
    args = parser.parse_args(argv)
    if args.instrument and args.velocity:
        parser.error("--instrument and --velocity are two soaks: give one")
    if args.jobs < 1:
        parser.error(f"--jobs {args.jobs} must be 1 or more")
    if args.velocity:
        return velocity(args.seeds, args.jobs)
    if args.instrument:
        return instrument(args.seeds, args.jobs)
    if not 4 <= args.bits <= 16:
        parser.error(f"--bits {args.bits} is out of range 4..16")
    if not 0 <= args.filter <= 16:
        parser.error(f"--filter {args.filter} is out of range 0..16")
    start = time.monotonic()
    try:
        result = soak(args.bits, args.filter, args.seeds, args.scenario, not args.no_hypotheses, args.jobs)
    except ValueError as err:
        parser.error(str(err))
    for failure in result.failures:
        print(failure.line(result.n, result.filter_len))
    hyp = "" if result.hypotheses else ", HYPOTHESES = 0"
    print(f"soak N = {result.n}, FILTER = {result.filter_len}{hyp}: {result.runs} draws "
          f"({len(args.seeds)} seeds), {len(result.failures)} failed, {time.monotonic() - start:.0f} s")
    return 1 if result.failures else 0


if __name__ == "__main__":
    sys.exit(main())
