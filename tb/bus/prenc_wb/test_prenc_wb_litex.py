# SPDX-License-Identifier: Apache-2.0
"""The LiteX example SoC on Verilator: a VexRiscv CPU runs the firmware of sw/litex/
(compiled against the generated header sw/prenc_wb.h) and prints what it reads from
prenc_wb on the SoC's UART, while the virtual encoder turns the disc on the reader's pins.

- Every line the firmware prints with `valid 1` holds the true hybrid position at the
  clock of its snapshot (SNAP_TIME), the core's latency before it, and the velocity
  within 0.1 %.
- Head 1 dies: the reader goes on, reduced to track 2, and the firmware prints mode 3.
- Head 2 dies too: the position is lost, prenc_wb's interrupt fires, the firmware's
  handler counts it and the lines say `valid 0` with `lost` >= 1.

The SoC is built by scripts/litex_soc.py --board sim (LiteX from PyPI, the CPU from
pythondata-cpu-vexriscv, the firmware with Debian's riscv64-unknown-elf-gcc).
"""

from __future__ import annotations

import re
import sys

import cocotb
from cocotb.clock import Clock
from cocotb.triggers import FallingEdge, RisingEdge, Timer

from common import PERIOD_NS, drive_events
from runner import REPO, SIM_BUILD, run

VERSION = (REPO / "VERSION").read_text().strip()

TOPLEVEL = "prenc_litex_soc"
PINS = ["encoder_head1", "encoder_head2", "encoder_sync_a", "encoder_sync_b"]
RESET = 8
SPEED = 1 / 400  # slots per clock
HEAD1_DIES, HEAD2_DIES, END = 300_000, 420_000, 600_000  # a line takes about 18,000 clocks
LINE = re.compile(r"pos (\d+) valid (\d) mode (\d) fine (-?\d+) vel (-?\d+) vvalid (\d) lost (\d+) time (\d+)")


def scenario():
    from prenc.virtual.encoder import Disc, VirtualEncoder
    from prenc.virtual.faults import DeadHead
    from prenc.virtual.trajectory import Trajectory

    traj = Trajectory(clk_hz=1, start=300.3).rest(RESET + 200).move_to(300.3 + SPEED * END, SPEED)
    faults = [DeadHead(1, "stuck0", start_clock=HEAD1_DIES), DeadHead(2, "stuck0", start_clock=HEAD2_DIES)]
    return VirtualEncoder(Disc(10), faults).run(traj)


@cocotb.test()
async def firmware_prints_the_true_position_and_takes_the_interrupt(dut):
    sys.path.insert(0, str(REPO / "scripts"))
    import litex_soc
    from prenc.virtual.scenarios import core_latency

    enc = scenario()
    events = enc.events()
    for pin, value in zip(PINS, events[0][1:]):
        getattr(dut, pin).value = value
    dut.serial_rx.value = 1
    dut.sys_rst.value = 1
    cocotb.start_soon(Clock(dut.sys_clk, PERIOD_NS, unit="ns").start(start_high=False))
    await RisingEdge(dut.sys_clk)
    await FallingEdge(dut.sys_clk)
    cocotb.start_soon(drive_events(dut, PINS, [(c - 1, *v) for c, *v in events[1:]], len(enc)))
    for _ in range(RESET - 1):
        await RisingEdge(dut.sys_clk)
    await FallingEdge(dut.sys_clk)
    dut.sys_rst.value = 0

    text = []
    bit_clocks = litex_soc.SIM_CLOCK_HZ / litex_soc.SIM_BAUD

    async def uart():
        from uart import UartSink

        sink = UartSink(dut.serial_tx, bit_clocks)
        while True:
            _, byte = await sink.queue.get()
            text.append(chr(byte))

    cocotb.start_soon(uart())
    await Timer((END - RESET) * PERIOD_NS, unit="ns")
    lines = "".join(text).splitlines()
    assert lines and lines[0] == f"prenc id 70726e63 version {VERSION} n 10 fine_bits 8", lines[:3]
    readings = [tuple(int(g) for g in m.groups()) for m in map(LINE.fullmatch, lines[1:]) if m]
    assert len(readings) >= 25, lines[-3:]
    latency = core_latency(2)
    checked = reduced = lost_lines = 0
    true_velocity = 4 * SPEED * 2**32  # quarters per clock x 2^32, the register's unit
    for pos, valid, mode, _fine, vel, vvalid, lost, time in readings:
        clock = time + RESET  # TIMESTAMP counts from the first clock out of reset
        if valid:
            truth = {int(enc.hybrid[c - latency]) for c in range(clock - 2, clock + 3)}
            assert pos in truth, f"pos {pos} at time {time}: the disc was at {sorted(truth)}"
            checked += 1
            reduced += mode == 3
            assert vvalid and abs(vel - true_velocity) <= 1e-3 * true_velocity, (time, vel, true_velocity)
        if clock > HEAD2_DIES and not valid:
            assert lost >= 1, "the position was lost but no interrupt was counted"
            lost_lines += 1
        if clock < HEAD2_DIES:
            assert lost == 0, f"an interrupt at time {time}, before the position was lost"
    assert checked >= 10 and reduced >= 2 and lost_lines >= 2, (checked, reduced, lost_lines)
    dut._log.info(f"{len(readings)} readings: {checked} valid ones checked against the disc "
                  f"({reduced} on track 2 alone), {lost_lines} after the loss")


def test_the_litex_soc_runs_the_firmware():
    sys.path.insert(0, str(REPO / "scripts"))  # LiteX itself comes from requirements.txt: no skip
    import litex_soc

    gateware, _ = litex_soc.build("sim", SIM_BUILD / "litex" / "sim")
    sources = (gateware / "sources.txt").read_text().split()
    # The generated SoC and the CPU are not lint clean (ours is: tb/lint): warnings only.
    run(__file__, TOPLEVEL, "verilator", sources=sources, build_args=["-Wno-fatal"])


def test_the_board_build_names_every_file_by_its_path_in_the_repository():
    """The YoWASP tools see no absolute path (issue 57): the board flow renames the
    SoC's memory files and the reader's ROM (add_prenc gives it absolute) in its Verilog."""
    sys.path.insert(0, str(REPO / "scripts"))
    import litex_soc

    gateware = SIM_BUILD / "litex" / "yowasp-names"
    gateware.mkdir(parents=True, exist_ok=True)
    (gateware / "mem.init").write_text("0\n")
    rom = SIM_BUILD / "roms" / "prenc_rom_n10.hex"
    verilog = f'$readmemh("mem.init", mem);\nprenc_wb #(.ROM_FILE("{rom}")) u ();\n'
    text = litex_soc.for_yowasp(verilog, gateware)
    assert '$readmemh("sim_build/litex/yowasp-names/mem.init", mem);' in text
    assert '.ROM_FILE("sim_build/roms/prenc_rom_n10.hex")' in text
    assert str(REPO) not in text
