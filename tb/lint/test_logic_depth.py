# SPDX-License-Identifier: Apache-2.0
"""scripts/logic_depth.py counts LUT levels into every register input of an iCE40
netlist: on a small netlist written here in Yosys's JSON form, whose depths are known
by construction (two LUTs in a row, a four-stage carry chain), and on bad input."""

from __future__ import annotations

import importlib.util
import json

import pytest

from runner import REPO

spec = importlib.util.spec_from_file_location("logic_depth", REPO / "scripts" / "logic_depth.py")
logic_depth = importlib.util.module_from_spec(spec)
spec.loader.exec_module(logic_depth)


def cell(kind: str, outputs: dict, inputs: dict) -> dict:
    directions = {**{p: "output" for p in outputs}, **{p: "input" for p in inputs}}
    return {"type": kind, "port_directions": directions, "connections": {**outputs, **inputs}}


def netlist() -> dict:
    """q (bit 2) -> LUT a (3) -> LUT b (4) -> d of r2; q -> carry x4 (10..13) -> LUT (14) -> d of r3."""
    cells = {
        "r1": cell("SB_DFF", {"Q": [2]}, {"C": [1], "D": [5]}),
        "a": cell("SB_LUT4", {"O": [3]}, {"I0": [2], "I1": ["0"], "I2": ["0"], "I3": ["0"]}),
        "b": cell("SB_LUT4", {"O": [4]}, {"I0": [3], "I1": [2], "I2": ["0"], "I3": ["0"]}),
        "r2": cell("SB_DFFE", {"Q": [5]}, {"C": [1], "D": [4], "E": [2]}),
        "c0": cell("SB_CARRY", {"CO": [10]}, {"I0": [2], "I1": [5], "CI": ["0"]}),
        "c1": cell("SB_CARRY", {"CO": [11]}, {"I0": [2], "I1": [5], "CI": [10]}),
        "c2": cell("SB_CARRY", {"CO": [12]}, {"I0": [2], "I1": [5], "CI": [11]}),
        "c3": cell("SB_CARRY", {"CO": [13]}, {"I0": [2], "I1": [5], "CI": [12]}),
        "s": cell("SB_LUT4", {"O": [14]}, {"I0": [2], "I1": ["0"], "I2": ["0"], "I3": [13]}),
        "r3": cell("SB_DFF", {"Q": [15]}, {"C": [1], "D": [14]}),
    }
    names = {"clk": [1], "q1": [2], "mid": [3], "sum": [14], "q2": [5], "q3": [15], "$auto$x": [4]}
    return {"modules": {"top": {"attributes": {"top": "00000001"}, "cells": cells,
                                "netnames": {n: {"bits": b} for n, b in names.items()}}}}


def test_depths_are_counted_from_the_nearest_register():
    net = logic_depth.Netlist(netlist())
    depth = {name: levels for levels, name, _ in net.endpoints()}
    assert depth["q2.D"] == 2.0          # two LUTs
    assert depth["q2.E"] == 0.0          # straight from a register
    assert depth["q1.D"] == 0.0
    assert depth["q3.D"] == pytest.approx(1 + 4 * logic_depth.CARRY)  # four carry stages and a LUT
    assert net.path(4) == ["q1", "mid", "$auto$x"]


def test_the_report_lists_the_deep_inputs(tmp_path, capsys):
    path = tmp_path / "n.json"
    path.write_text(json.dumps(netlist()))
    assert logic_depth.main([str(path), "--min", "1.2", "--paths", "1"]) == 0
    out = capsys.readouterr().out
    assert "2 inputs at 1.2 levels or more" in out
    assert "2.00    1 bit(s)  q2.D" in out and "path into q2.D (2.00)" in out


def test_bad_input_is_a_clear_error(tmp_path, capsys):
    assert logic_depth.main([str(tmp_path / "missing.json")]) == 1
    assert "logic_depth: error" in capsys.readouterr().err
    empty = tmp_path / "ecp5.json"
    empty.write_text(json.dumps({"modules": {"top": {"cells": {}, "netnames": {}}}}))
    assert logic_depth.main([str(empty)]) == 1
    assert "not an iCE40 netlist" in capsys.readouterr().err
    assert logic_depth.main([str(empty), "--top", "nope"]) == 1
    assert "no module 'nope'" in capsys.readouterr().err
