# SPDX-License-Identifier: Apache-2.0
"""prenc.board.protocol: CRC, frames, the parser fuzzed with random and corrupted streams."""

from __future__ import annotations

import random

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from prenc.board import protocol
from prenc.board.protocol import Answer, FrameParser, Kind


def test_crc_is_crc16_ccitt_false():
    assert protocol.crc16(b"123456789") == 0x29B1  # the catalogued check value


def test_frame_layout():
    assert protocol.read_request(Kind.TRACKS).hex() == "a50101" + "03" + f"{protocol.crc16(bytes([1, 1, 3])):04x}"
    assert protocol.stream_request(Kind.ABS, 500)[3:8] == bytes([0, 0, 0, 1, 0xF4])


@pytest.mark.parametrize("kind", list(Kind))
def test_answers_round_trip(kind):
    values = {Kind.ABS: {"position": 1023}, Kind.HYBRID: {"position": 4095}, Kind.INCREMENTAL: {"count": -123456},
              Kind.TRACKS: {"track1": 5, "track2": 6, "track1_valid": True, "track2_valid": False},
              Kind.STATUS: {"version": 1, "bits": 10, "track1_errors": 1, "track2_errors": 2, "sync_errors": 3,
                            "link_errors": 65535},
              Kind.FINE: {"fine_position": 0x3FFFF, "fine_bits": 6, "velocity": -641, "velocity_valid": True,
                          "interpolated": False, "clk_mhz": 30},
              Kind.EDGES: {"lost": False, "cw": True, "pos_valid": True, "run": 2, "edge": 4095,
                           "intervals": [65535, 1]},
              Kind.HEALTH: {"position": 1000, "track1_errors": 17, "track2_errors": 0, "sync_errors": 65535,
                            "warnings": 5}}[kind]
    answer = Answer(kind, True, 2, 1, False, 7, 123456789, values, warning=kind == Kind.HEALTH)
    frames = FrameParser().feed(protocol.encode_answer(answer))
    assert [protocol.decode(f) for f in frames] == [answer]


def test_write_cal_request_layout():
    frame = protocol.write_cal_request(0x012345, -2)
    assert frame[1:3] == bytes([0x04, 5]) and frame[3:8] == bytes([0x01, 0x23, 0x45, 0xFF, 0xFE])
    with pytest.raises(ValueError):
        protocol.write_cal_request(1 << 24, 0)


def test_velocity_in_rpm():
    # 600 rpm at N = 10, 30 MHz: 600 / 60 x 4096 quarters per second, over 30e6 clocks, x 2^32.
    word = round(600 / 60 * 4096 / 30e6 * 2**32)
    assert protocol.velocity_rpm(word, 30, 10) == pytest.approx(600, rel=1e-6)
    assert protocol.velocity_rpm(-word, 30, 10) == pytest.approx(-600, rel=1e-6)


@settings(max_examples=300, deadline=None)
@given(st.binary(max_size=400))
def test_random_bytes_never_raise_and_leave_the_parser_usable(junk):
    parser = FrameParser()
    parser.feed(junk)
    parser.idle()
    good = protocol.encode_answer(Answer(Kind.ABS, True, 1, 1, False, 0, 0, {"position": 3}))
    assert parser.feed(good) == [protocol.Frame(0x80, good[3:-2])]


@settings(max_examples=500, deadline=None)
@given(st.integers(0, 2**32 - 1), st.data())
def test_every_guaranteed_corruption_is_rejected_and_counted(seed, data):
    r = random.Random(seed)
    frame = protocol.encode(r.randrange(256), bytes(r.randrange(256) for _ in range(r.randrange(17))))
    bits = bytearray(frame)
    n = (len(frame) - 1) * 8
    flips = data.draw(st.lists(st.integers(0, n - 1), min_size=1, max_size=3, unique=True))
    if data.draw(st.booleans()):  # a burst of up to 16 bits instead
        start = data.draw(st.integers(0, n - 1))
        flips = sorted({start, min(start + data.draw(st.integers(0, 15)), n - 1)})
    for pos in flips:
        bits[1 + pos // 8] ^= 0x80 >> (pos % 8)
    parser = FrameParser()
    assert parser.feed(bytes(bits)) == []
    parser.idle()
    assert parser.errors >= 1 and parser.frames == 0  # an A5 inside the rest may start another


def test_a_corrupted_length_resynchronises_after_the_timeout():
    parser = FrameParser()
    bad = bytearray(protocol.encode(0x80, bytes(8)))
    bad[2] = 16  # claims more payload than follows: the parser waits
    good = protocol.encode(0x81, bytes(9))
    assert parser.feed(bytes(bad)) == []
    parser.idle()
    assert parser.feed(good) == [protocol.Frame(0x81, bytes(9))]
    assert parser.errors == 1


def test_decode_rejects_layouts_that_are_not_the_protocol():
    with pytest.raises(protocol.ProtocolError):
        protocol.decode(protocol.Frame(0x80, bytes(7)))  # ABS with 1 data byte
    with pytest.raises(protocol.ProtocolError):
        protocol.decode(protocol.Frame(0x90, bytes(8)))  # no such kind


def test_biss_frame_layout_and_the_documented_diagram():
    """prenc.board.biss: the frame's layout (CDS, data, nE, nW, CRC inverted), its decoding,
    and the timing diagram of docs/biss-c.md, which must be the protocol's."""
    from pathlib import Path

    from prenc.board import biss

    bits = biss.frame_bits(0b10, 0b0110, 2, 4, error=True, warning=False)
    assert bits[:9] == [0, 1, 0, 0, 1, 1, 0, 0, 1]  # CDS, turns, position, nE = 0, nW = 1
    assert biss.from_bits(1 - b for b in bits[9:]) == biss.crc6(bits[1:9])
    assert biss.decode(bits, 2, 4) == biss.Reading(2, 6, True, False, True)
    assert biss.clock_pulses(12, 12) == 37
    doc = (Path(__file__).resolve().parents[3] / "docs" / "biss-c.md").read_text()
    assert biss.timing_diagram(1, 0b1011, 2, 4) in doc
    assert "```{wavedrom}\n" + biss.wavedrom(1, 0b1011, 2, 4) + "\n```" in doc
