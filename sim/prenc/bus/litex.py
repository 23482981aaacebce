# SPDX-License-Identifier: Apache-2.0
"""prenc_wb in a LiteX SoC: its Wishbone slave, its interrupt, its ROM and its pins.

    from prenc.bus.litex import add_prenc

    add_prenc(soc, soc.platform.request("encoder"), n=10, rom_dir="build/rom")

`add_prenc` writes the conversion ROM for the chosen N (and taps) into rom_dir, adds
the RTL sources of prenc_wb (rtl/bus/prenc_wb.f) to the platform, maps the registers
(sw/prenc_wb.h, docs/registers.md) as an uncached region of the SoC's bus, and connects
prenc_wb's `irq` to an interrupt of the CPU: the SoC's generated headers then give
PRENC_BASE (mem.h) and PRENC_INTERRUPT (soc.h). The pads are the encoder's four signals:
head1, head2, sync_a, sync_b (a platform's connector, as in `encoder_io`).

The module imports LiteX (migen, litex) only here, so the rest of prenc needs neither.
"""

from __future__ import annotations

from pathlib import Path

from migen import ClockSignal, Constant, Instance, ResetSignal, Signal
from litex.gen import LiteXModule
from litex.soc.integration.soc import SoCRegion
from litex.soc.interconnect import wishbone

from ..codes.lfsr import check_taps, taps_mask
from ..codes.rom import write_rom
from ..rtl import file_list

ENCODER_SIGNALS = ("head1", "head2", "sync_a", "sync_b")
REGISTER_BYTES = 0x80  # 32 word addresses, wb_adr_i[4:0] (the map uses 0x00..0x64)


def encoder_io(pins: dict[str, str], iostandard=None, index: int = 0) -> list:
    """A platform's IO entry "encoder" for the four signals, pins {signal: site}."""
    from litex.build.generic_platform import IOStandard, Pins, Subsignal

    missing = set(ENCODER_SIGNALS) - set(pins)
    if missing:
        raise ValueError(f"encoder_io: no pin for {', '.join(sorted(missing))}")
    subsignals = [Subsignal(name, Pins(pins[name])) for name in ENCODER_SIGNALS]
    return [("encoder", index, *subsignals, *([IOStandard(iostandard)] if iostandard else []))]


class _Interrupt:
    """What LiteX's interrupt wiring looks for on a module: `ev.irq`."""

    def __init__(self) -> None:
        self.irq = Signal()


class PrencWishbone(LiteXModule):
    """prenc_wb: the reader core and its register map on a 32-bit Wishbone slave with
    word addresses, and its interrupt (`ev.irq`)."""

    def __init__(self, platform, pads, n: int = 10, taps=None, filter_len: int = 2,
                 rom_dir: str | Path = "build/rom", parameters: dict | None = None):
        taps = check_taps(n, taps)
        rom = Path(rom_dir).resolve() / f"prenc_rom_n{n}.hex"
        rom.parent.mkdir(parents=True, exist_ok=True)
        write_rom(rom, n, taps, "hex")
        self.rom_file = rom
        for source in file_list("prenc_wb"):
            platform.add_source(str(source))

        self.bus = wishbone.Interface(data_width=32, address_width=30, addressing="word")
        self.ev = _Interrupt()
        # Integer parameters as 32-bit constants, the width of a Verilog integer.
        values = {"N": n, "TAPS": taps_mask(taps), "FILTER": filter_len, **(parameters or {})}
        params = {f"p_{k}": Constant(v, 32) if isinstance(v, int) else v for k, v in values.items()}
        params["p_ROM_FILE"] = str(rom)
        self.specials += Instance(
            "prenc_wb", **params,
            i_clk=ClockSignal(), i_rst=ResetSignal(),
            i_wb_adr_i=self.bus.adr[:5], i_wb_dat_i=self.bus.dat_w, o_wb_dat_o=self.bus.dat_r,
            i_wb_we_i=self.bus.we, i_wb_sel_i=self.bus.sel, i_wb_stb_i=self.bus.stb,
            i_wb_cyc_i=self.bus.cyc, o_wb_ack_o=self.bus.ack, o_irq=self.ev.irq,
            i_head1=pads.head1, i_head2=pads.head2, i_sync_a=pads.sync_a, i_sync_b=pads.sync_b)


def add_prenc(soc, pads, name: str = "prenc", origin: int = 0x9000_0000, **kwargs) -> PrencWishbone:
    """Add prenc_wb to a LiteX SoC: its bus region at `origin` (uncached), its interrupt,
    its sources and ROM (kwargs: n, taps, filter_len, rom_dir, parameters)."""
    module = PrencWishbone(soc.platform, pads, **kwargs)
    setattr(soc, name, module)
    soc.bus.add_slave(name, module.bus, region=SoCRegion(origin=origin, size=REGISTER_BYTES, cached=False))
    soc.irq.add(name, use_loc_if_exists=True)
    return module
