# SPDX-License-Identifier: Apache-2.0
"""Benchmark for `make bench`: the link's achieved update rate, streaming back to back.

For each kind, asks for a stream with a 1 us period (shorter than any frame) and
measures the board-time spacing of 40 answers; writes {kind: answers per second,
frame bytes} as JSON to $BENCH_OUT.
"""

from __future__ import annotations

import json
import os

import cocotb

from prenc.board import protocol
from prenc.board.protocol import Kind
from test_prenc_host_link import setup


@cocotb.test()
async def back_to_back_rate(dut):
    link, r = await setup(dut)
    result = {}
    for kind in Kind:
        link.drive(r)
        await link.source.send(protocol.stream_request(kind, 1))
        stamps = []
        while len(stamps) < 40:
            answer = await link.answer()
            if answer.kind == kind and answer.streaming:
                stamps.append(answer.time_us)
        spacing_us = (stamps[-1] - stamps[4]) / (len(stamps) - 5)
        result[kind.name] = {"per_second": 1e6 / spacing_us,
                             "frame_bytes": 5 + protocol.HEADER_LEN + protocol.DATA_LEN[kind]}
        await link.source.send(protocol.stream_request(kind, 0))
        while True:
            answer = await link.answer()
            if answer.kind == Kind.STATUS and not answer.streaming:
                break
    with open(os.environ["BENCH_OUT"], "w") as f:
        json.dump(result, f)
