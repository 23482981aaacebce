# SPDX-License-Identifier: Apache-2.0
"""One version number, in the file VERSION, shared by the Python package, every FuseSoC
core, the register map's VERSION register (and so the RTL's), the docs and the CHANGELOG."""

from __future__ import annotations

import re
from importlib import metadata

from runner import REPO

VERSION = (REPO / "VERSION").read_text().strip()


def test_the_version_is_semantic():
    assert re.fullmatch(r"\d+\.\d+\.\d+", VERSION), VERSION


def test_the_python_package_has_it():
    import prenc

    assert prenc.__version__ == VERSION
    assert metadata.version("prenc") == VERSION, "reinstall the package (make venv) after changing VERSION"
    assert 'dynamic = ["version"]' in (REPO / "pyproject.toml").read_text()


def test_every_fusesoc_core_has_it():
    cores = sorted(REPO.glob("rtl/*/*.core")) + sorted(REPO.glob("constraints/*/*.core"))
    assert len(cores) >= 10
    for core in cores:
        name = re.search(r"^name:\s*(\S+)", core.read_text(), re.M).group(1)
        assert name.rsplit(":", 1)[1] == VERSION, f"{core.relative_to(REPO)}: {name}"


def test_the_register_map_has_it():
    rdl = (REPO / "rtl" / "bus" / "prenc_wb.rdl").read_text()
    block = rdl[rdl.index('name = "Version"'):rdl.index("} VERSION @")]
    fields = {m.group(1): int(m.group(2)) for m in re.finditer(r"\b(patch|minor|major)\[[^]]+\] = 8'd(\d+);", block)}
    assert f"{fields['major']}.{fields['minor']}.{fields['patch']}" == VERSION
    # the RTL's constant equals the RDL's reset value: tb/lint/test_regmap.py


def test_the_changelog_starts_with_it():
    first = re.search(r"^## (\S+)", (REPO / "CHANGELOG.md").read_text(), re.M).group(1)
    assert first == VERSION
