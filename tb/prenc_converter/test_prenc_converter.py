"""prenc_converter: every code word converts to the slot the disc code gives it.

The expected values come from the Python model (`prenc.converter.Converter`,
whose table is `prenc.debruijn.Code.positions`), never from the RTL. The ROM file
is written by the same code as `prenc rom`.
"""

from __future__ import annotations

import os
import random
from pathlib import Path

import cocotb
import pytest
from cocotb.clock import Clock
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge

from prenc.converter import CONVERTER_LATENCY, Converter
from prenc.debruijn import Code
from prenc.rom import write_rom
from runner import SIM_BUILD, SIMULATORS, run

TOPLEVEL = "prenc_converter"


class TB:
    """Clock, reset and the word driver of a prenc_converter."""

    def __init__(self, dut):
        self.dut = dut
        self.n = len(dut.word)
        self.code = Code(self.n)
        self.model = Converter(self.code)
        dut.word_valid.value = 0
        dut.word.value = 0
        dut.rst.value = 1
        cocotb.start_soon(Clock(dut.clk, 10, unit="ns").start())

    async def reset(self) -> None:
        self.dut.rst.value = 1
        for _ in range(2):
            await RisingEdge(self.dut.clk)
        await FallingEdge(self.dut.clk)
        self.dut.rst.value = 0
        self.model.reset()

    async def step(self, word_valid: int, word: int) -> None:
        """Drive one clock of inputs and check the outputs against the model."""
        self.dut.word_valid.value = word_valid
        self.dut.word.value = word
        await RisingEdge(self.dut.clk)
        await ReadOnly()
        expected = self.model.clock(word_valid, word)
        got_valid = int(self.dut.pos_valid.value)
        assert got_valid == expected.pos_valid, f"pos_valid {got_valid}, model {expected.pos_valid}"
        if expected.pos is not None:
            got = self.dut.pos.value.to_unsigned()
            assert got == expected.pos, (
                f"word {word:#x}: pos {got}, expected {expected.pos} (valid={got_valid})"
            )
        await FallingEdge(self.dut.clk)


@cocotb.test()
async def every_word_in_order(dut):
    """Back-to-back words 0 .. 2^N-1, one per clock: each gives its slot one clock later."""
    tb = TB(dut)
    await tb.reset()
    for word in range(1 << tb.n):
        await tb.step(1, word)
    await tb.step(0, 0)


@cocotb.test()
async def every_word_shuffled_with_gaps(dut):
    """All words in random order with random idle clocks; pos holds while idle."""
    tb = TB(dut)
    await tb.reset()
    rng = random.Random(int(os.environ.get("COCOTB_RANDOM_SEED", "1")))
    words = list(range(1 << tb.n))
    rng.shuffle(words)
    for word in words:
        while rng.random() < 0.25:
            await tb.step(0, rng.randrange(1 << tb.n))
        await tb.step(1, word)
    await tb.step(0, 0)


@cocotb.test()
async def latency_and_reset(dut):
    """Latency is CONVERTER_LATENCY clocks; reset drops pos_valid at once."""
    tb = TB(dut)
    await tb.reset()
    word = tb.code.window(3)
    dut.word_valid.value = 1
    dut.word.value = word
    clocks = 0
    while True:
        await RisingEdge(dut.clk)
        clocks += 1
        await ReadOnly()
        if int(dut.pos_valid.value):
            break
        assert clocks < 8, "pos_valid never rose"
    assert clocks == CONVERTER_LATENCY
    assert dut.pos.value.to_unsigned() == 3
    await FallingEdge(dut.clk)
    dut.rst.value = 1
    await RisingEdge(dut.clk)
    await ReadOnly()
    assert int(dut.pos_valid.value) == 0, "reset with word_valid high must clear pos_valid"


# -- pytest entry points ---------------------------------------------------------


def rom_for(n: int, fmt: str = "hex") -> Path:
    path = SIM_BUILD / "roms" / f"prenc_rom_n{n}.{fmt}"
    path.parent.mkdir(parents=True, exist_ok=True)
    write_rom(path, n, None, fmt)
    return path


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("n", [4, 6, 10, 12])
def test_prenc_converter(simulator, n):
    run(__file__, TOPLEVEL, simulator, parameters={"N": n, "ROM_FILE": rom_for(n)})
