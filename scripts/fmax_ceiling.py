#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""What limits the core's Fmax: each block's ceiling, with the others made ideal.

    python scripts/fmax_ceiling.py ice40-hx8k                        # the four rows, seeds 1-5
    python scripts/fmax_ceiling.py ecp5-25k --seeds 1,2,3 --param CONV_REG=1
    python scripts/fmax_ceiling.py ice40-hx8k --ideal prenc_mode_fsm  # one row

nextpnr reports the worst path of a placement, and the placer's seed moves it: a
change to one block rarely shows while another block is as slow. So this places the
core (N = 10, `synth.core_build`) with chosen submodules replaced by an *ideal* stub:
the same parameters and ports, every input captured in a kept register (so the logic
that drives it is placed and timed as in the core), every output a register one LUT
from three inputs (so what it drives starts from a register, as from the fastest
block possible). The rows:

    core             as it is
    ideal judge      prenc_mode_fsm ideal: the ceiling set by the track words and the rest
    ideal tracks     prenc_track_word ideal: the ceiling set by the judge and the rest
    ideal both       the front end's own (conditioner, decoder, count, position, glue)

Each row prints the logic cells and the mean Fmax over the placer seeds. A block's
goal is met when the row that makes the other blocks ideal clears it: 120 MHz on the
HX8K needs every row above 120. The stub's figures are a bound, not a design: the
stubbed blocks compute nothing.
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from synth import (REPO, TARGETS, FlowError, core_build, core_parameters, file_list, list_file,  # noqa: E402
                   placer_seeds, rel)

ROWS = {
    "core": (),
    "ideal judge": ("prenc_mode_fsm",),
    "ideal tracks": ("prenc_track_word",),
    "ideal both": ("prenc_mode_fsm", "prenc_track_word"),
}
PORT = re.compile(r"^\s*(input|output)\s+(?:wire|reg)?\s*(\[[^\]]+\])?\s*(\w+)\s*,?\s*(?://.*)?$")


def ideal_stub(source: str, module: str) -> str:
    """The module with its header kept and its body replaced by the ideal block (above)."""
    start = re.search(rf"^module\s+{module}\b", source, re.M)
    if not start:
        raise FlowError(f"no module {module} in its source")
    end = source.find("\n);", start.start())
    if end < 0:
        raise FlowError(f"{module}: the port list does not end with a line ');'")
    header = source[start.start():end + 3]
    ports = [PORT.match(line) for line in header.splitlines()]
    ports = [(m.group(1), m.group(2) or "", m.group(3)) for m in ports if m]
    inputs = [(r, n) for d, r, n in ports if d == "input" and n not in ("clk",)]
    outputs = [(r, n) for d, r, n in ports if d == "output"]
    if not inputs or not outputs or "clk" not in [n for _, _, n in ports]:
        raise FlowError(f"{module}: need a clk input, other inputs and outputs (found {len(ports)} ports)")
    lines = ["`default_nettype none", header, "  // Ideal stub (scripts/fmax_ceiling.py): not a design."]
    for k, (width, name) in enumerate(inputs):
        lines.append(f"  (* keep *) reg {width} ideal_in{k};")
        lines.append(f"  always @(posedge clk) ideal_in{k} <= {name};")
    for j, (width, name) in enumerate(outputs):
        a, b, c = (inputs[(j * 3 + i) % len(inputs)][1] for i in range(3))
        lines.append(f"  reg {width} ideal_out{j};")
        lines.append(f"  always @(posedge clk) ideal_out{j} <= {a} ^ ({b} >> 1) ^ ({c} << 1);")
        lines.append(f"  assign {name} = ideal_out{j};")
    lines += ["endmodule", "`default_nettype wire", ""]
    return "\n".join(lines)


def sources_with(ideal: tuple[str, ...], out: Path) -> list[Path]:
    """The core's sources with each `ideal` module's file replaced by its stub."""
    sources = file_list(list_file("prenc_core"))
    names = {p.stem for p in sources}
    for module in ideal:
        if module not in names:
            raise FlowError(f"{module} is not a source of prenc_core")
    out.mkdir(parents=True, exist_ok=True)
    result = []
    for path in sources:
        if path.stem in ideal:
            stub = out / f"{path.stem}_ideal.v"
            stub.write_text(ideal_stub(path.read_text(), path.stem))
            path = stub
        result.append(path)
    return result


def ceiling(target: str, ideal: tuple[str, ...], seeds: list[int], out: Path,
            parameters: dict[str, int]) -> tuple[int, list[float]]:
    """Logic cells and Fmax per seed of the core with `ideal` modules stubbed."""
    sources = sources_with(ideal, out)
    cells, fmax = 0, []
    for seed in seeds:
        result = core_build(target, 10, 100.0, out / f"seed{seed}", require_timing=False, seed=seed,
                            parameters=parameters, sources=sources)
        cells = result.used(TARGETS[target].logic)[0]
        fmax.append(result.fmax)
    return cells, fmax


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("target", choices=sorted(TARGETS))
    parser.add_argument("--seeds", default="1,2,3,4,5", help="placer seeds (default 1,2,3,4,5)")
    parser.add_argument("--ideal", action="append", choices=("prenc_mode_fsm", "prenc_track_word"),
                        help="one row: these modules ideal (repeatable); default: the four rows")
    parser.add_argument("--param", action="append", default=[], metavar="NAME=VALUE",
                        help="another integer parameter of prenc_core (e.g. CONV_REG=1), as synth.py's")
    parser.add_argument("--out", type=Path, default=REPO / "build" / "ceiling")
    args = parser.parse_args(argv)
    try:
        seeds = placer_seeds(args.seeds)
        parameters = core_parameters(args.param)
    except ValueError as err:
        parser.error(str(err))
    rows = {"custom": tuple(args.ideal)} if args.ideal else ROWS
    unit = TARGETS[args.target].logic
    print(f"prenc_core, N = 10, {TARGETS[args.target].name}, placer seeds {args.seeds}"
          + (f", {' '.join(args.param)}" if args.param else ""))
    try:
        for label, ideal in rows.items():
            out = args.out / args.target / (label.replace(" ", "_") if not args.ideal else "_".join(ideal))
            cells, fmax = ceiling(args.target, ideal, seeds, out, parameters)
            name = label if not args.ideal else "ideal " + " + ".join(ideal)
            print(f"  {name:14s} {cells:5d} {unit}  Fmax {sum(fmax) / len(fmax):6.1f} MHz  "
                  f"({', '.join(f'{f:.1f}' for f in fmax)})  [{rel(out)}]", flush=True)
    except FlowError as err:
        print(f"error: {err}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
