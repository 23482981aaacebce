# SPDX-License-Identifier: Apache-2.0
"""prenc.board.as5047, the AS5047P's SPI model, against the datasheet and the words the
drives send (tb/as5047_drivers.py names the sources)."""

from __future__ import annotations

import pytest

from prenc.board import as5047 as spec


@pytest.mark.parametrize("word, expected", [
    (spec.read_command(spec.ANGLECOM), 0xFFFF),     # ODrive, SimpleFOC, VESC, moteus
    (spec.read_command(spec.ANGLEUNC), 0x7FFE),     # Klipper, SimpleFOC drivers
    (spec.read_command(spec.NOP), 0xC000),          # Klipper's second frame
    (spec.read_command(spec.ERRFL), 0x4001),
    (spec.read_command(spec.DIAAGC), 0xFFFC),
    (spec.read_command(spec.MAG), 0x7FFD),
    (spec.read_command(spec.SETTINGS1), 0xC018),
    (spec.read_command(spec.SETTINGS2), 0x4019),
    (spec.read_command(spec.ZPOSM), 0x4016),
    (spec.read_command(spec.ZPOSL), 0xC017),
    (spec.write_command(spec.SETTINGS1), 0x0018),
    (spec.write_command(spec.SETTINGS2), 0x8019),
    (spec.write_command(spec.ZPOSM), 0x8016),
    (spec.write_command(spec.ZPOSL), 0x0017),
])
def test_command_words_are_the_drivers(word, expected):
    assert word == expected


def frame(slave: spec.As5047, word: int, raw: int = 0, valid: bool = True, clocks: int = 16) -> spec.Answer:
    answer = spec.Answer(slave.open(raw, valid))
    slave.shut(word, clocks)
    return answer


def test_a_read_is_answered_in_the_next_frame_with_parity_and_no_error():
    s = spec.As5047()
    frame(s, spec.read_command(spec.SETTINGS1))
    a = frame(s, spec.read_command(spec.ANGLECOM))
    assert (a.data, a.error, a.parity_ok) == (0x01, False, True)
    a = frame(s, spec.read_command(spec.NOP), raw=1234)
    assert (a.data, a.error, a.parity_ok) == (1234, False, True)
    assert frame(s, spec.read_command(spec.NOP)).word == 0x0000


def test_0x0000_is_a_nop_not_a_write():
    s = spec.As5047()
    frame(s, spec.read_command(spec.ANGLECOM))
    assert frame(s, 0x0000, raw=77).data == 77          # SimpleFOC's pair
    assert frame(s, spec.read_command(spec.ANGLECOM)).data == 0
    assert frame(s, spec.read_command(spec.ANGLECOM), raw=78).data == 78
    assert s.errfl == 0


def test_a_write_answers_the_old_then_the_new_contents():
    s = spec.As5047()
    frame(s, spec.write_command(spec.SETTINGS2))
    assert frame(s, spec.data_frame(0xA5)).data == 0x00
    assert frame(s, spec.read_command(spec.NOP)).data == 0xA5
    assert s.settings2 == 0xA5


def test_errors_set_errfl_and_ef_until_it_is_read():
    s = spec.As5047()
    frame(s, spec.read_command(spec.SETTINGS1) ^ 1)        # bad parity
    frame(s, spec.read_command(spec.SETTINGS1), clocks=15)
    frame(s, spec.read_command(0x0005))                     # no such register
    frame(s, spec.write_command(spec.MAG))                  # read-only
    a = frame(s, spec.read_command(spec.ERRFL), raw=42)
    assert a.error and a.parity_ok and a.data == 42   # still ANGLECOM: error frames change nothing
    e = frame(s, spec.read_command(spec.NOP))
    assert e.error and e.data == spec.PARERR | spec.FRERR | spec.INVCOMM
    assert not frame(s, spec.read_command(spec.NOP)).error


def test_zero_and_direction():
    s = spec.As5047()
    for address, value in ((spec.ZPOSM, 0x1ABC >> 6), (spec.ZPOSL, 0x1ABC & 0x3F)):
        frame(s, spec.write_command(address))
        frame(s, spec.data_frame(value))
    assert s.zero == 0x1ABC and s.angle(0x1ABC) == 0 and s.angle(0x1ABD) == 1
    frame(s, spec.write_command(spec.SETTINGS1))
    frame(s, spec.data_frame(0x01 | spec.DIR))
    assert s.angle(0x1ABC) == (-1 - 0x1ABC - 0x1ABC) % (1 << 14)
    assert (s.angle(100) - s.angle(101)) % (1 << 14) == 1


def test_while_not_valid_angles_carry_ef_and_the_last_valid_angle():
    s = spec.As5047()
    assert frame(s, spec.read_command(spec.ANGLECOM), raw=5, valid=False).word == spec.with_parity(1 << 14)
    frame(s, spec.read_command(spec.ANGLECOM), raw=300)     # valid: 300 is held
    a = frame(s, spec.read_command(spec.DIAAGC), raw=9, valid=False)
    assert (a.error, a.data) == (True, 300)
    d = frame(s, spec.read_command(spec.NOP), raw=9, valid=False)
    assert not d.error and d.data & spec.COF and d.data & spec.LF
