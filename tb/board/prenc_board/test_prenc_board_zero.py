# SPDX-License-Identifier: Apache-2.0
"""The zero and the direction a drive writes over SPI, as the SPI angle, ABI and UVW
then give the position.

prenc_board (N = 10, 30 MHz, SPI_SETTINGS2 = 0x03: 4 pole pairs, HYS 0) while the disc
turns at 600 rpm. Once the position is valid, the SimpleFOC drivers library's sequence
writes a zero z (ZPOSM then ZPOSL, each a command and a data frame, then read back),
then SETTINGS1's DIR. After each write, every reading must be of the new angle
(DIR ? -theta : theta) - z, from the definitions alone:

- the SPI angle (ANGLECOM, ODrive's frames) within one 14-bit LSB below it;
- a quadrature counter on A and B, counting from power-up: its count modulo 4000 steps is
  floor(angle x 4000) within one step once the outputs have stepped to the new angle
  (they walk there at the paced rate; within 2,000 steps: 0.5 ms);
- U, V, W: the Hall pattern of 4 x the angle within one sector; with the electrical zero
  written as the zero, U rises where the angle is 0.
"""

from __future__ import annotations

import cocotb
import numpy as np
from cocotb.triggers import Edge, First, Timer
from cocotb.utils import get_sim_time

from as5047_drivers import DRIVERS
from board_harness import drive_encoder, start_board
from common import PERIOD_NS
from prenc.board import abi as abi_spec
from prenc.board import as5047 as spec
from prenc.virtual.encoder import Disc
from runner import rom_file, run

TOPLEVEL = "prenc_board"
N, FILTER, CLK_HZ = 10, 2, 30_000_000
SPEED = 600 / 60 * (1 << N) / CLK_HZ       # slots per clock
START, THETA0 = 2_000, 40.7
STEPS, PAIRS = 4000, 4
TURN14 = 1 << 14


def theta_at(clocks) -> np.ndarray:
    c = np.asarray(clocks, dtype=np.float64)
    return (THETA0 + SPEED * np.clip(c - START, 0, None)) % (1 << N)


def now() -> float:
    return get_sim_time("ns") / PERIOD_NS


class Outputs:
    """A/B counted from power-up, U/V/W, watched on every edge."""

    STATES = {(0, 0): 0, (1, 0): 1, (1, 1): 2, (0, 1): 3}

    def __init__(self, dut):
        self.dut, self.count, self.state = dut, 0, 0
        cocotb.start_soon(self._watch())

    async def _watch(self):
        dut = self.dut
        while True:
            await First(Edge(dut.abi_a), Edge(dut.abi_b))
            await Timer(1, unit="ps")
            new = self.STATES[(int(dut.abi_a.value), int(dut.abi_b.value))]
            delta = (new - self.state) % 4
            assert delta != 2, f"illegal A/B transition at {now()}"
            self.count += {1: 1, 3: -1}.get(delta, 0)
            self.state = new

    def uvw(self) -> tuple[int, int, int]:
        return int(self.dut.uvw_u.value), int(self.dut.uvw_v.value), int(self.dut.uvw_w.value)


def shaft(clock: float, zero: int, direction: int) -> float:
    """The angle the outputs give, in turns, from the truth."""
    t = float(theta_at(np.array([clock]))[0]) / (1 << N)
    return ((-t if direction else t) - zero / TURN14) % 1.0


async def check(dut, out: Outputs, master, zero: int, direction: int, label: str) -> int:
    checks = 0
    for _ in range(12):
        opened = []
        word = await master.frame(0xFFFF, on_open=opened.append)
        word = await master.frame(0xFFFF, on_open=opened.append)
        a = spec.Answer(word)
        assert a.parity_ok and not a.error, (label, hex(word))
        expected = shaft(opened[-1] / PERIOD_NS, zero, direction)
        err = (a.data / TURN14 - expected + 0.5) % 1.0 - 0.5
        assert -1.2 / TURN14 <= err <= 0.2 / TURN14, (label, a.data, expected * TURN14)
        clock = now()
        angle = shaft(clock, zero, direction)
        off = (out.count - int(angle * STEPS) + STEPS // 2) % STEPS - STEPS // 2
        assert abs(off) <= 1, (label, clock, out.count % STEPS, int(angle * STEPS))
        sector = int(angle * PAIRS * 6) % 6
        assert out.uvw() in {abi_spec.UVW_PATTERN[(sector + d) % 6] for d in (-1, 0, 1)}, (label, out.uvw(), sector)
        checks += 1
        await Timer(20_000 * PERIOD_NS, unit="ns")
    return checks


@cocotb.test()
async def a_written_zero_and_direction_move_every_output(dut):
    await start_board(dut)
    cocotb.start_soon(drive_encoder(dut, theta_at, disc=Disc(N)))
    out = Outputs(dut)
    master = DRIVERS["simplefoc_as5047"].master(dut, CLK_HZ)
    await Timer(80_000 * PERIOD_NS, unit="ns")          # the position valid, the velocity settled
    checks = await check(dut, out, master, 0, 0, "after reset")
    # The drivers library's setZero: ZPOSM, ZPOSL (command, data), then getZero.
    zero = (int(shaft(now(), 0, 0) * TURN14) + 5000) % TURN14
    for address, value in ((spec.ZPOSM, zero >> 6), (spec.ZPOSL, zero & 0x3F)):
        await master.frame(spec.write_command(address))
        await master.frame(spec.data_frame(value))
    await master.frame(spec.read_command(spec.ZPOSM))
    assert spec.Answer(await master.frame(spec.read_command(spec.ZPOSL))).data == zero >> 6
    assert spec.Answer(await master.frame(0xFFFF)).data == zero & 0x3F
    await Timer(30_000 * PERIOD_NS, unit="ns")          # ABI walks 5000 / 16384 of a turn
    checks += await check(dut, out, master, zero, 0, "with the zero")
    # DIR: SETTINGS1 = 0x05.
    await master.frame(spec.write_command(spec.SETTINGS1))
    await master.frame(spec.data_frame(0x01 | spec.DIR))
    await Timer(40_000 * PERIOD_NS, unit="ns")
    checks += await check(dut, out, master, zero, 1, "with the zero and DIR")
    dut._log.info("%d checks of SPI, ABI and UVW against the written zero and direction", checks)


def test_prenc_board_zero():
    parameters = {"N": N, "TAPS": sum(1 << (t - 1) for t in Disc(N).taps), "FILTER": FILTER,
                  "ROM_FILE": rom_file(N), "CLK_HZ": CLK_HZ, "BAUD": 3_000_000, "SPI_SETTINGS2": 0x03}
    run(__file__, TOPLEVEL, "verilator", parameters=parameters)
