# SPDX-License-Identifier: Apache-2.0
"""Every board build, simulated as the netlist Yosys makes of it, equals its RTL clock
for clock.

For the iCEstick, the iCEBreaker and the ULX3S (whose fine velocity's program and
register file are block RAM: SB_RAM40_4K, DP16KD): the board's top is synthesized as `make synth` does it (scripts/synth.py's Yosys step: the same parameters, ROM and
`synth_<family>`), written as Verilog, and simulated on Icarus beside its RTL, with
the vendor's cell models (pair.py: Yosys's cells_sim.v; our models of the PLLs and of
ECP5's DP16KD and MULT18X18D, which Yosys has only as boxes). Both run from configuration: the
PLL's lock, the power-on reset, the ROM's contents from its INIT parameters on one
side and $readmemh on the other, every flip-flop's initial value (0 on the netlist, as
a configured FPGA's; X in the RTL until its reset or first load).

The scenario, on the board's pins: the virtual encoder (N = 10) turns clockwise from
rest, then back; a BiSS-C master reads frames at a fifth of the clock, an SSI
controller reads Gray frames, and where the board has the host link (iCEBreaker,
ULX3S) a host asks for the hybrid position (before the reversal). Every output pin of the RTL and of the
netlist is compared at every falling clock edge (`!==`), from the first clock: one
difference fails the test. What was read must also be the disc's: BiSS-C's and SSI's
frames valid with the position of the disc at the request (to the core's latency), the
host's answer the same.

The host link runs at 3 Mbaud on the iCEBreaker and 5 Mbaud on the ULX3S (10 clocks
per bit on both, `make synth BAUD=...`; the ULX3S's FTDI goes to 3 Mbaud), so that its
frames take a few thousand clocks; the builds are otherwise the boards' own. The ECP5
netlist is the slow one on Icarus (about 150 clocks a second: its carry chains ripple
through CCU2C cells), so the scenario is kept to about 6,000 clocks there.

`test_a_register_without_its_reset_is_caught`: the same on the iCEstick with one
register's reset taken out of the RTL (the judge's mode register in prenc_mode_fsm,
which the mode LEDs show): the netlist starts it at 0, as the FPGA does, the RTL at X,
and the comparison must see the difference in the first clocks.
"""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path

import cocotb
import numpy as np
import pytest
from cocotb.clock import Clock
from cocotb.triggers import ClockCycles, FallingEdge, Timer
from cocotb.utils import get_sim_time

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "prenc_board"))

from biss_master import Master  # noqa: E402
from board_harness import drive_encoder  # noqa: E402
from common import PERIOD_NS  # noqa: E402
from prenc.board import as5047, protocol, ssi  # noqa: E402
from prenc.board.abi import UVW_PATTERN  # noqa: E402
from prenc.virtual.encoder import Disc  # noqa: E402
from prenc.virtual.scenarios import core_latency  # noqa: E402
from runner import SIM_BUILD, run  # noqa: E402
from spi_master import SpiMaster  # noqa: E402
from uart import UartSink, UartSource  # noqa: E402

pytestmark = pytest.mark.synth  # Yosys makes the netlists

N, FILTER, MT_BITS = 10, 2, 12
ST_BITS = N + 2
SLOT_CLOCKS = 24          # the disc passes a slot in 24 clocks: a quadrature state in 6
START, REVERSE = 200, 3_600  # the disc turns clockwise from START, back from REVERSE
THETA0 = 100.3
BAUD = {"icebreaker": 3_000_000, "ulx3s": 5_000_000}  # 10 clocks per bit on both


def theta_at(clocks: np.ndarray) -> np.ndarray:
    c = np.asarray(clocks, dtype=np.float64)
    cw = np.clip(c - START, 0, REVERSE - START)
    ccw = np.clip(c - REVERSE, 0, None)
    return THETA0 + (cw - ccw) / SLOT_CLOCKS


def now() -> float:
    return get_sim_time("ns") / PERIOD_NS


def truth(first: float, last: float) -> set[int]:
    """The disc's hybrid positions from `first` less the core's latency to `last`."""
    clocks = np.arange(int(first) - core_latency(FILTER) - FILTER - 2, int(last) + 3)
    return set(Disc(N).hybrid(theta_at(clocks)).tolist())


async def read_ssi(dut, half_clocks: int) -> tuple[int, bool, float]:
    """One Gray SSI frame of N + 2 bits and the error bit: (position, valid, latch clock)."""
    bits, latched = [], now()
    for k in range(ST_BITS + 2):
        dut.ssi_clk.value = 0
        if k > 0:
            bits.append(int(dut.ssi_data.value))
        await Timer(half_clocks * PERIOD_NS, unit="ns")
        dut.ssi_clk.value = 1
        await Timer(half_clocks * PERIOD_NS, unit="ns")
    position, valid = ssi.decode(bits, ST_BITS, True)
    return position, valid, latched


async def ask_host(dut, bit_clocks: int) -> tuple[protocol.Answer, float, float]:
    """A READ HYBRID request on uart_rx; its answer from uart_tx, and when it went."""
    sink, parser = UartSink(dut.uart_tx, bit_clocks), protocol.FrameParser()
    asked = now()
    await UartSource(dut.uart_rx, bit_clocks).send(protocol.read_request(protocol.Kind.HYBRID))
    while True:
        _, byte = await sink.queue.get()
        frames = parser.feed(bytes([byte]))
        if frames:
            return protocol.decode(frames[0]), asked, now()


@cocotb.test()
async def the_netlist_equals_the_rtl_clock_for_clock(dut):
    board, clk_hz = os.environ["PRENC_BOARD"], int(os.environ["PRENC_CLK_HZ"])
    for pin in ("head1", "head2", "sync_a", "sync_b"):
        getattr(dut, pin).value = 0
    dut.ssi_clk.value = 1
    dut.ssi_gray.value = 1
    dut.biss_ma.value = 1
    dut.uart_rx.value = 1
    dut.spi_csn.value = 1
    dut.spi_sclk.value = 0
    dut.spi_mosi.value = 1
    cocotb.start_soon(Clock(dut.clk, PERIOD_NS, unit="ns").start())
    await ClockCycles(dut.clk, START)
    if os.environ.get("PRENC_EXPECT") == "mismatch":  # the RTL was edited: it must show
        mismatches = int(dut.mismatches.value)
        dut._log.info("%s with an edited RTL: %d mismatches in %d clocks", board, mismatches, START)
        assert mismatches > 0, "the netlist simulation did not see the RTL's difference"
        return
    cocotb.start_soon(drive_encoder(dut, theta_at, disc=Disc(N)))
    master = Master(dut, clk_hz / 5, clk_hz, ma="biss_ma", slo="biss_slo")
    spi = SpiMaster(dut, clk_hz / 6, clk_hz, lead_ns=200, gap_ns=200) if os.environ.get("PRENC_SPI") else None
    checked = {"biss": 0, "ssi": 0, "host": 0, "spi": 0}
    await ClockCycles(dut.clk, 1_000)
    for phase in ("clockwise", "back"):
        asked = []
        reading, _ = await master.read(MT_BITS, ST_BITS, on_start=lambda: asked.append(now()))
        assert reading.crc_ok and not reading.error, reading
        assert reading.turns == 0 and reading.position in truth(asked[0], asked[0]), (asked, reading)
        checked["biss"] += 1
        position, valid, latched = await read_ssi(dut, 5)  # while BiSS-C's timeout runs
        assert valid and position in truth(latched, latched), (latched, position)
        checked["ssi"] += 1
        if spi:   # ODrive's read: 0xFFFF, answered by the angle at CSn's fall
            opened = []
            await spi.frame(0xFFFF)
            answer = as5047.Answer(await spi.frame(0xFFFF, on_open=opened.append))
            assert answer.parity_ok and not answer.error, hex(answer.word)
            at = opened[0] / PERIOD_NS
            assert answer.data >> (14 - ST_BITS) in truth(at, at), (at, answer.data)
            checked["spi"] += 1
        if os.environ.get("PRENC_HOST_BAUD") and phase == "clockwise":
            answer, first, last = await ask_host(dut, clk_hz // int(os.environ["PRENC_HOST_BAUD"]))
            assert answer.valid and answer.values["position"] in truth(first, last), (first, last, answer)
            checked["host"] += 1
        if os.environ.get("PRENC_UVW"):   # one pole pair, zero at 0: six sectors a turn
            sector = int(6 * float(theta_at(np.array([now()]))[0]) / (1 << N)) % 6
            uvw = (int(dut.uvw_u.value), int(dut.uvw_v.value), int(dut.uvw_w.value))
            assert uvw in {UVW_PATTERN[(sector + d) % 6] for d in (-1, 0, 1)}, (now(), uvw, sector)
            checked["uvw"] = checked.get("uvw", 0) + 1
        if phase == "clockwise":
            await ClockCycles(dut.clk, max(1, int(REVERSE - now()) + 400))
    await ClockCycles(dut.clk, round(25e-6 * clk_hz))  # BiSS-C's timeout and SSI's monoflop end
    await FallingEdge(dut.clk)
    mismatches, clocks = int(dut.mismatches.value), int(dut.clocks.value)
    dut._log.info("%s: %d clocks compared, %d mismatches; read %s", board, clocks, mismatches, checked)
    assert mismatches == 0, f"the netlist differed from the RTL at {mismatches} falling edges (first: see the log)"


def prepare(board: str, where: Path, rtl_edit=None, extra: dict[str, int] | None = None
            ) -> tuple[list[Path], dict[str, str], list[str]]:
    """The netlist of the board build, the pair, and the sources to simulate; with
    `rtl_edit` (path, old, new), the RTL is first copied and that text replaced; `extra`:
    parameters beside the board's own (`make synth PARAMS=...`)."""
    import pair
    import synth

    if where.exists():
        shutil.rmtree(where)
    where.mkdir(parents=True)
    b = synth.BOARDS[board]
    rtl = synth.file_list(b.folder / f"{b.top}.f")
    if rtl_edit is not None:
        path, old, new = rtl_edit
        copied = where / "rtl" / Path(path).name
        copied.parent.mkdir()
        text = Path(path).read_text()
        assert text.count(old) == 1, f"{old!r} must occur once in {path}"
        copied.write_text(text.replace(old, new))
        rtl = [copied if p.resolve() == Path(path).resolve() else p for p in rtl]
    host_link = pair.BOARD_PINS[board].host_link
    parameters = synth.board_parameters(b, N, where, baud=BAUD[board] if host_link else None)  # as make synth
    parameters.update(extra or {})
    more_pins = pair.UVW_ON_LEDS if (extra or {}).get("UVW") else None
    net = pair.netlist(board, where, parameters, rtl)
    sources = [*pair.cell_library(board, where), *rtl, net, pair.pair_verilog(board, where, parameters, more_pins)]
    env = {"PRENC_BOARD": board, "PRENC_CLK_HZ": str(round(b.clock_mhz * 1e6))}
    if host_link:
        env["PRENC_HOST_BAUD"] = str(BAUD[board])
    if pair.BOARD_PINS[board].spi:
        env["PRENC_SPI"] = "1"
    if more_pins or board == "ulx3s":
        env["PRENC_UVW"] = "1"
    # Icarus takes no default values on input ports: every cell input is connected.
    args = ["-DNO_ICE40_DEFAULT_ASSIGNMENTS"]
    return sources, env, args


@pytest.mark.parametrize("board", ["icestick", "icebreaker", "ulx3s"])
def test_board_netlist(board):
    sources, env, args = prepare(board, SIM_BUILD / "netlist" / board)
    run(__file__, "board_pair", "icarus", sources=sources, extra_env=env, build_args=args,
        parameters={"BUILD": board})


def test_the_icebreaker_with_uvw_netlist():
    """`make synth BOARD=icebreaker PARAMS="UVW=1"`: U, V, W on the LED pins, as the RTL."""
    sources, env, args = prepare("icebreaker", SIM_BUILD / "netlist" / "icebreaker-uvw", extra={"UVW": 1})
    run(__file__, "board_pair", "icarus", sources=sources, extra_env=env, build_args=args,
        parameters={"BUILD": "icebreaker-uvw"})


def test_a_register_without_its_reset_is_caught():
    from runner import RTL

    edit = (RTL / "core" / "prenc_mode_fsm.v", "      mode_reg        <= ACQUIRE;\n", "")
    sources, env, args = prepare("icestick", SIM_BUILD / "netlist" / "icestick-edited", edit)
    run(__file__, "board_pair", "icarus", sources=sources, extra_env=env | {"PRENC_EXPECT": "mismatch"},
        build_args=args, parameters={"BUILD": "icestick-edited"})
