#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""`make board-sim`: the virtual board, for trying `prenc host` without a board.

    python scripts/board_sim.py [--profile constant|reversals|sine] [--rpm 600]
                                [--misreads 0.01] [--dead-head 2] [--missed-states 3]
                                [--seconds 0] [--clock-mhz 30 --baud 3000000]
                                [--fine-bits 0] [--printed] [--cal [--cal-file disc.cal]]
                                [--edge-tolerance 31]

prenc_board runs on Verilator (tb/board/prenc_board/virtual_board.py), driven by the
virtual encoder; its UART is a pseudo-terminal whose name this prints. In another
terminal:

    prenc host read    --port /dev/pts/N --kind hybrid
    prenc host monitor --port /dev/pts/N --rate 1000
    prenc host log     --port /dev/pts/N --out log.csv --rate 1000 --count 200
    prenc host plot    log.csv

The simulation is some hundred times slower than the board (it prints how much), so
board time runs slow: ask for streams at a high rate (--rate 1000 is one answer per
millisecond of board time). A lower clock (--clock-mhz 4 --baud 1000000) runs seven
times closer to real time. Stop it with Ctrl-C, or give --seconds of board time.

--printed turns a printed disc instead of the ideal one (the bench's: edges +-0.05
slot, phase 10 degrees, duty 45/55 %, eccentricity 0.2 slot; prenc.virtual.printing).
--cal builds the board with its calibration table (CAL = 1), empty or from --cal-file;
then `prenc calibrate --port /dev/pts/N --out disc.cal --apply` calibrates it
(docs/calibration.md). --edge-tolerance builds it with EDGE_TOLERANCE (1/1000 slot:
how far the edges may be off their places; 31 for --printed without --cal;
docs/fine.md).
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(REPO / "tb"), str(REPO / "sim")]

from prenc.virtual.profiles import PROFILES  # noqa: E402
from prenc.virtual.encoder import Disc  # noqa: E402
from runner import rom_file, run  # noqa: E402


def parse(argv=None) -> argparse.Namespace:
    p = argparse.ArgumentParser(prog="board_sim.py", description=__doc__.split("\n")[0])
    p.add_argument("--bits", type=int, default=10, help="N, the disc's code length (default 10)")
    p.add_argument("--profile", choices=PROFILES, default="constant", help="speed profile (default constant)")
    p.add_argument("--rpm", type=float, default=600.0, help="speed, or peak speed, in rpm (default 600)")
    p.add_argument("--misreads", type=float, default=0.0, help="each head's misread rate per slot pass")
    p.add_argument("--dead-head", type=int, choices=(1, 2), help="a head stuck at 0 from the start")
    p.add_argument("--missed-states", type=int, default=0,
                   help="missed quadrature states per 200,000 clocks of encoder signal")
    p.add_argument("--seed", type=int, default=1, help="seed of the random faults (default 1)")
    p.add_argument("--seconds", type=float, default=0.0, help="board time to run (default 0: until stopped)")
    p.add_argument("--clock-mhz", type=int, default=30, help="design clock in MHz (default 30, the iCEBreaker's)")
    p.add_argument("--baud", type=int, default=3_000_000, help="UART baud rate (default 3000000)")
    p.add_argument("--filter", type=int, default=2, help="glitch filter length in clocks (default 2)")
    p.add_argument("--port-file", help="write the pty's name to this file")
    p.add_argument("--fine-bits", type=int, default=0, choices=range(9), metavar="0..8",
                   help="fraction bits of the fine position (FINE_BITS; default 0)")
    p.add_argument("--printed", action="store_true", help="a printed disc (the bench's) instead of the ideal one")
    p.add_argument("--cal", action="store_true", help="build the board with its calibration table (CAL = 1)")
    p.add_argument("--cal-file", help="with --cal: the table it starts with (default: all zero)")
    p.add_argument("--edge-tolerance", type=int, default=0, choices=range(61), metavar="0..60",
                   help="EDGE_TOLERANCE, 1/1000 slot (default 0; 31 for --printed without --cal)")
    args = p.parse_args(argv)
    if args.clock_mhz * 1_000_000 < 4 * args.baud:
        p.error(f"--baud {args.baud} needs at least 4 clocks per bit: --clock-mhz >= {4 * args.baud / 1e6:g}")
    if not 0.0 <= args.misreads <= 1.0:
        p.error(f"--misreads {args.misreads} must be in 0..1")
    if args.cal_file and not args.cal:
        p.error("--cal-file needs --cal")
    if args.rpm == 0:
        p.error("--rpm must not be 0: the reader needs the disc to move to find its position")
    return args


def board_parameters(args: argparse.Namespace, clk_hz: int) -> dict[str, object]:
    """prenc_board's parameters for the options."""
    n = args.bits
    taps = sum(1 << (t - 1) for t in Disc(n).taps)
    parameters: dict[str, object] = {"N": n, "TAPS": taps, "FILTER": args.filter, "ROM_FILE": rom_file(n),
                                     "CLK_HZ": clk_hz, "BAUD": args.baud}
    if args.fine_bits:
        parameters["FINE_BITS"] = args.fine_bits
    if args.cal:
        parameters["CAL"] = 1
        if args.cal_file:
            parameters["CAL_FILE"] = str(Path(args.cal_file).resolve())
    if args.edge_tolerance:
        parameters["EDGE_TOLERANCE"] = args.edge_tolerance
    return parameters


def main(argv=None) -> int:
    args = parse(argv)
    n = args.bits
    cfg = {"n": n, "clk_hz": args.clock_mhz * 1_000_000, "baud": args.baud, "profile": args.profile,
           "rpm": args.rpm, "misreads": args.misreads, "dead_head": args.dead_head,
           "missed_states": args.missed_states, "seed": args.seed, "seconds": args.seconds,
           "port_file": str(Path(args.port_file).resolve()) if args.port_file else None,
           "printed": args.printed}
    parameters = board_parameters(args, cfg["clk_hz"])
    run(str(REPO / "tb" / "board" / "prenc_board" / "virtual_board.py"), "prenc_board", "verilator",
        parameters=parameters, extra_env={"PRENC_BOARD_SIM": json.dumps(cfg)})
    return 0


if __name__ == "__main__":
    sys.exit(main())
