# SPDX-License-Identifier: Apache-2.0
"""prenc_matrix_reader: positions from sensor images equal the model and the truth.

Images come from the Python sensor model (`prenc.matrix.sensor`: blur, noise,
sub-cell offsets along the track, radial misalignment). Each frame's reading is
compared with the integer model (`prenc.matrix.reader.read_frame`, every output)
and with the truth of the disc (`prenc.matrix.sensor.truth`: the window position
and the pixel where it starts). Expected values never come from the RTL.
"""

from __future__ import annotations

import os

import cocotb
import numpy as np
import pytest
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge, with_timeout

from common import start_clock_and_reset
from prenc.matrix.code import MatrixCode
from prenc.matrix.reader import DEFAULT_MIN_CONTRAST, latency, read_frame
from prenc.matrix.sensor import Geometry, Optics, default_geometry, render, truth
from runner import SIM_BUILD, SIMULATORS, matrix_rom_file, run

TOPLEVEL = "prenc_matrix_reader"


class TB:
    def __init__(self, dut):
        self.dut = dut
        self.n = int(dut.N.value)
        self.checksum = bool(int(dut.CHECKSUM.value))
        self.geom = Geometry(self.n, int(dut.CELL.value), int(dut.WIDTH.value), int(dut.HEIGHT.value),
                             int(dut.TOP.value), int(dut.PIXEL_BITS.value))
        self.code = MatrixCode(self.n, self.checksum)
        self.table = self.code.positions
        self.rng = np.random.default_rng(int(os.environ.get("COCOTB_RANDOM_SEED", "1")))
        self.readings = 0

    async def reset(self) -> None:
        await start_clock_and_reset(self.dut, 2, {"pixel_valid": 0, "pixel_first": 0, "pixel": 0})
        await with_timeout(self._ready(), 200_000 * 10, "ns")

    async def _ready(self) -> None:
        while not int(self.dut.ready.value):
            await RisingEdge(self.dut.ready)
        await FallingEdge(self.dut.clk)

    async def send(self, frame: np.ndarray, gap: int = 0) -> None:
        """Stream a frame, one pixel per clock (a gap of idle clocks between rows)."""
        dut = self.dut
        for y in range(frame.shape[0]):
            for x in range(frame.shape[1]):
                dut.pixel_valid.value = 1
                dut.pixel_first.value = int(x == 0 and y == 0)
                dut.pixel.value = int(frame[y, x])
                await FallingEdge(dut.clk)
            if gap:
                dut.pixel_valid.value = 0
                for _ in range(gap):
                    await FallingEdge(dut.clk)
        dut.pixel_valid.value = 0
        dut.pixel_first.value = 0

    async def reading(self, elapsed: int = 0) -> dict:
        """Wait for out_valid: exactly latency() clocks after the last pixel, of which
        `elapsed` have passed already."""
        dut = self.dut
        for clocks in range(elapsed + 1, latency(self.n) + 1):
            await RisingEdge(dut.clk)
            await ReadOnly()
            if int(dut.out_valid.value):
                break
        assert int(dut.out_valid.value), f"no reading within {latency(self.n)} clocks"
        assert clocks == latency(self.n), f"reading after {clocks} clocks, expected {latency(self.n)}"
        got = {name: int(getattr(dut, "out_" + name).value)
               for name in ("position", "phase", "cells", "ok", "low_contrast", "uncertain", "checksum_error")}
        await FallingEdge(dut.clk)
        self.readings += 1
        return got

    async def check(self, frame: np.ndarray, context: str, expect_truth: tuple[int, int] | None = None) -> dict:
        # the first frame's last pixel was taken on the clock before the FallingEdge
        # where send() returns; reading() counts from there
        await self.send(frame)
        got = await self.reading()
        m = read_frame(frame, self.geom, self.code, self.table, DEFAULT_MIN_CONTRAST)
        want = {"position": m.position, "phase": m.phase, "cells": m.cells, "ok": int(m.ok),
                "low_contrast": int(m.low_contrast), "uncertain": int(m.uncertain),
                "checksum_error": int(m.checksum_error)}
        assert got == want, f"{context}: RTL {got} != model {want}"
        if expect_truth is not None:
            assert (m.ok, m.position, m.phase) == (True, *expect_truth), \
                f"{context}: model read {m}, the disc says position {expect_truth[0]} phase {expect_truth[1]}"
        return got

    def image(self, p: int, optics: Optics | None = None, flip=None) -> tuple[np.ndarray, float]:
        """An image of window p at a random sub-cell offset away from the pixel-rounding tie."""
        j = int(self.rng.integers(0, self.geom.cell))
        theta = p - (j + self.rng.uniform(-0.25, 0.25)) / self.geom.cell
        if optics is None:
            optics = Optics(blur=0.5, noise=3.0, radial=float(self.rng.uniform(-0.3, 0.3)))
        return render(self.code, theta, self.geom, optics, self.rng, flip=flip), theta


@cocotb.test()
async def windows(dut):
    """Every window (or COUNT random ones): the position and phase of the truth, trusted."""
    tb = TB(dut)
    await tb.reset()
    count = int(os.environ.get("MATRIX_WINDOWS", "0"))
    positions = range(tb.code.length) if not count else tb.rng.integers(0, tb.code.length, count).tolist()
    for p in positions:
        frame, theta = tb.image(int(p))
        await tb.check(frame, f"window {p} at theta {theta:.3f}", truth(theta, tb.geom, tb.code.length))
    dut._log.info("%d readings equal the model and the truth", tb.readings)


@cocotb.test()
async def misread_cells(dut):
    """A defect that inverts one cell of the window: with the parity track it is flagged
    and the reading is not trusted; without it the model and RTL agree bit for bit."""
    tb = TB(dut)
    await tb.reset()
    for _ in range(40):
        p = int(tb.rng.integers(0, tb.code.length))
        t, i = int(tb.rng.integers(0, tb.n)), int(tb.rng.integers(0, tb.n))
        frame, theta = tb.image(p, flip=(t, p + i))
        got = await tb.check(frame, f"window {p}, cell ({t}, {i}) inverted")
        if tb.checksum:
            assert got["checksum_error"] == 1 and got["ok"] == 0, f"window {p}: a misread cell passed: {got}"


@cocotb.test()
async def untrusted_frames(dut):
    """Low contrast, a cell at the threshold, a frame restarted half-way, and a frame
    that starts while the reader is busy."""
    tb = TB(dut)
    await tb.reset()
    g = tb.geom
    flat = np.full((g.height, g.width), 120) + tb.rng.integers(-4, 5, (g.height, g.width))
    got = await tb.check(flat, "a flat grey frame")
    assert got["low_contrast"] == 1 and got["ok"] == 0, got

    frame, theta = tb.image(5 % tb.code.length)
    m = read_frame(frame, g, tb.code)
    # put the centre pixel of track 0's first cell on the threshold
    band = frame[g.band]
    frame = frame.copy()
    frame[g.centre_row(0), m.phase + g.cell // 2] = int(band.min()) + (int(band.max()) - int(band.min())) // 2
    got = await tb.check(frame, "a cell on the threshold")
    assert got["uncertain"] == 1 and got["ok"] == 0, got

    # half a frame, then a whole one: the half is dropped
    frame, theta = tb.image(7 % tb.code.length)
    await tb.send(frame[: g.height // 2])
    await tb.check(frame, "a frame after a dropped half frame", truth(theta, g, tb.code.length))

    # a frame whose first pixel comes while the reader is busy is ignored
    frame2, theta2 = tb.image(9 % tb.code.length)
    await tb.send(frame)
    dut.pixel_valid.value = 1
    dut.pixel_first.value = 1
    dut.pixel.value = 0
    await RisingEdge(dut.clk)
    await ReadOnly()
    assert int(dut.busy.value) == 1
    await FallingEdge(dut.clk)
    dut.pixel_valid.value = 0
    dut.pixel_first.value = 0
    got = await tb.reading(elapsed=1)
    assert got["position"] == truth(theta, g, tb.code.length)[0], "the ignored frame disturbed the reading"
    await tb.check(frame2, "the next frame", truth(theta2, g, tb.code.length))


@cocotb.test()
async def heavy_optics(dut):
    """Stronger blur and noise: the reader may place a boundary one pixel off, but never
    trusts a wrong window: a trusted reading is within one pixel of the truth."""
    tb = TB(dut)
    await tb.reset()
    g, L = tb.geom, tb.code.length
    trusted = 0
    for _ in range(60):
        p = int(tb.rng.integers(0, L))
        theta = p - float(tb.rng.uniform(0, 1))
        frame = render(tb.code, theta, g, Optics(blur=0.8, noise=6.0, radial=float(tb.rng.uniform(-0.4, 0.4))),
                       tb.rng)
        got = await tb.check(frame, f"theta {theta:.3f}")
        if got["ok"]:
            trusted += 1
            fine = (got["position"] * g.cell - got["phase"]) % (L * g.cell)
            err = (fine - round(theta * g.cell)) % (L * g.cell)
            assert min(err, L * g.cell - err) <= 1, f"theta {theta:.3f}: trusted reading {got} is off by {err} px"
    assert trusted >= 40, f"only {trusted} of 60 readings trusted"


def params(n: int, checksum: bool = False, table: str = "file") -> dict:
    p: dict[str, object] = dict(default_geometry(n).parameters())
    p["CHECKSUM"] = int(checksum)
    p["TABLE"] = table
    if table == "file":
        p["TABLE_FILE"] = matrix_rom_file(n, checksum)
    return p


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("n, checksum", [(2, False), (2, True), (3, False), (3, True)])
def test_every_window(simulator, n, checksum):
    run(__file__, TOPLEVEL, simulator, parameters=params(n, checksum))


@pytest.mark.parametrize("table", ["file", "generator"])
@pytest.mark.parametrize("checksum", [False, True])
def test_n4_random_windows(table, checksum):
    run(__file__, TOPLEVEL, "verilator", parameters=params(4, checksum, table),
        extra_env={"MATRIX_WINDOWS": "150"})


@pytest.mark.parametrize("n", [2, 3])
def test_generator_table_reads_every_window(n):
    run(__file__, TOPLEVEL, "verilator", parameters=params(n, False, "generator"), testcase="windows")


BAD = [
    ({"N": 5}, "prenc_matrix_reader_parameter_N_out_of_range_2_to_4"),
    ({"CELL": 2}, "prenc_matrix_reader_parameter_CELL_out_of_range_3_to_16"),
    ({"WIDTH": 14}, "prenc_matrix_reader_parameter_WIDTH_out_of_range"),
    ({"HEIGHT": 12}, "prenc_matrix_reader_parameter_HEIGHT_out_of_range"),
    ({"PIXEL_BITS": 3}, "prenc_matrix_reader_parameter_PIXEL_BITS_out_of_range_4_to_12"),
    ({"MIN_CONTRAST": 0}, "prenc_matrix_reader_parameter_MIN_CONTRAST_out_of_range"),
    ({"CHECKSUM": 2}, "prenc_matrix_reader_parameter_CHECKSUM_not_0_or_1"),
    ({"TABLE": "rom"}, "prenc_matrix_table_parameter_TABLE_not_file_or_generator"),
]


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("bad, name", BAD, ids=[b[1].split("parameter_")[1] for b in BAD])
def test_illegal_parameter_stops_elaboration(simulator, bad, name, capfd):
    with pytest.raises((SystemExit, RuntimeError)):
        run(__file__, TOPLEVEL, simulator, parameters={**params(4), **bad}, testcase="windows")
    out = capfd.readouterr()
    assert name in out.out + out.err


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_missing_table_file_stops_the_simulation(simulator, capfd):
    missing = SIM_BUILD / "roms" / "no_such_matrix_table.hex"
    with pytest.raises(SystemExit):
        run(__file__, TOPLEVEL, simulator, parameters={**params(2), "TABLE_FILE": missing}, testcase="windows")
    out = capfd.readouterr()
    assert f'TABLE_FILE "{missing}" cannot be opened' in out.out + out.err


@pytest.mark.synth
@pytest.mark.xdist_group("yowasp")
def test_n4_table_fits_the_up5k():
    """n = 4: the 64 Ki x 16 table in the UP5K's four SPRAMs (built on chip after reset),
    the whole encoder (reader + SSI) placed and routed at 24 MHz."""
    import sys

    from runner import REPO

    sys.path.insert(0, str(REPO / "scripts"))
    import synth

    result = synth.matrix_build(4, "ice40-up5k", 24.0, SIM_BUILD / "matrix_synth" / "up5k_n4", "generator")
    assert result.cells.get("SB_SPRAM256KA") == 4, result.cells
    assert result.used("ICESTORM_SPRAM") == (4, 4)
    assert result.used("ICESTORM_LC")[0] < 5280 // 2
    assert result.timing_met
