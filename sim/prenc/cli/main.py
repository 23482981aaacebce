# SPDX-License-Identifier: Apache-2.0
"""The `prenc` command.

    prenc rom    --bits N [--taps a,b,...] [--format hex|bin|mif|coe|mem] -o FILE
    prenc tracks --bits N [--taps a,b,...] [--shift D] [--format txt|csv] -o FILE
    prenc taps   --bits N [--taps a,b,...]
    prenc demo   [--out DIR]
    prenc host   read|monitor|log|plot ...   (the board over its UART; see prenc.board.host)
    prenc calibrate --port ... --out FILE    (the disc's sync track; prenc.board.calibration)
    prenc nd     search|table|phase|image|rom ...   ((n,d)-sequences; see prenc.nd.cli)
    prenc matrix generate|count|example|rom ...    (2-D matrix codes; see prenc.matrix.cli)
    prenc disc   dual|matrix|nd ...               (printable discs, SVG + PNG; see prenc.cli.disc)

Every error is one line on stderr and a non-zero exit status (2 for a malformed
command line, 1 for a request that cannot be carried out); no partial file is
ever left behind.
"""

from __future__ import annotations

import argparse
import sys
from typing import Sequence

from .. import __version__
from ..codes.debruijn import Code
from ..board.host import HostError
from ..virtual.encoder import default_shift
from ..codes.lfsr import taps_mask
from ..codes.lfsr import MAX_BITS, MIN_BITS, TapsError, check_bits, check_taps, poly_str, polynomial
from .arguments import bits_arg, taps_arg
from ..codes.rom import FORMATS, ROM_MAX_BITS, ROM_MIN_BITS, TRACK_FORMATS, format_tracks, write_atomically, write_rom


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (no usage dump)."""

    def error(self, message: str) -> None:  # type: ignore[override]
        sys.stderr.write(f"{self.prog}: error: {message} (see --help)\n")
        raise SystemExit(2)


def cmd_rom(args: argparse.Namespace) -> None:
    write_rom(args.output, args.bits, args.taps, args.format)


def cmd_tracks(args: argparse.Namespace) -> None:
    check_bits(args.bits, ROM_MIN_BITS, ROM_MAX_BITS)
    code = Code(args.bits, args.taps)
    shift = default_shift(code.n) if args.shift is None else args.shift
    if not 0 <= shift < code.length:
        raise ValueError(f"track shift D = {shift} is out of range 0..{code.length - 1}")
    write_atomically(args.output, lambda: format_tracks(code, shift, args.format))


def cmd_taps(args: argparse.Namespace) -> None:
    taps = check_taps(args.bits, args.taps)
    print(f"N={args.bits} taps={','.join(map(str, taps))} P(x)={poly_str(polynomial(taps))} primitive; "
          f"RTL parameter TAPS = 32'h{taps_mask(taps):08x}")


def cmd_demo(args: argparse.Namespace) -> None:
    from .demo import run_demo

    run_demo(args.out)


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="prenc", description="Pseudorandom absolute encoder tools.")
    parser.add_argument("--version", action="version", version=f"prenc {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

    def bits(p: argparse.ArgumentParser, lo: int, hi: int) -> None:
        p.add_argument("--bits", "-n", type=bits_arg, default=10, metavar="N",
                       help=f"code word length N, {lo}..{hi} (default 10)")
        p.add_argument("--taps", type=taps_arg, default=None, metavar="a,b,...",
                       help="LFSR feedback set, largest first (default: the project's primitive set for N; 10,3 for N=10)")

    rom = sub.add_parser("rom", help="write the conversion ROM (address w(p), data p)")
    bits(rom, ROM_MIN_BITS, ROM_MAX_BITS)
    rom.add_argument("--format", "-f", choices=FORMATS, default="hex",
                     help="hex/bin: $readmemh/$readmemb; mif: Intel; coe: Xilinx; mem: Lattice (N <= 16)")
    rom.add_argument("--output", "-o", default="-", metavar="FILE", help="output file, - for stdout (default)")
    rom.set_defaults(func=cmd_rom)

    tracks = sub.add_parser("tracks", help="write the two code track patterns (bit per slot) for printing a disc")
    bits(tracks, ROM_MIN_BITS, ROM_MAX_BITS)
    tracks.add_argument("--shift", "-d", type=int, default=None, metavar="D",
                        help="track 2 phase shift in slots (default 2^(N-1)+N-1)")
    tracks.add_argument("--format", "-f", choices=TRACK_FORMATS, default="txt",
                        help="txt: two lines of bits, track 1 then track 2; csv: slot,track1,track2")
    tracks.add_argument("--output", "-o", default="-", metavar="FILE", help="output file, - for stdout (default)")
    tracks.set_defaults(func=cmd_tracks)

    taps = sub.add_parser("taps", help="show the default feedback set for N, or check a given one")
    bits(taps, MIN_BITS, MAX_BITS)
    taps.set_defaults(func=cmd_taps)

    demo = sub.add_parser("demo", help="generate the default ROM and show the virtual encoder's signals")
    demo.add_argument("--out", default="build/demo", metavar="DIR", help="output folder (default build/demo)")
    demo.set_defaults(func=cmd_demo)

    from ..board.host import add_parser as add_host_parser

    add_host_parser(sub)
    from ..board.calibration import add_parser as add_calibrate_parser

    add_calibrate_parser(sub)
    from ..nd.cli import add_parser as add_nd_parser

    add_nd_parser(sub)
    from ..matrix.cli import add_parser as add_matrix_parser

    add_matrix_parser(sub)
    from .disc import add_parser as add_disc_parser

    add_disc_parser(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        args.func(args)
    except HostError as exc:
        sys.stderr.write(f"prenc {args.command}: error: {exc}\n")
        return 1
    except (ValueError, TapsError, OSError) as exc:
        message = str(exc) if not isinstance(exc, OSError) or not exc.filename else f"{exc.filename}: {exc.strerror}"
        sys.stderr.write(f"prenc {args.command}: error: {message}\n")
        return 1
    except KeyboardInterrupt:
        return 130
    return 0


if __name__ == "__main__":
    sys.exit(main())
