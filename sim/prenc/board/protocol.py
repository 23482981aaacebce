# SPDX-License-Identifier: Apache-2.0
"""The host protocol between the board and the PC (docs/host-protocol.md).

The Python side of rtl/board/prenc_frame_rx.v, rtl/board/prenc_frame_tx.v and the payload
layouts of rtl/board/prenc_host_link.v:

    frame = A5 | TYPE | LEN | PAYLOAD[LEN] | CRC16 (big-endian)

The CRC is CRC-16/CCITT-FALSE over TYPE, LEN and the payload: Python's
`binascii.crc_hqx(data, 0xFFFF)`.

`FrameParser` is the same state machine as prenc_frame_rx: it hunts for A5, follows
LEN, and rejects (and counts) a frame whose CRC differs, whose LEN is over its limit,
or which stops for longer than the timeout (`idle()`, called by the reader of the
line when it has waited that long). It never raises on input bytes.
"""

from __future__ import annotations

import binascii
import struct
from dataclasses import dataclass, field
from enum import IntEnum

SOF = 0xA5
VERSION = 4
REQUEST_MAX_LEN = 5  # prenc_host_link's parser limit
ANSWER_MAX_LEN = 16
HEADER_LEN = 6  # FLAGS, SEQ, TIME[4]


class Request(IntEnum):
    READ = 0x01
    STREAM = 0x02
    CLEAR = 0x03
    WRITE_CAL = 0x04


class Kind(IntEnum):
    ABS = 0
    HYBRID = 1
    INCREMENTAL = 2
    TRACKS = 3
    STATUS = 4
    FINE = 5
    EDGES = 6
    HEALTH = 7


ANSWER_DATA = 0x80
ANSWER_NACK = 0xFF
NACK_CODES = {1: "unknown request type", 2: "bad length", 3: "unknown kind",
              4: "the board has no calibration table (built with CAL = 0)",
              5: "calibration table address out of range"}
MODE_NAMES = {0: "ACQUIRE", 1: "NORMAL", 2: "REDUCED_1", 3: "REDUCED_2", 4: "INCREMENTAL"}

# Data bytes after the header, per kind.
DATA_LEN = {Kind.ABS: 2, Kind.HYBRID: 3, Kind.INCREMENTAL: 4, Kind.TRACKS: 5, Kind.STATUS: 10,
            Kind.FINE: 10, Kind.EDGES: 10, Kind.HEALTH: 9}
VELOCITY_FRAC = 32  # FINE's velocity: quarters per clock x 2^32


def velocity_rpm(velocity: int, clk_mhz: int, bits: int) -> float:
    """FINE's velocity (quarters per clock x 2^32) in revolutions per minute, for a disc of
    2^bits slots and the board's clock."""
    return velocity / 2.0 ** VELOCITY_FRAC * clk_mhz * 1e6 * 60 / (4 << bits)


def crc16(data: bytes) -> int:
    return binascii.crc_hqx(bytes(data), 0xFFFF)


def encode(frame_type: int, payload: bytes = b"") -> bytes:
    """A whole frame, SOF to CRC."""
    if not 0 <= frame_type <= 0xFF:
        raise ValueError(f"frame type {frame_type} is not a byte")
    if len(payload) > 0xFF:
        raise ValueError(f"payload of {len(payload)} bytes is longer than 255")
    body = bytes([frame_type, len(payload)]) + bytes(payload)
    return bytes([SOF]) + body + struct.pack(">H", crc16(body))


def read_request(kind: Kind | int) -> bytes:
    return encode(Request.READ, bytes([int(kind)]))


def stream_request(kind: Kind | int, period_us: int) -> bytes:
    if not 0 <= period_us < 1 << 32:
        raise ValueError(f"stream period {period_us} us is out of range 0..2^32-1")
    return encode(Request.STREAM, bytes([int(kind)]) + struct.pack(">I", period_us))


def clear_request() -> bytes:
    return encode(Request.CLEAR)


def write_cal_request(address: int, word: int) -> bytes:
    """WRITE_CAL: word c[address] of the calibration table (signed 16 bits)."""
    if not 0 <= address < 1 << 24:
        raise ValueError(f"calibration table address {address} is out of range 0..2^24-1")
    if not -(1 << 15) <= word < 1 << 16:
        raise ValueError(f"calibration word {word} does not fit 16 bits")
    return encode(Request.WRITE_CAL, address.to_bytes(3, "big") + struct.pack(">H", word & 0xFFFF))


@dataclass(frozen=True)
class Frame:
    type: int
    payload: bytes


@dataclass
class FrameParser:
    """Bytes in, checked frames out; the model of rtl/board/prenc_frame_rx.v."""

    max_len: int = ANSWER_MAX_LEN
    frames: int = 0
    errors: int = 0
    _state: str = "hunt"
    _type: int = 0
    _len: int = 0
    _body: bytearray = field(default_factory=bytearray)
    _crc: bytearray = field(default_factory=bytearray)

    @property
    def in_frame(self) -> bool:
        return self._state != "hunt"

    def idle(self) -> None:
        """The line stayed quiet for the timeout: a frame in progress is rejected."""
        if self._state != "hunt":
            self._reject()

    def byte_error(self) -> None:
        """A byte with a framing error (low stop bit) arrived."""
        self.idle()

    def _reject(self) -> None:
        self.errors += 1
        self._state = "hunt"

    def feed(self, data: bytes) -> list[Frame]:
        out = []
        for byte in bytes(data):
            frame = self.push(byte)
            if frame is not None:
                out.append(frame)
        return out

    def push(self, byte: int) -> Frame | None:
        state = self._state
        if state == "hunt":
            if byte == SOF:
                self._state, self._body, self._crc = "type", bytearray(), bytearray()
        elif state == "type":
            self._type = byte
            self._body.append(byte)
            self._state = "len"
        elif state == "len":
            self._len = byte
            self._body.append(byte)
            if byte > self.max_len:
                self._reject()
            else:
                self._state = "payload" if byte else "crc"
        elif state == "payload":
            self._body.append(byte)
            if len(self._body) == 2 + self._len:
                self._state = "crc"
        else:
            self._crc.append(byte)
            if len(self._crc) == 2:
                self._state = "hunt"
                if struct.unpack(">H", bytes(self._crc))[0] == crc16(bytes(self._body)):
                    self.frames += 1
                    return Frame(self._type, bytes(self._body[2:]))
                self.errors += 1
        return None


class ProtocolError(ValueError):
    """A frame that passed its CRC but does not follow the protocol."""


@dataclass(frozen=True)
class Answer:
    """One answer of the board, decoded."""

    kind: Kind
    valid: bool
    mode: int
    direction: int  # 1 = CW, as the core's `direction`
    streaming: bool
    seq: int
    time_us: int
    values: dict
    warning: bool = False  # prenc_health's warning: the corrections grow (FLAGS bit 1)

    @property
    def mode_name(self) -> str:
        return MODE_NAMES.get(self.mode, f"MODE_{self.mode}")


@dataclass(frozen=True)
class Nack:
    code: int
    request: int
    seq: int
    time_us: int

    @property
    def reason(self) -> str:
        return NACK_CODES.get(self.code, f"code {self.code}")


def decode(frame: Frame) -> Answer | Nack:
    """An answer frame's fields; ProtocolError when the layout is not the protocol's."""
    p = frame.payload
    if len(p) < HEADER_LEN:
        raise ProtocolError(f"answer of {len(p)} bytes is shorter than its {HEADER_LEN}-byte header")
    flags, seq, time_us = p[0], p[1], struct.unpack(">I", p[2:6])[0]
    data = p[HEADER_LEN:]
    if frame.type == ANSWER_NACK:
        if len(data) != 2:
            raise ProtocolError(f"NACK with {len(data)} data bytes, expected 2")
        return Nack(code=data[0], request=data[1], seq=seq, time_us=time_us)
    kind_value = frame.type - ANSWER_DATA
    if not 0 <= kind_value <= max(Kind):
        raise ProtocolError(f"unknown answer type 0x{frame.type:02X}")
    kind = Kind(kind_value)
    if len(data) != DATA_LEN[kind]:
        raise ProtocolError(f"{kind.name} answer with {len(data)} data bytes, expected {DATA_LEN[kind]}")
    if kind == Kind.ABS:
        values = {"position": struct.unpack(">H", data)[0]}
    elif kind == Kind.HYBRID:
        values = {"position": int.from_bytes(data, "big")}
    elif kind == Kind.INCREMENTAL:
        values = {"count": struct.unpack(">i", data)[0]}
    elif kind == Kind.TRACKS:
        t1, t2, tf = struct.unpack(">HHB", data)
        values = {"track1": t1, "track2": t2, "track1_valid": bool(tf & 1), "track2_valid": bool(tf & 2)}
    elif kind == Kind.HEALTH:
        position, e1, e2, es, warnings = struct.unpack(">HHHHB", data)
        values = {"position": position, "track1_errors": e1, "track2_errors": e2, "sync_errors": es,
                  "warnings": warnings & 7}
    elif kind == Kind.EDGES:
        info = data[0]
        run = info & 3
        values = {"lost": bool(info & 0x80), "cw": bool(info & 0x40), "pos_valid": bool(info & 0x20),
                  "run": run, "edge": int.from_bytes(data[1:4], "big"),
                  "intervals": list(struct.unpack(">HHH", data[4:10]))[:run]}
    elif kind == Kind.FINE:
        fine, velocity, info, clk_mhz = struct.unpack(">IiBB", data)
        values = {"fine_position": fine, "fine_bits": info & 0x0F, "velocity": velocity,
                  "velocity_valid": bool(info & 0x10), "interpolated": bool(info & 0x20), "clk_mhz": clk_mhz}
    else:
        version, n, e1, e2, es, el = struct.unpack(">BBHHHH", data)
        values = {"version": version, "bits": n, "track1_errors": e1, "track2_errors": e2,
                  "sync_errors": es, "link_errors": el}
    return Answer(kind=kind, valid=bool(flags & 0x80), mode=(flags >> 4) & 7, direction=(flags >> 3) & 1,
                  streaming=bool(flags & 0x04), seq=seq, time_us=time_us, values=values,
                  warning=bool(flags & 0x02))


def encode_answer(answer: Answer) -> bytes:
    """The frame the board sends for `answer` (for the protocol's own tests and fakes)."""
    flags = ((answer.valid << 7) | (answer.mode << 4) | (answer.direction << 3) | (answer.streaming << 2)
             | (answer.warning << 1))
    head = bytes([flags, answer.seq & 0xFF]) + struct.pack(">I", answer.time_us & 0xFFFFFFFF)
    v = answer.values
    if answer.kind == Kind.ABS:
        data = struct.pack(">H", v["position"])
    elif answer.kind == Kind.HYBRID:
        data = v["position"].to_bytes(3, "big")
    elif answer.kind == Kind.INCREMENTAL:
        data = struct.pack(">i", v["count"])
    elif answer.kind == Kind.TRACKS:
        data = struct.pack(">HHB", v["track1"], v["track2"], v["track1_valid"] | (v["track2_valid"] << 1))
    elif answer.kind == Kind.HEALTH:
        data = struct.pack(">HHHHB", v["position"], v["track1_errors"], v["track2_errors"], v["sync_errors"],
                           v["warnings"])
    elif answer.kind == Kind.EDGES:
        info = (v["lost"] << 7) | (v["cw"] << 6) | (v["pos_valid"] << 5) | v["run"]
        intervals = list(v["intervals"]) + [0] * (3 - len(v["intervals"]))
        data = bytes([info]) + v["edge"].to_bytes(3, "big") + struct.pack(">HHH", *intervals)
    elif answer.kind == Kind.FINE:
        info = v["fine_bits"] | (v["velocity_valid"] << 4) | (v["interpolated"] << 5)
        data = struct.pack(">IiBB", v["fine_position"], v["velocity"], info, v["clk_mhz"])
    else:
        data = struct.pack(">BBHHHH", v["version"], v["bits"], v["track1_errors"], v["track2_errors"],
                           v["sync_errors"], v["link_errors"])
    return encode(ANSWER_DATA + int(answer.kind), head + data)
