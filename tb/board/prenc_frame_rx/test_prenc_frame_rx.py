# SPDX-License-Identifier: Apache-2.0
"""prenc_frame_rx fuzzed: random and corrupted byte streams, against prenc.board.protocol.FrameParser.

The stream mixes good frames, frames with errors the CRC-16 is guaranteed to catch
(1 to 3 flipped bits, a burst of up to 16 bits; LEN is left alone, so that the frame
keeps its length and the CRC its place), frames cut short, frames with LEN
over the limit, framing errors inside a frame, and runs of random bytes; bytes
arrive with random gaps, and some gaps are longer than the parser's timeout.

Expected: the model (the host's parser, given `idle()` wherever the gap reaches the
timeout) accepts and counts exactly what the RTL does; no corrupted frame of the
guaranteed kinds that starts in the hunt state is accepted (one that starts while a cut
frame is still open may complete that frame: its start byte can be the missing CRC
byte, for the model as for the RTL); every good frame that starts in the hunt state is
accepted; and the RTL always ends back in the hunt state (no hang).
"""

from __future__ import annotations

import random

import cocotb
import pytest
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge

from common import rng, start_clock_and_reset
from prenc.board import protocol
from prenc.board.protocol import FrameParser
from runner import SIMULATORS, run

TOPLEVEL = "prenc_frame_rx"


def good_frame(r: random.Random, max_len: int) -> bytes:
    return protocol.encode(r.randrange(256), bytes(r.randrange(256) for _ in range(r.randrange(max_len + 1))))


def corrupt(frame: bytes, r: random.Random) -> bytes:
    """An error CRC-16/CCITT is guaranteed to detect, in TYPE, the payload or the CRC
    (not LEN: another length would move the CRC's place, and a misframed frame passes
    its CRC by chance, once in 2^16): 1 to 3 flipped bits (its distance is 4 at these
    lengths), or a burst of up to 16 bits after LEN."""
    data = bytearray(frame)
    positions = [b * 8 + k for b in [1, *range(3, len(data))] for k in range(8)]  # TYPE, payload, CRC
    if r.random() < 0.5:
        flipped = r.sample(positions, r.randrange(1, 4))
    else:
        after_len = (len(data) - 3) * 8  # payload and CRC, 16 bits at least
        length = r.randrange(1, min(16, after_len) + 1)
        start = 3 * 8 + r.randrange(after_len - length + 1)
        pattern = r.randrange(1 << length) | 1 | (1 << (length - 1))
        flipped = [start + k for k in range(length) if pattern >> k & 1]
    for pos in flipped:
        data[pos // 8] ^= 0x80 >> (pos % 8)
    return bytes(data)


def stream(r: random.Random, max_len: int, items: int):
    """[(bytes, kind)] with kind in good, corrupt, cut, long, junk, break."""
    out = []
    for _ in range(items):
        what = r.choices(["good", "corrupt", "cut", "long", "junk", "break"], [5, 4, 1, 1, 1, 1])[0]
        frame = good_frame(r, max_len)
        if what == "corrupt":
            frame = corrupt(frame, r)
        elif what == "cut":
            frame = frame[: r.randrange(1, len(frame))]
        elif what == "long":
            frame = protocol.encode(1, bytes(max_len + 1 + r.randrange(4)))
        elif what == "junk":
            frame = bytes(r.randrange(256) for _ in range(r.randrange(1, 40)))
        out.append((frame, what))
    return out


@cocotb.test()
async def fuzzed_streams_match_the_model_and_reject_every_corrupted_frame(dut):
    r = rng()
    max_len, timeout = int(dut.MAX_LEN.value), int(dut.TIMEOUT.value)
    dut.byte_valid.value = 0
    dut.byte_error.value = 0
    dut.byte_data.value = 0
    await start_clock_and_reset(dut, 4)
    model = FrameParser(max_len=max_len)
    model_frames = []
    accepted, errors = [], 0
    sent_good = set()
    counts = {}

    async def clock(valid: int = 0, data: int = 0, error: int = 0) -> None:
        nonlocal errors
        dut.byte_valid.value = valid
        dut.byte_data.value = data
        dut.byte_error.value = error
        await RisingEdge(dut.clk)
        await ReadOnly()
        if int(dut.frame_valid.value):
            n = int(dut.frame_len.value)
            payload = int(dut.frame_payload.value).to_bytes(max_len, "little")[:n]
            accepted.append(protocol.Frame(int(dut.frame_type.value), payload))
        errors += int(dut.frame_error.value)
        await FallingEdge(dut.clk)

    for frame, what in stream(r, max_len, 400):
        counts[what] = counts.get(what, 0) + 1
        hunting = not model.in_frame  # the item starts in the hunt state
        if what == "good" and hunting:
            sent_good.add(protocol.Frame(frame[1], frame[3:-2]))
        for i, byte in enumerate(frame):
            if what == "break" and i == 2:
                await clock(error=1)
                model.byte_error()
                continue
            got = model.feed(bytes([byte]))
            assert not (got and what == "corrupt" and hunting), "a corruption the CRC must catch passed it"
            model_frames.extend(got)
            await clock(valid=1, data=byte)
            gap = r.choice([0, 0, 0, 1, 3, timeout // 3])
            for _ in range(gap):
                await clock()
        # between items: sometimes a gap past the timeout
        if r.random() < 0.6:
            for _ in range(timeout + 2):
                await clock()
            model.idle()
    for _ in range(timeout + 2):
        await clock()
    model.idle()
    assert errors == model.errors, f"RTL rejected {errors} frames, the model {model.errors}"
    assert len(accepted) == model.frames
    assert accepted == model_frames, "the RTL and the model accepted different frames"
    assert sent_good <= set(accepted), "a good frame sent in the hunt state was not accepted"
    dut._log.info("items %s: %d frames accepted, %d rejected", counts, len(accepted), errors)


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_prenc_frame_rx(simulator):
    run(__file__, TOPLEVEL, simulator, parameters={"MAX_LEN": 5, "TIMEOUT": 40})
