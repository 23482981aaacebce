# SPDX-License-Identifier: Apache-2.0
"""scripts/soak.py (`make soak`): malformed requests stop with a message naming the
option; a failed draw prints its replay line and exits 1; a clean soak exits 0."""

from __future__ import annotations

import sys

import pytest

from runner import REPO

sys.path.insert(0, str(REPO / "scripts"))
import soak as soak_script  # noqa: E402
from prenc.virtual.soak import SoakFailure, SoakResult  # noqa: E402


@pytest.mark.parametrize("argv,message", [
    (["--seeds", "0..3"], "every seed must be 1 or more"),
    (["--seeds", "5..2"], "is empty"),
    (["--seeds", "1,x"], "expected A..B or S,S,..."),
    (["--seeds", "1,2,1"], "a seed is given twice"),
    (["--bits", "3"], "--bits 3 is out of range 4..16"),
    (["--filter", "-1"], "--filter -1 is out of range"),
    (["--jobs", "0"], "--jobs 0 must be 1 or more"),
    (["--seeds", "1", "--scenario", "nope"], "unknown scenario nope"),
    (["--velocity", "--instrument"], "two soaks: give one"),
    (["--velocity", "--jobs", "0"], "--jobs 0 must be 1 or more"),
])
def test_malformed_requests_exit_2_naming_the_option(argv, message, capsys):
    with pytest.raises(SystemExit) as stop:
        soak_script.main(argv)
    assert stop.value.code == 2
    assert message in capsys.readouterr().err


def test_a_failed_draw_prints_its_replay_and_exits_1(monkeypatch, capsys):
    def failing(n, filter_len, seeds, names, hypotheses, jobs):
        return SoakResult(n, filter_len, hypotheses, runs=1,
                          failures=[SoakFailure(seeds[0], "glitches", "wrong valid position at clock 344")])

    monkeypatch.setattr(soak_script, "soak", failing)
    assert soak_script.main(["--seeds", "809969825", "--scenario", "glitches"]) == 1
    out = capsys.readouterr().out
    assert "N=8 FILTER=2 glitches seed 809969825: wrong valid position at clock 344" in out
    assert "PRENC_SCENARIO_SEED=809969825" in out
    assert "1 failed" in out


def test_a_clean_draw_exits_0(capsys):
    assert soak_script.main(["--bits", "6", "--filter", "0", "--seeds", "1",
                             "--scenario", "start_at_rest_cw", "--jobs", "1"]) == 0
    assert "1 draws (1 seeds), 0 failed" in capsys.readouterr().out


def test_a_failed_velocity_run_prints_its_seed_and_exits_1(monkeypatch, capsys):
    from prenc.virtual import velocity_soak

    def failing(seeds, jobs):
        return [velocity_soak.VelocityResult(seeds[0], "ideal", 1000, ["ramp to 563 rpm at clock 9: 0.080 %"],
                                             [("ramp", 9.9, 12.0)])]

    monkeypatch.setattr(velocity_soak, "soak_velocity", failing)
    assert soak_script.main(["--velocity", "--seeds", "4"]) == 1
    out = capsys.readouterr().out
    assert "seed 4, ideal disc" in out and "FAILED: ramp to 563 rpm" in out
    assert "1 runs, 1 failed" in out
