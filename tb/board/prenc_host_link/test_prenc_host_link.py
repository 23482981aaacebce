# SPDX-License-Identifier: Apache-2.0
"""prenc_host_link: the protocol over the UART pins, at 115200, 1 M and 3 Mbaud.

Requests are sent bit by bit onto `rx` and answers decoded from `tx` with
prenc.board.protocol (the host's own parser and layouts). Expected values: the core
outputs the test drives, the protocol document's layouts, and the time base
(CLK_HZ): every kind of answer, NACKs, corrupted requests counted and the next
good one answered, CLEAR, and streaming at its period and back to back; WRITE_CAL's
word on cal_* (CAL = 1) or its NACK (CAL = 0), and EDGES taking the run it sends.
"""

from __future__ import annotations

import random

import cocotb
import pytest
from cocotb.triggers import ClockCycles, RisingEdge, with_timeout
from cocotb.utils import get_sim_time

from common import PERIOD_NS, rng, start_clock_and_reset
from prenc.board import protocol
from prenc.board.protocol import Answer, FrameParser, Kind, Nack
from runner import run
from uart import UartSink, UartSource

TOPLEVEL = "prenc_host_link"

class Link:
    def __init__(self, dut):
        self.dut = dut
        self.n = int(dut.N.value)
        clk_hz, baud = int(dut.CLK_HZ.value), int(dut.BAUD.value)
        self.bit_clocks = round(clk_hz / baud)
        self.clks_per_us = clk_hz // 1_000_000
        self.source = UartSource(dut.rx, self.bit_clocks)
        self.sink = UartSink(dut.tx, self.bit_clocks)
        self.parser = FrameParser()
        self.frame_clocks = 21 * 10 * self.bit_clocks

    def drive(self, r: random.Random) -> dict:
        n = self.n
        values = {"pos_abs": r.randrange(1 << n), "pos_hyb": r.randrange(1 << (n + 2)), "pos_valid": r.randrange(2),
                  "mode": r.randrange(5), "direction": r.randrange(2), "warnings": r.randrange(8), "incremental": r.randrange(1 << 32),
                  "track1_pos": r.randrange(1 << n), "track1_valid": r.randrange(2),
                  "track2_pos": r.randrange(1 << n), "track2_valid": r.randrange(2),
                  "track1_errors": r.randrange(1 << 16), "track2_errors": r.randrange(1 << 16),
                  "sync_errors": r.randrange(1 << 16), "fine_pos": r.randrange(1 << 32),
                  "velocity": r.randrange(1 << 32), "fine_info": r.randrange(64),
                  "edge_run": r.randrange(4), "edge_valid": r.randrange(2), "edge_cw": r.randrange(2),
                  "edge_first": r.randrange(1 << (n + 2)), "edge_interval0": r.randrange(1 << 16),
                  "edge_interval1": r.randrange(1 << 16), "edge_interval2": r.randrange(1 << 16),
                  "edge_lost": r.randrange(2)}
        for name, value in values.items():
            getattr(self.dut, name).value = value
        return values

    async def answer(self, timeout_clocks: int | None = None) -> Answer | Nack:
        limit = timeout_clocks or 3 * self.frame_clocks
        while True:
            _, byte = await with_timeout(self.sink.queue.get(), limit * PERIOD_NS, "ns")
            for frame in self.parser.feed(bytes([byte])):
                return protocol.decode(frame)

    async def no_answer(self, clocks: int) -> None:
        await ClockCycles(self.dut.clk, clocks)
        assert self.sink.queue.empty(), "the board answered a request it should have rejected"

    async def ask(self, request: bytes) -> Answer | Nack:
        await self.source.send(request)
        return await self.answer()


def expected_values(kind: Kind, v: dict, n: int, link_errors: int, clk_mhz: int = 0) -> dict:
    if kind == Kind.ABS:
        return {"position": v["pos_abs"]}
    if kind == Kind.HYBRID:
        return {"position": v["pos_hyb"]}
    if kind == Kind.INCREMENTAL:
        c = v["incremental"]
        return {"count": c - (1 << 32) if c >> 31 else c}
    if kind == Kind.TRACKS:
        return {"track1": v["track1_pos"], "track2": v["track2_pos"], "track1_valid": bool(v["track1_valid"]),
                "track2_valid": bool(v["track2_valid"])}
    if kind == Kind.FINE:
        w, info = v["velocity"], v["fine_info"]
        return {"fine_position": v["fine_pos"], "fine_bits": info & 15, "velocity": w - (1 << 32) if w >> 31 else w,
                "velocity_valid": bool(info & 16), "interpolated": bool(info & 32), "clk_mhz": clk_mhz}
    if kind == Kind.HEALTH:
        return {"position": v["pos_abs"], "track1_errors": v["track1_errors"], "track2_errors": v["track2_errors"],
                "sync_errors": v["sync_errors"], "warnings": v["warnings"]}
    if kind == Kind.EDGES:
        intervals = [v["edge_interval0"], v["edge_interval1"], v["edge_interval2"]][:v["edge_run"]]
        return {"lost": bool(v["edge_lost"]), "cw": bool(v["edge_cw"]), "pos_valid": bool(v["edge_valid"]),
                "run": v["edge_run"], "edge": v["edge_first"], "intervals": intervals}
    return {"version": protocol.VERSION, "bits": n, "track1_errors": v["track1_errors"],
            "track2_errors": v["track2_errors"], "sync_errors": v["sync_errors"], "link_errors": link_errors}


def check_flags(answer: Answer, v: dict, streaming: bool) -> None:
    assert answer.valid == bool(v["pos_valid"])
    assert answer.mode == v["mode"]
    assert answer.direction == v["direction"]
    assert answer.warning == bool(v["warnings"])
    assert answer.streaming == streaming


async def setup(dut) -> tuple[Link, random.Random]:
    r = rng()
    link = Link(dut)
    link.drive(r)
    await start_clock_and_reset(dut, 4)
    return link, r


@cocotb.test()
async def every_kind_on_demand(dut):
    link, r = await setup(dut)
    seq = 0
    for _ in range(2):
        for kind in Kind:
            v = link.drive(r)
            answer = await link.ask(protocol.read_request(kind))
            assert isinstance(answer, Answer) and answer.kind == kind, answer
            assert answer.values == expected_values(kind, v, link.n, 0, link.clks_per_us), (kind, answer.values, v)
            check_flags(answer, v, streaming=False)
            assert answer.seq == seq
            seq += 1
            now_us = get_sim_time("ns") / PERIOD_NS / link.clks_per_us
            assert now_us - 2 * link.frame_clocks / link.clks_per_us <= answer.time_us <= now_us


@cocotb.test()
async def edges_take_the_run_they_send(dut):
    """edge_take is high for one clock, on the clock the EDGES answer starts (its values
    are that clock's), and for no other answer."""
    link, r = await setup(dut)
    takes = []

    async def count_takes():
        while True:
            await RisingEdge(dut.clk)
            if int(dut.edge_take.value):
                takes.append(get_sim_time("ns"))
    watcher = cocotb.start_soon(count_takes())
    for kind in (Kind.EDGES, Kind.FINE, Kind.EDGES, Kind.STATUS):
        v = link.drive(r)
        answer = await link.ask(protocol.read_request(kind))
        assert answer.kind == kind and answer.values == expected_values(kind, v, link.n, 0, link.clks_per_us)
    watcher.cancel()
    assert len(takes) == 2, takes


@cocotb.test()
async def write_cal_writes_a_word_or_is_refused(dut):
    link, r = await setup(dut)
    cal = int(dut.CAL.value)
    size = 4 << link.n
    writes = []

    async def watch():
        while True:
            await RisingEdge(dut.clk)
            if int(dut.cal_write.value):
                writes.append((int(dut.cal_address.value), int(dut.cal_data.value)))
    watcher = cocotb.start_soon(watch())
    sent = [(r.randrange(size), r.randrange(-(1 << 15), 1 << 15)) for _ in range(3)]
    for address, word in sent:
        answer = await link.ask(protocol.write_cal_request(address, word))
        if cal:
            assert isinstance(answer, Answer) and answer.kind == Kind.STATUS, answer
        else:
            assert isinstance(answer, Nack) and (answer.code, answer.request) == (4, 4), answer
    answer = await link.ask(protocol.write_cal_request(size, 0))       # past the table
    assert isinstance(answer, Nack) and answer.code == (5 if cal else 4), answer
    answer = await link.ask(protocol.encode(protocol.Request.WRITE_CAL, b"\x00\x00\x01"))   # too short
    assert isinstance(answer, Nack) and answer.code == 2, answer
    watcher.cancel()
    assert writes == ([(a, w & 0xFFFF) for a, w in sent] if cal else []), writes


@cocotb.test()
async def bad_requests_get_nacks(dut):
    link, _ = await setup(dut)
    cases = [(protocol.encode(0x42), 1, 0x42),                               # unknown type
             (protocol.encode(protocol.Request.READ, b"\x00\x00"), 2, 1),     # READ with 2 bytes
             (protocol.encode(protocol.Request.READ, b"\x08"), 3, 1),         # unknown kind
             (protocol.encode(protocol.Request.STREAM, b"\x00"), 2, 2),       # STREAM too short
             (protocol.encode(protocol.Request.CLEAR, b"\x00"), 2, 3)]        # CLEAR with data
    for request, code, of in cases:
        answer = await link.ask(request)
        assert isinstance(answer, Nack), answer
        assert (answer.code, answer.request) == (code, of)


@cocotb.test()
async def corrupted_requests_are_counted_and_the_next_is_answered(dut):
    link, r = await setup(dut)
    good = protocol.read_request(Kind.ABS)
    model = FrameParser(max_len=protocol.REQUEST_MAX_LEN)  # what the board's parser must count
    for trial in range(12):
        bad = bytearray(protocol.read_request(Kind.TRACKS))
        how = trial % 4
        if how == 0:    # one bit flipped after the start byte
            i = r.randrange(1, len(bad))
            bad[i] ^= 1 << r.randrange(8)
        elif how == 1:  # a burst of up to 16 bits
            i = r.randrange(1, len(bad) - 1)
            burst = r.randrange(1, 1 << 16) | 1
            bad[i] ^= burst & 0xFF
            bad[i + 1] ^= burst >> 8
        elif how == 2:  # cut short: the board must time out
            bad = bad[: r.randrange(2, len(bad))]
        else:           # LEN over the parser's limit
            bad = bytearray(protocol.encode(protocol.Request.READ, bytes(6)))
        assert not model.feed(bytes(bad)), "a corruption the CRC must catch passed it"
        model.idle()
        await link.source.send(bytes(bad))
        await link.no_answer(30 * link.bit_clocks)  # longer than the parser's timeout
        v = link.drive(r)
        answer = await link.ask(good)
        assert isinstance(answer, Answer) and answer.values == {"position": v["pos_abs"]}
    status = await link.ask(protocol.read_request(Kind.STATUS))
    rejected = model.errors
    assert status.values["link_errors"] == rejected >= 10
    await link.source.send(good[:2])
    await link.source.send(good[2:3], break_stop=True)  # a framing error inside a frame
    await link.no_answer(30 * link.bit_clocks)
    status = await link.ask(protocol.read_request(Kind.STATUS))
    assert status.values["link_errors"] == rejected + 1


@cocotb.test()
async def clear_resets_every_counter(dut):
    link, r = await setup(dut)
    await link.source.send(protocol.read_request(Kind.ABS)[:-1])  # one rejected frame
    await link.no_answer(30 * link.bit_clocks)
    pulses = []

    async def watch():
        while True:
            await RisingEdge(dut.clk)
            if int(dut.clear_errors.value):
                pulses.append(get_sim_time("ns"))
                # the core clears on this edge: show it cleared counters from now on
                for name in ("track1_errors", "track2_errors", "sync_errors"):
                    getattr(dut, name).value = 0

    task = cocotb.start_soon(watch())
    answer = await link.ask(protocol.clear_request())
    task.cancel()
    assert len(pulses) == 1
    assert answer.kind == Kind.STATUS
    assert answer.values["link_errors"] == 0
    assert answer.values["track1_errors"] == answer.values["track2_errors"] == answer.values["sync_errors"] == 0


@cocotb.test()
async def streaming_at_a_period_and_back_to_back(dut):
    link, r = await setup(dut)
    frame_us = (3 + protocol.HEADER_LEN + 2 + 2) * 10 * link.bit_clocks / link.clks_per_us
    period = max(int(3 * frame_us), 20)
    v = link.drive(r)
    first = await link.ask(protocol.stream_request(Kind.ABS, period))
    assert first.streaming and first.values == {"position": v["pos_abs"]}
    times = [first.time_us]
    for _ in range(8):
        answer = await link.answer(timeout_clocks=4 * period * link.clks_per_us)
        assert answer.kind == Kind.ABS and answer.streaming
        times.append(answer.time_us)
    gaps = {b - a for a, b in zip(times[1:], times[2:])}
    assert gaps <= {period, period + 1}, f"stream gaps {sorted(gaps)} us, period {period} us"
    # A period shorter than a frame: answers back to back at the link's own rate.
    await link.source.send(protocol.stream_request(Kind.ABS, 1))
    stamps = []
    for _ in range(12):
        answer = await link.answer()
        if answer.kind == Kind.ABS:
            stamps.append(answer.time_us)
    spacing = (stamps[-1] - stamps[2]) / (len(stamps) - 3)
    assert frame_us <= spacing <= frame_us + 2, (spacing, frame_us)
    dut._log.info("back-to-back ABS stream: one answer per %.2f us = %.0f answers/s (frame %.2f us)",
                  spacing, 1e6 / spacing, frame_us)
    stop = await link.ask(protocol.stream_request(Kind.ABS, 0))
    while stop.kind != Kind.STATUS:
        stop = await link.answer()
    assert not stop.streaming
    await link.no_answer(3 * period * link.clks_per_us)


RATES = [(48_000_000, 115_200), (48_000_000, 1_000_000), (48_000_000, 3_000_000), (24_000_000, 3_000_000)]


@pytest.mark.parametrize("clk_hz,baud", RATES, ids=[f"{c // 10**6}MHz-{b}baud" for c, b in RATES])
def test_prenc_host_link(clk_hz, baud):
    run(__file__, TOPLEVEL, "verilator", parameters={"N": 10, "CLK_HZ": clk_hz, "BAUD": baud})


def test_prenc_host_link_icarus():
    run(__file__, TOPLEVEL, "icarus", parameters={"N": 10, "CLK_HZ": 24_000_000, "BAUD": 3_000_000})


@pytest.mark.parametrize("simulator", ["verilator", "icarus"])
def test_prenc_host_link_with_a_calibration_table(simulator):
    run(__file__, TOPLEVEL, simulator, parameters={"N": 10, "CLK_HZ": 24_000_000, "BAUD": 3_000_000, "CAL": 1},
        testcase="write_cal_writes_a_word_or_is_refused")
