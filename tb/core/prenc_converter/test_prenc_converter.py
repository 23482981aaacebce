# SPDX-License-Identifier: Apache-2.0
"""prenc_converter: every code word converts to the slot the disc code gives it.

The expected values come from the Python model (`prenc.core.converter.Converter`,
whose table is `prenc.codes.debruijn.Code.positions`), never from the RTL. The ROM file
is written by the same code as `prenc rom`.
"""

from __future__ import annotations

from pathlib import Path

import cocotb
import pytest
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge

from common import clock_and_check, rng, start_clock_and_reset
from prenc.core.converter import CONVERTER_LATENCY, Converter
from prenc.codes.debruijn import Code
from runner import SIM_BUILD, SIMULATORS, rom_file, run
from yosys import synthesize

TOPLEVEL = "prenc_converter"


class TB:
    """The converter with its model beside it."""

    def __init__(self, dut):
        self.dut = dut
        self.n = len(dut.word)
        self.code = Code(self.n)
        self.model = Converter(self.code)

    async def reset(self) -> None:
        await start_clock_and_reset(self.dut, 2, {"word_valid": 0, "word": 0})
        self.model.reset()

    async def step(self, word_valid: int, word: int) -> None:
        """Drive one clock of inputs and check the outputs against the model."""
        expected = self.model.clock(word_valid, word)
        check = {"pos_valid": expected.pos_valid}
        if expected.pos is not None:
            check["pos"] = expected.pos
        await clock_and_check(self.dut, {"word_valid": word_valid, "word": word}, check,
                              lambda: f"word {word:#x}")


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
    r = rng()
    words = list(range(1 << tb.n))
    r.shuffle(words)
    for word in words:
        while r.random() < 0.25:
            await tb.step(0, r.randrange(1 << tb.n))
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


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("n", [4, 6, 10, 12])
def test_prenc_converter(simulator, n):
    run(__file__, TOPLEVEL, simulator, parameters={"N": n, "ROM_FILE": rom_file(n)})


BAD_ROMS = SIM_BUILD / "roms" / "bad"


def bad_rom(case: str) -> Path:
    """A ROM file for N = 6 that must be rejected (fixed paths: builds are reused)."""
    BAD_ROMS.mkdir(parents=True, exist_ok=True)
    path = BAD_ROMS / f"{case}.hex"
    good = [f"{p:02x}" for p in Code(6).positions.tolist()]
    if case == "missing":
        path.unlink(missing_ok=True)
    elif case == "short":
        path.write_text("\n".join(good[:-1]) + "\n")  # 63 of 64 words
    elif case == "wide":
        path.write_text("\n".join(good[:-1] + ["7f"]) + "\n")  # a 7-bit word in a 6-bit ROM
    return path


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize(
    "case, message",
    [("missing", "cannot be opened"), ("short", "1 of 64 words missing"), ("wide", "1 of 64 words missing")],
)
def test_bad_rom_file_stops_the_simulation(simulator, case, message, capfd):
    with pytest.raises(SystemExit):
        run(__file__, TOPLEVEL, simulator, parameters={"N": 6, "ROM_FILE": bad_rom(case)},
            testcase="every_word_in_order")
    out = capfd.readouterr()
    text = out.out + out.err
    assert f'ERROR: {TOPLEVEL}.u_rom_check: ROM_FILE "{bad_rom(case)}"' in text
    assert message in text


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("n", [1, 25])
def test_illegal_n_stops_elaboration(simulator, n, capfd):
    with pytest.raises((SystemExit, RuntimeError)):  # a failed build raises RuntimeError
        run(__file__, TOPLEVEL, simulator, parameters={"N": n, "ROM_FILE": rom_file(4)})
    out = capfd.readouterr()
    assert "prenc_converter_parameter_N_out_of_range_2_to_24" in out.out + out.err


# Block RAM bits per primitive: iCE40 SB_RAM40_4K 4 kbit, ECP5 DP16KD 18 kbit (16 kbit at x16).
BLOCK_RAM = {"ice40": ("SB_RAM40_4K", 4096), "ecp5": ("DP16KD", 16384)}


@pytest.mark.synth
@pytest.mark.parametrize("family", sorted(BLOCK_RAM))
def test_rom_maps_to_block_ram(family):
    n = 10
    result = synthesize(TOPLEVEL, family, {"N": n, "ROM_FILE": rom_file(n)})
    cell, bits = BLOCK_RAM[family]
    assert result.cells.get(cell, 0) >= -(-(n << n) // bits), result.cells
    assert not any("LUT" in c for c in result.cells), f"ROM spilled into logic: {result.cells}"
    assert result.latches == 0
    assert result.warnings == []


@pytest.mark.synth
def test_missing_rom_file_fails_synthesis():
    with pytest.raises(RuntimeError, match="Can not open file"):
        synthesize(TOPLEVEL, "ice40", {"N": 6, "ROM_FILE": bad_rom("missing")})
