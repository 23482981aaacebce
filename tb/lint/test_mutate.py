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
    # per-task modes: the core's bounded tasks, the disc's included; its cover is left out
    assert tasks("prenc_core") == ["bmc", "disc"]
    assert tasks("prenc_mode_fsm") == ["prove", "prove_h0"]
    # one mode for every task (`mode prove` without a task prefix)
    assert tasks("prenc_converter") == ["prove"]


def test_every_proof_has_a_task_that_asserts():
    for proof in sorted(mutate.FORMAL.glob("*.sby")):
        assert tasks(proof.stem), proof.name
