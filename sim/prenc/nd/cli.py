# SPDX-License-Identifier: Apache-2.0
"""`prenc nd`: (n,d)-sequences, parallel phasing, the imaging experiment, decoder ROMs.

    prenc nd search  --n N --d D [--method exact|algorithm1|lfsr] [--length K] [--time-limit S] [--json]
    prenc nd search  --n N --d D --method sat [--length K | --at-least K] [--time-limit S]
                     [--solver NAME] [--no-symmetry] [--proof FILE] [--check-proof] [--cnf FILE] [--json]
    prenc nd table   --max-n M [--min-n 3] [--time-limit S] [--json | --markdown] [--no-sequences]
    prenc nd phase   --sequence 0110... [--sequence ...] --n N [--json]
    prenc nd phase   --disc [--bits N] [--json]
    prenc nd image   [--readings R] [--out PNG] [--json]
    prenc nd rom     --sequence ... [--phases a,b] --n N [-o FILE]

Every sequence printed has passed the independent minimum-distance check
(`prenc.nd.sequence.min_distance`).
"""

from __future__ import annotations

import argparse
import json
import sys

from .algorithm1 import algorithm1
from .beam import sequence_of_length
from .bounds import upper_bound
from .exact import exact_search
from .lfsr_codes import best_lfsr
from .sequence import as_bits, check


def _int_list(text: str) -> list[int]:
    try:
        return [int(t) for t in text.split(",") if t.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected integers separated by commas, got {text!r}") from None


def _check_nd(n: int, d: int) -> None:
    if not 2 <= n <= 20:
        raise ValueError(f"window length n = {n} is out of range 2..20")
    if not 1 <= d <= n:
        raise ValueError(f"distance d = {d} is out of range 1..n")


def cmd_search_sat(args) -> None:
    """--method sat: one question (--length, --at-least), or the longest and the best bound."""
    from .sat import Instance, settle, solve

    n, d = args.n, args.d
    if args.length is not None and args.at_least is not None:
        raise ValueError("give --length or --at-least, not both")
    if args.length is None and args.at_least is None:
        if args.proof or args.check_proof or args.cnf:
            raise ValueError("--proof, --check-proof and --cnf need one question: --length or --at-least")
        built = best_lfsr(n, d)

        def progress(r) -> None:
            if not args.json:
                sys.stderr.write(f"{r.instance.question}: {r.status} [{r.seconds:.1f} s]\n")

        res = settle(n, d, sequence=built.sequence if built else None, time_limit=args.time_limit,
                     solver=args.solver, symmetry=not args.symmetry_off, progress=progress)
        if res.sequence is None:
            raise ValueError(f"no ({n},{d})-sequence found within {args.time_limit} s per question")
        if args.json:
            print(json.dumps(res.as_dict()))
            return
        status = "proven maximal" if res.exact else "a lower bound"
        print(f"({n},{d})-sequence of length {res.lower} ({status}); upper bound {res.upper} "
              f"({res.upper_reason}); minimum window distance {check(res.sequence, n, d)} (checked)")
        print(res.sequence)
        return
    inst = Instance(n, d, args.length if args.length is not None else args.at_least,
                    at_least=args.at_least is not None, symmetry=not args.symmetry_off)
    res = solve(inst, time_limit=args.time_limit, solver=args.solver, proof_path=args.proof,
                check_proof=args.check_proof, cnf_path=args.cnf)
    if args.json:
        print(json.dumps(res.as_dict()))
    elif res.status == "sat":
        print(f"{inst.question}: found, length {len(res.sequence)}; minimum window distance "
              f"{check(res.sequence, n, d)} (checked) [{res.seconds:.1f} s, {res.solver}]")
        print(res.sequence)
    elif res.status == "unsat":
        proof = {None: "", True: "; DRAT proof checked", False: "; DRAT proof REJECTED"}[res.proof_checked]
        print(f"{inst.question}: none exists (UNSAT{proof}) [{res.seconds:.1f} s, {res.solver}, "
              f"{res.variables} variables, {res.clauses} clauses]")
    else:
        print(f"{inst.question}: unknown, the time limit of {args.time_limit} s ran out")
    if res.proof_checked is False:
        raise ValueError("the solver's DRAT proof did not check")


def cmd_search(args) -> None:
    n, d = args.n, args.d
    _check_nd(n, d)
    if args.method == "sat":
        cmd_search_sat(args)
        return
    for name in ("at_least", "proof", "cnf"):
        if getattr(args, name):
            raise ValueError(f"--{name.replace('_', '-')} needs --method sat")
    if args.check_proof or args.symmetry_off or args.solver != "cadical195":
        raise ValueError("--check-proof, --no-symmetry and --solver need --method sat")
    upper, reason = upper_bound(n, d)
    if args.length is not None:
        if not 1 <= args.length <= upper:
            raise ValueError(f"length {args.length} is out of range 1..{upper} ({reason})")
        seq = sequence_of_length(n, d, args.length, args.time_limit)
        if seq is None:
            raise ValueError(f"no ({n},{d})-sequence of length {args.length} found")
        out = {"n": n, "d": d, "length": len(seq), "exact": None, "sequence": seq, "method": "given length"}
    elif args.method == "algorithm1":
        out = algorithm1(n, d, time_limit=args.time_limit).as_dict()
    elif args.method == "lfsr":
        built = best_lfsr(n, d)
        if built is None:
            raise ValueError(f"no m-sequence of degree < {n} has {n}-windows at distance >= {d}")
        out = {"n": n, "d": d, "length": built.length, "exact": built.length >= upper,
               "sequence": built.sequence, "method": built.method}
    else:
        built = best_lfsr(n, d)
        res = exact_search(n, d, lower=built.length if built else 0,
                           lower_sequence=built.sequence if built else None, upper=upper,
                           time_limit=args.time_limit)
        out = res.as_dict()
        out["exact"] = res.exact or res.length >= upper
        if built and res.length == built.length:
            out["method"] += f" (no longer than the {built.method})"
    if out["sequence"] is None:
        raise ValueError(f"no ({n},{d})-sequence found")
    out["min_distance"] = check(out["sequence"], n, d)
    out["upper_bound"], out["upper_bound_reason"] = upper, reason
    if args.json:
        print(json.dumps(out))
        return
    status = "proven maximal" if out["exact"] else "a lower bound" if out["exact"] is False else "of the length asked"
    print(f"({n},{d})-sequence of length {out['length']} ({status}; upper bound {upper}, {reason}); "
          f"method: {out['method']}; minimum window distance {out['min_distance']} (checked)")
    print(out["sequence"])


def cmd_table(args) -> None:
    from .table import build_table, to_json, to_markdown

    def progress(e) -> None:
        if not args.quiet:
            status = "" if e.exact else f" (a lower bound: the time limit of {args.time_limit:g} s ran out)"
            sys.stderr.write(f"n={e.n} d={e.d}: {e.length}{status} [{e.seconds:.1f} s]\n")

    table = build_table(args.max_n, args.min_n, time_limit=args.time_limit, progress=progress)
    if args.json:
        print(json.dumps(to_json(table, not args.no_sequences)))
    else:
        print(to_markdown(table))


def cmd_phase(args) -> None:
    from .phasing import best_phasing, dual_track

    if args.disc:
        out = dual_track(args.bits).as_dict()
        if args.json:
            print(json.dumps(out))
            return
        line, heads, best = (out["line_sensor_at_track_shift"], out["two_heads_180_degrees"], out["best"])
        print(f"disc N={out['n']}, L={out['length']}, track shift D={out['track_shift']}")
        print(f"  line sensor across both tracks, offset D:      min summed distance {line['min_summed_distance']} "
              f"(detects {line['detects']}, corrects {line['corrects']})")
        print(f"  two heads 180 degrees apart, offset {out['head_offset']}:     min summed distance "
              f"{heads['min_summed_distance']} (detects {heads['detects']}, corrects {heads['corrects']})")
        print(f"  best offset {best['phases'][1]}: min summed distance {best['min_summed_distance']} "
              f"(detects {best['detects']}, corrects {best['corrects']}); "
              f"{len(out['best_offsets'])} offsets reach it")
        return
    if not args.sequence or args.n is None:
        raise ValueError("give --n and one --sequence per track (or --disc)")
    seqs = [as_bits(s) for s in args.sequence]
    ph = best_phasing(seqs, args.n)
    out = ph.as_dict()
    if args.json:
        print(json.dumps(out))
    else:
        print(f"phases {out['phases']}: min summed distance {out['min_summed_distance']} "
              f"(std {out['std']}, {out['pairs_at_min']} pairs at the minimum); "
              f"detects {out['detects']}, corrects {out['corrects']} misread bits")


def cmd_image(args) -> None:
    from .experiment import conclusions, plot, run

    def progress(name, values) -> None:
        sys.stderr.write(f"{name}: " + " ".join(f"{100 * v:.0f}" for v in values) + "\n")

    result = run(args.readings, seed=args.seed, progress=progress)
    verdict = conclusions(result)
    if args.out:
        plot(result, args.out)
    if args.json:
        print(json.dumps({**result.as_dict(), "conclusions": verdict}))
        return
    print("noise c: " + " ".join(f"{c:>5}" for c in result.levels))
    for name in result.names:
        print(f"{name:<22} " + " ".join(f"{100 * v:5.1f}" for v in result.correct[name]))
    for claim, holds in verdict.items():
        print(f"{'holds' if holds else 'FAILS'}: {claim}")


def cmd_rom(args) -> None:
    from ..codes.rom import write_atomically
    from .correlator import rom_text, rom_windows

    seqs = [as_bits(s) for s in args.sequence]
    phases = args.phases or [0] * len(seqs)
    windows = rom_windows(seqs, args.n, phases)
    text = rom_text(windows)
    if args.output == "-":
        sys.stdout.write(text)
    else:
        write_atomically(args.output, lambda: text.encode())


def add_parser(sub) -> None:
    nd = sub.add_parser("nd", help="error-tolerant (n,d)-sequences, parallel tracks, correlation decoding")
    cmds = nd.add_subparsers(dest="nd_command", required=True, parser_class=type(nd))

    search = cmds.add_parser("search", help="the longest (n,d)-sequence (or one of a given length)")
    search.add_argument("--n", type=int, required=True, help="window length n")
    search.add_argument("--d", type=int, required=True, help="minimum distance d between any two windows")
    search.add_argument("--method", choices=["exact", "algorithm1", "lfsr", "sat"], default="exact",
                        help="exact: DFS seeded by the best LFSR construction (default); algorithm1: the paper's "
                             "breadth-first search; lfsr: the construction alone; sat: a SAT solver (PySAT) on "
                             "the de Bruijn graph, which also proves that none exists")
    search.add_argument("--length", type=int, help="find a sequence of exactly this length instead")
    search.add_argument("--at-least", type=int, help="sat: is there a sequence of this length or longer?")
    search.add_argument("--time-limit", type=float, default=60.0,
                        help="seconds (default 60); for sat, of each question")
    search.add_argument("--solver", default="cadical195", help="sat: the PySAT solver (default cadical195)")
    search.add_argument("--no-symmetry", dest="symmetry_off", action="store_true",
                        help="sat: no symmetry breaking (complement, reversal)")
    search.add_argument("--proof", help="sat: write the solver's DRAT proof of an UNSAT answer to this file")
    search.add_argument("--check-proof", action="store_true",
                        help="sat: check the DRAT proof of an UNSAT answer (dratify; small instances)")
    search.add_argument("--cnf", help="sat: write the instance as DIMACS CNF, for any other solver")
    search.add_argument("--json", action="store_true")
    search.set_defaults(func=cmd_search)

    table = cmds.add_parser("table", help="Table 1 of the paper: best lengths for n = 3..M, d = 1..4")
    table.add_argument("--max-n", type=int, required=True)
    table.add_argument("--min-n", type=int, default=3)
    table.add_argument("--time-limit", type=float, default=20.0, help="seconds of exact search per entry (default 20)")
    table.add_argument("--json", action="store_true")
    table.add_argument("--no-sequences", action="store_true", help="leave the sequences out of the JSON")
    table.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    table.set_defaults(func=cmd_table)

    phase = cmds.add_parser("phase", help="phasing of parallel sequences (equation 1), or the project's disc")
    phase.add_argument("--sequence", action="append", help="a track's sequence (repeat per track)")
    phase.add_argument("--n", type=int, help="window length n")
    phase.add_argument("--disc", action="store_true", help="the dual-track disc: seed shift against the best")
    phase.add_argument("--bits", type=int, default=10, help="disc N for --disc (default 10)")
    phase.add_argument("--json", action="store_true")
    phase.set_defaults(func=cmd_phase)

    image = cmds.add_parser("image", help="the imaging experiment of the paper's figure 5")
    image.add_argument("--readings", type=int, default=400, help="readings per encoder and noise level (default 400)")
    image.add_argument("--seed", type=int, default=5)
    image.add_argument("--out", help="PNG plot to write")
    image.add_argument("--json", action="store_true")
    image.set_defaults(func=cmd_image)

    rom = cmds.add_parser("rom", help="the window ROM of rtl/nd/prenc_correlator.v")
    rom.add_argument("--sequence", action="append", required=True, help="a track's sequence (repeat per track)")
    rom.add_argument("--phases", type=_int_list, help="phase of each track (default all 0)")
    rom.add_argument("--n", type=int, required=True, help="window length n")
    rom.add_argument("--output", "-o", default="-", help="file, - for stdout (default)")
    rom.set_defaults(func=cmd_rom)
