# SPDX-License-Identifier: Apache-2.0
"""prenc_matrix_table: the table that builds itself equals the ROM of `prenc matrix rom`.

With TABLE = "generator" the on-chip FKM generator (prenc_matrix_fkm) fills the
RAM after reset; every address is then read back and compared with the model's
table (`prenc.matrix.code.MatrixCode.positions`), and the clocks to `ready` with
`prenc.matrix.code.build_clocks`. With TABLE = "file" the ROM gives the same.
"""

from __future__ import annotations

import os

import cocotb
import pytest
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge

from common import start_clock_and_reset
from prenc.matrix.code import MatrixCode, build_clocks
from runner import SIMULATORS, matrix_rom_file, run

TOPLEVEL = "prenc_matrix_table"


@cocotb.test()
async def every_address(dut):
    n, checksum = int(dut.N.value), bool(int(dut.CHECKSUM.value))
    generator = os.environ["MATRIX_TABLE"] == "generator"  # the TABLE parameter
    code = MatrixCode(n, checksum)
    table = code.positions
    await start_clock_and_reset(dut, 2, {"rd_en": 0, "rd_addr": 0})
    clocks = 0
    limit = build_clocks(n, checksum) + 10
    while True:
        await RisingEdge(dut.clk)
        clocks += 1
        await ReadOnly()
        if int(dut.ready.value) or clocks > limit:
            break
    assert int(dut.ready.value), f"not ready after {clocks} clocks"
    if generator:
        assert clocks == build_clocks(n, checksum), f"ready after {clocks} clocks, model {build_clocks(n, checksum)}"
    else:
        assert clocks == 1
    await FallingEdge(dut.clk)
    dut.rd_en.value = 1
    for address in range(code.length):  # registered read: the data on the next edge
        dut.rd_addr.value = address
        await RisingEdge(dut.clk)
        await ReadOnly()
        got = int(dut.rd_data.value)
        assert got == table[address], f"address {address:#x}: {got}, model {table[address]}"
        await FallingEdge(dut.clk)


@pytest.mark.parametrize("n, checksum", [(2, False), (2, True), (3, False), (3, True), (4, False), (4, True)])
def test_generator_builds_the_rom(n, checksum):
    run(__file__, TOPLEVEL, "verilator", parameters={"N": n, "CHECKSUM": int(checksum), "TABLE": "generator"},
        extra_env={"MATRIX_TABLE": "generator"})


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_file_table(simulator):
    run(__file__, TOPLEVEL, simulator, parameters={"N": 3, "CHECKSUM": 0, "TABLE": "file",
                                                   "TABLE_FILE": matrix_rom_file(3)},
        extra_env={"MATRIX_TABLE": "file"})


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_generator_on_icarus_too(simulator):
    run(__file__, TOPLEVEL, simulator, parameters={"N": 3, "CHECKSUM": 1, "TABLE": "generator"},
        extra_env={"MATRIX_TABLE": "generator"})
