# SPDX-License-Identifier: Apache-2.0
"""prenc_cal_lookup against prenc.cal.lookup.CalLookup, clock by clock, and its table
file's checks.

The quarter asked for walks both ways (a quarter per clock at times), jumps, and
stands; words are written near it and far from it; resets come. Expected values come
from the model, whose memory is the table file read by prenc.cal.table (the file
format's reader, not the RTL): `ok` always; with it, the pair and its quarter, and
the pair must be the table's words of that quarter (the table as written so far). A
quarter held for READ_DELAY + 2 clocks, with no write or reset in them, must have its
pair. A second run starts from an all-zero table (CAL_FILE "") and fills it by writes.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
import cocotb

from common import clock_and_check, rng, start_clock_and_reset
from prenc.cal.lookup import READ_DELAY, CalLookup
from prenc.cal.table import Table, read
from runner import SIM_BUILD, SIMULATORS, run
from yosys import synthesize

TOPLEVEL = "prenc_cal_lookup"
N = 6
CLOCKS = 6000


def table_file(n: int = N) -> Path:
    r = np.random.default_rng(6)
    return Table.from_quarters(n, r.uniform(-1.5, 1.5, 4 << n)).write(
        SIM_BUILD / "roms" / f"prenc_cal_lookup_n{n}.hex")


@cocotb.test()
async def matches_the_model(dut):
    r = np.random.default_rng(rng().randrange(1 << 30))
    size = 4 << N
    zero = os.environ.get("PRENC_CAL_ZERO") == "1"
    words = [0] * size if zero else [int(w) for w in read(table_file(), n=N).c]
    model = CalLookup(N, words)
    names = ("quarter", "write", "address", "data", "rst")
    await start_clock_and_reset(dut, 2, {k: 0 for k in names})
    model.clock(0, rst=1)
    q, ok_clocks, held, quiet = int(r.integers(0, size)), 0, 0, 0
    for c in range(CLOCKS):
        roll = r.random()
        before = q
        if roll < 0.02:
            q = int(r.integers(0, size))                 # a jump
        elif roll < 0.45:
            q = (q + int(r.choice([-1, 1]))) % size      # a quarter per clock
        held = held + 1 if q == before else 1
        write = int(r.random() < (0.3 if zero and c < 3000 else 0.03))
        address = (q + int(r.integers(-2, 4))) % size if r.random() < 0.5 else int(r.integers(0, size))
        data = int(r.integers(-(1 << 15), 1 << 15))
        rst = int(r.random() < 0.002)
        quiet = 0 if (write or rst) else quiet + 1
        now = {"quarter": q, "write": write, "address": address, "data": data & 0xFFFF,
               "rst": rst}
        model.clock(q, write, address, data, rst)
        expected = {"ok": model.ok}
        if model.ok:
            expected.update(c_lo=model.lo & 0xFFFF, c_hi=model.hi & 0xFFFF,
                            pair_quarter=model.quarter)
            # The definition: the table's words of that quarter, as last written.
            assert (model.lo, model.hi) == (words[model.quarter], words[(model.quarter + 1) % size])
            ok_clocks += 1
        elif held >= READ_DELAY + 2 and quiet >= READ_DELAY + 2:
            raise AssertionError(f"clock {c}: quarter {q} held {held} clocks has no pair")
        if model.ok and held >= READ_DELAY + 2 and quiet >= READ_DELAY + 2:
            assert model.quarter == q, c
        if write:
            words[address] = ((data + (1 << 15)) % (1 << 16)) - (1 << 15)
        await clock_and_check(dut, now, expected, lambda: f"clock {c}")
    assert ok_clocks > CLOCKS // 2


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("source", ["file", "zero"])
def test_prenc_cal_lookup(simulator, source):
    parameters = {"N": N} | ({"CAL_FILE": table_file()} if source == "file" else {})
    run(__file__, TOPLEVEL, simulator, parameters=parameters, testcase="matches_the_model",
        extra_env={"PRENC_CAL_ZERO": "1" if source == "zero" else "0"})


BAD = SIM_BUILD / "roms" / "bad"


def bad_table(case: str) -> Path:
    """A table file for N = 6 that must be rejected (fixed paths: builds are reused)."""
    BAD.mkdir(parents=True, exist_ok=True)
    path = BAD / f"cal_{case}.hex"
    text = Table.zero(N).text().splitlines()
    if case == "missing":
        path.unlink(missing_ok=True)
    elif case == "short":
        path.write_text("\n".join(text[:-1]) + "\n")       # 255 of 256 words
    return path


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("case, message", [("missing", "cannot be opened"),
                                           ("short", "1 of 256 words missing")])
def test_bad_table_file_stops_the_simulation(simulator, case, message, capfd):
    with pytest.raises(SystemExit):
        run(__file__, TOPLEVEL, simulator, parameters={"N": N, "CAL_FILE": bad_table(case)},
            testcase="matches_the_model")
    text = "".join(capfd.readouterr())
    assert f'CAL_FILE "{bad_table(case)}"' in text and message in text


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_illegal_n_stops_elaboration(simulator, capfd):
    with pytest.raises((SystemExit, RuntimeError)):
        run(__file__, TOPLEVEL, simulator, parameters={"N": 17}, testcase="matches_the_model")
    assert "prenc_cal_lookup_parameter_N_out_of_range_2_to_16" in "".join(capfd.readouterr())


@pytest.mark.synth
@pytest.mark.parametrize("family, cell, bits", [("ice40", "SB_RAM40_4K", 4096),
                                                ("ecp5", "DP16KD", 16384)])
def test_the_table_is_block_ram(family, cell, bits):
    n = 10
    result = synthesize(TOPLEVEL, family, {"N": n, "CAL_FILE": table_file(n)})
    assert result.cells.get(cell, 0) == (16 << (n + 2)) // bits, result.cells
    assert result.latches == 0
    assert result.warnings == []


@pytest.mark.synth
def test_a_missing_table_fails_synthesis():
    with pytest.raises(RuntimeError, match="Can not open file"):
        synthesize(TOPLEVEL, "ice40", {"N": N, "CAL_FILE": bad_table("missing")})
