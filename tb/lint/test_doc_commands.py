# SPDX-License-Identifier: Apache-2.0
"""Every command the README and the user guide show is run by a test.

The commands are the lines of their ```sh blocks. The quick ones (`prenc taps`, `rom`,
`tracks`, `disc`, `make rom`, `make demo`) run here, as a user types them, in a scratch
folder. The others need a board, a Verilator build of the board or a synthesis run, and
another test runs them: COVERED names that test and the words of the command it must
contain, so that a command added to the docs without a test, or a test that stops running
it, fails here. A board's port (/dev/ttyUSB1, /dev/pts/N) is the pseudo-terminal of the
simulated board in those tests. Only the programmers (iceprog, openFPGALoader) need real
hardware; NEEDS_A_BOARD lists them. One command is run by `make bench` instead of a
test, the LiteX example's ULX3S bitstream (minutes of place and route).
"""

from __future__ import annotations

import re
import shlex
import subprocess
import sys

import pytest

from runner import REPO

DOCS = [REPO / "README.md", *sorted((REPO / "docs" / "guide").glob("*.md"))]

# (the command's pattern, the test file that runs it, words that file must contain)
COVERED = [
    (r"make test", ".ci/run", ["make test"]),
    (r"make synth BOARD=(icebreaker|icestick|ulx3s)", "tb/lint/test_boards.py",
     ["def test_board_builds_and_meets_timing", "synth.BOARDS", "board_build"]),
    (r"make synth BOARD=ulx3s CAL=1", "tb/lint/test_boards.py",
     ["def test_the_ulx3s_with_the_calibration_table_meets_its_clock", 'cal="1"']),
    (r"make synth BOARD=icebreaker CAL=1", "tb/lint/test_boards.py",
     ["def test_the_icebreaker_with_the_calibration_table_meets_its_clock", 'cal="1"']),
    (r"\.venv/bin/python scripts/synth\.py --core ice40-hx8k", "tb/lint/test_boards.py", ['"--core"', "ice40-hx8k"]),
    (r"\.venv/bin/python scripts/synth\.py --core ice40-up5k --top prenc_core_harness", "tb/lint/test_boards.py",
     ["ice40-up5k", "prenc_core_harness"]),
    (r"\.venv/bin/python scripts/synth\.py --core ice40-hx8k --param HYPOTHESES=0 --seeds 1,2,3",
     "tb/lint/test_boards.py", ['"--param"', '"--seeds"', "HYPOTHESES"]),
    (r"make board-sim( ARGS=\"--seconds [0-9.]+\")?", "tb/board/prenc_board/test_virtual_board.py",
     ['"board_sim.py"', '"--seconds"']),
    (r"\.venv/bin/prenc host read +--port \S+ --kind (hybrid|fine)( --json)?",
     "tb/board/prenc_board/test_prenc_board.py", ['"read"', '"--kind"', '"--json"', "fine"]),
    (r"\.venv/bin/prenc host monitor +--port \S+( --rate 1000)?", "tb/board/prenc_board/test_prenc_board.py",
     ['"monitor"', '"--rate", "1000"']),
    (r"\.venv/bin/prenc host log +--port \S+ --out \S+ --rate 1000 --count 500",
     "tb/board/prenc_board/test_prenc_board.py", ['"log"', '"--out"', '"--rate"', '"--count"']),
    (r"\.venv/bin/prenc host plot +\S+ --out \S+", "tb/board/prenc_board/test_prenc_board.py", ['"plot"', '"--out"']),
    (r"\.venv/bin/prenc host map +--port \S+ --regions 32", "tb/board/prenc_board/test_prenc_board_map.py",
     ['"map"', '"--regions"']),
    (r"\.venv/bin/prenc calibrate --port \S+ --out \S+ --apply", "tb/board/prenc_board/test_calibrate_virtual_board.py",
     ['"calibrate"', '"--port"', '"--out"', '"--apply"']),
    (r"fusesoc library add prenc \S+", "tb/lint/test_fusesoc.py", ['"library", "add"']),
    (r"fusesoc run --target (lint|sim|synth_ice40) prenc:reader:core", "tb/lint/test_fusesoc.py",
     ['"--target", "lint", "prenc:reader:core"', '"--target", "sim", "prenc:reader:core"',
      '("synth_ice40", "SB_LUT4")']),
    (r"fusesoc run --target lint prenc:reader:core --FILTER=3 --HYPOTHESES=0", "tb/lint/test_fusesoc.py",
     ['"--FILTER=3", "--HYPOTHESES=0"']),
    (r"make litex-soc", "tb/bus/prenc_wb/test_prenc_wb_litex.py", ['litex_soc.build("sim"']),
    # The ULX3S example's bitstream takes minutes: make bench builds it (section 7), not make test.
    (r"make litex-soc BOARD=ulx3s", "scripts/bench.py", ['for board in ("ulx3s", "icebreaker")',
                                                         "litex_soc.build(board"]),
]
RUN_HERE = [r"\.venv/bin/prenc (taps|rom|tracks|disc) .*", r"make rom", r"make demo"]
NEEDS_A_BOARD = [r"iceprog \S+", r"openFPGALoader -b ulx3s \S+"]


def shown_commands() -> list[tuple[str, str]]:
    """(file, command) for every line of every ```sh block, without its comment."""
    found = []
    for path in DOCS:
        for block in re.findall(r"```sh\n(.*?)```", path.read_text(), re.S):
            for line in block.splitlines():
                command = re.split(r"\s+#\s", " " + line.strip() + " ", maxsplit=1)[0].strip()
                if command:
                    found.append((path.relative_to(REPO).as_posix(), command))
    return found


def kind(command: str) -> str:
    for pattern in RUN_HERE:
        if re.fullmatch(pattern, command):
            return "here"
    for pattern in NEEDS_A_BOARD:
        if re.fullmatch(pattern, command):
            return "board"
    for pattern, _, _ in COVERED:
        if re.fullmatch(pattern, command):
            return "covered"
    return "none"


def test_every_shown_command_is_run_by_a_test():
    commands = shown_commands()
    assert len(commands) > 30
    orphans = [f"{where}: {command}" for where, command in commands if kind(command) == "none"]
    assert not orphans, "commands in the docs that no test runs:\n" + "\n".join(orphans)


@pytest.mark.parametrize("pattern,test_file,words", COVERED, ids=[c[0][:40] for c in COVERED])
def test_the_covering_test_runs_the_command(pattern, test_file, words):
    text = (REPO / test_file).read_text()
    missing = [w for w in words if w not in text]
    assert not missing, f"{test_file} no longer holds {missing}, which run `{pattern}`"
    assert any(re.fullmatch(pattern, c) for _, c in shown_commands()), f"no command in the docs matches {pattern}"


def quick_commands() -> list[str]:
    return sorted({c for _, c in shown_commands() if kind(c) == "here" and c.startswith(".venv/bin/prenc")})


@pytest.mark.parametrize("command", quick_commands())
def test_a_prenc_command_from_the_docs_runs(command, tmp_path):
    args = shlex.split(command)[1:]
    proc = subprocess.run([sys.executable, "-m", "prenc.cli.main", *args], cwd=tmp_path,
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    outputs = [args[k + 1] for k, a in enumerate(args) if a in ("-o", "--png")]
    for name in outputs:
        assert (tmp_path / name).stat().st_size > 0, name
    assert outputs or proc.stdout.strip()


def test_make_rom_writes_the_default_table():
    subprocess.run(["make", "-s", "rom"], cwd=REPO, check=True, capture_output=True, timeout=300)
    lines = (REPO / "build" / "rom" / "prenc_rom_n10.hex").read_text().split()
    assert len(lines) == 1024


@pytest.mark.xdist_group("core_demo")
def test_make_demo_reads_the_story_without_a_wrong_valid_position(tmp_path):
    """What `make demo` runs (scripts/demo.py), into a scratch folder."""
    proc = subprocess.run([sys.executable, str(REPO / "scripts" / "demo.py"), "--out", str(tmp_path)],
                          cwd=REPO, capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    assert "protected core: 0 wrong valid clocks" in proc.stdout, proc.stdout
    assert (tmp_path / "demo.png").stat().st_size > 10_000
    # The instrument's part: over the turn at 600 rpm on the printed disc, the calibrated
    # fine position within issue 58's 1/256 slot RMS, and far better than without a table.
    turn = next(line for line in proc.stdout.splitlines() if line.strip().startswith("one turn at 600 rpm"))
    quarter, raw, calibrated = (float(cell.split("/")[0]) for cell in turn.split()[5:8])
    assert calibrated <= 1 / 256 and calibrated < raw / 10 and raw < quarter, turn
    assert (tmp_path / "instrument.png").stat().st_size > 10_000
