# SPDX-License-Identifier: Apache-2.0
"""scripts/mutate.py (`make mutate`): which tasks of a proof a mutant must pass."""

from __future__ import annotations

import sys

from runner import REPO

sys.path.insert(0, str(REPO / "scripts"))
import mutate  # noqa: E402


def tasks(name: str) -> list[str]:
    return mutate.checking_tasks(mutate.sections((mutate.FORMAL / f"{name}.sby").read_text()))


def test_a_mutant_runs_every_task_that_asserts_and_no_cover():
    # per-task modes: the core's bounded tasks, the disc's included; its covers are left out
    assert tasks("prenc_core") == ["disc", "bmc"]
    assert tasks("prenc_mode_fsm") == ["prove", "prove_h0"]
    # one mode for every task (`mode prove` without a task prefix)
    assert tasks("prenc_converter") == ["prove"]
    # --covers: the cover tasks as well
    core = mutate.sections((mutate.FORMAL / "prenc_core.sby").read_text())
    assert mutate.checking_tasks(core, covers=True) == ["disc", "bmc", "cover", "disc_cover"]
    # a mutant runs those that read the design as the listing task does (the first):
    # the core's disc and disc_cover, which read it with -DF_DISC, and not bmc or cover
    assert mutate.same_netlist_tasks(core, covers=True) == ["disc", "disc_cover"]
    fsm = mutate.sections((mutate.FORMAL / "prenc_mode_fsm.sby").read_text())
    assert mutate.same_netlist_tasks(fsm) == ["prove"]  # prove_h0 sets HYPOTHESES 0


def test_every_proof_has_a_task_that_asserts():
    for proof in sorted(mutate.FORMAL.glob("*.sby")):
        assert tasks(proof.stem), proof.name


def test_the_properties_are_never_mutated_nested_ifdefs_included():
    """Every line from `ifdef FORMAL to its own `endif is a property line, past the
    `endif of an `ifdef nested in it (the core's F_DISC)."""
    core = REPO / "rtl" / "core" / "prenc_core.v"
    lines = core.read_text().splitlines()
    numbers = mutate.yosys_numbers(core)
    skip = mutate.formal_lines(core)
    first = next(i for i, l in enumerate(lines) if l.strip().startswith("`ifdef FORMAL"))
    nested_end = next(i for i, l in enumerate(lines) if i > first and l.strip().startswith("`endif"))
    covers = [i for i, l in enumerate(lines) if i > nested_end and l.strip().startswith("cover (")]
    assert covers, "the core's covers follow its nested `ifdef"
    assert all(numbers[i] in skip for i in covers)
    assert numbers[first - 1] not in skip  # the design before it is mutated


def test_a_mutant_that_runs_too_long_is_reported_and_the_others_go_on(tmp_path, monkeypatch):
    """One mutant's proof past the limit must not stop the run (it used to raise)."""
    import subprocess

    def too_long(*args, **kwargs):
        raise subprocess.TimeoutExpired(args[0], mutate.TIMEOUT_S)

    monkeypatch.setattr(mutate.subprocess, "run", too_long)
    proof = mutate.FORMAL / "prenc_quadrature.sby"
    (tmp_path / proof.name).write_text(proof.read_text())
    index, _, verdict, _ = mutate.run_mutant(tmp_path / proof.name, tmp_path, 3, "mutate -mode inv")
    assert (index, verdict) == (3, "timeout")
