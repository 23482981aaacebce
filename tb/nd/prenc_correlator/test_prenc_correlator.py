# SPDX-License-Identifier: Apache-2.0
"""prenc_correlator: bit-exact against the Python decoder (prenc.nd.correlator).

Soft decision: readings from the imaging simulator (prenc.nd.imaging) of two
parallel (8,1)-sequences at noise levels from clean to beyond breaking, on both
simulators; every output (position, fraction, score, second, ambiguous) must equal
the model's, and the clean readings must also give the true position.
Hard decision: two parallel (7,3)-sequences of length 14 (minimum summed distance
>= 6), every position with every single- and double-bit error pattern: the decoder
must return the true position every time, as (d-1)/2 = 2 correction promises.
Expected values come from the model and the disc definition, never from the RTL.
"""

from __future__ import annotations

import itertools
import json
import os
from pathlib import Path

import cocotb
import numpy as np
import pytest
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge

from common import start_clock_and_reset
from runner import SIM_BUILD, SIMULATORS, run

from prenc.nd.correlator import decode, rom_text, rom_windows
from prenc.nd.exact import exact_search
from prenc.nd.imaging import Camera, Cylinder, Noise
from prenc.nd.beam import sequence_of_length
from prenc.nd.phasing import best_phasing

TOPLEVEL = "prenc_correlator"
CASES = SIM_BUILD / "correlator_cases"


def pack(samples: np.ndarray, bits: int) -> int:
    value = 0
    for s, x in enumerate(np.asarray(samples).ravel()):
        value |= int(x) << (s * bits)
    return value


def soft_case() -> dict:
    n, p, b, k = 8, 4, 8, 40
    seq = sequence_of_length(n, 1, k)
    phases = best_phasing([seq, seq], n).phases
    cam = Camera(Cylinder((seq, seq), phases, radius=55.0 * k / 170), n, p, b)
    rng = np.random.default_rng(11)
    readings, truth = [], []
    for c in (0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.5, 2.0, 3.0, 3.0):
        for theta in rng.uniform(0, 2 * np.pi, 3):
            readings.append(cam.sample(cam.render(theta, Noise(c), rng)).tolist())
            truth.append(cam.truth_start(theta) if c == 0 else None)
    return {"n": n, "p": p, "b": b, "sequences": [seq, seq], "phases": list(phases),
            "readings": readings, "truth": truth, "hard": False, "thresholds": [1, 50, 400]}


def hard_case() -> dict:
    n, b = 7, 4
    seq = exact_search(n, 3, target=14).sequence
    phases = best_phasing([seq, seq], n).phases
    return {"n": n, "p": 1, "b": b, "sequences": [seq, seq], "phases": list(phases), "hard": True}


def write_case(name: str, case: dict) -> tuple[Path, Path]:
    CASES.mkdir(parents=True, exist_ok=True)
    rom = CASES / f"{name}.hex"
    rom.write_text(rom_text(rom_windows(case["sequences"], case["n"], case["phases"])))
    path = CASES / f"{name}.json"
    path.write_text(json.dumps(case))
    return path, rom


class TB:
    def __init__(self, dut):
        self.dut = dut
        self.case = json.loads(Path(os.environ["PRENC_CORRELATOR_CASE"]).read_text())
        c = self.case
        self.m, self.n, self.p, self.b = len(c["sequences"]), c["n"], c["p"], c["b"]
        self.windows = rom_windows(c["sequences"], self.n, c["phases"])
        self.k = len(c["sequences"][0])

    async def reset(self):
        await start_clock_and_reset(self.dut, 3, {"start": 0, "hard": 0, "threshold": 0, "samples": 0})

    async def read(self, samples, hard: bool, threshold: int):
        """One reading: start, wait for done; returns (outputs, clocks from start to done)."""
        dut = self.dut
        dut.samples.value = pack(samples, self.b)
        dut.hard.value = int(hard)
        dut.threshold.value = threshold
        dut.start.value = 1
        await RisingEdge(dut.clk)
        await FallingEdge(dut.clk)
        dut.start.value = 0
        clocks = 0
        while True:
            await RisingEdge(dut.clk)
            clocks += 1
            await ReadOnly()
            assert int(dut.busy.value) or int(dut.done.value), "busy dropped before done"
            if int(dut.done.value):
                break
            assert clocks < 4 * self.k * self.p + 20, "no done"
        got = (int(dut.position.value), int(dut.fraction.value), dut.score.value.to_signed(),
               dut.second.value.to_signed(), int(dut.ambiguous.value))
        await FallingEdge(dut.clk)
        return got, clocks

    def expected(self, samples, hard: bool, threshold: int):
        d = decode(np.asarray(samples), self.windows, self.b, hard, threshold)
        return (d.position, d.fraction, d.score, d.second, int(d.ambiguous))


@cocotb.test()
async def soft_readings_match_the_model(dut):
    tb = TB(dut)
    await tb.reset()
    ambiguous = 0
    for reading, truth in zip(tb.case["readings"], tb.case["truth"]):
        for threshold in tb.case["thresholds"]:
            got, clocks = await tb.read(reading, False, threshold)
            want = tb.expected(reading, False, threshold)
            assert got == want, f"(pos, frac, score, second, ambiguous) got {got}, model {want}"
            assert clocks == 2 * tb.k * tb.p + 4, f"latency {clocks} clocks"
            ambiguous += got[4]
            if truth is not None:
                start = got[0] + got[1] / tb.p
                diff = (start - truth + tb.k / 2) % tb.k - tb.k / 2
                assert abs(diff) <= 1.0, f"clean reading: start {start}, truth {truth:.2f}"
    # the noisy readings and the large thresholds must exercise both outcomes
    assert 0 < ambiguous < len(tb.case["readings"]) * len(tb.case["thresholds"])


@cocotb.test()
async def hard_decision_corrects_every_double_error(dut):
    tb = TB(dut)
    await tb.reset()
    top = (1 << tb.b) - 1
    bits = tb.m * tb.n
    patterns = [()] + [(e,) for e in range(bits)] + list(itertools.combinations(range(bits), 2))
    for k in range(tb.k):
        clean = tb.windows[k, :, :tb.n].reshape(bits)
        for errors in patterns:
            word = clean.copy()
            word[list(errors)] ^= 1
            samples = (word * top).reshape(tb.m, tb.n, 1)
            got, _ = await tb.read(samples, True, 1)
            assert got == tb.expected(samples, True, 1), f"k {k} errors {errors}: got {got}"
            assert got[0] == k and got[1] == 0, f"k {k} errors {errors}: decoded {got[0]}"
            assert got[2] == bits - len(errors)


def _params(case: dict, rom: Path) -> dict:
    return {"M": len(case["sequences"]), "N": case["n"], "P": case["p"], "B": case["b"],
            "K": len(case["sequences"][0]), "ROM_FILE": rom}


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_soft_decoding_is_bit_exact(simulator):
    case = soft_case()
    path, rom = write_case("soft", case)
    run(__file__, TOPLEVEL, simulator, parameters=_params(case, rom),
        testcase="soft_readings_match_the_model", extra_env={"PRENC_CORRELATOR_CASE": str(path)})


def test_hard_decoding_corrects_two_errors():
    case = hard_case()
    path, rom = write_case("hard", case)
    run(__file__, TOPLEVEL, "verilator", parameters=_params(case, rom),
        testcase="hard_decision_corrects_every_double_error", extra_env={"PRENC_CORRELATOR_CASE": str(path)})


@pytest.mark.parametrize("simulator", SIMULATORS)
@pytest.mark.parametrize("name, value, module", [("M", 5, "M_out_of_range_1_to_4"), ("K", 3, "K_out_of_range_4_to_4096"),
                                                 ("P", 9, "P_out_of_range_1_to_8")])
def test_illegal_parameters_stop_elaboration(simulator, name, value, module, capfd):
    case = hard_case()
    _, rom = write_case("hard", case)
    params = _params(case, rom)
    params[name] = value
    with pytest.raises((SystemExit, RuntimeError)):
        run(__file__, TOPLEVEL, simulator, parameters=params)
    out = capfd.readouterr()
    assert f"prenc_correlator_parameter_{module}" in out.out + out.err


@pytest.mark.parametrize("simulator", SIMULATORS)
def test_missing_rom_stops_the_simulation(simulator, capfd):
    case = hard_case()
    params = _params(case, CASES / "no_such_rom.hex")
    with pytest.raises(SystemExit):
        run(__file__, TOPLEVEL, simulator, parameters=params, testcase="hard_decision_corrects_every_double_error",
            extra_env={"PRENC_CORRELATOR_CASE": str(write_case("hard", case)[0])})
    out = capfd.readouterr()
    assert "cannot be opened" in out.out + out.err
