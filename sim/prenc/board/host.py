# SPDX-License-Identifier: Apache-2.0
"""`prenc host`: read positions from the board over its UART (pyserial).

    prenc host read    --port P [--baud B] [--kind abs|hybrid|incremental|tracks|status] [--json]
    prenc host monitor --port P [--rate HZ] [--count K]
    prenc host log     --port P --out FILE.csv [--rate HZ] (--duration S | --count K)
    prenc host plot    FILE.csv [--out FILE.png]

`Board` is the client the commands use: it opens the port, checks the protocol
version, sends requests (prenc.board.protocol) and parses answers with the same parser
as the board's RTL. A frame with a bad CRC is counted (`Board.crc_errors`) and
skipped, never fatal. The errors a user can meet are `HostError`s with one line
each: a missing port, no answer within the timeout, a protocol version mismatch,
a NACK.
"""

from __future__ import annotations

import csv
import json
import math
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Iterator, TextIO

from . import protocol
from .protocol import Answer, FrameParser, Kind, Nack

DEFAULT_BAUD = 115200
KINDS = {k.name.lower(): k for k in Kind if k != Kind.EDGES}   # EDGES: prenc calibrate's
CSV_FIELDS = ("host_time_s", "board_time_us", "seq", "kind", "valid", "mode", "direction", "warning",
              "position", "angle_deg", "count", "track1", "track2", "track1_valid", "track2_valid",
              "fine_position", "fine_bits", "velocity_rpm", "velocity_valid")


class HostError(RuntimeError):
    """What went wrong, in one line for the user."""


def open_port(port: str, baud: int = DEFAULT_BAUD):
    """A pyserial port (device path or pyserial URL such as loop://)."""
    import serial

    try:
        return serial.serial_for_url(port, baudrate=baud, timeout=0.02, write_timeout=2.0)
    except (serial.SerialException, ValueError, OSError) as exc:
        text = str(exc)
        if "No such file" in text or "could not open" in text or "FileNotFoundError" in text:
            raise HostError(f"port {port} not found (is the board plugged in? `python -m serial.tools.list_ports` "
                            f"lists the ports)") from None
        raise HostError(f"cannot open port {port}: {text}") from None


@dataclass
class LinkStats:
    answers: int = 0
    nacks: int = 0
    protocol_errors: int = 0


class Board:
    """The board at the other end of a serial port."""

    def __init__(self, port, timeout: float = 1.0, idle_timeout: float = 0.05, name: str = "the board",
                 baud: int | None = None):
        self.port = port
        self.baud = baud
        self.timeout = timeout
        self.idle_timeout = idle_timeout
        self.name = name
        self.parser = FrameParser(max_len=protocol.ANSWER_MAX_LEN)
        self.stats = LinkStats()
        self.bits: int | None = None
        self._pending: list[protocol.Frame] = []
        self._last_byte = time.monotonic()

    @classmethod
    def open(cls, port: str, baud: int = DEFAULT_BAUD, timeout: float = 1.0) -> "Board":
        return cls(open_port(port, baud), timeout=timeout, name=port, baud=baud)

    def close(self) -> None:
        self.port.close()

    def __enter__(self) -> "Board":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    @property
    def crc_errors(self) -> int:
        """Answer frames rejected by the parser (bad CRC, bad length, cut short)."""
        return self.parser.errors

    # --- frames ---------------------------------------------------------------
    def _next_frame(self, deadline: float) -> protocol.Frame:
        while True:
            if self._pending:
                return self._pending.pop(0)
            now = time.monotonic()
            if now > deadline:
                hint = f" (is the board programmed, and is it at {self.baud} baud?)" if self.baud else ""
                raise HostError(f"no answer from {self.name} within {self.timeout:g} s{hint}")
            data = self.port.read(max(1, getattr(self.port, "in_waiting", 0) or 1))
            if data:
                self._last_byte = time.monotonic()
                self._pending.extend(self.parser.feed(data))
            elif self.parser.in_frame and time.monotonic() - self._last_byte > self.idle_timeout:
                self.parser.idle()

    def answers(self, timeout: float | None = None) -> Iterator[Answer | Nack]:
        """Every answer that arrives; stops with HostError after `timeout` s of silence."""
        wait = self.timeout if timeout is None else timeout
        while True:
            frame = self._next_frame(time.monotonic() + wait)
            try:
                answer = protocol.decode(frame)
            except protocol.ProtocolError:
                self.stats.protocol_errors += 1
                continue
            if isinstance(answer, Nack):
                self.stats.nacks += 1
            else:
                self.stats.answers += 1
            yield answer

    def _ask(self, request: bytes, kind: Kind) -> Answer:
        self.port.write(request)
        self.port.flush()
        for answer in self.answers():
            if isinstance(answer, Nack):
                raise HostError(f"the board refused the request: {answer.reason}")
            if answer.kind == kind:
                return answer
        raise AssertionError("unreachable")  # answers() ends only by raising

    # --- requests -------------------------------------------------------------
    def read(self, kind: Kind) -> Answer:
        return self._ask(protocol.read_request(kind), Kind(kind))

    def status(self) -> Answer:
        return self.read(Kind.STATUS)

    def check_version(self) -> Answer:
        """Ask for STATUS and stop with a clear error when the protocol version differs."""
        status = self.status()
        version = status.values["version"]
        if version != protocol.VERSION:
            raise HostError(f"protocol version mismatch: the board speaks version {version}, "
                            f"this host speaks {protocol.VERSION} (update the bitstream or prenc)")
        self.bits = status.values["bits"]
        return status

    def clear(self) -> Answer:
        return self._ask(protocol.clear_request(), Kind.STATUS)

    def write_cal(self, address: int, word: int) -> Answer:
        """Word `address` of the board's calibration table (WRITE_CAL)."""
        return self._ask(protocol.write_cal_request(address, word), Kind.STATUS)

    def start_stream(self, kind: Kind, period_us: int) -> Answer:
        if period_us <= 0:
            raise HostError("stream period must be at least 1 us")
        return self._ask(protocol.stream_request(kind, period_us), Kind(kind))

    def stop_stream(self) -> None:
        self.port.write(protocol.stream_request(Kind.STATUS, 0))
        self.port.flush()
        for answer in self.answers():
            if isinstance(answer, Answer) and answer.kind == Kind.STATUS and not answer.streaming:
                return


# --- values for people ---------------------------------------------------------

def angle_deg(answer: Answer, bits: int) -> float | None:
    if answer.kind == Kind.ABS:
        return 360.0 * answer.values["position"] / (1 << bits)
    if answer.kind == Kind.HYBRID:
        return 360.0 * answer.values["position"] / (1 << (bits + 2))
    if answer.kind == Kind.FINE:
        return 360.0 * answer.values["fine_position"] / (1 << (bits + 2 + answer.values["fine_bits"]))
    return None


def rpm_of(answer: Answer, bits: int) -> float | None:
    """The board's velocity in rpm (a FINE answer whose velocity is valid), else None."""
    v = answer.values
    if answer.kind != Kind.FINE or not v["velocity_valid"]:
        return None
    return protocol.velocity_rpm(v["velocity"], v["clk_mhz"], bits)


def as_dict(answer: Answer, bits: int) -> dict:
    out = {"kind": answer.kind.name.lower(), "valid": answer.valid, "mode": answer.mode_name,
           "direction": "cw" if answer.direction else "ccw", "warning": answer.warning, "seq": answer.seq,
           "board_time_us": answer.time_us}
    out.update(answer.values)
    angle = angle_deg(answer, bits)
    if angle is not None:
        out["angle_deg"] = round(angle, 4)
    if answer.kind == Kind.FINE:
        rpm = rpm_of(answer, bits)
        out["velocity_rpm"] = None if rpm is None else round(rpm, 4)
    return out


def describe(answer: Answer, bits: int) -> str:
    v = answer.values
    flags = f"{'valid' if answer.valid else 'NOT VALID'} {answer.mode_name} {'cw' if answer.direction else 'ccw'}"
    if answer.warning:
        flags += " WARNING"
    if answer.kind in (Kind.ABS, Kind.HYBRID):
        width = bits if answer.kind == Kind.ABS else bits + 2
        return f"{answer.kind.name.lower()} {v['position']} / {1 << width} = {angle_deg(answer, bits):.3f} deg  {flags}"
    if answer.kind == Kind.INCREMENTAL:
        return f"incremental {v['count']} quadrature steps ({v['count'] / (4 << bits):+.4f} turns)  {flags}"
    if answer.kind == Kind.TRACKS:
        return (f"track1 {v['track1']} ({'valid' if v['track1_valid'] else 'not valid'}), "
                f"track2 {v['track2']} ({'valid' if v['track2_valid'] else 'not valid'})  {flags}")
    if answer.kind == Kind.FINE:
        rpm = rpm_of(answer, bits)
        speed = "velocity not valid" if rpm is None else f"{rpm:+.3f} rpm"
        width = bits + 2 + v["fine_bits"]
        return f"fine {v['fine_position']} / {1 << width} = {angle_deg(answer, bits):.4f} deg  {speed}  {flags}"
    if answer.kind == Kind.HEALTH:
        warned = [name for bit, name in enumerate(("head 1", "head 2", "sync")) if v["warnings"] >> bit & 1]
        return (f"health: at slot {v['position']}, errors track1 {v['track1_errors']}, track2 {v['track2_errors']}, "
                f"sync {v['sync_errors']}, warnings {', '.join(warned) or 'none'}  {flags}")
    return (f"status: protocol v{v['version']}, N={v['bits']}, errors track1 {v['track1_errors']}, "
            f"track2 {v['track2_errors']}, sync {v['sync_errors']}, link {v['link_errors']}  {flags}")


class CorrectionMap:
    """Where on the disc the corrections happen, from streamed HEALTH answers: the
    corrections that the error counters gained between two answers, placed at the slot
    halfway between their positions (the shorter way round), in `regions` equal parts of
    the disc. Head 1 reads the disc where the position is, head 2 half a turn further
    (L/2); the sync track's illegal transitions are placed at the position. Intervals
    in which the position was not valid at either end are left out (`skipped`)."""

    SOURCES = ("head1", "head2", "sync")

    def __init__(self, bits: int, regions: int = 32):
        if not 1 <= regions <= 1 << bits:
            raise HostError(f"regions must be 1..{1 << bits}, got {regions}")
        self.bits, self.regions = bits, regions
        self.counts = [[0] * regions for _ in self.SOURCES]
        self.skipped = 0
        self.last: tuple[int, ...] | None = None

    def add(self, answer: Answer) -> None:
        v = answer.values
        now = (v["position"], v["track1_errors"], v["track2_errors"], v["sync_errors"])
        if self.last is not None:
            gained = [b - a if b >= a else b for a, b in zip(self.last[1:-1], now[1:])]  # b < a: cleared
            if answer.valid and self.last[-1]:
                turn = 1 << self.bits
                moved = (now[0] - self.last[0] + turn // 2) % turn - turn // 2
                middle = (self.last[0] + moved // 2) % turn
                for k, count in enumerate(gained):
                    where = (middle + (turn // 2 if k == 1 else 0)) % turn
                    self.counts[k][where * self.regions // turn] += count
            else:
                self.skipped += sum(gained)
        self.last = now + (answer.valid,)

    def rows(self) -> list[dict]:
        turn = 1 << self.bits
        return [{"region": r, "first_slot": r * turn // self.regions, "last_slot": (r + 1) * turn // self.regions - 1,
                 **{name: self.counts[k][r] for k, name in enumerate(self.SOURCES)}} for r in range(self.regions)]

    def table(self) -> str:
        peak = max(1, max(max(c) for c in self.counts))
        lines = [f"{'slots':>11} {'degrees':>15} {'head 1':>7} {'head 2':>7} {'sync':>6}"]
        for row in self.rows():
            a, b = row["first_slot"], row["last_slot"]
            deg = 360 / (1 << self.bits)
            total = row["head1"] + row["head2"] + row["sync"]
            bar = "#" * round(20 * max(row["head1"], row["head2"], row["sync"]) / peak) if total else ""
            lines.append(f"{a:>5}-{b:<5} {a * deg:>7.1f}-{(b + 1) * deg:<7.1f} {row['head1']:>7} {row['head2']:>7} "
                         f"{row['sync']:>6} {bar}".rstrip())
        lines.append(f"corrections while the position was not valid (not placed): {self.skipped}")
        return "\n".join(lines)


class SpeedMeter:
    """Speed in rpm from successive hybrid (or fine) positions and board times (unwrapped):
    for a board without a velocity (FINE = 0)."""

    def __init__(self, bits: int):
        self.bits = bits
        self.last: tuple[int, int] | None = None
        self.rpm = 0.0

    def update(self, answer: Answer) -> float:
        if answer.kind not in (Kind.HYBRID, Kind.FINE) or not answer.valid:
            return self.rpm
        if answer.kind == Kind.FINE:
            self.counts = 1 << (self.bits + 2 + answer.values["fine_bits"])
            now = (answer.values["fine_position"], answer.time_us)
        else:
            self.counts = 1 << (self.bits + 2)
            now = (answer.values["position"], answer.time_us)
        if self.last is not None:
            dt = (now[1] - self.last[1]) % (1 << 32)
            if dt > 0:
                dp = (now[0] - self.last[0] + self.counts // 2) % self.counts - self.counts // 2
                self.rpm = dp / self.counts / (dt * 1e-6) * 60.0
        self.last = now
        return self.rpm


def _row(answer: Answer, bits: int, t0: float) -> dict:
    v = answer.values
    return {"host_time_s": f"{time.monotonic() - t0:.6f}", "board_time_us": answer.time_us, "seq": answer.seq,
            "kind": answer.kind.name.lower(), "valid": int(answer.valid), "mode": answer.mode_name,
            "direction": "cw" if answer.direction else "ccw", "warning": int(answer.warning),
            "position": v.get("position", ""),
            "angle_deg": "" if angle_deg(answer, bits) is None else f"{angle_deg(answer, bits):.4f}",
            "count": v.get("count", ""), "track1": v.get("track1", ""), "track2": v.get("track2", ""),
            "track1_valid": "" if "track1_valid" not in v else int(v["track1_valid"]),
            "track2_valid": "" if "track2_valid" not in v else int(v["track2_valid"]),
            "fine_position": v.get("fine_position", ""), "fine_bits": v.get("fine_bits", ""),
            "velocity_rpm": "" if rpm_of(answer, bits) is None else f"{rpm_of(answer, bits):.4f}",
            "velocity_valid": "" if "velocity_valid" not in v else int(v["velocity_valid"])}


# --- commands --------------------------------------------------------------------

def cmd_read(args, out: TextIO | None = None) -> None:
    out = out or sys.stdout
    with Board.open(args.port, args.baud, args.timeout) as board:
        board.check_version()
        answer = board.read(KINDS[args.kind])
        if args.json:
            record = as_dict(answer, board.bits)
            record["crc_errors"] = board.crc_errors
            out.write(json.dumps(record) + "\n")
        else:
            out.write(describe(answer, board.bits) + "\n")


def _period_us(rate: float) -> int:
    if not rate > 0:
        raise HostError(f"rate must be positive, got {rate}")
    return max(1, round(1e6 / rate))


def cmd_monitor(args, out: TextIO | None = None) -> None:
    out = out or sys.stdout
    with Board.open(args.port, args.baud, args.timeout) as board:
        status = board.check_version()
        speed = SpeedMeter(board.bits)
        board.start_stream(Kind.FINE, _period_us(args.rate))
        shown, last_status = 0, time.monotonic()
        try:
            for answer in board.answers():
                if isinstance(answer, Nack):
                    continue
                if answer.kind == Kind.STATUS:
                    status = answer
                    continue
                if answer.kind != Kind.FINE:
                    continue
                # The board's velocity, or (a board without one) the positions' differences.
                measured = speed.update(answer)
                board_rpm = rpm_of(answer, board.bits)
                rpm = measured if board_rpm is None else board_rpm
                s = status.values
                pos = answer.values["fine_position"] >> answer.values["fine_bits"]
                line = (f"\rposition {pos:>6} {angle_deg(answer, board.bits):9.4f} deg  {rpm:+10.3f} rpm  "
                        f"{answer.mode_name:<11} {'valid' if answer.valid else 'NOT VALID':<9}  errors t1 "
                        f"{s['track1_errors']} t2 {s['track2_errors']} sync {s['sync_errors']} link "
                        f"{s['link_errors']}  crc {board.crc_errors}{'  WARNING' if answer.warning else ''}")
                out.write(line)
                out.flush()
                shown += 1
                if args.count and shown >= args.count:
                    break
                if time.monotonic() - last_status > 0.5:
                    board.port.write(protocol.read_request(Kind.STATUS))
                    last_status = time.monotonic()
        except KeyboardInterrupt:
            pass
        finally:
            out.write("\n")
            board.stop_stream()


def cmd_log(args, out: TextIO | None = None, progress: TextIO | None = None) -> None:
    out, progress = out or sys.stdout, progress or sys.stderr
    kind = KINDS[args.kind]
    path = Path(args.out)
    with Board.open(args.port, args.baud, args.timeout) as board:
        board.check_version()
        t0 = time.monotonic()
        rows = 0
        tmp = path.with_name(path.name + ".part")
        try:
            with tmp.open("w", newline="") as f:
                writer = csv.DictWriter(f, fieldnames=CSV_FIELDS)
                writer.writeheader()
                writer.writerow(_row(board.start_stream(kind, _period_us(args.rate)), board.bits, t0))
                rows = 1
                last_shown = 0.0
                for answer in board.answers():
                    if isinstance(answer, Nack) or answer.kind != kind:
                        continue
                    writer.writerow(_row(answer, board.bits, t0))
                    rows += 1
                    elapsed = time.monotonic() - t0
                    done = (args.count and rows >= args.count) or (args.duration and elapsed >= args.duration)
                    if done or elapsed - last_shown >= 0.25:
                        goal = f"/{args.count}" if args.count else f" in {elapsed:.1f}/{args.duration:g} s"
                        progress.write(f"\rlog {path}: {rows}{goal} rows, {rows / max(elapsed, 1e-9):.0f} /s, "
                                       f"crc errors {board.crc_errors}")
                        progress.flush()
                        last_shown = elapsed
                    if done:
                        break
            tmp.replace(path)
        except KeyboardInterrupt:
            tmp.replace(path)
        finally:
            progress.write("\n")
            board.stop_stream()
    out.write(f"wrote {rows} rows to {path}\n")


def cmd_map(args, out: TextIO | None = None, progress: TextIO | None = None) -> None:
    out, progress = out or sys.stdout, progress or sys.stderr
    with Board.open(args.port, args.baud, args.timeout) as board:
        board.check_version()
        counts = CorrectionMap(board.bits, args.regions)
        duration = args.duration if args.duration is not None else (None if args.count else 10.0)
        t0 = time.monotonic()
        answers = 0
        try:
            counts.add(board.start_stream(Kind.HEALTH, 1))
            answers = 1
            for answer in board.answers():
                if isinstance(answer, Nack) or answer.kind != Kind.HEALTH:
                    continue
                counts.add(answer)
                answers += 1
                elapsed = time.monotonic() - t0
                if (args.count and answers >= args.count) or (duration and elapsed >= duration):
                    break
        except KeyboardInterrupt:
            pass
        finally:
            board.stop_stream()
    progress.write(f"map: {answers} answers, crc errors {board.crc_errors}\n")
    if args.json:
        out.write(json.dumps({"bits": board.bits, "regions": counts.rows(), "skipped": counts.skipped}) + "\n")
    else:
        out.write(counts.table() + "\n")


def cmd_plot(args, out: TextIO | None = None) -> None:
    out = out or sys.stdout
    path = Path(args.log)
    if not path.exists():
        raise HostError(f"{path}: log not found")
    with path.open(newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames is None or "board_time_us" not in reader.fieldnames:
            raise HostError(f"{path}: not a `prenc host log` file (no board_time_us column)")
        rows = list(reader)
    if not rows:
        raise HostError(f"{path}: the log has no rows")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = [int(r["board_time_us"]) for r in rows]
    wraps, times = 0, []
    for i, value in enumerate(t):
        if i and value < t[i - 1]:
            wraps += 1
        times.append((value + (wraps << 32) - t[0]) * 1e-6)
    column = "angle_deg" if rows[0]["angle_deg"] else ("count" if rows[0]["count"] else "track1")
    y = [float(r[column]) if r[column] != "" else math.nan for r in rows]
    valid = [r["valid"] == "1" for r in rows]
    velocity = [float(r["velocity_rpm"]) if r.get("velocity_rpm") else math.nan for r in rows]
    with_velocity = any(not math.isnan(v) for v in velocity)
    if with_velocity:
        fig, (ax, ax_v) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
        ax_v.plot(times, velocity, lw=0.8, color="tab:green", label="velocity")
        ax_v.set_ylabel("velocity (rpm)")
        ax_v.grid(alpha=0.3)
    else:
        fig, ax = plt.subplots(figsize=(9, 4))
    ax.plot(times, y, lw=0.8, color="tab:blue", label=column)
    ax.scatter([x for x, v in zip(times, valid) if not v], [yy for yy, v in zip(y, valid) if not v],
               s=8, color="tab:red", label="not valid", zorder=3)
    (ax_v if with_velocity else ax).set_xlabel("board time (s)")
    ax.set_ylabel(column.replace("_", " "))
    ax.set_title(f"{path.name}: {len(rows)} readings")
    ax.legend(loc="upper right")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    target = Path(args.out) if args.out else path.with_suffix(".png")
    fig.savefig(target, dpi=120)
    plt.close(fig)
    out.write(f"wrote {target}\n")


def add_parser(sub) -> None:
    """The `prenc host` sub-commands."""
    host = sub.add_parser("host", help="read positions from the board over its UART")
    cmds = host.add_subparsers(dest="host_command", required=True, parser_class=type(host))

    def link(p) -> None:
        p.add_argument("--port", "-p", required=True, help="serial port (/dev/ttyUSB1, COM3, or a pyserial URL)")
        p.add_argument("--baud", "-b", type=int, default=DEFAULT_BAUD, help=f"baud rate (default {DEFAULT_BAUD})")
        p.add_argument("--timeout", type=float, default=1.0, help="seconds to wait for an answer (default 1)")

    read = cmds.add_parser("read", help="one value of a chosen kind")
    link(read)
    read.add_argument("--kind", "-k", choices=list(KINDS), default="abs")
    read.add_argument("--json", action="store_true", help="one JSON object instead of a sentence")
    read.set_defaults(func=cmd_read)

    monitor = cmds.add_parser("monitor", help="a live line: position, angle, speed (rpm), mode, error counts")
    link(monitor)
    monitor.add_argument("--rate", type=float, default=50.0, help="updates per second (default 50)")
    monitor.add_argument("--count", type=int, default=0, help="stop after this many updates (default: Ctrl-C)")
    monitor.set_defaults(func=cmd_monitor)

    log = cmds.add_parser("log", help="stream to a CSV file with timestamps")
    link(log)
    log.add_argument("--out", "-o", required=True, help="CSV file to write")
    log.add_argument("--kind", "-k", choices=[k for k in KINDS if k != "status"], default="hybrid")
    log.add_argument("--rate", type=float, default=1000.0, help="readings per second (default 1000)")
    stop = log.add_mutually_exclusive_group(required=True)
    stop.add_argument("--duration", type=float, help="seconds to log")
    stop.add_argument("--count", type=int, help="readings to log")
    log.set_defaults(func=cmd_log)

    where = cmds.add_parser("map", help="where on the disc the reader corrects its heads (streams HEALTH)")
    link(where)
    where.add_argument("--regions", type=int, default=32, help="parts of the disc (default 32)")
    where.add_argument("--json", action="store_true", help="the counts as one JSON object")
    span = where.add_mutually_exclusive_group()
    span.add_argument("--duration", type=float, help="seconds to stream (default 10)")
    span.add_argument("--count", type=int, help="answers to take instead")
    where.set_defaults(func=cmd_map)

    plot = cmds.add_parser("plot", help="plot a log written by `prenc host log`")
    plot.add_argument("log", help="the CSV log")
    plot.add_argument("--out", "-o", help="PNG to write (default: beside the log)")
    plot.set_defaults(func=cmd_plot)
