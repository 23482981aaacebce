# SPDX-License-Identifier: Apache-2.0
# DRAFT (issue 41, not merged): a LiteX SoC with VexRiscv and prenc_wb, generated without
# building; what the integration module will grow from.
import sys
from migen import *
from litex.build.generic_platform import GenericPlatform, Pins, Subsignal
from litex.soc.integration.soc_core import SoCCore
from litex.soc.integration.builder import Builder
from litex.soc.interconnect import wishbone
from litex.soc.integration.soc import SoCRegion

_io = [("sys_clk", 0, Pins(1)), ("sys_rst", 0, Pins(1)),
       ("serial", 0, Subsignal("tx", Pins(1)), Subsignal("rx", Pins(1))),
       ("encoder", 0, Subsignal("head1", Pins(1)), Subsignal("head2", Pins(1)),
        Subsignal("sync_a", Pins(1)), Subsignal("sync_b", Pins(1)))]

class Plat(GenericPlatform):
    default_clk_name = "sys_clk"
    def build(self, fragment, build_dir, build_name, **kw):
        import os
        os.makedirs(build_dir, exist_ok=True)
        v = self.get_verilog(fragment, name=build_name)
        v.write(os.path.join(build_dir, build_name + ".v"))
        return v

class Irq:
    def __init__(self): self.irq = Signal()

class Prenc(Module):
    def __init__(self, pads):
        self.bus = wishbone.Interface(data_width=32, address_width=30, addressing="word")
        self.ev = Irq()
        self.specials += Instance("prenc_wb",
            p_N=10, p_ROM_FILE="prenc_rom_n10.hex",
            i_clk=ClockSignal(), i_rst=ResetSignal(),
            i_wb_adr_i=self.bus.adr[:5], i_wb_dat_i=self.bus.dat_w, o_wb_dat_o=self.bus.dat_r,
            i_wb_we_i=self.bus.we, i_wb_sel_i=self.bus.sel, i_wb_stb_i=self.bus.stb, i_wb_cyc_i=self.bus.cyc,
            o_wb_ack_o=self.bus.ack, o_irq=self.ev.irq,
            i_head1=pads.head1, i_head2=pads.head2, i_sync_a=pads.sync_a, i_sync_b=pads.sync_b)

class SoC(SoCCore):
    def __init__(self):
        plat = Plat("", _io, name="sim")
        SoCCore.__init__(self, plat, clk_freq=int(10e6), cpu_type="vexriscv", cpu_variant="minimal",
                         integrated_rom_size=0x4000, integrated_sram_size=0x1000, uart_baudrate=1_000_000,
                         with_timer=True)
        from litex.build.io import CRG
        self.crg = CRG(plat.request("sys_clk"), plat.request("sys_rst"))
        self.prenc = Prenc(plat.request("encoder"))
        self.bus.add_slave("prenc", self.prenc.bus, region=SoCRegion(origin=0x90000000, size=0x100, cached=False))
        self.irq.add("prenc", use_loc_if_exists=True)

soc = SoC()
b = Builder(soc, output_dir="/tmp/soc_out", compile_software=False, compile_gateware=False)
b.build(build_name="prenc_soc")
