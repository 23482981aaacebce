# SPDX-License-Identifier: Apache-2.0
"""`prenc calibrate`: a calibration run on the board, over its host link
(docs/calibration.md).

    prenc calibrate --port /dev/ttyUSB1 --out disc.cal [--turns 10] [--apply]
    prenc calibrate --port /dev/ttyUSB1 --load disc.cal

While the motor turns one way at a roughly steady speed, the board streams the edges
the disc crosses with the clocks between them (the EDGES answer, back to back); the
host strings them into a record of consecutive crossings, starting it anew where the
record breaks (an entry the board dropped because the link was full, an illegal
transition, a reversal, the position not yet valid, an interval too long to count),
until it holds the turns asked for. prenc.cal.calibrate makes the table and checks it;
the table goes to --out (prenc.cal.table's format) and, with --apply, into the board's
table (WRITE_CAL, a word per request; the board needs CAL = 1). --load writes a table
file into the board.

The link carries three edges per EDGES answer (21 bytes): about 1,600 edges a second at
115200 baud, 14,000 at 1 Mbaud. A disc of 2^N slots has 4 x 2^N edges a turn, so turn
it slower than baud / 70 / 2^(N+2) turns a second (at N = 10: 24 rpm at 115200 baud,
210 rpm at 1 Mbaud); the clocks between two edges must stay below 65,535.
"""

from __future__ import annotations

import sys
import time
from dataclasses import dataclass, field
from typing import Iterable, TextIO

from ..cal.calibrate import CalibrationError, Record, calibrate
from ..cal.table import Table, TableError, read
from .host import DEFAULT_BAUD, Board, HostError
from .protocol import Answer, Kind

SATURATED = 0xFFFF
MAX_SECONDS = 600.0


@dataclass
class RecordBuilder:
    """Strings EDGES answers into a record of consecutive crossings of one direction."""

    bits: int
    need: int                                  # crossings the record must hold
    edges: list[int] = field(default_factory=list)
    clocks: list[int] = field(default_factory=list)
    cw: bool = True
    breaks: dict[str, int] = field(default_factory=lambda: {"lost": 0, "reversal": 0, "not valid": 0,
                                                            "too slow": 0})

    def _restart(self, why: str) -> None:
        if self.edges:
            self.breaks[why] += 1
        self.edges, self.clocks = [], []

    def feed(self, answer: Answer) -> bool:
        """Take one EDGES answer; True once the record holds `need` crossings."""
        v = answer.values
        if v["lost"]:
            self._restart("lost")
        if v["run"] == 0:
            return len(self.edges) >= self.need
        if not v["pos_valid"]:
            self._restart("not valid")
            return False
        size = 4 << self.bits
        step = 1 if v["cw"] else -1
        for k, interval in enumerate(v["intervals"]):
            edge = (v["edge"] + k * step) % size
            if self.edges and (v["cw"] != self.cw or edge != (self.edges[-1] + step) % size):
                self._restart("reversal")
            if interval == SATURATED:
                self._restart("too slow")
            if not self.edges:
                self.cw = v["cw"]
                self.edges, self.clocks = [edge], [0]
                continue
            self.edges.append(edge)
            self.clocks.append(self.clocks[-1] + interval)
        return len(self.edges) >= self.need

    def record(self) -> Record:
        return Record(self.bits, self.edges[: self.need], self.clocks[: self.need])


def collect(answers: Iterable[Answer], bits: int, turns: int, max_seconds: float = MAX_SECONDS) -> Record:
    """A record of `turns` whole turns from a stream of answers (EDGES ones count)."""
    builder = RecordBuilder(bits, turns * (4 << bits) + 1)
    deadline = time.monotonic() + max_seconds
    for answer in answers:
        if isinstance(answer, Answer) and answer.kind == Kind.EDGES and builder.feed(answer):
            return builder.record()
        if time.monotonic() > deadline:
            break
    got = len(builder.edges) / (4 << bits)
    breaks = ", ".join(f"{n} {why}" for why, n in builder.breaks.items() if n) or "none"
    raise HostError(f"no record of {turns} turns within {max_seconds:g} s (the longest was {got:.2f} turns; "
                    f"breaks: {breaks}). Is the disc turning one way, steadily, and slower than the link "
                    "carries (docs/calibration.md)? A board built without the edges' capture "
                    "(EDGE_CAPTURE = 0: the iCEBreaker) never sends a run.")


def record_from_board(board: Board, bits: int, turns: int, max_seconds: float = MAX_SECONDS) -> Record:
    first = board.start_stream(Kind.EDGES, 1)   # back to back, at the line's rate

    def stream():
        yield first
        yield from board.answers()
    try:
        return collect(stream(), bits, turns, max_seconds)
    finally:
        board.stop_stream()


def load_table(board: Board, table: Table, progress: TextIO | None = None) -> None:
    """Every word of the table into the board (WRITE_CAL)."""
    size = len(table.c)
    for x, word in enumerate(table.c.tolist()):
        board.write_cal(x, int(word))
        if progress is not None and (x + 1) % 512 == 0:
            progress.write(f"\rloading the table: {x + 1} / {size}")
            progress.flush()
    if progress is not None:
        progress.write(f"\rloading the table: {size} / {size}\n")


def cmd_calibrate(args, out: TextIO | None = None, progress: TextIO | None = None) -> None:
    out = out or sys.stdout
    progress = progress if progress is not None else sys.stderr
    with Board.open(args.port, args.baud, timeout=args.timeout) as board:
        status = board.check_version()
        bits = status.values["bits"]
        if args.load:
            try:
                table = read(args.load, n=bits)
            except TableError as exc:
                raise HostError(str(exc)) from None
            load_table(board, table, progress)
            out.write(f"loaded {args.load} ({len(table.c)} corrections) into the board\n")
            return
        clk_mhz = board.read(Kind.FINE).values["clk_mhz"]
        progress.write(f"recording {args.turns} turns of edges (N = {bits}) ...\n")
        record = record_from_board(board, bits, args.turns, args.max_seconds)
        try:
            result = calibrate(record, args.turns)
        except CalibrationError as exc:
            raise HostError(f"the run cannot be used: {exc}") from None
        result.table.write(args.out)
        out.write(result.summary(clk_mhz * 1e6 if clk_mhz else None) + "\n")
        out.write(f"wrote {args.out}\n")
        if args.apply:
            load_table(board, result.table, progress)
            out.write("the board uses the table now\n")


def add_parser(sub) -> None:
    p = sub.add_parser("calibrate", help="calibrate the disc's sync track on the board (docs/calibration.md)")
    p.add_argument("--port", "-p", required=True, help="serial port (/dev/ttyUSB1, COM3, or a pyserial URL)")
    p.add_argument("--baud", "-b", type=int, default=DEFAULT_BAUD, help=f"baud rate (default {DEFAULT_BAUD})")
    p.add_argument("--timeout", type=float, default=1.0, help="seconds to wait for an answer (default 1)")
    mode = p.add_mutually_exclusive_group(required=True)
    mode.add_argument("--out", "-o", help="run a calibration and write the table to this file")
    mode.add_argument("--load", help="write this table file into the board (it needs CAL = 1)")
    p.add_argument("--turns", type=int, default=10, help="turns to record (default 10)")
    p.add_argument("--apply", action="store_true", help="after the run, write the table into the board")
    p.add_argument("--max-seconds", type=float, default=MAX_SECONDS,
                   help=f"give up after this long without a whole record (default {MAX_SECONDS:g})")
    p.set_defaults(func=cmd_calibrate)
