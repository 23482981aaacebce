#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The LiteX example: a VexRiscv SoC that reads the encoder through prenc_wb, with the
firmware of sw/litex/ in its ROM (`make litex-soc BOARD=sim|ulx3s`).

    scripts/litex_soc.py --board sim   [--out DIR]   the SoC's Verilog for simulation
    scripts/litex_soc.py --board ulx3s [--out DIR]   the bitstream for the ULX3S
    scripts/litex_soc.py --board icebreaker          the bitstream for the iCEBreaker

Two passes: the SoC is elaborated once for its generated headers (csr.h, mem.h, soc.h),
the firmware is compiled against them and sw/prenc_wb.h with Debian's
riscv64-unknown-elf-gcc and picolibc, and the SoC is elaborated again with the firmware
in its integrated ROM. `sim`: a generic platform (clock, reset, UART, encoder pins) at
a nominal 10 MHz with the UART at 1 Mbaud, for tb/bus/prenc_wb/test_prenc_wb_litex.py.
`ulx3s`: 25 MHz -> 50 MHz by the ECP5 PLL, the UART at 115200 on the FTDI, the encoder
on J1 as the board's own top (docs/guide/wiring.md); LiteX writes the Verilog and the
pins, the project's flow (scripts/synth.py) builds the bitstream and its report.
`icebreaker`: 12 MHz -> 18 MHz by the iCE40 PLL (the UP5K places the SoC at 20 to 23 MHz),
`prenc_wb` without the fine position (FINE = 0), 2 KiB of ROM and 1 KiB of SRAM (the
block RAMs also hold the reader's ROM), the encoder on PMOD1A as the board's own top.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "sim"))
sys.path.insert(0, str(REPO / "scripts"))

FIRMWARE = REPO / "sw" / "litex"
CROSS = "riscv64-unknown-elf-"
ARCH = ["-march=rv32i_zicsr", "-mabi=ilp32"]  # VexRiscv "minimal": no multiply, no compressed
SIM_CLOCK_HZ, SIM_BAUD = 10_000_000, 1_000_000
CLOCK_HZ = {"sim": SIM_CLOCK_HZ, "ulx3s": 50_000_000, "icebreaker": 18_000_000}  # the UP5K: 20 to 23 MHz
TARGET = {"ulx3s": "ecp5-85k", "icebreaker": "ice40-up5k"}
# The integrated ROM and SRAM: the UP5K's 30 block RAMs (15 KiB) hold the reader's ROM too.
MEMORY = {"sim": (0x4000, 0x1000), "ulx3s": (0x4000, 0x1000), "icebreaker": (0x800, 0x400)}


def sim_platform():
    from litex.build.generic_platform import GenericPlatform, Pins, Subsignal
    from prenc.bus.litex import encoder_io

    io = [("sys_clk", 0, Pins(1)), ("sys_rst", 0, Pins(1)),
          ("serial", 0, Subsignal("tx", Pins(1)), Subsignal("rx", Pins(1)))]
    io += encoder_io({name: "X" for name in ("head1", "head2", "sync_a", "sync_b")})

    class SimPlatform(GenericPlatform):
        default_clk_name = "sys_clk"

        def build(self, fragment, build_dir, build_name, **kwargs):
            """The Verilog and its memory files, which it reads by absolute path (a
            simulator runs elsewhere)."""
            folder = Path(build_dir).resolve()
            folder.mkdir(parents=True, exist_ok=True)
            verilog = self.get_verilog(fragment, name=build_name)
            for name, content in verilog.data_files.items():
                (folder / name).write_text(content)
                verilog.main_source = verilog.main_source.replace(f'$readmemh("{name}"', f'$readmemh("{folder / name}"')
            (folder / f"{build_name}.v").write_text(verilog.main_source)
            return verilog

    return SimPlatform("", io, name="sim")


def ulx3s_platform():
    from litex.build.generic_platform import IOStandard, Misc, Pins, Subsignal
    from litex.build.lattice import LatticeECP5Platform
    from prenc.bus.litex import encoder_io

    io = [("clk25", 0, Pins("G2"), IOStandard("LVCMOS33")),
          ("rst", 0, Pins("R1"), IOStandard("LVCMOS33"), Misc("PULLMODE=DOWN")),
          ("serial", 0, Subsignal("tx", Pins("L4")), Subsignal("rx", Pins("M1")), IOStandard("LVCMOS33")),
          ("user_led", 0, Pins("B2"), IOStandard("LVCMOS33"))]
    io += encoder_io({"head1": "B11", "head2": "C11", "sync_a": "A10", "sync_b": "A11"}, "LVCMOS33")
    return LatticeECP5Platform("LFE5U-85F-6BG381C", io, toolchain="trellis")


def icebreaker_platform():
    from litex.build.generic_platform import IOStandard, Pins, Subsignal
    from litex.build.lattice import LatticeiCE40Platform
    from prenc.bus.litex import encoder_io

    io = [("clk12", 0, Pins("35"), IOStandard("LVCMOS33")),
          ("rst_n", 0, Pins("10"), IOStandard("LVCMOS33")),
          ("serial", 0, Subsignal("tx", Pins("9")), Subsignal("rx", Pins("6")), IOStandard("LVCMOS33")),
          ("user_led", 0, Pins("37"), IOStandard("LVCMOS33"))]
    io += encoder_io({"head1": "4", "head2": "2", "sync_a": "47", "sync_b": "45"}, "LVCMOS33")
    return LatticeiCE40Platform("ice40-up5k-sg48", io, toolchain="icestorm")


def make_soc(board: str, rom_dir: Path, firmware: list[int] | None):
    from migen import ClockDomain, Signal
    from litex.gen import LiteXModule
    from litex.soc.integration.soc_core import SoCCore
    from prenc.bus.litex import add_prenc

    platform = {"sim": sim_platform, "ulx3s": ulx3s_platform, "icebreaker": icebreaker_platform}[board]()
    clock = CLOCK_HZ[board]
    rom_bytes, sram_bytes = MEMORY[board]
    rom = {"integrated_rom_init": firmware} if firmware else {}
    soc = SoCCore(platform, clk_freq=clock, cpu_type="vexriscv", cpu_variant="minimal",
                  integrated_rom_size=rom_bytes, integrated_sram_size=sram_bytes,
                  uart_baudrate=SIM_BAUD if board == "sim" else 115200, with_timer=False,
                  ident="prenc LiteX example", **rom)
    reader = {}
    if board == "sim":
        from litex.build.io import CRG

        soc.crg = CRG(platform.request("sys_clk"), platform.request("sys_rst"))
    elif board == "icebreaker":
        from litex.soc.cores.clock import iCE40PLL

        class _CRG(LiteXModule):
            def __init__(self):
                self.cd_sys = ClockDomain()
                self.pll = pll = iCE40PLL(primitive="SB_PLL40_PAD")
                clk12 = platform.request("clk12")
                pll.register_clkin(clk12, 12e6)
                pll.create_clkout(self.cd_sys, clock)
                self.comb += pll.reset.eq(~platform.request("rst_n"))
                platform.add_period_constraint(clk12, 1e9 / 12e6)

        soc.crg = _CRG()
        reader = {"parameters": {"FINE": 0}}  # the UP5K has no room for the CPU and the fine position
    else:
        from litex.soc.cores.clock import ECP5PLL

        class _CRG(LiteXModule):
            def __init__(self):
                self.cd_sys = ClockDomain()
                self.pll = pll = ECP5PLL()
                clk25 = platform.request("clk25")
                pll.register_clkin(clk25, 25e6)
                pll.create_clkout(self.cd_sys, clock)
                self.comb += pll.reset.eq(platform.request("rst"))
                platform.add_period_constraint(clk25, 1e9 / 25e6)  # nextpnr derives the PLL's

        soc.crg = _CRG()
    if board != "sim":  # a pin held high: the ULX3S's LED 0 lights, the iCEBreaker's (active low) stays off
        led = platform.request("user_led")
        soc.comb += led.eq(Signal(reset=1))
    add_prenc(soc, platform.request("encoder"), n=10, rom_dir=rom_dir, **reader)
    return soc


def compile_firmware(include: Path, out: Path) -> list[int]:
    """The firmware for the SoC whose generated headers are in `include`, as ROM words."""
    import litex

    litex_root = Path(litex.__file__).parent
    includes = [include, litex_root / "soc" / "software" / "include",
                litex_root / "soc" / "cores" / "cpu" / "vexriscv", REPO / "sw"]
    flags = ["--specs=picolibc.specs", *ARCH, "-Os", "-std=c11", "-Wall", "-Wextra", "-Werror",
             "-ffreestanding", *[f"-I{p}" for p in includes]]
    out.mkdir(parents=True, exist_ok=True)
    objects = []
    for source in ("start.S", "main.c"):
        obj = out / f"{source}.o"
        subprocess.run([CROSS + "gcc", *flags, "-c", str(FIRMWARE / source), "-o", str(obj)], check=True)
        objects.append(str(obj))
    elf, binary = out / "firmware.elf", out / "firmware.bin"
    # The multilib is chosen by -march at the link: rv32i, whose libgcc gives the division.
    subprocess.run([CROSS + "gcc", "--specs=picolibc.specs", "-march=rv32i", "-mabi=ilp32",
                    "-nostartfiles", f"-L{include}", "-T", str(FIRMWARE / "linker.ld"),
                    *objects, "-lgcc", "-o", str(elf)], check=True)
    subprocess.run([CROSS + "objcopy", "-O", "binary", str(elf), str(binary)], check=True)
    data = binary.read_bytes()
    data += bytes(-len(data) % 4)
    return [int.from_bytes(data[k:k + 4], "little") for k in range(0, len(data), 4)]


def build(board: str, out: Path, run: bool = True):
    """Both passes; returns the gateware folder (the Verilog, its memory files, the
    sources' list) and, for the ULX3S with `run`, the synthesis result (scripts/synth.py's,
    the bitstream and report.md in gateware/synth/)."""
    from litex.soc.integration.builder import Builder

    out = out.resolve()
    headers = Builder(make_soc(board, out / "rom", None), output_dir=str(out / "headers"),
                      compile_software=False, compile_gateware=False)
    headers.build(build_name="prenc_litex_soc", run=False)
    firmware = compile_firmware(out / "headers" / "software" / "include", out / "firmware")
    soc = make_soc(board, out / "rom", firmware)
    builder = Builder(soc, output_dir=str(out), compile_software=False, compile_gateware=board != "sim")
    builder.build(build_name="prenc_litex_soc", run=False)
    gateware = Path(builder.gateware_dir)
    # Every source the SoC needs (prenc_wb's, the CPU's, then the SoC's own), for a
    # simulator and for the YoWASP tools, which see only files inside the repository:
    # the CPU's Verilog is copied beside the SoC's.
    sources = []
    for path, *_ in soc.platform.sources:
        path = Path(path).resolve()
        if REPO not in path.parents:
            (gateware / path.name).write_bytes(path.read_bytes())
            path = gateware / path.name
        sources.append(path)
    if gateware / "prenc_litex_soc.v" not in sources:  # LiteX's own build lists it already
        sources.append(gateware / "prenc_litex_soc.v")
    (gateware / "sources.txt").write_text("".join(f"{p}\n" for p in sources))
    result = synthesize(board, gateware, sources) if board != "sim" and run else None
    return gateware, result


def for_yowasp(verilog: str, gateware: Path) -> str:
    """The SoC's Verilog with every file it reads named by its path in the repository,
    the only one the YoWASP tools see: the memory files (LiteX names them from the
    gateware folder) and the reader's ROM (add_prenc names it by its absolute path)."""
    import synth

    for init in sorted(gateware.glob("*.init")):
        verilog = verilog.replace(f'$readmemh("{init.name}"', f'$readmemh("{synth.rel(init)}"')
    return verilog.replace(f'"{REPO}/', '"')


def synthesize(board: str, gateware: Path, sources: list[Path]):
    """The bitstream through the project's flow (scripts/synth.py: YoWASP Yosys, nextpnr
    at the design clock, ecppack or icepack), report.md beside it; a missed clock fails."""
    import synth

    verilog = gateware / "prenc_litex_soc.v"
    verilog.write_text(for_yowasp(verilog.read_text(), gateware))
    pins = gateware / ("prenc_litex_soc.lpf" if board == "ulx3s" else "prenc_litex_soc.pcf")
    result = synth.build("prenc_litex_soc", sources, TARGET[board], {}, CLOCK_HZ[board] / 1e6, gateware / "synth",
                         pins=pins)
    synth.write_report(result, gateware / "synth")
    return result


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--board", choices=("sim", "ulx3s", "icebreaker"), default="sim")
    parser.add_argument("--out", type=Path, help="output folder (default build/litex/<board>)")
    args = parser.parse_args(argv)
    out = args.out or REPO / "build" / "litex" / args.board
    gateware, result = build(args.board, out)
    if result is not None:
        import synth

        print(synth.summary(result))
    print(f"litex_soc: {gateware}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
