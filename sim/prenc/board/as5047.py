# SPDX-License-Identifier: Apache-2.0
"""The AS5047P's SPI interface: the model of rtl/board/prenc_as5047.v, frame for frame,
and the words a driver sends and reads (docs/interfaces/as5047.md).

A master's frame is 16 bits under one CSn low. The slave takes its answer when CSn
falls (`As5047.open`) and decodes the command when CSn rises (`As5047.shut`); a read's
register is answered in the next frame.
"""

from __future__ import annotations

from dataclasses import dataclass

NOP, ERRFL, PROG = 0x0000, 0x0001, 0x0003
ZPOSM, ZPOSL, SETTINGS1, SETTINGS2 = 0x0016, 0x0017, 0x0018, 0x0019
DIAAGC, MAG, ANGLEUNC, ANGLECOM = 0x3FFC, 0x3FFD, 0x3FFE, 0x3FFF
WRITABLE = (PROG, ZPOSM, ZPOSL, SETTINGS1, SETTINGS2)
READABLE = WRITABLE + (NOP, ERRFL, DIAAGC, MAG, ANGLEUNC, ANGLECOM)
FRERR, INVCOMM, PARERR = 1 << 0, 1 << 1, 1 << 2  # ERRFL's bits
DIR = 1 << 2                                      # SETTINGS1's
AGC, MAGNITUDE = 0x80, 0x1000                     # what DIAAGC and MAG show
LF, COF, MAGL = 1 << 8, 1 << 9, 1 << 11           # DIAAGC's (MAGL: prenc_health's warning)


def parity(word: int) -> int:
    """The even parity bit of bits 14:0."""
    return bin(word & 0x7FFF).count("1") & 1


def with_parity(word: int) -> int:
    return (word & 0x7FFF) | parity(word) << 15


def read_command(address: int) -> int:
    """The frame that reads `address` (answered in the next frame)."""
    return with_parity(1 << 14 | address)


def write_command(address: int) -> int:
    return with_parity(address)


def data_frame(value: int) -> int:
    """A write's second frame."""
    return with_parity(value & 0x3FFF)


@dataclass(frozen=True)
class Answer:
    word: int

    @property
    def parity_ok(self) -> bool:
        return bin(self.word).count("1") % 2 == 0

    @property
    def error(self) -> bool:
        return bool(self.word >> 14 & 1)

    @property
    def data(self) -> int:
        return self.word & 0x3FFF


class As5047:
    """The slave's registers; `open` and `shut` are what it does at CSn's edges."""

    def __init__(self, zero: int = 0, settings1: int = 0x01, settings2: int = 0x00):
        self.errfl = 0
        self.prog = 0
        self.zposm = zero >> 6
        self.zposl = zero & 0x3F
        self.settings1 = settings1
        self.settings2 = settings2
        self.answer_address = ANGLECOM   # the first frame after reset answers the angle
        self.write_pending = False
        self.been_valid = False
        self.held = 0

    @property
    def zero(self) -> int:
        return self.zposm << 6 | (self.zposl & 0x3F)

    def angle(self, raw: int) -> int:
        """The angle an answer carries for the reader's 14-bit angle `raw`."""
        directed = -1 - raw if self.settings1 & DIR else raw   # the one's complement
        return (directed - self.zero) % (1 << 14)

    def follow(self, raw: int, valid: bool) -> None:
        """A clock of the reader's angle: the last valid one is held, LF set."""
        if valid:
            self.held = self.angle(raw)
            self.been_valid = True

    def open(self, raw: int, valid: bool, warning: bool = False) -> int:
        """CSn falls: the answer word, with the angle `raw` and the warning of that instant."""
        a = self.answer_address
        angle = self.angle(raw) if valid else self.held
        data = {
            ERRFL: self.errfl, PROG: self.prog, ZPOSM: self.zposm, ZPOSL: self.zposl,
            SETTINGS1: self.settings1, SETTINGS2: self.settings2,
            DIAAGC: (0 if valid else COF) | (LF if self.been_valid else 0) | (MAGL if warning else 0) | AGC,
            MAG: MAGNITUDE, ANGLEUNC: angle, ANGLECOM: angle,
        }.get(a, 0)
        error = self.errfl != 0 or (a in (ANGLEUNC, ANGLECOM) and not valid)
        if a == ERRFL:
            self.errfl = 0
        self.follow(raw, valid)
        word = int(error) << 14 | data
        return with_parity(word)

    def shut(self, word: int, clocks: int) -> None:
        """CSn rises after `clocks` falling edges of SCLK that shifted in `word` (its
        last 16 bits)."""
        word &= 0xFFFF
        frame_error = clocks != 16
        parity_error = bin(word).count("1") % 2 == 1
        read, address = bool(word >> 14 & 1), word & 0x3FFF
        bad_command = not self.write_pending and (address not in (READABLE if read else WRITABLE + (NOP,)))
        if frame_error or parity_error or bad_command:
            if frame_error:
                self.errfl |= FRERR
            elif parity_error:
                self.errfl |= PARERR
            else:
                self.errfl |= INVCOMM
            self.write_pending = False
        elif self.write_pending:
            self.write_pending = False
            name = {PROG: "prog", ZPOSM: "zposm", ZPOSL: "zposl",
                    SETTINGS1: "settings1", SETTINGS2: "settings2"}[self.answer_address]
            setattr(self, name, word & 0xFF)
        else:
            self.answer_address = address
            self.write_pending = not read and address != NOP   # 0x0000 is a NOP
