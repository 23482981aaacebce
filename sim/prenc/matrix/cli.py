# SPDX-License-Identifier: Apache-2.0
"""`prenc matrix`: 2-D matrix codes.

    prenc matrix generate --n N [--checksum] [--format tracks|columns|json] [--cross-check] [-o FILE]
    prenc matrix count    --n N [--json]
    prenc matrix example  [--json]
    prenc matrix rom      --n N [--checksum] [--format hex|bin|mif|coe|mem] [-o FILE]

Every code printed has passed the check that each n x n window appears once.
"""

from __future__ import annotations

import json
import sys
import time

from ..codes.rom import FORMATS, write_atomically
from .code import MatrixCode, cost, windows_once
from .graph import (columns_of_cycle, count_hamiltonian_cycles, hamiltonian_cycle,
                    matrix_code_count)
from .paper import NUMBERINGS, PAPER_CYCLE, check_cycle, table_one
from .rom import rom_bytes


def cmd_generate(args) -> None:
    code = MatrixCode(args.n, args.checksum)
    if not windows_once(code.symbols, code.n, code.alphabet):
        raise AssertionError("FKM produced a sequence with a repeated window")  # never
    out: dict = {"n": code.n, "checksum": code.checksum, "length": code.length,
                 "address_bits": code.address_bits, "method": "FKM (Lyndon words)"}
    if args.cross_check:
        if args.checksum or args.n > 3:
            raise ValueError("--cross-check searches the paper's graph G: plain codes, n = 2 or 3")
        lex = hamiltonian_cycle(args.n, "lexicographic", time_limit=args.time_limit)
        warn = hamiltonian_cycle(args.n, "warnsdorff", time_limit=args.time_limit)
        if lex.cycle is None or warn.cycle is None:
            raise ValueError(f"the Hamiltonian-cycle search ran out of time ({args.time_limit} s)")
        warn_cols = columns_of_cycle(warn.cycle, args.n)
        out["cross_check"] = {
            "lexicographic_search_equals_fkm": columns_of_cycle(lex.cycle, args.n) == code.symbols,
            "lexicographic_nodes": lex.nodes,
            "warnsdorff_cycle_is_a_code": windows_once(warn_cols, args.n, 1 << args.n),
            "warnsdorff_nodes": warn.nodes,
            "warnsdorff_equals_fkm": warn_cols == code.symbols,
        }
    cols = code.columns.tolist()
    if args.format == "json":
        out["columns"] = cols
        text = json.dumps(out) + "\n"
    elif args.format == "columns":
        text = " ".join(str(c) for c in cols) + "\n"
    else:
        text = "".join("".join(str(int(v)) for v in row) + "\n" for row in code.cells())
    if args.format != "json":
        sys.stderr.write(f"n={code.n}{' with parity track' if code.checksum else ''}: "
                         f"{code.length} positions, every {code.n}x{code.n} window once (checked)\n")
        if "cross_check" in out:
            sys.stderr.write(f"cross-check in graph G: {out['cross_check']}\n")
    if args.output == "-":
        sys.stdout.write(text)
    else:
        write_atomically(args.output, lambda: text.encode())


def cmd_count(args) -> None:
    n = args.n
    formula = matrix_code_count(n)
    out: dict = {"n": n, "formula": str(formula), "formula_digits": len(str(formula))}
    if n == 2:
        t0 = time.perf_counter()
        out["enumerated"] = count_hamiltonian_cycles(n)
        out["enumeration_seconds"] = round(time.perf_counter() - t0, 3)
    if args.json:
        print(json.dumps(out))
        return
    if "enumerated" in out:
        print(out["enumerated"])
        sys.stderr.write(f"Hamiltonian cycles of G for n = 2, enumerated in {out['enumeration_seconds']} s; "
                         f"closed formula (k!)^(k^(n-1)) / k^n with k = 4: {formula} "
                         f"({'equal' if formula == out['enumerated'] else 'DIFFERENT'})\n")
    else:
        print(formula)
        sys.stderr.write(f"closed formula (k!)^(k^(n-1)) / k^n with k = {1 << n}: "
                         f"{len(str(formula))} digits, about {float(formula):.4e}; "
                         "enumeration is practical for n = 2 only\n")


def cmd_example(args) -> None:
    checks = {name: check_cycle(PAPER_CYCLE, name) for name in NUMBERINGS}
    holding = [name for name, c in checks.items() if c.holds]
    rows = table_one(PAPER_CYCLE, holding[0]) if holding else []
    if args.json:
        print(json.dumps({
            "cycle": PAPER_CYCLE,
            "numberings": {k: {"holds": c.holds, "bad_steps": c.bad_steps} for k, c in checks.items()},
            "table_one": [r.__dict__ for r in rows],
        }))
        return
    print("The paper's cycle " + ", ".join(f"B{b}" for b in PAPER_CYCLE))
    for name, c in checks.items():
        verdict = "a Hamiltonian cycle of G" if c.holds else f"{len(c.bad_steps)} of 16 steps are not arcs"
        print(f"  B numbered {name:<24} {verdict}")
    if rows:
        print(f"Table I ({holding[0]} numbering): position, window (track 0 / track 1), B, sector")
        for r in rows:
            print(f"  {r.position:2d}  {r.matrix}  B{r.number:<2d}  {r.angle_from:6.1f} .. {r.angle_to:6.1f} deg")


def cmd_rom(args) -> None:
    code = MatrixCode(args.n, args.checksum)
    write_atomically(args.output, lambda: rom_bytes(code, args.format))
    if args.output != "-":
        c = cost(args.n)
        sys.stderr.write(f"{args.output}: {code.length} words of {code.address_bits} bits"
                         + (f" (parity track: {c['checksum_positions']} positions instead of "
                            f"{c['plain_positions']})" if args.checksum else "") + "\n")


def add_parser(sub) -> None:
    matrix = sub.add_parser("matrix", help="2-D matrix codes: every n x n window of n tracks once")
    cmds = matrix.add_subparsers(dest="matrix_command", required=True, parser_class=type(matrix))

    def order(p, choices=(2, 3, 4)) -> None:
        p.add_argument("--n", type=int, required=True, choices=choices, help="number of tracks = window size")

    gen = cmds.add_parser("generate", help="the code by the FKM (Lyndon-word) construction")
    order(gen)
    gen.add_argument("--checksum", action="store_true", help="track n-1 carries each column's even parity")
    gen.add_argument("--format", choices=["tracks", "columns", "json"], default="tracks",
                     help="tracks: one line of cells per track (default); columns: column values; json")
    gen.add_argument("--cross-check", action="store_true",
                     help="also search G for Hamiltonian cycles (n = 2, 3) and compare")
    gen.add_argument("--time-limit", type=float, default=60.0, help="seconds per search (default 60)")
    gen.add_argument("--output", "-o", default="-", metavar="FILE", help="output file, - for stdout")
    gen.set_defaults(func=cmd_generate)

    count = cmds.add_parser("count", help="number of matrix codes (Hamiltonian cycles of G)")
    order(count)
    count.add_argument("--json", action="store_true")
    count.set_defaults(func=cmd_count)

    ex = cmds.add_parser("example", help="the paper's 16-position example, checked, with Table I")
    ex.add_argument("--json", action="store_true")
    ex.set_defaults(func=cmd_example)

    rom = cmds.add_parser("rom", help="the conversion ROM (address window, data position)")
    order(rom)
    rom.add_argument("--checksum", action="store_true", help="the code with the parity track")
    rom.add_argument("--format", "-f", choices=FORMATS, default="hex",
                     help="hex/bin: $readmemh/$readmemb; mif: Intel; coe: Xilinx; mem: Lattice")
    rom.add_argument("--output", "-o", default="-", metavar="FILE", help="output file, - for stdout")
    rom.set_defaults(func=cmd_rom)
